//! Whole documents: the basic shapes as the paths SVG defines them to be, and everything not
//! imported listed with its element and why.
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

mod svg_support;

use camber_interop::svg::{import_document, Orientation, SvgOptions};
use camber_sketch::Entity;
use svg_support::{entities, p};

fn raw() -> SvgOptions {
    SvgOptions::default().with_orientation(Orientation::Raw)
}

fn kinds(doc: &str) -> Vec<&'static str> {
    let out = import_document(doc, &raw()).unwrap();
    out.sketch.entities().map(|(_, e)| e.kind_name()).collect()
}

#[test]
fn basic_shapes_become_their_paths() {
    let doc = r#"<svg xmlns="http://www.w3.org/2000/svg">
      <line x1="0" y1="0" x2="3" y2="4"/>
      <polyline points="0,0 1,0 1,1"/>
      <polygon points="0 0 2 0 1 1"/>
      <rect x="1" y="1" width="4" height="2"/>
      <rect x="0" y="0" width="10" height="6" rx="2"/>
      <circle cx="1" cy="2" r="3"/>
      <ellipse cx="0" cy="0" rx="3" ry="1"/>
    </svg>"#;
    let out = import_document(doc, &raw()).unwrap();
    assert!(out.skipped.is_empty(), "{:?}", out.skipped);
    let k: Vec<&str> = out.sketch.entities().map(|(_, e)| e.kind_name()).collect();
    let mut expect = vec!["line"; 1 + 2 + 3 + 4];
    expect.extend(["line", "arc", "line", "arc", "line", "arc", "line", "arc"]);
    expect.extend(["circle", "ellipse"]);
    assert_eq!(k, expect);
    let e = entities(&out.sketch);
    assert_eq!(e[0], Entity::Line([p(0.0, 0.0), p(3.0, 4.0)]));
    // The polygon closes from its last point to its first.
    assert_eq!(e[5], Entity::Line([p(1.0, 1.0), p(0.0, 0.0)]));
    // The rounded rectangle's first corner: centre (8, 2), radius 2, from (8, 0) to (10, 2).
    let Entity::Arc([c, s, t]) = e[11] else {
        panic!("{:?}", e[11])
    };
    assert!((c - p(8.0, 2.0)).norm() < 1e-12);
    assert!(
        ((s - p(8.0, 0.0)).norm() < 1e-12 && (t - p(10.0, 2.0)).norm() < 1e-12)
            || ((t - p(8.0, 0.0)).norm() < 1e-12 && (s - p(10.0, 2.0)).norm() < 1e-12)
    );
    assert_eq!(
        e[18],
        Entity::Circle {
            center: p(1.0, 2.0),
            radius: 3.0
        }
    );
}

#[test]
fn a_rect_with_one_radius_uses_it_for_both_and_clamps_it_to_half_a_side() {
    // rx = 5 on a 4-high rectangle: ry = rx = 5 clamps to 2, rx stays 5 (half of 10): the
    // straight sides vanish in both directions, leaving four elliptic quarters.
    assert_eq!(
        kinds(r#"<svg><rect width="10" height="4" rx="5"/></svg>"#),
        ["elliptic arc"; 4]
    );
}

#[test]
fn what_is_not_imported_is_listed_with_its_element() {
    let doc = "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<text>a</text>\n<image href=\"x.png\"/>\n<use href=\"#nowhere\"/>\n<defs><path id=\"p\" d=\"M 0 0 L 1 1\"/></defs>\n<svg viewBox=\"0 0 1 1\"><path d=\"M 0 0 L 1 1\"/></svg>\n<path id=\"empty\"/>\n<rect width=\"2em\" height=\"1\"/>\n<circle r=\"0\"/>\n<g transform=\"scale(0)\"><path d=\"M 0 0 L 1 1\"/></g>\n<blink/>\n<title>not listed</title>\n</svg>";
    let out = import_document(doc, &raw()).unwrap();
    assert_eq!(out.sketch.entities().count(), 0);
    let places: Vec<&str> = out.skipped.iter().map(|s| s.location.as_str()).collect();
    assert_eq!(
        places,
        [
            "<text> (line 2)",
            "<image> (line 3)",
            "<use> (line 4)",
            "<defs> (line 5)",
            "<svg> (line 6)",
            "<path id=\"empty\"> (line 7)",
            "<rect> (line 8)",
            "<circle> (line 9)",
            "<path> (line 10)",
            "<blink> (line 11)",
        ]
    );
    assert!(
        out.skipped[3].reason.contains("1 shape"),
        "{}",
        out.skipped[3]
    );
    assert!(
        out.skipped[2].reason.contains("nowhere"),
        "{}",
        out.skipped[2]
    );
    assert!(
        out.skipped[4].reason.contains("not known"),
        "{}",
        out.skipped[4]
    );
    assert!(out.skipped[6].reason.contains("em"), "{}", out.skipped[6]);
    assert!(
        out.skipped[8].reason.contains("singular"),
        "{}",
        out.skipped[8]
    );
}

#[test]
fn elements_of_other_namespaces_are_passed_over() {
    let doc = r#"<svg xmlns="http://www.w3.org/2000/svg" xmlns:ed="http://editor.example/ns">
      <ed:guide><path d="M 0 0 L 1 1"/></ed:guide><path d="M 0 0 L 2 0"/></svg>"#;
    let out = import_document(doc, &raw()).unwrap();
    assert_eq!(out.sketch.entities().count(), 1);
    assert!(out.skipped.is_empty());
}

#[test]
fn the_segment_budget_counts_over_the_whole_document() {
    let doc = r#"<svg><path d="M 0 0 L 1 0 L 1 1"/><path d="M 5 5 L 6 5 L 6 6"/></svg>"#;
    let few = SvgOptions::default().with_max_segments(3);
    assert!(matches!(
        import_document(doc, &few),
        Err(camber_interop::svg::Error::TooManySegments {
            command: 2,
            max: 3,
            ..
        })
    ));
}
