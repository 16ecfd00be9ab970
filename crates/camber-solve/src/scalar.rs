//! The numeric bound residuals are generic over, and two helpers around it.
//!
//! [`Scalar`] has the same shape as `camber_geom::Scalar` (`nalgebra::RealField + Copy`, blanket
//! implemented), so any type meeting one meets the other; a later step unifies them by
//! re-exporting a single trait. camber-solve defines its own so that it does not depend on the
//! geometry crate: it knows nothing of curves.

use nalgebra::RealField;

/// The scalar type a residual is evaluated in: `f64` for values, a forward-mode dual number
/// (chosen inside this crate) for Jacobians.
///
/// ```
/// use camber_solve::Scalar;
/// fn cube<T: Scalar>(x: T) -> T { x * x * x }
/// assert!((cube(2.0_f64) - 8.0).abs() < 1e-15);
/// ```
pub trait Scalar: RealField + Copy {}

impl<T: RealField + Copy> Scalar for T {}

/// Converts an `f64` constant into `T` (a dual number gets a zero derivative part).
///
/// ```
/// let c: f64 = camber_solve::scalar::cst(1.5);
/// assert!((c - 1.5).abs() < 1e-15);
/// ```
#[inline]
pub fn cst<T: Scalar>(c: f64) -> T {
    nalgebra::convert::<f64, T>(c)
}

/// The real part of `x` as `f64` (the value itself for `f64`). Use it for branches that must not
/// depend on derivative parts.
///
/// ```
/// assert!((camber_solve::scalar::re(2.5_f64) - 2.5).abs() < 1e-15);
/// ```
#[inline]
pub fn re<T: Scalar>(x: T) -> f64 {
    x.to_subset().unwrap_or(f64::NAN)
}
