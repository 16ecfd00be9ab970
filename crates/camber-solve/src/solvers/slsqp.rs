//! SLSQP through NLopt: minimise an objective over z subject to every residual = 0.
//!
//! The problem handed to NLopt's SLSQP (sequential least-squares quadratic programming) is
//!
//! min f(z)  subject to  g(x(z)) = 0,  l ≤ z ≤ u,
//!
//! with f the chosen [`crate::model::objective::Objective`] (by default ½‖z − z₀‖²_W), the residual
//! rows as one vector-valued equality constraint whose Jacobian ∂g/∂z is the exact one from
//! the residuals' dual numbers (chain rule through x = A·z + c), and the box l, u the bounds of
//! the reduced unknowns intersected with z₀ ± h, h the smaller of
//! [`crate::model::nonlinear::NonlinearOptions::search_box`] and
//! [`crate::model::nonlinear::NonlinearOptions::search_box_relative`]·(1 + ‖z₀‖∞).
//! SLSQP does not need J to have full row rank, which is why it is the fallback for singular
//! and degenerate starts.
//!
//! The callbacks run inside C code and must not unwind: evaluation errors are stored and NaN is
//! returned, and the stored error is reported after the optimizer returns.
//!
//! Only problems within [`crate::model::nonlinear::slsqp_supports`] reach NLopt: at most as many
//! equality rows as unknowns (a caller with more rows hands over an independent subset, which
//! [`run`] evaluates out of the full residual vector) and a bounded size.

use std::cell::{Cell, RefCell};

use nlopt::{Algorithm, Nlopt, Target};

use crate::linalg::evaluator::Evaluator;
use crate::model::errors::{Error, Result};
use crate::model::options::Options;
use crate::model::problem::Problem;
use crate::solvers::objective::ObjectiveEval;

/// How an SLSQP run ended (the point is returned beside it).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SlsqpRun {
    /// Constraint evaluations made (one per SLSQP iterate or line-search point).
    pub(crate) evaluations: usize,
    /// NLopt's stopping state, as text.
    pub(crate) state: String,
}

/// What the callbacks share (they are `Fn`, so the mutable parts sit in cells).
struct Shared<'a> {
    problem: &'a Problem,
    evaluator: RefCell<&'a mut Evaluator>,
    objective: RefCell<ObjectiveEval>,
    reference: &'a [f64],
    options: &'a Options,
    /// The rows handed to SLSQP (`None`: all), and for each problem row its position among
    /// them.
    rows: Option<(&'a [usize], Vec<Option<usize>>)>,
    /// All residuals, when only a subset of rows is handed over.
    all: RefCell<Vec<f64>>,
    evaluations: Cell<usize>,
    error: RefCell<Option<Error>>,
}

impl Shared<'_> {
    fn record(&self, e: Error) {
        if let Ok(mut slot) = self.error.try_borrow_mut() {
            if slot.is_none() {
                *slot = Some(e);
            }
        }
    }

    fn objective(&self, z: &[f64], gradient: Option<&mut [f64]>) -> f64 {
        let (Ok(ev), Ok(mut obj)) = (self.evaluator.try_borrow(), self.objective.try_borrow_mut())
        else {
            return f64::NAN;
        };
        obj.value(
            &self.options.nonlinear.objective,
            self.problem,
            &ev.map,
            self.reference,
            z,
            gradient,
        )
    }

    fn constraints(&self, out: &mut [f64], z: &[f64], gradient: Option<&mut [f64]>) {
        self.evaluations.set(self.evaluations.get() + 1);
        let Ok(mut ev) = self.evaluator.try_borrow_mut() else {
            out.fill(f64::NAN);
            return;
        };
        let n = z.len();
        let Ok(mut all) = self.all.try_borrow_mut() else {
            out.fill(f64::NAN);
            return;
        };
        let g: &mut [f64] = if self.rows.is_some() { &mut all } else { out };
        let outcome = match gradient {
            None => ev.residuals(self.problem, z, g),
            Some(grad) => ev.linearize(self.problem, z, g).map(|()| {
                grad.fill(0.0);
                for &(i, j, v) in ev.triplets() {
                    let row = match &self.rows {
                        Some((_, position)) => position.get(i).copied().flatten(),
                        None => Some(i),
                    };
                    if let Some(slot) = row.and_then(|r| grad.get_mut(r * n + j)) {
                        *slot += v;
                    }
                }
            }),
        };
        if let Some((subset, _)) = &self.rows {
            for (slot, &r) in out.iter_mut().zip(subset.iter()) {
                *slot = all.get(r).copied().unwrap_or(f64::NAN);
            }
        }
        if let Err(e) = outcome {
            out.fill(f64::NAN);
            self.record(e);
        }
    }
}

/// Runs SLSQP from `start` (clamped into the box) with the objective measured from
/// `reference`, returning the final point whatever NLopt's verdict (the caller validates it).
/// With `rows`, only those residual rows (indices into the problem's rows, each at most once)
/// are equality constraints; the caller still validates every row.
///
/// # Errors
/// [`Error::OutsideSolverLimits`] when the problem (or the row subset) lies outside
/// [`crate::model::nonlinear::slsqp_supports`] — nothing is handed to NLopt then; an evaluation error
/// raised inside a callback, or [`Error::OptimizerFailed`] when NLopt refuses the setup.
pub(crate) fn run(
    problem: &Problem,
    ev: &mut Evaluator,
    start: &[f64],
    reference: &[f64],
    rows: Option<&[usize]>,
    options: &Options,
) -> Result<(Vec<f64>, SlsqpRun)> {
    let n = ev.cols();
    let all_rows = ev.rows();
    let m = rows.map_or(all_rows, <[usize]>::len);
    crate::model::nonlinear::slsqp_supports(n, m)?;
    crate::model::errors::check_len("SLSQP start", n, start.len())?;
    crate::model::errors::check_len("SLSQP reference", n, reference.len())?;
    let rows = match rows {
        Some(subset) => {
            let mut position = vec![None; all_rows];
            for (k, &r) in subset.iter().enumerate() {
                match position.get_mut(r) {
                    Some(slot @ None) => *slot = Some(k),
                    _ => {
                        return Err(Error::Dimension {
                            what: "SLSQP row subset (a row out of range or repeated)",
                            expected: all_rows,
                            found: r,
                        })
                    }
                }
            }
            Some((subset, position))
        }
        None => None,
    };
    let settings = &options.nonlinear;
    let half = settings.search_box_half_width(reference);
    let lower: Vec<f64> = (0..n)
        .map(|k| ev.lower[k].max(reference[k] - half))
        .collect();
    let upper: Vec<f64> = (0..n)
        .map(|k| ev.upper[k].min(reference[k] + half))
        .collect();
    let mut z: Vec<f64> = (0..n)
        .map(|k| start[k].max(lower[k]).min(upper[k]))
        .collect();
    if n == 0 {
        return Ok((
            z,
            SlsqpRun {
                evaluations: 0,
                state: "nothing to optimize".to_owned(),
            },
        ));
    }
    let shared = Shared {
        problem,
        objective: RefCell::new(ObjectiveEval::new(problem)),
        evaluator: RefCell::new(ev),
        reference,
        options,
        all: RefCell::new(vec![0.0; if rows.is_some() { all_rows } else { 0 }]),
        rows,
        evaluations: Cell::new(0),
        error: RefCell::new(None),
    };
    let failed = |what: &str, e: nlopt::FailState| Error::OptimizerFailed {
        solver: "SLSQP",
        detail: format!("{what}: {e:?}"),
    };
    let objective = |z: &[f64], g: Option<&mut [f64]>, _: &mut ()| shared.objective(z, g);
    let mut opt = Nlopt::new(Algorithm::Slsqp, n, objective, Target::Minimize, ());
    opt.set_lower_bounds(&lower)
        .map_err(|e| failed("lower bounds", e))?;
    opt.set_upper_bounds(&upper)
        .map_err(|e| failed("upper bounds", e))?;
    if m > 0 {
        let tolerances = vec![0.01 * options.tolerance; m];
        let constraint = |out: &mut [f64], z: &[f64], g: Option<&mut [f64]>, _: &mut ()| {
            shared.constraints(out, z, g);
        };
        opt.add_equality_mconstraint(m, constraint, (), &tolerances)
            .map_err(|e| failed("constraints", e))?;
    }
    opt.set_xtol_rel(settings.slsqp_xtol_rel)
        .map_err(|e| failed("x tolerance", e))?;
    opt.set_maxeval(settings.slsqp_max_evaluations)
        .map_err(|e| failed("evaluation limit", e))?;
    let state = match opt.optimize(&mut z) {
        Ok((s, _)) => format!("{s:?}"),
        Err((s, _)) => format!("{s:?}"),
    };
    drop(opt);
    if let Some(e) = shared.error.take() {
        return Err(e);
    }
    Ok((
        z,
        SlsqpRun {
            evaluations: shared.evaluations.get(),
            state,
        },
    ))
}
