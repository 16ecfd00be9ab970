//! Hostile input gives a typed error naming where, quickly, and never a panic.
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

use std::time::{Duration, Instant};

use camber_interop::svg::{import_document, import_path, Error, Item, SvgOptions};

fn path_err(d: &str) -> Error {
    import_path(d, &SvgOptions::default()).unwrap_err()
}

#[test]
fn truncated_and_malformed_data_name_the_command() {
    for (d, command) in [
        ("M 0 0 L 1", 1),
        ("M 0 0 C 1 1 2 2", 1),
        ("M 0 0 A 1 1 0 1", 1),
        ("M 0 0 A 1 1 0 2 0 3 3", 1),
        ("L 1 1", 0),
        ("M 0 0 L 1 1 Z 4", 3),
        ("M 0 0 L NaN 1", 1),
        ("M 0 0 L inf 1", 1),
        ("M 0 0 L 1e999 0", 1),
    ] {
        match path_err(d) {
            Error::MalformedPath {
                item: Item::PathData,
                command: c,
                ..
            } => assert_eq!(c, command, "{d}"),
            other => panic!("{d}: {other:?}"),
        }
    }
}

#[test]
fn overflowing_points_and_transforms_are_non_finite_errors() {
    assert!(matches!(
        path_err("M 1e308 1e308 l 1e308 0"),
        Error::NonFinite {
            command: 1,
            letter: 'l',
            what: "x",
            ..
        }
    ));
    let doc = r#"<svg><g transform="scale(1e200)"><path transform="scale(1e200)" d="M 0 0 L 1 1"/></g></svg>"#;
    assert!(matches!(
        import_document(doc, &SvgOptions::default()),
        Err(Error::MalformedAttribute {
            attribute: "transform",
            ..
        })
    ));
}

#[test]
fn huge_but_finite_numbers_import_or_are_listed() {
    // Radii near f64's extremes: the centre form is computed in the unit circle's frame.
    let out = import_path(
        "M 0 0 A 1e300 1e300 0 0 1 1e300 1e300",
        &SvgOptions::default(),
    )
    .unwrap();
    assert_eq!(out.sketch.entities().count() + out.skipped.len(), 1);
    let out = import_path(
        "M 0 0 A 1e-300 1e-300 0 0 1 1e300 0",
        &SvgOptions::default(),
    )
    .unwrap();
    assert_eq!(out.sketch.entities().count() + out.skipped.len(), 1);
}

#[test]
fn a_million_commands_stop_at_the_segment_budget_quickly() {
    let d = format!("M 0 0 {}", "l 1 1 ".repeat(1_000_000));
    let start = Instant::now();
    let e = path_err(&d);
    assert_eq!(
        e,
        Error::TooManySegments {
            item: Item::PathData,
            command: 100_001,
            max: 100_000
        }
    );
    assert!(
        start.elapsed() < Duration::from_secs(5),
        "{:?}",
        start.elapsed()
    );
    // The byte budget is checked before reading.
    let small = SvgOptions::default().with_max_input_bytes(1000);
    assert!(matches!(
        import_path(&d, &small),
        Err(Error::InputTooLarge { max: 1000, .. })
    ));
}

#[test]
fn deep_nesting_is_refused_at_the_depth_budget() {
    let n = 100_000;
    let doc = format!(
        "<svg>{}<path d='M 0 0 L 1 1'/>{}</svg>",
        "<g>".repeat(n),
        "</g>".repeat(n)
    );
    let start = Instant::now();
    let e = import_document(&doc, &SvgOptions::default()).unwrap_err();
    assert!(
        matches!(
            e,
            Error::TooDeep {
                depth: 257,
                max: 256,
                ..
            }
        ),
        "{e:?}"
    );
    assert!(
        start.elapsed() < Duration::from_secs(5),
        "{:?}",
        start.elapsed()
    );
}

#[test]
fn broken_xml_and_other_roots_are_refused() {
    for doc in [
        "",
        "<svg",
        "<svg><g></svg>",
        "not xml at all",
        "<svg>&undefined;</svg>",
    ] {
        assert!(
            matches!(
                import_document(doc, &SvgOptions::default()),
                Err(Error::Xml { .. })
            ),
            "{doc}"
        );
    }
    assert_eq!(
        import_document("<svg:svg xmlns:svg='x'/>", &SvgOptions::default())
            .map(|i| i.sketch.entities().count()),
        Ok(0)
    );
    // A billion laughs is bounded by the XML reader.
    let laughs = r#"<?xml version="1.0"?><!DOCTYPE lolz [<!ENTITY lol "lol"><!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;"><!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;"><!ENTITY lol4 "&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;"><!ENTITY lol5 "&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;"><!ENTITY lol6 "&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;"><!ENTITY lol7 "&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;"><!ENTITY lol8 "&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;"><!ENTITY lol9 "&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;">]><svg><title>&lol9;</title></svg>"#;
    let start = Instant::now();
    let _ = import_document(laughs, &SvgOptions::default());
    assert!(start.elapsed() < Duration::from_secs(5));
}

#[test]
fn errors_in_documents_name_the_element_by_id_and_line() {
    let doc = "<svg>\n<g>\n<path id=\"wing\" d=\"M 0 0 L 1\"/>\n</g>\n</svg>";
    let e = import_document(doc, &SvgOptions::default()).unwrap_err();
    let wing = Item::Element {
        tag: "path".into(),
        id: Some("wing".into()),
        line: 3,
    };
    assert!(
        matches!(&e, Error::MalformedPath { item, command: 1, .. } if *item == wing),
        "{e:?}"
    );
    assert!(
        e.to_string()
            .starts_with("<path id=\"wing\"> (line 3), command 1: malformed path data"),
        "{e}"
    );
}
