//! Solving a sketch component by component, atomically: every component to solve is built and
//! solved on its own problem by the one policy of `component::policy`, and only when
//! all of them succeed are the results written back. On any error the sketch is exactly as
//! before.

use camber_solve::SolveReport;

use crate::component::policy::{self, Start};
use crate::component::starts;
use crate::component::Component;
use crate::errors::Result;
use crate::sketch::Sketch;

pub use crate::component::policy::{default_options, penetration_tolerance, MAX_ACTIVE_ROWS};

/// The outcome of one component's solve.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ComponentReport {
    /// The component.
    pub component: Component,
    /// The solver's report (status, rank, DOF, redundant constraints, residuals, time).
    pub report: SolveReport,
}

/// The outcome of [`Sketch::solve`]: one report per component solved, and the warnings about
/// near-degenerate input. Serializes to JSON as `{"components": [{"component": {"entities",
/// "constraints"}, "report": {…}}], "warnings": [{"kind", …, "message"}]}`.
///
/// ```
/// use camber_sketch::constraints::Fixed;
/// use camber_sketch::{PointRef, Sketch};
/// use camber_geom::BezierCurve2;
/// use nalgebra::Point2;
/// let mut s = Sketch::new();
/// let c = s.add_bezier(BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(2.0, 0.0)])?)?;
/// s.add_constraint(Fixed::point(PointRef::Start(c)))?;
/// let report = s.solve()?;
/// let json = serde_json::to_value(&report).map_err(|e| e.to_string()).unwrap();
/// assert_eq!(json["components"][0]["component"]["entities"][0], 0);
/// assert_eq!(json["components"][0]["report"]["status"], "already_satisfied");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
pub struct SketchReport {
    /// Components that were solved (components without constraints are skipped).
    pub components: Vec<ComponentReport>,
    /// Near-degenerate input found in the sketch before the solve ([`Sketch::warnings`]).
    pub warnings: Vec<crate::warnings::Warning>,
    /// The residual tolerance the solve used ([`Sketch::solve_options`]): the options'
    /// tolerance, raised for sketches far from the origin to what double rounding can reach at
    /// their coordinates.
    pub tolerance: f64,
}

/// A component's solve report and the entities it moved, with their new values.
type Solved = (
    SolveReport,
    Vec<(crate::ids::EntityId, crate::entity::Entity)>,
);

impl SketchReport {
    /// The constraints left above tolerance because the whole set could not be met: those of
    /// a priority above 0 that gave way ([`Sketch::set_priority`]), in component order. Empty
    /// when every constraint is met.
    pub fn relaxed(&self) -> Vec<camber_solve::ConstraintId> {
        self.components
            .iter()
            .filter(|c| c.report.status == camber_solve::Status::Relaxed)
            .flat_map(|c| c.report.conflicting.iter().copied())
            .collect()
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

    /// Solves a built component by the policy from the constraints' own contact guesses; when
    /// that fails and the component has free contact parameters, from the other starts of
    /// `component::starts` (the first that solves wins, its report saying which start it took).
    /// The first error stands when none solves.
    fn solve_with_starts(
        &self,
        cp: &mut crate::component::ComponentProblem,
        options: &camber_solve::Options,
    ) -> Result<Solved> {
        // One evaluation budget for the whole attempt: the given start, its active-set rounds
        // and every other start share it, so a sketch that cannot be solved fails in bounded
        // time however many starts it has.
        cp.problem.start_budget(options.nonlinear.max_evaluations);
        let outcome = self.solve_from_each_start(cp, options);
        cp.problem.end_budget();
        outcome
    }

    /// The body of [`Sketch::solve_with_starts`], inside its budget.
    fn solve_from_each_start(
        &self,
        cp: &mut crate::component::ComponentProblem,
        options: &camber_solve::Options,
    ) -> Result<Solved> {
        let first = match policy::solve(cp, self, options, Start::Cold) {
            Ok(solved) => return Ok(solved),
            Err(e) => e,
        };
        let initial = cp.problem.state();
        let others = starts::contact_starts(cp, self)?;
        let count = others.len();
        for (k, start) in others.into_iter().enumerate() {
            if cp.problem.budget_spent() {
                break;
            }
            cp.problem.restore(&initial);
            for (block, u) in &start {
                cp.problem.set_block_values(*block, &[*u])?;
            }
            if let Ok((mut r, solved)) = policy::solve(cp, self, options, Start::Cold) {
                r.reason = format!(
                    "{}; from contact start {} of {} after the given guesses failed",
                    r.reason,
                    k + 1,
                    count
                );
                return Ok((r, solved));
            }
        }
        cp.problem.restore(&initial);
        Err(first)
    }

    fn solve_components(&mut self, comps: Vec<Component>) -> Result<SketchReport> {
        let mut updates = Vec::new();
        let mut clean = Vec::new();
        // The options depend on the largest coordinate of the whole sketch: worked out once per
        // solve, not once per component (which made many components quadratic).
        let options = self.solve_options();
        let mut report = SketchReport {
            warnings: self.warnings(),
            tolerance: options.tolerance,
            ..SketchReport::default()
        };
        let mut free = Vec::new();
        for comp in comps {
            clean.extend(comp.entities.iter().copied());
            if comp.constraints.is_empty() {
                continue;
            }
            let mut cp = self.build_component(&comp, None)?;
            let (r, solved) = self.solve_with_starts(&mut cp, &options)?;
            free.extend(cp.free_at(cp.problem().values())?);
            updates.extend(solved);
            report.components.push(ComponentReport {
                component: comp,
                report: r,
            });
        }
        self.commit(updates, &clean);
        self.store_free(&free);
        Ok(report)
    }
}
