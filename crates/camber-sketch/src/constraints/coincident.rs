//! `coincident`: two points are one, P_a − P_b = 0.
//!
//! Two affine rows; when both are single point blocks the component builder merges them into
//! one set of unknowns instead (crate::component::merge). File form:
//! `{"kind": "coincident", "a": {"end": 1}, "b": {"start": 2}}`.

use serde::{Deserialize, Serialize};

use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::ETerms;
use crate::ground::errors::Result;
use crate::ground::ids::PointRef;
use crate::ground::lookup::EntityLookup;

/// Two points coincide: a − b = 0 (two rows).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Coincident {
    /// The first point.
    pub a: PointRef,
    /// The second point.
    pub b: PointRef,
}

impl ConstraintKind for Coincident {
    const TAG: &'static str = "coincident";
    const LABEL: &'static str = "coincident";

    fn entities(&self, out: &mut Entities) {
        out.add_point(self.a);
        out.add_point(self.b);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let mut terms = ETerms::new();
        cx.point_terms(self.a, 1.0, &mut terms)?;
        cx.point_terms(self.b, -1.0, &mut terms)?;
        cx.combination(Self::LABEL, terms, [0.0; 2]);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![
            Glyph::Ring(glyph::point(at, self.a)?),
            Glyph::Ring(glyph::point(at, self.b)?),
        ])
    }
}
