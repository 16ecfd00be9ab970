//! camber-py: the Python package `camber`, built by maturin into an abi3 wheel (CPython ≥ 3.9).
//!
//! ```text
//! pip install ./crates/camber-py
//! python -c "import camber, numpy as np; c = camber.BezierCurve([[0, 0], [1, 2], [3, 0]]); print(c.evaluate(np.linspace(0, 1, 5)))"
//! ```
//!
//! # Usage
//! The native module `camber._native` is re-exported by the package `camber` (python/camber):
//! curves (`BezierCurve`, `BSplineCurve`, `NurbsCurve`, `HermiteCurve`) from numpy arrays, with
//! evaluation vectorised over arrays of parameters; sketches (`Sketch`) with every constraint
//! kind, solve, analysis, drags and iterative displacement; custom constraints written in
//! Python and differentiated exactly with dual numbers; `solve_many` for batches on rayon.
//! docs/python.md is the guide.
//!
//! # Design
//! The bindings add no mathematics of their own: each method converts its arguments, calls
//! the library with the GIL released where it loops or solves, and converts the result (reports
//! cross as dicts through their serde form). Every library error becomes an exception of the
//! `CamberError` hierarchy with the library's message ([`errors`]).

pub mod arrays;
pub mod batch;
pub mod composite;
pub mod curve;
pub mod curve_kinds;
pub mod curve_ops;
pub mod custom;
pub mod dxf;
pub mod errors;
pub mod expression;
pub mod interrupt;
pub mod json;
pub mod sketch;
pub mod surface;

use pyo3::prelude::*;

/// The native module: every class and function of the package.
#[pymodule(name = "_native")]
fn camber_native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    errors::register(m)?;
    curve_kinds::register(m)?;
    curve_ops::register(m)?;
    sketch::register(m)?;
    m.add_function(wrap_pyfunction!(batch::solve_many, m)?)?;
    m.add_function(wrap_pyfunction!(dxf::read_dxf, m)?)?;
    m.add_function(wrap_pyfunction!(dxf::write_dxf, m)?)?;
    m.add_function(wrap_pyfunction!(eval_loop_seconds, m)?)?;
    m.add_function(wrap_pyfunction!(custom::custom_derivatives, m)?)?;
    m.add_function(wrap_pyfunction!(surface::creased_face_case, m)?)?;
    m.add_function(wrap_pyfunction!(surface::deform_case_to_g1, m)?)?;
    Ok(())
}

/// Seconds the plain Rust loop takes to evaluate `curve` at `n` parameters spread evenly over
/// its domain, timed inside Rust with no Python object involved: the reference of the
/// vectorised-evaluation benchmark (`Curve.evaluate` on a numpy array of the same parameters
/// is compared with it; see docs/python.md).
#[pyfunction]
#[pyo3(name = "_eval_loop_seconds")]
fn eval_loop_seconds(py: Python<'_>, curve: PyRef<'_, curve::Curve>, n: usize) -> PyResult<f64> {
    let inner = &curve.inner;
    py.detach(|| {
        let (a, b) = curve::each!(inner, c => camber_geom::ParametricCurve::domain(c));
        let step = if n > 1 { (b - a) / (n - 1) as f64 } else { 0.0 };
        let us: Vec<f64> = (0..n).map(|i| (a + step * i as f64).min(b)).collect();
        let start = std::time::Instant::now();
        let flat = curve::each!(inner, c => curve::points_flat(c, &us));
        let elapsed = start.elapsed().as_secs_f64();
        std::hint::black_box(flat).map(|_| elapsed)
    })
    .map_err(errors::geometry)
}
