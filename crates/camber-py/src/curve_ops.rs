//! The curve operations beyond evaluation, as plain functions the classes call: arc length
//! and the arc-length map, curve–curve intersection and distance, offsets, fitting
//! (interpolation, least squares, fitting to a tolerance), and the parsing of their option
//! words. Every long loop runs with the GIL released; every library error becomes a
//! `GeometryError` with the library's message.

use camber_geom::arc_length::{self, ArcLengthMap as GeomArcLengthMap};
use camber_geom::extend::{CurveEnd, ExtensionContinuity};
use camber_geom::fit::{
    self, Fit, FitOptions, JointContinuity, KnotPlacement, ParameterMethod, SplitAt, SplitFit,
};
use camber_geom::queries::{
    curve_distance, intersect_curves_with_overlaps, BezierPieces, CurveCurveOptions,
    CurveIntersections, CurvePairPoint,
};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::arrays::{columns, vector, RealArray2};
use crate::curve::AnyCurve;
use crate::curve_kinds::wrap;
use crate::errors::{geometry, input};
use crate::interrupt::run_geometry;
use camber_geom::Budget;

/// `"start"` or `"end"`.
pub fn curve_end(word: &str) -> PyResult<CurveEnd> {
    match word.to_ascii_lowercase().as_str() {
        "start" => Ok(CurveEnd::Start),
        "end" => Ok(CurveEnd::End),
        _ => Err(input(format!(
            "end: expected \"start\" or \"end\", found {word:?}"
        ))),
    }
}

/// `"G1"` (a straight piece along the end tangent) or `"G2"` (the end piece continued).
pub fn continuity(word: &str) -> PyResult<ExtensionContinuity> {
    match word.to_ascii_uppercase().as_str() {
        "G1" => Ok(ExtensionContinuity::G1),
        "G2" => Ok(ExtensionContinuity::G2),
        _ => Err(input(format!(
            "continuity: expected \"G1\" or \"G2\", found {word:?}"
        ))),
    }
}

/// `"uniform"`, `"chord_length"` or `"centripetal"`.
fn parameter_method(word: &str) -> PyResult<ParameterMethod> {
    match word.to_ascii_lowercase().replace('-', "_").as_str() {
        "uniform" => Ok(ParameterMethod::Uniform),
        "chord_length" | "chord" => Ok(ParameterMethod::ChordLength),
        "centripetal" => Ok(ParameterMethod::Centripetal),
        _ => Err(input(format!(
            "method: expected \"uniform\", \"chord_length\" or \"centripetal\", found {word:?}"
        ))),
    }
}

/// The arc length between u0 and u1 (the whole domain when both are None).
pub fn length(
    py: Python<'_>,
    c: &AnyCurve,
    span: Option<(f64, f64)>,
    tolerance: f64,
) -> PyResult<f64> {
    run_geometry(py, |budget| {
        crate::curve::each!(c, c => {
            let (a, b) = span.unwrap_or_else(|| camber_geom::ParametricCurve::domain(c));
            arc_length::arc_length_between_with(c, a, b, tolerance, budget).map(|r| r.length)
        })
    })
}

/// The parameter at arc length s from the start, for one s or an array: one quadrature of
/// the curve (an `ArcLengthTable`) serves every s.
pub fn parameter_at_length(
    py: Python<'_>,
    c: &AnyCurve,
    s: &Bound<'_, PyAny>,
    tolerance: f64,
) -> PyResult<Py<PyAny>> {
    let table = run_geometry(
        py,
        |budget| crate::curve::each!(c, c => arc_length::ArcLengthTable::new(c, tolerance, budget)),
    )?;
    // Each parameter is a bounded Newton search on the table: short, no stop flag needed.
    let budget = Budget::default();
    crate::curve::scalar_map(
        py,
        s,
        |s| crate::curve::each!(c, c => table.parameter(c, s, &budget)),
    )
}

/// The arc-length parameterization of a curve, u(s), as a piecewise cubic interpolant of
/// the exact map whose measured error is within the tolerance it was made with:
/// `curve.arc_length_map(1e-8)`. `map.parameter(s)` takes a float or an array of arc lengths,
/// so `curve.evaluate(map.parameter(np.linspace(0, map.length, n)))` gives n points evenly
/// spaced along the curve.
#[pyclass(name = "ArcLengthMap", frozen, module = "camber._native")]
#[derive(Debug, Clone)]
pub struct ArcLengthMap {
    inner: GeomArcLengthMap<f64>,
}

#[pymethods]
impl ArcLengthMap {
    /// The total length of the curve.
    #[getter]
    fn length(&self) -> f64 {
        self.inner.length()
    }

    /// The largest |L(u(s)) − s| measured (length units).
    #[getter]
    fn max_error(&self) -> f64 {
        self.inner.max_error()
    }

    /// The tolerance the map was made to: the one asked for, or, when that was below what
    /// f64 resolves on the curve, that floor (compare it with what you asked).
    #[getter]
    fn tolerance(&self) -> f64 {
        self.inner.tolerance()
    }

    /// The number of interpolation nodes.
    #[getter]
    fn node_count(&self) -> usize {
        self.inner.node_count()
    }

    /// The parameter u(s) for arc lengths s (clamped to [0, length]): a float or an array.
    fn parameter(&self, py: Python<'_>, s: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let map = &self.inner;
        crate::curve::scalar_map(py, s, |s| map.parameter(s))
    }

    fn __repr__(&self) -> String {
        format!(
            "<ArcLengthMap length {} with {} nodes, error {:.1e}>",
            self.inner.length(),
            self.inner.node_count(),
            self.inner.max_error()
        )
    }
}

/// The arc-length map of a curve within `tolerance`.
pub fn arc_length_map(py: Python<'_>, c: &AnyCurve, tolerance: f64) -> PyResult<ArcLengthMap> {
    let inner = run_geometry(
        py,
        |budget| crate::curve::each!(c, c => arc_length::arc_length_map_with(c, tolerance, budget)),
    )?;
    Ok(ArcLengthMap { inner })
}

/// The curve as Bézier pieces in the plane, if planar.
fn pieces2(c: &AnyCurve) -> Option<&(dyn BezierPieces<2> + Sync)> {
    Some(match c {
        AnyCurve::Bezier2(c) => c,
        AnyCurve::BSpline2(c) => c,
        AnyCurve::Nurbs2(c) => c,
        AnyCurve::Hermite2(c) => c,
        AnyCurve::Composite2(c) => c,
        _ => return None,
    })
}

/// The curve as Bézier pieces in space, if spatial.
fn pieces3(c: &AnyCurve) -> Option<&(dyn BezierPieces<3> + Sync)> {
    Some(match c {
        AnyCurve::Bezier3(c) => c,
        AnyCurve::BSpline3(c) => c,
        AnyCurve::Nurbs3(c) => c,
        AnyCurve::Hermite3(c) => c,
        AnyCurve::Composite3(c) => c,
        _ => return None,
    })
}

/// A pair of points of two curves as a dict.
fn pair_dict<'py, const D: usize>(
    py: Python<'py>,
    p: &CurvePairPoint<D>,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("parameter_a", p.parameter_a)?;
    d.set_item("parameter_b", p.parameter_b)?;
    d.set_item(
        "point_a",
        PyArray1::from_slice(py, p.point_a.coords.as_slice()),
    )?;
    d.set_item(
        "point_b",
        PyArray1::from_slice(py, p.point_b.coords.as_slice()),
    )?;
    d.set_item("distance", p.distance)?;
    d.set_item("tangential", p.tangential)?;
    Ok(d)
}

fn options(tolerance: f64, max_candidates: usize, budget: &Budget) -> CurveCurveOptions {
    CurveCurveOptions::default()
        .with_tolerance(tolerance)
        .with_max_candidates(max_candidates)
        .with_budget(budget.clone())
}

fn same_dimension(a: &AnyCurve, b: &AnyCurve, what: &str) -> PyResult<()> {
    if a.dim() == b.dim() {
        Ok(())
    } else {
        Err(input(format!(
            "{what}: the curves must have the same dimension (found {} and {})",
            a.dim(),
            b.dim()
        )))
    }
}

/// The contacts and overlaps of two curves as dicts, in order along `a`: contacts as
/// [`pair_dict`] with `"kind": "point"`, overlaps as `{"kind": "overlap", "interval_a":
/// (s0, s1), "interval_b": (t0, t1)}`.
fn intersection_dicts<'py, const D: usize>(
    py: Python<'py>,
    found: &CurveIntersections<D>,
) -> PyResult<Vec<Bound<'py, PyDict>>> {
    let mut out: Vec<(f64, Bound<'py, PyDict>)> = Vec::new();
    for p in &found.points {
        let d = pair_dict(py, p)?;
        d.set_item("kind", "point")?;
        out.push((p.parameter_a, d));
    }
    for o in &found.overlaps {
        let d = PyDict::new(py);
        d.set_item("kind", "overlap")?;
        d.set_item("interval_a", o.a)?;
        d.set_item("interval_b", o.b)?;
        out.push((o.a.0, d));
    }
    out.sort_by(|x, y| x.0.total_cmp(&y.0));
    Ok(out.into_iter().map(|(_, d)| d).collect())
}

/// Every intersection of two curves of the same dimension, in order along `a`: isolated
/// contacts, and stretches where the curves coincide as parameter intervals.
pub fn intersect<'py>(
    py: Python<'py>,
    a: &AnyCurve,
    b: &AnyCurve,
    tolerance: f64,
    max_candidates: usize,
) -> PyResult<Vec<Bound<'py, PyDict>>> {
    same_dimension(a, b, "intersect_curve")?;
    match (pieces2(a), pieces2(b), pieces3(a), pieces3(b)) {
        (Some(a), Some(b), _, _) => intersection_dicts(
            py,
            &run_geometry(py, |budget| {
                intersect_curves_with_overlaps(a, b, &options(tolerance, max_candidates, budget))
            })?,
        ),
        (_, _, Some(a), Some(b)) => intersection_dicts(
            py,
            &run_geometry(py, |budget| {
                intersect_curves_with_overlaps(a, b, &options(tolerance, max_candidates, budget))
            })?,
        ),
        _ => Err(input("intersect_curve: curves of different dimensions")),
    }
}

/// The closest pair of points of two curves of the same dimension.
pub fn distance<'py>(
    py: Python<'py>,
    a: &AnyCurve,
    b: &AnyCurve,
    tolerance: f64,
    max_candidates: usize,
) -> PyResult<Bound<'py, PyDict>> {
    same_dimension(a, b, "distance_to_curve")?;
    match (pieces2(a), pieces2(b), pieces3(a), pieces3(b)) {
        (Some(a), Some(b), _, _) => pair_dict(
            py,
            &run_geometry(py, |budget| {
                curve_distance(a, b, &options(tolerance, max_candidates, budget))
            })?,
        ),
        (_, _, Some(a), Some(b)) => pair_dict(
            py,
            &run_geometry(py, |budget| {
                curve_distance(a, b, &options(tolerance, max_candidates, budget))
            })?,
        ),
        _ => Err(input("distance_to_curve: curves of different dimensions")),
    }
}

/// The offset of a planar curve at a signed distance (positive to the left): a cubic
/// B-spline on [0, 1] and the largest deviation measured.
pub fn offset(
    py: Python<'_>,
    c: &AnyCurve,
    distance: f64,
    tolerance: f64,
) -> PyResult<(Py<PyAny>, f64)> {
    let planar = crate::curve::planar(c, "offset")?;
    let found = run_geometry(py, |budget| {
        camber_geom::offset::offset_with(planar, distance, tolerance, budget)
    })?;
    Ok((wrap(py, AnyCurve::BSpline2(found.curve))?, found.max_error))
}

/// A fit as (curve, parameters of the data points, largest error at the data points).
fn fit_tuple<const D: usize>(
    py: Python<'_>,
    f: Fit<f64, D>,
    make: fn(camber_geom::BSplineCurve<f64, D>) -> AnyCurve,
) -> PyResult<(Py<PyAny>, Py<PyAny>, f64)> {
    Ok((
        wrap(py, make(f.curve))?,
        PyArray1::from_vec(py, f.parameters).into_any().unbind(),
        f.max_error,
    ))
}

/// The B-spline of `degree` through every data point (global interpolation), with the data
/// points' parameters by `method` (`"uniform"`, `"chord_length"`, `"centripetal"`) and,
/// optionally, the end derivatives `end_derivatives = (d0, d1)` (per unit of the [0, 1]
/// parameter). Returns (curve, parameters, max_error).
#[pyfunction]
#[pyo3(signature = (points, degree = 3, method = "chord_length", end_derivatives = None))]
pub fn interpolate(
    py: Python<'_>,
    points: RealArray2<'_>,
    degree: usize,
    method: &str,
    end_derivatives: Option<(Vec<f64>, Vec<f64>)>,
) -> PyResult<(Py<PyAny>, Py<PyAny>, f64)> {
    let method = parameter_method(method)?;
    match columns(&points) {
        3 => {
            let pts = crate::arrays::points::<3>(&points, "points")?;
            let ends = end_derivatives
                .map(|(a, b)| Ok::<_, PyErr>((vector::<3>(&a, "d0")?, vector::<3>(&b, "d1")?)))
                .transpose()?;
            let f = py
                .detach(|| fit::interpolate(&pts, degree, method, ends))
                .map_err(geometry)?;
            fit_tuple(py, f, AnyCurve::BSpline3)
        }
        _ => {
            let pts = crate::arrays::points::<2>(&points, "points")?;
            let ends = end_derivatives
                .map(|(a, b)| Ok::<_, PyErr>((vector::<2>(&a, "d0")?, vector::<2>(&b, "d1")?)))
                .transpose()?;
            let f = py
                .detach(|| fit::interpolate(&pts, degree, method, ends))
                .map_err(geometry)?;
            fit_tuple(py, f, AnyCurve::BSpline2)
        }
    }
}

/// `"averaged"` or `"adaptive"`.
fn knot_placement(word: &str) -> PyResult<KnotPlacement> {
    match word.to_ascii_lowercase().as_str() {
        "averaged" => Ok(KnotPlacement::Averaged),
        "adaptive" => Ok(KnotPlacement::Adaptive),
        _ => Err(input(format!(
            "knots: expected \"averaged\" or \"adaptive\", found {word:?}"
        ))),
    }
}

/// `"G1"` or `"G2"` for the joints of a split fit.
fn joint_continuity(word: &str) -> PyResult<JointContinuity> {
    match word.to_ascii_uppercase().as_str() {
        "G1" => Ok(JointContinuity::G1),
        "G2" => Ok(JointContinuity::G2),
        _ => Err(input(format!(
            "joint: expected \"G1\" or \"G2\", found {word:?}"
        ))),
    }
}

/// `None`, `"leading_edge"`, or a list of data parameters in (0, 1) to split at.
fn split_at(split: Option<&Bound<'_, PyAny>>) -> PyResult<Option<SplitAt>> {
    let Some(split) = split else {
        return Ok(None);
    };
    if split.is_none() {
        return Ok(None);
    }
    if let Ok(word) = split.extract::<String>() {
        return match word.to_ascii_lowercase().replace('-', "_").as_str() {
            "leading_edge" | "le" => Ok(Some(SplitAt::LeadingEdge)),
            _ => Err(input(format!(
                "split: expected \"leading_edge\" or a list of parameters, found {word:?}"
            ))),
        };
    }
    let values: Vec<f64> = split.extract().map_err(|_| {
        input("split: expected \"leading_edge\" or a list of parameters in (0, 1)".to_owned())
    })?;
    Ok(Some(SplitAt::Parameters(values)))
}

/// The least-squares B-spline of `degree` with `control_points` control points through the
/// data points, its ends on the first and last data points when `fixed_ends`; `knots` is
/// `"averaged"` (from the data parameters) or `"adaptive"` (spread by the errors of trial fits,
/// parameters corrected to foot points). Returns (curve, parameters, max_error), max_error the
/// largest distance from a data point to the curve.
#[pyfunction]
#[pyo3(signature = (points, degree, control_points, method = "chord_length", fixed_ends = true, knots = "averaged"))]
pub fn approximate(
    py: Python<'_>,
    points: RealArray2<'_>,
    degree: usize,
    control_points: usize,
    method: &str,
    fixed_ends: bool,
    knots: &str,
) -> PyResult<(Py<PyAny>, Py<PyAny>, f64)> {
    let options = FitOptions {
        degree,
        method: parameter_method(method)?,
        knots: knot_placement(knots)?,
        fixed_ends,
    };
    match columns(&points) {
        3 => {
            let pts = crate::arrays::points::<3>(&points, "points")?;
            let f = py
                .detach(|| fit::approximate_with(&pts, control_points, &options))
                .map_err(geometry)?;
            fit_tuple(py, f, AnyCurve::BSpline3)
        }
        _ => {
            let pts = crate::arrays::points::<2>(&points, "points")?;
            let f = py
                .detach(|| fit::approximate_with(&pts, control_points, &options))
                .map_err(geometry)?;
            fit_tuple(py, f, AnyCurve::BSpline2)
        }
    }
}

/// A split fit as (list of curves, list of parameter arrays, max_error).
fn split_tuple<const D: usize>(
    py: Python<'_>,
    f: SplitFit<f64, D>,
    make: fn(camber_geom::BSplineCurve<f64, D>) -> AnyCurve,
) -> PyResult<(Py<PyAny>, Py<PyAny>, f64)> {
    let mut curves = Vec::with_capacity(f.pieces.len());
    let mut params = Vec::with_capacity(f.pieces.len());
    for piece in f.pieces {
        curves.push(wrap(py, make(piece.curve))?);
        params.push(PyArray1::from_vec(py, piece.parameters).into_any().unbind());
    }
    Ok((
        pyo3::types::PyList::new(py, curves)?.into_any().unbind(),
        pyo3::types::PyList::new(py, params)?.into_any().unbind(),
        f.max_error,
    ))
}

/// The B-spline of `degree` within `tolerance` of every data point (the largest distance from
/// a data point to the curve, never above the tolerance) with as few control points as the
/// adaptive search finds (`knots="adaptive"`; `"averaged"` searches the count with averaged
/// knots and residuals at the parameters). Returns (curve, parameters, max_error).
///
/// With `split="leading_edge"` (the point of smallest x) or a list of data parameters in
/// (0, 1), every piece between split points gets its own curve, and neighbouring curves share
/// the joint's point and tangent direction (`joint="G1"`) and curvature (`joint="G2"`); then the
/// result is (list of curves, list of parameter arrays, max_error).
#[pyfunction]
#[pyo3(signature = (points, degree, tolerance, method = "chord_length", knots = "adaptive", split = None, joint = "G1"))]
#[allow(clippy::too_many_arguments)] // the Python keyword arguments, one per option
pub fn fit_to_tolerance(
    py: Python<'_>,
    points: RealArray2<'_>,
    degree: usize,
    tolerance: f64,
    method: &str,
    knots: &str,
    split: Option<&Bound<'_, PyAny>>,
    joint: &str,
) -> PyResult<(Py<PyAny>, Py<PyAny>, f64)> {
    let options = FitOptions {
        degree,
        method: parameter_method(method)?,
        knots: knot_placement(knots)?,
        fixed_ends: true,
    };
    let joint = joint_continuity(joint)?;
    let split = split_at(split)?;
    match (columns(&points), split) {
        (3, None) => {
            let pts = crate::arrays::points::<3>(&points, "points")?;
            let f = run_geometry(py, |budget| {
                fit::fit_to_tolerance_with(&pts, tolerance, &options, budget)
            })?;
            fit_tuple(py, f, AnyCurve::BSpline3)
        }
        (3, Some(at)) => {
            let pts = crate::arrays::points::<3>(&points, "points")?;
            let f = run_geometry(py, |budget| {
                fit::fit_split(&pts, tolerance, &options, &at, joint, budget)
            })?;
            split_tuple(py, f, AnyCurve::BSpline3)
        }
        (_, None) => {
            let pts = crate::arrays::points::<2>(&points, "points")?;
            let f = run_geometry(py, |budget| {
                fit::fit_to_tolerance_with(&pts, tolerance, &options, budget)
            })?;
            fit_tuple(py, f, AnyCurve::BSpline2)
        }
        (_, Some(at)) => {
            let pts = crate::arrays::points::<2>(&points, "points")?;
            let f = run_geometry(py, |budget| {
                fit::fit_split(&pts, tolerance, &options, &at, joint, budget)
            })?;
            split_tuple(py, f, AnyCurve::BSpline2)
        }
    }
}

/// Adds the classes and functions of this module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<ArcLengthMap>()?;
    m.add_function(wrap_pyfunction!(interpolate, m)?)?;
    m.add_function(wrap_pyfunction!(approximate, m)?)?;
    m.add_function(wrap_pyfunction!(fit_to_tolerance, m)?)?;
    Ok(())
}
