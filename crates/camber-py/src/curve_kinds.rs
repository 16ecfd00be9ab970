//! The four curve classes (subclasses of `Curve`): construction from numpy arrays, their
//! properties, and each kind's operations (split, knot insertion, refinement, degree
//! elevation, reparameterization, conversions, extension, knot removal, degree reduction).
//! Every operation returns a new curve.

use camber_geom::{BSplineCurve, BezierCurve, HermiteCurve, KnotVector, NurbsCurve};
use nalgebra::Point;
use numpy::{PyArray1, PyArray2};
use pyo3::prelude::*;
use pyo3::IntoPyObjectExt;
use serde::de::DeserializeOwned;

use crate::arrays::{columns, points, points_array, vector, RealArray2};
use crate::composite::CompositeCurve_;
use crate::curve::{AnyCurve, Curve};
use crate::curve_ops::{continuity as ext_continuity, curve_end};
use crate::errors::{geometry, input};

/// The Python class name of a curve's kind.
pub fn class_name(c: &AnyCurve) -> &'static str {
    match c {
        AnyCurve::Bezier2(_) | AnyCurve::Bezier3(_) => "BezierCurve",
        AnyCurve::BSpline2(_) | AnyCurve::BSpline3(_) => "BSplineCurve",
        AnyCurve::Nurbs2(_) | AnyCurve::Nurbs3(_) => "NurbsCurve",
        AnyCurve::Hermite2(_) | AnyCurve::Hermite3(_) => "HermiteCurve",
        AnyCurve::Composite2(_) | AnyCurve::Composite3(_) => "CompositeCurve",
    }
}

/// A curve as an object of its own class.
pub fn wrap(py: Python<'_>, inner: AnyCurve) -> PyResult<Py<PyAny>> {
    let name = class_name(&inner);
    let base = PyClassInitializer::from(Curve { inner });
    match name {
        "BezierCurve" => Py::new(py, base.add_subclass(BezierCurve_))?.into_py_any(py),
        "BSplineCurve" => Py::new(py, base.add_subclass(BSplineCurve_))?.into_py_any(py),
        "NurbsCurve" => Py::new(py, base.add_subclass(NurbsCurve_))?.into_py_any(py),
        "CompositeCurve" => Py::new(py, base.add_subclass(CompositeCurve_))?.into_py_any(py),
        _ => Py::new(py, base.add_subclass(HermiteCurve_))?.into_py_any(py),
    }
}

fn pair(py: Python<'_>, a: AnyCurve, b: AnyCurve) -> PyResult<(Py<PyAny>, Py<PyAny>)> {
    Ok((wrap(py, a)?, wrap(py, b)?))
}

/// Control points as an array, whatever the dimension.
fn control_points_of<'py>(py: Python<'py>, c: &AnyCurve) -> Bound<'py, PyArray2<f64>> {
    match c {
        AnyCurve::Bezier2(c) => points_array(py, c.control_points()),
        AnyCurve::Bezier3(c) => points_array(py, c.control_points()),
        AnyCurve::BSpline2(c) => points_array(py, c.control_points()),
        AnyCurve::BSpline3(c) => points_array(py, c.control_points()),
        AnyCurve::Nurbs2(c) => points_array(py, c.control_points()),
        AnyCurve::Nurbs3(c) => points_array(py, c.control_points()),
        AnyCurve::Hermite2(c) => points_array(py, &[c.p0(), c.p1()]),
        AnyCurve::Hermite3(c) => points_array(py, &[c.p0(), c.p1()]),
        AnyCurve::Composite2(c) => points_array(py, &c.control_points()),
        AnyCurve::Composite3(c) => points_array(py, &c.control_points()),
    }
}

/// Reads a curve's JSON form in 2 dimensions, or else in 3.
fn from_json_2_or_3<C2: DeserializeOwned, C3: DeserializeOwned>(
    text: &str,
    two: fn(C2) -> AnyCurve,
    three: fn(C3) -> AnyCurve,
) -> PyResult<AnyCurve> {
    match serde_json::from_str::<C2>(text) {
        Ok(c) => Ok(two(c)),
        Err(e2) => serde_json::from_str::<C3>(text)
            .map(three)
            .map_err(|_| input(format!("invalid curve JSON: {e2}"))),
    }
}

/// Runs `$body` with `$c` bound to the curve of the given kind in either dimension, wrapping
/// a curve result `$wrap!(…)` back into the same dimension.
macro_rules! by_dim {
    ($any:expr, $v2:ident, $v3:ident, $c:ident => $body:expr) => {
        match $any {
            AnyCurve::$v2($c) => {
                #[allow(unused_macros)] // not every body builds a curve
                macro_rules! same {
                    ($x:expr) => {
                        AnyCurve::$v2($x)
                    };
                }
                $body
            }
            AnyCurve::$v3($c) => {
                #[allow(unused_macros)] // not every body builds a curve
                macro_rules! same {
                    ($x:expr) => {
                        AnyCurve::$v3($x)
                    };
                }
                $body
            }
            _ => Err(input("internal: curve of another kind")),
        }
    };
}

/// A Bézier curve of any degree: `BezierCurve(control_points)` with an (n, 2) or (n, 3)
/// array; defined on [0, 1].
#[pyclass(name = "BezierCurve", extends = Curve, frozen, module = "camber._native")]
#[derive(Debug)]
#[allow(non_camel_case_types)] // the Rust name differs from the library's struct; Python sees `BezierCurve`
pub struct BezierCurve_;

#[pymethods]
impl BezierCurve_ {
    #[new]
    fn new(control_points: RealArray2<'_>) -> PyResult<PyClassInitializer<Self>> {
        let inner = match columns(&control_points) {
            3 => AnyCurve::Bezier3(
                BezierCurve::try_new(points::<3>(&control_points, "control_points")?)
                    .map_err(geometry)?,
            ),
            _ => AnyCurve::Bezier2(
                BezierCurve::try_new(points::<2>(&control_points, "control_points")?)
                    .map_err(geometry)?,
            ),
        };
        Ok(PyClassInitializer::from(Curve { inner }).add_subclass(BezierCurve_))
    }

    /// Reads the JSON form `{"control_points": [[x, y], …]}`.
    #[staticmethod]
    fn from_json(py: Python<'_>, text: &str) -> PyResult<Py<PyAny>> {
        wrap(
            py,
            from_json_2_or_3(text, AnyCurve::Bezier2, AnyCurve::Bezier3)?,
        )
    }

    /// The control points, (n, d).
    #[getter]
    fn control_points<'py>(slf: PyRef<'py, Self>) -> Bound<'py, PyArray2<f64>> {
        control_points_of(slf.py(), &slf.as_super().inner)
    }

    /// The degree (control points − 1).
    #[getter]
    fn degree(slf: PyRef<'_, Self>) -> PyResult<usize> {
        by_dim!(&slf.as_super().inner, Bezier2, Bezier3, c => Ok(c.degree()))
    }

    /// The derivative curve C′ (degree − 1).
    fn hodograph(slf: PyRef<'_, Self>) -> PyResult<Py<PyAny>> {
        let py = slf.py();
        by_dim!(&slf.as_super().inner, Bezier2, Bezier3, c => wrap(py, same!(c.hodograph())))
    }

    /// The two halves at t (de Casteljau).
    fn subdivide(slf: PyRef<'_, Self>, t: f64) -> PyResult<(Py<PyAny>, Py<PyAny>)> {
        let py = slf.py();
        by_dim!(&slf.as_super().inner, Bezier2, Bezier3, c => {
            let (a, b) = c.subdivide(t).map_err(geometry)?;
            pair(py, same!(a), same!(b))
        })
    }

    /// The piece between t0 and t1, reparameterized to [0, 1].
    fn segment(slf: PyRef<'_, Self>, t0: f64, t1: f64) -> PyResult<Py<PyAny>> {
        let py = slf.py();
        by_dim!(&slf.as_super().inner, Bezier2, Bezier3, c =>
            wrap(py, same!(c.segment(t0, t1).map_err(geometry)?)))
    }

    /// The same curve with its degree raised `times` times.
    #[pyo3(signature = (times = 1))]
    fn elevate_degree(slf: PyRef<'_, Self>, times: usize) -> PyResult<Py<PyAny>> {
        let py = slf.py();
        by_dim!(&slf.as_super().inner, Bezier2, Bezier3, c =>
            wrap(py, same!(c.try_elevate_degree(times).map_err(geometry)?)))
    }

    /// The same curve as a clamped B-spline on [0, 1].
    fn to_bspline(slf: PyRef<'_, Self>) -> PyResult<Py<PyAny>> {
        let py = slf.py();
        match &slf.as_super().inner {
            AnyCurve::Bezier2(c) => wrap(py, AnyCurve::BSpline2(BSplineCurve::from_bezier(c))),
            AnyCurve::Bezier3(c) => wrap(py, AnyCurve::BSpline3(BSplineCurve::from_bezier(c))),
            _ => Err(input("internal: curve of another kind")),
        }
    }

    /// The natural extension: the same polynomial pieces continued (or cut back) so that the
    /// domain reaches `t` at `end` (`"start"` or `"end"`); C(u) is unchanged on the old domain.
    fn extrapolated(slf: PyRef<'_, Self>, end: &str, t: f64) -> PyResult<Py<PyAny>> {
        let py = slf.py();
        let end = curve_end(end)?;
        by_dim!(&slf.as_super().inner, Bezier2, Bezier3, c =>
            wrap(py, same!(c.extrapolated(end, t).map_err(geometry)?)))
    }

    /// The curve extended at `end` (`"start"` or `"end"`) by an arc of `length` (length
    /// units): `"G1"` a straight piece along the end tangent, `"G2"` the end piece continued
    /// naturally (found by arc length).
    /// The result is a B-spline.
    #[pyo3(signature = (end, length, continuity = "G2"))]
    fn extended_by_length(
        slf: PyRef<'_, Self>,
        end: &str,
        length: f64,
        continuity: &str,
    ) -> PyResult<Py<PyAny>> {
        let py = slf.py();
        let (end, how) = (curve_end(end)?, ext_continuity(continuity)?);
        match &slf.as_super().inner {
            AnyCurve::Bezier2(c) => wrap(
                py,
                AnyCurve::BSpline2(
                    py.detach(|| c.extended_by_length(end, length, how))
                        .map_err(geometry)?,
                ),
            ),
            AnyCurve::Bezier3(c) => wrap(
                py,
                AnyCurve::BSpline3(
                    py.detach(|| c.extended_by_length(end, length, how))
                        .map_err(geometry)?,
                ),
            ),
            _ => Err(input("internal: curve of another kind")),
        }
    }

    /// The best curve of one degree less (least squares on the control points): (curve,
    /// error_bound), error_bound bounding max_u |C(u) − C̃(u)| (0 up to rounding when the
    /// curve was degree-elevated).
    fn reduce_degree(slf: PyRef<'_, Self>) -> PyResult<(Py<PyAny>, f64)> {
        let py = slf.py();
        by_dim!(&slf.as_super().inner, Bezier2, Bezier3, c => {
            let r = c.reduce_degree().map_err(geometry)?;
            Ok((wrap(py, same!(r.curve))?, r.error_bound))
        })
    }

    /// The same cubic as a Hermite curve (end points and end tangents).
    fn to_hermite(slf: PyRef<'_, Self>) -> PyResult<Py<PyAny>> {
        let py = slf.py();
        match &slf.as_super().inner {
            AnyCurve::Bezier2(c) => wrap(
                py,
                AnyCurve::Hermite2(HermiteCurve::from_bezier(c).map_err(geometry)?),
            ),
            AnyCurve::Bezier3(c) => wrap(
                py,
                AnyCurve::Hermite3(HermiteCurve::from_bezier(c).map_err(geometry)?),
            ),
            _ => Err(input("internal: curve of another kind")),
        }
    }
}

fn knot_vector(knots: Vec<f64>) -> PyResult<KnotVector<f64>> {
    KnotVector::try_new(knots).map_err(geometry)
}

/// The `#[pymethods]` of a knotted curve class (B-spline or NURBS): the class's own methods
/// `$own`, then the degree, knot and shape operations the two kinds share, each run on the
/// curve of variant `$v2` or `$v3` and returning a curve of the same class and dimension.
macro_rules! knotted_curve_methods {
    ($class:ident, $v2:ident, $v3:ident; $($own:tt)*) => {
        #[pymethods]
        impl $class {
            $($own)*

            /// The degree.
            #[getter]
            fn degree(slf: PyRef<'_, Self>) -> PyResult<usize> {
                by_dim!(&slf.as_super().inner, $v2, $v3, c => Ok(c.degree()))
            }

            /// The knot vector.
            #[getter]
            fn knots<'py>(slf: PyRef<'py, Self>) -> PyResult<Bound<'py, PyArray1<f64>>> {
                let py = slf.py();
                by_dim!(&slf.as_super().inner, $v2, $v3, c =>
                    Ok(PyArray1::from_slice(py, c.knots().as_slice())))
            }

            /// The same curve with the knot u inserted `times` times (Boehm).
            #[pyo3(signature = (u, times = 1))]
            fn insert_knot(slf: PyRef<'_, Self>, u: f64, times: usize) -> PyResult<Py<PyAny>> {
                let py = slf.py();
                by_dim!(&slf.as_super().inner, $v2, $v3, c =>
                    wrap(py, same!(c.insert_knot(u, times).map_err(geometry)?)))
            }

            /// The same curve with every knot of `knots` inserted (knot refinement).
            fn refine(slf: PyRef<'_, Self>, knots: Vec<f64>) -> PyResult<Py<PyAny>> {
                let py = slf.py();
                by_dim!(&slf.as_super().inner, $v2, $v3, c =>
                    wrap(py, same!(c.refine(&knots).map_err(geometry)?)))
            }

            /// The two pieces on either side of u.
            fn split(slf: PyRef<'_, Self>, u: f64) -> PyResult<(Py<PyAny>, Py<PyAny>)> {
                let py = slf.py();
                by_dim!(&slf.as_super().inner, $v2, $v3, c => {
                    let (a, b) = c.split(u).map_err(geometry)?;
                    pair(py, same!(a), same!(b))
                })
            }

            /// The same curve with its degree raised `times` times.
            #[pyo3(signature = (times = 1))]
            fn elevate_degree(slf: PyRef<'_, Self>, times: usize) -> PyResult<Py<PyAny>> {
                let py = slf.py();
                by_dim!(&slf.as_super().inner, $v2, $v3, c =>
                    wrap(py, same!(c.elevate_degree(times).map_err(geometry)?)))
            }

            /// The same curve on the domain [a, b] (affine change of parameter).
            fn reparameterized(slf: PyRef<'_, Self>, a: f64, b: f64) -> PyResult<Py<PyAny>> {
                let py = slf.py();
                by_dim!(&slf.as_super().inner, $v2, $v3, c =>
                    wrap(py, same!(c.reparameterized(a, b).map_err(geometry)?)))
            }

            /// The same curve with clamped ends (end knots of full multiplicity).
            fn clamped(slf: PyRef<'_, Self>) -> PyResult<Py<PyAny>> {
                let py = slf.py();
                by_dim!(&slf.as_super().inner, $v2, $v3, c => wrap(py, same!(c.clamped())))
            }

            /// The natural extension: the same polynomial pieces continued (or cut back) so that the
            /// domain reaches `t` at `end` (`"start"` or `"end"`); C(u) is unchanged on the old domain.
            fn extrapolated(slf: PyRef<'_, Self>, end: &str, t: f64) -> PyResult<Py<PyAny>> {
                let py = slf.py();
                let end = curve_end(end)?;
                by_dim!(&slf.as_super().inner, $v2, $v3, c =>
                    wrap(py, same!(c.extrapolated(end, t).map_err(geometry)?)))
            }

            /// The curve extended at `end` (`"start"` or `"end"`) by an arc of `length` (length
            /// units): `"G1"` a straight piece along the end tangent, `"G2"` the end piece continued
            /// naturally (found by arc length).
            #[pyo3(signature = (end, length, continuity = "G2"))]
            fn extended_by_length(
                slf: PyRef<'_, Self>,
                end: &str,
                length: f64,
                continuity: &str,
            ) -> PyResult<Py<PyAny>> {
                let py = slf.py();
                let (end, how) = (curve_end(end)?, ext_continuity(continuity)?);
                by_dim!(&slf.as_super().inner, $v2, $v3, c => wrap(
                    py,
                    same!(py.detach(|| c.extended_by_length(end, length, how)).map_err(geometry)?)
                ))
            }

            /// Removes the knot u up to `times` times while the curve moves by at most `tolerance`
            /// (length units): (curve, removed, error_bound); removed is 0 when no removal fits.
            #[pyo3(signature = (u, times = 1, tolerance = 1e-9))]
            fn remove_knot(
                slf: PyRef<'_, Self>,
                u: f64,
                times: usize,
                tolerance: f64,
            ) -> PyResult<(Py<PyAny>, usize, f64)> {
                let py = slf.py();
                by_dim!(&slf.as_super().inner, $v2, $v3, c => {
                    let r = py.detach(|| c.remove_knot(u, times, tolerance)).map_err(geometry)?;
                    Ok((wrap(py, same!(r.curve))?, r.removed, r.error_bound))
                })
            }

            /// The curve of one degree less, its pieces reduced and its knots removed as far as the
            /// original continuity and `tolerance` (length units) allow: (curve, error_bound). The
            /// bound holds everywhere; it exceeds the tolerance only when the pieces themselves
            /// cannot be reduced within it (check it).
            #[pyo3(signature = (tolerance = 1e-9))]
            fn reduce_degree(slf: PyRef<'_, Self>, tolerance: f64) -> PyResult<(Py<PyAny>, f64)> {
                let py = slf.py();
                by_dim!(&slf.as_super().inner, $v2, $v3, c => {
                    let r = py.detach(|| c.reduce_degree(tolerance)).map_err(geometry)?;
                    Ok((wrap(py, same!(r.curve))?, r.error_bound))
                })
            }
        }
    };
}

/// A B-spline curve: `BSplineCurve(degree, knots, control_points)`; the knot vector has
/// control points + degree + 1 entries. `BSplineCurve.clamped_uniform(degree, control_points)` makes
/// the clamped uniform knots on [0, 1].
#[pyclass(name = "BSplineCurve", extends = Curve, frozen, module = "camber._native")]
#[derive(Debug)]
#[allow(non_camel_case_types)] // the Rust name differs from the library's struct; Python sees `BSplineCurve`
pub struct BSplineCurve_;

knotted_curve_methods! {
    BSplineCurve_, BSpline2, BSpline3;

    #[new]
    fn new(
        degree: usize,
        knots: Vec<f64>,
        control_points: RealArray2<'_>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let k = knot_vector(knots)?;
        let inner = match columns(&control_points) {
            3 => AnyCurve::BSpline3(
                BSplineCurve::try_new(degree, k, points::<3>(&control_points, "control_points")?)
                    .map_err(geometry)?,
            ),
            _ => AnyCurve::BSpline2(
                BSplineCurve::try_new(degree, k, points::<2>(&control_points, "control_points")?)
                    .map_err(geometry)?,
            ),
        };
        Ok(PyClassInitializer::from(Curve { inner }).add_subclass(BSplineCurve_))
    }

    /// A B-spline with clamped uniform knots on [0, 1].
    #[staticmethod]
    fn clamped_uniform(
        py: Python<'_>,
        degree: usize,
        control_points: RealArray2<'_>,
    ) -> PyResult<Py<PyAny>> {
        let n = control_points.as_array().nrows();
        let k = KnotVector::clamped_uniform(degree, n).map_err(geometry)?;
        let inner = match columns(&control_points) {
            3 => AnyCurve::BSpline3(
                BSplineCurve::try_new(degree, k, points::<3>(&control_points, "control_points")?)
                    .map_err(geometry)?,
            ),
            _ => AnyCurve::BSpline2(
                BSplineCurve::try_new(degree, k, points::<2>(&control_points, "control_points")?)
                    .map_err(geometry)?,
            ),
        };
        wrap(py, inner)
    }

    /// Reads the JSON form `{"degree", "knots", "control_points"}`.
    #[staticmethod]
    fn from_json(py: Python<'_>, text: &str) -> PyResult<Py<PyAny>> {
        wrap(
            py,
            from_json_2_or_3(text, AnyCurve::BSpline2, AnyCurve::BSpline3)?,
        )
    }

    /// The control points, (n, d).
    #[getter]
    fn control_points<'py>(slf: PyRef<'py, Self>) -> Bound<'py, PyArray2<f64>> {
        control_points_of(slf.py(), &slf.as_super().inner)
    }

    /// Removes every removable interior knot while the curve moves by at most `tolerance`
    /// in all: (curve, removed, error_bound).
    #[pyo3(signature = (tolerance = 1e-9))]
    fn remove_knots(slf: PyRef<'_, Self>, tolerance: f64) -> PyResult<(Py<PyAny>, usize, f64)> {
        let py = slf.py();
        by_dim!(&slf.as_super().inner, BSpline2, BSpline3, c => {
            let r = crate::interrupt::run_geometry(py, |budget| c.remove_knots_with(tolerance, budget))?;
            Ok((wrap(py, same!(r.curve))?, r.removed, r.error_bound))
        })
    }

    /// The Bézier pieces between distinct knots: a list of (a, b, BezierCurve).
    fn to_bezier_segments(slf: PyRef<'_, Self>) -> PyResult<Vec<(f64, f64, Py<PyAny>)>> {
        let py = slf.py();
        match &slf.as_super().inner {
            AnyCurve::BSpline2(c) => c
                .to_bezier_segments()
                .into_iter()
                .map(|(a, b, s)| Ok((a, b, wrap(py, AnyCurve::Bezier2(s))?)))
                .collect(),
            AnyCurve::BSpline3(c) => c
                .to_bezier_segments()
                .into_iter()
                .map(|(a, b, s)| Ok((a, b, wrap(py, AnyCurve::Bezier3(s))?)))
                .collect(),
            _ => Err(input("internal: curve of another kind")),
        }
    }
}

/// A NURBS curve: `NurbsCurve(degree, knots, control_points, weights)` (weights > 0).
#[pyclass(name = "NurbsCurve", extends = Curve, frozen, module = "camber._native")]
#[derive(Debug)]
#[allow(non_camel_case_types)] // the Rust name differs from the library's struct; Python sees `NurbsCurve`
pub struct NurbsCurve_;

knotted_curve_methods! {
    NurbsCurve_, Nurbs2, Nurbs3;

    #[new]
    fn new(
        degree: usize,
        knots: Vec<f64>,
        control_points: RealArray2<'_>,
        weights: Vec<f64>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let k = knot_vector(knots)?;
        let inner = match columns(&control_points) {
            3 => AnyCurve::Nurbs3(
                NurbsCurve::try_new(
                    degree,
                    k,
                    points::<3>(&control_points, "control_points")?,
                    weights,
                )
                .map_err(geometry)?,
            ),
            _ => AnyCurve::Nurbs2(
                NurbsCurve::try_new(
                    degree,
                    k,
                    points::<2>(&control_points, "control_points")?,
                    weights,
                )
                .map_err(geometry)?,
            ),
        };
        Ok(PyClassInitializer::from(Curve { inner }).add_subclass(NurbsCurve_))
    }

    /// The exact circular arc of `radius` about `center` from angle `start` to `end`
    /// (radians, counter-clockwise).
    #[staticmethod]
    fn circular_arc(
        py: Python<'_>,
        center: Vec<f64>,
        radius: f64,
        start: f64,
        end: f64,
    ) -> PyResult<Py<PyAny>> {
        let c = Point::from(vector::<2>(&center, "center")?);
        wrap(
            py,
            AnyCurve::Nurbs2(
                NurbsCurve::try_circular_arc(c, radius, start, end).map_err(geometry)?,
            ),
        )
    }

    /// Reads the JSON form `{"degree", "knots", "control_points", "weights"}`.
    #[staticmethod]
    fn from_json(py: Python<'_>, text: &str) -> PyResult<Py<PyAny>> {
        wrap(
            py,
            from_json_2_or_3(text, AnyCurve::Nurbs2, AnyCurve::Nurbs3)?,
        )
    }

    /// The control points, (n, d).
    #[getter]
    fn control_points<'py>(slf: PyRef<'py, Self>) -> Bound<'py, PyArray2<f64>> {
        control_points_of(slf.py(), &slf.as_super().inner)
    }

    /// The weights.
    #[getter]
    fn weights<'py>(slf: PyRef<'py, Self>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let py = slf.py();
        by_dim!(&slf.as_super().inner, Nurbs2, Nurbs3, c =>
            Ok(PyArray1::from_slice(py, c.weights())))
    }

    /// Whether every weight is equal (the curve is a plain B-spline).
    fn is_polynomial(slf: PyRef<'_, Self>) -> PyResult<bool> {
        by_dim!(&slf.as_super().inner, Nurbs2, Nurbs3, c => Ok(c.is_polynomial()))
    }

    /// The rational Bézier pieces between distinct knots: a list of (a, b, NurbsCurve).
    fn to_bezier_segments(slf: PyRef<'_, Self>) -> PyResult<Vec<(f64, f64, Py<PyAny>)>> {
        let py = slf.py();
        by_dim!(&slf.as_super().inner, Nurbs2, Nurbs3, c => c
            .to_bezier_segments()
            .into_iter()
            .map(|(a, b, s)| Ok((a, b, wrap(py, same!(s))?)))
            .collect())
    }
}

/// A cubic Hermite curve on [0, 1]: `HermiteCurve(p0, p1, t0, t1)` (end points and end
/// tangent vectors).
#[pyclass(name = "HermiteCurve", extends = Curve, frozen, module = "camber._native")]
#[derive(Debug)]
#[allow(non_camel_case_types)] // the Rust name differs from the library's struct; Python sees `HermiteCurve`
pub struct HermiteCurve_;

#[pymethods]
impl HermiteCurve_ {
    #[new]
    fn new(
        p0: Vec<f64>,
        p1: Vec<f64>,
        t0: Vec<f64>,
        t1: Vec<f64>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let inner = match p0.len() {
            3 => AnyCurve::Hermite3(
                HermiteCurve::try_new(
                    Point::from(vector::<3>(&p0, "p0")?),
                    Point::from(vector::<3>(&p1, "p1")?),
                    vector::<3>(&t0, "t0")?,
                    vector::<3>(&t1, "t1")?,
                )
                .map_err(geometry)?,
            ),
            _ => AnyCurve::Hermite2(
                HermiteCurve::try_new(
                    Point::from(vector::<2>(&p0, "p0")?),
                    Point::from(vector::<2>(&p1, "p1")?),
                    vector::<2>(&t0, "t0")?,
                    vector::<2>(&t1, "t1")?,
                )
                .map_err(geometry)?,
            ),
        };
        Ok(PyClassInitializer::from(Curve { inner }).add_subclass(HermiteCurve_))
    }

    /// Reads the JSON form of a Hermite curve.
    #[staticmethod]
    fn from_json(py: Python<'_>, text: &str) -> PyResult<Py<PyAny>> {
        wrap(
            py,
            from_json_2_or_3(text, AnyCurve::Hermite2, AnyCurve::Hermite3)?,
        )
    }

    /// The end points [p0, p1], (2, d).
    #[getter]
    fn control_points<'py>(slf: PyRef<'py, Self>) -> Bound<'py, PyArray2<f64>> {
        control_points_of(slf.py(), &slf.as_super().inner)
    }

    /// The end tangents [t0, t1], (2, d).
    #[getter]
    fn tangents<'py>(slf: PyRef<'py, Self>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let py = slf.py();
        by_dim!(&slf.as_super().inner, Hermite2, Hermite3, c => Ok(points_array(
            py,
            &[Point::from(c.t0()), Point::from(c.t1())]
        )))
    }

    /// The piece between ui and uj, reparameterized to [0, 1].
    fn truncated(slf: PyRef<'_, Self>, ui: f64, uj: f64) -> PyResult<Py<PyAny>> {
        let py = slf.py();
        by_dim!(&slf.as_super().inner, Hermite2, Hermite3, c =>
            wrap(py, same!(c.truncated(ui, uj).map_err(geometry)?)))
    }

    /// `n` equal pieces.
    fn subdivided(slf: PyRef<'_, Self>, n: usize) -> PyResult<Vec<Py<PyAny>>> {
        let py = slf.py();
        by_dim!(&slf.as_super().inner, Hermite2, Hermite3, c => c
            .subdivided(n)
            .map_err(geometry)?
            .into_iter()
            .map(|s| wrap(py, same!(s)))
            .collect())
    }

    /// The pieces between the given interior joints.
    fn subdivided_at(slf: PyRef<'_, Self>, joints: Vec<f64>) -> PyResult<Vec<Py<PyAny>>> {
        let py = slf.py();
        by_dim!(&slf.as_super().inner, Hermite2, Hermite3, c => c
            .subdivided_at(&joints)
            .map_err(geometry)?
            .into_iter()
            .map(|s| wrap(py, same!(s)))
            .collect())
    }

    /// The same curve as a cubic Bézier curve.
    fn to_bezier(slf: PyRef<'_, Self>) -> PyResult<Py<PyAny>> {
        let py = slf.py();
        match &slf.as_super().inner {
            AnyCurve::Hermite2(c) => wrap(py, AnyCurve::Bezier2(c.to_bezier().map_err(geometry)?)),
            AnyCurve::Hermite3(c) => wrap(py, AnyCurve::Bezier3(c.to_bezier().map_err(geometry)?)),
            _ => Err(input("internal: curve of another kind")),
        }
    }
}

/// Adds the curve classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Curve>()?;
    m.add_class::<BezierCurve_>()?;
    m.add_class::<BSplineCurve_>()?;
    m.add_class::<NurbsCurve_>()?;
    m.add_class::<HermiteCurve_>()?;
    m.add_class::<CompositeCurve_>()?;
    Ok(())
}
