//! Where a contact is likely to be: the target of a contact as a shape with a signed gap
//! (positive on the intended side), the parameter of a curve where that gap is least, and the
//! other starts a failed solve tries for free contact parameters.
//!
//! A solve from the contact guesses a user gave can fail because a guess is far from any
//! contact the curve can make (two contacts guessed at the same parameter, say). Before it gives
//! up, the sketch's solve tries a bounded set of other starts ([`MAX_STARTS`]): every free
//! contact at the parameter of least gap to its target (the curve's nearest approach, or its
//! deepest crossing), then, one contact at a time, spread parameters with the others at their
//! least gap. The first start that solves wins; the user's guesses are always tried first.

use camber_geom::Ellipse;
use nalgebra::{Point2, Vector2};

use crate::component::problem::ComponentProblem;
use crate::constraints::check::{ContactSpec, ContactTarget};
use crate::constraints::shared::ellipses::ellipse_gap;
use crate::constraints::shared::round_contacts::round;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::{CircleSide, Contact, LineSide, Rotation, Sense};

/// Starts tried after the given one fails, at most.
pub const MAX_STARTS: usize = 8;

/// Parameters (fractions of the domain) a contact is tried at, the others at their least gap.
const SPREAD: [f64; 3] = [0.2, 0.5, 0.8];

/// Samples of the curve per contact for the least gap.
const SAMPLES: usize = 200;

/// The fixed target of a contact and the side and orientation asked for.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Shape {
    Circle {
        center: Point2<f64>,
        radius: f64,
        outside: bool,
        counter_clockwise: bool,
    },
    Ellipse {
        ellipse: Ellipse<f64>,
        outside: bool,
        counter_clockwise: bool,
    },
    Line {
        a: Point2<f64>,
        direction: Vector2<f64>,
        left: bool,
        along: bool,
    },
}

impl Shape {
    /// The signed gap of q (positive on the intended side, length units).
    pub(crate) fn gap(&self, q: Point2<f64>) -> f64 {
        match *self {
            Shape::Circle {
                center,
                radius,
                outside,
                ..
            } => {
                let d = (q - center).norm() - radius;
                if outside {
                    d
                } else {
                    -d
                }
            }
            Shape::Ellipse {
                ref ellipse,
                outside,
                ..
            } => {
                let d = ellipse_gap(ellipse, &q);
                if outside {
                    d
                } else {
                    -d
                }
            }
            Shape::Line {
                a, direction, left, ..
            } => {
                let d = cross(direction, q - a);
                if left {
                    d
                } else {
                    -d
                }
            }
        }
    }

    /// The nearest target point to q and the target's oriented unit tangent there.
    pub(crate) fn foot(&self, q: Point2<f64>) -> (Point2<f64>, Vector2<f64>) {
        match *self {
            Shape::Circle {
                center,
                radius,
                counter_clockwise,
                ..
            } => {
                let v = q - center;
                let n = if v.norm() > 0.0 {
                    v / v.norm()
                } else {
                    Vector2::x()
                };
                let t = if counter_clockwise {
                    Vector2::new(-n.y, n.x)
                } else {
                    Vector2::new(n.y, -n.x)
                };
                (center + radius * n, t)
            }
            Shape::Ellipse {
                ref ellipse,
                counter_clockwise,
                ..
            } => {
                // The kernel's closest point (a non-finite q has none: the centre's vertex).
                let angle = ellipse.closest_point(&q).map_or(0.0, |c| c.parameter);
                let t = ellipse.derivative_at_angle(angle, 1);
                let t = if t.norm() > 0.0 {
                    t / t.norm()
                } else {
                    Vector2::x()
                };
                (
                    ellipse.point_at_angle(angle),
                    if counter_clockwise { t } else { -t },
                )
            }
            Shape::Line {
                a,
                direction,
                along,
                ..
            } => {
                let foot = a + direction * direction.dot(&(q - a));
                (foot, if along { direction } else { -direction })
            }
        }
    }
}

pub(crate) fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The parameter in [lo, hi] where `f` is least: the best of `samples` + 1 samples, refined by
/// golden section between its neighbours.
pub(crate) fn least(f: impl Fn(f64) -> f64, lo: f64, hi: f64, samples: usize) -> f64 {
    let step = (hi - lo) / samples as f64;
    let mut best = (f64::INFINITY, lo);
    for i in 0..=samples {
        let s = lo + step * i as f64;
        let v = f(s);
        if v < best.0 {
            best = (v, s);
        }
    }
    let (mut l, mut r) = ((best.1 - step).max(lo), (best.1 + step).min(hi));
    let phi = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..60 {
        let (x1, x2) = (r - phi * (r - l), l + phi * (r - l));
        if f(x1) <= f(x2) {
            r = x2;
        } else {
            l = x1;
        }
    }
    let s = 0.5 * (l + r);
    if f(s) <= best.0 {
        s
    } else {
        best.1
    }
}

impl Shape {
    /// The shape of a contact's target in the entities of `lookup`.
    ///
    /// # Errors
    /// [`Error::UnknownEntity`] for a target that is not the circle or line it should be.
    pub(crate) fn of(spec: &ContactSpec, lookup: &dyn EntityLookup) -> Result<Self> {
        Ok(match spec.target {
            ContactTarget::Circle {
                circle,
                side,
                rotation,
            } => {
                let Some((center, radius, _)) = round(lookup.lookup(circle)?) else {
                    return Err(Error::UnknownEntity { entity: circle });
                };
                Shape::Circle {
                    center,
                    radius,
                    outside: matches!(side, CircleSide::Outside),
                    counter_clockwise: matches!(rotation, Rotation::CounterClockwise),
                }
            }
            ContactTarget::Ellipse {
                ellipse,
                side,
                rotation,
            } => {
                let Some(el) = lookup.lookup(ellipse)?.as_ellipse() else {
                    return Err(Error::UnknownEntity { entity: ellipse });
                };
                Shape::Ellipse {
                    ellipse: el,
                    outside: matches!(side, CircleSide::Outside),
                    counter_clockwise: matches!(rotation, Rotation::CounterClockwise),
                }
            }
            ContactTarget::Line { line, side, sense } => {
                let Entity::Line([a, b]) = lookup.lookup(line)? else {
                    return Err(Error::UnknownEntity { entity: line });
                };
                let d = b - a;
                let n = d.norm();
                Shape::Line {
                    a: *a,
                    direction: if n > 0.0 { d / n } else { Vector2::x() },
                    left: matches!(side, LineSide::Left),
                    along: matches!(sense, Sense::Agree),
                }
            }
        })
    }
}

/// The parameter of `curve` (in `lookup`) where its signed gap to the contact's target is least.
///
/// # Errors
/// An unknown or wrong-kind entity.
pub(crate) fn least_gap(spec: &ContactSpec, lookup: &dyn EntityLookup) -> Result<f64> {
    let shape = Shape::of(spec, lookup)?;
    let e = lookup.lookup(spec.curve)?;
    let (lo, hi) = e.domain().ok_or(Error::WrongEntityKind {
        entity: spec.curve,
        expected: "curve",
        found: e.kind_name(),
    })?;
    let gap = |s: f64| {
        e.point_tangent(s)
            .map_or(f64::INFINITY, |(q, _)| shape.gap(q))
    };
    Ok(least(gap, lo, hi, SAMPLES))
}

/// The other starts for a built component's free contact parameters, each a list of (block,
/// value) to set: all at their least gap, then each in turn at the spread parameters with the
/// others at their least gap; at most [`MAX_STARTS`], without repeats. Empty when the component
/// has no free contact with a circle or line.
///
/// # Errors
/// An unknown or wrong-kind entity.
pub(crate) fn contact_starts(
    cp: &ComponentProblem,
    lookup: &dyn EntityLookup,
) -> Result<Vec<Vec<(camber_solve::BlockId, f64)>>> {
    let mut contacts = Vec::new();
    // A contact with an ellipse also owns the ellipse's parametric angle θ (its free block
    // after u): each start sets it to the angle of the ellipse point nearest C(u).
    let mut angles = Vec::new();
    for entry in &cp.checks {
        let Some(spec) = entry.check.contact() else {
            continue;
        };
        let (Contact::Free(_), Some(&block)) = (spec.u, entry.free.first()) else {
            continue;
        };
        let curve = lookup.lookup(spec.curve)?;
        let (lo, hi) = curve.domain().unwrap_or((0.0, 1.0));
        contacts.push((block, least_gap(&spec, lookup)?, lo, hi));
        if let (Shape::Ellipse { ellipse, .. }, Some(&theta)) =
            (Shape::of(&spec, lookup)?, entry.free.get(1))
        {
            angles.push((block, theta, ellipse, curve));
        }
    }
    if contacts.is_empty() {
        return Ok(Vec::new());
    }
    let with_angles = |start: Vec<(camber_solve::BlockId, f64)>| {
        let mut out = start.clone();
        for (block, theta, ellipse, curve) in &angles {
            let u = start.iter().find(|(b, _)| b == block).map(|(_, u)| *u);
            let foot = u
                .and_then(|u| curve.point_tangent(u))
                .and_then(|(q, _)| ellipse.closest_point(&q).ok());
            if let Some(foot) = foot {
                out.push((*theta, foot.parameter));
            }
        }
        out
    };
    let closest: Vec<_> = contacts.iter().map(|(b, u, _, _)| (*b, *u)).collect();
    let mut starts = vec![closest.clone()];
    'spread: for (i, (_, _, lo, hi)) in contacts.iter().enumerate() {
        for t in SPREAD {
            if starts.len() >= MAX_STARTS {
                break 'spread;
            }
            let mut start = closest.clone();
            start[i].1 = lo + t * (hi - lo);
            if !starts.contains(&start) {
                starts.push(start);
            }
        }
    }
    Ok(starts.into_iter().map(with_angles).collect())
}
