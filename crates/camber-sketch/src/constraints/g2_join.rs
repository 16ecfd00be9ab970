//! `g2_join`: a [`G1JoinFree`](super::G1JoinFree) join plus equal signed curvature on both
//! sides of the joint, κ₁(b₁) − κ₂(a₂) = 0 with κ = cross(C′, C″)/|C′|³ (four rows in all).
//! File form: `{"kind": "g2_join", "first": 0, "second": 1}`.

use std::sync::Arc;

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::shared::joins::{joint_bases, joint_coincidence, verify_same_sense, TangentsParallel};
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::ground::curve_eval::CurveBasis;
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::residuals::curve::curvature;

/// [`G1JoinFree`](super::G1JoinFree) plus equal signed curvature on both sides of the joint
/// (G2 continuity; four rows).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct G2Join {
    /// The curve that ends at the joint.
    pub first: EntityId,
    /// The curve that starts at the joint.
    pub second: EntityId,
}

/// κ₁(u₁) − κ₂(u₂) = 0 with κ = cross(C′, C″)/|C′|³, the signed curvature: two curves have the
/// same curvature at fixed parameters (blocks: the first curve's control points, then the
/// second's). With a G1 joint it makes the joint G2.
#[derive(Debug, Clone, PartialEq)]
pub struct CurvatureMatch {
    first: (CurveBasis, f64),
    second: (CurveBasis, f64),
}

impl CurvatureMatch {
    /// Equal curvature of `first` at u₁ and `second` at u₂.
    pub fn new(first: (CurveBasis, f64), second: (CurveBasis, f64)) -> Self {
        Self { first, second }
    }
}

impl Residual for CurvatureMatch {
    fn name(&self) -> &str {
        G2Join::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2; self.first.0.count() + self.second.0.count()])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let n1 = self.first.0.count();
        let k1 = curvature(self.first.0.eval2(x, cst(self.first.1)));
        let k2 = curvature(self.second.0.eval2(&x[n1..], cst(self.second.1)));
        out[0] = k1 - k2;
    }
}

impl ConstraintKind for G2Join {
    const TAG: &'static str = "g2_join";
    const LABEL: &'static str = "G2 join";

    fn entities(&self, out: &mut Entities) {
        out.add(self.first);
        out.add(self.second);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        joint_coincidence(cx, Self::LABEL, self.first, self.second)?;
        let k = joint_bases(cx, self.first, self.second, 2)?;
        cx.residual(CurvatureMatch::new(k.first, k.second), k.slots, None);
        let t = joint_bases(cx, self.first, self.second, 1)?;
        cx.residual(
            TangentsParallel::new(t.first, t.second),
            t.slots,
            Some(Arc::new(*self)),
        );
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let b = glyph::domain_end(at, self.first, true)?;
        Ok(vec![glyph::tangent_arrow(at, self.first, b)?])
    }
}

impl SolvedCheck for G2Join {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        verify_same_sense(state, self.first, self.second)
    }

    fn joint(&self) -> Option<(EntityId, EntityId)> {
        Some((self.first, self.second))
    }
}
