//! `distance`: two points are D > 0 apart, (|a − b|² − D²)/(2D) = 0 (one row in length units;
//! smooth at the solution, unlike |a − b| − D at a = b). File form:
//! `{"kind": "distance", "a": {"point": 1}, "b": {"point": 2}, "distance": 3}`.

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::positive;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::component::piece::Slot;
use crate::errors::{Error, Result};
use crate::ids::PointRef;
use crate::lookup::EntityLookup;
use crate::residuals::curve::{dot, sub};

/// Two points are `distance` (> 0) apart (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Distance {
    /// The first point (a single block).
    pub a: PointRef,
    /// The second point (a single block).
    pub b: PointRef,
    /// The distance.
    pub distance: f64,
}

/// (|a − b|² − D²)/(2D) = 0: two points D apart (blocks: a, b; D > 0).
#[derive(Debug, Clone, PartialEq)]
pub struct PointDistance {
    distance: f64,
}

impl PointDistance {
    /// The distance residual for D = `distance` (> 0, checked by the constraint).
    pub fn new(distance: f64) -> Self {
        Self { distance }
    }
}

impl Residual for PointDistance {
    fn name(&self) -> &str {
        Distance::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let v = sub(x[0], x[1]);
        let d = cst::<T>(self.distance);
        out[0] = (dot(v, v) - d * d) / (cst::<T>(2.0) * d);
    }
}

impl ConstraintKind for Distance {
    const TAG: &'static str = "distance";
    const LABEL: &'static str = "distance";

    fn entities(&self, out: &mut Entities) {
        out.add_point(self.a);
        out.add_point(self.b);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let d = positive("distance", self.distance)?;
        let (ea, ja) = cx.single_block(self.a)?;
        let (eb, jb) = cx.single_block(self.b)?;
        if (ea, ja) == (eb, jb) {
            return Err(Error::SameEntity { entity: ea });
        }
        let slots = vec![Slot::Point(ea, ja), Slot::Point(eb, jb)];
        cx.residual(PointDistance::new(d), slots, None);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![
            Glyph::Ring(glyph::point(at, self.a)?),
            Glyph::Ring(glyph::point(at, self.b)?),
        ])
    }
}
