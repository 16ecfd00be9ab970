//! The model: what a problem is, before anything solves it. Parameter blocks of unknowns with
//! their bindings, bounds and weights ([`Problem`]), the residual traits a constraint
//! implements ([`Residual`], [`DynResidual`]), ids, options, the evaluation budget, priority
//! tiers, errors and reports.
//!
//! It imports nothing above it: the derivatives, the linear algebra, the analysis, the solvers
//! and the policy all stand on it.

pub(crate) mod budget;
pub(crate) mod errors;
pub(crate) mod ids;
pub mod nonlinear;
pub(crate) mod objective;
pub(crate) mod options;
pub(crate) mod priority;
pub(crate) mod problem;
pub(crate) mod report;
pub(crate) mod residual;
pub mod scalar;

pub use errors::{Error, Result};
pub use ids::{AuxId, BlockId, ConstraintId, ResidualId, UnknownId, Var};
pub use nonlinear::{
    slsqp_supports, NonlinearOptions, SolverChoice, DEFAULT_MAX_EVALUATIONS,
    DEFAULT_SEARCH_BOX_RELATIVE, SLSQP_MAX_UNKNOWNS,
};
pub use objective::{Objective, UserObjective};
pub use options::{CancelFlag, Options};
pub use priority::Priority;
pub use problem::{Binding, Problem, ProblemState, Stamps};
pub use report::{ConstraintResidual, Selection, SolveReport, SolverKind, Status, TierOutcome};
pub use residual::{DynResidual, Residual};
pub use scalar::Scalar;
