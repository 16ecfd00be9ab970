//! The envelope (profile) Cholesky factorization of M = J·D·Jᵀ when M, in its own order, has a
//! narrow band: the rows of a chain or a strip, numbered along it as sketches number their
//! constraints.
//!
//! Row i of M is stored from its first structurally nonzero column fᵢ to the diagonal. The
//! factor L of M = L·Lᵀ has no entry left of fᵢ in row i (an entry of L left of the envelope
//! would need a nonzero of M there), so L fits in M's envelope and the whole symbolic analysis is
//! fᵢ, found in one pass over J: rows i and j of J meet in M exactly when they share a column,
//! so fᵢ is the least first row over the columns of row i. Forming M costs one product per pair
//! of rows sharing a column, the factorization Σᵢ wᵢ²/2 multiply-adds for the row widths wᵢ,
//! each solve 2·Σᵢ wᵢ: for a band of a few rows far below a general sparse factorization's
//! symbolic work (ordering, elimination tree, supernodes).

use crate::linalg::sparse::{entries_by_column, SparseMatrix};
use crate::model::errors::{Error, Result};

/// The envelope is used when Σᵢ wᵢ² ≤ this × m (the row widths wᵢ have a root mean square of
/// at most 16): the factorization then costs at most 128 multiply-adds per row.
pub(crate) const ENVELOPE_MAX_SQUARED_WIDTH: usize = 256;

/// The structure of M = J·D·Jᵀ's envelope for one sparsity pattern of J, with J's entries by
/// column to form M from.
#[derive(Debug, Clone)]
pub(crate) struct EnvelopePattern {
    /// fᵢ, the first column of row i of M's envelope.
    first: Vec<usize>,
    /// Row i of the envelope is `start[i]..start[i + 1]` of the values (columns fᵢ ..= i).
    start: Vec<usize>,
    /// J by columns: the entries of column c are `by_col[col_ptr[c]..col_ptr[c + 1]]` as (row,
    /// index of the value in J's compressed rows), rows increasing.
    col_ptr: Vec<usize>,
    by_col: Vec<(usize, usize)>,
}

impl EnvelopePattern {
    /// The envelope of J·D·Jᵀ if it is narrow enough ([`ENVELOPE_MAX_SQUARED_WIDTH`]).
    pub(crate) fn try_new(j: &SparseMatrix) -> Option<Self> {
        let (row_ptr, col_idx, _) = j.raw();
        let (m, n) = (j.nrows(), j.ncols());
        // The first row reading each column (rows are visited in order).
        let mut first_row = vec![usize::MAX; n];
        let mut first = Vec::with_capacity(m);
        let mut squared = 0_usize;
        for i in 0..m {
            let mut f = i;
            for &c in &col_idx[row_ptr[i]..row_ptr[i + 1]] {
                if first_row[c] == usize::MAX {
                    first_row[c] = i;
                }
                f = f.min(first_row[c]);
            }
            let w = i - f + 1;
            squared = squared.saturating_add(w * w);
            first.push(f);
        }
        if squared > ENVELOPE_MAX_SQUARED_WIDTH.saturating_mul(m.max(1)) {
            return None;
        }
        let mut start = Vec::with_capacity(m + 1);
        start.push(0);
        for (i, f) in first.iter().enumerate() {
            start.push(start[i] + i - f + 1);
        }
        let (col_ptr, by_col) = entries_by_column(n, row_ptr, col_idx);
        Some(Self {
            first,
            start,
            col_ptr,
            by_col,
        })
    }

    /// Entries of the envelope (M's lower triangle within it, and L's).
    pub(crate) fn len(&self) -> usize {
        self.start.last().copied().unwrap_or(0)
    }

    /// Forms M = J·D·Jᵀ (J with the pattern this was built for, D = diag(`inv_w`)) in the
    /// envelope and factorizes it.
    ///
    /// # Errors
    /// [`Error::RankDeficient`] when a pivot is not positive (M not positive definite: J lacks
    /// full row rank).
    pub(crate) fn factorize(&self, j: &SparseMatrix, inv_w: &[f64]) -> Result<EnvelopeFactor> {
        let (_, _, jv) = j.raw();
        let m = self.first.len();
        let mut l = vec![0.0; self.len()];
        for (c, d) in inv_w.iter().enumerate() {
            let entries = &self.by_col[self.col_ptr[c]..self.col_ptr[c + 1]];
            for (k, &(b, vb)) in entries.iter().enumerate() {
                let scaled = jv[vb] * d;
                let row = self.start[b] - self.first[b];
                for &(a, va) in &entries[..=k] {
                    l[row + a] += jv[va] * scaled;
                }
            }
        }
        // Row by row: L[i][j] = (M[i][j] − Σₖ L[i][k]·L[j][k]) / L[j][j] over the columns k both
        // envelopes hold, then the pivot.
        for i in 0..m {
            let (done, rest) = l.split_at_mut(self.start[i]);
            let row = &mut rest[..self.start[i + 1] - self.start[i]];
            let fi = self.first[i];
            for j in fi..i {
                let fj = self.first[j];
                let lo = fi.max(fj);
                let lj = &done[self.start[j]..self.start[j + 1]];
                let dot: f64 = row[lo - fi..j - fi]
                    .iter()
                    .zip(&lj[lo - fj..j - fj])
                    .map(|(a, b)| a * b)
                    .sum();
                row[j - fi] = (row[j - fi] - dot) / lj[j - fj];
            }
            let (off, diag) = row.split_at_mut(i - fi);
            let d = diag[0] - off.iter().map(|v| v * v).sum::<f64>();
            if d.is_nan() || d <= 0.0 {
                return Err(Error::RankDeficient { rows: m });
            }
            diag[0] = d.sqrt();
        }
        Ok(EnvelopeFactor {
            first: self.first.clone(),
            start: self.start.clone(),
            l,
        })
    }
}

/// M = L·Lᵀ with L stored in M's envelope.
#[derive(Debug, Clone)]
pub(crate) struct EnvelopeFactor {
    first: Vec<usize>,
    start: Vec<usize>,
    l: Vec<f64>,
}

impl EnvelopeFactor {
    /// Overwrites `rhs` with M⁻¹·rhs (`rhs` has M's order): L·y = rhs forward, Lᵀ·x = y back.
    pub(crate) fn solve_in_place(&self, rhs: &mut [f64]) {
        let m = self.first.len().min(rhs.len());
        for i in 0..m {
            let fi = self.first[i];
            let row = &self.l[self.start[i]..self.start[i + 1]];
            let (off, diag) = row.split_at(i - fi);
            let dot: f64 = off.iter().zip(&rhs[fi..i]).map(|(a, b)| a * b).sum();
            rhs[i] = (rhs[i] - dot) / diag[0];
        }
        for i in (0..m).rev() {
            let fi = self.first[i];
            let row = &self.l[self.start[i]..self.start[i + 1]];
            let (off, diag) = row.split_at(i - fi);
            let xi = rhs[i] / diag[0];
            rhs[i] = xi;
            for (r, a) in rhs[fi..i].iter_mut().zip(off) {
                *r -= a * xi;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use nalgebra::{DMatrix, DVector};

    /// A band of random rows: row i reads columns i … i + `reach` (some left out), plus
    /// `extra` entries anywhere before.
    fn banded(m: usize, reach: usize, seed: u64) -> DMatrix<f64> {
        let mut s = seed;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 33) as f64) / f64::from(1_u32 << 31) - 0.5
        };
        let mut j = DMatrix::zeros(m, m + reach);
        for i in 0..m {
            for c in i..=i + reach {
                if c == i || next() > 0.0 {
                    j[(i, c)] = next() + if c == i { 2.0 } else { 0.0 };
                }
            }
        }
        j
    }

    #[test]
    fn solves_like_the_dense_cholesky() {
        for (m, reach, seed) in [(1, 0, 1), (7, 2, 3), (60, 3, 5), (200, 6, 9)] {
            let jd = banded(m, reach, seed);
            let j = SparseMatrix::from_dense(&jd);
            let inv_w: Vec<f64> = (0..jd.ncols()).map(|k| 0.5 + (k % 4) as f64).collect();
            let dense =
                &jd * DMatrix::from_diagonal(&DVector::from_vec(inv_w.clone())) * jd.transpose();
            let pattern = EnvelopePattern::try_new(&j).unwrap();
            let factor = pattern.factorize(&j, &inv_w).unwrap();
            let rhs: Vec<f64> = (0..m).map(|i| ((i * 7) % 5) as f64 - 1.5).collect();
            let mut y = rhs.clone();
            factor.solve_in_place(&mut y);
            let want = dense
                .clone()
                .cholesky()
                .unwrap()
                .solve(&DVector::from_vec(rhs.clone()));
            for i in 0..m {
                assert_relative_eq!(y[i], want[i], epsilon = 1e-12, max_relative = 1e-10);
            }
            let back = &dense * DVector::from_vec(y);
            for i in 0..m {
                assert_relative_eq!(back[i], rhs[i], epsilon = 1e-11);
            }
        }
    }

    #[test]
    fn the_envelope_is_the_first_shared_row() {
        // Rows 0 and 2 share column 0; row 1 reads only column 1; row 3 nothing.
        let j = SparseMatrix::try_from_triplets(
            4,
            3,
            &[(0, 0, 1.0), (1, 1, 1.0), (2, 0, 1.0), (2, 2, 1.0)],
        )
        .unwrap();
        let p = EnvelopePattern::try_new(&j).unwrap();
        assert_eq!(p.first, vec![0, 1, 0, 3]);
        assert_eq!(p.len(), 1 + 1 + 3 + 1);
        // Row 3 of J is empty: M is singular.
        assert_eq!(
            p.factorize(&j, &[1.0; 3]).unwrap_err(),
            Error::RankDeficient { rows: 4 }
        );
    }

    #[test]
    fn a_wide_envelope_is_refused_and_dependent_rows_fail() {
        // An arrow whose full row comes first: every row's envelope starts at 0.
        let m = 100;
        let mut t: Vec<(usize, usize, f64)> = (0..m).map(|k| (0, k, 1.0)).collect();
        t.extend((1..m).map(|i| (i, i, 1.0)));
        let arrow = SparseMatrix::try_from_triplets(m, m, &t).unwrap();
        assert!(EnvelopePattern::try_new(&arrow).is_none());
        let dependent = SparseMatrix::try_from_triplets(2, 2, &[(0, 0, 1.0), (1, 0, 2.0)]).unwrap();
        let p = EnvelopePattern::try_new(&dependent).unwrap();
        assert!(p.factorize(&dependent, &[1.0, 1.0]).is_err());
    }
}
