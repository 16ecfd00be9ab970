//! Compiling the nonlinear constraints (contact with free parameters, circles and lines as
//! unknowns, distances, angles, the free-direction G1 joint) into residual pieces over slots,
//! and the honesty checks every solved contact must pass before anything is written back.
//!
//! A slot is a block the residual reads: an entity point, a circle radius, or a new contact
//! parameter u bounded to the curve's domain [a, b]. After a solve, each contact is checked on
//! the solved entities: the tangent keeps its recorded sense (rotation about a circle, sense
//! along a line) and does not vanish (a cusp), and the curve sampled on
//! [u − w, u + w] ∩ [a, b], w = (b − a)/5, stays on the recorded side of the target up to a
//! small penetration tolerance.

use std::collections::HashMap;
use std::sync::Arc;

use camber_solve::{BlockId, ConstraintId, DynResidual};

use crate::compile::{ETerms, EntityLookup, Piece};
use crate::constraint::{CircleSide, Constraint, Contact, LineSide, Rotation, Sense};
use crate::contact::{
    CircleContact, CurvatureMatch, CurveCurveContact, LineAngle, LineContact, OnCircle, OnCurve,
    Param, PointDistance, RadiusValue, TangentsParallel,
};
use crate::curve_eval::CurveBasis;
use crate::entity::Entity;
use crate::errors::{Error, Result};
use crate::ids::{EntityId, PointRef};

/// Samples of the crossing check on each side of a contact.
const SIDE_SAMPLES: usize = 24;

/// A block read by a nonlinear residual.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Slot {
    /// Point `index` of an entity.
    Point(EntityId, usize),
    /// The radius of a circle entity.
    Radius(EntityId),
    /// A new contact parameter starting at `u0`, bounded to [lo, hi].
    Contact { u0: f64, lo: f64, hi: f64 },
    /// A block of the problem already built (a contact parameter read by a clearance row).
    Existing(BlockId),
}

/// The parameter a check reads.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum CheckParam {
    /// A fixed value.
    Fixed(f64),
    /// The piece's slot with this index (before building).
    Slot(usize),
    /// The problem block holding u (after building).
    Block(BlockId),
}

/// What is verified on the solved entities.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Check {
    Circle {
        curve: EntityId,
        circle: EntityId,
        u: CheckParam,
        side: CircleSide,
        rotation: Rotation,
        floor: f64,
    },
    Line {
        curve: EntityId,
        line: EntityId,
        u: CheckParam,
        side: LineSide,
        sense: Sense,
        floor: f64,
    },
    Join {
        first: EntityId,
        second: EntityId,
    },
    Curves {
        first: EntityId,
        second: EntityId,
        u: CheckParam,
        v: CheckParam,
        sense: Sense,
        floors: [f64; 2],
    },
    Angle {
        first: EntityId,
        second: EntityId,
        cos: f64,
        sin: f64,
    },
}

/// The tangent speed |C′| below which a solved contact counts as a cusp: a millionth of the
/// curve's mean speed before the solve (its control-polygon length over its parameter span).
/// A solve that shrinks a curve a million times over has collapsed it, not touched anything.
fn speed_floor(e: &Entity) -> f64 {
    let length: f64 = e.points().windows(2).map(|w| (w[1] - w[0]).norm()).sum();
    let (a, b) = e.domain().unwrap_or((0.0, 1.0));
    1e-6 * length / (b - a).max(f64::MIN_POSITIVE)
}

fn kind<'a>(
    lookup: &'a impl EntityLookup,
    id: EntityId,
    expected: &'static str,
    ok: fn(&Entity) -> bool,
) -> Result<&'a Entity> {
    let e = lookup.lookup(id)?;
    if ok(e) {
        Ok(e)
    } else {
        Err(Error::WrongEntityKind {
            entity: id,
            expected,
            found: e.kind_name(),
        })
    }
}

pub(crate) fn curve_basis(
    lookup: &impl EntityLookup,
    id: EntityId,
) -> Result<(CurveBasis, Vec<Slot>)> {
    let e = kind(lookup, id, "curve", Entity::is_curve)?;
    let basis = CurveBasis::of(e).ok_or(Error::WrongEntityKind {
        entity: id,
        expected: "curve",
        found: e.kind_name(),
    })?;
    let slots = (0..e.points().len()).map(|j| Slot::Point(id, j)).collect();
    Ok((basis, slots))
}

/// The basis, slots and parameter of a contact on `curve`: at a fixed parameter, the basis
/// restricted to it and the slots of the control points it reads; at a free one, the whole
/// curve and a new slot for u bounded to the domain (the last slot).
fn curve_contact(
    lookup: &impl EntityLookup,
    curve: EntityId,
    u: Contact,
) -> Result<(CurveBasis, Vec<Slot>, Param, CheckParam)> {
    let (basis, mut slots) = curve_basis(lookup, curve)?;
    let v = u.value();
    let (lo, hi) = basis.domain();
    if !v.is_finite() {
        return Err(Error::NonFinite {
            what: "parameter",
            index: 0,
            value: v,
        });
    }
    if v < lo || v > hi {
        return Err(Error::ParameterOutsideDomain {
            entity: curve,
            value: v,
            min: lo,
            max: hi,
        });
    }
    Ok(match u {
        Contact::At(_) => {
            let (basis, points) = basis.at(v, 1);
            let slots = points.iter().map(|j| Slot::Point(curve, *j)).collect();
            (basis, slots, Param::Fixed(v), CheckParam::Fixed(v))
        }
        Contact::Free(_) => {
            slots.push(Slot::Contact { u0: v, lo, hi });
            let k = slots.len() - 1;
            (basis, slots, Param::Block, CheckParam::Slot(k))
        }
    })
}

/// The single block a point reference denotes.
pub(crate) fn single_block(lookup: &impl EntityLookup, r: PointRef) -> Result<(EntityId, usize)> {
    let e = lookup.lookup(r.entity())?;
    match e.resolve(r)?.as_slice() {
        [(j, c)] if (c - 1.0).abs() <= 0.0 => Ok((r.entity(), *j)),
        _ => Err(Error::WrongEntityKind {
            entity: r.entity(),
            expected: "a single point block (point, control point or clamped end)",
            found: e.kind_name(),
        }),
    }
}

fn positive(what: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::NotPositive { what, value })
    }
}

fn is_line(e: &Entity) -> bool {
    matches!(e, Entity::Line(_))
}

fn is_circle(e: &Entity) -> bool {
    matches!(e, Entity::Circle { .. })
}

fn general(
    name: &'static str,
    residual: impl DynResidual + 'static,
    slots: Vec<Slot>,
    check: Option<Check>,
) -> Piece {
    Piece::General {
        name,
        residual: Arc::new(residual),
        slots,
        check,
    }
}

fn distinct(a: EntityId, b: EntityId) -> Result<()> {
    if a == b {
        Err(Error::SameEntity { entity: a })
    } else {
        Ok(())
    }
}

/// Compiles a nonlinear constraint; `None` for the constraints [`crate::compile`] handles.
pub(crate) fn compile_general(
    lookup: &impl EntityLookup,
    c: &Constraint,
    out: &mut smallvec::SmallVec<[Piece; 3]>,
) -> Result<bool> {
    let name = c.kind_name();
    match c {
        Constraint::PointOnCurve { point, curve, u } => {
            let (basis, mut slots, param, _) = curve_contact(lookup, *curve, *u)?;
            let (e, j) = single_block(lookup, *point)?;
            distinct(e, *curve)?;
            slots.push(Slot::Point(e, j));
            out.push(general(name, OnCurve::new(basis, param), slots, None));
        }
        Constraint::TangentToLine {
            curve,
            line,
            u,
            side,
            sense,
        } => {
            distinct(*curve, *line)?;
            kind(lookup, *line, "line", is_line)?;
            let (basis, mut slots, param, check_u) = curve_contact(lookup, *curve, *u)?;
            slots.extend([Slot::Point(*line, 0), Slot::Point(*line, 1)]);
            let check = Check::Line {
                curve: *curve,
                line: *line,
                u: check_u,
                side: *side,
                sense: *sense,
                floor: speed_floor(lookup.lookup(*curve)?),
            };
            out.push(general(
                name,
                LineContact::new(basis, param),
                slots,
                Some(check),
            ));
        }
        Constraint::TangentToCircle {
            curve,
            circle,
            u,
            side,
            rotation,
        } => {
            kind(lookup, *circle, "circle", is_circle)?;
            let (basis, mut slots, param, check_u) = curve_contact(lookup, *curve, *u)?;
            slots.extend([Slot::Point(*circle, 0), Slot::Radius(*circle)]);
            let check = Check::Circle {
                curve: *curve,
                circle: *circle,
                u: check_u,
                side: *side,
                rotation: *rotation,
                floor: speed_floor(lookup.lookup(*curve)?),
            };
            out.push(general(
                name,
                CircleContact::new(basis, param, *rotation == Rotation::Clockwise),
                slots,
                Some(check),
            ));
        }
        Constraint::PointOnCircle { point, circle } => {
            kind(lookup, *circle, "circle", is_circle)?;
            let (e, j) = single_block(lookup, *point)?;
            distinct(e, *circle)?;
            let slots = vec![
                Slot::Point(e, j),
                Slot::Point(*circle, 0),
                Slot::Radius(*circle),
            ];
            out.push(general(name, OnCircle, slots, None));
        }
        Constraint::Radius { circle, radius } => {
            kind(lookup, *circle, "circle", is_circle)?;
            let r = positive("radius", *radius)?;
            out.push(general(
                name,
                RadiusValue::new(r),
                vec![Slot::Radius(*circle)],
                None,
            ));
        }
        Constraint::Distance { a, b, distance } => {
            let d = positive("distance", *distance)?;
            let (ea, ja) = single_block(lookup, *a)?;
            let (eb, jb) = single_block(lookup, *b)?;
            if (ea, ja) == (eb, jb) {
                return Err(Error::SameEntity { entity: ea });
            }
            let slots = vec![Slot::Point(ea, ja), Slot::Point(eb, jb)];
            out.push(general(name, PointDistance::new(d), slots, None));
        }
        Constraint::Parallel(first, second)
        | Constraint::Perpendicular(first, second)
        | Constraint::Angle { first, second, .. } => {
            distinct(*first, *second)?;
            kind(lookup, *first, "line", is_line)?;
            kind(lookup, *second, "line", is_line)?;
            let angle = match c {
                Constraint::Perpendicular(..) => std::f64::consts::FRAC_PI_2,
                Constraint::Angle { angle, .. } => {
                    if !angle.is_finite() {
                        return Err(Error::NonFinite {
                            what: "angle",
                            index: 0,
                            value: *angle,
                        });
                    }
                    *angle
                }
                _ => 0.0,
            };
            let slots = vec![
                Slot::Point(*first, 0),
                Slot::Point(*first, 1),
                Slot::Point(*second, 0),
                Slot::Point(*second, 1),
            ];
            let check = matches!(c, Constraint::Angle { .. }).then_some(Check::Angle {
                first: *first,
                second: *second,
                cos: angle.cos(),
                sin: angle.sin(),
            });
            out.push(general(name, LineAngle::new(name, angle), slots, check));
        }
        Constraint::G1JoinFree { first, second } | Constraint::G2Join { first, second } => {
            distinct(*first, *second)?;
            // The joint's tangents (and curvatures) read only the end spans' control points.
            let (full1, _) = curve_basis(lookup, *first)?;
            let (full2, _) = curve_basis(lookup, *second)?;
            let (u1, u2) = (full1.domain().1, full2.domain().0);
            let ends = |order: usize| {
                let ((b1, r1), (b2, r2)) = (full1.at(u1, order), full2.at(u2, order));
                let slots: Vec<Slot> = r1
                    .iter()
                    .map(|j| Slot::Point(*first, *j))
                    .chain(r2.iter().map(|j| Slot::Point(*second, *j)))
                    .collect();
                (b1, b2, slots)
            };
            let mut joint = ETerms::new();
            for (r, sign) in [
                (PointRef::End(*first), 1.0),
                (PointRef::Start(*second), -1.0),
            ] {
                for (j, k) in lookup.lookup(r.entity())?.resolve(r)? {
                    joint.push((r.entity(), j, sign * k));
                }
            }
            out.push(Piece::Combination {
                name,
                terms: joint,
                target: [0.0; 2],
            });
            let check = Check::Join {
                first: *first,
                second: *second,
            };
            if matches!(c, Constraint::G2Join { .. }) {
                let (b1, b2, slots) = ends(2);
                out.push(general(
                    name,
                    CurvatureMatch::new((b1, u1), (b2, u2)),
                    slots,
                    None,
                ));
            }
            let (b1, b2, slots) = ends(1);
            out.push(general(
                name,
                TangentsParallel::new((b1, u1), (b2, u2)),
                slots,
                Some(check),
            ));
        }
        Constraint::CurveCurveTangent {
            first,
            u,
            second,
            v,
            sense,
        } => {
            distinct(*first, *second)?;
            let (b1, mut slots, p1, c1) = curve_contact(lookup, *first, *u)?;
            let (b2, s2, p2, c2) = curve_contact(lookup, *second, *v)?;
            // The second curve's contact slot moves behind the first curve's slots.
            let c2 = match c2 {
                CheckParam::Slot(k) => CheckParam::Slot(k + slots.len()),
                other => other,
            };
            slots.extend(s2);
            let check = Check::Curves {
                first: *first,
                second: *second,
                u: c1,
                v: c2,
                sense: *sense,
                floors: [
                    speed_floor(lookup.lookup(*first)?),
                    speed_floor(lookup.lookup(*second)?),
                ],
            };
            out.push(general(
                name,
                CurveCurveContact::new((b1, p1), (b2, p2)),
                slots,
                Some(check),
            ));
        }
        _ => return Ok(false),
    }
    Ok(true)
}

/// C(s) and C′(s) of a solved curve entity (s clamped to its domain).
pub(crate) fn point_tangent(e: &Entity, id: EntityId, s: f64) -> Result<([f64; 2], [f64; 2])> {
    let (a, b) = e.domain().unwrap_or((0.0, 1.0));
    let (p, t) = e
        .point_tangent(s.clamp(a, b))
        .ok_or(Error::WrongEntityKind {
            entity: id,
            expected: "curve",
            found: e.kind_name(),
        })?;
    Ok(([p.x, p.y], [t.x, t.y]))
}

/// The half-width w = (b − a)/5 of the window beside a contact on the domain [a, b], where the
/// crossing check samples and a clearance row looks.
pub(crate) fn side_width((a, b): (f64, f64)) -> f64 {
    (b - a) / 5.0
}

/// Parameters sampled on [u − w, u + w] ∩ [a, b].
fn window(e: &Entity, u: f64) -> impl Iterator<Item = f64> {
    let (a, b) = e.domain().unwrap_or((0.0, 1.0));
    let w = side_width((a, b));
    let (lo, hi) = ((u - w).max(a), (u + w).min(b));
    let n = 2 * SIDE_SAMPLES;
    (0..=n).map(move |i| lo + (hi - lo) * i as f64 / n as f64)
}

/// The deepest sample of the window around u where the signed clearance `gap` (positive on
/// the intended side) is below −`tolerance`, as [`Error::ContactCrossed`].
fn deepest(
    owner: ConstraintId,
    e: &Entity,
    curve: EntityId,
    u: f64,
    tolerance: f64,
    gap: impl Fn([f64; 2]) -> f64,
) -> Result<()> {
    let mut worst: Option<(f64, f64)> = None;
    if !e.is_curve() {
        return Err(Error::WrongEntityKind {
            entity: curve,
            expected: "curve",
            found: e.kind_name(),
        });
    }
    for s in window(e, u) {
        // Samples lie in the domain; a kernel error (none expected) counts as a crossing.
        let d = e
            .point_tangent(s)
            .map_or(f64::NEG_INFINITY, |(q, _)| gap([q.x, q.y]));
        if d < -tolerance && worst.is_none_or(|(_, w)| d < w) {
            worst = Some((s, d));
        }
    }
    match worst {
        Some((parameter, d)) => Err(Error::ContactCrossed {
            constraint: owner,
            parameter,
            depth: -d,
        }),
        None => Ok(()),
    }
}

fn get<'a>(solved: &HashMap<EntityId, &'a Entity>, id: EntityId) -> Result<&'a Entity> {
    solved
        .get(&id)
        .copied()
        .ok_or(Error::UnknownEntity { entity: id })
}

impl Check {
    /// Verifies the check on the solved entities, with `u` the solved contact parameter and
    /// `tolerance` the allowed penetration (length units).
    pub(crate) fn verify(
        &self,
        owner: ConstraintId,
        solved: &HashMap<EntityId, &Entity>,
        param: &dyn Fn(CheckParam) -> Result<f64>,
        tolerance: f64,
    ) -> Result<()> {
        let flipped = |dot: f64| -> Result<()> {
            if dot > 0.0 {
                Ok(())
            } else {
                Err(Error::OrientationFlipped {
                    constraint: owner,
                    dot,
                })
            }
        };
        match *self {
            Check::Circle {
                curve,
                circle,
                side,
                rotation,
                u,
                floor,
            } => {
                let u = param(u)?;
                let e = get(solved, curve)?;
                let Entity::Circle { center, radius } = get(solved, circle)? else {
                    return Err(Error::UnknownEntity { entity: circle });
                };
                let (p, t) = point_tangent(e, curve, u)?;
                let speed = t[0].hypot(t[1]);
                if speed.is_nan() || speed <= floor {
                    return Err(Error::Cusp {
                        constraint: owner,
                        speed,
                    });
                }
                let turn = (p[0] - center.x) * t[1] - (p[1] - center.y) * t[0];
                flipped(match rotation {
                    Rotation::CounterClockwise => turn,
                    Rotation::Clockwise => -turn,
                })?;
                let sign = match side {
                    CircleSide::Outside => 1.0,
                    CircleSide::Inside => -1.0,
                };
                deepest(owner, e, curve, u, tolerance, |q| {
                    sign * ((q[0] - center.x).hypot(q[1] - center.y) - radius)
                })?;
            }
            Check::Line {
                curve,
                line,
                side,
                sense,
                u,
                floor,
            } => {
                let u = param(u)?;
                let e = get(solved, curve)?;
                let Entity::Line([a, b]) = get(solved, line)? else {
                    return Err(Error::UnknownEntity { entity: line });
                };
                let d = [b.x - a.x, b.y - a.y];
                let len = d[0].hypot(d[1]);
                let (_, t) = point_tangent(e, curve, u)?;
                let speed = t[0].hypot(t[1]);
                if speed.is_nan() || speed <= floor {
                    return Err(Error::Cusp {
                        constraint: owner,
                        speed,
                    });
                }
                flipped(sense.sign() * (t[0] * d[0] + t[1] * d[1]))?;
                let sign = match side {
                    LineSide::Left => 1.0,
                    LineSide::Right => -1.0,
                };
                deepest(owner, e, curve, u, tolerance, |q| {
                    sign * (d[0] * (q[1] - a.y) - d[1] * (q[0] - a.x)) / len
                })?;
            }
            Check::Curves {
                first,
                second,
                u,
                v,
                sense,
                floors,
            } => {
                let (u, v) = (param(u)?, param(v)?);
                let (_, t1) = point_tangent(get(solved, first)?, first, u)?;
                let (_, t2) = point_tangent(get(solved, second)?, second, v)?;
                let (s1, s2) = (t1[0].hypot(t1[1]), t2[0].hypot(t2[1]));
                if s1.is_nan() || s2.is_nan() || s1 <= floors[0] || s2 <= floors[1] {
                    return Err(Error::Cusp {
                        constraint: owner,
                        speed: s1.min(s2),
                    });
                }
                flipped(sense.sign() * (t1[0] * t2[0] + t1[1] * t2[1]))?;
            }
            Check::Join { first, second } => {
                let (e1, e2) = (get(solved, first)?, get(solved, second)?);
                let (b1, a2) = (
                    e1.domain().unwrap_or((0.0, 1.0)).1,
                    e2.domain().unwrap_or((0.0, 1.0)).0,
                );
                let (_, t1) = point_tangent(e1, first, b1)?;
                let (_, t2) = point_tangent(e2, second, a2)?;
                flipped(t1[0] * t2[0] + t1[1] * t2[1])?;
            }
            Check::Angle {
                first,
                second,
                cos,
                sin,
            } => {
                let (Entity::Line([a1, b1]), Entity::Line([a2, b2])) =
                    (get(solved, first)?, get(solved, second)?)
                else {
                    return Err(Error::UnknownEntity { entity: first });
                };
                let (d1, d2) = (b1 - a1, b2 - a2);
                let (dot, crs) = (d1.dot(&d2), d1.x * d2.y - d1.y * d2.x);
                flipped(dot * cos + crs * sin)?;
            }
        }
        Ok(())
    }

    /// The check with its contact slot replaced by the problem block `slots[k]`.
    pub(crate) fn resolved(mut self, slots: &[Option<BlockId>]) -> Self {
        let fix = |u: &mut CheckParam| {
            if let CheckParam::Slot(k) = *u {
                if let Some(Some(b)) = slots.get(k) {
                    *u = CheckParam::Block(*b);
                }
            }
        };
        match &mut self {
            Check::Circle { u, .. } | Check::Line { u, .. } => fix(u),
            Check::Curves { u, v, .. } => {
                fix(u);
                fix(v);
            }
            Check::Join { .. } | Check::Angle { .. } => {}
        }
        self
    }
}
