//! Arc length of any curve: globally adaptive Gauss–Legendre quadrature of the speed |C′(u)|
//! with an error estimate, the parameter at given arc lengths, and an arc-length
//! reparameterization whose error is measured — each under a work [`Budget`].
//!
//! The length of C over [u₀, u₁] is ∫ |C′(u)| du. On each polynomial (or rational) piece between
//! [`breakpoints`](ParametricCurve::breakpoints) the speed is smooth, so the 8-point
//! Gauss–Legendre rule converges fast. Every interval carries the rule on the whole (I₁) and on
//! its halves (I₂); |I₂ − I₁| estimates its error, and the interval with the largest estimate
//! is split until their sum is within the tolerance. Because the halved
//! rule is far more accurate than the whole one on smooth integrands, the sum bounds the true
//! error of the kept value in practice (it is an estimate, not a proof).
//!
//! **Tolerances f64 cannot reach.** A length Λ is known to a few ulps at best, so a tolerance
//! below [`floor`]`(Λ)` = 64·ε·Λ is raised to it: [`ArcLength::tolerance`] (and the table's and
//! map's `tolerance()`) report the tolerance honoured, so a caller can tell when it was
//! clamped. A curve with a control point at 10¹⁵ and the default tolerance 10⁻¹⁰ is measured to
//! about 10 length units of its 10¹⁵, in a few hundred evaluations.
//!
//! ```
//! use camber_geom::arc_length::arc_length;
//! use camber_geom::BezierCurve2;
//! use nalgebra::Point2;
//! // A straight cubic with uneven control points is still 5 long.
//! let line = BezierCurve2::try_new(vec![Point2::new(0.0_f64, 0.0), Point2::new(0.3, 0.4),
//!     Point2::new(2.4, 3.2), Point2::new(3.0, 4.0)])?;
//! let length = arc_length(&line, 1e-12)?;
//! assert!((length.length - 5.0).abs() < 1e-12 && length.error_estimate <= 1e-12);
//! # Ok::<(), camber_geom::Error>(())
//! ```

mod map;
mod quadrature;
mod table;

pub use map::{arc_length_map, arc_length_map_with, ArcLengthMap, ACCEPT, MAP_FLOOR_ULPS};
pub use quadrature::{floor, FLOOR_ULPS};
pub use table::ArcLengthTable;

use crate::budget::{default_limit, Budget};
use crate::curve::ParametricCurve;
use crate::errors::Result;
use crate::scalar::Scalar;
use quadrature::{check_tolerance, integrate};

/// The length of a curve (or of part of it) with its error estimate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArcLength<T> {
    /// The arc length, in the curve's length unit.
    pub length: T,
    /// The sum of the per-interval differences between the whole and the halved rule: an
    /// estimate of (in practice a bound on) |length − true length|.
    pub error_estimate: f64,
    /// How many speed evaluations were made.
    pub evaluations: usize,
    /// The tolerance honoured: the one asked for, or [`floor`] of the length when that was
    /// below it (a tolerance f64 cannot reach on this curve).
    pub tolerance: f64,
}

/// The arc length of the whole curve, to an absolute `tolerance` (length units, > 0), under the
/// default budget.
///
/// Errors: [`Error::NonPositiveTolerance`](crate::Error::NonPositiveTolerance) or
/// [`Error::NonFinite`](crate::Error::NonFinite) for a bad tolerance, and whatever the curve's
/// evaluation reports.
pub fn arc_length<T, const D: usize, C>(curve: &C, tolerance: f64) -> Result<ArcLength<T>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    arc_length_with(curve, tolerance, &Budget::default())
}

/// [`arc_length`] under `budget`: fails with
/// [`Error::BudgetExhausted`](crate::Error::BudgetExhausted) or
/// [`Error::Cancelled`](crate::Error::Cancelled), operation "arc length".
pub fn arc_length_with<T, const D: usize, C>(
    curve: &C,
    tolerance: f64,
    budget: &Budget,
) -> Result<ArcLength<T>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let (a, b) = curve.domain();
    arc_length_between_with(curve, a, b, tolerance, budget)
}

/// The arc length of the curve between parameters u₀ ≤ u₁ (both in the domain), to an
/// absolute `tolerance`, under the default budget.
///
/// ```
/// use camber_geom::arc_length::arc_length_between;
/// use camber_geom::NurbsCurve2;
/// use nalgebra::Point2;
/// // A quarter of the unit circle, in the rational quadratic form.
/// let circle = NurbsCurve2::try_circular_arc(Point2::origin(), 1.0, 0.0, std::f64::consts::TAU)?;
/// let quarter = arc_length_between(&circle, 0.0, 0.25, 1e-12)?;
/// assert!((quarter.length - std::f64::consts::FRAC_PI_2).abs() < 1e-11);
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// Errors: [`Error::InvalidInterval`](crate::Error::InvalidInterval) for u₁ < u₀,
/// [`Error::ParameterOutsideDomain`](crate::Error::ParameterOutsideDomain) for an end outside
/// the domain, and the errors of [`arc_length`].
pub fn arc_length_between<T, const D: usize, C>(
    curve: &C,
    u0: T,
    u1: T,
    tolerance: f64,
) -> Result<ArcLength<T>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    arc_length_between_with(curve, u0, u1, tolerance, &Budget::default())
}

/// [`arc_length_between`] under `budget` (operation "arc length").
pub fn arc_length_between_with<T, const D: usize, C>(
    curve: &C,
    u0: T,
    u1: T,
    tolerance: f64,
    budget: &Budget,
) -> Result<ArcLength<T>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    check_tolerance(tolerance, "arc length tolerance")?;
    let mut meter = budget.meter("arc length", default_limit(curve.breakpoints().len()));
    let q = integrate(curve, u0, u1, tolerance, &mut meter)?;
    Ok(ArcLength {
        length: q.length(),
        error_estimate: q.error,
        evaluations: usize::try_from(q.evaluations).unwrap_or(usize::MAX),
        tolerance: q.tolerance,
    })
}

/// The parameter u at which the arc length from the start of the domain equals `s`
/// (0 ≤ s ≤ total length, up to the tolerance), to an absolute length `tolerance`, under the
/// default budget. For many lengths of one curve use [`parameters_at_lengths`] (one
/// quadrature for all).
///
/// The adaptive quadrature gives a table of intervals with their lengths; inside the interval
/// holding s, safeguarded Newton on L(u) − s (L′ = |C′|, bisection when a step leaves the
/// interval) finds u. With dual numbers the final Newton step gives u the implicit derivative.
///
/// ```
/// use camber_geom::arc_length::parameter_at_length;
/// use camber_geom::BezierCurve2;
/// use nalgebra::Point2;
/// // x = 3t² − 2t³ on a straight line of length 1: L(t) = 3t² − 2t³.
/// let c = BezierCurve2::try_new(vec![Point2::new(0.0_f64, 0.0), Point2::new(0.0, 0.0),
///     Point2::new(1.0, 0.0), Point2::new(1.0, 0.0)])?;
/// let u = parameter_at_length(&c, 0.5, 1e-12)?;
/// assert!((u - 0.5).abs() < 1e-10);
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// Errors: [`Error::NonFinite`](crate::Error::NonFinite) for a non-finite s,
/// [`Error::LengthOutsideCurve`](crate::Error::LengthOutsideCurve) for s < 0 or s beyond the
/// length, and the errors of [`arc_length`].
pub fn parameter_at_length<T, const D: usize, C>(curve: &C, s: T, tolerance: f64) -> Result<T>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    parameter_at_length_with(curve, s, tolerance, &Budget::default())
}

/// [`parameter_at_length`] under `budget` (operations "arc length" for the quadrature and
/// "parameter at length" for the search).
pub fn parameter_at_length_with<T, const D: usize, C>(
    curve: &C,
    s: T,
    tolerance: f64,
    budget: &Budget,
) -> Result<T>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    if !crate::scalar::re(s).is_finite() {
        return Err(crate::Error::NonFinite {
            what: "arc length",
            index: 0,
            value: crate::scalar::re(s),
        });
    }
    ArcLengthTable::new(curve, tolerance, budget)?.parameter(curve, s, budget)
}

/// The parameters at every arc length in `lengths` (each as in [`parameter_at_length`]), from
/// one quadrature of the curve: the cost is one quadrature plus a short Newton search per
/// length, so a million lengths take about a second.
///
/// ```
/// use camber_geom::arc_length::parameters_at_lengths;
/// use camber_geom::budget::Budget;
/// use camber_geom::BezierCurve2;
/// use nalgebra::Point2;
/// let c = BezierCurve2::try_new(vec![Point2::new(0.0_f64, 0.0), Point2::new(0.0, 0.0),
///     Point2::new(1.0, 0.0), Point2::new(1.0, 0.0)])?;
/// let us = parameters_at_lengths(&c, &[0.0, 0.5, 1.0], 1e-12, &Budget::default())?;
/// assert!(us[0].abs() < 1e-15 && (us[1] - 0.5).abs() < 1e-10);
/// // At the end the speed vanishes (x′ = 6t(1 − t)), so L(u) − 1 ≈ −3(1 − u)² and u is
/// // determined only to the square root of the rounding of the length there.
/// assert!((us[2] - 1.0).abs() < 1e-7);
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// Errors: those of [`parameter_at_length`], for the first length that fails.
pub fn parameters_at_lengths<T, const D: usize, C>(
    curve: &C,
    lengths: &[T],
    tolerance: f64,
    budget: &Budget,
) -> Result<Vec<T>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    if let Some((index, &s)) = lengths
        .iter()
        .enumerate()
        .find(|(_, &s)| !crate::scalar::re(s).is_finite())
    {
        return Err(crate::Error::NonFinite {
            what: "arc length",
            index,
            value: crate::scalar::re(s),
        });
    }
    ArcLengthTable::new(curve, tolerance, budget)?.parameters(curve, lengths, budget)
}
