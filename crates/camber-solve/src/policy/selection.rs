//! The solve entry: DOF analysis, choice of the solver, validation and write-back.
//!
//! [`solve`] looks at the problem at its current values and picks a path:
//! - all residuals affine: conflicting rows → [`Error::Conflicting`] (or the soft mode when
//!   [`crate::model::nonlinear::NonlinearOptions::soft`] is set); otherwise the linear minimum-norm step
//!   ([`crate::solve_linear`]);
//! - nonlinear with J of full row rank at the start (or only consistent dependent rows, which
//!   are left out): Newton minimum-norm ([`crate::solvers::newton`]); if it fails, SLSQP;
//! - nonlinear and rank deficient at the start: SLSQP (the `slsqp` module, `nlopt` feature);
//! - when those fail (or SLSQP is not built): Levenberg–Marquardt on the least-squares sum from
//!   the start, then Newton from its answer with the pull-back toward the start;
//! - when nothing meets every constraint: the soft compromise if asked; otherwise
//!   [`Error::Conflicting`] naming the constraints left above tolerance when the
//!   least-squares search ended at a least-squares point (g orthogonal to the range of J:
//!   no step reduces every residual, so they conflict there), and [`Error::NotSolved`] with
//!   each constraint's residual when it stopped short of one (nothing proves a conflict).
//!
//! Every candidate is re-evaluated before anything is written: all residuals within
//! `options.tolerance` and all bounds held, or the problem keeps its values. The report's
//! `reason` tells which path ran and why.

use std::time::Instant;

use crate::analysis::certificate::certainly_full_row_rank;
use crate::analysis::{self, DofAnalysis};
use crate::linalg::evaluator::{norm2, Evaluator};
use crate::model::errors::{Error, Result};
use crate::model::ids::ConstraintId;
use crate::model::nonlinear::SolverChoice;
use crate::model::options::Options;
use crate::model::problem::Problem;
use crate::model::report::{ConstraintResidual, Selection, SolveReport, SolverKind, Status};
use crate::policy::linear::LinearPath;
use crate::policy::plan::{Plan, Start};
use crate::solvers::newton::{self, NewtonWorkspace};
use crate::solvers::soft;

/// What the analysis at the start says, carried into every report.
#[derive(Debug, Clone)]
struct Verdict {
    clock: Instant,
    z0: Vec<f64>,
    rows: usize,
    rank: usize,
    dof: usize,
    redundant: Vec<ConstraintId>,
    /// Dependent and inconsistent rows of the linearization at the start.
    conflicting: Vec<ConstraintId>,
    /// Independent rows when only consistent dependent rows exist (and may be dropped).
    independent: Option<Vec<usize>>,
    /// A maximal independent set of rows at the start (when the analysis ran): what SLSQP
    /// gets when the rows outnumber the unknowns.
    basis: Option<Vec<usize>>,
    affine: bool,
    full_rank: bool,
}

impl Verdict {
    /// The analysis at the problem's values, whether they already satisfy every residual,
    /// and the evaluator with its linearization there (map, residuals, Jacobian), which Newton
    /// takes over as its first iteration's instead of building and evaluating them again.
    fn new(
        problem: &Problem,
        options: &Options,
        ev: &mut Evaluator,
    ) -> Result<(Self, bool, Primed)> {
        let clock = Instant::now();
        options.validate()?;
        options.nonlinear.validate()?;
        let (m, n) = (ev.rows(), ev.cols());
        let z0 = ev.map.z0().to_vec();
        let mut g = vec![0.0; m];
        // Not charged: Newton charges it as its first iteration's.
        ev.linearize_for_report(problem, &z0, &mut g)?;
        let affine = problem.residuals.iter().all(|rb| rb.residual.is_affine());
        let dense_analysis = m.saturating_mul(n) <= options.dense_analysis_max_entries;
        // Every row independent by the analysis' own test: its answer is known (rank m,
        // nothing redundant or conflicting) without the singular values.
        let certified = dense_analysis
            && m > 0
            && m <= n
            && m.saturating_mul(n) <= analysis::DENSE_ANALYSIS_MAX_ENTRIES
            && certainly_full_row_rank(&ev.dense_jacobian(), options.rank_tolerance);
        let analysis: Option<DofAnalysis> = if dense_analysis && !certified {
            Some(analysis::analyze(
                &problem.linearize()?,
                options.rank_tolerance,
                options.tolerance,
            )?)
        } else {
            None
        };
        let satisfied = g.iter().all(|v| v.abs() <= options.tolerance);
        let pending = ev
            .expanded()
            .iter()
            .zip(problem.values())
            .any(|(a, b)| (a - b).abs() > 0.0);
        let start = match analysis {
            Some(a) => Self {
                full_rank: a.rank == m,
                independent: (a.conflicting.is_empty()
                    && !a.rows.dependent.is_empty()
                    && options.drop_redundant)
                    .then(|| a.rows.independent.clone()),
                basis: Some(a.rows.independent.clone()),
                rank: a.rank,
                dof: a.dof,
                redundant: a.redundant,
                conflicting: a.conflicting,
                clock,
                z0: z0.clone(),
                rows: m,
                affine,
            },
            None => Self {
                clock,
                z0: z0.clone(),
                rows: m,
                rank: m.min(n),
                dof: n.saturating_sub(m),
                redundant: Vec::new(),
                conflicting: Vec::new(),
                independent: None,
                basis: certified.then(|| (0..m).collect()),
                affine,
                full_rank: true,
            },
        };
        Ok((start, satisfied && !pending, Primed { z: z0, g }))
    }

    fn report(
        &self,
        solver: SolverKind,
        selection: Selection,
        reason: String,
        iterations: usize,
        residuals: Vec<ConstraintResidual>,
        z: &[f64],
    ) -> SolveReport {
        let moved: Vec<f64> = z.iter().zip(&self.z0).map(|(a, b)| a - b).collect();
        SolveReport {
            status: Status::Solved,
            solver,
            selection,
            reason,
            iterations,
            residuals,
            displacement_norm: norm2(&moved),
            rank: self.rank,
            dof: self.dof,
            redundant: self.redundant.clone(),
            conflicting: Vec::new(),
            priorities: Vec::new(),
            elapsed: self.clock.elapsed(),
        }
    }

    fn already_satisfied(&self, problem: &Problem) -> Result<SolveReport> {
        let ev = Evaluator::new(problem)?;
        let mut g = vec![0.0; ev.rows()];
        problem.evaluate_at(problem.values(), &mut g)?;
        let mut r = self.report(
            SolverKind::None,
            Selection::AlreadySatisfied,
            "every residual is already within tolerance".to_owned(),
            0,
            ev.per_constraint(&g),
            &self.z0,
        );
        r.status = Status::AlreadySatisfied;
        Ok(r)
    }
}

/// The point `z` at which the solve's evaluator was just linearized, with the residuals `g`
/// there: Newton's first iteration takes them over.
struct Primed {
    z: Vec<f64>,
    g: Vec<f64>,
}

/// Re-evaluates every residual at z and writes z back only if all are within tolerance and
/// every bound holds.
fn commit(
    problem: &mut Problem,
    ev: &mut Evaluator,
    z: &[f64],
    options: &Options,
) -> Result<Vec<ConstraintResidual>> {
    let mut g = vec![0.0; ev.rows()];
    ev.residuals(problem, z, &mut g)?;
    let residuals = ev.per_constraint(&g);
    let failed: Vec<_> = residuals
        .iter()
        .filter(|r| r.max_abs > options.tolerance || r.max_abs.is_nan())
        .map(|r| (r.constraint, r.max_abs))
        .collect();
    if !failed.is_empty() {
        return Err(Error::NotSatisfied { failed });
    }
    problem.apply_reduced(&ev.map, z)?;
    Ok(residuals)
}

/// Newton from `start` toward `reference`, validated and written back. `ev` holds the map of
/// the problem as it is (the solve's evaluator); when it was just linearized at `start`,
/// `primed` says so.
#[allow(clippy::too_many_arguments)] // the parts of one solve, each a different thing
fn newton_path(
    problem: &mut Problem,
    options: &Options,
    ws: &mut NewtonWorkspace,
    ev: &mut Evaluator,
    start: &[f64],
    reference: &[f64],
    rows: Option<&[usize]>,
    primed: Option<Primed>,
) -> Result<(usize, bool, Vec<ConstraintResidual>, Vec<f64>)> {
    if let Some(p) = primed {
        ws.prime(p.z, p.g);
    }
    let run = newton::run(problem, ev, ws, start, reference, rows, options);
    ws.unprime();
    let run = run?;
    let residuals = commit(problem, ev, &ws.z, options)?;
    Ok((run.iterations, run.stationary, residuals, ws.z.clone()))
}

/// SLSQP from `start` toward `reference`, validated and written back. When the rows
/// outnumber the unknowns SLSQP gets the independent `basis` rows only (NLopt's SLSQP takes at
/// most as many equality rows as unknowns); without a basis it is not called
/// ([`Error::OutsideSolverLimits`]).
#[cfg(feature = "nlopt")]
fn slsqp_path(
    problem: &mut Problem,
    options: &Options,
    start: &[f64],
    reference: &[f64],
    basis: Option<&[usize]>,
) -> Result<(
    crate::solvers::slsqp::SlsqpRun,
    Vec<ConstraintResidual>,
    Vec<f64>,
)> {
    let mut ev = Evaluator::new(problem)?;
    let rows = basis.filter(|_| ev.rows() > ev.cols());
    let (z, run) = crate::solvers::slsqp::run(problem, &mut ev, start, reference, rows, options)?;
    let residuals = commit(problem, &mut ev, &z, options).map_err(|e| match e {
        Error::NotSatisfied { failed } if run.state.contains("Fail") => Error::OptimizerFailed {
            solver: "SLSQP",
            detail: format!(
                "{} with constraints not satisfied: {}",
                run.state,
                failed
                    .iter()
                    .map(|(c, g)| format!("{c} (max |g| = {g:.3e})"))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        },
        e => e,
    })?;
    Ok((run, residuals, z))
}

#[cfg(not(feature = "nlopt"))]
fn slsqp_path(
    _: &mut Problem,
    _: &Options,
    _: &[f64],
    _: &[f64],
    _: Option<&[usize]>,
) -> Result<(SlsqpInfo, Vec<ConstraintResidual>, Vec<f64>)> {
    Err(Error::SolverUnavailable {
        solver: "SLSQP",
        reason: "camber-solve was built without the `nlopt` feature",
    })
}

/// Stand-in for the SLSQP run record when the feature is off (never constructed).
#[cfg(not(feature = "nlopt"))]
#[derive(Debug)]
struct SlsqpInfo {
    evaluations: usize,
    state: String,
}

/// Runs the soft least-squares mode and writes its answer back (bounds permitting).
fn soft_path(
    problem: &mut Problem,
    options: &Options,
    start: &Verdict,
    why: &str,
) -> Result<SolveReport> {
    let mut ev = Evaluator::new(problem)?;
    let (z, run) = soft::run(
        problem,
        &mut ev,
        &start.z0,
        &start.z0,
        options.nonlinear.soft_epsilon,
        options.nonlinear.max_iterations,
    )?;
    let mut g = vec![0.0; ev.rows()];
    ev.residuals(problem, &z, &mut g)?;
    let residuals = ev.per_constraint(&g);
    let unsatisfied: Vec<ConstraintId> = residuals
        .iter()
        .filter(|r| r.max_abs > options.tolerance || r.max_abs.is_nan())
        .map(|r| r.constraint)
        .collect();
    problem.apply_reduced(&ev.map, &z)?;
    let mut report = start.report(
        SolverKind::LevenbergMarquardt,
        Selection::Soft,
        format!(
            "{why}; soft mode: least squares Σg² + ε‖z − z₀‖²_W (ε = {}), cost {:.3e}",
            options.nonlinear.soft_epsilon, run.cost
        ),
        run.iterations,
        residuals,
        &z,
    );
    if !unsatisfied.is_empty() {
        report.status = Status::Relaxed;
        report.conflicting = unsatisfied;
    }
    Ok(report)
}

/// Solves a problem by the path its DOF analysis selects (see the module documentation), or by
/// the solver forced in [`crate::model::nonlinear::NonlinearOptions::force`].
///
/// ```
/// use camber_solve::{solve, ConstraintId, Options, Problem, Residual, Scalar, SolverKind};
/// use camber_solve::scalar::cst;
///
/// /// |p|² = 1: the point lies on the unit circle.
/// #[derive(Debug)]
/// struct OnUnitCircle;
/// impl Residual for OnUnitCircle {
///     fn name(&self) -> &str { "on unit circle" }
///     fn dim(&self) -> usize { 1 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
///         out[0] = x[0][0] * x[0][0] + x[0][1] * x[0][1] - cst(1.0);
///     }
/// }
///
/// let mut p = Problem::new();
/// let b = p.add_block(&[3.0, 4.0])?;
/// p.add_residual(OnUnitCircle, &[b], ConstraintId(1))?;
/// let report = solve(&mut p, &Options::default())?;
/// assert_eq!(report.solver, SolverKind::Newton);
/// // The nearest point of the circle: (3, 4)/5.
/// assert!((p.values()[0] - 0.6).abs() < 1e-10 && (p.values()[1] - 0.8).abs() < 1e-10);
/// # Ok::<(), camber_solve::Error>(())
/// ```
///
/// When the whole set cannot be met ([`Error::Conflicting`] or [`Error::NotSolved`]) and some
/// constraints have a priority above 0 ([`Problem::set_priority`]), the tiers are met in order
/// instead, each as well as the tiers before it allow (lexicographic least squares); the report then
/// has [`Status::Relaxed`] and names the relaxed constraints. Not with a forced solver or the
/// soft mode, which answer for the whole set.
///
/// # Errors
/// [`Error::Conflicting`] naming the constraints that cannot be met together (without soft
/// mode; with priorities, the required ones); [`Error::SolverUnavailable`] when a forced solver
/// is not built; the errors of the forced solver otherwise. The problem's values are unchanged
/// on every error.
pub fn solve(problem: &mut Problem, options: &Options) -> Result<SolveReport> {
    let mut plan = Plan::one_off();
    let outcome = plan.solve(problem, options, &Start::Cold);
    plan.release();
    outcome
}

/// The selection from the analysis at the problem's values, for a problem that is not affine
/// (or a forced solver): Newton, SLSQP, the rescue paths (see the module documentation).
pub(crate) fn cold(
    problem: &mut Problem,
    options: &Options,
    ws: &mut NewtonWorkspace,
    ev: &mut Evaluator,
    linear: &mut LinearPath,
) -> Result<SolveReport> {
    let (start, satisfied, primed) = Verdict::new(problem, options, ev)?;
    if satisfied {
        return start.already_satisfied(problem);
    }
    if let Some(choice) = options.nonlinear.force {
        return forced(problem, options, &start, choice, ws, ev, linear);
    }
    if start.affine {
        if !start.conflicting.is_empty() {
            if options.nonlinear.soft {
                return soft_path(problem, options, &start, "affine and conflicting");
            }
            return Err(Error::Conflicting {
                constraints: start.conflicting.clone(),
            });
        }
        return linear.solve(problem, options);
    }

    let mut notes: Vec<String> = Vec::new();
    if start.full_rank || start.independent.is_some() {
        let rows = start.independent.as_deref();
        match newton_path(
            problem,
            options,
            ws,
            ev,
            &start.z0,
            &start.z0,
            rows,
            Some(primed),
        ) {
            Ok((iterations, stationary, residuals, z)) => {
                let reason =
                    format!(
                    "nonlinear, J of rank {} with {} rows at the start{} → Newton minimum norm{}",
                    start.rank,
                    start.rows,
                    if rows.is_some() { " (consistent dependent rows left out)" } else { "" },
                    if stationary { "" } else { " (pull-back not fully converged)" }
                );
                let selection = if rows.is_some() {
                    Selection::DependentRowsLeftOut
                } else {
                    Selection::FullRank
                };
                return Ok(start.report(
                    SolverKind::Newton,
                    selection,
                    reason,
                    iterations,
                    residuals,
                    &z,
                ));
            }
            Err(e) => notes.push(format!("Newton failed ({e})")),
        }
    } else {
        notes.push(format!(
            "nonlinear, J rank deficient at the start (rank {} of {} rows)",
            start.rank, start.rows
        ));
    }
    match slsqp_path(
        problem,
        options,
        &start.z0,
        &start.z0,
        start.basis.as_deref(),
    ) {
        Ok((run, residuals, z)) => {
            let reason = format!(
                "{} → SLSQP ({}, {} evaluations)",
                notes.join("; "),
                run.state,
                run.evaluations
            );
            let selection = if notes.iter().any(|n| n.starts_with("Newton failed")) {
                Selection::Fallback
            } else {
                Selection::RankDeficient
            };
            return Ok(start.report(
                SolverKind::Slsqp,
                selection,
                reason,
                run.evaluations,
                residuals,
                &z,
            ));
        }
        Err(e) => notes.push(format!("SLSQP failed ({e})")),
    }

    // Rescue: least squares from the start, then Newton from there toward the start.
    let (z_lm, lm) = soft::run(
        problem,
        ev,
        &start.z0,
        &start.z0,
        options.nonlinear.soft_epsilon,
        options.nonlinear.max_iterations,
    )?;
    if lm.max_residual <= options.tolerance.sqrt() {
        if let Ok((iterations, _, residuals, z)) =
            newton_path(problem, options, ws, ev, &z_lm, &start.z0, None, None)
        {
            let reason = format!(
                "{} → Levenberg–Marquardt ({} iterations) then Newton minimum norm",
                notes.join("; "),
                lm.iterations
            );
            return Ok(start.report(
                SolverKind::Newton,
                Selection::Fallback,
                reason,
                lm.iterations + iterations,
                residuals,
                &z,
            ));
        }
        // Newton could not polish it (J singular there, say): the least-squares point itself
        // is kept when it meets every constraint (validated by `commit`).
        if lm.max_residual <= options.tolerance {
            let mut ev_lm = Evaluator::new(problem)?;
            if let Ok(residuals) = commit(problem, &mut ev_lm, &z_lm, options) {
                let reason = format!(
                    "{} → Levenberg–Marquardt ({} iterations), constraints met",
                    notes.join("; "),
                    lm.iterations
                );
                return Ok(start.report(
                    SolverKind::LevenbergMarquardt,
                    Selection::Fallback,
                    reason,
                    lm.iterations,
                    residuals,
                    &z_lm,
                ));
            }
        }
    }
    // A singular start (J rank deficient on a nonlinear problem) may be a symmetric point
    // that no method leaves (x = 0 where two curves touch by design): once more by Newton
    // from a start moved slightly along the independent rows, toward the start.
    if !start.full_rank && !problem.budget.exhausted() {
        if let Some(basis) = start.basis.as_deref() {
            let mut ev_moved = Evaluator::new(problem)?;
            let moved = match crate::analysis::accidental::moved_along(
                problem,
                &mut ev_moved,
                &start.z0,
                basis,
                options,
            ) {
                Err(Error::BudgetSpent { .. }) => None,
                moved => moved?,
            };
            if let Some(z1) = moved {
                if let Ok((iterations, _, residuals, z)) =
                    newton_path(problem, options, ws, ev, &z1, &start.z0, None, None)
                {
                    let reason = format!(
                        "{} → Newton minimum norm from a start moved off the singular one",
                        notes.join("; ")
                    );
                    return Ok(start.report(
                        SolverKind::Newton,
                        Selection::Fallback,
                        reason,
                        lm.iterations + iterations,
                        residuals,
                        &z,
                    ));
                }
            }
        }
    }
    if options.nonlinear.soft {
        return soft_path(problem, options, &start, &notes.join("; "));
    }
    let mut g = vec![0.0; ev.rows()];
    ev.linearize_for_report(problem, &z_lm, &mut g)?;
    let residuals = ev.per_constraint(&g);
    if !start.conflicting.is_empty() || at_least_squares_point(&ev.jacobian(&[])?, &g)? {
        let mut named = start.conflicting.clone();
        for r in &residuals {
            if (r.max_abs > options.tolerance || r.max_abs.is_nan())
                && !named.contains(&r.constraint)
            {
                named.push(r.constraint);
            }
        }
        return Err(Error::Conflicting { constraints: named });
    }
    let budget = match problem.budget.limit() {
        Some(limit) if problem.budget.exhausted() => {
            format!(" (the budget of {limit} evaluations is spent)")
        }
        _ => String::new(),
    };
    Err(Error::NotSolved {
        best_effort: z_lm,
        tried: format!(
            "{} → Levenberg–Marquardt ({} iterations) stopped short of a least-squares point{budget}",
            notes.join("; "),
            lm.iterations
        ),
        residuals,
    })
}

/// Whether g is (numerically) orthogonal to the range of J: the point is stationary for ‖g‖²
/// (Jᵀg = 0) while g ≠ 0, so no step, however small, reduces every residual: the constraints
/// conflict there. The test is relative, ‖Jᵀg‖ ≤ [`LEAST_SQUARES_COSINE`]·‖J‖_F·‖g‖: the
/// cosine between g and its best approximation from the range of J.
fn at_least_squares_point(j: &crate::linalg::sparse::SparseMatrix, g: &[f64]) -> Result<bool> {
    let mut jtg = vec![0.0; j.ncols()];
    let mut frobenius = 0.0;
    for (i, gi) in g.iter().enumerate() {
        let (cols, vals) = j.row(i);
        for (c, v) in cols.iter().zip(vals) {
            jtg[*c] += v * gi;
            frobenius += v * v;
        }
    }
    let (gradient, g_norm) = (norm2(&jtg), norm2(g));
    Ok(g_norm > 0.0 && gradient <= LEAST_SQUARES_COSINE * frobenius.sqrt() * g_norm)
}

/// See [`at_least_squares_point`].
const LEAST_SQUARES_COSINE: f64 = 1e-6;

/// Runs the forced solver.
fn forced(
    problem: &mut Problem,
    options: &Options,
    start: &Verdict,
    choice: SolverChoice,
    ws: &mut NewtonWorkspace,
    ev: &mut Evaluator,
    linear: &mut LinearPath,
) -> Result<SolveReport> {
    let why = format!("forced {choice:?}");
    match choice {
        SolverChoice::Linear => {
            let mut report = linear.solve(problem, options)?;
            report.selection = Selection::Forced;
            report.reason = format!("{why}; {}", report.reason);
            Ok(report)
        }
        SolverChoice::Newton => {
            let (iterations, _, residuals, z) =
                newton_path(problem, options, ws, ev, &start.z0, &start.z0, None, None)?;
            Ok(start.report(
                SolverKind::Newton,
                Selection::Forced,
                why,
                iterations,
                residuals,
                &z,
            ))
        }
        SolverChoice::Slsqp => {
            let (run, residuals, z) = slsqp_path(
                problem,
                options,
                &start.z0,
                &start.z0,
                start.basis.as_deref(),
            )?;
            let reason = format!("{why} ({}, {} evaluations)", run.state, run.evaluations);
            Ok(start.report(
                SolverKind::Slsqp,
                Selection::Forced,
                reason,
                run.evaluations,
                residuals,
                &z,
            ))
        }
        SolverChoice::Soft => soft_path(problem, options, start, &why),
    }
}

/// The soft compromise for an affine problem the linear path found conflicting: the analysis
/// at the start, then the soft mode.
pub(crate) fn soft_for_affine(
    problem: &mut Problem,
    options: &Options,
    ev: &mut Evaluator,
) -> Result<SolveReport> {
    let (start, _, _) = Verdict::new(problem, options, ev)?;
    soft_path(problem, options, &start, "affine and conflicting")
}

/// Newton from `start` toward `reference` (reduced unknowns) with no analysis first: the warm
/// path of drags and re-solves. The report's rank and DOF are those of the rows and unknowns.
pub(crate) fn warm_newton(
    problem: &mut Problem,
    options: &Options,
    ws: &mut NewtonWorkspace,
    ev: &mut Evaluator,
    start: &[f64],
    reference: &[f64],
) -> Result<SolveReport> {
    let clock = Instant::now();
    let z0 = ev.map.z0().to_vec();
    let (iterations, stationary, residuals, z) =
        newton_path(problem, options, ws, ev, start, reference, None, None)?;
    let moved: Vec<f64> = z.iter().zip(&z0).map(|(a, b)| a - b).collect();
    let n = z.len();
    Ok(SolveReport {
        status: Status::Solved,
        solver: SolverKind::Newton,
        selection: Selection::WarmStart,
        reason: format!(
            "warm-started Newton minimum norm{}",
            if stationary {
                ""
            } else {
                " (pull-back not fully converged)"
            }
        ),
        iterations,
        residuals,
        displacement_norm: norm2(&moved),
        rank: problem.num_rows().min(n),
        dof: n.saturating_sub(problem.num_rows()),
        redundant: Vec::new(),
        conflicting: Vec::new(),
        priorities: Vec::new(),
        elapsed: clock.elapsed(),
    })
}

/// Newton minimum norm from the current values, with the pull-back toward them; validated
/// and written back (the null-space pull-back of docs/solver.md).
///
/// # Errors
/// [`Error::RankDeficient`], [`Error::NotConverged`], [`Error::NotSatisfied`],
/// [`Error::OutOfBounds`]; the problem is unchanged on error.
pub fn solve_newton(problem: &mut Problem, options: &Options) -> Result<SolveReport> {
    let opts = options.clone().with_force(Some(SolverChoice::Newton));
    solve(problem, &opts)
}

/// Warm-started Newton for drag sessions: iterates from `start` (e.g. the previous step's
/// solution) with the pull-back toward `reference` (where the unknowns should stay if they
/// can), both over the reduced unknowns in the order of [`crate::ReducedMap::vars`]; the
/// workspace's buffers are reused from call to call. No analysis runs first. The result is
/// validated and written back like every solve.
///
/// ```
/// use camber_solve::{solve_newton_from, ConstraintId, NewtonWorkspace, Options, Problem};
/// use camber_solve::{Residual, Scalar};
/// #[derive(Debug)]
/// struct OnUnitCircle;
/// impl Residual for OnUnitCircle {
///     fn name(&self) -> &str { "on unit circle" }
///     fn dim(&self) -> usize { 1 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
///         out[0] = x[0][0] * x[0][0] + x[0][1] * x[0][1] - T::one();
///     }
/// }
/// let mut p = Problem::new();
/// let b = p.add_block(&[1.0, 0.0])?;
/// p.add_residual(OnUnitCircle, &[b], ConstraintId(1))?;
/// let mut ws = NewtonWorkspace::new();
/// // Drag toward (1, 1): start from the current solution, pull toward the mouse.
/// solve_newton_from(&mut p, &Options::default(), &mut ws, &[1.0, 0.0], &[1.0, 1.0])?;
/// let h = 0.5_f64.sqrt();
/// assert!((p.values()[0] - h).abs() < 1e-9 && (p.values()[1] - h).abs() < 1e-9);
/// # Ok::<(), camber_solve::Error>(())
/// ```
///
/// # Errors
/// [`Error::Dimension`] for slices of the wrong length, and those of [`solve_newton`].
pub fn solve_newton_from(
    problem: &mut Problem,
    options: &Options,
    workspace: &mut NewtonWorkspace,
    start: &[f64],
    reference: &[f64],
) -> Result<SolveReport> {
    options.validate()?;
    options.nonlinear.validate()?;
    let mut ev = Evaluator::new(problem)?;
    warm_newton(problem, options, workspace, &mut ev, start, reference)
}

#[cfg(test)]
mod tests {
    /// A nonlinear problem: a point (x, y) on the circle of radius `r` about the origin with
    /// x − y = `d`, started at `start`.
    fn circle_and_line(r: f64, d: f64, start: [f64; 2]) -> crate::Problem {
        #[derive(Debug)]
        struct OnCircle(f64);
        impl crate::Residual for OnCircle {
            fn name(&self) -> &str {
                "on circle"
            }
            fn dim(&self) -> usize {
                1
            }
            fn eval<T: crate::Scalar>(&self, x: &[&[T]], out: &mut [T]) {
                let r = crate::model::scalar::cst::<T>(self.0);
                out[0] = x[0][0] * x[0][0] + x[0][1] * x[0][1] - r * r;
            }
        }
        #[derive(Debug)]
        struct Apart(f64);
        impl crate::Residual for Apart {
            fn name(&self) -> &str {
                "apart"
            }
            fn dim(&self) -> usize {
                1
            }
            fn eval<T: crate::Scalar>(&self, x: &[&[T]], out: &mut [T]) {
                out[0] = x[0][0] - x[0][1] - crate::model::scalar::cst::<T>(self.0);
            }
            fn is_affine(&self) -> bool {
                true
            }
        }
        let mut p = crate::Problem::new();
        let b = p.add_block(&start).unwrap();
        p.add_residual(OnCircle(r), &[b], crate::ConstraintId(1))
            .unwrap();
        p.add_residual(Apart(d), &[b], crate::ConstraintId(2))
            .unwrap();
        p
    }

    /// A solve after another problem's (whose Newton workspace it takes over on this thread)
    /// gives bit for bit what it gives first on a fresh thread.
    #[test]
    fn a_reused_workspace_gives_the_same_solve() {
        let options = crate::Options::default();
        let fresh = std::thread::spawn(|| {
            let mut p = circle_and_line(2.0, 0.5, [1.9, 0.3]);
            crate::solve(&mut p, &crate::Options::default()).unwrap();
            p.values().to_vec()
        })
        .join()
        .unwrap();
        let mut other = circle_and_line(5.0, -1.0, [3.0, 3.5]);
        crate::solve(&mut other, &options).unwrap();
        let mut p = circle_and_line(2.0, 0.5, [1.9, 0.3]);
        crate::solve(&mut p, &options).unwrap();
        let again: Vec<u64> = p.values().iter().map(|v| v.to_bits()).collect();
        assert_eq!(again, fresh.iter().map(|v| v.to_bits()).collect::<Vec<_>>());
        let (x, y) = (p.values()[0], p.values()[1]);
        assert!((x * x + y * y - 4.0).abs() < 1e-9 && (x - y - 0.5).abs() < 1e-9);
    }
}
