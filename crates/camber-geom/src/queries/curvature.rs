//! Curvature of a parametric curve: unsigned in any dimension, signed in the plane, and the
//! curvature vector.
//!
//! With a = C′(u) and b = C″(u):
//! - unsigned curvature κ = √(|a|²|b|² − (a·b)²) / |a|³, evaluated as
//!   √(Σ_{i<j} (a_i b_j − a_j b_i)²) / |a|³ (the same quantity without the cancellation of the
//!   first form, so a straight piece gives exactly 0);
//! - signed curvature in the plane κ_s = (a × b) / |a|³, positive where the curve turns left
//!   (counter-clockwise);
//! - curvature vector k = (b − (a·b/|a|²)·a) / |a|², of length κ, pointing to the centre of
//!   curvature.
//!
//! All are in inverse length units and undefined where C′ = 0 (a cusp or a stationary
//! parameterisation): the `*_from_derivatives` helpers return `None` there and the curve
//! functions fail with [`Error::ZeroLength`].

use nalgebra::{SVector, Vector2};

use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::scalar::{cst, re, Scalar};

/// The error for a zero first derivative.
fn singular() -> Error {
    Error::ZeroLength {
        what: "first derivative (curvature is undefined)",
    }
}

/// C′ and C″ both multiplied by s = 2⁻ᵉ, the power of two nearest below 1/max|C′ᵢ|, and s:
/// exact (a power of two), and it keeps |C′|³ and |C′ × C″|² inside f64 for any finite
/// curve (κ(sC′, sC″) = κ/s, the curve scaled by s). `None` when C′ = 0. A non-finite C′ is
/// left as it is (the result is then non-finite too, as the curve's derivatives are).
fn scaled<T: Scalar, const D: usize>(
    d1: &SVector<T, D>,
    d2: &SVector<T, D>,
) -> Option<(SVector<T, D>, SVector<T, D>, f64)> {
    let largest = d1.iter().map(|x| re(*x).abs()).fold(0.0_f64, f64::max);
    if largest == 0.0 {
        return None;
    }
    if !largest.is_finite() {
        return Some((*d1, *d2, 1.0));
    }
    // 2^e ≤ largest < 2^(e+1); e within [−1074, 1023], s kept a normal number.
    let e = largest.log2().floor().clamp(-1022.0, 1022.0) as i32;
    let s = 2.0_f64.powi(-e);
    let st: T = cst(s);
    Some((d1 * st, d2 * st, s))
}

/// Unsigned curvature κ from C′ = `d1` and C″ = `d2`, or `None` when C′ = 0.
///
/// ```
/// use camber_geom::queries::curvature_from_derivatives;
/// use nalgebra::Vector2;
/// // A circle of radius 2 at unit angular speed: C′ = (0, 2), C″ = (−2, 0).
/// let k = curvature_from_derivatives(&Vector2::new(0.0_f64, 2.0), &Vector2::new(-2.0, 0.0)).unwrap();
/// assert!((k - 0.5).abs() < 1e-15);
/// ```
pub fn curvature_from_derivatives<T: Scalar, const D: usize>(
    d1: &SVector<T, D>,
    d2: &SVector<T, D>,
) -> Option<T> {
    let (d1, d2, s) = scaled(d1, d2)?;
    let speed2 = d1.norm_squared();
    let mut cross2 = T::zero();
    for i in 0..D {
        for j in i + 1..D {
            let c = d1[i] * d2[j] - d1[j] * d2[i];
            cross2 += c * c;
        }
    }
    Some(cross2.sqrt() / (speed2 * speed2.sqrt()) * cst::<T>(s))
}

/// Signed planar curvature (C′ × C″)/|C′|³ from C′ = `d1` and C″ = `d2`, or `None` when
/// C′ = 0. Positive when the curve turns counter-clockwise.
pub fn signed_curvature_from_derivatives<T: Scalar>(d1: &Vector2<T>, d2: &Vector2<T>) -> Option<T> {
    let (d1, d2, s) = scaled(d1, d2)?;
    let speed2 = d1.norm_squared();
    Some((d1.x * d2.y - d1.y * d2.x) / (speed2 * speed2.sqrt()) * cst::<T>(s))
}

/// The curvature vector (C″ − (C′·C″/|C′|²)·C′)/|C′|² from C′ = `d1` and C″ = `d2`: length κ,
/// direction the principal normal (towards the centre of curvature); `None` when C′ = 0.
pub fn curvature_vector_from_derivatives<T: Scalar, const D: usize>(
    d1: &SVector<T, D>,
    d2: &SVector<T, D>,
) -> Option<SVector<T, D>> {
    let (d1, d2, s) = scaled(d1, d2)?;
    let speed2 = d1.norm_squared();
    let normal_part = d2 - d1 * (d1.dot(&d2) / speed2);
    Some(normal_part / speed2 * cst::<T>(s))
}

/// Unsigned curvature κ(u) ≥ 0 of any curve in any dimension (1/length).
///
/// Fails where the curve cannot be evaluated and with [`Error::ZeroLength`] where C′(u) = 0.
/// For dual numbers note that κ = |…| has no derivative where κ = 0; use
/// [`signed_curvature`] in the plane.
///
/// ```
/// use camber_geom::queries::curvature;
/// # use camber_geom::{ParametricCurve, Result};
/// # use nalgebra::SVector;
/// # struct Circle3;
/// # impl ParametricCurve<f64, 2> for Circle3 {
/// #     fn domain(&self) -> (f64, f64) { (0.0, 6.0) }
/// #     fn derivatives_into(&self, u: f64, out: &mut [SVector<f64, 2>]) -> Result<()> {
/// #         for (k, o) in out.iter_mut().enumerate() {
/// #             let a = u + k as f64 * std::f64::consts::FRAC_PI_2;
/// #             *o = SVector::from([3.0 * a.cos(), 3.0 * a.sin()]);
/// #         }
/// #         Ok(())
/// #     }
/// # }
/// // `Circle3` is the circle of radius 3 at angle u.
/// assert!((curvature(&Circle3, 1.0)? - 1.0 / 3.0).abs() < 1e-14);
/// # Ok::<(), camber_geom::Error>(())
/// ```
pub fn curvature<T, const D: usize, C>(curve: &C, u: T) -> Result<T>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let [_, d1, d2] = curve.second_order(u)?;
    curvature_from_derivatives(&d1, &d2).ok_or_else(singular)
}

/// Signed curvature κ_s(u) = (C′ × C″)/|C′|³ of a planar curve: positive where it turns
/// counter-clockwise, negative clockwise (1/length).
///
/// Fails where the curve cannot be evaluated and with [`Error::ZeroLength`] where C′(u) = 0.
pub fn signed_curvature<T, C>(curve: &C, u: T) -> Result<T>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    let [_, d1, d2] = curve.second_order(u)?;
    signed_curvature_from_derivatives(&d1, &d2).ok_or_else(singular)
}

/// The curvature vector k(u) (length κ, towards the centre of curvature) of any curve.
///
/// Fails where the curve cannot be evaluated and with [`Error::ZeroLength`] where C′(u) = 0.
pub fn curvature_vector<T, const D: usize, C>(curve: &C, u: T) -> Result<SVector<T, D>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let [_, d1, d2] = curve.second_order(u)?;
    curvature_vector_from_derivatives(&d1, &d2).ok_or_else(singular)
}
