//! `directional_tangent_at`: the tangent C′(u) at a given parameter is parallel to a fixed
//! direction T, cross(C′(u), T) = 0 (one row affine in the control points), pointing along or
//! against it (checked after every solve). File form:
//! `{"kind": "directional_tangent_at", "curve": 0, "u": 0.5, "direction": [1, 0], "sense": "agree"}`.

use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use super::compiler::check_direction;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::Piece;
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::{xy_vector, Sense};

/// cross(C′(u), T) = 0 with sense·(C′(u)·T) > 0 (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DirectionalTangentAt {
    /// The curve.
    pub curve: EntityId,
    /// The parameter.
    pub u: f64,
    /// The direction T.
    #[serde(with = "xy_vector")]
    pub direction: Vector2<f64>,
    /// Along or against T.
    #[serde(default)]
    pub sense: Sense,
}

impl ConstraintKind for DirectionalTangentAt {
    const TAG: &'static str = "directional_tangent_at";
    const LABEL: &'static str = "directional tangent at";

    fn entities(&self, out: &mut Entities) {
        out.add(self.curve);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let d = check_direction("tangent", &self.direction)?;
        let s = self.sense.sign();
        let terms = cx.curve_terms(self.curve, self.u, 1)?;
        cx.push(Piece::Cross {
            name: Self::LABEL,
            terms,
            direction: d,
            orient: Some([s * d[0], s * d[1]]),
        });
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![Glyph::Arrow(
            glyph::curve_point(at, self.curve, self.u)?,
            self.direction * self.sense.sign(),
        )])
    }
}
