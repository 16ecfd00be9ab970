//! `c2_join`: [`C1Join`](super::C1Join) plus equal second derivatives,
//! C₁″(b₁) = C₂″(a₂) (six affine rows in all: parametric C2 continuity). For two cubic Béziers
//! on [0, 1] the rows are P3ᵢ = P0ᵢ₊₁, P3ᵢ − P2ᵢ = P1ᵢ₊₁ − P0ᵢ₊₁ and
//! P1ᵢ − 2P2ᵢ + P3ᵢ = P0ᵢ₊₁ − 2P1ᵢ₊₁ + P2ᵢ₊₁ (times 3 and 6). File form:
//! `{"kind": "c2_join", "first": 0, "second": 1}`.

use serde::{Deserialize, Serialize};

use super::shared::joins::{join_mark, parametric_join};
use super::glyph::Glyph;
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;

/// `first` ends where `second` starts, with equal first and second derivatives (six rows).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct C2Join {
    /// The curve that ends at the joint.
    pub first: EntityId,
    /// The curve that starts at the joint.
    pub second: EntityId,
}

impl ConstraintKind for C2Join {
    const TAG: &'static str = "c2_join";
    const LABEL: &'static str = "C2 join";

    fn entities(&self, out: &mut Entities) {
        out.add(self.first);
        out.add(self.second);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        parametric_join(cx, Self::LABEL, (self.first, self.second), 2)
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        join_mark(at, self.first, "C2")
    }
}
