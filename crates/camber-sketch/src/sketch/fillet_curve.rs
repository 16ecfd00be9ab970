//! The fillet of a line and a free-form curve, or of two free-form curves, at a shared end.
//!
//! Two legs A(u) and B(v) (a line or a Bézier, B-spline or NURBS curve) meet at a corner X, an
//! end of each. With n the unit left normal and s = ±1 the side of each leg the corner's
//! inside lies on, a circle of radius R touches A at A(u) from that side exactly when its
//! centre is the offset point A(u) + s·R·n(u); the centre of the fillet is where the two
//! offsets meet,
//!
//! F(u, v) = A(u) + sₐ·R·nₐ(u) − B(v) − s_b·R·n_b(v) = 0,
//!
//! two equations in the foot parameters u, v. The offset's derivative is A′(u)·(1 − s·R·κ(u))
//! (κ the signed curvature, κ = A′ × A″ / |A′|³), which gives Newton's method its Jacobian.
//! The search starts at a small radius, where the legs are nearly straight and the feet lie
//! R/tan θ from X along their tangents there (2θ the corner's angle), and grows the radius to
//! R in [`STAGES`] steps, each a Newton iteration of at most [`NEWTON_STEPS`] steps from the
//! last solution. A foot that runs past a leg's far end, a corner where the legs are tangent,
//! and a radius larger than a leg's radius of curvature at its foot (1 − s·R·κ ≤ 0: the arc
//! would cut into the leg) are refused.
//!
//! The legs are then trimmed to the feet: a line's end at X moves to its foot, a curve is cut
//! there and keeps the piece at its far end ([`super::cut`]: same kind, same number of
//! control points, exact shape), and the constraints that read the curve's removed end (the
//! corner's `coincident` among them) go with it. The arc runs between the feet the way the
//! legs travel through the corner and is held by a `coincident` at each join, an
//! `arc_tangent_to_line` or `arc_tangent_to_curve` at each arc end with the sense the drawing
//! has, and a `radius` — with the corner's coincidence removed, no freedom is added: the arc's
//! 5 DOF and the corner's 2 are taken by 4 + 2 + 1 rows.

use nalgebra::{Point2, Vector2};

use super::cut::{carried_ends, piece};
use super::fillet::Fillet;
use crate::constraints::arc_tangent_to_curve::ArcTangentToCurve;
use crate::constraints::arc_tangent_to_line::{ArcEnd, ArcTangentToLine};
use crate::constraints::{Coincident, Constraint, Radius};
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{ConstraintId, EntityId, PointRef};
use crate::ground::vocabulary::Sense;
use crate::sketch::Sketch;

/// Radius steps from a small radius to the one asked for.
pub const STAGES: usize = 16;
/// Newton steps allowed in each stage.
pub const NEWTON_STEPS: usize = 50;

fn cross(u: Vector2<f64>, v: Vector2<f64>) -> f64 {
    u.x * v.y - u.y * v.x
}

fn rot90(v: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-v.y, v.x)
}

/// An offset point, its derivative and the factor 1 − s·ρ·κ.
type Offset = (Vector2<f64>, Vector2<f64>, f64);

/// One leg of the fillet.
struct Leg {
    id: EntityId,
    entity: Entity,
    domain: (f64, f64),
    /// The corner is at the end of the domain (else at its start).
    corner_at_end: bool,
    /// The side of the centre: +1 on the left normal, −1 on the right.
    side: f64,
}

impl Leg {
    fn corner(&self) -> f64 {
        if self.corner_at_end {
            self.domain.1
        } else {
            self.domain.0
        }
    }

    fn far(&self) -> f64 {
        if self.corner_at_end {
            self.domain.0
        } else {
            self.domain.1
        }
    }

    fn clamp(&self, u: f64) -> f64 {
        u.clamp(self.domain.0, self.domain.1)
    }

    /// C, C′ and C″ at u.
    fn jet(&self, u: f64) -> Result<[Vector2<f64>; 3]> {
        match &self.entity {
            Entity::Line([a, b]) => Ok([(a + (b - a) * u).coords, b - a, Vector2::zeros()]),
            e => {
                let curve = e.as_curve().ok_or(Error::WrongEntityKind {
                    entity: self.id,
                    expected: "line, Bézier, B-spline, NURBS or Hermite curve",
                    found: e.kind_name(),
                })?;
                let mut out = [Vector2::zeros(); 3];
                curve.derivatives_into(u, &mut out)?;
                Ok(out)
            }
        }
    }

    /// The offset point C + s·ρ·n at u, its derivative C′·(1 − s·ρ·κ) and the factor 1 − s·ρ·κ;
    /// `None` where the tangent vanishes.
    fn offset(&self, u: f64, rho: f64) -> Result<Option<Offset>> {
        let [c, d1, d2] = self.jet(u)?;
        let speed = d1.norm();
        if speed.is_nan() || speed <= 0.0 {
            return Ok(None);
        }
        let kappa = cross(d1, d2) / (speed * speed * speed);
        let stretch = 1.0 - self.side * rho * kappa;
        Ok(Some((
            c + rot90(d1) * (self.side * rho / speed),
            d1 * stretch,
            stretch,
        )))
    }

    /// The unit tangent at the corner pointing into the leg, away from the corner.
    fn inward(&self) -> Result<Vector2<f64>> {
        let d = self.jet(self.corner())?[1];
        let d = if self.corner_at_end { -d } else { d };
        Ok(d / d.norm())
    }

    /// The point reference of the leg's end at the corner (after the trim, its foot).
    fn near(&self) -> PointRef {
        match (&self.entity, self.corner_at_end) {
            (Entity::Line(_), end) => PointRef::Control(self.id, usize::from(end)),
            (_, false) => PointRef::Start(self.id),
            (_, true) => PointRef::End(self.id),
        }
    }
}

/// How the Newton search ended.
enum Search {
    Found(f64, f64),
    /// A foot would leave its leg.
    Beyond,
    /// No convergence or a singular step.
    Lost,
}

/// The feet (u, v) of the fillet of radius `radius` (module documentation).
fn feet(a: &Leg, b: &Leg, radius: f64, theta: f64, scale: f64) -> Result<Search> {
    let start = |l: &Leg, rho: f64| -> Result<f64> {
        let d = l.jet(l.corner())?[1];
        let toward = if l.corner_at_end { -1.0 } else { 1.0 };
        Ok(l.clamp(l.corner() + toward * rho / theta.tan() / d.norm()))
    };
    let rho0 = radius / STAGES as f64;
    let (mut u, mut v) = (start(a, rho0)?, start(b, rho0)?);
    let tol = 1e-14 * scale;
    for stage in 1..=STAGES {
        let rho = radius * stage as f64 / STAGES as f64;
        if stage > 1 {
            // The feet move away from the corner about in proportion to the radius.
            let grow = stage as f64 / (stage - 1) as f64;
            u = a.clamp(a.corner() + (u - a.corner()) * grow);
            v = b.clamp(b.corner() + (v - b.corner()) * grow);
        }
        let mut converged = false;
        let mut best = f64::INFINITY;
        // Whether the last step was clamped at a leg's far end.
        let mut pinned = (false, false);
        for _ in 0..NEWTON_STEPS {
            let (Some((pa, ja, _)), Some((pb, jb, _))) = (a.offset(u, rho)?, b.offset(v, rho)?)
            else {
                return Ok(Search::Lost);
            };
            let f = pa - pb;
            let gap = f.norm();
            if gap <= tol || (gap <= 1e-11 * scale && gap >= best) {
                converged = true;
                break;
            }
            best = best.min(gap);
            // [ja, −jb]·(du, dv) = −f.
            let det = cross(ja, -jb);
            if det.is_nan() || det.abs() <= 0.0 {
                return Ok(Search::Lost);
            }
            let du = cross(-f, -jb) / det;
            let dv = cross(ja, -f) / det;
            let (wa, wb) = (a.domain.1 - a.domain.0, b.domain.1 - b.domain.0);
            let shrink = (0.25 * wa / du.abs()).min(0.25 * wb / dv.abs()).min(1.0);
            let (nu, nv) = (u + du * shrink, v + dv * shrink);
            let past = |l: &Leg, w: f64| (w - l.far()) * (l.far() - l.corner()) > 0.0;
            let now = (past(a, nu), past(b, nv));
            if (now.0 && pinned.0) || (now.1 && pinned.1) {
                return Ok(Search::Beyond);
            }
            pinned = now;
            (u, v) = (a.clamp(nu), b.clamp(nv));
        }
        if !converged {
            let near_far =
                |l: &Leg, w: f64| (w - l.far()).abs() <= 1e-9 * (l.domain.1 - l.domain.0);
            if near_far(a, u) || near_far(b, v) {
                return Ok(Search::Beyond);
            }
            return Ok(Search::Lost);
        }
    }
    Ok(Search::Found(u, v))
}

/// # Operations
impl Sketch {
    /// The fillet of a line and a curve or of two curves at a shared end (module
    /// `fillet_curve`); [`Sketch::fillet`] sends non-line pairs here.
    pub(super) fn fillet_curves(
        &mut self,
        first: EntityId,
        second: EntityId,
        radius: f64,
    ) -> Result<Fillet> {
        let impossible = |reason| Error::FilletImpossible {
            first,
            second,
            radius,
            reason,
        };
        let (ea, eb) = (self.entity(first)?.clone(), self.entity(second)?.clone());
        let domain = |e: &Entity| e.domain().unwrap_or((0.0, 1.0));
        let ends = |e: &Entity| -> Result<[Point2<f64>; 2]> {
            let (lo, hi) = domain(e);
            let at = |u| {
                e.point_tangent(u)
                    .map(|(p, _)| p)
                    .ok_or(Error::WrongEntityKind {
                        entity: first,
                        expected: "line, Bézier, B-spline, NURBS or Hermite curve",
                        found: e.kind_name(),
                    })
            };
            Ok([at(lo)?, at(hi)?])
        };
        let (pa, pb) = (ends(&ea)?, ends(&eb)?);
        let scale = ea
            .points()
            .iter()
            .chain(eb.points())
            .map(|p| p.coords.amax())
            .fold(radius, f64::max);
        // The corner: the closest pair of ends, which must meet.
        let mut corner = (0, 0, f64::INFINITY);
        for (i, p) in pa.iter().enumerate() {
            for (j, q) in pb.iter().enumerate() {
                let d = (p - q).norm();
                if d < corner.2 {
                    corner = (i, j, d);
                }
            }
        }
        if corner.2 > 1e-9 * scale {
            return Err(impossible("they share no end"));
        }
        let mut a = Leg {
            id: first,
            domain: domain(&ea),
            entity: ea,
            corner_at_end: corner.0 == 1,
            side: 1.0,
        };
        let mut b = Leg {
            id: second,
            domain: domain(&eb),
            entity: eb,
            corner_at_end: corner.1 == 1,
            side: 1.0,
        };
        let (ia, ib) = (a.inward()?, b.inward()?);
        if !(ia.norm() > 0.0 && ib.norm() > 0.0) {
            return Err(impossible("a tangent vanishes at the corner"));
        }
        let sine = cross(ia, ib);
        if sine.abs() <= 1e-9 {
            return Err(impossible("they are tangent at the corner"));
        }
        let theta = ia.dot(&ib).clamp(-1.0, 1.0).acos() / 2.0;
        // The centre lies towards the other leg from each.
        let normal = |l: &Leg| -> Result<Vector2<f64>> { Ok(rot90(l.jet(l.corner())?[1])) };
        a.side = normal(&a)?.dot(&ib).signum();
        b.side = normal(&b)?.dot(&ia).signum();
        let (u, v) = match feet(&a, &b, radius, theta, scale)? {
            Search::Found(u, v) => (u, v),
            Search::Beyond => {
                return Err(impossible(
                    "the radius puts a tangent point beyond an entity's far end",
                ))
            }
            Search::Lost => {
                return Err(impossible(
                    "no tangent point on the entities fits the radius",
                ))
            }
        };
        let margin = |l: &Leg, w: f64| {
            let width = l.domain.1 - l.domain.0;
            (w - l.corner()).abs() > 1e-9 * width && (w - l.far()).abs() > 1e-9 * width
        };
        if !margin(&a, u) || !margin(&b, v) {
            return Err(impossible(
                "the radius puts a tangent point at an entity's end",
            ));
        }
        let (Some((ca, _, sa)), Some((_, _, sb))) = (a.offset(u, radius)?, b.offset(v, radius)?)
        else {
            return Err(impossible("a tangent vanishes at a tangent point"));
        };
        if !(sa > 0.0 && sb > 0.0) {
            return Err(impossible(
                "the radius exceeds a curve's radius of curvature at its tangent point",
            ));
        }
        let center = Point2::from(ca);
        let (ta, tb) = (Point2::from(a.jet(u)?[0]), Point2::from(b.jet(v)?[0]));
        // The arc leaves A travelling towards the corner.
        let toward = a.jet(u)?[1] * if a.corner_at_end { 1.0 } else { -1.0 };
        let (start, end) = if rot90(ta - center).dot(&toward) > 0.0 {
            ((&a, u, ta), (&b, v, tb))
        } else {
            ((&b, v, tb), (&a, u, ta))
        };
        let angle = |p: Point2<f64>| (p - center).y.atan2((p - center).x);
        let geometry =
            camber_geom::CircularArc::try_new(center, radius, angle(start.2), angle(end.2))?;

        // What each curve leg's trim removes: the constraints at its corner end; one that
        // cannot follow the trim stops the fillet here, with nothing changed.
        let mut removed: Vec<ConstraintId> = Vec::new();
        for leg in [&a, &b] {
            if matches!(leg.entity, Entity::Line(_)) {
                continue;
            }
            let corner_end = if leg.corner_at_end {
                ArcEnd::End
            } else {
                ArcEnd::Start
            };
            for id in self.constraints_at(leg.id) {
                let c = self.constraint(id)?;
                if !c.entities().contains(&leg.id) {
                    continue;
                }
                let ends =
                    carried_ends(c, leg.id, &leg.entity).ok_or(Error::EntityConstrained {
                        entity: leg.id,
                        constraint: id,
                        operation: "fillet",
                    })?;
                if ends.contains(&corner_end) && !removed.contains(&id) {
                    removed.push(id);
                }
            }
        }
        let trimmed: Vec<(EntityId, Entity)> = [(&a, u), (&b, v)]
            .into_iter()
            .map(|(leg, w)| {
                let kept = match &leg.entity {
                    Entity::Line(ends) => {
                        let mut ends = *ends;
                        ends[usize::from(leg.corner_at_end)] = Point2::from(leg.jet(w)?[0]);
                        Entity::Line(ends)
                    }
                    e => piece(leg.id, e, w, !leg.corner_at_end)?,
                };
                Ok((leg.id, kept))
            })
            .collect::<Result<_>>()?;

        let (arc, journal) = self.transaction(|sk, j| {
            for id in &removed {
                j.remove_constraint(sk, *id)?;
            }
            for (id, kept) in &trimmed {
                j.replace_entity(sk, *id, kept.clone())?;
            }
            let arc = j.add_entity(sk, Entity::arc(&geometry))?;
            for ((leg, w, p), arc_end) in [(start, ArcEnd::Start), (end, ArcEnd::End)] {
                j.add_constraint(
                    sk,
                    Coincident {
                        a: leg.near(),
                        b: arc_end.point(arc),
                    },
                )?;
                let travel = rot90(p - center);
                let tangency: Constraint = match &leg.entity {
                    Entity::Line([l0, l1]) => ArcTangentToLine {
                        arc,
                        end: arc_end,
                        line: leg.id,
                        sense: sense(travel.dot(&(l1 - l0))),
                    }
                    .into(),
                    _ => ArcTangentToCurve {
                        arc,
                        end: arc_end,
                        curve: leg.id,
                        curve_end: if leg.corner_at_end {
                            ArcEnd::End
                        } else {
                            ArcEnd::Start
                        },
                        sense: sense(travel.dot(&leg.jet(w)?[1])),
                    }
                    .into(),
                };
                j.add_constraint(sk, tangency)?;
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
        Ok(Fillet {
            arc,
            geometry,
            added: journal.added_constraints(),
            removed,
        })
    }
}

fn sense(dot: f64) -> Sense {
    if dot > 0.0 {
        Sense::Agree
    } else {
        Sense::Oppose
    }
}
