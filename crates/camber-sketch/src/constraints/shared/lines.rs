//! The signed offset of a point from a line, shared by `point_on_line` and
//! `point_line_distance` ([`LineOffset`]).

use crate::constraints::compiler::distinct;
use crate::constraints::piece::Slot;
use crate::constraints::Compiler;
use crate::ground::errors::Result;
use crate::ground::ids::{EntityId, PointRef};
use crate::residuals::curve::{cross, dot, sub};
use camber_solve::{Residual, Scalar};

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
    let slots = vec![
        Slot::Point(e, j),
        Slot::Point(line, 0),
        Slot::Point(line, 1),
    ];
    cx.residual(LineOffset::new(name, offset), slots, None);
    Ok(())
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
