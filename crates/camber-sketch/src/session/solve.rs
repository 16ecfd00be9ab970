//! Solving a sketch component by component, atomically: every component to solve is built and
//! solved on its own problem (`component::solve`: camber-solve's policy, then the checks of the
//! solved geometry), and only when
//! all of them succeed are the results written back. On any error the sketch is exactly as
//! before.

use camber_solve::SolveReport;

use camber_solve::Start;

use crate::component::solve as policy;
use crate::component::Component;
use crate::ground::errors::Result;
use crate::session::starts;
use crate::sketch::Sketch;

pub use crate::component::solve::{default_options, penetration_tolerance, MAX_ACTIVE_ROWS};

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
    /// Near-degenerate input found before the solve in the components it solved
    /// ([`Sketch::warnings`] of their entities and constraints; all of them for
    /// [`Sketch::solve_all`] or a first solve).
    pub warnings: Vec<crate::sketch::warnings::Warning>,
    /// The residual tolerance the solve used ([`Sketch::solve_options`]): the options'
    /// tolerance, raised for sketches far from the origin to what double rounding can reach at
    /// their coordinates.
    pub tolerance: f64,
}

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
        let comps = self.dirty_components();
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
    ) -> Result<SolveReport> {
        // One evaluation budget for the whole attempt: the given start, its active-set rounds
        // and every other start share it, so a sketch that cannot be solved fails in bounded
        // time however many starts it has.
        cp.problem.set_cancel(options.cancel.clone());
        cp.problem.start_budget(options.nonlinear.max_evaluations);
        let outcome = match self.solve_from_each_start(cp, options) {
            Err(_) if options.cancel.as_ref().is_some_and(|c| c.is_cancelled()) => Err(
                crate::ground::errors::Error::Solve(camber_solve::Error::Cancelled),
            ),
            outcome => outcome,
        };
        cp.problem.end_budget();
        cp.problem.set_cancel(None);
        outcome
    }

    /// The body of [`Sketch::solve_with_starts`], inside its budget.
    fn solve_from_each_start(
        &self,
        cp: &mut crate::component::ComponentProblem,
        options: &camber_solve::Options,
    ) -> Result<SolveReport> {
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
            if let Ok(mut r) = policy::solve(cp, self, options, Start::Cold) {
                r.reason = format!(
                    "{}; from contact start {} of {} after the given guesses failed",
                    r.reason,
                    k + 1,
                    count
                );
                return Ok(r);
            }
        }
        cp.problem.restore(&initial);
        Err(first)
    }

    /// Solves `comps` and, only when every one succeeds, writes all their results back. The
    /// components are independent problems over disjoint entities, so they are built and solved
    /// in parallel when there are enough of them to pay for it ([`solves_in_parallel`]), one
    /// after another otherwise; both ways give the same reports in component order, the same
    /// error (that of the first failing component in component order) and write nothing on an
    /// error.
    fn solve_components(&mut self, comps: Vec<Component>) -> Result<SketchReport> {
        let parallel = solves_in_parallel(&comps);
        self.solve_components_in(comps, parallel)
    }

    /// [`Sketch::solve_components`] with the choice of parallel or sequential solves given.
    fn solve_components_in(
        &mut self,
        comps: Vec<Component>,
        parallel: bool,
    ) -> Result<SketchReport> {
        self.solve_components_with(comps, parallel, &mut |_, _| None)
    }

    /// [`Sketch::solve_components_in`], where a component that this sketch has not prepared
    /// is solved on the problem `donor` gives for it, if any (a problem of the same structure
    /// with this sketch's values and edits: `crate::session::batch`); the others are built.
    pub(crate) fn solve_components_with(
        &mut self,
        comps: Vec<Component>,
        parallel: bool,
        donor: &mut dyn FnMut(&Sketch, &Component) -> Option<crate::component::ComponentProblem>,
    ) -> Result<SketchReport> {
        // The options depend on the largest coordinate of the whole sketch: worked out once per
        // solve, not once per component (which made many components quadratic).
        let options = self.solve_options();
        let mut report = SketchReport {
            warnings: self.warnings_in(
                comps.iter().flat_map(|c| c.entities.iter().copied()),
                comps.iter().flat_map(|c| c.constraints.iter().copied()),
            ),
            tolerance: options.tolerance,
            ..SketchReport::default()
        };
        let clean: Vec<crate::ground::ids::EntityId> = comps
            .iter()
            .flat_map(|c| c.entities.iter().copied())
            .collect();
        let comps: Vec<Component> = comps
            .into_iter()
            .filter(|c| !c.constraints.is_empty())
            .collect();
        // Each component with the problem an earlier solve prepared for it, if any.
        let mut jobs: Vec<Job> = comps
            .into_iter()
            .map(|comp| {
                let prepared = self.prepared.take(&comp);
                (comp, prepared)
            })
            .collect();
        for (comp, prepared) in &mut jobs {
            if prepared.is_none() {
                *prepared = donor(self, comp).map(|cp| (cp, Vec::new()));
            }
        }
        let outcomes = if parallel {
            self.solve_each_in_parallel(jobs, &options)?
        } else {
            jobs.into_iter()
                .map(|job| self.solve_component(job, &options))
                .collect::<Result<Vec<_>>>()?
        };
        let mut updates = Vec::new();
        let mut free = Vec::new();
        let mut kept = Vec::with_capacity(outcomes.len());
        for outcome in outcomes {
            updates.extend(outcome.updates);
            free.extend(outcome.free);
            report.components.push(outcome.report);
            kept.push(outcome.problem);
        }
        self.commit(updates, &clean);
        self.store_free(&free);
        // The solved problems hold exactly the values just written back: kept for the next
        // solve after a dimension edit.
        for cp in kept {
            self.prepared.keep(cp);
        }
        Ok(report)
    }

    /// Solves one component on its prepared problem (its edited constraints' residuals replaced
    /// in place) or on one built now; nothing is written to the sketch.
    fn solve_component(
        &self,
        (comp, prepared): Job,
        options: &camber_solve::Options,
    ) -> Result<ComponentOutcome> {
        let kept = prepared
            .and_then(|(mut cp, edited)| self.replace_edited(&mut cp, &edited).then_some(cp));
        let mut cp = match kept {
            Some(cp) => cp,
            None => self.build_component(&comp)?,
        };
        let r = self.solve_with_starts(&mut cp, options)?;
        let updates = cp.entities_at(self, cp.problem().values())?;
        let free = cp.free_at(cp.problem().values())?;
        Ok(ComponentOutcome {
            report: ComponentReport {
                component: comp,
                report: r,
            },
            updates,
            free,
            problem: cp,
        })
    }

    /// Replaces the residuals of the constraints `edited` (new values) in a prepared problem;
    /// `false` when one cannot be replaced in place (the component is then built again).
    pub(crate) fn replace_edited(
        &self,
        cp: &mut crate::component::ComponentProblem,
        edited: &[crate::ground::ids::ConstraintId],
    ) -> bool {
        edited.iter().all(|id| {
            self.constraint(*id)
                .and_then(|c| c.compile(self))
                .and_then(|pieces| cp.replace_pieces(*id, &pieces))
                .unwrap_or(false)
        })
    }

    /// [`Sketch::solve_component`] for every component on rayon's pool, the outcomes in
    /// component order. The error is that of the first failing component in component order,
    /// as one after another: a component after a known failure is skipped (its outcome could
    /// not be used), one before it always runs.
    fn solve_each_in_parallel(
        &self,
        comps: Vec<Job>,
        options: &camber_solve::Options,
    ) -> Result<Vec<ComponentOutcome>> {
        use rayon::prelude::*;
        use std::sync::atomic::{AtomicUsize, Ordering};
        let first_failure = AtomicUsize::new(usize::MAX);
        let outcomes: Vec<Option<Result<ComponentOutcome>>> = comps
            .into_par_iter()
            .enumerate()
            .map(|(k, comp)| {
                if k > first_failure.load(Ordering::Relaxed) {
                    return None;
                }
                let outcome = self.solve_component(comp, options);
                if outcome.is_err() {
                    first_failure.fetch_min(k, Ordering::Relaxed);
                }
                Some(outcome)
            })
            .collect();
        // Every component before the first failure ran, so the first error met in order is
        // that failure; skipped components all come after it.
        outcomes.into_iter().flatten().collect()
    }
}

/// A component to solve, with the problem an earlier solve prepared for it and the constraints
/// of it whose value changed since.
type Job = (
    Component,
    Option<(
        crate::component::ComponentProblem,
        Vec<crate::ground::ids::ConstraintId>,
    )>,
);

/// One solved component, not yet written: its report, the entities it moved with their new
/// values, the free parameters (constraint, index, value) to store, and its problem (kept).
#[derive(Debug)]
struct ComponentOutcome {
    problem: crate::component::ComponentProblem,
    report: ComponentReport,
    updates: Vec<(crate::ground::ids::EntityId, crate::ground::entity::Entity)>,
    free: Vec<(camber_solve::ConstraintId, usize, f64)>,
}

/// Fewer constraints than this in all the components to solve are solved one after another.
/// The caller waits while rayon's pool does the work, so a parallel solve costs the wake-up
/// of the pool's threads: tens of microseconds on an idle machine, but a scheduler slice
/// (milliseconds) when other processes hold the cores. 512 constraints of small components
/// take about a millisecond one after another (W5 with 47 rectangles), where the threads
/// surely pay; an interactive solve, one or two small dirty components, never waits for them.
const PARALLEL_MIN_CONSTRAINTS: usize = 512;

/// Whether the components are solved on rayon's pool: more than one component, more than one
/// thread to run on, and at least [`PARALLEL_MIN_CONSTRAINTS`] constraints in all.
pub(crate) fn solves_in_parallel(comps: &[Component]) -> bool {
    comps.iter().filter(|c| !c.constraints.is_empty()).count() > 1
        && comps.iter().map(|c| c.constraints.len()).sum::<usize>() >= PARALLEL_MIN_CONSTRAINTS
        && rayon::current_num_threads() > 1
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use crate::constraints::{Coincident, Distance, Fixed, Horizontal, Vertical};
    use crate::file::to_json;
    use crate::{EntityId, PointRef};
    use nalgebra::Point2;

    /// `n` perturbed rectangles, each a component of four lines held by coincident corners,
    /// horizontals, verticals, two side lengths and a fixed corner. Rectangle k's width is
    /// 2 + k mod 3; those in `conflicting` get a second width that contradicts the first.
    fn rectangles(n: usize, conflicting: &[usize]) -> Sketch {
        let mut s = Sketch::new();
        for k in 0..n {
            let (x, y) = (10.0 * k as f64, 0.0);
            let wobble = |i: usize| 0.05 * (((k * 7 + i * 3) % 11) as f64 / 11.0 - 0.5);
            let corners = [
                Point2::new(x + wobble(0), y + wobble(1)),
                Point2::new(x + 2.0 + wobble(2), y + wobble(3)),
                Point2::new(x + 2.0 + wobble(4), y + 1.0 + wobble(5)),
                Point2::new(x + wobble(6), y + 1.0 + wobble(7)),
            ];
            let lines: Vec<EntityId> = (0..4)
                .map(|i| s.add_line(corners[i], corners[(i + 1) % 4]).unwrap())
                .collect();
            for i in 0..4 {
                s.add_constraint(Coincident {
                    a: PointRef::End(lines[i]),
                    b: PointRef::Start(lines[(i + 1) % 4]),
                })
                .unwrap();
            }
            s.add_constraint(Horizontal::line(lines[0])).unwrap();
            s.add_constraint(Horizontal::line(lines[2])).unwrap();
            s.add_constraint(Vertical::line(lines[1])).unwrap();
            s.add_constraint(Vertical::line(lines[3])).unwrap();
            let width = 2.0 + (k % 3) as f64;
            let side = |line: EntityId, distance: f64| Distance {
                a: PointRef::Start(line),
                b: PointRef::End(line),
                distance,
            };
            s.add_constraint(side(lines[0], width)).unwrap();
            s.add_constraint(side(lines[1], 1.0)).unwrap();
            if conflicting.contains(&k) {
                s.add_constraint(side(lines[2], width + 1.0)).unwrap();
            }
            s.add_constraint(Fixed::point(PointRef::Start(lines[0])))
                .unwrap();
        }
        s
    }

    /// A report with its timings zeroed (the only part that differs between two runs).
    fn untimed(mut r: SketchReport) -> SketchReport {
        for c in &mut r.components {
            c.report.elapsed = std::time::Duration::ZERO;
        }
        r
    }

    #[test]
    fn parallel_and_sequential_solves_agree_exactly() {
        let base = rectangles(50, &[]);
        assert!(solves_in_parallel(&base.components()) || rayon::current_num_threads() == 1);
        let (mut seq, mut par) = (base.clone(), base.clone());
        let comps = base.components();
        let rs = seq.solve_components_in(comps.clone(), false).unwrap();
        let rp = par.solve_components_in(comps, true).unwrap();
        assert_eq!(rs.components.len(), 50);
        assert_eq!(untimed(rs), untimed(rp));
        // Bit for bit the same sketch, dirty marks included.
        assert_eq!(to_json(&seq).unwrap(), to_json(&par).unwrap());
        assert_eq!(seq.dirty().count(), 0);
        assert_eq!(par.dirty().count(), 0);
        for k in 0..50 {
            let line = seq.components()[k].entities[0];
            let (a, b) = (
                par.point(PointRef::Start(line)).unwrap(),
                par.point(PointRef::End(line)).unwrap(),
            );
            assert!(((b - a).norm() - (2.0 + (k % 3) as f64)).abs() < 1e-9);
        }
    }

    #[test]
    fn the_first_failing_component_in_order_is_the_error_and_nothing_is_written() {
        // Components 5, 17 and 33 conflict; whichever thread finds one first, the error is
        // component 5's, as one after another, and no component is written.
        let base = rectangles(40, &[33, 17, 5]);
        let comps = base.components();
        let (mut seq, mut par) = (base.clone(), base.clone());
        let es = seq.solve_components_in(comps.clone(), false).unwrap_err();
        let ep = par.solve_components_in(comps, true).unwrap_err();
        assert_eq!(es, ep);
        let mut only_fifth = rectangles(6, &[5]);
        let e5 = only_fifth.solve_all().unwrap_err();
        // The same kind of failure on the same constraints, up to the ids of the components
        // before it (rectangle 5 holds the same place in both sketches).
        assert_eq!(e5, ep);
        let before = to_json(&base).unwrap();
        assert_eq!(to_json(&seq).unwrap(), before);
        assert_eq!(to_json(&par).unwrap(), before);
        assert_eq!(par.dirty().count(), base.dirty().count());
    }

    #[test]
    fn small_sketches_stay_sequential() {
        assert!(!solves_in_parallel(&rectangles(1, &[]).components()));
        // 46 rectangles: 506 constraints, below the threshold.
        assert!(!solves_in_parallel(&rectangles(46, &[]).components()));
        let many = rectangles(47, &[]).components();
        assert_eq!(
            solves_in_parallel(&many),
            rayon::current_num_threads() > 1,
            "517 constraints in 47 components"
        );
    }
}
