//! `horizontal`: a line, or two points, lie level: b_y − a_y = 0 (one affine row, written as
//! cross(b − a, (1, 0)) = 0). File form: `{"kind": "horizontal", "of": {"line": 3}}` or
//! `{"of": {"a": {"point": 1}, "b": {"point": 2}}}`.

use serde::{Deserialize, Serialize};

use super::glyph::Glyph;
use super::shared::axes::{pair_mark, axis_row};
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::PointPair;

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
