//! A component's solve: camber-solve's policy ([`camber_solve::Plan`], kept with the
//! component), then the checks of the solved geometry, and the active set of honest contact
//! around them. Used by [`crate::Sketch::solve`] and by drag sessions.
//!
//! 1. **Path.** The component's plan decides (linear minimum norm for an affine component;
//!    Newton minimum norm, SLSQP within its limits or least squares from the DOF analysis
//!    otherwise; priority tiers when the whole set cannot be met). A warm start (a drag) asks
//!    it for Newton from the previous solution with the pull-back toward it first.
//! 2. **Checks.** Tangent orientations, then every [`crate::constraints::check::SolvedCheck`]
//!    on the solved entities (contacts keep their side and travel direction, no cusp).
//! 3. **Active set of honest contact** ([`crate::residuals::clearance`]): a crossing adds the
//!    clearance row on its side of the contact, a cusp the floor on the contact's tangent speed,
//!    and the component is solved again from its start; a start whose contact tangents point
//!    the wrong way asks the plan for Newton alone first, then with their floors, then the
//!    plain selection; when every check passes, an active row whose multiplier says it does
//!    not bind is dropped and the solve resumes from the current solution. The rows are
//!    appended to the problem and taken back ([`camber_solve::Problem::truncate_residuals`]);
//!    the problem is never rebuilt. At most [`MAX_ACTIVE_ROWS`] rows are added (besides the
//!    predicted floors) and a row once dropped is not added again, so the loop ends.
//!
//! On success the problem holds the solution; on any error it holds its starting values. Either
//! way it ends with the rows it started with.

use camber_solve::{Options, SolveReport, SolverChoice, Start};

use crate::component::contact::ActiveRow;
use crate::component::problem::ComponentProblem;
use crate::ground::entity::Entity;
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;

/// Active rows (clearances of contacts that crossed, speed floors of contacts that collapsed or
/// started reversed) added per component solve before giving up.
pub const MAX_ACTIVE_ROWS: usize = 4;

/// The solver options a [`crate::Sketch`] uses by default: camber-solve's defaults, except that
/// the rank analysis runs up front only for components of at most 2¹⁶ Jacobian entries
/// (larger components go straight to the sparse factorization and are analysed, sparsely, only
/// if it meets dependent rows).
pub fn default_options() -> Options {
    Options::default().with_dense_analysis_max_entries(1 << 16)
}

/// How far (length units) a solved curve may lie past the line or circle it touches before the
/// contact counts as crossed: 100 × the solve tolerance, at least 1e-9.
pub fn penetration_tolerance(options: &Options) -> f64 {
    (100.0 * options.tolerance).max(1e-9)
}

impl ComponentProblem {
    /// One solve by the component's plan from `start`, with the tangent orientations checked;
    /// the problem holds the result.
    pub(crate) fn solve_once(&mut self, options: &Options, start: &Start) -> Result<SolveReport> {
        let mut report = self.plan.solve(&mut self.problem, options, start)?;
        self.check_orientations(self.problem.values())?;
        self.name_merged_redundant(&mut report.redundant);
        Ok(report)
    }

    /// Adds the constraints whose coincidence joined points already merged to a list of
    /// redundant constraints (sorted, without repeats).
    pub(crate) fn name_merged_redundant(
        &self,
        redundant: &mut Vec<crate::ground::ids::ConstraintId>,
    ) {
        redundant.extend(self.merged_redundant.iter().copied());
        redundant.sort_unstable();
        redundant.dedup();
    }
}

/// Solves a built component by the policy of the module documentation: `before` holds the
/// entities as they are before the solve (the problem's starting values), `start` says where
/// Newton begins. Returns the report; the problem holds the solution
/// ([`ComponentProblem::entities_at`] reads the solved entities from it).
///
/// # Errors
/// The first failure that no active row answers ([`crate::Error::Conflicting`],
/// [`crate::Error::NotSatisfied`], [`crate::Error::OrientationFlipped`],
/// [`crate::Error::ContactCrossed`], [`crate::Error::Cusp`], …); the problem is back at its
/// starting values then.
pub(crate) fn solve(
    cp: &mut ComponentProblem,
    before: &dyn EntityLookup,
    options: &Options,
    start: Start,
) -> Result<SolveReport> {
    let mut initial = std::mem::take(&mut cp.saved);
    cp.problem.save_state(&mut initial);
    let base_rows = cp.problem.num_residuals();
    let outcome = active_set(cp, before, options, start, base_rows, &initial);
    let active = cp.problem.num_residuals().saturating_sub(base_rows);
    // The active rows are taken back either way: they belong to this solve only.
    cp.problem.truncate_residuals(base_rows);
    let outcome = match outcome {
        Ok(report) if active > 0 => equality_dof(cp, options, report),
        other => other,
    };
    if outcome.is_err() {
        cp.problem.restore(&initial);
    }
    cp.saved = initial;
    outcome
}

/// The report's rank and DOF counted on the constraints' own rows at the solution. The active
/// rows of honest contact are inequalities (the curve on its side of the target): binding, they
/// keep the solution on one side of a boundary but take no dimension from the set of solutions,
/// and the solver, which saw them as rows, counted them in its rank. `camber check` and
/// [`crate::Sketch::analyze`] count without them, and so does the report now.
fn equality_dof(
    cp: &ComponentProblem,
    options: &Options,
    mut report: SolveReport,
) -> Result<SolveReport> {
    let analysis = cp.problem.analyze(options)?;
    report.rank = analysis.rank;
    report.dof = analysis.dof;
    Ok(report)
}

fn active_set(
    cp: &mut ComponentProblem,
    before: &dyn EntityLookup,
    options: &Options,
    start: Start,
    base_rows: usize,
    initial: &camber_solve::ProblemState,
) -> Result<SolveReport> {
    let forced = options.nonlinear.force.is_some();
    let reversed = cp.reversed_contacts(before)?;
    let (mut floors_on, mut plain_fallback) = (false, false);
    let mut rows: Vec<ActiveRow> = Vec::new();
    let mut dropped: Vec<ActiveRow> = Vec::new();
    let mut added = 0;
    let (mut warm, reference) = match start {
        Start::Warm { from, toward } => (Some(from), Some(toward)),
        _ => (None, None),
    };
    let mut first = true;
    loop {
        cp.problem.truncate_residuals(base_rows);
        cp.problem.restore(initial);
        let mut live = Vec::with_capacity(rows.len());
        for row in &rows {
            if cp.add_active_row(before, *row)? {
                live.push(*row);
            }
        }
        rows = live;
        // The start in reduced unknowns is read only by the multipliers of active rows: the
        // reduced map is not built for it when there are none (the common case).
        let z_start = match &reference {
            Some(z) => z.clone(),
            None if rows.is_empty() => Vec::new(),
            None => cp.problem.reduced_map()?.z0().to_vec(),
        };
        let newton_only =
            first && warm.is_none() && !forced && cp.nonlinear.is_some() && !reversed.is_empty();
        first = false;
        let solved = match warm.take() {
            Some(z) => cp.solve_once(
                options,
                &Start::Warm {
                    from: z,
                    toward: z_start.clone(),
                },
            ),
            None if newton_only => cp.solve_once(
                &options.clone().with_force(Some(SolverChoice::Newton)),
                &Start::Cold,
            ),
            None => cp.solve_once(options, &Start::Cold),
        };
        let mut report = match solved {
            Ok(r) => r,
            Err(e) => {
                if !floors_on && !plain_fallback && !reversed.is_empty() {
                    // The plain solve failed on a start with reversed contacts: their floors.
                    floors_on = true;
                    for row in &reversed {
                        if !rows.contains(row) {
                            rows.push(*row);
                        }
                    }
                    continue;
                }
                if floors_on && !plain_fallback {
                    // The floors did not help: the full selection without them.
                    plain_fallback = true;
                    rows.retain(|row| !reversed.contains(row));
                    continue;
                }
                return Err(e);
            }
        };
        // The solved values and entities are read only by the checks of the solved state (and
        // the active row a failed check asks for).
        let (x, solved): (Vec<f64>, Vec<(EntityId, Entity)>) = if cp.checks.is_empty() {
            (Vec::new(), Vec::new())
        } else {
            let x = cp.problem.values().to_vec();
            let solved = cp.entities_at(before, &x)?;
            (x, solved)
        };
        let failure = match cp.check_solved(before, &solved, &x, penetration_tolerance(options)) {
            Ok(()) => {
                let mu = if rows.is_empty() {
                    Vec::new()
                } else {
                    cp.active_multipliers(&z_start, rows.len())?
                };
                let scale = 1e-8 * mu.iter().fold(1.0_f64, |m, v| m.max(v.abs()));
                let slack = mu
                    .iter()
                    .enumerate()
                    .filter(|(_, v)| **v < -scale)
                    .min_by(|a, b| a.1.total_cmp(b.1));
                if let Some((k, _)) = slack {
                    dropped.push(rows.remove(k));
                    warm = Some(cp.plan.last_solution().to_vec());
                    continue;
                }
                if !rows.is_empty() || !dropped.is_empty() {
                    report.reason = format!(
                        "{}; with {} active row(s) of honest contact ({} dropped as slack)",
                        report.reason,
                        rows.len(),
                        dropped.len()
                    );
                }
                return Ok(report);
            }
            Err(e) => e,
        };
        match cp.active_row_for(&failure, &x, &solved, before)? {
            Some(row)
                if added < MAX_ACTIVE_ROWS && !rows.contains(&row) && !dropped.contains(&row) =>
            {
                rows.push(row);
                added += 1;
            }
            _ => return Err(failure),
        }
    }
}
