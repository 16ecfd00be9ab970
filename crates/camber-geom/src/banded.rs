//! A small banded linear solver: Gaussian elimination with partial pivoting that touches only
//! the band, for the collocation and normal-equation systems of [`crate::fit`].
//!
//! A matrix whose non-zeros in row r lie in columns r − kl … r + ku needs O(n·kl·(kl + ku))
//! operations instead of the O(n³) of dense LU: for a B-spline system, kl and ku are about the
//! degree. Row exchanges within the kl rows below the pivot widen the upper band to kl + ku,
//! which the elimination allows for.

use nalgebra::DMatrix;

use crate::scalar::{re, Scalar};

/// Solves A X = B for a square `a` (dense storage, banded contents) and a right-hand side with
/// any number of columns. Returns `None` when a pivot is zero (A singular) or a value is not
/// finite.
///
/// ```
/// use camber_geom::banded::solve_banded;
/// use nalgebra::DMatrix;
/// // A tridiagonal system with solution (1, 2, 3).
/// let a = DMatrix::from_row_slice(3, 3, &[2.0_f64, 1.0, 0.0, 1.0, 2.0, 1.0, 0.0, 1.0, 2.0]);
/// let b = DMatrix::from_column_slice(3, 1, &[4.0, 8.0, 8.0]);
/// let x = solve_banded(a, b).unwrap();
/// assert!((x[0] - 1.0).abs() < 1e-14 && (x[1] - 2.0).abs() < 1e-14 && (x[2] - 3.0).abs() < 1e-14);
/// ```
pub fn solve_banded<T: Scalar>(mut a: DMatrix<T>, mut b: DMatrix<T>) -> Option<DMatrix<T>> {
    let n = a.nrows();
    if a.ncols() != n || b.nrows() != n {
        return None;
    }
    // Band widths from the contents.
    let (mut kl, mut ku) = (0usize, 0usize);
    for r in 0..n {
        for c in 0..n {
            if re(a[(r, c)]) != 0.0 {
                if r > c {
                    kl = kl.max(r - c);
                } else {
                    ku = ku.max(c - r);
                }
            }
        }
    }
    let width = kl + ku;
    for j in 0..n {
        // Pivot: the largest magnitude among rows j … j + kl.
        let last_row = (j + kl).min(n - 1);
        let mut pivot = j;
        for r in j + 1..=last_row {
            if re(a[(r, j)]).abs() > re(a[(pivot, j)]).abs() {
                pivot = r;
            }
        }
        if re(a[(pivot, j)]) == 0.0 || !re(a[(pivot, j)]).is_finite() {
            return None;
        }
        let last_col = (j + width).min(n - 1);
        if pivot != j {
            for c in j..=last_col {
                a.swap((j, c), (pivot, c));
            }
            b.swap_rows(j, pivot);
        }
        let p = a[(j, j)];
        for r in j + 1..=last_row {
            let factor = a[(r, j)] / p;
            if re(factor) == 0.0 {
                continue;
            }
            a[(r, j)] = T::zero();
            for c in j + 1..=last_col {
                let v = a[(j, c)];
                a[(r, c)] -= factor * v;
            }
            for c in 0..b.ncols() {
                let v = b[(j, c)];
                b[(r, c)] -= factor * v;
            }
        }
    }
    // Back substitution over the widened upper band.
    for j in (0..n).rev() {
        let last_col = (j + width).min(n - 1);
        for c in 0..b.ncols() {
            let mut v = b[(j, c)];
            for k in j + 1..=last_col {
                v -= a[(j, k)] * b[(k, c)];
            }
            b[(j, c)] = v / a[(j, j)];
        }
    }
    b.iter().all(|v| re(*v).is_finite()).then_some(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agrees_with_dense_lu_on_a_pivoting_case() {
        // A zero on the diagonal forces a row exchange inside the band.
        let a = DMatrix::from_row_slice(
            4,
            4,
            &[
                0.0, 1.0, 0.0, 0.0, 2.0, 1.0, 1.0, 0.0, 0.0, 3.0, 1.0, 2.0, 0.0, 0.0, 1.0, 4.0,
            ],
        );
        let b = DMatrix::from_column_slice(4, 2, &[1.0, 2.0, 3.0, 4.0, -1.0, 0.5, 2.0, 7.0]);
        let banded = solve_banded(a.clone(), b.clone()).unwrap();
        let dense = a.lu().solve(&b).unwrap();
        assert!((banded - dense).norm() < 1e-13);
        let singular = DMatrix::from_row_slice(2, 2, &[1.0, 2.0, 2.0, 4.0]);
        assert!(solve_banded(singular, DMatrix::from_column_slice(2, 1, &[1.0, 1.0])).is_none());
    }
}
