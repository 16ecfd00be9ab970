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
//! - Unknowns are reduced by an affine map x = A·z + c (fixed, merged and eliminated unknowns,
//!   see [`problem`] and [`reduced`]); solves run over z with a diagonal weight W.
//! - [`Residual`] is generic; its object-safe face [`DynResidual`] is blanket implemented and is
//!   what the problem stores. Dual types stay inside [`autodiff`].
//! - Jacobians are assembled sparse ([`SparseMatrix`]); the minimum-norm step
//!   ([`MinNormFactorization`]) is dense for small problems and sparse (faer) for large ones.
//! - Every fallible call returns [`Result`]; [`solve_linear`] never changes the problem on error.
//! - [`solve_linear`] handles affine residuals only (nonlinear ones are refused with
//!   [`Error::NonlinearNotAvailable`]); [`solve()`] selects the path from the DOF analysis:
//!   linear, Newton minimum-norm with the pull-back toward the start, SLSQP through NLopt
//!   (feature `nlopt`, on by default), and on request a soft least-squares compromise for
//!   conflicting systems.

mod accidental;
pub mod analysis;
pub mod autodiff;
mod block_analysis;
mod budget;
pub mod composed;
mod envelope;
pub mod errors;
mod free_columns;
mod held_step;
pub mod hessian;
pub mod ids;
pub mod linear;
pub mod lsq;
pub mod min_norm;
pub mod normal;
pub mod options;
pub mod priority;
pub mod problem;
pub(crate) mod projected_cg;
pub mod reduced;
pub mod report;
pub mod residual;
pub mod scalar;
pub mod sparse;
pub mod structure;
#[cfg(feature = "testing")]
pub mod testing;

pub use analysis::{Dependency, DofAnalysis};
pub use errors::{Error, Result};
pub use ids::{AuxId, BlockId, ConstraintId, ResidualId, UnknownId, Var};
pub use linear::solve_linear;
pub use lsq::{solve_least_squares, LsqOptions, LsqReport};
pub use min_norm::MinNormFactorization;
pub use normal::NormalCache;
pub use options::{CancelFlag, Options};
pub use priority::Priority;
pub use problem::{Binding, Problem, ProblemState};
pub use reduced::{Linearization, ReducedMap};
pub use report::{ConstraintResidual, Selection, SolveReport, SolverKind, Status, TierOutcome};
pub use residual::{DynResidual, Residual};
pub use scalar::Scalar;
pub use sparse::SparseMatrix;
pub(crate) mod evaluator;
pub(crate) mod lu_triangles;
pub mod newton;
pub mod nonlinear;
pub mod objective;
pub mod selection;
#[cfg(feature = "nlopt")]
pub(crate) mod slsqp;
pub(crate) mod soft;
pub(crate) mod sparse_lu;
pub(crate) mod square;
pub use newton::NewtonWorkspace;
pub use nonlinear::{NonlinearOptions, SolverChoice};
pub use objective::{Objective, UserObjective};
pub use selection::{solve, solve_newton, solve_newton_from};
