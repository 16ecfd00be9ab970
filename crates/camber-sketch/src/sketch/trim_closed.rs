//! Trimming a circle or an ellipse into an arc between its crossings with other entities.
//!
//! A closed entity has no start or end to keep, so a trim of it names a point instead: the
//! piece around that point, between the two crossings nearest it on either side, is removed,
//! and the rest becomes a circular arc (same centre and radius) or an elliptic arc (same
//! centre, vertex and semi-axes) whose ends are held on the entities crossed there
//! (`point_on_line`, `point_on_circle`, `point_on_arc`, `point_on_ellipse`, or `point_on_curve`
//! at a free parameter starting at the crossing), as [`Sketch::trim`] holds a cut end.
//!
//! Angles are a circle's polar angle about its centre and an ellipse's parametric angle
//! (E(t) = C + a·cos t·u + b·sin t·v; a point off the ellipse reads the angle of the ray from
//! the centre through it). With the crossings at angles θᵢ and the point at θₚ, each crossing
//! is δᵢ = (θᵢ − θₚ) mod 2π counter-clockwise from the point: the arc runs counter-clockwise
//! from the crossing of least δ to the crossing of greatest δ. Crossings within 10⁻⁹ of the
//! sketch's size of each other count once.
//!
//! The entity keeps its id and changes kind, so every constraint reading it must mean the same
//! of the arc: `radius`, `equal_radius` and `concentric` of a circle, `semi_axis` of an
//! ellipse, and the point kinds that read its centre (`Control(id, 0)`) or an ellipse's vertex
//! (`Control(id, 1)`), which the arc keeps at the same index. They are removed and added back
//! under their ids, with their priorities and parameter bindings; any other is refused with
//! [`Error::EntityConstrained`]. Any failure leaves the sketch as it was.

use camber_geom::queries::{intersect_curves, CurveCurveOptions};
use nalgebra::{Point2, Vector2};

use super::split::shape;
use crate::constraints::Constraint;
use crate::ground::entity::{check_point, Entity};
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{ConstraintId, EntityId, PointRef};
use crate::ground::vocabulary::FixTarget;
use crate::sketch::Sketch;

/// What [`Sketch::trim_closed`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct ClosedTrim {
    /// The entity, now the kept arc.
    pub entity: EntityId,
    /// The arc's start (the crossing counter-clockwise after the removed piece).
    pub start: Point2<f64>,
    /// The arc's end (the crossing counter-clockwise before the removed piece).
    pub end: Point2<f64>,
    /// The constraints added: the start on its entity, then the end on its entity.
    pub added: [ConstraintId; 2],
}

/// One crossing: its angle on the closed entity, the entity crossed and the parameter of the
/// crossing on it.
#[derive(Debug, Clone, Copy)]
struct Crossing {
    angle: f64,
    other: EntityId,
    other_parameter: f64,
}

/// The closed entity being trimmed.
enum Closed {
    Circle {
        center: Point2<f64>,
        radius: f64,
    },
    Ellipse {
        points: [Point2<f64>; 2],
        semi_axis_b: f64,
        shape: camber_geom::Ellipse<f64>,
    },
}

impl Closed {
    /// The angle of `p` (module header).
    fn angle_of(&self, p: &Point2<f64>) -> f64 {
        match self {
            Closed::Circle { center, .. } => (p.y - center.y).atan2(p.x - center.x),
            Closed::Ellipse { shape, .. } => shape.angle_of(p),
        }
    }

    /// The point at angle `t`.
    fn point_at(&self, t: f64) -> Point2<f64> {
        match self {
            Closed::Circle { center, radius } => center + *radius * Vector2::new(t.cos(), t.sin()),
            Closed::Ellipse { shape, .. } => shape.point_at_angle(t),
        }
    }

    /// The arc of it from `start` to `end`, counter-clockwise.
    fn arc(&self, start: Point2<f64>, end: Point2<f64>) -> Entity {
        match self {
            Closed::Circle { center, .. } => Entity::Arc([*center, start, end]),
            Closed::Ellipse {
                points: [c, v],
                semi_axis_b,
                ..
            } => Entity::EllipticArc {
                points: [*c, *v, start, end],
                semi_axis_b: *semi_axis_b,
            },
        }
    }

    /// Whether constraint `c` on the entity `id` means the same of the arc.
    fn carries(&self, c: &Constraint, id: EntityId) -> bool {
        let kept = match self {
            Closed::Circle { .. } => 0,
            Closed::Ellipse { .. } => 1,
        };
        let point =
            |r: PointRef| r.entity() != id || matches!(r, PointRef::Control(_, i) if i <= kept);
        match (self, c) {
            (
                Closed::Circle { .. },
                Constraint::Radius(_) | Constraint::EqualRadius(_) | Constraint::Concentric(_),
            )
            | (Closed::Ellipse { .. }, Constraint::SemiAxis(_)) => true,
            (_, Constraint::Coincident(k)) => point(k.a) && point(k.b),
            (_, Constraint::Fixed(k)) => matches!(k.target, FixTarget::Point(r) if point(r)),
            (_, Constraint::PointOnLine(k)) => point(k.point),
            (_, Constraint::PointOnCircle(k)) => k.circle != id && point(k.point),
            (_, Constraint::PointOnEllipse(k)) => k.ellipse != id && point(k.point),
            (_, Constraint::PointOnArc(k)) => point(k.point),
            (_, Constraint::PointOnCurve(k)) => point(k.point),
            _ => false,
        }
    }
}

/// # Operations
impl Sketch {
    /// Trims the circle or ellipse `entity` where it crosses the entities `at`, removing the
    /// piece around `remove_near` between the two crossings nearest it on either side; the
    /// entity becomes a circular or elliptic arc (same id and shape) with each end held on the
    /// entity it lies on (module `trim_closed`).
    ///
    /// ```
    /// use camber_sketch::{Entity, PointRef, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let c = s.add_circle(Point2::new(0.0, 0.0), 1.0)?;
    /// let cut = s.add_line(Point2::new(0.5, -2.0), Point2::new(0.5, 2.0))?;
    /// // Remove the cap to the right of x = 0.5.
    /// let trim = s.trim_closed(c, &[cut], Point2::new(1.0, 0.0))?;
    /// assert!(matches!(s.entity(c)?, Entity::Arc(_)));
    /// assert!((trim.start - Point2::new(0.5, 0.75_f64.sqrt())).norm() < 1e-12);
    /// assert!((s.point(PointRef::End(c))? - Point2::new(0.5, -(0.75_f64.sqrt()))).norm() < 1e-12);
    /// s.solve()?;
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::WrongEntityKind`] when `entity` is not a circle or an ellipse, or an entity of
    /// `at` is a point; [`Error::SameEntity`] when `at` holds the entity; [`Error::NonFinite`]
    /// for a non-finite `remove_near`; [`Error::TooFewCrossings`] with fewer than two distinct
    /// crossings; [`Error::EntityConstrained`] for a constraint on the entity that the arc
    /// cannot carry (module `trim_closed`); the kernel's errors. The sketch is unchanged then.
    pub fn trim_closed(
        &mut self,
        entity: EntityId,
        at: &[EntityId],
        remove_near: Point2<f64>,
    ) -> Result<ClosedTrim> {
        let e = self.entity(entity)?;
        let wrong = || Error::WrongEntityKind {
            entity,
            expected: "circle or ellipse",
            found: e.kind_name(),
        };
        let closed = match *e {
            Entity::Circle { center, radius } => Closed::Circle { center, radius },
            Entity::Ellipse {
                points,
                semi_axis_b,
            } => Closed::Ellipse {
                points,
                semi_axis_b,
                shape: e.as_ellipse().ok_or_else(wrong)?,
            },
            _ => return Err(wrong()),
        };
        check_point("point to remove near", 0, &remove_near)?;
        let readers = self.constraints_at(entity);
        for &id in &readers {
            if !closed.carries(self.constraint(id)?, entity) {
                return Err(Error::EntityConstrained {
                    entity,
                    constraint: id,
                    operation: "trim",
                });
            }
        }
        let crossings = self.closed_crossings(entity, &closed, at)?;
        if crossings.len() < 2 {
            return Err(Error::TooFewCrossings {
                entity,
                count: crossings.len(),
            });
        }
        // A point at the centre reads as the angle 0.
        let pick = closed.angle_of(&remove_near);
        let ahead = |x: &&Crossing| (x.angle - pick).rem_euclid(std::f64::consts::TAU);
        let by_ahead = |a: &&Crossing, b: &&Crossing| ahead(a).total_cmp(&ahead(b));
        let (Some(&first), Some(&last)) = (
            crossings.iter().min_by(by_ahead),
            crossings.iter().max_by(by_ahead),
        ) else {
            return Err(Error::TooFewCrossings { entity, count: 0 });
        };
        let (start, end) = (closed.point_at(first.angle), closed.point_at(last.angle));
        let arc = closed.arc(start, end);
        let (added, _) = self.transaction(|sk, j| {
            let removed = readers
                .iter()
                .map(|&id| j.remove_constraint(sk, id))
                .collect::<Result<Vec<_>>>()?;
            let tag = sk.tag(entity).map(str::to_owned);
            let weights = sk.weights_of(entity);
            j.remove_entity(sk, entity)?;
            j.add_entity_with_id(sk, entity, arc.clone())?;
            // The centre (and an ellipse's vertex) keep their indices; a circle's radius and an
            // ellipse's b have no point weight to carry.
            for (index, w) in weights {
                if index < 2 {
                    sk.weights.insert((entity, index), w);
                }
            }
            if let Some(tag) = tag {
                sk.set_tag(entity, Some(&tag))?;
            }
            for (id, was) in readers.iter().zip(&removed) {
                j.restore_constraint(sk, *id, was)?;
            }
            let on_start =
                sk.on_other(PointRef::Start(entity), first.other, first.other_parameter)?;
            let on_end = sk.on_other(PointRef::End(entity), last.other, last.other_parameter)?;
            Ok([
                j.add_constraint(sk, on_start)?,
                j.add_constraint(sk, on_end)?,
            ])
        })?;
        Ok(ClosedTrim {
            entity,
            start,
            end,
            added,
        })
    }

    /// The distinct crossings of the closed entity `id` (`closed`) with the entities `at`
    /// (module `trim_closed`).
    fn closed_crossings(
        &self,
        id: EntityId,
        closed: &Closed,
        at: &[EntityId],
    ) -> Result<Vec<Crossing>> {
        let se = shape(id, self.entity(id)?)?;
        let merge = 1e-9 * self.extent.magnitude().max(1.0);
        let mut found: Vec<(Point2<f64>, Crossing)> = Vec::new();
        for &other in at {
            if other == id {
                return Err(Error::SameEntity { entity: id });
            }
            let so = shape(other, self.entity(other)?)?;
            let hits = intersect_curves(se.curve(), so.curve(), &CurveCurveOptions::default())?;
            found.extend(hits.into_iter().map(|h| {
                (
                    h.point_a,
                    Crossing {
                        angle: closed.angle_of(&h.point_a),
                        other,
                        other_parameter: h.parameter_b,
                    },
                )
            }));
        }
        // Points within `merge` of each other are neighbours in angle: sort by angle and keep
        // one of each run (O(k log k) in the crossings), then drop a last one that meets the
        // first across θ = ±π.
        found.sort_by(|a, b| a.1.angle.total_cmp(&b.1.angle));
        found.dedup_by(|later, kept| (later.0 - kept.0).norm() <= merge);
        if found.len() > 1
            && found
                .first()
                .zip(found.last())
                .is_some_and(|(a, b)| (a.0 - b.0).norm() <= merge)
        {
            found.pop();
        }
        Ok(found.into_iter().map(|(_, x)| x).collect())
    }
}
