//! What the ellipse kinds share: the check that an entity is an ellipse or an elliptic arc,
//! the block of an elliptic arc's end, its direction of travel there, and the first-order
//! signed distance to an ellipse, the ellipse of an entity, and the blocks of a contact at a
//! free parametric angle.

use camber_geom::Ellipse;
use nalgebra::{Point2, Vector2};

use super::arc_ends::ArcEnd;
use crate::constraints::compiler::finite;
use crate::constraints::piece::Slot;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;

/// Fails unless `id` is an ellipse or an elliptic arc; `true` for an arc.
pub(crate) fn ellipse_kind(e: &Entity, id: EntityId) -> Result<bool> {
    match e {
        Entity::Ellipse { .. } => Ok(false),
        Entity::EllipticArc { .. } => Ok(true),
        other => Err(Error::WrongEntityKind {
            entity: id,
            expected: "ellipse or elliptic arc",
            found: other.kind_name(),
        }),
    }
}

/// The point block of an elliptic arc's end: 2 the start, 3 the end.
pub(crate) fn end_block(end: ArcEnd) -> usize {
    end.block() + 1
}

/// The counter-clockwise tangent E′ = −(a/b)·y′·u + (b/a)·x′·v at the point P of the ellipse
/// of blocks [C, V] and b (f64).
pub(crate) fn travel(
    c: &nalgebra::Point2<f64>,
    v: &nalgebra::Point2<f64>,
    b: f64,
    p: &nalgebra::Point2<f64>,
) -> Vector2<f64> {
    let w = v - c;
    let a = w.norm();
    let u = w / a;
    let n = Vector2::new(-u.y, u.x);
    let d = p - c;
    let (x, y) = (d.dot(&u), d.dot(&n));
    u * (-(a / b) * y) + n * ((b / a) * x)
}

/// The first-order signed distance from `q` to the ellipse, F/|∇F| with F = (x′/a)² + (y′/b)²
/// − 1 in the ellipse's frame (positive outside): exact in sign and to second order in the
/// distance near the ellipse, where contacts and crossings are measured, with no iteration. At
/// the centre, where ∇F vanishes, the distance to the ellipse is the smaller semi-axis.
pub(crate) fn ellipse_gap(ellipse: &Ellipse<f64>, q: &Point2<f64>) -> f64 {
    let (a, b) = (ellipse.semi_axis_a(), ellipse.semi_axis_b());
    let local = ellipse.to_frame(q);
    let gradient = Vector2::new(2.0 * local.x / (a * a), 2.0 * local.y / (b * b)).norm();
    if gradient > f64::EPSILON {
        ellipse.implicit_value(q) / gradient
    } else {
        -a.min(b)
    }
}

/// The ellipse of an ellipse or elliptic arc entity `e` (entity `id`).
///
/// # Errors
/// [`Error::WrongEntityKind`] for another kind or an ellipse without positive semi-axes.
pub(crate) fn ellipse_of(e: &Entity, id: EntityId) -> Result<Ellipse<f64>> {
    ellipse_kind(e, id)?;
    e.as_ellipse().ok_or(Error::WrongEntityKind {
        entity: id,
        expected: "ellipse with positive semi-axes",
        found: e.kind_name(),
    })
}

/// The blocks of a contact on an ellipse at a free parametric angle: its centre, vertex and
/// semi-axis b, then the angle θ (radians, unbounded) starting at `theta`.
///
/// # Errors
/// [`Error::NonFinite`](crate::Error) for a non-finite `theta`.
pub(crate) fn contact_slots(ellipse: EntityId, theta: f64) -> Result<[Slot; 4]> {
    let start = finite("contact angle", theta)?;
    Ok([
        Slot::Point(ellipse, 0),
        Slot::Point(ellipse, 1),
        Slot::Radius(ellipse),
        Slot::Free {
            start,
            lo: f64::NEG_INFINITY,
            hi: f64::INFINITY,
        },
    ])
}
