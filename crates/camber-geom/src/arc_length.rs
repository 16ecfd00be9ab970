//! Arc length of any curve: adaptive Gauss–Legendre quadrature of the speed |C′(u)| with an
//! error estimate, the parameter at a given arc length, and an approximate arc-length
//! reparameterization whose error is measured.
//!
//! The length of C over [u₀, u₁] is ∫ |C′(u)| du. On each polynomial (or rational) piece between
//! [`breakpoints`](ParametricCurve::breakpoints) the speed is smooth, so an n-point
//! Gauss–Legendre rule converges fast. An interval is accepted when the rule on the whole
//! interval (I₁) and the rule on its two halves (I₂) agree within the interval's share of the
//! tolerance; I₂ is kept and |I₂ − I₁| is added to the reported error estimate. Because the
//! halved rule is far more accurate than the whole one on smooth integrands, this sum bounds the
//! true error of the kept value in practice (it is an estimate, not a proof).
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

use crate::curve::{check_parameter, ParametricCurve};
use crate::errors::{Error, Result};
use crate::scalar::{cst, re, Scalar};

/// Points of the Gauss–Legendre rule used on every interval.
const GAUSS_POINTS: usize = 8;
/// Deepest bisection of one piece; an interval at this depth is accepted with its estimate.
const MAX_DEPTH: usize = 40;

/// The nodes x_k ∈ (−1, 1) and weights w_k of the `GAUSS_POINTS`-point Gauss–Legendre rule,
/// found as the roots of the Legendre polynomial P_n by Newton's method from Chebyshev-like
/// starts (exact for polynomials up to degree 2n − 1).
fn gauss_legendre() -> [(f64, f64); GAUSS_POINTS] {
    let n = GAUSS_POINTS;
    let mut rule = [(0.0, 0.0); GAUSS_POINTS];
    #[allow(clippy::cast_precision_loss)] // n ≤ 8
    let nf = n as f64;
    for (k, slot) in rule.iter_mut().enumerate() {
        #[allow(clippy::cast_precision_loss)] // k < 8
        let kf = k as f64;
        let mut x = (std::f64::consts::PI * (kf + 0.75) / (nf + 0.5)).cos();
        let mut derivative = 1.0;
        for _ in 0..100 {
            // P_n(x) and P_n′(x) by the three-term recurrence.
            let (mut p0, mut p1) = (1.0, x);
            for j in 2..=n {
                #[allow(clippy::cast_precision_loss)] // j ≤ 8
                let jf = j as f64;
                let p2 = ((2.0 * jf - 1.0) * x * p1 - (jf - 1.0) * p0) / jf;
                p0 = p1;
                p1 = p2;
            }
            derivative = nf * (x * p1 - p0) / (x * x - 1.0);
            let step = p1 / derivative;
            x -= step;
            if step.abs() < 1e-16 {
                break;
            }
        }
        *slot = (x, 2.0 / ((1.0 - x * x) * derivative * derivative));
    }
    rule
}

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
}

/// One accepted interval of the adaptive quadrature: [start, end] and its length.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Interval<T> {
    start: T,
    end: T,
    length: T,
}

/// The speed |C′(u)|.
fn speed<T, const D: usize, C>(curve: &C, u: T) -> Result<T>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    Ok(curve.derivative(u)?.norm())
}

/// Gauss–Legendre on [a, b].
fn rule<T, const D: usize, C>(
    curve: &C,
    nodes: &[(f64, f64); GAUSS_POINTS],
    a: T,
    b: T,
    evaluations: &mut usize,
) -> Result<T>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let half = (b - a) * cst::<T>(0.5);
    let mid = (a + b) * cst::<T>(0.5);
    let mut sum = T::zero();
    for &(x, w) in nodes {
        sum += speed(curve, mid + half * cst::<T>(x))? * cst::<T>(w);
        *evaluations += 1;
    }
    Ok(sum * half)
}

/// Checks that a tolerance is finite and positive.
fn check_tolerance(tolerance: f64) -> Result<()> {
    if !tolerance.is_finite() {
        return Err(Error::NonFinite {
            what: "arc length tolerance",
            index: 0,
            value: tolerance,
        });
    }
    if tolerance <= 0.0 {
        return Err(Error::NonPositiveTolerance { value: tolerance });
    }
    Ok(())
}

/// Integrates the speed over [u₀, u₁] (u₀ ≤ u₁, both in the domain) piece by piece, returning
/// the accepted intervals in order, the error estimate and the evaluation count.
fn integrate<T, const D: usize, C>(
    curve: &C,
    u0: T,
    u1: T,
    tolerance: f64,
) -> Result<(Vec<Interval<T>>, f64, usize)>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    check_tolerance(tolerance)?;
    let domain = curve.domain();
    check_parameter(u0, domain)?;
    check_parameter(u1, domain)?;
    if u1 < u0 {
        return Err(Error::InvalidInterval {
            start: re(u0),
            end: re(u1),
        });
    }
    let nodes = gauss_legendre();
    let mut cuts = vec![u0];
    for b in curve.breakpoints() {
        if b > u0 && b < u1 {
            cuts.push(b);
        }
    }
    cuts.push(u1);
    let total = re(u1 - u0);
    let mut intervals = Vec::new();
    let mut error = 0.0;
    let mut evaluations = 0;
    if total <= 0.0 {
        return Ok((intervals, error, evaluations));
    }
    for pair in cuts.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        if b <= a {
            continue;
        }
        let whole = rule(curve, &nodes, a, b, &mut evaluations)?;
        // Depth-first with an explicit stack, right half pushed first so intervals come out in
        // order.
        let mut stack = vec![(a, b, whole, 0usize)];
        while let Some((a, b, whole, depth)) = stack.pop() {
            let mid = (a + b) * cst::<T>(0.5);
            let left = rule(curve, &nodes, a, mid, &mut evaluations)?;
            let right = rule(curve, &nodes, mid, b, &mut evaluations)?;
            let difference = re(left + right - whole).abs();
            let share = tolerance * re(b - a) / total;
            if difference <= share || depth >= MAX_DEPTH || mid <= a || mid >= b {
                error += difference;
                intervals.push(Interval {
                    start: a,
                    end: mid,
                    length: left,
                });
                intervals.push(Interval {
                    start: mid,
                    end: b,
                    length: right,
                });
            } else {
                stack.push((mid, b, right, depth + 1));
                stack.push((a, mid, left, depth + 1));
            }
        }
    }
    Ok((intervals, error, evaluations))
}

/// The arc length of the whole curve, to an absolute `tolerance` (length units, > 0).
///
/// Errors: [`Error::NonPositiveTolerance`] or [`Error::NonFinite`] for a bad tolerance, and
/// whatever the curve's evaluation reports.
pub fn arc_length<T, const D: usize, C>(curve: &C, tolerance: f64) -> Result<ArcLength<T>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let (a, b) = curve.domain();
    arc_length_between(curve, a, b, tolerance)
}

/// The arc length of the curve between parameters u₀ ≤ u₁ (both in the domain), to an
/// absolute `tolerance`.
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
/// Errors: [`Error::InvalidInterval`] for u₁ < u₀, [`Error::ParameterOutsideDomain`] for an end
/// outside the domain, and the errors of [`arc_length`].
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
    let (intervals, error_estimate, evaluations) = integrate(curve, u0, u1, tolerance)?;
    let length = intervals.iter().fold(T::zero(), |s, i| s + i.length);
    Ok(ArcLength {
        length,
        error_estimate,
        evaluations,
    })
}

/// The parameter u at which the arc length from the start of the domain equals `s`
/// (0 ≤ s ≤ total length, up to the tolerance), to an absolute length `tolerance`.
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
/// Errors: [`Error::NonFinite`] for a non-finite s, [`Error::LengthOutsideCurve`] for s < 0 or
/// s beyond the length, and the errors of [`arc_length`].
pub fn parameter_at_length<T, const D: usize, C>(curve: &C, s: T, tolerance: f64) -> Result<T>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    if !re(s).is_finite() {
        return Err(Error::NonFinite {
            what: "arc length",
            index: 0,
            value: re(s),
        });
    }
    let (a, b) = curve.domain();
    let (intervals, error, _) = integrate(curve, a, b, tolerance)?;
    let table = Table::new(intervals, a);
    table.parameter(curve, s, tolerance.max(error))
}

/// Cumulative lengths over the accepted intervals.
struct Table<T> {
    intervals: Vec<Interval<T>>,
    /// cumulative[k] = length before interval k; one extra entry for the total.
    cumulative: Vec<T>,
    start: T,
}

impl<T: Scalar> Table<T> {
    fn new(intervals: Vec<Interval<T>>, start: T) -> Self {
        let mut cumulative = Vec::with_capacity(intervals.len() + 1);
        let mut sum = T::zero();
        cumulative.push(sum);
        for i in &intervals {
            sum += i.length;
            cumulative.push(sum);
        }
        Self {
            intervals,
            cumulative,
            start,
        }
    }

    fn total(&self) -> T {
        self.cumulative.last().copied().unwrap_or_else(T::zero)
    }

    /// u with L(u) = s.
    fn parameter<const D: usize, C>(&self, curve: &C, s: T, tolerance: f64) -> Result<T>
    where
        C: ParametricCurve<T, D> + ?Sized,
    {
        let total = self.total();
        if re(s) < -tolerance || re(s) > re(total) + tolerance {
            return Err(Error::LengthOutsideCurve {
                value: re(s),
                length: re(total),
            });
        }
        if self.intervals.is_empty() {
            return Ok(self.start);
        }
        let k = self.cumulative[1..]
            .partition_point(|&c| c < s)
            .min(self.intervals.len() - 1);
        let interval = self.intervals[k];
        let target = s - self.cumulative[k];
        let nodes = gauss_legendre();
        let (mut lo, mut hi) = (interval.start, interval.end);
        // Linear start inside the interval.
        let fraction = if re(interval.length) > 0.0 {
            (target / interval.length).max(T::zero()).min(T::one())
        } else {
            T::zero()
        };
        let mut u = lo + (hi - lo) * fraction;
        let width = re(hi - lo);
        let mut evaluations = 0;
        for _ in 0..100 {
            let f = rule(curve, &nodes, interval.start, u, &mut evaluations)? - target;
            if re(f) == 0.0 {
                break;
            }
            if re(f) > 0.0 {
                hi = u;
            } else {
                lo = u;
            }
            let slope = speed(curve, u)?;
            let newton = u - f / slope;
            let next = if re(slope) > 0.0 && newton > lo && newton < hi {
                newton
            } else {
                (lo + hi) * cst::<T>(0.5)
            };
            let step = re(next - u).abs();
            u = next;
            if step <= 1e-15 * width.max(1e-300) || re(hi - lo) <= 1e-15 * width {
                break;
            }
        }
        Ok(u)
    }
}

/// An approximate arc-length parameterization u(s) of a curve: a piecewise cubic Hermite
/// interpolant of the exact map through the adaptive quadrature's nodes, with slopes
/// du/ds = 1/|C′(u)|, and the error measured at the middle of every interval.
#[derive(Debug, Clone, PartialEq)]
pub struct ArcLengthMap<T> {
    /// Node parameters u_k, increasing.
    parameters: Vec<T>,
    /// Arc lengths s_k = L(u_k), increasing.
    lengths: Vec<T>,
    /// du/ds at the start and at the end of every interval (they differ at a breakpoint).
    slopes: Vec<(T, T)>,
    /// The largest |L(u(s)) − s| found at the middle of the intervals, in length units.
    max_error: f64,
}

impl<T: Scalar> ArcLengthMap<T> {
    /// The total length of the curve.
    pub fn length(&self) -> T {
        self.lengths.last().copied().unwrap_or_else(T::zero)
    }

    /// The measured error: the largest |L(u(s)) − s| (length units, how far along the curve the
    /// approximate point lies from the true one) over the midpoints of every interval, where a
    /// cubic interpolant's error is largest.
    pub fn max_error(&self) -> f64 {
        self.max_error
    }

    /// The number of interpolation nodes.
    pub fn node_count(&self) -> usize {
        self.parameters.len()
    }

    /// The approximate parameter u(s) for 0 ≤ s ≤ length (s is clamped to that range).
    pub fn parameter(&self, s: T) -> T {
        let n = self.lengths.len();
        if n < 2 {
            return self.parameters.first().copied().unwrap_or_else(T::zero);
        }
        let s = s.max(self.lengths[0]).min(self.lengths[n - 1]);
        let k = self.lengths[1..].partition_point(|&c| c < s).min(n - 2);
        hermite(
            (self.lengths[k], self.lengths[k + 1]),
            (self.parameters[k], self.parameters[k + 1]),
            self.slopes[k],
            s,
        )
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

/// The arc-length parameterization of `curve`: the map s ↦ u(s) with C(u(s)) at arc length s,
/// approximated so that its measured error is at most `tolerance` (length units), or as close
/// as 16 rounds of interval halving get.
///
/// ```
/// use camber_geom::arc_length::arc_length_map;
/// use camber_geom::{BezierCurve2, ParametricCurve};
/// use nalgebra::Point2;
/// let c = BezierCurve2::try_new(vec![Point2::new(0.0_f64, 0.0), Point2::new(1.0, 2.0),
///     Point2::new(3.0, 2.0), Point2::new(4.0, 0.0)])?;
/// let map = arc_length_map(&c, 1e-8)?;
/// assert!(map.max_error() <= 1e-8);
/// let half = map.parameter(map.length() / 2.0);
/// // By symmetry the middle of the arc is at t = 1/2.
/// assert!((half - 0.5).abs() < 1e-7);
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// Errors: those of [`arc_length`].
pub fn arc_length_map<T, const D: usize, C>(curve: &C, tolerance: f64) -> Result<ArcLengthMap<T>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    check_tolerance(tolerance)?;
    let (a, b) = curve.domain();
    // Quadrature well below the requested map error, so that the measured error is the map's.
    let quad_tol = tolerance * 1e-3;
    let (intervals, _, _) = integrate(curve, a, b, quad_tol)?;
    let nodes = gauss_legendre();
    let mut parameters = vec![a];
    let mut lengths = vec![T::zero()];
    for i in &intervals {
        parameters.push(i.end);
        let previous = lengths.last().copied().unwrap_or_else(T::zero);
        lengths.push(previous + i.length);
    }
    let mut max_error = f64::INFINITY;
    for _ in 0..16 {
        let slopes = node_slopes(curve, &parameters, &lengths)?;
        let map = ArcLengthMap {
            parameters: parameters.clone(),
            lengths: lengths.clone(),
            slopes,
            max_error: 0.0,
        };
        // Error at each interval's middle in s: the length from u_k to the approximate
        // parameter, compared with s_mid − s_k.
        let mut worst = 0.0_f64;
        let mut bad = Vec::new();
        let mut evaluations = 0;
        for k in 0..parameters.len() - 1 {
            let s_mid = (lengths[k] + lengths[k + 1]) * cst::<T>(0.5);
            let u = map.parameter(s_mid);
            let along = if u >= parameters[k] {
                rule(curve, &nodes, parameters[k], u, &mut evaluations)?
            } else {
                -rule(curve, &nodes, u, parameters[k], &mut evaluations)?
            };
            let e = re(along - (s_mid - lengths[k])).abs();
            worst = worst.max(e);
            if e > tolerance {
                bad.push(k);
            }
        }
        max_error = worst;
        if bad.is_empty() {
            return Ok(ArcLengthMap { max_error, ..map });
        }
        // Halve every interval that is too coarse (from the back so indices stay valid).
        for &k in bad.iter().rev() {
            let mid = (parameters[k] + parameters[k + 1]) * cst::<T>(0.5);
            let left = rule(curve, &nodes, parameters[k], mid, &mut evaluations)?;
            parameters.insert(k + 1, mid);
            lengths.insert(k + 1, lengths[k] + left);
        }
    }
    let slopes = node_slopes(curve, &parameters, &lengths)?;
    Ok(ArcLengthMap {
        parameters,
        lengths,
        slopes,
        max_error,
    })
}

/// du/ds = 1/|C′(u)| at both ends of every interval, the end speed taken just inside the
/// interval (a node on a breakpoint has one speed on each side). Where the speed vanishes (a cusp
/// or a stationary parameterization) the interval's secant slope stands in.
fn node_slopes<T, const D: usize, C>(
    curve: &C,
    parameters: &[T],
    lengths: &[T],
) -> Result<Vec<(T, T)>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let mut slopes = Vec::with_capacity(parameters.len().saturating_sub(1));
    for k in 0..parameters.len().saturating_sub(1) {
        let (u0, u1) = (parameters[k], parameters[k + 1]);
        let ds = lengths[k + 1] - lengths[k];
        let secant = if re(ds) > 0.0 {
            (u1 - u0) / ds
        } else {
            T::zero()
        };
        let inside = (u1 - u0) * cst::<T>(LEFT_LIMIT);
        let mut pair = [T::zero(); 2];
        for (slot, u) in pair.iter_mut().zip([u0, u1 - inside]) {
            let v = speed(curve, u)?;
            // A speed far below the secant's would give a huge, useless slope.
            *slot = if re(v) > 0.0 && re(T::one() / v) < 1e3 * re(secant).max(1e-300) {
                T::one() / v
            } else {
                secant
            };
        }
        slopes.push((pair[0], pair[1]));
    }
    Ok(slopes)
}

/// How far inside an interval its end speed is taken, as a fraction of its length.
const LEFT_LIMIT: f64 = 1e-10;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rule_integrates_polynomials_to_degree_fifteen() {
        let rule = gauss_legendre();
        let weights: f64 = rule.iter().map(|r| r.1).sum();
        assert!((weights - 2.0).abs() < 1e-14);
        // ∫_{−1}^{1} x¹⁴ dx = 2/15; x¹⁵ integrates to 0.
        let even: f64 = rule.iter().map(|(x, w)| w * x.powi(14)).sum();
        let odd: f64 = rule.iter().map(|(x, w)| w * x.powi(15)).sum();
        assert!((even - 2.0 / 15.0).abs() < 1e-14);
        assert!(odd.abs() < 1e-14);
    }

    #[test]
    fn hermite_reproduces_cubics() {
        // u(s) = s³ on [1, 2]: values 1, 8, slopes 3, 12.
        let v: f64 = hermite((1.0, 2.0), (1.0, 8.0), (3.0, 12.0), 1.5);
        assert!((v - 3.375).abs() < 1e-14);
    }
}
