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
//!
//! **Ordering.** The symbolic factorization first takes M in its own order, in which the rows
//! of a chain or a ladder (numbered along it, as sketches number their constraints) give M a
//! narrow band and little fill. Only when that order would fill L beyond
//! [`NATURAL_FILL_LIMIT`] times M's own lower triangle is faer's approximate minimum degree
//! ordering computed instead, which costs several times the rest of the symbolic work.
//!
//! **Envelope.** Before any of this, an M whose rows, in its own order, reach only a few rows
//! back (a chain, a strip) is formed and factorized in its envelope instead (the `envelope`
//! module): its symbolic work is one pass over J, and no general sparse factorization matches
//! it on a narrow band.

use std::sync::Arc;

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, LltRef, SymbolicCholesky, SymmetricOrdering,
};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, MatMut, Par, Side};

use crate::linalg::envelope::{EnvelopeFactor, EnvelopePattern};
use crate::linalg::sparse::{entries_by_column, SparseMatrix};
use crate::model::errors::{Error, Result};

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
    structure: Structure,
}

/// How M is factorized for one pattern of J.
#[derive(Debug, Clone)]
enum Structure {
    /// In its envelope (a narrow band in M's own order).
    Envelope(EnvelopePattern),
    /// By faer's supernodal Cholesky.
    General(General),
}

/// M's pattern and faer's symbolic factorization.
#[derive(Debug, Clone)]
struct General {
    /// M's lower triangle in compressed columns.
    m_col_ptr: Vec<usize>,
    m_row_idx: Vec<usize>,
    /// The products J_jk·J_ik (slot of M[i, j], value index of J_jk, value index of J_ik), i ≥ j,
    /// by columns j of M.
    terms: Vec<(usize, usize, usize)>,
    symbolic: Arc<SymbolicCholesky<usize>>,
    values: Vec<f64>,
}

/// The order of M is kept when its factor L holds at most this many times the entries of M's
/// lower triangle (a fill that no ordering could cut by much); above, the minimum degree
/// ordering is computed.
pub const NATURAL_FILL_LIMIT: usize = 2;

/// A numeric Cholesky factor M = L·Lᵀ of J·D·Jᵀ.
#[derive(Debug)]
pub(crate) enum NormalFactor {
    /// L in M's envelope.
    Envelope(EnvelopeFactor),
    /// faer's supernodal factor.
    General(SupernodalFactor),
}

/// faer's factor: the symbolic factorization shared with the cache and the values of L, with
/// the scratch its solves reuse.
pub(crate) struct SupernodalFactor {
    symbolic: Arc<SymbolicCholesky<usize>>,
    values: Vec<f64>,
    scratch: MemBuffer,
}

impl std::fmt::Debug for SupernodalFactor {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SupernodalFactor")
            .field("rows", &self.symbolic.nrows())
            .field("factor_entries", &self.values.len())
            .finish()
    }
}

impl NormalFactor {
    /// Overwrites `rhs` with M⁻¹·rhs (`rhs` has M's order).
    pub(crate) fn solve_in_place(&mut self, rhs: &mut [f64]) {
        match self {
            Self::Envelope(f) => f.solve_in_place(rhs),
            Self::General(f) => {
                let m = rhs.len();
                LltRef::new(&f.symbolic, &f.values).solve_in_place_with_conj(
                    Conj::No,
                    MatMut::from_column_major_slice_mut(rhs, m, 1),
                    Par::Seq,
                    MemStack::new(&mut f.scratch),
                );
            }
        }
    }

    /// Whether the factorization kept M's own order (no fill-reducing permutation).
    #[cfg(test)]
    fn natural_order(&self) -> bool {
        match self {
            Self::Envelope(_) => true,
            Self::General(f) => f.symbolic.perm().is_none(),
        }
    }
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
    pub(crate) fn factorize(&mut self, j: &SparseMatrix, inv_w: &[f64]) -> Result<NormalFactor> {
        let (row_ptr, col_idx, _) = j.raw();
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
        match &mut p.structure {
            Structure::Envelope(e) => Ok(NormalFactor::Envelope(e.factorize(j, inv_w)?)),
            Structure::General(g) => Ok(NormalFactor::General(g.factorize(j, inv_w)?)),
        }
    }
}

impl General {
    /// Forms M in its pattern and factorizes it numerically.
    fn factorize(&mut self, j: &SparseMatrix, inv_w: &[f64]) -> Result<SupernodalFactor> {
        let (_, col_idx, values) = j.raw();
        let m = j.nrows();
        let p = self;
        p.values.fill(0.0);
        for &(slot, a, b) in &p.terms {
            p.values[slot] += values[a] * inv_w[col_idx[a]] * values[b];
        }
        let pattern = SymbolicSparseColMatRef::new_checked(m, m, &p.m_col_ptr, None, &p.m_row_idx);
        let mat = SparseColMatRef::new(pattern, &p.values);
        let mut values = vec![0.0; p.symbolic.len_val()];
        p.symbolic
            .factorize_numeric_llt::<f64>(
                &mut values,
                mat,
                Side::Lower,
                Default::default(),
                Par::Seq,
                MemStack::new(&mut MemBuffer::new(
                    p.symbolic
                        .factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default()),
                )),
                Default::default(),
            )
            .map_err(|_| Error::RankDeficient { rows: m })?;
        let solve_scratch = p.symbolic.solve_in_place_scratch::<f64>(1, Par::Seq);
        Ok(SupernodalFactor {
            symbolic: Arc::clone(&p.symbolic),
            values,
            scratch: MemBuffer::new(solve_scratch),
        })
    }
}

impl Pattern {
    /// The envelope of M when it is narrow (the `envelope` module), M's pattern and faer's
    /// symbolic factorization otherwise.
    fn build(j: &SparseMatrix) -> Result<Self> {
        let (row_ptr, col_idx, _) = j.raw();
        let structure = match EnvelopePattern::try_new(j) {
            Some(e) => Structure::Envelope(e),
            None => Structure::General(General::build(j)?),
        };
        Ok(Self {
            j_cols: j.ncols(),
            j_row_ptr: row_ptr.to_vec(),
            j_col_idx: col_idx.to_vec(),
            structure,
        })
    }
}

impl General {
    /// M's pattern column by column: column j of M (row j of J) meets row i exactly when rows
    /// i and j of J share a column, found through J's columns with a marker per row, so no
    /// global sort is needed, only each column's few rows. The upper triangle (for the
    /// symbolic factorization) comes from the same pass, and every product J_jk·J_ik is
    /// listed with the slot of M it adds to.
    fn build(j: &SparseMatrix) -> Result<Self> {
        let (row_ptr, col_idx, _) = j.raw();
        let (m, n) = (j.nrows(), j.ncols());
        // The entries of each column: (row, value index).
        let (col_count, by_col) = entries_by_column(n, row_ptr, col_idx);
        // For column j: `mark[i] == j` once row i is listed, `slot[i]` its slot then.
        let mut mark = vec![usize::MAX; m];
        let mut slot = vec![0_usize; m];
        let mut m_col_ptr = Vec::with_capacity(m + 1);
        let mut m_row_idx = Vec::with_capacity(4 * m);
        let mut upper_col_ptr = Vec::with_capacity(m + 1);
        let mut upper_row_idx = Vec::with_capacity(4 * m);
        let mut terms = Vec::with_capacity(8 * m);
        m_col_ptr.push(0);
        upper_col_ptr.push(0);
        for jr in 0..m {
            let entries = row_ptr[jr]..row_ptr[jr + 1];
            // Every diagonal entry is present, even for an empty row of J.
            mark[jr] = jr;
            let lower_start = m_row_idx.len();
            let upper_start = upper_row_idx.len();
            m_row_idx.push(jr);
            upper_row_idx.push(jr);
            for &c in &col_idx[entries.clone()] {
                for &(i, _) in &by_col[col_count[c]..col_count[c + 1]] {
                    if mark[i] != jr {
                        mark[i] = jr;
                        if i > jr {
                            m_row_idx.push(i);
                        } else {
                            upper_row_idx.push(i);
                        }
                    }
                }
            }
            m_row_idx[lower_start..].sort_unstable();
            upper_row_idx[upper_start..].sort_unstable();
            for (s, &i) in m_row_idx.iter().enumerate().skip(lower_start) {
                slot[i] = s;
            }
            m_col_ptr.push(m_row_idx.len());
            upper_col_ptr.push(upper_row_idx.len());
            for (a, &c) in col_idx
                .iter()
                .enumerate()
                .take(entries.end)
                .skip(entries.start)
            {
                for &(i, b) in &by_col[col_count[c]..col_count[c + 1]] {
                    if i >= jr {
                        terms.push((slot[i], a, b));
                    }
                }
            }
        }
        let symbolic = Arc::new(symbolic_of(
            m,
            &upper_col_ptr,
            &upper_row_idx,
            m_row_idx.len(),
        )?);
        let values = vec![0.0; m_row_idx.len()];
        Ok(Self {
            m_col_ptr,
            m_row_idx,
            terms,
            symbolic,
            values,
        })
    }
}

/// The symbolic Cholesky factorization of M's pattern, given as its upper triangle in
/// compressed columns (m × m, `lower_len` entries in either triangle): in M's own order when
/// its factor has at most [`NATURAL_FILL_LIMIT`] times the entries of a triangle, after the
/// approximate minimum degree ordering otherwise.
fn symbolic_of(
    m: usize,
    upper_col_ptr: &[usize],
    upper_row_idx: &[usize],
    lower_len: usize,
) -> Result<SymbolicCholesky<usize>> {
    let rank_deficient = |_| Error::RankDeficient { rows: m };
    // faer reads the pattern as given when it keeps the order, and then as the upper
    // triangle whatever side is named.
    let upper = SymbolicSparseColMatRef::new_checked(m, m, upper_col_ptr, None, upper_row_idx);
    let natural = factorize_symbolic_cholesky(
        upper,
        Side::Upper,
        SymmetricOrdering::Identity,
        Default::default(),
    )
    .map_err(rank_deficient)?;
    if natural.len_val() <= NATURAL_FILL_LIMIT.saturating_mul(lower_len) {
        return Ok(natural);
    }
    factorize_symbolic_cholesky(
        upper,
        Side::Upper,
        SymmetricOrdering::Amd,
        Default::default(),
    )
    .map_err(rank_deficient)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use nalgebra::DMatrix;

    /// Factorizes J·D·Jᵀ through the cache and checks M·(M⁻¹·r) = r against the dense M for a
    /// fixed right-hand side; returns the factor.
    fn check_solve(cache: &mut NormalCache, jd: &DMatrix<f64>, inv_w: &[f64]) -> NormalFactor {
        let j = SparseMatrix::from_dense(jd);
        let mut factor = cache.factorize(&j, inv_w).unwrap();
        let dense = jd
            * DMatrix::from_diagonal(&nalgebra::DVector::from_column_slice(inv_w))
            * jd.transpose();
        let m = jd.nrows();
        let rhs: Vec<f64> = (0..m).map(|i| ((i * 7) % 5) as f64 - 1.5).collect();
        let mut y = rhs.clone();
        factor.solve_in_place(&mut y);
        let back = &dense * nalgebra::DVector::from_column_slice(&y);
        for i in 0..m {
            assert_relative_eq!(back[i], rhs[i], epsilon = 1e-10);
        }
        factor
    }

    #[test]
    fn a_chain_keeps_its_order_and_an_arrow_is_reordered() {
        // A chain: row i reads columns i and i + 1 (M tridiagonal, no fill in its own order).
        let m = 40;
        let mut chain = DMatrix::zeros(m, m + 1);
        for i in 0..m {
            chain[(i, i)] = 1.0 + i as f64 * 0.01;
            chain[(i, i + 1)] = -1.0;
        }
        let inv_w: Vec<f64> = (0..=m).map(|k| 1.0 + (k % 3) as f64).collect();
        assert!(check_solve(&mut NormalCache::new(), &chain, &inv_w).natural_order());
        // An arrow: row 0 reads every column, so M's first column is full and, in its own
        // order, L would be full too; the minimum degree ordering moves that row last.
        let mut arrow = chain.clone();
        for k in 0..=m {
            arrow[(0, k)] = 0.5;
        }
        assert!(!check_solve(&mut NormalCache::new(), &arrow, &inv_w).natural_order());
    }

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
            check_solve(&mut cache, &(&jd * scale), &inv_w);
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
