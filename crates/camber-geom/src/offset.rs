//! Offset curves of planar curves, approximated by B-splines to a tolerance, with the error
//! measured.
//!
//! The offset of C at signed distance d is O(u) = C(u) + d·n(u), with n = (−C′_y, C′_x)/|C′|
//! the unit normal to the left of the direction of travel (d > 0 offsets to the left). Except
//! for lines and circles O is not a (rational) polynomial, so it is approximated: O is sampled
//! at parameters spread evenly over every piece between breakpoints, the samples are fitted by
//! a cubic B-spline F to half the tolerance with the normalized curve parameter
//! s = (u − a)/(b − a) as the fitting parameter (see [`crate::fit`]), and the error
//! max |F(s) − O(u)| is measured at eight parameters between each pair of samples. Until it is
//! within the tolerance the sampling is doubled (at most eight times); the error reported is
//! the measured one either way.
//!
//! The offset is not trimmed: where |d| exceeds the radius of curvature it has cusps and loops,
//! and across a corner of C (a breakpoint where the tangent jumps) the exact offset has a gap
//! that the fit bridges; in both cases the measured error says how well the fit follows O.
//!
//! ```
//! use camber_geom::offset::offset;
//! use camber_geom::{NurbsCurve2, ParametricCurve};
//! use nalgebra::Point2;
//! // A counter-clockwise unit circle offset by −0.25 (to the right, outwards).
//! let circle = NurbsCurve2::try_circular_arc(Point2::origin(), 1.0, 0.0, std::f64::consts::TAU)?;
//! let o = offset(&circle, -0.25, 1e-6)?;
//! assert!(o.max_error <= 1e-6);
//! assert!((o.curve.point(0.3)?.coords.norm() - 1.25).abs() < 1e-6);
//! # Ok::<(), camber_geom::Error>(())
//! ```

use nalgebra::{Point2, Vector2};

use crate::bspline::BSplineCurve;
use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::fit::fit_to_tolerance_at;
use crate::scalar::{cst, from_usize, re, Scalar};

/// An offset curve and how far it is from the exact offset.
#[derive(Debug, Clone, PartialEq)]
pub struct OffsetCurve<T: Scalar> {
    /// The approximating cubic B-spline, on [0, 1]: F(s) approximates O(a + (b − a)s).
    pub curve: BSplineCurve<T, 2>,
    /// The largest |F(s) − O(u)| measured (length units).
    pub max_error: f64,
}

/// Samples per piece to start with.
const START_SAMPLES: usize = 8;
/// Doublings of the sampling before giving up on the tolerance.
const MAX_DOUBLINGS: usize = 8;
/// Measurement points between consecutive samples.
const CHECKS_BETWEEN: usize = 8;

/// The exact offset point at u.
fn offset_point<T, C>(curve: &C, distance: T, u: T) -> Result<Point2<T>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    let (p, d) = curve.point_and_derivative(u)?;
    let speed = d.norm();
    if re(speed) <= 0.0 {
        return Err(Error::ZeroLength {
            what: "tangent of the curve to offset",
        });
    }
    Ok(p + Vector2::new(-d.y, d.x) * (distance / speed))
}

/// The offset of the planar `curve` at signed `distance` (length units; positive to the left
/// of the direction of travel), approximated by a cubic B-spline within `tolerance`
/// (length units, > 0) where the sampling allows.
///
/// Errors: [`Error::NonFinite`] for a non-finite distance or tolerance,
/// [`Error::NonPositiveTolerance`], [`Error::ZeroLength`] where the curve has no tangent, and
/// the fitting errors.
pub fn offset<T, C>(curve: &C, distance: T, tolerance: f64) -> Result<OffsetCurve<T>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    if !re(distance).is_finite() {
        return Err(Error::NonFinite {
            what: "offset distance",
            index: 0,
            value: re(distance),
        });
    }
    if !tolerance.is_finite() {
        return Err(Error::NonFinite {
            what: "offset tolerance",
            index: 0,
            value: tolerance,
        });
    }
    if tolerance <= 0.0 {
        return Err(Error::NonPositiveTolerance { value: tolerance });
    }
    let (a, b) = curve.domain();
    let mut breaks: Vec<T> = vec![a];
    for u in curve.breakpoints() {
        if u > a && u < b && breaks.last().is_some_and(|&l| u > l) {
            breaks.push(u);
        }
    }
    breaks.push(b);
    let normalize = |u: T| (u - a) / (b - a);
    let mut per_piece = START_SAMPLES;
    let mut best: Option<OffsetCurve<T>> = None;
    for _ in 0..=MAX_DOUBLINGS {
        let mut params = Vec::new();
        for w in breaks.windows(2) {
            for j in 0..per_piece {
                params.push(w[0] + (w[1] - w[0]) * from_usize::<T>(j) / from_usize::<T>(per_piece));
            }
        }
        params.push(b);
        let points = params
            .iter()
            .map(|&u| offset_point(curve, distance, u))
            .collect::<Result<Vec<_>>>()?;
        let mut fit_params: Vec<T> = params.iter().map(|&u| normalize(u)).collect();
        fit_params[0] = T::zero();
        if let Some(last) = fit_params.last_mut() {
            *last = T::one();
        }
        let fit = fit_to_tolerance_at(&points, &fit_params, 3, tolerance * 0.5)?;
        let mut worst = fit.max_error;
        for w in params.windows(2) {
            for k in 1..CHECKS_BETWEEN {
                let u = w[0] + (w[1] - w[0]) * cst::<T>(k as f64 / CHECKS_BETWEEN as f64);
                let exact = offset_point(curve, distance, u)?;
                let approx = fit.curve.point(normalize(u).max(T::zero()).min(T::one()))?;
                worst = worst.max(re((approx - exact).norm()));
            }
        }
        let result = OffsetCurve {
            curve: fit.curve,
            max_error: worst,
        };
        if worst <= tolerance {
            return Ok(result);
        }
        if best.as_ref().is_none_or(|b| worst < b.max_error) {
            best = Some(result);
        }
        per_piece *= 2;
    }
    best.ok_or(Error::ZeroCount {
        what: "offset samples",
    })
}
