//! The fillet of two lines: an arc of a given radius tangent to both, the lines trimmed to it.
//!
//! Let X be the meeting point of the two lines' infinite lines, uₐ and u_b the unit directions
//! from X towards each line's far end, and 2θ the angle between them (0 < 2θ < π). The circle
//! of radius R tangent to both lines inside that angle has its centre on the bisector,
//!
//! C = X + R/sin θ · (uₐ + u_b)/|uₐ + u_b|,
//!
//! and touches the lines at Tₐ = X + R/tan θ · uₐ and T_b = X + R/tan θ · u_b, the feet of C on
//! them. The fillet arc runs between the two tangent points (a sweep of π − 2θ),
//! counter-clockwise from whichever of them makes that turn counter-clockwise about C. Each
//! line's end nearer X moves to its tangent point, and the fillet is held by constraints, not
//! only drawn: a `coincident` at each join, an `arc_tangent_to_line` at each arc end (with the
//! sense the drawn geometry has) and the `radius`. A `coincident` that joined the two trimmed
//! ends (the corner) is removed: the corner is now the arc. With that corner, the fillet adds
//! no freedom: the arc's 5 DOF and the corner's 2 given back are taken by 2 + 2 coincident,
//! 2 tangency and 1 radius rows.

use nalgebra::{Point2, Vector2};

use crate::constraints::arc_tangent_to_line::{ArcEnd, ArcTangentToLine};
use crate::constraints::{Coincident, Constraint, Radius};
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{ConstraintId, EntityId, PointRef};
use crate::ground::vocabulary::Sense;
use crate::sketch::Sketch;

/// What [`Sketch::fillet`] added.
#[derive(Debug, Clone, PartialEq)]
pub struct Fillet {
    /// The arc.
    pub arc: EntityId,
    /// Its centre, radius and ends as made (the closed form above).
    pub geometry: camber_geom::CircularArc<f64>,
    /// The constraints added: two coincident, two tangency, the radius.
    pub added: Vec<ConstraintId>,
    /// The constraints removed: the corner coincidence, and with a trimmed free-form curve
    /// every constraint reading its removed end.
    pub removed: Vec<ConstraintId>,
}

/// One line of the fillet: its id, the index of its end nearer the corner, its unit direction
/// from the corner towards its far end, and the distance from the corner to the far end.
struct Side {
    line: EntityId,
    near: usize,
    along: Vector2<f64>,
    reach: f64,
}

fn side(line: EntityId, ends: [Point2<f64>; 2], x: Point2<f64>) -> Side {
    let near = usize::from((ends[1] - x).norm() < (ends[0] - x).norm());
    let far = ends[1 - near];
    let v = far - x;
    Side {
        line,
        near,
        along: v / v.norm(),
        reach: v.norm(),
    }
}

/// # Operations
impl Sketch {
    /// Rounds the corner between two lines, a line and a free-form curve (Bézier, B-spline,
    /// NURBS, cubic Hermite) or two free-form curves with an arc of radius `radius` tangent to both, trimming
    /// them to its ends. Two lines need not meet (module `fillet`: the closed form and what is
    /// added and removed); a pair with a curve must share an end, the corner (module
    /// `fillet_curve`: the offset-curve search, the trim of a curve, what is added and removed).
    /// On any error the sketch is unchanged.
    ///
    /// ```
    /// use camber_sketch::constraints::Coincident;
    /// use camber_sketch::{PointRef, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let a = s.add_line(Point2::new(4.0, 0.0), Point2::new(0.0, 0.0))?;
    /// let b = s.add_line(Point2::new(0.0, 0.0), Point2::new(0.0, 4.0))?;
    /// s.add_constraint(Coincident { a: PointRef::End(a), b: PointRef::Start(b) })?;
    /// let f = s.fillet(a, b, 1.0)?;
    /// assert!((f.geometry.center() - Point2::new(1.0, 1.0)).norm() < 1e-12);
    /// assert!((s.point(PointRef::End(a))? - Point2::new(1.0, 0.0)).norm() < 1e-12);
    /// assert_eq!(f.removed.len(), 1);
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::WrongEntityKind`] for an entity that is neither a line nor a Bézier, B-spline,
    /// NURBS or cubic Hermite curve (a composite curve cannot be trimmed, see
    /// [`Sketch::trim`]); [`Error::SameEntity`]; [`Error::NotPositive`] for the radius;
    /// [`Error::FilletImpossible`] for parallel lines, a curve pair sharing no end or tangent
    /// there, or a radius that does not fit (tangent points beyond a far end, larger than a
    /// curve's radius of curvature); [`Error::EntityConstrained`] for a constraint on a curve
    /// that its trim cannot carry.
    pub fn fillet(&mut self, first: EntityId, second: EntityId, radius: f64) -> Result<Fillet> {
        let kind = |s: &Sketch, id: EntityId| match s.entity(id)? {
            Entity::Line(_) => Ok(true),
            Entity::Bezier(_) | Entity::BSpline(_) | Entity::Nurbs(_) | Entity::Hermite(_) => {
                Ok(false)
            }
            other => Err(Error::WrongEntityKind {
                entity: id,
                expected: "line, Bézier, B-spline, NURBS or Hermite curve",
                found: other.kind_name(),
            }),
        };
        let lines = kind(self, first)? & kind(self, second)?;
        if first == second {
            return Err(Error::SameEntity { entity: first });
        }
        if !(radius.is_finite() && radius > 0.0) {
            return Err(Error::NotPositive {
                what: "fillet radius",
                value: radius,
            });
        }
        if lines {
            self.fillet_lines(first, second, radius)
        } else {
            self.fillet_curves(first, second, radius)
        }
    }

    /// The fillet of two lines (module documentation).
    fn fillet_lines(&mut self, first: EntityId, second: EntityId, radius: f64) -> Result<Fillet> {
        let line = |s: &Sketch, id: EntityId| match s.entity(id)? {
            Entity::Line(ends) => Ok(*ends),
            other => Err(Error::WrongEntityKind {
                entity: id,
                expected: "line",
                found: other.kind_name(),
            }),
        };
        let (la, lb) = (line(self, first)?, line(self, second)?);
        let impossible = |reason| Error::FilletImpossible {
            first,
            second,
            radius,
            reason,
        };
        // X = A₀ + s·dₐ on both lines: cross(dₐ, d_b)·s = cross(B₀ − A₀, d_b).
        let (da, db) = (la[1] - la[0], lb[1] - lb[0]);
        let cross = |u: Vector2<f64>, v: Vector2<f64>| u.x * v.y - u.y * v.x;
        let denominator = cross(da, db);
        if denominator.abs() <= 1e-12 * da.norm() * db.norm() {
            return Err(impossible("the lines are parallel"));
        }
        let x = la[0] + da * (cross(lb[0] - la[0], db) / denominator);
        let (a, b) = (side(first, la, x), side(second, lb, x));
        let cos = a.along.dot(&b.along).clamp(-1.0, 1.0);
        let theta = cos.acos() / 2.0;
        if !(theta > 1e-9 && theta < std::f64::consts::FRAC_PI_2 - 1e-9) {
            return Err(impossible("the lines are collinear"));
        }
        let t = radius / theta.tan();
        if t >= a.reach || t >= b.reach {
            return Err(impossible(
                "the radius puts a tangent point beyond a line's far end",
            ));
        }
        let bisector = (a.along + b.along).normalize();
        let center = x + bisector * (radius / theta.sin());
        let (ta, tb) = (x + a.along * t, x + b.along * t);
        // Counter-clockwise from the tangent point that makes the short turn so.
        let (start, end) = if cross(ta - center, tb - center) > 0.0 {
            ((&a, ta), (&b, tb))
        } else {
            ((&b, tb), (&a, ta))
        };
        let angle = |p: Point2<f64>| (p - center).y.atan2((p - center).x);
        let geometry =
            camber_geom::CircularArc::try_new(center, radius, angle(start.1), angle(end.1))?;

        let near = |s: &Side| PointRef::Control(s.line, s.near);
        let (na, nb) = (near(&a), near(&b));
        let block = |r: PointRef| -> Option<(EntityId, usize)> {
            let e = self.entity(r.entity()).ok()?;
            match e.resolve(r).ok()?.as_slice() {
                [(j, _)] => Some((r.entity(), *j)),
                _ => None,
            }
        };
        let same = |p: PointRef, q: PointRef| block(p).is_some() && block(p) == block(q);
        // The corner's coincidences read both lines: only the constraints at the first line
        // are looked at, so a fillet costs the same in a sketch of any size.
        let corner: Vec<ConstraintId> = self
            .constraints_at(first)
            .into_iter()
            .filter(|id| match self.constraint(*id) {
                Ok(Constraint::Coincident(k)) => {
                    (same(k.a, na) && same(k.b, nb)) || (same(k.a, nb) && same(k.b, na))
                }
                _ => false,
            })
            .collect();
        // The steps, each through the journal so that a failure puts everything back.
        let (arc, journal) = self.transaction(|sk, j| {
            for id in &corner {
                j.remove_constraint(sk, *id)?;
            }
            for (side, p) in [(&a, ta), (&b, tb)] {
                let mut ends = if side.line == first { la } else { lb };
                ends[side.near] = p;
                j.replace_entity(sk, side.line, Entity::Line(ends))?;
            }
            let arc = j.add_entity(sk, Entity::arc(&geometry))?;
            for (side, arc_end) in [(start.0, ArcEnd::Start), (end.0, ArcEnd::End)] {
                j.add_constraint(
                    sk,
                    Coincident {
                        a: near(side),
                        b: arc_end.point(arc),
                    },
                )?;
                // The sense the drawn arc has: its counter-clockwise travel along B − A or not.
                let p = if arc_end == ArcEnd::Start {
                    geometry.start_point()
                } else {
                    geometry.end_point()
                };
                let r = p - center;
                let [l0, l1] = if side.line == first { la } else { lb };
                let sense = if Vector2::new(-r.y, r.x).dot(&(l1 - l0)) > 0.0 {
                    Sense::Agree
                } else {
                    Sense::Oppose
                };
                j.add_constraint(
                    sk,
                    ArcTangentToLine {
                        arc,
                        end: arc_end,
                        line: side.line,
                        sense,
                    },
                )?;
            }
            j.add_constraint(
                sk,
                Radius {
                    circle: arc,
                    radius,
                },
            )?;
            Ok(arc)
        })?;
        let added = journal.added_constraints();
        Ok(Fillet {
            arc,
            geometry,
            added,
            removed: corner,
        })
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use crate::constraints::Fixed;
    use approx::assert_relative_eq;

    fn dof(s: &Sketch) -> usize {
        s.analyze().unwrap().iter().map(|a| a.analysis.dof).sum()
    }

    /// Lines along +x and at 60° from a common corner at the origin, R = 1: the half angle is
    /// 30°, so the centre is 2 from the corner on the 30° bisector, (√3, 1), and the tangent
    /// points are √3 from the corner, (√3, 0) and √3·(½, √3/2).
    #[test]
    fn the_fillet_of_a_sixty_degree_corner_meets_the_closed_form() {
        let mut s = Sketch::new();
        let d = Vector2::new(0.5, 3f64.sqrt() / 2.0);
        let a = s.add_line(Point2::new(5.0, 0.0), Point2::origin()).unwrap();
        let b = s.add_line(Point2::origin(), Point2::from(d * 5.0)).unwrap();
        s.add_constraint(Coincident {
            a: PointRef::End(a),
            b: PointRef::Start(b),
        })
        .unwrap();
        s.add_constraint(Fixed::point(PointRef::Start(a))).unwrap();
        s.add_constraint(Fixed::point(PointRef::End(b))).unwrap();
        let before = dof(&s);
        let f = s.fillet(a, b, 1.0).unwrap();
        let r3 = 3f64.sqrt();
        assert_relative_eq!(*f.geometry.center(), Point2::new(r3, 1.0), epsilon = 1e-12);
        assert_relative_eq!(
            f.geometry.sweep(),
            2.0 * std::f64::consts::PI / 3.0,
            epsilon = 1e-12
        );
        assert_relative_eq!(
            s.point(PointRef::End(a)).unwrap(),
            Point2::new(r3, 0.0),
            epsilon = 1e-12
        );
        assert_relative_eq!(
            s.point(PointRef::Start(b)).unwrap(),
            Point2::from(d * r3),
            epsilon = 1e-12
        );
        assert_eq!((f.added.len(), f.removed.len()), (5, 1));
        // No hidden freedom, and the drawn fillet already satisfies its constraints.
        assert_eq!(dof(&s), before);
        let arc = f.arc;
        let made = s.entity(arc).unwrap().clone();
        s.solve().unwrap();
        for (p, q) in made.points().iter().zip(s.entity(arc).unwrap().points()) {
            assert_relative_eq!(p, q, epsilon = 1e-10);
        }
    }

    /// Lines that do not meet yet (the corner is where their infinite lines cross) and point
    /// either way: the fillet is the same closed form, the ends nearer the corner are trimmed.
    #[test]
    fn the_fillet_of_lines_apart_trims_the_ends_nearer_the_corner() {
        let mut s = Sketch::new();
        let a = s
            .add_line(Point2::new(0.5, 2.0), Point2::new(6.0, 2.0))
            .unwrap();
        let b = s
            .add_line(Point2::new(0.0, 7.0), Point2::new(0.0, 2.5))
            .unwrap();
        let f = s.fillet(b, a, 0.5).unwrap();
        assert_relative_eq!(*f.geometry.center(), Point2::new(0.5, 2.5), epsilon = 1e-12);
        assert_relative_eq!(
            s.point(PointRef::Start(a)).unwrap(),
            Point2::new(0.5, 2.0),
            epsilon = 1e-12
        );
        assert_relative_eq!(
            s.point(PointRef::End(b)).unwrap(),
            Point2::new(0.0, 2.5),
            epsilon = 1e-12
        );
        assert!(f.removed.is_empty());
        s.solve().unwrap();
    }

    /// A fillet that fails half way (here: the sketch's ids run out after its arc is added)
    /// puts everything back: the corner under its id and priority, the lines with their
    /// weights, no arc, and the same next automatic id.
    #[test]
    fn a_fillet_failing_half_way_leaves_the_sketch_as_it_was() {
        let mut s = Sketch::new();
        let a = s.add_line(Point2::new(2.0, 0.0), Point2::origin()).unwrap();
        let b = s.add_line(Point2::origin(), Point2::new(0.0, 2.0)).unwrap();
        let corner = s
            .add_constraint(Coincident {
                a: PointRef::End(a),
                b: PointRef::Start(b),
            })
            .unwrap();
        s.set_priority(corner, 2).unwrap();
        s.set_weight(PointRef::Control(a, 1), 3.0).unwrap();
        // The next automatic id is the last one: the arc takes it, the first constraint
        // added after it finds it taken.
        s.add_entity_with_id(EntityId(u64::MAX - 1), Entity::Point(Point2::new(9.0, 9.0)))
            .unwrap();
        let before = crate::file::to_json(&s).unwrap();
        let mut twin = s.clone();
        assert!(matches!(
            s.fillet(a, b, 0.5),
            Err(Error::DuplicateId { .. })
        ));
        assert_eq!(crate::file::to_json(&s).unwrap(), before);
        assert_eq!(s.priority(corner), 2);
        // Weights are not in the file: checked on their own, bit for bit.
        let weight = crate::ground::lookup::EntityLookup::weight(&s, a, 1);
        assert_eq!(weight.to_bits(), 3f64.to_bits());
        assert_eq!(
            s.add_point(Point2::origin()).unwrap(),
            twin.add_point(Point2::origin()).unwrap()
        );
    }

    #[test]
    fn impossible_fillets_are_refused_and_change_nothing() {
        let mut s = Sketch::new();
        let a = s
            .add_line(Point2::new(0.0, 0.0), Point2::new(1.0, 0.0))
            .unwrap();
        let b = s
            .add_line(Point2::new(0.0, 1.0), Point2::new(1.0, 1.0))
            .unwrap();
        let c = s
            .add_line(Point2::new(0.0, 0.0), Point2::new(0.0, 1.0))
            .unwrap();
        let k = s.add_circle(Point2::new(5.0, 5.0), 1.0).unwrap();
        let before = crate::file::to_json(&s).unwrap();
        assert!(matches!(
            s.fillet(a, b, 0.1),
            Err(Error::FilletImpossible { .. })
        ));
        assert!(matches!(
            s.fillet(a, c, 2.0),
            Err(Error::FilletImpossible { .. })
        ));
        assert!(matches!(
            s.fillet(a, c, -1.0),
            Err(Error::NotPositive { .. })
        ));
        assert!(matches!(s.fillet(a, a, 1.0), Err(Error::SameEntity { .. })));
        assert!(matches!(
            s.fillet(a, k, 1.0),
            Err(Error::WrongEntityKind { .. })
        ));
        assert_eq!(crate::file::to_json(&s).unwrap(), before);
    }
}
