//! The composite curve class: an ordered chain of curves of any kind (Bézier, B-spline, NURBS,
//! Hermite) evaluated as one curve on the global parameter s ∈ [0, n], piece i on [i, i + 1]
//! (camber-geom's [`CompositeCurve`] over a closed set of piece kinds, so the chain is `Clone`,
//! `Send` and `Sync` and every query of the base class runs on it with the GIL released), with
//! the continuity report of its joints and an exact JSON form
//! `{"pieces": [{"type": "bezier", …}, …]}` — the `pieces` of `camber fit --split`'s output.

use camber_geom::composite::{Continuity, ContinuityTolerances, JointReport};
use camber_geom::queries::RationalPiece;
use camber_geom::{
    BSplineCurve, BezierCurve, CompositeCurve, HermiteCurve, NurbsCurve, ParametricCurve,
};
use nalgebra::{Point, SVector};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::curve::{AnyCurve, Curve};
use crate::curve_kinds::wrap;
use crate::errors::{geometry, input};

/// One piece of a chain: a curve of any kind in D dimensions, tagged by `"type"` in JSON as in
/// camber's single-curve files.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "lowercase")]
pub enum Piece<const D: usize> {
    /// A Bézier curve.
    Bezier(BezierCurve<f64, D>),
    /// A polynomial B-spline.
    #[serde(rename = "bspline")]
    BSpline(BSplineCurve<f64, D>),
    /// A rational B-spline.
    Nurbs(NurbsCurve<f64, D>),
    /// A cubic Hermite curve.
    Hermite(HermiteCurve<f64, D>),
}

/// Runs `$body` with `$c` bound to the piece's curve, whatever its kind.
macro_rules! each_piece {
    ($piece:expr, $c:ident => $body:expr) => {
        match $piece {
            Piece::Bezier($c) => $body,
            Piece::BSpline($c) => $body,
            Piece::Nurbs($c) => $body,
            Piece::Hermite($c) => $body,
        }
    };
}

impl<const D: usize> Piece<D> {
    /// The same piece traversed backwards.
    fn reversed(&self) -> Self {
        match self {
            Piece::Bezier(c) => Piece::Bezier(c.reversed()),
            Piece::BSpline(c) => Piece::BSpline(c.reversed()),
            Piece::Nurbs(c) => Piece::Nurbs(c.reversed()),
            Piece::Hermite(c) => Piece::Hermite(c.reversed()),
        }
    }
}

impl<const D: usize> ParametricCurve<f64, D> for Piece<D> {
    fn domain(&self) -> (f64, f64) {
        each_piece!(self, c => c.domain())
    }

    fn derivatives_into(&self, u: f64, out: &mut [SVector<f64, D>]) -> camber_geom::Result<()> {
        each_piece!(self, c => c.derivatives_into(u, out))
    }

    fn breakpoints(&self) -> Vec<f64> {
        each_piece!(self, c => c.breakpoints())
    }

    fn bezier_enclosure(&self) -> camber_geom::Result<Option<Vec<RationalPiece<D>>>> {
        each_piece!(self, c => c.bezier_enclosure())
    }
}

/// A chain of pieces under one global parameter s ∈ [0, n].
#[derive(Debug, Clone)]
pub struct Chain<const D: usize>(CompositeCurve<f64, D, Piece<D>>);

impl<const D: usize> Chain<D> {
    /// The chain of `pieces` in order; fails for an empty list.
    pub fn try_new(pieces: Vec<Piece<D>>) -> camber_geom::Result<Self> {
        CompositeCurve::try_from_pieces(pieces).map(Self)
    }

    /// The pieces in order.
    pub fn pieces(&self) -> &[Piece<D>] {
        self.0.pieces()
    }

    /// The chain traversed backwards: the pieces in reverse order, each reversed
    /// (s ↦ n − s).
    pub fn reversed(&self) -> Self {
        let pieces = self.pieces().iter().rev().map(Piece::reversed).collect();
        // As many pieces as this chain, each with a valid domain: the construction holds.
        Self(CompositeCurve::try_from_pieces(pieces).unwrap_or_else(|_| self.0.clone()))
    }

    /// Every piece's control points in order (a Hermite piece's end points), a joint's point
    /// once per piece.
    pub fn control_points(&self) -> Vec<Point<f64, D>> {
        let mut out = Vec::new();
        for piece in self.pieces() {
            match piece {
                Piece::Bezier(c) => out.extend_from_slice(c.control_points()),
                Piece::BSpline(c) => out.extend_from_slice(c.control_points()),
                Piece::Nurbs(c) => out.extend_from_slice(c.control_points()),
                Piece::Hermite(c) => out.extend([c.p0(), c.p1()]),
            }
        }
        out
    }

    /// The continuity report of every joint, in order.
    pub fn joints(&self) -> camber_geom::Result<Vec<JointReport<f64>>> {
        self.0.joints()
    }
}

impl<const D: usize> ParametricCurve<f64, D> for Chain<D> {
    fn domain(&self) -> (f64, f64) {
        self.0.domain()
    }

    fn derivatives_into(&self, s: f64, out: &mut [SVector<f64, D>]) -> camber_geom::Result<()> {
        self.0.derivatives_into(s, out)
    }

    fn breakpoints(&self) -> Vec<f64> {
        self.0.breakpoints()
    }

    fn bezier_enclosure(&self) -> camber_geom::Result<Option<Vec<RationalPiece<D>>>> {
        self.0.bezier_enclosure()
    }
}

/// The JSON form of a chain: its pieces only.
#[derive(Serialize, Deserialize)]
struct ChainForm<const D: usize> {
    pieces: Vec<Piece<D>>,
}

impl<const D: usize> Serialize for Chain<D> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        ChainForm {
            pieces: self.pieces().to_vec(),
        }
        .serialize(serializer)
    }
}

impl<'de, const D: usize> Deserialize<'de> for Chain<D> {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let form = ChainForm::<D>::deserialize(deserializer)?;
        Chain::try_new(form.pieces).map_err(serde::de::Error::custom)
    }
}

/// One curve of any class as pieces in D dimensions (a composite gives all of its own), or
/// an error naming it by its position.
fn piece_of<const D: usize>(
    curve: &AnyCurve,
    index: usize,
    out: &mut Vec<Piece<D>>,
) -> PyResult<()> {
    let found: Option<Vec<Piece<D>>> = match curve {
        AnyCurve::Bezier2(c) => cast::<2, D>(Piece::Bezier(c.clone())),
        AnyCurve::Bezier3(c) => cast::<3, D>(Piece::Bezier(c.clone())),
        AnyCurve::BSpline2(c) => cast::<2, D>(Piece::BSpline(c.clone())),
        AnyCurve::BSpline3(c) => cast::<3, D>(Piece::BSpline(c.clone())),
        AnyCurve::Nurbs2(c) => cast::<2, D>(Piece::Nurbs(c.clone())),
        AnyCurve::Nurbs3(c) => cast::<3, D>(Piece::Nurbs(c.clone())),
        AnyCurve::Hermite2(c) => cast::<2, D>(Piece::Hermite(c.clone())),
        AnyCurve::Hermite3(c) => cast::<3, D>(Piece::Hermite(c.clone())),
        AnyCurve::Composite2(c) => cast_all::<2, D>(c.pieces()),
        AnyCurve::Composite3(c) => cast_all::<3, D>(c.pieces()),
    };
    match found {
        Some(pieces) => {
            out.extend(pieces);
            Ok(())
        }
        None => Err(input(format!(
            "pieces[{index}]: a {}-D curve in a {D}-D composite curve",
            curve.dim()
        ))),
    }
}

/// A piece of dimension E as one of dimension D, when E = D.
fn cast<const E: usize, const D: usize>(piece: Piece<E>) -> Option<Vec<Piece<D>>> {
    use std::any::Any;
    let boxed: Box<dyn Any> = Box::new(piece);
    boxed.downcast::<Piece<D>>().ok().map(|p| vec![*p])
}

/// The pieces of a chain of dimension E as pieces of dimension D, when E = D.
fn cast_all<const E: usize, const D: usize>(pieces: &[Piece<E>]) -> Option<Vec<Piece<D>>> {
    pieces
        .iter()
        .map(|p| cast::<E, D>(p.clone()).and_then(|mut v| v.pop()))
        .collect()
}

/// The chain of `curves` (each a `Curve`; a composite contributes its pieces).
fn chain_of(curves: &[PyRef<'_, Curve>]) -> PyResult<AnyCurve> {
    let Some(first) = curves.first() else {
        return Err(input(
            "pieces: a composite curve needs at least one piece, found none",
        ));
    };
    let inner = if first.inner.dim() == 3 {
        let mut pieces = Vec::with_capacity(curves.len());
        for (i, c) in curves.iter().enumerate() {
            piece_of::<3>(&c.inner, i, &mut pieces)?;
        }
        AnyCurve::Composite3(Chain::try_new(pieces).map_err(geometry)?)
    } else {
        let mut pieces = Vec::with_capacity(curves.len());
        for (i, c) in curves.iter().enumerate() {
            piece_of::<2>(&c.inner, i, &mut pieces)?;
        }
        AnyCurve::Composite2(Chain::try_new(pieces).map_err(geometry)?)
    };
    Ok(inner)
}

/// A piece as the curve class of its kind.
fn piece_object<const D: usize>(py: Python<'_>, piece: &Piece<D>) -> PyResult<Py<PyAny>> {
    use std::any::Any;
    let any: &dyn Any = piece;
    let inner = if let Some(p) = any.downcast_ref::<Piece<2>>() {
        match p.clone() {
            Piece::Bezier(c) => AnyCurve::Bezier2(c),
            Piece::BSpline(c) => AnyCurve::BSpline2(c),
            Piece::Nurbs(c) => AnyCurve::Nurbs2(c),
            Piece::Hermite(c) => AnyCurve::Hermite2(c),
        }
    } else if let Some(p) = any.downcast_ref::<Piece<3>>() {
        match p.clone() {
            Piece::Bezier(c) => AnyCurve::Bezier3(c),
            Piece::BSpline(c) => AnyCurve::BSpline3(c),
            Piece::Nurbs(c) => AnyCurve::Nurbs3(c),
            Piece::Hermite(c) => AnyCurve::Hermite3(c),
        }
    } else {
        return Err(input(format!("internal: a {D}-D piece")));
    };
    wrap(py, inner)
}

/// The name of a continuity class, as the file formats and the CLI write it.
fn continuity_name(c: Continuity) -> &'static str {
    match c {
        Continuity::None => "none",
        Continuity::C0 => "C0",
        Continuity::G1 => "G1",
        Continuity::C1 => "C1",
        Continuity::G2 => "G2",
        Continuity::C2 => "C2",
    }
}

/// A chain of curves evaluated as one: `CompositeCurve(pieces)` with a list of curves of any
/// kind (and dimension 2 or 3, all the same); a composite in the list contributes its pieces.
///
/// The global parameter s runs over [0, n] for n pieces: piece i covers [i, i + 1], mapped
/// affinely onto the piece's own domain [a_i, b_i], so the k-th derivative in s is the piece's
/// k-th derivative times (b_i − a_i)^k. At a joint s = i the right-hand piece is evaluated
/// (the last piece at s = n). Every method of `Curve` (evaluation, closest point,
/// intersections, arc length, offsets) works on the whole chain. The chain need not be
/// continuous: `joints()` reports how well neighbouring pieces meet.
#[pyclass(name = "CompositeCurve", extends = Curve, frozen, module = "camber._native")]
#[derive(Debug)]
#[allow(non_camel_case_types)] // the Rust name differs from the library's struct; Python sees `CompositeCurve`
pub struct CompositeCurve_;

#[pymethods]
impl CompositeCurve_ {
    #[new]
    fn new(pieces: Vec<PyRef<'_, Curve>>) -> PyResult<PyClassInitializer<Self>> {
        let inner = chain_of(&pieces)?;
        Ok(PyClassInitializer::from(Curve { inner }).add_subclass(CompositeCurve_))
    }

    /// Reads the JSON form `{"pieces": [curve, …]}` (other keys, such as those `camber fit
    /// --split` writes beside the pieces, are ignored).
    #[staticmethod]
    fn from_json(py: Python<'_>, text: &str) -> PyResult<Py<PyAny>> {
        let inner = match serde_json::from_str::<Chain<2>>(text) {
            Ok(c) => AnyCurve::Composite2(c),
            Err(e2) => serde_json::from_str::<Chain<3>>(text)
                .map(AnyCurve::Composite3)
                .map_err(|_| input(format!("invalid composite curve JSON: {e2}")))?,
        };
        wrap(py, inner)
    }

    /// The pieces in order, each as a curve of its own class on its own domain.
    #[getter]
    fn pieces(slf: PyRef<'_, Self>) -> PyResult<Vec<Py<PyAny>>> {
        let py = slf.py();
        match &slf.as_super().inner {
            AnyCurve::Composite2(c) => c.pieces().iter().map(|p| piece_object(py, p)).collect(),
            AnyCurve::Composite3(c) => c.pieces().iter().map(|p| piece_object(py, p)).collect(),
            _ => Err(input("internal: curve of another kind")),
        }
    }

    /// The number of pieces n (the global domain is [0, n]).
    fn __len__(slf: PyRef<'_, Self>) -> usize {
        match &slf.as_super().inner {
            AnyCurve::Composite2(c) => c.pieces().len(),
            AnyCurve::Composite3(c) => c.pieces().len(),
            _ => 0,
        }
    }

    /// How well each pair of neighbouring pieces meets, one dict per joint in order:
    /// `index` (the joint between pieces index and index + 1), `position_gap` (length),
    /// `tangent_angle` (radians, π when a derivative vanishes), `first_derivative_mismatch`,
    /// `curvature_difference`, `curvature_vector_difference` (1/length; infinite when a
    /// derivative vanishes), `second_derivative_mismatch` — all in the pieces' own parameters —
    /// and `continuity`, the smoothest class that holds within the tolerances: "none", "C0",
    /// "G1", "C1", "G2" or "C2".
    #[pyo3(signature = (position = 1e-9, angle = 1e-9, derivative = 1e-9, curvature = 1e-9))]
    fn joints<'py>(
        slf: PyRef<'py, Self>,
        position: f64,
        angle: f64,
        derivative: f64,
        curvature: f64,
    ) -> PyResult<Vec<Bound<'py, PyDict>>> {
        let py = slf.py();
        for (name, value) in [
            ("position", position),
            ("angle", angle),
            ("derivative", derivative),
            ("curvature", curvature),
        ] {
            if !(value >= 0.0 && value.is_finite()) {
                return Err(input(format!(
                    "{name}: a tolerance must be finite and not negative, found {value}"
                )));
            }
        }
        let tol = ContinuityTolerances {
            position,
            angle,
            derivative,
            curvature,
        };
        let reports = match &slf.as_super().inner {
            AnyCurve::Composite2(c) => c.joints(),
            AnyCurve::Composite3(c) => c.joints(),
            _ => return Err(input("internal: curve of another kind")),
        }
        .map_err(geometry)?;
        reports
            .iter()
            .map(|r| {
                let d = PyDict::new(py);
                d.set_item("index", r.index)?;
                d.set_item("position_gap", r.position_gap)?;
                d.set_item("tangent_angle", r.tangent_angle)?;
                d.set_item("first_derivative_mismatch", r.first_derivative_mismatch)?;
                d.set_item("curvature_difference", r.curvature_difference)?;
                d.set_item("curvature_vector_difference", r.curvature_vector_difference)?;
                d.set_item("second_derivative_mismatch", r.second_derivative_mismatch)?;
                d.set_item("continuity", continuity_name(r.continuity(&tol)))?;
                Ok(d)
            })
            .collect()
    }

    /// The piece holding global parameter s and the piece's own parameter there:
    /// (index, u). At a joint the right-hand piece, at s = n the last one.
    fn locate(slf: PyRef<'_, Self>, s: f64) -> PyResult<(usize, f64)> {
        match &slf.as_super().inner {
            AnyCurve::Composite2(c) => c.0.piece_at(s),
            AnyCurve::Composite3(c) => c.0.piece_at(s),
            _ => return Err(input("internal: curve of another kind")),
        }
        .map_err(geometry)
    }
}
