//! The file form of sketches: serde types that mirror entities and constraints with snake-case
//! tags and named fields, and the conversions both ways. A new constraint variant needs one
//! variant in [`RawBody`] and one arm in each of its three matches.

use camber_geom::{BSplineCurve2, BezierCurve2, KnotVector, NurbsCurve2};
use nalgebra::{Point2, Vector2};
use serde::{Deserialize, Serialize};
use serde_json::Value;

use super::{CustomRegistry, FileError};
use crate::constraint::{Constraint, FixTarget, Sense, TangentForm, Target};
use crate::entity::Entity;
use crate::ids::{ConstraintId, EntityId, PointRef};

type Xy = [f64; 2];

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

/// A point reference: `{"point": 3}`, `{"control": [3, 1]}`, `{"start": 3}`, `{"end": 3}`.
#[derive(Serialize, Deserialize, Clone, Copy)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub(super) enum RawPoint {
    Point(u64),
    Control(u64, usize),
    Start(u64),
    End(u64),
}

impl From<RawPoint> for PointRef {
    fn from(p: RawPoint) -> Self {
        match p {
            RawPoint::Point(e) => PointRef::Point(EntityId(e)),
            RawPoint::Control(e, i) => PointRef::Control(EntityId(e), i),
            RawPoint::Start(e) => PointRef::Start(EntityId(e)),
            RawPoint::End(e) => PointRef::End(EntityId(e)),
        }
    }
}

impl From<PointRef> for RawPoint {
    fn from(p: PointRef) -> Self {
        match p {
            PointRef::Point(e) => RawPoint::Point(e.0),
            PointRef::Control(e, i) => RawPoint::Control(e.0, i),
            PointRef::Start(e) => RawPoint::Start(e.0),
            PointRef::End(e) => RawPoint::End(e.0),
        }
    }
}

#[derive(Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub(super) enum RawFix {
    Entity(u64),
    Point(RawPoint),
}

#[derive(Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub(super) enum RawTarget {
    At(Xy),
    Point(RawPoint),
}

#[derive(Serialize, Deserialize, Clone, Copy, Default)]
#[serde(rename_all = "snake_case")]
pub(super) enum RawSense {
    #[default]
    Agree,
    Oppose,
}

#[derive(Serialize, Deserialize, Clone, Copy, Default)]
#[serde(rename_all = "snake_case")]
pub(super) enum RawForm {
    #[default]
    Row,
    Elimination,
}

impl From<RawSense> for Sense {
    fn from(s: RawSense) -> Self {
        match s {
            RawSense::Agree => Sense::Agree,
            RawSense::Oppose => Sense::Oppose,
        }
    }
}

impl From<Sense> for RawSense {
    fn from(s: Sense) -> Self {
        match s {
            Sense::Agree => RawSense::Agree,
            Sense::Oppose => RawSense::Oppose,
        }
    }
}

impl From<RawForm> for TangentForm {
    fn from(s: RawForm) -> Self {
        match s {
            RawForm::Row => TangentForm::Row,
            RawForm::Elimination => TangentForm::Elimination,
        }
    }
}

impl From<TangentForm> for RawForm {
    fn from(s: TangentForm) -> Self {
        match s {
            TangentForm::Row => RawForm::Row,
            TangentForm::Elimination => RawForm::Elimination,
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
        })
    }
}
