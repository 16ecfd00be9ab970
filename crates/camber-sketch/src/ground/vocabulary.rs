//! The small types constraints are written with: which way a tangent points ([`Sense`]), how
//! an end tangency is imposed ([`TangentForm`]), what a `Fixed` constraint holds
//! ([`FixTarget`]), where a curve point goes ([`Target`]), where a contact takes place
//! ([`Contact`]), and which side of a circle or line a curve keeps to ([`CircleSide`],
//! [`LineSide`], [`Rotation`]), and how two round entities touch ([`Tangency`]).
//!
//! Each serializes in its sketch-file form (snake-case words, `{"at": 0.5}`, points as
//! `[x, y]`), so a constraint kind's file form is its struct's own serde derive.

use nalgebra::Point2;
use serde::{Deserialize, Serialize};

use crate::ground::ids::{EntityId, PointRef};

/// Whether a curve tangent must point along the given direction or against it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Sense {
    /// C′(u)·T > 0.
    #[default]
    Agree,
    /// C′(u)·T < 0.
    Oppose,
}

impl Sense {
    /// +1 for [`Sense::Agree`], −1 for [`Sense::Oppose`].
    pub fn sign(self) -> f64 {
        match self {
            Sense::Agree => 1.0,
            Sense::Oppose => -1.0,
        }
    }
}

/// How a start or end tangency is imposed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TangentForm {
    /// One row cross(C′(a), T) = 0: the control points stay unknowns and move by the minimum
    /// norm in the control points.
    #[default]
    Row,
    /// The paper's elimination P₁ = P₀ + t·s·T (at the end Pₙ₋₁ = Pₙ − t·s·T) with t > 0 a new
    /// unknown: P₁ stops being an unknown, and the minimum norm is taken over (…, P₀, t, …).
    /// Needs a curve clamped at that end. If P₁ is fixed, or already eliminated or used as the
    /// base of another elimination, the row form is used instead.
    Elimination,
}

/// What a `Fixed` constraint holds in place: `{"entity": 3}` or `{"point": {"start": 3}}`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum FixTarget {
    /// Every point (and radius) of the entity.
    Entity(EntityId),
    /// One point (a point entity, a control point, or a curve end).
    Point(PointRef),
}

/// Where a curve point must go: `{"at": [x, y]}` or `{"point": {"point": 4}}`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Target {
    /// A fixed location.
    At(#[serde(with = "xy_point")] Point2<f64>),
    /// Another (movable) point of the sketch.
    Point(PointRef),
}

/// Where a contact takes place on a curve: `{"at": 0.3}` or `{"free": 0.3}`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Contact {
    /// At this fixed parameter.
    At(f64),
    /// At a free parameter (an unknown bounded to the curve's domain) starting here; a
    /// successful solve stores the solved value back into the constraint.
    Free(f64),
}

impl Contact {
    /// The parameter value (fixed, or the current value of the free one).
    pub fn value(self) -> f64 {
        match self {
            Contact::At(u) | Contact::Free(u) => u,
        }
    }

    /// Stores a solved value into a free contact (a fixed one keeps its value).
    pub fn set_free(&mut self, value: f64) {
        if let Contact::Free(u) = self {
            *u = value;
        }
    }

    /// Whether the parameter is an unknown.
    pub fn is_free(self) -> bool {
        matches!(self, Contact::Free(_))
    }
}

/// Which side of a circle the curve lies on near the contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CircleSide {
    /// |C(s) − c| ≥ r near the contact.
    Outside,
    /// |C(s) − c| ≤ r near the contact.
    Inside,
}

/// Which side of a line A→B the curve lies on near the contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LineSide {
    /// cross(B − A, C(s) − A) ≥ 0.
    Left,
    /// cross(B − A, C(s) − A) ≤ 0.
    Right,
}

/// How two round entities touch: `"external"` (each outside the other, |C₁ − C₂| = r₁ + r₂)
/// or `"internal"` (one inside the other, |C₁ − C₂| = |r₁ − r₂|).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Tangency {
    /// Each outside the other: |C₁ − C₂| = r₁ + r₂.
    External,
    /// One inside the other: |C₁ − C₂| = |r₁ − r₂|.
    Internal,
}

/// How a curve runs around a circle at the contact: the sign of cross(C(u) − c, C′(u)).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Rotation {
    /// cross(C − c, C′) > 0.
    CounterClockwise,
    /// cross(C − c, C′) < 0.
    Clockwise,
}

/// Serde for a `Point2<f64>` as `[x, y]` (use with `#[serde(with = "…")]`).
pub mod xy_point {
    use nalgebra::Point2;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    /// Writes `[x, y]`.
    ///
    /// # Errors
    /// The serializer's.
    pub fn serialize<S: Serializer>(p: &Point2<f64>, s: S) -> Result<S::Ok, S::Error> {
        [p.x, p.y].serialize(s)
    }

    /// Reads `[x, y]`.
    ///
    /// # Errors
    /// Anything but an array of two numbers.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Point2<f64>, D::Error> {
        let [x, y] = <[f64; 2]>::deserialize(d)?;
        Ok(Point2::new(x, y))
    }
}

/// Serde for a `Vector2<f64>` as `[x, y]` (use with `#[serde(with = "…")]`).
pub mod xy_vector {
    use nalgebra::Vector2;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    /// Writes `[x, y]`.
    ///
    /// # Errors
    /// The serializer's.
    pub fn serialize<S: Serializer>(v: &Vector2<f64>, s: S) -> Result<S::Ok, S::Error> {
        [v.x, v.y].serialize(s)
    }

    /// Reads `[x, y]`.
    ///
    /// # Errors
    /// Anything but an array of two numbers.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vector2<f64>, D::Error> {
        let [x, y] = <[f64; 2]>::deserialize(d)?;
        Ok(Vector2::new(x, y))
    }
}

/// Two points, given as the ends of a line entity or as two point references: what horizontal,
/// vertical, equal-length and axis-distance constraints relate. File form `{"line": 3}` or
/// `{"a": {"point": 1}, "b": {"control": [2, 0]}}`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(try_from = "PairForm", into = "PairForm")]
pub enum PointPair {
    /// The two ends of a line entity, start then end.
    Line(EntityId),
    /// Two points.
    Points(PointRef, PointRef),
}

impl PointPair {
    /// The two points, in order.
    pub fn points(self) -> [PointRef; 2] {
        match self {
            PointPair::Line(l) => [PointRef::Control(l, 0), PointRef::Control(l, 1)],
            PointPair::Points(a, b) => [a, b],
        }
    }

    /// The entities they belong to.
    pub fn entities(self) -> [EntityId; 2] {
        let [a, b] = self.points();
        [a.entity(), b.entity()]
    }
}

/// The file form of a [`PointPair`].
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct PairForm {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    line: Option<EntityId>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    a: Option<PointRef>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    b: Option<PointRef>,
}

impl TryFrom<PairForm> for PointPair {
    type Error = &'static str;
    fn try_from(f: PairForm) -> Result<Self, Self::Error> {
        match (f.line, f.a, f.b) {
            (Some(l), None, None) => Ok(PointPair::Line(l)),
            (None, Some(a), Some(b)) => Ok(PointPair::Points(a, b)),
            _ => Err("expected either \"line\" or both \"a\" and \"b\""),
        }
    }
}

impl From<PointPair> for PairForm {
    fn from(p: PointPair) -> Self {
        match p {
            PointPair::Line(l) => PairForm {
                line: Some(l),
                a: None,
                b: None,
            },
            PointPair::Points(a, b) => PairForm {
                line: None,
                a: Some(a),
                b: Some(b),
            },
        }
    }
}

/// What an argument of a custom constraint is, as its residual declares it (see
/// `constraints::custom`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ArgKind {
    /// A point (x, y).
    Point,
    /// One number: a radius, another constraint's free parameter, or an own parameter.
    Scalar,
    /// A whole curve.
    Curve,
}
