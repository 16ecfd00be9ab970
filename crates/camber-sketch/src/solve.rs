//! Solving a sketch component by component, atomically: every component to solve is built and
//! solved on its own problem, the tangent orientations are checked, and only when all of them
//! succeed are the results written back. On any error the sketch is exactly as before.

use camber_solve::{solve_linear, DofAnalysis, SolveReport};

use crate::build::{Component, ComponentProblem};
use crate::errors::Result;
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
        Ok(report)
    }
}

/// # Solving
impl Sketch {
    /// Solves the components that contain an entity changed since the last solve.
    ///
    /// # Errors
    /// The first failing component's error ([`crate::Error::Conflicting`],
    /// [`crate::Error::NotSatisfied`], [`crate::Error::OrientationFlipped`],
    /// [`crate::Error::NeedsNonlinear`], …); the sketch is unchanged then.
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
        for comp in comps {
            clean.extend(comp.entities.iter().copied());
            if comp.constraints.is_empty() {
                continue;
            }
            let mut cp = self.build_component(&comp, None)?;
            let r = cp.solve(self.options())?;
            let x = cp.problem().values();
            updates.extend(cp.entities_at(self, x)?);
            report.components.push(ComponentReport {
                component: comp,
                report: r,
            });
        }
        self.commit(updates, &clean);
        Ok(report)
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
            let analysis = cp.problem().analyze(self.options())?;
            out.push(ComponentAnalysis {
                component: comp,
                analysis,
            });
        }
        Ok(out)
    }
}
