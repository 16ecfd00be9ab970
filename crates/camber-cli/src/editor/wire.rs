//! The editor's JSON: what the page sends (request bodies) and what it gets back (the scene,
//! the DOF analysis per component, the reports). docs/cli.md describes every field.
//!
//! Geometry goes out as the [`crate::scene`] computes it: control points in full precision,
//! curve samples in f64 (f32 would overflow to null on large drawings), glyphs in model coordinates.

use std::collections::{BTreeMap, BTreeSet};

use anyhow::Result;
use camber_sketch::{Constraint, ConstraintId, Entity, EntityId, Sketch};
use serde::{Deserialize, Serialize};

use crate::draw::{sample_curve, SAMPLES_PER_PIECE};
use crate::scene::{glyphs, kind_word, Glyph, View};

/// `POST /api/drag/start`: the point to drag, as an entity and the index of its point
/// (control point, line end 0 or 1, circle centre 0, point entity 0).
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DragStart {
    /// The entity id.
    pub entity: u64,
    /// The point's index in the entity.
    pub index: usize,
}

/// `POST /api/drag/move`: where the dragged point should go, in model coordinates.
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DragMove {
    /// The target `[x, y]`.
    pub to: [f64; 2],
}

/// One entity as drawn: its points (control points, line ends, circle centre, the point), the
/// radius of a circle, the sampled polyline of a curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EntityJson {
    /// The entity id.
    pub id: u64,
    /// `point`, `line`, `circle`, `arc`, `ellipse`, `elliptic_arc`, `bezier`, `bspline`,
    /// `nurbs`, `hermite` or `composite`.
    pub kind: &'static str,
    /// The entity's points in file order, in full precision, where they are grabbed: a
    /// Hermite or composite curve's tangent blocks at their handles N ± t/3.
    pub points: Vec<[f64; 2]>,
    /// The control polygon to draw when it is not `points` in order (Hermite and composite
    /// curves: nodes and handles, segment by segment).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub polygon: Vec<[f64; 2]>,
    /// A circle's radius.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// Points along a curve (Bézier, B-spline, NURBS, Hermite, composite), an arc, an ellipse
    /// or an elliptic arc, for drawing (see [`outline`]).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub samples: Vec<[f64; 2]>,
}

impl EntityJson {
    /// The drawing of one entity.
    ///
    /// # Errors
    /// A curve that cannot be evaluated (not for an entity the sketch accepted).
    pub fn of(id: EntityId, e: &Entity) -> Result<Self> {
        let samples = outline(e)?;
        Ok(Self {
            id: id.0,
            kind: kind_word(e),
            points: (0..e.points().len())
                .filter_map(|j| e.handle(j))
                .map(|p| [p.x, p.y])
                .collect(),
            polygon: match e {
                Entity::Hermite(_) | Entity::Composite(_) => {
                    e.hull_points().iter().map(|p| [p.x, p.y]).collect()
                }
                _ => Vec::new(),
            },
            radius: match e {
                Entity::Circle { radius, .. } => Some(*radius),
                _ => None,
            },
            samples,
        })
    }
}

/// Points along an entity for drawing: a free-form curve sampled per piece
/// ([`SAMPLES_PER_PIECE`]); a circular or elliptic arc at 65 points evenly in its (parametric)
/// angle, both ends included; a whole ellipse at 129, closed; nothing for points, lines and
/// circles, which the page draws from their own fields (or for an arc whose blocks make none).
///
/// # Errors
/// A curve that cannot be evaluated (not for an entity the sketch accepted).
pub fn outline(e: &Entity) -> Result<Vec<[f64; 2]>> {
    if let Some(c) = e.as_curve() {
        return Ok(sample_curve(c, SAMPLES_PER_PIECE)?
            .iter()
            .map(|p| [p.x, p.y])
            .collect());
    }
    let even = |n: u32, at: &dyn Fn(f64) -> nalgebra::Point2<f64>| -> Vec<[f64; 2]> {
        (0..=n)
            .map(|k| at(f64::from(k) / f64::from(n)))
            .map(|p| [p.x, p.y])
            .collect()
    };
    Ok(match e {
        Entity::Arc(_) => e.as_arc().map(|a| even(64, &|t| a.point(t))),
        Entity::EllipticArc { .. } => e.as_elliptic_arc().map(|a| even(64, &|t| a.point_at(t))),
        Entity::Ellipse { .. } => e
            .as_ellipse()
            .map(|el| even(128, &|t| el.point_at_angle(t * std::f64::consts::TAU))),
        _ => None,
    }
    .unwrap_or_default())
}

/// One glyph of one constraint.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GlyphJson {
    /// The constraint it marks.
    pub constraint: u64,
    /// `arrow`, `fixed`, `ring` or `mark`.
    pub shape: &'static str,
    /// Where it sits.
    pub at: [f64; 2],
    /// An arrow's direction (any length).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dir: Option<[f64; 2]>,
    /// A mark's text ("H", "V", "=", "R", …).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub text: Option<&'static str>,
    /// Whether the DOF analysis names the constraint conflicting (drawn in red).
    pub conflicting: bool,
    /// A name drawn beside the mark with the residual: an expression constraint's `name`
    /// (`expression` when it has none). Other kinds have none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub label: Option<String>,
    /// For a labelled glyph, max |g| over the constraint's rows at the geometry drawn (during
    /// a drag, the drag's current state), when the editor knows it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub residual: Option<f64>,
}

/// The label of a constraint's glyphs: an expression's name.
fn label_of(c: &Constraint) -> Option<String> {
    match c {
        Constraint::Expression(e) if e.name.trim().is_empty() => Some("expression".to_owned()),
        Constraint::Expression(e) => Some(e.name.clone()),
        _ => None,
    }
}

impl GlyphJson {
    fn of(constraint: ConstraintId, g: Glyph, conflicting: bool) -> Self {
        let (shape, at, dir, text) = match g {
            Glyph::Arrow(p, d) => ("arrow", p, Some([d.x, d.y]), None),
            Glyph::Fixed(p) => ("fixed", p, None, None),
            Glyph::Ring(p) => ("ring", p, None, None),
            Glyph::Mark(p, t) => ("mark", p, None, Some(t)),
        };
        Self {
            constraint: constraint.0,
            shape,
            at: [at.x, at.y],
            dir,
            text,
            conflicting,
            label: None,
            residual: None,
        }
    }
}

/// Entities and glyphs: the whole sketch, or the part a drag update changed.
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct SceneJson {
    /// Entities by increasing id.
    pub entities: Vec<EntityJson>,
    /// Glyphs by increasing constraint id.
    pub glyphs: Vec<GlyphJson>,
}

impl SceneJson {
    /// The entities whose ids pass `keep`, and the glyphs of the constraints that read one of
    /// them, as `view` shows them; labelled glyphs ([`GlyphJson::label`]) carry their
    /// constraint's entry of `residuals`.
    ///
    /// # Errors
    /// Evaluation failures (not for a sketch the library accepted).
    pub fn of(
        view: &View,
        conflicting: &BTreeSet<ConstraintId>,
        residuals: &BTreeMap<ConstraintId, f64>,
        keep: impl Fn(EntityId) -> bool,
    ) -> Result<Self> {
        let mut out = Self::default();
        for (id, e) in view.entities() {
            if keep(id) {
                out.entities.push(EntityJson::of(id, e)?);
            }
        }
        for (id, c) in view.sketch().constraints() {
            if c.entities().iter().any(|e| keep(*e)) {
                let red = conflicting.contains(&id);
                let label = label_of(c);
                for g in glyphs(view, c)? {
                    let mut glyph = GlyphJson::of(id, g, red);
                    if label.is_some() {
                        glyph.label.clone_from(&label);
                        glyph.residual = residuals.get(&id).copied();
                    }
                    out.glyphs.push(glyph);
                }
            }
        }
        Ok(out)
    }
}

/// A constraint named by id and kind.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConstraintRef {
    /// The constraint id.
    pub id: u64,
    /// Its kind in words ("G1 join", "tangent to circle", …).
    pub kind: &'static str,
}

impl ConstraintRef {
    /// The id with the kind the sketch gives it ("unknown" for an id it does not hold).
    pub fn of(sketch: &Sketch, id: ConstraintId) -> Self {
        Self {
            id: id.0,
            kind: sketch.constraint(id).map_or("unknown", |c| c.kind_name()),
        }
    }

    /// [`ConstraintRef::of`] for a list.
    pub fn list(sketch: &Sketch, ids: &[ConstraintId]) -> Vec<Self> {
        ids.iter().map(|id| Self::of(sketch, *id)).collect()
    }
}

/// The DOF analysis of one component.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AnalysisJson {
    /// Free unknowns.
    pub free_unknowns: usize,
    /// Rank of the Jacobian.
    pub rank: usize,
    /// Degrees of freedom left.
    pub dof: usize,
    /// Constraints with consistent dependent rows.
    pub redundant: Vec<ConstraintRef>,
    /// Constraints with consistent dependent rows that are still needed (deleting them would
    /// change the sketch).
    pub partly_redundant: Vec<ConstraintRef>,
    /// Constraints with inconsistent dependent rows.
    pub conflicting: Vec<ConstraintRef>,
    /// What can still move, entity by entity (entities not listed are fully determined).
    pub free: Vec<camber_sketch::EntityFreedom>,
    /// Contact parameters that can still slide.
    pub free_parameters: Vec<camber_sketch::ParameterFreedom>,
}

/// One connected component: its ids, its DOF analysis, its largest residual now.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ComponentJson {
    /// Entity ids.
    pub entities: Vec<u64>,
    /// Constraint ids.
    pub constraints: Vec<u64>,
    /// Whether a residual is nonlinear (Newton/SLSQP path) rather than affine.
    pub nonlinear: bool,
    /// The analysis, or `null` for a component too large to analyse here.
    pub analysis: Option<AnalysisJson>,
    /// max |g| over the component's residual rows at the current geometry (during a drag, for
    /// the dragged component, at the drag's current state, as in [`MoveJson`]).
    pub residual: f64,
    /// The constraint owning that largest row, if any row is non-zero.
    pub worst: Option<ConstraintRef>,
}

/// One component's line of a report: what ran, how far from satisfied, how long.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ComponentReportJson {
    /// Entity ids.
    pub entities: Vec<u64>,
    /// The solver (or the drag path) that ran.
    pub solver: String,
    /// Why that solver, or how the drag went.
    pub reason: String,
    /// Degrees of freedom left.
    pub dof: Option<usize>,
    /// Largest residual afterwards.
    pub residual: f64,
    /// Wall-clock time in milliseconds (for a drag: all updates together).
    pub time_ms: f64,
}

/// The outcome of the last solve or drag.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReportJson {
    /// `solve` or `drag`.
    pub action: &'static str,
    /// One sentence for the status line.
    pub summary: String,
    /// One line per component the action touched.
    pub components: Vec<ComponentReportJson>,
}

/// The point a drag session holds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DraggedJson {
    /// The entity.
    pub entity: u64,
    /// The point's index in the entity.
    pub index: usize,
    /// Whether the component takes the linear path (a cached factorization) or Newton.
    pub linear: bool,
}

/// Everything the page shows: `GET /api/state`, and the answer of every action that changes
/// the sketch.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StateJson {
    /// The file the sketch came from.
    pub file: String,
    /// Where `POST /api/save` writes.
    pub output: String,
    /// Whether the sketch differs from what was last loaded or saved.
    pub unsaved: bool,
    /// Whether `POST /api/undo` has something to undo.
    pub can_undo: bool,
    /// Whether `POST /api/redo` has something to redo (an undo not followed by a change).
    pub can_redo: bool,
    /// The drag in progress, if any (the scene then shows its current geometry).
    pub dragging: Option<DraggedJson>,
    /// Every entity and glyph.
    pub scene: SceneJson,
    /// One entry per connected component.
    pub components: Vec<ComponentJson>,
    /// The last solve or drag, if any since the start.
    pub report: Option<ReportJson>,
    /// Every constraint by increasing id, with its residual, its status and its value.
    pub constraints: Vec<ConstraintJson>,
    /// The sketch's named parameters by name.
    pub parameters: Vec<ParameterJson>,
    /// Curves with a cusp or crossing themselves, at the geometry drawn.
    pub warnings: Vec<super::fairness::ShapeWarning>,
    /// An id no entity and no constraint has (one above the largest; entities and
    /// constraints share one space of ids).
    pub next_id: u64,
}

/// The answer to a successful `POST /api/drag/move`: the entities that moved and the glyphs
/// of the constraints reading them, the dragged component's residuals now, and the update's
/// own time.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MoveJson {
    /// Changed entities and their glyphs.
    #[serde(flatten)]
    pub scene: SceneJson,
    /// max |g| over the dragged component's constraint rows at the drag's current state
    /// (what the component's `residual` becomes if the drag ends here).
    pub residual: f64,
    /// The constraint with that largest residual, if any residual is non-zero.
    pub worst: Option<ConstraintRef>,
    /// Each constraint of the dragged component with its max |g| now, by increasing id.
    pub constraint_residuals: Vec<ConstraintResidualJson>,
    /// The moved curves that now have a cusp or cross themselves (not checked when they hold
    /// more than [`super::fairness::MAX_MOVE_SAMPLES`] samples together: the state at the
    /// drag's end has them).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<super::fairness::ShapeWarning>,
    /// Time of `DragSession::update`, in microseconds.
    pub update_us: f64,
    /// Time in the handler up to this answer: parsing the body, the update, rebuilding and
    /// sampling the moved entities, their glyphs (not writing this JSON), in microseconds.
    pub handler_us: f64,
}

/// One constraint's residual during a drag.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConstraintResidualJson {
    /// The constraint id.
    pub id: u64,
    /// max |g| over its rows.
    pub residual: f64,
}

/// `POST /api/save`: where the sketch went, and the state (now saved).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SavedJson {
    /// The file written.
    pub saved: String,
    /// Its size in bytes.
    pub bytes: usize,
    /// The state after saving.
    pub state: StateJson,
}

/// An error answer: one plain sentence.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ErrorJson {
    /// What went wrong.
    pub error: String,
}

/// `POST /api/create`: entities and constraints to add, in their file form, each with the id
/// the page chose for it (from `next_id` of [`StateJson`] up); the
/// constraints may read the new entities. All or nothing.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CreateRequest {
    /// Entities (`{"id": 7, "kind": "line", "from": …, "to": …}`).
    #[serde(default)]
    pub entities: Vec<serde_json::Value>,
    /// Constraints (`{"id": 12, "kind": "horizontal", "of": {"line": 7}}`).
    #[serde(default)]
    pub constraints: Vec<serde_json::Value>,
    /// Whether to solve the touched components afterwards (default `true`).
    #[serde(default = "yes")]
    pub solve: bool,
}

fn yes() -> bool {
    true
}

/// `POST /api/delete`: entities and constraints to remove. The constraints reading a removed
/// entity (or the free parameters of a removed constraint) go with it.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DeleteRequest {
    /// Entity ids.
    #[serde(default)]
    pub entities: Vec<u64>,
    /// Constraint ids.
    #[serde(default)]
    pub constraints: Vec<u64>,
}

/// `POST /api/dimension`: a dimension's new value, a number or an expression of the sketch's
/// parameters (`"chord / 2"`); the sketch is re-solved.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DimensionRequest {
    /// The constraint (a distance, a radius, an angle, an arc length, …).
    pub constraint: u64,
    /// A number, or the text of an expression (a text that reads as a number is one).
    pub value: DimensionValue,
}

/// A dimension's value as typed.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(untagged)]
pub enum DimensionValue {
    /// A number.
    Number(f64),
    /// An expression of the parameters.
    Text(String),
}

/// `POST /api/parameter`: defines or changes a named parameter; the components reading it
/// are re-solved.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ParameterRequest {
    /// The name (a letter or `_`, then letters, digits or `_`).
    pub name: String,
    /// The value.
    pub value: f64,
}

/// `POST /api/fillet`: rounds the corner between two lines or curves with a tangent arc
/// ([`camber_sketch::Sketch::fillet`]).
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FilletRequest {
    /// One line or curve.
    pub first: u64,
    /// The other.
    pub second: u64,
    /// The arc's radius.
    pub radius: f64,
}

/// `POST /api/save-as`: a file name (no folder) in the folder of the current output; it
/// becomes where "Save" writes.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SaveAsRequest {
    /// The file name, ending in `.json`.
    pub file: String,
    /// Whether an existing file may be replaced (default `false`: 409).
    #[serde(default)]
    pub overwrite: bool,
}

/// One constraint as the page lists it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConstraintJson {
    /// The id.
    pub id: u64,
    /// The kind as the file names it (`distance`, `g1`, …).
    pub kind: &'static str,
    /// The kind in words.
    pub name: &'static str,
    /// The entities it reads.
    pub entities: Vec<u64>,
    /// max |g| over its rows at the geometry drawn; `null` for a constraint without rows.
    pub residual: Option<f64>,
    /// `ok`, `redundant`, `partly_redundant` or `conflicting` (from its component's DOF
    /// analysis; `unanalysed` when the component was too large to analyse).
    pub status: &'static str,
    /// A dimension's value.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub value: Option<f64>,
    /// The expression of the parameters the value follows, if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub expression: Option<String>,
}

/// One named parameter.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ParameterJson {
    /// The name.
    pub name: String,
    /// The value.
    pub value: f64,
    /// The constraints reading it.
    pub readers: Vec<u64>,
}
