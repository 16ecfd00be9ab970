//! A banded linear solver: Gaussian elimination with partial pivoting on a matrix stored by its
//! band, for the collocation and normal-equation systems of [`crate::fit`].
//!
//! A matrix whose non-zeros in row r lie in columns r − kl … r + ku needs O(n·kl·(kl + ku))
//! operations instead of the O(n³) of dense LU, and O(n·(2·kl + ku)) storage instead of n²:
//! for a B-spline system kl and ku are about the degree, so fitting 100,000 points costs a few
//! megabytes, not the 80 GB of a dense matrix. Row exchanges within the kl rows below the pivot
//! widen the upper band to kl + ku, for which the storage keeps room.

use nalgebra::DMatrix;

use crate::scalar::{re, Scalar};

/// A square n × n matrix stored by its band: entry (r, c) may be non-zero only for
/// −kl ≤ c − r ≤ ku. Each row also keeps kl more places to the right for the fill of row
/// exchanges, so the matrix factors in place.
///
/// ```
/// use camber_geom::banded::BandedMatrix;
/// use nalgebra::DMatrix;
/// // A tridiagonal system with solution (1, 2, 3).
/// let mut a = BandedMatrix::zeros(3, 1, 1);
/// for (r, c, v) in [(0, 0, 2.0), (0, 1, 1.0), (1, 0, 1.0), (1, 1, 2.0), (1, 2, 1.0), (2, 1, 1.0), (2, 2, 2.0)] {
///     a.set(r, c, v).unwrap();
/// }
/// let x = a.solve(DMatrix::from_column_slice(3, 1, &[4.0_f64, 8.0, 8.0])).unwrap();
/// assert!((x[0] - 1.0).abs() < 1e-14 && (x[1] - 2.0).abs() < 1e-14 && (x[2] - 3.0).abs() < 1e-14);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BandedMatrix<T> {
    n: usize,
    kl: usize,
    ku: usize,
    /// Row r holds columns r − kl … r + kl + ku at offsets 0 … 2·kl + ku, row after row.
    data: Vec<T>,
}

impl<T: Scalar> BandedMatrix<T> {
    /// The zero n × n matrix with lower band width `kl` and upper band width `ku`.
    pub fn zeros(n: usize, kl: usize, ku: usize) -> Self {
        Self {
            n,
            kl,
            ku,
            data: vec![T::zero(); n * (2 * kl + ku + 1)],
        }
    }

    /// The banded copy of a dense square matrix, its band widths read from its non-zeros.
    /// This scans all n² entries; build a [`BandedMatrix`] directly for large systems.
    pub fn from_dense(a: &DMatrix<T>) -> Option<Self> {
        let n = a.nrows();
        if a.ncols() != n {
            return None;
        }
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
        let mut out = Self::zeros(n, kl, ku);
        for r in 0..n {
            for c in r.saturating_sub(kl)..=(r + ku).min(n.saturating_sub(1)) {
                out.set(r, c, a[(r, c)])?;
            }
        }
        Some(out)
    }

    /// The order n.
    pub fn order(&self) -> usize {
        self.n
    }

    /// The lower and upper band widths (kl, ku).
    pub fn band_widths(&self) -> (usize, usize) {
        (self.kl, self.ku)
    }

    /// The width of a stored row: the band plus the room for fill.
    fn stride(&self) -> usize {
        2 * self.kl + self.ku + 1
    }

    /// Where (r, c) is stored, if it lies within the stored part of row r.
    fn index(&self, r: usize, c: usize) -> Option<usize> {
        if r >= self.n || c >= self.n || c + self.kl < r || c > r + self.kl + self.ku {
            return None;
        }
        Some(r * self.stride() + c + self.kl - r)
    }

    /// Entry (r, c): zero outside the band.
    pub fn get(&self, r: usize, c: usize) -> T {
        self.index(r, c).map_or(T::zero(), |i| self.data[i])
    }

    /// Sets entry (r, c); `None` (and nothing changed) when it lies outside the band
    /// −kl ≤ c − r ≤ ku or outside the matrix.
    pub fn set(&mut self, r: usize, c: usize, v: T) -> Option<()> {
        let i = self.index(r, c).filter(|_| c <= r + self.ku)?;
        self.data[i] = v;
        Some(())
    }

    /// Adds `v` to entry (r, c); `None` (and nothing changed) outside the band, as
    /// [`BandedMatrix::set`].
    pub fn add(&mut self, r: usize, c: usize, v: T) -> Option<()> {
        let i = self.index(r, c).filter(|_| c <= r + self.ku)?;
        self.data[i] += v;
        Some(())
    }

    /// Adds the outer product v·vᵀ to the square block of rows and columns
    /// `start` … `start + v.len() − 1` (one data point's contribution to the normal equations
    /// of a least-squares fit, v its non-zero basis values); `None` (and nothing changed) when
    /// the block leaves the matrix or the band.
    pub(crate) fn add_outer(&mut self, start: usize, v: &[T]) -> Option<()> {
        let len = v.len();
        let width = len.saturating_sub(1);
        if start + len > self.n || width > self.kl || width > self.ku {
            return None;
        }
        let stride = self.stride();
        for (i, &vi) in v.iter().enumerate() {
            let r = start + i;
            // (r, c) is stored at r·stride + c + kl − r; c runs from start.
            let row = &mut self.data[r * stride + start + self.kl - r..][..len];
            for (entry, &vj) in row.iter_mut().zip(v) {
                *entry += vi * vj;
            }
        }
        Some(())
    }

    /// The dense copy (for small matrices and fallbacks).
    pub fn to_dense(&self) -> DMatrix<T> {
        DMatrix::from_fn(self.n, self.n, |r, c| self.get(r, c))
    }

    /// Solves A·X = B for a right-hand side with any number of columns by banded Gaussian
    /// elimination with partial pivoting, consuming A (it is factored in place). `None` when
    /// a pivot is zero (A singular), a value is not finite, or B has the wrong number of rows.
    pub fn solve(mut self, mut b: DMatrix<T>) -> Option<DMatrix<T>> {
        let (n, kl) = (self.n, self.kl);
        if b.nrows() != n {
            return None;
        }
        let width = self.kl + self.ku;
        let stride = self.stride();
        for j in 0..n {
            // Pivot: the largest magnitude among rows j … j + kl.
            let last_row = (j + kl).min(n - 1);
            let mut pivot = j;
            for r in j + 1..=last_row {
                if re(self.get(r, j)).abs() > re(self.get(pivot, j)).abs() {
                    pivot = r;
                }
            }
            let p = self.get(pivot, j);
            if re(p) == 0.0 || !re(p).is_finite() {
                return None;
            }
            let last_col = (j + width).min(n - 1);
            if pivot != j {
                // Both rows hold columns j … j + kl + ku: row j by its room for fill, row
                // `pivot` (at most kl below) by its band.
                for c in j..=last_col {
                    let (a, z) = (j * stride + c + kl - j, pivot * stride + c + kl - pivot);
                    self.data.swap(a, z);
                }
                b.swap_rows(j, pivot);
            }
            let row_j = j * stride + kl - j;
            for r in j + 1..=last_row {
                let row_r = r * stride + kl - r;
                let factor = self.data[row_r + j] / p;
                if re(factor) == 0.0 {
                    continue;
                }
                self.data[row_r + j] = T::zero();
                for c in j + 1..=last_col {
                    let v = self.data[row_j + c];
                    self.data[row_r + c] -= factor * v;
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
            let row_j = j * stride + kl - j;
            for c in 0..b.ncols() {
                let mut v = b[(j, c)];
                for k in j + 1..=last_col {
                    v -= self.data[row_j + k] * b[(k, c)];
                }
                b[(j, c)] = v / self.data[row_j + j];
            }
        }
        b.iter().all(|v| re(*v).is_finite()).then_some(b)
    }
}

/// Solves A X = B for a square `a` given densely (banded contents, widths read from its
/// non-zeros) and a right-hand side with any number of columns. Returns `None` when a pivot is
/// zero (A singular) or a value is not finite. Reading the widths scans all n² entries: large
/// systems should be assembled as a [`BandedMatrix`].
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
pub fn solve_banded<T: Scalar>(a: DMatrix<T>, b: DMatrix<T>) -> Option<DMatrix<T>> {
    BandedMatrix::from_dense(&a)?.solve(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_outer_product_block_adds_like_its_entries() {
        let v = [0.5_f64, 0.25, 0.125];
        let mut block = BandedMatrix::zeros(5, 2, 2);
        block.add_outer(1, &v).unwrap();
        block.add_outer(2, &v).unwrap();
        let mut entries = BandedMatrix::zeros(5, 2, 2);
        for start in [1, 2] {
            for (i, &a) in v.iter().enumerate() {
                for (j, &b) in v.iter().enumerate() {
                    entries.add(start + i, start + j, a * b).unwrap();
                }
            }
        }
        assert_eq!(block, entries);
        // Past the last row, or wider than the band: refused, nothing changed.
        assert!(block.add_outer(3, &v).is_none());
        assert!(block.add_outer(0, &[1.0, 1.0, 1.0, 1.0]).is_none());
        assert_eq!(block, entries);
    }

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

    #[test]
    fn entries_outside_the_band_are_refused_and_read_as_zero() {
        let mut a = BandedMatrix::<f64>::zeros(5, 1, 2);
        assert_eq!(a.band_widths(), (1, 2));
        assert!(a.set(3, 1, 1.0).is_none()); // two below the diagonal
        assert!(a.set(0, 3, 1.0).is_none()); // three above (room for fill is not band)
        assert!(a.set(5, 5, 1.0).is_none());
        assert!(a.set(2, 4, 3.0).is_some());
        assert!(a.add(2, 4, 1.0).is_some());
        assert_eq!(a.get(2, 4).to_bits(), 4.0_f64.to_bits());
        assert_eq!(a.get(4, 0).to_bits(), 0.0_f64.to_bits());
        assert_eq!(a.to_dense()[(2, 4)].to_bits(), 4.0_f64.to_bits());
        assert_eq!(
            BandedMatrix::from_dense(&a.to_dense()).unwrap().to_dense(),
            a.to_dense()
        );
    }

    #[test]
    fn a_long_band_solves_in_band_storage() {
        // The tridiagonal (−1, 2, −1) system of order 100,000 with x = 1 everywhere: the
        // right-hand side is 1 at both ends and 0 inside. Dense storage would need 80 GB.
        let n = 100_000;
        let mut a = BandedMatrix::<f64>::zeros(n, 1, 1);
        for r in 0..n {
            a.set(r, r, 2.0).unwrap();
            if r > 0 {
                a.set(r, r - 1, -1.0).unwrap();
            }
            if r + 1 < n {
                a.set(r, r + 1, -1.0).unwrap();
            }
        }
        let mut b = DMatrix::<f64>::zeros(n, 1);
        b[0] = 1.0;
        b[n - 1] = 1.0;
        let x = a.solve(b).unwrap();
        assert!(x.iter().all(|v| (v - 1.0).abs() < 1e-6));
    }
}
