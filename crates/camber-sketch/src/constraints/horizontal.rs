//! `horizontal`: a line, or two points, lie level: b_y − a_y = 0 (one affine row, written as
//! cross(b − a, (1, 0)) = 0). File form: `{"kind": "horizontal", "of": {"line": 3}}` or
//! `{"of": {"a": {"point": 1}, "b": {"point": 2}}}`.

use serde::{Deserialize, Serialize};

use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::component::piece::{ETerms, Piece};
use crate::errors::{Error, Result};
use crate::ids::EntityId;
use crate::lookup::EntityLookup;
use crate::vocabulary::PointPair;

/// The two points of `of` have the same y (one row).
///
/// ```
/// use camber_sketch::constraints::Horizontal;
/// use camber_sketch::{PointRef, Sketch};
/// use nalgebra::Point2;
/// let mut s = Sketch::new();
/// let l = s.add_line(Point2::new(0.0, 0.0), Point2::new(2.0, 0.4))?;
/// s.add_constraint(Horizontal::line(l))?;
/// s.solve()?;
/// // Both ends moved by the least amount: 0.2 each.
/// assert!((s.point(PointRef::Start(l))?.y - 0.2).abs() < 1e-12);
/// assert!((s.point(PointRef::End(l))?.y - 0.2).abs() < 1e-12);
/// # Ok::<(), camber_sketch::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Horizontal {
    /// The line or the two points.
    pub of: PointPair,
}

impl Horizontal {
    /// A horizontal line.
    pub fn line(line: EntityId) -> Self {
        Self {
            of: PointPair::Line(line),
        }
    }
}

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

impl ConstraintKind for Horizontal {
    const TAG: &'static str = "horizontal";
    const LABEL: &'static str = "horizontal";

    fn entities(&self, out: &mut Entities) {
        for e in self.of.entities() {
            out.add(e);
        }
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        axis_row(cx, Self::LABEL, self.of, [1.0, 0.0])
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![pair_mark(at, self.of, "H")?])
    }
}
