//! Work budgets and cancellation for the toolkit's iterative and adaptive routines.
//!
//! Every routine whose running time is not fixed by the size of its input — adaptive
//! quadrature, subdivision searches, root finding, fitting, knot removal, offsets — counts its
//! work in *work units* on a [`Meter`] made from a [`Budget`]. One unit is one small step of
//! bounded cost: a curve evaluation, a de Casteljau halving, one knot-removal attempt, one data
//! point of a fitting pass (a few hundred nanoseconds to a few microseconds). When the count
//! passes the limit the routine stops with [`Error::BudgetExhausted`], which names it; when
//! the budget's stop flag is set it stops with [`Error::Cancelled`]. The flag is read on every
//! charge, so a routine notices it within microseconds of work.
//!
//! Without an explicit limit ([`Budget::default`]) each routine takes its own, scale-aware
//! one: [`DEFAULT_BASE_WORK`] plus [`DEFAULT_WORK_PER_PIECE`] per polynomial piece (or data
//! point) of its input, enough for any input the routine can answer and small enough that an
//! input it cannot answer fails in seconds rather than running for hours.
//!
//! ```
//! use std::sync::atomic::{AtomicBool, Ordering};
//! use std::sync::Arc;
//! use camber_geom::arc_length::arc_length_with;
//! use camber_geom::budget::Budget;
//! use camber_geom::{BezierCurve2, Error};
//! use nalgebra::Point2;
//!
//! let c = BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(1.0, 2.0),
//!     Point2::new(3.0, 2.0), Point2::new(4.0, 0.0)])?;
//! // A tiny limit: the quadrature stops and says which routine ran out.
//! let err = arc_length_with(&c, 1e-12, &Budget::default().with_max_work(5)).unwrap_err();
//! assert_eq!(err, Error::BudgetExhausted { operation: "arc length", limit: 5 });
//! // A stop flag set (by a Ctrl-C handler, another thread, …): the call returns at once.
//! let stop = Arc::new(AtomicBool::new(true));
//! let err = arc_length_with(&c, 1e-12, &Budget::default().with_stop(stop.clone())).unwrap_err();
//! assert_eq!(err, Error::Cancelled { operation: "arc length" });
//! stop.store(false, Ordering::Relaxed);
//! assert!(arc_length_with(&c, 1e-12, &Budget::default().with_stop(stop)).is_ok());
//! # Ok::<(), Error>(())
//! ```

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use crate::errors::{Error, Result};

/// Work units every routine may spend whatever the size of its input (about a second of
/// curve evaluations).
pub const DEFAULT_BASE_WORK: u64 = 20_000_000;

/// Work units a routine may spend per polynomial piece (or data point) of its input, on top
/// of [`DEFAULT_BASE_WORK`].
pub const DEFAULT_WORK_PER_PIECE: u64 = 2_000;

/// The default limit of a routine whose input has `pieces` polynomial pieces (or data points):
/// [`DEFAULT_BASE_WORK`] + [`DEFAULT_WORK_PER_PIECE`] · `pieces`, saturating.
///
/// ```
/// use camber_geom::budget::{default_limit, DEFAULT_BASE_WORK, DEFAULT_WORK_PER_PIECE};
/// assert_eq!(default_limit(10), DEFAULT_BASE_WORK + 10 * DEFAULT_WORK_PER_PIECE);
/// assert_eq!(default_limit(usize::MAX), u64::MAX);
/// ```
pub fn default_limit(pieces: usize) -> u64 {
    let pieces = u64::try_from(pieces).unwrap_or(u64::MAX);
    DEFAULT_BASE_WORK.saturating_add(DEFAULT_WORK_PER_PIECE.saturating_mul(pieces))
}

/// How much work one call may do, and a flag that stops it.
///
/// Cloning is cheap (the flag is shared): one budget can be handed to many calls, and every
/// call holding a clone stops when the flag is set. The limit applies to each call on its own.
///
/// ```
/// use std::sync::atomic::AtomicBool;
/// use std::sync::Arc;
/// use camber_geom::budget::Budget;
/// let stop = Arc::new(AtomicBool::new(false));
/// let budget = Budget::default().with_max_work(1_000_000).with_stop(stop);
/// assert_eq!(budget.max_work(), Some(1_000_000));
/// assert!(!budget.is_stopped());
/// ```
#[derive(Debug, Clone, Default)]
pub struct Budget {
    max_work: Option<u64>,
    stop: Option<Arc<AtomicBool>>,
}

impl PartialEq for Budget {
    /// Equal limits and the same stop flag (the same allocation, not an equal value).
    fn eq(&self, other: &Self) -> bool {
        self.max_work == other.max_work
            && match (&self.stop, &other.stop) {
                (None, None) => true,
                (Some(a), Some(b)) => Arc::ptr_eq(a, b),
                _ => false,
            }
    }
}

impl Budget {
    /// The default budget: each routine's own scale-aware limit ([`default_limit`]), no flag.
    pub fn new() -> Self {
        Self::default()
    }

    /// Sets the limit in work units (instead of the routine's default).
    pub fn with_max_work(mut self, units: u64) -> Self {
        self.max_work = Some(units);
        self
    }

    /// Sets the stop flag: when anyone stores `true` in it, every routine running under this
    /// budget returns [`Error::Cancelled`] within microseconds of work.
    pub fn with_stop(mut self, stop: Arc<AtomicBool>) -> Self {
        self.stop = Some(stop);
        self
    }

    /// The explicit limit, if one was set.
    pub fn max_work(&self) -> Option<u64> {
        self.max_work
    }

    /// Whether the stop flag is set.
    pub fn is_stopped(&self) -> bool {
        self.stop
            .as_ref()
            .is_some_and(|s| s.load(Ordering::Relaxed))
    }

    /// A meter for one run of `operation`, with the explicit limit or else `default_limit`.
    ///
    /// ```
    /// use camber_geom::budget::Budget;
    /// use camber_geom::Error;
    /// let budget = Budget::default();
    /// let mut meter = budget.meter("my search", 3);
    /// assert!(meter.charge(3).is_ok());
    /// assert_eq!(meter.charge(1), Err(Error::BudgetExhausted { operation: "my search", limit: 3 }));
    /// ```
    pub fn meter(&self, operation: &'static str, default_limit: u64) -> Meter<'_> {
        Meter {
            stop: self.stop.as_deref(),
            operation,
            limit: self.max_work.unwrap_or(default_limit),
            used: 0,
        }
    }
}

/// The running count of one routine's work against its [`Budget`].
#[derive(Debug)]
pub struct Meter<'a> {
    stop: Option<&'a AtomicBool>,
    operation: &'static str,
    limit: u64,
    used: u64,
}

impl Meter<'_> {
    /// Counts `units` of work. Fails with [`Error::Cancelled`] when the stop flag is set and
    /// with [`Error::BudgetExhausted`] when the count passes the limit.
    pub fn charge(&mut self, units: u64) -> Result<()> {
        if self.stop.is_some_and(|s| s.load(Ordering::Relaxed)) {
            return Err(Error::Cancelled {
                operation: self.operation,
            });
        }
        self.used = self.used.saturating_add(units);
        if self.used > self.limit {
            return Err(Error::BudgetExhausted {
                operation: self.operation,
                limit: self.limit,
            });
        }
        Ok(())
    }

    /// Units counted so far.
    pub fn used(&self) -> u64 {
        self.used
    }

    /// The limit in force.
    pub fn limit(&self) -> u64 {
        self.limit
    }

    /// The routine this meter counts for.
    pub fn operation(&self) -> &'static str {
        self.operation
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_flag_is_seen_on_the_next_charge() {
        let stop = Arc::new(AtomicBool::new(false));
        let budget = Budget::default().with_stop(stop.clone());
        let mut meter = budget.meter("test", u64::MAX);
        assert!(meter.charge(1).is_ok());
        stop.store(true, Ordering::Relaxed);
        assert_eq!(meter.charge(1), Err(Error::Cancelled { operation: "test" }));
        assert!(budget.is_stopped());
    }

    #[test]
    fn counts_saturate_instead_of_wrapping() {
        let budget = Budget::default();
        let mut meter = budget.meter("test", u64::MAX);
        assert!(meter.charge(u64::MAX).is_ok());
        assert!(meter.charge(u64::MAX).is_ok());
        assert_eq!(meter.used(), u64::MAX);
    }
}
