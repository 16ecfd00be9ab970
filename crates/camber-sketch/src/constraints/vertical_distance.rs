//! `vertical_distance`: the second point of a pair lies D above the first, b_y − a_y − D = 0
//! (one affine row; D may be negative). File form:
//! `{"kind": "vertical_distance", "of": {"a": {"point": 1}, "b": {"point": 2}}, "distance": 0.5}`.

use serde::{Deserialize, Serialize};

use super::glyph::Glyph;
use super::shared::axes::pair_mark;
use super::shared::axes::axis_offset;
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::PointPair;

/// b_y − a_y = `distance` for the pair (a, b) (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VerticalDistance {
    /// The line or the two points (a, b).
    pub of: PointPair,
    /// b_y − a_y, in length units (any sign).
    pub distance: f64,
}

impl ConstraintKind for VerticalDistance {
    const TAG: &'static str = "vertical_distance";
    const LABEL: &'static str = "vertical distance";

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
        axis_offset(cx, Self::LABEL, self.of, 1, self.distance)
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![pair_mark(at, self.of, "dy")?])
    }
}
