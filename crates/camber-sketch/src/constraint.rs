//! The built-in constraints and their validation. The first group is affine in the control
//! points (knots, weights, parameters and directions being data); the second
//! ([`Constraint::PointOnCurve`] onward) is nonlinear: free contact parameters ([`Contact`]),
//! circles and lines whose points and radii are unknowns, distances, angles and the G1 joint
//! with a free direction, compiled to the residuals of [`crate::contact`]. Contacts record the
//! side of the target the curve stays on ([`CircleSide`], [`LineSide`]) and the direction of
//! travel ([`Rotation`], [`Sense`]), checked after every solve.
//!
//! Each constraint becomes rows of a [`camber_solve::Problem`] through the residuals of
//! [`crate::residuals`] (or, for `Fixed` and the elimination form of end tangency, through the
//! problem's bindings); see [`crate::build`]. Every tangency records its [`Sense`]: the one-row
//! cross-product form cross(C′(u), T) = 0 also holds when C′ points against T, so after every
//! solve sense·(C′(u)·T) > 0 is checked and a solve that flips it is rejected.

use std::sync::Arc;

use camber_solve::{DynResidual, Residual};
use nalgebra::{Point2, Vector2};
use smallvec::SmallVec;

use crate::ids::{EntityId, PointRef};

/// Whether a curve tangent must point along the given direction or against it.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Hash, Default, serde::Serialize, serde::Deserialize,
)]
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
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Hash, Default, serde::Serialize, serde::Deserialize,
)]
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

/// What a `Fixed` constraint holds in place.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum FixTarget {
    /// Every point (and radius) of the entity.
    Entity(EntityId),
    /// One point (a point entity, a control point, or a curve end).
    Point(PointRef),
}

/// Where a curve point must go.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Target {
    /// A fixed location.
    At(Point2<f64>),
    /// Another (movable) point of the sketch.
    Point(PointRef),
}

/// Where a contact takes place on a curve.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
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
}

/// Which side of a circle the curve lies on near the contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum CircleSide {
    /// |C(s) − c| ≥ r near the contact.
    Outside,
    /// |C(s) − c| ≤ r near the contact.
    Inside,
}

/// Which side of a line A→B the curve lies on near the contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum LineSide {
    /// cross(B − A, C(s) − A) ≥ 0.
    Left,
    /// cross(B − A, C(s) − A) ≤ 0.
    Right,
}

/// How a curve runs around a circle at the contact: the sign of cross(C(u) − c, C′(u)).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum Rotation {
    /// cross(C − c, C′) > 0.
    CounterClockwise,
    /// cross(C − c, C′) < 0.
    Clockwise,
}

/// A user-written residual ([`camber_solve::Residual`]) over points of the sketch, each point
/// one block (x, y) in the order given. Points must be point entities, control points (line
/// ends, circle centres) or the clamped ends of curves. A non-affine residual sends its
/// component to the nonlinear solver ([`camber_solve::solve()`]).
///
/// ```
/// use camber_sketch::{Constraint, Custom, PointRef, Sketch};
/// use camber_solve::{Residual, Scalar};
/// use nalgebra::Point2;
/// /// The two points are one unit apart in x: q.x − p.x − 1 = 0.
/// #[derive(Debug)]
/// struct UnitApart;
/// impl Residual for UnitApart {
///     fn name(&self) -> &str { "unit apart" }
///     fn dim(&self) -> usize { 1 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) { out[0] = x[1][0] - x[0][0] - T::one(); }
///     fn is_affine(&self) -> bool { true }
/// }
/// let mut s = Sketch::new();
/// let (p, q) = (s.add_point(Point2::new(0.0, 0.0))?, s.add_point(Point2::new(3.0, 0.0))?);
/// s.add_constraint(Constraint::Custom(Custom::new(UnitApart, vec![PointRef::Point(p), PointRef::Point(q)])))?;
/// s.solve()?;
/// assert!((s.point(PointRef::Point(q))?.x - s.point(PointRef::Point(p))?.x - 1.0).abs() < 1e-12);
/// # Ok::<(), camber_sketch::Error>(())
/// ```
#[derive(Clone)]
pub struct Custom {
    pub(crate) residual: Arc<dyn DynResidual>,
    pub(crate) points: Vec<PointRef>,
    /// The kind name and parameters a sketch file stores it under (see [`crate::file`]).
    pub(crate) file_form: Option<(String, serde_json::Value)>,
}

impl Custom {
    /// A custom constraint reading `points` (one block each, in order).
    pub fn new<R: Residual>(residual: R, points: Vec<PointRef>) -> Self {
        Self {
            residual: Arc::new(residual),
            points,
            file_form: None,
        }
    }

    /// The points read.
    pub fn points(&self) -> &[PointRef] {
        &self.points
    }
}

impl std::fmt::Debug for Custom {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Custom")
            .field("residual", &self.residual.name())
            .field("points", &self.points)
            .finish()
    }
}

/// Two custom constraints are equal when they share the same residual object and points.
impl PartialEq for Custom {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.residual, &other.residual) && self.points == other.points
    }
}

/// A built-in constraint. Parameters u must lie in the curve's domain; directions must be
/// finite and non-zero (their length does not matter except for `TangentVectorAt`).
///
/// ```
/// use camber_sketch::{Constraint, PointRef, Sketch, Sense, TangentForm};
/// use camber_geom::BezierCurve2;
/// use nalgebra::{Point2, Vector2};
/// let mut s = Sketch::new();
/// let c = s.add_bezier(BezierCurve2::try_new(vec![
///     Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(2.0, 1.0), Point2::new(3.0, 0.0),
/// ])?)?;
/// s.add_constraint(Constraint::StartTangent {
///     curve: c,
///     direction: Vector2::new(1.0, 0.0),
///     sense: Sense::Agree,
///     form: TangentForm::Row,
/// })?;
/// s.solve()?;
/// let p1 = s.point(PointRef::Control(c, 1))?;
/// let p0 = s.point(PointRef::Control(c, 0))?;
/// assert!((p1.y - p0.y).abs() < 1e-12 && p1.x > p0.x);
/// # Ok::<(), camber_sketch::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum Constraint {
    /// The target does not move.
    Fixed(FixTarget),
    /// Two points coincide: a − b = 0 (two rows).
    Coincident(PointRef, PointRef),
    /// C(u) = target (two rows).
    PointAtParameter {
        /// The curve.
        curve: EntityId,
        /// The parameter, inside the domain.
        u: f64,
        /// Where C(u) goes.
        target: Target,
    },
    /// C′(u) = vector, direction and length (two rows).
    TangentVectorAt {
        /// The curve.
        curve: EntityId,
        /// The parameter.
        u: f64,
        /// The tangent vector, in length units per unit of u.
        vector: Vector2<f64>,
    },
    /// cross(C′(u), T) = 0 with sense·(C′(u)·T) > 0 (one row).
    DirectionalTangentAt {
        /// The curve.
        curve: EntityId,
        /// The parameter.
        u: f64,
        /// The direction T.
        direction: Vector2<f64>,
        /// Along or against T.
        sense: Sense,
    },
    /// The start tangent C′(a) is parallel to T with the given sense.
    StartTangent {
        /// The curve.
        curve: EntityId,
        /// The direction T.
        direction: Vector2<f64>,
        /// Along or against T.
        sense: Sense,
        /// Row or elimination form.
        form: TangentForm,
    },
    /// The end tangent C′(b) is parallel to T with the given sense.
    EndTangent {
        /// The curve.
        curve: EntityId,
        /// The direction T.
        direction: Vector2<f64>,
        /// Along or against T.
        sense: Sense,
        /// Row or elimination form.
        form: TangentForm,
    },
    /// C(u) lies on the fixed line through `point` along `direction`, and C′(u) is parallel to
    /// it with the given sense: cross(C(u) − L₀, d) = 0 and cross(C′(u), d) = 0 (two rows).
    TangentToLineAt {
        /// The curve.
        curve: EntityId,
        /// The parameter.
        u: f64,
        /// A point of the line.
        point: Point2<f64>,
        /// The line direction d.
        direction: Vector2<f64>,
        /// Along or against d.
        sense: Sense,
    },
    /// The end of `first` coincides with the start of `second`, and both tangents there are
    /// parallel to the fixed joint direction d and point along it (four rows).
    G1Join {
        /// The curve that ends at the joint.
        first: EntityId,
        /// The curve that starts at the joint.
        second: EntityId,
        /// The joint direction d.
        direction: Vector2<f64>,
    },
    /// A user-written residual over points.
    Custom(Custom),
    /// The point lies on the curve: C(u) = P (two rows, nonlinear when u is free).
    PointOnCurve {
        /// The point (a single block: a point, control point or clamped curve end).
        point: PointRef,
        /// The curve.
        curve: EntityId,
        /// The parameter.
        u: Contact,
    },
    /// The curve touches the line entity (A, B) at u and runs along it with the given sense
    /// relative to B − A, lying on `side` near the contact (two rows).
    TangentToLine {
        /// The curve.
        curve: EntityId,
        /// The line entity (its ends may be unknowns).
        line: EntityId,
        /// The contact parameter.
        u: Contact,
        /// Which side of the line the curve stays on near the contact.
        side: LineSide,
        /// C′(u) along or against B − A.
        sense: Sense,
    },
    /// The curve touches the circle entity at u: |C(u) − c|² = r² and (C(u) − c)·C′(u) = 0,
    /// lying on `side` near the contact and running around it in `rotation` (two rows).
    TangentToCircle {
        /// The curve.
        curve: EntityId,
        /// The circle entity (centre and radius may be unknowns).
        circle: EntityId,
        /// The contact parameter.
        u: Contact,
        /// Outside or inside the circle near the contact.
        side: CircleSide,
        /// The direction of travel around the circle.
        rotation: Rotation,
    },
    /// The point lies on the circle: |P − c| = r (one row).
    PointOnCircle {
        /// The point (a single block).
        point: PointRef,
        /// The circle entity.
        circle: EntityId,
    },
    /// The circle's radius equals the value (> 0; one affine row).
    Radius {
        /// The circle entity.
        circle: EntityId,
        /// The radius.
        radius: f64,
    },
    /// Two points are `distance` (> 0) apart (one row).
    Distance {
        /// The first point (a single block).
        a: PointRef,
        /// The second point (a single block).
        b: PointRef,
        /// The distance.
        distance: f64,
    },
    /// Two line entities are parallel, either sense (one row).
    Parallel(EntityId, EntityId),
    /// Two line entities are perpendicular (one row).
    Perpendicular(EntityId, EntityId),
    /// The angle from the first line's direction to the second's is `angle` radians
    /// (counter-clockwise positive; one row plus a check of the sense).
    Angle {
        /// The first line.
        first: EntityId,
        /// The second line.
        second: EntityId,
        /// The angle θ in radians.
        angle: f64,
    },
    /// [`Constraint::G1JoinFree`] plus equal signed curvature on both sides of the joint
    /// (G2 continuity; four rows).
    G2Join {
        /// The curve that ends at the joint.
        first: EntityId,
        /// The curve that starts at the joint.
        second: EntityId,
    },
    /// Two curves touch: C₁(u) = C₂(v) and their tangents there are parallel with the given
    /// sense (C₁′·C₂′ > 0 for [`Sense::Agree`]); u and v may be free (three rows).
    CurveCurveTangent {
        /// The first curve.
        first: EntityId,
        /// Its contact parameter.
        u: Contact,
        /// The second curve.
        second: EntityId,
        /// Its contact parameter.
        v: Contact,
        /// Same or opposite travel directions at the contact.
        sense: Sense,
    },
    /// The end of `first` coincides with the start of `second` and their tangents there are
    /// parallel and point the same way, the direction being free (three rows).
    G1JoinFree {
        /// The curve that ends at the joint.
        first: EntityId,
        /// The curve that starts at the joint.
        second: EntityId,
    },
}

impl Constraint {
    /// The kind as a word, used as the residual name in reports.
    pub fn kind_name(&self) -> &'static str {
        match self {
            Constraint::Fixed(_) => "fixed",
            Constraint::Coincident(..) => "coincident",
            Constraint::PointAtParameter { .. } => "point at parameter",
            Constraint::TangentVectorAt { .. } => "tangent vector at",
            Constraint::DirectionalTangentAt { .. } => "directional tangent at",
            Constraint::StartTangent { .. } => "start tangent",
            Constraint::EndTangent { .. } => "end tangent",
            Constraint::TangentToLineAt { .. } => "tangent to line at",
            Constraint::G1Join { .. } => "G1 join",
            Constraint::Custom(_) => "custom",
            Constraint::PointOnCurve { .. } => "point on curve",
            Constraint::TangentToLine { .. } => "tangent to line",
            Constraint::TangentToCircle { .. } => "tangent to circle",
            Constraint::PointOnCircle { .. } => "point on circle",
            Constraint::Radius { .. } => "radius",
            Constraint::Distance { .. } => "distance",
            Constraint::Parallel(..) => "parallel",
            Constraint::Perpendicular(..) => "perpendicular",
            Constraint::Angle { .. } => "angle",
            Constraint::G1JoinFree { .. } => "G1 join (free direction)",
            Constraint::CurveCurveTangent { .. } => "curve-curve tangent",
            Constraint::G2Join { .. } => "G2 join",
        }
    }

    /// The entities the constraint reads (its edges in the sketch graph), without repeats.
    pub fn entities(&self) -> SmallVec<[EntityId; 2]> {
        let mut out: SmallVec<[EntityId; 2]> = SmallVec::new();
        let mut push = |e: EntityId| {
            if !out.contains(&e) {
                out.push(e);
            }
        };
        match self {
            Constraint::Fixed(FixTarget::Entity(e)) => push(*e),
            Constraint::Fixed(FixTarget::Point(p)) => push(p.entity()),
            Constraint::Coincident(a, b) => {
                push(a.entity());
                push(b.entity());
            }
            Constraint::PointAtParameter { curve, target, .. } => {
                push(*curve);
                if let Target::Point(p) = target {
                    push(p.entity());
                }
            }
            Constraint::TangentVectorAt { curve, .. }
            | Constraint::DirectionalTangentAt { curve, .. }
            | Constraint::StartTangent { curve, .. }
            | Constraint::EndTangent { curve, .. }
            | Constraint::TangentToLineAt { curve, .. } => push(*curve),
            Constraint::G1Join { first, second, .. } => {
                push(*first);
                push(*second);
            }
            Constraint::Custom(c) => {
                for p in &c.points {
                    push(p.entity());
                }
            }
            Constraint::PointOnCurve { point, curve, .. } => {
                push(point.entity());
                push(*curve);
            }
            Constraint::TangentToLine {
                curve, line: other, ..
            }
            | Constraint::TangentToCircle {
                curve,
                circle: other,
                ..
            } => {
                push(*curve);
                push(*other);
            }
            Constraint::PointOnCircle { point, circle } => {
                push(point.entity());
                push(*circle);
            }
            Constraint::Radius { circle, .. } => push(*circle),
            Constraint::Distance { a, b, .. } => {
                push(a.entity());
                push(b.entity());
            }
            Constraint::Parallel(first, second)
            | Constraint::Perpendicular(first, second)
            | Constraint::Angle { first, second, .. }
            | Constraint::G1JoinFree { first, second }
            | Constraint::CurveCurveTangent { first, second, .. }
            | Constraint::G2Join { first, second } => {
                push(*first);
                push(*second);
            }
        }
        out
    }

    /// Stores a solved free contact parameter (no effect on other constraints).
    pub(crate) fn set_contact(&mut self, value: f64) {
        match self {
            Constraint::PointOnCurve { u, .. }
            | Constraint::TangentToLine { u, .. }
            | Constraint::TangentToCircle { u, .. } => {
                if let Contact::Free(v) = u {
                    *v = value;
                }
            }
            _ => {}
        }
    }

    /// Stores the `k`-th solved free contact parameter of a constraint with two (k = 0: u,
    /// k = 1: v); other constraints use [`Constraint::set_contact`].
    pub(crate) fn set_contact_at(&mut self, k: usize, value: f64) {
        match self {
            Constraint::CurveCurveTangent { u, v, .. } => {
                let free: Vec<&mut Contact> = [u, v]
                    .into_iter()
                    .filter(|c| matches!(c, Contact::Free(_)))
                    .collect();
                if let Some(Contact::Free(x)) = free.into_iter().nth(k) {
                    *x = value;
                }
            }
            other => {
                if k == 0 {
                    other.set_contact(value);
                }
            }
        }
    }
}
