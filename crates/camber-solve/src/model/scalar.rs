//! The numeric bound residuals are generic over, and helpers around it.
//!
//! This is camber-scalar's [`Scalar`] (`nalgebra::RealField + Copy`, blanket implemented),
//! re-exported so that residuals and curve evaluations share one bound: a residual generic over
//! `T: camber_solve::Scalar` can evaluate any camber-geom curve at `T`. The solver knows nothing
//! of curves and does not depend on the geometry crate.
//!
//! ```
//! use camber_solve::Scalar;
//! fn cube<T: Scalar>(x: T) -> T { x * x * x }
//! assert!((cube(2.0_f64) - 8.0).abs() < 1e-15);
//! let c: f64 = camber_solve::scalar::cst(1.5);
//! assert!((camber_solve::scalar::re(c) - 1.5).abs() < 1e-15);
//! ```

pub use camber_scalar::{cst, from_usize, is_finite, re, Readable, Scalar};
