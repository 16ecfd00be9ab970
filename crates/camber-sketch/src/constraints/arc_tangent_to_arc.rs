//! `arc_tangent_to_arc`: at one end P₁ of a circular arc (centre C₁) the arc runs along
//! another arc at one of its ends P₂ (centre C₂), or along a full circle (centre C₂) at P₁
//! itself: the two radii to the shared point are collinear. With r₁ = P₁ − C₁ and r₂ = P₂ − C₂
//! (r₂ = P₁ − C₂ for a circle), one row
//!
//! g = atan2(σ·(r₁ × r₂), σ·(r₁·r₂)) = 0 (radians; σ = +1 for `agree`, −1 for `oppose`),
//!
//! the signed angle between the radii, free of the sketch's scale, whose gradient vanishes
//! only at a tangency (as [`ArcTangentToCurve`](super::ArcTangentToCurve)'s). The travels
//! rot₉₀(r₁) and rot₉₀(r₂) of the two counter-clockwise arcs make the same angle, so `agree`
//! says the two arcs run the same way at the chosen ends; σ·(r₁·r₂) > 0 is checked after every
//! solve (a flip is refused, as for `arc_tangent_to_line`).
//!
//! The row says nothing of where the ends lie. With `coincident` on the two ends it makes a G1
//! join of two arcs; the centres then lie on one line through the joint, on the same side of
//! it when the radii point the same way (r₁·r₂ > 0: one circle inside the other, |C₁ − C₂| =
//! |r₁ − r₂|) and on opposite sides otherwise (an S-bend, |C₁ − C₂| = r₁ + r₂). Which of the
//! two follows from the sense and the ends chosen: the end of one arc joined to the start of
//! the next, both turning the same way, is `agree` and internal; an end joined to an end is
//! `oppose`. With `point_on_circle` (the arc's end on a circle) it makes the arc end touch the
//! circle. File form: `{"kind": "arc_tangent_to_arc", "arc": 1, "end": "end", "other": 2,
//! "other_end": "start", "sense": "agree"}` (no `other_end` when `other` is a circle).

use std::sync::Arc;

use camber_solve::{Residual, Scalar};
use nalgebra::{Point2, Vector2};
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::Glyph;
use super::shared::angles::angle_between;
use super::shared::arc_ends::ArcEnd;
use super::shared::radii::Round;
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::Sense;
use crate::residuals::curve::sub;

/// The arc's end runs along another arc's end, or along a circle, with a sense (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArcTangentToArc {
    /// The circular arc.
    pub arc: EntityId,
    /// Which end of it.
    pub end: ArcEnd,
    /// The other arc, or a circle.
    pub other: EntityId,
    /// Which end of the other arc; `None` (left out of the file) for a circle.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub other_end: Option<ArcEnd>,
    /// Whether the two arcs' counter-clockwise travels at the chosen ends agree or oppose.
    #[serde(default)]
    pub sense: Sense,
}

/// g of the module documentation over the blocks [C₁, P₁, C₂, P₂] (`circle` false) or
/// [C₁, P₁, C₂] with P₂ = P₁ (`circle` true).
///
/// ```
/// use camber_sketch::constraints::arc_tangent_to_arc::ArcArcTangency;
/// use camber_solve::Residual;
/// // Arcs centred at (0, 0) and (3, 0), both through (1, 0): the radii (1, 0) and (−2, 0)
/// // point opposite ways, an S-bend; the row of the sense "oppose" vanishes there.
/// let mut g = [f64::NAN];
/// let x: [&[f64]; 4] = [&[0.0, 0.0], &[1.0, 0.0], &[3.0, 0.0], &[1.0, 0.0]];
/// ArcArcTangency::new(-1.0, false).eval(&x, &mut g);
/// assert!(g[0].abs() < 1e-15);
/// // The sense "agree" reads a half turn there.
/// ArcArcTangency::new(1.0, false).eval(&x, &mut g);
/// assert!((g[0].abs() - std::f64::consts::PI).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArcArcTangency {
    sense: f64,
    circle: bool,
}

impl ArcArcTangency {
    /// The row for the sense ±1, against an arc's end (`circle` false) or a circle.
    pub fn new(sense: f64, circle: bool) -> Self {
        Self { sense, circle }
    }
}

impl Residual for ArcArcTangency {
    fn name(&self) -> &str {
        ArcTangentToArc::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(if self.circle {
            vec![2, 2, 2]
        } else {
            vec![2, 2, 2, 2]
        })
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let r1 = sub(x[1], x[0]);
        let p2 = if self.circle { x[1] } else { x[3] };
        let r2 = sub(p2, x[2]);
        // rot₉₀ turns both radii alike: the angle between the travels is the radii's.
        out[0] = angle_between(r1, r2, self.sense);
    }
}

impl ArcTangentToArc {
    /// The radii r₁ = P₁ − C₁ and r₂ (to P₂, or to P₁ for a circle) with the shared points, in
    /// the state `at` gives.
    fn radii<'e>(
        &self,
        at: impl Fn(EntityId) -> Result<&'e Entity>,
    ) -> Result<[(Point2<f64>, Vector2<f64>); 2]> {
        let e = at(self.arc)?;
        let Entity::Arc(blocks) = e else {
            return Err(Error::WrongEntityKind {
                entity: self.arc,
                expected: "arc",
                found: e.kind_name(),
            });
        };
        let p1 = blocks[self.end.block()];
        let first = (p1, p1 - blocks[0]);
        let second = match (at(self.other)?, self.other_end) {
            (Entity::Arc(other), Some(end)) => {
                let p2 = other[end.block()];
                (p2, p2 - other[0])
            }
            (Entity::Circle { center, .. }, None) => (p1, p1 - center),
            (e, _) => return Err(self.wrong_other(e.kind_name())),
        };
        Ok([first, second])
    }

    /// The error of an `other` that does not match `other_end`.
    fn wrong_other(&self, found: &'static str) -> Error {
        Error::WrongEntityKind {
            entity: self.other,
            expected: if self.other_end.is_some() {
                "arc (an other_end is given)"
            } else {
                "circle (no other_end is given)"
            },
            found,
        }
    }
}

impl ConstraintKind for ArcTangentToArc {
    const TAG: &'static str = "arc_tangent_to_arc";
    const LABEL: &'static str = "arc tangent to arc";

    fn entities(&self, out: &mut Entities) {
        out.add(self.arc);
        out.add(self.other);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        Round::arc(cx, self.arc)?;
        distinct(self.arc, self.other)?;
        let other = Round::of(cx, self.other)?;
        let mut slots = vec![
            Slot::Point(self.arc, 0),
            Slot::Point(self.arc, self.end.block()),
            Slot::Point(self.other, 0),
        ];
        match (other.is_arc(), self.other_end) {
            (true, Some(end)) => slots.push(Slot::Point(self.other, end.block())),
            (false, None) => {}
            (true, None) => return Err(self.wrong_other("arc")),
            (false, Some(_)) => return Err(self.wrong_other("circle")),
        }
        cx.residual(
            ArcArcTangency::new(self.sense.sign(), !other.is_arc()),
            slots,
            Some(Arc::new(*self)),
        );
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(self
            .radii(|id| at.lookup(id))?
            .into_iter()
            .map(|(p, r)| Glyph::Arrow(p, Vector2::new(-r.y, r.x)))
            .collect())
    }
}

impl SolvedCheck for ArcTangentToArc {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let [(_, r1), (_, r2)] = self.radii(|id| state.entity(id))?;
        state.sense(self.sense.sign() * r1.dot(&r2))
    }
}
