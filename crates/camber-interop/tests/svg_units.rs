//! Units and viewports: lengths in absolute units and percentages as user units (96 px per
//! inch), the root's viewBox-to-viewport map when the sketch is in physical units, nested
//! `svg` viewports, each against coordinates worked out by hand.
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

mod svg_support;

use approx::assert_relative_eq;
use camber_interop::svg::{
    import_document, Error, Orientation, SketchUnits, SvgOptions, Unit, PX_PER_INCH,
};
use camber_sketch::Entity;
use nalgebra::Point2;
use svg_support::{entities, p};

fn raw() -> SvgOptions {
    SvgOptions::default().with_orientation(Orientation::Raw)
}

fn in_mm() -> SvgOptions {
    raw().with_units(SketchUnits::Physical(Unit::Millimetre))
}

/// The ends of the only line of `doc`.
fn line_ends(doc: &str, options: &SvgOptions) -> [Point2<f64>; 2] {
    let out = import_document(doc, options).unwrap();
    match entities(&out.sketch).as_slice() {
        [Entity::Line(ends)] => *ends,
        other => panic!("{other:?}, skipped {:?}", out.skipped),
    }
}

fn assert_ends(ends: [Point2<f64>; 2], want: [Point2<f64>; 2]) {
    for (a, b) in ends.iter().zip(want) {
        assert_relative_eq!(*a, b, epsilon = 1e-12, max_relative = 1e-14);
    }
}

const MM_DOC: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 200 100">
  <line x1="0" y1="0" x2="200" y2="100"/></svg>"#;

#[test]
fn a_millimetre_document_lands_its_view_box_in_millimetres() {
    // 200 × 100 user units on a 100 mm × 50 mm page: a user unit is half a millimetre.
    assert_ends(line_ends(MM_DOC, &in_mm()), [p(0.0, 0.0), p(100.0, 50.0)]);
    // Upright flips y after the placement: (200, 100) lands at (100, −50) mm.
    let upright = SvgOptions::default().with_units(SketchUnits::Physical(Unit::Millimetre));
    assert_ends(line_ends(MM_DOC, &upright), [p(0.0, 0.0), p(100.0, -50.0)]);
    // In inches: 100 mm = 100/25.4 in.
    let inches = raw().with_units(SketchUnits::Physical(Unit::Inch));
    assert_ends(
        line_ends(MM_DOC, &inches),
        [p(0.0, 0.0), p(100.0 / 25.4, 50.0 / 25.4)],
    );
}

#[test]
fn user_units_keep_the_numbers_written_in_the_file() {
    assert_ends(line_ends(MM_DOC, &raw()), [p(0.0, 0.0), p(200.0, 100.0)]);
}

#[test]
fn a_root_without_a_view_box_is_taken_at_one_user_unit_per_px() {
    let doc = r#"<svg width="96px" height="48"><line x1="0" y1="0" x2="96" y2="48"/></svg>"#;
    // 96 px = 1 in = 25.4 mm.
    assert_ends(line_ends(doc, &in_mm()), [p(0.0, 0.0), p(25.4, 12.7)]);
    // No size at all: still 1 px a unit, and the guess is listed.
    let doc = r#"<svg viewBox="0 0 96 48"><line x1="0" y1="0" x2="96" y2="48"/></svg>"#;
    let out = import_document(doc, &in_mm()).unwrap();
    assert_ends(
        match entities(&out.sketch).as_slice() {
            [Entity::Line(e)] => *e,
            other => panic!("{other:?}"),
        },
        [p(0.0, 0.0), p(25.4, 12.7)],
    );
    assert_eq!(out.skipped.len(), 1);
    assert!(out.skipped[0].reason.contains("1 px"), "{}", out.skipped[0]);
    // One side given: the other follows the viewBox's aspect ratio (2 in wide → 1 in high).
    let doc = r#"<svg width="2in" viewBox="0 0 10 5"><line x1="0" y1="0" x2="10" y2="5"/></svg>"#;
    let inches = raw().with_units(SketchUnits::Physical(Unit::Inch));
    assert_ends(line_ends(doc, &inches), [p(0.0, 0.0), p(2.0, 1.0)]);
}

#[test]
fn preserve_aspect_ratio_fits_centres_slices_or_stretches() {
    // A 100 × 50 viewBox on a 200 × 200 px page.
    let doc = |par: &str| {
        format!(
            r#"<svg width="200" height="200" viewBox="0 0 100 50" preserveAspectRatio="{par}"><line x1="0" y1="0" x2="100" y2="50"/></svg>"#
        )
    };
    let px = raw().with_units(SketchUnits::Physical(Unit::Pixel));
    // meet (the default alignment xMidYMid): scale 2, 50 px spare above and below.
    assert_ends(
        line_ends(&doc("xMidYMid meet"), &px),
        [p(0.0, 50.0), p(200.0, 150.0)],
    );
    // slice from the top left: scale 4.
    assert_ends(
        line_ends(&doc("xMinYMin slice"), &px),
        [p(0.0, 0.0), p(400.0, 200.0)],
    );
    // none: 2 across, 4 down.
    assert_ends(line_ends(&doc("none"), &px), [p(0.0, 0.0), p(200.0, 200.0)]);
}

#[test]
fn shape_lengths_with_units_are_user_units_at_96_px_per_inch() {
    let doc = r#"<svg><line x1="1in" y1="2.54cm" x2="50.8mm" y2="36pt"/><circle cx="6pc" cy="0" r="1in"/></svg>"#;
    let out = import_document(doc, &raw()).unwrap();
    let e = entities(&out.sketch);
    let Entity::Line([a, b]) = e[0] else {
        panic!("{:?}", e[0])
    };
    assert_relative_eq!(a, p(PX_PER_INCH, 96.0), max_relative = 1e-15);
    assert_relative_eq!(b, p(192.0, 48.0), max_relative = 1e-15);
    let Entity::Circle { center, radius } = e[1] else {
        panic!("{:?}", e[1])
    };
    assert_relative_eq!(center, p(96.0, 0.0), max_relative = 1e-15);
    assert_relative_eq!(radius, 96.0);
    // A 10 mm × 1 cm rectangle at x = 1 in: its first side runs from (96, 0) to (96 + 10·96/25.4, 0).
    let doc = r#"<svg><rect x="1in" width="10mm" height="1cm"/></svg>"#;
    let e = entities(&import_document(doc, &raw()).unwrap().sketch);
    assert_eq!(e.len(), 4);
    let Entity::Line([a, b]) = e[0] else {
        panic!("{:?}", e[0])
    };
    assert_relative_eq!(a, p(96.0, 0.0));
    assert_relative_eq!(b, p(96.0 + 960.0 / 25.4, 0.0), max_relative = 1e-15);
}

#[test]
fn percentages_are_of_the_nearest_viewport() {
    // Of the root's viewBox: 200 × 100; r is of √((200² + 100²)/2) = √25000.
    let doc = r#"<svg viewBox="0 0 200 100"><circle cx="50%" cy="50%" r="10%"/></svg>"#;
    let e = entities(&import_document(doc, &raw()).unwrap().sketch);
    let Entity::Circle { center, radius } = e[0] else {
        panic!("{:?}", e[0])
    };
    assert_relative_eq!(center, p(100.0, 50.0));
    assert_relative_eq!(radius, 0.1 * 25_000f64.sqrt(), max_relative = 1e-15);
    // Of a nested viewBox (0 0 10 10): 50% is 5 there, then placed.
    let doc = r#"<svg viewBox="0 0 200 100"><svg x="20" width="40" height="40" viewBox="0 0 10 10"><line x1="0" y1="0" x2="50%" y2="50%"/></svg></svg>"#;
    assert_ends(line_ends(doc, &raw()), [p(20.0, 0.0), p(40.0, 20.0)]);
    // With no viewport size known, a percentage lists its shape.
    let out = import_document(r#"<svg><circle r="10%"/></svg>"#, &raw()).unwrap();
    assert_eq!(out.sketch.entities().count(), 0);
    assert!(
        out.skipped[0].reason.contains("r=\"10%\""),
        "{}",
        out.skipped[0]
    );
}

#[test]
fn a_nested_svg_places_its_view_box_at_x_y() {
    // viewBox 0 0 10 10 into 50 × 50 at (10, 20): scale 5.
    let doc = r#"<svg><svg x="10" y="20" width="50" height="50" viewBox="0 0 10 10"><line x1="0" y1="0" x2="10" y2="10"/></svg></svg>"#;
    assert_ends(line_ends(doc, &raw()), [p(10.0, 20.0), p(60.0, 70.0)]);
    // Inside a group's transform, and without a viewBox only translated.
    let doc = r#"<svg><g transform="scale(2)"><svg x="1" y="1"><line x1="0" y1="0" x2="1" y2="0"/></svg></g></svg>"#;
    assert_ends(line_ends(doc, &raw()), [p(2.0, 2.0), p(4.0, 2.0)]);
    // A nested viewport of no size draws nothing, listed.
    let out = import_document(
        r#"<svg><svg width="0" height="10"><line x1="0" y1="0" x2="1" y2="0"/></svg></svg>"#,
        &raw(),
    )
    .unwrap();
    assert_eq!(out.sketch.entities().count(), 0);
    assert!(
        out.skipped[0].reason.contains("not positive"),
        "{}",
        out.skipped[0]
    );
}

#[test]
fn font_relative_lengths_list_their_shape_naming_the_attribute() {
    let out = import_document(r#"<svg><rect width="3em" height="1"/></svg>"#, &raw()).unwrap();
    assert_eq!(out.sketch.entities().count(), 0);
    assert_eq!(out.skipped[0].location, "<rect> (line 1)");
    assert!(
        out.skipped[0].reason.contains("width=\"3em\""),
        "{}",
        out.skipped[0]
    );
}

#[test]
fn bad_lengths_and_view_boxes_are_typed_errors_naming_the_attribute() {
    for (doc, attribute) in [
        (
            r#"<svg><rect width="10furlong" height="1"/></svg>"#,
            "width",
        ),
        (r#"<svg><rect width="NaN" height="1"/></svg>"#, "width"),
        (r#"<svg><circle r="1e307in"/></svg>"#, "r"),
        (r#"<svg><line x1="1e999mm"/></svg>"#, "x1"),
        (r#"<svg width="-5mm" height="1mm"/>"#, "width"),
        (r#"<svg width="0" height="1mm"/>"#, "width"),
        (r#"<svg width="NaN" height="1mm"/>"#, "width"),
        (r#"<svg viewBox="0 0 0 10"/>"#, "viewBox"),
        (r#"<svg viewBox="0 0 NaN 10"/>"#, "viewBox"),
        (r#"<svg viewBox="0 0 10"/>"#, "viewBox"),
        (
            r#"<svg viewBox="0 0 1 1" preserveAspectRatio="sideways"/>"#,
            "preserveAspectRatio",
        ),
        (
            r#"<svg><svg viewBox="0 0 -1 1" width="1" height="1"/></svg>"#,
            "viewBox",
        ),
        (r#"<svg><svg x="1e999" width="1" height="1"/></svg>"#, "x"),
    ] {
        match import_document(doc, &in_mm()) {
            Err(Error::MalformedAttribute { attribute: a, .. }) => {
                assert_eq!(a, attribute, "{doc}")
            }
            other => panic!("{doc}: {other:?}"),
        }
    }
}

#[test]
fn a_placement_that_overflows_is_an_error_not_infinities() {
    // A viewBox 1e-300 wide on a 1e300 px page: a scale of 1e600.
    let doc = r#"<svg width="1e300" height="1e300" viewBox="0 0 1e-300 1e-300"><line x1="0" y1="0" x2="1" y2="1"/></svg>"#;
    assert!(matches!(
        import_document(doc, &in_mm()),
        Err(Error::MalformedAttribute {
            attribute: "viewBox",
            ..
        })
    ));
    let doc = r#"<svg><svg width="1e300" height="1e300" viewBox="0 0 1e-300 1e-300"><line x1="0" y1="0" x2="1" y2="1"/></svg></svg>"#;
    assert!(matches!(
        import_document(doc, &raw()),
        Err(Error::MalformedAttribute {
            attribute: "viewBox",
            ..
        })
    ));
}
