//! `g1_join_free`: the end of one curve is the start of the next and the tangents there are
//! parallel and point the same way, the direction itself being free:
//! P_end(first) − P_start(second) = 0 (two affine rows, or a merged unknown) and
//! the angle from C₁′(b₁) to C₂′(a₂), atan2(cross(C₁′, C₂′), C₁′·C₂′) = 0 (one nonlinear row, in
//! radians; its gradient vanishes only with a tangent, unlike the sine's at a right angle, see
//! [`Angle`](super::Angle)), with C₁′·C₂′ > 0 checked after every solve. [`G2Join`](super::G2Join) adds equal curvature. File form:
//! `{"kind": "g1_join_free", "first": 0, "second": 1}`.

use std::sync::Arc;

use serde::{Deserialize, Serialize};

use super::glyph::{self, Glyph};
pub use super::shared::joins::TangentsParallel;
use super::shared::joins::{joint_bases, joint_coincidence, verify_same_sense};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;

/// The end of `first` coincides with the start of `second` and their tangents there are
/// parallel and point the same way, the direction being free (three rows).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct G1JoinFree {
    /// The curve that ends at the joint.
    pub first: EntityId,
    /// The curve that starts at the joint.
    pub second: EntityId,
}

impl ConstraintKind for G1JoinFree {
    const TAG: &'static str = "g1_join_free";
    const LABEL: &'static str = "G1 join (free direction)";

    fn entities(&self, out: &mut Entities) {
        out.add(self.first);
        out.add(self.second);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        joint_coincidence(cx, Self::LABEL, self.first, self.second)?;
        let j = joint_bases(cx, self.first, self.second, 1)?;
        cx.residual(
            TangentsParallel::new(j.first, j.second),
            j.slots,
            Some(Arc::new(*self)),
        );
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let b = glyph::domain_end(at, self.first, true)?;
        Ok(vec![glyph::tangent_arrow(at, self.first, b)?])
    }
}

impl SolvedCheck for G1JoinFree {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        verify_same_sense(state, self.first, self.second)
    }

    fn joint(&self) -> Option<(EntityId, EntityId)> {
        Some((self.first, self.second))
    }
}
