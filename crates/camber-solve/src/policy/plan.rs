//! [`Plan`]: the one decision of how a problem is solved, with what it keeps between solves.
//!
//! Every solve goes through [`Plan::solve`]: a first solve, a re-solve after a change of
//! values, a drag update, a forced solver, priority tiers. The path:
//!
//! 1. an affine problem takes the linear path (`policy::linear`: the analysis, one minimum-norm
//!    step, validation), its factorization kept while the problem's structure and residual
//!    objects stay the same;
//! 2. a warm start ([`Start::Warm`]: a drag, a re-solve from a previous solution) first tries
//!    Newton minimum norm from the given point pulling toward the reference, with no analysis;
//! 3. otherwise (or when the warm Newton fails) the selection from the DOF analysis at the
//!    problem's values (`policy::selection`): Newton minimum norm, SLSQP within its limits, least
//!    squares and Newton from there, the soft compromise when asked;
//! 4. when the whole set cannot be met and constraints have priorities, the tiers in order
//!    (`solvers::lexicographic`).
//!
//! **Warm state is data.** A plan keeps the evaluator of the problem (its patterns of J and H,
//! the triplets of affine residuals), Newton's workspace (buffers, the LU pivots and patterns
//! of a square J, the ordering of J·W⁻¹·Jᵀ) and the linear path's J, verdict and
//! factorization. It compares the problem's [`Stamps`] at every solve: values that changed are
//! read again; replaced residual objects drop what depends on their coefficients; a change of
//! structure drops everything. So one plan may serve one problem for its whole life (a sketch
//! component, a drag session), and a plan given a different problem simply starts over.

use crate::linalg::evaluator::Evaluator;
use crate::model::errors::{Error, Result};
use crate::model::options::Options;
use crate::model::problem::{Problem, Stamps};
use crate::model::report::SolveReport;
use crate::policy::linear::LinearPath;
use crate::policy::selection;
use crate::solvers::newton::NewtonWorkspace;

/// Where a solve starts.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Start {
    /// From the problem's values, by the selection of the DOF analysis.
    #[default]
    Cold,
    /// Newton minimum norm from `from` (reduced unknowns, in the order of
    /// [`crate::ReducedMap::vars`]: a previous solution) pulling toward `toward` (where the
    /// unknowns should stay if they can), with the cold selection as fallback.
    Warm {
        /// The point Newton starts from.
        from: Vec<f64>,
        /// The point it pulls toward.
        toward: Vec<f64>,
    },
}

/// The prepared solve of one problem: the policy's decision and what it keeps between solves
/// (see the module documentation).
///
/// ```
/// use camber_solve::policy::{Plan, Start};
/// use camber_solve::{scalar::cst, ConstraintId, Options, Problem, Residual, Scalar};
///
/// /// |p|² = r²: the point lies on the circle of radius r about the origin.
/// #[derive(Debug)]
/// struct OnCircle(f64);
/// impl Residual for OnCircle {
///     fn name(&self) -> &str { "on circle" }
///     fn dim(&self) -> usize { 1 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
///         out[0] = x[0][0] * x[0][0] + x[0][1] * x[0][1] - cst(self.0 * self.0);
///     }
/// }
///
/// let mut p = Problem::new();
/// let b = p.add_block(&[3.0, 4.0])?;
/// let r = p.add_residual(OnCircle(1.0), &[b], ConstraintId(1))?;
/// let mut plan = Plan::new();
/// plan.solve(&mut p, &Options::default(), &Start::Cold)?;
/// assert!((p.values()[0] - 0.6).abs() < 1e-10);
/// // A new value of the dimension: the same plan solves again, from where the last solve left.
/// p.replace_residual(r, std::sync::Arc::new(OnCircle(2.0)))?;
/// plan.solve(&mut p, &Options::default(), &Start::Cold)?;
/// assert!((p.values()[0] - 1.2).abs() < 1e-10 && (p.values()[1] - 1.6).abs() < 1e-10);
/// # Ok::<(), camber_solve::Error>(())
/// ```
#[derive(Debug, Default)]
pub struct Plan {
    /// The stamps the evaluator was made or refreshed at.
    stamps: Option<Stamps>,
    evaluator: Option<Evaluator>,
    newton: NewtonWorkspace,
    linear: Box<LinearPath>,
    /// Whether the plan borrows this thread's spare storage (a one-off solve).
    one_off: bool,
    /// The reduced unknowns written back by the last successful solve.
    last: Vec<f64>,
}

impl Plan {
    /// A plan that keeps nothing yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// A plan for one solve: it borrows the storage this thread's last one-off solve left, and
    /// gives it back in [`Plan::release`] (a sketch of many small components solves them one
    /// after another, and their allocations cost more than their arithmetic).
    pub(crate) fn one_off() -> Self {
        Self {
            newton: NewtonWorkspace::take_spare(),
            linear: LinearPath::take_spare(),
            one_off: true,
            ..Self::default()
        }
    }

    /// Gives a one-off plan's storage back to the thread.
    pub(crate) fn release(self) {
        if self.one_off {
            self.newton.keep_as_spare();
            self.linear.keep_as_spare();
        }
    }

    /// Forgets everything kept: the next solve starts as the first.
    pub fn forget(&mut self) {
        self.stamps = None;
        self.evaluator = None;
        self.newton.forget_patterns();
        self.linear.forget();
    }

    /// Solves `problem` from `start` (see the module documentation); on success the problem
    /// holds the solution, on every error its values are as they were.
    ///
    /// # Errors
    /// [`Error::Conflicting`] naming the constraints that cannot be met together (without soft
    /// mode; with priorities, the required ones), [`Error::NotSolved`] when no path met them and
    /// nothing proves a conflict, [`Error::SolverUnavailable`] when a forced solver is not
    /// built, the errors of a forced solver, [`Error::BudgetSpent`], [`Error::Cancelled`] once
    /// [`Options::cancel`] is raised.
    pub fn solve(
        &mut self,
        problem: &mut Problem,
        options: &Options,
        start: &Start,
    ) -> Result<SolveReport> {
        // A budget started by the caller spans its several solves; otherwise this one has its
        // own.
        let own_budget = !problem.budget.running();
        if own_budget {
            problem.set_cancel(options.cancel.clone());
            problem.start_budget(options.nonlinear.max_evaluations);
        }
        let outcome = match self.whole(problem, options, start) {
            Err(e @ (Error::Conflicting { .. } | Error::NotSolved { .. }))
                if problem.has_priorities()
                    && options.nonlinear.force.is_none()
                    && !options.nonlinear.soft =>
            {
                // The tiers cannot be met on a spent budget: the whole set's failure stands.
                match crate::solvers::lexicographic::solve(problem, options) {
                    Err(Error::BudgetSpent { .. }) => Err(e),
                    tiers => tiers,
                }
            }
            outcome => outcome,
        };
        // A cancelled solve fails as cancelled, whatever its paths made of their refused
        // charges.
        let outcome = match outcome {
            Err(_) if problem.budget.cancelled() => Err(Error::Cancelled),
            outcome => outcome,
        };
        if own_budget {
            problem.end_budget();
            problem.set_cancel(None);
        }
        if outcome.is_ok() {
            problem.reduced_values_into(&mut self.last);
        }
        outcome
    }

    /// Gives back a report this plan made: its storage serves the next report (a drag, which
    /// reads its report and drops it, then allocates nothing per update on the linear path).
    pub fn recycle(&mut self, report: SolveReport) {
        self.linear.recycle(report);
    }

    /// The reduced unknowns (in the order of [`crate::ReducedMap::vars`]) the last successful
    /// solve wrote back: where a warm start of the next solve begins. Empty before any.
    pub fn last_solution(&self) -> &[f64] {
        &self.last
    }

    /// [`Plan::solve`] for the whole set of constraints, priorities aside.
    fn whole(
        &mut self,
        problem: &mut Problem,
        options: &Options,
        start: &Start,
    ) -> Result<SolveReport> {
        options.validate()?;
        options.nonlinear.validate()?;
        let affine = problem.residuals.iter().all(|rb| rb.affine);
        if affine && options.nonlinear.force.is_none() {
            return match self.linear.solve(problem, options) {
                Err(Error::Conflicting { .. }) if options.nonlinear.soft => {
                    let ev = self_evaluator(&mut self.stamps, &mut self.evaluator, problem)?;
                    selection::soft_for_affine(problem, options, ev)
                }
                outcome => outcome,
            };
        }
        if let (Start::Warm { from, toward }, None) = (start, options.nonlinear.force) {
            let ev = self_evaluator(&mut self.stamps, &mut self.evaluator, problem)?;
            if let Ok(report) =
                selection::warm_newton(problem, options, &mut self.newton, ev, from, toward)
            {
                return Ok(report);
            }
        }
        let ev = self_evaluator(&mut self.stamps, &mut self.evaluator, problem)?;
        selection::cold(problem, options, &mut self.newton, ev, &mut self.linear)
    }
}

/// The evaluator of the problem as it is: the kept one with the values read again, or a new
/// one when the structure changed (on the plan's fields, so that the Newton workspace can be
/// borrowed beside it).
fn self_evaluator<'a>(
    stamps: &mut Option<Stamps>,
    evaluator: &'a mut Option<Evaluator>,
    problem: &Problem,
) -> Result<&'a mut Evaluator> {
    let now = problem.stamps();
    let same_shape = stamps.is_some_and(|s| s.shape == now.shape);
    match evaluator {
        Some(ev) if same_shape => {
            if stamps.is_some_and(|s| s.residuals != now.residuals) {
                ev.forget_residuals();
            }
            ev.refresh(problem)?;
        }
        _ => *evaluator = Some(Evaluator::new(problem)?),
    }
    *stamps = Some(now);
    evaluator.as_mut().ok_or(Error::RankDeficient {
        rows: problem.num_rows(),
    })
}
