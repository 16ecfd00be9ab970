//! `circle_touches_circle`: two round entities, each a full circle or a circular arc (centre
//! Cᵢ, radius rᵢ: a circle's radius block, or |Sᵢ − Cᵢ| for an arc), touch externally
//! (|C₁ − C₂| = r₁ + r₂, each outside the other) or internally (|C₁ − C₂| = |r₁ − r₂|, one
//! inside the other), as recorded. One row in length units,
//!
//! g = (|C₁ − C₂|² − (r₁ ± r₂)²) / (2(r₁ + r₂)) = 0 (+ external, − internal),
//!
//! the row of `arc_touches_circle` ([`RoundContact::between`]), which near a solution reads
//! |C₁ − C₂| − (r₁ + r₂) or (|r₁ − r₂|/(r₁ + r₂))·(|C₁ − C₂| − |r₁ − r₂|): smooth, with no
//! square root of the centre distance, and an external contact cannot turn internal (nor back)
//! without a radius going through zero. Which of two internally touching circles is inside is
//! not recorded: the smaller one is, and the radii may trade places only by passing through
//! equal radii with coincident centres. The contact lies on the line of centres; when either
//! entity is an arc it must lie within that arc's sweep after every solve (to the solve's
//! tolerance over the radius), else the solve fails with
//! [`Error::ContactOffArc`](crate::Error::ContactOffArc) naming the constraint and the arc, and
//! the sketch is left as it was. Coincident circles touch everywhere and pass. File form:
//! `{"kind": "circle_touches_circle", "first": 1, "second": 2, "tangency": "internal"}`.

use std::sync::Arc;

use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::Glyph;
use super::shared::radii::Round;
use super::shared::round_contacts::{contact_point, verify_on_arcs, RoundContact};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::Tangency;

/// Two circles or arcs, in either order, touch externally or internally (one row, and the
/// contact checked within each arc's sweep after the solve).
///
/// ```
/// use camber_sketch::constraints::{CircleTouchesCircle, Fixed};
/// use camber_sketch::{Entity, Sketch, Tangency};
/// use nalgebra::Point2;
/// let mut s = Sketch::new();
/// let big = s.add_entity(Entity::Circle { center: Point2::new(0.0, 0.0), radius: 3.0 })?;
/// let small = s.add_entity(Entity::Circle { center: Point2::new(0.5, 0.0), radius: 1.0 })?;
/// s.add_constraint(Fixed::entity(big))?;
/// s.add_constraint(camber_sketch::constraints::Radius { circle: small, radius: 1.0 })?;
/// s.add_constraint(CircleTouchesCircle { first: big, second: small, tangency: Tangency::Internal })?;
/// s.solve()?;
/// let Entity::Circle { center, .. } = s.entity(small)? else { unreachable!() };
/// assert!((center.coords.norm() - 2.0).abs() < 1e-10);
/// # Ok::<(), camber_sketch::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CircleTouchesCircle {
    /// The first circle or arc.
    pub first: EntityId,
    /// The second circle or arc.
    pub second: EntityId,
    /// Each outside the other, or one inside the other.
    pub tangency: Tangency,
}

/// The slots of a round entity's centre and radius: [C, S] for an arc, [C, r] for a circle.
fn round_slots(round: Round, id: EntityId, out: &mut Vec<Slot>) {
    out.push(Slot::Point(id, 0));
    out.push(if round.is_arc() {
        Slot::Point(id, 1)
    } else {
        Slot::Radius(id)
    });
}

impl ConstraintKind for CircleTouchesCircle {
    const TAG: &'static str = "circle_touches_circle";
    const LABEL: &'static str = "circle touches circle";

    fn entities(&self, out: &mut Entities) {
        out.add(self.first);
        out.add(self.second);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let first = Round::of(cx, self.first)?;
        distinct(self.first, self.second)?;
        let second = Round::of(cx, self.second)?;
        let mut slots = Vec::with_capacity(4);
        round_slots(first, self.first, &mut slots);
        round_slots(second, self.second, &mut slots);
        let check: Option<Arc<dyn SolvedCheck>> = if first.is_arc() || second.is_arc() {
            Some(Arc::new(*self))
        } else {
            None
        };
        cx.residual(
            RoundContact::between(self.tangency, first.is_arc(), second.is_arc()),
            slots,
            check,
        );
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let pair = (self.first, self.second);
        Ok(match contact_point(pair, self.tangency, |id| at.lookup(id))? {
            Some((x, w1, _)) => vec![
                Glyph::Arrow(x, Vector2::new(-w1.y, w1.x)),
                Glyph::Ring(x),
            ],
            None => Vec::new(),
        })
    }
}

impl SolvedCheck for CircleTouchesCircle {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        verify_on_arcs((self.first, self.second), self.tangency, state)
    }
}
