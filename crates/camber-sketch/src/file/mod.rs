//! Sketch files: a sketch as JSON, with a format version, stable ids, every built-in entity and
//! constraint kind, and user-defined constraint kinds through a [`CustomRegistry`].
//!
//! ```json
//! {
//!   "version": 1,
//!   "entities": [
//!     {"id": 0, "kind": "bezier", "control_points": [[0, 0], [1, 1], [2, 0]]}
//!   ],
//!   "constraints": [
//!     {"id": 1, "kind": "fixed", "target": {"point": {"start": 0}}},
//!     {"id": 2, "kind": "point_at_parameter", "curve": 0, "u": 0.5, "target": {"at": [1, 1]}}
//!   ]
//! }
//! ```
//!
//! Each constraint kind's file form is its own struct's serde form under its tag
//! ([`crate::constraints`]): the fields are named as in Rust, so a new kind needs nothing here.
//! Entities have a file form of their own (private here) and may carry `"tag": "NAME"` (see
//! [`Sketch::set_tag`]). Any constraint may carry
//! `"priority": P` (0–255; absent means 0, required): see [`Sketch::set_priority`].
//!
//! Loading ([`from_json`], [`from_json_with`]) runs in three stages, each reporting its own
//! failures: JSON syntax and numbers (`1e999` is out of range, so no non-finite value gets in);
//! the shape of the document, with the JSON path of the bad field
//! (`at constraints[2].curve: invalid type …`); and the sketch's own checks, through
//! [`Sketch::add_entity_with_id`] and [`Sketch::add_constraint_with_id`], with the id of the
//! offending entity or constraint (`constraint 5 (g1_join): entity 9 does not exist`). Saving
//! ([`to_json`]) writes entities and constraints in id order; loading what was saved gives the
//! same sketch with the same ids, and saving it again gives the same text.
//!
//! The full reference is docs/file-format.md.

use std::collections::BTreeMap;
use std::sync::Arc;

use camber_solve::Priority;
use serde_json::Value;

use crate::constraints::custom::{Arg, Custom};
use crate::constraints::Constraint;
use crate::ground::entity::Entity;
use crate::ground::errors::Error;
use crate::ground::ids::{ConstraintId, EntityId};
use crate::sketch::Sketch;

mod raw;
mod words;

use raw::{RawEntity, RawShape, RawSketch};

/// The format version this build reads and writes.
pub const FORMAT_VERSION: u64 = 1;

/// Why a sketch file could not be read or written. Messages are one plain line.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum FileError {
    /// Not JSON, or a number outside the f64 range.
    #[error("invalid JSON: {message}")]
    Syntax {
        /// serde_json's message, with line and column.
        message: String,
    },
    /// Valid JSON of the wrong shape: a missing or unknown field, a wrong type, an unknown kind.
    #[error("at {path}: {message}")]
    Shape {
        /// The JSON path of the bad value (`constraints[2].curve`).
        path: String,
        /// What is wrong there.
        message: String,
    },
    /// A `version` other than [`FORMAT_VERSION`], or none.
    #[error("unsupported version {found} (this build reads version {FORMAT_VERSION})")]
    Version {
        /// The version found (as written).
        found: String,
    },
    /// The sketch refused an entity (bad knots, weights, radius, a duplicate id, a zero-length
    /// line, …).
    #[error("entity {id} ({kind}): {}", entity_reason(source))]
    Entity {
        /// The entity's id in the file.
        id: u64,
        /// Its kind tag.
        kind: &'static str,
        /// The sketch's reason.
        source: Error,
    },
    /// The sketch refused a constraint (an unknown id, a parameter outside the domain, …).
    #[error("constraint {id} ({kind}): {source}")]
    Constraint {
        /// The constraint's id in the file.
        id: u64,
        /// Its kind tag.
        kind: String,
        /// The sketch's reason.
        source: Error,
    },
    /// A named parameter the sketch refuses (a name that is not one).
    #[error("parameter {name}: {source}")]
    Parameter {
        /// The parameter's name.
        name: String,
        /// The sketch's reason.
        source: Error,
    },
    /// A custom constraint whose kind no [`CustomRegistry`] entry knows.
    #[error("constraint {id}: custom kind \"{name}\" is not registered")]
    UnregisteredCustom {
        /// The constraint's id.
        id: u64,
        /// The kind name asked for.
        name: String,
    },
    /// A registered custom kind refused its parameters.
    #[error("constraint {id}: custom kind \"{name}\": {message}")]
    CustomParams {
        /// The constraint's id.
        id: u64,
        /// The kind name.
        name: String,
        /// The decoder's message.
        message: String,
    },
    /// Saving a custom constraint that carries no file form ([`Custom::with_file_form`]).
    #[error("constraint {id} ({name}) is a custom constraint without a file form")]
    CustomNotSavable {
        /// The constraint's id.
        id: u64,
        /// Its residual's name.
        name: String,
    },
}

/// The sketch's reason for refusing an entity, without naming the entity again.
fn entity_reason(e: &Error) -> String {
    match e {
        Error::DegenerateEntity { reason, .. } => (*reason).to_owned(),
        other => other.to_string(),
    }
}

/// Decodes the parameters of one custom kind into a constraint over the given arguments.
pub type CustomDecoder =
    dyn Fn(&Value, Vec<Arg>) -> std::result::Result<Custom, String> + Send + Sync;

/// User-defined constraint kinds a sketch file may name: kind name → decoder.
///
/// A custom constraint is stored as
/// `{"id": 4, "kind": "custom", "name": "unit_apart", "points": [...], "params": {...}}` (or
/// with `"args"` instead of `"points"` when it reads more than points, see [`Arg`]); on load the
/// decoder registered under `name` receives `params` (`null` when absent) and the arguments,
/// and returns the [`Custom`] constraint (or a message saying what is wrong). The loaded
/// constraint remembers its name and parameters, so saving writes them back.
///
/// ```
/// use camber_sketch::file::{from_json_with, to_json, CustomRegistry};
/// use camber_sketch::{Custom, EntityId, PointRef};
/// use camber_solve::{Residual, Scalar};
/// /// q.x − p.x = gap.
/// #[derive(Debug)]
/// struct Gap(f64);
/// impl Residual for Gap {
///     fn name(&self) -> &str { "gap" }
///     fn dim(&self) -> usize { 1 }
///     fn block_sizes(&self) -> Option<Vec<usize>> { Some(vec![2, 2]) }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
///         out[0] = x[1][0] - x[0][0] - nalgebra::convert::<f64, T>(self.0);
///     }
///     fn is_affine(&self) -> bool { true }
/// }
/// let mut registry = CustomRegistry::new();
/// registry.register("gap", |params, args| {
///     let gap = params.get("gap").and_then(|v| v.as_f64()).ok_or("needs a number \"gap\"")?;
///     Ok(Custom::plain(Gap(gap), args))
/// });
/// let text = r#"{"version": 1,
///   "entities": [{"id": 0, "kind": "point", "at": [0, 0]}, {"id": 1, "kind": "point", "at": [5, 0]}],
///   "constraints": [{"id": 2, "kind": "custom", "name": "gap",
///                    "points": [{"point": 0}, {"point": 1}], "params": {"gap": 2}}]}"#;
/// let mut sketch = from_json_with(text, &registry)?;
/// sketch.solve()?;
/// let (p, q) = (sketch.point(PointRef::Point(EntityId(0)))?, sketch.point(PointRef::Point(EntityId(1)))?);
/// assert!((q.x - p.x - 2.0).abs() < 1e-12);
/// assert!(to_json(&sketch)?.contains("\"gap\""));
/// // Without the registration the file is refused.
/// let err = camber_sketch::file::from_json(text).unwrap_err();
/// assert_eq!(err.to_string(), "constraint 2: custom kind \"gap\" is not registered");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Default)]
pub struct CustomRegistry {
    kinds: BTreeMap<String, Arc<CustomDecoder>>,
}

impl CustomRegistry {
    /// An empty registry.
    pub fn new() -> Self {
        Self::default()
    }

    /// Registers (or replaces) the decoder of the custom kind `name`.
    pub fn register<F>(&mut self, name: impl Into<String>, decoder: F) -> &mut Self
    where
        F: Fn(&Value, Vec<Arg>) -> std::result::Result<Custom, String> + Send + Sync + 'static,
    {
        self.kinds.insert(name.into(), Arc::new(decoder));
        self
    }

    /// Whether `name` is registered.
    pub fn contains(&self, name: &str) -> bool {
        self.kinds.contains_key(name)
    }
}

impl std::fmt::Debug for CustomRegistry {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_set().entries(self.kinds.keys()).finish()
    }
}

/// Reads a sketch file with no custom kinds registered.
///
/// ```
/// let s = camber_sketch::file::from_json(r#"{"version": 1,
///   "entities": [{"id": 3, "kind": "line", "from": [0, 0], "to": [1, 0]}]}"#)?;
/// assert_eq!(s.entities().count(), 1);
/// let bad = camber_sketch::file::from_json(r#"{"version": 1,
///   "entities": [{"id": 0, "kind": "bspline", "degree": 2, "knots": [0, 0, 1, 1],
///                 "control_points": [[0, 0], [1, 1], [2, 0]]}]}"#);
/// assert!(bad.unwrap_err().to_string().starts_with("entity 0 (bspline): geometry:"));
/// # Ok::<(), camber_sketch::file::FileError>(())
/// ```
///
/// # Errors
/// As [`from_json_with`].
pub fn from_json(text: &str) -> std::result::Result<Sketch, FileError> {
    from_json_with(text, &CustomRegistry::new())
}

/// Reads a sketch file; custom constraints are decoded through `registry`. Entities are added
/// first, then constraints, each in file order under its own id. A leading UTF-8 byte order
/// mark is skipped.
///
/// # Errors
/// [`FileError::Syntax`], [`FileError::Version`], [`FileError::Shape`] (with the JSON path),
/// [`FileError::Entity`] / [`FileError::Constraint`] (with the id and the sketch's reason),
/// [`FileError::UnregisteredCustom`], [`FileError::CustomParams`].
pub fn from_json_with(
    text: &str,
    registry: &CustomRegistry,
) -> std::result::Result<Sketch, FileError> {
    // A UTF-8 byte order mark (some editors write one) is not part of the JSON.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let value: Value = serde_json::from_str(text).map_err(|e| FileError::Syntax {
        message: if e.to_string().starts_with("number out of range") {
            format!(
                "non-finite number (outside the f64 range) at line {} column {}",
                e.line(),
                e.column()
            )
        } else {
            e.to_string()
        },
    })?;
    match value.get("version") {
        Some(v) if v.as_u64() == Some(FORMAT_VERSION) => {}
        Some(v) => {
            return Err(FileError::Version {
                found: v.to_string(),
            })
        }
        None if value.is_object() => {
            return Err(FileError::Version {
                found: "(missing)".into(),
            })
        }
        None => {}
    }
    if !value.is_object() {
        return Err(FileError::Shape {
            path: ".".into(),
            message: format!(
                "expected a sketch: an object with \"version\", \"entities\" and \"constraints\", \
                 found {}",
                json_kind(&value)
            ),
        });
    }
    let raw: RawSketch = serde_path_to_error::deserialize(value).map_err(|e| FileError::Shape {
        path: e.path().to_string(),
        message: words::plain_words(&e.inner().to_string()),
    })?;
    let mut sketch = Sketch::new();
    add_entities(&mut sketch, raw.entities)?;
    for (name, value) in &raw.parameters {
        sketch
            .define_parameter(name, *value)
            .map_err(|source| FileError::Parameter {
                name: name.clone(),
                source,
            })?;
    }
    add_constraints(&mut sketch, raw.constraints, registry)?;
    Ok(sketch)
}

/// Adds entities in their file form (each with its `id`, `kind`, optional `tag`), in order.
fn add_entities(sketch: &mut Sketch, entities: Vec<Value>) -> std::result::Result<(), FileError> {
    let entities = entities
        .into_iter()
        .enumerate()
        .map(|(i, v)| load_entity(i, v))
        .collect::<std::result::Result<Vec<_>, _>>()?;
    for e in entities {
        let kind = e.shape.kind();
        let entity = e.shape.into_entity().map_err(|source| FileError::Entity {
            id: e.id,
            kind,
            source,
        })?;
        sketch
            .add_entity_with_id(EntityId(e.id), entity)
            .and_then(|id| sketch.set_tag(id, e.tag.as_deref()))
            .map_err(|source| FileError::Entity {
                id: e.id,
                kind,
                source,
            })?;
    }
    Ok(())
}

/// Adds constraints in their file form (each with its `id`, `kind`, optional `priority`, its
/// numbers possibly expressions of the sketch's parameters), in order.
fn add_constraints(
    sketch: &mut Sketch,
    constraints: Vec<Value>,
    registry: &CustomRegistry,
) -> std::result::Result<(), FileError> {
    for (i, mut value) in constraints.into_iter().enumerate() {
        let priority = load_priority(i, &mut value)?;
        let (id, constraint, bindings) = load_constraint(i, value, registry, sketch.parameters())?;
        let kind = constraint.tag().to_owned();
        sketch
            .add_constraint_with_id(ConstraintId(id), constraint)
            .map_err(|source| FileError::Constraint {
                id,
                kind: kind.clone(),
                source,
            })?;
        sketch.set_bindings(ConstraintId(id), bindings);
        if priority > 0 {
            sketch
                .set_priority(ConstraintId(id), priority)
                .map_err(|source| FileError::Constraint { id, kind, source })?;
        }
    }
    Ok(())
}

/// Adds entities, then constraints, in their file form — the objects of a file's
/// `"entities"` and `"constraints"` arrays, each with its own `id` — to a sketch, as a
/// sketcher adds what a user drew with the constraints inferred from it. Constraints may read
/// the new entities and the sketch's own. All or nothing: when one is refused, the ones
/// already added are removed again and the sketch is as it was. Error paths count from the
/// start of each list (`entities[1].to`). Custom kinds are refused (they need a
/// [`CustomRegistry`]).
///
/// ```
/// use camber_sketch::{file::add_from_values, EntityId, Sketch};
/// use serde_json::json;
/// let mut s = Sketch::new();
/// add_from_values(&mut s,
///     vec![json!({"id": 4, "kind": "line", "from": [0, 0], "to": [2, 0.1]})],
///     vec![json!({"id": 9, "kind": "horizontal", "of": {"line": 4}})])?;
/// assert_eq!(s.constraints().count(), 1);
/// // A constraint on an entity that does not exist: nothing of the call stays.
/// let refused = add_from_values(&mut s,
///     vec![json!({"id": 5, "kind": "point", "at": [1, 1]})],
///     vec![json!({"id": 10, "kind": "vertical", "of": {"line": 77}})]);
/// assert!(refused.unwrap_err().to_string().starts_with("constraint 10 (vertical)"));
/// assert!(s.entity(EntityId(5)).is_err());
/// # Ok::<(), camber_sketch::file::FileError>(())
/// ```
///
/// # Errors
/// As [`from_json_with`] for the entities and constraints of a file.
pub fn add_from_values(
    sketch: &mut Sketch,
    entities: Vec<Value>,
    constraints: Vec<Value>,
) -> std::result::Result<(), FileError> {
    let entities_before: std::collections::BTreeSet<EntityId> =
        sketch.entities().map(|(id, _)| id).collect();
    let constraints_before: std::collections::BTreeSet<ConstraintId> =
        sketch.constraints().map(|(id, _)| id).collect();
    let added = add_entities(sketch, entities)
        .and_then(|()| add_constraints(sketch, constraints, &CustomRegistry::new()));
    if added.is_err() {
        let new_constraints: Vec<ConstraintId> = sketch
            .constraints()
            .map(|(id, _)| id)
            .filter(|id| !constraints_before.contains(id))
            .collect();
        // Newest first: a constraint may read the free parameters of one added before it.
        for id in new_constraints.into_iter().rev() {
            let _ = sketch.remove_constraint(id);
        }
        let new_entities: Vec<EntityId> = sketch
            .entities()
            .map(|(id, _)| id)
            .filter(|id| !entities_before.contains(id))
            .collect();
        for id in new_entities {
            let _ = sketch.remove_entity(id);
        }
    }
    added
}

/// Reads one constraint from its file form without an id (`{"kind": "distance", …}`), as
/// bindings and tools that build constraints from data do. Custom kinds are refused (they need
/// a [`CustomRegistry`]).
///
/// ```
/// use camber_sketch::file::constraint_from_value;
/// let c = constraint_from_value(serde_json::json!(
///     {"kind": "horizontal", "of": {"a": {"point": 0}, "b": {"point": 1}}}))?;
/// assert_eq!(c.tag(), "horizontal");
/// let err = constraint_from_value(serde_json::json!({"kind": "horizontal"})).unwrap_err();
/// assert!(err.to_string().starts_with("at constraints[0]"));
/// # Ok::<(), camber_sketch::file::FileError>(())
/// ```
///
/// # Errors
/// [`FileError::Shape`] (an unknown kind, a missing or malformed field, with its path),
/// [`FileError::UnregisteredCustom`] for a custom kind.
pub fn constraint_from_value(mut value: Value) -> std::result::Result<Constraint, FileError> {
    if let Value::Object(map) = &mut value {
        map.entry("id").or_insert(Value::from(0));
    }
    load_constraint(
        0,
        value,
        &CustomRegistry::new(),
        &crate::sketch::parameters::Parameters::default(),
    )
    .map(|(_, c, _)| c)
}

/// Adds one constraint from its file form without an id (`{"kind": "distance", …}`), its
/// numbers possibly expressions of the sketch's parameters (`"distance": "chord / 2"`, kept as
/// bindings, see [`crate::parameters`]). Custom kinds are refused.
///
/// ```
/// use camber_sketch::{file::add_constraint_from_value, Sketch};
/// let mut s = Sketch::new();
/// let a = s.add_point(nalgebra::Point2::new(0.0, 0.0))?;
/// let b = s.add_point(nalgebra::Point2::new(1.0, 0.0))?;
/// s.define_parameter("chord", 4.0)?;
/// let id = add_constraint_from_value(&mut s, serde_json::json!(
///     {"kind": "distance", "a": {"point": a.0}, "b": {"point": b.0}, "distance": "chord / 2"}))?;
/// assert_eq!(s.parameters().bindings(id)[0].text, "chord / 2");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// As [`constraint_from_value`]; [`FileError::Constraint`] when the sketch refuses it.
pub fn add_constraint_from_value(
    sketch: &mut Sketch,
    mut value: Value,
) -> std::result::Result<ConstraintId, FileError> {
    if let Value::Object(map) = &mut value {
        map.entry("id").or_insert(Value::from(0));
    }
    let (_, c, bindings) = load_constraint(0, value, &CustomRegistry::new(), sketch.parameters())?;
    let kind = c.tag().to_owned();
    let id = sketch
        .add_constraint(c)
        .map_err(|source| FileError::Constraint {
            id: 0,
            kind,
            source,
        })?;
    sketch.set_bindings(id, bindings);
    Ok(id)
}

/// One constraint's file form without its id (`{"kind": …, …fields}`).
///
/// # Errors
/// [`FileError::Syntax`] when serialization fails (it does not for built-in kinds).
pub fn constraint_to_value(constraint: &Constraint) -> std::result::Result<Value, FileError> {
    let text = constraint.save().map_err(|e| FileError::Syntax {
        message: e.to_string(),
    })?;
    serde_json::from_str(&text).map_err(|e| FileError::Syntax {
        message: e.to_string(),
    })
}

/// One entity's file form without its id (`{"kind": "bezier", "control_points": …}`).
///
/// ```
/// use camber_sketch::{file::entity_to_value, Entity};
/// let v = entity_to_value(&Entity::Point(nalgebra::Point2::new(1.0, 2.0)))?;
/// assert_eq!(v, serde_json::json!({"kind": "point", "at": [1.0, 2.0]}));
/// # Ok::<(), camber_sketch::file::FileError>(())
/// ```
///
/// # Errors
/// [`FileError::Syntax`] when serialization fails (it does not for finite geometry).
pub fn entity_to_value(entity: &Entity) -> std::result::Result<Value, FileError> {
    serde_json::to_value(RawShape::from_entity(entity)).map_err(|e| FileError::Syntax {
        message: e.to_string(),
    })
}

/// One entity of a file: its id and shape, with the JSON path of a bad field inside it
/// (`entities[0].control_points[1]: invalid length 3, expected an array of length 2`).
fn load_entity(i: usize, mut value: Value) -> std::result::Result<RawEntity, FileError> {
    let shape = |path: String, message: String| FileError::Shape { path, message };
    let Value::Object(map) = &mut value else {
        return Err(shape(
            format!("entities[{i}]"),
            "expected an object with \"id\" and \"kind\"".into(),
        ));
    };
    let id = match map.remove("id") {
        Some(v) => v.as_u64().ok_or_else(|| {
            shape(
                format!("entities[{i}].id"),
                format!("expected a non-negative integer id, found {v}"),
            )
        })?,
        None => return Err(shape(format!("entities[{i}]"), "missing field `id`".into())),
    };
    let tag = match map.remove("tag") {
        None => None,
        Some(Value::String(t)) => Some(t),
        Some(v) => {
            return Err(shape(
                format!("entities[{i}].tag"),
                format!("expected a tag, a string, found {v}"),
            ))
        }
    };
    let kind = match map.remove("kind") {
        Some(Value::String(k)) => k,
        Some(v) => {
            return Err(shape(
                format!("entities[{i}].kind"),
                format!("expected a kind name, found {v}"),
            ))
        }
        None => {
            return Err(shape(
                format!("entities[{i}]"),
                "missing field `kind`".into(),
            ))
        }
    };
    let mut keyed = serde_json::Map::new();
    keyed.insert(kind, value);
    let shape_of: raw::KeyedShape = serde_path_to_error::deserialize(Value::Object(keyed))
        .map_err(|e| {
            // The path starts with the kind (the key of the keyed form): drop it.
            let path = e.path().to_string();
            let message = words::plain_words(&e.inner().to_string()).replace(
                "expected fewer elements in array",
                "expected a point [x, y] of 2 numbers",
            );
            let (inner, message) = match path.split_once('.') {
                Some((_, rest)) if !rest.is_empty() && rest != "?" => (
                    format!("entities[{i}].{rest}"),
                    message.replace("unknown variant", "unknown value"),
                ),
                // The keyed form's only variant names are the entity kinds.
                _ if message.starts_with("unknown variant") => (
                    format!("entities[{i}].kind"),
                    message.replace("unknown variant", "unknown entity kind"),
                ),
                _ => (format!("entities[{i}]"), message),
            };
            shape(inner, message)
        })?;
    let shape_of: raw::RawShape = shape_of.into();
    if let Some((field, message)) = shape_of
        .arc_form_problem()
        .or_else(|| shape_of.ellipse_form_problem())
    {
        return Err(shape(format!("entities[{i}].{field}"), message));
    }
    Ok(RawEntity {
        id,
        tag,
        shape: shape_of,
    })
}

/// What a JSON value is, for messages: `null`, `an array`, `a number`, …
fn json_kind(value: &Value) -> &'static str {
    match value {
        Value::Null => "null",
        Value::Bool(_) => "true or false",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// A constraint's optional `"priority"` (0–255, 0 when absent), taken out of its object.
fn load_priority(i: usize, value: &mut Value) -> std::result::Result<Priority, FileError> {
    let Value::Object(map) = value else {
        return Ok(0);
    };
    match map.remove("priority") {
        None => Ok(0),
        Some(v) => v
            .as_u64()
            .and_then(|p| Priority::try_from(p).ok())
            .ok_or_else(|| FileError::Shape {
                path: format!("constraints[{i}].priority"),
                message: format!(
                    "expected a priority tier, an integer from 0 (required) to 255, found {v}"
                ),
            }),
    }
}

/// One constraint of a file: its id, and the constraint in its kind's form (a custom one
/// decoded through the registry). `i` is its place in the file, for error paths.
fn load_constraint(
    i: usize,
    mut value: Value,
    registry: &CustomRegistry,
    parameters: &crate::sketch::parameters::Parameters,
) -> std::result::Result<(u64, Constraint, Vec<crate::sketch::parameters::Binding>), FileError> {
    let shape = |path: String, message: String| FileError::Shape { path, message };
    let Value::Object(map) = &mut value else {
        return Err(shape(
            format!("constraints[{i}]"),
            "expected an object with \"id\" and \"kind\"".into(),
        ));
    };
    let id = match map.remove("id") {
        Some(v) => v.as_u64().ok_or_else(|| {
            shape(
                format!("constraints[{i}].id"),
                format!("expected a non-negative integer id, found {v}"),
            )
        })?,
        None => {
            return Err(shape(
                format!("constraints[{i}]"),
                "missing field `id`".into(),
            ))
        }
    };
    let kind = match map.get("kind") {
        Some(Value::String(k)) => k.clone(),
        Some(v) => {
            return Err(shape(
                format!("constraints[{i}].kind"),
                format!("expected a kind name, found {v}"),
            ))
        }
        None => {
            return Err(shape(
                format!("constraints[{i}]"),
                "missing field `kind`".into(),
            ))
        }
    };
    let (constraint, bindings) =
        match crate::sketch::parameters::load_with_dimensions(&kind, value, parameters) {
            Some(Ok(c)) => c,
            Some(Err((path, message))) => {
                let path = if path == "." {
                    format!("constraints[{i}]")
                } else {
                    format!("constraints[{i}].{path}")
                };
                return Err(shape(
                    path,
                    words::plain_words(&message).replace("unknown variant", "unknown value"),
                ));
            }
            None => {
                return Err(shape(
                    format!("constraints[{i}].kind"),
                    format!(
                        "unknown constraint kind `{kind}`, expected one of: {}",
                        Constraint::TAGS.join(", ")
                    ),
                ))
            }
        };
    let Constraint::Custom(custom) = constraint else {
        return Ok((id, constraint, bindings));
    };
    let (name, params) = custom
        .file_form()
        .map(|(n, p)| (n.to_owned(), p.clone()))
        .unwrap_or_default();
    let decode = registry
        .kinds
        .get(&name)
        .ok_or_else(|| FileError::UnregisteredCustom {
            id,
            name: name.clone(),
        })?;
    let decoded =
        decode(&params, custom.args().to_vec()).map_err(|message| FileError::CustomParams {
            id,
            name: name.clone(),
            message,
        })?;
    Ok((id, decoded.with_file_form(name, params).into(), bindings))
}

/// Writes a sketch as file text (one entity or constraint per line, a final newline), entities
/// and constraints in id order. Point weights ([`Sketch::set_weight`]) are not part of the format.
///
/// # Errors
/// [`FileError::CustomNotSavable`] for a custom constraint without a file form.
pub fn to_json(sketch: &Sketch) -> std::result::Result<String, FileError> {
    let entities = sketch
        .entities()
        .map(|(id, e)| RawEntity {
            id: id.0,
            tag: sketch.tag(id).map(str::to_owned),
            shape: RawShape::from_entity(e),
        })
        .collect();
    let mut constraints = Vec::new();
    for (id, c) in sketch.constraints() {
        if let Constraint::Custom(custom) = c {
            if custom.file_form().is_none() {
                return Err(FileError::CustomNotSavable {
                    id: id.0,
                    name: custom.name().to_owned(),
                });
            }
        }
        let mut body = c.save().map_err(|e| FileError::Syntax {
            message: e.to_string(),
        })?;
        let bindings = sketch.parameters().bindings(id);
        if !bindings.is_empty() {
            body = crate::sketch::parameters::with_texts(&body, bindings).map_err(|e| {
                FileError::Syntax {
                    message: e.to_string(),
                }
            })?;
        }
        // {"id": N, "priority": P, "kind": …, …}: the kind's own form behind the id (and the
        // priority, when it is not the default 0).
        let priority = match sketch.priority(id) {
            0 => String::new(),
            p => format!("\"priority\":{p},"),
        };
        constraints.push(format!(
            "{{\"id\":{},{priority}{}",
            id.0,
            body.trim_start_matches('{')
        ));
    }
    // One entity or constraint per line: diffs stay readable and large files compact.
    let enc = |v: &dyn erased::Item| {
        v.encode().map_err(|e| FileError::Syntax {
            message: e.to_string(),
        })
    };
    let entities: Vec<RawEntity> = entities;
    let mut text = format!("{{\n  \"version\": {FORMAT_VERSION},\n");
    if !sketch.parameters().is_empty() {
        let values: std::collections::BTreeMap<&str, f64> = sketch
            .parameters()
            .iter()
            .map(|(n, p)| (n, p.value))
            .collect();
        text.push_str(&format!("  \"parameters\": {},\n", enc(&values)?));
    }
    text.push_str("  \"entities\": [");
    for (i, e) in entities.iter().enumerate() {
        text.push_str(if i == 0 { "\n    " } else { ",\n    " });
        text.push_str(&enc(e)?);
    }
    text.push_str(if entities.is_empty() {
        "],\n"
    } else {
        "\n  ],\n"
    });
    text.push_str("  \"constraints\": [");
    for (i, c) in constraints.iter().enumerate() {
        text.push_str(if i == 0 { "\n    " } else { ",\n    " });
        text.push_str(c);
    }
    text.push_str(if constraints.is_empty() {
        "]\n}\n"
    } else {
        "\n  ]\n}\n"
    });
    Ok(text)
}

/// Compact JSON of one file item (every value is a finite f64, a string or a map with string
/// keys, so encoding cannot fail in practice; a failure is still reported, not unwrapped).
mod erased {
    pub(super) trait Item {
        fn encode(&self) -> serde_json::Result<String>;
    }
    impl<T: serde::Serialize> Item for T {
        fn encode(&self) -> serde_json::Result<String> {
            serde_json::to_string(self)
        }
    }
}
