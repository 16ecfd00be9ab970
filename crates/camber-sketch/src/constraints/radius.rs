//! `radius`: a circle's radius equals a value R > 0, r − R = 0 (one affine row on the radius
//! unknown). File form: `{"kind": "radius", "circle": 1, "radius": 0.5}`.

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use nalgebra::Point2;
use serde::{Deserialize, Serialize};

use super::compiler::positive;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::component::piece::Slot;
use crate::errors::Result;
use crate::ids::EntityId;
use crate::lookup::EntityLookup;

/// The circle's radius equals the value (> 0; one affine row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Radius {
    /// The circle entity.
    pub circle: EntityId,
    /// The radius.
    pub radius: f64,
}

/// r − R = 0: the radius block holds R (affine).
#[derive(Debug, Clone, PartialEq)]
pub struct RadiusValue {
    radius: f64,
}

impl RadiusValue {
    /// The residual r − `radius`.
    pub fn new(radius: f64) -> Self {
        Self { radius }
    }
}

impl Residual for RadiusValue {
    fn name(&self) -> &str {
        Radius::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![1])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = x[0][0] - cst::<T>(self.radius);
    }
    fn is_affine(&self) -> bool {
        true
    }
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
