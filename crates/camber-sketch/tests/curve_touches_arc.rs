//! A free-form curve touching a circular arc in the arc's interior at a free contact parameter
//! (`tangent_to_circle` with an arc): the symmetric closed form, the contact refused off the
//! arc's sweep, the file round trip, the exact derivatives of the rows, and drags of the arc
//! that keep the curve on its side without crossing.

#![allow(clippy::unwrap_used)]

use std::f64::consts::PI;

use camber_geom::{BezierCurve2, CircularArc, ParametricCurve};
use camber_sketch::constraints::tangent_to_circle::CircleContact;
use camber_sketch::constraints::{Fixed, TangentToCircle};
use camber_sketch::curve_eval::CurveBasis;
use camber_sketch::file::{from_json, to_json};
use camber_sketch::residuals::Param;
use camber_sketch::{
    CircleSide, Constraint, ConstraintId, Contact, Entity, EntityId, Error, PointRef, Rotation,
    Sketch,
};
use camber_solve::testing::check_jacobian;
use nalgebra::{Point2, Vector2};

/// A cubic from (−2, 1.5) to (2, 1.5), flat, its ends fixed; an arc of radius 1 about the
/// origin from `start` to `end` (radians); the curve touching the arc from outside, running
/// clockwise over it, contact starting at u = 0.5.
fn over_an_arc(start: f64, end: f64, fix_arc: bool) -> (Sketch, EntityId, EntityId, ConstraintId) {
    let mut s = Sketch::new();
    let c = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(-2.0, 1.5),
                Point2::new(-0.7, 1.5),
                Point2::new(0.7, 1.5),
                Point2::new(2.0, 1.5),
            ])
            .unwrap(),
        )
        .unwrap();
    for j in [0, 3] {
        s.add_constraint(Fixed::point(PointRef::Control(c, j)))
            .unwrap();
    }
    let a = s
        .add_arc(&CircularArc::try_new(Point2::new(0.0, 0.0), 1.0, start, end).unwrap())
        .unwrap();
    if fix_arc {
        s.add_constraint(Fixed::entity(a)).unwrap();
    }
    let k = s
        .add_constraint(TangentToCircle {
            curve: c,
            circle: a,
            u: Contact::Free(0.5),
            side: CircleSide::Outside,
            rotation: Rotation::Clockwise,
        })
        .unwrap();
    (s, c, a, k)
}

/// The curve and the solved contact parameter of constraint `k`.
fn solved(s: &Sketch, c: EntityId, k: ConstraintId) -> (BezierCurve2<f64>, f64) {
    let Constraint::TangentToCircle(TangentToCircle { u, .. }) = s.constraint(k).unwrap() else {
        panic!("not a tangency");
    };
    let Entity::Bezier(curve) = s.entity(c).unwrap() else {
        panic!("not a Bézier curve");
    };
    (curve.clone(), u.value())
}

/// The least of |C(u) − c| − r over 2,000 samples of the curve.
fn least_gap(curve: &BezierCurve2<f64>, centre: Point2<f64>, radius: f64) -> f64 {
    (0..=2000)
        .map(|i| (curve.point(i as f64 / 2000.0).unwrap() - centre).norm() - radius)
        .fold(f64::INFINITY, f64::min)
}

/// Everything is symmetric about x = 0 and the least move keeps it so: the contact is the
/// arc's apex (0, 1) at u = ½, and the curve stays outside the arc's circle everywhere.
#[test]
fn a_curve_over_an_arc_touches_it_at_the_apex() {
    let (mut s, c, _, k) = over_an_arc(0.3, PI - 0.3, true);
    s.solve().unwrap();
    let (curve, u) = solved(&s, c, k);
    assert!((u - 0.5).abs() < 1e-9, "u = {u}");
    let p = curve.point(u).unwrap();
    assert!((p - Point2::new(0.0, 1.0)).norm() < 1e-9, "{p}");
    let gap = least_gap(&curve, Point2::origin(), 1.0);
    assert!(gap > -1e-9 && gap < 1e-6, "{gap}");
}

/// An arc below its centre: its circle would touch the curve at the top, the arc does not.
/// The solve fails naming the constraint and the arc, and the sketch is left as it was.
#[test]
fn a_contact_off_the_arc_is_refused_and_nothing_changes() {
    let (mut s, _, a, k) = over_an_arc(PI + 0.3, 2.0 * PI - 0.3, true);
    let before = to_json(&s).unwrap();
    let err = s.solve().unwrap_err();
    assert!(
        matches!(err, Error::ContactOffArc { constraint, arc, outside }
            if constraint == k && arc == a && outside > 1.0),
        "{err}"
    );
    assert_eq!(to_json(&s).unwrap(), before);
}

/// Saved and loaded, the sketch solves to the same contact.
#[test]
fn the_arc_contact_survives_a_file_round_trip() {
    let (s, c, _, k) = over_an_arc(0.3, PI - 0.3, true);
    let mut loaded = from_json(&to_json(&s).unwrap()).unwrap();
    let mut original = s;
    original.solve().unwrap();
    loaded.solve().unwrap();
    let ((a, ua), (b, ub)) = (solved(&original, c, k), solved(&loaded, c, k));
    assert_eq!(ua.to_bits(), ub.to_bits());
    assert_eq!(a.control_points(), b.control_points());
}

/// The rows' Jacobian (dual numbers) against central differences, the contact parameter and
/// the arc's centre and start included.
#[test]
fn the_arc_contact_rows_have_exact_derivatives() {
    let line = Entity::Line([Point2::new(-1.0, 1.1), Point2::new(1.2, 0.9)]);
    let rows = CircleContact::new(CurveBasis::of(&line).unwrap(), Param::Block, true).on_arc();
    let x: [&[f64]; 5] = [
        &[-1.0, 1.1],
        &[1.2, 0.9],
        &[0.45],
        &[0.1, -0.05],
        &[0.8, 0.6],
    ];
    check_jacobian(&rows, &x, 1e-6, 1e-7).unwrap();
}

/// The arc, free to move with its radius held by its own rows, is dragged by its centre in
/// 40 steps: the curve keeps touching it from outside, never crossing its circle.
#[test]
fn dragging_the_arc_keeps_the_curve_touching_it_from_outside() {
    let (mut s, c, a, _) = over_an_arc(0.3, PI - 0.3, false);
    s.solve().unwrap();
    let centre = PointRef::Control(a, 0);
    let start = s.point(centre).unwrap();
    let mut drag = s.drag(centre).unwrap();
    for i in 1..=40 {
        let t = i as f64 / 40.0;
        let target = start + Vector2::new(0.3 * (2.0 * PI * t).sin(), 0.25 * t);
        drag.update(target).unwrap();
        let entities = drag.entities().unwrap();
        let find = |id| {
            entities
                .iter()
                .find(|(e, _)| *e == id)
                .map(|(_, e)| e.clone())
        };
        let Some(Entity::Bezier(curve)) = find(c) else {
            panic!("curve");
        };
        let arc = find(a).and_then(|e| e.as_arc()).unwrap();
        let gap = least_gap(&curve, *arc.center(), arc.radius());
        assert!(gap > -1e-7, "step {i}: the curve crosses by {gap}");
        assert!(gap < 1e-6, "step {i}: the contact is lost ({gap})");
    }
}
