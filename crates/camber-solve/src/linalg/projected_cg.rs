//! The equality-constrained quadratic step of Newton's method, by projected conjugate
//! gradients with the minimum-norm factorization as the constraint preconditioner.
//!
//! At an iterate z with residuals g, Jacobian J, multipliers λ and H = Σᵢ λᵢ·∇²gᵢ, the
//! second-order step Δ solves
//!
//! min ½·Δᵀ·K·Δ + cᵀ·Δ  subject to  J·Δ = −g,   K = W + H,  c = W·(z − z_ref),
//!
//! whose optimality conditions K·Δ + c + Jᵀ·λ⁺ = 0, J·Δ = −g are Newton's equations for the
//! stationary points of ½‖z − z_ref‖²_W on g = 0. Conjugate gradients run in the null space of J
//! (Gould, Hribar and Nocedal, 2001): a feasible start Δ₀ = −J⁺·g, then every residual
//! r = K·Δ + c is projected with P·r = W⁻¹·(r − Jᵀ·y) ([`MinNormFactorization::project`]), so
//! each search direction keeps J·Δ = −g, and y gives the multiplier estimate λ⁺ = −y. The
//! cached Cholesky factor of J·W⁻¹·Jᵀ is the only factorization: no KKT matrix is formed.
//!
//! With H = 0 the projected system is the identity in the W metric and one iteration returns
//! the Gauss–Newton pull-back step d − J⁺·(g + J·d) exactly; H only adds iterations in the
//! directions it bends.
//! A direction of non-positive curvature (H makes the reduced problem non-convex there) stops
//! the iteration: on the first direction it is reported so that the caller can use the
//! Gauss–Newton step instead; later, the step so far is kept (it already lowers the model).

use crate::linalg::min_norm::MinNormFactorization;
use crate::linalg::sparse::SparseMatrix;
use crate::model::errors::Result;

/// ‖P·r‖²_W below this fraction of ‖r‖²_{W⁻¹} is rounding in the projection (about ε in
/// norm), not a direction.
const ROUNDING: f64 = 1e-26;

/// Scratch vectors of [`solve`], kept between Newton iterations.
#[derive(Debug, Default, Clone)]
pub(crate) struct CgWorkspace {
    r: Vec<f64>,
    v: Vec<f64>,
    p: Vec<f64>,
    kp: Vec<f64>,
    hp: Vec<f64>,
    y: Vec<f64>,
    /// Δ₀ = −J⁺·g of the last solve, for [`Start::Reuse`].
    feasible: Vec<f64>,
}

/// Where the feasible start Δ₀ = −J⁺·g comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Start {
    /// Solve for it.
    Compute,
    /// The last solve's, when the factorization and g are the same.
    Reuse,
}

/// How the quadratic step ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum CgOutcome {
    /// The projected residual fell below the tolerance (or the iteration limit was met, or a
    /// later direction had non-positive curvature).
    Converged {
        /// Conjugate-gradient iterations.
        iterations: usize,
    },
    /// The first direction already had non-positive curvature: the step is unusable.
    NegativeCurvature,
}

/// The problem data of one quadratic step.
pub(crate) struct QpData<'a> {
    /// Diagonal weights W.
    pub(crate) weights: &'a [f64],
    /// H = Σ λᵢ∇²gᵢ over the reduced unknowns, `None` for zero.
    pub(crate) hessian: Option<&'a SparseMatrix>,
    /// c = W·(z − z_ref).
    pub(crate) gradient: &'a [f64],
    /// The residuals g of the rows in the factorization.
    pub(crate) residuals: &'a [f64],
    /// Unknowns held at a bound: their step stays zero.
    pub(crate) held: &'a [bool],
    /// Where Δ₀ comes from.
    pub(crate) start: Start,
    /// The relative reduction of rᵀ·P·r at which the step counts as solved.
    pub(crate) tolerance: f64,
}

/// Conjugate-gradient iterations of one quadratic step at most.
pub(crate) const MAX_ITERATIONS: usize = 50;

/// Solves the quadratic step into `step` and its multipliers λ⁺ into `lambda` (one per row of
/// the factorization). Stops at once when the projected residual is rounding against the whole
/// (the start is already stationary), and otherwise when rᵀ·P·r ≤ `tolerance`²·(r₀ᵀ·P·r₀) or
/// after [`MAX_ITERATIONS`].
///
/// # Errors
/// Dimension errors of the factorization's solves.
pub(crate) fn solve(
    factorization: &mut MinNormFactorization,
    data: &QpData<'_>,
    ws: &mut CgWorkspace,
    step: &mut [f64],
    lambda: &mut [f64],
) -> Result<CgOutcome> {
    let (start, tolerance, max_iterations) = (data.start, data.tolerance, MAX_ITERATIONS);
    let n = step.len();
    for v in [&mut ws.r, &mut ws.v, &mut ws.p, &mut ws.kp, &mut ws.hp] {
        v.clear();
        v.resize(n, 0.0);
    }
    ws.y.clear();
    ws.y.resize(lambda.len(), 0.0);

    // Feasible start: the minimum-norm solution of J·Δ = −g.
    if start == Start::Compute || ws.feasible.len() != n {
        ws.feasible.resize(n, 0.0);
        factorization.solve_refined(data.residuals, &mut ws.feasible, 2, 0.0)?;
    }
    step.copy_from_slice(&ws.feasible);
    apply_k(data, step, &mut ws.hp, &mut ws.r)?;
    for (r, c) in ws.r.iter_mut().zip(data.gradient) {
        *r += c;
    }
    project(factorization, data.held, ws)?;
    for (l, y) in lambda.iter_mut().zip(&ws.y) {
        *l = -y;
    }
    // rᵀ·P·r, computed as ‖P·r‖²_W (equal, since P·W·P = P): rᵀ·v would carry rounding of
    // order ε·‖r‖², which swamps a small but real projected part.
    // No null space to move in: as many rows as unknowns that may move, J of full row rank
    // (its factorization exists), so P = 0 and the feasible start is the step. What the
    // projection leaves of r is rounding, which the iterations would only chase (on a large
    // square component it stays above `ROUNDING` and they ran to the limit, 50 solves).
    let free = data.held.iter().filter(|h| !**h).count();
    if free <= lambda.len() {
        return Ok(CgOutcome::Converged { iterations: 0 });
    }
    let w = data.weights;
    let mut rho = w_dot(w, &ws.v, &ws.v);
    let rho0 = rho;
    let whole: f64 = ws.r.iter().zip(w).map(|(r, wk)| r * r / wk).sum();
    if rho <= ROUNDING * whole {
        return Ok(CgOutcome::Converged { iterations: 0 });
    }
    for (p, v) in ws.p.iter_mut().zip(&ws.v) {
        *p = -v;
    }
    for iteration in 0..max_iterations {
        apply_k(data, &ws.p, &mut ws.hp, &mut ws.kp)?;
        let curvature = dot(&ws.p, &ws.kp);
        if curvature <= 1e-10 * w_dot(w, &ws.p, &ws.p) {
            if iteration == 0 {
                return Ok(CgOutcome::NegativeCurvature);
            }
            return Ok(CgOutcome::Converged {
                iterations: iteration,
            });
        }
        let alpha = rho / curvature;
        for ((sk, rk), (pk, kpk)) in step
            .iter_mut()
            .zip(ws.r.iter_mut())
            .zip(ws.p.iter().zip(&ws.kp))
        {
            *sk += alpha * pk;
            *rk += alpha * kpk;
        }
        project(factorization, data.held, ws)?;
        for (l, y) in lambda.iter_mut().zip(&ws.y) {
            *l = -y;
        }
        let next = w_dot(w, &ws.v, &ws.v);
        // Converged, or down to the rounding of the projection.
        let whole: f64 = ws.r.iter().zip(w).map(|(r, wk)| r * r / wk).sum();
        if next <= tolerance * tolerance * rho0 || next <= ROUNDING * whole {
            return Ok(CgOutcome::Converged {
                iterations: iteration + 1,
            });
        }
        let beta = next / rho;
        rho = next;
        for (p, v) in ws.p.iter_mut().zip(&ws.v) {
            *p = -v + beta * *p;
        }
    }
    Ok(CgOutcome::Converged {
        iterations: max_iterations,
    })
}

/// ⟨a, b⟩_W = Σ w_k·a_k·b_k.
fn w_dot(w: &[f64], a: &[f64], b: &[f64]) -> f64 {
    w.iter().zip(a).zip(b).map(|((wk, x), y)| wk * x * y).sum()
}

/// out = K·v = W·v + H·v (`hv` is scratch).
fn apply_k(data: &QpData<'_>, v: &[f64], hv: &mut [f64], out: &mut [f64]) -> Result<()> {
    match data.hessian {
        Some(h) => h.mul_vec(v, hv)?,
        None => hv.fill(0.0),
    }
    for (o, ((vk, w), hk)) in out
        .iter_mut()
        .zip(v.iter().zip(data.weights).zip(hv.iter()))
    {
        *o = w * vk + hk;
    }
    Ok(())
}

/// v = P·r with the held unknowns' entries zeroed (the projection onto the null space of J
/// within the unknowns that may move: J has no entry in a held column), y its multipliers.
fn project(
    factorization: &mut MinNormFactorization,
    held: &[bool],
    ws: &mut CgWorkspace,
) -> Result<()> {
    factorization.project(&ws.r, &mut ws.v, &mut ws.y)?;
    for (v, h) in ws.v.iter_mut().zip(held) {
        if *h {
            *v = 0.0;
        }
    }
    Ok(())
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use nalgebra::{DMatrix, DVector};

    /// The KKT system [K Jᵀ; J 0]·[Δ; λ] = [−c; −g] solved densely by LU.
    fn kkt(k: &DMatrix<f64>, j: &DMatrix<f64>, c: &[f64], g: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let (n, m) = (k.nrows(), j.nrows());
        let mut a = DMatrix::zeros(n + m, n + m);
        a.view_mut((0, 0), (n, n)).copy_from(k);
        a.view_mut((0, n), (n, m)).copy_from(&j.transpose());
        a.view_mut((n, 0), (m, n)).copy_from(j);
        let mut b = DVector::zeros(n + m);
        for i in 0..n {
            b[i] = -c[i];
        }
        for i in 0..m {
            b[n + i] = -g[i];
        }
        let x = a.lu().solve(&b).unwrap();
        (
            x.rows(0, n).iter().copied().collect(),
            x.rows(n, m).iter().copied().collect(),
        )
    }

    #[test]
    fn matches_the_dense_kkt_solution() {
        // n = 4, m = 2, H symmetric with K = W + H positive definite.
        let jd = DMatrix::from_row_slice(2, 4, &[1.0, 2.0, 0.0, -1.0, 0.0, 1.0, 1.0, 1.0]);
        let w = [1.0, 2.0, 0.5, 1.0];
        let hd = DMatrix::from_row_slice(
            4,
            4,
            &[
                0.5, 0.2, 0.0, 0.1, 0.2, -0.3, 0.1, 0.0, 0.0, 0.1, 0.4, 0.0, 0.1, 0.0, 0.0, 0.2,
            ],
        );
        let j = SparseMatrix::from_dense(&jd);
        let h = SparseMatrix::from_dense(&hd);
        let c = [0.3, -0.2, 1.0, 0.5];
        let g = [0.1, -0.4];
        let mut kd = hd.clone();
        for i in 0..4 {
            kd[(i, i)] += w[i];
        }
        let (want_step, want_lambda) = kkt(&kd, &jd, &c, &g);
        for sparse in [false, true] {
            let mut f = if sparse {
                MinNormFactorization::try_sparse(&j, &w).unwrap()
            } else {
                MinNormFactorization::try_dense(&j, &w).unwrap()
            };
            let data = QpData {
                weights: &w,
                hessian: Some(&h),
                gradient: &c,
                residuals: &g,
                held: &[false; 4],
                start: Start::Compute,
                tolerance: 1e-14,
            };
            let (mut step, mut lambda) = ([0.0; 4], [0.0; 2]);
            let out = solve(
                &mut f,
                &data,
                &mut CgWorkspace::default(),
                &mut step,
                &mut lambda,
            )
            .unwrap();
            assert!(matches!(out, CgOutcome::Converged { iterations, .. } if iterations <= 2));
            for (a, b) in step.iter().zip(&want_step) {
                assert_relative_eq!(*a, *b, epsilon = 1e-12);
            }
            for (a, b) in lambda.iter().zip(&want_lambda) {
                assert_relative_eq!(*a, *b, epsilon = 1e-12);
            }
        }
    }

    #[test]
    fn without_curvature_one_iteration_gives_the_pull_back_step() {
        // Δ = d − J⁺(g + J·d) with d = −W⁻¹c (that is, c = −W·d).
        let jd = DMatrix::from_row_slice(1, 3, &[1.0, 1.0, 1.0]);
        let j = SparseMatrix::from_dense(&jd);
        let w = [1.0; 3];
        let d = [0.5, -1.0, 0.25];
        let c: Vec<f64> = d.iter().map(|v| -v).collect();
        let g = [0.6];
        let mut f = MinNormFactorization::try_dense(&j, &w).unwrap();
        let data = QpData {
            weights: &w,
            hessian: None,
            gradient: &c,
            residuals: &g,
            held: &[false; 3],
            start: Start::Compute,
            tolerance: 1e-14,
        };
        let (mut step, mut lambda) = ([0.0; 3], [0.0]);
        let out = solve(
            &mut f,
            &data,
            &mut CgWorkspace::default(),
            &mut step,
            &mut lambda,
        )
        .unwrap();
        assert!(matches!(out, CgOutcome::Converged { iterations, .. } if iterations <= 1));
        // g + J·d = 0.6 − 0.25 = 0.35, J⁺ of it = 0.35/3 per entry.
        for k in 0..3 {
            assert_relative_eq!(step[k], d[k] - 0.35 / 3.0, epsilon = 1e-14);
        }
        assert_relative_eq!(lambda[0], 0.35 / 3.0, epsilon = 1e-14);
    }

    /// As many rows as free unknowns: the step is −J⁻¹·g with no iteration, whatever the
    /// curvature and the pull toward the reference, and λ solves Jᵀ·λ = −(K·Δ + c). One unknown
    /// held leaves a square system in the others.
    #[test]
    fn without_a_null_space_the_feasible_start_is_the_step() {
        let jd = DMatrix::from_row_slice(2, 3, &[2.0, 1.0, 0.0, -1.0, 3.0, 0.0]);
        let j = SparseMatrix::from_dense(&jd);
        let w = [1.0, 2.0, 1.0];
        let h = SparseMatrix::from_dense(&DMatrix::from_row_slice(
            3,
            3,
            &[0.5, 0.1, 0.0, 0.1, -0.2, 0.0, 0.0, 0.0, 0.0],
        ));
        let c = [0.4, -0.3, 0.0];
        let g = [1.0, -2.0];
        // [2 1; −1 3]·Δ = −g: Δ = (−5/7, 3/7).
        let want = [-5.0 / 7.0, 3.0 / 7.0];
        for (sparse, hessian) in [(false, None), (true, None), (true, Some(&h))] {
            let mut f = if sparse {
                MinNormFactorization::try_sparse(&j, &w).unwrap()
            } else {
                MinNormFactorization::try_dense(&j, &w).unwrap()
            };
            let data = QpData {
                weights: &w,
                hessian,
                gradient: &c,
                residuals: &g,
                held: &[false, false, true],
                start: Start::Compute,
                tolerance: 1e-14,
            };
            let (mut step, mut lambda) = ([0.0; 3], [0.0; 2]);
            let out = solve(
                &mut f,
                &data,
                &mut CgWorkspace::default(),
                &mut step,
                &mut lambda,
            )
            .unwrap();
            assert_eq!(out, CgOutcome::Converged { iterations: 0 });
            assert_relative_eq!(step[0], want[0], epsilon = 1e-14);
            assert_relative_eq!(step[1], want[1], epsilon = 1e-14);
            assert_relative_eq!(step[2], 0.0, epsilon = 1e-14);
            // Jᵀ·λ = −(K·Δ + c) in the free unknowns.
            let mut kd = [0.0; 2];
            for i in 0..2 {
                kd[i] = w[i] * step[i] + c[i];
                if hessian.is_some() {
                    let hd = [[0.5, 0.1], [0.1, -0.2]];
                    kd[i] += hd[i][0] * step[0] + hd[i][1] * step[1];
                }
            }
            for col in 0..2 {
                let jt_l: f64 = (0..2).map(|r| jd[(r, col)] * lambda[r]).sum();
                assert_relative_eq!(jt_l, -kd[col], epsilon = 1e-12);
            }
        }
    }

    #[test]
    fn non_positive_curvature_on_the_first_direction_is_reported() {
        let jd = DMatrix::from_row_slice(1, 2, &[1.0, 0.0]);
        let j = SparseMatrix::from_dense(&jd);
        let w = [1.0, 1.0];
        // K = W + H = diag(1, −1): the null space direction (0, 1) has negative curvature.
        let h = SparseMatrix::from_dense(&DMatrix::from_row_slice(2, 2, &[0.0, 0.0, 0.0, -2.0]));
        let mut f = MinNormFactorization::try_dense(&j, &w).unwrap();
        let data = QpData {
            weights: &w,
            hessian: Some(&h),
            gradient: &[0.0, 1.0],
            residuals: &[0.0],
            held: &[false; 2],
            start: Start::Compute,
            tolerance: 1e-14,
        };
        let (mut step, mut lambda) = ([0.0; 2], [0.0]);
        let out = solve(
            &mut f,
            &data,
            &mut CgWorkspace::default(),
            &mut step,
            &mut lambda,
        )
        .unwrap();
        assert_eq!(out, CgOutcome::NegativeCurvature);
    }
}
