//! `radius`: a circle's radius equals a value R > 0, r − R = 0 (one affine row on the radius
//! unknown). File form: `{"kind": "radius", "circle": 1, "radius": 0.5}`.

use nalgebra::Point2;
use serde::{Deserialize, Serialize};

use super::compiler::positive;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::Slot;
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
pub use crate::residuals::affine::RadiusValue;

/// The circle's radius equals the value (> 0; one affine row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Radius {
    /// The circle entity.
    pub circle: EntityId,
    /// The radius.
    pub radius: f64,
}

impl ConstraintKind for Radius {
    const TAG: &'static str = "radius";
    const LABEL: &'static str = "radius";

    fn entities(&self, out: &mut Entities) {
        out.add(self.circle);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        cx.circle(self.circle)?;
        let r = positive("radius", self.radius)?;
        cx.residual(RadiusValue::new(r), vec![Slot::Radius(self.circle)], None);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        // "R" at the top of the circle.
        let (c, r) = glyph::circle(at, self.circle)?;
        Ok(vec![Glyph::Mark(Point2::new(c.x, c.y + r), "R")])
    }
}
