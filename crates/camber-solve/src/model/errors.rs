//! The error type of camber-solve: one enum whose variants carry the offending ids and values.
//!
//! Constraints are named by the caller's [`ConstraintId`] so that a user interface can point at
//! them. Every error of [`crate::solve_linear`] leaves the problem's values unchanged.

use crate::model::ids::ConstraintId;
use crate::model::scalar::Readable;

/// Everything that can go wrong when building or solving a [`crate::Problem`].
///
/// ```
/// use camber_solve::{Error, Problem};
/// let mut p = Problem::new();
/// let err = p.add_block(&[0.0, f64::NAN]).unwrap_err();
/// assert!(matches!(err, Error::NonFinite { what: "block value", index: 1, .. }));
/// let err = p.add_block(&[]).unwrap_err();
/// assert_eq!(err, Error::Dimension { what: "block values", expected: 1, found: 0 });
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A number that must be finite is NaN or infinite.
    #[error("{what} {index} is not finite ({})", Readable(*value))]
    NonFinite {
        /// What the number is ("block value", "weight", "bound", …).
        what: &'static str,
        /// Its index in the input.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// A block id that this problem did not issue.
    #[error("block {block} does not exist ({blocks} blocks)")]
    UnknownBlock {
        /// The block index asked for.
        block: usize,
        /// Number of blocks in the problem.
        blocks: usize,
    },
    /// An unknown (or an offset inside a block) that does not exist.
    #[error("unknown {index} does not exist ({len} available)")]
    UnknownUnknown {
        /// The index asked for (flat, or the offset inside a block).
        index: usize,
        /// How many exist (unknowns of the problem, or of the block).
        len: usize,
    },
    /// An auxiliary unknown id that this problem did not issue.
    #[error("auxiliary unknown {aux} does not exist ({len} declared)")]
    UnknownAux {
        /// The auxiliary index asked for.
        aux: usize,
        /// Number of auxiliary unknowns declared.
        len: usize,
    },
    /// A slice has the wrong length.
    #[error("{what}: expected {expected} entries, found {found}")]
    Dimension {
        /// Which slice ("residual output", "block values", "weights", …).
        what: &'static str,
        /// Entries expected.
        expected: usize,
        /// Entries given.
        found: usize,
    },
    /// A lower bound is above its upper bound.
    #[error(
        "unknown {unknown}: lower bound {} is above upper bound {}",
        Readable(*lower),
        Readable(*upper)
    )]
    InvalidBounds {
        /// The unknown (flat index).
        unknown: usize,
        /// Lower bound.
        lower: f64,
        /// Upper bound.
        upper: f64,
    },
    /// A weight of the minimum-norm metric is zero or negative.
    #[error("weight {index} is not positive ({})", Readable(*value))]
    NonPositiveWeight {
        /// Index of the reduced unknown (or of the weight in the slice given).
        index: usize,
        /// The weight.
        value: f64,
    },
    /// A substitution refers to an unknown that is itself substituted (substitutions do not
    /// chain).
    #[error(
        "unknown {unknown} is substituted in terms of unknown {referenced}, itself substituted"
    )]
    SubstitutionChain {
        /// The substituted unknown (flat index).
        unknown: usize,
        /// The unknown it refers to (flat index).
        referenced: usize,
    },
    /// A residual that is not affine: only the linear solver exists so far.
    #[error("{constraint} ({name}) is not affine; the nonlinear solver is not available yet")]
    NonlinearNotAvailable {
        /// The constraint owning the residual.
        constraint: ConstraintId,
        /// The residual's name.
        name: String,
    },
    /// Dependent constraint rows whose right-hand sides contradict the independent rows.
    #[error("conflicting constraints: {}", constraint_list(constraints))]
    Conflicting {
        /// The constraints owning an inconsistent dependent row, in row order.
        constraints: Vec<ConstraintId>,
    },
    /// No solver met every constraint, and nothing proves that they conflict: the
    /// least-squares search stopped where its residual still has a component along the range
    /// of the Jacobian (it could go on decreasing), so the constraints may well be consistent
    /// from another start. Not [`Error::Conflicting`], which needs that proof.
    #[error(
        "not solved: {tried}; largest residuals: {}",
        worst_residuals(residuals)
    )]
    NotSolved {
        /// The solvers tried and how each ended.
        tried: String,
        /// Each constraint's largest |g| where the least-squares search stopped.
        residuals: Vec<crate::model::report::ConstraintResidual>,
        /// Where it stopped: the reduced unknowns, in the order of the problem's
        /// [`crate::ReducedMap`]. The problem keeps its values; a caller who wants the
        /// compromise applies it with `problem.apply_reduced(&problem.reduced_map()?, &z)`.
        best_effort: Vec<f64>,
    },
    /// The solve spent every evaluation its budget allowed
    /// ([`crate::NonlinearOptions::max_evaluations`], [`crate::Problem::start_budget`]).
    /// The solve paths take it as their end; a caller sees it inside [`Error::NotSolved`]'s
    /// account of what was tried, or alone from a path run outside the selection.
    #[error("the budget of {evaluations} evaluations is spent")]
    BudgetSpent {
        /// The evaluations the budget allowed.
        evaluations: usize,
    },
    /// The caller cancelled the solve ([`crate::CancelFlag`], set from another
    /// thread, e.g. on Ctrl-C in Python): it stopped at its next evaluation; nothing was
    /// written back.
    #[error("the solve was cancelled")]
    Cancelled,
    /// Consistent but dependent rows while the options forbid dropping them.
    #[error("redundant constraints: {}", constraint_list(constraints))]
    Redundant {
        /// The constraints owning a consistent dependent row, in row order.
        constraints: Vec<ConstraintId>,
    },
    /// The Cholesky factorization of J·W⁻¹·Jᵀ failed: J does not have full row rank (numerically).
    #[error("J·W⁻¹·Jᵀ ({rows}×{rows}) is not positive definite: the rows are dependent")]
    RankDeficient {
        /// Number of rows of J.
        rows: usize,
    },
    /// A residual evaluated to NaN or infinity.
    #[error(
        "{constraint} ({name}): residual row {row} is not finite ({})",
        Readable(*value)
    )]
    NonFiniteResidual {
        /// The owning constraint.
        constraint: ConstraintId,
        /// The residual's name.
        name: String,
        /// Row inside the residual block.
        row: usize,
        /// The value.
        value: f64,
    },
    /// After the solve some residuals are still above the tolerance; nothing was written back.
    #[error("constraints not satisfied after the solve: {}", failed_list(failed))]
    NotSatisfied {
        /// Each failing constraint with its largest absolute residual.
        failed: Vec<(ConstraintId, f64)>,
    },
    /// The solution leaves an unknown outside its bounds; nothing was written back. For an
    /// auxiliary unknown, `unknown` is its index among the reduced unknowns.
    #[error(
        "unknown {unknown} would move to {}, outside [{}, {}]",
        Readable(*value),
        Readable(*lower),
        Readable(*upper)
    )]
    OutOfBounds {
        /// The unknown (flat index).
        unknown: usize,
        /// The value the solve produced.
        value: f64,
        /// Lower bound.
        lower: f64,
        /// Upper bound.
        upper: f64,
    },
    /// An autodiff Jacobian entry disagrees with central differences (see the `testing`
    /// feature).
    #[error(
        "{name}: Jacobian entry (row {row}, block {block}, column {column}) is {} by \
         autodiff but {} by central differences",
        Readable(*autodiff),
        Readable(*central)
    )]
    JacobianMismatch {
        /// The residual's name.
        name: String,
        /// Row of the residual.
        row: usize,
        /// Block (position in the slice of blocks read).
        block: usize,
        /// Column inside the block.
        column: usize,
        /// The autodiff value.
        autodiff: f64,
        /// The central-difference value.
        central: f64,
    },
    /// A residual was given blocks of another count or length than it declares
    /// ([`crate::Residual::block_sizes`]); nothing was added.
    #[error(
        "residual \"{residual}\" of {owner} reads blocks of lengths {expected:?} but was given {found:?}"
    )]
    BlockShape {
        /// The residual's name.
        residual: String,
        /// The constraint it belongs to.
        owner: ConstraintId,
        /// The block lengths it declares.
        expected: Vec<usize>,
        /// The lengths of the blocks given.
        found: Vec<usize>,
    },
    /// The solver asked for was not built into this crate (a cargo feature is off).
    #[error("{solver} is not available: {reason}")]
    SolverUnavailable {
        /// The solver ("SLSQP").
        solver: &'static str,
        /// Why ("built without the `nlopt` feature").
        reason: &'static str,
    },
    /// An iterative solver stopped before the residuals came within tolerance; nothing was
    /// written back.
    #[error(
        "{solver} did not converge in {iterations} iterations (max |g| = {})",
        Readable(*max_residual)
    )]
    NotConverged {
        /// The solver ("Newton", "Levenberg–Marquardt").
        solver: &'static str,
        /// Iterations run.
        iterations: usize,
        /// The largest absolute residual reached.
        max_residual: f64,
    },
    /// A problem lies outside what a solver supports, so it was not handed to it (SLSQP
    /// needs at most as many equality rows as unknowns and a dense workspace of a bounded
    /// size; see [`crate::model::nonlinear::SLSQP_MAX_UNKNOWNS`]).
    #[error("{solver} cannot take {rows} equality rows over {unknowns} unknowns: {why}")]
    OutsideSolverLimits {
        /// The solver ("SLSQP").
        solver: &'static str,
        /// Unknowns of the problem as handed over.
        unknowns: usize,
        /// Equality rows of the problem as handed over.
        rows: usize,
        /// Which limit is exceeded.
        why: &'static str,
    },
    /// An external optimizer reported a failure; nothing was written back.
    #[error("{solver} failed: {detail}")]
    OptimizerFailed {
        /// The solver ("SLSQP").
        solver: &'static str,
        /// What the optimizer said.
        detail: String,
    },
}

/// Result with camber-solve's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;

/// The constraints above 1e-9 in `residuals`, largest first, at most five, as text.
/// "4, 7 and 9": constraint numbers in plain words.
fn constraint_list(constraints: &[ConstraintId]) -> String {
    let ids: Vec<String> = constraints.iter().map(|c| c.0.to_string()).collect();
    match ids.split_last() {
        None => "none".to_owned(),
        Some((last, [])) => last.clone(),
        Some((last, rest)) => format!("{} and {last}", rest.join(", ")),
    }
}

/// "constraint 4 |g| = 2.350e0, constraint 5 |g| = …".
fn failed_list(failed: &[(ConstraintId, f64)]) -> String {
    failed
        .iter()
        .map(|(c, g)| format!("{c} |g| = {g:.3e}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Checks that a slice has the expected length.
pub(crate) fn check_len(what: &'static str, expected: usize, found: usize) -> Result<()> {
    if expected == found {
        Ok(())
    } else {
        Err(Error::Dimension {
            what,
            expected,
            found,
        })
    }
}

fn worst_residuals(residuals: &[crate::model::report::ConstraintResidual]) -> String {
    let mut worst: Vec<&crate::model::report::ConstraintResidual> = residuals
        .iter()
        .filter(|r| r.max_abs > 1e-9 || r.max_abs.is_nan())
        .collect();
    worst.sort_by(|a, b| b.max_abs.total_cmp(&a.max_abs));
    let shown: Vec<String> = worst
        .iter()
        .take(5)
        .map(|r| format!("constraint {} |g| = {:.3e}", r.constraint.0, r.max_abs))
        .collect();
    if shown.is_empty() {
        "none above 1e-9".to_owned()
    } else {
        shown.join(", ")
    }
}
