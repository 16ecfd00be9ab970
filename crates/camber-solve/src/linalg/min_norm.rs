//! The weighted minimum-norm step of an underdetermined linear system, with a cached
//! factorization.
//!
//! For J (m × n, full row rank m ≤ n), a positive diagonal weight W and a right-hand side g, the
//! step of least weighted norm ‖Δz‖²_W = Σ w_k Δz_k² that solves J·Δz = −g is
//!
//! Δz = −W⁻¹·Jᵀ·(J·W⁻¹·Jᵀ)⁻¹·g
//!
//! (the Lagrange condition W·Δz = Jᵀ·λ plus the constraint). M = J·W⁻¹·Jᵀ is symmetric positive
//! definite exactly when J has full row rank; it is factorized once by Cholesky, M = L·Lᵀ, and
//! every right-hand side then costs two triangular solves and one product with Jᵀ. No inverse is
//! ever formed. Small systems use nalgebra's dense Cholesky; large ones faer's sparse Cholesky
//! (with a fill-reducing ordering) of the sparse M.

use nalgebra::{Cholesky, DMatrix, DVector, Dyn};

use crate::linalg::normal::{NormalCache, NormalFactor};
use crate::linalg::sparse::SparseMatrix;
use crate::model::errors::check_len;
use crate::model::errors::{Error, Result};

/// A factorization of J·W⁻¹·Jᵀ, reusable for any number of right-hand sides (dragging: J and W
/// stay, g changes with every mouse event).
///
/// ```
/// use camber_solve::{MinNormFactorization, SparseMatrix};
/// // One equation x + y = g-correction: the step splits evenly.
/// let j = SparseMatrix::try_from_triplets(1, 2, &[(0, 0, 1.0), (0, 1, 1.0)])?;
/// let mut f = MinNormFactorization::try_dense(&j, &[1.0, 1.0])?;
/// let mut dz = [0.0; 2];
/// f.solve(&[-2.0], &mut dz)?; // residual −2: x + y must grow by 2
/// assert!((dz[0] - 1.0).abs() < 1e-15 && (dz[1] - 1.0).abs() < 1e-15);
/// # Ok::<(), camber_solve::Error>(())
/// ```
#[derive(Debug)]
pub struct MinNormFactorization {
    inv_w: Vec<f64>,
    backend: Backend,
    /// Scratch for refinement: the residual J·Δz + g (m) and a correction (n).
    residual: Vec<f64>,
    correction: Vec<f64>,
    /// Scratch of [`MinNormFactorization::project`]: J·W⁻¹·v (m).
    rhs: Vec<f64>,
}

#[derive(Debug)]
enum Backend {
    Dense {
        j: DMatrix<f64>,
        chol: Cholesky<f64, Dyn>,
        y: DVector<f64>,
    },
    Sparse {
        j: SparseMatrix,
        llt: NormalFactor,
        y: Vec<f64>,
    },
}

/// # Construction
impl MinNormFactorization {
    /// Factorizes densely (nalgebra Cholesky of the m × m matrix J·W⁻¹·Jᵀ).
    ///
    /// # Errors
    /// [`Error::Dimension`] / [`Error::NonPositiveWeight`] for bad weights,
    /// [`Error::RankDeficient`] when J·W⁻¹·Jᵀ is not positive definite.
    pub fn try_dense(j: &SparseMatrix, weights: &[f64]) -> Result<Self> {
        let inv_w = inverse_weights(j, weights)?;
        let jd = j.to_dense();
        // J·W⁻¹·Jᵀ by its lower triangle and symmetry: at these sizes a plain loop beats the
        // general matrix product (which also needed a scaled copy of J).
        let rows = jd.nrows();
        let mut m = DMatrix::<f64>::zeros(rows, rows);
        for a in 0..rows {
            for b in 0..=a {
                let mut sum = 0.0;
                for (k, w) in inv_w.iter().enumerate() {
                    sum += jd[(a, k)] * w * jd[(b, k)];
                }
                m[(a, b)] = sum;
                m[(b, a)] = sum;
            }
        }
        let chol = Cholesky::new(m).ok_or(Error::RankDeficient { rows: j.nrows() })?;
        Ok(Self::assemble(
            inv_w,
            Backend::Dense {
                j: jd,
                chol,
                y: DVector::zeros(j.nrows()),
            },
        ))
    }

    /// Factorizes sparsely (faer sparse Cholesky of J·W⁻¹·Jᵀ, formed sparse).
    ///
    /// # Errors
    /// As [`MinNormFactorization::try_dense`].
    pub fn try_sparse(j: &SparseMatrix, weights: &[f64]) -> Result<Self> {
        Self::try_sparse_cached(j, weights, &mut NormalCache::new())
    }

    /// [`MinNormFactorization::try_sparse`] reusing the pattern work of `cache` when J has the
    /// sparsity pattern of the cache's last factorization (Newton iterations, drag updates).
    ///
    /// # Errors
    /// As [`MinNormFactorization::try_dense`].
    pub fn try_sparse_cached(
        j: &SparseMatrix,
        weights: &[f64],
        cache: &mut NormalCache,
    ) -> Result<Self> {
        let inv_w = inverse_weights(j, weights)?;
        let llt = cache.factorize(j, &inv_w)?;
        Ok(Self::assemble(
            inv_w,
            Backend::Sparse {
                j: j.clone(),
                llt,
                y: vec![0.0; j.nrows()],
            },
        ))
    }

    fn assemble(inv_w: Vec<f64>, backend: Backend) -> Self {
        let rows = match &backend {
            Backend::Dense { j, .. } => j.nrows(),
            Backend::Sparse { j, .. } => j.nrows(),
        };
        let correction = vec![0.0; inv_w.len()];
        Self {
            inv_w,
            backend,
            residual: vec![0.0; rows],
            correction,
            rhs: vec![0.0; rows],
        }
    }

    /// Dense when J has at most `dense_max_unknowns` columns, sparse otherwise.
    ///
    /// # Errors
    /// As [`MinNormFactorization::try_dense`].
    pub fn try_auto(j: &SparseMatrix, weights: &[f64], dense_max_unknowns: usize) -> Result<Self> {
        Self::try_auto_cached(j, weights, dense_max_unknowns, &mut NormalCache::new())
    }

    /// [`MinNormFactorization::try_auto`] with the sparse path reusing `cache`.
    ///
    /// # Errors
    /// As [`MinNormFactorization::try_dense`].
    pub fn try_auto_cached(
        j: &SparseMatrix,
        weights: &[f64],
        dense_max_unknowns: usize,
        cache: &mut NormalCache,
    ) -> Result<Self> {
        if j.ncols() <= dense_max_unknowns {
            Self::try_dense(j, weights)
        } else {
            Self::try_sparse_cached(j, weights, cache)
        }
    }
}

impl MinNormFactorization {
    /// Rows m of J.
    pub fn rows(&self) -> usize {
        match &self.backend {
            Backend::Dense { j, .. } => j.nrows(),
            Backend::Sparse { j, .. } => j.nrows(),
        }
    }

    /// Columns n of J (reduced unknowns).
    pub fn cols(&self) -> usize {
        self.inv_w.len()
    }

    /// Whether the sparse backend is in use.
    pub fn is_sparse(&self) -> bool {
        matches!(self.backend, Backend::Sparse { .. })
    }

    /// Δz = −W⁻¹·Jᵀ·(J·W⁻¹·Jᵀ)⁻¹·g, the least-weighted-norm step with J·Δz = −g. The dense
    /// backend does not allocate.
    ///
    /// # Errors
    /// [`Error::Dimension`] when `g` or `dz` has the wrong length.
    pub fn solve(&mut self, g: &[f64], dz: &mut [f64]) -> Result<()> {
        check_len("right-hand side", self.rows(), g.len())?;
        check_len("step", self.cols(), dz.len())?;
        match &mut self.backend {
            Backend::Dense { j, chol, y } => {
                y.as_mut_slice().copy_from_slice(g);
                chol.solve_mut(y);
                for (k, (dzk, col)) in dz.iter_mut().zip(j.column_iter()).enumerate() {
                    *dzk = -self.inv_w[k] * col.dot(y);
                }
            }
            Backend::Sparse { j, llt, y } => {
                y.copy_from_slice(g);
                llt.solve_in_place(y);
                dz.fill(0.0);
                for (i, yi) in y.iter().enumerate() {
                    let (cols, vals) = j.row(i);
                    for (c, v) in cols.iter().zip(vals) {
                        dz[*c] -= v * yi;
                    }
                }
                for (dzk, d) in dz.iter_mut().zip(&self.inv_w) {
                    *dzk *= d;
                }
            }
        }
        Ok(())
    }
}

impl MinNormFactorization {
    /// The W-orthogonal projection of v onto the null space of J, in the metric of W⁻¹:
    ///
    /// P·v = W⁻¹·(v − Jᵀ·y),  y = (J·W⁻¹·Jᵀ)⁻¹·J·W⁻¹·v,
    ///
    /// so that J·P·v = 0 and y is the least-squares multiplier of v (the λ minimising
    /// ‖v − Jᵀλ‖ in the W⁻¹ norm). This is the preconditioner of the projected conjugate
    /// gradients of the second-order Newton step; with v = W·d it returns the part of d that
    /// keeps J·d unchanged. Writes P·v into `out` and y into `multipliers`.
    ///
    /// ```
    /// use camber_solve::{MinNormFactorization, SparseMatrix};
    /// // J = [1 1]: the null space is spanned by (1, −1).
    /// let j = SparseMatrix::try_from_triplets(1, 2, &[(0, 0, 1.0), (0, 1, 1.0)])?;
    /// let mut f = MinNormFactorization::try_dense(&j, &[1.0, 1.0])?;
    /// let (mut pv, mut y) = ([0.0; 2], [0.0; 1]);
    /// f.project(&[3.0, 1.0], &mut pv, &mut y)?;
    /// assert!((pv[0] - 1.0).abs() < 1e-15 && (pv[1] + 1.0).abs() < 1e-15);
    /// assert!((y[0] - 2.0).abs() < 1e-15);
    /// # Ok::<(), camber_solve::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::Dimension`] for wrong lengths.
    pub fn project(&mut self, v: &[f64], out: &mut [f64], multipliers: &mut [f64]) -> Result<()> {
        check_len("projected vector", self.cols(), v.len())?;
        check_len("projection", self.cols(), out.len())?;
        check_len("multipliers", self.rows(), multipliers.len())?;
        for (o, (vk, d)) in out.iter_mut().zip(v.iter().zip(&self.inv_w)) {
            *o = vk * d;
        }
        let mut rhs = std::mem::take(&mut self.rhs);
        self.apply_j(out, &mut rhs);
        let outcome = self.solve(&rhs, out);
        self.rhs = rhs;
        outcome?;
        for (o, (vk, d)) in out.iter_mut().zip(v.iter().zip(&self.inv_w)) {
            *o += vk * d;
        }
        match &self.backend {
            Backend::Dense { y, .. } => multipliers.copy_from_slice(y.as_slice()),
            Backend::Sparse { y, .. } => multipliers.copy_from_slice(y),
        }
        Ok(())
    }

    /// [`MinNormFactorization::solve`] followed by up to `steps` rounds of iterative refinement:
    /// r = J·Δz + g is what the step misses (rounding amplified by the condition of
    /// J·W⁻¹·Jᵀ), and Δz += step(r) removes most of it. Corrections lie in the range of W⁻¹·Jᵀ,
    /// so the result stays the minimum-norm step. Stops early once max |r| ≤ `tolerance`, or
    /// once every rᵢ is within the rounding of the products that form it (another round would
    /// only correct rounding noise: a well-conditioned system needs no round at all).
    /// Allocation-free on the dense backend.
    ///
    /// # Errors
    /// As [`MinNormFactorization::solve`].
    pub fn solve_refined(
        &mut self,
        g: &[f64],
        dz: &mut [f64],
        steps: usize,
        tolerance: f64,
    ) -> Result<()> {
        self.solve(g, dz)?;
        let mut residual = std::mem::take(&mut self.residual);
        let mut correction = std::mem::take(&mut self.correction);
        let mut outcome = Ok(());
        for _ in 0..steps {
            let (worst, at_rounding) = self.miss(dz, g, &mut residual);
            if worst <= tolerance || at_rounding {
                break;
            }
            outcome = self.solve(&residual, &mut correction);
            if outcome.is_err() {
                break;
            }
            for (d, c) in dz.iter_mut().zip(&correction) {
                *d += c;
            }
        }
        self.residual = residual;
        self.correction = correction;
        outcome
    }

    /// r = J·v + g into `out` (lengths already checked by the caller), with max |rᵢ| and
    /// whether every rᵢ lies within the rounding of the sum that forms it,
    /// |rᵢ| ≤ 4ε·(Σⱼ |Jᵢⱼ·vⱼ| + |gᵢ|): then r is indistinguishable from zero and a correction
    /// would only solve for rounding noise.
    fn miss(&self, v: &[f64], g: &[f64], out: &mut [f64]) -> (f64, bool) {
        /// (gᵢ + Σ terms, |gᵢ| + Σ |terms|).
        fn sum_and_size(gi: f64, terms: impl Iterator<Item = f64>) -> (f64, f64) {
            terms.fold((gi, gi.abs()), |(s, a), t| (s + t, a + t.abs()))
        }
        let mut worst = 0.0_f64;
        let mut at_rounding = true;
        for (i, (o, gi)) in out.iter_mut().zip(g).enumerate() {
            let (sum, size) = match &self.backend {
                Backend::Dense { j, .. } => {
                    sum_and_size(*gi, j.row(i).iter().zip(v).map(|(a, b)| a * b))
                }
                Backend::Sparse { j, .. } => {
                    let (cols, vals) = j.row(i);
                    sum_and_size(*gi, cols.iter().zip(vals).map(|(c, a)| a * v[*c]))
                }
            };
            *o = sum;
            worst = worst.max(sum.abs());
            // NaN fails the test and is left to the solve that follows.
            at_rounding &= sum.abs() <= 4.0 * f64::EPSILON * size;
        }
        (worst, at_rounding)
    }

    /// out = J·v (lengths already checked by the caller).
    fn apply_j(&self, v: &[f64], out: &mut [f64]) {
        match &self.backend {
            Backend::Dense { j, .. } => {
                for (i, o) in out.iter_mut().enumerate() {
                    *o = j.row(i).iter().zip(v).map(|(a, b)| a * b).sum();
                }
            }
            Backend::Sparse { j, .. } => {
                for (i, o) in out.iter_mut().enumerate() {
                    let (cols, vals) = j.row(i);
                    *o = cols.iter().zip(vals).map(|(c, a)| a * v[*c]).sum();
                }
            }
        }
    }
}

/// Rows up to which [`solve_small_refined`] works on the stack.
pub(crate) const SMALL_ROWS: usize = 8;

/// [`MinNormFactorization::solve_refined`] for a J of at most [`SMALL_ROWS`] rows, without
/// building a factorization: J·W⁻¹·Jᵀ is formed from J's sparse rows and factorized by
/// Cholesky on the stack, and the step and its refinements (same stopping rule) are written
/// into `dz` directly. Nothing is allocated: for the many small components of a sketch the
/// allocations of the general path cost more than the arithmetic.
///
/// # Errors
/// [`Error::Dimension`] for wrong lengths or more than [`SMALL_ROWS`] rows;
/// [`Error::NonPositiveWeight`]; [`Error::RankDeficient`] when J·W⁻¹·Jᵀ is not positive
/// definite.
pub(crate) fn solve_small_refined(
    j: &SparseMatrix,
    weights: &[f64],
    g: &[f64],
    dz: &mut [f64],
    steps: usize,
    tolerance: f64,
) -> Result<()> {
    let m = j.nrows();
    check_len("weights", j.ncols(), weights.len())?;
    check_len("right-hand side", m, g.len())?;
    check_len("step", j.ncols(), dz.len())?;
    if m > SMALL_ROWS {
        return Err(Error::Dimension {
            what: "rows of a small minimum-norm system",
            expected: SMALL_ROWS,
            found: m,
        });
    }
    if let Some((index, w)) = weights
        .iter()
        .enumerate()
        .find(|(_, w)| !(w.is_finite() && **w > 0.0))
    {
        return Err(Error::NonPositiveWeight { index, value: *w });
    }
    // L (lower triangle) of J·W⁻¹·Jᵀ = L·Lᵀ.
    let mut l = [[0.0_f64; SMALL_ROWS]; SMALL_ROWS];
    for (a, l_a) in l.iter_mut().enumerate().take(m) {
        let (ca, va) = j.row(a);
        for (b, l_ab) in l_a.iter_mut().enumerate().take(a + 1) {
            let (cb, vb) = j.row(b);
            // The two rows' common columns (both sorted).
            let (mut x, mut y, mut sum) = (0, 0, 0.0);
            while x < ca.len() && y < cb.len() {
                match ca[x].cmp(&cb[y]) {
                    std::cmp::Ordering::Less => x += 1,
                    std::cmp::Ordering::Greater => y += 1,
                    std::cmp::Ordering::Equal => {
                        sum += va[x] * (1.0 / weights[ca[x]]) * vb[y];
                        x += 1;
                        y += 1;
                    }
                }
            }
            *l_ab = sum;
        }
    }
    for c in 0..m {
        let (done, below) = l.split_at_mut(c + 1);
        let l_c = &mut done[c];
        let d = l_c[c] - l_c[..c].iter().map(|v| v * v).sum::<f64>();
        if d.is_nan() || d <= 0.0 {
            return Err(Error::RankDeficient { rows: m });
        }
        let d = d.sqrt();
        l_c[c] = d;
        for l_r in below.iter_mut().take(m - c - 1) {
            let v = l_r[c]
                - l_r[..c]
                    .iter()
                    .zip(&l_c[..c])
                    .map(|(a, b)| a * b)
                    .sum::<f64>();
            l_r[c] = v / d;
        }
    }
    // Adds −W⁻¹·Jᵀ·(L·Lᵀ)⁻¹·rhs to dz.
    let step = |rhs: &[f64], dz: &mut [f64]| {
        let mut y = [0.0_f64; SMALL_ROWS];
        for r in 0..m {
            let mut v = rhs[r];
            for k in 0..r {
                v -= l[r][k] * y[k];
            }
            y[r] = v / l[r][r];
        }
        for r in (0..m).rev() {
            let mut v = y[r];
            for k in r + 1..m {
                v -= l[k][r] * y[k];
            }
            y[r] = v / l[r][r];
        }
        for (i, yi) in y.iter().enumerate().take(m) {
            let (cols, vals) = j.row(i);
            for (c, v) in cols.iter().zip(vals) {
                dz[*c] -= v * yi / weights[*c];
            }
        }
    };
    dz.fill(0.0);
    step(g, dz);
    let mut residual = [0.0_f64; SMALL_ROWS];
    for _ in 0..steps {
        // r = J·Δz + g, and whether every rᵢ is within the rounding of its sum (as
        // `MinNormFactorization::miss`).
        let mut worst = 0.0_f64;
        let mut at_rounding = true;
        for (i, (r, gi)) in residual.iter_mut().zip(g).enumerate() {
            let (cols, vals) = j.row(i);
            let (sum, size) = cols
                .iter()
                .zip(vals)
                .map(|(c, a)| a * dz[*c])
                .fold((*gi, gi.abs()), |(s, z), t| (s + t, z + t.abs()));
            *r = sum;
            worst = worst.max(sum.abs());
            at_rounding &= sum.abs() <= 4.0 * f64::EPSILON * size;
        }
        if worst <= tolerance || at_rounding {
            break;
        }
        step(&residual[..m], dz);
    }
    Ok(())
}

/// 1/w for every column, after checking the weights.
fn inverse_weights(j: &SparseMatrix, weights: &[f64]) -> Result<Vec<f64>> {
    check_len("weights", j.ncols(), weights.len())?;
    weights
        .iter()
        .enumerate()
        .map(|(index, w)| {
            if w.is_finite() && *w > 0.0 {
                Ok(1.0 / w)
            } else {
                Err(Error::NonPositiveWeight { index, value: *w })
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn one_equation_by_hand() {
        // a·x = b from x0: Δx = a(b − a·x0)/|a|², here residual g = a·x0 − b.
        let a = [3.0, -4.0, 12.0];
        let (x0, b) = ([1.0, 2.0, 0.5], 7.0);
        let g = a.iter().zip(&x0).map(|(p, q)| p * q).sum::<f64>() - b;
        let j = SparseMatrix::try_from_triplets(1, 3, &[(0, 0, a[0]), (0, 1, a[1]), (0, 2, a[2])])
            .unwrap();
        for mut f in [
            MinNormFactorization::try_dense(&j, &[1.0; 3]).unwrap(),
            MinNormFactorization::try_sparse(&j, &[1.0; 3]).unwrap(),
        ] {
            let mut dx = [0.0; 3];
            f.solve(&[g], &mut dx).unwrap();
            for k in 0..3 {
                assert_relative_eq!(dx[k], a[k] * (-g) / 169.0, epsilon = 1e-15);
            }
        }
    }

    #[test]
    fn weights_shift_the_move_to_cheap_unknowns() {
        // x + y = 1 from 0 with w = (1, 4): Δ = W⁻¹aᵀ/(a W⁻¹ aᵀ) = (1, 1/4)/(5/4) = (0.8, 0.2).
        let j = SparseMatrix::try_from_triplets(1, 2, &[(0, 0, 1.0), (0, 1, 1.0)]).unwrap();
        let mut f = MinNormFactorization::try_sparse(&j, &[1.0, 4.0]).unwrap();
        let mut dz = [0.0; 2];
        f.solve(&[-1.0], &mut dz).unwrap();
        assert_relative_eq!(dz[0], 0.8, epsilon = 1e-15);
        assert_relative_eq!(dz[1], 0.2, epsilon = 1e-15);
        assert!(f.is_sparse());
        assert_eq!((f.rows(), f.cols()), (1, 2));
    }

    /// Refinement still runs where the normal equations lose digits (two nearly parallel
    /// rows: cond(J) ≈ 4·10⁵, cond(J·Jᵀ) ≈ 10¹¹), and a system the first solve meets up to
    /// rounding gets no correction at all.
    #[test]
    fn refinement_runs_only_while_the_miss_is_above_rounding() {
        let j = SparseMatrix::try_from_triplets(
            2,
            3,
            &[
                (0, 0, 1.0),
                (0, 1, 1.0),
                (1, 0, 1.0),
                (1, 1, 1.0 + 1e-5),
                (1, 2, 1e-6),
            ],
        )
        .unwrap();
        let g = [-1.0, 2.0];
        let miss = |dz: &[f64]| {
            (0..2)
                .map(|i| {
                    let (cols, vals) = j.row(i);
                    let r: f64 = cols.iter().zip(vals).map(|(c, a)| a * dz[*c]).sum();
                    (r + g[i]).abs()
                })
                .fold(0.0, f64::max)
        };
        for mut f in [
            MinNormFactorization::try_dense(&j, &[1.0; 3]).unwrap(),
            MinNormFactorization::try_sparse(&j, &[1.0; 3]).unwrap(),
        ] {
            let (mut plain, mut refined) = ([0.0; 3], [0.0; 3]);
            f.solve(&g, &mut plain).unwrap();
            f.solve_refined(&g, &mut refined, 2, 0.0).unwrap();
            // ‖Δz‖ is about 3·10⁵, so rounding in J·Δz alone is about 10⁻¹⁰.
            assert!(miss(&refined) <= 1e-9, "refined miss {}", miss(&refined));
            assert!(
                miss(&refined) <= miss(&plain),
                "{} > {}",
                miss(&refined),
                miss(&plain)
            );
        }
        // Exact in floating point: J = diag(1, 2) padded, g = (−1, −4), Δz = (1, 2, 0).
        let easy = SparseMatrix::try_from_triplets(2, 3, &[(0, 0, 1.0), (1, 1, 2.0)]).unwrap();
        let mut f = MinNormFactorization::try_dense(&easy, &[1.0; 3]).unwrap();
        let (mut plain, mut refined) = ([0.0; 3], [0.0; 3]);
        f.solve(&[-1.0, -4.0], &mut plain).unwrap();
        f.solve_refined(&[-1.0, -4.0], &mut refined, 2, 0.0)
            .unwrap();
        assert_eq!(plain.map(f64::to_bits), refined.map(f64::to_bits));
        assert_relative_eq!(refined[1], 2.0, epsilon = 1e-15);
    }

    /// The stack path gives the dense factorization's refined step on random small systems
    /// (1–8 rows, sparse rows, uneven weights), and the same errors.
    #[test]
    fn the_small_path_agrees_with_the_factorization() {
        let mut seed = 7_u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 33) as f64) / f64::from(1_u32 << 31) - 0.5
        };
        for m in 1..=SMALL_ROWS {
            for _ in 0..20 {
                let n = m + 3;
                let mut triplets = Vec::new();
                for i in 0..m {
                    // Row i reads columns i … i + 3 (some entries left out): full row rank.
                    for c in i..i + 4 {
                        if c == i || next() > -0.2 {
                            triplets.push((i, c, next() + if c == i { 2.0 } else { 0.0 }));
                        }
                    }
                }
                let j = SparseMatrix::try_from_triplets(m, n, &triplets).unwrap();
                let w: Vec<f64> = (0..n).map(|_| 1.5 + next()).collect();
                let g: Vec<f64> = (0..m).map(|_| 3.0 * next()).collect();
                let (mut want, mut got) = (vec![0.0; n], vec![0.0; n]);
                MinNormFactorization::try_dense(&j, &w)
                    .unwrap()
                    .solve_refined(&g, &mut want, 3, 0.0)
                    .unwrap();
                solve_small_refined(&j, &w, &g, &mut got, 3, 0.0).unwrap();
                for k in 0..n {
                    assert_relative_eq!(got[k], want[k], epsilon = 1e-13, max_relative = 1e-12);
                }
                // J·Δz = −g.
                let mut jz = vec![0.0; m];
                j.mul_vec(&got, &mut jz).unwrap();
                for i in 0..m {
                    assert_relative_eq!(jz[i], -g[i], epsilon = 1e-13);
                }
            }
        }
        let dependent = SparseMatrix::try_from_triplets(2, 2, &[(0, 0, 1.0), (1, 0, 2.0)]).unwrap();
        let mut dz = [0.0; 2];
        assert_eq!(
            solve_small_refined(&dependent, &[1.0, 1.0], &[1.0, 2.0], &mut dz, 3, 0.0),
            Err(Error::RankDeficient { rows: 2 })
        );
        assert_eq!(
            solve_small_refined(&dependent, &[1.0, 0.0], &[1.0, 2.0], &mut dz, 3, 0.0),
            Err(Error::NonPositiveWeight {
                index: 1,
                value: 0.0
            })
        );
        let tall = SparseMatrix::try_from_triplets(SMALL_ROWS + 1, 1, &[]).unwrap();
        let mut one = [0.0];
        assert!(
            solve_small_refined(&tall, &[1.0], &[0.0; SMALL_ROWS + 1], &mut one, 3, 0.0).is_err()
        );
    }

    #[test]
    fn dependent_rows_fail_to_factorize() {
        let j = SparseMatrix::try_from_triplets(2, 2, &[(0, 0, 1.0), (1, 0, 2.0)]).unwrap();
        assert_eq!(
            MinNormFactorization::try_dense(&j, &[1.0, 1.0]).unwrap_err(),
            Error::RankDeficient { rows: 2 }
        );
        assert_eq!(
            MinNormFactorization::try_sparse(&j, &[1.0, 1.0]).unwrap_err(),
            Error::RankDeficient { rows: 2 }
        );
        let empty_row = SparseMatrix::try_from_triplets(2, 2, &[(0, 0, 1.0)]).unwrap();
        assert!(MinNormFactorization::try_sparse(&empty_row, &[1.0, 1.0]).is_err());
        assert_eq!(
            MinNormFactorization::try_dense(&j, &[1.0, -1.0]).unwrap_err(),
            Error::NonPositiveWeight {
                index: 1,
                value: -1.0
            }
        );
    }
}
