//! `point_on_line`: a point lies on the infinite line through a line entity's ends A, B (not
//! only on the segment): cross(P − A, B − A)/|B − A| = 0, the signed distance from the line
//! (one row in length units). [`PointOnCurve`](super::PointOnCurve) with the line as the curve
//! keeps the point on the segment instead. File form:
//! `{"kind": "point_on_line", "point": {"point": 4}, "line": 2}`.

use serde::{Deserialize, Serialize};

use super::glyph::{self, Glyph};
use super::shared::lines::{line_offset};
pub use super::shared::lines::LineOffset;
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;

/// The point lies on the infinite line of a line entity (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointOnLine {
    /// The point (a single block).
    pub point: PointRef,
    /// The line entity.
    pub line: EntityId,
}

impl ConstraintKind for PointOnLine {
    const TAG: &'static str = "point_on_line";
    const LABEL: &'static str = "point on line";

    fn entities(&self, out: &mut Entities) {
        out.add_point(self.point);
        out.add(self.line);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        line_offset(cx, Self::LABEL, self.point, self.line, 0.0)
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![Glyph::Ring(glyph::point(at, self.point)?)])
    }
}
