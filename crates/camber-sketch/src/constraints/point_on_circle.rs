//! `point_on_circle`: a point lies on a circle entity, (|P − c|² − r²)/(2r) = 0 (one row in
//! length units; centre and radius may be unknowns). File form:
//! `{"kind": "point_on_circle", "point": {"point": 3}, "circle": 1}`.

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::Slot;
use crate::ground::errors::Result;
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;
use crate::residuals::curve::{dot, sub};

/// The point lies on the circle: |P − c| = r (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointOnCircle {
    /// The point (a single block).
    pub point: PointRef,
    /// The circle entity.
    pub circle: EntityId,
}

/// (|P − c|² − r²)/(2r) = 0: the point lies on the circle (blocks: P, centre, radius).
#[derive(Debug, Clone, PartialEq)]
pub struct OnCircle;

impl Residual for OnCircle {
    fn name(&self) -> &str {
        PointOnCircle::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2, 1])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let v = sub(x[0], x[1]);
        let r = x[2][0];
        out[0] = (dot(v, v) - r * r) / (cst::<T>(2.0) * r);
    }
}

impl ConstraintKind for PointOnCircle {
    const TAG: &'static str = "point_on_circle";
    const LABEL: &'static str = "point on circle";

    fn entities(&self, out: &mut Entities) {
        out.add_point(self.point);
        out.add(self.circle);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        cx.circle(self.circle)?;
        let (e, j) = cx.single_block(self.point)?;
        distinct(e, self.circle)?;
        let slots = vec![
            Slot::Point(e, j),
            Slot::Point(self.circle, 0),
            Slot::Radius(self.circle),
        ];
        cx.residual(OnCircle, slots, None);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![Glyph::Ring(glyph::point(at, self.point)?)])
    }
}
