//! The built-in constraints, all affine in the control points (knots, weights, parameters and
//! directions being data), and their validation.
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

/// A user-written residual ([`camber_solve::Residual`]) over points of the sketch, each point
/// one block (x, y) in the order given. Points must be point entities, control points (line
/// ends, circle centres) or the clamped ends of curves. A non-affine residual makes its
/// component need the nonlinear solver, which is reported as [`crate::Error::NeedsNonlinear`].
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
        }
        out
    }
}
