//! Angle rows at the start a designer often draws: lines at right angles, curves meeting at a
//! corner. Each row is an angle (atan2), whose gradient does not vanish there, so the analysis
//! calls nothing singular and the solve reaches the sense asked. Expected values by hand.

#![allow(clippy::unwrap_used)] // fixture helpers unwrap like the tests do

use camber_geom::BezierCurve2;
use camber_sketch::constraints::{
    Angle, CurveCurveTangent, Fixed, G1JoinFree, Parallel, Perpendicular,
};
use camber_sketch::{Constraint, Contact, Entity, EntityId, PointRef, Sense, Sketch};
use nalgebra::{Point2, Vector2};

fn cubic(s: &mut Sketch, points: [[f64; 2]; 4]) -> EntityId {
    s.add_bezier(
        BezierCurve2::try_new(points.iter().map(|p| Point2::new(p[0], p[1])).collect()).unwrap(),
    )
    .unwrap()
}

fn direction(s: &Sketch, line: EntityId) -> Vector2<f64> {
    match s.entity(line).unwrap() {
        Entity::Line([a, b]) => b - a,
        other => panic!("not a line: {other:?}"),
    }
}

/// The tangent of a curve at its start (`end` false) or end, from its control points.
fn end_tangent(s: &Sketch, curve: EntityId, end: bool) -> Vector2<f64> {
    let p = s.entity(curve).unwrap().points().to_vec();
    if end {
        p[3] - p[2]
    } else {
        p[1] - p[0]
    }
}

/// One component whose analysis names nothing singular, redundant or conflicting, with
/// `rows` independent rows.
fn assert_regular(s: &Sketch, rows: usize) {
    let analyses = s.analyze().unwrap();
    assert_eq!(analyses.len(), 1);
    let a = &analyses[0].analysis;
    assert!(a.accidental.is_empty(), "{a:?}");
    assert!(a.redundant.is_empty() && a.conflicting.is_empty(), "{a:?}");
    assert_eq!(a.rank, rows, "{a:?}");
}

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

#[test]
fn a_g1_join_at_a_right_angle_corner_is_regular_and_solves_same_sense() {
    let mut s = Sketch::new();
    let a = cubic(&mut s, [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]]);
    let b = cubic(&mut s, [[3.0, 0.0], [3.0, 1.0], [3.0, 2.0], [3.0, 3.0]]);
    s.add_constraint(Fixed::point(PointRef::Start(a))).unwrap();
    s.add_constraint(G1JoinFree {
        first: a,
        second: b,
    })
    .unwrap();
    // Coincidence (two rows, merged away or kept) and the angle row: the angle row counts.
    let analyses = s.analyze().unwrap();
    let an = &analyses[0].analysis;
    assert!(
        an.accidental.is_empty() && an.conflicting.is_empty(),
        "{an:?}"
    );
    s.solve().unwrap();
    let (t1, t2) = (end_tangent(&s, a, true), end_tangent(&s, b, false));
    assert!(
        cross(t1, t2).abs() <= 1e-9 * t1.norm() * t2.norm(),
        "{t1} {t2}"
    );
    assert!(t1.dot(&t2) > 0.0);
}

#[test]
fn parallel_from_perpendicular_and_perpendicular_from_parallel_are_regular() {
    for (kind, second_to) in [("parallel", [3.0, 2.0]), ("perpendicular", [5.0, 0.0])] {
        let mut s = Sketch::new();
        let l1 = s
            .add_line(Point2::new(0.0, 0.0), Point2::new(2.0, 0.0))
            .unwrap();
        let l2 = s
            .add_line(
                Point2::new(3.0, 0.0),
                Point2::new(second_to[0], second_to[1]),
            )
            .unwrap();
        let c: Constraint = if kind == "parallel" {
            Parallel {
                first: l1,
                second: l2,
            }
            .into()
        } else {
            Perpendicular {
                first: l1,
                second: l2,
            }
            .into()
        };
        s.add_constraint(c).unwrap();
        assert_regular(&s, 1);
        s.solve().unwrap();
        let (d1, d2) = (direction(&s, l1), direction(&s, l2));
        let sine = cross(d1, d2) / (d1.norm() * d2.norm());
        let cosine = d1.dot(&d2) / (d1.norm() * d2.norm());
        let off = if kind == "parallel" { sine } else { cosine };
        assert!(off.abs() < 1e-9, "{kind}: {d1} {d2}");
    }
}

/// An angle asked from the opposite sense (the start is θ + π away): the row reads π, not 0,
/// so the solve turns the line round and the sense check passes.
#[test]
fn an_angle_from_the_opposite_sense_turns_round() {
    let mut s = Sketch::new();
    let l1 = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(2.0, 0.0))
        .unwrap();
    let l2 = s
        .add_line(Point2::new(2.0, 1.0), Point2::new(0.0, 1.0))
        .unwrap();
    s.add_constraint(Fixed::entity(l1)).unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(l2, 0)))
        .unwrap();
    s.add_constraint(Angle {
        first: l1,
        second: l2,
        angle: 0.0,
    })
    .unwrap();
    assert_regular(&s, 1);
    s.solve().unwrap();
    let d2 = direction(&s, l2);
    assert!(d2.y.abs() < 1e-9 * d2.norm() && d2.x > 0.0, "{d2}");
}

/// Two curves touching at a right angle, asked to touch with opposite travel: the angle row
/// is measured against −C₂′, regular there, and the solve ends opposite.
#[test]
fn a_curve_curve_tangency_at_a_right_angle_is_regular_for_either_sense() {
    for sense in [Sense::Agree, Sense::Oppose] {
        let mut s = Sketch::new();
        let a = cubic(&mut s, [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]]);
        let b = cubic(&mut s, [[1.5, -1.5], [1.5, -0.5], [1.5, 0.5], [1.5, 1.5]]);
        s.add_constraint(Fixed::point(PointRef::Start(a))).unwrap();
        s.add_constraint(Fixed::point(PointRef::End(a))).unwrap();
        s.add_constraint(CurveCurveTangent {
            first: a,
            u: Contact::At(0.5),
            second: b,
            v: Contact::At(0.5),
            sense,
        })
        .unwrap();
        let an = &s.analyze().unwrap()[0].analysis;
        assert!(
            an.accidental.is_empty() && an.conflicting.is_empty(),
            "{sense:?}: {an:?}"
        );
        s.solve().unwrap();
        let pa = s.entity(a).unwrap().points().to_vec();
        let pb = s.entity(b).unwrap().points().to_vec();
        // At u = ½ a cubic's tangent is (3/4)·(P₂ + P₃ − P₀ − P₁).
        let t = |p: &[Point2<f64>]| (p[2] - p[0]) + (p[3] - p[1]);
        let (t1, t2) = (t(&pa), t(&pb));
        assert!(
            cross(t1, t2).abs() <= 1e-9 * t1.norm() * t2.norm(),
            "{sense:?}"
        );
        assert!(sense.sign() * t1.dot(&t2) > 0.0, "{sense:?}: {t1} {t2}");
    }
}
