//! The arc-length reparameterization s ↦ u(s) of a curve, as a piecewise cubic Hermite
//! interpolant of the exact map whose error is measured and kept within the tolerance asked.
//!
//! The nodes are the quadrature's interval ends (u_k, s_k = L(u_k)); the slopes are
//! du/ds = 1/|C′(u)|, taken just inside each interval so that a node on a corner has one slope
//! per side. The error of the map at s is how far along the curve its point lies from the true
//! one: e(s) = |L(u_k, u(s)) − (s − s_k)|, L(u_k, u) by one Gauss–Legendre rule on the
//! quadrature's interval. For a cubic Hermite interpolant e ≈ t²(1 − t)²·g(t) on the interval
//! (t its fraction), largest near the middle only when g is nearly constant; so e is measured
//! at the seven points t = j/8, whose largest is within a few percent of the true maximum
//! whenever g varies slowly across the interval (about 1 % when g varies linearly by its own
//! size). An interval is accepted when its measured maximum is within [`ACCEPT`] of the
//! tolerance, and halved otherwise. The reported `max_error` is the largest measured value
//! plus the quadrature's error estimate (the drift of the node lengths).

use super::quadrature::{check_tolerance, gauss_legendre, integrate, rule, speed, GAUSS_POINTS};
use crate::budget::{default_limit, Budget, Meter};
use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::scalar::{cst, re, Scalar};

/// An interval is accepted when its measured error is within this fraction of the tolerance:
/// the margin covers the error between the measurement points.
pub const ACCEPT: f64 = 0.8;

/// Measurement points per interval: t = j / `MEASURE_STEPS`, j = 1 … `MEASURE_STEPS` − 1.
const MEASURE_STEPS: usize = 8;

/// The smallest map tolerance honoured, in ulps of the length (scaled by the parameter's
/// resolution: a domain far from 0 resolves u more coarsely).
pub const MAP_FLOOR_ULPS: f64 = 1024.0;

/// Rounds of halving at most; each halves every interval still too coarse.
const MAX_ROUNDS: usize = 64;

/// How far inside an interval its end speed is taken, as a fraction of its length.
const LEFT_LIMIT: f64 = 1e-10;

/// An approximate arc-length parameterization u(s) of a curve: a piecewise cubic Hermite
/// interpolant of the exact map through the adaptive quadrature's nodes, with slopes
/// du/ds = 1/|C′(u)|, its error measured at seven points of every interval.
#[derive(Debug, Clone, PartialEq)]
pub struct ArcLengthMap<T> {
    /// Node parameters u_k, increasing.
    parameters: Vec<T>,
    /// Arc lengths s_k = L(u_k), increasing.
    lengths: Vec<T>,
    /// du/ds at the start and at the end of every interval (they differ at a breakpoint).
    slopes: Vec<(T, T)>,
    /// The largest |L(u(s)) − s| measured plus the quadrature's estimate, in length units.
    max_error: f64,
    /// The tolerance honoured (the one asked for, or the f64 floor).
    tolerance: f64,
}

impl<T: Scalar> ArcLengthMap<T> {
    /// The total length of the curve.
    pub fn length(&self) -> T {
        self.lengths.last().copied().unwrap_or_else(T::zero)
    }

    /// The error of the map: the largest |L(u(s)) − s| (length units, how far along the curve
    /// the approximate point lies from the true one) measured at seven points of every
    /// interval, plus the quadrature's error estimate.
    pub fn max_error(&self) -> f64 {
        self.max_error
    }

    /// The tolerance the map was made to: the one asked for, or, when that was below what
    /// f64 can resolve on this curve, the floor [`MAP_FLOOR_ULPS`]·ε·L·max(1, |u|/(b − a)).
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// The number of interpolation nodes.
    pub fn node_count(&self) -> usize {
        self.parameters.len()
    }

    /// The approximate parameter u(s) for 0 ≤ s ≤ length (a finite s outside is clamped to
    /// that range).
    ///
    /// Errors: [`Error::NonFinite`] for a NaN or infinite s.
    pub fn parameter(&self, s: T) -> Result<T> {
        if !re(s).is_finite() {
            return Err(Error::NonFinite {
                what: "arc length",
                index: 0,
                value: re(s),
            });
        }
        let n = self.lengths.len();
        if n < 2 {
            return Ok(self.parameters.first().copied().unwrap_or_else(T::zero));
        }
        let s = s.max(self.lengths[0]).min(self.lengths[n - 1]);
        let k = self.lengths[1..].partition_point(|&c| c < s).min(n - 2);
        Ok(hermite(
            (self.lengths[k], self.lengths[k + 1]),
            (self.parameters[k], self.parameters[k + 1]),
            self.slopes[k],
            s,
        ))
    }
}

/// The cubic Hermite interpolant on [s0, s1] with values u0, u1 and slopes m0, m1, at s.
fn hermite<T: Scalar>((s0, s1): (T, T), (u0, u1): (T, T), (m0, m1): (T, T), s: T) -> T {
    let h = s1 - s0;
    if re(h) <= 0.0 {
        return u0;
    }
    let t = (s - s0) / h;
    let t2 = t * t;
    let t3 = t2 * t;
    let two = cst::<T>(2.0);
    let three = cst::<T>(3.0);
    let h00 = two * t3 - three * t2 + T::one();
    let h10 = t3 - two * t2 + t;
    let h01 = three * t2 - two * t3;
    let h11 = t3 - t2;
    h00 * u0 + h10 * h * m0 + h01 * u1 + h11 * h * m1
}

/// The arc-length parameterization of `curve` within `tolerance` (length units) under the
/// default budget: see [`arc_length_map_with`].
///
/// ```
/// use camber_geom::arc_length::arc_length_map;
/// use camber_geom::{BezierCurve2, ParametricCurve};
/// use nalgebra::Point2;
/// let c = BezierCurve2::try_new(vec![Point2::new(0.0_f64, 0.0), Point2::new(1.0, 2.0),
///     Point2::new(3.0, 2.0), Point2::new(4.0, 0.0)])?;
/// let map = arc_length_map(&c, 1e-8)?;
/// assert!(map.max_error() <= 1e-8);
/// let half = map.parameter(map.length() / 2.0)?;
/// // By symmetry the middle of the arc is at t = 1/2.
/// assert!((half - 0.5).abs() < 1e-7);
/// # Ok::<(), camber_geom::Error>(())
/// ```
pub fn arc_length_map<T, const D: usize, C>(curve: &C, tolerance: f64) -> Result<ArcLengthMap<T>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    arc_length_map_with(curve, tolerance, &Budget::default())
}

/// The arc-length parameterization of `curve`: the map s ↦ u(s) with C(u(s)) at arc length s,
/// approximated so that its error (measured, see the module documentation) is within
/// `tolerance` (length units, > 0). A tolerance below what f64 resolves on this curve is
/// raised to that floor, which [`ArcLengthMap::tolerance`] reports.
///
/// Errors: [`Error::NonPositiveTolerance`] or [`Error::NonFinite`] for a bad tolerance,
/// [`Error::BudgetExhausted`] / [`Error::Cancelled`] ("arc length" for the quadrature,
/// "arc-length map" for the refinement), and the curve's evaluation errors.
pub fn arc_length_map_with<T, const D: usize, C>(
    curve: &C,
    tolerance: f64,
    budget: &Budget,
) -> Result<ArcLengthMap<T>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    check_tolerance(tolerance, "arc-length map tolerance")?;
    let (a, b) = curve.domain();
    let limit = default_limit(curve.breakpoints().len());
    // Quadrature well below the map's tolerance, so that the node lengths do not drift.
    let q = {
        let mut meter = budget.meter("arc length", limit);
        integrate(curve, a, b, tolerance * 1e-3, &mut meter)?
    };
    let total = re(q.length());
    let resolution = (re(a).abs().max(re(b).abs()) / re(b - a)).max(1.0);
    let tolerance = tolerance.max(MAP_FLOOR_ULPS * f64::EPSILON * total * resolution);
    let mut meter = budget.meter("arc-length map", limit);
    let nodes = gauss_legendre();
    let mut parameters = Vec::with_capacity(q.intervals.len() + 1);
    parameters.push(a);
    parameters.extend(q.intervals.iter().map(|i| i.end));
    let mut lengths = Vec::with_capacity(parameters.len());
    lengths.push(T::zero());
    let (mut sum, mut carry) = (T::zero(), T::zero());
    for i in &q.intervals {
        let y = i.length - carry;
        let t = sum + y;
        carry = (t - sum) - y;
        sum = t;
        lengths.push(sum);
    }
    // Slopes and measured errors per interval; halving an interval measures only its halves
    // (an interval's slopes and error depend on nothing outside it).
    let mut slopes = Vec::with_capacity(parameters.len() - 1);
    let mut errors = Vec::with_capacity(parameters.len() - 1);
    for k in 0..parameters.len() - 1 {
        let (u, s) = (
            (parameters[k], parameters[k + 1]),
            (lengths[k], lengths[k + 1]),
        );
        let slope = interval_slopes(curve, u, s, &mut meter)?;
        errors.push(measure(curve, &nodes, u, s, slope, &mut meter)?);
        slopes.push(slope);
    }
    for _ in 0..MAX_ROUNDS {
        let splittable = |k: usize| {
            let mid = (parameters[k] + parameters[k + 1]) * cst::<T>(0.5);
            parameters[k] < mid && mid < parameters[k + 1]
        };
        let bad: Vec<usize> = (0..errors.len())
            .filter(|&k| errors[k] > ACCEPT * tolerance && splittable(k))
            .collect();
        if bad.is_empty() {
            break;
        }
        // Halve every interval that is too coarse, rebuilding the lists in one pass.
        let grown = parameters.len() + bad.len();
        let mut new_parameters = Vec::with_capacity(grown);
        let mut new_lengths = Vec::with_capacity(grown);
        let mut new_slopes = Vec::with_capacity(grown - 1);
        let mut new_errors = Vec::with_capacity(grown - 1);
        let mut next_bad = bad.iter().peekable();
        for k in 0..parameters.len() {
            new_parameters.push(parameters[k]);
            new_lengths.push(lengths[k]);
            if k + 1 == parameters.len() {
                break;
            }
            if next_bad.peek() == Some(&&k) {
                next_bad.next();
                let (u0, u1) = (parameters[k], parameters[k + 1]);
                let mid = (u0 + u1) * cst::<T>(0.5);
                let s_mid = lengths[k] + rule(curve, &nodes, u0, mid, &mut meter)?;
                new_parameters.push(mid);
                new_lengths.push(s_mid);
                for (u, s) in [
                    ((u0, mid), (lengths[k], s_mid)),
                    ((mid, u1), (s_mid, lengths[k + 1])),
                ] {
                    let slope = interval_slopes(curve, u, s, &mut meter)?;
                    new_errors.push(measure(curve, &nodes, u, s, slope, &mut meter)?);
                    new_slopes.push(slope);
                }
            } else {
                new_slopes.push(slopes[k]);
                new_errors.push(errors[k]);
            }
        }
        parameters = new_parameters;
        lengths = new_lengths;
        slopes = new_slopes;
        errors = new_errors;
    }
    let worst = errors.iter().copied().fold(0.0, f64::max);
    Ok(ArcLengthMap {
        parameters,
        lengths,
        slopes,
        max_error: worst + q.error,
        tolerance,
    })
}

/// The largest e(s) = |L(u₀, u(s)) − (s − s₀)| at the measurement points of the interval
/// [u₀, u₁] (lengths [s₀, s₁], end slopes `slope`).
fn measure<T, const D: usize, C>(
    curve: &C,
    nodes: &[(f64, f64); GAUSS_POINTS],
    (u0, u1): (T, T),
    (s0, s1): (T, T),
    slope: (T, T),
    meter: &mut Meter<'_>,
) -> Result<f64>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let mut worst = 0.0_f64;
    for j in 1..MEASURE_STEPS {
        #[allow(clippy::cast_precision_loss)] // j < 8
        let t = cst::<T>(j as f64 / MEASURE_STEPS as f64);
        let s = s0 + (s1 - s0) * t;
        let u = hermite((s0, s1), (u0, u1), slope, s);
        let along = if u >= u0 {
            rule(curve, nodes, u0, u, meter)?
        } else {
            -rule(curve, nodes, u, u0, meter)?
        };
        worst = worst.max(re(along - (s - s0)).abs());
    }
    Ok(worst)
}

/// du/ds = 1/|C′(u)| at both ends of the interval [u₀, u₁] (lengths [s₀, s₁]), the end speed
/// taken just inside it (a node on a breakpoint has one speed on each side). Where the speed
/// vanishes (a cusp or a stationary parameterization) the interval's secant slope stands in.
fn interval_slopes<T, const D: usize, C>(
    curve: &C,
    (u0, u1): (T, T),
    (s0, s1): (T, T),
    meter: &mut Meter<'_>,
) -> Result<(T, T)>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let ds = s1 - s0;
    let secant = if re(ds) > 0.0 {
        (u1 - u0) / ds
    } else {
        T::zero()
    };
    let inside = (u1 - u0) * cst::<T>(LEFT_LIMIT);
    let mut pair = [T::zero(); 2];
    meter.charge(2)?;
    for (slot, u) in pair.iter_mut().zip([u0, u1 - inside]) {
        let v = speed(curve, u)?;
        // A speed far below the secant's would give a huge, useless slope.
        *slot = if re(v) > 0.0 && re(T::one() / v) < 1e3 * re(secant).max(1e-300) {
            T::one() / v
        } else {
            secant
        };
    }
    Ok((pair[0], pair[1]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hermite_reproduces_cubics() {
        // u(s) = s³ on [1, 2]: values 1, 8, slopes 3, 12.
        let v: f64 = hermite((1.0, 2.0), (1.0, 8.0), (3.0, 12.0), 1.5);
        assert!((v - 3.375).abs() < 1e-14);
    }
}
