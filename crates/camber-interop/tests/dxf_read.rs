//! Reading DXF text written by hand: every supported entity against its closed form, the
//! object coordinates of mirrored entities, joins, and what is listed as skipped.
#![allow(clippy::unwrap_used)] // helpers outside #[test] functions unwrap too

use approx::assert_abs_diff_eq;
use camber_interop::dxf::{self, ReadOptions};
use camber_interop::Imported;
use camber_sketch::constraints::Coincident;
use camber_sketch::{Constraint, Entity, EntityId, PointRef};
use nalgebra::Point2;

/// A DXF file of one ENTITIES section holding `entities`, each a list of (group code, value).
fn dxf_text(entities: &[&[(i32, &str)]]) -> String {
    let mut s = String::from("0\nSECTION\n2\nENTITIES\n");
    for e in entities {
        for (code, value) in *e {
            s.push_str(&format!("{code}\n{value}\n"));
        }
    }
    s.push_str("0\nENDSEC\n0\nEOF\n");
    s
}

fn read(entities: &[&[(i32, &str)]]) -> Imported {
    dxf::read(dxf_text(entities).as_bytes(), &ReadOptions::default()).expect("readable DXF")
}

fn entities(imported: &Imported) -> Vec<(EntityId, Entity)> {
    imported
        .sketch
        .entities()
        .map(|(id, e)| (id, e.clone()))
        .collect()
}

fn coincidences(imported: &Imported) -> Vec<(PointRef, PointRef)> {
    imported
        .sketch
        .constraints()
        .filter_map(|(_, c)| match c {
            Constraint::Coincident(Coincident { a, b }) => Some((*a, *b)),
            _ => None,
        })
        .collect()
}

fn close(p: Point2<f64>, x: f64, y: f64) {
    assert_abs_diff_eq!(p.x, x, epsilon = 1e-12);
    assert_abs_diff_eq!(p.y, y, epsilon = 1e-12);
}

const LINE: &[(i32, &str)] = &[
    (0, "LINE"),
    (8, "WALLS"),
    (10, "1.5"),
    (20, "-2"),
    (30, "0"),
    (11, "4"),
    (21, "2"),
    (31, "0"),
];

#[test]
fn a_line_keeps_its_ends_and_its_layer_becomes_its_tag() {
    let im = read(&[LINE]);
    assert!(im.skipped.is_empty(), "{:?}", im.skipped);
    let all = entities(&im);
    assert_eq!(
        all[0].1,
        Entity::Line([Point2::new(1.5, -2.0), Point2::new(4.0, 2.0)])
    );
    assert_eq!(im.sketch.tag(all[0].0), Some("WALLS"));
}

#[test]
fn a_point_and_a_circle_are_read() {
    let im = read(&[
        &[(0, "POINT"), (10, "3"), (20, "4"), (30, "0")],
        &[(0, "CIRCLE"), (10, "1"), (20, "1"), (30, "0"), (40, "2.5")],
    ]);
    let all = entities(&im);
    assert_eq!(all[0].1, Entity::Point(Point2::new(3.0, 4.0)));
    assert_eq!(
        all[1].1,
        Entity::Circle {
            center: Point2::new(1.0, 1.0),
            radius: 2.5
        }
    );
    // Layer 0 is the default layer: no tag.
    assert_eq!(im.sketch.tag(all[0].0), None);
}

#[test]
fn an_arc_runs_counter_clockwise_from_its_start_angle() {
    // Centre (1, 2), radius 2, from 90° to 180°: from (1, 4) to (−1, 2).
    let im = read(&[&[
        (0, "ARC"),
        (10, "1"),
        (20, "2"),
        (30, "0"),
        (40, "2"),
        (50, "90"),
        (51, "180"),
    ]]);
    let id = entities(&im)[0].0;
    close(im.sketch.point(PointRef::Start(id)).unwrap(), 1.0, 4.0);
    close(im.sketch.point(PointRef::End(id)).unwrap(), -1.0, 2.0);
    close(im.sketch.point(PointRef::Control(id, 0)).unwrap(), 1.0, 2.0);
}

#[test]
fn an_arc_extruded_along_minus_z_is_mirrored_into_world_coordinates() {
    // Object centre (1, 0), radius 1, 0°..90°: object points (2, 0) and (1, 1), world
    // (−2, 0) and (−1, 1), clockwise in the world, so the sketch arc runs from (−1, 1) to
    // (−2, 0) about (−1, 0).
    let im = read(&[&[
        (0, "ARC"),
        (10, "1"),
        (20, "0"),
        (30, "0"),
        (40, "1"),
        (210, "0"),
        (220, "0"),
        (230, "-1"),
        (50, "0"),
        (51, "90"),
    ]]);
    assert!(im.skipped.is_empty(), "{:?}", im.skipped);
    let id = entities(&im)[0].0;
    close(
        im.sketch.point(PointRef::Control(id, 0)).unwrap(),
        -1.0,
        0.0,
    );
    close(im.sketch.point(PointRef::Start(id)).unwrap(), -1.0, 1.0);
    close(im.sketch.point(PointRef::End(id)).unwrap(), -2.0, 0.0);
}

#[test]
fn a_bulged_polyline_is_lines_and_arcs_joined_end_to_end() {
    // (0, 0) → (2, 0) straight; (2, 0) → (2, 2) with bulge 1, a counter-clockwise half circle
    // about (2, 1) through (3, 1); (2, 2) → (0, 2) with bulge −tan(π/8), a clockwise quarter
    // turn on the chord of length 2 (radius √2); closed back to (0, 0) straight.
    let b = format!("{}", -(std::f64::consts::PI / 8.0).tan());
    let im = read(&[&[
        (0, "LWPOLYLINE"),
        (100, "AcDbEntity"),
        (8, "0"),
        (100, "AcDbPolyline"),
        (90, "4"),
        (70, "1"),
        (10, "0"),
        (20, "0"),
        (10, "2"),
        (20, "0"),
        (42, "1"),
        (10, "2"),
        (20, "2"),
        (42, &b),
        (10, "0"),
        (20, "2"),
    ]]);
    assert!(im.skipped.is_empty(), "{:?}", im.skipped);
    let all = entities(&im);
    assert_eq!(all.len(), 4);
    assert_eq!(
        all[0].1,
        Entity::Line([Point2::new(0.0, 0.0), Point2::new(2.0, 0.0)])
    );
    let Entity::Arc([c, s, e]) = all[1].1 else {
        panic!("segment 1 is an arc: {:?}", all[1].1)
    };
    close(c, 2.0, 1.0);
    close(s, 2.0, 0.0);
    close(e, 2.0, 2.0);
    // Clockwise from (2, 2) to (0, 2), travelling in −x, the arc bulges below the chord, so its
    // centre lies above it at (1, 3) (distance 1 from the chord's midpoint, radius √2); the
    // sketch arc runs counter-clockwise from (0, 2) to (2, 2) through (1, 3 − √2).
    let Entity::Arc([c, s, e]) = all[2].1 else {
        panic!("segment 2 is an arc: {:?}", all[2].1)
    };
    close(c, 1.0, 3.0);
    close(s, 0.0, 2.0);
    close(e, 2.0, 2.0);
    assert_eq!(
        all[3].1,
        Entity::Line([Point2::new(0.0, 2.0), Point2::new(0.0, 0.0)])
    );
    // Four joins close the loop; the reversed arc joins through its end and start.
    let joins = coincidences(&im);
    assert_eq!(joins.len(), 4, "{joins:?}");
    for (a, b) in joins {
        let (pa, pb) = (im.sketch.point(a).unwrap(), im.sketch.point(b).unwrap());
        assert!((pa - pb).norm() < 1e-12, "{a} and {b} are apart");
    }
}

#[test]
fn the_bulge_centre_formula_matches_the_quarter_circle() {
    // From (1, 0) to (0, 1) with bulge tan(π/8): the counter-clockwise quarter about (0, 0).
    let b = format!("{}", (std::f64::consts::PI / 8.0).tan());
    let im = read(&[&[
        (0, "LWPOLYLINE"),
        (90, "2"),
        (70, "0"),
        (10, "1"),
        (20, "0"),
        (42, &b),
        (10, "0"),
        (20, "1"),
    ]]);
    let Entity::Arc([c, s, e]) = entities(&im)[0].1 else {
        panic!("an arc")
    };
    close(c, 0.0, 0.0);
    close(s, 1.0, 0.0);
    close(e, 0.0, 1.0);
}

#[test]
fn an_ellipse_and_an_elliptic_arc_are_read_in_both_extrusions() {
    // Centre (1, 1), major axis (2, 0), ratio 0.5: a = 2, b = 1.
    let full: &[(i32, &str)] = &[
        (0, "ELLIPSE"),
        (10, "1"),
        (20, "1"),
        (30, "0"),
        (11, "2"),
        (21, "0"),
        (31, "0"),
        (40, "0.5"),
        (41, "0"),
        (42, "6.283185307179586"),
    ];
    // The quarter from t = 0 to t = π/2: from (3, 1) to (1, 2).
    let quarter: &[(i32, &str)] = &[
        (0, "ELLIPSE"),
        (10, "1"),
        (20, "1"),
        (30, "0"),
        (11, "2"),
        (21, "0"),
        (31, "0"),
        (40, "0.5"),
        (41, "0"),
        (42, "1.5707963267948966"),
    ];
    // The same quarter with N = −Z: P(t) = C + cos t·M + sin t·k·(N × M) = (1 + 2 cos t,
    // 1 − sin t), from (3, 1) to (1, 0), clockwise; the sketch arc runs from (1, 0) to (3, 1).
    let mirrored: &[(i32, &str)] = &[
        (0, "ELLIPSE"),
        (10, "1"),
        (20, "1"),
        (30, "0"),
        (11, "2"),
        (21, "0"),
        (31, "0"),
        (210, "0"),
        (220, "0"),
        (230, "-1"),
        (40, "0.5"),
        (41, "0"),
        (42, "1.5707963267948966"),
    ];
    let im = read(&[full, quarter, mirrored]);
    assert!(im.skipped.is_empty(), "{:?}", im.skipped);
    let all = entities(&im);
    let Entity::Ellipse {
        points: [c, v],
        semi_axis_b,
    } = all[0].1
    else {
        panic!("an ellipse: {:?}", all[0].1)
    };
    close(c, 1.0, 1.0);
    close(v, 3.0, 1.0);
    assert_abs_diff_eq!(semi_axis_b, 1.0, epsilon = 1e-15);
    close(
        im.sketch.point(PointRef::Start(all[1].0)).unwrap(),
        3.0,
        1.0,
    );
    close(im.sketch.point(PointRef::End(all[1].0)).unwrap(), 1.0, 2.0);
    close(
        im.sketch.point(PointRef::Start(all[2].0)).unwrap(),
        1.0,
        0.0,
    );
    close(im.sketch.point(PointRef::End(all[2].0)).unwrap(), 3.0, 1.0);
}

#[test]
fn a_rational_spline_is_a_nurbs_curve_and_a_one_span_spline_a_bezier() {
    // The quarter of the unit circle: degree 2, weights 1, √2/2, 1.
    let w = format!("{}", std::f64::consts::FRAC_1_SQRT_2);
    let quarter: Vec<(i32, &str)> = vec![
        (0, "SPLINE"),
        (70, "12"),
        (71, "2"),
        (40, "0"),
        (40, "0"),
        (40, "0"),
        (40, "1"),
        (40, "1"),
        (40, "1"),
        (41, "1"),
        (41, &w),
        (41, "1"),
        (10, "1"),
        (20, "0"),
        (30, "0"),
        (10, "1"),
        (20, "1"),
        (30, "0"),
        (10, "0"),
        (20, "1"),
        (30, "0"),
    ];
    let cubic: &[(i32, &str)] = &[
        (0, "SPLINE"),
        (70, "8"),
        (71, "3"),
        (40, "0"),
        (40, "0"),
        (40, "0"),
        (40, "0"),
        (40, "1"),
        (40, "1"),
        (40, "1"),
        (40, "1"),
        (10, "0"),
        (20, "0"),
        (30, "0"),
        (10, "1"),
        (20, "2"),
        (30, "0"),
        (10, "3"),
        (20, "2"),
        (30, "0"),
        (10, "4"),
        (20, "0"),
        (30, "0"),
    ];
    let im = read(&[&quarter, cubic]);
    assert!(im.skipped.is_empty(), "{:?}", im.skipped);
    let all = entities(&im);
    assert!(matches!(all[0].1, Entity::Nurbs(_)), "{:?}", all[0].1);
    for k in 0..=10 {
        let p = im
            .sketch
            .curve_point(all[0].0, f64::from(k) / 10.0)
            .unwrap();
        assert_abs_diff_eq!(p.coords.norm(), 1.0, epsilon = 1e-14);
    }
    assert!(matches!(all[1].1, Entity::Bezier(_)), "{:?}", all[1].1);
    // C(½) of the cubic: (P₀ + 3P₁ + 3P₂ + P₃)/8 = (2, 1.5).
    close(im.sketch.curve_point(all[1].0, 0.5).unwrap(), 2.0, 1.5);
}

#[test]
fn lines_that_meet_within_the_tolerance_are_joined_and_others_are_not() {
    let a: &[(i32, &str)] = &[(0, "LINE"), (10, "0"), (20, "0"), (11, "1"), (21, "0")];
    let near: &[(i32, &str)] = &[
        (0, "LINE"),
        (10, "1.0000000000001"),
        (20, "0"),
        (11, "1"),
        (21, "1"),
    ];
    let far: &[(i32, &str)] = &[(0, "LINE"), (10, "1.001"), (20, "1"), (11, "2"), (21, "2")];
    let im = read(&[a, near, far]);
    let all = entities(&im);
    assert_eq!(
        coincidences(&im),
        vec![(PointRef::End(all[0].0), PointRef::Start(all[1].0))]
    );
    // No joins at all with a negative tolerance.
    let text = dxf_text(&[a, near, far]);
    let options = ReadOptions {
        join_tolerance: -1.0,
        ..ReadOptions::default()
    };
    let im = dxf::read(text.as_bytes(), &options).unwrap();
    assert!(coincidences(&im).is_empty());
}

#[test]
fn what_is_not_sketch_geometry_is_listed_with_its_handle_and_reason() {
    let im = read(&[
        LINE,
        &[
            (0, "TEXT"),
            (5, "2F"),
            (10, "0"),
            (20, "0"),
            (40, "1"),
            (1, "hello"),
        ],
        &[
            (0, "LINE"),
            (5, "30"),
            (10, "0"),
            (20, "0"),
            (30, "0"),
            (11, "1"),
            (21, "0"),
            (31, "1"),
        ],
        &[
            (0, "SPLINE"),
            (5, "31"),
            (71, "3"),
            (11, "0"),
            (21, "0"),
            (31, "0"),
            (11, "1"),
            (21, "1"),
            (31, "0"),
        ],
        &[
            (0, "CIRCLE"),
            (5, "32"),
            (10, "0"),
            (20, "0"),
            (30, "0"),
            (40, "0"),
        ],
        &[
            (0, "INSERT"),
            (5, "33"),
            (2, "BOLT"),
            (10, "0"),
            (20, "0"),
            (30, "0"),
        ],
    ]);
    assert_eq!(im.sketch.entities().count(), 1, "only the first line");
    let listed: Vec<String> = im.skipped.iter().map(ToString::to_string).collect();
    assert_eq!(listed.len(), 5, "{listed:#?}");
    assert!(listed[0].starts_with("TEXT 1 (handle 2F)"), "{}", listed[0]);
    assert!(listed[1].contains("differ in z"), "{}", listed[1]);
    assert!(listed[2].contains("fit points"), "{}", listed[2]);
    assert!(listed[3].contains("radius"), "{}", listed[3]);
    assert!(listed[4].contains("block references"), "{}", listed[4]);
}

#[test]
fn an_imported_profile_is_already_solved() {
    // Two lines and an arc tangent to neither, joined: the joins hold, so a solve moves
    // nothing.
    let im = read(&[
        &[(0, "LINE"), (10, "0"), (20, "0"), (11, "2"), (21, "0")],
        &[
            (0, "ARC"),
            (10, "2"),
            (20, "1"),
            (40, "1"),
            (50, "270"),
            (51, "90"),
        ],
        &[(0, "LINE"), (10, "2"), (20, "2"), (11, "0"), (21, "2")],
    ]);
    assert_eq!(coincidences(&im).len(), 2);
    let before = entities(&im);
    let mut sketch = im.sketch;
    sketch.solve().expect("the joins hold");
    for ((_, a), (_, b)) in before.iter().zip(sketch.entities()) {
        let (pa, pb) = (blocks(a), blocks(b));
        for (p, q) in pa.iter().zip(&pb) {
            assert!((p - q).norm() < 1e-9, "{a:?} moved to {b:?}");
        }
    }
}

fn blocks(e: &Entity) -> Vec<Point2<f64>> {
    match e {
        Entity::Line(p) => p.to_vec(),
        Entity::Arc(p) => p.to_vec(),
        other => panic!("unexpected {other:?}"),
    }
}
