//! The Newton step of a large square system by a sparse LU of J.
//!
//! The sparse counterpart of [`crate::linalg::square::SquareLu`]: when J is n × n above the dense size
//! and nonsingular, the step −J⁻¹·g comes from one sparse LU of J instead of the Cholesky
//! factor of J·W⁻¹·Jᵀ, the refined minimum-norm solves and the projection. J keeps its
//! sparsity pattern from one Newton iteration to the next, so everything that depends on the
//! pattern alone is done once per pattern ([`Pattern`]): where every triplet of the
//! linearization lands among J's compressed columns (repeats summed), and the column order.
//! That order is J's own while it fills L and U little (the rows of a chain or a ladder,
//! numbered along it, give a narrow band), and faer's COLAMD once the natural order fills
//! more than [`NATURAL_FILL_LIMIT`] times J's entries. Each iteration then scatters the new
//! values into place. The first factorization of a pattern is faer's left-looking
//! simplicial LU, which pivots by rows (partial pivoting, the largest candidate of each
//! column) and finds the patterns of L and U as it goes; later ones keep its pivots and
//! patterns and only redo the arithmetic ([`crate::linalg::lu_triangles`]), until a kept pivot falls
//! below a tenth of its column's largest candidate, when faer pivots afresh. The solves run
//! on those triangles.
//!
//! **Singular J.** faer refuses only a structurally singular J (a column left without a
//! candidate pivot); it accepts a pivot of any size, zero included. This module reads U's
//! diagonal after the factorization and refuses the LU when a pivot is at most
//! [`SINGULAR_PIVOT`] times J's largest entry, or not finite: the test of the dense
//! [`crate::linalg::square::SquareLu`], made on the pivots of this elimination order (COLAMD's columns,
//! rows by partial pivoting) instead of the natural one, followed by the same condition
//! estimate behind a pivot below [`SUSPECT_PIVOT`] (see [`crate::linalg::square`]). On a nearly
//! singular J the two orders may decide differently. A refused LU sends the caller to the
//! minimum-norm path, which decides about rank deficiency as it always did.
//!
//! The step is refined like the dense one (J·Δ + g recomputed with J's own values, a
//! correction unless the miss is rounding, at most [`REFINEMENT`]), and the multipliers
//! λ = −J⁻ᵀ·(W·Δ + c) come from the transposed solve with the same factors.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::perm::PermRef;
use faer::sparse::linalg::colamd;
use faer::sparse::linalg::lu::simplicial::{
    factorize_simplicial_numeric_lu, factorize_simplicial_numeric_lu_scratch, SimplicialLu,
};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};

use crate::linalg::lu_triangles::{Columns, Triangles};

use crate::linalg::square::{ill_conditioned, SINGULAR_PIVOT, SUSPECT_PIVOT};

/// Rounds of iterative refinement after the first solve (skipped when the miss is rounding).
/// One, where the dense LU takes two: a round costs a sparse solve, and one already brings
/// the step to the accuracy that Newton's convergence test can see.
const REFINEMENT: usize = 1;

/// J's own column order is kept while L and U hold at most this many times J's entries (the
/// rows of a chain or a ladder, numbered along it, fill little); above, COLAMD's order is
/// computed once for the pattern and J factorized again.
const NATURAL_FILL_LIMIT: usize = 3;

/// The pattern work of one sparsity pattern of J: kept while the linearizations keep it.
#[derive(Debug, Clone)]
struct Pattern {
    n: usize,
    total_rows: usize,
    /// The row selection this pattern was built for (empty: all rows).
    rows: Vec<usize>,
    /// (row, column) of every triplet, in the order the linearization gives them.
    keys: Vec<(usize, usize)>,
    /// The value slot of every triplet in J's compressed columns, `usize::MAX` for a triplet
    /// of a row that is not used.
    slots: Vec<usize>,
    /// J in compressed columns: rows sorted within each column, no repeats.
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    /// The column order: column `col_perm[k]` of J is eliminated k-th. J's own order until
    /// it fills L and U too much ([`NATURAL_FILL_LIMIT`]), COLAMD's from then on.
    col_perm: Vec<usize>,
    col_perm_inv: Vec<usize>,
    /// Whether `col_perm` is COLAMD's.
    reordered: bool,
}

impl Pattern {
    /// The pattern of the n × n matrix of `triplets` restricted to `rows` (all when `None`),
    /// with its column order. `None` when the rows used are not n, an index is out of range,
    /// or a column is empty (J structurally singular).
    fn build(
        n: usize,
        triplets: &[(usize, usize, f64)],
        total_rows: usize,
        rows: Option<&[usize]>,
    ) -> Option<Self> {
        if n == 0 || rows.map_or(total_rows, <[usize]>::len) != n {
            return None;
        }
        let mut place = vec![usize::MAX; total_rows];
        match rows {
            Some(rows) => {
                for (k, r) in rows.iter().enumerate() {
                    *place.get_mut(*r)? = k;
                }
            }
            None => {
                for (k, p) in place.iter_mut().enumerate() {
                    *p = k;
                }
            }
        }
        // The used triplets bucketed by column: (row of J, triplet index).
        let mut count = vec![0_usize; n + 1];
        for &(r, c, _) in triplets {
            if c >= n {
                return None;
            }
            if *place.get(r)? != usize::MAX {
                count[c + 1] += 1;
            }
        }
        for c in 0..n {
            count[c + 1] += count[c];
        }
        let mut next = count.clone();
        let mut bucket = vec![(0_usize, 0_usize); count[n]];
        for (t, &(r, c, _)) in triplets.iter().enumerate() {
            let row = place[r];
            if row != usize::MAX {
                bucket[next[c]] = (row, t);
                next[c] += 1;
            }
        }
        let mut slots = vec![usize::MAX; triplets.len()];
        let mut col_ptr = Vec::with_capacity(n + 1);
        let mut row_idx = Vec::with_capacity(count[n]);
        col_ptr.push(0);
        for c in 0..n {
            let entries = &mut bucket[count[c]..count[c + 1]];
            if entries.is_empty() {
                return None;
            }
            entries.sort_unstable();
            for &(row, t) in entries.iter() {
                if row_idx.len() == col_ptr[c] || row_idx.last() != Some(&row) {
                    row_idx.push(row);
                }
                slots[t] = row_idx.len() - 1;
            }
            col_ptr.push(row_idx.len());
        }
        Some(Self {
            n,
            total_rows,
            rows: rows.map(<[usize]>::to_vec).unwrap_or_default(),
            keys: triplets.iter().map(|&(r, c, _)| (r, c)).collect(),
            slots,
            col_ptr,
            row_idx,
            col_perm: (0..n).collect(),
            col_perm_inv: (0..n).collect(),
            reordered: false,
        })
    }

    /// Replaces J's own column order by COLAMD's. `false` when COLAMD fails.
    fn reorder(&mut self) -> bool {
        let n = self.n;
        let symbolic =
            SymbolicSparseColMatRef::new_checked(n, n, &self.col_ptr, None, &self.row_idx);
        let mut scratch = MemBuffer::new(colamd::order_scratch::<usize>(n, n, self.row_idx.len()));
        self.reordered = true;
        colamd::order(
            &mut self.col_perm,
            &mut self.col_perm_inv,
            symbolic,
            colamd::Control::default(),
            MemStack::new(&mut scratch),
        )
        .is_ok()
    }

    /// Whether this pattern is that of `triplets` over the same rows.
    fn fits(
        &self,
        n: usize,
        triplets: &[(usize, usize, f64)],
        total_rows: usize,
        rows: Option<&[usize]>,
    ) -> bool {
        self.n == n
            && self.total_rows == total_rows
            && self.rows == rows.unwrap_or(&[])
            && self.keys.len() == triplets.len()
            && self
                .keys
                .iter()
                .zip(triplets)
                .all(|(k, &(r, c, _))| *k == (r, c))
    }
}

/// The sparse LU factors of a square Jacobian, with J's values kept for refinement. One value
/// is refactorized at every Newton iteration ([`SparseLu::refactorize`]), reusing its pattern
/// work while J's pattern stays the same, and its buffers.
#[derive(Default)]
pub(crate) struct SparseLu {
    /// The order of the current factors, 0 when there are none.
    n: usize,
    pattern: Option<Pattern>,
    /// J's values in the pattern's compressed columns.
    values: Vec<f64>,
    lu: SimplicialLu<usize, f64>,
    row_perm: Vec<usize>,
    row_perm_inv: Vec<usize>,
    /// Scratch of faer's factorization.
    scratch: Option<MemBuffer>,
    /// The factors in use, copied from faer's or refactorized with their pivots.
    triangles: Triangles,
    /// Whether `triangles` hold pivots of the current pattern and column order.
    pivots_kept: bool,
    /// Scratch: the miss J·Δ + g, the sizes of the sums that form it, a correction.
    miss: Vec<f64>,
    size: Vec<f64>,
    correction: Vec<f64>,
}

impl std::fmt::Debug for SparseLu {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SparseLu")
            .field("order", &self.n)
            .field("entries", &self.values.len())
            .field("pattern_kept", &self.pattern.is_some())
            .finish()
    }
}

impl Clone for SparseLu {
    /// A clone without factors (the scratch of faer is not clonable): it factorizes anew.
    fn clone(&self) -> Self {
        Self {
            pattern: self.pattern.clone(),
            ..Self::default()
        }
    }
}

impl SparseLu {
    /// Factorizes the n × n matrix of `triplets` (row, column, value; repeats summed)
    /// restricted to the rows `rows` (all when `None`; row `rows[k]` becomes row k). `false`
    /// (the factors then unusable) when the rows used are not n, an index is out of range, an
    /// entry is not finite, J is structurally singular, or a pivot is singular by
    /// [`SINGULAR_PIVOT`] relative to J's largest entry (see the module notes).
    pub(crate) fn refactorize(
        &mut self,
        n: usize,
        triplets: &[(usize, usize, f64)],
        total_rows: usize,
        rows: Option<&[usize]>,
    ) -> bool {
        self.n = 0;
        if !self
            .pattern
            .as_ref()
            .is_some_and(|p| p.fits(n, triplets, total_rows, rows))
        {
            self.pattern = Pattern::build(n, triplets, total_rows, rows);
            self.scratch = None;
            self.pivots_kept = false;
            // faer's simplicial LU keeps the column pointers of a larger earlier matrix (they
            // only grow), which its views then reject: a new pattern starts it afresh.
            self.lu = SimplicialLu::new();
        }
        let Some(p) = &self.pattern else {
            return false;
        };
        self.values.clear();
        self.values.resize(p.row_idx.len(), 0.0);
        for (&(_, _, v), &slot) in triplets.iter().zip(&p.slots) {
            if let Some(value) = self.values.get_mut(slot) {
                *value += v;
            }
        }
        let scale = self.values.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        if !(scale.is_finite() && scale > 0.0) {
            return false;
        }
        let columns = Columns {
            col_ptr: &p.col_ptr,
            row_idx: &p.row_idx,
            values: &self.values,
            col_perm: &p.col_perm,
        };
        // The pivots of the last factorization, while they stay stable; else faer's.
        if !(self.pivots_kept && self.triangles.refactorize(&columns)) {
            self.pivots_kept = false;
            let entries = p.row_idx.len();
            if !self.factorize_numeric(n) {
                return false;
            }
            let fill = self.lu.l_factor_unsorted().compute_nnz()
                + self.lu.u_factor_unsorted().compute_nnz();
            if fill > NATURAL_FILL_LIMIT * entries {
                let reordered = self
                    .pattern
                    .as_mut()
                    .is_some_and(|p| !p.reordered && p.reorder());
                if reordered && !self.factorize_numeric(n) {
                    return false;
                }
            }
            self.triangles
                .take_from(&self.lu, &self.row_perm, &self.row_perm_inv);
            self.pivots_kept = true;
        }
        let Some(p) = &self.pattern else {
            return false;
        };
        let smallest = self.triangles.pivots().iter().fold(f64::INFINITY, |m, d| {
            if d.is_finite() && !m.is_nan() {
                m.min(d.abs())
            } else {
                f64::NAN
            }
        });
        // NaN (a non-finite pivot) counts as singular.
        if smallest.partial_cmp(&(SINGULAR_PIVOT * scale)) != Some(std::cmp::Ordering::Greater) {
            return false;
        }
        for v in [&mut self.miss, &mut self.size, &mut self.correction] {
            v.clear();
            v.resize(n, 0.0);
        }
        self.n = n;
        if smallest <= SUSPECT_PIVOT * scale {
            let norm1 = (0..n)
                .map(|c| {
                    self.values[p.col_ptr[c]..p.col_ptr[c + 1]]
                        .iter()
                        .map(|v| v.abs())
                        .sum::<f64>()
                })
                .fold(0.0, f64::max);
            let Some(f) = self.factors() else {
                return false;
            };
            let mut solve = |b: &[f64], x: &mut [f64], transpose: bool| {
                x.copy_from_slice(b);
                if transpose {
                    f.triangles.solve_transpose_in_place(&f.p.col_perm, x);
                } else {
                    f.triangles.solve_in_place(&f.p.col_perm, x);
                }
            };
            if ill_conditioned(n, norm1, &mut solve) {
                self.n = 0;
                return false;
            }
        }
        true
    }

    /// The numeric factorization of `values` in the pattern's column order. `false` when
    /// faer finds J structurally singular.
    fn factorize_numeric(&mut self, n: usize) -> bool {
        let Some(p) = &self.pattern else {
            return false;
        };
        let scratch = self.scratch.get_or_insert_with(|| {
            MemBuffer::new(factorize_simplicial_numeric_lu_scratch::<usize, f64>(n, n))
        });
        self.row_perm.resize(n, 0);
        self.row_perm_inv.resize(n, 0);
        let j = SparseColMatRef::new(
            SymbolicSparseColMatRef::new_checked(n, n, &p.col_ptr, None, &p.row_idx),
            &self.values,
        );
        let col_perm = PermRef::new_checked(&p.col_perm, &p.col_perm_inv, n);
        factorize_simplicial_numeric_lu(
            &mut self.row_perm,
            &mut self.row_perm_inv,
            &mut self.lu,
            j,
            col_perm,
            MemStack::new(scratch),
        )
        .is_ok()
    }

    /// The order n (0 when the last factorization was refused).
    pub(crate) fn order(&self) -> usize {
        self.n
    }

    /// Δ = −J⁻¹·g, refined while J·Δ + g is above the rounding of the sums that form it
    /// (slices of length n, checked by the callers).
    pub(crate) fn step(&mut self, g: &[f64], dz: &mut [f64]) {
        let Some(factors) = self.factors() else {
            return;
        };
        let Factors {
            p,
            values,
            triangles,
            miss,
            size,
            correction,
        } = factors;
        for (d, gk) in dz.iter_mut().zip(g) {
            *d = -gk;
        }
        triangles.solve_in_place(&p.col_perm, dz);
        for _ in 0..REFINEMENT {
            for ((o, s), gi) in miss.iter_mut().zip(size.iter_mut()).zip(g) {
                *o = *gi;
                *s = gi.abs();
            }
            for (c, d) in dz.iter().enumerate() {
                let range = p.col_ptr[c]..p.col_ptr[c + 1];
                for (r, a) in p.row_idx[range.clone()].iter().zip(&values[range]) {
                    let t = a * d;
                    miss[*r] += t;
                    size[*r] += t.abs();
                }
            }
            let at_rounding = miss
                .iter()
                .zip(size.iter())
                .all(|(o, s)| o.abs() <= 4.0 * f64::EPSILON * s);
            if at_rounding {
                break;
            }
            correction.copy_from_slice(miss);
            triangles.solve_in_place(&p.col_perm, correction);
            for (d, c) in dz.iter_mut().zip(correction.iter()) {
                *d -= c;
            }
        }
    }

    /// The parts of a usable factorization, borrowed apart.
    fn factors(&mut self) -> Option<Factors<'_>> {
        if self.n == 0 {
            return None;
        }
        Some(Factors {
            p: self.pattern.as_ref()?,
            values: &self.values,
            triangles: &mut self.triangles,
            miss: &mut self.miss,
            size: &mut self.size,
            correction: &mut self.correction,
        })
    }

    /// y = J⁻ᵀ·b (slices of length n, checked by the callers).
    pub(crate) fn solve_transpose(&mut self, b: &[f64], y: &mut [f64]) {
        y.copy_from_slice(b);
        if let Some(f) = self.factors() {
            f.triangles.solve_transpose_in_place(&f.p.col_perm, y);
        }
    }

    /// Drops the pattern work and the buffers (a workspace kept between solves holds no
    /// memory of a large one).
    pub(crate) fn forget(&mut self) {
        *self = Self::default();
    }
}

/// The parts of [`SparseLu`] that a solve reads and the scratch it writes.
struct Factors<'a> {
    p: &'a Pattern,
    values: &'a [f64],
    triangles: &'a mut Triangles,
    miss: &'a mut Vec<f64>,
    size: &'a mut Vec<f64>,
    correction: &'a mut Vec<f64>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::linalg::square::SquareLu;
    use approx::assert_relative_eq;
    use proptest::prelude::*;

    fn triplets(a: &[&[f64]]) -> Vec<(usize, usize, f64)> {
        let mut t = Vec::new();
        for (i, row) in a.iter().enumerate() {
            for (c, v) in row.iter().enumerate() {
                if *v != 0.0 {
                    t.push((i, c, *v));
                }
            }
        }
        t
    }

    fn factorize(
        n: usize,
        t: &[(usize, usize, f64)],
        total_rows: usize,
        rows: Option<&[usize]>,
    ) -> Option<SparseLu> {
        let mut lu = SparseLu::default();
        lu.refactorize(n, t, total_rows, rows).then_some(lu)
    }

    /// J·x for J given by its triplets restricted to `rows` (all when `None`).
    fn apply(
        n: usize,
        t: &[(usize, usize, f64)],
        rows: Option<&[usize]>,
        x: &[f64],
        transpose: bool,
    ) -> Vec<f64> {
        let mut out = vec![0.0; n];
        for &(r, c, v) in t {
            let row = match rows {
                Some(rows) => match rows.iter().position(|k| *k == r) {
                    Some(k) => k,
                    None => continue,
                },
                None => r,
            };
            if transpose {
                out[c] += v * x[row];
            } else {
                out[row] += v * x[c];
            }
        }
        out
    }

    /// A system that needs a row exchange (zero leading entry), solved by hand:
    /// [0 2 1; 1 1 0; 2 0 3]·(1, 2, 3) = (7, 3, 11), and Aᵀ·(1, −1, 2) = (3, 1, 7).
    #[test]
    fn pivoted_solve_and_transpose_match_hand_values() {
        let a: [&[f64]; 3] = [&[0.0, 2.0, 1.0], &[1.0, 1.0, 0.0], &[2.0, 0.0, 3.0]];
        let mut lu = factorize(3, &triplets(&a), 3, None).unwrap();
        assert_eq!(lu.order(), 3);
        let mut dz = [0.0; 3];
        lu.step(&[-7.0, -3.0, -11.0], &mut dz);
        for (d, e) in dz.iter().zip([1.0, 2.0, 3.0]) {
            assert_relative_eq!(*d, e, epsilon = 1e-14);
        }
        let mut y = [0.0; 3];
        lu.solve_transpose(&[3.0, 1.0, 7.0], &mut y);
        for (yk, e) in y.iter().zip([1.0, -1.0, 2.0]) {
            assert_relative_eq!(*yk, e, epsilon = 1e-14);
        }
    }

    /// Rows picked and reordered by `rows`; rows outside it are ignored; repeats are summed.
    #[test]
    fn selected_rows_and_repeated_entries() {
        let t = vec![
            (0, 0, 1.0),
            (0, 0, 1.0),
            (0, 1, 1.0),
            (1, 0, 5.0),
            (1, 1, 7.0),
            (2, 1, 4.0),
        ];
        let mut lu = factorize(2, &t, 3, Some(&[2, 0])).unwrap();
        // [0 4; 2 1]·Δ = −g with g = (−8, −5): Δ = (1.5, 2).
        let mut dz = [0.0; 2];
        lu.step(&[-8.0, -5.0], &mut dz);
        assert_relative_eq!(dz[0], 1.5, epsilon = 1e-15);
        assert_relative_eq!(dz[1], 2.0, epsilon = 1e-15);
    }

    #[test]
    fn singular_or_misshapen_systems_are_refused() {
        // Numerically singular: the second row twice the first.
        let dependent = triplets(&[&[1.0, 2.0], &[2.0, 4.0]]);
        assert!(factorize(2, &dependent, 2, None).is_none());
        // Structurally singular: an empty column, and two rows reading one column only.
        let empty_column = triplets(&[&[1.0, 0.0], &[3.0, 0.0]]);
        assert!(factorize(2, &empty_column, 2, None).is_none());
        let one_column = triplets(&[&[1.0, 0.0, 0.0], &[2.0, 0.0, 0.0], &[0.0, 1.0, 1.0]]);
        assert!(factorize(3, &one_column, 3, None).is_none());
        // A pivot below the threshold relative to the largest entry.
        let tiny = triplets(&[&[1.0, 0.0], &[0.0, 1e-13]]);
        assert!(factorize(2, &tiny, 2, None).is_none());
        assert!(factorize(2, &triplets(&[&[1.0, 0.0], &[0.0, 1e-11]]), 2, None).is_some());
        // Three rows for two unknowns, an empty matrix, NaN and infinite entries, indices out
        // of range.
        assert!(factorize(2, &dependent, 3, None).is_none());
        assert!(factorize(0, &[], 0, None).is_none());
        assert!(factorize(1, &[(0, 0, f64::NAN)], 1, None).is_none());
        assert!(factorize(1, &[(0, 0, f64::INFINITY)], 1, None).is_none());
        assert!(factorize(1, &[(0, 1, 1.0)], 1, None).is_none());
        assert!(factorize(1, &[(3, 0, 1.0)], 1, None).is_none());
        assert!(factorize(1, &[(0, 0, 1.0)], 2, Some(&[5])).is_none());
    }

    /// A factorization kept across new values of the same pattern (refactorized with the
    /// kept pivots), across a refused one and across another pattern gives what a fresh one
    /// gives.
    #[test]
    fn refactorizing_reuses_the_pattern_with_the_same_results() {
        let a = triplets(&[&[0.0, 2.0, 1.0], &[1.0, 1.0, 0.0], &[2.0, 0.0, 3.0]]);
        let b: Vec<_> = a.iter().map(|&(r, c, v)| (r, c, v * 1.5 + 0.25)).collect();
        let other = triplets(&[&[4.0, 1.0], &[1.0, 3.0]]);
        let singular: Vec<_> = a.iter().map(|&(r, c, _)| (r, c, 0.0)).collect();
        let mut reused = SparseLu::default();
        assert!(reused.refactorize(3, &a, 3, None));
        assert!(!reused.refactorize(3, &singular, 3, None));
        assert_eq!(reused.order(), 0);
        assert!(reused.refactorize(2, &other, 2, None));
        assert!(reused.refactorize(3, &a, 3, None));
        assert!(reused.pivots_kept);
        assert!(reused.refactorize(3, &b, 3, None));
        let mut fresh = factorize(3, &b, 3, None).unwrap();
        let g = [0.3, -1.7, 0.9];
        let (mut d1, mut d2) = ([0.0; 3], [0.0; 3]);
        reused.step(&g, &mut d1);
        fresh.step(&g, &mut d2);
        let (mut y1, mut y2) = ([0.0; 3], [0.0; 3]);
        reused.solve_transpose(&g, &mut y1);
        fresh.solve_transpose(&g, &mut y2);
        for k in 0..3 {
            assert_relative_eq!(d1[k], d2[k], epsilon = 1e-14);
            assert_relative_eq!(y1[k], y2[k], epsilon = 1e-14);
        }
        let jd = apply(3, &b, None, &d1, false);
        for (j, gk) in jd.iter().zip(g) {
            assert_relative_eq!(*j, -gk, epsilon = 1e-14);
        }
        // A forgotten factorization has no order and factorizes anew.
        reused.forget();
        assert_eq!(reused.order(), 0);
        assert!(reused.refactorize(2, &other, 2, None));
    }

    /// New values that make a kept pivot small against its column ([1 0; ε 1] after [2 0;
    /// 1 1], rows then in the wrong order for partial pivoting) are pivoted afresh.
    #[test]
    fn a_kept_pivot_that_became_small_is_chosen_again() {
        let first = [(0, 0, 2.0), (1, 0, 1.0), (1, 1, 1.0), (0, 1, 0.0)];
        let mut lu = factorize(2, &first, 2, None).unwrap();
        // Row 0 was the pivot of column 0; now it is 1e-3 against row 1's 1.
        let second = [(0, 0, 1e-3), (1, 0, 1.0), (1, 1, 1.0), (0, 1, 1.0)];
        assert!(lu.refactorize(2, &second, 2, None));
        assert_relative_eq!(lu.triangles.pivots()[0].abs(), 1.0, epsilon = 1e-15);
        let mut dz = [0.0; 2];
        lu.step(&[-1.0, -2.0], &mut dz);
        for (jd, gk) in apply(2, &second, None, &dz, false).iter().zip([-1.0, -2.0]) {
            assert_relative_eq!(*jd, -gk, epsilon = 1e-14);
        }
    }

    /// An arrowhead J (full first row and column, a diagonal) fills L and U completely in its
    /// own order and not at all in COLAMD's: the pattern is reordered, and the step is right.
    /// A tridiagonal J keeps its own order.
    #[test]
    fn the_column_order_changes_only_when_the_natural_one_fills() {
        let n = 40;
        let mut arrow = vec![(0, 0, 10.0)];
        for k in 1..n {
            arrow.extend([(0, k, 1.0), (k, 0, 1.0), (k, k, 2.0 + k as f64)]);
        }
        let mut lu = factorize(n, &arrow, n, None).unwrap();
        assert!(lu.pattern.as_ref().unwrap().reordered);
        let g: Vec<f64> = (0..n).map(|k| (k as f64).sin()).collect();
        let mut dz = vec![0.0; n];
        lu.step(&g, &mut dz);
        for (jd, gk) in apply(n, &arrow, None, &dz, false).iter().zip(&g) {
            assert_relative_eq!(*jd, -gk, epsilon = 1e-13);
        }
        let mut band = Vec::new();
        for k in 0..n {
            band.push((k, k, 4.0));
            if k + 1 < n {
                band.extend([(k, k + 1, 1.0), (k + 1, k, -1.0)]);
            }
        }
        let lu = factorize(n, &band, n, None).unwrap();
        assert!(!lu.pattern.as_ref().unwrap().reordered);
    }

    /// A random sparse n × n J, strictly diagonally dominant by rows before its rows are
    /// shuffled (so nonsingular, while the natural diagonal is no pivot), diagonal entries
    /// split in two triplets; and three right-hand sides.
    fn sparse_system() -> impl Strategy<Value = (usize, Vec<(usize, usize, f64)>, Vec<f64>)> {
        (1_usize..60).prop_flat_map(|n| {
            (
                proptest::collection::vec((0..n, 0..n, -1.0..1.0_f64), 0..3 * n),
                proptest::collection::vec(0.5..2.0_f64, n),
                Just((0..n).collect::<Vec<_>>()).prop_shuffle(),
                proptest::collection::vec(-10.0..10.0_f64, 3 * n),
            )
                .prop_map(move |(off, diag, shuffle, rhs)| {
                    let mut t = Vec::new();
                    for (k, d) in diag.iter().enumerate() {
                        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
                        t.push((shuffle[k], k, 0.5 * sign * d));
                        t.push((shuffle[k], k, 0.5 * sign * d));
                    }
                    // The off-diagonal entries of a row sum to less than 0.4 in size.
                    let mut count = vec![0_usize; n];
                    for &(r, c, _) in &off {
                        if r != c {
                            count[r] += 1;
                        }
                    }
                    for (r, c, v) in off {
                        if r != c {
                            t.push((shuffle[r], c, 0.4 * v / count[r] as f64));
                        }
                    }
                    (n, t, rhs)
                })
        })
    }

    proptest! {
        /// On random sparse nonsingular systems the sparse step agrees with the dense LU's and
        /// with the weighted minimum-norm step it replaces, meets J·Δ = −g, and the transposed
        /// solve meets Jᵀ·y = b.
        #[test]
        fn sparse_step_matches_dense_and_minimum_norm((n, t, rhs) in sparse_system()) {
            let g = &rhs[..n];
            let b = &rhs[n..2 * n];
            let w: Vec<f64> = rhs[2 * n..].iter().map(|v| 1.0 + v.abs()).collect();
            let mut sparse = factorize(n, &t, n, None).unwrap();
            let mut dense = SquareLu::factorize(n, &t, n, None).unwrap();
            let (mut ds, mut dd) = (vec![0.0; n], vec![0.0; n]);
            sparse.step(g, &mut ds);
            dense.step(g, &mut dd);
            let j = crate::SparseMatrix::try_from_triplets(n, n, &t).unwrap();
            let mut min_norm = crate::linalg::min_norm::MinNormFactorization::try_dense(&j, &w).unwrap();
            let mut dm = vec![0.0; n];
            min_norm.solve(g, &mut dm).unwrap();
            let scale = 1.0 + dd.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            for k in 0..n {
                prop_assert!((ds[k] - dd[k]).abs() <= 1e-11 * scale, "{} vs {}", ds[k], dd[k]);
                prop_assert!((ds[k] - dm[k]).abs() <= 1e-9 * scale, "{} vs {}", ds[k], dm[k]);
            }
            for (jd, gk) in apply(n, &t, None, &ds, false).iter().zip(g) {
                prop_assert!((jd + gk).abs() <= 1e-11 * (1.0 + gk.abs()) * scale);
            }
            let mut y = vec![0.0; n];
            sparse.solve_transpose(b, &mut y);
            let mut yd = vec![0.0; n];
            dense.solve_transpose(b, &mut yd);
            let ymax = 1.0 + yd.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            for (jy, bk) in apply(n, &t, None, &y, true).iter().zip(b) {
                prop_assert!((jy - bk).abs() <= 1e-11 * ymax * (1.0 + bk.abs()));
            }
            for k in 0..n {
                prop_assert!((y[k] - yd[k]).abs() <= 1e-10 * ymax);
            }
        }

        /// The same system with one row replaced by the sum of two others (exactly
        /// representable) is refused, as the dense LU refuses it.
        #[test]
        fn dependent_rows_are_refused(
            (n, t, _) in sparse_system().prop_filter("three rows", |(n, _, _)| *n >= 3),
            pick in any::<[proptest::sample::Index; 3]>(),
        ) {
            // Round the values to multiples of 1/8 so that the sum is exact.
            let mut rows: Vec<Vec<(usize, f64)>> = vec![Vec::new(); n];
            for &(r, c, v) in &t {
                rows[r].push((c, (v * 8.0).round() / 8.0));
            }
            let a = pick[0].index(n);
            let b = (a + 1 + pick[1].index(n - 1)) % n;
            let mut target = pick[2].index(n);
            while target == a || target == b {
                target = (target + 1) % n;
            }
            let mut sum = rows[a].clone();
            sum.extend_from_slice(&rows[b]);
            rows[target] = sum;
            let singular: Vec<_> = rows
                .iter()
                .enumerate()
                .flat_map(|(r, row)| row.iter().map(move |&(c, v)| (r, c, v)))
                .collect();
            prop_assert!(SquareLu::factorize(n, &singular, n, None).is_none());
            prop_assert!(factorize(n, &singular, n, None).is_none());
        }

        /// New values on the same pattern, refactorized with the pivots of the first values
        /// (or pivoted afresh when they became unstable), give the dense LU's step.
        #[test]
        fn kept_pivots_give_the_dense_step(
            (n, t, rhs) in sparse_system(),
            factors in proptest::collection::vec(0.5..1.5_f64, 200),
        ) {
            let mut sparse = factorize(n, &t, n, None).unwrap();
            let moved: Vec<_> = t
                .iter()
                .enumerate()
                .map(|(k, &(r, c, v))| (r, c, v * factors[k % factors.len()]))
                .collect();
            prop_assert!(sparse.refactorize(n, &moved, n, None));
            let mut dense = SquareLu::factorize(n, &moved, n, None).unwrap();
            let g = &rhs[..n];
            let (mut ds, mut dd) = (vec![0.0; n], vec![0.0; n]);
            sparse.step(g, &mut ds);
            dense.step(g, &mut dd);
            let scale = 1.0 + dd.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            for k in 0..n {
                prop_assert!((ds[k] - dd[k]).abs() <= 1e-11 * scale, "{} vs {}", ds[k], dd[k]);
            }
            let b = &rhs[n..2 * n];
            let (mut y, mut yd) = (vec![0.0; n], vec![0.0; n]);
            sparse.solve_transpose(b, &mut y);
            dense.solve_transpose(b, &mut yd);
            let ymax = 1.0 + yd.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            for k in 0..n {
                prop_assert!((y[k] - yd[k]).abs() <= 1e-10 * ymax);
            }
        }

        /// Selected rows: the rows outside the selection do not count.
        #[test]
        fn selected_rows_match_the_dense_lu((n, t, rhs) in sparse_system()) {
            // J's rows spread over 2n rows of a taller matrix (odd rows unused, filled with
            // noise), selected back in reverse order.
            let mut tall: Vec<_> = t.iter().map(|&(r, c, v)| (2 * r, c, v)).collect();
            tall.extend((0..n).map(|k| (2 * k + 1, (k + 1) % n, 7.0)));
            let rows: Vec<usize> = (0..n).rev().map(|k| 2 * k).collect();
            let g = &rhs[..n];
            let mut sparse = factorize(n, &tall, 2 * n, Some(&rows)).unwrap();
            let mut dense = SquareLu::factorize(n, &tall, 2 * n, Some(&rows)).unwrap();
            let (mut ds, mut dd) = (vec![0.0; n], vec![0.0; n]);
            sparse.step(g, &mut ds);
            dense.step(g, &mut dd);
            let scale = 1.0 + dd.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            for k in 0..n {
                prop_assert!((ds[k] - dd[k]).abs() <= 1e-11 * scale);
            }
            for (jd, gk) in apply(n, &tall, Some(&rows), &ds, false).iter().zip(g) {
                prop_assert!((jd + gk).abs() <= 1e-11 * (1.0 + gk.abs()) * scale);
            }
        }
    }
}
