//! `horizontal_distance`: the second point of a pair lies D to the right of the first,
//! b_x − a_x − D = 0 (one affine row; D may be negative, to the left). File form:
//! `{"kind": "horizontal_distance", "of": {"line": 2}, "distance": 1.5}`.
//! [`VerticalDistance`](super::VerticalDistance) is the same along y.

use serde::{Deserialize, Serialize};

use super::glyph::Glyph;
use super::shared::axes::pair_mark;
use super::shared::axes::{axis_offset};
pub use super::shared::axes::AxisOffset;
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::PointPair;

/// b_x − a_x = `distance` for the pair (a, b) (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HorizontalDistance {
    /// The line or the two points (a, b).
    pub of: PointPair,
    /// b_x − a_x, in length units (any sign).
    pub distance: f64,
}

impl ConstraintKind for HorizontalDistance {
    const TAG: &'static str = "horizontal_distance";
    const LABEL: &'static str = "horizontal distance";

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
        for e in self.of.entities() {
            out.add(e);
        }
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        axis_offset(cx, Self::LABEL, self.of, 0, self.distance)
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![pair_mark(at, self.of, "dx")?])
    }
}
