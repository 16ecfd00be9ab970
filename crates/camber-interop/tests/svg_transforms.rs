//! Transforms applied exactly: each imported entity sampled against the SVG curve sampled by
//! its own definition and mapped by the transform written out by hand (and the y flip).
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

mod svg_support;

use camber_interop::svg::{import_document, Orientation, SvgOptions};
use camber_sketch::Entity;
use nalgebra::{Matrix2, Point2, Vector2};
use svg_support::{bezier, entities, flip, max_deviation, p, svg_arc};

/// The document of one path `d` inside a group with `transform`.
fn doc(transform: &str, d: &str) -> String {
    format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg"><g transform="{transform}"><path d="{d}"/></g></svg>"#
    )
}

/// (x, y) ↦ M·(x, y) + t, then the y flip of the default orientation.
fn affine(m: [f64; 4], t: [f64; 2]) -> impl Fn(Point2<f64>) -> Point2<f64> + Copy {
    move |q| {
        flip(Point2::from(
            Matrix2::new(m[0], m[1], m[2], m[3]) * q.coords + Vector2::new(t[0], t[1]),
        ))
    }
}

const PATH: &str = "M 1 0 A 1 1 0 0 1 0 1 C 0 2 1 3 2 3 Q 3 3 3 2 L 3 1";

/// Every segment of [`PATH`] against its definition under `map`.
fn check(transform: &str, map: impl Fn(Point2<f64>) -> Point2<f64> + Copy) -> Vec<Entity> {
    let out = import_document(&doc(transform, PATH), &SvgOptions::default()).unwrap();
    assert!(
        out.skipped.iter().all(|s| s.location.contains("join")),
        "{:?}",
        out.skipped
    );
    let e = entities(&out.sketch);
    assert_eq!(e.len(), 4, "{e:?}");
    let arc = svg_arc(p(1.0, 0.0), p(0.0, 1.0), (1.0, 1.0), 0.0, false, true);
    let cubic = |t| bezier(&[p(0.0, 1.0), p(0.0, 2.0), p(1.0, 3.0), p(2.0, 3.0)], t);
    let quad = |t| bezier(&[p(2.0, 3.0), p(3.0, 3.0), p(3.0, 2.0)], t);
    let line = |t| bezier(&[p(3.0, 2.0), p(3.0, 1.0)], t);
    assert!(
        max_deviation(&e[0], arc, map, 200) < 1e-12,
        "{transform}: arc {:?}",
        e[0]
    );
    assert!(
        max_deviation(&e[1], cubic, map, 50) < 1e-12,
        "{transform}: cubic"
    );
    assert!(
        max_deviation(&e[2], quad, map, 50) < 1e-12,
        "{transform}: quadratic"
    );
    assert!(
        max_deviation(&e[3], line, map, 10) < 1e-12,
        "{transform}: line"
    );
    e
}

#[test]
fn a_translation_moves_every_segment() {
    let e = check("translate(5 -2)", affine([1.0, 0.0, 0.0, 1.0], [5.0, -2.0]));
    assert!(matches!(e[0], Entity::Arc(_)));
}

#[test]
fn a_rotation_keeps_the_arc_circular() {
    let (s, c) = 30f64.to_radians().sin_cos();
    let e = check("rotate(30)", affine([c, -s, s, c], [0.0, 0.0]));
    assert!(matches!(e[0], Entity::Arc(_)));
    // About a centre: rotate(a cx cy) = translate(cx cy) rotate(a) translate(−cx −cy).
    let (cx, cy) = (2.0, 1.0);
    check(
        "rotate(30 2 1)",
        affine([c, -s, s, c], [cx - c * cx + s * cy, cy - s * cx - c * cy]),
    );
}

#[test]
fn a_non_uniform_scale_turns_the_circular_arc_elliptic() {
    let e = check("scale(3 1)", affine([3.0, 0.0, 0.0, 1.0], [0.0, 0.0]));
    let a = e[0].as_elliptic_arc().unwrap();
    assert!(
        (a.ellipse().semi_axis_a() - 3.0).abs() < 1e-12
            && (a.ellipse().semi_axis_b() - 1.0).abs() < 1e-12
    );
}

#[test]
fn skews_and_matrices_map_arcs_by_their_ellipse() {
    let t = 25f64.to_radians().tan();
    let e = check("skewX(25)", affine([1.0, t, 0.0, 1.0], [0.0, 0.0]));
    assert!(matches!(e[0], Entity::EllipticArc { .. }));
    check(
        "skewY(-40)",
        affine([1.0, 0.0, (-40f64).to_radians().tan(), 1.0], [0.0, 0.0]),
    );
    // matrix(a b c d e f): (x, y) ↦ (a·x + c·y + e, b·x + d·y + f).
    check(
        "matrix(1.5 0.3 -0.7 0.8 4 5)",
        affine([1.5, -0.7, 0.3, 0.8], [4.0, 5.0]),
    );
}

#[test]
fn a_reflection_reverses_the_arc_so_it_still_runs_counter_clockwise() {
    // scale(−1 1) and the y flip together keep orientation; scale(1 −1) undoes the flip.
    check("scale(-1 1)", affine([-1.0, 0.0, 0.0, 1.0], [0.0, 0.0]));
    let e = check("scale(1 -1)", affine([1.0, 0.0, 0.0, -1.0], [0.0, 0.0]));
    let arc = e[0].as_arc().unwrap();
    // Net map: the identity, and the SVG arc from (1, 0) to (0, 1) with fS = 1 is
    // counter-clockwise about the origin: the camber arc starts at (1, 0).
    assert!((arc.start_point() - p(1.0, 0.0)).norm() < 1e-12);
}

#[test]
fn group_transforms_compose_from_the_outside_in_with_the_path_own() {
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg">
      <g transform="translate(10 0)"><g transform="scale(2)">
        <path transform="rotate(90)" d="M 1 0 L 2 0"/>
      </g></g></svg>"#;
    let out = import_document(svg, &SvgOptions::default()).unwrap();
    // (1, 0) → rotate → (0, 1) → scale → (0, 2) → translate → (10, 2) → flip → (10, −2).
    let e = entities(&out.sketch);
    let Entity::Line([a, b]) = e[0] else {
        panic!("{e:?}")
    };
    assert!(
        (a - p(10.0, -2.0)).norm() < 1e-12 && (b - p(10.0, -4.0)).norm() < 1e-12,
        "{a} {b}"
    );
}

#[test]
fn raw_orientation_keeps_user_coordinates() {
    let raw = SvgOptions::default().with_orientation(Orientation::Raw);
    let out = import_document(&doc("translate(1 1)", "M 0 0 L 1 2"), &raw).unwrap();
    assert_eq!(
        entities(&out.sketch)[0],
        Entity::Line([p(1.0, 1.0), p(2.0, 3.0)])
    );
}

#[test]
fn a_circle_element_under_a_non_uniform_scale_is_an_ellipse() {
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg"><circle transform="scale(2 1)" cx="1" cy="1" r="1"/><circle cx="0" cy="0" r="3" transform="rotate(10)"/></svg>"#;
    let out = import_document(svg, &SvgOptions::default()).unwrap();
    let e = entities(&out.sketch);
    let ellipse = e[0].as_ellipse().unwrap();
    assert!(
        (ellipse.semi_axis_a() - 2.0).abs() < 1e-12 && (ellipse.semi_axis_b() - 1.0).abs() < 1e-12
    );
    assert!((ellipse.center() - p(2.0, -1.0)).norm() < 1e-12);
    assert!(matches!(e[1], Entity::Circle { radius, .. } if (radius - 3.0).abs() < 1e-12));
}
