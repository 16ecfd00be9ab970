//! Conformance checks for user residuals (feature `testing`).
//!
//! [`check_jacobian`] compares the autodiff Jacobian of a [`Residual`] (as the solvers compute
//! it, after [`Residual::depends_on`]) with central differences
//! (g(x + h·e_k) − g(x − h·e_k)) / 2h, whose error is O(h²·|g‴|) plus O(ε·|g|/h) of rounding. The
//! error of an entry is |autodiff − central| / max(1, |autodiff|), so it is absolute for small
//! entries and relative for large ones.

use crate::derive::autodiff::jacobian_active;
use crate::model::errors::{Error, Result};
use crate::model::residual::Residual;

/// The worst Jacobian entry found by [`check_jacobian`].
#[derive(Debug, Clone, PartialEq)]
pub struct JacobianCheck {
    /// Row of the residual.
    pub row: usize,
    /// Block (position in the slice of blocks).
    pub block: usize,
    /// Column inside the block.
    pub column: usize,
    /// The autodiff value.
    pub autodiff: f64,
    /// The central-difference value.
    pub central: f64,
    /// The scaled error |autodiff − central| / max(1, |autodiff|).
    pub error: f64,
}

/// Checks the Jacobian of `residual` at `x` against central differences of step `step`,
/// returning the worst entry, or [`Error::JacobianMismatch`] if its scaled error exceeds
/// `tolerance`. A residual with no columns or rows passes with a zero report.
///
/// ```
/// use camber_solve::{testing::check_jacobian, Residual, Scalar};
/// #[derive(Debug)]
/// struct Dist;
/// impl Residual for Dist {
///     fn name(&self) -> &str { "distance" }
///     fn dim(&self) -> usize { 1 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
///         let (dx, dy) = (x[1][0] - x[0][0], x[1][1] - x[0][1]);
///         out[0] = (dx * dx + dy * dy).sqrt();
///     }
/// }
/// let worst = check_jacobian(&Dist, &[&[0.0, 0.0][..], &[3.0, 4.0][..]], 1e-6, 1e-7)?;
/// assert!(worst.error < 1e-7);
/// # Ok::<(), camber_solve::Error>(())
/// ```
///
/// # Errors
/// [`Error::JacobianMismatch`]; [`Error::NonFinite`] for a non-finite input or a step that is
/// not positive and finite.
pub fn check_jacobian<R: Residual>(
    residual: &R,
    x: &[&[f64]],
    step: f64,
    tolerance: f64,
) -> Result<JacobianCheck> {
    if !(step.is_finite() && step > 0.0) {
        return Err(Error::NonFinite {
            what: "difference step",
            index: 0,
            value: step,
        });
    }
    let mut flat: Vec<f64> = x.iter().flat_map(|b| b.iter().copied()).collect();
    if let Some((index, v)) = flat.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Err(Error::NonFinite {
            what: "input",
            index,
            value: *v,
        });
    }
    let dim = residual.dim();
    let n = flat.len();
    let mut values = vec![0.0; dim];
    let mut jac = vec![0.0; dim * n];
    // The Jacobian the solvers use: a `depends_on` that drops a block g does depend on shows
    // up as a zero column against a non-zero difference.
    jacobian_active(residual, x, &vec![true; x.len()], &mut values, &mut jac)?;
    let lens: Vec<usize> = x.iter().map(|b| b.len()).collect();
    let mut worst = JacobianCheck {
        row: 0,
        block: 0,
        column: 0,
        autodiff: 0.0,
        central: 0.0,
        error: 0.0,
    };
    let (mut plus, mut minus) = (vec![0.0; dim], vec![0.0; dim]);
    let (mut block, mut column) = (0, 0);
    for k in 0..n {
        while lens.get(block).is_some_and(|l| column >= *l) {
            block += 1;
            column = 0;
        }
        let x0 = flat[k];
        flat[k] = x0 + step;
        eval_flat(residual, &flat, &lens, &mut plus);
        flat[k] = x0 - step;
        eval_flat(residual, &flat, &lens, &mut minus);
        flat[k] = x0;
        for row in 0..dim {
            let central = (plus[row] - minus[row]) / (2.0 * step);
            let autodiff = jac[row * n + k];
            let error = (autodiff - central).abs() / autodiff.abs().max(1.0);
            if error > worst.error || error.is_nan() {
                worst = JacobianCheck {
                    row,
                    block,
                    column,
                    autodiff,
                    central,
                    error,
                };
            }
        }
        column += 1;
    }
    if worst.error > tolerance || worst.error.is_nan() {
        return Err(Error::JacobianMismatch {
            name: residual.name().to_owned(),
            row: worst.row,
            block: worst.block,
            column: worst.column,
            autodiff: worst.autodiff,
            central: worst.central,
        });
    }
    Ok(worst)
}

fn eval_flat<R: Residual>(residual: &R, flat: &[f64], lens: &[usize], out: &mut [f64]) {
    let mut slices: Vec<&[f64]> = Vec::with_capacity(lens.len());
    let mut rest = flat;
    for len in lens {
        let (head, tail) = rest.split_at(*len);
        slices.push(head);
        rest = tail;
    }
    residual.eval(&slices, out);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::scalar::Scalar;

    /// A residual whose eval is right but whose is meant to be compared: sin(x)·y² and x/y.
    #[derive(Debug)]
    struct Smooth;

    impl Residual for Smooth {
        fn name(&self) -> &str {
            "smooth"
        }
        fn dim(&self) -> usize {
            2
        }
        fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
            out[0] = x[0][0].sin() * x[1][0] * x[1][0];
            out[1] = x[0][0] / x[1][0];
        }
    }

    /// A residual that branches on the scalar's real part so its derivative is discontinuous:
    /// |x| at x = 0 has no central-difference derivative equal to the one-sided autodiff value.
    #[derive(Debug)]
    struct Kink;

    impl Residual for Kink {
        fn name(&self) -> &str {
            "kink"
        }
        fn dim(&self) -> usize {
            1
        }
        fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
            out[0] = if crate::model::scalar::re(x[0][0]) >= 0.0 {
                x[0][0]
            } else {
                -x[0][0]
            };
        }
    }

    #[test]
    fn smooth_residual_passes() {
        let worst = check_jacobian(&Smooth, &[&[0.7][..], &[1.3][..]], 1e-6, 1e-8).unwrap();
        assert!(worst.error < 1e-8);
    }

    #[test]
    fn kink_is_reported_with_its_entry() {
        let err = check_jacobian(&Kink, &[&[0.0][..]], 1e-6, 1e-6).unwrap_err();
        match err {
            Error::JacobianMismatch {
                name,
                row,
                block,
                column,
                autodiff,
                central,
            } => {
                assert_eq!((name.as_str(), row, block, column), ("kink", 0, 0, 0));
                assert!((autodiff - 1.0).abs() < 1e-15 && central.abs() < 1e-9);
            }
            other => panic!("unexpected {other:?}"),
        }
        assert!(check_jacobian(&Kink, &[&[1.0][..]], 0.0, 1e-6).is_err());
    }
}
