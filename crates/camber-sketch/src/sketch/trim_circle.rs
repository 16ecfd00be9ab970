//! Trimming a circle into an arc between its crossings with other entities.
//!
//! A closed circle has no start or end to keep, so a trim of it names a point instead: the
//! piece of the circle around that point, between the two crossings nearest it on either
//! side, is removed, and the rest becomes a circular arc (same centre and radius) whose ends
//! are held on the entities crossed there (`point_on_line`, `point_on_circle`, `point_on_arc`,
//! `point_on_ellipse`, or `point_on_curve` at a free parameter starting at the crossing), as
//! [`Sketch::trim`] holds a cut end.
//!
//! With the crossings at angles θᵢ about the centre and the point at angle θₚ, each crossing
//! is δᵢ = (θᵢ − θₚ) mod 2π counter-clockwise from the point: the arc runs counter-clockwise
//! from the crossing of least δ to the crossing of greatest δ. Crossings within 10⁻⁹ of the
//! sketch's size of each other count once.
//!
//! The entity keeps its id and changes kind, so every constraint reading it must mean the same
//! of an arc: `radius`, `equal_radius`, `concentric`, and the point kinds that read its centre
//! (`Control(id, 0)` is the centre of both). They are removed and added back under their ids,
//! with their priorities and parameter bindings; any other is refused with
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

/// What [`Sketch::trim_circle`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct CircleTrim {
    /// The entity, now the kept arc.
    pub entity: EntityId,
    /// The arc's start (the crossing counter-clockwise after the removed piece).
    pub start: Point2<f64>,
    /// The arc's end (the crossing counter-clockwise before the removed piece).
    pub end: Point2<f64>,
    /// The constraints added: the start on its entity, then the end on its entity.
    pub added: [ConstraintId; 2],
}

/// One crossing of the circle: its angle about the centre, the entity crossed and the
/// parameter of the crossing on it.
#[derive(Debug, Clone, Copy)]
struct Crossing {
    angle: f64,
    other: EntityId,
    other_parameter: f64,
}

/// Whether constraint `c` means the same when the circle `id` becomes an arc of it.
fn follows_to_arc(c: &Constraint, id: EntityId) -> bool {
    let centre = |r: PointRef| r.entity() != id || r == PointRef::Control(id, 0);
    match c {
        Constraint::Radius(_) | Constraint::EqualRadius(_) | Constraint::Concentric(_) => true,
        Constraint::Coincident(k) => centre(k.a) && centre(k.b),
        Constraint::Fixed(k) => matches!(k.target, FixTarget::Point(r) if centre(r)),
        Constraint::PointOnLine(k) => centre(k.point),
        Constraint::PointOnCircle(k) => k.circle != id && centre(k.point),
        Constraint::PointOnEllipse(k) => centre(k.point),
        Constraint::PointOnArc(k) => centre(k.point),
        Constraint::PointOnCurve(k) => centre(k.point),
        _ => false,
    }
}

/// # Operations
impl Sketch {
    /// Trims the circle `circle` where it crosses the entities `at`, removing the piece
    /// around `remove_near` between the two crossings nearest it on either side; the circle
    /// becomes an arc (same id, centre and radius) with each end held on the entity it lies on
    /// (module `trim_circle`).
    ///
    /// ```
    /// use camber_sketch::{Entity, PointRef, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let c = s.add_circle(Point2::new(0.0, 0.0), 1.0)?;
    /// let cut = s.add_line(Point2::new(0.5, -2.0), Point2::new(0.5, 2.0))?;
    /// // Remove the cap to the right of x = 0.5.
    /// let trim = s.trim_circle(c, &[cut], Point2::new(1.0, 0.0))?;
    /// assert!(matches!(s.entity(c)?, Entity::Arc(_)));
    /// assert!((trim.start - Point2::new(0.5, 0.75_f64.sqrt())).norm() < 1e-12);
    /// assert!((s.point(PointRef::End(c))? - Point2::new(0.5, -(0.75_f64.sqrt()))).norm() < 1e-12);
    /// s.solve()?;
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::WrongEntityKind`] when `circle` is not a circle or an entity of `at` is a
    /// point; [`Error::SameEntity`] when `at` holds the circle; [`Error::NonFinite`] for a
    /// non-finite `remove_near`; [`Error::TooFewCrossings`] with fewer than two distinct
    /// crossings; [`Error::EntityConstrained`] for a constraint on the circle that an arc cannot
    /// carry (module `trim_circle`); the kernel's errors. The sketch is unchanged then.
    pub fn trim_circle(
        &mut self,
        circle: EntityId,
        at: &[EntityId],
        remove_near: Point2<f64>,
    ) -> Result<CircleTrim> {
        let e = self.entity(circle)?;
        let Entity::Circle { center, radius } = *e else {
            return Err(Error::WrongEntityKind {
                entity: circle,
                expected: "circle",
                found: e.kind_name(),
            });
        };
        check_point("point to remove near", 0, &remove_near)?;
        let readers = self.constraints_at(circle);
        for &id in &readers {
            if !follows_to_arc(self.constraint(id)?, circle) {
                return Err(Error::EntityConstrained {
                    entity: circle,
                    constraint: id,
                    operation: "trim",
                });
            }
        }
        let crossings = self.circle_crossings(circle, center, at)?;
        if crossings.len() < 2 {
            return Err(Error::TooFewCrossings {
                entity: circle,
                count: crossings.len(),
            });
        }
        // A point at the centre reads as the direction +x.
        let pick = (remove_near.y - center.y).atan2(remove_near.x - center.x);
        let ahead = |x: &&Crossing| (x.angle - pick).rem_euclid(std::f64::consts::TAU);
        let by_ahead = |a: &&Crossing, b: &&Crossing| ahead(a).total_cmp(&ahead(b));
        let (Some(&first), Some(&last)) = (
            crossings.iter().min_by(by_ahead),
            crossings.iter().max_by(by_ahead),
        ) else {
            return Err(Error::TooFewCrossings {
                entity: circle,
                count: 0,
            });
        };
        let on_circle = |angle: f64| center + radius * Vector2::new(angle.cos(), angle.sin());
        let (start, end) = (on_circle(first.angle), on_circle(last.angle));
        let arc = Entity::Arc([center, start, end]);
        let (added, _) = self.transaction(|sk, j| {
            let removed = readers
                .iter()
                .map(|&id| j.remove_constraint(sk, id))
                .collect::<Result<Vec<_>>>()?;
            let tag = sk.tag(circle).map(str::to_owned);
            let weight = sk.weights_of(circle);
            j.remove_entity(sk, circle)?;
            j.add_entity_with_id(sk, circle, arc.clone())?;
            // The centre is point 0 of both; a circle's other weights (its radius) have no
            // counterpart on the arc.
            for (index, w) in weight {
                if index == 0 {
                    sk.weights.insert((circle, 0), w);
                }
            }
            if let Some(tag) = tag {
                sk.set_tag(circle, Some(&tag))?;
            }
            for (id, was) in readers.iter().zip(&removed) {
                j.restore_constraint(sk, *id, was)?;
            }
            let on_start =
                sk.on_other(PointRef::Start(circle), first.other, first.other_parameter)?;
            let on_end = sk.on_other(PointRef::End(circle), last.other, last.other_parameter)?;
            Ok([
                j.add_constraint(sk, on_start)?,
                j.add_constraint(sk, on_end)?,
            ])
        })?;
        Ok(CircleTrim {
            entity: circle,
            start,
            end,
            added,
        })
    }

    /// The distinct crossings of circle `circle` (centred at `center`) with the entities `at`
    /// (module `trim_circle`).
    fn circle_crossings(
        &self,
        circle: EntityId,
        center: Point2<f64>,
        at: &[EntityId],
    ) -> Result<Vec<Crossing>> {
        let se = shape(circle, self.entity(circle)?)?;
        let merge = 1e-9 * self.extent.magnitude().max(1.0);
        let mut found: Vec<(Point2<f64>, Crossing)> = Vec::new();
        for &other in at {
            if other == circle {
                return Err(Error::SameEntity { entity: circle });
            }
            let so = shape(other, self.entity(other)?)?;
            let hits = intersect_curves(se.curve(), so.curve(), &CurveCurveOptions::default())?;
            for h in hits {
                if found.iter().any(|(p, _)| (p - h.point_a).norm() <= merge) {
                    continue;
                }
                let d = h.point_a - center;
                found.push((
                    h.point_a,
                    Crossing {
                        angle: d.y.atan2(d.x),
                        other,
                        other_parameter: h.parameter_b,
                    },
                ));
            }
        }
        Ok(found.into_iter().map(|(_, x)| x).collect())
    }
}
