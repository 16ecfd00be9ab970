//! `point_at_parameter`: the curve point C(u) at a given parameter goes to a fixed location or
//! onto another point: C(u) − target = 0, two rows affine in the control points (u is data).
//! File form: `{"kind": "point_at_parameter", "curve": 0, "u": 0.5, "target": {"at": [1, 1]}}`.

use serde::{Deserialize, Serialize};

use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::Target;

/// C(u) = target (two rows).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointAtParameter {
    /// The curve.
    pub curve: EntityId,
    /// The parameter, inside the domain.
    pub u: f64,
    /// Where C(u) goes.
    pub target: Target,
}

impl ConstraintKind for PointAtParameter {
    const TAG: &'static str = "point_at_parameter";
    const LABEL: &'static str = "point at parameter";

    fn entities(&self, out: &mut Entities) {
        out.add(self.curve);
        if let Target::Point(p) = self.target {
            out.add_point(p);
        }
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let mut terms = cx.curve_terms(self.curve, self.u, 0)?;
        let target = match self.target {
            Target::At(p) => {
                crate::ground::entity::check_point("target", 0, &p)?;
                [p.x, p.y]
            }
            Target::Point(r) => {
                cx.point_terms(r, -1.0, &mut terms)?;
                [0.0; 2]
            }
        };
        cx.combination(Self::LABEL, terms, target);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let target = match self.target {
            Target::At(q) => q,
            Target::Point(r) => glyph::point(at, r)?,
        };
        Ok(vec![
            Glyph::Ring(glyph::curve_point(at, self.curve, self.u)?),
            Glyph::Ring(target),
        ])
    }
}
