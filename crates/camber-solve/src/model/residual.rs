//! Residuals: the generic trait a user implements once, and its object-safe face.
//!
//! A residual block reads some parameter blocks x₁, …, x_k (one slice each) and writes `dim()`
//! values g(x₁, …, x_k). The user writes [`Residual::eval`] generically over [`Scalar`]; the
//! blanket implementation of [`DynResidual`] evaluates it with `f64` for values and with
//! forward-mode dual numbers for the exact Jacobian ∂g/∂x_b of every block (see
//! [`crate::derive::autodiff`]). Users never name a dual type.

use std::any::Any;
use std::fmt::Debug;

use crate::model::errors::Result;
use crate::model::scalar::Scalar;

/// A user constraint written once, generically over the scalar type.
///
/// `x` holds one slice per parameter block the residual reads, in the order given to
/// [`crate::Problem::add_residual`]; `out` has exactly [`Residual::dim`] entries.
///
/// **Block shapes are declared, and checked once.** [`Residual::block_sizes`] says how many
/// blocks the residual reads and how long each is. [`crate::Problem::add_residual`] compares
/// that with the blocks it is given and refuses a mismatch with
/// [`crate::Error::BlockShape`] naming the residual; every later
/// evaluation through the problem then hands `eval` exactly those shapes, so `eval` may index
/// `x` and `out` freely. A residual that does not declare its blocks (`None`, the default)
/// cannot be checked and must cope with whatever blocks it is given; camber-sketch refuses
/// such residuals in custom constraints. `eval` must not branch on derivative parts (compare
/// real parts with [`crate::model::scalar::re`] if it branches at all).
///
/// ```
/// use camber_solve::{Residual, Scalar};
///
/// /// a·x − b = 0 for a single block x.
/// #[derive(Debug)]
/// struct Linear { a: Vec<f64>, b: f64 }
///
/// impl Residual for Linear {
///     fn name(&self) -> &str { "linear" }
///     fn dim(&self) -> usize { 1 }
///     fn block_sizes(&self) -> Option<Vec<usize>> { Some(vec![self.a.len()]) }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
///         let mut s = camber_solve::scalar::cst::<T>(-self.b);
///         for (ai, xi) in self.a.iter().zip(x[0]) {
///             s += camber_solve::scalar::cst::<T>(*ai) * *xi;
///         }
///         out[0] = s;
///     }
///     fn is_affine(&self) -> bool { true }
/// }
///
/// let r = Linear { a: vec![3.0, 4.0], b: 5.0 };
/// let mut g = [0.0_f64];
/// r.eval(&[&[1.0, 1.0][..]], &mut g);
/// assert!((g[0] - 2.0).abs() < 1e-15);
/// ```
pub trait Residual: Debug + Send + Sync + 'static {
    /// A short human-readable name used in reports ("coincident", "tangent at u", …).
    fn name(&self) -> &str;
    /// Number of rows (residual values) this block contributes.
    fn dim(&self) -> usize;
    /// The length of every block read, in order (`Some(vec![2, 2])` for two points): the
    /// problem refuses blocks of another count or length (see the trait documentation).
    /// `None` (the default) declares nothing and is not checked.
    fn block_sizes(&self) -> Option<Vec<usize>> {
        None
    }
    /// Whether blocks of the lengths `sizes` (in order) are what this residual reads: by
    /// default, whether they equal [`Residual::block_sizes`] (anything when that is `None`).
    /// A residual may answer the same question without building the list, which the problem
    /// otherwise allocates for every residual block it adds.
    fn accepts_block_sizes(&self, sizes: &[usize]) -> bool {
        self.block_sizes().is_none_or(|expected| expected == sizes)
    }
    /// Writes g(x) into `out` (`dim()` entries); `x` holds one slice per block read.
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]);
    /// Whether g is affine in the unknowns it reads (g(x) = M·x + b with M, b constant). Only
    /// affine residuals may use the linear solver.
    fn is_affine(&self) -> bool {
        false
    }
    /// Clears the entries of `blocks` (one per block of `x`, all true on entry) for the blocks
    /// g does not depend on near x: every derivative with respect to them is zero there, so
    /// Jacobians and Hessians skip them. A curve residual at a free parameter u reads every
    /// control point but depends only on the p + 1 of u's knot span. Optional: the default
    /// keeps every block, which is always correct.
    fn depends_on(&self, x: &[&[f64]], blocks: &mut [bool]) {
        let _ = (x, blocks);
    }
    /// The values and the active columns of the Jacobian by the residual's own structure,
    /// when it knows a cheaper exact way than dual numbers over all its unknowns (a curve
    /// residual composed of a small function of the curve's point and derivatives:
    /// [`crate::derive::composed`]). Same contract as [`crate::derive::autodiff::jacobian_active`], whose
    /// checked slices it receives; returns `false` (the default) to leave it to dual numbers.
    /// Built-in residuals only: a user residual keeps the default.
    fn structured_jacobian(
        &self,
        x: &[&[f64]],
        active: &[bool],
        values: &mut [f64],
        jac: &mut [f64],
    ) -> bool {
        let _ = (x, active, values, jac);
        false
    }
    /// H = Σᵢ λᵢ·∇²gᵢ(x) by the residual's own structure (see
    /// [`Residual::structured_jacobian`]). Same contract as
    /// [`crate::derive::hessian::weighted_hessian`], whose checked slices it receives; returns `false`
    /// (the default) to leave it to hyper-dual numbers.
    fn structured_hessian(
        &self,
        x: &[&[f64]],
        weights: &[f64],
        active: &[bool],
        out: &mut [f64],
    ) -> bool {
        let _ = (x, weights, active, out);
        false
    }
}

/// The object-safe face of a [`Residual`], stored by the problem as `Arc<dyn DynResidual>`.
///
/// Every [`Residual`] gets it through a blanket implementation. The Jacobian is written row
/// major, `dim()` rows by (Σ block lengths) columns, the columns of block 0 first.
pub trait DynResidual: Debug + Send + Sync {
    /// The residual's name.
    fn name(&self) -> &str;
    /// Number of rows.
    fn dim(&self) -> usize;
    /// The length of every block read, in order, when the residual declares them.
    fn block_sizes(&self) -> Option<Vec<usize>>;
    /// Whether blocks of the lengths `sizes` (in order) are what the residual reads
    /// (see [`Residual::accepts_block_sizes`]); by default, compared with
    /// [`DynResidual::block_sizes`].
    fn accepts_block_sizes(&self, sizes: &[usize]) -> bool {
        self.block_sizes().is_none_or(|expected| expected == sizes)
    }
    /// Whether the residual is affine in its unknowns.
    fn is_affine(&self) -> bool;
    /// Writes g(x) into `out`.
    ///
    /// # Errors
    /// [`crate::Error::Dimension`] when `out` does not have `dim()` entries.
    fn values(&self, x: &[&[f64]], out: &mut [f64]) -> Result<()>;
    /// Writes g(x) into `values` and ∂g/∂x into `jac` (row major, `dim()` × Σ|x_b|), by
    /// forward-mode automatic differentiation.
    ///
    /// # Errors
    /// [`crate::Error::Dimension`] when a slice has the wrong length.
    fn jacobian(&self, x: &[&[f64]], values: &mut [f64], jac: &mut [f64]) -> Result<()>;
    /// [`DynResidual::jacobian`] where only the columns of blocks whose `active` entry is true
    /// are needed (the others may be left at zero): the solvers never read the derivatives of
    /// fixed unknowns. The default computes every column; every [`Residual`] skips the inactive
    /// ones ([`crate::derive::autodiff::jacobian_active`]).
    ///
    /// # Errors
    /// [`crate::Error::Dimension`] for wrong slice lengths.
    fn jacobian_active(
        &self,
        x: &[&[f64]],
        active: &[bool],
        values: &mut [f64],
        jac: &mut [f64],
    ) -> Result<()> {
        let _ = active;
        self.jacobian(x, values, jac)
    }
    /// Writes H = Σᵢ λᵢ·∇²gᵢ(x) into `out` (row major, N × N with N = Σ|x_b|), leaving the
    /// rows and columns of blocks whose `active` entry is false at zero; `weights` holds λ.
    /// Returns whether second derivatives are available: the default says no (a residual that
    /// only implements this trait by hand), and the solvers then treat its H as zero, which
    /// slows Newton's convergence but not its result. Every [`Residual`] has them, by
    /// hyper-dual numbers ([`crate::derive::hessian`]).
    ///
    /// # Errors
    /// [`crate::Error::Dimension`] for wrong slice lengths.
    fn weighted_hessian(
        &self,
        x: &[&[f64]],
        weights: &[f64],
        active: &[bool],
        out: &mut [f64],
    ) -> Result<bool> {
        let _ = (x, weights, active, out);
        Ok(false)
    }
    /// The concrete residual, for downcasting.
    fn as_any(&self) -> &dyn Any;
}
