//! `radius`: a circle's or an arc's radius equals a value R > 0. For a circle r − R = 0 (one
//! affine row on the radius unknown); for an arc |S − C| − R = 0 (one row on its centre and
//! start blocks; its end follows through the arc's own row). File form:
//! `{"kind": "radius", "circle": 1, "radius": 0.5}` (`circle` names a circle or an arc).

use camber_solve::{Residual, Scalar};
use nalgebra::Point2;
use serde::{Deserialize, Serialize};

use super::compiler::positive;
use super::glyph::{self, Glyph};
use super::shared::radii::{radius_of, Round};
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
pub use crate::residuals::affine::RadiusValue;

/// The circle's (or arc's) radius equals the value (> 0; one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Radius {
    /// The circle or arc entity.
    pub circle: EntityId,
    /// The radius.
    pub radius: f64,
}

/// |S − C| − R = 0 over an arc's blocks [C, S] (one row, length units).
///
/// ```
/// use camber_sketch::constraints::radius::ArcRadiusValue;
/// use camber_solve::Residual;
/// let mut g = [0.0_f64];
/// ArcRadiusValue(2.0).eval(&[&[1.0, 1.0][..], &[4.0, 5.0][..]], &mut g);
/// assert!((g[0] - 3.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArcRadiusValue(pub f64);

impl Residual for ArcRadiusValue {
    fn name(&self) -> &str {
        Radius::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = radius_of(true, x).0 - nalgebra::convert::<f64, T>(self.0);
    }
}

impl ConstraintKind for Radius {
    const TAG: &'static str = "radius";
    const LABEL: &'static str = "radius";

    fn value(&self) -> Option<f64> {
        Some(self.radius)
    }

    fn value_field(&self) -> Option<&'static str> {
        Some("radius")
    }

    fn set_value(&mut self, value: f64) -> bool {
        self.radius = value;
        true
    }

    fn entities(&self, out: &mut Entities) {
        out.add(self.circle);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let round = Round::of(cx, self.circle)?;
        let r = positive("radius", self.radius)?;
        let slots = round.radius_slots().to_vec();
        if round.is_arc() {
            cx.residual(ArcRadiusValue(r), slots, None);
        } else {
            cx.residual(RadiusValue::new(r), slots, None);
        }
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        // "R" at the top of the circle.
        let (c, r) = glyph::circle(at, self.circle)?;
        Ok(vec![Glyph::Mark(Point2::new(c.x, c.y + r), "R")])
    }
}
