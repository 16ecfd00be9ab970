//! The joins of imported subpaths: which constraints each pair gets, that they hold as
//! imported (no redundant or conflicting constraint, a solve moves nothing), and that smooth
//! joins no kind fits are listed.
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

mod svg_support;

use camber_interop::svg::{import_path, SvgOptions};
use camber_interop::Imported;
use camber_sketch::{Constraint, Sense};
use svg_support::entities;

fn tags(out: &Imported) -> Vec<&'static str> {
    out.sketch.constraints().map(|(_, c)| c.tag()).collect()
}

/// The analysis finds nothing redundant or conflicting, and a solve leaves every point where
/// the import put it.
fn holds_as_imported(out: &Imported) {
    for c in out.sketch.analyze().unwrap() {
        assert!(
            c.analysis.redundant.is_empty(),
            "redundant: {:?}",
            c.analysis.redundant
        );
        assert!(
            c.analysis.partly_redundant.is_empty(),
            "partly redundant: {:?}",
            c.analysis.partly_redundant
        );
        assert!(
            c.analysis.conflicting.is_empty(),
            "conflicting: {:?}",
            c.analysis.conflicting
        );
    }
    let before = entities(&out.sketch);
    let mut s = out.sketch.clone();
    s.solve().unwrap();
    for (a, b) in before.iter().zip(entities(&s)) {
        for (p, q) in a.points().iter().zip(b.points()) {
            assert!((p - q).norm() < 1e-9, "{a:?} moved to {b:?}");
        }
        for (p, q) in a.scalars().iter().zip(b.scalars()) {
            assert!((p - q).abs() < 1e-9, "{a:?} moved to {b:?}");
        }
    }
}

fn import(d: &str) -> Imported {
    import_path(d, &SvgOptions::default()).unwrap()
}

#[test]
fn a_rounded_slot_gets_coincidences_and_arc_line_tangencies_that_hold() {
    let out = import("M 0 0 H 10 A 5 5 0 0 1 10 10 H 0 A 5 5 0 0 1 0 0 Z");
    assert!(out.skipped.is_empty(), "{:?}", out.skipped);
    let t = tags(&out);
    assert_eq!(t.iter().filter(|k| **k == "coincident").count(), 4, "{t:?}");
    assert_eq!(
        t.iter().filter(|k| **k == "arc_tangent_to_line").count(),
        4,
        "{t:?}"
    );
    holds_as_imported(&out);
}

#[test]
fn smooth_bezier_and_line_joins_get_a_free_g1_join_corners_a_coincidence() {
    // C then S (smooth by reflection), then a line along the S end tangent, then a corner.
    let out = import("M 0 0 C 1 1 2 1 3 0 S 5 -1 6 0 L 7 1 L 8 0");
    assert_eq!(tags(&out), ["g1_join_free", "g1_join_free", "coincident"]);
    holds_as_imported(&out);
}

#[test]
fn a_closed_outline_joins_its_last_segment_to_its_first() {
    let out = import("M 0 0 L 4 0 L 4 3 Z");
    assert_eq!(tags(&out), ["coincident"; 3]);
    holds_as_imported(&out);
    // A smooth closing join (a teardrop: the quadratic's ends along the lines).
    let drop = import("M 0 0 L 2 2 Q 4 4 4 2 Q 4 0 2 2 Z");
    holds_as_imported(&drop);
}

#[test]
fn elliptic_arcs_join_lines_and_curves_with_their_own_kinds() {
    // An elliptic quarter (rx 4, ry 2) between a line along its start tangent and a cubic
    // along its end tangent.
    let out = import("M -2 0 L 0 0 A 4 2 0 0 1 4 2 C 4 3 4 4 5 5");
    assert_eq!(
        tags(&out),
        [
            "coincident",
            "elliptic_arc_tangent_to_line",
            "coincident",
            "elliptic_arc_tangent_to_curve"
        ]
    );
    assert!(out.skipped.is_empty(), "{:?}", out.skipped);
    holds_as_imported(&out);
}

#[test]
fn a_smooth_arc_to_curve_join_gets_the_arc_curve_tangency_both_ways() {
    // A circular quarter then a cubic along its end tangent, and the cubic then the arc.
    for d in [
        "M 0 0 A 2 2 0 0 1 2 2 C 2 3 2 4 3 5",
        "M 3 5 C 2 4 2 3 2 2 A 2 2 0 0 0 0 0",
    ] {
        let out = import(d);
        assert_eq!(tags(&out), ["coincident", "arc_tangent_to_curve"], "{d}");
        assert!(out.skipped.is_empty(), "{:?}", out.skipped);
        holds_as_imported(&out);
    }
}

#[test]
fn a_smooth_arc_to_arc_join_gets_the_arc_arc_tangency_that_holds() {
    // Two circular quarters continuing one another's tangent: an S bend (the travels of the
    // two counter-clockwise arcs oppose), and two quarters of one circle (they agree).
    for (d, sense) in [
        ("M 0 0 A 1 1 0 0 1 1 1 A 1 1 0 0 0 2 2", Sense::Oppose),
        ("M 1 0 A 1 1 0 0 1 0 1 A 1 1 0 0 1 -1 0", Sense::Agree),
    ] {
        let out = import(d);
        assert_eq!(tags(&out), ["coincident", "arc_tangent_to_arc"], "{d}");
        assert!(out.skipped.is_empty(), "{:?}", out.skipped);
        let Some((_, Constraint::ArcTangentToArc(t))) = out.sketch.constraints().nth(1) else {
            panic!("{d}: no arc tangency");
        };
        assert_eq!(t.sense, sense, "{d}");
        holds_as_imported(&out);
    }
}

#[test]
fn the_tangent_tolerance_decides_what_is_smooth() {
    // Directions (1, 0) and (1, 0.0005): 5·10⁻⁴ rad apart.
    let d = "M 0 0 L 1 0 L 2 0.0005";
    assert_eq!(tags(&import(d)), ["g1_join_free"]);
    let strict = SvgOptions::default().with_tangent_tolerance(1e-4);
    assert_eq!(tags(&import_path(d, &strict).unwrap()), ["coincident"]);
}

#[test]
fn a_closed_single_curve_joins_its_end_to_its_own_start() {
    // A loop: one cubic from (0, 0) back to (0, 0), its end tangents opposite (a corner).
    let corner = import("M 0 0 C 2 2 -2 2 0 0 Z");
    assert_eq!(tags(&corner), ["coincident"]);
    assert!(corner.skipped.is_empty(), "{:?}", corner.skipped);
    // A teardrop whose ends leave and arrive along one direction: smooth, but no kind joins
    // a curve to itself, so it is listed.
    let smooth = import("M 0 0 C 1 0 2 2 0 2 C -2 2 -1 0 0 0 Z");
    assert_eq!(tags(&smooth), ["g1_join_free", "g1_join_free"]);
    let looped = import("M 0 0 C 3 0 -3 0 0 0 Z");
    assert_eq!(tags(&looped), ["coincident"]);
    assert!(
        looped
            .skipped
            .iter()
            .any(|s| s.reason.contains("with itself")),
        "{:?}",
        looped.skipped
    );
}
