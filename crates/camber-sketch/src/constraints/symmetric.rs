//! `symmetric`: two points are mirror images in the infinite line of a line entity (A, B):
//! their midpoint lies on the line and their difference is perpendicular to it,
//!
//! cross((a + b)/2 − A, d)/|d| = 0 and (b − a)·d/|d| = 0 with d = B − A (two rows in length
//! units). File form: `{"kind": "symmetric", "a": {"point": 1}, "b": {"point": 2}, "line": 3}`.

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::Slot;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;
use crate::residuals::curve::{cross, dot, sub};

/// `a` and `b` are symmetric about the line (two rows).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Symmetric {
    /// One point.
    pub a: PointRef,
    /// Its mirror image.
    pub b: PointRef,
    /// The mirror line.
    pub line: EntityId,
}

/// The two rows of the module documentation (blocks a, b, A, B).
#[derive(Debug, Clone, PartialEq)]
pub struct Mirror;

impl Residual for Mirror {
    fn name(&self) -> &str {
        Symmetric::LABEL
    }
    fn dim(&self) -> usize {
        2
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2; 4])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let d = sub(x[3], x[2]);
        let len = dot(d, d).sqrt();
        let half = cst::<T>(0.5);
        let m = [
            half * (x[0][0] + x[1][0]) - x[2][0],
            half * (x[0][1] + x[1][1]) - x[2][1],
        ];
        out[0] = cross(d, m) / len;
        out[1] = dot(sub(x[1], x[0]), d) / len;
    }
}

impl ConstraintKind for Symmetric {
    const TAG: &'static str = "symmetric";
    const LABEL: &'static str = "symmetric";

    fn entities(&self, out: &mut Entities) {
        out.add_point(self.a);
        out.add_point(self.b);
        out.add(self.line);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        cx.line(self.line)?;
        let (ea, ja) = cx.single_block(self.a)?;
        let (eb, jb) = cx.single_block(self.b)?;
        distinct(ea, self.line)?;
        distinct(eb, self.line)?;
        if (ea, ja) == (eb, jb) {
            return Err(Error::SameEntity { entity: ea });
        }
        let slots = vec![
            Slot::Point(ea, ja),
            Slot::Point(eb, jb),
            Slot::Point(self.line, 0),
            Slot::Point(self.line, 1),
        ];
        cx.residual(Mirror, slots, None);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![
            Glyph::Ring(glyph::point(at, self.a)?),
            Glyph::Ring(glyph::point(at, self.b)?),
            glyph::line_arrow(at, self.line)?,
        ])
    }
}
