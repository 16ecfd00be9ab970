//! The Newton step of a square system: as many rows as free unknowns.
//!
//! When J is n × n and nonsingular, J·Δ = −g has exactly one solution, so the weighted
//! minimum-norm step −W⁻¹·Jᵀ·(J·W⁻¹·Jᵀ)⁻¹·g of [`crate::min_norm`] is simply −J⁻¹·g and the
//! null space that the pull-back moves in is empty. One LU factorization of J with partial
//! pivoting (n³/3 flops) then replaces the product J·W⁻¹·Jᵀ, its Cholesky factorization, the
//! refined solve and the projection of the projected conjugate gradients, and it works on J's
//! own condition number instead of its square. The multipliers of the step (K·Δ + c + Jᵀ·λ = 0
//! with K = W) are λ = −J⁻ᵀ·(W·Δ + c): one more solve with the same factors.
//!
//! A J whose pivots fall below [`SINGULAR_PIVOT`] relative to its largest entry is refused
//! ([`SquareLu::factorize`] returns `None`) and the caller keeps the minimum-norm path, which
//! decides about rank deficiency as it always did.

/// A pivot at most this fraction of max |Jᵢⱼ| counts as singular (the LU is refused).
pub(crate) const SINGULAR_PIVOT: f64 = 1e-12;

/// Rounds of iterative refinement after the first solve (stopped early once the miss is
/// rounding).
const REFINEMENT: usize = 2;

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
        let mut reference = crate::MinNormFactorization::try_dense(&j, &w).unwrap();
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
}
