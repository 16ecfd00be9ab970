//! Newton minimum-norm iterations with the null-space pull-back toward a reference point,
//! and their second-order form.
//!
//! At the current z, with g = g(z), J = ∂g/∂z, the W-weighted pseudo-inverse
//! J⁺ = W⁻¹·Jᵀ·(J·W⁻¹·Jᵀ)⁻¹ and d = z_ref − z, the Gauss–Newton pull-back step is
//!
//! Δz = −J⁺·g + (I − J⁺·J)·d = d − J⁺·(g + J·d),
//!
//! the step of the quadratic program min ½‖z + Δ − z_ref‖²_W subject to g + J·Δ = 0. The first
//! part drives g to zero; the second moves within the null space of J toward z_ref. Its fixed
//! points are the points of g = 0 where W·(z − z_ref) lies in the range of Jᵀ: the first-order
//! conditions of the solution W-nearest to z_ref, not just any solution. It converges to them
//! only linearly, though, at the rate of the constraints' curvature against W.
//!
//! **Second-order step.** With the multipliers λ of the previous step, the Hessian of the
//! Lagrangian ½‖z − z_ref‖²_W + λᵀ·g is K = W + H, H = Σ λᵢ·∇²gᵢ (exact, from hyper-dual
//! numbers, [`crate::derive::hessian`]), and the quadratic program with K in place of W is Newton's
//! method on the first-order conditions: quadratic convergence. It is solved by projected
//! conjugate gradients on the same factorization (the `projected_cg` module). Far from the
//! solution its model can mislead, so every iteration tries the second-order step at full length
//! (or with its second-order correction) and keeps it only if the merit accepts it; otherwise it
//! takes the Gauss–Newton step with a backtracking search. Near the solution the second-order
//! steps are accepted and the iteration count stops growing with the curvature. With as many
//! independent rows as free unknowns the null space is empty and the second-order step is the
//! Gauss–Newton step, so it is not formed; the step −J⁻¹·g then comes from one LU of the square
//! J (the `square` module) instead of the factorization of J·W⁻¹·Jᵀ and the projection.
//!
//! **Damping.** Steps are accepted by the merit φ(z) = ½‖z − z_ref‖²_W + μ‖g(z)‖₂ (an exact
//! penalty; μ grows so that Δz is a descent direction and stays above ‖λ‖, as in Nocedal &
//! Wright §18.3). A pure decrease test on ‖g‖ would refuse the pull-back moves once g is zero.
//! When a full step is refused, second-order corrections −J⁺·g(z + Δz) (same factorization, up
//! to three while each halves ‖g‖) are tried before the step is cut.
//!
//! **Bounds.** Trial points are clamped to the bounds of the reduced unknowns; an unknown at a
//! bound whose Gauss–Newton step points outward is held there (its column dropped) for the
//! iteration.

use crate::linalg::evaluator::{max_abs, norm2, Evaluator};
use crate::linalg::min_norm::MinNormFactorization;
use crate::linalg::projected_cg::{self, CgOutcome, QpData, Start};
use crate::linalg::square::SquareFactors;
use crate::model::errors::{Error, Result};
use crate::model::options::Options;
use crate::model::problem::Problem;

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
    p2: Vec<f64>,
    /// The Gauss–Newton pull-back step and the second-order step.
    step: Vec<f64>,
    step2: Vec<f64>,
    /// A second-order correction.
    soc: Vec<f64>,
    drop: Vec<bool>,
    /// c = W·(z − z_ref) of the quadratic step.
    c: Vec<f64>,
    /// Multipliers of the rows used: the current estimate, those of the Gauss–Newton and of
    /// the second-order step, and a full-length copy for the Hessian.
    lambda: Vec<f64>,
    lambda_gn: Vec<f64>,
    lambda2: Vec<f64>,
    lambda_full: Vec<f64>,
    cg: crate::linalg::projected_cg::CgWorkspace,
    /// The pattern work of the sparse factorizations (J keeps its pattern between iterations).
    normal: crate::linalg::normal::NormalCache,
    /// The point z and residuals g at which the evaluator passed to the next run was just
    /// linearized (by the selection's analysis): its first iteration takes them over.
    primed: Option<(Vec<f64>, Vec<f64>)>,
    /// The LU of a square J (dense or sparse), refactorized in place at every iteration.
    square: SquareFactors,
}

impl NewtonWorkspace {
    /// An empty workspace (buffers grow on first use).
    pub fn new() -> Self {
        Self::default()
    }

    /// Tells the next [`run`] that its evaluator holds the linearization at `z` with the
    /// residuals `g` (used when the run starts at exactly that z).
    pub(crate) fn prime(&mut self, z: Vec<f64>, g: Vec<f64>) {
        self.primed = Some((z, g));
    }

    /// Forgets a linearization handed over by [`NewtonWorkspace::prime`].
    pub(crate) fn unprime(&mut self) {
        self.primed = None;
    }

    /// The workspace the last solve on this thread left ([`NewtonWorkspace::keep_as_spare`]),
    /// or a new one. Every run sizes and fills the vectors it uses, so a workspace from another
    /// problem serves as well as a new one; the sparse factorization's pattern cache checks
    /// the pattern it is given.
    pub(crate) fn take_spare() -> Self {
        SPARE
            .with(|spare| spare.borrow_mut().take())
            .unwrap_or_default()
    }

    /// Forgets the patterns kept for the sparse factorizations (the structure changed).
    pub(crate) fn forget_patterns(&mut self) {
        self.normal = crate::linalg::normal::NormalCache::default();
        self.square.forget_sparse();
        self.primed = None;
    }

    /// Keeps this workspace for the next solve on this thread ([`NewtonWorkspace::take_spare`]):
    /// a sketch's small components, solved one after another, then allocate their vectors
    /// once instead of once each. A workspace grown past [`SPARE_MAX_UNKNOWNS`] is dropped, and
    /// the sparse pattern cache is never kept, so a large solve does not hold its memory.
    pub(crate) fn keep_as_spare(mut self) {
        if self.z.capacity() > SPARE_MAX_UNKNOWNS {
            return;
        }
        self.normal = crate::linalg::normal::NormalCache::default();
        self.square.forget_sparse();
        self.primed = None;
        SPARE.with(|spare| *spare.borrow_mut() = Some(self));
    }
}

/// Largest workspace (in unknowns) kept between solves by [`NewtonWorkspace::keep_as_spare`].
const SPARE_MAX_UNKNOWNS: usize = 4096;

thread_local! {
    /// The Newton workspace of the last finished solve on this thread.
    static SPARE: std::cell::RefCell<Option<NewtonWorkspace>> = const { std::cell::RefCell::new(None) };
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

/// Iterations in a row that meet the rows (max |g| within the inner tolerance) without halving
/// the shortest pull-back step seen since the rows were met and without changing
/// ½‖z − z_ref‖²_W by more than [`STALLED_DISTANCE`] of it, after which the run stops as
/// stationary. Near the solution the second-order steps converge quadratically, so a step
/// that no longer halves while the objective stands still is the rounding floor of J⁺, about
/// ε·κ(J·W⁻¹·Jᵀ)·‖z − z_ref‖: on a chain of n links κ grows like n², and past some thousands
/// of links that floor exceeds `step_tolerance`·(1 + max |z|), which grows only like n.
/// Without this stop such a run went on to the iteration limit, moving by rounding (a chain
/// of 10⁴ points: 100 linearizations, 7.5 s, instead of 12). A slow but real pull-back (steps
/// refused by the merit, Gauss–Newton's linear rate) still moves the objective and goes on.
const STALLED_ITERATIONS: usize = 3;

/// The relative change of ½‖z − z_ref‖²_W between two iterations below which the pull-back
/// counts as standing still ([`STALLED_ITERATIONS`]): some hundred roundings of a sum of
/// positive terms.
const STALLED_DISTANCE: f64 = 1e-12;

/// Relative size of the projected residual at which a quadratic step is taken as solved (with
/// H = 0 one conjugate-gradient iteration solves it exactly; this only ends the rounding).
const CG_TOLERANCE: f64 = 1e-6;

/// Writes the multipliers of the rows used (`rows`, all when None) into their places of the
/// full-length `out`, zero elsewhere.
fn spread(lambda: &[f64], rows: Option<&[usize]>, out: &mut [f64]) {
    match rows {
        None => out.copy_from_slice(lambda),
        Some(rows) => {
            out.fill(0.0);
            for (i, l) in rows.iter().zip(lambda) {
                if let Some(slot) = out.get_mut(*i) {
                    *slot = *l;
                }
            }
        }
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
/// final point in `ws.z`.
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
    crate::model::errors::check_len("Newton start", n, start.len())?;
    crate::model::errors::check_len("Newton reference", n, reference.len())?;
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
        &mut ws.p2,
        &mut ws.step,
        &mut ws.step2,
        &mut ws.soc,
        &mut ws.c,
    ] {
        v.clear();
        v.resize(n, 0.0);
    }
    ws.drop.clear();
    ws.drop.resize(n, false);
    let used_rows = rows.map_or(m, <[usize]>::len);
    for v in [&mut ws.lambda, &mut ws.lambda_gn, &mut ws.lambda2] {
        v.clear();
        v.resize(used_rows, 0.0);
    }
    ws.lambda_full.clear();
    ws.lambda_full.resize(m, 0.0);
    let weights = ev.map.weights().to_vec();
    let mut merit = Merit {
        reference,
        weights: &weights,
        rows,
        mu: 0.0,
        inner_tol,
    };
    let mut last_max: f64;
    // The longest Gauss–Newton step at which the second-order step is tried.
    let mut second_order_gate = f64::INFINITY;
    // The linearization handed over by the caller, if it was taken at this very start.
    let mut primed = ws.primed.take().filter(|(z, g)| {
        g.len() == m && z.len() == n && z.iter().zip(&ws.z).all(|(a, b)| a.to_bits() == b.to_bits())
    });
    // The LU of a square J (its buffers reused from one iteration to the next), and whether
    // it is that of the last accepted square step: a chord step with it shows a point that
    // already meets the rows to be stationary without linearizing and factorizing it again.
    let mut lu = std::mem::take(&mut ws.square);
    let mut chord = false;
    // Iterations in a row that met the rows without halving the pull-back step or visibly
    // moving ½‖z − z_ref‖²_W, the shortest step and the distance since (see
    // [`STALLED_ITERATIONS`]).
    let mut stalled = 0;
    let mut met_step = f64::INFINITY;
    let mut met_distance = f64::INFINITY;
    for iteration in 0..settings.max_iterations {
        if std::mem::take(&mut chord) {
            // `gs_trial` holds the rows at the accepted point, now `z`. With an empty null
            // space there is nothing to pull back: stationary is g = 0 up to the step
            // tolerance, which −J⁻¹·g with the previous J shows as well as with the new one
            // (their difference is of the order of the step times |g|).
            let met = max_abs(&ws.gs_trial);
            if met <= inner_tol && ws.gs_trial.len() == lu.order() {
                lu.step(&ws.gs_trial, &mut ws.soc);
                if max_abs(&ws.soc) <= settings.step_tolerance * (1.0 + max_abs(&ws.z)) {
                    ws.square = lu;
                    return Ok(NewtonRun {
                        iterations: iteration,
                        max_residual: met,
                        stationary: true,
                    });
                }
            }
        }
        match primed.take() {
            Some((_, g)) => {
                problem.budget.charge()?;
                ws.g.copy_from_slice(&g);
            }
            None => ev.linearize(problem, &ws.z, &mut ws.g)?,
        }
        select(&ws.g, rows, &mut ws.gs);
        let gnorm = norm2(&ws.gs);
        last_max = max_abs(&ws.gs);

        // The Gauss–Newton pull-back step: by one LU of J when it is square (no null space to
        // pull back in), else by the minimum-norm factorization, holding unknowns at a bound
        // whose step points outward.
        let mut factorization = if square_step(ev, ws, &mut lu, &weights, reference, rows, options)
        {
            Factors::Square(&mut lu)
        } else {
            Factors::MinNorm(Box::new(min_norm_step(
                ev, ws, &weights, reference, rows, options,
            )?))
        };

        let zmax = max_abs(&ws.z);
        if last_max <= inner_tol && max_abs(&ws.step) <= settings.step_tolerance * (1.0 + zmax) {
            ws.square = lu;
            return Ok(NewtonRun {
                iterations: iteration,
                max_residual: last_max,
                stationary: true,
            });
        }
        // The rows are met and the pull-back steps have stopped shrinking: they are at the
        // rounding floor of the factorization, not converging (see [`STALLED_ITERATIONS`]).
        if last_max <= inner_tol {
            let length = max_abs(&ws.step);
            let here = distance(&ws.z, reference, &weights);
            let still = (here - met_distance).abs() <= STALLED_DISTANCE * here;
            stalled = if length > 0.5 * met_step && still {
                stalled + 1
            } else {
                0
            };
            met_step = met_step.min(length);
            met_distance = here;
            if stalled >= STALLED_ITERATIONS {
                ws.square = lu;
                return Ok(NewtonRun {
                    iterations: iteration,
                    max_residual: last_max,
                    stationary: true,
                });
            }
        } else {
            stalled = 0;
            met_step = f64::INFINITY;
            met_distance = f64::INFINITY;
        }

        // The second-order step with the multipliers of the previous iteration, taken only at
        // full length (or with its second-order correction). After a refusal it is tried again
        // once the Gauss–Newton steps have shrunk fourfold: far from the solution its model is
        // poor, and each attempt costs a Hessian and a conjugate-gradient solve.
        let gn_length = max_abs(&ws.step);
        // With as many independent rows as free unknowns (a square component, the classic
        // sketch), J·Δ = −g fixes Δ alone: the null space is empty, the second-order step is
        // the Gauss–Newton step, and its Hessian and solve would be spent for nothing.
        let held = ws.drop.iter().filter(|d| **d).count();
        let null_space = n.saturating_sub(held).saturating_sub(used_rows) > 0;
        if let (true, Factors::MinNorm(min_norm)) = (
            null_space
                && iteration > 0
                && gn_length <= second_order_gate
                && ws.lambda.iter().any(|l| *l != 0.0),
            &mut factorization,
        ) {
            spread(&ws.lambda, rows, &mut ws.lambda_full);
            if let Some(h) = ev.hessian(problem, &ws.z, &ws.lambda_full)? {
                let data = QpData {
                    weights: &weights,
                    hessian: Some(&h),
                    gradient: &ws.c,
                    residuals: &ws.gs,
                    held: &ws.drop,
                    start: Start::Reuse,
                    tolerance: CG_TOLERANCE,
                };
                let outcome = projected_cg::solve(
                    min_norm,
                    &data,
                    &mut ws.cg,
                    &mut ws.step2,
                    &mut ws.lambda2,
                )?;
                if outcome != CgOutcome::NegativeCurvature {
                    h.mul_vec(&ws.step2, &mut ws.p2)?;
                    let bend = dot(&ws.step2, &ws.p2);
                    std::mem::swap(&mut ws.step, &mut ws.step2);
                    merit.raise_penalty(&ws.z, &ws.step, bend, gnorm, &ws.lambda2);
                    let taken = merit.search(
                        problem,
                        ev,
                        ws,
                        &mut Factors::Borrowed(min_norm),
                        gnorm,
                        SearchLength::FullOnly,
                    )?;
                    if taken.is_some() {
                        std::mem::swap(&mut ws.lambda, &mut ws.lambda2);
                        std::mem::swap(&mut ws.z, &mut ws.z_trial);
                        continue;
                    }
                    std::mem::swap(&mut ws.step, &mut ws.step2);
                }
                second_order_gate = 0.25 * gn_length;
            }
        }

        merit.raise_penalty(&ws.z, &ws.step, 0.0, gnorm, &ws.lambda_gn);
        let taken = merit.search(
            problem,
            ev,
            ws,
            &mut factorization,
            gnorm,
            SearchLength::Backtrack,
        )?;
        let Some(alpha) = taken else {
            // No progress possible: a solution counts if the residuals are already met.
            if last_max <= inner_tol {
                ws.square = lu;
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
        };
        // λ moves with the accepted fraction of the step.
        for (l, t) in ws.lambda.iter_mut().zip(&ws.lambda_gn) {
            *l += alpha * (t - *l);
        }
        std::mem::swap(&mut ws.z, &mut ws.z_trial);
        chord = matches!(factorization, Factors::Square(_));
    }
    ws.square = lu;
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

/// The factorization a Newton iteration solves its steps with.
enum Factors<'a> {
    /// Of J·W⁻¹·Jᵀ: the weighted minimum-norm steps (boxed: the square variant is a
    /// reference).
    MinNorm(Box<MinNormFactorization>),
    /// The same, borrowed.
    Borrowed(&'a mut MinNormFactorization),
    /// The LU of a square J: the steps −J⁻¹·g.
    Square(&'a mut SquareFactors),
}

impl Factors<'_> {
    /// Δz = −J⁺·g (−J⁻¹·g when J is square).
    fn solve(&mut self, g: &[f64], dz: &mut [f64]) -> Result<()> {
        match self {
            Factors::MinNorm(f) => f.solve(g, dz),
            Factors::Borrowed(f) => f.solve(g, dz),
            Factors::Square(lu) => {
                crate::model::errors::check_len("right-hand side", lu.order(), g.len())?;
                crate::model::errors::check_len("step", lu.order(), dz.len())?;
                lu.step(g, dz);
                Ok(())
            }
        }
    }
}

/// Whether unknown k sits at a bound that the step pushes it through.
fn outward(ev: &Evaluator, z: &[f64], step: &[f64], k: usize) -> bool {
    (z[k] <= ev.lower[k] && step[k] < 0.0) || (z[k] >= ev.upper[k] && step[k] > 0.0)
}

/// The Gauss–Newton step of a square J (the rows used as many as the unknowns) by one LU of J
/// into `lu`, dense within the dense size ([`crate::linalg::square`]) and sparse above it
/// ([`crate::linalg::sparse_lu`]): Δ = −J⁻¹·g into `ws.step`, its multipliers λ = −J⁻ᵀ·(W·Δ + c) into
/// `ws.lambda_gn`. `false`, leaving the step to [`min_norm_step`], when J is not square, the
/// LU finds it singular, or the step pushes an unknown through a bound (which the
/// minimum-norm path holds there).
fn square_step(
    ev: &Evaluator,
    ws: &mut NewtonWorkspace,
    lu: &mut SquareFactors,
    weights: &[f64],
    reference: &[f64],
    rows: Option<&[usize]>,
    options: &Options,
) -> bool {
    let n = ev.cols();
    if ws.gs.len() != n {
        return false;
    }
    if !lu.refactorize(
        n,
        ev.triplets(),
        ev.rows(),
        rows,
        options.dense_max_unknowns,
    ) {
        return false;
    }
    lu.step(&ws.gs, &mut ws.step);
    if (0..n).any(|k| outward(ev, &ws.z, &ws.step, k)) {
        return false;
    }
    ws.drop.fill(false);
    for k in 0..n {
        ws.c[k] = weights[k] * (ws.z[k] - reference[k]);
        ws.p2[k] = weights[k] * ws.step[k] + ws.c[k];
    }
    lu.solve_transpose(&ws.p2, &mut ws.lambda_gn);
    for l in &mut ws.lambda_gn {
        *l = -*l;
    }
    true
}

/// The Gauss–Newton pull-back step d − J⁺·(g + J·d) by the minimum-norm factorization and
/// projected conjugate gradients, into `ws.step` with its multipliers in `ws.lambda_gn`,
/// holding unknowns at a bound whose step points outward (their columns dropped, `ws.drop`).
fn min_norm_step(
    ev: &mut Evaluator,
    ws: &mut NewtonWorkspace,
    weights: &[f64],
    reference: &[f64],
    rows: Option<&[usize]>,
    options: &Options,
) -> Result<MinNormFactorization> {
    let n = ev.cols();
    ws.drop.fill(false);
    let mut pass = 0;
    loop {
        for (k, ck) in ws.c.iter_mut().enumerate() {
            *ck = if ws.drop[k] {
                0.0
            } else {
                weights[k] * (ws.z[k] - reference[k])
            };
        }
        let full = ev.jacobian(&ws.drop)?;
        let j = match rows {
            Some(rows) => full.select_rows(rows),
            None => full,
        };
        let mut factorization = MinNormFactorization::try_auto_cached(
            &j,
            weights,
            options.dense_max_unknowns,
            &mut ws.normal,
        )?;
        let data = QpData {
            weights,
            hessian: None,
            gradient: &ws.c,
            residuals: &ws.gs,
            held: &ws.drop,
            start: Start::Compute,
            tolerance: CG_TOLERANCE,
        };
        projected_cg::solve(
            &mut factorization,
            &data,
            &mut ws.cg,
            &mut ws.step,
            &mut ws.lambda_gn,
        )?;
        let mut changed = false;
        for k in 0..n {
            if outward(ev, &ws.z, &ws.step, k) && !ws.drop[k] {
                ws.drop[k] = true;
                changed = true;
            }
        }
        pass += 1;
        if !changed || pass > 3 {
            return Ok(factorization);
        }
    }
}

/// Second-order corrections tried on a refused full step (chord iterations toward g = 0).
const MAX_CORRECTIONS: usize = 3;

/// How far a merit search may cut the step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum SearchLength {
    /// The full step or its second-order correction, nothing shorter.
    FullOnly,
    /// Halving down to 2⁻⁴⁰.
    Backtrack,
}

/// The exact-penalty merit φ(z) = ½‖z − z_ref‖²_W + μ‖g(z)‖₂.
struct Merit<'a> {
    reference: &'a [f64],
    weights: &'a [f64],
    /// The rows g counts (all when None).
    rows: Option<&'a [usize]>,
    mu: f64,
    inner_tol: f64,
}

impl Merit<'_> {
    fn at(&self, z: &[f64], gs: &[f64]) -> f64 {
        distance(z, self.reference, self.weights) + self.mu * norm2(gs)
    }

    /// ∇(½‖z − z_ref‖²_W)·Δ.
    fn slope(&self, z: &[f64], step: &[f64]) -> f64 {
        z.iter()
            .zip(self.reference)
            .zip(self.weights.iter().zip(step))
            .map(|((a, b), (w, s))| w * (a - b) * s)
            .sum()
    }

    /// Raises μ so that the step (which meets J·Δ = −g) descends on φ with room to spare:
    /// μ ≥ (∇fᵀΔ + ½·max(ΔᵀKΔ, 0))/(½‖g‖) with K = W + H, `bend` = ΔᵀHΔ (Nocedal & Wright
    /// 18.36), and μ above the multipliers' Euclidean norm, where the penalty is exact.
    fn raise_penalty(&mut self, z: &[f64], step: &[f64], bend: f64, gnorm: f64, lambda: &[f64]) {
        let quad: f64 = self
            .weights
            .iter()
            .zip(step)
            .map(|(w, s)| w * s * s)
            .sum::<f64>()
            + bend;
        if gnorm > 0.0 {
            let needed = (self.slope(z, step) + 0.5 * quad.max(0.0)) / (0.5 * gnorm);
            if self.mu < needed {
                self.mu = 1.5 * needed;
            }
        }
        let lambda_norm = norm2(lambda);
        if self.mu < lambda_norm {
            self.mu = 1.5 * lambda_norm;
        }
    }

    /// Searches along `ws.step` (slope ∇fᵀΔ − μ‖g‖), with one second-order correction
    /// −J⁺·g(z + Δz) when the full step is refused: the accepted fraction (1 for the corrected
    /// point), with the trial point left in `ws.z_trial`, or `None`.
    fn search(
        &self,
        problem: &Problem,
        ev: &mut Evaluator,
        ws: &mut NewtonWorkspace,
        factorization: &mut Factors<'_>,
        gnorm: f64,
        length: SearchLength,
    ) -> Result<Option<f64>> {
        let rows = self.rows;
        let dphi = self.slope(&ws.z, &ws.step) - self.mu * gnorm;
        let d0 = distance(&ws.z, self.reference, self.weights);
        let phi0 = d0 + self.mu * gnorm;
        let mut alpha = 1.0;
        for attempt in 0..40 {
            for ((t, z), s) in ws.z_trial.iter_mut().zip(&ws.z).zip(&ws.step) {
                *t = z + alpha * s;
            }
            ev.clamp(&mut ws.z_trial);
            let phi = match ev.residuals(problem, &ws.z_trial, &mut ws.g_trial) {
                Ok(()) => {
                    select(&ws.g_trial, rows, &mut ws.gs_trial);
                    self.at(&ws.z_trial, &ws.gs_trial)
                }
                Err(_) => f64::INFINITY,
            };
            // Once g is met, rounding in φ can hide the small pull-back gains: a trial that
            // keeps g met and does not move away from the reference is taken too.
            let feasible = phi.is_finite()
                && max_abs(&ws.gs_trial) <= self.inner_tol
                && distance(&ws.z_trial, self.reference, self.weights) <= d0;
            if phi <= phi0 + 1e-4 * alpha * dphi || feasible {
                return Ok(Some(alpha));
            }
            if attempt == 0 && phi.is_finite() {
                // Second-order corrections: remove what the curvature added to g, with the
                // factorization at z (a chord iteration), while they keep halving ‖g‖.
                ws.p2.copy_from_slice(&ws.z_trial);
                let mut last = norm2(&ws.gs_trial);
                for _ in 0..MAX_CORRECTIONS {
                    factorization.solve(&ws.gs_trial, &mut ws.soc)?;
                    for (p, d) in ws.p2.iter_mut().zip(&ws.soc) {
                        *p += d;
                    }
                    ev.clamp(&mut ws.p2);
                    if ev.residuals(problem, &ws.p2, &mut ws.g_trial).is_err() {
                        break;
                    }
                    select(&ws.g_trial, rows, &mut ws.gs_trial);
                    if self.at(&ws.p2, &ws.gs_trial) <= phi0 + 1e-4 * dphi {
                        std::mem::swap(&mut ws.z_trial, &mut ws.p2);
                        return Ok(Some(1.0));
                    }
                    let now = norm2(&ws.gs_trial);
                    if now.is_nan() || now >= 0.5 * last {
                        break;
                    }
                    last = now;
                }
            }
            if length == SearchLength::FullOnly {
                return Ok(None);
            }
            alpha *= 0.5;
        }
        Ok(None)
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}
