//! Rows and marks along a coordinate axis, shared by `horizontal`, `vertical`, their distance
//! kinds and `equal_length`: the axis row of a point pair, the [`AxisOffset`] residual, the
//! point slots of a pair and its glyph.

use crate::constraints::compiler::finite;
use crate::constraints::glyph::{self, Glyph};
use crate::constraints::piece::Slot;
use crate::constraints::piece::{ETerms, Piece};
use crate::constraints::Compiler;
use crate::ground::errors::{Error, Result};
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::PointPair;
use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};

/// Writes cross(b − a, d) = 0 for the pair (one affine row): `d` = (1, 0) levels them, (0, 1)
/// stacks them.
pub(crate) fn axis_row(
    cx: &mut Compiler<'_>,
    name: &'static str,
    of: PointPair,
    direction: [f64; 2],
) -> Result<()> {
    if let PointPair::Line(l) = of {
        cx.line(l)?;
    }
    let [a, b] = of.points();
    let mut terms = ETerms::new();
    cx.point_terms(b, 1.0, &mut terms)?;
    cx.point_terms(a, -1.0, &mut terms)?;
    if a == b {
        return Err(Error::SameEntity { entity: a.entity() });
    }
    cx.push(Piece::Cross {
        name,
        terms,
        direction,
        orient: None,
    });
    Ok(())
}

/// A text mark at the middle of a pair.
pub(crate) fn pair_mark(at: &dyn EntityLookup, of: PointPair, text: &'static str) -> Result<Glyph> {
    let [a, b] = of.points();
    let (p, q) = (glyph::point(at, a)?, glyph::point(at, b)?);
    Ok(Glyph::Mark(nalgebra::center(&p, &q), text))
}

/// The single point blocks of a pair, refusing a pair of one point twice.
pub(crate) fn pair_slots(cx: &Compiler<'_>, pair: PointPair) -> Result<[Slot; 2]> {
    if let PointPair::Line(l) = pair {
        cx.line(l)?;
    }
    let [a, b] = pair.points();
    let ((ea, ja), (eb, jb)) = (cx.single_block(a)?, cx.single_block(b)?);
    if (ea, ja) == (eb, jb) {
        return Err(Error::SameEntity { entity: ea });
    }
    Ok([Slot::Point(ea, ja), Slot::Point(eb, jb)])
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
