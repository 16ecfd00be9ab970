//! The contact of two round entities (circles and circular arcs) touching externally or
//! internally, as `arc_touches_circle` and `circle_touches_circle` read it: the contact point
//! on the line of centres, the directions from each centre to it, and the check after a solve
//! that the contact lies within the sweep of each entity that is an arc.
//!
//! With u = (C₂ − C₁)/|C₂ − C₁| the contact is X = C₁ + r₁·w₁, w₁ = u for an external contact
//! and for an internal one with r₁ ≥ r₂, w₁ = −u when the first lies inside the second
//! (r₁ < r₂); w₂ = (X − C₂)/r₂.

use camber_geom::CircularArc;
use nalgebra::{Point2, Vector2};

use super::arc_span::outside_sweep;
use crate::constraints::check::SolvedState;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::vocabulary::Tangency;

/// A round entity's centre, radius and, for an arc, the arc; `None` for any other entity.
pub(crate) fn round(e: &Entity) -> Option<(Point2<f64>, f64, Option<CircularArc<f64>>)> {
    match e {
        Entity::Circle { center, radius } => Some((*center, *radius, None)),
        Entity::Arc(b) => Some((b[0], (b[1] - b[0]).norm(), e.as_arc())),
        _ => None,
    }
}

/// The contact point X of the round entities `first` and `second` and the unit directions
/// w₁, w₂ from their centres to it (module documentation), in the state `at` gives; `None`
/// for concentric entities (no single contact).
///
/// # Errors
/// Unknown ids; [`Error::WrongEntityKind`] for an entity that is not round.
#[allow(clippy::type_complexity)] // Three named results read plainer than a struct here.
pub(crate) fn contact_point<'e>(
    (first, second): (EntityId, EntityId),
    tangency: Tangency,
    at: impl Fn(EntityId) -> Result<&'e Entity>,
) -> Result<Option<(Point2<f64>, Vector2<f64>, Vector2<f64>)>> {
    let wrong = |id: EntityId, e: &Entity| Error::WrongEntityKind {
        entity: id,
        expected: "circle or arc",
        found: e.kind_name(),
    };
    let (e1, e2) = (at(first)?, at(second)?);
    let (c1, r1, _) = round(e1).ok_or_else(|| wrong(first, e1))?;
    let (c2, r2, _) = round(e2).ok_or_else(|| wrong(second, e2))?;
    let delta = c2 - c1;
    let n = delta.norm();
    if n <= 1e-12 * (r1 + r2) {
        return Ok(None);
    }
    let u = delta / n;
    let w1 = match tangency {
        Tangency::Internal if r1 < r2 => -u,
        _ => u,
    };
    let x = c1 + r1 * w1;
    let w2 = (x - c2) / r2;
    Ok(Some((x, w1, w2)))
}

/// Fails with [`Error::ContactOffArc`] (naming the owner and the arc) when the contact of the
/// solved state lies outside the sweep of `first` or `second`, whichever is an arc, by more
/// than the solve's tolerance over the radius. Concentric entities pass.
///
/// # Errors
/// That one, and those of [`contact_point`].
pub(crate) fn verify_on_arcs(
    (first, second): (EntityId, EntityId),
    tangency: Tangency,
    state: &SolvedState<'_>,
) -> Result<()> {
    let Some((_, w1, w2)) = contact_point((first, second), tangency, |id| state.entity(id))? else {
        return Ok(());
    };
    for (id, w) in [(first, w1), (second, w2)] {
        let Some((_, _, Some(arc))) = round(state.entity(id)?) else {
            continue;
        };
        if let Some(outside) = outside_sweep(&arc, w, state.penetration) {
            return Err(Error::ContactOffArc {
                constraint: state.owner,
                arc: id,
                outside,
            });
        }
    }
    Ok(())
}
