//! The error type of camber-sketch: one enum whose variants name the offending entity,
//! constraint, index or value.
//!
//! Every fallible operation of [`crate::Sketch`] leaves the sketch exactly as it was when it
//! returns an error: edits are validated before anything is stored, and solves write back only
//! after every component has succeeded.

use camber_solve::scalar::Readable;
use camber_solve::ConstraintId;

use crate::ground::ids::{EntityId, PointRef};

/// Everything that can go wrong when editing, solving or dragging a [`crate::Sketch`].
///
/// ```
/// use camber_sketch::{EntityId, Error, Sketch};
/// let sketch = Sketch::new();
/// assert_eq!(
///     sketch.entity(EntityId(4)).unwrap_err(),
///     Error::UnknownEntity { entity: EntityId(4) }
/// );
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// An entity id this sketch does not hold.
    #[error("{entity} does not exist")]
    UnknownEntity {
        /// The id asked for.
        entity: EntityId,
    },
    /// A constraint id this sketch does not hold.
    #[error("{constraint} does not exist")]
    UnknownConstraint {
        /// The id asked for.
        constraint: ConstraintId,
    },
    /// A control point index past the entity's points.
    #[error("{entity} has {count} points, index {index} does not exist")]
    UnknownPoint {
        /// The entity.
        entity: EntityId,
        /// The index asked for.
        index: usize,
        /// How many points the entity has.
        count: usize,
    },
    /// The entity is of a kind the operation does not accept (a parameter on a point, a
    /// tangent of a circle, …).
    #[error("{entity} is {} {found}, expected {expected}", article(found))]
    WrongEntityKind {
        /// The entity.
        entity: EntityId,
        /// What the operation needs ("curve", "point", …).
        expected: &'static str,
        /// What the entity is.
        found: &'static str,
    },
    /// A number that must be finite is NaN or infinite.
    #[error("{what} {index} is not finite ({})", Readable(*value))]
    NonFinite {
        /// What the number is ("target", "parameter", "direction", …).
        what: &'static str,
        /// Its index in the input (coordinate index for points and vectors).
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// A tangent or line direction of zero length.
    #[error("the {what} direction ({}, {}) has zero length", Readable(*x), Readable(*y))]
    ZeroDirection {
        /// Which direction ("tangent", "line", …).
        what: &'static str,
        /// Its x component.
        x: f64,
        /// Its y component.
        y: f64,
    },
    /// A curve parameter outside the curve's domain.
    #[error(
        "parameter {} is outside the domain [{}, {}] of {entity}",
        Readable(*value),
        Readable(*min),
        Readable(*max)
    )]
    ParameterOutsideDomain {
        /// The curve.
        entity: EntityId,
        /// The parameter.
        value: f64,
        /// Start of the domain.
        min: f64,
        /// End of the domain.
        max: f64,
    },
    /// The elimination form of an end tangency needs the first (or last) two control points to
    /// span the end tangent: a curve clamped at that end (degree ≥ 1). Hermite and composite
    /// curves never give this error: their end tangent is itself a block of unknowns.
    #[error("{entity} is not clamped at its {end} end; use the row form of the tangency")]
    NotClampedEnd {
        /// The curve.
        entity: EntityId,
        /// "start" or "end".
        end: &'static str,
    },
    /// An entity whose points all lie on one place (a zero-length line, a curve whose control
    /// points are all equal), or a curve of degree 0: it has no direction, so every tangent,
    /// length and angle of it is undefined.
    ///
    /// ```
    /// use camber_sketch::{EntityId, Error, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let p = Point2::new(1.0, 1.0);
    /// assert_eq!(
    ///     s.add_line(p, p).unwrap_err(),
    ///     Error::DegenerateEntity { entity: EntityId(0), kind: "line", reason: "has zero length" }
    /// );
    /// ```
    #[error("{entity} ({kind}) {reason}")]
    DegenerateEntity {
        /// The entity.
        entity: EntityId,
        /// Its kind ("line", "bezier", …).
        kind: &'static str,
        /// What is degenerate, in words.
        reason: &'static str,
    },
    /// An arc the kernel refuses: a radius that is not positive, a sweep of zero (start and
    /// end in one direction from the centre, or a whole turn), an angle that is not finite or
    /// too large; the reason carries the value.
    ///
    /// ```
    /// use camber_sketch::{Entity, EntityId, Error, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let c = Point2::new(0.0, 0.0);
    /// let err = s.add_entity(Entity::Arc([c, Point2::new(1.0, 0.0), Point2::new(2.0, 0.0)])).unwrap_err();
    /// assert_eq!(err, Error::InvalidArc {
    ///     entity: EntityId(0),
    ///     reason: camber_geom::Error::DegenerateSweep { start: 0.0, end: 0.0 },
    /// });
    /// ```
    #[error("{entity} (arc): {reason}")]
    InvalidArc {
        /// The arc.
        entity: EntityId,
        /// What the kernel refused, with the value.
        reason: camber_geom::Error,
    },
    /// An ellipse or elliptic arc the kernel refuses: a semi-axis that is not positive (the
    /// a-axis vertex at the centre, b ≤ 0), an end at the centre, a sweep of zero, a value that
    /// is not finite; the reason carries the value.
    ///
    /// ```
    /// use camber_sketch::{Entity, EntityId, Error, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let points = [Point2::new(0.0, 0.0), Point2::new(2.0, 0.0)];
    /// let err = s.add_entity(Entity::Ellipse { points, semi_axis_b: -1.0 }).unwrap_err();
    /// assert_eq!(err, Error::InvalidEllipse {
    ///     entity: EntityId(0),
    ///     reason: camber_geom::Error::NonPositiveSemiAxis { axis: "b", value: -1.0 },
    /// });
    /// ```
    #[error("{entity} (ellipse): {reason}")]
    InvalidEllipse {
        /// The ellipse or elliptic arc.
        entity: EntityId,
        /// What the kernel refused, with the value.
        reason: camber_geom::Error,
    },
    /// Two entities that cannot be filleted with the radius asked for: parallel or collinear
    /// lines, a line or curve pair that shares no end or is tangent at it, or a radius whose
    /// tangent points fall beyond an entity's far end or exceed a curve's radius of curvature.
    ///
    /// ```
    /// use camber_sketch::{Error, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let a = s.add_line(Point2::new(0.0, 0.0), Point2::new(1.0, 0.0))?;
    /// let b = s.add_line(Point2::new(0.0, 1.0), Point2::new(1.0, 1.0))?;
    /// assert_eq!(
    ///     s.fillet(a, b, 0.1).unwrap_err().to_string(),
    ///     "cannot fillet entity 0 and entity 1 with radius 0.1: the lines are parallel"
    /// );
    /// # Ok::<(), Error>(())
    /// ```
    #[error("cannot fillet {first} and {second} with radius {radius}: {reason}")]
    FilletImpossible {
        /// The first entity.
        first: EntityId,
        /// The second entity.
        second: EntityId,
        /// The radius asked for.
        radius: f64,
        /// Why, in words.
        reason: &'static str,
    },
    /// An operation that cuts an entity (a fillet's trim of a free-form curve, a split, a trim)
    /// met a constraint reading that entity that it cannot carry to the piece it keeps (one
    /// reading the whole entity, an interior point or a parameter; docs/sketch.md lists what is
    /// carried). Nothing changed.
    ///
    /// ```
    /// use camber_sketch::constraints::Horizontal;
    /// use camber_sketch::{Error, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let a = s.add_line(Point2::new(0.0, 0.0), Point2::new(2.0, 0.0))?;
    /// let b = s.add_line(Point2::new(1.0, -1.0), Point2::new(1.0, 1.0))?;
    /// let h = s.add_constraint(Horizontal::line(a))?;
    /// assert_eq!(
    ///     s.split_at_intersection(a, b, None).unwrap_err(),
    ///     Error::EntityConstrained { entity: a, constraint: h, operation: "split" }
    /// );
    /// # Ok::<(), Error>(())
    /// ```
    #[error("cannot {operation} {entity}: {constraint} reads it and would change meaning")]
    EntityConstrained {
        /// The entity to cut.
        entity: EntityId,
        /// The constraint that reads it.
        constraint: ConstraintId,
        /// "split", "trim" or "fillet".
        operation: &'static str,
    },
    /// A split or trim of an entity where it crosses another found no crossing in the cut
    /// entity's interior.
    ///
    /// ```
    /// use camber_sketch::{Error, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let a = s.add_line(Point2::new(0.0, 0.0), Point2::new(1.0, 0.0))?;
    /// let b = s.add_line(Point2::new(0.0, 1.0), Point2::new(1.0, 1.0))?;
    /// assert_eq!(
    ///     s.split_at_intersection(a, b, None).unwrap_err().to_string(),
    ///     "entity 0 does not cross entity 1 in its interior"
    /// );
    /// # Ok::<(), Error>(())
    /// ```
    #[error("{entity} does not cross {other} in its interior")]
    NoIntersection {
        /// The entity to cut.
        entity: EntityId,
        /// The entity it should cross.
        other: EntityId,
    },
    /// A split or trim without a point to choose by, where the entity crosses the other more
    /// than once: pass the point the crossing should be nearest.
    ///
    /// ```
    /// use camber_sketch::{Error, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let a = s.add_line(Point2::new(-2.0, 0.0), Point2::new(2.0, 0.0))?;
    /// let c = s.add_circle(Point2::new(0.0, 0.0), 1.0)?;
    /// assert_eq!(
    ///     s.split_at_intersection(a, c, None).unwrap_err(),
    ///     Error::AmbiguousIntersection { entity: a, other: c, count: 2 }
    /// );
    /// assert!(s.split_at_intersection(a, c, Some(Point2::new(1.0, 0.0))).is_ok());
    /// # Ok::<(), Error>(())
    /// ```
    #[error("{entity} crosses {other} {count} times: give the point the crossing is nearest")]
    AmbiguousIntersection {
        /// The entity to cut.
        entity: EntityId,
        /// The entity it crosses.
        other: EntityId,
        /// How many crossings there are.
        count: usize,
    },
    /// A trim of a circle or an ellipse ([`crate::Sketch::trim_closed`]) that crosses the
    /// entities given fewer than two times: the arc it keeps needs a crossing at each end.
    #[error(
        "{entity} crosses the entities given {count} time(s): trimming a closed entity needs two crossings"
    )]
    TooFewCrossings {
        /// The circle or ellipse.
        entity: EntityId,
        /// The distinct crossings found.
        count: usize,
    },
    /// A solve that would turn an arc inside out: its end carried past its start (or the
    /// reverse), so that its sweep, read from its blocks, jumps by more than π (from near 0 to
    /// near 2π, say) and the arc becomes its complement on the circle.
    #[error(
        "{entity} (arc) would turn inside out: its sweep would go from {} to {} rad",
        Readable(*before),
        Readable(*after)
    )]
    ArcTurnedInsideOut {
        /// The arc.
        entity: EntityId,
        /// Its sweep before the solve (radians).
        before: f64,
        /// Its sweep after it.
        after: f64,
    },
    /// A point held on an arc's circle that a solve left outside the arc's sweep (it would
    /// be on the circle, not on the arc).
    #[error(
        "{constraint}: the point lies on the arc's circle at {} rad past the nearer end of the arc",
        Readable(*outside)
    )]
    PointOffArc {
        /// The point-on-arc constraint.
        constraint: ConstraintId,
        /// How far (radians) the point's direction lies outside the sweep.
        outside: f64,
    },
    /// An arc held tangent to a line or a circle in its interior whose solved contact (the
    /// foot of the perpendicular from its centre, or the point on the line of centres) lies
    /// on the arc's circle but outside the arc's sweep: the arc's circle touches, the arc does
    /// not.
    #[error(
        "{constraint}: the contact lies on the arc's circle at {} rad past the nearer end of the arc",
        Readable(*outside)
    )]
    ContactOffArc {
        /// The tangency constraint.
        constraint: ConstraintId,
        /// The arc whose sweep the contact misses.
        arc: EntityId,
        /// How far (radians) the contact's direction lies outside the sweep.
        outside: f64,
    },
    /// An entity cannot be removed while constraints read it.
    #[error("{entity} is read by {constraint}")]
    EntityInUse {
        /// The entity.
        entity: EntityId,
        /// A constraint reading it.
        constraint: ConstraintId,
    },
    /// The geometry kernel refused a curve (bad knots, weights, points, …).
    #[error("geometry: {0}")]
    Geometry(#[from] camber_geom::Error),
    /// Dependent constraints whose values contradict each other; nothing was moved.
    #[error("conflicting constraints: {}", ids(constraints))]
    Conflicting {
        /// The constraints owning an inconsistent dependent row.
        constraints: Vec<ConstraintId>,
    },
    /// Consistent dependent constraints while the options forbid dropping them.
    #[error("redundant constraints: {}", ids(constraints))]
    Redundant {
        /// The constraints owning a consistent dependent row.
        constraints: Vec<ConstraintId>,
    },
    /// Constraints still violated after the solve; nothing was moved.
    #[error("constraints not satisfied: {}", residuals(failed))]
    NotSatisfied {
        /// Each failing constraint with its largest absolute residual.
        failed: Vec<(ConstraintId, f64)>,
    },
    /// A constraint that is not affine in the unknowns met a path that only takes affine ones
    /// (the linear solver forced through the options).
    #[error("{constraint} ({name}) is not affine and needs the nonlinear solver")]
    NeedsNonlinear {
        /// The constraint.
        constraint: ConstraintId,
        /// Its residual's name.
        name: String,
    },
    /// The solve would reverse a tangency (a cusp): the tangent no longer points along the
    /// recorded sense. Nothing was moved.
    #[error(
        "{constraint} would flip its tangent orientation (signed dot {})",
        Readable(*dot)
    )]
    OrientationFlipped {
        /// The tangency constraint.
        constraint: ConstraintId,
        /// sense·(C′(u)·T) after the solve (≤ 0).
        dot: f64,
    },
    /// The dragged point cannot move: it is fixed or fully determined by the constraints.
    #[error("{point} cannot be dragged: it is fixed or determined by the constraints")]
    NotDraggable {
        /// The point asked for.
        point: PointRef,
    },
    /// A drag target farther from the sketch's centre than [`crate::drag::MAX_DRAG_REACH`]
    /// times its scale: a slip of the hand or a hostile request, refused before it wrecks the
    /// sketch's numbers (the session keeps its state).
    #[error(
        "the drag target ({}, {}) is too far from the sketch (more than {} from its centre)",
        number(*x), number(*y), number(*reach)
    )]
    DragTargetTooFar {
        /// The target's x.
        x: f64,
        /// The target's y.
        y: f64,
        /// The largest distance from the centre allowed.
        reach: f64,
    },
    /// A drag session finished on a sketch edited since the session began.
    #[error("the sketch changed since the drag began (revision {expected}, now {found})")]
    StaleSession {
        /// The revision the session was built on.
        expected: u64,
        /// The sketch's revision now.
        found: u64,
    },
    /// Any other failure of the constraint solver.
    #[error("solver: {0}")]
    Solve(camber_solve::Error),
    /// A point weight that is not a positive finite number.
    #[error(
        "weight {} of point {index} of entity {entity} is not a positive finite number",
        Readable(*value)
    )]
    InvalidWeight {
        /// The entity.
        entity: EntityId,
        /// The point's index in the entity.
        index: usize,
        /// The offending weight.
        value: f64,
    },
    /// An entity tag that is too long or holds a control character.
    #[error("tag {tag:?} of entity {entity}: {reason}")]
    InvalidTag {
        /// The entity.
        entity: EntityId,
        /// The offending tag (its first 64 characters when longer).
        tag: String,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A number that must be positive (a radius, a distance) is not.
    #[error("{what} {} must be a positive finite number", Readable(*value))]
    NotPositive {
        /// What the number is.
        what: &'static str,
        /// The offending value.
        value: f64,
    },
    /// A number outside the open range its meaning allows (an arc's sweep in (0, 2π)).
    #[error(
        "{what} {} must lie strictly between {} and {}",
        Readable(*value),
        Readable(*min),
        Readable(*max)
    )]
    OutOfRange {
        /// What the number is.
        what: &'static str,
        /// The offending value.
        value: f64,
        /// The open range's lower end.
        min: f64,
        /// Its upper end.
        max: f64,
    },
    /// A constraint relating two entities (or points) was given the same one twice.
    #[error("the constraint relates {entity} to itself")]
    SameEntity {
        /// The entity named twice.
        entity: EntityId,
    },
    /// After the solve, the curve's tangent vanishes at a contact, or an oriented tangent
    /// (a joint's, a recorded tangent direction's) collapses to zero length (a cusp). Nothing
    /// was moved.
    #[error(
        "{constraint} would leave a cusp where it holds: the tangent vanishes (|C′| = {})",
        Readable(*speed)
    )]
    Cusp {
        /// The contact constraint.
        constraint: ConstraintId,
        /// |C′(u)| at the contact.
        speed: f64,
    },
    /// After the solve, the curve crosses the line or circle it should only touch, near the
    /// contact. Nothing was moved.
    #[error(
        "{constraint}: the curve crosses its target at u = {} by {}",
        Readable(*parameter),
        Readable(*depth)
    )]
    ContactCrossed {
        /// The contact constraint.
        constraint: ConstraintId,
        /// A curve parameter on the wrong side.
        parameter: f64,
        /// How far past the target it lies (length units, > 0).
        depth: f64,
    },
    /// An entity or constraint id already taken (entities and constraints share one id space).
    #[error("id {id} is already used by an entity or a constraint")]
    DuplicateId {
        /// The id asked for.
        id: u64,
    },
    /// A method that needs fixed contact targets (iterative displacement) met a contact whose
    /// circle or line may move.
    #[error("{constraint} touches {entity}, which is not fixed")]
    TargetNotFixed {
        /// The contact.
        constraint: ConstraintId,
        /// Its circle or line.
        entity: EntityId,
    },
    /// A custom constraint read from a sketch file whose kind no registry decoded.
    #[error(
        "the custom constraint kind \"{name}\" was not decoded (register it in a CustomRegistry)"
    )]
    UnresolvedCustom {
        /// The kind name in the file.
        name: String,
    },
    /// A custom constraint's plain residual does not declare its block sizes, so its
    /// arguments cannot be checked.
    #[error(
        "the custom residual \"{name}\" does not declare its block sizes (Residual::block_sizes)"
    )]
    UndeclaredBlocks {
        /// The residual's name.
        name: String,
    },
    /// A custom constraint's arguments do not match what its residual reads.
    #[error(
        "the custom residual \"{name}\" reads {expected:?} but the constraint gives {found:?}"
    )]
    CustomArgs {
        /// The residual's name.
        name: String,
        /// The argument kinds the residual declares.
        expected: Vec<crate::ground::vocabulary::ArgKind>,
        /// The argument kinds given.
        found: Vec<crate::ground::vocabulary::ArgKind>,
    },
    /// A custom residual larger than a solve can hold: more rows than
    /// [`crate::constraints::custom::MAX_CUSTOM_ROWS`], or a Jacobian block (rows × unknowns
    /// read) of more than [`crate::constraints::custom::MAX_CUSTOM_JACOBIAN`] entries. Refused
    /// before anything of that size is allocated.
    #[error(
        "the custom residual \"{name}\" declares {rows} rows over {unknowns} unknowns: at most {max_rows} rows and {max_entries} Jacobian entries (rows × unknowns) are allowed"
    )]
    CustomTooLarge {
        /// The residual's name.
        name: String,
        /// The rows it declares.
        rows: usize,
        /// The unknowns its arguments read.
        unknowns: usize,
        /// The most rows allowed.
        max_rows: usize,
        /// The most Jacobian entries allowed.
        max_entries: usize,
    },
    /// An expression (a constraint's rows, a dimension's value) the language refuses: its
    /// message names the column (and the row).
    #[error(transparent)]
    Expression(#[from] camber_expr::Error),
    /// A value set on a constraint whose kind has none ([`crate::Sketch::set_value`]).
    #[error("{constraint} ({kind}) has no value to set")]
    NoValue {
        /// The constraint.
        constraint: ConstraintId,
        /// Its kind.
        kind: &'static str,
    },
    /// A value set on a dimension that follows an expression of the sketch's parameters
    /// ([`crate::Sketch::set_value`] on a dimension bound by
    /// [`crate::Sketch::bind_dimension`]): the next change of a parameter would overwrite it.
    #[error(
        "{constraint}'s value follows the expression `{expression}` at `{path}`: change its parameters, or bind it to a new expression"
    )]
    ValueBound {
        /// The constraint.
        constraint: ConstraintId,
        /// The path of the bound number in the constraint's file form.
        path: String,
        /// The expression it follows.
        expression: String,
    },
    /// A constraint reads a free parameter another constraint does not have.
    #[error("{constraint} reads free parameter {index} of {of}, which it does not have")]
    UnknownFreeParameter {
        /// The constraint reading it.
        constraint: ConstraintId,
        /// The constraint asked.
        of: ConstraintId,
        /// The index asked for.
        index: usize,
    },
    /// A constraint cannot be removed while another reads its free parameters.
    #[error("{constraint} is read by {by}")]
    ConstraintInUse {
        /// The constraint.
        constraint: ConstraintId,
        /// A constraint reading it.
        by: ConstraintId,
    },
    /// A list in an entity's data with the wrong number of entries (a composite curve's
    /// `nodes`, `joins` or `tangents`, the blocks given to rebuild one).
    ///
    /// ```
    /// use camber_sketch::hermite_chain::{HermiteChain, Join};
    /// use camber_sketch::Error;
    /// use nalgebra::{Point2, Vector2};
    /// let e = HermiteChain::try_new(vec![Point2::origin()], vec![], vec![]).unwrap_err();
    /// assert_eq!(e, Error::CountMismatch { field: "nodes", expected: 2, found: 1 });
    /// assert_eq!(e.to_string(), "`nodes` has 1 entries, expected 2");
    /// ```
    #[error("`{field}` has {found} entries, expected {expected}")]
    CountMismatch {
        /// The field.
        field: &'static str,
        /// How many it needs (at least, for `nodes`).
        expected: usize,
        /// How many it has.
        found: usize,
    },
    /// An option out of its range.
    #[error("{what}: {detail}")]
    InvalidOption {
        /// Which option.
        what: &'static str,
        /// What was wrong, with the value.
        detail: String,
    },
}

/// A constraint in words; the drag's own pin row is "the drag target", never its internal id.
fn constraint_name(id: ConstraintId) -> String {
    if id == crate::ground::ids::DRAG_CONSTRAINT {
        "the drag target".to_owned()
    } else if id == crate::ground::ids::ARC_ROW {
        "an arc's own row (its end on its circle)".to_owned()
    } else if id == crate::ground::ids::ELLIPSE_ROW {
        "an elliptic arc's own rows (its ends on its ellipse)".to_owned()
    } else {
        id.to_string()
    }
}

/// "constraint 4, constraint 7" for a list of ids.
fn ids(list: &[ConstraintId]) -> String {
    list.iter()
        .map(|&c| constraint_name(c))
        .collect::<Vec<_>>()
        .join(", ")
}

/// "constraint 4 (|g| = 1.000e-3), …" for failing constraints with their largest residual.
fn residuals(list: &[(ConstraintId, f64)]) -> String {
    list.iter()
        .map(|&(c, g)| format!("{} (|g| = {g:.3e})", constraint_name(c)))
        .collect::<Vec<_>>()
        .join(", ")
}

impl From<camber_solve::Error> for Error {
    fn from(e: camber_solve::Error) -> Self {
        use camber_solve::Error as S;
        match e {
            S::Conflicting { constraints } => Error::Conflicting { constraints },
            S::Redundant { constraints } => Error::Redundant { constraints },
            S::NotSatisfied { failed } => Error::NotSatisfied { failed },
            S::NonlinearNotAvailable { constraint, name } => {
                Error::NeedsNonlinear { constraint, name }
            }
            other => Error::Solve(other),
        }
    }
}

/// Result with camber-sketch's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;

/// A number for a message with few digits: plain between 1e-4 and 1e6, scientific outside
/// (so that 1e308 is not printed with 309 digits).
fn number(x: f64) -> String {
    if x == 0.0 || !x.is_finite() || (1e-4..1e6).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// "an" before a kind name that starts with a vowel ("an arc", "an ellipse"), "a" otherwise.
fn article(kind: &str) -> &'static str {
    if kind.starts_with(['a', 'e', 'i', 'o', 'u']) {
        "an"
    } else {
        "a"
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_wrong_kind_reads_as_english() {
        let wrong = |found| Error::WrongEntityKind {
            entity: EntityId(3),
            expected: "line",
            found,
        };
        assert_eq!(
            wrong("arc").to_string(),
            "entity 3 is an arc, expected line"
        );
        assert_eq!(
            wrong("elliptic arc").to_string(),
            "entity 3 is an elliptic arc, expected line"
        );
        assert_eq!(
            wrong("circle").to_string(),
            "entity 3 is a circle, expected line"
        );
    }
}
