//! The constraints that hold consecutive segments of a subpath together.
//!
//! Every join gets the coincidence of the first segment's end with the next one's start. When
//! their directions of travel there meet at an angle of at most the tangent tolerance, the
//! join is smooth and also gets a G1 constraint that keeps the sense, of the existing kind
//! that fits the pair:
//!
//! | pair (either order)            | constraints                                              |
//! |--------------------------------|----------------------------------------------------------|
//! | line or Bézier, line or Bézier | `g1_join_free` (its rows include the coincidence)        |
//! | circular arc, line             | `coincident` + `arc_tangent_to_line`                     |
//! | elliptic arc, line             | `coincident` + `elliptic_arc_tangent_to_line`            |
//! | circular arc, Bézier           | `coincident` + `arc_tangent_to_curve`                    |
//! | elliptic arc, Bézier           | `coincident` + `elliptic_arc_tangent_to_curve`           |
//! | circular arc, circular arc    | `coincident` + `arc_tangent_to_arc`                      |
//! | elliptic arc with an arc; a segment closing on itself | `coincident` only, and a note in `skipped`: no kind holds that tangency |
//!
//! A join where a Bézier's end derivative vanishes (an end control point doubled) has no
//! direction to keep and gets its coincidence only. The sense of each tangency is read from
//! the imported geometry: an arc's counter-clockwise travel at its end against the line's
//! B − A, the curve's C′ or the other arc's counter-clockwise travel.

use camber_sketch::constraints::arc_tangent_to_line::ArcEnd;
use camber_sketch::constraints::{
    ArcTangentToArc, ArcTangentToCurve, ArcTangentToLine, Coincident, EllipticArcTangentToCurve,
    EllipticArcTangentToLine, G1JoinFree,
};
use camber_sketch::{Constraint, Entity, EntityId, PointRef, Sense};
use nalgebra::{Point2, Vector2};

/// A segment in the sketch: its entity and which way it runs along the path.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Placed {
    /// Its id.
    pub(crate) id: EntityId,
    /// The entity as added.
    pub(crate) entity: Entity,
    /// Whether the entity runs against the path.
    pub(crate) reversed: bool,
}

impl Placed {
    /// The entity's end (`ArcEnd::End`) or start that is the path's end (`at_end`) or start.
    fn end(&self, at_end: bool) -> ArcEnd {
        if at_end != self.reversed {
            ArcEnd::End
        } else {
            ArcEnd::Start
        }
    }

    /// Where the path enters (`at_end` false) or leaves the segment.
    pub(crate) fn path_point(&self, at_end: bool) -> Option<Point2<f64>> {
        let points = self.entity.points();
        let k = match (&self.entity, self.end(at_end)) {
            (Entity::Arc(_), ArcEnd::Start) => 1,
            (Entity::Arc(_), ArcEnd::End) => 2,
            (Entity::EllipticArc { .. }, ArcEnd::Start) => 2,
            (Entity::EllipticArc { .. }, ArcEnd::End) => 3,
            (_, ArcEnd::Start) => 0,
            (_, ArcEnd::End) => points.len().checked_sub(1)?,
        };
        points.get(k).copied()
    }

    /// The entity's own derivative at that end: C′ for lines and Béziers, the
    /// counter-clockwise tangent for arcs (not normalised).
    fn own_tangent(&self, at_end: bool) -> Vector2<f64> {
        let end = self.end(at_end);
        match &self.entity {
            Entity::Line([a, b]) => b - a,
            Entity::Bezier(c) => {
                let p = c.control_points();
                let n = p.len();
                let d = match end {
                    ArcEnd::Start if n >= 2 => p[1] - p[0],
                    ArcEnd::End if n >= 2 => p[n - 1] - p[n - 2],
                    _ => Vector2::zeros(),
                };
                d * (n.saturating_sub(1)) as f64
            }
            Entity::Arc([c, s, e]) => {
                let r = if end == ArcEnd::Start { s - c } else { e - c };
                Vector2::new(-r.y, r.x)
            }
            Entity::EllipticArc {
                points: [c, v, s, e],
                semi_axis_b,
            } => {
                let p = if end == ArcEnd::Start { s } else { e };
                ellipse_tangent(c, v, *semi_axis_b, p)
            }
            _ => Vector2::zeros(),
        }
    }

    /// The path's direction of travel there.
    fn travel(&self, at_end: bool) -> Vector2<f64> {
        let t = self.own_tangent(at_end);
        if self.reversed {
            -t
        } else {
            t
        }
    }

    fn point_ref(&self, at_end: bool) -> PointRef {
        self.end(at_end).point(self.id)
    }
}

/// The counter-clockwise tangent of the ellipse of blocks [C, V] and b at its point P:
/// −(a/b)·y′·u + (b/a)·x′·v with u = (V − C)/a, v = rot₉₀(u), x′ = (P − C)·u, y′ = (P − C)·v.
fn ellipse_tangent(c: &Point2<f64>, v: &Point2<f64>, b: f64, p: &Point2<f64>) -> Vector2<f64> {
    let w = v - c;
    let a = w.norm();
    if a <= 0.0 || b <= 0.0 {
        return Vector2::zeros();
    }
    let u = w / a;
    let n = Vector2::new(-u.y, u.x);
    let d = p - c;
    let (x, y) = (d.dot(&u), d.dot(&n));
    u * (-(a / b) * y) + n * ((b / a) * x)
}

/// What a join became: its constraints, and a note when a smooth join has no G1 kind.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Join {
    /// The constraints to add.
    pub(crate) constraints: Vec<Constraint>,
    /// Why a smooth join is held by its coincidence only.
    pub(crate) note: Option<String>,
}

fn sense(v: f64) -> Sense {
    if v >= 0.0 {
        Sense::Agree
    } else {
        Sense::Oppose
    }
}

/// The angle between two directions, radians in [0, π]; `None` when one is zero.
fn angle_between(a: &Vector2<f64>, b: &Vector2<f64>) -> Option<f64> {
    let (na, nb) = (a.norm(), b.norm());
    if !(na > 0.0 && nb > 0.0 && na.is_finite() && nb.is_finite()) {
        return None;
    }
    let (a, b) = (a / na, b / nb);
    Some((a.x * b.y - a.y * b.x).abs().atan2(a.dot(&b)))
}

/// The constraints of the join where `first` ends and `second` starts (see the module
/// documentation).
pub(crate) fn join(first: &Placed, second: &Placed, tangent_tolerance: f64) -> Join {
    let coincident: Constraint = Coincident {
        a: first.point_ref(true),
        b: second.point_ref(false),
    }
    .into();
    let angle = angle_between(&first.travel(true), &second.travel(false));
    let smooth = angle.is_some_and(|a| a <= tangent_tolerance);
    if !smooth {
        return Join {
            constraints: vec![coincident],
            note: None,
        };
    }
    let kind = |e: &Entity| match e {
        Entity::Line(_) => Kind::Line,
        Entity::Bezier(_) => Kind::Curve,
        Entity::Arc(_) => Kind::Arc,
        Entity::EllipticArc { .. } => Kind::Elliptic,
        _ => Kind::Other,
    };
    let (k1, k2) = (kind(&first.entity), kind(&second.entity));
    let same = first.id == second.id;
    // The arc, and the other segment with whether it is the second one.
    let arc_pair = |arc_first: bool| {
        if arc_first {
            (first, true, second, false)
        } else {
            (second, false, first, true)
        }
    };
    let tangency: Option<Constraint> = match (k1, k2) {
        _ if same => None,
        (Kind::Line | Kind::Curve, Kind::Line | Kind::Curve) => {
            return Join {
                constraints: vec![G1JoinFree {
                    first: first.id,
                    second: second.id,
                }
                .into()],
                note: None,
            }
        }
        (Kind::Arc, Kind::Line) | (Kind::Line, Kind::Arc) => {
            let (arc, arc_at_end, line, _) = arc_pair(k1 == Kind::Arc);
            let Entity::Line([a, b]) = line.entity else {
                return Join {
                    constraints: vec![coincident],
                    note: None,
                };
            };
            Some(
                ArcTangentToLine {
                    arc: arc.id,
                    end: arc.end(arc_at_end),
                    line: line.id,
                    sense: sense(arc.own_tangent(arc_at_end).dot(&(b - a))),
                }
                .into(),
            )
        }
        (Kind::Elliptic, Kind::Line) | (Kind::Line, Kind::Elliptic) => {
            let (arc, arc_at_end, line, _) = arc_pair(k1 == Kind::Elliptic);
            let Entity::Line([a, b]) = line.entity else {
                return Join {
                    constraints: vec![coincident],
                    note: None,
                };
            };
            Some(
                EllipticArcTangentToLine {
                    arc: arc.id,
                    end: arc.end(arc_at_end),
                    line: line.id,
                    sense: sense(arc.own_tangent(arc_at_end).dot(&(b - a))),
                }
                .into(),
            )
        }
        (Kind::Arc, Kind::Arc) => Some(
            ArcTangentToArc {
                arc: first.id,
                end: first.end(true),
                other: second.id,
                other_end: Some(second.end(false)),
                sense: sense(first.own_tangent(true).dot(&second.own_tangent(false))),
            }
            .into(),
        ),
        (Kind::Arc | Kind::Elliptic, Kind::Curve) | (Kind::Curve, Kind::Arc | Kind::Elliptic) => {
            let (arc, arc_at_end, curve, curve_at_end) = arc_pair(k2 == Kind::Curve);
            let (end, curve_end) = (arc.end(arc_at_end), curve.end(curve_at_end));
            let sense = sense(
                arc.own_tangent(arc_at_end)
                    .dot(&curve.own_tangent(curve_at_end)),
            );
            Some(if matches!(arc.entity, Entity::Arc(_)) {
                ArcTangentToCurve {
                    arc: arc.id,
                    end,
                    curve: curve.id,
                    curve_end,
                    sense,
                }
                .into()
            } else {
                EllipticArcTangentToCurve {
                    arc: arc.id,
                    end,
                    curve: curve.id,
                    curve_end,
                    sense,
                }
                .into()
            })
        }
        _ => None,
    };
    match tangency {
        Some(t) => Join {
            constraints: vec![coincident, t],
            note: None,
        },
        None => Join {
            constraints: vec![coincident],
            note: Some(if same {
                "a smooth join of a segment with itself is held by its coincidence only: no constraint kind makes a curve tangent to itself".to_string()
            } else {
                format!(
                    "a smooth join is held by its coincidence only: no constraint kind makes {} tangent to {}",
                    article(first.entity.kind_name()),
                    article(second.entity.kind_name())
                )
            }),
        },
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Line,
    Curve,
    Arc,
    Elliptic,
    Other,
}

fn article(word: &str) -> String {
    match word.chars().next() {
        Some('a' | 'e' | 'i' | 'o' | 'u') => format!("an {word}"),
        _ => format!("a {word}"),
    }
}
