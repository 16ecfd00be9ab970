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
//! For affine rows this lands on the lexicographic least-squares point in one step, to the
//! rounding of the factorizations: no damping, no acceptance test on a cost that has stopped
//! changing in its leading digits. That is what the iterative search of the lexicographic solver
//! cannot promise for a tier whose residual stays large, so the search finishes each tier
//! with these steps when the component is dense-sized.

use nalgebra::{DMatrix, DVector};

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
    /// the largest (and at least n·ε times it) count as zero. `None` when the SVD does not
    /// converge.
    pub(crate) fn new(j_held: &DMatrix<f64>, weights: &[f64], rank_tolerance: f64) -> Option<Self> {
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
        // Padded with zero rows to at least n so that the SVD's Vᵀ is the full n × n basis.
        let mut a = DMatrix::zeros(k.max(n), n);
        for r in 0..k {
            for c in 0..n {
                a[(r, c)] = j_held[(r, c)] * scale[c];
            }
        }
        let svd = nalgebra::linalg::SVD::try_new(a, true, true, f64::EPSILON, 0)?;
        let (u, v_t) = (svd.u?, svd.v_t?);
        let sigma = &svd.singular_values;
        let top = sigma.max();
        let floor = top * rank_tolerance.max(n as f64 * f64::EPSILON);
        let kept: Vec<usize> = (0..sigma.len())
            .filter(|i| top > 0.0 && sigma[*i] > floor)
            .collect();
        let dropped: Vec<usize> = (0..n).filter(|i| !kept.contains(i)).collect();
        let mut v_over_sigma = DMatrix::zeros(kept.len(), n);
        let mut u_kept = DMatrix::zeros(k, kept.len());
        for (slot, i) in kept.iter().enumerate() {
            for c in 0..n {
                v_over_sigma[(slot, c)] = v_t[(*i, c)] / sigma[*i];
            }
            for r in 0..k {
                u_kept[(r, slot)] = u[(r, *i)];
            }
        }
        let null = DMatrix::from_fn(n, dropped.len(), |r, c| v_t[(dropped[c], r)]);
        Some(Self {
            scale,
            v_over_sigma,
            u: u_kept,
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
    /// `rank_tolerance` times the largest count as zero. `None` when the SVD does not converge.
    pub(crate) fn tier_step(
        &self,
        h: &DVector<f64>,
        j_tier: &DMatrix<f64>,
        g_tier: &DVector<f64>,
        rank_tolerance: f64,
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
            let svd = nalgebra::linalg::SVD::try_new(b, true, true, f64::EPSILON, 0)?;
            let top = svd.singular_values.max();
            let floor = top * rank_tolerance.max(n as f64 * f64::EPSILON);
            let y = if top > 0.0 {
                svd.solve(&rhs, floor).ok()?
            } else {
                DVector::zeros(self.null.ncols())
            };
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Tier x + y = 2 held; the tier wants x = 3 and y = 0 (least squares within the line:
    /// x − y = 3, so (2.5, −0.5)).
    #[test]
    fn a_tier_on_a_held_line_reaches_its_least_squares_point() {
        let held = DMatrix::from_row_slice(1, 2, &[1.0, 1.0]);
        let rows = HeldRows::new(&held, &[1.0, 1.0], 1e-12).unwrap();
        let z = [0.0, 0.0];
        let h = DVector::from_vec(vec![z[0] + z[1] - 2.0]);
        let tier = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 0.0, 1.0]);
        let g = DVector::from_vec(vec![z[0] - 3.0, z[1]]);
        let step = rows.tier_step(&h, &tier, &g, 1e-12).unwrap();
        assert!((step[0] - 2.5).abs() < 1e-14 && (step[1] + 0.5).abs() < 1e-14);
    }

    /// Without a tier the step is the minimum-W-norm correction: for x + y = 1 from 0 with
    /// weights (1, 4), Δ ∝ W⁻¹·(1, 1) = (0.8, 0.2).
    #[test]
    fn the_correction_is_least_in_the_weighted_norm() {
        let held = DMatrix::from_row_slice(1, 2, &[1.0, 1.0]);
        let rows = HeldRows::new(&held, &[1.0, 4.0], 1e-12).unwrap();
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
        let rows = HeldRows::new(&held, &[1.0, 1.0], 1e-12).unwrap();
        let h = DVector::from_vec(vec![-1.0, -1.0, -2.0]);
        let tier = DMatrix::from_row_slice(1, 2, &[1.0, 0.0]);
        let g = DVector::from_vec(vec![-4.0]);
        let step = rows.tier_step(&h, &tier, &g, 1e-12).unwrap();
        assert!((step[0] - 4.0).abs() < 1e-14 && (step[1] - 1.0).abs() < 1e-14);
    }
}
