//! `midpoint`: a point is the midpoint of a line (or of two points), P − (A + B)/2 = 0 (two
//! affine rows). File form: `{"kind": "midpoint", "point": {"point": 4}, "of": {"line": 2}}`.

use serde::{Deserialize, Serialize};

use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::ETerms;
use crate::ground::errors::Result;
use crate::ground::ids::PointRef;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::PointPair;

/// `point` is the midpoint of `of` (two rows).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Midpoint {
    /// The middle point.
    pub point: PointRef,
    /// The line or the two points it halves.
    pub of: PointPair,
}

impl ConstraintKind for Midpoint {
    const TAG: &'static str = "midpoint";
    const LABEL: &'static str = "midpoint";

    fn entities(&self, out: &mut Entities) {
        out.add_point(self.point);
        for e in self.of.entities() {
            out.add(e);
        }
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        if let crate::ground::vocabulary::PointPair::Line(l) = self.of {
            cx.line(l)?;
        }
        let [a, b] = self.of.points();
        let mut terms = ETerms::new();
        cx.point_terms(self.point, 1.0, &mut terms)?;
        cx.point_terms(a, -0.5, &mut terms)?;
        cx.point_terms(b, -0.5, &mut terms)?;
        cx.combination(Self::LABEL, terms, [0.0; 2]);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let p = glyph::point(at, self.point)?;
        Ok(vec![Glyph::Ring(p), Glyph::Mark(p, "M")])
    }
}
