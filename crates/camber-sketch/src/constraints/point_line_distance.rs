//! `point_line_distance`: a point lies at distance D > 0 from the infinite line of a line
//! entity, on a given side: cross(P − A, B − A)/|B − A| = ±D (one row in length units, + on the
//! left of A→B). File form: `{"kind": "point_line_distance", "point": {"point": 4},
//! "line": 2, "distance": 0.5, "side": "left"}`.

use serde::{Deserialize, Serialize};

use super::compiler::positive;
use super::glyph::{self, Glyph};
use super::shared::lines::line_offset;
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::LineSide;

/// The point is `distance` from the line's infinite line, on `side` of A→B (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointLineDistance {
    /// The point (a single block).
    pub point: PointRef,
    /// The line entity.
    pub line: EntityId,
    /// The distance D > 0.
    pub distance: f64,
    /// Which side of the line A→B the point keeps to.
    pub side: LineSide,
}

impl ConstraintKind for PointLineDistance {
    const TAG: &'static str = "point_line_distance";
    const LABEL: &'static str = "point-line distance";

    fn value(&self) -> Option<f64> {
        Some(self.distance)
    }

    fn value_field(&self) -> Option<&'static str> {
        Some("distance")
    }

    fn set_value(&mut self, value: f64) -> bool {
        self.distance = value;
        true
    }

    fn entities(&self, out: &mut Entities) {
        out.add_point(self.point);
        out.add(self.line);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let d = positive("distance", self.distance)?;
        let signed = match self.side {
            LineSide::Left => d,
            LineSide::Right => -d,
        };
        line_offset(cx, Self::LABEL, self.point, self.line, signed)
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![
            Glyph::Ring(glyph::point(at, self.point)?),
            glyph::line_mark(at, self.line, "d")?,
        ])
    }
}
