//! The three terms of the deformation objective as camber-solve residual blocks.
//!
//! The unknowns are the control points P_k (one parameter block of 3 each) and, per continuity
//! sample s, the pair (λ_s, μ_s) (one block of 2). The weights are held fixed, so at a fixed
//! (u, v) the point S = Σ R_k P_k and the tangents S_u = Σ ∂_u R_k P_k, S_v = Σ ∂_v R_k P_k are
//! linear in the P_k: every residual below is affine and the least-squares solve is one exact
//! step of the normal equations.
//!
//! - curve error (term D): (S(P, w_s) − E_s) / L, E_s the initial boundary point, L the size;
//! - control-point error (term H): (P_k − P_k⁰) / L;
//! - quasi-G1 error (term G): (S_u(P, w_s) − λ_s a_s) / |a_s| and (S_v(P, w_s) − μ_s b_s) / |b_s|,
//!   a_s, b_s the initial tangents projected onto the neighbour's tangent plane.
//!
//! Dividing by L and by |a_s|, |b_s| makes every term dimensionless, so the weights α, β, γ do
//! not depend on the model's units.

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};

/// Term D at one sample: reads the acting control points' blocks (3 each), writes 3 rows.
#[derive(Debug, Clone)]
pub(crate) struct PointSample {
    /// R_k(w_s), one per block read.
    pub(crate) coeffs: Vec<f64>,
    /// E_s.
    pub(crate) target: [f64; 3],
    /// 1 / L.
    pub(crate) inv_scale: f64,
}

impl Residual for PointSample {
    fn name(&self) -> &str {
        "boundary sample"
    }
    fn dim(&self) -> usize {
        3
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        for (c, o) in out.iter_mut().enumerate().take(3) {
            let mut s = cst::<T>(-self.target[c]);
            for (r, p) in self.coeffs.iter().zip(x) {
                s += cst::<T>(*r) * p[c];
            }
            *o = s * cst::<T>(self.inv_scale);
        }
    }
    fn is_affine(&self) -> bool {
        true
    }
}

/// Term H for one control point: reads its block, writes 3 rows.
#[derive(Debug, Clone)]
pub(crate) struct Anchor {
    /// P_k⁰.
    pub(crate) start: [f64; 3],
    /// 1 / L.
    pub(crate) inv_scale: f64,
}

impl Residual for Anchor {
    fn name(&self) -> &str {
        "control point movement"
    }
    fn dim(&self) -> usize {
        3
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        for (c, o) in out.iter_mut().enumerate().take(3) {
            *o = (x[0][c] - cst::<T>(self.start[c])) * cst::<T>(self.inv_scale);
        }
    }
    fn is_affine(&self) -> bool {
        true
    }
}

/// Term G at one sample: reads the acting control points' blocks, then the (λ, μ) block last;
/// writes 6 rows (3 for S_u, 3 for S_v).
#[derive(Debug, Clone)]
pub(crate) struct TangentSample {
    /// ∂_u R_k(w_s).
    pub(crate) du: Vec<f64>,
    /// ∂_v R_k(w_s).
    pub(crate) dv: Vec<f64>,
    /// a_s.
    pub(crate) a: [f64; 3],
    /// b_s.
    pub(crate) b: [f64; 3],
    /// 1 / |a_s| and 1 / |b_s|.
    pub(crate) inv_norms: [f64; 2],
}

impl Residual for TangentSample {
    fn name(&self) -> &str {
        "quasi-G1 sample"
    }
    fn dim(&self) -> usize {
        6
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let n = self.du.len();
        let (points, scalars) = x.split_at(n);
        let Some(lm) = scalars.first() else { return };
        for c in 0..3 {
            let (mut su, mut sv) = (T::zero(), T::zero());
            for ((ru, rv), p) in self.du.iter().zip(&self.dv).zip(points) {
                su += cst::<T>(*ru) * p[c];
                sv += cst::<T>(*rv) * p[c];
            }
            out[c] = (su - lm[0] * cst::<T>(self.a[c])) * cst::<T>(self.inv_norms[0]);
            out[3 + c] = (sv - lm[1] * cst::<T>(self.b[c])) * cst::<T>(self.inv_norms[1]);
        }
    }
    fn is_affine(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use camber_solve::DynResidual;

    #[test]
    fn tangent_sample_values_and_jacobian() {
        let r = TangentSample {
            du: vec![-1.0, 1.0],
            dv: vec![0.5, 0.5],
            a: [1.0, 0.0, 0.0],
            b: [0.0, 2.0, 0.0],
            inv_norms: [1.0, 0.5],
        };
        let (p0, p1, lm) = ([0.0, 0.0, 0.0], [2.0, 0.0, 1.0], [1.5, 1.0]);
        let x = [&p0[..], &p1[..], &lm[..]];
        let mut g = [0.0; 6];
        let mut j = [0.0; 6 * 8];
        r.jacobian(&x, &mut g, &mut j).unwrap();
        // S_u = (2, 0, 1), λa = (1.5, 0, 0); S_v = (1, 0, 0.5), μb = (0, 2, 0), halved.
        let want = [0.5, 0.0, 1.0, 0.5, -1.0, 0.25];
        for (a, b) in g.iter().zip(want) {
            assert_relative_eq!(*a, b, epsilon = 1e-15);
        }
        // ∂ row 0 / ∂λ = −a_x·(1/|a|) = −1 (column 6); ∂ row 4 / ∂μ = −2·0.5 = −1 (column 7).
        assert_relative_eq!(j[6], -1.0);
        assert_relative_eq!(j[4 * 8 + 7], -1.0);
        assert!(DynResidual::is_affine(&r));
    }
}
