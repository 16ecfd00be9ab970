//! The blanket implementation of [`DynResidual`] for every [`Residual`]: values with `f64`,
//! exact Jacobians by forward dual numbers ([`crate::derive::autodiff`]) and weighted Hessians
//! by hyper-dual numbers ([`crate::derive::hessian`]); and the shared form `Arc<R>`.

use std::any::Any;

use crate::derive::autodiff::{self, JacobianMode};
use crate::model::errors::{Error, Result};
use crate::model::residual::{DynResidual, Residual};

impl<R: Residual> DynResidual for R {
    fn name(&self) -> &str {
        Residual::name(self)
    }

    fn dim(&self) -> usize {
        Residual::dim(self)
    }

    fn block_sizes(&self) -> Option<Vec<usize>> {
        Residual::block_sizes(self)
    }

    fn accepts_block_sizes(&self, sizes: &[usize]) -> bool {
        Residual::accepts_block_sizes(self, sizes)
    }

    fn is_affine(&self) -> bool {
        Residual::is_affine(self)
    }

    fn values(&self, x: &[&[f64]], out: &mut [f64]) -> Result<()> {
        let dim = Residual::dim(self);
        if out.len() != dim {
            return Err(Error::Dimension {
                what: "residual output",
                expected: dim,
                found: out.len(),
            });
        }
        self.eval(x, out);
        Ok(())
    }

    fn jacobian(&self, x: &[&[f64]], values: &mut [f64], jac: &mut [f64]) -> Result<()> {
        autodiff::jacobian_with(self, x, values, jac, JacobianMode::Auto)
    }

    fn jacobian_active(
        &self,
        x: &[&[f64]],
        active: &[bool],
        values: &mut [f64],
        jac: &mut [f64],
    ) -> Result<()> {
        autodiff::jacobian_active(self, x, active, values, jac)
    }

    fn weighted_hessian(
        &self,
        x: &[&[f64]],
        weights: &[f64],
        active: &[bool],
        out: &mut [f64],
    ) -> Result<bool> {
        crate::derive::hessian::weighted_hessian(self, x, weights, active, out)?;
        Ok(true)
    }

    fn as_any(&self) -> &dyn Any {
        self
    }
}

/// A shared residual is a residual: one object can sit in several problems (a sketch builds a
/// component's problem from the same constraint objects at every solve).
impl<R: DynResidual + ?Sized> DynResidual for std::sync::Arc<R> {
    fn name(&self) -> &str {
        (**self).name()
    }
    fn dim(&self) -> usize {
        (**self).dim()
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        (**self).block_sizes()
    }
    fn accepts_block_sizes(&self, sizes: &[usize]) -> bool {
        (**self).accepts_block_sizes(sizes)
    }
    fn is_affine(&self) -> bool {
        (**self).is_affine()
    }
    fn values(&self, x: &[&[f64]], out: &mut [f64]) -> Result<()> {
        (**self).values(x, out)
    }
    fn jacobian(&self, x: &[&[f64]], values: &mut [f64], jac: &mut [f64]) -> Result<()> {
        (**self).jacobian(x, values, jac)
    }
    fn jacobian_active(
        &self,
        x: &[&[f64]],
        active: &[bool],
        values: &mut [f64],
        jac: &mut [f64],
    ) -> Result<()> {
        (**self).jacobian_active(x, active, values, jac)
    }
    fn weighted_hessian(
        &self,
        x: &[&[f64]],
        weights: &[f64],
        active: &[bool],
        out: &mut [f64],
    ) -> Result<bool> {
        (**self).weighted_hessian(x, weights, active, out)
    }
    fn as_any(&self) -> &dyn Any {
        (**self).as_any()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::scalar::Scalar;
    use approx::assert_relative_eq;

    /// g = (x0·y0 − 1, sin(x1) + y0²): nonlinear, two blocks.
    #[derive(Debug)]
    struct Mixed;

    impl Residual for Mixed {
        fn name(&self) -> &str {
            "mixed"
        }
        fn dim(&self) -> usize {
            2
        }
        fn block_sizes(&self) -> Option<Vec<usize>> {
            Some(vec![2, 1])
        }
        fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
            out[0] = x[0][0] * x[1][0] - T::one();
            out[1] = x[0][1].sin() + x[1][0] * x[1][0];
        }
    }

    #[test]
    fn dyn_face_gives_values_and_exact_jacobian() {
        let r: Box<dyn DynResidual> = Box::new(Mixed);
        let (a, b) = ([2.0, 0.5], [3.0]);
        let x = [&a[..], &b[..]];
        let mut g = [0.0; 2];
        let mut j = [0.0; 6];
        r.jacobian(&x, &mut g, &mut j).unwrap();
        assert_relative_eq!(g[0], 5.0);
        assert_relative_eq!(g[1], 0.5_f64.sin() + 9.0);
        // columns: x0, x1, y0
        let expected = [3.0, 0.0, 2.0, 0.0, 0.5_f64.cos(), 6.0];
        for (got, want) in j.iter().zip(expected) {
            assert_relative_eq!(*got, want, epsilon = 1e-15);
        }
        assert!(!r.is_affine());
        assert_eq!(r.name(), "mixed");
        assert!(r.as_any().downcast_ref::<Mixed>().is_some());
    }

    #[test]
    fn wrong_output_length_is_an_error() {
        let r: Box<dyn DynResidual> = Box::new(Mixed);
        let x = [&[1.0, 2.0][..], &[3.0][..]];
        let mut g = [0.0; 3];
        assert_eq!(
            r.values(&x, &mut g),
            Err(Error::Dimension {
                what: "residual output",
                expected: 2,
                found: 3
            })
        );
    }
}
