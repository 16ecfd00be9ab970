//! `parallel`: two line entities are parallel, either sense: the angle φ between their
//! directions, folded into [−π/2, π/2], is 0 (one row, the angle row of [`Angle`](super::Angle)
//! at θ = 0 for either sense).
//! File form: `{"kind": "parallel", "first": 1, "second": 2}`.

use serde::{Deserialize, Serialize};

use super::shared::angles::line_angle;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;

/// Two line entities are parallel, either sense (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Parallel {
    /// The first line.
    pub first: EntityId,
    /// The second line.
    pub second: EntityId,
}

impl ConstraintKind for Parallel {
    const TAG: &'static str = "parallel";
    const LABEL: &'static str = "parallel";

    fn entities(&self, out: &mut Entities) {
        out.add(self.first);
        out.add(self.second);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        line_angle(cx, Self::LABEL, (self.first, self.second), 0.0, None)
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![
            glyph::line_arrow(at, self.first)?,
            glyph::line_arrow(at, self.second)?,
        ])
    }
}
