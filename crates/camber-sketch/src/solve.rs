//! Solving a sketch component by component, atomically: every component to solve is built and
//! solved on its own problem, the tangent orientations are checked, and only when all of them
//! succeed are the results written back. On any error the sketch is exactly as before.
//!
//! An affine component takes the linear path; any other goes to [`camber_solve::solve()`]
//! (selection by the DOF analysis). Contacts are then checked on the solved entities; a
//! crossing adds a clearance row on its side of the contact, a cusp the floor on the contact's
//! tangent speed ([`crate::clearance`]), and the component is solved again from the sketch's
//! state, up to [`MAX_ACTIVE_ROWS`] rows.

use camber_solve::{solve_linear, ConstraintId, DofAnalysis, SolveReport};

use crate::active::ActiveRow;
use crate::build::{Component, ComponentProblem};

use crate::entity::Entity;
use crate::errors::Result;
use crate::ids::EntityId;
use crate::sketch::Sketch;

/// Components with rows × unknowns up to this many get the dense rank analysis anyway when the
/// sparse factorization finds dependent rows (so that redundant rows are dropped and
/// conflicting constraints named); above it the solver's rank error is returned as it is.
pub const NAMING_ANALYSIS_MAX_ENTRIES: usize = 1 << 22;

/// The solver options a [`Sketch`] uses by default: camber-solve's defaults, except that the
/// dense rank analysis runs up front only for components of at most 2¹⁶ Jacobian entries
/// (larger components go straight to the sparse factorization and are analysed only if it
/// fails, see [`NAMING_ANALYSIS_MAX_ENTRIES`]).
pub fn default_options() -> camber_solve::Options {
    camber_solve::Options::default().with_dense_analysis_max_entries(1 << 16)
}

/// A solved component: its problem, the solver's report and the solved entities.
type Solved = (ComponentProblem, SolveReport, Vec<(EntityId, Entity)>);

/// Active rows (clearances of contacts that crossed, speed floors of contacts that collapsed or
/// started reversed) added per component solve before giving up.
pub const MAX_ACTIVE_ROWS: usize = 4;

/// How far (length units) a solved curve may lie past the line or circle it touches before the
/// contact counts as crossed: 100 × the solve tolerance, at least 1e-9.
pub fn penetration_tolerance(options: &camber_solve::Options) -> f64 {
    (100.0 * options.tolerance).max(1e-9)
}

/// The outcome of one component's solve.
#[derive(Debug, Clone, PartialEq)]
pub struct ComponentReport {
    /// The component.
    pub component: Component,
    /// The solver's report (status, rank, DOF, redundant constraints, residuals, time).
    pub report: SolveReport,
}

/// The outcome of [`Sketch::solve`]: one report per component solved.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SketchReport {
    /// Components that were solved (components without constraints are skipped).
    pub components: Vec<ComponentReport>,
}

/// The DOF analysis of one component at the current state.
#[derive(Debug, Clone, PartialEq)]
pub struct ComponentAnalysis {
    /// The component.
    pub component: Component,
    /// Free unknowns, rank, DOF, redundant and conflicting constraints.
    pub analysis: DofAnalysis,
}

impl ComponentProblem {
    /// Solves on the linear path and checks the tangent orientations; the problem (not the
    /// sketch) holds the result.
    pub(crate) fn solve(&mut self, options: &camber_solve::Options) -> Result<SolveReport> {
        if self.nonlinear.is_some() {
            let mut report = camber_solve::solve(&mut self.problem, options)?;
            self.check_orientations(self.problem.values())?;
            self.name_merged_redundant(&mut report.redundant);
            return Ok(report);
        }
        let report = match solve_linear(&mut self.problem, options) {
            Err(camber_solve::Error::RankDeficient { .. })
                if self.problem.num_rows() * self.problem.num_unknowns()
                    <= NAMING_ANALYSIS_MAX_ENTRIES =>
            {
                // The fast path skipped the dense analysis and met dependent rows: run it now
                // to drop redundant rows or name the conflicting constraints.
                let full = options
                    .clone()
                    .with_dense_analysis_max_entries(NAMING_ANALYSIS_MAX_ENTRIES);
                solve_linear(&mut self.problem, &full)?
            }
            other => other?,
        };
        self.check_orientations(self.problem.values())?;
        let mut report = report;
        self.name_merged_redundant(&mut report.redundant);
        Ok(report)
    }

    /// Solves by Newton alone (no fallback), from the problem's values toward them; checks the
    /// tangent orientations.
    pub(crate) fn solve_newton_only(
        &mut self,
        options: &camber_solve::Options,
    ) -> Result<SolveReport> {
        let report = camber_solve::solve_newton(&mut self.problem, options)?;
        self.check_orientations(self.problem.values())?;
        Ok(report)
    }

    /// Solves from the reduced point `z` (a previous solution) with the pull-back toward
    /// `reference` (the start) by Newton, falling back to the full selection from the problem's
    /// own values; checks the tangent orientations.
    pub(crate) fn solve_from(
        &mut self,
        options: &camber_solve::Options,
        z: &[f64],
        reference: &[f64],
    ) -> Result<SolveReport> {
        let mut ws = camber_solve::NewtonWorkspace::new();
        let report = match camber_solve::solve_newton_from(
            &mut self.problem,
            options,
            &mut ws,
            z,
            reference,
        ) {
            Ok(r) => r,
            Err(_) => camber_solve::solve(&mut self.problem, options)?,
        };
        self.check_orientations(self.problem.values())?;
        Ok(report)
    }

    /// Adds the constraints whose coincidence joined points already merged (module `merge`)
    /// to a list of redundant constraints (sorted, without repeats).
    pub(crate) fn name_merged_redundant(&self, redundant: &mut Vec<ConstraintId>) {
        redundant.extend(self.merged_redundant.iter().copied());
        redundant.sort_unstable();
        redundant.dedup();
    }
}

/// # Solving
impl Sketch {
    /// Solves the components that contain an entity changed since the last solve.
    ///
    /// # Errors
    /// The first failing component's error ([`crate::Error::Conflicting`],
    /// [`crate::Error::NotSatisfied`], [`crate::Error::OrientationFlipped`],
    /// [`crate::Error::ContactCrossed`], [`crate::Error::Cusp`], …); the sketch is unchanged
    /// then.
    pub fn solve(&mut self) -> Result<SketchReport> {
        let comps: Vec<Component> = self
            .components()
            .into_iter()
            .filter(|c| self.is_dirty(c))
            .collect();
        self.solve_components(comps)
    }

    /// Solves every component, dirty or not.
    ///
    /// # Errors
    /// As [`Sketch::solve`].
    pub fn solve_all(&mut self) -> Result<SketchReport> {
        let comps = self.components();
        self.solve_components(comps)
    }

    fn solve_components(&mut self, comps: Vec<Component>) -> Result<SketchReport> {
        let mut updates = Vec::new();
        let mut clean = Vec::new();
        let mut report = SketchReport::default();
        let mut contacts = Vec::new();
        for comp in comps {
            clean.extend(comp.entities.iter().copied());
            if comp.constraints.is_empty() {
                continue;
            }
            let (cp, r, solved) = self.solve_component(&comp)?;
            contacts.extend(cp.contacts_at(cp.problem().values())?);
            updates.extend(solved);
            report.components.push(ComponentReport {
                component: comp,
                report: r,
            });
        }
        self.commit(updates, &clean);
        self.store_contacts(&contacts);
        Ok(report)
    }

    /// Solves one component from the sketch's state and runs the contact checks, treating the
    /// inequalities of honest contact as an active set ([`crate::clearance`]):
    ///
    /// - a failed check adds the row that answers it: a crossing the clearance on its side of
    ///   the contact (the curve touches the target there, at a free second point, instead of
    ///   crossing it), a cusp the floor on the contact's tangent speed; the solve restarts from
    ///   the sketch's state;
    /// - when a contact's tangent points the wrong way at the start, the first solve is Newton
    ///   alone (or the solver the options force); if it fails, the floors of those contacts are
    ///   added and the solve restarts, and if that fails too, the selection runs without them;
    /// - when every check passes, an active row whose multiplier says it does not bind is
    ///   dropped and the solve resumes from the current solution toward the same start.
    ///
    /// At most [`MAX_ACTIVE_ROWS`] rows are added (besides the predicted floors) and a row once
    /// dropped is not added again, so the loop ends.
    fn solve_component(&self, comp: &Component) -> Result<Solved> {
        let forced = self.options().nonlinear.force.is_some();
        let mut predicted: Option<Vec<ActiveRow>> = None;
        let (mut floors_on, mut plain_fallback) = (false, false);
        let mut rows: Vec<ActiveRow> = Vec::new();
        let mut dropped: Vec<ActiveRow> = Vec::new();
        let mut added = 0;
        let mut warm: Option<Vec<f64>> = None;
        loop {
            let mut cp = self.build_component(comp, None)?;
            let first = predicted.is_none();
            let reversed = match &predicted {
                Some(p) => p.clone(),
                None => cp.reversed_contacts(self)?,
            };
            predicted = Some(reversed.clone());
            let mut live = Vec::with_capacity(rows.len());
            for row in &rows {
                if cp.add_active_row(self, *row)? {
                    live.push(*row);
                }
            }
            rows = live;
            let z_start = cp.problem().reduced_map()?.z0().to_vec();
            let newton_only = first && !forced && cp.nonlinear.is_some() && !reversed.is_empty();
            let solved = match warm.take() {
                Some(z) => cp.solve_from(self.options(), &z, &z_start),
                None if newton_only => cp.solve_newton_only(self.options()),
                None => cp.solve(self.options()),
            };
            let mut r = match solved {
                Ok(r) => r,
                Err(e) => {
                    if !floors_on && !plain_fallback && !reversed.is_empty() {
                        // The plain solve failed on a start with reversed contacts: their floors.
                        floors_on = true;
                        for row in reversed {
                            if !rows.contains(&row) {
                                rows.push(row);
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
            let x = cp.problem().values();
            let solved = cp.entities_at(self, x)?;
            let e = match cp.check_contacts(&solved, x, penetration_tolerance(self.options())) {
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
                        warm = Some(cp.problem().reduced_map()?.z0().to_vec());
                        continue;
                    }
                    if !rows.is_empty() || !dropped.is_empty() {
                        r.reason = format!(
                            "{}; with {} active row(s) of honest contact ({} dropped as slack)",
                            r.reason,
                            rows.len(),
                            dropped.len()
                        );
                    }
                    return Ok((cp, r, solved));
                }
                Err(e) => e,
            };
            match cp.active_row_for(&e, x)? {
                Some(row)
                    if added < MAX_ACTIVE_ROWS
                        && !rows.contains(&row)
                        && !dropped.contains(&row) =>
                {
                    rows.push(row);
                    added += 1;
                }
                _ => return Err(e),
            }
        }
    }

    /// The DOF analysis of every component (components without constraints included: their
    /// DOF is their number of unknowns).
    ///
    /// # Errors
    /// Errors of building the problems.
    pub fn analyze(&self) -> Result<Vec<ComponentAnalysis>> {
        let mut out = Vec::new();
        for comp in self.components() {
            let cp = self.build_component(&comp, None)?;
            let mut analysis = cp.problem().analyze(self.options())?;
            cp.name_merged_redundant(&mut analysis.redundant);
            out.push(ComponentAnalysis {
                component: comp,
                analysis,
            });
        }
        Ok(out)
    }
}
