//! DXF files in and out of sketches, through the `dxf` crate's reader and writer.
//!
//! | sketch entity | DXF entity |
//! | --- | --- |
//! | point | POINT |
//! | line | LINE |
//! | circle | CIRCLE |
//! | arc | ARC (angles in degrees, counter-clockwise) |
//! | ellipse, elliptic arc | ELLIPSE (centre, major axis, ratio, parametric angles) |
//! | Bézier | SPLINE of one span (knots 0 and 1, each p + 1 times) |
//! | B-spline | SPLINE (degree, knots, control points) |
//! | NURBS | rational SPLINE (weights too) |
//! | Hermite, composite | cubic SPLINE over the segments' Bézier points (interior knots 3 times) |
//!
//! Reading also takes LWPOLYLINE and 2D POLYLINE (straight segments become lines, bulged ones
//! arcs, consecutive segments joined), and a SPLINE of one span with clamped knots on [0, 1]
//! comes back as a Bézier curve, so every sketch entity but the Hermite kinds survives a round
//! trip as its own kind. An entity's DXF layer becomes its tag ([`Sketch::set_tag`]) and its
//! tag the layer it is written on (layer `0` when it has none).
//!
//! Geometry must lie in a plane parallel to XY: entities with an extrusion direction other than
//! ±Z, or whose points differ in z, are listed as skipped; a constant z is dropped. An entity
//! with the extrusion −Z (a mirrored arc, circle or polyline) is turned into world
//! coordinates. What the reader does not take (text, hatches, block references, dimensions,
//! splines given by fit points only, 3D polylines and meshes) is listed in
//! [`Imported::skipped`] with its handle, type and reason, never dropped silently.
//!
//! End points of different entities closer than [`ReadOptions::join_tolerance`] are held
//! together by `Coincident` constraints, so a profile drawn as separate lines and arcs imports
//! as one connected sketch. Constraints themselves are not part of a DXF file: writing keeps
//! the geometry only.
//!
//! **Precision.** Both forms keep every number exactly: text writes the shortest decimal that
//! reads back as the same f64 (the vendored `dxf` crate is patched for it, see
//! docs/decisions/0016-patched-dxf.md), binary ([`Form::Binary`]) the f64 bits. So points,
//! knots and weights come back bit for bit; arcs and ellipses pass through their angles
//! (degrees for arcs), which costs a few units of the last place.
//!
//! ```
//! use camber_interop::dxf::{self, Form, ReadOptions};
//! use camber_sketch::{Entity, Sketch};
//! use nalgebra::Point2;
//! let mut s = Sketch::new();
//! let line = s.add_entity(Entity::Line([Point2::new(0.0, 0.0), Point2::new(2.0, 1.0)]))?;
//! s.set_tag(line, Some("OUTLINE"))?;
//! let bytes = dxf::write(&s, Form::Binary)?;
//! let back = dxf::read(&bytes, &ReadOptions::default())?;
//! assert!(back.skipped.is_empty());
//! let (id, entity) = back.sketch.entities().next().expect("one entity");
//! assert_eq!(entity, &Entity::Line([Point2::new(0.0, 0.0), Point2::new(2.0, 1.0)]));
//! assert_eq!(back.sketch.tag(id), Some("OUTLINE"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use camber_sketch::{EntityId, Sketch};

use crate::Imported;

mod plane;
mod read;
mod write;

/// The largest DXF input [`read()`] takes by default, in bytes (256 MiB).
pub const DEFAULT_MAX_BYTES: usize = 256 << 20;

/// The most entities [`read()`] takes from one file by default.
pub const DEFAULT_MAX_ENTITIES: usize = 1_000_000;

/// The most control points or knots of one SPLINE: DXF stores their counts as 16-bit integers.
pub const MAX_SPLINE_ITEMS: usize = i16::MAX as usize;

/// How [`read()`] imports a file.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReadOptions {
    /// End points of different entities at most this far apart (drawing units) are joined by
    /// `Coincident` constraints; 0 joins only equal points, a negative value joins nothing.
    /// Default 1e-9.
    pub join_tolerance: f64,
    /// The largest input taken, in bytes; larger inputs are refused before parsing.
    pub max_bytes: usize,
    /// The most entities taken from one file.
    pub max_entities: usize,
}

impl Default for ReadOptions {
    fn default() -> Self {
        Self {
            join_tolerance: 1e-9,
            max_bytes: DEFAULT_MAX_BYTES,
            max_entities: DEFAULT_MAX_ENTITIES,
        }
    }
}

/// The encoding [`write()`] produces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Form {
    /// ASCII DXF: readable, every number in its shortest exact decimal form.
    #[default]
    Text,
    /// Binary DXF: numbers as their f64 bits; smaller and faster to read.
    Binary,
}

/// Why a DXF file could not be read or a sketch written as DXF.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// The input is larger than [`ReadOptions::max_bytes`].
    #[error("the DXF input has {size} bytes, above the limit of {limit}")]
    TooLarge {
        /// The input's size, in bytes.
        size: usize,
        /// The limit.
        limit: usize,
    },
    /// The file has more entities than [`ReadOptions::max_entities`].
    #[error("the DXF file has {count} entities, above the limit of {limit}")]
    TooManyEntities {
        /// How many it has.
        count: usize,
        /// The limit.
        limit: usize,
    },
    /// The input is not a DXF file the reader understands.
    #[error("not a readable DXF file: {message}")]
    Malformed {
        /// The reader's own words.
        message: String,
    },
    /// A curve has more control points or knots than a DXF SPLINE can count.
    #[error(
        "entity {entity} has {count} {what}, more than the {MAX_SPLINE_ITEMS} a DXF SPLINE can hold"
    )]
    SplineTooLarge {
        /// The entity.
        entity: EntityId,
        /// "control points" or "knots".
        what: &'static str,
        /// How many it has.
        count: usize,
    },
    /// An entity's tag cannot be a DXF layer name.
    #[error("the tag {tag:?} of entity {entity} is not a DXF layer name: {reason}")]
    LayerName {
        /// The entity.
        entity: EntityId,
        /// Its tag.
        tag: String,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// The DXF writer failed.
    #[error("writing DXF: {message}")]
    Write {
        /// The writer's own words.
        message: String,
    },
    /// The sketch refused a join the reader built (an internal inconsistency).
    #[error("building the sketch: {0}")]
    Sketch(#[from] camber_sketch::Error),
}

/// Reads a DXF file (text or binary) into a sketch: every entity it can take as a sketch
/// entity, joins as `Coincident` constraints, and the list of what it left out.
///
/// # Errors
/// [`Error::TooLarge`] before parsing an input above [`ReadOptions::max_bytes`];
/// [`Error::Malformed`] for input the DXF reader rejects (truncated, wrong group codes, bad
/// numbers); [`Error::TooManyEntities`]. An entity that is valid DXF but not valid geometry (a
/// zero radius, NaN, bad knots) is not an error: it is listed in [`Imported::skipped`].
pub fn read(bytes: &[u8], options: &ReadOptions) -> Result<Imported, Error> {
    if bytes.len() > options.max_bytes {
        return Err(Error::TooLarge {
            size: bytes.len(),
            limit: options.max_bytes,
        });
    }
    read::read(bytes, options)
}

/// Writes a sketch as a DXF file (AutoCAD 2000 format, which every current reader takes).
///
/// # Errors
/// [`Error::SplineTooLarge`] for a curve with more than [`MAX_SPLINE_ITEMS`] control points or
/// knots; [`Error::LayerName`] for a tag that is not a valid layer name; [`Error::Write`].
pub fn write(sketch: &Sketch, form: Form) -> Result<Vec<u8>, Error> {
    write::write(sketch, form)
}
