//! The linear algebra of the solvers: sparse matrices ([`sparse`]), the reduced map
//! x = A·z + c and the linearization of a problem ([`reduced`]), the evaluator of a whole
//! problem's residuals, Jacobian and Hessian ([`evaluator`]), the weighted minimum-norm step
//! ([`min_norm`]) over the normal equations ([`normal`], band [`envelope`]), the LU of a square
//! Jacobian ([`square`], [`sparse_lu`], [`lu_triangles`]), the projected conjugate gradients of
//! Newton's second-order step ([`projected_cg`]) and the exact Gauss–Newton step of a priority
//! tier ([`held_step`]).
//!
//! It stands on `model` and `derive`, and decides nothing: which factorization or solver runs is
//! the business of the layers above.

pub(crate) mod envelope;
pub(crate) mod evaluator;
pub(crate) mod held_step;
pub(crate) mod lu_triangles;
pub(crate) mod min_norm;
pub(crate) mod normal;
pub(crate) mod projected_cg;
pub(crate) mod reduced;
pub(crate) mod sparse;
pub(crate) mod sparse_lu;
pub(crate) mod square;
