//! Exact derivatives of residuals: Jacobians by forward dual numbers ([`autodiff`]), weighted
//! Hessians by hyper-dual numbers ([`hessian`]), the chain rule for a residual composed of a
//! small function of a curve's point and derivatives ([`composed`]), and the blanket
//! implementation that turns every [`crate::Residual`] into the object-safe
//! [`crate::DynResidual`] a problem stores.
//!
//! It stands on `model` only; dual types never leave it.

pub mod autodiff;
pub mod composed;
pub(crate) mod dyn_residual;
pub mod hessian;
#[cfg(feature = "testing")]
pub mod testing;
