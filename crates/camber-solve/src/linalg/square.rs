//! The Newton step of a square system: as many rows as free unknowns.
//!
//! When J is n × n and nonsingular, J·Δ = −g has exactly one solution, so the weighted
//! minimum-norm step −W⁻¹·Jᵀ·(J·W⁻¹·Jᵀ)⁻¹·g of [`crate::linalg::min_norm`] is simply −J⁻¹·g and the
//! null space that the pull-back moves in is empty. One LU factorization of J with partial
//! pivoting (n³/3 flops) then replaces the product J·W⁻¹·Jᵀ, its Cholesky factorization, the
//! refined solve and the projection of the projected conjugate gradients, and it works on J's
//! own condition number instead of its square. The multipliers of the step (K·Δ + c + Jᵀ·λ = 0
//! with K = W) are λ = −J⁻ᵀ·(W·Δ + c): one more solve with the same factors.
//!
//! A J whose pivots fall below [`SINGULAR_PIVOT`] relative to its largest entry is refused
//! ([`SquareLu::factorize`] returns `None`) and the caller keeps the minimum-norm path, which
//! decides about rank deficiency as it always did. Partial pivoting does not reveal rank,
//! though: a small but genuine pivot p divides the rounding left in the candidates it
//! eliminates by p, and an exactly singular J can then end with a last pivot far above the
//! threshold (a random sparse case: a genuine pivot 3·10⁻⁸ turned the exact zero into 9·10⁻¹⁰).
//! So when a pivot is below [`SUSPECT_PIVOT`] relative to the largest entry, the 1-norm
//! condition number is estimated with the factors ([`inverse_norm1_estimate`], Hager's method
//! with Higham's safeguard, a handful of solves) and J is refused when it exceeds
//! 1/[`SINGULAR_PIVOT`]. Above that gate every pivot amplifies rounding by less than
//! 1/[`SUSPECT_PIVOT`], which leaves the zero pivot of a singular J far below the threshold.
//!
//! Above the dense size the same step comes from a sparse LU ([`crate::linalg::sparse_lu`]);
//! [`SquareFactors`] holds both and picks by the order.

use crate::linalg::sparse_lu::SparseLu;

/// A pivot at most this fraction of max |Jᵢⱼ| counts as singular (the LU is refused).
pub(crate) const SINGULAR_PIVOT: f64 = 1e-12;

/// A pivot at most this fraction of max |Jᵢⱼ| makes the condition number worth estimating.
pub(crate) const SUSPECT_PIVOT: f64 = 1e-4;

/// `solve(b, x, transpose)`: x = J⁻¹·b, or J⁻ᵀ·b when `transpose`, with a J's factors.
pub(crate) type Solve<'a> = dyn FnMut(&[f64], &mut [f64], bool) + 'a;

/// Whether the condition number κ₁(J) = ‖J‖₁·‖J⁻¹‖₁ exceeds 1/[`SINGULAR_PIVOT`], with
/// ‖J⁻¹‖₁ from [`inverse_norm1_estimate`]; `solve(b, x, transpose)` writes J⁻¹·b (J⁻ᵀ·b).
pub(crate) fn ill_conditioned(n: usize, norm1: f64, solve: &mut Solve<'_>) -> bool {
    let inverse = inverse_norm1_estimate(n, solve);
    // NaN counts as ill-conditioned.
    let refused =
        (norm1 * inverse).partial_cmp(&(1.0 / SINGULAR_PIVOT)) != Some(std::cmp::Ordering::Less);
    #[cfg(test)]
    if refused {
        CONDITION_REFUSALS.with(|c| c.set(c.get() + 1));
    }
    refused
}

#[cfg(test)]
thread_local! {
    /// How many factorizations [`ill_conditioned`] refused on this thread (for the tests that
    /// show which test refused a J).
    pub(crate) static CONDITION_REFUSALS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

/// A lower estimate of ‖J⁻¹‖₁ (usually within a factor of 3) from a few solves with J's
/// factors: Hager's method as Higham refined it (LAPACK's `xLACON`), at most five rounds of
/// J⁻¹·x at a vertex of the unit ball and one J⁻ᵀ·sign, then the larger of that and the
/// alternating-sign test vector's 2‖J⁻¹·b‖₁/(3n). Infinite when a solve leaves a non-finite
/// entry.
pub(crate) fn inverse_norm1_estimate(n: usize, solve: &mut Solve<'_>) -> f64 {
    if n == 0 {
        return 0.0;
    }
    let norm1 = |v: &[f64]| v.iter().map(|x| x.abs()).sum::<f64>();
    let sign = |v: f64| if v < 0.0 { -1.0 } else { 1.0 };
    let mut x = vec![1.0 / n as f64; n];
    let mut y = vec![0.0; n];
    let mut xi = vec![0.0; n];
    solve(&x, &mut y, false);
    let mut estimate = norm1(&y);
    if !estimate.is_finite() {
        return f64::INFINITY;
    }
    if n == 1 {
        return estimate;
    }
    for (s, v) in xi.iter_mut().zip(&y) {
        *s = sign(*v);
    }
    solve(&xi, &mut x, true);
    let argmax = |v: &[f64]| {
        v.iter()
            .enumerate()
            .fold(
                (0, -1.0),
                |(k, m), (i, a)| if a.abs() > m { (i, a.abs()) } else { (k, m) },
            )
            .0
    };
    let mut j = argmax(&x);
    for _ in 0..4 {
        x.fill(0.0);
        x[j] = 1.0;
        solve(&x, &mut y, false);
        let previous = estimate;
        estimate = norm1(&y);
        if !estimate.is_finite() {
            return f64::INFINITY;
        }
        let same_signs = xi.iter().zip(&y).all(|(s, v)| (*s < 0.0) == (*v < 0.0));
        if same_signs || estimate <= previous {
            estimate = estimate.max(previous);
            break;
        }
        for (s, v) in xi.iter_mut().zip(&y) {
            *s = sign(*v);
        }
        solve(&xi, &mut x, true);
        let last = j;
        j = argmax(&x);
        if x[last].abs() >= x[j].abs() {
            break;
        }
    }
    // Higham's safeguard against the cases where the vertices mislead.
    let denominator = (n - 1) as f64;
    for (i, v) in x.iter_mut().enumerate() {
        let size = 1.0 + i as f64 / denominator;
        *v = if i % 2 == 0 { size } else { -size };
    }
    solve(&x, &mut y, false);
    let alternating = 2.0 * norm1(&y) / (3.0 * n as f64);
    if alternating.is_finite() {
        estimate.max(alternating)
    } else {
        f64::INFINITY
    }
}

/// Rounds of iterative refinement after the first solve (stopped early once the miss is
/// rounding).
const REFINEMENT: usize = 2;

/// The LU of a square Jacobian: dense ([`SquareLu`]) up to the dense size, sparse
/// ([`SparseLu`]) above it. One value is refactorized at every Newton iteration, reusing the
/// buffers of both and the sparse pattern work.
#[derive(Debug, Clone, Default)]
pub(crate) struct SquareFactors {
    dense: SquareLu,
    sparse: SparseLu,
    /// Whether the current factors are the sparse ones.
    sparse_active: bool,
}

impl SquareFactors {
    /// Factorizes J as [`SquareLu::refactorize`] does, by the sparse LU when n exceeds
    /// `dense_max_unknowns`: `false` (the factors then unusable) where that refuses J.
    pub(crate) fn refactorize(
        &mut self,
        n: usize,
        triplets: &[(usize, usize, f64)],
        total_rows: usize,
        rows: Option<&[usize]>,
        dense_max_unknowns: usize,
    ) -> bool {
        self.sparse_active = n > dense_max_unknowns;
        if self.sparse_active {
            self.sparse.refactorize(n, triplets, total_rows, rows)
        } else {
            self.dense.refactorize(n, triplets, total_rows, rows)
        }
    }

    /// The order n of the current factors (0 when the last factorization was refused).
    pub(crate) fn order(&self) -> usize {
        if self.sparse_active {
            self.sparse.order()
        } else {
            self.dense.order()
        }
    }

    /// Δ = −J⁻¹·g, refined (slices of length n, checked by the callers).
    pub(crate) fn step(&mut self, g: &[f64], dz: &mut [f64]) {
        if self.sparse_active {
            self.sparse.step(g, dz);
        } else {
            self.dense.step(g, dz);
        }
    }

    /// y = J⁻ᵀ·b (slices of length n, checked by the callers).
    pub(crate) fn solve_transpose(&mut self, b: &[f64], y: &mut [f64]) {
        if self.sparse_active {
            self.sparse.solve_transpose(b, y);
        } else {
            self.dense.solve_transpose(b, y);
        }
    }

    /// Drops the sparse pattern work and buffers (kept dense buffers are small).
    pub(crate) fn forget_sparse(&mut self) {
        self.sparse.forget();
        self.sparse_active = false;
    }
}

/// The LU factors P·J = L·U of a dense square Jacobian, with J kept for refinement. One value
/// is refactorized at every Newton iteration ([`SquareLu::refactorize`]), reusing its buffers.
#[derive(Debug, Clone, Default)]
pub(crate) struct SquareLu {
    n: usize,
    /// J, row-major.
    j: Vec<f64>,
    /// L (unit diagonal, below) and U (on and above), row-major, rows in pivot order.
    lu: Vec<f64>,
    /// Row `perm[k]` of J is row k of P·J.
    perm: Vec<usize>,
    /// Scratch: the place of every row of the whole J among the rows used.
    place: Vec<usize>,
    /// Scratch: a residual, a correction, and the intermediate of the transposed solve.
    miss: Vec<f64>,
    correction: Vec<f64>,
    w: Vec<f64>,
}

impl SquareLu {
    /// Factorizes the n × n matrix of `triplets` (row, column, value; repeats summed) restricted
    /// to the rows `rows` (all when `None`; row `rows[k]` becomes row k). `None` when the rows
    /// used are not n, an index is out of range, an entry is not finite, or a pivot is
    /// singular by [`SINGULAR_PIVOT`].
    #[cfg(test)]
    pub(crate) fn factorize(
        n: usize,
        triplets: &[(usize, usize, f64)],
        total_rows: usize,
        rows: Option<&[usize]>,
    ) -> Option<Self> {
        let mut lu = Self::default();
        lu.refactorize(n, triplets, total_rows, rows).then_some(lu)
    }

    /// [`SquareLu::factorize`] into this value, reusing its buffers: `false` (the factors
    /// then unusable) where that gives `None`.
    pub(crate) fn refactorize(
        &mut self,
        n: usize,
        triplets: &[(usize, usize, f64)],
        total_rows: usize,
        rows: Option<&[usize]>,
    ) -> bool {
        self.n = 0;
        if n == 0 || rows.map_or(total_rows, <[usize]>::len) != n {
            return false;
        }
        let place = &mut self.place;
        place.clear();
        if let Some(rows) = rows {
            place.resize(total_rows, usize::MAX);
            for (k, r) in rows.iter().enumerate() {
                match place.get_mut(*r) {
                    Some(slot) => *slot = k,
                    None => return false,
                }
            }
        }
        let j = &mut self.j;
        j.clear();
        j.resize(n * n, 0.0);
        for &(r, c, v) in triplets {
            let row = if rows.is_some() {
                match place.get(r) {
                    Some(k) if *k != usize::MAX => *k,
                    Some(_) => continue,
                    None => return false,
                }
            } else {
                r
            };
            if row >= n || c >= n {
                return false;
            }
            j[row * n + c] += v;
        }
        let scale = j.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        if !(scale.is_finite() && scale > 0.0) {
            return false;
        }
        let lu = &mut self.lu;
        lu.clear();
        lu.extend_from_slice(j);
        let perm = &mut self.perm;
        perm.clear();
        perm.extend(0..n);
        let mut suspect = false;
        for k in 0..n {
            // Partial pivoting: the largest entry of column k at or below the diagonal.
            let mut p = k;
            for i in k + 1..n {
                if lu[i * n + k].abs() > lu[p * n + k].abs() {
                    p = i;
                }
            }
            let pivot = lu[p * n + k];
            if pivot.abs() <= SINGULAR_PIVOT * scale || pivot.is_nan() {
                return false;
            }
            suspect |= pivot.abs() <= SUSPECT_PIVOT * scale;
            if p != k {
                for c in 0..n {
                    lu.swap(k * n + c, p * n + c);
                }
                perm.swap(k, p);
            }
            // Rows below k by slices (the same arithmetic without an index check per entry).
            let (top, below) = lu.split_at_mut((k + 1) * n);
            let pivot_row = &top[k * n + k + 1..(k + 1) * n];
            for row in below.chunks_exact_mut(n) {
                let f = row[k] / pivot;
                row[k] = f;
                if f != 0.0 {
                    for (a, p) in row[k + 1..].iter_mut().zip(pivot_row) {
                        *a -= f * p;
                    }
                }
            }
        }
        for v in [&mut self.miss, &mut self.correction, &mut self.w] {
            v.clear();
            v.resize(n, 0.0);
        }
        self.n = n;
        if suspect {
            let norm1 = (0..n)
                .map(|c| (0..n).map(|i| self.j[i * n + c].abs()).sum::<f64>())
                .fold(0.0, f64::max);
            let mut solve = |b: &[f64], x: &mut [f64], transpose: bool| {
                if transpose {
                    self.solve_transpose(b, x);
                } else {
                    self.solve_plain(b, x);
                }
            };
            if ill_conditioned(n, norm1, &mut solve) {
                self.n = 0;
                return false;
            }
        }
        true
    }

    /// The order n.
    pub(crate) fn order(&self) -> usize {
        self.n
    }

    /// x = J⁻¹·b (slices of length n, checked by the callers).
    fn solve_plain(&self, b: &[f64], x: &mut [f64]) {
        let n = self.n;
        // L·y = P·b.
        for k in 0..n {
            let row = &self.lu[k * n..k * n + k];
            let known: f64 = row.iter().zip(&x[..k]).map(|(a, v)| a * v).sum();
            x[k] = b[self.perm[k]] - known;
        }
        // U·x = y.
        for k in (0..n).rev() {
            let row = &self.lu[k * n + k + 1..(k + 1) * n];
            let known: f64 = row.iter().zip(&x[k + 1..]).map(|(a, v)| a * v).sum();
            x[k] = (x[k] - known) / self.lu[k * n + k];
        }
    }

    /// Δ = −J⁻¹·g, refined while J·Δ + g is above the rounding of the sums that form it.
    pub(crate) fn step(&mut self, g: &[f64], dz: &mut [f64]) {
        let n = self.n;
        self.solve_plain(g, dz);
        for d in dz.iter_mut() {
            *d = -*d;
        }
        let mut miss = std::mem::take(&mut self.miss);
        let mut correction = std::mem::take(&mut self.correction);
        for _ in 0..REFINEMENT {
            let mut at_rounding = true;
            for (i, (o, gi)) in miss.iter_mut().zip(g).enumerate() {
                let (mut sum, mut size) = (*gi, gi.abs());
                for (a, d) in self.j[i * n..(i + 1) * n].iter().zip(dz.iter()) {
                    let t = a * d;
                    sum += t;
                    size += t.abs();
                }
                *o = sum;
                at_rounding &= sum.abs() <= 4.0 * f64::EPSILON * size;
            }
            if at_rounding {
                break;
            }
            self.solve_plain(&miss, &mut correction);
            for (d, c) in dz.iter_mut().zip(&correction) {
                *d -= c;
            }
        }
        self.miss = miss;
        self.correction = correction;
    }

    /// y = J⁻ᵀ·b (Jᵀ = Uᵀ·Lᵀ·P).
    pub(crate) fn solve_transpose(&mut self, b: &[f64], y: &mut [f64]) {
        let n = self.n;
        let mut w = std::mem::take(&mut self.w);
        w.clear();
        w.resize(n, 0.0);
        // Uᵀ·w = b.
        for k in 0..n {
            let known: f64 = w[..k]
                .iter()
                .enumerate()
                .map(|(r, v)| self.lu[r * n + k] * v)
                .sum();
            w[k] = (b[k] - known) / self.lu[k * n + k];
        }
        // Lᵀ·v = w (in place).
        for k in (0..n).rev() {
            let known: f64 = w[k + 1..]
                .iter()
                .enumerate()
                .map(|(i, v)| self.lu[(k + 1 + i) * n + k] * v)
                .sum();
            w[k] -= known;
        }
        // y = Pᵀ·v.
        for (k, v) in w.iter().enumerate() {
            y[self.perm[k]] = *v;
        }
        self.w = w;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

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

    /// A system that needs a row exchange (zero leading entry), solved by hand:
    /// [0 2 1; 1 1 0; 2 0 3]·(1, 2, 3) = (7, 3, 11).
    #[test]
    fn pivoted_solve_and_transpose_match_hand_values() {
        let a: [&[f64]; 3] = [&[0.0, 2.0, 1.0], &[1.0, 1.0, 0.0], &[2.0, 0.0, 3.0]];
        let x = [1.0, 2.0, 3.0];
        // A·x = (7, 3, 11).
        let g = [-7.0, -3.0, -11.0];
        let mut lu = SquareLu::factorize(3, &triplets(&a), 3, None).unwrap();
        let mut dz = [0.0; 3];
        lu.step(&g, &mut dz);
        for k in 0..3 {
            assert_relative_eq!(dz[k], x[k], epsilon = 1e-14);
        }
        // Aᵀ·y = b with y = (1, −1, 2): Aᵀy = (0·1 + 1·(−1) + 2·2, 2 − 1 + 0, 1 + 0 + 6).
        let b = [3.0, 1.0, 7.0];
        let mut y = [0.0; 3];
        lu.solve_transpose(&b, &mut y);
        for (yk, e) in y.iter().zip([1.0, -1.0, 2.0]) {
            assert_relative_eq!(*yk, e, epsilon = 1e-14);
        }
    }

    /// Rows picked and reordered by `rows`; rows outside it are ignored; repeats are summed.
    #[test]
    fn selected_rows_and_repeated_entries() {
        // Rows 0 and 2 of a 3-row J, the (0, 0) entry split in two.
        let t = vec![
            (0, 0, 1.0),
            (0, 0, 1.0),
            (0, 1, 1.0),
            (1, 0, 5.0),
            (1, 1, 7.0),
            (2, 1, 4.0),
        ];
        let mut lu = SquareLu::factorize(2, &t, 3, Some(&[2, 0])).unwrap();
        assert_eq!(lu.order(), 2);
        // [0 4; 2 1]·Δ = −g with g = (−8, −5): Δ = (1.5, 2).
        let mut dz = [0.0; 2];
        lu.step(&[-8.0, -5.0], &mut dz);
        assert_relative_eq!(dz[0], 1.5, epsilon = 1e-15);
        assert_relative_eq!(dz[1], 2.0, epsilon = 1e-15);
    }

    /// A factorization reused for another system (of another order, after a refused one) gives
    /// bit for bit what a fresh one gives.
    #[test]
    fn refactorizing_reuses_buffers_with_the_same_results() {
        let a: [&[f64]; 3] = [&[0.0, 2.0, 1.0], &[1.0, 1.0, 0.0], &[2.0, 0.0, 3.0]];
        let b: [&[f64]; 2] = [&[4.0, 1.0], &[1.0, 3.0]];
        let mut reused = SquareLu::default();
        assert!(reused.refactorize(3, &triplets(&a), 3, None));
        let singular = triplets(&[&[1.0, 2.0], &[2.0, 4.0]]);
        assert!(!reused.refactorize(2, &singular, 2, None));
        assert!(reused.refactorize(2, &triplets(&b), 3, Some(&[1, 0])));
        assert!(reused.refactorize(2, &triplets(&b), 2, None));
        let mut fresh = SquareLu::factorize(2, &triplets(&b), 2, None).unwrap();
        let g = [0.3, -1.7];
        let (mut d1, mut d2) = ([0.0; 2], [0.0; 2]);
        reused.step(&g, &mut d1);
        fresh.step(&g, &mut d2);
        assert_eq!(d1.map(f64::to_bits), d2.map(f64::to_bits));
        let (mut y1, mut y2) = ([0.0; 2], [0.0; 2]);
        reused.solve_transpose(&g, &mut y1);
        fresh.solve_transpose(&g, &mut y2);
        assert_eq!(y1.map(f64::to_bits), y2.map(f64::to_bits));
        // [4 1; 1 3]·Δ = −g.
        assert_relative_eq!(4.0 * d1[0] + d1[1], -g[0], epsilon = 1e-15);
        assert_relative_eq!(d1[0] + 3.0 * d1[1], -g[1], epsilon = 1e-15);
    }

    #[test]
    fn singular_or_misshapen_systems_are_refused() {
        let dependent = triplets(&[&[1.0, 2.0], &[2.0, 4.0]]);
        assert!(SquareLu::factorize(2, &dependent, 2, None).is_none());
        // Three rows for two unknowns, an empty matrix, a NaN entry, an index out of range.
        assert!(SquareLu::factorize(2, &dependent, 3, None).is_none());
        assert!(SquareLu::factorize(0, &[], 0, None).is_none());
        assert!(SquareLu::factorize(1, &[(0, 0, f64::NAN)], 1, None).is_none());
        assert!(SquareLu::factorize(1, &[(0, 1, 1.0)], 1, None).is_none());
        assert!(SquareLu::factorize(1, &[(0, 0, 1.0)], 2, Some(&[5])).is_none());
    }

    /// The step agrees with the weighted minimum-norm solve it replaces, on a random
    /// well-conditioned J, and λ = −J⁻ᵀ·r solves Jᵀ·λ = −r.
    #[test]
    fn agrees_with_the_minimum_norm_step() {
        let n = 6;
        let mut state = 12345_u64;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64) / ((1_u64 << 53) as f64) - 0.5
        };
        let mut t = Vec::new();
        for i in 0..n {
            for c in 0..n {
                let v = next() + if i == c { 3.0 } else { 0.0 };
                t.push((i, c, v));
            }
        }
        let g: Vec<f64> = (0..n).map(|_| next()).collect();
        let w: Vec<f64> = (0..n).map(|k| 1.0 + k as f64).collect();
        let j = crate::SparseMatrix::try_from_triplets(n, n, &t).unwrap();
        let mut reference =
            crate::linalg::min_norm::MinNormFactorization::try_dense(&j, &w).unwrap();
        let mut expected = vec![0.0; n];
        reference.solve(&g, &mut expected).unwrap();
        let mut lu = SquareLu::factorize(n, &t, n, None).unwrap();
        let mut dz = vec![0.0; n];
        lu.step(&g, &mut dz);
        for k in 0..n {
            assert_relative_eq!(dz[k], expected[k], epsilon = 1e-12);
        }
        let r: Vec<f64> = (0..n).map(|_| next()).collect();
        let mut y = vec![0.0; n];
        lu.solve_transpose(&r, &mut y);
        let jd = j.to_dense();
        for c in 0..n {
            let s: f64 = (0..n).map(|i| jd[(i, c)] * y[i]).sum();
            assert_relative_eq!(s, r[c], epsilon = 1e-12);
        }
    }

    /// The estimate of ‖J⁻¹‖₁ is a lower bound of the exact value (the largest column sum of
    /// J⁻¹, from n solves) and, on these random matrices, close to it; the pivot test and the
    /// estimate together refuse a J whose rows depend on each other after a small genuine
    /// pivot.
    #[test]
    fn inverse_norm_estimate_bounds_the_exact_norm() {
        let mut state = 987_u64;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64) / ((1_u64 << 53) as f64) - 0.5
        };
        for n in 1..12 {
            let t: Vec<_> = (0..n)
                .flat_map(|i| (0..n).map(move |c| (i, c)))
                .map(|(i, c)| (i, c, next() + if i == c { 0.3 } else { 0.0 }))
                .collect();
            let mut lu = SquareLu::factorize(n, &t, n, None).unwrap();
            let mut exact = 0.0_f64;
            let (mut e, mut col) = (vec![0.0; n], vec![0.0; n]);
            for k in 0..n {
                e.fill(0.0);
                e[k] = 1.0;
                lu.solve_plain(&e, &mut col);
                exact = exact.max(col.iter().map(|v| v.abs()).sum());
            }
            let estimate = inverse_norm1_estimate(n, &mut |b, x, transpose| {
                if transpose {
                    lu.solve_transpose(b, x);
                } else {
                    lu.solve_plain(b, x);
                }
            });
            assert!(
                estimate <= exact * (1.0 + 1e-12),
                "n = {n}: {estimate} > {exact}"
            );
            assert!(estimate >= exact / 3.0, "n = {n}: {estimate} ≪ {exact}");
        }
        // diag(1, 1/4): ‖J⁻¹‖₁ = 4.
        let mut lu = SquareLu::factorize(2, &[(0, 0, 1.0), (1, 1, 0.25)], 2, None).unwrap();
        let estimate = inverse_norm1_estimate(2, &mut |b, x, transpose| {
            if transpose {
                lu.solve_transpose(b, x);
            } else {
                lu.solve_plain(b, x);
            }
        });
        assert_relative_eq!(estimate, 4.0, epsilon = 1e-15);
    }

    /// Rows r₂ = r₀ + t·(r₁ − r₀) (singular up to the rounding of their entries), with
    /// r₁ − r₀ small (1e-8) in the second column: partial pivoting takes that genuine small
    /// pivot, divides the rounding of the elimination by it, and leaves a last pivot far
    /// above the singular threshold. The condition estimate refuses J. Without the dependence
    /// (t moved off the line) J is accepted.
    #[test]
    fn a_dependence_hidden_behind_a_small_pivot_is_refused() {
        let (a, b, p, q, t) = (1.0 / 3.0, 0.7, 1e-8 * std::f64::consts::PI, 1.0, 0.37);
        let rows = |third: [f64; 3]| {
            let r = [[1.0, a, b], [1.0, a + p, b + q], third];
            let mut out = Vec::new();
            for (i, row) in r.iter().enumerate() {
                for (c, v) in row.iter().enumerate() {
                    out.push((i, c, *v));
                }
            }
            out
        };
        let before = CONDITION_REFUSALS.with(std::cell::Cell::get);
        let dependent = rows([1.0, a + t * p, b + t * q]);
        assert!(SquareLu::factorize(3, &dependent, 3, None).is_none());
        assert_eq!(CONDITION_REFUSALS.with(std::cell::Cell::get), before + 1);
        let independent = rows([1.0, a + t * p, b + 2.0 * t * q]);
        assert!(SquareLu::factorize(3, &independent, 3, None).is_some());
    }
}
