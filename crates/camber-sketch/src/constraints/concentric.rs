//! `concentric`: two circles or arcs (any pair of them) share their centre, c₁ − c₂ = 0 (two affine rows, merged into one
//! set of unknowns when the centres are free). File form:
//! `{"kind": "concentric", "first": 1, "second": 2}`.

use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::shared::radii::Round;
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::ETerms;
use crate::ground::errors::Result;
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;

/// The two circles or arcs have the same centre (two rows; the centre is block 0 of both).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Concentric {
    /// The first circle or arc.
    pub first: EntityId,
    /// The second circle or arc.
    pub second: EntityId,
}

impl ConstraintKind for Concentric {
    const TAG: &'static str = "concentric";
    const LABEL: &'static str = "concentric";

    fn entities(&self, out: &mut Entities) {
        out.add(self.first);
        out.add(self.second);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        distinct(self.first, self.second)?;
        Round::of(cx, self.first)?;
        Round::of(cx, self.second)?;
        let mut terms = ETerms::new();
        cx.point_terms(PointRef::Control(self.first, 0), 1.0, &mut terms)?;
        cx.point_terms(PointRef::Control(self.second, 0), -1.0, &mut terms)?;
        cx.combination(Self::LABEL, terms, [0.0; 2]);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let (c, _) = glyph::circle(at, self.first)?;
        Ok(vec![Glyph::Ring(c), Glyph::Mark(c, "◎")])
    }
}
