//! The exact Gauss–Newton step of one priority tier within the rows held by the tiers before
//! it, for components small enough to work on densely.
//!
//! With J_H and h = g_H − τ_H the held rows, J_t and g_t the tier's, and W the unknowns'
//! weights, the step Δ solves
//!
//! min ‖J_t·Δ + g_t‖  over  {Δ : J_H·Δ = −h in the least-squares sense},
//!
//! and among the minimisers has the least ‖Δ‖_W. In the scaled unknowns u = W^½·Δ (A = J·W^−½)
//! the full SVD of A_H = U·Σ·Vᵀ gives both parts: the particular step u₀ = −A_H⁺·h (the
//! minimum-norm correction of the held rows, zero when they hold) and an orthonormal basis N
//! of the held null space, the columns of V past the numerical rank. The tier then takes
//! u = u₀ + N·y with y = −(A_t·N)⁺·(g_t + A_t·u₀), again by SVD. The two parts are orthogonal,
//! so u is the least-norm step of the lexicographic problem.
//!
//! Both rank decisions are absolute: a singular value counts as zero when it is at most
//! `rank_tolerance` times the *component's* scale s, the largest row norm of J·W^−½ over every
//! row of every tier (or the matrix's own σ_max, if larger). A tier whose rows the held rows
//! determine already has A_t·N made of rounding (singular values about 1e-17·s); measured
//! against its own σ_max that rounding would count as rank, y would be rounding⁻¹·rhs, and N·y
//! would throw the unknowns no row reads (most of N) to 1e16 and beyond while every residual
//! stayed right. Against s it is zero, and y = 0.
//!
//! The SVDs are faer's (one-sided Jacobi-quality accuracy, singular values sorted). nalgebra
//! 0.35's SVD was used first and returned, for a 2 × 4 matrix of rank 1 with a zero column,
//! singular vectors whose recomposition missed the matrix by 0.18 (its convergence test with
//! ε as the threshold, nalgebra issues 1072 and 1172): the held step then moved unknowns no
//! row reads by a third of its length.
//!
//! For affine rows this lands on the lexicographic least-squares point in one step, to the
//! rounding of the factorizations: no damping, no acceptance test on a cost that has stopped
//! changing in its leading digits. That is what the iterative search of [`crate::priority`]
//! cannot promise for a tier whose residual stays large, so the search finishes each tier
//! with these steps when the component is dense-sized.

use nalgebra::{DMatrix, DVector};

/// A full SVD A = U·diag(σ)·Vᵀ: U m × m, V n × n, σ of length min(m, n), nonincreasing.
struct FullSvd {
    u: DMatrix<f64>,
    sigma: Vec<f64>,
    v: DMatrix<f64>,
}

impl FullSvd {
    /// The SVD of `a` by faer; `None` when it does not converge.
    fn new(a: &DMatrix<f64>) -> Option<Self> {
        let (m, n) = a.shape();
        let mat = faer::Mat::<f64>::from_fn(m, n, |i, j| a[(i, j)]);
        let svd = mat.svd().ok()?;
        let (u, v) = (svd.U(), svd.V());
        let s = svd.S().column_vector();
        Some(Self {
            u: DMatrix::from_fn(m, m, |i, j| u[(i, j)]),
            sigma: (0..m.min(n)).map(|i| s[i]).collect(),
            v: DMatrix::from_fn(n, n, |i, j| v[(i, j)]),
        })
    }

    /// σ_max (0 for an empty matrix).
    fn top(&self) -> f64 {
        self.sigma.first().copied().unwrap_or(0.0)
    }

    /// How many singular values exceed `floor`.
    fn rank(&self, floor: f64) -> usize {
        self.sigma.iter().take_while(|s| **s > floor).count()
    }
}

/// The held rows of one linearization, factorized: the projector of a correction onto the
/// held rows and the basis of their null space, in scaled unknowns.
pub(crate) struct HeldRows {
    /// W^−½ per unknown.
    scale: Vec<f64>,
    /// The right singular vectors of A_H with nonzero singular value (rank × n), each scaled
    /// by 1/σ, and the matching left singular vectors (k × rank).
    v_over_sigma: DMatrix<f64>,
    u: DMatrix<f64>,
    /// The null-space basis N of A_H (n × (n − rank)).
    null: DMatrix<f64>,
}

impl HeldRows {
    /// Factorizes the held rows `j_held` (k × n, k may be 0 or exceed n) under the weights
    /// `weights` (positive, one per unknown). Singular values at most `rank_tolerance` times
    /// `component_scale` (see [`row_scale`]) or times the largest, whichever is larger (and at
    /// least n·ε times the largest), count as zero. `None` when the SVD does not converge.
    pub(crate) fn new(
        j_held: &DMatrix<f64>,
        weights: &[f64],
        rank_tolerance: f64,
        component_scale: f64,
    ) -> Option<Self> {
        let n = j_held.ncols();
        let k = j_held.nrows();
        let scale: Vec<f64> = weights.iter().map(|w| 1.0 / w.sqrt()).collect();
        if k == 0 {
            return Some(Self {
                scale,
                v_over_sigma: DMatrix::zeros(0, n),
                u: DMatrix::zeros(0, 0),
                null: DMatrix::identity(n, n),
            });
        }
        let a = DMatrix::from_fn(k, n, |r, c| j_held[(r, c)] * scale[c]);
        let svd = FullSvd::new(&a)?;
        let rank = svd.rank(zero_below(svd.top(), component_scale, rank_tolerance, n));
        let v_over_sigma = DMatrix::from_fn(rank, n, |i, c| svd.v[(c, i)] / svd.sigma[i]);
        let u = svd.u.columns(0, rank).into_owned();
        let null = svd.v.columns(rank, n - rank).into_owned();
        Some(Self {
            scale,
            v_over_sigma,
            u,
            null,
        })
    }

    /// u₀ = −A_H⁺·h in scaled unknowns (zeros without held rows).
    fn particular(&self, h: &DVector<f64>) -> DVector<f64> {
        if self.u.nrows() == 0 {
            return DVector::zeros(self.scale.len());
        }
        -(self.v_over_sigma.transpose() * (self.u.transpose() * h))
    }

    /// The minimum-W-norm correction Δ with J_H·Δ = −h in the least-squares sense.
    pub(crate) fn correction(&self, h: &DVector<f64>) -> DVector<f64> {
        self.unscale(self.particular(h))
    }

    /// The tier's step Δ (see the module documentation) for the held misses `h`, the tier's
    /// rows `j_tier` (r × n) and residuals `g_tier`. Singular values of A_t·N at most
    /// `rank_tolerance` times `component_scale` or times the largest, whichever is larger, count
    /// as zero: a tier the held rows determine already does not move. `None` when the SVD does
    /// not converge.
    pub(crate) fn tier_step(
        &self,
        h: &DVector<f64>,
        j_tier: &DMatrix<f64>,
        g_tier: &DVector<f64>,
        rank_tolerance: f64,
        component_scale: f64,
    ) -> Option<DVector<f64>> {
        let n = self.scale.len();
        let u0 = self.particular(h);
        let mut a_t = j_tier.clone();
        for c in 0..n {
            a_t.column_mut(c).scale_mut(self.scale[c]);
        }
        let mut u = u0.clone();
        if self.null.ncols() > 0 && j_tier.nrows() > 0 {
            let b = &a_t * &self.null;
            let rhs = -(g_tier + &a_t * &u0);
            let svd = FullSvd::new(&b)?;
            let rank = svd.rank(zero_below(svd.top(), component_scale, rank_tolerance, n));
            // y = Σ over the kept singular triples of v_i·(u_iᵀ·rhs)/σ_i.
            let mut y = DVector::zeros(self.null.ncols());
            for i in 0..rank {
                let weight = svd.u.column(i).dot(&rhs) / svd.sigma[i];
                y.axpy(weight, &svd.v.column(i), 1.0);
            }
            u += &self.null * y;
        }
        Some(self.unscale(u))
    }

    /// Δ = W^−½·u.
    fn unscale(&self, mut u: DVector<f64>) -> DVector<f64> {
        for (v, s) in u.iter_mut().zip(&self.scale) {
            *v *= s;
        }
        u
    }
}

/// The scale s of the rank decisions: the largest row norm of J·W^−½ (`j` every row of the
/// component, `weights` one per column).
pub(crate) fn row_scale(j: &DMatrix<f64>, weights: &[f64]) -> f64 {
    j.row_iter()
        .map(|row| {
            row.iter()
                .zip(weights)
                .map(|(v, w)| v * v / w)
                .sum::<f64>()
                .sqrt()
        })
        .fold(0.0, f64::max)
}

/// The largest singular value that counts as zero in a matrix of n columns whose largest is
/// `top`, in a component of scale `scale`: `rank_tolerance`·max(top, scale), and at least
/// n·ε·top (rounding of the SVD itself).
fn zero_below(top: f64, scale: f64, rank_tolerance: f64, n: usize) -> f64 {
    (rank_tolerance * top.max(scale)).max(n as f64 * f64::EPSILON * top)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tier x + y = 2 held; the tier wants x = 3 and y = 0 (least squares within the line:
    /// x − y = 3, so (2.5, −0.5)).
    #[test]
    fn a_tier_on_a_held_line_reaches_its_least_squares_point() {
        let held = DMatrix::from_row_slice(1, 2, &[1.0, 1.0]);
        let rows = HeldRows::new(&held, &[1.0, 1.0], 1e-12, 1.0).unwrap();
        let z = [0.0, 0.0];
        let h = DVector::from_vec(vec![z[0] + z[1] - 2.0]);
        let tier = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 0.0, 1.0]);
        let g = DVector::from_vec(vec![z[0] - 3.0, z[1]]);
        let step = rows.tier_step(&h, &tier, &g, 1e-12, 1.0).unwrap();
        assert!((step[0] - 2.5).abs() < 1e-14 && (step[1] + 0.5).abs() < 1e-14);
    }

    /// Without a tier the step is the minimum-W-norm correction: for x + y = 1 from 0 with
    /// weights (1, 4), Δ ∝ W⁻¹·(1, 1) = (0.8, 0.2).
    #[test]
    fn the_correction_is_least_in_the_weighted_norm() {
        let held = DMatrix::from_row_slice(1, 2, &[1.0, 1.0]);
        let rows = HeldRows::new(&held, &[1.0, 4.0], 1e-12, 1.0).unwrap();
        let d = rows.correction(&DVector::from_vec(vec![-1.0]));
        assert!(
            (d[0] - 0.8).abs() < 1e-15 && (d[1] - 0.2).abs() < 1e-15,
            "{d}"
        );
    }

    /// Dependent held rows (the same row twice, more rows than unknowns) and a tier reading
    /// only x: y, which nothing reads after the held row, is set by the held row alone.
    #[test]
    fn dependent_held_rows_and_unread_unknowns() {
        let held = DMatrix::from_row_slice(3, 2, &[0.0, 1.0, 0.0, 1.0, 0.0, 2.0]);
        let rows = HeldRows::new(&held, &[1.0, 1.0], 1e-12, 1.0).unwrap();
        let h = DVector::from_vec(vec![-1.0, -1.0, -2.0]);
        let tier = DMatrix::from_row_slice(1, 2, &[1.0, 0.0]);
        let g = DVector::from_vec(vec![-4.0]);
        let step = rows.tier_step(&h, &tier, &g, 1e-12, 1.0).unwrap();
        assert!((step[0] - 4.0).abs() < 1e-14 && (step[1] - 1.0).abs() < 1e-14);
    }
}
