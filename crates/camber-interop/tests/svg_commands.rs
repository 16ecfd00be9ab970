//! Every path command, absolute and relative, against geometry worked out by hand (raw
//! coordinates, so the numbers are the ones written), and the arc conversion against the
//! closed form of known cases.
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

mod svg_support;

use camber_geom::BezierCurve2;
use camber_interop::svg::{import_path, Orientation, SvgOptions};
use camber_sketch::Entity;
use std::f64::consts::PI;
use svg_support::{entities, max_deviation, p, svg_arc};

fn raw() -> SvgOptions {
    SvgOptions::default().with_orientation(Orientation::Raw)
}

fn import(d: &str) -> Vec<Entity> {
    let out = import_path(d, &raw()).unwrap();
    assert!(out.skipped.is_empty(), "{d}: {:?}", out.skipped);
    entities(&out.sketch)
}

fn bez(points: &[[f64; 2]]) -> Entity {
    Entity::Bezier(BezierCurve2::try_new(points.iter().map(|q| p(q[0], q[1])).collect()).unwrap())
}

fn line(a: [f64; 2], b: [f64; 2]) -> Entity {
    Entity::Line([p(a[0], a[1]), p(b[0], b[1])])
}

#[test]
fn lines_absolute_and_relative_and_horizontal_and_vertical() {
    let expect = vec![
        line([1.0, 2.0], [4.0, 2.0]),
        line([4.0, 2.0], [4.0, 7.0]),
        line([4.0, 7.0], [-1.0, 7.0]),
        line([-1.0, 7.0], [-1.0, 3.0]),
        line([-1.0, 3.0], [0.0, 0.0]),
    ];
    assert_eq!(import("M 1 2 L 4 2 L 4 7 H -1 V 3 L 0 0"), expect);
    assert_eq!(import("m 1 2 l 3 0 l 0 5 h -5 v -4 l 1 -3"), expect);
    // Implicit repeats: pairs after a move are lines, after a line more lines.
    assert_eq!(import("M 1 2 4 2 4 7 H -1 V 3 L 0 0"), expect);
    assert_eq!(import("m 1 2 3 0 0 5 h -5 v -4 l 1 -3"), expect);
    // After v, more numbers are more v commands.
    assert_eq!(import("M 0 0 v 1 2")[1], line([0.0, 1.0], [0.0, 3.0]));
}

#[test]
fn cubics_absolute_and_relative() {
    let expect = vec![bez(&[[1.0, 1.0], [2.0, 3.0], [4.0, 3.0], [5.0, 1.0]])];
    assert_eq!(import("M 1 1 C 2 3 4 3 5 1"), expect);
    assert_eq!(import("m 1 1 c 1 2 3 2 4 0"), expect);
}

#[test]
fn smooth_cubics_reflect_the_previous_second_control_point() {
    // After C, S's first control point is 2·(5, 1) − (4, 3) = (6, −1).
    let expect = vec![
        bez(&[[1.0, 1.0], [2.0, 3.0], [4.0, 3.0], [5.0, 1.0]]),
        bez(&[[5.0, 1.0], [6.0, -1.0], [8.0, -1.0], [9.0, 1.0]]),
        // After S, again the reflection of S's second control point: 2·(9, 1) − (8, −1).
        bez(&[[9.0, 1.0], [10.0, 3.0], [11.0, 2.0], [12.0, 0.0]]),
    ];
    assert_eq!(import("M 1 1 C 2 3 4 3 5 1 S 8 -1 9 1 S 11 2 12 0"), expect);
    assert_eq!(import("m 1 1 c 1 2 3 2 4 0 s 3 -2 4 0 s 2 1 3 -1"), expect);
    // After anything else, the first control point is the current point.
    assert_eq!(
        import("M 0 0 L 1 0 S 2 1 3 0"),
        vec![
            line([0.0, 0.0], [1.0, 0.0]),
            bez(&[[1.0, 0.0], [1.0, 0.0], [2.0, 1.0], [3.0, 0.0]])
        ]
    );
    // After a quadratic too (S reflects only C and S).
    assert_eq!(
        import("M 0 0 Q 1 1 2 0 S 3 1 4 0")[1],
        bez(&[[2.0, 0.0], [2.0, 0.0], [3.0, 1.0], [4.0, 0.0]])
    );
}

#[test]
fn quadratics_and_their_smooth_reflections() {
    let expect = vec![
        bez(&[[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]),
        // T after Q: 2·(2, 0) − (1, 2) = (3, −2).
        bez(&[[2.0, 0.0], [3.0, -2.0], [4.0, 0.0]]),
        // T after T: 2·(4, 0) − (3, −2) = (5, 2).
        bez(&[[4.0, 0.0], [5.0, 2.0], [6.0, 0.0]]),
    ];
    assert_eq!(import("M 0 0 Q 1 2 2 0 T 4 0 T 6 0"), expect);
    assert_eq!(import("m 0 0 q 1 2 2 0 t 2 0 t 2 0"), expect);
    // T after a cubic or a line: the control point is the current point.
    assert_eq!(
        import("M 0 0 L 1 1 T 2 0")[1],
        bez(&[[1.0, 1.0], [1.0, 1.0], [2.0, 0.0]])
    );
}

#[test]
fn close_draws_the_closing_side_and_the_next_command_starts_at_the_subpath_start() {
    assert_eq!(
        import("M 0 0 H 2 V 1 Z l 0 -3"),
        vec![
            line([0.0, 0.0], [2.0, 0.0]),
            line([2.0, 0.0], [2.0, 1.0]),
            line([2.0, 1.0], [0.0, 0.0]),
            line([0.0, 0.0], [0.0, -3.0]),
        ]
    );
    // A relative move after Z is relative to the subpath's start.
    assert_eq!(
        import("M 5 5 h 1 v 1 z m 1 0 h 1")[3],
        line([6.0, 5.0], [7.0, 5.0])
    );
    // Z at the start point draws nothing more.
    assert_eq!(import("M 0 0 H 2 V 1 L 0 0 Z").len(), 3);
}

/// (centre, radius, start, end) of a circular arc entity.
fn circular(e: &Entity) -> ([f64; 2], f64, [f64; 2], [f64; 2]) {
    let Entity::Arc([c, s, t]) = e else {
        panic!("not a circular arc: {e:?}")
    };
    ([c.x, c.y], (s - c).norm(), [s.x, s.y], [t.x, t.y])
}

fn near(a: [f64; 2], b: [f64; 2]) -> bool {
    (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12
}

#[test]
fn a_semicircle_has_the_closed_form_centre_radius_and_direction() {
    // From (0, 0) to (2, 0), r = 1, fS = 1: θ increases from π to 2π through (1, −1); in raw
    // coordinates (y up in the sketch) that is counter-clockwise, so the arc starts at (0, 0).
    for d in ["M 0 0 A 1 1 0 0 1 2 0", "m 0 0 a 1 1 0 0 1 2 0"] {
        let e = import(d);
        let (c, r, s, t) = circular(&e[0]);
        assert!(
            near(c, [1.0, 0.0])
                && (r - 1.0).abs() < 1e-15
                && near(s, [0.0, 0.0])
                && near(t, [2.0, 0.0]),
            "{d}: {e:?}"
        );
        let arc = e[0].as_arc().unwrap();
        assert!((arc.sweep() - PI).abs() < 1e-12);
        assert!((arc.point(0.5) - p(1.0, -1.0)).norm() < 1e-12);
    }
    // fS = 0 goes through (1, 1), clockwise: the camber arc runs from (2, 0) to (0, 0).
    let e = import("M 0 0 A 1 1 0 0 0 2 0");
    let (c, _, s, t) = circular(&e[0]);
    assert!(near(c, [1.0, 0.0]) && near(s, [2.0, 0.0]) && near(t, [0.0, 0.0]));
    assert!((e[0].as_arc().unwrap().point(0.5) - p(1.0, 1.0)).norm() < 1e-12);
}

#[test]
fn the_flags_pick_each_of_the_four_arcs_between_two_points() {
    // From (1, 0) to (0, 1) with r = 1: centre (0, 0) or (1, 1), a quarter or three quarters.
    for (fa, fs, centre, sweep) in [
        (0, 1, [0.0, 0.0], PI / 2.0),
        (1, 0, [0.0, 0.0], 1.5 * PI),
        (0, 0, [1.0, 1.0], PI / 2.0),
        (1, 1, [1.0, 1.0], 1.5 * PI),
    ] {
        let d = format!("M 1 0 A 1 1 0 {fa} {fs} 0 1");
        let e = import(&d);
        let (c, r, ..) = circular(&e[0]);
        assert!(near(c, centre) && (r - 1.0).abs() < 1e-12, "{d}: {e:?}");
        assert!(
            (e[0].as_arc().unwrap().sweep() - sweep).abs() < 1e-12,
            "{d}"
        );
        let dev = max_deviation(
            &e[0],
            svg_arc(p(1.0, 0.0), p(0.0, 1.0), (1.0, 1.0), 0.0, fa == 1, fs == 1),
            |q| q,
            64,
        );
        assert!(dev < 1e-12, "{d}: {dev}");
    }
}

#[test]
fn an_elliptic_arc_with_rotation_matches_its_definition_absolute_and_relative() {
    for d in ["M 3 -1 A 10 6 30 1 0 -2 4", "m 3 -1 a 10 6 30 1 0 -5 5"] {
        let e = import(d);
        assert!(matches!(e[0], Entity::EllipticArc { .. }), "{d}: {e:?}");
        let a = e[0].as_elliptic_arc().unwrap();
        assert!(
            (a.ellipse().semi_axis_a() - 10.0).abs() < 1e-12
                && (a.ellipse().semi_axis_b() - 6.0).abs() < 1e-12
        );
        let dev = max_deviation(
            &e[0],
            svg_arc(p(3.0, -1.0), p(-2.0, 4.0), (10.0, 6.0), 30.0, true, false),
            |q| q,
            128,
        );
        assert!(dev < 1e-11, "{d}: {dev}");
    }
}

#[test]
fn radii_too_small_grow_and_zero_radii_make_a_line() {
    // r = 0.5 cannot span a chord of 4: scaled to 2, a semicircle about (2, 0).
    let e = import("M 0 0 A 0.5 0.5 0 0 1 4 0");
    let (c, r, ..) = circular(&e[0]);
    assert!(near(c, [2.0, 0.0]) && (r - 2.0).abs() < 1e-12);
    // Negative radii count by their magnitude.
    assert_eq!(
        import("M 0 0 A -1 -1 0 0 1 2 0"),
        import("M 0 0 A 1 1 0 0 1 2 0")
    );
    assert_eq!(
        import("M 0 0 A 0 3 0 0 1 2 0"),
        vec![line([0.0, 0.0], [2.0, 0.0])]
    );
    assert_eq!(
        import("m 1 1 a 3 0 0 0 1 2 0"),
        vec![line([1.0, 1.0], [3.0, 1.0])]
    );
}

#[test]
fn zero_length_segments_are_skipped_and_listed_with_their_command() {
    let out = import_path(
        "M 0 0 L 0 0 L 1 0 A 1 1 0 0 1 1 0 C 1 0 1 0 1 0 l 0 1",
        &raw(),
    )
    .unwrap();
    let kinds: Vec<&str> = out.sketch.entities().map(|(_, e)| e.kind_name()).collect();
    assert_eq!(kinds, ["line", "line"]);
    let places: Vec<&str> = out.skipped.iter().map(|s| s.location.as_str()).collect();
    assert_eq!(
        places,
        [
            "the path data, command 1 (L)",
            "the path data, command 3 (A)",
            "the path data, command 4 (C)"
        ]
    );
    assert!(out.skipped[1].reason.contains("same point"));
    // The lines either side of the skipped ones are still joined.
    assert_eq!(out.sketch.constraints().count(), 1);
}

#[test]
fn upright_orientation_flips_y_and_keeps_arcs_on_their_side() {
    let up = import_path("M 0 0 A 1 1 0 0 1 2 0", &SvgOptions::default()).unwrap();
    let e = entities(&up.sketch);
    // Through (1, −1) on the page, so through (1, 1) in the sketch: clockwise from (0, 0).
    let arc = e[0].as_arc().unwrap();
    assert!((arc.point(0.5) - p(1.0, 1.0)).norm() < 1e-12);
    assert!((arc.start_point() - p(2.0, 0.0)).norm() < 1e-12);
}
