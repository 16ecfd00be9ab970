//! The numeric bound every evaluator is generic over: camber-scalar's [`Scalar`] and its helpers,
//! re-exported so that `camber_geom::Scalar` and `camber_solve::Scalar` are one trait.
//!
//! [`Scalar`] is blanket-implemented for every `nalgebra::RealField + Copy` type, so `f64` and the
//! forward-mode dual numbers of num-dual run through exactly the same code.
//!
//! ```
//! use camber_geom::Scalar;
//! fn square<T: Scalar>(x: T) -> T { x * x }
//! assert!((square(3.0_f64) - 9.0).abs() < 1e-15);
//! let half: f64 = camber_geom::scalar::cst(0.5);
//! assert!((camber_geom::scalar::re(half) - 0.5).abs() < 1e-15);
//! ```

pub use camber_scalar::{cst, from_usize, is_finite, re, Scalar};
