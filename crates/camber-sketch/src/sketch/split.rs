//! Splitting and trimming an entity where it crosses another.
//!
//! The crossing is found by the kernel's curve–curve intersection
//! ([`camber_geom::queries::intersect_curves`]: Bézier pieces in box trees, each candidate
//! refined by Newton's method to the rounding of the coordinates) between the cut entity — a
//! line, a circular arc (through its exact rational form), an elliptic arc (cut at the
//! parametric angle of the crossing) or a Bézier, B-spline, NURBS or cubic Hermite curve — and
//! the other entity, which may also be a circle, an ellipse, an elliptic arc or a composite
//! curve. Crossings within 10⁻⁹ of the sketch's size of an end of the
//! cut entity are not cuts (a piece would be empty). With one crossing left it is the cut;
//! with several, the caller names a point and the crossing nearest it is taken; without a
//! point that is [`Error::AmbiguousIntersection`].
//!
//! **Split** ([`Sketch::split_at_intersection`]): the entity keeps its id and becomes the piece
//! from its start to the crossing; a new entity of the same kind holds the piece from the
//! crossing to its end (module `cut`: exact shape, a curve's pieces each with as many control
//! points as the curve). Two constraints keep the join closed: a `coincident` of the first
//! piece's end and the second's start, and the joint on the other entity (`point_on_line`,
//! `point_on_circle`, `point_on_arc`, `point_on_ellipse`, or `point_on_curve` at a free
//! parameter starting at the crossing). The constraints that read the entity's end move to the
//! second piece; the others stay with the first. The pieces are not held collinear, concentric
//! or tangent to each other: only their joint is.
//!
//! **Trim** ([`Sketch::trim`]): the same cut, keeping one piece under the entity's id and
//! dropping the other together with the constraints that read the dropped end; the kept cut
//! end is held on the other entity.
//!
//! Both refuse a constraint on the entity that cannot follow the cut (module `cut`) with
//! [`Error::EntityConstrained`], and any failure leaves the sketch as it was.

use camber_geom::queries::{intersect_curves, CurveCurveOptions};
use camber_geom::{NurbsCurve2, ParametricCurve, Segment};
use nalgebra::Point2;

use super::cut::{carried_ends, cuttable, end_of, line_or_arc_parameter, piece};
use crate::constraints::arc_tangent_to_line::ArcEnd;
use crate::constraints::{
    Coincident, Constraint, PointOnArc, PointOnCircle, PointOnCurve, PointOnEllipse, PointOnLine,
};
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{ConstraintId, EntityId, PointRef};
use crate::ground::vocabulary::{Contact, FixTarget};
use crate::sketch::Sketch;

/// Which piece [`Sketch::trim`] keeps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Keep {
    /// The piece from the entity's start to the crossing.
    Start,
    /// The piece from the crossing to the entity's end.
    End,
}

/// What [`Sketch::split_at_intersection`] made.
#[derive(Debug, Clone, PartialEq)]
pub struct Split {
    /// The first piece, from the start to the crossing: the entity's own id.
    pub first: EntityId,
    /// The second piece, from the crossing to the end: a new entity.
    pub second: EntityId,
    /// The crossing.
    pub point: Point2<f64>,
    /// The constraints added: the pieces' `coincident`, then the joint on the other entity.
    pub added: Vec<ConstraintId>,
    /// The constraints at the entity's end moved to the second piece: (old id, new id).
    pub moved: Vec<(ConstraintId, ConstraintId)>,
}

/// What [`Sketch::trim`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct Trim {
    /// The entity, now the kept piece.
    pub entity: EntityId,
    /// The crossing, the kept piece's cut end.
    pub point: Point2<f64>,
    /// The constraint added: the cut end on the other entity.
    pub added: ConstraintId,
    /// The constraints that read the dropped end, removed with it.
    pub removed: Vec<ConstraintId>,
}

/// A curve the intersection search reads, owned where it had to be made.
pub(super) enum Shape<'a> {
    Borrowed(&'a dyn ParametricCurve<f64, 2>),
    Segment(Segment<f64>),
    Nurbs(NurbsCurve2<f64>),
    Circle(camber_geom::Circle<f64>),
    Ellipse(camber_geom::Ellipse<f64>),
    EllipticArc(camber_geom::EllipticArc<f64>),
}

impl Shape<'_> {
    pub(super) fn curve(&self) -> &dyn ParametricCurve<f64, 2> {
        match self {
            Shape::Borrowed(c) => *c,
            Shape::Segment(c) => c,
            Shape::Nurbs(c) => c,
            Shape::Circle(c) => c,
            Shape::Ellipse(c) => c,
            Shape::EllipticArc(c) => c,
        }
    }
}

/// The curve the intersection search reads for entity `id` (a line, circle, arc, ellipse,
/// elliptic arc or curve; a point is [`Error::WrongEntityKind`]).
pub(super) fn shape(id: EntityId, e: &Entity) -> Result<Shape<'_>> {
    let wrong = || Error::WrongEntityKind {
        entity: id,
        expected: "line, circle, arc, ellipse or curve",
        found: e.kind_name(),
    };
    Ok(match e {
        Entity::Line([a, b]) => Shape::Segment(Segment::try_new(*a, *b)?),
        Entity::Circle { center, radius } => {
            Shape::Circle(camber_geom::Circle::try_new(*center, *radius)?)
        }
        Entity::Arc(_) => Shape::Nurbs(e.as_arc().ok_or_else(wrong)?.to_nurbs()?),
        Entity::Ellipse { .. } => Shape::Ellipse(e.as_ellipse().ok_or_else(wrong)?),
        Entity::EllipticArc { .. } => Shape::EllipticArc(e.as_elliptic_arc().ok_or_else(wrong)?),
        Entity::Point(_) => return Err(wrong()),
        _ => Shape::Borrowed(e.as_curve().ok_or_else(wrong)?),
    })
}

/// The chosen crossing: the cut parameter on the entity (an arc's: the angle), the point,
/// and the parameter on the other entity.
struct Crossing {
    t: f64,
    point: Point2<f64>,
    other_parameter: f64,
}

/// # Operations
impl Sketch {
    /// The crossing of `entity` with `other` to cut at (module `split`).
    fn crossing(
        &self,
        entity: EntityId,
        other: EntityId,
        near: Option<Point2<f64>>,
    ) -> Result<Crossing> {
        let (e, o) = (self.entity(entity)?, self.entity(other)?);
        if !cuttable(e) {
            return Err(Error::WrongEntityKind {
                entity,
                expected: "line, arc, elliptic arc, Bézier, B-spline, NURBS or Hermite curve",
                found: e.kind_name(),
            });
        }
        let (se, so) = (shape(entity, e)?, shape(other, o)?);
        if entity == other {
            return Err(Error::SameEntity { entity });
        }
        if let Some(p) = near {
            crate::ground::entity::check_point("nearest point", 0, &p)?;
        }
        let hits = intersect_curves(se.curve(), so.curve(), &CurveCurveOptions::default())?;
        let ends = [
            e.points()[match e {
                Entity::Arc(_) => 1,
                Entity::EllipticArc { .. } => 2,
                _ => 0,
            }],
            *e.points().last().unwrap_or(&Point2::origin()),
        ];
        let (lo, hi) = e.domain().unwrap_or((0.0, 1.0));
        let ends = match e {
            Entity::Line(_) | Entity::Arc(_) | Entity::EllipticArc { .. } => ends,
            _ => {
                let at = |u| e.point_tangent(u).map_or(Point2::origin(), |(p, _)| p);
                [at(lo), at(hi)]
            }
        };
        let size = self.extent.magnitude().max(1.0);
        let inside: Vec<_> = hits
            .into_iter()
            .filter(|h| ends.iter().all(|q| (h.point_a - q).norm() > 1e-9 * size))
            .collect();
        let hit = match (inside.len(), near) {
            (0, _) => return Err(Error::NoIntersection { entity, other }),
            (1, _) => inside[0],
            (count, None) => {
                return Err(Error::AmbiguousIntersection {
                    entity,
                    other,
                    count,
                })
            }
            (_, Some(p)) => inside
                .iter()
                .copied()
                .min_by(|a, b| (a.point_a - p).norm().total_cmp(&(b.point_a - p).norm()))
                .unwrap_or(inside[0]),
        };
        let t = line_or_arc_parameter(e, hit.point_a).unwrap_or(hit.parameter_a);
        let point = match e {
            Entity::Line([a, b]) => a + (b - a) * t,
            _ => hit.point_a,
        };
        Ok(Crossing {
            t,
            point,
            other_parameter: hit.parameter_b,
        })
    }

    /// The constraint holding `point` on entity `other` (module `split`).
    pub(super) fn on_other(&self, point: PointRef, other: EntityId, u: f64) -> Result<Constraint> {
        Ok(match self.entity(other)? {
            Entity::Line(_) => PointOnLine { point, line: other }.into(),
            Entity::Circle { .. } => PointOnCircle {
                point,
                circle: other,
            }
            .into(),
            Entity::Arc(_) => PointOnArc { point, arc: other }.into(),
            Entity::Ellipse { .. } | Entity::EllipticArc { .. } => PointOnEllipse {
                point,
                ellipse: other,
            }
            .into(),
            _ => PointOnCurve {
                point,
                curve: other,
                u: Contact::Free(u),
            }
            .into(),
        })
    }

    /// The constraints reading `entity` directly, each with the ends of it they read; fails
    /// on one that cannot follow a cut.
    fn cut_readers(
        &self,
        entity: EntityId,
        operation: &'static str,
    ) -> Result<Vec<(ConstraintId, super::cut::EndsRead)>> {
        let e = self.entity(entity)?;
        let mut out = Vec::new();
        for id in self.constraints_at(entity) {
            let c = self.constraint(id)?;
            if !c.entities().contains(&entity) {
                continue;
            }
            let ends = carried_ends(c, entity, e).ok_or(Error::EntityConstrained {
                entity,
                constraint: id,
                operation,
            })?;
            out.push((id, ends));
        }
        Ok(out)
    }

    /// Splits `entity` (a line, a circular arc or a Bézier, B-spline or NURBS curve) where it
    /// crosses `other`, at the crossing nearest `near` when there are several (module
    /// `split`). On any error the sketch is unchanged.
    ///
    /// ```
    /// use camber_sketch::{PointRef, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let a = s.add_line(Point2::new(0.0, 0.0), Point2::new(4.0, 0.0))?;
    /// let b = s.add_line(Point2::new(1.0, -1.0), Point2::new(1.0, 1.0))?;
    /// let split = s.split_at_intersection(a, b, None)?;
    /// assert!((s.point(PointRef::End(a))? - Point2::new(1.0, 0.0)).norm() < 1e-15);
    /// assert!((s.point(PointRef::Start(split.second))? - Point2::new(1.0, 0.0)).norm() < 1e-15);
    /// assert_eq!(split.added.len(), 2);
    /// s.solve()?;
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::WrongEntityKind`] for an entity that cannot be cut or an `other` that is a
    /// point; [`Error::SameEntity`]; [`Error::NoIntersection`];
    /// [`Error::AmbiguousIntersection`] without `near`; [`Error::EntityConstrained`]; the
    /// kernel's errors of the intersection search.
    pub fn split_at_intersection(
        &mut self,
        entity: EntityId,
        other: EntityId,
        near: Option<Point2<f64>>,
    ) -> Result<Split> {
        let x = self.crossing(entity, other, near)?;
        let readers = self.cut_readers(entity, "split")?;
        let e = self.entity(entity)?.clone();
        let first = piece(entity, &e, x.t, false)?;
        let second = piece(entity, &e, x.t, true)?;
        let moving: Vec<ConstraintId> = readers
            .iter()
            .filter(|(_, ends)| ends.contains(&ArcEnd::End))
            .map(|(id, _)| *id)
            .collect();
        let ((second, moved_ids), journal) = self.transaction(|sk, j| {
            let was = moving
                .iter()
                .map(|id| j.remove_constraint(sk, *id))
                .collect::<Result<Vec<_>>>()?;
            j.replace_entity(sk, entity, first.clone())?;
            let new = j.add_entity(sk, second.clone())?;
            let moved = was
                .iter()
                .map(|w| j.add_carried(sk, to_second(&w.constraint, entity, &e, new), w))
                .collect::<Result<Vec<_>>>()?;
            j.add_constraint(
                sk,
                Coincident {
                    a: PointRef::End(entity),
                    b: PointRef::Start(new),
                },
            )?;
            let on = sk.on_other(PointRef::End(entity), other, x.other_parameter)?;
            j.add_constraint(sk, on)?;
            Ok((new, moved))
        })?;
        let added = journal.added_constraints()[moved_ids.len()..].to_vec();
        Ok(Split {
            first: entity,
            second,
            point: x.point,
            added,
            moved: moving.into_iter().zip(moved_ids).collect(),
        })
    }

    /// Trims `entity` (a line, a circular arc or a Bézier, B-spline or NURBS curve) where it
    /// crosses `at`, keeping the piece `keep` and holding its cut end on `at`; with several
    /// crossings, the one nearest `near` (module `split`). The constraints that read the
    /// dropped end are removed. On any error the sketch is unchanged.
    ///
    /// ```
    /// use camber_sketch::sketch::split::Keep;
    /// use camber_sketch::{PointRef, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let a = s.add_line(Point2::new(0.0, 0.0), Point2::new(4.0, 0.0))?;
    /// let c = s.add_circle(Point2::new(4.0, 0.0), 1.0)?;
    /// let trim = s.trim(a, c, Keep::Start, None)?;
    /// assert!((s.point(PointRef::End(a))? - Point2::new(3.0, 0.0)).norm() < 1e-12);
    /// assert!(trim.removed.is_empty());
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Sketch::split_at_intersection`].
    pub fn trim(
        &mut self,
        entity: EntityId,
        at: EntityId,
        keep: Keep,
        near: Option<Point2<f64>>,
    ) -> Result<Trim> {
        let x = self.crossing(entity, at, near)?;
        let readers = self.cut_readers(entity, "trim")?;
        let e = self.entity(entity)?.clone();
        let (dropped, cut_end) = match keep {
            Keep::Start => (ArcEnd::End, PointRef::End(entity)),
            Keep::End => (ArcEnd::Start, PointRef::Start(entity)),
        };
        let kept = piece(entity, &e, x.t, keep == Keep::End)?;
        let removed: Vec<ConstraintId> = readers
            .iter()
            .filter(|(_, ends)| ends.contains(&dropped))
            .map(|(id, _)| *id)
            .collect();
        let (added, _) = self.transaction(|sk, j| {
            for id in &removed {
                j.remove_constraint(sk, *id)?;
            }
            j.replace_entity(sk, entity, kept.clone())?;
            let on = sk.on_other(cut_end, at, x.other_parameter)?;
            j.add_constraint(sk, on)
        })?;
        Ok(Trim {
            entity,
            point: x.point,
            added,
            removed,
        })
    }
}

/// Constraint `c`, which reads the end of entity `id` (the entity `e`), re-pointed at the end
/// of the second piece `new`.
fn to_second(c: &Constraint, id: EntityId, e: &Entity, new: EntityId) -> Constraint {
    let map = |r: PointRef| {
        if end_of(e, id, r) == Some(ArcEnd::End) {
            PointRef::End(new)
        } else {
            r
        }
    };
    let mut c = c.clone();
    match &mut c {
        Constraint::Coincident(k) => {
            k.a = map(k.a);
            k.b = map(k.b);
        }
        Constraint::Fixed(k) => {
            if let FixTarget::Point(r) = k.target {
                k.target = FixTarget::Point(map(r));
            }
        }
        Constraint::PointOnLine(k) => k.point = map(k.point),
        Constraint::PointOnCircle(k) => k.point = map(k.point),
        Constraint::PointOnEllipse(k) => k.point = map(k.point),
        Constraint::PointOnArc(k) => k.point = map(k.point),
        Constraint::PointOnCurve(k) => k.point = map(k.point),
        Constraint::ArcTangentToCurve(k) => {
            if k.arc == id && k.end == ArcEnd::End {
                k.arc = new;
            }
            if k.curve == id && k.curve_end == ArcEnd::End {
                k.curve = new;
            }
        }
        Constraint::EllipticArcTangentToCurve(k) if k.curve == id && k.curve_end == ArcEnd::End => {
            k.curve = new;
        }
        Constraint::ArcTangentToLine(k) if k.arc == id && k.end == ArcEnd::End => {
            k.arc = new;
        }
        _ => {}
    }
    c
}
