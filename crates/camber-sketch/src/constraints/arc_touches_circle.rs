//! `arc_touches_circle`: a circular arc (centre C₁, radius r₁ = |S₁ − C₁|) touches a circle
//! or the circle of another arc (centre C₂, radius r₂) somewhere in its interior, externally
//! (|C₁ − C₂| = r₁ + r₂) or internally (|C₁ − C₂| = |r₁ − r₂|), as recorded. One row in length
//! units, free of square roots of the centre distance and of absolute values,
//!
//! g = (|C₁ − C₂|² − (r₁ ± r₂)²) / (2(r₁ + r₂)) = 0 (+ external, − internal),
//!
//! which near a solution reads |C₁ − C₂| − (r₁ + r₂) (external) and
//! (|r₁ − r₂|/(r₁ + r₂))·(|C₁ − C₂| − |r₁ − r₂|) (internal). External and internal contacts
//! cannot turn into each other without a radius going through zero. The contact lies on the
//! line of centres: in the direction u = (C₂ − C₁)/|C₁ − C₂| from C₁ for an external contact
//! and for an internal one with r₁ > r₂, in the direction −u when the arc lies inside the
//! larger circle. After every solve that direction must lie within the arc's sweep (and within
//! the other's, when it is an arc), to the solve's tolerance over the radius, else the solve
//! fails with [`Error::ContactOffArc`](crate::Error::ContactOffArc) naming the constraint and the arc, and the sketch is
//! left as it was. (Coincident circles, an internal contact with C₁ = C₂ and r₁ = r₂, touch
//! everywhere and pass.) For an arc end on a circle or on another arc's end,
//! `arc_tangent_to_arc` is the kind; for two circles, or a circle first, `circle_touches_circle`.
//! File form:
//! `{"kind": "arc_touches_circle", "arc": 1, "circle": 2, "tangency": "external"}`.

use std::sync::Arc;

use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::Glyph;
use super::shared::radii::Round;
pub use super::shared::round_contacts::RoundContact;
use super::shared::round_contacts::{contact_point, verify_on_arcs};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::Tangency;

/// The arc touches a circle (or another arc's circle) in its interior, externally or
/// internally (one row, and the contact checked within the sweeps after the solve).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArcTouchesCircle {
    /// The circular arc.
    pub arc: EntityId,
    /// The circle, or another arc.
    pub circle: EntityId,
    /// Each outside the other, or one inside the other.
    pub tangency: Tangency,
}

impl ConstraintKind for ArcTouchesCircle {
    const TAG: &'static str = "arc_touches_circle";
    const LABEL: &'static str = "arc touches circle";

    fn entities(&self, out: &mut Entities) {
        out.add(self.arc);
        out.add(self.circle);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        Round::arc(cx, self.arc)?;
        distinct(self.arc, self.circle)?;
        let other = Round::of(cx, self.circle)?;
        let mut slots = vec![
            Slot::Point(self.arc, 0),
            Slot::Point(self.arc, 1),
            Slot::Point(self.circle, 0),
        ];
        slots.push(if other.is_arc() {
            Slot::Point(self.circle, 1)
        } else {
            Slot::Radius(self.circle)
        });
        cx.residual(
            RoundContact::new(self.tangency, other.is_arc()),
            slots,
            Some(Arc::new(*self)),
        );
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(match contact_point((self.arc, self.circle), self.tangency, |id| at.lookup(id))? {
            Some((x, w1, _)) => vec![
                Glyph::Arrow(x, Vector2::new(-w1.y, w1.x)),
                Glyph::Ring(x),
            ],
            None => Vec::new(),
        })
    }
}

impl SolvedCheck for ArcTouchesCircle {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        verify_on_arcs((self.arc, self.circle), self.tangency, state)
    }
}
