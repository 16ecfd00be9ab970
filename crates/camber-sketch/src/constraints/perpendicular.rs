//! `perpendicular`: two line entities are perpendicular: the angle φ between their directions
//! is π/2 up to a half turn (one row, the angle row of [`Angle`](super::Angle) at θ = π/2 for
//! either sense). File form: `{"kind": "perpendicular", "first": 1, "second": 2}`.

use serde::{Deserialize, Serialize};

use super::shared::angles::line_angle;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;

/// Two line entities are perpendicular (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Perpendicular {
    /// The first line.
    pub first: EntityId,
    /// The second line.
    pub second: EntityId,
}

impl ConstraintKind for Perpendicular {
    const TAG: &'static str = "perpendicular";
    const LABEL: &'static str = "perpendicular";

    fn entities(&self, out: &mut Entities) {
        out.add(self.first);
        out.add(self.second);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        line_angle(
            cx,
            Self::LABEL,
            (self.first, self.second),
            std::f64::consts::FRAC_PI_2,
            None,
        )
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![
            glyph::line_arrow(at, self.first)?,
            glyph::line_arrow(at, self.second)?,
        ])
    }
}
