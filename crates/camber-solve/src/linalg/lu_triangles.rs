//! The triangles of a sparse LU, P·J·Q = L·U, kept in their own arrays: triangular solves
//! (plain and transposed) and a numeric refactorization with the pivots of an earlier one.
//!
//! [`crate::linalg::sparse_lu`] factorizes J with faer's simplicial LU, which pivots by rows and finds
//! the patterns of L and U column by column (a depth-first search per column). In a Newton
//! solve J keeps its pattern and its values move a little from one iteration to the next, so
//! the pivots of the last factorization usually serve again: with the row order P, the
//! column order Q and the patterns of L and U fixed, a new J is factorized by the same
//! left-looking elimination without any search (as KLU's refactorization does),
//!
//! for every column j: x = P·J·Q[:, j]; for k in U's column j, in the order that the first
//! factorization found (each k after those its column of L updates): u_kj = x_k,
//! x −= u_kj·L[:, k]; then u_jj = x_j and L[:, j] = x/u_jj below the diagonal.
//!
//! A pivot that has become small against the rest of its column (below [`THRESHOLD`] times
//! the largest candidate) would make the factorization unstable: the refactorization is then
//! refused and the caller pivots afresh.
//!
//! Indices: rows of L and U are steps of the elimination (row `perm[p]` of J is step p),
//! columns are steps too (column `col_perm[j]` of J is step j).

use faer::sparse::linalg::lu::simplicial::SimplicialLu;

/// A kept pivot must be at least this fraction of the largest candidate of its column
/// (threshold partial pivoting).
pub(crate) const THRESHOLD: f64 = 0.1;

/// L (unit lower, without its diagonal) and U (upper, diagonal apart) by columns, in steps.
#[derive(Debug, Clone, Default)]
pub(crate) struct Triangles {
    n: usize,
    /// Row `perm[p]` of J is row p of P·J; `perm_inv` the inverse.
    perm: Vec<usize>,
    perm_inv: Vec<usize>,
    l_ptr: Vec<usize>,
    l_idx: Vec<usize>,
    l_val: Vec<f64>,
    /// U's columns without the diagonal, each in an order in which the elimination may run.
    u_ptr: Vec<usize>,
    u_idx: Vec<usize>,
    u_val: Vec<f64>,
    u_diag: Vec<f64>,
    /// Scratch: a dense column (all zero between uses).
    work: Vec<f64>,
}

/// J in compressed columns with its column order: what a refactorization reads.
pub(crate) struct Columns<'a> {
    pub(crate) col_ptr: &'a [usize],
    pub(crate) row_idx: &'a [usize],
    pub(crate) values: &'a [f64],
    pub(crate) col_perm: &'a [usize],
}

impl Triangles {
    /// Copies the factors of faer's simplicial LU with its row order (`row_perm[p]` is the row
    /// of J at step p, `row_perm_inv` the inverse).
    pub(crate) fn take_from(
        &mut self,
        lu: &SimplicialLu<usize, f64>,
        row_perm: &[usize],
        row_perm_inv: &[usize],
    ) {
        let n = row_perm.len();
        self.n = n;
        self.perm.clear();
        self.perm.extend_from_slice(row_perm);
        self.perm_inv.clear();
        self.perm_inv.extend_from_slice(row_perm_inv);
        let l = lu.l_factor_unsorted();
        let u = lu.u_factor_unsorted();
        for v in [
            &mut self.l_ptr,
            &mut self.l_idx,
            &mut self.u_ptr,
            &mut self.u_idx,
        ] {
            v.clear();
        }
        self.l_val.clear();
        self.u_val.clear();
        self.u_diag.clear();
        self.u_diag.resize(n, 0.0);
        self.l_ptr.push(0);
        self.u_ptr.push(0);
        for k in 0..n {
            for (i, v) in l.row_idx_of_col(k).zip(l.val_of_col(k)) {
                if i != k {
                    self.l_idx.push(i);
                    self.l_val.push(*v);
                }
            }
            self.l_ptr.push(self.l_idx.len());
            for (i, v) in u.row_idx_of_col(k).zip(u.val_of_col(k)) {
                if i == k {
                    self.u_diag[k] = *v;
                } else {
                    self.u_idx.push(i);
                    self.u_val.push(*v);
                }
            }
            self.u_ptr.push(self.u_idx.len());
        }
        self.work.clear();
        self.work.resize(n, 0.0);
    }

    /// U's diagonal: the pivots.
    pub(crate) fn pivots(&self) -> &[f64] {
        &self.u_diag
    }

    /// Factorizes `j` (the pattern of the factorization these triangles came from) again
    /// with the same pivots. `false` (the triangles then unusable until taken again) when a
    /// pivot falls below [`THRESHOLD`] times the largest candidate of its column or is not
    /// finite.
    pub(crate) fn refactorize(&mut self, j: &Columns<'_>) -> bool {
        let n = self.n;
        if j.col_perm.len() != n || j.col_ptr.len() != n + 1 {
            return false;
        }
        let x = &mut self.work;
        for step in 0..n {
            let c = j.col_perm[step];
            let range = j.col_ptr[c]..j.col_ptr[c + 1];
            for (r, v) in j.row_idx[range.clone()].iter().zip(&j.values[range]) {
                x[self.perm_inv[*r]] += v;
            }
            for t in self.u_ptr[step]..self.u_ptr[step + 1] {
                let k = self.u_idx[t];
                let ukj = x[k];
                x[k] = 0.0;
                self.u_val[t] = ukj;
                for s in self.l_ptr[k]..self.l_ptr[k + 1] {
                    x[self.l_idx[s]] -= self.l_val[s] * ukj;
                }
            }
            let pivot = x[step];
            x[step] = 0.0;
            let lower = self.l_ptr[step]..self.l_ptr[step + 1];
            let largest = self.l_idx[lower.clone()]
                .iter()
                .fold(0.0_f64, |m, i| m.max(x[*i].abs()));
            if !(pivot.is_finite() && pivot.abs() >= THRESHOLD * largest && pivot != 0.0) {
                x.fill(0.0);
                return false;
            }
            self.u_diag[step] = pivot;
            for s in lower {
                let i = self.l_idx[s];
                self.l_val[s] = x[i] / pivot;
                x[i] = 0.0;
            }
        }
        true
    }

    /// Overwrites `x` (length n) with J⁻¹·x: x ← Q·U⁻¹·L⁻¹·P·x. `col_perm` is the column
    /// order Q.
    pub(crate) fn solve_in_place(&mut self, col_perm: &[usize], x: &mut [f64]) {
        let w = &mut self.work;
        for (p, wp) in w.iter_mut().enumerate() {
            *wp = x[self.perm[p]];
        }
        for k in 0..self.n {
            let wk = w[k];
            if wk != 0.0 {
                for s in self.l_ptr[k]..self.l_ptr[k + 1] {
                    w[self.l_idx[s]] -= self.l_val[s] * wk;
                }
            }
        }
        for j in (0..self.n).rev() {
            let wj = w[j] / self.u_diag[j];
            w[j] = wj;
            if wj != 0.0 {
                for t in self.u_ptr[j]..self.u_ptr[j + 1] {
                    w[self.u_idx[t]] -= self.u_val[t] * wj;
                }
            }
        }
        for (j, wj) in w.iter_mut().enumerate() {
            x[col_perm[j]] = *wj;
            *wj = 0.0;
        }
    }

    /// Overwrites `x` (length n) with J⁻ᵀ·x: Uᵀ·Lᵀ·P·y = Qᵀ·x, solved forward then
    /// backward. `col_perm` is the column order Q.
    pub(crate) fn solve_transpose_in_place(&mut self, col_perm: &[usize], x: &mut [f64]) {
        let w = &mut self.work;
        for j in 0..self.n {
            let known: f64 = (self.u_ptr[j]..self.u_ptr[j + 1])
                .map(|t| self.u_val[t] * w[self.u_idx[t]])
                .sum();
            w[j] = (x[col_perm[j]] - known) / self.u_diag[j];
        }
        for k in (0..self.n).rev() {
            let known: f64 = (self.l_ptr[k]..self.l_ptr[k + 1])
                .map(|s| self.l_val[s] * w[self.l_idx[s]])
                .sum();
            w[k] -= known;
        }
        for (p, wp) in w.iter_mut().enumerate() {
            x[self.perm[p]] = *wp;
            *wp = 0.0;
        }
    }
}
