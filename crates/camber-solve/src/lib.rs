//! camber-solve: constraint problems over parameter blocks, solved by minimum-norm steps.
//!
//! A [`Problem`] owns a flat vector of unknowns organised in parameter blocks, and residual
//! blocks that read some of them. A constraint is written once as a [`Residual`], generically
//! over the scalar type; its exact Jacobian comes from forward-mode dual numbers. The linear
//! solver moves the unknowns by the smallest weighted displacement that satisfies every affine
//! constraint, after a rank analysis that counts the degrees of freedom and names redundant and
//! conflicting constraints. This crate knows nothing of curves.
//!
//! ```
//! use camber_solve::{ConstraintId, Options, Problem, Residual, Scalar, solve_linear};
//!
//! /// The midpoint of two points (blocks a and b) lies at the origin: two rows.
//! #[derive(Debug)]
//! struct MidpointAtOrigin;
//! impl Residual for MidpointAtOrigin {
//!     fn name(&self) -> &str { "midpoint at origin" }
//!     fn dim(&self) -> usize { 2 }
//!     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
//!         out[0] = x[0][0] + x[1][0];
//!         out[1] = x[0][1] + x[1][1];
//!     }
//!     fn is_affine(&self) -> bool { true }
//! }
//!
//! let mut p = Problem::new();
//! let a = p.add_block(&[1.0, 1.0])?;
//! let b = p.add_block(&[3.0, -1.0])?;
//! p.add_residual(MidpointAtOrigin, &[a, b], ConstraintId(1))?;
//! let report = solve_linear(&mut p, &Options::default())?;
//! // Both points move by the same amount, −(2, 0) each.
//! assert!((p.values()[0] + 1.0).abs() < 1e-12 && (p.values()[2] - 1.0).abs() < 1e-12);
//! assert_eq!(report.dof, 2);
//! # Ok::<(), camber_solve::Error>(())
//! ```
//!
//! # Design
//! The crate is six layers, each importing only the ones before it (docs/architecture.md
//! draws them, and a test reads the sources to keep it so):
//!
//! 1. [`model`]: problems, ids, options, budget, reports, errors, the residual traits;
//! 2. [`mod@derive`]: exact Jacobians and Hessians by dual numbers, the chain rule of composed
//!    residuals, the blanket [`DynResidual`] face of every [`Residual`];
//! 3. `linalg`: sparse matrices, the reduced map x = A·z + c, the evaluator, the minimum-norm
//!    step, band and LU factorizations, projected conjugate gradients;
//! 4. `analysis`: the DOF analysis (rank, redundant and conflicting rows, free unknowns);
//! 5. `solvers`: linear, Newton, SLSQP, least squares, soft, priority tiers;
//! 6. [`policy`]: the one decision of which solver runs, validation and write-back.
//!
//! Only `model`, `derive` and `policy` are public; what users need from the others is
//! re-exported here.
//!
//! - Unknowns are reduced by an affine map x = A·z + c (fixed, merged and eliminated unknowns,
//!   see [`Problem`] and [`ReducedMap`]); solves run over z with a diagonal weight W.
//! - [`Residual`] is generic; its object-safe face [`DynResidual`] is blanket implemented and is
//!   what the problem stores. Dual types stay inside [`mod@derive`].
//! - Jacobians are assembled sparse ([`SparseMatrix`]); the minimum-norm step is dense for
//!   small problems and sparse (faer) for large ones.
//! - Every fallible call returns [`Result`]; [`solve_linear`] never changes the problem on error.
//! - [`solve_linear`] handles affine residuals only (nonlinear ones are refused with
//!   [`Error::NonlinearNotAvailable`]); [`solve()`] selects the path from the DOF analysis:
//!   linear, Newton minimum-norm with the pull-back toward the start, SLSQP through NLopt
//!   (feature `nlopt`, on by default), and on request a soft least-squares compromise for
//!   conflicting systems.

pub mod derive;
pub mod model;
pub mod policy;

mod analysis;
mod linalg;
mod solvers;

#[cfg(feature = "testing")]
pub use derive::testing;
pub use model::scalar;

pub use model::{
    slsqp_supports, AuxId, Binding, BlockId, CancelFlag, ConstraintId, ConstraintResidual,
    DynResidual, Error, NonlinearOptions, Objective, Options, Priority, Problem, ProblemState,
    Residual, ResidualId, Result, Scalar, Selection, SolveReport, SolverChoice, SolverKind, Stamps,
    Status, TierOutcome, UnknownId, UserObjective, Var, DEFAULT_MAX_EVALUATIONS,
    DEFAULT_SEARCH_BOX_RELATIVE, SLSQP_MAX_UNKNOWNS,
};
pub use policy::{solve, solve_linear, solve_newton, solve_newton_from, Plan, Start};

pub use analysis::structure;
pub use analysis::{
    analyze, analyze_rows, analyze_rows_sparse, mobility, multipliers, Dependency, DependentRow,
    DofAnalysis, Mobility, RowAnalysis, StructureSummary, DENSE_ANALYSIS_MAX_ENTRIES,
};
pub use linalg::min_norm::MinNormFactorization;
pub use linalg::reduced::{Linearization, ReducedMap};
pub use linalg::sparse::SparseMatrix;
pub use solvers::lsq::{solve_least_squares, LsqOptions, LsqReport};
pub use solvers::newton::NewtonWorkspace;
