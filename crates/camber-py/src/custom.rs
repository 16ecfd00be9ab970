//! Custom constraints written in Python, with exact derivatives from dual numbers.
//!
//! The user writes `residual(x)` over generic numbers (`x` a list of the argument values,
//! points as two entries), returning `dim` values. camber wraps it as a plain
//! [`camber_solve::Residual`] whose generic `eval::<T>` works for every scalar type the solver
//! uses:
//!
//! - at `f64` it calls `residual` with floats;
//! - for first derivatives (`Dual64`, `DualSVec64<N>`) it calls `num_dual.jacobian(residual,
//!   x)` once, which evaluates `residual` with num-dual's vector dual numbers: the exact
//!   Jacobian J, never a finite difference;
//! - for second derivatives (the hyper-dual types of Newton's Hessian terms) it calls
//!   `num_dual.hessian` once per row, giving each row's exact Hessian Hᵢ.
//!
//! The value at the dual point then follows from the exact Taylor polynomial at the real parts
//! x₀: g(x₀ + δ) = g(x₀) + J·δ + ½·δᵀHᵢδ, evaluated in `T`, where δ holds the pure derivative
//! parts of the dual arguments. A first-order dual number drops δ·δ, so this reproduces J
//! exactly; a second-order one keeps it and reproduces H exactly. Results are cached for the
//! last point, so the several dual passes of one Jacobian call Python once.
//!
//! **Cost per evaluation**: one call of `residual` with floats for the values; one call with
//! vector duals (length n, the number of unknowns read) for a Jacobian; `dim` calls for the
//! Hessians. Python exceptions raised inside `residual` are kept and raised again when the
//! solve returns (the solver meanwhile sees NaN).

use std::any::TypeId;
use std::sync::Mutex;

use camber_sketch::{Arg, ArgKind, Args, Custom, CustomResidual};
use camber_solve::scalar::{cst, re};
use camber_solve::{Residual, Scalar};
use num_dual::{Dual64, DualSVec64};
use pyo3::prelude::*;

use crate::errors;
use crate::json::to_value;

/// The first Python error a residual raised during the current solve.
static PENDING: Mutex<Option<PyErr>> = Mutex::new(None);

fn keep(err: PyErr) {
    if let Ok(mut slot) = PENDING.lock() {
        if slot.is_none() {
            *slot = Some(err);
        }
    }
}

/// Raises the error a Python residual raised during the last solve, if any.
pub fn raise_pending(_py: Python<'_>) -> PyResult<()> {
    let err = PENDING.lock().ok().and_then(|mut slot| slot.take());
    match err {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

/// How many derivative orders the scalar type `T` carries: 0 for `f64`, 1 for the first-order
/// dual numbers of Jacobians, 2 otherwise (the Hessian's hyper-dual and second-order types).
fn order_of<T: Scalar>() -> u8 {
    let t = TypeId::of::<T>();
    if t == TypeId::of::<f64>() {
        return 0;
    }
    macro_rules! first_order {
        ($($n:literal),*) => {
            t == TypeId::of::<Dual64>() $(|| t == TypeId::of::<DualSVec64<$n>>())*
        };
    }
    if first_order!(1, 2, 3, 4, 5, 6, 7, 8) {
        1
    } else {
        2
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
                keep(err);
                None
            }
        }
    }
}

impl Residual for PyResidual {
    fn name(&self) -> &str {
        &self.name
    }
    fn dim(&self) -> usize {
        self.dim
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(self.sizes.clone())
    }
    fn is_affine(&self) -> bool {
        self.affine
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let flat: Vec<T> = x.iter().flat_map(|b| b.iter().copied()).collect();
        let reals: Vec<f64> = flat.iter().map(|v| re(*v)).collect();
        let order = order_of::<T>();
        let Some(e) = self.expansion(&reals, order) else {
            out.iter_mut().for_each(|o| *o = cst(f64::NAN));
            return;
        };
        let n = flat.len();
        if order == 0 {
            for (o, v) in out.iter_mut().zip(&e.value) {
                *o = cst(*v);
            }
            return;
        }
        // δ: the pure derivative parts of the arguments.
        let delta: Vec<T> = flat.iter().zip(&reals).map(|(v, r)| *v - cst(*r)).collect();
        for (i, o) in out.iter_mut().enumerate() {
            let mut g: T = cst(e.value[i]);
            for (j, d) in e.jacobian[i * n..(i + 1) * n].iter().zip(&delta) {
                g += cst::<T>(*j) * *d;
            }
            if order == 2 {
                let h = &e.hessians[i * n * n..(i + 1) * n * n];
                for k in 0..n {
                    for l in 0..n {
                        g += cst::<T>(0.5 * h[k * n + l]) * delta[k] * delta[l];
                    }
                }
            }
            *o = g;
        }
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

/// The custom residual of a constraint: the Python function over every block its arguments
/// read, in order (a curve argument reads all its control points, x then y of each).
#[derive(Debug)]
struct PyCustom {
    residual: PyResidual,
    kinds: Vec<ArgKind>,
}

impl CustomResidual for PyCustom {
    fn name(&self) -> &str {
        &self.residual.name
    }
    fn dim(&self) -> usize {
        self.residual.dim
    }
    fn arg_kinds(&self) -> Vec<ArgKind> {
        self.kinds.clone()
    }
    fn eval<T: Scalar>(&self, args: &Args<'_, T>, out: &mut [T]) {
        Residual::eval(&self.residual, args.blocks(), out);
    }
    fn is_affine(&self) -> bool {
        self.residual.affine
    }
}

/// A custom constraint calling `func` (see the module documentation). `func` receives the
/// values of every argument in order, flattened: a point gives x, y; a radius, a free
/// parameter or an own parameter one number; a curve (`{"curve": id}`) the coordinates of all
/// its control points (x₀, y₀, x₁, y₁, …), its degree, knots and weights staying data.
pub fn custom(
    func: Py<PyAny>,
    args: &[Bound<'_, PyAny>],
    dim: usize,
    name: String,
    affine: bool,
) -> PyResult<Custom> {
    let args: Vec<Arg> = args.iter().map(arg).collect::<PyResult<_>>()?;
    let kinds: Vec<ArgKind> = args.iter().map(Arg::kind).collect();
    let sizes = kinds
        .iter()
        .map(|k| if *k == ArgKind::Point { 2 } else { 1 })
        .collect();
    Ok(Custom::with_args(
        PyCustom {
            residual: PyResidual {
                func,
                name,
                dim,
                sizes,
                affine,
                cache: Mutex::new(None),
            },
            kinds,
        },
        args,
    ))
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
    use camber_solve::DynResidual;
    let n: usize = sizes.iter().sum();
    if n != x.len() || weights.len() != dim {
        return Err(errors::input(format!(
            "need {n} values of x (found {}) and {dim} weights (found {})",
            x.len(),
            weights.len()
        )));
    }
    let r = PyResidual {
        func,
        name: "check".into(),
        dim,
        sizes: sizes.clone(),
        affine: false,
        cache: Mutex::new(None),
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
    raise_pending(py)?;
    done.map_err(|e| errors::SolveError::new_err(e.to_string()))?;
    Ok((
        values,
        jac.chunks(n.max(1)).map(<[f64]>::to_vec).collect(),
        hess.chunks(n.max(1)).map(<[f64]>::to_vec).collect(),
    ))
}
