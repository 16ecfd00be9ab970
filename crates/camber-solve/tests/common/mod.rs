//! Residuals shared by the integration tests.
#![allow(dead_code)] // each test file uses a different subset

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use nalgebra::DMatrix;

/// g = M·x − b, x being the blocks read laid end to end.
#[derive(Debug, Clone)]
pub struct Affine {
    pub m: DMatrix<f64>,
    pub b: Vec<f64>,
}

impl Residual for Affine {
    fn name(&self) -> &str {
        "affine"
    }
    fn dim(&self) -> usize {
        self.m.nrows()
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        for (i, o) in out.iter_mut().enumerate() {
            let mut s = cst::<T>(-self.b[i]);
            for (j, xj) in x.iter().flat_map(|blk| blk.iter()).enumerate() {
                s += cst::<T>(self.m[(i, j)]) * *xj;
            }
            *o = s;
        }
    }
    fn is_affine(&self) -> bool {
        true
    }
}

/// One row a·x = b over the blocks read.
pub fn row(a: &[f64], b: f64) -> Affine {
    Affine {
        m: DMatrix::from_row_slice(1, a.len(), a),
        b: vec![b],
    }
}

/// A nonlinear residual: (|p − q|² − d², p_x·q_y − sin(q_x)).
#[derive(Debug)]
pub struct Nonlinear {
    pub d: f64,
}

impl Residual for Nonlinear {
    fn name(&self) -> &str {
        "nonlinear"
    }
    fn dim(&self) -> usize {
        2
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (dx, dy) = (x[1][0] - x[0][0], x[1][1] - x[0][1]);
        out[0] = dx * dx + dy * dy - cst(self.d * self.d);
        out[1] = x[0][0] * x[1][1] - x[1][0].sin();
    }
}
