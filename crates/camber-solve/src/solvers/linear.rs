//! The linear solve of an affine problem: analysis → minimum-norm step → re-evaluation →
//! write-back on success.

use std::borrow::Cow;
use std::time::Instant;

use crate::analysis;
use crate::linalg::min_norm::{self, MinNormFactorization};
use crate::linalg::reduced::Linearization;
use crate::model::errors::{Error, Result};
use crate::model::options::Options;
use crate::model::problem::Problem;
use crate::model::report::{per_constraint, Selection, SolveReport, SolverKind, Status};

/// Rounds of iterative refinement after the minimum-norm step (see
/// [`MinNormFactorization::solve_refined`]).
const REFINEMENT_STEPS: usize = 3;

/// Solves a problem whose residuals are all affine by one weighted minimum-norm step over the
/// reduced unknowns: Δz = −W⁻¹·Jᵀ·(J·W⁻¹·Jᵀ)⁻¹·g , after a DOF analysis
/// that drops consistent dependent rows (if allowed) and refuses conflicting ones. The
/// residuals are re-evaluated at the result, which is written back only if every constraint is
/// within `options.tolerance` and every bound holds.
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
    let mut scratch = Scratch::take();
    let outcome = solve_in(problem, options, &mut scratch);
    scratch.keep();
    outcome
}

/// The storage of [`solve_linear`], kept per thread between solves of small problems: a sketch
/// of many small components solves them one after another on each thread, and their
/// allocations cost more than their arithmetic.
struct Scratch {
    lin: Linearization,
    /// Δz, z, x(z), g(x(z)).
    dz: Vec<f64>,
    z: Vec<f64>,
    x: Vec<f64>,
    g: Vec<f64>,
    /// The last success reason and what it was made of (dependent rows dropped, reduced
    /// unknowns, dense, threshold): sketches solve many components of one size.
    reason: Option<((bool, usize, bool, usize), String)>,
}

thread_local! {
    static SCRATCH: std::cell::Cell<Option<Box<Scratch>>> = const { std::cell::Cell::new(None) };
}

/// Storage is kept for the next solve only up to this many rows or reduced unknowns (a large
/// problem's allocations are small next to its arithmetic, and its memory is given back).
const SCRATCH_MAX: usize = 4096;

impl Scratch {
    /// This thread's kept storage, or new storage (also when a solve is already using it).
    fn take() -> Box<Self> {
        SCRATCH.with(std::cell::Cell::take).unwrap_or_else(|| {
            Box::new(Self {
                lin: Linearization::empty(),
                dz: Vec::new(),
                z: Vec::new(),
                x: Vec::new(),
                g: Vec::new(),
                reason: None,
            })
        })
    }

    /// Keeps the storage for this thread's next solve, if it is small.
    fn keep(self: Box<Self>) {
        if self.lin.g.capacity().max(self.dz.capacity()) <= SCRATCH_MAX {
            SCRATCH.with(|s| s.set(Some(self)));
        }
    }
}

/// [`solve_linear`] in the given storage.
fn solve_in(
    problem: &mut Problem,
    options: &Options,
    scratch: &mut Scratch,
) -> Result<SolveReport> {
    let start = Instant::now();
    options.validate()?;
    if let Some(rb) = problem.residuals.iter().find(|rb| !rb.residual.is_affine()) {
        return Err(Error::NonlinearNotAvailable {
            constraint: rb.owner,
            name: rb.residual.name().to_owned(),
        });
    }
    let Scratch {
        lin,
        dz,
        z,
        x,
        g,
        reason,
    } = scratch;
    problem.linearize_into(lin)?;
    let lin = &*lin;
    let (m, n) = (lin.g.len(), lin.map.len());

    let dense_analysis = m.saturating_mul(n) <= options.dense_analysis_max_entries;
    // The rows kept for the step (`None`: all of them).
    let (rank, dof, redundant, rows) = if dense_analysis
        && crate::analysis::certificate::certainly_full_row_rank_of(lin, options.rank_tolerance)
    {
        // Every row independent by the analysis' own test: its answer is known.
        (m, n - m, Vec::new(), None)
    } else if dense_analysis {
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
        (a.rank, a.dof, a.redundant, Some(a.rows.independent))
    } else {
        (m.min(n), n.saturating_sub(m), Vec::new(), None)
    };

    let satisfied = lin.g.iter().all(|v| v.abs() <= options.tolerance);
    let substitution_pending = lin
        .x
        .iter()
        .zip(problem.values())
        .any(|(a, b)| (a - b).abs() > 0.0);
    if satisfied && !substitution_pending {
        return Ok(SolveReport {
            status: Status::AlreadySatisfied,
            solver: SolverKind::None,
            selection: Selection::AlreadySatisfied,
            reason: "every residual is already within tolerance".to_owned(),
            iterations: 0,
            residuals: per_constraint(&lin.row_owner, &lin.g),
            displacement_norm: 0.0,
            rank,
            dof,
            redundant,
            conflicting: Vec::new(),
            priorities: Vec::new(),
            elapsed: start.elapsed(),
        });
    }

    dz.clear();
    dz.resize(n, 0.0);
    let dense = n <= options.dense_max_unknowns;
    let kept = rows.as_ref().map_or(m, Vec::len);
    if kept > 0 {
        // Every row kept (the usual case): J and g as they are, no copy.
        let (j, g) = match &rows {
            Some(rows) if rows.len() < m => (
                Cow::Owned(lin.jacobian.select_rows(rows)),
                Cow::Owned(rows.iter().map(|i| lin.g[*i]).collect()),
            ),
            _ => (
                Cow::Borrowed(&lin.jacobian),
                Cow::Borrowed(lin.g.as_slice()),
            ),
        };
        let weights = lin.map.weights();
        let refine = 0.01 * options.tolerance;
        if dense && kept <= min_norm::SMALL_ROWS {
            min_norm::solve_small_refined(&j, weights, &g, dz, REFINEMENT_STEPS, refine)?;
        } else {
            let mut f = if dense {
                MinNormFactorization::try_dense(&j, weights)?
            } else {
                MinNormFactorization::try_sparse(&j, weights)?
            };
            f.solve_refined(&g, dz, REFINEMENT_STEPS, refine)?;
        }
    }
    z.clear();
    z.extend(lin.map.z0().iter().zip(dz.iter()).map(|(a, b)| a + b));
    x.clear();
    x.resize(problem.num_unknowns(), 0.0);
    lin.map.expand(z, x)?;
    g.clear();
    g.resize(m, 0.0);
    problem.evaluate_at(x, g)?;
    let residuals = per_constraint(&lin.row_owner, g);
    let failed: Vec<_> = residuals
        .iter()
        .filter(|r| r.max_abs > options.tolerance || r.max_abs.is_nan())
        .map(|r| (r.constraint, r.max_abs))
        .collect();
    if !failed.is_empty() {
        return Err(Error::NotSatisfied { failed });
    }
    problem.apply_reduced(&lin.map, z)?;

    let (solver, backend) = if dense {
        (SolverKind::DenseMinNorm, "dense")
    } else {
        (SolverKind::SparseMinNorm, "sparse")
    };
    let key = (!redundant.is_empty(), n, dense, options.dense_max_unknowns);
    let reason = match reason {
        Some((k, text)) if *k == key => text.clone(),
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
            *reason = Some((key, text.clone()));
            text
        }
    };
    Ok(SolveReport {
        status: Status::Solved,
        solver,
        selection: Selection::Affine,
        reason,
        iterations: 1,
        residuals,
        displacement_norm: dz.iter().map(|v| v * v).sum::<f64>().sqrt(),
        rank,
        dof,
        redundant,
        conflicting: Vec::new(),
        priorities: Vec::new(),
        elapsed: start.elapsed(),
    })
}
