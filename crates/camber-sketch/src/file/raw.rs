//! The file form of sketches: serde types that mirror entities and constraints with snake-case
//! tags and named fields, and the conversions both ways. A new constraint variant needs one
//! variant in [`RawBody`] and one arm in each of its three matches.

use camber_geom::{BSplineCurve2, BezierCurve2, KnotVector, NurbsCurve2};
use nalgebra::{Point2, Vector2};
use serde::{Deserialize, Serialize};
use serde_json::Value;

use super::leaf::{
    RawCircleSide, RawContact, RawFix, RawForm, RawLineSide, RawPoint, RawRotation, RawSense,
    RawTarget,
};
use super::{CustomRegistry, FileError};
use crate::constraint::{Constraint, FixTarget, Target};
use crate::entity::Entity;
use crate::ids::{ConstraintId, EntityId, PointRef};

pub(super) type Xy = [f64; 2];

fn pt(p: Xy) -> Point2<f64> {
    Point2::new(p[0], p[1])
}

fn vec2(v: Xy) -> Vector2<f64> {
    Vector2::new(v[0], v[1])
}

fn xy_p(p: &Point2<f64>) -> Xy {
    [p.x, p.y]
}

fn xy_v(v: &Vector2<f64>) -> Xy {
    [v.x, v.y]
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSketch {
    pub(super) version: u64,
    #[serde(default)]
    pub(super) entities: Vec<RawEntity>,
    #[serde(default)]
    pub(super) constraints: Vec<RawConstraint>,
}

#[derive(Serialize, Deserialize)]
pub(super) struct RawEntity {
    pub(super) id: u64,
    #[serde(flatten)]
    pub(super) shape: RawShape,
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

#[derive(Serialize, Deserialize)]
pub(super) struct RawConstraint {
    pub(super) id: u64,
    #[serde(flatten)]
    pub(super) body: RawBody,
}

#[derive(Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub(super) enum RawBody {
    Fixed {
        target: RawFix,
    },
    Coincident {
        a: RawPoint,
        b: RawPoint,
    },
    PointAtParameter {
        curve: u64,
        u: f64,
        target: RawTarget,
    },
    TangentVectorAt {
        curve: u64,
        u: f64,
        vector: Xy,
    },
    DirectionalTangentAt {
        curve: u64,
        u: f64,
        direction: Xy,
        #[serde(default)]
        sense: RawSense,
    },
    StartTangent {
        curve: u64,
        direction: Xy,
        #[serde(default)]
        sense: RawSense,
        #[serde(default)]
        form: RawForm,
    },
    EndTangent {
        curve: u64,
        direction: Xy,
        #[serde(default)]
        sense: RawSense,
        #[serde(default)]
        form: RawForm,
    },
    TangentToLineAt {
        curve: u64,
        u: f64,
        point: Xy,
        direction: Xy,
        #[serde(default)]
        sense: RawSense,
    },
    G1Join {
        first: u64,
        second: u64,
        direction: Xy,
    },
    Custom {
        name: String,
        points: Vec<RawPoint>,
        #[serde(default, skip_serializing_if = "Value::is_null")]
        params: Value,
    },
    PointOnCurve {
        point: RawPoint,
        curve: u64,
        u: RawContact,
    },
    TangentToLine {
        curve: u64,
        line: u64,
        u: RawContact,
        side: RawLineSide,
        #[serde(default)]
        sense: RawSense,
    },
    TangentToCircle {
        curve: u64,
        circle: u64,
        u: RawContact,
        side: RawCircleSide,
        rotation: RawRotation,
    },
    PointOnCircle {
        point: RawPoint,
        circle: u64,
    },
    Radius {
        circle: u64,
        radius: f64,
    },
    Distance {
        a: RawPoint,
        b: RawPoint,
        distance: f64,
    },
    Parallel {
        first: u64,
        second: u64,
    },
    Perpendicular {
        first: u64,
        second: u64,
    },
    Angle {
        first: u64,
        second: u64,
        angle: f64,
    },
    G1JoinFree {
        first: u64,
        second: u64,
    },
    G2Join {
        first: u64,
        second: u64,
    },
    CurveCurveTangent {
        first: u64,
        u: RawContact,
        second: u64,
        v: RawContact,
        #[serde(default)]
        sense: RawSense,
    },
}

impl RawBody {
    pub(super) fn kind(&self) -> &'static str {
        match self {
            RawBody::Fixed { .. } => "fixed",
            RawBody::Coincident { .. } => "coincident",
            RawBody::PointAtParameter { .. } => "point_at_parameter",
            RawBody::TangentVectorAt { .. } => "tangent_vector_at",
            RawBody::DirectionalTangentAt { .. } => "directional_tangent_at",
            RawBody::StartTangent { .. } => "start_tangent",
            RawBody::EndTangent { .. } => "end_tangent",
            RawBody::TangentToLineAt { .. } => "tangent_to_line_at",
            RawBody::G1Join { .. } => "g1_join",
            RawBody::Custom { .. } => "custom",
            RawBody::PointOnCurve { .. } => "point_on_curve",
            RawBody::TangentToLine { .. } => "tangent_to_line",
            RawBody::TangentToCircle { .. } => "tangent_to_circle",
            RawBody::PointOnCircle { .. } => "point_on_circle",
            RawBody::Radius { .. } => "radius",
            RawBody::Distance { .. } => "distance",
            RawBody::Parallel { .. } => "parallel",
            RawBody::Perpendicular { .. } => "perpendicular",
            RawBody::Angle { .. } => "angle",
            RawBody::G1JoinFree { .. } => "g1_join_free",
            RawBody::G2Join { .. } => "g2_join",
            RawBody::CurveCurveTangent { .. } => "curve_curve_tangent",
        }
    }

    pub(super) fn into_constraint(
        self,
        id: u64,
        registry: &CustomRegistry,
    ) -> std::result::Result<Constraint, FileError> {
        let e = EntityId;
        Ok(match self {
            RawBody::Fixed { target } => Constraint::Fixed(match target {
                RawFix::Entity(x) => FixTarget::Entity(e(x)),
                RawFix::Point(p) => FixTarget::Point(p.into()),
            }),
            RawBody::Coincident { a, b } => Constraint::Coincident(a.into(), b.into()),
            RawBody::PointAtParameter { curve, u, target } => Constraint::PointAtParameter {
                curve: e(curve),
                u,
                target: match target {
                    RawTarget::At(p) => Target::At(pt(p)),
                    RawTarget::Point(p) => Target::Point(p.into()),
                },
            },
            RawBody::TangentVectorAt { curve, u, vector } => Constraint::TangentVectorAt {
                curve: e(curve),
                u,
                vector: vec2(vector),
            },
            RawBody::DirectionalTangentAt {
                curve,
                u,
                direction,
                sense,
            } => Constraint::DirectionalTangentAt {
                curve: e(curve),
                u,
                direction: vec2(direction),
                sense: sense.into(),
            },
            RawBody::StartTangent {
                curve,
                direction,
                sense,
                form,
            } => Constraint::StartTangent {
                curve: e(curve),
                direction: vec2(direction),
                sense: sense.into(),
                form: form.into(),
            },
            RawBody::EndTangent {
                curve,
                direction,
                sense,
                form,
            } => Constraint::EndTangent {
                curve: e(curve),
                direction: vec2(direction),
                sense: sense.into(),
                form: form.into(),
            },
            RawBody::TangentToLineAt {
                curve,
                u,
                point,
                direction,
                sense,
            } => Constraint::TangentToLineAt {
                curve: e(curve),
                u,
                point: pt(point),
                direction: vec2(direction),
                sense: sense.into(),
            },
            RawBody::G1Join {
                first,
                second,
                direction,
            } => Constraint::G1Join {
                first: e(first),
                second: e(second),
                direction: vec2(direction),
            },
            RawBody::Custom {
                name,
                points,
                params,
            } => {
                let decode =
                    registry
                        .kinds
                        .get(&name)
                        .ok_or_else(|| FileError::UnregisteredCustom {
                            id,
                            name: name.clone(),
                        })?;
                let points = points.into_iter().map(PointRef::from).collect();
                let custom =
                    decode(&params, points).map_err(|message| FileError::CustomParams {
                        id,
                        name: name.clone(),
                        message,
                    })?;
                Constraint::Custom(custom.with_file_form(name, params))
            }
            RawBody::PointOnCurve { point, curve, u } => Constraint::PointOnCurve {
                point: point.into(),
                curve: e(curve),
                u: u.into(),
            },
            RawBody::TangentToLine {
                curve,
                line,
                u,
                side,
                sense,
            } => Constraint::TangentToLine {
                curve: e(curve),
                line: e(line),
                u: u.into(),
                side: side.into(),
                sense: sense.into(),
            },
            RawBody::TangentToCircle {
                curve,
                circle,
                u,
                side,
                rotation,
            } => Constraint::TangentToCircle {
                curve: e(curve),
                circle: e(circle),
                u: u.into(),
                side: side.into(),
                rotation: rotation.into(),
            },
            RawBody::PointOnCircle { point, circle } => Constraint::PointOnCircle {
                point: point.into(),
                circle: e(circle),
            },
            RawBody::Radius { circle, radius } => Constraint::Radius {
                circle: e(circle),
                radius,
            },
            RawBody::Distance { a, b, distance } => Constraint::Distance {
                a: a.into(),
                b: b.into(),
                distance,
            },
            RawBody::Parallel { first, second } => Constraint::Parallel(e(first), e(second)),
            RawBody::Perpendicular { first, second } => {
                Constraint::Perpendicular(e(first), e(second))
            }
            RawBody::Angle {
                first,
                second,
                angle,
            } => Constraint::Angle {
                first: e(first),
                second: e(second),
                angle,
            },
            RawBody::G1JoinFree { first, second } => Constraint::G1JoinFree {
                first: e(first),
                second: e(second),
            },
            RawBody::G2Join { first, second } => Constraint::G2Join {
                first: e(first),
                second: e(second),
            },
            RawBody::CurveCurveTangent {
                first,
                u,
                second,
                v,
                sense,
            } => Constraint::CurveCurveTangent {
                first: e(first),
                u: u.into(),
                second: e(second),
                v: v.into(),
                sense: sense.into(),
            },
        })
    }

    pub(super) fn from_constraint(
        id: ConstraintId,
        c: &Constraint,
    ) -> std::result::Result<Self, FileError> {
        Ok(match c {
            Constraint::Fixed(t) => RawBody::Fixed {
                target: match t {
                    FixTarget::Entity(x) => RawFix::Entity(x.0),
                    FixTarget::Point(p) => RawFix::Point((*p).into()),
                },
            },
            Constraint::Coincident(a, b) => RawBody::Coincident {
                a: (*a).into(),
                b: (*b).into(),
            },
            Constraint::PointAtParameter { curve, u, target } => RawBody::PointAtParameter {
                curve: curve.0,
                u: *u,
                target: match target {
                    Target::At(p) => RawTarget::At(xy_p(p)),
                    Target::Point(p) => RawTarget::Point((*p).into()),
                },
            },
            Constraint::TangentVectorAt { curve, u, vector } => RawBody::TangentVectorAt {
                curve: curve.0,
                u: *u,
                vector: xy_v(vector),
            },
            Constraint::DirectionalTangentAt {
                curve,
                u,
                direction,
                sense,
            } => RawBody::DirectionalTangentAt {
                curve: curve.0,
                u: *u,
                direction: xy_v(direction),
                sense: (*sense).into(),
            },
            Constraint::StartTangent {
                curve,
                direction,
                sense,
                form,
            } => RawBody::StartTangent {
                curve: curve.0,
                direction: xy_v(direction),
                sense: (*sense).into(),
                form: (*form).into(),
            },
            Constraint::EndTangent {
                curve,
                direction,
                sense,
                form,
            } => RawBody::EndTangent {
                curve: curve.0,
                direction: xy_v(direction),
                sense: (*sense).into(),
                form: (*form).into(),
            },
            Constraint::TangentToLineAt {
                curve,
                u,
                point,
                direction,
                sense,
            } => RawBody::TangentToLineAt {
                curve: curve.0,
                u: *u,
                point: xy_p(point),
                direction: xy_v(direction),
                sense: (*sense).into(),
            },
            Constraint::G1Join {
                first,
                second,
                direction,
            } => RawBody::G1Join {
                first: first.0,
                second: second.0,
                direction: xy_v(direction),
            },
            Constraint::Custom(custom) => {
                let (name, params) =
                    custom
                        .file_form()
                        .ok_or_else(|| FileError::CustomNotSavable {
                            id: id.0,
                            name: custom.residual.name().to_owned(),
                        })?;
                RawBody::Custom {
                    name: name.to_owned(),
                    points: custom.points.iter().map(|p| RawPoint::from(*p)).collect(),
                    params: params.clone(),
                }
            }
            Constraint::PointOnCurve { point, curve, u } => RawBody::PointOnCurve {
                point: (*point).into(),
                curve: curve.0,
                u: (*u).into(),
            },
            Constraint::TangentToLine {
                curve,
                line,
                u,
                side,
                sense,
            } => RawBody::TangentToLine {
                curve: curve.0,
                line: line.0,
                u: (*u).into(),
                side: (*side).into(),
                sense: (*sense).into(),
            },
            Constraint::TangentToCircle {
                curve,
                circle,
                u,
                side,
                rotation,
            } => RawBody::TangentToCircle {
                curve: curve.0,
                circle: circle.0,
                u: (*u).into(),
                side: (*side).into(),
                rotation: (*rotation).into(),
            },
            Constraint::PointOnCircle { point, circle } => RawBody::PointOnCircle {
                point: (*point).into(),
                circle: circle.0,
            },
            Constraint::Radius { circle, radius } => RawBody::Radius {
                circle: circle.0,
                radius: *radius,
            },
            Constraint::Distance { a, b, distance } => RawBody::Distance {
                a: (*a).into(),
                b: (*b).into(),
                distance: *distance,
            },
            Constraint::Parallel(first, second) => RawBody::Parallel {
                first: first.0,
                second: second.0,
            },
            Constraint::Perpendicular(first, second) => RawBody::Perpendicular {
                first: first.0,
                second: second.0,
            },
            Constraint::Angle {
                first,
                second,
                angle,
            } => RawBody::Angle {
                first: first.0,
                second: second.0,
                angle: *angle,
            },
            Constraint::G1JoinFree { first, second } => RawBody::G1JoinFree {
                first: first.0,
                second: second.0,
            },
            Constraint::G2Join { first, second } => RawBody::G2Join {
                first: first.0,
                second: second.0,
            },
            Constraint::CurveCurveTangent {
                first,
                u,
                second,
                v,
                sense,
            } => RawBody::CurveCurveTangent {
                first: first.0,
                u: (*u).into(),
                second: second.0,
                v: (*v).into(),
                sense: (*sense).into(),
            },
        })
    }
}
