//! `vertical`: a line, or two points, lie plumb: b_x − a_x = 0 (one affine row, written as
//! cross(b − a, (0, 1)) = 0). File form: `{"kind": "vertical", "of": {"line": 3}}`.

use serde::{Deserialize, Serialize};

use super::glyph::Glyph;
use super::shared::axes::{axis_row, pair_mark};
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::PointPair;

/// The two points of `of` have the same x (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Vertical {
    /// The line or the two points.
    pub of: PointPair,
}

impl Vertical {
    /// A vertical line.
    pub fn line(line: EntityId) -> Self {
        Self {
            of: PointPair::Line(line),
        }
    }
}

impl ConstraintKind for Vertical {
    const TAG: &'static str = "vertical";
    const LABEL: &'static str = "vertical";

    fn entities(&self, out: &mut Entities) {
        for e in self.of.entities() {
            out.add(e);
        }
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        axis_row(cx, Self::LABEL, self.of, [0.0, 1.0])
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![pair_mark(at, self.of, "V")?])
    }
}
