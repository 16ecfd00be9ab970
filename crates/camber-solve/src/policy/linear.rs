//! The policy's linear path, for a problem whose residuals are all affine: one weighted
//! minimum-norm step from the current values, validated and written back.
//!
//! 1. **Which rows.** Small problems (rows × unknowns up to `dense_analysis_max_entries`) are
//!    analysed first: a cheap certificate proves full row rank, or the DOF analysis names
//!    conflicting rows ([`Error::Conflicting`]) and drops consistent dependent ones (or refuses
//!    them, [`Error::Redundant`], when `drop_redundant` is off). Larger ones go straight to the
//!    sparse factorization and are analysed only when it meets dependent rows.
//! 2. **The step**, Δz = −W⁻¹·Jᵀ·(J·W⁻¹·Jᵀ)⁻¹·g over the kept rows, refined to rounding
//!    (`solvers::linear`), dense up to `dense_max_unknowns` reduced unknowns, sparse above.
//! 3. **Validation.** Every residual is evaluated at the result; it is written back only when
//!    all are within `tolerance` and every bound holds.
//!
//! **Kept between solves.** J of an affine problem depends on its structure and residual
//! objects only, not on the values, so the path keeps J, the verdict of step 1 and the
//! factorization of step 2 while the problem's stamps ([`crate::Problem::stamps`]) stay the
//! same: a drag, a moved point or a fixed value changed re-solves in one evaluation of g, one
//! step and one validation. From the second step on a small factorization is written out as a
//! dense gain (`solvers::linear`); a step it gives that misses the tolerance is redone by the
//! factorization before anything is refused.

use std::time::Instant;

use crate::analysis;
use crate::analysis::certificate::certainly_full_row_rank_of;
use crate::linalg::min_norm;
use crate::linalg::normal::NormalCache;
use crate::linalg::reduced::Linearization;
use crate::model::errors::{Error, Result};
use crate::model::ids::ConstraintId;
use crate::model::options::Options;
use crate::model::problem::{Problem, Stamps};
use crate::model::report::{
    per_constraint_into, ConstraintResidual, Selection, SolveReport, SolverKind, Status,
};
use crate::solvers::linear::{small_step, LinearSolver};

/// What step 1 decided, kept with the solver.
#[derive(Debug, Clone)]
struct Verdict {
    rank: usize,
    dof: usize,
    redundant: Vec<ConstraintId>,
    /// The rows kept (`None`: all of them).
    rows: Option<Vec<usize>>,
    /// Whether the rows were analysed (or certified); unanalysed rows are analysed when the
    /// factorization meets dependent ones.
    analysed: bool,
}

/// The linear path with what it keeps between solves (see the module documentation).
#[derive(Debug)]
pub(crate) struct LinearPath {
    /// The stamps the kept J, verdict and solver were made at.
    stamps: Option<Stamps>,
    lin: Linearization,
    verdict: Option<Verdict>,
    solver: Option<LinearSolver>,
    /// Steps taken with the kept solver (its gain is written out at the second).
    uses: usize,
    cache: NormalCache,
    /// Δz, z, x(z), g(x(z)).
    dz: Vec<f64>,
    z: Vec<f64>,
    x: Vec<f64>,
    g: Vec<f64>,
    /// The last success reason and what it was made of (dependent rows dropped, reduced
    /// unknowns, dense, threshold).
    reason: Option<((bool, usize, bool, usize), String)>,
    /// Storage of reports given back ([`LinearPath::recycle`]): the next report is written in
    /// it instead of new vectors.
    spare_residuals: Vec<ConstraintResidual>,
    spare_reason: String,
}

impl Default for LinearPath {
    fn default() -> Self {
        Self {
            stamps: None,
            lin: Linearization::empty(),
            verdict: None,
            solver: None,
            uses: 0,
            cache: NormalCache::default(),
            dz: Vec::new(),
            z: Vec::new(),
            x: Vec::new(),
            g: Vec::new(),
            reason: None,
            spare_residuals: Vec::new(),
            spare_reason: String::new(),
        }
    }
}

impl LinearPath {
    /// Forgets everything kept (the next solve analyses and factorizes again).
    pub(crate) fn forget(&mut self) {
        self.stamps = None;
        self.verdict = None;
        self.solver = None;
        self.uses = 0;
    }

    /// Takes back the storage of a report this path made (its residuals and reason), for the
    /// next one.
    pub(crate) fn recycle(&mut self, report: SolveReport) {
        if report.residuals.capacity() > self.spare_residuals.capacity() {
            self.spare_residuals = report.residuals;
        }
        if report.reason.capacity() > self.spare_reason.capacity() {
            self.spare_reason = report.reason;
        }
    }

    /// Whether J, the verdict and the solver kept are those of this problem as it is.
    pub(crate) fn is_kept_for(&self, problem: &Problem) -> bool {
        self.stamps == Some(problem.stamps()) && self.verdict.is_some()
    }

    /// One solve by the linear path (see the module documentation).
    ///
    /// # Errors
    /// [`Error::NonlinearNotAvailable`] for a residual that is not affine; [`Error::Conflicting`],
    /// [`Error::Redundant`], [`Error::RankDeficient`] from the analysis and factorization;
    /// [`Error::NotSatisfied`] and [`Error::OutOfBounds`] after the step. The problem's values
    /// are unchanged on every error.
    pub(crate) fn solve(
        &mut self,
        problem: &mut Problem,
        options: &Options,
    ) -> Result<SolveReport> {
        let start = Instant::now();
        options.validate()?;
        if let Some(rb) = problem.residuals.iter().find(|rb| !rb.affine) {
            return Err(Error::NonlinearNotAvailable {
                constraint: rb.owner,
                name: rb.residual.name().to_owned(),
            });
        }
        let kept = self.is_kept_for(problem);
        if kept {
            // Values only: J is the kept one; the map's start and constants and g are new.
            problem.reduced_map_into(&mut self.lin.map)?;
            self.lin.x.resize(problem.num_unknowns(), 0.0);
            self.lin.map.expand(self.lin.map.z0(), &mut self.lin.x)?;
            problem.evaluate_at(&self.lin.x, &mut self.lin.g)?;
        } else {
            self.forget();
            problem.linearize_into(&mut self.lin)?;
            self.stamps = Some(problem.stamps());
        }
        let (m, n) = (self.lin.g.len(), self.lin.map.len());
        if self.verdict.is_none() {
            self.verdict = Some(self.decide_rows(options)?);
        }
        let satisfied = self.lin.g.iter().all(|v| v.abs() <= options.tolerance);
        let substitution_pending = self
            .lin
            .x
            .iter()
            .zip(problem.values())
            .any(|(a, b)| (a - b).abs() > 0.0);
        if satisfied && !substitution_pending {
            let v = self
                .verdict
                .as_ref()
                .ok_or(Error::RankDeficient { rows: m })?;
            let mut reason = std::mem::take(&mut self.spare_reason);
            reason.clear();
            reason.push_str("every residual is already within tolerance");
            let mut residuals = std::mem::take(&mut self.spare_residuals);
            per_constraint_into(&self.lin.row_owner, &self.lin.g, &mut residuals);
            return Ok(SolveReport {
                status: Status::AlreadySatisfied,
                solver: SolverKind::None,
                selection: Selection::AlreadySatisfied,
                reason,
                iterations: 0,
                residuals,
                displacement_norm: 0.0,
                rank: v.rank,
                dof: v.dof,
                redundant: v.redundant.clone(),
                conflicting: Vec::new(),
                priorities: Vec::new(),
                elapsed: start.elapsed(),
            });
        }

        let dense = n <= options.dense_max_unknowns;
        let refine = 0.01 * options.tolerance;
        self.dz.clear();
        self.dz.resize(n, 0.0);
        let mut used_gain = false;
        if self.solver.is_none() && !kept {
            self.first_step(options, dense, refine)?;
        } else {
            if self.solver.is_none() {
                self.make_solver(options, dense)?;
            }
            if let Some(solver) = self.solver.as_mut() {
                if self.uses >= 1 {
                    solver.with_gain(m)?;
                }
                used_gain = solver.has_gain();
                solver.step(&self.lin.g, &mut self.dz, refine)?;
            }
            self.uses += 1;
        }
        let met = self.try_step(problem, options)?;
        if !met && used_gain {
            // The gain's product missed: the refined factorization decides.
            if let Some(solver) = self.solver.as_mut() {
                solver.step_refined(&self.lin.g, &mut self.dz, refine)?;
            }
            if !self.try_step(problem, options)? {
                return Err(Error::NotSatisfied {
                    failed: self.failed(options),
                });
            }
        } else if !met {
            return Err(Error::NotSatisfied {
                failed: self.failed(options),
            });
        }
        problem.apply_reduced(&self.lin.map, &self.z)?;
        Ok(self.report(options, dense, start))
    }

    /// The rows the step keeps, and the rank and DOF (step 1 of the module documentation).
    fn decide_rows(&self, options: &Options) -> Result<Verdict> {
        let lin = &self.lin;
        let (m, n) = (lin.g.len(), lin.map.len());
        let dense_analysis = m.saturating_mul(n) <= options.dense_analysis_max_entries;
        if dense_analysis && certainly_full_row_rank_of(lin, options.rank_tolerance) {
            // Every row independent by the analysis' own test: its answer is known.
            Ok(Verdict {
                rank: m,
                dof: n - m,
                redundant: Vec::new(),
                rows: None,
                analysed: true,
            })
        } else if dense_analysis {
            analysed_rows(lin, options)
        } else {
            Ok(Verdict {
                rank: m.min(n),
                dof: n.saturating_sub(m),
                redundant: Vec::new(),
                rows: None,
                analysed: false,
            })
        }
    }

    /// The step of a one-off solve (the structure is new): a small dense J on the stack,
    /// anything else through a solver kept for the next solve.
    fn first_step(&mut self, options: &Options, dense: bool, refine: f64) -> Result<()> {
        let rows = self.verdict.as_ref().and_then(|v| v.rows.clone());
        let kept_rows = rows.as_ref().map_or(self.lin.g.len(), Vec::len);
        if kept_rows == 0 {
            return Ok(());
        }
        if dense && kept_rows <= min_norm::SMALL_ROWS {
            let weights = self.lin.map.weights();
            return match &rows {
                Some(rows) if rows.len() < self.lin.g.len() => {
                    let j = self.lin.jacobian.select_rows(rows);
                    let g: Vec<f64> = rows.iter().map(|i| self.lin.g[*i]).collect();
                    small_step(&j, weights, &g, &mut self.dz, refine)
                }
                _ => small_step(
                    &self.lin.jacobian,
                    weights,
                    &self.lin.g,
                    &mut self.dz,
                    refine,
                ),
            };
        }
        self.make_solver(options, dense)?;
        if let Some(solver) = self.solver.as_mut() {
            solver.step(&self.lin.g, &mut self.dz, refine)?;
        }
        self.uses = 1;
        Ok(())
    }

    /// Factorizes the kept rows; when unanalysed rows turn out dependent, analyses them
    /// (sparsely at this size) and factorizes the independent ones.
    fn make_solver(&mut self, options: &Options, dense: bool) -> Result<()> {
        let weights = self.lin.map.weights().to_vec();
        let verdict = self.verdict.clone().ok_or(Error::RankDeficient {
            rows: self.lin.g.len(),
        })?;
        let made = LinearSolver::factorize(
            &self.lin.jacobian,
            &weights,
            verdict.rows.clone(),
            dense,
            &mut self.cache,
        );
        let solver = match made {
            Err(Error::RankDeficient { .. }) if !verdict.analysed => {
                let analysed = analysed_rows(&self.lin, options)?;
                let solver = LinearSolver::factorize(
                    &self.lin.jacobian,
                    &weights,
                    analysed.rows.clone(),
                    dense,
                    &mut self.cache,
                )?;
                self.verdict = Some(analysed);
                solver
            }
            other => other?,
        };
        self.solver = Some(solver);
        Ok(())
    }

    /// z = z₀ + Δz, x(z) and g(x(z)) into the path's buffers; whether every row is within
    /// tolerance (then nothing is allocated: the constraints above it are listed by
    /// [`LinearPath::failed`] only when the step is refused).
    fn try_step(&mut self, problem: &Problem, options: &Options) -> Result<bool> {
        self.z.clear();
        self.z
            .extend(self.lin.map.z0().iter().zip(&self.dz).map(|(a, b)| a + b));
        self.x.clear();
        self.x.resize(problem.num_unknowns(), 0.0);
        self.lin.map.expand(&self.z, &mut self.x)?;
        self.g.clear();
        self.g.resize(self.lin.g.len(), 0.0);
        problem.evaluate_at(&self.x, &mut self.g)?;
        Ok(self.g.iter().all(|v| v.abs() <= options.tolerance))
    }

    /// The constraints above tolerance after the last step, with their largest |g| (NaN for a
    /// row that is not a number).
    fn failed(&self, options: &Options) -> Vec<(ConstraintId, f64)> {
        let mut failed: Vec<(ConstraintId, f64)> = Vec::new();
        for (owner, v) in self.lin.row_owner.iter().zip(&self.g) {
            let a = v.abs();
            if a > options.tolerance || v.is_nan() {
                match failed.iter_mut().find(|(c, _)| c == owner) {
                    Some(slot) => slot.1 = slot.1.max(a),
                    None => failed.push((*owner, if v.is_nan() { f64::NAN } else { a })),
                }
            }
        }
        failed
    }

    /// The report of a successful step.
    fn report(&mut self, options: &Options, dense: bool, start: Instant) -> SolveReport {
        let n = self.lin.map.len();
        let (rank, dof, redundant) = match &self.verdict {
            Some(v) => (v.rank, v.dof, v.redundant.clone()),
            None => (0, n, Vec::new()),
        };
        let (solver, backend) = if dense {
            (SolverKind::DenseMinNorm, "dense")
        } else {
            (SolverKind::SparseMinNorm, "sparse")
        };
        let key = (!redundant.is_empty(), n, dense, options.dense_max_unknowns);
        let mut spare = std::mem::take(&mut self.spare_reason);
        let reason = match &self.reason {
            Some((k, text)) if *k == key => {
                spare.clear();
                spare.push_str(text);
                spare
            }
            _ => {
                let dropped = if key.0 {
                    ", consistent redundant rows dropped"
                } else {
                    ""
                };
                let text = format!(
                    "all residuals affine and full row rank{dropped}; {n} reduced unknowns → \
                     {backend} (threshold {})",
                    options.dense_max_unknowns
                );
                self.reason = Some((key, text.clone()));
                text
            }
        };
        SolveReport {
            status: Status::Solved,
            solver,
            selection: Selection::Affine,
            reason,
            iterations: 1,
            residuals: {
                let mut out = std::mem::take(&mut self.spare_residuals);
                per_constraint_into(&self.lin.row_owner, &self.g, &mut out);
                out
            },
            displacement_norm: self.dz.iter().map(|v| v * v).sum::<f64>().sqrt(),
            rank,
            dof,
            redundant,
            conflicting: Vec::new(),
            priorities: Vec::new(),
            elapsed: start.elapsed(),
        }
    }
}

/// The DOF analysis of the rows: conflicting rows refused, consistent dependent ones dropped
/// (or refused when they may not be).
fn analysed_rows(lin: &Linearization, options: &Options) -> Result<Verdict> {
    let a = analysis::analyze(lin, options.rank_tolerance, options.tolerance)?;
    if !a.conflicting.is_empty() {
        return Err(Error::Conflicting {
            constraints: a.conflicting,
        });
    }
    let dependent = !a.redundant.is_empty() || !a.partly_redundant.is_empty();
    if dependent && !options.drop_redundant {
        let mut constraints = a.redundant.clone();
        constraints.extend(&a.partly_redundant);
        return Err(Error::Redundant { constraints });
    }
    Ok(Verdict {
        rank: a.rank,
        dof: a.dof,
        redundant: a.redundant,
        rows: Some(a.rows.independent),
        analysed: true,
    })
}

/// Solves a problem whose residuals are all affine by one weighted minimum-norm step over the
/// reduced unknowns: Δz = −W⁻¹·Jᵀ·(J·W⁻¹·Jᵀ)⁻¹·g, after a DOF analysis that drops consistent
/// dependent rows (if allowed) and refuses conflicting ones. The residuals are re-evaluated at
/// the result, which is written back only if every constraint is within `options.tolerance` and
/// every bound holds. This is the policy's linear path ([`crate::policy::Plan`] keeps its
/// factorization between solves); it refuses nonlinear residuals where [`crate::solve()`]
/// would choose another path.
///
/// ```
/// use camber_solve::{ConstraintId, Options, Problem, Residual, Scalar, solve_linear, Status};
/// /// x = 3 on the first unknown of a block.
/// #[derive(Debug)]
/// struct XIs3;
/// impl Residual for XIs3 {
///     fn name(&self) -> &str { "x is 3" }
///     fn dim(&self) -> usize { 1 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
///         out[0] = x[0][0] - camber_solve::scalar::cst(3.0);
///     }
///     fn is_affine(&self) -> bool { true }
/// }
/// let mut p = Problem::new();
/// let b = p.add_block(&[0.0, 5.0])?;
/// p.add_residual(XIs3, &[b], ConstraintId(9))?;
/// let r = solve_linear(&mut p, &Options::default())?;
/// assert_eq!(r.status, Status::Solved);
/// assert!((p.values()[0] - 3.0).abs() < 1e-12 && (p.values()[1] - 5.0).abs() < 1e-15);
/// # Ok::<(), camber_solve::Error>(())
/// ```
///
/// # Errors
/// [`Error::NonlinearNotAvailable`] for a residual that is not affine; [`Error::Conflicting`],
/// [`Error::Redundant`], [`Error::RankDeficient`] from the analysis and factorization;
/// [`Error::NotSatisfied`] and [`Error::OutOfBounds`] after the step; the problem's values are
/// unchanged in every case.
pub fn solve_linear(problem: &mut Problem, options: &Options) -> Result<SolveReport> {
    let mut path = LinearPath::take_spare();
    let outcome = path.solve(problem, options);
    path.keep_as_spare();
    outcome
}

thread_local! {
    /// The storage of the last one-off linear solve on this thread: a sketch of many small
    /// components solves them one after another, and their allocations cost more than their
    /// arithmetic.
    static SPARE: std::cell::Cell<Option<Box<LinearPath>>> = const { std::cell::Cell::new(None) };
}

/// Storage is kept for the next one-off solve only up to this many rows or reduced unknowns.
const SPARE_MAX: usize = 4096;

impl LinearPath {
    /// This thread's kept storage (with nothing kept of any problem), or new storage.
    pub(crate) fn take_spare() -> Box<Self> {
        let mut path = SPARE.with(std::cell::Cell::take).unwrap_or_default();
        path.forget();
        path
    }

    /// Keeps the storage for this thread's next one-off solve, if it is small.
    pub(crate) fn keep_as_spare(self: Box<Self>) {
        if self.lin.g.capacity().max(self.dz.capacity()) <= SPARE_MAX {
            SPARE.with(|s| s.set(Some(self)));
        }
    }
}
