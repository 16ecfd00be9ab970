//! The curve classes: a base class `Curve` holding any camber-geom curve in 2 or 3 dimensions,
//! with evaluation vectorised over numpy arrays of parameters (the GIL released during the
//! loop) and the queries; the subclasses `BezierCurve`, `BSplineCurve`, `NurbsCurve` and
//! `HermiteCurve` (module `curve_kinds`) and `CompositeCurve` (module `composite`) add
//! construction and each kind's operations.

use camber_geom::queries::{
    closest_point, curvature, distance_to_circle, distance_to_line, intersect_circle,
    intersect_line, signed_curvature, ClosestPoint, Intersection,
};
use camber_geom::{
    BSplineCurve, BezierCurve, Circle, HermiteCurve, Line, NurbsCurve, ParametricCurve,
};
use nalgebra::{Point, Point2, SVector};
use numpy::ndarray::Array3;
use numpy::{IntoPyArray, PyArray1};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use pyo3::IntoPyObjectExt;

use crate::arrays::{points, points_array, refuse_complex, rows_array, vector, Params, RealArray2};
use crate::composite::Chain;
use crate::errors::{geometry, input};

/// Any curve the package handles, in the plane or in space.
#[derive(Debug, Clone)]
pub enum AnyCurve {
    /// A planar Bézier curve.
    Bezier2(BezierCurve<f64, 2>),
    /// A spatial Bézier curve.
    Bezier3(BezierCurve<f64, 3>),
    /// A planar B-spline curve.
    BSpline2(BSplineCurve<f64, 2>),
    /// A spatial B-spline curve.
    BSpline3(BSplineCurve<f64, 3>),
    /// A planar NURBS curve.
    Nurbs2(NurbsCurve<f64, 2>),
    /// A spatial NURBS curve.
    Nurbs3(NurbsCurve<f64, 3>),
    /// A planar cubic Hermite curve.
    Hermite2(HermiteCurve<f64, 2>),
    /// A spatial cubic Hermite curve.
    Hermite3(HermiteCurve<f64, 3>),
    /// A planar chain of curves under one global parameter.
    Composite2(Chain<2>),
    /// A spatial chain of curves under one global parameter.
    Composite3(Chain<3>),
}

/// Runs `$body` with `$c` bound to the concrete curve, whatever its kind and dimension.
macro_rules! each {
    ($any:expr, $c:ident => $body:expr) => {
        match $any {
            $crate::curve::AnyCurve::Bezier2($c) => $body,
            $crate::curve::AnyCurve::Bezier3($c) => $body,
            $crate::curve::AnyCurve::BSpline2($c) => $body,
            $crate::curve::AnyCurve::BSpline3($c) => $body,
            $crate::curve::AnyCurve::Nurbs2($c) => $body,
            $crate::curve::AnyCurve::Nurbs3($c) => $body,
            $crate::curve::AnyCurve::Hermite2($c) => $body,
            $crate::curve::AnyCurve::Hermite3($c) => $body,
            $crate::curve::AnyCurve::Composite2($c) => $body,
            $crate::curve::AnyCurve::Composite3($c) => $body,
        }
    };
}
pub(crate) use each;

/// The curve as a planar one, or an error naming the query that needs the plane.
pub fn planar<'a>(
    c: &'a AnyCurve,
    what: &str,
) -> PyResult<&'a (dyn ParametricCurve<f64, 2> + Sync)> {
    Ok(match c {
        AnyCurve::Bezier2(c) => c,
        AnyCurve::BSpline2(c) => c,
        AnyCurve::Nurbs2(c) => c,
        AnyCurve::Hermite2(c) => c,
        AnyCurve::Composite2(c) => c,
        _ => return Err(input(format!("{what} needs a planar curve (2 columns)"))),
    })
}

impl AnyCurve {
    /// The dimension of the space (2 or 3).
    pub fn dim(&self) -> usize {
        match self {
            AnyCurve::Bezier2(_)
            | AnyCurve::BSpline2(_)
            | AnyCurve::Nurbs2(_)
            | AnyCurve::Hermite2(_)
            | AnyCurve::Composite2(_) => 2,
            _ => 3,
        }
    }

    /// The reversed curve, of the same kind.
    pub fn reversed(&self) -> AnyCurve {
        match self {
            AnyCurve::Bezier2(c) => AnyCurve::Bezier2(c.reversed()),
            AnyCurve::Bezier3(c) => AnyCurve::Bezier3(c.reversed()),
            AnyCurve::BSpline2(c) => AnyCurve::BSpline2(c.reversed()),
            AnyCurve::BSpline3(c) => AnyCurve::BSpline3(c.reversed()),
            AnyCurve::Nurbs2(c) => AnyCurve::Nurbs2(c.reversed()),
            AnyCurve::Nurbs3(c) => AnyCurve::Nurbs3(c.reversed()),
            AnyCurve::Hermite2(c) => AnyCurve::Hermite2(c.reversed()),
            AnyCurve::Hermite3(c) => AnyCurve::Hermite3(c.reversed()),
            AnyCurve::Composite2(c) => AnyCurve::Composite2(c.reversed()),
            AnyCurve::Composite3(c) => AnyCurve::Composite3(c.reversed()),
        }
    }
}

/// C(u), …, C⁽ᵏ⁾(u) for every u, appended to `out` as `us.len()` × (k + 1) × D values.
///
/// One scratch buffer for the whole loop: no allocation per parameter.
pub fn derivatives_flat<C, const D: usize>(
    curve: &C,
    us: &[f64],
    order: usize,
) -> Result<Vec<f64>, camber_geom::Error>
where
    C: ParametricCurve<f64, D> + ?Sized,
{
    // The order is checked before anything is sized by it.
    camber_geom::curve::check_derivative_order(order)?;
    let mut out = Vec::with_capacity(us.len() * (order + 1) * D);
    let mut scratch = vec![SVector::<f64, D>::zeros(); order + 1];
    for &u in us {
        curve.derivatives_into(u, &mut scratch)?;
        for v in &scratch {
            out.extend_from_slice(v.as_slice());
        }
    }
    Ok(out)
}

/// Points C(u) for every u, as `us.len()` × D values (the Rust loop of the evaluation benchmark).
pub fn points_flat<C, const D: usize>(curve: &C, us: &[f64]) -> Result<Vec<f64>, camber_geom::Error>
where
    C: ParametricCurve<f64, D> + ?Sized,
{
    derivatives_flat(curve, us, 0)
}

/// A scalar function of u over many parameters (curvatures).
pub(crate) fn scalar_map(
    py: Python<'_>,
    u: &Bound<'_, PyAny>,
    f: impl Fn(f64) -> Result<f64, camber_geom::Error> + Send + Sync,
) -> PyResult<Py<PyAny>> {
    let params = Params::extract(u)?;
    let values = py
        .detach(|| {
            params
                .as_slice()
                .iter()
                .map(|&u| f(u))
                .collect::<Result<Vec<_>, _>>()
        })
        .map_err(geometry)?;
    match params {
        Params::One(_) => values[0].into_py_any(py),
        Params::Many(_) => Ok(PyArray1::from_vec(py, values).into_any().unbind()),
    }
}

/// The curve of a 3-D `inner` for the query `what`.
fn spatial<'a>(
    inner: &'a AnyCurve,
    what: &str,
) -> PyResult<&'a (dyn ParametricCurve<f64, 3> + Sync)> {
    Ok(match inner {
        AnyCurve::Bezier3(c) => c,
        AnyCurve::BSpline3(c) => c,
        AnyCurve::Nurbs3(c) => c,
        AnyCurve::Hermite3(c) => c,
        AnyCurve::Composite3(c) => c,
        _ => {
            return Err(input(format!(
                "{what}: the point's dimension is not the curve's"
            )))
        }
    })
}

/// The closest points of `curve` to every point of `pts`, as arrays (parameters (n,), points
/// (n, D), distances (n,)); the GIL released, Ctrl-C honoured between points.
fn closest_arrays<'py, const D: usize>(
    py: Python<'py>,
    curve: &(dyn ParametricCurve<f64, D> + Sync),
    pts: &[Point<f64, D>],
) -> PyResult<Bound<'py, PyTuple>> {
    let found = crate::interrupt::run_geometry(py, |budget| {
        let mut params = Vec::with_capacity(pts.len());
        let mut coords = Vec::with_capacity(pts.len() * D);
        let mut distances = Vec::with_capacity(pts.len());
        for p in pts {
            if budget.is_stopped() {
                return Err(camber_geom::Error::Cancelled {
                    operation: "closest_point",
                });
            }
            let c = closest_point(curve, p)?;
            params.push(c.parameter);
            coords.extend_from_slice(c.point.coords.as_slice());
            distances.push(c.distance);
        }
        Ok((params, coords, distances))
    })?;
    let (params, coords, distances) = found;
    PyTuple::new(
        py,
        [
            PyArray1::from_vec(py, params).into_any(),
            rows_array(py, coords, D).into_any(),
            PyArray1::from_vec(py, distances).into_any(),
        ],
    )
}

fn closest_tuple<'py, const D: usize>(
    py: Python<'py>,
    c: ClosestPoint<f64, D>,
) -> PyResult<Bound<'py, PyTuple>> {
    let p = PyArray1::from_slice(py, c.point.coords.as_slice());
    PyTuple::new(
        py,
        [
            c.parameter.into_bound_py_any(py)?,
            p.into_any(),
            c.distance.into_bound_py_any(py)?,
        ],
    )
}

fn intersections<'py>(
    py: Python<'py>,
    found: Vec<Intersection<f64>>,
) -> PyResult<Bound<'py, PyTuple>> {
    let params: Vec<f64> = found.iter().map(|i| i.parameter).collect();
    let points: Vec<Point2<f64>> = found.iter().map(|i| i.point).collect();
    PyTuple::new(
        py,
        [
            PyArray1::from_vec(py, params).into_any(),
            points_array(py, &points).into_any(),
        ],
    )
}

/// A parametric curve (base class of `BezierCurve`, `BSplineCurve`, `NurbsCurve`,
/// `HermiteCurve`, `CompositeCurve`): evaluation, derivatives, curvature and queries.
///
/// Evaluation methods take one parameter (a float) or many (a 1-D array) and loop in Rust with
/// the GIL released: `curve.evaluate(np.linspace(0, 1, 10**6))` returns a (10⁶, d) array.
#[pyclass(subclass, frozen, module = "camber._native")]
#[derive(Debug, Clone)]
pub struct Curve {
    /// The curve itself.
    pub inner: AnyCurve,
}

#[pymethods]
impl Curve {
    /// The dimension of the space (2 or 3).
    #[getter]
    fn dim(&self) -> usize {
        self.inner.dim()
    }

    /// The parametric domain (a, b).
    #[getter]
    fn domain(&self) -> (f64, f64) {
        each!(&self.inner, c => c.domain())
    }

    /// Parameters where the curve may be less smooth than its pieces (ends included).
    #[getter]
    fn breakpoints(&self) -> Vec<f64> {
        each!(&self.inner, c => c.breakpoints())
    }

    /// Points C(u): shape (d,) for one parameter, (n, d) for an array of n.
    fn evaluate(&self, py: Python<'_>, u: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let params = Params::extract(u)?;
        let d = self.inner.dim();
        let flat = py
            .detach(|| each!(&self.inner, c => points_flat(c, params.as_slice())))
            .map_err(geometry)?;
        Ok(match params {
            Params::One(_) => PyArray1::from_vec(py, flat).into_any().unbind(),
            Params::Many(_) => rows_array(py, flat, d).into_any().unbind(),
        })
    }

    /// C(u), C′(u), …, C⁽ᵏ⁾(u) with k = `order`: shape (k + 1, d) for one parameter,
    /// (n, k + 1, d) for n.
    #[pyo3(signature = (u, order = 1))]
    fn derivatives(
        &self,
        py: Python<'_>,
        u: &Bound<'_, PyAny>,
        order: usize,
    ) -> PyResult<Py<PyAny>> {
        let params = Params::extract(u)?;
        let d = self.inner.dim();
        let flat = py
            .detach(|| each!(&self.inner, c => derivatives_flat(c, params.as_slice(), order)))
            .map_err(geometry)?;
        let n = params.as_slice().len();
        let array =
            Array3::from_shape_vec((n, order + 1, d), flat).map_err(|e| input(e.to_string()))?;
        Ok(match params {
            Params::One(_) => array
                .index_axis_move(numpy::ndarray::Axis(0), 0)
                .into_pyarray(py)
                .into_any()
                .unbind(),
            Params::Many(_) => array.into_pyarray(py).into_any().unbind(),
        })
    }

    /// The first derivative C′(u): shape (d,) or (n, d).
    fn derivative(&self, py: Python<'_>, u: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let params = Params::extract(u)?;
        let d = self.inner.dim();
        let flat = py
            .detach(|| each!(&self.inner, c => derivatives_flat(c, params.as_slice(), 1)))
            .map_err(geometry)?;
        let first: Vec<f64> = flat
            .chunks(2 * d)
            .flat_map(|ch| ch[d..].iter().copied())
            .collect();
        Ok(match params {
            Params::One(_) => PyArray1::from_vec(py, first).into_any().unbind(),
            Params::Many(_) => rows_array(py, first, d).into_any().unbind(),
        })
    }

    /// Curvature κ(u) = |C′ × C″| / |C′|³ (1/length): a float or an array.
    fn curvature(&self, py: Python<'_>, u: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let inner = &self.inner;
        scalar_map(py, u, |u| each!(inner, c => curvature(c, u)))
    }

    /// Signed curvature of a planar curve (positive turning counter-clockwise).
    fn signed_curvature(&self, py: Python<'_>, u: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let c = planar(&self.inner, "signed_curvature")?;
        scalar_map(py, u, |u| signed_curvature(c, u))
    }

    /// The point of the curve closest to `point`: (parameter, point, distance). For an
    /// (n, d) array of points (any dtype numpy casts to float, any memory layout): arrays of
    /// shape (n,), (n, d) and (n,), computed with the GIL released (Ctrl-C stops between
    /// points).
    fn closest_point<'py>(
        &self,
        py: Python<'py>,
        point: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        refuse_complex(point, "point")?;
        // A 2-D array is many points even when it has none.
        let table = point
            .getattr("ndim")
            .and_then(|n| n.extract::<usize>())
            .is_ok_and(|n| n == 2);
        if let Some(one) = (!table).then(|| point.extract::<Vec<f64>>().ok()).flatten() {
            return match self.inner.dim() {
                2 => {
                    let p = Point::from(vector::<2>(&one, "point")?);
                    let c = planar(&self.inner, "closest_point")?;
                    closest_tuple(py, py.detach(|| closest_point(c, &p)).map_err(geometry)?)
                }
                _ => {
                    let p = Point::from(vector::<3>(&one, "point")?);
                    let c = spatial(&self.inner, "closest_point")?;
                    closest_tuple(py, py.detach(|| closest_point(c, &p)).map_err(geometry)?)
                }
            };
        }
        let many: RealArray2<'_> = point.extract()?;
        match self.inner.dim() {
            2 => {
                let pts = points::<2>(&many, "points")?;
                let c = planar(&self.inner, "closest_point")?;
                closest_arrays(py, c, &pts)
            }
            _ => {
                let pts = points::<3>(&many, "points")?;
                let c = spatial(&self.inner, "closest_point")?;
                closest_arrays(py, c, &pts)
            }
        }
    }

    /// Every intersection with the line through `point` along `direction` (planar curves):
    /// (parameters (k,), points (k, 2)).
    fn intersect_line<'py>(
        &self,
        py: Python<'py>,
        point: Vec<f64>,
        direction: Vec<f64>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let c = planar(&self.inner, "intersect_line")?;
        let line = Line::try_new(
            Point::from(vector::<2>(&point, "point")?),
            vector::<2>(&direction, "direction")?,
        )
        .map_err(geometry)?;
        intersections(
            py,
            py.detach(|| intersect_line(c, &line)).map_err(geometry)?,
        )
    }

    /// Every intersection with the circle (planar curves): (parameters (k,), points (k, 2)).
    fn intersect_circle<'py>(
        &self,
        py: Python<'py>,
        center: Vec<f64>,
        radius: f64,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let c = planar(&self.inner, "intersect_circle")?;
        let circle = Circle::try_new(Point::from(vector::<2>(&center, "center")?), radius)
            .map_err(geometry)?;
        intersections(
            py,
            py.detach(|| intersect_circle(c, &circle))
                .map_err(geometry)?,
        )
    }

    /// The least distance to a line (planar curves): (parameter, point, distance).
    fn distance_to_line<'py>(
        &self,
        py: Python<'py>,
        point: Vec<f64>,
        direction: Vec<f64>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let c = planar(&self.inner, "distance_to_line")?;
        let line = Line::try_new(
            Point::from(vector::<2>(&point, "point")?),
            vector::<2>(&direction, "direction")?,
        )
        .map_err(geometry)?;
        closest_tuple(
            py,
            py.detach(|| distance_to_line(c, &line)).map_err(geometry)?,
        )
    }

    /// The least distance to a circle (planar curves): (parameter, point, distance).
    fn distance_to_circle<'py>(
        &self,
        py: Python<'py>,
        center: Vec<f64>,
        radius: f64,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let c = planar(&self.inner, "distance_to_circle")?;
        let circle = Circle::try_new(Point::from(vector::<2>(&center, "center")?), radius)
            .map_err(geometry)?;
        closest_tuple(
            py,
            py.detach(|| distance_to_circle(c, &circle))
                .map_err(geometry)?,
        )
    }

    /// The arc length over the whole domain, to an absolute `tolerance` (length units;
    /// adaptive Gauss–Legendre quadrature split at the breakpoints).
    #[pyo3(signature = (tolerance = 1e-10))]
    fn arc_length(&self, py: Python<'_>, tolerance: f64) -> PyResult<f64> {
        crate::curve_ops::length(py, &self.inner, None, tolerance)
    }

    /// The arc length between the parameters u0 ≤ u1.
    #[pyo3(signature = (u0, u1, tolerance = 1e-10))]
    fn arc_length_between(
        &self,
        py: Python<'_>,
        u0: f64,
        u1: f64,
        tolerance: f64,
    ) -> PyResult<f64> {
        crate::curve_ops::length(py, &self.inner, Some((u0, u1)), tolerance)
    }

    /// The parameter at arc length `s` from the start (0 ≤ s ≤ length), solved to
    /// `tolerance` in length: a float or an array for an array of lengths.
    #[pyo3(signature = (s, tolerance = 1e-10))]
    fn parameter_at_length(
        &self,
        py: Python<'_>,
        s: &Bound<'_, PyAny>,
        tolerance: f64,
    ) -> PyResult<Py<PyAny>> {
        crate::curve_ops::parameter_at_length(py, &self.inner, s, tolerance)
    }

    /// The arc-length parameterization u(s) within `tolerance` (length units), as an
    /// `ArcLengthMap` (fast to evaluate at many lengths).
    #[pyo3(signature = (tolerance = 1e-8))]
    fn arc_length_map(
        &self,
        py: Python<'_>,
        tolerance: f64,
    ) -> PyResult<crate::curve_ops::ArcLengthMap> {
        crate::curve_ops::arc_length_map(py, &self.inner, tolerance)
    }

    /// Every intersection with another curve of the same dimension, in order along this one:
    /// a list of dicts, each a contact {kind: "point", parameter_a, parameter_b, point_a,
    /// point_b, distance, tangential} (a tangential one is a touch) or a stretch where the
    /// curves coincide {kind: "overlap", interval_a: (s0, s1), interval_b: (t0, t1)}
    /// (t0 > t1 when the other curve runs the opposite way). Points closer than `tolerance`
    /// coincide; raises `GeometryError` when the search needs more than `max_candidates`
    /// candidate pairs.
    #[pyo3(signature = (other, tolerance = 1e-9, max_candidates = 20_000))]
    fn intersect_curve<'py>(
        &self,
        py: Python<'py>,
        other: PyRef<'py, Curve>,
        tolerance: f64,
        max_candidates: usize,
    ) -> PyResult<Vec<Bound<'py, pyo3::types::PyDict>>> {
        crate::curve_ops::intersect(py, &self.inner, &other.inner, tolerance, max_candidates)
    }

    /// The closest pair of points of this curve and another of the same dimension: a dict
    /// {parameter_a, parameter_b, point_a, point_b, distance, tangential}.
    #[pyo3(signature = (other, tolerance = 1e-9, max_candidates = 20_000))]
    fn distance_to_curve<'py>(
        &self,
        py: Python<'py>,
        other: PyRef<'py, Curve>,
        tolerance: f64,
        max_candidates: usize,
    ) -> PyResult<Bound<'py, pyo3::types::PyDict>> {
        crate::curve_ops::distance(py, &self.inner, &other.inner, tolerance, max_candidates)
    }

    /// The offset of a planar curve at signed `distance` (positive to the left of the
    /// direction of travel), approximated by a cubic B-spline on [0, 1] within `tolerance`:
    /// (BSplineCurve, max_error).
    #[pyo3(signature = (distance, tolerance = 1e-6))]
    fn offset(&self, py: Python<'_>, distance: f64, tolerance: f64) -> PyResult<(Py<PyAny>, f64)> {
        crate::curve_ops::offset(py, &self.inner, distance, tolerance)
    }

    /// The same curve traversed backwards, of the same kind.
    fn reversed(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        crate::curve_kinds::wrap(py, self.inner.reversed())
    }

    /// The curve in camber's JSON curve form.
    fn to_json(&self) -> PyResult<String> {
        each!(&self.inner, c => serde_json::to_string(c)).map_err(|e| input(e.to_string()))
    }

    /// Pickling goes through camber's curve JSON: `type(c).from_json(c.to_json())`, exact
    /// (numbers are written in their shortest round-trip form).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (String,))> {
        let text = slf.borrow().to_json()?;
        Ok((slf.get_type().getattr("from_json")?, (text,)))
    }

    fn __repr__(&self) -> String {
        let (a, b) = each!(&self.inner, c => c.domain());
        format!(
            "<{} in {}D on [{a}, {b}]>",
            crate::curve_kinds::class_name(&self.inner),
            self.inner.dim()
        )
    }
}
