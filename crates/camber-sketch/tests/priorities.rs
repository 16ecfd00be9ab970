//! Issue 17, item 4: constraint priorities. When the whole set cannot be met, the tiers are met
//! in order (0 required, then 1, 2, …), each as closely as the tiers before allow, and the
//! report names every constraint that gave way; a failed required tier changes nothing.

#![allow(clippy::unwrap_used)] // fixture helpers unwrap like the tests do

use camber_geom::BezierCurve2;
use camber_sketch::constraints::{
    Coincident, Distance, Fixed, PointAtParameter, PointOnCircle, PointOnLine,
};
use camber_sketch::file::{from_json, to_json};
use camber_sketch::{Error, PointRef, Sketch, Target};
use camber_solve::{Selection, Status};
use nalgebra::Point2;

fn close(a: Point2<f64>, b: Point2<f64>, tol: f64) -> bool {
    (a - b).norm() <= tol
}

#[test]
fn a_lower_tier_gives_way_to_a_higher_one_on_a_curve() {
    // A quadratic with fixed ends: C(½) = ¼P₀ + ½P₁ + ¼P₂. Priority 1 wants C(½) at (1, 1),
    // priority 2 wants it at (1, 3): the first is met exactly, the second relaxed.
    let mut s = Sketch::new();
    let c = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 0.0),
                Point2::new(1.0, 0.5),
                Point2::new(2.0, 0.0),
            ])
            .unwrap(),
        )
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(c))).unwrap();
    s.add_constraint(Fixed::point(PointRef::End(c))).unwrap();
    let near = s
        .add_constraint(PointAtParameter {
            curve: c,
            u: 0.5,
            target: Target::At(Point2::new(1.0, 1.0)),
        })
        .unwrap();
    let far = s
        .add_constraint(PointAtParameter {
            curve: c,
            u: 0.5,
            target: Target::At(Point2::new(1.0, 3.0)),
        })
        .unwrap();
    s.set_priority(near, 1).unwrap();
    s.set_priority(far, 2).unwrap();
    let report = s.solve().unwrap();
    assert_eq!(report.relaxed(), vec![far]);
    let r = &report.components[0].report;
    assert_eq!(
        (r.status, r.selection),
        (Status::Relaxed, Selection::Prioritized)
    );
    let tiers: Vec<(u8, bool)> = r.priorities.iter().map(|t| (t.priority, t.met)).collect();
    assert_eq!(tiers, vec![(0, true), (1, true), (2, false)]);
    // P₁ = 2·(1, 1) − ¼(P₀ + P₂)·2 = (1, 2).
    assert!(close(
        s.curve_point(c, 0.5).unwrap(),
        Point2::new(1.0, 1.0),
        1e-9
    ));
    assert!(close(
        s.point(PointRef::Control(c, 1)).unwrap(),
        Point2::new(1.0, 2.0),
        1e-9
    ));
}

#[test]
fn a_fixed_point_of_lower_priority_moves_as_little_as_it_can() {
    // P is fixed at (0, 0) with priority 1 and must lie on the circle of radius 1 about (3, 0)
    // (required): the nearest point of the circle, (2, 0).
    let mut s = Sketch::new();
    let p = s.add_point(Point2::new(0.0, 0.0)).unwrap();
    let circle = s.add_circle(Point2::new(3.0, 0.0), 1.0).unwrap();
    s.add_constraint(Fixed::entity(circle)).unwrap();
    let hold = s.add_constraint(Fixed::point(PointRef::Point(p))).unwrap();
    s.add_constraint(PointOnCircle {
        point: PointRef::Point(p),
        circle,
    })
    .unwrap();
    s.set_priority(hold, 1).unwrap();
    let report = s.solve().unwrap();
    assert_eq!(report.relaxed(), vec![hold]);
    assert!(close(
        s.point(PointRef::Point(p)).unwrap(),
        Point2::new(2.0, 0.0),
        1e-8
    ));
    // The circle did not move: it is required.
    assert_eq!(
        s.point(PointRef::Control(circle, 0)).unwrap(),
        Point2::new(3.0, 0.0)
    );
}

#[test]
fn a_coincidence_with_a_priority_is_not_merged_and_gives_way() {
    // Two fixed points cannot coincide; the coincidence (priority 3) is relaxed, nothing moves.
    let mut s = Sketch::new();
    let a = s.add_point(Point2::new(0.0, 0.0)).unwrap();
    let b = s.add_point(Point2::new(1.0, 0.0)).unwrap();
    s.add_constraint(Fixed::point(PointRef::Point(a))).unwrap();
    s.add_constraint(Fixed::point(PointRef::Point(b))).unwrap();
    let join = s
        .add_constraint(Coincident {
            a: PointRef::Point(a),
            b: PointRef::Point(b),
        })
        .unwrap();
    assert!(matches!(s.clone().solve(), Err(Error::Conflicting { .. })));
    s.set_priority(join, 3).unwrap();
    let report = s.solve().unwrap();
    assert_eq!(report.relaxed(), vec![join]);
    assert_eq!(s.point(PointRef::Point(b)).unwrap(), Point2::new(1.0, 0.0));
}

#[test]
fn a_consistent_sketch_solves_as_without_priorities() {
    let mut s = Sketch::new();
    let a = s.add_point(Point2::new(0.0, 0.0)).unwrap();
    let b = s.add_point(Point2::new(1.0, 0.0)).unwrap();
    s.add_constraint(Fixed::point(PointRef::Point(a))).unwrap();
    let d = s
        .add_constraint(Distance {
            a: PointRef::Point(a),
            b: PointRef::Point(b),
            distance: 2.0,
        })
        .unwrap();
    s.set_priority(d, 1).unwrap();
    let report = s.solve().unwrap();
    assert!(report.relaxed().is_empty());
    let r = &report.components[0].report;
    assert_eq!(r.status, Status::Solved);
    assert!(r.priorities.is_empty());
    assert!(close(
        s.point(PointRef::Point(b)).unwrap(),
        Point2::new(2.0, 0.0),
        1e-9
    ));
}

#[test]
fn conflicting_required_constraints_still_fail_and_change_nothing() {
    // The point must be on two parallel fixed lines (required): no priority can help, and the
    // error names required constraints only.
    let mut s = Sketch::new();
    let p = s.add_point(Point2::new(0.0, 0.5)).unwrap();
    let l1 = s
        .add_line(Point2::new(-1.0, 0.0), Point2::new(1.0, 0.0))
        .unwrap();
    let l2 = s
        .add_line(Point2::new(-1.0, 1.0), Point2::new(1.0, 1.0))
        .unwrap();
    s.add_constraint(Fixed::entity(l1)).unwrap();
    s.add_constraint(Fixed::entity(l2)).unwrap();
    let on1 = s
        .add_constraint(PointOnLine {
            point: PointRef::Point(p),
            line: l1,
        })
        .unwrap();
    let on2 = s
        .add_constraint(PointOnLine {
            point: PointRef::Point(p),
            line: l2,
        })
        .unwrap();
    let wish = s.add_constraint(Fixed::point(PointRef::Point(p))).unwrap();
    s.set_priority(wish, 1).unwrap();
    let before = to_json(&s).unwrap();
    match s.solve() {
        Err(Error::Conflicting { constraints }) => {
            assert!(
                constraints.iter().all(|c| *c == on1 || *c == on2),
                "{constraints:?}"
            );
        }
        other => panic!("expected conflicting required constraints, got {other:?}"),
    }
    assert_eq!(to_json(&s).unwrap(), before);
}

#[test]
fn priorities_round_trip_through_files_and_bad_ones_are_named() {
    let text = r#"{"version": 1,
      "entities": [{"id": 0, "kind": "point", "at": [0, 0]}, {"id": 1, "kind": "point", "at": [1, 0]}],
      "constraints": [
        {"id": 2, "kind": "fixed", "target": {"point": {"point": 0}}},
        {"id": 3, "priority": 2, "kind": "distance", "a": {"point": 0}, "b": {"point": 1}, "distance": 2}
      ]}"#;
    let s = from_json(text).unwrap();
    assert_eq!(s.priority(camber_sketch::ConstraintId(3)), 2);
    assert_eq!(s.priority(camber_sketch::ConstraintId(2)), 0);
    let saved = to_json(&s).unwrap();
    assert!(
        saved.contains(r#"{"id":3,"priority":2,"kind":"distance""#),
        "{saved}"
    );
    assert!(!saved.contains(r#""id":2,"priority""#));
    assert_eq!(to_json(&from_json(&saved).unwrap()).unwrap(), saved);
    for bad in ["256", "-1", "\"high\"", "1.5"] {
        let text = text.replace(r#""priority": 2"#, &format!(r#""priority": {bad}"#));
        let err = from_json(&text).unwrap_err().to_string();
        assert!(
            err.contains("constraints[1].priority") && err.contains("0 (required) to 255"),
            "{bad}: {err}"
        );
    }
}

#[test]
fn a_drag_target_is_a_wish_below_every_tier() {
    // B keeps 1 from A with priority 1. The cursor is not a constraint: dragged around a
    // circle of radius 1.2, B follows on its own circle of radius 1 and the distance never
    // gives way to the cursor.
    let mut s = Sketch::new();
    let a = s.add_point(Point2::new(0.0, 0.0)).unwrap();
    let b = s.add_point(Point2::new(1.0, 0.0)).unwrap();
    s.add_constraint(Fixed::point(PointRef::Point(a))).unwrap();
    let d = s
        .add_constraint(Distance {
            a: PointRef::Point(a),
            b: PointRef::Point(b),
            distance: 1.0,
        })
        .unwrap();
    s.set_priority(d, 1).unwrap();
    let mut drag = s.drag(PointRef::Point(b)).unwrap();
    for k in 1..=40 {
        let angle = std::f64::consts::FRAC_PI_2 * f64::from(k) / 40.0;
        drag.update(Point2::new(1.2 * angle.cos(), 1.2 * angle.sin()))
            .unwrap();
    }
    drag.finish(&mut s).unwrap();
    let at = s.point(PointRef::Point(b)).unwrap();
    // On the circle the distance keeps, and up where the cursor went.
    assert!((at.coords.norm() - 1.0).abs() < 1e-9, "{at:?}");
    assert!(at.y > 0.95, "{at:?}");
}

#[test]
fn a_tier_the_ones_before_determine_leaves_unread_control_points_alone() {
    // A cubic with a fixed start. Priority 1 puts its end at (1, 1); priority 2 wants the
    // start at (1.5, 2) and priority 3 the ends 1 apart: both are settled by the tiers before
    // (their rows have no freedom left) and relaxed. No constraint reads P₁ and P₂: they stay
    // where they were (they were once thrown to 3e15 while every residual looked right).
    let mut s = Sketch::new();
    let start = [
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 0.5),
        Point2::new(2.0, 0.3),
        Point2::new(3.0, 0.0),
    ];
    let c = s
        .add_bezier(BezierCurve2::try_new(start.to_vec()).unwrap())
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(c))).unwrap();
    let end = s
        .add_constraint(PointAtParameter {
            curve: c,
            u: 1.0,
            target: Target::At(Point2::new(1.0, 1.0)),
        })
        .unwrap();
    let moved_start = s
        .add_constraint(PointAtParameter {
            curve: c,
            u: 0.0,
            target: Target::At(Point2::new(1.5, 2.0)),
        })
        .unwrap();
    let apart = s
        .add_constraint(Distance {
            a: PointRef::Start(c),
            b: PointRef::End(c),
            distance: 1.0,
        })
        .unwrap();
    s.set_priority(end, 1).unwrap();
    s.set_priority(moved_start, 2).unwrap();
    s.set_priority(apart, 3).unwrap();
    let report = s.solve().unwrap();
    assert_eq!(report.relaxed(), vec![moved_start, apart]);
    for (k, was) in start.iter().enumerate().take(3).skip(1) {
        let now = s.point(PointRef::Control(c, k)).unwrap();
        assert!(close(now, *was, 1e-12), "P{k} moved to {now:?}");
    }
    assert!(close(
        s.point(PointRef::End(c)).unwrap(),
        Point2::new(1.0, 1.0),
        1e-9
    ));
}
