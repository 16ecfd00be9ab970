//! Solving a sketch component by component, atomically: every component to solve is built and
//! solved on its own problem, the tangent orientations are checked, and only when all of them
//! succeed are the results written back. On any error the sketch is exactly as before.
//!
//! An affine component takes the linear path; any other goes to [`camber_solve::solve()`]
//! (selection by the DOF analysis). Contacts are then checked on the solved entities; a
//! crossing is pushed back by one more row and the component solved again from the sketch's
//! state, up to [`MAX_PUSH_BACKS`] times.

use camber_solve::{solve_linear, DofAnalysis, SolveReport};

use crate::build::{Component, ComponentProblem};
use camber_solve::ConstraintId;

use crate::entity::Entity;
use crate::errors::{Error, Result};
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

/// Push-backs of crossing contacts tried per component solve before giving up.
pub const MAX_PUSH_BACKS: usize = 4;

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

    /// Adds the constraints whose coincidence joined points already merged ([`crate::merge`])
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

    /// Solves one component from the sketch's state and runs the contact checks. A contact
    /// that crosses its target is pushed back: the solve restarts from the sketch's state with
    /// one more row putting the deepest crossing point back on the target (the seed's
    /// push-back), at most [`MAX_PUSH_BACKS`] times.
    fn solve_component(&self, comp: &Component) -> Result<Solved> {
        let mut pushed: Vec<(ConstraintId, f64)> = Vec::new();
        loop {
            let mut cp = self.build_component(comp, None)?;
            for (owner, s) in &pushed {
                cp.push_back(self, *owner, *s)?;
            }
            let mut r = cp.solve(self.options())?;
            let x = cp.problem().values();
            let solved = cp.entities_at(self, x)?;
            match cp.check_contacts(&solved, x, penetration_tolerance(self.options())) {
                Ok(()) => {
                    if !pushed.is_empty() {
                        r.reason = format!(
                            "{}; after {} push-back(s) of crossing contacts",
                            r.reason,
                            pushed.len()
                        );
                    }
                    return Ok((cp, r, solved));
                }
                Err(Error::ContactCrossed {
                    constraint,
                    parameter,
                    ..
                }) if pushed.len() < MAX_PUSH_BACKS
                    && !pushed.contains(&(constraint, parameter)) =>
                {
                    pushed.push((constraint, parameter));
                }
                Err(e) => return Err(e),
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
