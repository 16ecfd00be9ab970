//! The one solve policy of a component, used by [`crate::Sketch::solve`] and by drag sessions
//! on nonlinear components.
//!
//! 1. **Path.** An affine component takes the linear minimum-norm path; any other goes to
//!    [`camber_solve::solve()`], whose selection runs from the DOF analysis (Newton minimum
//!    norm, SLSQP within its limits, least squares). A warm start (a drag) first tries Newton
//!    from the previous solution with the pull-back toward it, then that selection.
//! 2. **Checks.** Tangent orientations, then every [`crate::constraints::check::SolvedCheck`] on the solved
//!    entities (contacts keep their side and travel direction, no cusp).
//! 3. **Active set of honest contact** ([`crate::residuals::clearance`]): a crossing adds the
//!    clearance row on its side of the contact, a cusp the floor on the contact's tangent speed,
//!    and the component is solved again from its start; a start whose contact tangents point
//!    the wrong way tries Newton alone first, then with their floors, then the plain selection;
//!    when every check passes, an active row whose multiplier says it does not bind is dropped
//!    and the solve resumes from the current solution. The rows are appended to the problem
//!    and taken back ([`camber_solve::Problem::truncate_residuals`]); the problem is never
//!    rebuilt. At most [`MAX_ACTIVE_ROWS`] rows are added (besides the predicted floors) and a
//!    row once dropped is not added again, so the loop ends.
//!
//! On success the problem holds the solution; on any error it holds its starting values. Either
//! way it ends with the rows it started with.

use camber_solve::{solve_linear, NewtonWorkspace, Options, SolveReport};

use super::contact::ActiveRow;
use super::problem::ComponentProblem;
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

/// Where a solve starts.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Start {
    /// From the problem's values, with the selection of the DOF analysis.
    Cold,
    /// Newton from `from` (reduced unknowns, a previous solution) pulling toward `toward`,
    /// with the selection as fallback (drag updates).
    Warm { from: Vec<f64>, toward: Vec<f64> },
}

impl ComponentProblem {
    /// One solve on the path the component calls for, with the tangent orientations checked;
    /// the problem holds the result.
    pub(crate) fn solve_once(&mut self, options: &Options) -> Result<SolveReport> {
        // Priorities need the selection's fallback to the tiers, affine or not.
        let report = if self.nonlinear.is_some() || self.problem.has_priorities() {
            camber_solve::solve(&mut self.problem, options)?
        } else {
            match solve_linear(&mut self.problem, options) {
                Err(camber_solve::Error::RankDeficient { .. }) => {
                    // The fast path skipped the analysis and met dependent rows: run it now
                    // (sparse at this size) to drop redundant rows or name the conflicting
                    // constraints.
                    let full = options.clone().with_dense_analysis_max_entries(usize::MAX);
                    solve_linear(&mut self.problem, &full)?
                }
                other => other?,
            }
        };
        self.check_orientations(self.problem.values())?;
        let mut report = report;
        self.name_merged_redundant(&mut report.redundant);
        Ok(report)
    }

    /// Newton alone (no fallback), from the problem's values toward them.
    fn solve_newton_only(&mut self, options: &Options) -> Result<SolveReport> {
        let report = camber_solve::solve_newton(&mut self.problem, options)?;
        self.check_orientations(self.problem.values())?;
        Ok(report)
    }

    /// Newton from the reduced point `from` pulling toward `toward`, then the selection from
    /// the problem's own values if it fails.
    fn solve_warm(
        &mut self,
        options: &Options,
        from: &[f64],
        toward: &[f64],
    ) -> Result<SolveReport> {
        let mut ws = NewtonWorkspace::new();
        let report = match camber_solve::solve_newton_from(
            &mut self.problem,
            options,
            &mut ws,
            from,
            toward,
        ) {
            Ok(r) => r,
            Err(_) => camber_solve::solve(&mut self.problem, options)?,
        };
        self.check_orientations(self.problem.values())?;
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
/// Newton begins. Returns the report and the solved entities; the problem holds the solution.
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
) -> Result<(SolveReport, Vec<(EntityId, Entity)>)> {
    let initial = cp.problem.state();
    let base_rows = cp.problem.num_residuals();
    let outcome = active_set(cp, before, options, start, base_rows, &initial);
    let active = cp.problem.num_residuals().saturating_sub(base_rows);
    // The active rows are taken back either way: they belong to this solve only.
    cp.problem.truncate_residuals(base_rows);
    let outcome = match outcome {
        Ok((report, solved)) if active > 0 => {
            equality_dof(cp, options, report).map(|report| (report, solved))
        }
        other => other,
    };
    if outcome.is_err() {
        cp.problem.restore(&initial);
    }
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
) -> Result<(SolveReport, Vec<(EntityId, Entity)>)> {
    let forced = options.nonlinear.force.is_some();
    let reversed = cp.reversed_contacts(before)?;
    let (mut floors_on, mut plain_fallback) = (false, false);
    let mut rows: Vec<ActiveRow> = Vec::new();
    let mut dropped: Vec<ActiveRow> = Vec::new();
    let mut added = 0;
    let (mut warm, reference) = match start {
        Start::Cold => (None, None),
        Start::Warm { from, toward } => (Some(from), Some(toward)),
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
            Some(z) => cp.solve_warm(options, &z, &z_start),
            None if newton_only => cp.solve_newton_only(options),
            None => cp.solve_once(options),
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
        let x = cp.problem.values().to_vec();
        let solved = cp.entities_at(before, &x)?;
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
                    warm = Some(cp.problem.reduced_map()?.z0().to_vec());
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
                return Ok((report, solved));
            }
            Err(e) => e,
        };
        match cp.active_row_for(&failure, &x)? {
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
