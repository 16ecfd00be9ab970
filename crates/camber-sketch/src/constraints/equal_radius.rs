//! `equal_radius`: two circles have the same radius, r₁ − r₂ = 0 (one affine row on the radius
//! unknowns). File form: `{"kind": "equal_radius", "first": 1, "second": 2}`.

use camber_solve::{Residual, Scalar};
use nalgebra::Point2;
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::Slot;
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;

/// The two circles' radii are equal (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EqualRadius {
    /// The first circle.
    pub first: EntityId,
    /// The second circle.
    pub second: EntityId,
}

/// r₁ − r₂ = 0 (blocks r₁, r₂; affine).
#[derive(Debug, Clone, PartialEq)]
pub struct RadiiEqual;

impl Residual for RadiiEqual {
    fn name(&self) -> &str {
        EqualRadius::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![1, 1])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = x[0][0] - x[1][0];
    }
    fn is_affine(&self) -> bool {
        true
    }
}

impl ConstraintKind for EqualRadius {
    const TAG: &'static str = "equal_radius";
    const LABEL: &'static str = "equal radius";

    fn entities(&self, out: &mut Entities) {
        out.add(self.first);
        out.add(self.second);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        distinct(self.first, self.second)?;
        cx.circle(self.first)?;
        cx.circle(self.second)?;
        let slots = vec![Slot::Radius(self.first), Slot::Radius(self.second)];
        cx.residual(RadiiEqual, slots, None);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        [self.first, self.second]
            .into_iter()
            .map(|c| {
                let (centre, r) = glyph::circle(at, c)?;
                Ok(Glyph::Mark(Point2::new(centre.x, centre.y + r), "="))
            })
            .collect()
    }
}
