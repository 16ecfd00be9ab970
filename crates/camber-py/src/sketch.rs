//! The `Sketch` class: entities, every constraint kind through its file form, load and save,
//! solve (a `SolveReport` with per-constraint residuals), the DOF analysis, iterative
//! displacement, and drag sessions (`DragSession`). Solves, analyses and drags release the
//! GIL.

use camber_sketch::displacement::DisplacementOptions;
use camber_sketch::file::{constraint_to_value, entity_to_value};
use camber_sketch::{ConstraintId, Entity, EntityId, PointRef, SketchReport};
use nalgebra::Point2;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::arrays::{points, vector, RealArray2};
use crate::curve::{AnyCurve, Curve};
use crate::custom::Raised;
use crate::errors;
use crate::interrupt;
use crate::json::{to_python, to_value};

/// A point reference: an int (a point entity) or its file form (`{"point": 0}`,
/// `{"control": [curve, index]}`, `{"start": curve}`, `{"end": curve}`).
pub fn point_ref(obj: &Bound<'_, PyAny>) -> PyResult<PointRef> {
    if let Ok(id) = obj.extract::<u64>() {
        return Ok(PointRef::Point(EntityId(id)));
    }
    serde_json::from_value(to_value(obj)?)
        .map_err(|e| errors::SketchError::new_err(format!("invalid point reference: {e}")))
}

/// A priority tier from its file form: an integer from 0 to 255.
fn priority(v: &serde_json::Value) -> PyResult<u8> {
    v.as_u64()
        .and_then(|p| u8::try_from(p).ok())
        .ok_or_else(|| {
            errors::FileError::new_err(format!(
                "priority: expected a priority tier, an integer from 0 (required) to 255, found {v}"
            ))
        })
}

fn xy(v: &[f64], what: &str) -> PyResult<Point2<f64>> {
    Ok(Point2::from(vector::<2>(v, what)?))
}

/// A solve report as a `camber.reports.SolveReport`.
pub fn report_object(py: Python<'_>, report: &SketchReport) -> PyResult<Py<PyAny>> {
    let dict = to_python(py, report)?;
    Ok(py
        .import("camber.reports")?
        .getattr("SolveReport")?
        .call1((dict,))?
        .unbind())
}

/// A planar sketch of points, lines, circles and curves held by constraints.
///
/// Entities and constraints are named by integer ids that stay valid across edits. Constraints
/// of every kind are added by their file form: `sketch.add_constraint("distance",
/// a={"point": 0}, b={"point": 1}, value=2.0)` (docs/file-format.md lists the kinds and
/// fields).
#[pyclass(module = "camber._native")]
#[derive(Debug, Clone, Default)]
pub struct Sketch {
    /// The library's sketch.
    pub inner: camber_sketch::Sketch,
}

#[pymethods]
impl Sketch {
    #[new]
    fn new() -> Self {
        Self::default()
    }

    /// Reads a sketch from its JSON text (Ctrl-C stops a long read).
    #[staticmethod]
    fn from_json(py: Python<'_>, text: &str) -> PyResult<Self> {
        let inner =
            interrupt::run(py, |_| camber_sketch::file::from_json(text))?.map_err(errors::file)?;
        Ok(Self { inner })
    }

    /// Reads a sketch file.
    #[staticmethod]
    fn load(py: Python<'_>, path: std::path::PathBuf) -> PyResult<Self> {
        let text = std::fs::read_to_string(&path).map_err(|e| {
            errors::FileError::new_err(format!("cannot read {}: {e}", path.display()))
        })?;
        Self::from_json(py, &text)
    }

    /// The sketch as JSON text (the file format).
    fn to_json(&self) -> PyResult<String> {
        camber_sketch::file::to_json(&self.inner).map_err(errors::file)
    }

    /// Writes the sketch file.
    fn save(&self, path: std::path::PathBuf) -> PyResult<()> {
        let text = self.to_json()?;
        std::fs::write(&path, text).map_err(|e| {
            errors::FileError::new_err(format!("cannot write {}: {e}", path.display()))
        })
    }

    /// An independent copy.
    fn copy(&self) -> Self {
        self.clone()
    }

    /// The sketch as plain Python values (dicts, lists, numbers, strings): the file format
    /// read by `json.loads`.
    fn to_dict(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        let text = self.to_json()?;
        Ok(py.import("json")?.call_method1("loads", (text,))?.unbind())
    }

    /// Reads a sketch from plain Python values in the file format (what `to_dict` gives).
    #[staticmethod]
    fn from_dict(py: Python<'_>, data: &Bound<'_, PyAny>) -> PyResult<Self> {
        let text: String = py
            .import("json")?
            .call_method1("dumps", (data,))?
            .extract()?;
        Self::from_json(py, &text)
    }

    /// Pickling goes through the file format: `Sketch.from_json(sketch.to_json())`. A sketch
    /// holding a Python custom constraint has no file form, so it cannot be pickled.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (String,))> {
        let text = slf.borrow().to_json()?;
        Ok((slf.get_type().getattr("from_json")?, (text,)))
    }

    /// Adds a point entity; returns its id.
    fn add_point(&mut self, at: Vec<f64>) -> PyResult<u64> {
        let p = xy(&at, "at")?;
        Ok(self.inner.add_point(p).map_err(errors::sketch)?.0)
    }

    /// Adds a line through two points; returns its id.
    fn add_line(&mut self, start: Vec<f64>, end: Vec<f64>) -> PyResult<u64> {
        let (a, b) = (xy(&start, "start")?, xy(&end, "end")?);
        Ok(self.inner.add_line(a, b).map_err(errors::sketch)?.0)
    }

    /// Adds a circle; returns its id.
    fn add_circle(&mut self, center: Vec<f64>, radius: f64) -> PyResult<u64> {
        let c = xy(&center, "center")?;
        Ok(self.inner.add_circle(c, radius).map_err(errors::sketch)?.0)
    }

    /// Adds a circular arc, counter-clockwise from `start_angle` to `end_angle` (radians) on the
    /// circle of `center` and `radius` (> 0); returns its id. Its points are 0 the centre, 1
    /// the start, 2 the end (`{"start": arc}`, `{"end": arc}` name its ends).
    fn add_arc(
        &mut self,
        center: Vec<f64>,
        radius: f64,
        start_angle: f64,
        end_angle: f64,
    ) -> PyResult<u64> {
        let c = xy(&center, "center")?;
        let arc = camber_geom::CircularArc::try_new(c, radius, start_angle, end_angle)
            .map_err(errors::geometry)?;
        Ok(self.inner.add_arc(&arc).map_err(errors::sketch)?.0)
    }

    /// Adds an ellipse of `center`, semi-axes `a` along the direction `rotation` (radians from
    /// +x) and `b` across it (both > 0); returns its id. Its points are 0 the centre and 1 the
    /// a-axis vertex; b is a scalar of its own (`semi_axis` with `axis="b"` holds it).
    fn add_ellipse(&mut self, center: Vec<f64>, a: f64, b: f64, rotation: f64) -> PyResult<u64> {
        let c = xy(&center, "center")?;
        let ellipse = camber_geom::Ellipse::try_new(c, a, b, rotation).map_err(errors::geometry)?;
        Ok(self.inner.add_ellipse(&ellipse).map_err(errors::sketch)?.0)
    }

    /// Adds an arc of the ellipse of [`add_ellipse`](Self::add_ellipse), counter-clockwise
    /// from the parametric angle `start_angle` to `end_angle` (radians; the point at θ is
    /// C + a·cos θ·u + b·sin θ·v in the ellipse's frame); returns its id. Its points are 0 the
    /// centre, 1 the a-axis vertex, 2 the start and 3 the end (`{"start": arc}`,
    /// `{"end": arc}` name its ends).
    #[allow(clippy::too_many_arguments)] // The six numbers of an elliptic arc, named as in the file.
    fn add_elliptic_arc(
        &mut self,
        center: Vec<f64>,
        a: f64,
        b: f64,
        rotation: f64,
        start_angle: f64,
        end_angle: f64,
    ) -> PyResult<u64> {
        let c = xy(&center, "center")?;
        let arc = camber_geom::EllipticArc::try_new(c, a, b, rotation, start_angle, end_angle)
            .map_err(errors::geometry)?;
        Ok(self.inner.add_elliptic_arc(&arc).map_err(errors::sketch)?.0)
    }

    /// Rounds the corner between two lines, a line and a curve, or two curves (Bézier,
    /// B-spline, NURBS; a pair with a curve must share an end) with an arc of `radius` tangent
    /// to both, trimming them to its tangent points and holding it by constraints (a
    /// coincident and an `arc_tangent_to_line` or `arc_tangent_to_curve` at each end, the
    /// `radius`); a coincidence that joined the corner is removed (with a curve, every
    /// constraint at its removed end). Returns `{"arc": id, "added": [ids], "removed": [ids]}`.
    /// A fillet that cannot be made (parallel lines, a radius too large, legs tangent at the
    /// corner) raises and changes nothing.
    fn fillet(
        &mut self,
        py: Python<'_>,
        first: u64,
        second: u64,
        radius: f64,
    ) -> PyResult<Py<PyAny>> {
        let f = self
            .inner
            .fillet(EntityId(first), EntityId(second), radius)
            .map_err(errors::sketch)?;
        let d = PyDict::new(py);
        d.set_item("arc", f.arc.0)?;
        d.set_item("added", f.added.iter().map(|c| c.0).collect::<Vec<_>>())?;
        d.set_item("removed", f.removed.iter().map(|c| c.0).collect::<Vec<_>>())?;
        Ok(d.into_any().unbind())
    }

    /// Splits entity `entity` (a line, an arc or a Bézier, B-spline or NURBS curve) where it
    /// crosses `other`; with several crossings, `near` ([x, y]) picks the nearest, and without
    /// it the split raises. The entity keeps the piece from its start to the crossing, a new
    /// entity holds the rest; a coincident and the joint on `other` are added. Returns
    /// `{"first": id, "second": id, "point": [x, y], "added": [ids], "moved": [[old, new]]}`.
    /// Raises and changes nothing when they do not cross or a constraint cannot follow.
    #[pyo3(signature = (entity, other, near = None))]
    fn split_at_intersection(
        &mut self,
        py: Python<'_>,
        entity: u64,
        other: u64,
        near: Option<Vec<f64>>,
    ) -> PyResult<Py<PyAny>> {
        let near = near.map(|p| xy(&p, "near")).transpose()?;
        let split = self
            .inner
            .split_at_intersection(EntityId(entity), EntityId(other), near)
            .map_err(errors::sketch)?;
        let d = PyDict::new(py);
        d.set_item("first", split.first.0)?;
        d.set_item("second", split.second.0)?;
        d.set_item("point", [split.point.x, split.point.y])?;
        d.set_item("added", split.added.iter().map(|c| c.0).collect::<Vec<_>>())?;
        d.set_item(
            "moved",
            split
                .moved
                .iter()
                .map(|(a, b)| [a.0, b.0])
                .collect::<Vec<_>>(),
        )?;
        Ok(d.into_any().unbind())
    }

    /// Trims entity `entity` where it crosses `at`, keeping `keep` ("start": the piece from
    /// its start to the crossing, or "end") and holding the cut end on `at`; `near` picks among
    /// several crossings. The constraints at the dropped end are removed. Returns
    /// `{"entity": id, "point": [x, y], "added": id, "removed": [ids]}`; raises and changes
    /// nothing on bad input.
    #[pyo3(signature = (entity, at, keep, near = None))]
    fn trim(
        &mut self,
        py: Python<'_>,
        entity: u64,
        at: u64,
        keep: &str,
        near: Option<Vec<f64>>,
    ) -> PyResult<Py<PyAny>> {
        let keep = match keep {
            "start" => camber_sketch::sketch::split::Keep::Start,
            "end" => camber_sketch::sketch::split::Keep::End,
            other => {
                return Err(errors::SketchError::new_err(format!(
                    "keep: expected \"start\" or \"end\", found {other:?}"
                )))
            }
        };
        let near = near.map(|p| xy(&p, "near")).transpose()?;
        let trim = self
            .inner
            .trim(EntityId(entity), EntityId(at), keep, near)
            .map_err(errors::sketch)?;
        let d = PyDict::new(py);
        d.set_item("entity", trim.entity.0)?;
        d.set_item("point", [trim.point.x, trim.point.y])?;
        d.set_item("added", trim.added.0)?;
        d.set_item(
            "removed",
            trim.removed.iter().map(|c| c.0).collect::<Vec<_>>(),
        )?;
        Ok(d.into_any().unbind())
    }

    /// Trims the circle or ellipse `entity` where it crosses the entities `at`, removing the
    /// piece around `remove_near` ([x, y]) between the two crossings nearest it on either
    /// side; it becomes a circular or elliptic arc (same id and shape) with each end held on
    /// the entity it lies on. Returns `{"entity": id, "start": [x, y], "end": [x, y], "added": [id, id]}`; raises
    /// and changes nothing on bad input (fewer than two crossings, a constraint an arc cannot
    /// carry).
    fn trim_closed(
        &mut self,
        py: Python<'_>,
        entity: u64,
        at: Vec<u64>,
        remove_near: Vec<f64>,
    ) -> PyResult<Py<PyAny>> {
        let near = xy(&remove_near, "remove_near")?;
        let at: Vec<EntityId> = at.into_iter().map(EntityId).collect();
        let trim = self
            .inner
            .trim_closed(EntityId(entity), &at, near)
            .map_err(errors::sketch)?;
        let d = PyDict::new(py);
        d.set_item("entity", trim.entity.0)?;
        d.set_item("start", [trim.start.x, trim.start.y])?;
        d.set_item("end", [trim.end.x, trim.end.y])?;
        d.set_item("added", trim.added.map(|c| c.0))?;
        Ok(d.into_any().unbind())
    }

    /// Adds a planar Bézier, B-spline or NURBS curve (a `camber` curve object); returns its id.
    fn add_curve(&mut self, curve: PyRef<'_, Curve>) -> PyResult<u64> {
        let id = match &curve.inner {
            AnyCurve::Bezier2(c) => self.inner.add_bezier(c.clone()),
            AnyCurve::BSpline2(c) => self.inner.add_bspline(c.clone()),
            AnyCurve::Nurbs2(c) => self.inner.add_nurbs(c.clone()),
            _ => {
                return Err(errors::SketchError::new_err(
                    "a sketch holds planar Bézier, B-spline and NURBS curves",
                ))
            }
        };
        Ok(id.map_err(errors::sketch)?.0)
    }

    /// Adds a Bézier curve from an (n, 2) array of control points; returns its id.
    fn add_bezier(&mut self, control_points: RealArray2<'_>) -> PyResult<u64> {
        let pts = points::<2>(&control_points, "control_points")?;
        let c = camber_geom::BezierCurve2::try_new(pts).map_err(errors::geometry)?;
        Ok(self.inner.add_bezier(c).map_err(errors::sketch)?.0)
    }

    /// Entity ids, in increasing order.
    fn entity_ids(&self) -> Vec<u64> {
        self.inner.entities().map(|(id, _)| id.0).collect()
    }

    /// Constraint ids, in increasing order.
    fn constraint_ids(&self) -> Vec<u64> {
        self.inner.constraints().map(|(id, _)| id.0).collect()
    }

    /// Labels an entity with a tag (a free name such as the DXF layer it came from; saved in
    /// files, never read by a solve), or clears it with `None`.
    #[pyo3(signature = (id, tag))]
    fn set_tag(&mut self, id: u64, tag: Option<&str>) -> PyResult<()> {
        self.inner
            .set_tag(EntityId(id), tag)
            .map_err(errors::sketch)
    }

    /// An entity's tag, `None` when it has none.
    fn tag(&self, id: u64) -> Option<String> {
        self.inner.tag(EntityId(id)).map(str::to_owned)
    }

    /// An entity's file form as a dict (`{"kind": "bezier", "control_points": …}`).
    fn entity(&self, py: Python<'_>, id: u64) -> PyResult<Py<PyAny>> {
        let e = self.inner.entity(EntityId(id)).map_err(errors::sketch)?;
        to_python(py, &entity_to_value(e).map_err(errors::file)?)
    }

    /// A curve entity as a camber curve object with the same points at the same parameters,
    /// for evaluation and plotting: a line as a Bézier curve of degree 1, a Hermite curve as
    /// itself, a composite as the exact cubic B-spline over its segments' Bézier points (on
    /// [0, n], interior knots three times), an arc, ellipse or elliptic arc as its exact NURBS
    /// form. Points and circles raise `SketchError`.
    fn curve(&self, py: Python<'_>, id: u64) -> PyResult<Py<PyAny>> {
        let e = self.inner.entity(EntityId(id)).map_err(errors::sketch)?;
        let inner = match e {
            Entity::Bezier(c) => AnyCurve::Bezier2(c.clone()),
            Entity::BSpline(c) => AnyCurve::BSpline2(c.clone()),
            Entity::Nurbs(c) => AnyCurve::Nurbs2(c.clone()),
            Entity::Line([a, b]) => AnyCurve::Bezier2(
                camber_geom::BezierCurve2::try_new(vec![*a, *b]).map_err(errors::geometry)?,
            ),
            // An arc as its exact rational form (quadratic pieces of at most a quarter turn).
            Entity::Arc(_) => match e.as_arc() {
                Some(arc) => AnyCurve::Nurbs2(arc.to_nurbs().map_err(errors::geometry)?),
                None => {
                    return Err(errors::SketchError::new_err(format!(
                        "entity {id} is an arc whose ends are at the centre"
                    )))
                }
            },
            Entity::Ellipse { .. } | Entity::EllipticArc { .. } => {
                // `as_ellipse` gives an elliptic arc's whole ellipse too: ask by kind.
                let nurbs = match (e, e.as_ellipse(), e.as_elliptic_arc()) {
                    (Entity::EllipticArc { .. }, _, Some(arc)) => arc.to_nurbs(),
                    (Entity::Ellipse { .. }, Some(ellipse), _) => ellipse.to_nurbs(),
                    _ => {
                        return Err(errors::SketchError::new_err(format!(
                            "entity {id} is an {} whose blocks make no curve",
                            e.kind_name()
                        )))
                    }
                };
                AnyCurve::Nurbs2(nurbs.map_err(errors::geometry)?)
            }
            Entity::Hermite(chain) => AnyCurve::Hermite2(chain.segment(0).map_err(errors::sketch)?),
            Entity::Composite(chain) => AnyCurve::BSpline2(
                camber_geom::BSplineCurve2::try_new(3, chain.knots(), chain.bezier_points())
                    .map_err(errors::geometry)?,
            ),
            other => {
                return Err(errors::SketchError::new_err(format!(
                    "entity {id} is a {}, not a curve",
                    other.kind_name()
                )))
            }
        };
        crate::curve_kinds::wrap(py, inner)
    }

    /// The coordinates of a point (see the class documentation for point references).
    fn point<'py>(
        &self,
        py: Python<'py>,
        at: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let p = self.inner.point(point_ref(at)?).map_err(errors::sketch)?;
        Ok(PyArray1::from_slice(py, p.coords.as_slice()))
    }

    /// Moves a point (marks its component for the next solve).
    fn set_point(&mut self, at: &Bound<'_, PyAny>, to: Vec<f64>) -> PyResult<()> {
        let r = point_ref(at)?;
        let p = xy(&to, "to")?;
        self.inner.set_point(r, p).map_err(errors::sketch)
    }

    /// The point C(u) of a curve entity.
    fn curve_point<'py>(
        &self,
        py: Python<'py>,
        curve: u64,
        u: f64,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let p = self
            .inner
            .curve_point(EntityId(curve), u)
            .map_err(errors::sketch)?;
        Ok(PyArray1::from_slice(py, p.coords.as_slice()))
    }

    /// Removes an entity (and the constraints on it); returns its file form.
    fn remove_entity(&mut self, py: Python<'_>, id: u64) -> PyResult<Py<PyAny>> {
        let e = self
            .inner
            .remove_entity(EntityId(id))
            .map_err(errors::sketch)?;
        to_python(py, &entity_to_value(&e).map_err(errors::file)?)
    }

    /// Adds a constraint of kind `kind` with the fields of its file form; returns its id.
    ///
    /// `sketch.add_constraint("fixed", target={"point": {"start": 0}})`,
    /// `sketch.add_constraint("tangent_to_circle", curve=0, circle=1, u={"free": 0.5},
    /// side="outside", rotation="clockwise")`. The kind's JSON is read by the library's own
    /// loader, so every kind and field the file format has is available and checked the same
    /// way (errors name the bad field). `priority=P` (0 required, the default; 1–255 a tier
    /// that gives way to lower ones when not all can be met) is the file's `"priority"` field.
    #[pyo3(signature = (kind, **fields))]
    fn add_constraint(&mut self, kind: &str, fields: Option<&Bound<'_, PyDict>>) -> PyResult<u64> {
        let mut map = match fields {
            Some(f) => match to_value(f.as_any())? {
                serde_json::Value::Object(m) => m,
                _ => serde_json::Map::new(),
            },
            None => serde_json::Map::new(),
        };
        let priority = match map.remove("priority") {
            None => 0,
            Some(v) => priority(&v)?,
        };
        map.insert("kind".into(), serde_json::Value::String(kind.to_owned()));
        // A number given as a string is an expression of the sketch's parameters.
        let id = camber_sketch::file::add_constraint_from_value(
            &mut self.inner,
            serde_json::Value::Object(map),
        )
        .map_err(errors::file)?;
        if priority > 0 {
            if let Err(e) = self.inner.set_priority(id, priority) {
                // The constraint goes with its refused priority: nothing half added.
                let _ = self.inner.remove_constraint(id);
                return Err(errors::sketch(e));
            }
        }
        Ok(id.0)
    }

    /// Sets a constraint's priority tier (0 required; 1–255 gives way to lower tiers when not
    /// every constraint can be met).
    fn set_priority(&mut self, id: u64, priority: u8) -> PyResult<()> {
        self.inner
            .set_priority(ConstraintId(id), priority)
            .map_err(errors::sketch)
    }

    /// A constraint's priority tier (0 for a required one).
    fn priority(&self, id: u64) -> PyResult<u8> {
        self.inner
            .constraint(ConstraintId(id))
            .map_err(errors::sketch)?;
        Ok(self.inner.priority(ConstraintId(id)))
    }

    /// Adds an expression constraint; returns its id. `rows` is a string or a list of strings
    /// (each a scalar or vector row, `a = b` meaning a − b; docs/custom-constraints.md gives
    /// the language), `name` is shown in reports and pictures, and every other keyword names a
    /// sketch quantity: an int (an entity: a point entity, a curve, a line or a circle, by its
    /// kind) or a file form (`{"control": [curve, i]}`, `{"start": curve}`, `{"end": curve}`,
    /// `{"free": 0.5}` for an unknown of its own). Compiled once to a tape evaluated in Rust:
    /// solves release the GIL and run on every thread of `solve_many`.
    #[pyo3(signature = (rows, name = String::new(), **args))]
    fn add_expression(
        &mut self,
        rows: &Bound<'_, PyAny>,
        name: String,
        args: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<u64> {
        let form = crate::expression::form(&self.inner, rows, name, args)?;
        Ok(
            camber_sketch::file::add_constraint_from_value(&mut self.inner, form)
                .map_err(errors::file)?
                .0,
        )
    }

    /// Defines parameter `name` or changes its value without solving (see `set_parameter`).
    fn define_parameter(&mut self, name: &str, value: f64) -> PyResult<()> {
        self.inner
            .define_parameter(name, value)
            .map(|_| ())
            .map_err(errors::sketch)
    }

    /// Sets parameter `name` and re-solves the components that read it; returns the
    /// `SolveReport`. A failed solve leaves the sketch as it was (and raises `SolveError`).
    fn set_parameter(&mut self, py: Python<'_>, name: &str, value: f64) -> PyResult<Py<PyAny>> {
        let inner = &mut self.inner;
        let report = py
            .detach(|| inner.set_parameter(name, value))
            .map_err(errors::solve)?;
        report_object(py, &report)
    }

    /// The value of parameter `name` (None when there is none).
    fn parameter(&self, name: &str) -> Option<f64> {
        self.inner.parameter(name)
    }

    /// Every parameter as a dict name → value.
    #[getter]
    fn parameters(&self) -> std::collections::BTreeMap<String, f64> {
        self.inner
            .parameters()
            .iter()
            .map(|(n, p)| (n.to_owned(), p.value))
            .collect()
    }

    /// Writes the number at `path` of constraint `id`'s file form (`"distance"`,
    /// `"target.at[0]"`) as the expression `text` of the parameters.
    fn bind_dimension(&mut self, id: u64, path: &str, text: &str) -> PyResult<()> {
        self.inner
            .bind_dimension(ConstraintId(id), path, text)
            .map_err(errors::sketch)
    }

    /// Sets the value of dimension `id` (a distance, a radius, an angle, an arc length, …);
    /// the next solve re-solves its component. Raises for a kind without a value, a value the
    /// kind refuses, or a value that follows an expression of the parameters (`unbind_value`
    /// first).
    fn set_value(&mut self, id: u64, value: f64) -> PyResult<()> {
        self.inner
            .set_value(ConstraintId(id), value)
            .map_err(errors::sketch)
    }

    /// Writes the value of dimension `id` (its `distance`, `radius`, `angle`, `length`, …) as
    /// the expression `text` of the parameters.
    fn bind_value(&mut self, id: u64, text: &str) -> PyResult<()> {
        self.inner
            .bind_value(ConstraintId(id), text)
            .map_err(errors::sketch)
    }

    /// Drops the expression dimension `id`'s value follows: it keeps its current number.
    fn unbind_value(&mut self, id: u64) -> PyResult<()> {
        self.inner
            .unbind_value(ConstraintId(id))
            .map_err(errors::sketch)
    }

    /// Adds a custom constraint whose residual is the Python function `residual(x)`; returns
    /// its id. `args` lists what it reads, in order: an int (a point entity) or a file form
    /// (`{"point": ref}` / `{"control": [curve, i]}` wrapped as `{"point": {...}}`,
    /// `{"radius": circle}`, `{"curve": curve}`, `{"free_of": [constraint, index]}`, `{"param":
    /// start}`); `x` is their values flattened (a point gives two, a curve all its control
    /// points' coordinates, x₀, y₀, x₁, …; see `camber.custom.curve_point` to evaluate it
    /// inside the residual). `residual` returns `dim` numbers and is
    /// differentiated exactly with num-dual's dual numbers (see `camber.custom`). Declare
    /// `affine=True` only for a residual affine in its arguments: its component may then take
    /// the one-step linear path.
    #[pyo3(signature = (residual, args, dim, name = "python".to_owned(), affine = false))]
    fn add_custom(
        &mut self,
        py: Python<'_>,
        residual: Py<PyAny>,
        args: Vec<Bound<'_, PyAny>>,
        dim: usize,
        name: String,
        affine: bool,
    ) -> PyResult<u64> {
        let c = crate::custom::custom(py, residual, &args, dim, name, affine)?;
        Ok(self.inner.add_constraint(c).map_err(errors::sketch)?.0)
    }

    /// The current value of a custom constraint's own parameters (its `{"param": …}` args).
    fn custom_params(&self, id: u64) -> PyResult<Vec<f64>> {
        let c = self
            .inner
            .constraint(ConstraintId(id))
            .map_err(errors::sketch)?;
        let custom = c.as_custom().ok_or_else(|| {
            errors::SketchError::new_err(format!("constraint {id} is not a custom constraint"))
        })?;
        Ok(custom
            .args()
            .iter()
            .filter_map(|a| match a {
                camber_sketch::Arg::Param(v) => Some(*v),
                _ => None,
            })
            .collect())
    }

    /// A constraint's file form as a dict (`{"kind": …, …fields}`, with `"priority"` when it
    /// is not 0, as in a sketch file).
    fn constraint(&self, py: Python<'_>, id: u64) -> PyResult<Py<PyAny>> {
        let c = self
            .inner
            .constraint(ConstraintId(id))
            .map_err(errors::sketch)?;
        let mut value = constraint_to_value(c).map_err(errors::file)?;
        let priority = self.inner.priority(ConstraintId(id));
        if let (serde_json::Value::Object(map), true) = (&mut value, priority > 0) {
            map.insert("priority".into(), priority.into());
        }
        to_python(py, &value)
    }

    /// Removes a constraint; returns its file form (custom constraints: their name).
    fn remove_constraint(&mut self, py: Python<'_>, id: u64) -> PyResult<Py<PyAny>> {
        let c = self
            .inner
            .remove_constraint(ConstraintId(id))
            .map_err(errors::sketch)?;
        match constraint_to_value(&c) {
            Ok(v) => to_python(py, &v),
            Err(_) => to_python(py, &serde_json::json!({"kind": c.tag()})),
        }
    }

    /// The connected components: a list of {"entities": [...], "constraints": [...]}.
    fn components(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        to_python(py, &self.inner.components())
    }

    /// Solves the components changed since the last solve (every component with `all=True`).
    /// Returns a `SolveReport`; raises `SolveError` (the sketch unchanged) when a component
    /// fails, or the exception a custom residual raised when that made it fail. The GIL is
    /// released during the solve; Ctrl-C stops it (`KeyboardInterrupt`, the sketch unchanged).
    #[pyo3(signature = (all = false))]
    fn solve(&mut self, py: Python<'_>, all: bool) -> PyResult<Py<PyAny>> {
        let raised = Raised::of(&self.inner);
        let inner = &mut self.inner;
        let report = interrupt::run(py, |flag| {
            cancellable(inner, flag, |s| if all { s.solve_all() } else { s.solve() })
        });
        let report = raised.finish(py, report, |e| errors::solve_in(inner, e))?;
        report_object(py, &report)
    }

    /// The DOF analysis of every component: a list of {"component", "analysis": {"unknowns",
    /// "rank", "dof", "redundant", "conflicting", …}}. Ctrl-C stops it.
    fn analyze(&mut self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        let raised = Raised::of(&self.inner);
        let inner = &mut self.inner;
        let analysis = interrupt::run(py, |flag| cancellable(inner, flag, |s| s.analyze()));
        let analysis = raised.finish(py, analysis, |e| errors::solve_in(inner, e))?;
        to_python(py, &analysis)
    }

    /// Solves contacts with fixed circles and lines by iterative displacement (the blade-design
    /// method). Returns {"rounds", "converged", "history", "report": SolveReport}.
    #[pyo3(signature = (max_rounds = 50, tolerance = 1e-6, samples = 200))]
    fn solve_by_displacement(
        &mut self,
        py: Python<'_>,
        max_rounds: usize,
        tolerance: f64,
        samples: usize,
    ) -> PyResult<Py<PyAny>> {
        let options = DisplacementOptions {
            max_rounds,
            tolerance,
            samples,
        };
        let raised = Raised::of(&self.inner);
        let inner = &mut self.inner;
        let run = interrupt::run(py, |flag| {
            cancellable(inner, flag, |s| s.solve_by_displacement(&options))
        });
        let run = raised.finish(py, run, |e| errors::solve_in(inner, e))?;
        let out = PyDict::new(py);
        out.set_item("rounds", run.rounds)?;
        out.set_item("converged", run.converged)?;
        out.set_item("history", run.history)?;
        out.set_item("report", report_object(py, &run.report)?)?;
        Ok(out.into_any().unbind())
    }

    /// Starts dragging a point; `session.update(xy)` moves it, `session.finish()` writes the
    /// dragged state back into this sketch. Ctrl-C stops a long start.
    fn drag(slf: Bound<'_, Self>, at: &Bound<'_, PyAny>) -> PyResult<DragSession> {
        let r = point_ref(at)?;
        let py = slf.py();
        let (session, raised) = {
            let mut this = slf.borrow_mut();
            let raised = Raised::of(&this.inner);
            let inner = &mut this.inner;
            let session = interrupt::run(py, |flag| cancellable(inner, flag, |s| s.drag(r)));
            let mut session = raised.finish(py, session, |e| errors::solve_in(inner, e))?;
            session.set_cancel(None);
            (session, raised)
        };
        Ok(DragSession {
            session: Some(session),
            sketch: slf.unbind(),
            raised,
        })
    }

    fn __repr__(&self) -> String {
        format!(
            "<Sketch: {} entities, {} constraints>",
            self.inner.entities().count(),
            self.inner.constraints().count()
        )
    }
}

/// Runs `work` on `sketch` with `flag` as its solves' cancel flag, the sketch's options as
/// they were afterwards.
fn cancellable<T>(
    sketch: &mut camber_sketch::Sketch,
    flag: &camber_solve::CancelFlag,
    work: impl FnOnce(&mut camber_sketch::Sketch) -> T,
) -> T {
    let before = sketch.options().cancel.clone();
    sketch.set_options(sketch.options().clone().with_cancel(Some(flag.clone())));
    let out = work(sketch);
    sketch.set_options(sketch.options().clone().with_cancel(before));
    out
}

/// An interactive drag of one point of a sketch (see `Sketch.drag`).
#[pyclass(module = "camber._native")]
pub struct DragSession {
    session: Option<camber_sketch::DragSession>,
    sketch: Py<Sketch>,
    /// The exception slots of the Python residuals the drag runs.
    raised: Raised,
}

impl DragSession {
    fn live(&mut self) -> PyResult<&mut camber_sketch::DragSession> {
        self.session
            .as_mut()
            .ok_or_else(|| errors::SolveError::new_err("the drag session is finished"))
    }
}

#[pymethods]
impl DragSession {
    /// Moves the dragged point towards `target` and re-solves its component (GIL released,
    /// Ctrl-C honoured). Returns what changed: `{"moved": [entity ids], "residuals":
    /// {constraint id: max |g|}}`. A target farther than a thousand sketch sizes from the
    /// sketch is refused with `SolveError`; a refused update keeps the session's state.
    fn update<'py>(&mut self, py: Python<'py>, target: Vec<f64>) -> PyResult<Bound<'py, PyDict>> {
        let p = xy(&target, "target")?;
        let session = self
            .session
            .as_mut()
            .ok_or_else(|| errors::SolveError::new_err("the drag session is finished"))?;
        let done = interrupt::run(py, |flag| {
            session.set_cancel(Some(flag.clone()));
            let done = session.update(p).cloned();
            session.set_cancel(None);
            done
        });
        let update = {
            let sketch = self.sketch.borrow(py);
            self.raised
                .finish(py, done, |e| errors::solve_in(&sketch.inner, e))?
        };
        let out = PyDict::new(py);
        let moved: Vec<u64> = update.moved.iter().map(|id| id.0).collect();
        out.set_item("moved", moved)?;
        let residuals = PyDict::new(py);
        for (id, r) in &update.residuals {
            residuals.set_item(id.0, *r)?;
        }
        out.set_item("residuals", residuals)?;
        Ok(out)
    }

    /// A point's coordinates in the dragged state.
    fn point<'py>(
        &mut self,
        py: Python<'py>,
        at: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let r = point_ref(at)?;
        let p = self.live()?.point(r).map_err(errors::solve)?;
        Ok(PyArray1::from_slice(py, p.coords.as_slice()))
    }

    /// How the point can move: ("free", None), ("along", (dx, dy)) or ("determined", None).
    #[getter]
    fn freedom(&mut self) -> PyResult<(&'static str, Option<(f64, f64)>)> {
        Ok(match self.live()?.freedom() {
            camber_sketch::drag::Freedom::Free => ("free", None),
            camber_sketch::drag::Freedom::Along(d) => ("along", Some((d.x, d.y))),
            camber_sketch::drag::Freedom::Determined => ("determined", None),
        })
    }

    /// Writes the dragged state back into the sketch and ends the session.
    fn finish(&mut self, py: Python<'_>) -> PyResult<()> {
        let session = self
            .session
            .take()
            .ok_or_else(|| errors::SolveError::new_err("the drag session is finished"))?;
        let mut sketch = self.sketch.borrow_mut(py);
        session.finish(&mut sketch.inner).map_err(errors::solve)
    }
}

/// Adds the sketch classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Sketch>()?;
    m.add_class::<DragSession>()?;
    Ok(())
}
