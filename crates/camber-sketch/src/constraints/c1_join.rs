//! `c1_join`: the end of one curve is the start of the next with the same first derivative,
//! C₁(b₁) = C₂(a₂) and C₁′(b₁) = C₂′(a₂) (four affine rows: parametric C1 continuity, the
//! joint of a composite curve). [`C2Join`](super::C2Join) adds the second derivative.
//! File form: `{"kind": "c1_join", "first": 0, "second": 1}`.

use serde::{Deserialize, Serialize};

use super::glyph::Glyph;
use super::shared::joins::{join_mark, parametric_join};
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;

/// `first` ends where `second` starts, with equal first derivatives there (four rows).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct C1Join {
    /// The curve that ends at the joint.
    pub first: EntityId,
    /// The curve that starts at the joint.
    pub second: EntityId,
}

impl ConstraintKind for C1Join {
    const TAG: &'static str = "c1_join";
    const LABEL: &'static str = "C1 join";

    fn entities(&self, out: &mut Entities) {
        out.add(self.first);
        out.add(self.second);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        parametric_join(cx, Self::LABEL, (self.first, self.second), 1)
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        join_mark(at, self.first, "C1")
    }
}
