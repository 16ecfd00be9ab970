//! Offset curves of planar curves, approximated by B-splines to a tolerance, with the error
//! measured.
//!
//! The offset of C at signed distance d is O(u) = C(u) + d·n(u), with n = (−C′_y, C′_x)/|C′|
//! the unit normal to the left of the direction of travel (d > 0 offsets to the left). Except
//! for lines and circles O is not a (rational) polynomial, so it is approximated.
//!
//! **Sections.** O′ = C′·(1 − dκ) (κ the signed curvature): wherever C′ or κ jumps — at every
//! knot of a quadratic B-spline, at a G1 joint that is not C1 — O′ jumps too, and a smooth cubic
//! fit can only follow that with ever more control points (the error falls like the spacing, not
//! its fourth power). So the curve is cut at those breakpoints into *sections* (a breakpoint is
//! a cut when |O′| or its direction differs on the two sides by more than 10⁻⁶ relative,
//! the left side read just before it), each section is approximated on its own, and the
//! approximations are joined at triple knots (C0 in the parameter, G1 in shape where C is G1).
//! Corners of C (tangent jumps) are not cut: the exact offset has a gap there, which the fit
//! bridges.
//!
//! **Fitting a section.** O is sampled at parameters spread evenly over every piece of the
//! section, the samples are fitted by a cubic B-spline F to half the tolerance with the
//! section's normalized parameter (see [`crate::fit`]), and the error max |F(s) − O(u)| is
//! measured at seven parameters between each pair of samples. Until it is within the tolerance
//! the section's sampling is doubled (at most eight times); the error reported is the measured
//! one either way, the largest over the sections.
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
use crate::budget::{default_limit, Budget, Meter};
use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::fit::fit_to_tolerance_at;
use crate::knots::KnotVector;
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
/// A relative jump of O′ above this at a breakpoint cuts the curve there.
const JUMP: f64 = 1e-6;
/// How far before a breakpoint its left side is read, as a fraction of the piece on its left.
const LEFT_LIMIT: f64 = 1e-9;

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

/// O′ = C′·(1 − dκ) at u, in f64 (to compare the two sides of a breakpoint).
fn offset_derivative<T, C>(curve: &C, distance: f64, u: T) -> Result<Vector2<f64>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    let [_, d1, d2] = curve.second_order(u)?;
    let (x1, y1, x2, y2) = (re(d1.x), re(d1.y), re(d2.x), re(d2.y));
    let speed2 = x1 * x1 + y1 * y1;
    if speed2 <= 0.0 {
        return Ok(Vector2::zeros());
    }
    let kappa = (x1 * y2 - y1 * x2) / (speed2 * speed2.sqrt());
    Ok(Vector2::new(x1, y1) * (1.0 - distance * kappa))
}

/// Whether the offset is cut at the interior breakpoint `u` (piece on its left starting at
/// `before`): the tangent direction of C is continuous there (else it is a corner, bridged),
/// and O′ jumps.
fn is_cut<T, C>(curve: &C, distance: f64, before: T, u: T) -> Result<bool>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    let left_u = u - (u - before) * cst::<T>(LEFT_LIMIT);
    let (tl, tr) = (curve.derivative(left_u)?, curve.derivative(u)?);
    let (tl, tr) = (
        Vector2::new(re(tl.x), re(tl.y)),
        Vector2::new(re(tr.x), re(tr.y)),
    );
    let (nl, nr) = (tl.norm(), tr.norm());
    if nl <= 0.0 || nr <= 0.0 {
        return Ok(false);
    }
    let sine = (tl.x * tr.y - tl.y * tr.x) / (nl * nr);
    if sine.abs() > 1e-7 || tl.dot(&tr) <= 0.0 {
        return Ok(false);
    }
    let (ol, or) = (
        offset_derivative(curve, distance, left_u)?,
        offset_derivative(curve, distance, u)?,
    );
    Ok((ol - or).norm() > JUMP * ol.norm().max(or.norm()))
}

/// The offset of the planar `curve` at signed `distance` (length units; positive to the left
/// of the direction of travel), approximated by a cubic B-spline within `tolerance`
/// (length units, > 0) where the sampling allows, under the default budget.
///
/// Errors: [`Error::NonFinite`] for a non-finite distance or tolerance,
/// [`Error::NonPositiveTolerance`], [`Error::ZeroLength`] where the curve has no tangent, and
/// the fitting errors.
pub fn offset<T, C>(curve: &C, distance: T, tolerance: f64) -> Result<OffsetCurve<T>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    offset_with(curve, distance, tolerance, &Budget::default())
}

/// [`offset`] under `budget` (one unit per offset point evaluated and per data point of every
/// fitting pass): fails with [`Error::BudgetExhausted`] or [`Error::Cancelled`], operation
/// "offset".
pub fn offset_with<T, C>(
    curve: &C,
    distance: T,
    tolerance: f64,
    budget: &Budget,
) -> Result<OffsetCurve<T>>
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
    let mut meter = budget.meter("offset", default_limit(breaks.len()));
    meter.charge(0)?;
    // Sections: runs of pieces between cuts.
    let mut sections: Vec<&[T]> = Vec::new();
    let mut first = 0;
    for k in 1..breaks.len() - 1 {
        meter.charge(4)?;
        if is_cut(curve, re(distance), breaks[k - 1], breaks[k])? {
            sections.push(&breaks[first..=k]);
            first = k;
        }
    }
    sections.push(&breaks[first..]);
    let mut knots: Vec<T> = Vec::new();
    let mut points: Vec<Point2<T>> = Vec::new();
    let mut max_error = 0.0_f64;
    for section in sections {
        let piece = offset_section(curve, distance, tolerance, section, &mut meter)?;
        max_error = max_error.max(piece.max_error);
        // The section's curve on [0, 1] mapped onto its share of [0, 1].
        let (c, d) = (section[0], section[section.len() - 1]);
        let (lo, hi) = ((c - a) / (b - a), (d - a) / (b - a));
        let map = |k: T| lo + (hi - lo) * k;
        let own = piece.curve.knots().as_slice();
        if knots.is_empty() {
            knots.extend(own[..own.len() - 4].iter().map(|&k| map(k)));
            points.extend_from_slice(piece.curve.control_points());
        } else {
            // The joint: a triple knot (C0), the shared end point kept once.
            knots.extend(own[4..own.len() - 4].iter().map(|&k| map(k)));
            points.extend_from_slice(&piece.curve.control_points()[1..]);
        }
        // The section's end knots (four, or three at a joint) follow the next section's
        // start: push the end value three times now, once more at the very end.
        knots.extend(std::iter::repeat_n(map(T::one()), 3));
    }
    knots.push(T::one());
    if let Some(first) = knots.first_mut() {
        *first = T::zero();
    }
    let curve = BSplineCurve::try_new(3, KnotVector::new_unchecked(knots), points)?;
    Ok(OffsetCurve { curve, max_error })
}

/// The offset of one section (its breakpoints `breaks`, at least two) as a cubic B-spline on
/// [0, 1] in the section's normalized parameter, with the error measured.
fn offset_section<T, C>(
    curve: &C,
    distance: T,
    tolerance: f64,
    breaks: &[T],
    meter: &mut Meter<'_>,
) -> Result<OffsetCurve<T>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    let (a, b) = (breaks[0], breaks[breaks.len() - 1]);
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
        meter.charge(u64::try_from(params.len()).unwrap_or(u64::MAX))?;
        let points = params
            .iter()
            .map(|&u| offset_point(curve, distance, u))
            .collect::<Result<Vec<_>>>()?;
        let mut fit_params: Vec<T> = params.iter().map(|&u| normalize(u)).collect();
        fit_params[0] = T::zero();
        if let Some(last) = fit_params.last_mut() {
            *last = T::one();
        }
        let fit = fit_to_tolerance_at(&points, &fit_params, 3, tolerance * 0.5, meter)?;
        let mut worst = fit.max_error;
        for w in params.windows(2) {
            meter.charge(2 * (CHECKS_BETWEEN as u64 - 1))?;
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
