//! The dxf fuzz target: DXF bytes → import → sketch file → export → import again.
//!
//! The promises checked are listed on [`dxf`].

use camber_interop::dxf::{self, Form, ReadOptions};
use camber_sketch::constraints::Coincident;
use camber_sketch::Constraint;

/// The most entities one input may bring in.
const MAX_ENTITIES: usize = 256;

/// Imports `data` as DXF. Promises: the reader returns an error or a sketch; every join it
/// made holds within its tolerance; the sketch saves as a sketch file that loads again with
/// as many entities; when the sketch can be written as DXF, reading either form back gives as
/// many entities and skips nothing.
pub fn dxf(data: &[u8]) {
    let options = ReadOptions {
        max_entities: MAX_ENTITIES,
        max_bytes: super::MAX_INPUT,
        ..ReadOptions::default()
    };
    let Ok(imported) = dxf::read(data, &options) else {
        return;
    };
    let sketch = imported.sketch;
    let count = sketch.entities().count();
    for (id, c) in sketch.constraints() {
        let Constraint::Coincident(Coincident { a, b }) = c else {
            panic!("constraint {id} of an import is not a join: {c:?}");
        };
        let (pa, pb) = (
            sketch.point(*a).expect("a join reads a point"),
            sketch.point(*b).expect("a join reads a point"),
        );
        assert!(
            (pa - pb).norm() <= options.join_tolerance,
            "join {id}: {a} and {b} are {} apart",
            (pa - pb).norm()
        );
    }
    let text = camber_sketch::file::to_json(&sketch).expect("an imported sketch saves");
    let loaded = camber_sketch::file::from_json(&text).expect("a saved import loads");
    assert_eq!(loaded.entities().count(), count);
    for form in [Form::Text, Form::Binary] {
        let Ok(bytes) = dxf::write(&sketch, form) else {
            continue;
        };
        let again = dxf::read(&bytes, &ReadOptions::default()).expect("a written DXF reads");
        assert!(
            again.skipped.is_empty(),
            "{form:?}: written entities are skipped: {:?}",
            again.skipped
        );
        assert_eq!(again.sketch.entities().count(), count, "{form:?}");
    }
}
