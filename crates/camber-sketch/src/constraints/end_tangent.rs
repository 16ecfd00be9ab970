//! `end_tangent`: the tangent at the end of a curve, C′(b), is parallel to a fixed direction T
//! with the given sense, in the row or the elimination form Pₙ₋₁ = Pₙ − t·s·T (see
//! [`start_tangent`](super::start_tangent)). File form:
//! `{"kind": "end_tangent", "curve": 0, "direction": [1, 0], "sense": "agree", "form": "elimination"}`.

use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use super::glyph::{self, Glyph};
use super::shared::joins::end_tangency;
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::{xy_vector, Sense, TangentForm};

/// The end tangent C′(b) is parallel to T with the given sense.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EndTangent {
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

impl ConstraintKind for EndTangent {
    const TAG: &'static str = "end_tangent";
    const LABEL: &'static str = "end tangent";

    fn entities(&self, out: &mut Entities) {
        out.add(self.curve);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        end_tangency(
            cx,
            Self::LABEL,
            (self.curve, &self.direction, self.sense, self.form),
            true,
        )
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![Glyph::Arrow(
            glyph::point(at, PointRef::End(self.curve))?,
            self.direction * self.sense.sign(),
        )])
    }
}
