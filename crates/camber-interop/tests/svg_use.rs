//! `use` references and what is not drawn: instances placed by hand-worked maps, `display`
//! and `visibility`, definitions drawn only where referenced, and hostile references (loops,
//! deep chains, bombs) refused with typed errors.
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

mod svg_support;

use std::time::{Duration, Instant};

use approx::assert_relative_eq;
use camber_interop::svg::{import_document, Error, Orientation, SvgOptions};
use camber_sketch::Entity;
use nalgebra::Point2;
use svg_support::{entities, p};

fn raw() -> SvgOptions {
    SvgOptions::default().with_orientation(Orientation::Raw)
}

fn lines(doc: &str) -> Vec<[Point2<f64>; 2]> {
    let out = import_document(doc, &raw()).unwrap();
    entities(&out.sketch)
        .into_iter()
        .map(|e| match e {
            Entity::Line(ends) => ends,
            other => panic!("{other:?}"),
        })
        .collect()
}

fn assert_line(got: [Point2<f64>; 2], want: [Point2<f64>; 2]) {
    for (a, b) in got.iter().zip(want) {
        assert_relative_eq!(*a, b, epsilon = 1e-12);
    }
}

#[test]
fn a_use_draws_its_reference_translated_after_its_own_transform() {
    // The instance's map: rotate(90) · translate(10, 5) · scale(2).
    // (0, 0) → (0, 0) → (10, 5) → (−5, 10); (1, 0) → (2, 0) → (12, 5) → (−5, 12).
    for href in ["href", "xlink:href"] {
        let doc = format!(
            r##"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink">
              <defs><path id="p" d="M 0 0 L 1 0" transform="scale(2)"/></defs>
              <use {href}="#p" x="10" y="5" transform="rotate(90)"/></svg>"##
        );
        let l = lines(&doc);
        assert_eq!(l.len(), 1, "{href}");
        assert_line(l[0], [p(-5.0, 10.0), p(-5.0, 12.0)]);
    }
}

#[test]
fn a_referenced_element_outside_defs_is_drawn_where_it_stands_and_again() {
    let doc = r##"<svg><line id="a" x1="0" y1="0" x2="1" y2="0"/><use href="#a" y="3"/><use href="#a" x="2"/></svg>"##;
    let l = lines(doc);
    assert_eq!(l.len(), 3);
    assert_line(l[0], [p(0.0, 0.0), p(1.0, 0.0)]);
    assert_line(l[1], [p(0.0, 3.0), p(1.0, 3.0)]);
    assert_line(l[2], [p(2.0, 0.0), p(3.0, 0.0)]);
}

#[test]
fn uses_of_uses_compose_their_translations() {
    // u2 draws g (holding a use of the line at x = 1) at x = 10, inside a group at y = 100.
    let doc = r##"<svg><defs><line id="l" x1="0" y1="0" x2="1" y2="0"/><g id="g"><use href="#l" x="1"/></g></defs>
      <g transform="translate(0 100)"><use href="#g" x="10"/></g></svg>"##;
    let l = lines(doc);
    assert_eq!(l.len(), 1);
    assert_line(l[0], [p(11.0, 100.0), p(12.0, 100.0)]);
}

#[test]
fn a_symbol_is_placed_as_a_viewport_of_the_use_size() {
    // viewBox 0 0 10 10 into the use's 20 × 20 at (5, 5): scale 2.
    let doc = r##"<svg><symbol id="s" viewBox="0 0 10 10"><line x1="0" y1="0" x2="10" y2="10"/></symbol>
      <use href="#s" x="5" y="5" width="20" height="20"/></svg>"##;
    let l = lines(doc);
    assert_eq!(l.len(), 1);
    assert_line(l[0], [p(5.0, 5.0), p(25.0, 25.0)]);
    // An unreferenced symbol is listed, not drawn.
    let out = import_document(
        r#"<svg><symbol id="s"><line x1="0" y1="0" x2="1" y2="1"/></symbol></svg>"#,
        &raw(),
    )
    .unwrap();
    assert_eq!(out.sketch.entities().count(), 0);
    assert!(
        out.skipped[0].reason.contains("1 shape"),
        "{}",
        out.skipped[0]
    );
}

#[test]
fn definitions_list_only_the_shapes_no_use_draws() {
    let doc = r##"<svg><defs><path id="drawn" d="M 0 0 L 1 0"/><path d="M 0 0 L 0 1"/><g id="grp"><circle r="1"/></g></defs>
      <use href="#drawn"/><use href="#grp"/><clipPath><rect width="1" height="1"/></clipPath></svg>"##;
    let out = import_document(doc, &raw()).unwrap();
    let kinds: Vec<&str> = out.sketch.entities().map(|(_, e)| e.kind_name()).collect();
    assert_eq!(kinds, ["line", "circle"]);
    let places: Vec<&str> = out.skipped.iter().map(|s| s.location.as_str()).collect();
    assert_eq!(places, ["<defs> (line 1)", "<clipPath> (line 2)"]);
    assert!(
        out.skipped[0].reason.contains("the 1 shape(s)"),
        "{}",
        out.skipped[0]
    );
}

#[test]
fn references_that_lead_nowhere_are_listed() {
    let doc = "<svg>\n<use href=\"#missing\"/>\n<use href=\"parts.svg#bolt\"/>\n<use/>\n<defs><clipPath id=\"c\"><rect width=\"1\" height=\"1\"/></clipPath></defs>\n<use href=\"#c\"/>\n</svg>";
    let out = import_document(doc, &raw()).unwrap();
    assert_eq!(out.sketch.entities().count(), 0);
    let places: Vec<&str> = out.skipped.iter().map(|s| s.location.as_str()).collect();
    assert_eq!(
        places,
        [
            "<use> (line 2)",
            "<use> (line 3)",
            "<use> (line 4)",
            "<defs> (line 5)",
            "<use> (line 6)"
        ]
    );
    assert!(out.skipped[0].reason.contains("#missing"));
    assert!(out.skipped[1].reason.contains("other files"));
    assert!(out.skipped[4].reason.contains("clipPath"));
}

#[test]
fn display_none_leaves_out_the_element_and_its_content_listed() {
    // An editor's hidden layer, a hidden path by attribute, and a use of a hidden element.
    let doc = "<svg>\n<g style=\"display:none\" id=\"layer2\"><path d=\"M 0 0 L 1 0\"/><path d=\"M 0 0 L 0 1\"/></g>\n<path display=\"none\" d=\"M 0 0 L 2 0\"/>\n<path d=\"M 0 0 L 3 0\"/>\n<g display=\"none\"><title>nothing drawn, not listed</title></g>\n</svg>";
    let out = import_document(doc, &raw()).unwrap();
    assert_eq!(out.sketch.entities().count(), 1);
    let places: Vec<&str> = out.skipped.iter().map(|s| s.location.as_str()).collect();
    assert_eq!(places, ["<g id=\"layer2\"> (line 2)", "<path> (line 3)"]);
    assert!(out.skipped[0].reason.contains("display is none"));
}

#[test]
fn visibility_hides_shapes_and_a_descendant_may_show_again() {
    let doc = "<svg>\n<g visibility=\"hidden\">\n<path d=\"M 0 0 L 1 0\"/>\n<path style=\"visibility: visible\" d=\"M 0 0 L 2 0\"/>\n</g>\n<path style=\"fill:none;visibility:collapse\" d=\"M 0 0 L 3 0\"/>\n</svg>";
    let out = import_document(doc, &raw()).unwrap();
    let l: Vec<Entity> = entities(&out.sketch);
    assert_eq!(l, [Entity::Line([p(0.0, 0.0), p(2.0, 0.0)])]);
    let places: Vec<&str> = out.skipped.iter().map(|s| s.location.as_str()).collect();
    assert_eq!(places, ["<path> (line 3)", "<path> (line 6)"]);
    assert!(out.skipped[0].reason.contains("visibility is hidden"));
    // A hidden use hides its instance.
    let doc = r##"<svg><defs><path id="p" d="M 0 0 L 1 0"/></defs><use href="#p" visibility="hidden"/></svg>"##;
    let out = import_document(doc, &raw()).unwrap();
    assert_eq!(out.sketch.entities().count(), 0);
    assert_eq!(out.skipped.len(), 1);
}

#[test]
fn a_style_sheet_is_listed_as_not_read() {
    let out = import_document(
        r#"<svg><style>.hidden { display: none }</style><path class="hidden" d="M 0 0 L 1 0"/></svg>"#,
        &raw(),
    )
    .unwrap();
    assert_eq!(out.sketch.entities().count(), 1);
    assert_eq!(out.skipped.len(), 1);
    assert!(out.skipped[0].reason.contains("style sheets"));
}

#[test]
fn self_and_mutual_references_are_loops() {
    for (doc, href) in [
        (r##"<svg><use id="u" href="#u"/></svg>"##, "#u"),
        (
            r##"<svg><g id="g"><path d="M 0 0 L 1 0"/><use href="#g"/></g></svg>"##,
            "#g",
        ),
        (r##"<svg id="root"><use href="#root"/></svg>"##, "#root"),
        (
            r##"<svg><defs><g id="a"><use href="#b"/></g><g id="b"><use href="#a"/></g></defs><use href="#a"/></svg>"##,
            "#a",
        ),
    ] {
        match import_document(doc, &raw()) {
            Err(Error::ReferenceLoop { href: h, .. }) => assert_eq!(h, href, "{doc}"),
            other => panic!("{doc}: {other:?}"),
        }
    }
}

#[test]
fn a_long_chain_of_uses_is_refused_by_the_depth_budget() {
    // u0 → u1 → … → u9999, each a separate element at the top level.
    let mut doc = String::from("<svg>");
    for k in 0..10_000 {
        doc += &format!(r##"<use id="u{k}" href="#u{}"/>"##, k + 1);
    }
    doc += r#"<path id="u10000" d="M 0 0 L 1 0"/></svg>"#;
    let t = Instant::now();
    assert!(matches!(
        import_document(&doc, &raw()),
        Err(Error::TooDeep { max: 256, .. })
    ));
    assert!(t.elapsed() < Duration::from_secs(5), "{:?}", t.elapsed());
}

#[test]
fn a_use_bomb_is_refused_by_the_element_budget_quickly() {
    // Ten levels of ten uses of the level below: 10¹⁰ lines if drawn.
    let mut doc = String::from(r#"<svg><defs><path id="l0" d="M 0 0 L 1 0"/>"#);
    for k in 1..=10 {
        doc += &format!(r#"<g id="l{k}">"#);
        for _ in 0..10 {
            doc += &format!(r##"<use href="#l{}"/>"##, k - 1);
        }
        doc += "</g>";
    }
    doc += r##"</defs><use href="#l10"/></svg>"##;
    let t = Instant::now();
    assert!(matches!(
        import_document(&doc, &raw()),
        Err(Error::TooManyUseElements { max: 100_000, .. })
    ));
    assert!(t.elapsed() < Duration::from_secs(5), "{:?}", t.elapsed());
    // Within a budget it draws every instance: 1 + 10 (uses) + 10 (lines) elements.
    let small = r##"<svg><defs><path id="l0" d="M 0 0 L 1 0"/><g id="l1"><use href="#l0"/><use href="#l0" x="1"/></g></defs><use href="#l1"/></svg>"##;
    let tight = raw().with_max_use_elements(5);
    assert_eq!(
        import_document(small, &tight)
            .unwrap()
            .sketch
            .entities()
            .count(),
        2
    );
    let tighter = raw().with_max_use_elements(4);
    assert!(matches!(
        import_document(small, &tighter),
        Err(Error::TooManyUseElements { max: 4, .. })
    ));
}

#[test]
fn bad_use_offsets_are_typed_errors() {
    for doc in [
        r##"<svg><path id="p" d="M 0 0 L 1 0"/><use href="#p" x="NaN"/></svg>"##,
        r##"<svg><path id="p" d="M 0 0 L 1 0"/><use href="#p" y="1e999"/></svg>"##,
        r##"<svg><path id="p" d="M 0 0 L 1 0"/><use href="#p" x="3 furlongs"/></svg>"##,
    ] {
        assert!(
            matches!(
                import_document(doc, &raw()),
                Err(Error::MalformedAttribute { .. })
            ),
            "{doc}"
        );
    }
    // An offset that overflows the drawing is a non-finite error, not infinities.
    let doc = r##"<svg><path id="p" d="M 0 0 L 1 0"/><use href="#p" x="1e308" transform="scale(1e10)"/></svg>"##;
    assert!(import_document(doc, &raw()).is_err());
}

#[test]
fn a_use_bomb_of_a_large_hidden_group_costs_no_more_than_its_budget() {
    // A hidden group of 20,000 paths drawn 10⁵ times: asking 10⁵ times whether it holds
    // shapes would walk 2·10⁹ elements; it is asked once.
    let mut doc = String::from(r#"<svg><defs><g id="l0" display="none">"#);
    for _ in 0..20_000 {
        doc += r#"<path d="M 0 0 L 1 0"/>"#;
    }
    doc += "</g>";
    for k in 1..=5 {
        doc += &format!(r#"<g id="l{k}">"#);
        for _ in 0..10 {
            doc += &format!(r##"<use href="#l{}"/>"##, k - 1);
        }
        doc += "</g>";
    }
    doc += r##"</defs><use href="#l5"/></svg>"##;
    let t = Instant::now();
    assert!(matches!(
        import_document(&doc, &raw()),
        Err(Error::TooManyUseElements { .. })
    ));
    assert!(t.elapsed() < Duration::from_secs(5), "{:?}", t.elapsed());
}

#[test]
fn definitions_inside_a_drawn_group_are_listed_once() {
    let doc = r##"<svg><defs><g id="g"><path d="M 0 0 L 1 0"/><defs><circle r="1"/></defs></g></defs>
      <use href="#g"/><use href="#g" x="5"/></svg>"##;
    let out = import_document(doc, &raw()).unwrap();
    assert_eq!(out.sketch.entities().count(), 2);
    assert_eq!(out.skipped.len(), 1, "{:?}", out.skipped);
    assert!(out.skipped[0].reason.contains("the 1 shape(s)"));
}
