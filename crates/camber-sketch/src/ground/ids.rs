//! Stable typed ids of entities and constraints, and references to points of entities.
//!
//! Ids come from a counter of the sketch and are never reused, so they stay valid (or become
//! unknown) across edits; the petgraph node behind an id is an internal detail. Constraint ids
//! are camber-solve's [`ConstraintId`], so solver reports name the sketch's constraints directly.

pub use camber_solve::ConstraintId;

/// A stable entity id (point, line, circle or curve) of a [`crate::Sketch`].
///
/// ```
/// use camber_sketch::EntityId;
/// assert_eq!(EntityId(3).to_string(), "entity 3");
/// ```
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize,
)]
#[serde(transparent)]
pub struct EntityId(pub u64);

impl std::fmt::Display for EntityId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "entity {}", self.0)
    }
}

/// A point of an entity, as constraints and drags refer to it.
///
/// - `Point(e)`: a point entity;
/// - `Control(e, i)`: control point i of a curve; end i ∈ {0, 1} of a line; the centre (i = 0)
///   of a circle;
/// - `Start(e)` / `End(e)`: the curve point C(a) / C(b) at the ends of its domain (for a clamped
///   curve the first / last control point, otherwise a fixed combination of control points).
///
/// ```
/// use camber_sketch::{EntityId, PointRef};
/// let p = PointRef::Control(EntityId(1), 2);
/// assert_eq!(p.entity(), EntityId(1));
/// // In sketch files: {"point": 3}, {"control": [3, 1]}, {"start": 3}, {"end": 3}.
/// assert_eq!(serde_json::to_string(&p)?, r#"{"control":[1,2]}"#);
/// # Ok::<(), serde_json::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum PointRef {
    /// A point entity.
    Point(EntityId),
    /// Control point (line end, circle centre) `index` of an entity.
    Control(EntityId, usize),
    /// The start C(a) of a curve or line.
    Start(EntityId),
    /// The end C(b) of a curve or line.
    End(EntityId),
}

/// In words: "point entity 3", "control point 1 of entity 0", "the start of entity 2", "the
/// end of entity 2".
///
/// ```
/// use camber_sketch::{EntityId, PointRef};
/// assert_eq!(PointRef::Control(EntityId(0), 1).to_string(), "control point 1 of entity 0");
/// ```
impl std::fmt::Display for PointRef {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            PointRef::Point(e) => write!(f, "point {e}"),
            PointRef::Control(e, i) => write!(f, "control point {i} of {e}"),
            PointRef::Start(e) => write!(f, "the start of {e}"),
            PointRef::End(e) => write!(f, "the end of {e}"),
        }
    }
}

impl PointRef {
    /// The entity the point belongs to.
    pub fn entity(self) -> EntityId {
        match self {
            PointRef::Point(e)
            | PointRef::Control(e, _)
            | PointRef::Start(e)
            | PointRef::End(e) => e,
        }
    }
}

/// The constraint id owning the rows that pin a dragged point.
pub const DRAG_CONSTRAINT: ConstraintId = ConstraintId(u64::MAX);

/// The constraint id owning every arc's own row |E − C| − |S − C| = 0 (its end on the circle
/// of its centre and start; `crate::residuals::arc`). Reports call it "an arc's own row".
pub const ARC_ROW: ConstraintId = ConstraintId(u64::MAX - 1);

/// The owner of an elliptic arc's own rows (its start and end on its ellipse,
/// `crate::residuals::ellipse`). Reports call it "an elliptic arc's own rows".
pub const ELLIPSE_ROW: ConstraintId = ConstraintId(u64::MAX - 2);
