//! `start_tangent`: the tangent at the start of a curve, C′(a), is parallel to a fixed
//! direction T and points along it (or against it), in one of two forms:
//!
//! - the row cross(C′(a), T) = 0, the control points staying unknowns;
//! - the paper's elimination P₁ = P₀ + t·s·T with t > 0 a new unknown (P₁ stops being an
//!   unknown, and the minimum norm is taken over P₀, t and the rest), for a curve clamped at
//!   its start; when P₁ is fixed or already bound by another elimination, the row is used.
//!
//! [`end_tangent`](super::end_tangent) is the same at the end (Pₙ₋₁ = Pₙ − t·s·T). File form:
//! `{"kind": "start_tangent", "curve": 0, "direction": [1, 0], "sense": "agree", "form": "row"}`.

use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use super::glyph::{self, Glyph};
use super::shared::joins::{end_tangency};
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::{xy_vector, Sense, TangentForm};

/// The start tangent C′(a) is parallel to T with the given sense.
///
/// ```
/// use camber_sketch::constraints::StartTangent;
/// use camber_sketch::{PointRef, Sense, Sketch, TangentForm};
/// use camber_geom::BezierCurve2;
/// use nalgebra::{Point2, Vector2};
/// let mut s = Sketch::new();
/// let c = s.add_bezier(BezierCurve2::try_new(vec![
///     Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(2.0, 1.0), Point2::new(3.0, 0.0),
/// ])?)?;
/// s.add_constraint(StartTangent {
///     curve: c,
///     direction: Vector2::new(1.0, 0.0),
///     sense: Sense::Agree,
///     form: TangentForm::Row,
/// })?;
/// s.solve()?;
/// let (p0, p1) = (s.point(PointRef::Control(c, 0))?, s.point(PointRef::Control(c, 1))?);
/// assert!((p1.y - p0.y).abs() < 1e-12 && p1.x > p0.x);
/// # Ok::<(), camber_sketch::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StartTangent {
    /// The curve.
    pub curve: EntityId,
    /// The direction T.
    #[serde(with = "xy_vector")]
    pub direction: Vector2<f64>,
    /// Along or against T.
    #[serde(default)]
    pub sense: Sense,
    /// Row or elimination form.
    #[serde(default)]
    pub form: TangentForm,
}

impl ConstraintKind for StartTangent {
    const TAG: &'static str = "start_tangent";
    const LABEL: &'static str = "start tangent";

    fn entities(&self, out: &mut Entities) {
        out.add(self.curve);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        end_tangency(
            cx,
            Self::LABEL,
            (self.curve, &self.direction, self.sense, self.form),
            false,
        )
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![Glyph::Arrow(
            glyph::point(at, PointRef::Start(self.curve))?,
            self.direction * self.sense.sign(),
        )])
    }
}
