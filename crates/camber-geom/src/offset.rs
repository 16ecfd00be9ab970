//! Offset curves of planar curves, approximated by B-splines to a tolerance, with the error
//! measured.
//!
//! The offset of C at signed distance d is O(u) = C(u) + d·n(u), with n = (−C′_y, C′_x)/|C′|
//! the unit normal to the left of the direction of travel (d > 0 offsets to the left). Except
//! for lines and circles O is not a (rational) polynomial, so it is approximated by a cubic
//! B-spline F(s), s = (u − a)/(b − a).
//!
//! **Knots where O is less smooth.** O′ = C′·(1 − dκ) (κ the signed curvature), so O is as
//! smooth as C′ and κ: where C′ or κ jumps — at every knot of a quadratic B-spline, at a G1
//! joint that is not C1 — O′ jumps, and where only C‴ jumps (a simple knot of a cubic) O″ does.
//! A smooth cubic follows such a jump only with ever more control points (its error falls like
//! the spacing, or its square, instead of its fourth power: a quadratic B-spline's offset at
//! 10⁻⁶ used to end at 1.7·10⁻⁴ with 6,145 control points). So every breakpoint of C becomes a
//! knot of F whose multiplicity matches O there: 3 (C0) where O′ or the tangent direction of C
//! jumps, 2 (C1) where O″ jumps, 1 otherwise — the two sides compared just before and at the
//! breakpoint, a jump being a relative difference above 10⁻⁶. At a corner of C (a tangent jump)
//! the exact offset has a gap, which the fit bridges across its triple knot.
//!
//! **Fitting.** O is sampled at parameters spread evenly over every piece, the samples are fitted
//! by least squares on those knots to half the tolerance (spans whose data are too far are split
//! further, see [`crate::fit`]), and the error max |F(s) − O(u)| is measured at seven parameters
//! between each pair of samples. Until it is within the tolerance the sampling of every piece
//! whose measured error misses it is doubled (at most eight times), the other pieces keep
//! theirs, so the work follows where the offset is hard, not the size of the curve; the error
//! reported is the measured one either way.
//!
//! The offset is not trimmed: where |d| exceeds the radius of curvature it has cusps and loops,
//! and across a corner of C the fit bridges the gap; in both cases the measured error says how
//! well the fit follows O.
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
use crate::budget::{default_limit, Budget};
use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::fit::fit_at_parameters;
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
/// A relative difference above this between the two sides of a breakpoint is a jump.
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

/// Whether two vectors differ by more than [`JUMP`] of the larger.
fn jumps(x: &Vector2<f64>, y: &Vector2<f64>) -> bool {
    (x - y).norm() > JUMP * x.norm().max(y.norm())
}

/// The multiplicity of the fit's knot at the interior breakpoint `u` (the piece on its left
/// starting at `before`): 3 where the tangent direction of C or O′ = C′·(1 − dκ) jumps, 2 where
/// only O″ can (C‴ jumps), 1 otherwise.
fn multiplicity<T, C>(curve: &C, distance: f64, before: T, u: T) -> Result<usize>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    let left_u = u - (u - before) * cst::<T>(LEFT_LIMIT);
    let mut sides = [[Vector2::<f64>::zeros(); 4]; 2];
    for (side, at) in sides.iter_mut().zip([left_u, u]) {
        let mut d = [nalgebra::SVector::<T, 2>::zeros(); 4];
        curve.derivatives_into(at, &mut d)?;
        for (v, w) in side.iter_mut().zip(&d) {
            *v = Vector2::new(re(w.x), re(w.y));
        }
    }
    let ([_, l1, l2, l3], [_, r1, r2, r3]) = (sides[0], sides[1]);
    let (nl, nr) = (l1.norm(), r1.norm());
    if nl <= 0.0 || nr <= 0.0 {
        return Ok(3);
    }
    // O′ = C′·(1 − dκ), κ = (x′y″ − y′x″)/|C′|³.
    let o1 = |c1: &Vector2<f64>, c2: &Vector2<f64>| {
        let kappa = (c1.x * c2.y - c1.y * c2.x) / c1.norm().powi(3);
        c1 * (1.0 - distance * kappa)
    };
    let direction = jumps(&(l1 / nl), &(r1 / nr));
    if direction || jumps(&o1(&l1, &l2), &o1(&r1, &r2)) {
        return Ok(3);
    }
    if jumps(&l2, &r2) || jumps(&l3, &r3) {
        return Ok(2);
    }
    Ok(1)
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
    let normalize = |u: T| (u - a) / (b - a);
    // The fit's knots at the breakpoints, each as often as O's continuity there asks.
    let mut knots: Vec<T> = Vec::new();
    for k in 1..breaks.len() - 1 {
        meter.charge(8)?;
        let times = multiplicity(curve, re(distance), breaks[k - 1], breaks[k])?;
        knots.extend(std::iter::repeat_n(normalize(breaks[k]), times));
    }
    // Samples per piece: each piece whose measured error misses the tolerance is sampled twice
    // as densely in the next round, the others keep theirs (a global doubling made the work
    // grow faster than the curve: one erring piece among 10⁴ doubled all of them).
    let pieces = breaks.len() - 1;
    let mut per_piece = vec![START_SAMPLES; pieces];
    let mut best: Option<OffsetCurve<T>> = None;
    for _ in 0..=MAX_DOUBLINGS {
        // Charged before anything is allocated for the samples.
        let count = per_piece
            .iter()
            .fold(1usize, |total, &n| total.saturating_add(n));
        meter.charge(u64::try_from(count).unwrap_or(u64::MAX))?;
        let mut params = Vec::with_capacity(count);
        let mut piece_of = Vec::with_capacity(count);
        for (piece, w) in breaks.windows(2).enumerate() {
            let n = per_piece[piece];
            for j in 0..n {
                params.push(w[0] + (w[1] - w[0]) * from_usize::<T>(j) / from_usize::<T>(n));
                piece_of.push(piece);
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
        let fit = fit_at_parameters(&points, &fit_params, 3, tolerance * 0.5, &knots, &mut meter)?;
        let mut worst = fit.max_error;
        let mut missed = vec![fit.max_error > tolerance; pieces];
        for (i, w) in params.windows(2).enumerate() {
            meter.charge(2 * (CHECKS_BETWEEN as u64 - 1))?;
            for k in 1..CHECKS_BETWEEN {
                let u = w[0] + (w[1] - w[0]) * cst::<T>(k as f64 / CHECKS_BETWEEN as f64);
                let exact = offset_point(curve, distance, u)?;
                let approx = fit.curve.point(normalize(u).max(T::zero()).min(T::one()))?;
                let e = re((approx - exact).norm());
                worst = worst.max(e);
                if e > tolerance {
                    missed[piece_of[i]] = true;
                }
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
        for (n, &miss) in per_piece.iter_mut().zip(&missed) {
            if miss {
                *n *= 2;
            }
        }
    }
    best.ok_or(Error::ZeroCount {
        what: "offset samples",
    })
}
