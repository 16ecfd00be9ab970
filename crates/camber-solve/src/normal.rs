//! The sparse matrix M = J·D·Jᵀ (D = W⁻¹ diagonal) and its symbolic Cholesky factorization,
//! kept between factorizations of Jacobians with the same sparsity pattern.
//!
//! Newton iterations and drag updates factorize J·W⁻¹·Jᵀ again and again with J's pattern
//! unchanged. Everything that depends on the pattern alone is done once here: the pattern of M
//! (its lower triangle in compressed columns, every diagonal entry present), for every product
//! J_ik·J_jk (i ≥ j) of a column k the slot of M it adds to, and faer's symbolic factorization
//! (fill-reducing ordering, elimination tree, supernodes). A new J with the same pattern then
//! costs one pass over the products,
//!
//! M[i, j] = Σ_k J_ik·d_k·J_jk,
//!
//! and the numeric factorization. A J with another pattern rebuilds the cache.

use faer::sparse::linalg::solvers::{Llt, SymbolicLlt};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::Side;

use crate::errors::{Error, Result};
use crate::sparse::SparseMatrix;

/// The pattern work of factorizing J·D·Jᵀ for one sparsity pattern of J.
#[derive(Debug, Clone, Default)]
pub struct NormalCache {
    pattern: Option<Pattern>,
}

#[derive(Debug, Clone)]
struct Pattern {
    /// The pattern of J (CSR) this cache was built for.
    j_cols: usize,
    j_row_ptr: Vec<usize>,
    j_col_idx: Vec<usize>,
    /// M's lower triangle in compressed columns.
    m_col_ptr: Vec<usize>,
    m_row_idx: Vec<usize>,
    /// Per column k of J, `terms[term_ptr[k]..term_ptr[k+1]]` are the products (slot of M,
    /// value index a, value index b) with J's values a, b in column k.
    term_ptr: Vec<usize>,
    terms: Vec<(usize, usize, usize)>,
    symbolic: SymbolicLlt<usize>,
    values: Vec<f64>,
}

impl NormalCache {
    /// An empty cache (filled by the first factorization).
    pub fn new() -> Self {
        Self::default()
    }

    /// Factorizes M = J·D·Jᵀ for `inv_w` = D's diagonal, reusing the pattern work when J has
    /// the pattern of the last call.
    ///
    /// # Errors
    /// [`Error::RankDeficient`] when M is not positive definite (J lacks full row rank).
    pub(crate) fn factorize(&mut self, j: &SparseMatrix, inv_w: &[f64]) -> Result<Llt<usize, f64>> {
        let (row_ptr, col_idx, values) = j.raw();
        let m = j.nrows();
        let fits = self.pattern.as_ref().is_some_and(|p| {
            p.j_cols == j.ncols() && p.j_row_ptr == row_ptr && p.j_col_idx == col_idx
        });
        if !fits {
            self.pattern = Some(Pattern::build(j)?);
        }
        let p = self
            .pattern
            .as_mut()
            .ok_or(Error::RankDeficient { rows: m })?;
        p.values.fill(0.0);
        for (k, d) in inv_w.iter().enumerate() {
            for &(slot, a, b) in &p.terms[p.term_ptr[k]..p.term_ptr[k + 1]] {
                p.values[slot] += values[a] * d * values[b];
            }
        }
        let symbolic = SymbolicSparseColMatRef::new_checked(m, m, &p.m_col_ptr, None, &p.m_row_idx);
        let mat = SparseColMatRef::new(symbolic, &p.values);
        Llt::try_new_with_symbolic(p.symbolic.clone(), mat, Side::Lower)
            .map_err(|_| Error::RankDeficient { rows: m })
    }
}

impl Pattern {
    fn build(j: &SparseMatrix) -> Result<Self> {
        let (row_ptr, col_idx, _) = j.raw();
        let (m, n) = (j.nrows(), j.ncols());
        // The entries of each column: (row, value index).
        let mut col_count = vec![0_usize; n + 1];
        for &c in col_idx {
            col_count[c + 1] += 1;
        }
        for k in 0..n {
            col_count[k + 1] += col_count[k];
        }
        let mut next = col_count.clone();
        let mut by_col = vec![(0_usize, 0_usize); col_idx.len()];
        for i in 0..m {
            for (a, &c) in col_idx
                .iter()
                .enumerate()
                .take(row_ptr[i + 1])
                .skip(row_ptr[i])
            {
                by_col[next[c]] = (i, a);
                next[c] += 1;
            }
        }
        // The lower-triangle positions (column j, row i ≥ j) of M, with every diagonal.
        let mut positions: Vec<(usize, usize)> = (0..m).map(|i| (i, i)).collect();
        for k in 0..n {
            let entries = &by_col[col_count[k]..col_count[k + 1]];
            for (x, &(ia, _)) in entries.iter().enumerate() {
                for &(ib, _) in &entries[..x] {
                    positions.push((ia.min(ib), ia.max(ib)));
                }
            }
        }
        let (m_col_ptr, m_row_idx) = crate::sparse::compress(m, &positions);
        let slot = |row: usize, col: usize| -> usize {
            let rows = &m_row_idx[m_col_ptr[col]..m_col_ptr[col + 1]];
            m_col_ptr[col] + rows.binary_search(&row).unwrap_or(0)
        };
        let mut term_ptr = Vec::with_capacity(n + 1);
        let mut terms = Vec::new();
        term_ptr.push(0);
        for k in 0..n {
            let entries = &by_col[col_count[k]..col_count[k + 1]];
            for (x, &(ia, a)) in entries.iter().enumerate() {
                for &(ib, b) in &entries[..=x] {
                    terms.push((slot(ia.max(ib), ia.min(ib)), a, b));
                }
            }
            term_ptr.push(terms.len());
        }
        let symbolic_ref = SymbolicSparseColMatRef::new_checked(m, m, &m_col_ptr, None, &m_row_idx);
        let symbolic = SymbolicLlt::try_new(symbolic_ref, Side::Lower)
            .map_err(|_| Error::RankDeficient { rows: m })?;
        let values = vec![0.0; m_row_idx.len()];
        Ok(Self {
            j_cols: n,
            j_row_ptr: row_ptr.to_vec(),
            j_col_idx: col_idx.to_vec(),
            m_col_ptr,
            m_row_idx,
            term_ptr,
            terms,
            symbolic,
            values,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use faer::linalg::solvers::Solve;
    use faer::MatMut;
    use nalgebra::DMatrix;

    #[test]
    fn solves_like_the_dense_normal_matrix_and_reuses_its_pattern() {
        let jd = DMatrix::from_row_slice(
            3,
            5,
            &[
                1.0, 2.0, 0.0, 0.0, -1.0, //
                0.0, 1.0, 3.0, 0.0, 0.0, //
                0.5, 0.0, 0.0, 2.0, 1.0,
            ],
        );
        let inv_w = [1.0, 0.5, 2.0, 1.0, 0.25];
        let mut cache = NormalCache::new();
        for scale in [1.0, 2.0] {
            let j = SparseMatrix::from_dense(&(&jd * scale));
            let llt = cache.factorize(&j, &inv_w).unwrap();
            let dense = &jd
                * scale
                * DMatrix::from_diagonal(&nalgebra::DVector::from_column_slice(&inv_w))
                * (&jd * scale).transpose();
            let rhs = [1.0, -2.0, 0.5];
            let mut y = rhs;
            llt.solve_in_place(MatMut::from_column_major_slice_mut(&mut y, 3, 1));
            let back = &dense * nalgebra::DVector::from_column_slice(&y);
            for i in 0..3 {
                assert_relative_eq!(back[i], rhs[i], epsilon = 1e-12);
            }
        }
        // The second factorization reused the pattern built by the first.
        assert!(cache.pattern.is_some());
    }

    #[test]
    fn dependent_rows_are_rank_deficient() {
        let j = SparseMatrix::try_from_triplets(2, 2, &[(0, 0, 1.0), (1, 0, 2.0)]).unwrap();
        assert_eq!(
            NormalCache::new().factorize(&j, &[1.0, 1.0]).unwrap_err(),
            Error::RankDeficient { rows: 2 }
        );
    }
}
