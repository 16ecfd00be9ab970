//! `c1_join`: the end of one curve is the start of the next with the same first derivative,
//! C₁(b₁) = C₂(a₂) and C₁′(b₁) = C₂′(a₂) (four affine rows: parametric C1 continuity, the
//! joint of a composite curve). [`C2Join`](super::C2Join) adds the second derivative.
//! File form: `{"kind": "c1_join", "first": 0, "second": 1}`.

use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::component::piece::ETerms;
use crate::errors::Result;
use crate::ids::{EntityId, PointRef};
use crate::lookup::EntityLookup;

/// `first` ends where `second` starts, with equal first derivatives there (four rows).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct C1Join {
    /// The curve that ends at the joint.
    pub first: EntityId,
    /// The curve that starts at the joint.
    pub second: EntityId,
}

/// Writes C₁⁽ᵏ⁾(b₁) − C₂⁽ᵏ⁾(a₂) = 0 for k = 0 … `order` (two affine rows each).
pub(crate) fn parametric_join(
    cx: &mut Compiler<'_>,
    name: &'static str,
    (first, second): (EntityId, EntityId),
    order: usize,
) -> Result<()> {
    distinct(first, second)?;
    let (_, b) = cx.domain(first)?;
    let (a, _) = cx.domain(second)?;
    let mut joint = ETerms::new();
    cx.point_terms(PointRef::End(first), 1.0, &mut joint)?;
    cx.point_terms(PointRef::Start(second), -1.0, &mut joint)?;
    cx.combination(name, joint, [0.0; 2]);
    for k in 1..=order {
        let mut terms = cx.curve_derivative_terms(first, b, k)?;
        for (e, j, c) in cx.curve_derivative_terms(second, a, k)? {
            terms.push((e, j, -c));
        }
        cx.combination(name, terms, [0.0; 2]);
    }
    Ok(())
}

/// The glyph of a parametric join: its name beside the joint.
pub(crate) fn join_mark(at: &dyn EntityLookup, first: EntityId, text: &'static str) -> Result<Vec<Glyph>> {
    let b = glyph::domain_end(at, first, true)?;
    Ok(vec![
        glyph::tangent_arrow(at, first, b)?,
        Glyph::Mark(glyph::curve_point(at, first, b)?, text),
    ])
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
