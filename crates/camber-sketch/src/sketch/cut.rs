//! Cutting an entity at a parameter: the piece kept, and which constraints reading the entity
//! can follow it.
//!
//! A cut keeps the exact shape. A line keeps its two end blocks (one moved to the cut point);
//! a circular arc keeps its centre and moves one end block to the cut point, projected onto
//! its circle; a Bézier curve is subdivided by de Casteljau's algorithm (same degree, so the
//! same number of control points); a B-spline or NURBS curve is split by knot insertion and
//! the piece kept is then refined (a knot in the middle of its widest span, repeatedly) until
//! it has as many control points as the curve had, so a cut frees no unknowns and takes none;
//! a cubic Hermite curve keeps its four blocks: the piece of p on [t, 1] (or [0, t]) read on
//! [0, 1] has end points p(t) and p(1) (or p(0) and p(t)) and end tangents scaled by the
//! piece's length in u, (1 − t)·p′(t) and (1 − t)·p′(1) (or t·p′(0) and t·p′(t)).
//!
//! A whole circle or ellipse has no ends to keep, and a composite curve cannot be cut: each of
//! its segments runs over one unit of u, so the cut segment's piece would carry tangents
//! scaled by its length while a smooth join shares one tangent block with the next segment
//! (the join would have to become a corner with a tangent block of its own, an unknown more).
//!
//! A constraint reading the entity can follow the cut only when it reads the entity at an end
//! or through what every piece shares: a `coincident` or `fixed` on an end point, an end point
//! held on another entity (`point_on_line`, `point_on_circle`, `point_on_arc`,
//! `point_on_ellipse`, `point_on_curve`), the arc tangencies at a curve's end
//! (`arc_tangent_to_curve`, `elliptic_arc_tangent_to_curve`) or at a cut arc's end, a point on
//! a cut line and the arc and elliptic-arc tangencies to a cut line (its infinite line), and
//! the radius of a cut arc. Any other one (an interior control point, a contact at a parameter,
//! the whole entity fixed, a length) would change meaning and stops the operation.

use camber_geom::ParametricCurve;
use nalgebra::{Point2, Vector2};
use smallvec::SmallVec;

use crate::constraints::arc_tangent_to_line::ArcEnd;
use crate::constraints::Constraint;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::hermite_chain::HermiteChain;
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::vocabulary::FixTarget;

/// The ends of an entity a carried constraint reads (none for one that reads only what every
/// piece shares, such as a line's direction).
pub(crate) type EndsRead = SmallVec<[ArcEnd; 2]>;

/// Whether `e` is a kind that can be cut: a line, a circular or elliptic arc, or a Bézier,
/// B-spline, NURBS or cubic Hermite curve (module documentation: not a whole circle or
/// ellipse, not a composite curve).
pub(crate) fn cuttable(e: &Entity) -> bool {
    matches!(
        e,
        Entity::Line(_)
            | Entity::Arc(_)
            | Entity::EllipticArc { .. }
            | Entity::Bezier(_)
            | Entity::BSpline(_)
            | Entity::Nurbs(_)
            | Entity::Hermite(_)
    )
}

/// Which end of entity `id` (the entity `e`) the point reference `r` reads: `Start`/`End`, or
/// the control point an end resolves to (a line's 0 and 1, an arc's 1 and 2, an elliptic
/// arc's 2 and 3, a curve's first and last); `None` for any other point (a centre, an interior control point).
pub(crate) fn end_of(e: &Entity, id: EntityId, r: PointRef) -> Option<ArcEnd> {
    if r.entity() != id {
        return None;
    }
    match r {
        PointRef::Start(_) => Some(ArcEnd::Start),
        PointRef::End(_) => Some(ArcEnd::End),
        PointRef::Control(_, i) => {
            let n = e.points().len();
            let (first, last) = match e {
                Entity::Arc(_) => (1, 2),
                Entity::EllipticArc { .. } => (2, 3),
                // Blocks [p0, p1, t0, t1]: the end points come first.
                Entity::Hermite(_) => (0, 1),
                _ => (0, n.saturating_sub(1)),
            };
            let is_arc = matches!(
                e,
                Entity::Arc(_) | Entity::EllipticArc { .. } | Entity::Hermite(_)
            );
            if i == first && (is_arc || e.is_clamped(false)) {
                Some(ArcEnd::Start)
            } else if i == last && (is_arc || e.is_clamped(true)) {
                Some(ArcEnd::End)
            } else {
                None
            }
        }
        PointRef::Point(_) => None,
    }
}

/// The ends of entity `id` that constraint `c` reads, when it can follow a cut of that entity
/// (module documentation); `None` when it cannot.
pub(crate) fn carried_ends(c: &Constraint, id: EntityId, e: &Entity) -> Option<EndsRead> {
    let mut ends = EndsRead::new();
    let mut point = |r: PointRef| -> Option<()> {
        if r.entity() == id {
            ends.push(end_of(e, id, r)?);
        }
        Some(())
    };
    match c {
        Constraint::Coincident(k) => {
            point(k.a)?;
            point(k.b)?;
        }
        Constraint::Fixed(k) => match k.target {
            FixTarget::Point(r) => point(r)?,
            FixTarget::Entity(_) => return None,
        },
        Constraint::ArcTangentToCurve(k) => {
            if k.arc == id {
                ends.push(k.end);
            }
            if k.curve == id {
                ends.push(k.curve_end);
            }
        }
        Constraint::EllipticArcTangentToCurve(k) => {
            if k.arc == id {
                return None;
            }
            ends.push(k.curve_end);
        }
        Constraint::ArcTangentToLine(k) => {
            if k.arc == id {
                ends.push(k.end);
            }
        }
        Constraint::EllipticArcTangentToLine(k) => {
            if k.arc == id {
                return None;
            }
        }
        Constraint::Radius(k) if k.circle == id => {}
        Constraint::PointOnLine(k) => point(k.point)?,
        Constraint::PointOnCircle(k) => point(k.point)?,
        Constraint::PointOnEllipse(k) => point(k.point)?,
        Constraint::PointOnArc(k) if k.arc != id => point(k.point)?,
        Constraint::PointOnCurve(k) if k.curve != id => point(k.point)?,
        _ => return None,
    }
    Some(ends)
}

/// The piece of entity `e` from the cut at parameter `t` to its end (`keep_end`) or from its
/// start to the cut, as the same kind of entity (module documentation). For an arc, `t` is
/// read as the cut point's angle about the centre; for an elliptic arc, as its parametric
/// angle (the cut point is C + a·cos t·u + b·sin t·v on the ellipse).
///
/// # Errors
/// The kernel's errors for a cut too near an end ([`camber_geom::Error::DegenerateSpan`], …);
/// [`Error::WrongEntityKind`] for a kind that cannot be cut.
pub(crate) fn piece(id: EntityId, e: &Entity, t: f64, keep_end: bool) -> Result<Entity> {
    Ok(match e {
        Entity::Line([a, b]) => {
            let x = a + (b - a) * t;
            if keep_end {
                Entity::Line([x, *b])
            } else {
                Entity::Line([*a, x])
            }
        }
        Entity::Arc([c, s, f]) => {
            let r = (s - c).norm();
            let x = c + Vector2::new(t.cos(), t.sin()) * r;
            if keep_end {
                Entity::Arc([*c, x, *f])
            } else {
                Entity::Arc([*c, *s, x])
            }
        }
        Entity::EllipticArc {
            points: [c, v, s, f],
            semi_axis_b,
        } => {
            let x = ellipse_of(id, e)?.point_at_angle(t);
            let points = if keep_end {
                [*c, *v, x, *f]
            } else {
                [*c, *v, *s, x]
            };
            Entity::EllipticArc {
                points,
                semi_axis_b: *semi_axis_b,
            }
        }
        Entity::Bezier(curve) => {
            let (left, right) = curve.subdivide(t)?;
            Entity::Bezier(if keep_end { right } else { left })
        }
        Entity::BSpline(curve) => {
            let (left, right) = curve.split(t)?;
            let mut kept = if keep_end { right } else { left };
            while kept.control_points().len() < curve.control_points().len() {
                kept = kept.insert_knot(widest_span(kept.knots().as_slice()), 1)?;
            }
            Entity::BSpline(kept)
        }
        Entity::Nurbs(curve) => {
            let (left, right) = curve.split(t)?;
            let mut kept = if keep_end { right } else { left };
            while kept.control_points().len() < curve.control_points().len() {
                kept = kept.insert_knot(widest_span(kept.knots().as_slice()), 1)?;
            }
            Entity::Nurbs(kept)
        }
        Entity::Hermite(chain) => {
            let curve = chain.segment(0)?;
            let (at, along) = (curve.point(t)?, curve.derivative(t)?);
            let single = if keep_end {
                let s = 1.0 - t;
                HermiteChain::single(at, curve.p1(), along * s, curve.t1() * s)?
            } else {
                HermiteChain::single(curve.p0(), at, curve.t0() * t, along * t)?
            };
            Entity::Hermite(single)
        }
        other => {
            return Err(Error::WrongEntityKind {
                entity: id,
                expected: "line, arc, elliptic arc, Bézier, B-spline, NURBS or Hermite curve",
                found: other.kind_name(),
            })
        }
    })
}

/// The middle of the widest span of a knot vector.
fn widest_span(knots: &[f64]) -> f64 {
    let (mut lo, mut hi) = (knots[0], knots[0]);
    for w in knots.windows(2) {
        if w[1] - w[0] > hi - lo {
            (lo, hi) = (w[0], w[1]);
        }
    }
    0.5 * (lo + hi)
}

/// The cut parameter of point `x` on entity `e`: the line parameter of its foot, the angle of
/// x about an arc's centre, the parametric angle of x on an elliptic arc's ellipse; `None` for
/// free-form curves (their parameter comes from the query that found the point).
pub(crate) fn line_or_arc_parameter(e: &Entity, x: Point2<f64>) -> Option<f64> {
    match e {
        Entity::Line([a, b]) => {
            let d = b - a;
            Some((x - a).dot(&d) / d.norm_squared())
        }
        Entity::Arc([c, _, _]) => Some((x - c).y.atan2((x - c).x)),
        Entity::EllipticArc { .. } => e.as_ellipse().map(|el| el.angle_of(&x)),
        _ => None,
    }
}

/// The ellipse of elliptic arc `e` (entity `id`).
fn ellipse_of(id: EntityId, e: &Entity) -> Result<camber_geom::Ellipse<f64>> {
    e.as_ellipse().ok_or(Error::WrongEntityKind {
        entity: id,
        expected: "elliptic arc with positive semi-axes",
        found: e.kind_name(),
    })
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use camber_geom::{BSplineCurve2, KnotVector, ParametricCurve};

    /// Both pieces of a cubic Hermite curve keep its four blocks and trace its shape: the piece
    /// kept from t on at s is the curve at t + (1 − t)·s, the piece up to t at s is the curve
    /// at t·s (points and first derivatives scaled by the piece's length in u).
    #[test]
    fn a_hermite_piece_keeps_the_blocks_and_the_shape() {
        let chain = HermiteChain::single(
            Point2::new(0.0, 0.0),
            Point2::new(3.0, 1.0),
            Vector2::new(4.0, 5.0),
            Vector2::new(-1.0, 2.0),
        )
        .unwrap();
        let whole = chain.segment(0).unwrap();
        let e = Entity::Hermite(chain);
        let t = 0.37;
        for keep_end in [false, true] {
            let p = piece(EntityId(0), &e, t, keep_end).unwrap();
            assert_eq!(p.points().len(), 4);
            let curve = p.as_curve().unwrap();
            let (start, scale) = if keep_end { (t, 1.0 - t) } else { (0.0, t) };
            for k in 0..=20 {
                let s = f64::from(k) / 20.0;
                let u = start + scale * s;
                let (a, b) = (curve.point(s).unwrap(), whole.point(u).unwrap());
                assert!((a - b).norm() < 1e-14, "{keep_end} {s}: {a} against {b}");
                let (da, db) = (curve.derivative(s).unwrap(), whole.derivative(u).unwrap());
                assert!(
                    (da - db * scale).norm() < 1e-13,
                    "{keep_end} {s}: {da} against {db}"
                );
            }
        }
    }

    /// The kept piece of a B-spline has the curve's number of control points and its shape.
    #[test]
    fn a_bspline_piece_keeps_the_count_and_the_shape() {
        let pts = (0..7)
            .map(|i| Point2::new(f64::from(i), f64::from(i * i % 5)))
            .collect();
        let c = BSplineCurve2::try_new(3, KnotVector::clamped_uniform(3, 7).unwrap(), pts).unwrap();
        let e = Entity::BSpline(c.clone());
        for keep_end in [false, true] {
            let p = piece(EntityId(0), &e, 0.6, keep_end).unwrap();
            assert_eq!(p.points().len(), 7);
            let curve = p.as_curve().unwrap();
            let (a, b) = curve.domain();
            for k in 0..=20 {
                let u = a + (b - a) * f64::from(k) / 20.0;
                assert!((curve.point(u).unwrap() - c.point(u).unwrap()).norm() < 1e-12);
            }
        }
    }
}
