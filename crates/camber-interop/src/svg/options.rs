//! What an SVG import may change: the orientation and units of the result, the tolerances that
//! decide which joins are smooth and which segments have no length, and the work budgets.

use super::units::Unit;

/// What one unit of the sketch is.
///
/// ```
/// use camber_interop::svg::{SketchUnits, SvgOptions, Unit};
/// assert_eq!(SvgOptions::default().units, SketchUnits::User);
/// let mm = SvgOptions::default().with_units(SketchUnits::Physical(Unit::Millimetre));
/// assert_eq!(mm.units, SketchUnits::Physical(Unit::Millimetre));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SketchUnits {
    /// The user units of the root `<svg>` (of its `viewBox` when it has one): the numbers
    /// written in the file's paths and shapes come through unchanged (the default). The root's
    /// `width`, `height` and `preserveAspectRatio` are not applied.
    #[default]
    User,
    /// The document's physical size in the given unit: the root's viewBox-to-viewport map is
    /// applied (its `width` and `height`, converted at 96 px per inch), then px are converted
    /// to the unit. A root without `width` and `height` is taken at one user unit per px.
    Physical(Unit),
}

/// Which way the sketch's y axis points relative to the SVG picture.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Orientation {
    /// (x, y) ↦ (x, −y) after every SVG transform: SVG's y axis points down the page, camber's
    /// up, so the flip keeps the picture upright (the default). A flip reverses every turn, so
    /// an arc drawn clockwise on the page is still clockwise on screen.
    #[default]
    Upright,
    /// SVG user coordinates as they are: the picture appears mirrored top to bottom in a y-up
    /// view.
    Raw,
}

/// Options of [`import_path`](super::import_path) and [`import_document`](super::import_document).
///
/// ```
/// use camber_interop::svg::{Orientation, SvgOptions};
/// let o = SvgOptions::default().with_orientation(Orientation::Raw).with_tangent_tolerance(1e-6);
/// assert_eq!(o.orientation, Orientation::Raw);
/// assert_eq!(o.max_segments, 100_000);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SvgOptions {
    /// y flipped (default) or raw.
    pub orientation: Orientation,
    /// The user units of the root (default) or a physical unit.
    pub units: SketchUnits,
    /// Two segments meeting at an angle of at most this many radians between their
    /// directions of travel get a G1 constraint besides their coincidence. Default 10⁻³ rad
    /// (about 0.06°): loose enough for coordinates written to 3–4 significant digits, tight
    /// enough that no drawn corner passes for smooth.
    pub tangent_tolerance: f64,
    /// A segment whose points all lie within this distance (in the sketch's units) of its
    /// start has no length and is skipped (listed). Default 10⁻⁹.
    pub length_tolerance: f64,
    /// The largest input accepted, in bytes, checked before reading it. Default 8 MiB.
    pub max_input_bytes: usize,
    /// The most drawing segments (path commands that draw, shapes' sides) in one input,
    /// counted while reading, before anything is built. Default 100,000.
    pub max_segments: usize,
    /// The deepest element nesting walked in a document (the root is 0). Default 256.
    pub max_depth: usize,
    /// The most XML nodes a document may have (elements, attributes' text, comments),
    /// checked by the XML reader. Default 1,000,000.
    pub max_nodes: u32,
    /// The most elements drawn through `use` references, each element of a referenced
    /// subtree counted once for every `use` that draws it (a `use` of a group of ten `use`s
    /// of a group of ten shapes counts 1 + 10 + 100 + …). Default 100,000. It bounds the
    /// work of a file whose references multiply (a "use bomb"): the import stops with
    /// [`Error::TooManyUseElements`](super::Error::TooManyUseElements) as the count passes it.
    pub max_use_elements: usize,
}

impl Default for SvgOptions {
    fn default() -> Self {
        Self {
            orientation: Orientation::Upright,
            units: SketchUnits::User,
            tangent_tolerance: 1e-3,
            length_tolerance: 1e-9,
            max_input_bytes: 8 << 20,
            max_segments: 100_000,
            max_depth: 256,
            max_nodes: 1_000_000,
            max_use_elements: 100_000,
        }
    }
}

impl SvgOptions {
    /// With the orientation `o`.
    pub fn with_orientation(self, o: Orientation) -> Self {
        Self {
            orientation: o,
            ..self
        }
    }

    /// With the sketch's units `units`.
    pub fn with_units(self, units: SketchUnits) -> Self {
        Self { units, ..self }
    }

    /// With the budget of elements drawn through references `elements`.
    pub fn with_max_use_elements(self, elements: usize) -> Self {
        Self {
            max_use_elements: elements,
            ..self
        }
    }

    /// With the tangent tolerance `radians`.
    pub fn with_tangent_tolerance(self, radians: f64) -> Self {
        Self {
            tangent_tolerance: radians,
            ..self
        }
    }

    /// With the length tolerance `distance`.
    pub fn with_length_tolerance(self, distance: f64) -> Self {
        Self {
            length_tolerance: distance,
            ..self
        }
    }

    /// With the input budget `bytes`.
    pub fn with_max_input_bytes(self, bytes: usize) -> Self {
        Self {
            max_input_bytes: bytes,
            ..self
        }
    }

    /// With the segment budget `segments`.
    pub fn with_max_segments(self, segments: usize) -> Self {
        Self {
            max_segments: segments,
            ..self
        }
    }

    /// With the nesting budget `depth`.
    pub fn with_max_depth(self, depth: usize) -> Self {
        Self {
            max_depth: depth,
            ..self
        }
    }
}
