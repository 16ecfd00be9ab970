//! The file form of a sketch's frame and entities: serde types that mirror entities with
//! snake-case tags and named fields, and the conversions both ways. Constraints are read and
//! written in their kinds' own forms ([`crate::constraints`]), one JSON object each.

use camber_geom::{BSplineCurve2, BezierCurve2, KnotVector, NurbsCurve2};
use nalgebra::Point2;
use serde::{Deserialize, Serialize};
use serde_json::Value;

use crate::entity::Entity;

pub(super) type Xy = [f64; 2];

fn pt(p: Xy) -> Point2<f64> {
    Point2::new(p[0], p[1])
}

fn xy_p(p: &Point2<f64>) -> Xy {
    [p.x, p.y]
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSketch {
    pub(super) version: u64,
    #[serde(default)]
    pub(super) entities: Vec<Value>,
    #[serde(default)]
    pub(super) constraints: Vec<Value>,
}

#[derive(Serialize, Deserialize)]
pub(super) struct RawEntity {
    pub(super) id: u64,
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
}

impl From<KeyedShape> for RawShape {
    fn from(k: KeyedShape) -> Self {
        match k {
            KeyedShape::Point { at } => RawShape::Point { at },
            KeyedShape::Line { from, to } => RawShape::Line { from, to },
            KeyedShape::Circle { center, radius } => RawShape::Circle { center, radius },
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
}

impl RawShape {
    pub(super) fn kind(&self) -> &'static str {
        match self {
            RawShape::Point { .. } => "point",
            RawShape::Line { .. } => "line",
            RawShape::Circle { .. } => "circle",
            RawShape::Bezier { .. } => "bezier",
            RawShape::Bspline { .. } => "bspline",
            RawShape::Nurbs { .. } => "nurbs",
        }
    }

    pub(super) fn into_entity(self) -> crate::Result<Entity> {
        let pts = |v: Vec<Xy>| v.into_iter().map(pt).collect::<Vec<_>>();
        Ok(match self {
            RawShape::Point { at } => Entity::Point(pt(at)),
            RawShape::Line { from, to } => Entity::Line([pt(from), pt(to)]),
            RawShape::Circle { center, radius } => Entity::Circle {
                center: pt(center),
                radius,
            },
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
        }
    }
}
