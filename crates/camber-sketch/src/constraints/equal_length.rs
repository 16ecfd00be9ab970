//! `equal_length`: two segments (lines, or point pairs) are equally long:
//! |b₁ − a₁| − |b₂ − a₂| = 0 (one row in length units, smooth wherever neither segment has
//! zero length). File form: `{"kind": "equal_length", "first": {"line": 1}, "second":
//! {"line": 2}}`.

use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::glyph::Glyph;
use super::shared::axes::pair_mark;
use super::shared::axes::{pair_slots};
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::lookup::EntityLookup;
use crate::residuals::curve::{dot, sub};
use crate::ground::vocabulary::PointPair;

/// The two segments have the same length (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EqualLength {
    /// The first segment.
    pub first: PointPair,
    /// The second segment.
    pub second: PointPair,
}

/// |b₁ − a₁| − |b₂ − a₂| = 0 (blocks a₁, b₁, a₂, b₂).
#[derive(Debug, Clone, PartialEq)]
pub struct LengthsEqual;

impl Residual for LengthsEqual {
    fn name(&self) -> &str {
        EqualLength::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2; 4])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (d1, d2) = (sub(x[1], x[0]), sub(x[3], x[2]));
        out[0] = dot(d1, d1).sqrt() - dot(d2, d2).sqrt();
    }
}

impl ConstraintKind for EqualLength {
    const TAG: &'static str = "equal_length";
    const LABEL: &'static str = "equal length";

    fn entities(&self, out: &mut Entities) {
        for e in self.first.entities().into_iter().chain(self.second.entities()) {
            out.add(e);
        }
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let mut slots = pair_slots(cx, self.first)?.to_vec();
        slots.extend(pair_slots(cx, self.second)?);
        cx.residual(LengthsEqual, slots, None);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![
            pair_mark(at, self.first, "=")?,
            pair_mark(at, self.second, "=")?,
        ])
    }
}
