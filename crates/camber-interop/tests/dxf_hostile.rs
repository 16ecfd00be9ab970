//! Bad DXF input: truncated, wrong group codes, huge declared counts, NaN and infinite numbers,
//! inputs above the limits. Every one gives a typed error or a listed skip, never a panic.
#![allow(clippy::unwrap_used)] // helpers outside #[test] functions unwrap too

use camber_interop::dxf::{self, Error, Form, ReadOptions};
use camber_sketch::{Entity, Sketch};
use nalgebra::Point2;
use proptest::prelude::*;

fn body(entities: &str) -> String {
    format!("0\nSECTION\n2\nENTITIES\n{entities}0\nENDSEC\n0\nEOF\n")
}

fn read(text: &str) -> Result<camber_interop::Imported, Error> {
    dxf::read(text.as_bytes(), &ReadOptions::default())
}

/// A valid file with several kinds, written by camber itself.
fn sample() -> Vec<u8> {
    let mut s = Sketch::new();
    s.add_entity(Entity::Line([Point2::new(0.0, 0.0), Point2::new(1.0, 0.0)]))
        .unwrap();
    s.add_entity(Entity::Circle {
        center: Point2::new(2.0, 2.0),
        radius: 0.5,
    })
    .unwrap();
    s.add_entity(Entity::Arc([
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 0.0),
        Point2::new(0.0, 1.0),
    ]))
    .unwrap();
    dxf::write(&s, Form::Text).unwrap()
}

#[test]
fn a_file_cut_anywhere_is_an_error_or_a_partial_sketch() {
    let full = sample();
    let text = String::from_utf8(full).unwrap();
    let mut cuts: Vec<usize> = text.match_indices('\n').map(|(i, _)| i + 1).collect();
    // Also inside numbers and names.
    cuts.extend((0..text.len()).step_by(37));
    for cut in cuts {
        let _ = dxf::read(&text.as_bytes()[..cut], &ReadOptions::default());
    }
}

#[test]
fn a_wrong_group_code_is_a_malformed_file() {
    let err = read("0\nSECTION\n2\nENTITIES\n0\nLINE\nten\n0\n0\nENDSEC\n0\nEOF\n").unwrap_err();
    assert!(matches!(err, Error::Malformed { .. }), "{err}");
    let err = read("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\nnot a number\n0\nENDSEC\n0\nEOF\n")
        .unwrap_err();
    assert!(matches!(err, Error::Malformed { .. }), "{err}");
}

#[test]
fn nan_and_infinite_coordinates_are_skipped_with_the_sketch_reason() {
    for bad in ["nan", "NaN", "inf", "1e400", "-1e999"] {
        let im = read(&body(&format!(
            "0\nLINE\n5\nA1\n10\n{bad}\n20\n0\n11\n1\n21\n0\n0\nCIRCLE\n10\n0\n20\n0\n40\n{bad}\n"
        )));
        let Ok(im) = im else { continue }; // refused by the reader: also fine
        assert_eq!(im.sketch.entities().count(), 0, "{bad}");
        assert_eq!(im.skipped.len(), 2, "{bad}: {:?}", im.skipped);
    }
}

#[test]
fn huge_declared_counts_allocate_nothing_and_are_ignored() {
    let im = read(&body(
        "0\nLWPOLYLINE\n90\n2147483647\n70\n0\n10\n0\n20\n0\n10\n1\n20\n0\n\
         0\nSPLINE\n71\n1\n72\n32767\n73\n32767\n40\n0\n40\n0\n40\n1\n40\n1\n\
         10\n0\n20\n0\n30\n0\n10\n1\n20\n1\n30\n0\n",
    ))
    .expect("the counts are not trusted");
    assert_eq!(im.sketch.entities().count(), 2, "{:?}", im.skipped);
}

#[test]
fn a_spline_with_a_huge_degree_or_bad_knots_is_skipped() {
    let im = read(&body(
        "0\nSPLINE\n71\n2000000000\n40\n0\n40\n1\n10\n0\n20\n0\n30\n0\n10\n1\n20\n1\n30\n0\n\
         0\nSPLINE\n71\n1\n40\n1\n40\n0\n40\n1\n40\n1\n10\n0\n20\n0\n30\n0\n10\n1\n20\n1\n30\n0\n\
         0\nSPLINE\n71\n-3\n10\n0\n20\n0\n30\n0\n",
    ))
    .unwrap();
    assert_eq!(im.sketch.entities().count(), 0);
    assert_eq!(im.skipped.len(), 3, "{:?}", im.skipped);
}

#[test]
fn inputs_above_the_limits_are_refused() {
    let text = sample();
    let options = ReadOptions {
        max_bytes: text.len() - 1,
        ..ReadOptions::default()
    };
    assert!(matches!(
        dxf::read(&text, &options),
        Err(Error::TooLarge { .. })
    ));
    let options = ReadOptions {
        max_entities: 2,
        ..ReadOptions::default()
    };
    assert!(matches!(
        dxf::read(&text, &options),
        Err(Error::TooManyEntities { count: 3, limit: 2 })
    ));
    // A polyline counts its segments.
    let mut vertices = String::new();
    for i in 0..10 {
        vertices.push_str(&format!("10\n{i}\n20\n0\n"));
    }
    let polyline = body(&format!("0\nLWPOLYLINE\n70\n0\n{vertices}"));
    let options = ReadOptions {
        max_entities: 5,
        ..ReadOptions::default()
    };
    assert!(matches!(
        dxf::read(polyline.as_bytes(), &options),
        Err(Error::TooManyEntities { .. })
    ));
}

#[test]
fn empty_and_foreign_inputs_are_errors_or_empty() {
    for input in [
        &b""[..],
        b"\n",
        b"0\nEOF\n",
        b"AutoCAD Binary DXF\r\n\x1a\x00\x00\x00",
        b"{\"version\": 1}",
        b"\xff\xfe\x00garbage",
    ] {
        if let Ok(im) = dxf::read(input, &ReadOptions::default()) {
            assert_eq!(im.sketch.entities().count(), 0);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn any_bytes_give_an_error_or_a_sketch(bytes in proptest::collection::vec(any::<u8>(), 0..512)) {
        let _ = dxf::read(&bytes, &ReadOptions::default());
    }

    #[test]
    fn a_valid_file_with_one_byte_changed_gives_an_error_or_a_sketch(
        at in 0usize..10_000, byte in any::<u8>()
    ) {
        let mut bytes = sample();
        let at = at % bytes.len();
        bytes[at] = byte;
        let _ = dxf::read(&bytes, &ReadOptions::default());
    }
}
