//! What an import gives back: the sketch, and every item of the file it left out, with why.

use camber_sketch::Sketch;

/// One item of an input file that an importer did not turn into geometry.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Skipped {
    /// Where the item is in its file, in the file's own terms (a DXF entity's handle and type,
    /// an SVG path command's index and letter).
    pub location: String,
    /// Why it was left out, in a sentence.
    pub reason: String,
}

impl std::fmt::Display for Skipped {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.location, self.reason)
    }
}

/// The result of an import: the sketch built from a file and what was left out.
#[derive(Debug, Clone)]
pub struct Imported {
    /// The sketch, unsolved: the file's geometry as it was, with the constraints the importer
    /// recognised (coincident joins, tangencies).
    pub sketch: Sketch,
    /// Every item the importer did not bring in, in file order.
    pub skipped: Vec<Skipped>,
}
