//! `point_on_line`: a point lies on the infinite line through a line entity's ends A, B (not
//! only on the segment): cross(P − A, B − A)/|B − A| = 0, the signed distance from the line
//! (one row in length units). [`PointOnCurve`](super::PointOnCurve) with the line as the curve
//! keeps the point on the segment instead. File form:
//! `{"kind": "point_on_line", "point": {"point": 4}, "line": 2}`.

use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::component::piece::Slot;
use crate::errors::Result;
use crate::ids::{EntityId, PointRef};
use crate::lookup::EntityLookup;
use crate::residuals::curve::{cross, dot, sub};

/// The point lies on the infinite line of a line entity (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointOnLine {
    /// The point (a single block).
    pub point: PointRef,
    /// The line entity.
    pub line: EntityId,
}

/// cross(P − A, B − A)/|B − A| − offset = 0: the signed distance of P from the line through A
/// and B (positive on the left of A→B) equals `offset` (blocks P, A, B).
#[derive(Debug, Clone, PartialEq)]
pub struct LineOffset {
    name: &'static str,
    offset: f64,
}

impl LineOffset {
    /// The residual named `name` for the signed distance `offset`.
    pub fn new(name: &'static str, offset: f64) -> Self {
        Self { name, offset }
    }
}

impl Residual for LineOffset {
    fn name(&self) -> &str {
        self.name
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let d = sub(x[2], x[1]);
        let v = sub(x[0], x[1]);
        out[0] = cross(d, v) / dot(d, d).sqrt() - camber_solve::scalar::cst::<T>(self.offset);
    }
}

/// Writes the signed-distance row of a point from a line entity.
pub(crate) fn line_offset(
    cx: &mut Compiler<'_>,
    name: &'static str,
    point: PointRef,
    line: EntityId,
    offset: f64,
) -> Result<()> {
    cx.line(line)?;
    let (e, j) = cx.single_block(point)?;
    distinct(e, line)?;
    let slots = vec![Slot::Point(e, j), Slot::Point(line, 0), Slot::Point(line, 1)];
    cx.residual(LineOffset::new(name, offset), slots, None);
    Ok(())
}

impl ConstraintKind for PointOnLine {
    const TAG: &'static str = "point_on_line";
    const LABEL: &'static str = "point on line";

    fn entities(&self, out: &mut Entities) {
        out.add_point(self.point);
        out.add(self.line);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        line_offset(cx, Self::LABEL, self.point, self.line, 0.0)
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![Glyph::Ring(glyph::point(at, self.point)?)])
    }
}
