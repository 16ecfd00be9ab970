//! Custom constraints written in Python, with exact derivatives from dual numbers.
//!
//! The user writes `residual(x)` over generic numbers (`x` a list of the argument values,
//! points as two entries), returning `dim` values. camber wraps it as a boxed residual
//! ([`camber_solve::DynResidual`], the object-safe face a problem stores) that gives its own
//! derivatives, exactly, from num-dual's Python package:
//!
//! - values: `residual` called with floats;
//! - the Jacobian: `num_dual.jacobian(residual, x)` once, which evaluates `residual` with
//!   num-dual's vector dual numbers: the exact J, never a finite difference;
//! - the weighted Hessian Σ λᵢ·Hᵢ of Newton's second-order terms: `num_dual.hessian` once per
//!   row, each row's exact Hᵢ.
//!
//! Results are cached for the last point, so the values, Jacobian and Hessian of one iterate
//! call Python once each at most.
//!
//! **Cost per evaluation**: one call of `residual` with floats for the values; one call with
//! vector duals (length n, the number of unknowns read) for a Jacobian; `dim` calls for the
//! Hessians. Python exceptions raised inside `residual` are kept and raised again when the
//! solve returns (the solver meanwhile sees NaN).

use std::any::Any;
use std::sync::{Arc, Mutex};

use camber_sketch::{Arg, ArgKind, Custom};
use camber_solve::DynResidual;
use pyo3::prelude::*;

use crate::errors;
use crate::json::to_value;

/// Where a Python residual keeps the first exception it raised, until the call that ran it
/// collects it ([`Raised`]). One slot per residual (clones of a sketch share it), so batch
/// items and concurrent calls keep their errors apart.
type Slot = Arc<Mutex<Option<PyErr>>>;

/// The exception slots of every Python residual of a sketch, gathered before a call runs and
/// read after it ([`Raised::finish`]).
#[derive(Debug, Default)]
pub struct Raised(Vec<(String, Slot)>);

impl Raised {
    /// The slots of the Python residuals among `sketch`'s custom constraints.
    pub fn of(sketch: &camber_sketch::Sketch) -> Self {
        Self(
            sketch
                .constraints()
                .filter_map(|(_, c)| c.as_custom())
                .filter_map(|c| c.residual_any()?.downcast_ref::<PyResidual>())
                .map(|r| (r.name.clone(), r.raised.clone()))
                .collect(),
        )
    }

    /// The first exception kept by any of the residuals, with the residual's name; every slot
    /// is emptied.
    pub fn take(&self) -> Option<(String, PyErr)> {
        let mut first = None;
        for (name, slot) in &self.0 {
            let err = slot.lock().ok().and_then(|mut s| s.take());
            if let (None, Some(err)) = (&first, err) {
                first = Some((name.clone(), err));
            }
        }
        first
    }

    /// The first exception kept, still in its slot (for batch items sharing residuals).
    pub fn peek(&self, py: Python<'_>) -> Option<(String, PyErr)> {
        self.0.iter().find_map(|(name, slot)| {
            let s = slot.lock().ok()?;
            s.as_ref().map(|e| (name.clone(), e.clone_ref(py)))
        })
    }

    /// The outcome of a call that ran these residuals ([`crate::interrupt::run`]'s result): an
    /// interrupted call raises the interrupt; a failed call raises the exception a residual
    /// raised (the cause of its failure; `failure` converts the library's error otherwise); a
    /// call that succeeded although a residual raised at some trial point, its answer checked
    /// at a point where no residual raised, returns its result and issues a `RuntimeWarning`
    /// naming the exception. Every slot is emptied.
    pub fn finish<T, E>(
        &self,
        py: Python<'_>,
        outcome: PyResult<Result<T, E>>,
        failure: impl FnOnce(E) -> PyErr,
    ) -> PyResult<T> {
        let kept = self.take();
        let outcome = outcome?;
        match (outcome, kept) {
            (Err(_), Some((_, err))) => Err(err),
            (Err(e), None) => Err(failure(e)),
            (Ok(v), None) => Ok(v),
            (Ok(v), Some((name, err))) => {
                let message = format!(
                    "custom constraint {name}: the residual raised {} at a trial point; the \
                     solve went on without that point and its answer is checked",
                    err.value(py)
                        .repr()
                        .map(|r| r.to_string())
                        .unwrap_or_default()
                );
                let category = py.get_type::<pyo3::exceptions::PyRuntimeWarning>();
                PyErr::warn(py, &category, &std::ffi::CString::new(message)?, 1)?;
                Ok(v)
            }
        }
    }
}

/// g, J and the Hessians at one real point.
#[derive(Debug, Clone, Default)]
struct Expansion {
    x: Vec<f64>,
    order: u8,
    value: Vec<f64>,
    /// dim × n, row major.
    jacobian: Vec<f64>,
    /// dim × n × n.
    hessians: Vec<f64>,
}

/// A Python function as a camber residual (see the module documentation).
pub struct PyResidual {
    func: Py<PyAny>,
    name: String,
    dim: usize,
    sizes: Vec<usize>,
    affine: bool,
    cache: Mutex<Option<Expansion>>,
    /// The first exception `func` raised since the last call collected it.
    raised: Slot,
}

impl std::fmt::Debug for PyResidual {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PyResidual")
            .field("name", &self.name)
            .field("dim", &self.dim)
            .field("sizes", &self.sizes)
            .finish()
    }
}

/// A float from a Python number or from the `.value` of a dual number.
fn real(obj: &Bound<'_, PyAny>) -> PyResult<f64> {
    match obj.extract::<f64>() {
        Ok(v) => Ok(v),
        Err(_) => obj.getattr("value")?.extract(),
    }
}

impl PyResidual {
    /// Evaluates the function at x with the derivatives `order` needs.
    fn expand(&self, x: &[f64], order: u8) -> PyResult<Expansion> {
        Python::attach(|py| {
            let n = x.len();
            let mut e = Expansion {
                x: x.to_vec(),
                order,
                ..Expansion::default()
            };
            let check = |len: usize| {
                if len == self.dim {
                    Ok(())
                } else {
                    Err(errors::SketchError::new_err(format!(
                        "custom constraint {}: residual returned {len} values, declared dim {}",
                        self.name, self.dim
                    )))
                }
            };
            if order == 0 {
                let out = self.func.bind(py).call1((x.to_vec(),))?;
                let values: Vec<Bound<'_, PyAny>> = out.try_iter()?.collect::<PyResult<_>>()?;
                check(values.len())?;
                e.value = values.iter().map(real).collect::<PyResult<_>>()?;
                return Ok(e);
            }
            let nd = py.import("num_dual")?;
            let (value, jac): (Vec<f64>, Vec<Vec<f64>>) = nd
                .getattr("jacobian")?
                .call1((self.func.bind(py), x.to_vec()))?
                .extract()?;
            check(value.len())?;
            e.value = value;
            e.jacobian = jac.into_iter().flatten().collect();
            if e.jacobian.len() != self.dim * n {
                return Err(errors::SketchError::new_err(format!(
                    "custom constraint {}: Jacobian of the wrong shape",
                    self.name
                )));
            }
            if order == 2 {
                let helpers = py.import("camber.custom")?;
                for i in 0..self.dim {
                    let row = helpers.getattr("row")?.call1((self.func.bind(py), i))?;
                    let (_, _, h): (f64, Vec<f64>, Vec<Vec<f64>>) =
                        nd.getattr("hessian")?.call1((row, x.to_vec()))?.extract()?;
                    e.hessians.extend(h.into_iter().flatten());
                }
                if e.hessians.len() != self.dim * n * n {
                    return Err(errors::SketchError::new_err(format!(
                        "custom constraint {}: Hessian of the wrong shape",
                        self.name
                    )));
                }
            }
            Ok(e)
        })
    }

    /// The expansion at x to at least `order`, from the cache or from Python.
    fn expansion(&self, x: &[f64], order: u8) -> Option<Expansion> {
        if let Ok(cache) = self.cache.lock() {
            if let Some(e) = cache.as_ref() {
                if e.order >= order
                    && e.x.len() == x.len()
                    && e.x.iter().zip(x).all(|(a, b)| a.to_bits() == b.to_bits())
                {
                    return Some(e.clone());
                }
            }
        }
        match self.expand(x, order) {
            Ok(e) => {
                if let Ok(mut cache) = self.cache.lock() {
                    *cache = Some(e.clone());
                }
                Some(e)
            }
            Err(err) => {
                if let Ok(mut slot) = self.raised.lock() {
                    slot.get_or_insert(err);
                }
                None
            }
        }
    }
}

impl PyResidual {
    /// The expansion at the flattened blocks `x` to `order`, or NaN values (the Python error
    /// is kept for the end of the solve).
    fn at(&self, x: &[&[f64]], order: u8) -> Option<Expansion> {
        let flat: Vec<f64> = x.iter().flat_map(|b| b.iter().copied()).collect();
        self.expansion(&flat, order)
    }

    fn check_out(
        &self,
        what: &'static str,
        expected: usize,
        found: usize,
    ) -> camber_solve::Result<()> {
        if expected == found {
            Ok(())
        } else {
            Err(camber_solve::Error::Dimension {
                what,
                expected,
                found,
            })
        }
    }
}

/// The Python residual as camber-solve's object-safe face: values, Jacobian and weighted
/// Hessian straight from its expansion (see the module documentation).
impl DynResidual for PyResidual {
    fn name(&self) -> &str {
        &self.name
    }
    fn dim(&self) -> usize {
        self.dim
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(self.sizes.clone())
    }
    fn accepts_block_sizes(&self, _sizes: &[usize]) -> bool {
        // Python reads the flattened arguments, whatever their blocks: a curve argument gives
        // one block per control point, known only when the component is built.
        true
    }
    fn is_affine(&self) -> bool {
        self.affine
    }
    fn values(&self, x: &[&[f64]], out: &mut [f64]) -> camber_solve::Result<()> {
        self.check_out("residual output", self.dim, out.len())?;
        match self.at(x, 0) {
            Some(e) => out.copy_from_slice(&e.value),
            None => out.fill(f64::NAN),
        }
        Ok(())
    }
    fn jacobian(
        &self,
        x: &[&[f64]],
        values: &mut [f64],
        jac: &mut [f64],
    ) -> camber_solve::Result<()> {
        let n: usize = x.iter().map(|b| b.len()).sum();
        self.check_out("residual output", self.dim, values.len())?;
        self.check_out("Jacobian", self.dim * n, jac.len())?;
        match self.at(x, 1) {
            Some(e) => {
                values.copy_from_slice(&e.value);
                jac.copy_from_slice(&e.jacobian);
            }
            None => {
                values.fill(f64::NAN);
                jac.fill(f64::NAN);
            }
        }
        Ok(())
    }
    fn weighted_hessian(
        &self,
        x: &[&[f64]],
        weights: &[f64],
        active: &[bool],
        out: &mut [f64],
    ) -> camber_solve::Result<bool> {
        let n: usize = x.iter().map(|b| b.len()).sum();
        self.check_out("Hessian weights", self.dim, weights.len())?;
        self.check_out("Hessian", n * n, out.len())?;
        self.check_out("active blocks", x.len(), active.len())?;
        // Whether each flattened unknown belongs to an active block.
        let live: Vec<bool> = x
            .iter()
            .zip(active)
            .flat_map(|(b, a)| std::iter::repeat_n(*a, b.len()))
            .collect();
        out.fill(0.0);
        let Some(e) = self.at(x, 2) else {
            out.fill(f64::NAN);
            return Ok(true);
        };
        for (i, w) in weights.iter().enumerate() {
            let h = &e.hessians[i * n * n..(i + 1) * n * n];
            for k in (0..n).filter(|k| live[*k]) {
                for l in (0..n).filter(|l| live[*l]) {
                    out[k * n + l] += w * h[k * n + l];
                }
            }
        }
        Ok(true)
    }
    fn as_any(&self) -> &dyn Any {
        self
    }
}

/// One argument of a custom constraint from Python: an int (a point entity) or its file form
/// (`{"point": ref}`, `{"radius": circle}`, `{"curve": curve}`, `{"free_of": [constraint,
/// index]}`, `{"param": start}`).
fn arg(obj: &Bound<'_, PyAny>) -> PyResult<Arg> {
    if let Ok(id) = obj.extract::<u64>() {
        return Ok(Arg::Point(camber_sketch::PointRef::Point(
            camber_sketch::EntityId(id),
        )));
    }
    serde_json::from_value(to_value(obj)?)
        .map_err(|e| errors::SketchError::new_err(format!("invalid custom argument: {e}")))
}

/// `func` wrapped so that it always returns a list (`camber.custom.rows`).
fn listed(py: Python<'_>, func: Py<PyAny>) -> PyResult<Py<PyAny>> {
    Ok(py
        .import("camber.custom")?
        .getattr("rows")?
        .call1((func,))?
        .unbind())
}

/// A custom constraint calling `func` (see the module documentation). `func` receives the
/// values of every argument in order, flattened: a point gives x, y; a radius, a free
/// parameter or an own parameter one number; a curve (`{"curve": id}`) the coordinates of all
/// its control points (x₀, y₀, x₁, y₁, …), its degree, knots and weights staying data.
///
/// `dim` is checked before anything is sized by it: at least 1, at most
/// [`camber_sketch::constraints::custom::MAX_CUSTOM_ROWS`]. A one-row residual may return its
/// number alone (`camber.custom.rows` wraps `func`).
pub fn custom(
    py: Python<'_>,
    func: Py<PyAny>,
    args: &[Bound<'_, PyAny>],
    dim: usize,
    name: String,
    affine: bool,
) -> PyResult<Custom> {
    let max = camber_sketch::constraints::custom::MAX_CUSTOM_ROWS;
    if dim == 0 || dim > max {
        return Err(errors::SketchError::new_err(format!(
            "custom constraint {name}: dim is {dim}, the number of rows its residual returns must \
             be between 1 and {max}"
        )));
    }
    let func = listed(py, func)?;
    let args: Vec<Arg> = args.iter().map(arg).collect::<PyResult<_>>()?;
    let kinds: Vec<ArgKind> = args.iter().map(Arg::kind).collect();
    let sizes = kinds
        .iter()
        .map(|k| if *k == ArgKind::Point { 2 } else { 1 })
        .collect();
    let residual = PyResidual {
        func,
        name,
        dim,
        sizes,
        affine,
        cache: Mutex::new(None),
        raised: Slot::default(),
    };
    Ok(Custom::boxed(Arc::new(residual), kinds, args))
}

/// Values, Jacobian and weighted Hessian Σ λᵢ∇²gᵢ of a Python residual at x, computed exactly
/// as a solve computes them (camber-solve's dual-number passes through [`PyResidual`]): for
/// tests and for users checking a residual. `sizes` gives the blocks (2 for a point, 1 for a
/// number).
#[pyfunction]
#[pyo3(name = "_custom_derivatives")]
#[allow(clippy::type_complexity)] // the three arrays are the function's whole result
pub fn custom_derivatives(
    py: Python<'_>,
    func: Py<PyAny>,
    sizes: Vec<usize>,
    x: Vec<f64>,
    dim: usize,
    weights: Vec<f64>,
) -> PyResult<(Vec<f64>, Vec<Vec<f64>>, Vec<Vec<f64>>)> {
    let n: usize = sizes.iter().sum();
    if n != x.len() || weights.len() != dim {
        return Err(errors::input(format!(
            "need {n} values of x (found {}) and {dim} weights (found {})",
            x.len(),
            weights.len()
        )));
    }
    let r = PyResidual {
        func: listed(py, func)?,
        name: "check".into(),
        dim,
        sizes: sizes.clone(),
        affine: false,
        cache: Mutex::new(None),
        raised: Slot::default(),
    };
    let mut blocks: Vec<&[f64]> = Vec::with_capacity(sizes.len());
    let mut at = 0;
    for s in &sizes {
        blocks.push(&x[at..at + s]);
        at += s;
    }
    let mut values = vec![0.0; dim];
    let mut jac = vec![0.0; dim * n];
    let mut hess = vec![0.0; n * n];
    let active = vec![true; sizes.len()];
    let done = DynResidual::jacobian(&r, &blocks, &mut values, &mut jac)
        .and_then(|()| DynResidual::weighted_hessian(&r, &blocks, &weights, &active, &mut hess));
    if let Some(err) = r.raised.lock().ok().and_then(|mut s| s.take()) {
        return Err(err);
    }
    done.map_err(|e| errors::SolveError::new_err(e.to_string()))?;
    Ok((
        values,
        jac.chunks(n.max(1)).map(<[f64]>::to_vec).collect(),
        hess.chunks(n.max(1)).map(<[f64]>::to_vec).collect(),
    ))
}
