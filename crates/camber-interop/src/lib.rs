//! camber-interop: geometry in and out of camber sketches.
//!
//! Every importer answers with an [`Imported`]: the sketch it built and the list of what it
//! could not bring in ([`Skipped`]), so nothing in a file is ever dropped silently. Importers
//! and exporters live one format a module.

pub mod dxf;
mod joins;
mod report;
pub mod svg;

pub use report::{Imported, Skipped};
