//! The table of cumulative arc length over the quadrature's intervals, and the parameter at a
//! given length found in it: one quadrature serves any number of lengths.
//!
//! For a length s the interval holding it is found by binary search in the cumulative lengths;
//! inside it, safeguarded Newton on g(u) = L(u_k, u) − (s − s_k) (g′ = |C′|, bisection when a
//! step leaves the bracket) finds u, L(u_k, u) being one Gauss–Legendre rule on [u_k, u] (the
//! interval is one the quadrature accepted, so the rule is accurate on any part of it). The
//! last step is a Newton step, so with dual numbers u carries the implicit derivative.

use super::quadrature::{
    check_tolerance, gauss_legendre, integrate, rule, speed, Interval, Quadrature,
};
use crate::budget::{default_limit, Budget, Meter};
use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::scalar::{cst, re, Scalar};

/// Newton iterations per length at most (each halves the bracket at worst, so 200 reach the
/// f64 resolution of any interval).
const MAX_ITERATIONS: usize = 200;

/// The cumulative arc length of a curve over its quadrature intervals, for finding the
/// parameters at many lengths with one quadrature.
///
/// ```
/// use camber_geom::arc_length::ArcLengthTable;
/// use camber_geom::budget::Budget;
/// use camber_geom::{BezierCurve2, ParametricCurve};
/// use nalgebra::Point2;
/// let c = BezierCurve2::try_new(vec![Point2::new(0.0_f64, 0.0), Point2::new(1.0, 2.0),
///     Point2::new(3.0, 2.0), Point2::new(4.0, 0.0)])?;
/// let budget = Budget::default();
/// let table = ArcLengthTable::new(&c, 1e-12, &budget)?;
/// let lengths: Vec<f64> = (0..=100).map(|k| table.length() * f64::from(k) / 100.0).collect();
/// let us = table.parameters(&c, &lengths, &budget)?;
/// // By symmetry the middle of the arc is at t = 1/2.
/// assert!((us[50] - 0.5).abs() < 1e-10);
/// # Ok::<(), camber_geom::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ArcLengthTable<T> {
    intervals: Vec<Interval<T>>,
    /// cumulative[k] = length before interval k; one extra entry for the total.
    cumulative: Vec<T>,
    start: T,
    error: f64,
    tolerance: f64,
}

impl<T: Scalar> ArcLengthTable<T> {
    /// The table of the whole curve, its quadrature to `tolerance` (length units, > 0; clamped
    /// to what f64 can reach, see [`floor`](super::floor)) under `budget`.
    ///
    /// Errors: [`Error::NonPositiveTolerance`] or [`Error::NonFinite`] for a bad tolerance,
    /// [`Error::BudgetExhausted`] / [`Error::Cancelled`] ("arc length"), and the curve's
    /// evaluation errors.
    pub fn new<const D: usize, C>(curve: &C, tolerance: f64, budget: &Budget) -> Result<Self>
    where
        C: ParametricCurve<T, D> + ?Sized,
    {
        check_tolerance(tolerance, "arc length tolerance")?;
        let limit = default_limit(curve.breakpoints().len());
        let mut meter = budget.meter("arc length", limit);
        let (a, b) = curve.domain();
        let q = integrate(curve, a, b, tolerance, &mut meter)?;
        Ok(Self::from_quadrature(q, a))
    }

    pub(super) fn from_quadrature(q: Quadrature<T>, start: T) -> Self {
        let mut cumulative = Vec::with_capacity(q.intervals.len() + 1);
        let (mut sum, mut carry) = (T::zero(), T::zero());
        cumulative.push(sum);
        for i in &q.intervals {
            // Kahan: the running total stays within a few ulps over millions of intervals.
            let y = i.length - carry;
            let t = sum + y;
            carry = (t - sum) - y;
            sum = t;
            cumulative.push(sum);
        }
        Self {
            intervals: q.intervals,
            cumulative,
            start,
            error: q.error,
            tolerance: q.tolerance,
        }
    }

    /// The total length.
    pub fn length(&self) -> T {
        self.cumulative.last().copied().unwrap_or_else(T::zero)
    }

    /// The quadrature's error estimate (length units).
    pub fn error_estimate(&self) -> f64 {
        self.error
    }

    /// The tolerance the quadrature honoured: the one asked for, or the f64 floor when that
    /// was below it.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// The parameter at arc length `s` from the start (0 ≤ s ≤ length, up to the tolerance).
    ///
    /// Errors: [`Error::NonFinite`] for a non-finite s, [`Error::LengthOutsideCurve`],
    /// [`Error::BudgetExhausted`] / [`Error::Cancelled`] ("parameter at length").
    pub fn parameter<const D: usize, C>(&self, curve: &C, s: T, budget: &Budget) -> Result<T>
    where
        C: ParametricCurve<T, D> + ?Sized,
    {
        let mut meter = budget.meter("parameter at length", default_limit(1));
        self.solve(curve, s, &mut meter)
    }

    /// The parameters at every length of `lengths` (each as in [`parameter`](Self::parameter)),
    /// under one budget whose default limit grows with the number of lengths.
    pub fn parameters<const D: usize, C>(
        &self,
        curve: &C,
        lengths: &[T],
        budget: &Budget,
    ) -> Result<Vec<T>>
    where
        C: ParametricCurve<T, D> + ?Sized,
    {
        let mut meter = budget.meter("parameter at length", default_limit(lengths.len()));
        lengths
            .iter()
            .map(|&s| self.solve(curve, s, &mut meter))
            .collect()
    }

    /// u with L(u) = s.
    fn solve<const D: usize, C>(&self, curve: &C, s: T, meter: &mut Meter<'_>) -> Result<T>
    where
        C: ParametricCurve<T, D> + ?Sized,
    {
        if !re(s).is_finite() {
            return Err(Error::NonFinite {
                what: "arc length",
                index: 0,
                value: re(s),
            });
        }
        let total = self.length();
        let slack = self.tolerance.max(self.error);
        if re(s) < -slack || re(s) > re(total) + slack {
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
        // At or beyond an end of the interval the answer is that end (where the speed may
        // vanish, Newton would find it only to the square root of the rounding).
        if re(target) <= 0.0 {
            return Ok(interval.start);
        }
        if re(target) >= re(interval.length) {
            return Ok(interval.end);
        }
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
        for _ in 0..MAX_ITERATIONS {
            let f = rule(curve, &nodes, interval.start, u, meter)? - target;
            if re(f) == 0.0 {
                break;
            }
            if re(f) > 0.0 {
                hi = u;
            } else {
                lo = u;
            }
            meter.charge(1)?;
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
