//! `solve_many`: independent sketches solved in parallel on a rayon pool, the GIL released.
//!
//! Each item is a `Sketch` (solved in place, like `Sketch.solve`) or a path to a sketch file
//! (read and solved on the pool). One failure does not stop the others: every item gets its
//! own result, a Python exception raised by an item's custom residual included. The items are
//! solved by one `camber_sketch::solve_many` call, so items of one structure (variants of one
//! design) are solved on one prepared problem per worker. The pool has at most one worker per
//! core ([`workers`]); Ctrl-C stops the batch (the running solves at their next evaluation,
//! the others at their first) and raises `KeyboardInterrupt`, leaving every item as it was.

use std::path::PathBuf;

use camber_sketch::SketchReport;
use camber_solve::CancelFlag;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;

use crate::custom::Raised;
use crate::errors;
use crate::interrupt;
use crate::sketch::{report_object, Sketch};

enum Job {
    Sketch(Box<camber_sketch::Sketch>),
    Path(PathBuf),
}

struct Outcome {
    sketch: Option<camber_sketch::Sketch>,
    result: Result<SketchReport, String>,
}

/// Reads (for a path) one item; `Err` for a file that cannot be read or parsed.
fn load(job: Job) -> Result<camber_sketch::Sketch, String> {
    match job {
        Job::Sketch(s) => Ok(*s),
        Job::Path(p) => std::fs::read_to_string(&p)
            .map_err(|e| format!("cannot read {}: {e}", p.display()))
            .and_then(|t| camber_sketch::file::from_json(&t).map_err(|e| e.to_string())),
    }
}

/// Reads the items and solves them all by one [`camber_sketch::solve_many`] call on the
/// current pool (one prepared problem per worker for items of one structure), watching
/// `cancel`: once the flag is raised the running solves stop at their next evaluation and the
/// others fail at their first.
fn run_all(jobs: Vec<Job>, cancel: &CancelFlag) -> Vec<Outcome> {
    let loaded: Vec<Result<camber_sketch::Sketch, String>> =
        jobs.into_par_iter().map(load).collect();
    let mut sketches = Vec::with_capacity(loaded.len());
    let loaded: Vec<Result<(), String>> = loaded
        .into_iter()
        .map(|l| {
            l.map(|mut sketch| {
                sketch.set_options(sketch.options().clone().with_cancel(Some(cancel.clone())));
                sketches.push(sketch);
            })
        })
        .collect();
    let results = camber_sketch::solve_many(&mut sketches);
    let mut solved = sketches.into_iter().zip(results);
    loaded
        .into_iter()
        .map(
            |l| match l.and_then(|()| solved.next().ok_or_else(|| "lost".to_owned())) {
                Ok((mut sketch, result)) => {
                    let result = result.map_err(|e| sketch.describe_error(&e));
                    sketch.set_options(sketch.options().clone().with_cancel(None));
                    Outcome {
                        sketch: Some(sketch),
                        result,
                    }
                }
                Err(e) => Outcome {
                    sketch: None,
                    result: Err(e),
                },
            },
        )
        .collect()
}

/// The workers of the pool: `threads` (all cores when None or 0), at most the cores the
/// machine has (`std::thread::available_parallelism`): more threads than cores only add
/// switching, and a count from a typing slip (`threads=10000`) would start that many threads.
pub fn workers(threads: Option<usize>) -> usize {
    let cores = std::thread::available_parallelism().map_or(1, std::num::NonZero::get);
    match threads {
        None | Some(0) => cores,
        Some(n) => n.min(cores),
    }
}

/// Solves independent sketches in parallel (rayon, `threads` workers, capped at the number of
/// cores; all cores when None).
///
/// `items` holds `Sketch` objects (solved in place on success) and paths of sketch files.
/// Returns one dict per item, in order: {"ok": bool, "report": SolveReport or None,
/// "error": message or None, "exception": the exception a custom residual of the item raised
/// when that made it fail, or None, "sketch": the solved Sketch (a failed item's unchanged;
/// None when a file could not be read)}.
///
/// With `parameters` (a dict name → list of values, all of one length n), `items` is one
/// sketch (a `Sketch` or a path, left unchanged) solved for each of the n rows of values:
/// one dict per variant, {"row", "ok", "max_residual", "error", every parameter's value, and
/// `"<constraint id>.<name>"` for every solved free parameter of an expression constraint}.
#[pyfunction]
#[pyo3(signature = (items, threads = None, parameters = None))]
pub fn solve_many(
    py: Python<'_>,
    items: Bound<'_, PyAny>,
    threads: Option<usize>,
    parameters: Option<std::collections::BTreeMap<String, Vec<f64>>>,
) -> PyResult<Vec<Py<PyAny>>> {
    if let Some(table) = parameters {
        return sweep(py, &items, threads, table);
    }
    let items: Vec<Bound<'_, PyAny>> = items.extract()?;
    let mut jobs = Vec::with_capacity(items.len());
    for item in &items {
        if let Ok(s) = item.cast::<Sketch>() {
            jobs.push(Job::Sketch(Box::new(s.borrow().inner.clone())));
        } else {
            let path: PathBuf = item.extract().map_err(|_| {
                errors::SketchError::new_err(format!(
                    "solve_many takes Sketch objects and paths, found {}",
                    item.get_type()
                        .name()
                        .map(|n| n.to_string())
                        .unwrap_or_default()
                ))
            })?;
            jobs.push(Job::Path(path));
        }
    }
    let raised: Vec<Raised> = items
        .iter()
        .map(|item| match item.cast::<Sketch>() {
            Ok(s) => Raised::of(&s.borrow().inner),
            Err(_) => Raised::default(),
        })
        .collect();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(workers(threads))
        .build()
        .map_err(|e| errors::CamberError::new_err(format!("cannot start the thread pool: {e}")))?;
    let outcomes = interrupt::run(py, |cancel| pool.install(|| run_all(jobs, cancel)));
    // The exceptions stay on the failed items they belong to (items copied from one sketch
    // share residuals, hence the look before the slots are emptied).
    let exceptions: Vec<Option<(String, PyErr)>> = match &outcomes {
        Ok(outcomes) => raised
            .iter()
            .zip(outcomes)
            .map(|(r, o)| o.result.as_ref().err().and(r.peek(py)))
            .collect(),
        Err(_) => Vec::new(),
    };
    for r in &raised {
        r.take();
    }
    let outcomes = outcomes?;
    let mut out = Vec::with_capacity(outcomes.len());
    for ((item, outcome), exception) in items.iter().zip(outcomes).zip(exceptions) {
        let d = PyDict::new(py);
        d.set_item("ok", outcome.result.is_ok())?;
        match (&outcome.result, exception) {
            (Ok(r), _) => {
                d.set_item("report", report_object(py, r)?)?;
                d.set_item("error", py.None())?;
                d.set_item("exception", py.None())?;
            }
            (Err(e), None) => {
                d.set_item("report", py.None())?;
                d.set_item("error", e)?;
                d.set_item("exception", py.None())?;
            }
            (Err(_), Some((name, exception))) => {
                let value = exception.value(py);
                d.set_item("report", py.None())?;
                d.set_item(
                    "error",
                    format!(
                        "custom constraint {name}: the residual raised {}",
                        value.repr()?
                    ),
                )?;
                d.set_item("exception", value)?;
            }
        }
        let sketch_obj: Py<PyAny> = match (item.cast::<Sketch>(), outcome.sketch) {
            (Ok(s), Some(solved)) => {
                if outcome.result.is_ok() {
                    s.borrow_mut().inner = solved;
                }
                s.clone().into_any().unbind()
            }
            (Err(_), Some(solved)) => Py::new(py, Sketch { inner: solved })?.into_any(),
            (_, None) => py.None(),
        };
        d.set_item("sketch", sketch_obj)?;
        out.push(d.into_any().unbind());
    }
    Ok(out)
}

/// `solve_many(sketch, parameters=…)`: one solve per row of the table.
fn sweep(
    py: Python<'_>,
    item: &Bound<'_, PyAny>,
    threads: Option<usize>,
    table: std::collections::BTreeMap<String, Vec<f64>>,
) -> PyResult<Vec<Py<PyAny>>> {
    use camber_sketch::parameters::sweep::{solve_variants, Table};
    let base = if let Ok(s) = item.cast::<Sketch>() {
        s.borrow().inner.clone()
    } else {
        let path: PathBuf = item.extract().map_err(|_| {
            errors::SketchError::new_err("with parameters, solve_many takes one Sketch or path")
        })?;
        let text = std::fs::read_to_string(&path).map_err(|e| {
            errors::FileError::new_err(format!("cannot read {}: {e}", path.display()))
        })?;
        camber_sketch::file::from_json(&text).map_err(errors::file)?
    };
    let table = Table::try_new(table.into_iter().collect()).map_err(errors::sketch)?;
    let rows = py
        .detach(|| solve_variants(&base, &table, threads))
        .map_err(errors::sketch)?;
    let mut out = Vec::with_capacity(rows.len());
    for r in rows {
        let d = PyDict::new(py);
        d.set_item("row", r.row)?;
        d.set_item("ok", r.ok)?;
        d.set_item("max_residual", r.max_residual)?;
        d.set_item("error", r.error)?;
        for (name, value) in table.row(r.row) {
            d.set_item(name, value)?;
        }
        for (id, name, value) in r.free {
            d.set_item(format!("{id}.{name}"), value)?;
        }
        out.push(d.into_any().unbind());
    }
    Ok(out)
}
