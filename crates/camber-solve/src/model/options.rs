//! [`Options`]: the tolerances and thresholds every solve path reads (the linear step, Newton,
//! SLSQP and the DOF analysis), and the [`CancelFlag`] another thread may raise to stop a solve.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use crate::model::errors::{Error, Result};
use crate::model::nonlinear::{NonlinearOptions, SolverChoice};
use crate::model::objective::Objective;

/// A flag another thread raises to stop a solve: every evaluation a solve charges to its budget
/// first reads it ([`crate::Problem::start_budget`]), so a cancelled solve stops at its next
/// evaluation with [`Error::Cancelled`] and leaves the problem as it was. The Python package
/// raises it on Ctrl-C. Clones share the flag; two flags are equal when they are the same flag.
///
/// ```
/// use camber_solve::CancelFlag;
/// let flag = CancelFlag::new();
/// let seen_elsewhere = flag.clone();
/// assert!(!seen_elsewhere.is_cancelled());
/// flag.cancel();
/// assert!(seen_elsewhere.is_cancelled());
/// assert_eq!(flag, seen_elsewhere);
/// assert_ne!(flag, CancelFlag::new());
/// ```
#[derive(Debug, Clone, Default)]
pub struct CancelFlag(Arc<AtomicBool>);

impl CancelFlag {
    /// A flag not raised.
    pub fn new() -> Self {
        Self::default()
    }

    /// Raises the flag.
    pub fn cancel(&self) {
        self.0.store(true, Ordering::Relaxed);
    }

    /// Whether the flag is raised.
    pub fn is_cancelled(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }

    /// The shared atomic itself (to hand the same flag to other crates' budgets).
    pub fn as_arc(&self) -> &Arc<AtomicBool> {
        &self.0
    }
}

impl From<Arc<AtomicBool>> for CancelFlag {
    fn from(flag: Arc<AtomicBool>) -> Self {
        Self(flag)
    }
}

impl PartialEq for CancelFlag {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

/// Tolerances and thresholds of a solve.
///
/// ```
/// let o = camber_solve::Options::default().with_tolerance(1e-9).with_drop_redundant(false);
/// assert!((o.tolerance - 1e-9).abs() < 1e-24 && !o.drop_redundant);
/// ```
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Options {
    /// A constraint is satisfied when every row has |g| ≤ tolerance (absolute).
    pub tolerance: f64,
    /// Relative tolerance of the rank decisions (times σ_max of J in the dense analysis, its
    /// largest row norm in the sparse one).
    pub rank_tolerance: f64,
    /// Up to this many reduced unknowns the dense backend is used, above it the sparse one.
    pub dense_max_unknowns: usize,
    /// The rank analysis runs before the linear step when rows × reduced unknowns is at most
    /// this (dense up to [`crate::analysis::DENSE_ANALYSIS_MAX_ENTRIES`] entries, sparse above);
    /// above it full row rank is inferred from a successful sparse Cholesky, and the caller
    /// runs the analysis only when that fails.
    pub dense_analysis_max_entries: usize,
    /// Whether consistent dependent rows may be dropped (otherwise [`Error::Redundant`]).
    pub drop_redundant: bool,
    /// Settings of the nonlinear solvers and of the selection ([`crate::solve()`]).
    pub nonlinear: NonlinearOptions,
    /// A flag that stops the solve at its next evaluation when raised (none by default).
    pub cancel: Option<CancelFlag>,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            tolerance: 1e-10,
            rank_tolerance: 1e-10,
            dense_max_unknowns: 200,
            dense_analysis_max_entries: 1 << 22,
            drop_redundant: true,
            nonlinear: NonlinearOptions::default(),
            cancel: None,
        }
    }
}

impl Options {
    /// Sets [`Options::tolerance`].
    pub fn with_tolerance(mut self, tolerance: f64) -> Self {
        self.tolerance = tolerance;
        self
    }

    /// Sets [`Options::rank_tolerance`].
    pub fn with_rank_tolerance(mut self, rank_tolerance: f64) -> Self {
        self.rank_tolerance = rank_tolerance;
        self
    }

    /// Sets [`Options::dense_max_unknowns`].
    pub fn with_dense_max_unknowns(mut self, n: usize) -> Self {
        self.dense_max_unknowns = n;
        self
    }

    /// Sets [`Options::dense_analysis_max_entries`].
    pub fn with_dense_analysis_max_entries(mut self, n: usize) -> Self {
        self.dense_analysis_max_entries = n;
        self
    }

    /// Sets [`Options::drop_redundant`].
    pub fn with_drop_redundant(mut self, drop: bool) -> Self {
        self.drop_redundant = drop;
        self
    }

    /// Sets [`Options::cancel`].
    pub fn with_cancel(mut self, cancel: Option<CancelFlag>) -> Self {
        self.cancel = cancel;
        self
    }

    pub(crate) fn validate(&self) -> Result<()> {
        for (index, v) in [self.tolerance, self.rank_tolerance]
            .into_iter()
            .enumerate()
        {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::NonFinite {
                    what: "tolerance",
                    index,
                    value: v,
                });
            }
        }
        Ok(())
    }
}

/// # Nonlinear settings
impl Options {
    /// Sets [`Options::nonlinear`].
    pub fn with_nonlinear(mut self, nonlinear: NonlinearOptions) -> Self {
        self.nonlinear = nonlinear;
        self
    }

    /// Forces a solver ([`NonlinearOptions::force`]); `None` restores the selection.
    pub fn with_force(mut self, solver: Option<SolverChoice>) -> Self {
        self.nonlinear.force = solver;
        self
    }

    /// Allows the soft mode ([`NonlinearOptions::soft`]).
    pub fn with_soft(mut self, soft: bool) -> Self {
        self.nonlinear.soft = soft;
        self
    }

    /// Sets the SLSQP objective ([`NonlinearOptions::objective`]).
    pub fn with_objective(mut self, objective: Objective) -> Self {
        self.nonlinear.objective = objective;
        self
    }
}
