//! The ends of circular and elliptic arcs, as the arc kinds name them, and what the kinds
//! holding an arc end tangent to a curve end share: the check of the recorded sense on the
//! solved state, at the curve end's parameter.

use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use crate::constraints::check::{point_tangent, SolvedState};
use crate::ground::errors::Result;
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::vocabulary::Sense;

/// Which end of an arc: `"start"` or `"end"`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ArcEnd {
    /// The start (block 1).
    Start,
    /// The end (block 2).
    End,
}

impl ArcEnd {
    /// The arc's point block of this end.
    pub fn block(self) -> usize {
        match self {
            ArcEnd::Start => 1,
            ArcEnd::End => 2,
        }
    }

    /// The end as a point reference of `arc`.
    pub fn point(self, arc: EntityId) -> PointRef {
        match self {
            ArcEnd::Start => PointRef::Start(arc),
            ArcEnd::End => PointRef::End(arc),
        }
    }
}

/// The parameter of a curve's `end`, at the start or end of its domain `(lo, hi)`.
pub(crate) fn domain_end((lo, hi): (f64, f64), end: ArcEnd) -> f64 {
    match end {
        ArcEnd::Start => lo,
        ArcEnd::End => hi,
    }
}

/// The check of an arc-end tangency to a curve end after a solve: σ·(t·C′) > 0, with t the
/// arc's counter-clockwise travel at its end, C′ the solved curve's tangent at `curve_end` and
/// σ the recorded sense's sign.
///
/// # Errors
/// [`crate::Error::OrientationFlipped`] when the travel turned against the sense; unknown ids.
pub(crate) fn verify_curve_end_sense(
    state: &SolvedState<'_>,
    travel: Vector2<f64>,
    curve: EntityId,
    curve_end: ArcEnd,
    sense: Sense,
) -> Result<()> {
    let e = state.entity(curve)?;
    let u = domain_end(e.domain().unwrap_or((0.0, 1.0)), curve_end);
    let (_, c1) = point_tangent(e, curve, u)?;
    state.sense(sense.sign() * (travel.x * c1[0] + travel.y * c1[1]))
}
