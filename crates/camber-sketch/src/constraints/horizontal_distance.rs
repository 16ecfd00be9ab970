//! `horizontal_distance`: the second point of a pair lies D to the right of the first,
//! b_x − a_x − D = 0 (one affine row; D may be negative, to the left). File form:
//! `{"kind": "horizontal_distance", "of": {"line": 2}, "distance": 1.5}`.
//! [`VerticalDistance`](super::VerticalDistance) is the same along y.

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::finite;
use super::equal_length::pair_slots;
use super::glyph::Glyph;
use super::horizontal::pair_mark;
use super::{Compiler, ConstraintKind, Entities};
use crate::errors::Result;
use crate::lookup::EntityLookup;
use crate::vocabulary::PointPair;

/// b_x − a_x = `distance` for the pair (a, b) (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HorizontalDistance {
    /// The line or the two points (a, b).
    pub of: PointPair,
    /// b_x − a_x, in length units (any sign).
    pub distance: f64,
}

/// b_k − a_k − D = 0 along one axis k (blocks a, b; affine).
#[derive(Debug, Clone, PartialEq)]
pub struct AxisOffset {
    name: &'static str,
    axis: usize,
    distance: f64,
}

impl AxisOffset {
    /// The offset along `axis` (0 for x, 1 for y), named `name` in reports.
    pub fn new(name: &'static str, axis: usize, distance: f64) -> Self {
        Self {
            name,
            axis: axis.min(1),
            distance,
        }
    }
}

impl Residual for AxisOffset {
    fn name(&self) -> &str {
        self.name
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = x[1][self.axis] - x[0][self.axis] - cst::<T>(self.distance);
    }
    fn is_affine(&self) -> bool {
        true
    }
}

/// Writes the axis offset of a pair.
pub(crate) fn axis_offset(
    cx: &mut Compiler<'_>,
    name: &'static str,
    of: PointPair,
    axis: usize,
    distance: f64,
) -> Result<()> {
    let d = finite("distance", distance)?;
    let slots = pair_slots(cx, of)?.to_vec();
    cx.residual(AxisOffset::new(name, axis, d), slots, None);
    Ok(())
}

impl ConstraintKind for HorizontalDistance {
    const TAG: &'static str = "horizontal_distance";
    const LABEL: &'static str = "horizontal distance";

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
