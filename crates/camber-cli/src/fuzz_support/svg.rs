//! The svg fuzz target: bytes → SVG import (a document when the text starts with `<`, path
//! data otherwise; a document both in user units and in millimetres).
//!
//! The promises checked are listed on [`svg`].

use camber_interop::svg::{import_document, import_path, SketchUnits, SvgOptions, Unit};
use camber_interop::Imported;
use camber_sketch::Constraint;

use super::{reloads, text};

/// Imports `data` as SVG. Promises: the import returns a typed error or a sketch; every
/// coincident join it made holds as imported (its two points within the length tolerance,
/// relative to the coordinates' size); the sketch saves to a file that loads again. A document
/// is imported in user units and again in millimetres, with the same promises.
pub fn svg(data: &[u8]) {
    let Some(text) = text(data) else { return };
    let options = SvgOptions::default();
    if text.trim_start().starts_with('<') {
        check(import_document(text, &options), &options);
        let mm = options.with_units(SketchUnits::Physical(Unit::Millimetre));
        check(import_document(text, &mm), &mm);
    } else {
        check(import_path(text, &options), &options);
    }
}

fn check(result: Result<Imported, camber_interop::svg::Error>, options: &SvgOptions) {
    let imported = match result {
        Ok(i) => i,
        Err(e) => {
            assert!(!e.to_string().is_empty(), "an error says what is wrong");
            return;
        }
    };
    let s = &imported.sketch;
    for (id, c) in s.constraints() {
        if let Constraint::Coincident(c) = c {
            let (Ok(a), Ok(b)) = (s.point(c.a), s.point(c.b)) else {
                panic!(
                    "coincident join {} reads a point the sketch does not have",
                    id.0
                );
            };
            let size = a.coords.amax().max(b.coords.amax()).max(1.0);
            assert!(
                (a - b).norm() <= options.length_tolerance + 1e-12 * size,
                "coincident join {} is {:e} apart as imported",
                id.0,
                (a - b).norm()
            );
        }
    }
    reloads(s, "the imported sketch");
}
