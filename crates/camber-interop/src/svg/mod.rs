//! SVG paths into sketches: every command of SVG's path data (M L H V C S Q T A Z, absolute
//! and relative) as camber entities, with the joins of each subpath as constraints.
//!
//! ```
//! use camber_interop::svg::{import_path, SvgOptions};
//! use camber_sketch::Entity;
//! // A rounded slot: a line, a half circle, a line back, a half circle home.
//! let slot = import_path("M 0 0 H 10 A 5 5 0 0 1 10 10 H 0 A 5 5 0 0 1 0 0 Z", &SvgOptions::default())?;
//! let kinds: Vec<&str> = slot.sketch.entities().map(|(_, e)| e.kind_name()).collect();
//! assert_eq!(kinds, ["line", "arc", "line", "arc"]);
//! // Four coincident joins, four tangencies (arc to line, with the sense kept).
//! assert_eq!(slot.sketch.constraints().count(), 8);
//! assert!(slot.skipped.is_empty());
//! # Ok::<(), camber_interop::svg::Error>(())
//! ```
//!
//! # What maps to what
//! - `M`/`m` starts a subpath; `L`, `H`, `V` (and `Z` when it draws a side) make
//!   [`Entity::Line`](camber_sketch::Entity::Line)s; `C`/`S` cubic and `Q`/`T` quadratic
//!   [`Entity::Bezier`](camber_sketch::Entity::Bezier)s, `S` and `T` reflecting the previous
//!   `C`/`S` (`Q`/`T`) control point about the current point, as SVG says.
//! - `A` becomes a circular arc when its ellipse, after the transform, is round, else an
//!   elliptic arc; radii of 0 make a line, radii too small to reach both ends are scaled up
//!   (SVG 1.1 F.6.6), ends at one point draw nothing.
//! - Segments without length (within [`SvgOptions::length_tolerance`]) are left out and listed.
//!
//! # Orientation
//! SVG's y axis points down the page. By default ([`Orientation::Upright`]) the importer maps
//! (x, y) ↦ (x, −y) after every SVG transform, so the picture is upright in camber's y-up
//! frame; [`Orientation::Raw`] keeps the user coordinates.
//!
//! # Units
//! Path data is in user units. In a document, lengths in absolute units become user units at
//! 96 px per inch ([`Unit`], [`PX_PER_INCH`]), percentages are of the nearest viewport, nested
//! `svg` viewports are placed by their viewBox; the sketch is in the root's user units
//! ([`SketchUnits::User`], the default: the numbers written in the file) or, on request, in the
//! document's physical size ([`SketchUnits::Physical`]). See [`import_document`].
//!
//! # Joins
//! Consecutive segments of a subpath (and the last and first of a closed one) get a
//! `coincident` constraint; when their directions of travel agree within
//! [`SvgOptions::tangent_tolerance`] (default 10⁻³ rad) a G1 kind too, the one that fits the
//! pair (the table is in docs/interop.md, "SVG paths"). A smooth join of a pair no kind fits (a circular
//! arc with a Bézier or another arc) keeps its coincidence only and is listed in
//! [`Imported::skipped`](crate::Imported::skipped), so the imported sketch states exactly the
//! constraints it holds and no invented ones.

mod affine;
mod arc;
mod build;
mod builder;
mod commands;
mod document;
mod ellipse_map;
mod errors;
mod joins;
mod nesting;
mod options;
mod placement;
mod references;
mod shapes;
mod style;
mod units;
mod viewport;

pub use document::import_document;
pub use ellipse_map::CIRCLE_TOLERANCE;
pub use errors::{Error, Item};
pub use options::{Orientation, SketchUnits, SvgOptions};
pub use units::{Unit, PX_PER_INCH};

use crate::Imported;

/// The sketch of one path's data (the `d` attribute of a `<path>`), in user units, under
/// `options` (see the module documentation).
///
/// ```
/// use camber_interop::svg::{import_path, Orientation, SvgOptions};
/// use camber_sketch::Entity;
/// use nalgebra::Point2;
/// let raw = SvgOptions::default().with_orientation(Orientation::Raw);
/// let two = import_path("M 1 2 l 3 0 v 4", &raw)?;
/// let lines: Vec<&Entity> = two.sketch.entities().map(|(_, e)| e).collect();
/// assert_eq!(lines[1], &Entity::Line([Point2::new(4.0, 2.0), Point2::new(4.0, 6.0)]));
/// // Upright (the default) flips y.
/// let up = import_path("M 1 2 l 3 0", &SvgOptions::default())?;
/// assert_eq!(up.sketch.entities().next().map(|(_, e)| e.points()[0]), Some(Point2::new(1.0, -2.0)));
/// # Ok::<(), camber_interop::svg::Error>(())
/// ```
///
/// # Errors
/// [`Error::InputTooLarge`] above [`SvgOptions::max_input_bytes`] (before reading);
/// [`Error::MalformedPath`], [`Error::NonFinite`], [`Error::TooManySegments`] naming the
/// command; [`Error::Sketch`] if the sketch refuses a join's constraint.
pub fn import_path(d: &str, options: &SvgOptions) -> Result<Imported, Error> {
    if d.len() > options.max_input_bytes {
        return Err(Error::InputTooLarge {
            bytes: d.len(),
            max: options.max_input_bytes,
        });
    }
    let mut b = builder::Builder::new(options);
    b.add_path(
        &Item::PathData,
        svgtypes::PathParser::from(d),
        &affine::Affine::identity(),
    )?;
    Ok(b.finish())
}
