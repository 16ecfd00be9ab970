//! Newton minimum-norm iterations with the null-space pull-back toward a reference point.
//!
//! At the current z, with g = g(z), J = ∂g/∂z, the W-weighted pseudo-inverse
//! J⁺ = W⁻¹·Jᵀ·(J·W⁻¹·Jᵀ)⁻¹ and d = z_ref − z, the step is
//!
//! Δz = −J⁺·g + (I − J⁺·J)·d = d − J⁺·(g + J·d),
//!
//! so one minimum-norm solve with the right-hand side g + J·d gives it (no inverse is formed;
//! [`crate::MinNormFactorization`] does the solve). The first part drives g to zero; the second
//! moves within the null space of J toward z_ref. It is exactly the step of the quadratic
//! program min ½‖z + Δ − z_ref‖²_W subject to g + J·Δ = 0, so its fixed points are the points
//! of g = 0 where W·(z − z_ref) lies in the range of Jᵀ: the first-order conditions of the
//! solution W-nearest to z_ref, not just any solution.
//!
//! **Damping.** Steps are accepted by backtracking on the merit
//! φ(z) = ½‖z − z_ref‖²_W + μ‖g(z)‖₂ (an exact penalty; μ grows so that Δz is a descent
//! direction, as in Nocedal & Wright §18.3). A pure decrease test on ‖g‖ would refuse the
//! pull-back moves once g is zero. When the full step is refused, a second-order correction
//! −J⁺·g(z + Δz) (same factorization) is tried before halving the step.
//!
//! **Bounds.** Trial points are clamped to the bounds of the reduced unknowns; an unknown at a
//! bound whose step points outward is held there (its column dropped) for the iteration.

use crate::errors::{Error, Result};
use crate::evaluator::{max_abs, norm2, Evaluator};
use crate::min_norm::MinNormFactorization;
use crate::problem::Problem;
use crate::solve::Options;

/// Reusable buffers of the Newton iterations: a drag session keeps one and passes it to
/// [`crate::solve_newton_from`] at every mouse event, so repeated solves of the same problem
/// shape reuse their vectors.
#[derive(Debug, Default)]
pub struct NewtonWorkspace {
    pub(crate) z: Vec<f64>,
    g: Vec<f64>,
    g_trial: Vec<f64>,
    gs: Vec<f64>,
    gs_trial: Vec<f64>,
    z_trial: Vec<f64>,
    d: Vec<f64>,
    r: Vec<f64>,
    p: Vec<f64>,
    p2: Vec<f64>,
    step: Vec<f64>,
    drop: Vec<bool>,
}

impl NewtonWorkspace {
    /// An empty workspace (buffers grow on first use).
    pub fn new() -> Self {
        Self::default()
    }
}

/// How a Newton run ended (the point is left in the workspace's `z`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct NewtonRun {
    pub(crate) iterations: usize,
    /// max |g| over the rows used, at the final point.
    pub(crate) max_residual: f64,
    /// Whether the pull-back also converged (step below the step tolerance).
    pub(crate) stationary: bool,
}

/// Copies the selected rows of `g` (all of them when `rows` is None) into `out`.
fn select(g: &[f64], rows: Option<&[usize]>, out: &mut Vec<f64>) {
    out.clear();
    match rows {
        None => out.extend_from_slice(g),
        Some(rows) => out.extend(rows.iter().map(|i| g.get(*i).copied().unwrap_or(f64::NAN))),
    }
}

/// ½‖z − z_ref‖²_W.
fn distance(z: &[f64], reference: &[f64], w: &[f64]) -> f64 {
    z.iter()
        .zip(reference)
        .zip(w)
        .map(|((a, b), wk)| 0.5 * wk * (a - b) * (a - b))
        .sum()
}

/// Runs Newton from `start` toward `reference` on the rows `rows` (all when None), leaving the
/// final point in `ws.z`. The evaluator must be `ws.evaluator`'s content, passed separately.
///
/// # Errors
/// [`Error::RankDeficient`] when J·W⁻¹·Jᵀ cannot be factorized at an iterate,
/// [`Error::NotConverged`] when the line search or the iteration limit stops it short, and
/// evaluation errors.
pub(crate) fn run(
    problem: &Problem,
    ev: &mut Evaluator,
    ws: &mut NewtonWorkspace,
    start: &[f64],
    reference: &[f64],
    rows: Option<&[usize]>,
    options: &Options,
) -> Result<NewtonRun> {
    let n = ev.cols();
    let m = ev.rows();
    crate::sparse::check_len("Newton start", n, start.len())?;
    crate::sparse::check_len("Newton reference", n, reference.len())?;
    let settings = &options.nonlinear;
    let inner_tol = 0.1 * options.tolerance;
    ws.z.clear();
    ws.z.extend_from_slice(start);
    ev.clamp(&mut ws.z);
    for v in [&mut ws.g, &mut ws.g_trial] {
        v.clear();
        v.resize(m, 0.0);
    }
    for v in [
        &mut ws.z_trial,
        &mut ws.d,
        &mut ws.p,
        &mut ws.p2,
        &mut ws.step,
    ] {
        v.clear();
        v.resize(n, 0.0);
    }
    ws.drop.clear();
    ws.drop.resize(n, false);
    let weights = ev.map.weights().to_vec();
    let mut mu = 0.0_f64;
    let mut last_max: f64;
    for iteration in 0..settings.max_iterations {
        ev.linearize(problem, &ws.z, &mut ws.g)?;
        select(&ws.g, rows, &mut ws.gs);
        let gnorm = norm2(&ws.gs);
        last_max = max_abs(&ws.gs);

        // The step, holding unknowns at a bound whose step points outward.
        ws.drop.fill(false);
        let mut factorization;
        let mut pass = 0;
        loop {
            for (((dk, held), rk), zk) in ws.d.iter_mut().zip(&ws.drop).zip(reference).zip(&ws.z) {
                *dk = if *held { 0.0 } else { rk - zk };
            }
            let full = ev.jacobian(&ws.drop)?;
            let j = match rows {
                Some(rows) => full.select_rows(rows),
                None => full,
            };
            ws.r.clear();
            ws.r.resize(j.nrows(), 0.0);
            j.mul_vec(&ws.d, &mut ws.r)?;
            for (ri, gi) in ws.r.iter_mut().zip(&ws.gs) {
                *ri += gi;
            }
            factorization =
                MinNormFactorization::try_auto(&j, &weights, options.dense_max_unknowns)?;
            factorization.solve_refined(&ws.r, &mut ws.p, 2, 1e-3 * inner_tol)?;
            for k in 0..n {
                ws.step[k] = ws.d[k] + ws.p[k];
            }
            let mut changed = false;
            for k in 0..n {
                let outward = (ws.z[k] <= ev.lower[k] && ws.step[k] < 0.0)
                    || (ws.z[k] >= ev.upper[k] && ws.step[k] > 0.0);
                if outward && !ws.drop[k] {
                    ws.drop[k] = true;
                    changed = true;
                }
            }
            pass += 1;
            if !changed || pass > 3 {
                break;
            }
        }

        let zmax = max_abs(&ws.z);
        if last_max <= inner_tol && max_abs(&ws.step) <= settings.step_tolerance * (1.0 + zmax) {
            return Ok(NewtonRun {
                iterations: iteration,
                max_residual: last_max,
                stationary: true,
            });
        }

        // Merit φ = ½‖z − z_ref‖²_W + μ‖g‖ and its directional derivative along the step.
        let gtd: f64 = (0..n)
            .map(|k| weights[k] * (ws.z[k] - reference[k]) * ws.step[k])
            .sum();
        let quad: f64 = (0..n).map(|k| weights[k] * ws.step[k] * ws.step[k]).sum();
        if gnorm > 0.0 {
            let needed = (gtd + 0.5 * quad) / (0.5 * gnorm);
            if mu < needed {
                mu = 1.5 * needed;
            }
        }
        let dphi = gtd - mu * gnorm;
        let phi0 = distance(&ws.z, reference, &weights) + mu * gnorm;

        let mut accepted = false;
        let mut alpha = 1.0;
        for attempt in 0..40 {
            for k in 0..n {
                ws.z_trial[k] = ws.z[k] + alpha * ws.step[k];
            }
            ev.clamp(&mut ws.z_trial);
            let phi = match ev.residuals(problem, &ws.z_trial, &mut ws.g_trial) {
                Ok(()) => {
                    select(&ws.g_trial, rows, &mut ws.gs_trial);
                    distance(&ws.z_trial, reference, &weights) + mu * norm2(&ws.gs_trial)
                }
                Err(_) => f64::INFINITY,
            };
            // Once g is met, rounding in φ can hide the small pull-back gains: a trial that
            // keeps g met and does not move away from the reference is taken too.
            let feasible = phi.is_finite()
                && max_abs(&ws.gs_trial) <= inner_tol
                && distance(&ws.z_trial, reference, &weights)
                    <= distance(&ws.z, reference, &weights);
            if phi <= phi0 + 1e-4 * alpha * dphi || feasible {
                accepted = true;
                break;
            }
            if attempt == 0 && phi.is_finite() {
                // Second-order correction: remove what the curvature added to g.
                factorization.solve(&ws.gs_trial, &mut ws.p2)?;
                for k in 0..n {
                    ws.p2[k] += ws.z_trial[k];
                }
                ev.clamp(&mut ws.p2);
                if ev.residuals(problem, &ws.p2, &mut ws.g_trial).is_ok() {
                    select(&ws.g_trial, rows, &mut ws.gs_trial);
                    let phi = distance(&ws.p2, reference, &weights) + mu * norm2(&ws.gs_trial);
                    if phi <= phi0 + 1e-4 * dphi {
                        std::mem::swap(&mut ws.z_trial, &mut ws.p2);
                        accepted = true;
                        break;
                    }
                }
            }
            alpha *= 0.5;
        }
        if !accepted {
            // No progress possible: a solution counts if the residuals are already met.
            if last_max <= inner_tol {
                return Ok(NewtonRun {
                    iterations: iteration,
                    max_residual: last_max,
                    stationary: false,
                });
            }
            return Err(Error::NotConverged {
                solver: "Newton",
                iterations: iteration,
                max_residual: last_max,
            });
        }
        std::mem::swap(&mut ws.z, &mut ws.z_trial);
    }
    // Out of iterations: accept a point that meets the residuals, flagged as not stationary.
    ev.residuals(problem, &ws.z, &mut ws.g)?;
    select(&ws.g, rows, &mut ws.gs);
    last_max = max_abs(&ws.gs);
    if last_max <= inner_tol {
        Ok(NewtonRun {
            iterations: settings.max_iterations,
            max_residual: last_max,
            stationary: false,
        })
    } else {
        Err(Error::NotConverged {
            solver: "Newton",
            iterations: settings.max_iterations,
            max_residual: last_max,
        })
    }
}
