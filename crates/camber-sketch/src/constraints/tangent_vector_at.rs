//! `tangent_vector_at`: the derivative C′(u) at a given parameter equals a vector (direction
//! and length, in length units per unit of u): two rows affine in the control points. File
//! form: `{"kind": "tangent_vector_at", "curve": 0, "u": 0.0, "vector": [3, 0]}`.

use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::xy_vector;

/// C′(u) = vector, direction and length (two rows).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TangentVectorAt {
    /// The curve.
    pub curve: EntityId,
    /// The parameter.
    pub u: f64,
    /// The tangent vector, in length units per unit of u.
    #[serde(with = "xy_vector")]
    pub vector: Vector2<f64>,
}

impl ConstraintKind for TangentVectorAt {
    const TAG: &'static str = "tangent_vector_at";
    const LABEL: &'static str = "tangent vector at";

    fn entities(&self, out: &mut Entities) {
        out.add(self.curve);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let terms = cx.curve_terms(self.curve, self.u, 1)?;
        crate::ground::entity::check_finite2("tangent vector", 0, [self.vector.x, self.vector.y])?;
        cx.combination(Self::LABEL, terms, [self.vector.x, self.vector.y]);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![Glyph::Arrow(
            glyph::curve_point(at, self.curve, self.u)?,
            self.vector,
        )])
    }
}
