//! `g1_join`: the end of one curve is the start of the next, and both tangents there point
//! along a fixed joint direction d: P_end(first) − P_start(second) = 0 (two rows) and
//! cross(C′, d) = 0 on each side (one row each), all affine, with both senses checked. The
//! joint direction being data keeps the join on the linear path; [`G1JoinFree`] lets it move.
//! File form: `{"kind": "g1_join", "first": 0, "second": 1, "direction": [1, 0]}`.
//!
//! [`G1JoinFree`]: super::G1JoinFree

use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use super::compiler::check_direction;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::{ETerms, Piece};
use crate::ground::errors::Result;
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::xy_vector;

/// The end of `first` coincides with the start of `second`, and both tangents there are
/// parallel to the fixed joint direction d and point along it (four rows).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct G1Join {
    /// The curve that ends at the joint.
    pub first: EntityId,
    /// The curve that starts at the joint.
    pub second: EntityId,
    /// The joint direction d.
    #[serde(with = "xy_vector")]
    pub direction: Vector2<f64>,
}

impl ConstraintKind for G1Join {
    const TAG: &'static str = "g1_join";
    const LABEL: &'static str = "G1 join";

    fn entities(&self, out: &mut Entities) {
        out.add(self.first);
        out.add(self.second);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let d = check_direction("joint", &self.direction)?;
        let (_, b) = cx.domain(self.first)?;
        let (a, _) = cx.domain(self.second)?;
        let mut joint = ETerms::new();
        cx.point_terms(PointRef::End(self.first), 1.0, &mut joint)?;
        cx.point_terms(PointRef::Start(self.second), -1.0, &mut joint)?;
        cx.combination(Self::LABEL, joint, [0.0; 2]);
        for (curve, u) in [(self.first, b), (self.second, a)] {
            let terms = cx.curve_terms(curve, u, 1)?;
            cx.push(Piece::Cross {
                name: Self::LABEL,
                terms,
                direction: d,
                orient: Some(d),
            });
        }
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![Glyph::Arrow(
            glyph::point(at, PointRef::End(self.first))?,
            self.direction,
        )])
    }
}
