//! The file form of a sketch's frame and entities: serde types that mirror entities with
//! snake-case tags and named fields, and the conversions both ways. Constraints are read and
//! written in their kinds' own forms ([`crate::constraints`]), one JSON object each.

use camber_geom::{
    BSplineCurve2, BezierCurve2, CircularArc, Ellipse, EllipticArc, KnotVector, NurbsCurve2,
};
use nalgebra::{Point2, Vector2};
use serde::{Deserialize, Serialize};
use serde_json::Value;

use crate::ground::ellipse_blocks::frame_angle;
use crate::ground::entity::Entity;
use crate::ground::hermite_chain::{HermiteChain, Join};

pub(super) type Xy = [f64; 2];

fn pt(p: Xy) -> Point2<f64> {
    Point2::new(p[0], p[1])
}

/// Whether `x ≤ tol`; false for NaN, so a comparison that cannot be made refuses.
fn within(x: f64, tol: f64) -> bool {
    x <= tol
}

fn vec(v: Xy) -> Vector2<f64> {
    Vector2::new(v[0], v[1])
}

fn xy_p(p: &Point2<f64>) -> Xy {
    [p.x, p.y]
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSketch {
    pub(super) version: u64,
    /// Named parameters (crate::parameters).
    #[serde(default)]
    pub(super) parameters: std::collections::BTreeMap<String, f64>,
    #[serde(default)]
    pub(super) entities: Vec<Value>,
    #[serde(default)]
    pub(super) constraints: Vec<Value>,
}

#[derive(Serialize, Deserialize)]
pub(super) struct RawEntity {
    pub(super) id: u64,
    /// The entity's tag (`Sketch::set_tag`), written only when there is one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) tag: Option<String>,
    #[serde(flatten)]
    pub(super) shape: RawShape,
}

/// The same shapes keyed by kind (`{"line": {"from": …, "to": …}}`): loading reads an
/// entity's fields through this form, so that an error's JSON path reaches inside the entity
/// (`entities[0].control_points[1]`), which an internally tagged enum cannot report.
#[derive(Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub(super) enum KeyedShape {
    Point {
        at: Xy,
    },
    Line {
        from: Xy,
        to: Xy,
    },
    Circle {
        center: Xy,
        radius: f64,
    },
    Arc {
        center: Xy,
        #[serde(default)]
        radius: Option<f64>,
        #[serde(default)]
        start_angle: Option<f64>,
        #[serde(default)]
        end_angle: Option<f64>,
        #[serde(default)]
        start: Option<Xy>,
        #[serde(default)]
        end: Option<Xy>,
    },
    Ellipse {
        center: Xy,
        #[serde(default)]
        semi_axis_a: Option<f64>,
        semi_axis_b: f64,
        #[serde(default)]
        rotation: Option<f64>,
        #[serde(default)]
        vertex: Option<Xy>,
    },
    EllipticArc {
        center: Xy,
        #[serde(default)]
        semi_axis_a: Option<f64>,
        semi_axis_b: f64,
        #[serde(default)]
        rotation: Option<f64>,
        #[serde(default)]
        start_angle: Option<f64>,
        #[serde(default)]
        end_angle: Option<f64>,
        #[serde(default)]
        vertex: Option<Xy>,
        #[serde(default)]
        start: Option<Xy>,
        #[serde(default)]
        end: Option<Xy>,
    },
    Bezier {
        control_points: Vec<Xy>,
    },
    Bspline {
        degree: usize,
        knots: Vec<f64>,
        control_points: Vec<Xy>,
    },
    Nurbs {
        degree: usize,
        knots: Vec<f64>,
        control_points: Vec<Xy>,
        weights: Vec<f64>,
    },
    Hermite {
        p0: Xy,
        p1: Xy,
        t0: Xy,
        t1: Xy,
    },
    Composite {
        nodes: Vec<Xy>,
        tangents: Vec<Xy>,
        #[serde(default)]
        joins: Vec<Join>,
    },
}

impl From<KeyedShape> for RawShape {
    fn from(k: KeyedShape) -> Self {
        match k {
            KeyedShape::Point { at } => RawShape::Point { at },
            KeyedShape::Line { from, to } => RawShape::Line { from, to },
            KeyedShape::Circle { center, radius } => RawShape::Circle { center, radius },
            KeyedShape::Arc {
                center,
                radius,
                start_angle,
                end_angle,
                start,
                end,
            } => RawShape::Arc {
                center,
                radius,
                start_angle,
                end_angle,
                start,
                end,
            },
            KeyedShape::Ellipse {
                center,
                semi_axis_a,
                semi_axis_b,
                rotation,
                vertex,
            } => RawShape::Ellipse {
                center,
                semi_axis_a,
                semi_axis_b,
                rotation,
                vertex,
            },
            KeyedShape::EllipticArc {
                center,
                semi_axis_a,
                semi_axis_b,
                rotation,
                start_angle,
                end_angle,
                vertex,
                start,
                end,
            } => RawShape::EllipticArc {
                center,
                semi_axis_a,
                semi_axis_b,
                rotation,
                start_angle,
                end_angle,
                vertex,
                start,
                end,
            },
            KeyedShape::Bezier { control_points } => RawShape::Bezier { control_points },
            KeyedShape::Bspline {
                degree,
                knots,
                control_points,
            } => RawShape::Bspline {
                degree,
                knots,
                control_points,
            },
            KeyedShape::Nurbs {
                degree,
                knots,
                control_points,
                weights,
            } => RawShape::Nurbs {
                degree,
                knots,
                control_points,
                weights,
            },
            KeyedShape::Hermite { p0, p1, t0, t1 } => RawShape::Hermite { p0, p1, t0, t1 },
            KeyedShape::Composite {
                nodes,
                tangents,
                joins,
            } => RawShape::Composite {
                nodes,
                tangents,
                joins,
            },
        }
    }
}

#[derive(Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub(super) enum RawShape {
    Point {
        at: Xy,
    },
    Line {
        from: Xy,
        to: Xy,
    },
    Circle {
        center: Xy,
        radius: f64,
    },
    /// By radius and angles (the author's form), by its end points (exact), or both (as
    /// saved): [`RawShape::arc_form_problem`] says which are complete and agree.
    Arc {
        center: Xy,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        radius: Option<f64>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        start_angle: Option<f64>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        end_angle: Option<f64>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        start: Option<Xy>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        end: Option<Xy>,
    },
    /// By semi-axis a and rotation (and, for an arc, its angles), by its points (the a-axis
    /// vertex, and the arc's ends: exact), or both (as saved): see
    /// [`RawShape::ellipse_form_problem`].
    Ellipse {
        center: Xy,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        semi_axis_a: Option<f64>,
        semi_axis_b: f64,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        rotation: Option<f64>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        vertex: Option<Xy>,
    },
    EllipticArc {
        center: Xy,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        semi_axis_a: Option<f64>,
        semi_axis_b: f64,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        rotation: Option<f64>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        start_angle: Option<f64>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        end_angle: Option<f64>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        vertex: Option<Xy>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        start: Option<Xy>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        end: Option<Xy>,
    },
    Bezier {
        control_points: Vec<Xy>,
    },
    Bspline {
        degree: usize,
        knots: Vec<f64>,
        control_points: Vec<Xy>,
    },
    Nurbs {
        degree: usize,
        knots: Vec<f64>,
        control_points: Vec<Xy>,
        weights: Vec<f64>,
    },
    Hermite {
        p0: Xy,
        p1: Xy,
        t0: Xy,
        t1: Xy,
    },
    Composite {
        nodes: Vec<Xy>,
        tangents: Vec<Xy>,
        #[serde(default)]
        joins: Vec<Join>,
    },
}

impl RawShape {
    pub(super) fn kind(&self) -> &'static str {
        match self {
            RawShape::Point { .. } => "point",
            RawShape::Line { .. } => "line",
            RawShape::Circle { .. } => "circle",
            RawShape::Arc { .. } => "arc",
            RawShape::Ellipse { .. } => "ellipse",
            RawShape::EllipticArc { .. } => "elliptic_arc",
            RawShape::Bezier { .. } => "bezier",
            RawShape::Bspline { .. } => "bspline",
            RawShape::Nurbs { .. } => "nurbs",
            RawShape::Hermite { .. } => "hermite",
            RawShape::Composite { .. } => "composite",
        }
    }

    /// For an arc: the field and the reason when its form is incomplete (neither the radius
    /// and both angles nor both end points) or its two forms disagree (the radius against
    /// |start − center|, an angle against the direction of its end point from the centre, each
    /// within 10⁻⁹·max(1, r) as a distance). `None` for every other shape.
    pub(super) fn arc_form_problem(&self) -> Option<(&'static str, String)> {
        let RawShape::Arc {
            center,
            radius,
            start_angle,
            end_angle,
            start,
            end,
        } = self
        else {
            return None;
        };
        let angles = (radius, start_angle, end_angle);
        let points = match (start, end) {
            (Some(s), Some(e)) => (pt(*s), pt(*e)),
            (Some(_), None) => {
                return Some((
                    "end",
                    "the arc gives its start point but not its end point".into(),
                ))
            }
            (None, Some(_)) => {
                return Some((
                    "start",
                    "the arc gives its end point but not its start point".into(),
                ))
            }
            (None, None) => {
                return match angles {
                    (Some(_), Some(_), Some(_)) => None,
                    (None, ..) => Some((
                        "radius",
                        "missing field `radius` (or give `start` and `end` points)".into(),
                    )),
                    (_, None, _) => Some((
                        "start_angle",
                        "missing field `start_angle` (or give `start` and `end` points)".into(),
                    )),
                    (.., None) => Some((
                        "end_angle",
                        "missing field `end_angle` (or give `start` and `end` points)".into(),
                    )),
                };
            }
        };
        let c = pt(*center);
        let (vs, ve) = (points.0 - c, points.1 - c);
        let r = vs.norm();
        let tol = 1e-9 * r.max(1.0);
        if let Some(given) = radius {
            if !within((given - r).abs(), tol) {
                return Some(("radius", format!("radius {given} disagrees with the distance {r} of the start point from the centre")));
            }
        }
        for (field, given, v) in [
            ("start_angle", start_angle, vs),
            ("end_angle", end_angle, ve),
        ] {
            if let Some(a) = given {
                let off = (a - v.y.atan2(v.x) + std::f64::consts::PI)
                    .rem_euclid(std::f64::consts::TAU)
                    - std::f64::consts::PI;
                if !within(off.abs() * v.norm(), tol) {
                    return Some((field, format!("{field} {a} disagrees with the direction of the arc's {} point from the centre", if field == "start_angle" { "start" } else { "end" })));
                }
            }
        }
        None
    }

    /// For an ellipse or an elliptic arc: the field and the reason when neither form is
    /// complete (the numbers: semi-axis a, rotation and, for an arc, both angles; the points:
    /// the a-axis vertex and, for an arc, both ends) or when given numbers disagree with the
    /// points (a against |vertex − center|, the rotation against the vertex's direction, an
    /// angle against the parametric angle of its end point, each within 10⁻⁹·max(1, a, b) as a
    /// distance). `None` for every other shape.
    pub(super) fn ellipse_form_problem(&self) -> Option<(&'static str, String)> {
        let (center, a, b, rotation, angles, vertex, ends) = match self {
            RawShape::Ellipse {
                center,
                semi_axis_a,
                semi_axis_b,
                rotation,
                vertex,
            } => (
                center,
                semi_axis_a,
                *semi_axis_b,
                rotation,
                None,
                vertex,
                None,
            ),
            RawShape::EllipticArc {
                center,
                semi_axis_a,
                semi_axis_b,
                rotation,
                start_angle,
                end_angle,
                vertex,
                start,
                end,
            } => (
                center,
                semi_axis_a,
                *semi_axis_b,
                rotation,
                Some([("start_angle", start_angle), ("end_angle", end_angle)]),
                vertex,
                Some([("start", start), ("end", end)]),
            ),
            _ => return None,
        };
        let given_points = [("vertex", vertex)]
            .into_iter()
            .chain(ends.into_iter().flatten())
            .collect::<Vec<_>>();
        let missing_point = given_points
            .iter()
            .find(|(_, p)| p.is_none())
            .map(|(f, _)| *f);
        let any_point = given_points.iter().any(|(_, p)| p.is_some());
        let numbers = [("semi_axis_a", a), ("rotation", rotation)]
            .into_iter()
            .chain(angles.into_iter().flatten())
            .collect::<Vec<_>>();
        let Some(v) = vertex.filter(|_| missing_point.is_none()) else {
            if let (true, Some(field)) = (any_point, missing_point) {
                return Some((
                    field,
                    format!("missing field `{field}`: give every point of the point form or none"),
                ));
            }
            return numbers.iter().find(|(_, x)| x.is_none()).map(|(field, _)| {
                (
                    *field,
                    format!(
                        "missing field `{field}` (or give the points: `vertex`{})",
                        if ends.is_some() {
                            ", `start` and `end`"
                        } else {
                            ""
                        }
                    ),
                )
            });
        };
        let (c, v) = (pt(*center), pt(v));
        let w = v - c;
        let a_points = w.norm();
        let tol = 1e-9 * a_points.max(b.abs()).max(1.0);
        if let Some(given) = a {
            if !within((given - a_points).abs(), tol) {
                return Some(("semi_axis_a", format!("semi_axis_a {given} disagrees with the distance {a_points} of the vertex from the centre")));
            }
        }
        let turn = |x: f64| {
            (x + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI
        };
        if let Some(given) = rotation {
            if !within(turn(given - w.y.atan2(w.x)).abs() * a_points, tol) {
                return Some(("rotation", format!("rotation {given} disagrees with the direction of the vertex from the centre")));
            }
        }
        if let (Some(angles), Some(ends)) = (angles, ends) {
            for ((field, given), (_, point)) in angles.into_iter().zip(ends) {
                if let (Some(phi), Some(p)) = (given, point) {
                    let at = frame_angle(&c, &v, b, &pt(*p));
                    if !within(turn(phi - at).abs() * a_points.max(b.abs()), tol) {
                        return Some((field, format!("{field} {phi} disagrees with the parametric angle {at} of the arc's {} point", if field == "start_angle" { "start" } else { "end" })));
                    }
                }
            }
        }
        None
    }

    pub(super) fn into_entity(self) -> crate::ground::errors::Result<Entity> {
        let pts = |v: Vec<Xy>| v.into_iter().map(pt).collect::<Vec<_>>();
        Ok(match self {
            RawShape::Point { at } => Entity::Point(pt(at)),
            RawShape::Line { from, to } => Entity::Line([pt(from), pt(to)]),
            RawShape::Circle { center, radius } => Entity::Circle {
                center: pt(center),
                radius,
            },
            // The end points, when given, are the arc exactly (checked against the radius and
            // angles by `arc_form_problem`); a missing number is refused as not finite.
            RawShape::Arc {
                center,
                start: Some(start),
                end: Some(end),
                ..
            } => Entity::Arc([pt(center), pt(start), pt(end)]),
            RawShape::Arc {
                center,
                radius,
                start_angle,
                end_angle,
                ..
            } => Entity::arc(&CircularArc::try_new(
                pt(center),
                radius.unwrap_or(f64::NAN),
                start_angle.unwrap_or(f64::NAN),
                end_angle.unwrap_or(f64::NAN),
            )?),
            // The points, when given, are the entity exactly (checked against the numbers by
            // `ellipse_form_problem`); a missing number is refused as not finite.
            RawShape::Ellipse {
                center,
                semi_axis_b,
                vertex: Some(v),
                ..
            } => Entity::Ellipse {
                points: [pt(center), pt(v)],
                semi_axis_b,
            },
            RawShape::Ellipse {
                center,
                semi_axis_a,
                semi_axis_b,
                rotation,
                ..
            } => Entity::ellipse(&Ellipse::try_new(
                pt(center),
                semi_axis_a.unwrap_or(f64::NAN),
                semi_axis_b,
                rotation.unwrap_or(f64::NAN),
            )?),
            RawShape::EllipticArc {
                center,
                semi_axis_b,
                vertex: Some(v),
                start: Some(p),
                end: Some(q),
                ..
            } => Entity::EllipticArc {
                points: [pt(center), pt(v), pt(p), pt(q)],
                semi_axis_b,
            },
            RawShape::EllipticArc {
                center,
                semi_axis_a,
                semi_axis_b,
                rotation,
                start_angle,
                end_angle,
                ..
            } => Entity::elliptic_arc(&EllipticArc::try_new(
                pt(center),
                semi_axis_a.unwrap_or(f64::NAN),
                semi_axis_b,
                rotation.unwrap_or(f64::NAN),
                start_angle.unwrap_or(f64::NAN),
                end_angle.unwrap_or(f64::NAN),
            )?),
            RawShape::Bezier { control_points } => {
                Entity::Bezier(BezierCurve2::try_new(pts(control_points))?)
            }
            RawShape::Bspline {
                degree,
                knots,
                control_points,
            } => Entity::BSpline(BSplineCurve2::try_new(
                degree,
                KnotVector::try_new(knots)?,
                pts(control_points),
            )?),
            RawShape::Nurbs {
                degree,
                knots,
                control_points,
                weights,
            } => Entity::Nurbs(NurbsCurve2::try_new(
                degree,
                KnotVector::try_new(knots)?,
                pts(control_points),
                weights,
            )?),
            RawShape::Hermite { p0, p1, t0, t1 } => {
                Entity::Hermite(HermiteChain::single(pt(p0), pt(p1), vec(t0), vec(t1))?)
            }
            RawShape::Composite {
                nodes,
                tangents,
                joins,
            } => Entity::Composite(HermiteChain::try_new(
                pts(nodes),
                tangents.into_iter().map(vec).collect(),
                joins,
            )?),
        })
    }

    pub(super) fn from_entity(e: &Entity) -> Self {
        let pts = |v: &[Point2<f64>]| v.iter().map(xy_p).collect();
        match e {
            Entity::Point(p) => RawShape::Point { at: xy_p(p) },
            Entity::Line([a, b]) => RawShape::Line {
                from: xy_p(a),
                to: xy_p(b),
            },
            Entity::Circle { center, radius } => RawShape::Circle {
                center: xy_p(center),
                radius: *radius,
            },
            Entity::Arc([c, s, e]) => {
                // The blocks' arc for a reader: radius |S − C|, angles in (−π, π] (atan2), so
                // a loaded file's angles come back reduced; and the blocks themselves, so that
                // saving and loading is the identity (angles and a radius would round).
                let (vs, ve) = (s - c, e - c);
                RawShape::Arc {
                    center: xy_p(c),
                    radius: Some(vs.norm()),
                    start_angle: Some(vs.y.atan2(vs.x)),
                    end_angle: Some(ve.y.atan2(ve.x)),
                    start: Some(xy_p(s)),
                    end: Some(xy_p(e)),
                }
            }
            Entity::Ellipse {
                points: [c, v],
                semi_axis_b,
            } => {
                // The blocks' ellipse: a = |V − C|, rotation atan2(V − C) ∈ (−π, π].
                let w = v - c;
                RawShape::Ellipse {
                    center: xy_p(c),
                    semi_axis_a: Some(w.norm()),
                    semi_axis_b: *semi_axis_b,
                    rotation: Some(w.y.atan2(w.x)),
                    vertex: Some(xy_p(v)),
                }
            }
            Entity::EllipticArc {
                points: [c, v, s, e],
                semi_axis_b,
            } => {
                // The ends' parametric angles, atan2 ∈ (−π, π], for a reader; and the points
                // themselves, so that saving and loading is the identity.
                let w = v - c;
                RawShape::EllipticArc {
                    center: xy_p(c),
                    semi_axis_a: Some(w.norm()),
                    semi_axis_b: *semi_axis_b,
                    rotation: Some(w.y.atan2(w.x)),
                    start_angle: Some(frame_angle(c, v, *semi_axis_b, s)),
                    end_angle: Some(frame_angle(c, v, *semi_axis_b, e)),
                    vertex: Some(xy_p(v)),
                    start: Some(xy_p(s)),
                    end: Some(xy_p(e)),
                }
            }
            Entity::Bezier(c) => RawShape::Bezier {
                control_points: pts(c.control_points()),
            },
            Entity::BSpline(c) => RawShape::Bspline {
                degree: c.degree(),
                knots: c.knots().as_slice().to_vec(),
                control_points: pts(c.control_points()),
            },
            Entity::Nurbs(c) => RawShape::Nurbs {
                degree: c.degree(),
                knots: c.knots().as_slice().to_vec(),
                control_points: pts(c.control_points()),
                weights: c.weights().to_vec(),
            },
            Entity::Hermite(c) if c.segment_count() == 1 => {
                // One segment: blocks [p0, p1, t0, t1].
                let b = c.blocks();
                RawShape::Hermite {
                    p0: xy_p(&b[0]),
                    p1: xy_p(&b[1]),
                    t0: xy_p(&b[2]),
                    t1: xy_p(&b[3]),
                }
            }
            Entity::Hermite(c) | Entity::Composite(c) => RawShape::Composite {
                nodes: pts(c.nodes()),
                tangents: c.tangents().iter().map(|t| [t.x, t.y]).collect(),
                joins: c.joins().to_vec(),
            },
        }
    }
}
