//! Globally adaptive Gauss–Legendre quadrature of the speed |C′(u)|, split at the breakpoints,
//! under a work budget.
//!
//! Every *leaf* interval [a, b] carries the 8-point rule on the whole (I₁) and on its two halves
//! (I₂ = L + R); its error estimate is the larger of |I₂ − I₁| and what the decay of the speed's
//! Legendre coefficients on each half says ([`tail_error`]: the difference alone vanishes by
//! accident when both rules are wrong alike). The leaf with the largest estimate is split
//! (its halves become leaves; their own halves cost two rules each) until the sum of the
//! estimates is within the tolerance. Splitting where the error is, rather than giving every
//! interval a share of the tolerance by its parameter length, is what keeps a curve whose speed
//! varies by orders of magnitude (a control point at 10¹⁵) to a few hundred evaluations.
//!
//! **What f64 can reach.** A rule's value carries a rounding error of a few ulps of itself, and
//! a sum of lengths a few ulps of the total Λ. A leaf whose estimate is at that level
//! (≤ [`ROUNDING_ULPS`]·ε·|I₂|), or whose width can no longer be halved, is *settled*: splitting
//! it would only measure rounding. The tolerance is clamped to [`floor`] = [`FLOOR_ULPS`]·ε·Λ
//! (the length is first estimated by the unrefined leaves); the tolerance used is reported.
//!
//! **Dips of the speed.** Where C′ passes through or near zero (a cusp, or a curve that turns
//! back on itself along a line) the speed has a kink or a sharp dip, which a polynomial rule
//! cannot follow; when the dip lies between a leaf's outermost nodes in both I₁ and I₂, both
//! rules smooth it over alike and the estimate misses the error. So each piece is also cut at
//! the local minima of the speed: the sign changes from − to + of g(u) = C′(u)·C″(u) (half the
//! derivative of |C′|²), found on [`DIP_SAMPLES`] samples per piece and bisected to the last
//! bits. On each side of such a cut the speed is smooth again.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use crate::budget::Meter;
use crate::curve::{check_parameter, ParametricCurve};
use crate::errors::{Error, Result};
use crate::scalar::{cst, re, Scalar};

/// Points of the Gauss–Legendre rule used on every interval.
pub(super) const GAUSS_POINTS: usize = 8;

/// A leaf whose estimate is within this many ulps of its value is settled (rounding only).
pub(super) const ROUNDING_ULPS: f64 = 32.0;

/// Samples of C′·C″ per piece when looking for the minima of the speed.
pub(super) const DIP_SAMPLES: usize = 32;

/// The smallest tolerance honoured, in ulps of the curve's length.
pub const FLOOR_ULPS: f64 = 64.0;

/// The smallest absolute tolerance worth asking of a length Λ: [`FLOOR_ULPS`]·ε·Λ (and the
/// smallest positive normal number for Λ = 0).
///
/// ```
/// use camber_geom::arc_length::floor;
/// assert!((floor(1.0) - 64.0 * f64::EPSILON).abs() < 1e-30);
/// ```
pub fn floor(length: f64) -> f64 {
    (FLOOR_ULPS * f64::EPSILON * length.abs()).max(f64::MIN_POSITIVE)
}

/// The nodes x_k ∈ (−1, 1) and weights w_k of the `GAUSS_POINTS`-point Gauss–Legendre rule,
/// found as the roots of the Legendre polynomial P_n by Newton's method from Chebyshev-like
/// starts (exact for polynomials up to degree 2n − 1).
pub(super) fn gauss_legendre() -> [(f64, f64); GAUSS_POINTS] {
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

/// The speed |C′(u)|.
pub(super) fn speed<T, const D: usize, C>(curve: &C, u: T) -> Result<T>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    Ok(curve.derivative(u)?.norm())
}

/// The Gauss–Legendre rule on [a, b], charging its evaluations to `meter`. Fails with
/// [`Error::NonFinite`] when the speed overflows f64 (coordinates near the f64 limit).
pub(super) fn rule<T, const D: usize, C>(
    curve: &C,
    nodes: &[(f64, f64); GAUSS_POINTS],
    a: T,
    b: T,
    meter: &mut Meter<'_>,
) -> Result<T>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let mut speeds = [0.0; GAUSS_POINTS];
    rule_sampled(curve, nodes, a, b, meter, &mut speeds)
}

/// [`rule`], also writing the speed at each node to `speeds` (in f64).
fn rule_sampled<T, const D: usize, C>(
    curve: &C,
    nodes: &[(f64, f64); GAUSS_POINTS],
    a: T,
    b: T,
    meter: &mut Meter<'_>,
    speeds: &mut [f64; GAUSS_POINTS],
) -> Result<T>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    meter.charge(GAUSS_POINTS as u64)?;
    let half = (b - a) * cst::<T>(0.5);
    let mid = (a + b) * cst::<T>(0.5);
    let mut sum = T::zero();
    for (&(x, w), sample) in nodes.iter().zip(speeds.iter_mut()) {
        // Nodes stay inside [a, b] even when rounding would put one a hair outside.
        let u = (mid + half * cst::<T>(x)).max(a).min(b);
        let v = speed(curve, u)?;
        *sample = re(v);
        sum += v * cst::<T>(w);
    }
    let value = sum * half;
    if !re(value).is_finite() {
        return Err(Error::NonFinite {
            what: "speed integral of the curve (its coordinates overflow f64)",
            index: 0,
            value: re(value),
        });
    }
    Ok(value)
}

/// The highest Legendre coefficients the rule's nodes can resolve, as weights on the node
/// values: c_j = (2j + 1)/2 · Σᵢ wᵢ·P_j(xᵢ)·f(xᵢ) for j = [`TAIL`] (exact for f of degree
/// ≤ 15 − j), and c₀ (the mean) last.
pub(super) type TailWeights = [[f64; TAIL.len() + 1]; GAUSS_POINTS];

/// The orders of the Legendre coefficients read by [`tail_error`].
const TAIL: [usize; 3] = [5, 6, 7];

/// The weights of [`TailWeights`] for the rule's nodes.
pub(super) fn tail_weights(nodes: &[(f64, f64); GAUSS_POINTS]) -> TailWeights {
    let mut table = [[0.0; TAIL.len() + 1]; GAUSS_POINTS];
    for (&(x, w), row) in nodes.iter().zip(table.iter_mut()) {
        // P_0 … P_7 at x by the three-term recurrence.
        let mut p = [0.0; GAUSS_POINTS];
        p[0] = 1.0;
        p[1] = x;
        for j in 2..GAUSS_POINTS {
            #[allow(clippy::cast_precision_loss)] // j < 8
            let jf = j as f64;
            p[j] = ((2.0 * jf - 1.0) * x * p[j - 1] - (jf - 1.0) * p[j - 2]) / jf;
        }
        for (slot, &j) in row.iter_mut().zip(TAIL.iter()) {
            #[allow(clippy::cast_precision_loss)] // j < 8
            let jf = j as f64;
            *slot = (2.0 * jf + 1.0) / 2.0 * w * p[j];
        }
        row[TAIL.len()] = w / 2.0;
    }
    table
}

/// A second error estimate of the rule on an interval of `width`, from the speed at its nodes
/// alone: the decay of the speed's Legendre coefficients. With |c_j| ≈ K·ρ⁻ʲ the rule's error
/// is about width·|c₁₆| = width·K·ρ⁻¹⁶; the tail t = max |c₅|, |c₆|, |c₇| is at least K·ρ⁻⁷
/// and t/|c₀| is at least ρ⁻⁷ (c₀ ≈ K), so width·t·(t/|c₀|) over-estimates the error by ρ² or
/// more. It is tiny once the speed is resolved (t at rounding level) and large where a nearby
/// singularity of the speed — a near-zero of C′ just off the interval, a pole of a rational
/// curve — keeps ρ small: exactly where the whole-versus-halves difference can vanish by
/// accident (both rules wrong by the same amount).
fn tail_error(table: &TailWeights, speeds: &[f64; GAUSS_POINTS], width: f64) -> f64 {
    let mut c = [0.0; TAIL.len() + 1];
    for (row, &f) in table.iter().zip(speeds) {
        for (cj, &weight) in c.iter_mut().zip(row) {
            *cj += weight * f;
        }
    }
    let mean = c[TAIL.len()].abs();
    let tail = c[..TAIL.len()]
        .iter()
        .fold(0.0_f64, |m, cj| m.max(cj.abs()));
    if tail == 0.0 {
        return 0.0;
    }
    width.abs() * tail * (tail / mean).min(1.0)
}

/// g(u) = C′(u)·C″(u) in f64, half the derivative of the squared speed.
fn speed_slope<T, const D: usize, C>(curve: &C, u: f64) -> Result<f64>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let mut d = [nalgebra::SVector::<T, D>::zeros(); 3];
    curve.derivatives_into(cst::<T>(u), &mut d)?;
    Ok(re(d[1].dot(&d[2])))
}

/// The interior local minima of the speed on (a, b): where g = C′·C″ changes sign from − to +
/// between two of [`DIP_SAMPLES`] evenly spaced samples, bisected until the bracket is a few
/// ulps wide (or lands on a sample where g is 0). Charges every evaluation to `meter`.
fn speed_minima<T, const D: usize, C>(
    curve: &C,
    a: f64,
    b: f64,
    meter: &mut Meter<'_>,
) -> Result<Vec<f64>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let mut found = Vec::new();
    if b.partial_cmp(&a) != Some(Ordering::Greater) {
        return Ok(found);
    }
    meter.charge(DIP_SAMPLES as u64 + 1)?;
    let at = |k: usize| {
        if k == DIP_SAMPLES {
            b
        } else {
            a + (b - a) * (k as f64 / DIP_SAMPLES as f64)
        }
    };
    let g: Vec<f64> = (0..=DIP_SAMPLES)
        .map(|k| speed_slope(curve, at(k)))
        .collect::<Result<_>>()?;
    for k in 0..DIP_SAMPLES {
        let (g0, g1) = (g[k], g[k + 1]);
        if k > 0 && g0 == 0.0 && g[k - 1] < 0.0 && g1 > 0.0 {
            found.push(at(k));
        } else if g0 < 0.0 && g1 > 0.0 {
            let (mut lo, mut hi) = (at(k), at(k + 1));
            // Each halving costs one evaluation; 64 reach any f64 bracket's last bits.
            for _ in 0..64 {
                let mid = 0.5 * (lo + hi);
                if !(mid > lo && mid < hi) {
                    break;
                }
                meter.charge(1)?;
                let gm = speed_slope(curve, mid)?;
                if gm < 0.0 {
                    lo = mid;
                } else if gm > 0.0 {
                    hi = mid;
                } else {
                    lo = mid;
                    hi = mid;
                    break;
                }
            }
            found.push(0.5 * (lo + hi));
        }
    }
    Ok(found)
}

/// Checks that a tolerance is finite and positive.
pub(super) fn check_tolerance(tolerance: f64, what: &'static str) -> Result<()> {
    if !tolerance.is_finite() {
        return Err(Error::NonFinite {
            what,
            index: 0,
            value: tolerance,
        });
    }
    if tolerance <= 0.0 {
        return Err(Error::NonPositiveTolerance { value: tolerance });
    }
    Ok(())
}

/// One accepted interval of the quadrature: [start, end] and its length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Interval<T> {
    pub start: T,
    pub end: T,
    pub length: T,
}

/// The outcome of [`integrate`]: accepted intervals in order (each leaf's two halves), the
/// summed error estimate, the evaluations made and the tolerance honoured.
pub(super) struct Quadrature<T> {
    pub intervals: Vec<Interval<T>>,
    pub error: f64,
    pub evaluations: u64,
    pub tolerance: f64,
}

impl<T: Scalar> Quadrature<T> {
    /// The sum of the interval lengths, compensated (Kahan), so that many short intervals add
    /// up to the total within a few ulps.
    pub fn length(&self) -> T {
        compensated_sum(self.intervals.iter().map(|i| i.length))
    }
}

/// Kahan's compensated sum.
pub(super) fn compensated_sum<T: Scalar>(values: impl Iterator<Item = T>) -> T {
    let (mut sum, mut carry) = (T::zero(), T::zero());
    for v in values {
        let y = v - carry;
        let t = sum + y;
        carry = (t - sum) - y;
        sum = t;
    }
    sum
}

/// A leaf of the adaptive subdivision.
#[derive(Debug, Clone, Copy)]
struct Leaf<T> {
    a: T,
    m: T,
    b: T,
    left: T,
    right: T,
    error: f64,
}

impl<T: Scalar> Leaf<T> {
    /// The leaf [a, b] whose whole-interval rule gave `whole`: its halves are integrated.
    /// Its error estimate is the larger of |I₂ − I₁| (halves against whole) and the halves'
    /// [`tail_error`]s.
    fn new<const D: usize, C>(
        curve: &C,
        (nodes, tails): (&[(f64, f64); GAUSS_POINTS], &TailWeights),
        (a, b, whole): (T, T, T),
        meter: &mut Meter<'_>,
    ) -> Result<Self>
    where
        C: ParametricCurve<T, D> + ?Sized,
    {
        let m = (a + b) * cst::<T>(0.5);
        let mut speeds = [0.0; GAUSS_POINTS];
        let left = rule_sampled(curve, nodes, a, m, meter, &mut speeds)?;
        let tail_left = tail_error(tails, &speeds, re(m - a));
        let right = rule_sampled(curve, nodes, m, b, meter, &mut speeds)?;
        let tail_right = tail_error(tails, &speeds, re(b - m));
        let error = re(left + right - whole).abs().max(tail_left + tail_right);
        Ok(Self {
            a,
            m,
            b,
            left,
            right,
            error,
        })
    }

    /// Whether splitting would only measure rounding: the estimate is at the rounding level of
    /// the value, or a half can no longer be halved.
    fn settled(&self) -> bool {
        let value = re(self.left).abs() + re(self.right).abs();
        if self.error <= ROUNDING_ULPS * f64::EPSILON * value {
            return true;
        }
        let quarter_left = (self.a + self.m) * cst::<T>(0.5);
        let quarter_right = (self.m + self.b) * cst::<T>(0.5);
        !(self.a < self.m
            && self.m < self.b
            && self.a < quarter_left
            && quarter_left < self.m
            && self.m < quarter_right
            && quarter_right < self.b)
    }
}

/// A heap entry: the leaf's index, ordered by its error estimate.
struct ByError(f64, usize);

impl PartialEq for ByError {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for ByError {}
impl PartialOrd for ByError {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for ByError {
    fn cmp(&self, other: &Self) -> Ordering {
        self.0.total_cmp(&other.0).then(other.1.cmp(&self.1))
    }
}

/// Integrates the speed over [u₀, u₁] (u₀ ≤ u₁, both in the domain) to `tolerance` (clamped to
/// [`floor`] of the length), splitting first at the curve's breakpoints.
pub(super) fn integrate<T, const D: usize, C>(
    curve: &C,
    u0: T,
    u1: T,
    tolerance: f64,
    meter: &mut Meter<'_>,
) -> Result<Quadrature<T>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let domain = curve.domain();
    check_parameter(u0, domain)?;
    check_parameter(u1, domain)?;
    if u1 < u0 {
        return Err(Error::InvalidInterval {
            start: re(u0),
            end: re(u1),
        });
    }
    let start_units = meter.used();
    let mut out = Quadrature {
        intervals: Vec::new(),
        error: 0.0,
        evaluations: 0,
        tolerance,
    };
    if re(u1 - u0) <= 0.0 {
        return Ok(out);
    }
    let nodes = gauss_legendre();
    let tails = tail_weights(&nodes);
    let mut pieces = vec![u0];
    for b in curve.breakpoints() {
        if b > u0 && b < u1 && pieces.last().is_some_and(|&l| b > l) {
            pieces.push(b);
        }
    }
    pieces.push(u1);
    let mut cuts = vec![u0];
    for pair in pieces.windows(2) {
        for m in speed_minima(curve, re(pair[0]), re(pair[1]), meter)? {
            let m = cst::<T>(m);
            if cuts.last().is_some_and(|&l| m > l) && m < pair[1] {
                cuts.push(m);
            }
        }
        cuts.push(pair[1]);
    }
    let mut leaves: Vec<Leaf<T>> = Vec::with_capacity(cuts.len() - 1);
    for pair in cuts.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let whole = rule(curve, &nodes, a, b, meter)?;
        leaves.push(Leaf::new(curve, (&nodes, &tails), (a, b, whole), meter)?);
    }
    let estimate: f64 = leaves
        .iter()
        .map(|l| re(l.left).abs() + re(l.right).abs())
        .sum();
    let tolerance = tolerance.max(floor(estimate));
    let mut heap: BinaryHeap<ByError> = leaves
        .iter()
        .enumerate()
        .filter(|(_, l)| !l.settled())
        .map(|(i, l)| ByError(l.error, i))
        .collect();
    let mut total: f64 = leaves.iter().map(|l| l.error).sum();
    while total > tolerance {
        let Some(ByError(_, i)) = heap.pop() else {
            break;
        };
        let leaf = leaves[i];
        let left = Leaf::new(curve, (&nodes, &tails), (leaf.a, leaf.m, leaf.left), meter)?;
        let right = Leaf::new(curve, (&nodes, &tails), (leaf.m, leaf.b, leaf.right), meter)?;
        leaves[i] = left;
        leaves.push(right);
        let j = leaves.len() - 1;
        for (k, l) in [(i, left), (j, right)] {
            if !l.settled() {
                heap.push(ByError(l.error, k));
            }
        }
        total = total - leaf.error + left.error + right.error;
        if total <= tolerance {
            // The running sum drifts by rounding: recount before stopping.
            total = leaves.iter().map(|l| l.error).sum();
        }
    }
    leaves.sort_by(|x, y| re(x.a).total_cmp(&re(y.a)));
    out.intervals.reserve(2 * leaves.len());
    for l in &leaves {
        out.intervals.push(Interval {
            start: l.a,
            end: l.m,
            length: l.left,
        });
        out.intervals.push(Interval {
            start: l.m,
            end: l.b,
            length: l.right,
        });
    }
    out.error = leaves.iter().map(|l| l.error).sum();
    out.evaluations = meter.used() - start_units;
    out.tolerance = tolerance;
    Ok(out)
}

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
    fn the_tail_reads_legendre_coefficients_by_hand() {
        let nodes = gauss_legendre();
        let table = tail_weights(&nodes);
        let at = |f: &dyn Fn(f64) -> f64| {
            let mut speeds = [0.0; GAUSS_POINTS];
            for (s, (x, _)) in speeds.iter_mut().zip(nodes) {
                *s = f(x);
            }
            speeds
        };
        // A quartic has no Legendre coefficient above c₄: no tail.
        let quartic = at(&|x: f64| 3.0 + x - 2.0 * x.powi(4));
        assert!(tail_error(&table, &quartic, 2.0) < 1e-14);
        // 2 + P₇(x): c₇ = 1, c₀ = 2, so width·1·(1/2).
        let p7 =
            |x: f64| (429.0 * x.powi(7) - 693.0 * x.powi(5) + 315.0 * x.powi(3) - 35.0 * x) / 16.0;
        let seventh = at(&|x| 2.0 + p7(x));
        assert!((tail_error(&table, &seventh, 2.0) - 1.0).abs() < 1e-12);
        assert!((tail_error(&table, &seventh, 0.5) - 0.25).abs() < 1e-12);
        // A zero speed has no error.
        assert!(tail_error(&table, &[0.0; GAUSS_POINTS], 1.0).abs() < f64::MIN_POSITIVE);
    }

    #[test]
    fn compensation_keeps_many_small_terms() {
        // 10⁷ terms of 0.1: a plain sum drifts by about 1e-9 relative, the compensated one
        // stays within a few ulps of 10⁶.
        let sum: f64 = compensated_sum(std::iter::repeat_n(0.1_f64, 10_000_000));
        assert!((sum - 1e6).abs() < 1e-8, "{sum}");
    }
}
