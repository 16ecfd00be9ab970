//! Issue 13: the cases a new user met where the analysis or the solve said something untrue,
//! or a drag refused what could move. Each is checked against the right answer.

#![allow(clippy::unwrap_used)] // fixture helpers unwrap like the tests do

use camber_geom::BezierCurve2;
use camber_sketch::constraints::{Fixed, TangentToCircle, TangentToLine};
use camber_sketch::{
    CircleSide, Constraint, Contact, Entity, EntityId, LineSide, PointRef, Rotation, Sense,
    Sketch,
};
use nalgebra::Point2;

/// Case 4: a cubic with fixed ends, touching a fixed circle from outside (counter-clockwise)
/// and a fixed line on its left, both at free parameters guessed at ½ (an impossible start:
/// one parameter for two contacts).
fn case_4(u_circle: f64, u_line: f64) -> (Sketch, EntityId, [camber_sketch::ConstraintId; 2]) {
    let mut s = Sketch::new();
    let c = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(-3.0, 0.0),
                Point2::new(-1.0, 1.0),
                Point2::new(1.0, 0.6),
                Point2::new(3.0, 0.0),
            ])
            .unwrap(),
        )
        .unwrap();
    let circle = s.add_circle(Point2::new(0.3, 2.2), 1.0).unwrap();
    let line = s
        .add_line(Point2::new(-3.0, -0.8), Point2::new(3.0, -0.5))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(c))).unwrap();
    s.add_constraint(Fixed::point(PointRef::End(c))).unwrap();
    s.add_constraint(Fixed::entity(circle)).unwrap();
    s.add_constraint(Fixed::entity(line)).unwrap();
    let a = s
        .add_constraint(TangentToCircle {
            curve: c,
            circle,
            u: Contact::Free(u_circle),
            side: CircleSide::Outside,
            rotation: Rotation::CounterClockwise,
        })
        .unwrap();
    let b = s
        .add_constraint(TangentToLine {
            curve: c,
            line,
            u: Contact::Free(u_line),
            side: LineSide::Left,
            sense: Sense::Agree,
        })
        .unwrap();
    (s, c, [a, b])
}

/// The solved contact parameters of case 4's two contacts.
fn contacts(s: &Sketch, ids: [camber_sketch::ConstraintId; 2]) -> [f64; 2] {
    ids.map(|id| match s.constraint(id).unwrap() {
        Constraint::TangentToCircle(t) => t.u.value(),
        Constraint::TangentToLine(t) => t.u.value(),
        other => panic!("{other:?}"),
    })
}

#[test]
fn issue_13_case_4_solves_from_a_start_the_user_could_not_guess() {
    let (mut given, c, ids) = case_4(0.5, 0.5);
    let report = given.solve().unwrap();
    assert!(
        report.components[0]
            .report
            .reason
            .to_string()
            .contains("contact start"),
        "{}",
        report.components[0].report.reason
    );
    // The good guesses solve directly (to a slightly different member of the 2-DOF family: the
    // minimum-norm metric counts the contact parameters' moves too).
    let (mut reference, _, _) = case_4(0.3, 0.8);
    reference.solve().unwrap();
    let [u, v] = contacts(&given, ids);
    assert!(u < v, "the circle is touched before the line: {u} {v}");
    // The contacts hold where they are recorded.
    let Entity::Bezier(curve) = given.entity(c).unwrap() else {
        unreachable!()
    };
    let p = camber_geom::ParametricCurve::point(curve, u).unwrap();
    assert!(((p - Point2::new(0.3, 2.2)).norm() - 1.0).abs() < 1e-9);
    // On the line y = −0.8 + 0.05·(x + 3), tangent to it, from above.
    let (q, t) = camber_geom::ParametricCurve::point_and_derivative(curve, v).unwrap();
    assert!((q.y - (-0.8 + 0.05 * (q.x + 3.0))).abs() < 1e-9);
    assert!((t.y - 0.05 * t.x).abs() < 1e-9 * t.norm() && t.x > 0.0);
    // Honest: the curve stays on or above the line and outside the circle everywhere.
    for i in 0..=2000 {
        let r = camber_geom::ParametricCurve::point(curve, f64::from(i) / 2000.0).unwrap();
        assert!(r.y >= -0.8 + 0.05 * (r.x + 3.0) - 1e-7);
        assert!((r - Point2::new(0.3, 2.2)).norm() >= 1.0 - 1e-7);
    }
}
