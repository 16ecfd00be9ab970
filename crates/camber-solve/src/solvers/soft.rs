//! The soft mode: a least-squares compromise for systems that cannot be met exactly.
//!
//! It minimises S(z) = Σ_i g_i(z)² + ε·‖z − z_ref‖²_W by Levenberg–Marquardt. With J = ∂g/∂z
//! the Gauss–Newton model of S gives the normal equations
//!
//! (JᵀJ + εW + λ·D)·Δz = −(Jᵀg + εW·(z − z_ref)),
//!
//! D being the diagonal of JᵀJ + εW (Marquardt's scaling) and λ ≥ 0 the damping, raised when a
//! step does not lower S and lowered when it does. The matrix is symmetric positive definite
//! for ε > 0, so a sparse Cholesky (faer) solves it; it is n × n over the reduced unknowns and
//! is formed sparse from the rows of J. Trial points are clamped to the bounds.
//!
//! The ε term keeps the answer near the start where the residuals leave freedom, but it also
//! pulls a consistent system slightly off g = 0 (by about ε times the distance moved). Two
//! proximal rounds follow, each minimising Σ g_i² + ε‖z − z_prev‖²_W from the previous answer:
//! the bias shrinks by a factor of about ε/σ² per round (σ a singular value of J), so the
//! constraints that can be met end up met to rounding and only conflicting ones stay above
//! tolerance, while the point hardly moves.

use faer::linalg::solvers::Solve;
use faer::sparse::{SparseColMat, Triplet};
use faer::{MatMut, Side};

use crate::linalg::evaluator::{max_abs, Evaluator};
use crate::model::errors::{Error, Result};
use crate::model::problem::Problem;

/// How a Levenberg–Marquardt run ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LmRun {
    /// Iterations run (both stages).
    pub(crate) iterations: usize,
    /// S at the end (of the last stage).
    pub(crate) cost: f64,
    /// max |g| at the end.
    pub(crate) max_residual: f64,
}

/// S(z) = ‖g‖² + ε‖z − z_ref‖²_W, with g written into `g`.
fn cost(
    problem: &Problem,
    ev: &mut Evaluator,
    z: &[f64],
    reference: &[f64],
    epsilon: f64,
    g: &mut [f64],
) -> f64 {
    if ev.residuals(problem, z, g).is_err() {
        return f64::INFINITY;
    }
    let w = ev.map.weights();
    let pull: f64 = (0..z.len())
        .map(|k| w[k] * (z[k] - reference[k]).powi(2))
        .sum();
    g.iter().map(|v| v * v).sum::<f64>() + epsilon * pull
}

/// One stage of Levenberg–Marquardt on S with the given ε, from `z` (updated in place).
fn stage(
    problem: &Problem,
    ev: &mut Evaluator,
    z: &mut Vec<f64>,
    reference: &[f64],
    epsilon: f64,
    max_iterations: usize,
) -> Result<(usize, f64)> {
    let (n, m) = (ev.cols(), ev.rows());
    let w = ev.map.weights().to_vec();
    let mut g = vec![0.0; m];
    let mut g_trial = vec![0.0; m];
    let mut z_trial = vec![0.0; n];
    let mut grad = vec![0.0; n];
    let mut diag = vec![0.0; n];
    let mut step = vec![0.0; n];
    let mut lambda = 1e-3;
    let mut s = cost(problem, ev, z, reference, epsilon, &mut g);
    let mut iterations = 0;
    // A spent evaluation budget ends the run where it is, as the iteration limit does.
    while iterations < max_iterations && !problem.budget.exhausted() {
        iterations += 1;
        ev.linearize(problem, z, &mut g)?;
        let j = ev.jacobian(&[])?;
        // Gradient (halved) b = Jᵀg + εW(z − z_ref) and the diagonal of JᵀJ + εW.
        for k in 0..n {
            grad[k] = epsilon * w[k] * (z[k] - reference[k]);
            diag[k] = epsilon * w[k];
        }
        let mut lower = Vec::new();
        for (i, gi) in g.iter().enumerate() {
            let (cols, vals) = j.row(i);
            for (a, (ca, va)) in cols.iter().zip(vals).enumerate() {
                grad[*ca] += va * gi;
                diag[*ca] += va * va;
                for (cb, vb) in cols[..a].iter().zip(vals) {
                    // Columns within a row increase, so ca > cb: the lower triangle.
                    lower.push(Triplet::new(*ca, *cb, va * vb));
                }
            }
        }
        if max_abs(&grad) <= 1e-300_f64.max(1e-16 * s) {
            break;
        }
        let mut accepted = false;
        for _ in 0..12 {
            let mut t = lower.clone();
            for (k, d) in diag.iter().enumerate() {
                t.push(Triplet::new(k, k, d * (1.0 + lambda)));
            }
            let mat = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, &t)
                .map_err(|_| Error::RankDeficient { rows: n })?;
            let Ok(llt) = mat.sp_cholesky(Side::Lower) else {
                lambda *= 10.0;
                continue;
            };
            for k in 0..n {
                step[k] = -grad[k];
            }
            llt.solve_in_place(MatMut::from_column_major_slice_mut(&mut step, n, 1));
            for k in 0..n {
                z_trial[k] = z[k] + step[k];
            }
            ev.clamp(&mut z_trial);
            let s_trial = cost(problem, ev, &z_trial, reference, epsilon, &mut g_trial);
            // Near the minimum of a large-residual sum the decrease of S drowns in rounding
            // (S changes by the square of the error); a step whose predicted decrease is
            // below that level is taken as long as S does not visibly grow.
            let predicted: f64 = -grad.iter().zip(&step).map(|(a, b)| a * b).sum::<f64>();
            let rounding = 1e-13 * s.abs();
            if s_trial < s || (predicted.abs() <= rounding && s_trial <= s + rounding) {
                let tiny = max_abs(&step) <= 1e-15 * (1.0 + max_abs(z));
                std::mem::swap(z, &mut z_trial);
                s = s_trial;
                lambda = (lambda / 3.0).max(1e-12);
                if tiny {
                    return Ok((iterations, s));
                }
                accepted = true;
                break;
            }
            lambda *= 4.0;
        }
        if !accepted {
            break;
        }
    }
    Ok((iterations, s))
}

/// Levenberg–Marquardt on S from `start`, then two proximal rounds; returns the final point.
///
/// # Errors
/// Evaluation errors.
pub(crate) fn run(
    problem: &Problem,
    ev: &mut Evaluator,
    start: &[f64],
    reference: &[f64],
    epsilon: f64,
    max_iterations: usize,
) -> Result<(Vec<f64>, LmRun)> {
    crate::model::errors::check_len("soft start", ev.cols(), start.len())?;
    crate::model::errors::check_len("soft reference", ev.cols(), reference.len())?;
    let mut z = start.to_vec();
    ev.clamp(&mut z);
    let (mut iterations, mut cost) =
        stage(problem, ev, &mut z, reference, epsilon, max_iterations)?;
    // Proximal rounds: the same ε, pulled toward the previous answer instead of the start.
    for _ in 0..2 {
        let here = z.clone();
        let (it, c) = stage(problem, ev, &mut z, &here, epsilon, max_iterations)?;
        iterations += it;
        cost = c;
    }
    let mut g = vec![0.0; ev.rows()];
    ev.residuals_for_report(problem, &z, &mut g)?;
    Ok((
        z,
        LmRun {
            iterations,
            cost,
            max_residual: max_abs(&g),
        },
    ))
}
