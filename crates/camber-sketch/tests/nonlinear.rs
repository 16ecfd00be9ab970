//! The nonlinear constraints in sketches: each solved from a hand-made start and checked
//! against its definition; Newton and SLSQP agree on a well-posed case; conflicts name their
//! constraints; honest contact refuses a result on the wrong side, leaving the sketch as it was.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_abs_diff_eq;
use camber_geom::{BezierCurve2, ParametricCurve};
use camber_sketch::constraints::{
    Angle, CurveCurveTangent, Distance, Fixed, G1JoinFree, G2Join, Parallel, Perpendicular,
    PointOnCircle, Radius, TangentToCircle, TangentToLine,
};
use camber_sketch::{
    CircleSide, Constraint, Contact, Entity, Error, LineSide, PointRef, Rotation, Sense, Sketch,
};
use camber_solve::{SolverChoice, SolverKind};
use camber_workloads::w2_bspline7;
use nalgebra::{Point2, Vector2};

fn bezier(s: &Sketch, id: camber_sketch::EntityId) -> BezierCurve2<f64> {
    match s.entity(id).unwrap() {
        Entity::Bezier(c) => c.clone(),
        _ => panic!("not a Bézier curve"),
    }
}

fn contact_u(s: &Sketch, id: camber_solve::ConstraintId) -> f64 {
    match s.constraint(id).unwrap() {
        Constraint::TangentToLine(TangentToLine { u, .. })
        | Constraint::TangentToCircle(TangentToCircle { u, .. }) => u.value(),
        _ => panic!("not a contact"),
    }
}

#[test]
fn tangent_to_line_at_a_free_parameter() {
    let mut s = Sketch::new();
    let c = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 1.0),
                Point2::new(1.0, 0.3),
                Point2::new(2.0, 0.4),
                Point2::new(3.0, 1.0),
            ])
            .unwrap(),
        )
        .unwrap();
    let line = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(1.0, 0.0))
        .unwrap();
    s.add_constraint(Fixed::entity(line)).unwrap();
    let id = s
        .add_constraint(TangentToLine {
            curve: c,
            line,
            u: Contact::Free(0.5),
            side: LineSide::Left,
            sense: Sense::Agree,
        })
        .unwrap();
    let report = s.solve().unwrap();
    assert_eq!(report.components[0].report.solver, SolverKind::Newton);
    let u = contact_u(&s, id);
    let (p, t) = bezier(&s, c).point_and_derivative(u).unwrap();
    assert_abs_diff_eq!(p.y, 0.0, epsilon = 1e-9);
    assert_abs_diff_eq!(t.y, 0.0, epsilon = 1e-9);
    assert!(t.x > 0.0);
    // The curve stays above the line (its left side).
    for k in 0..=100 {
        assert!(bezier(&s, c).point(f64::from(k) / 100.0).unwrap().y > -1e-9);
    }
}

#[test]
fn points_circles_and_distances() {
    let mut s = Sketch::new();
    let circle = s.add_circle(Point2::new(0.0, 0.0), 1.5).unwrap();
    let p = s.add_point(Point2::new(1.0, 1.0)).unwrap();
    let q = s.add_point(Point2::new(3.0, 1.0)).unwrap();
    s.add_constraint(Radius {
        circle,
        radius: 2.0,
    })
    .unwrap();
    s.add_constraint(PointOnCircle {
        point: PointRef::Point(p),
        circle,
    })
    .unwrap();
    s.add_constraint(Distance {
        a: PointRef::Point(p),
        b: PointRef::Point(q),
        distance: 1.0,
    })
    .unwrap();
    s.solve().unwrap();
    let Entity::Circle { center, radius } = s.entity(circle).unwrap().clone() else {
        panic!("circle");
    };
    let (pp, qq) = (
        s.point(PointRef::Point(p)).unwrap(),
        s.point(PointRef::Point(q)).unwrap(),
    );
    assert_abs_diff_eq!(radius, 2.0, epsilon = 1e-9);
    assert_abs_diff_eq!((pp - center).norm(), 2.0, epsilon = 1e-9);
    assert_abs_diff_eq!((qq - pp).norm(), 1.0, epsilon = 1e-9);
}

#[test]
fn parallel_perpendicular_and_angle_between_lines() {
    let mut s = Sketch::new();
    let base = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(1.0, 0.0))
        .unwrap();
    s.add_constraint(Fixed::entity(base)).unwrap();
    let a = s
        .add_line(Point2::new(0.0, 1.0), Point2::new(1.0, 1.2))
        .unwrap();
    let b = s
        .add_line(Point2::new(0.0, 2.0), Point2::new(0.2, 3.0))
        .unwrap();
    let c = s
        .add_line(Point2::new(0.0, 3.0), Point2::new(1.0, 3.4))
        .unwrap();
    s.add_constraint(Parallel {
        first: base,
        second: a,
    })
    .unwrap();
    s.add_constraint(Perpendicular {
        first: base,
        second: b,
    })
    .unwrap();
    let theta = 30f64.to_radians();
    s.add_constraint(Angle {
        first: base,
        second: c,
        angle: theta,
    })
    .unwrap();
    s.solve().unwrap();
    let dir = |id| match s.entity(id).unwrap() {
        Entity::Line([p, q]) => (q - p).normalize(),
        _ => panic!("line"),
    };
    assert_abs_diff_eq!(dir(a).y, 0.0, epsilon = 1e-9);
    assert_abs_diff_eq!(dir(b).x, 0.0, epsilon = 1e-9);
    assert_abs_diff_eq!(
        dir(c),
        Vector2::new(theta.cos(), theta.sin()),
        epsilon = 1e-9
    );
}

#[test]
fn g1_join_with_a_free_direction() {
    let mut s = Sketch::new();
    let first = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 0.0),
                Point2::new(1.0, 1.0),
                Point2::new(2.0, 1.0),
                Point2::new(3.0, 0.2),
            ])
            .unwrap(),
        )
        .unwrap();
    let second = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(3.1, 0.0),
                Point2::new(4.0, 0.5),
                Point2::new(5.0, 1.0),
                Point2::new(6.0, 0.0),
            ])
            .unwrap(),
        )
        .unwrap();
    s.add_constraint(G1JoinFree { first, second }).unwrap();
    s.solve().unwrap();
    let (c1, c2) = (bezier(&s, first), bezier(&s, second));
    let (p1, t1) = c1.point_and_derivative(1.0).unwrap();
    let (p2, t2) = c2.point_and_derivative(0.0).unwrap();
    assert_abs_diff_eq!(p1, p2, epsilon = 1e-9);
    assert_abs_diff_eq!(t1.x * t2.y - t1.y * t2.x, 0.0, epsilon = 1e-8);
    assert!(t1.dot(&t2) > 0.0);
}

#[test]
fn newton_and_slsqp_agree_on_the_diffuser() {
    let (s0, w) = w2_bspline7().unwrap();
    let mut pts = Vec::new();
    for force in [SolverChoice::Newton, SolverChoice::Slsqp] {
        let mut s = s0.clone();
        s.set_options(camber_sketch::solve::default_options().with_force(Some(force)));
        s.solve().unwrap();
        pts.push(
            (0..7)
                .map(|j| s.point(PointRef::Control(w.curve, j)).unwrap())
                .collect::<Vec<_>>(),
        );
    }
    for (a, b) in pts[0].iter().zip(&pts[1]) {
        assert_abs_diff_eq!(a, b, epsilon = 1e-6);
    }
}

#[test]
fn conflicting_circles_are_named() {
    let mut s = Sketch::new();
    let small = s.add_circle(Point2::new(0.0, 0.0), 1.0).unwrap();
    let large = s.add_circle(Point2::new(0.0, 0.0), 2.0).unwrap();
    s.add_constraint(Fixed::entity(small)).unwrap();
    s.add_constraint(Fixed::entity(large)).unwrap();
    let p = s.add_point(Point2::new(1.5, 0.1)).unwrap();
    let a = s
        .add_constraint(PointOnCircle {
            point: PointRef::Point(p),
            circle: small,
        })
        .unwrap();
    let b = s
        .add_constraint(PointOnCircle {
            point: PointRef::Point(p),
            circle: large,
        })
        .unwrap();
    match s.solve() {
        Err(Error::Conflicting { constraints }) => {
            assert!(
                constraints.contains(&a) && constraints.contains(&b),
                "{constraints:?}"
            );
        }
        other => panic!("expected a conflict, got {other:?}"),
    }
    assert_abs_diff_eq!(s.point(PointRef::Point(p)).unwrap(), Point2::new(1.5, 0.1));
}

#[test]
fn a_contact_on_the_wrong_side_is_refused() {
    let mut s = Sketch::new();
    // A straight segment can touch a circle only from outside: asking for the inside must fail
    // (the crossing is found, and its clearance row, whose curvature margin at the contact is
    // −|C′|²/(2r) < 0 for a segment, cannot be met; or the segment collapses to a point, a
    // cusp).
    let c = s
        .add_line(Point2::new(-2.0, 1.3), Point2::new(2.0, 1.1))
        .unwrap();
    let circle = s.add_circle(Point2::new(0.0, 0.0), 1.0).unwrap();
    s.add_constraint(Fixed::entity(circle)).unwrap();
    let id = s
        .add_constraint(TangentToCircle {
            curve: c,
            circle,
            u: Contact::Free(0.5),
            side: CircleSide::Inside,
            rotation: Rotation::Clockwise,
        })
        .unwrap();
    let before = s.entity(c).unwrap().clone();
    let err = s.solve().unwrap_err();
    assert!(
        matches!(err, Error::ContactCrossed { constraint, .. } if constraint == id)
            || matches!(err, Error::Cusp { constraint, .. } if constraint == id)
            || matches!(&err, Error::Conflicting { constraints } if constraints.contains(&id))
            // Or no proof of a conflict (the least-squares search approaches the segment's
            // collapse without reaching a stationary point), with the contact's residual named.
            || matches!(&err, Error::Solve(camber_solve::Error::NotSolved { residuals, .. })
                if residuals.iter().any(|r| r.constraint == id && r.max_abs > 1e-6)),
        "{err:?}"
    );
    assert_eq!(s.entity(c).unwrap(), &before);
    assert_abs_diff_eq!(contact_u(&s, id), 0.5);
    // The same contact asked from outside solves, and stores the solved parameter.
    s.remove_constraint(id).unwrap();
    let id = s
        .add_constraint(TangentToCircle {
            curve: c,
            circle,
            u: Contact::Free(0.5),
            side: CircleSide::Outside,
            rotation: Rotation::Clockwise,
        })
        .unwrap();
    s.solve().unwrap();
    let Entity::Line([p, q]) = s.entity(c).unwrap().clone() else {
        panic!("line");
    };
    let u = contact_u(&s, id);
    let touch = p + (q - p) * u;
    assert_abs_diff_eq!(touch.coords.norm(), 1.0, epsilon = 1e-9);
    assert_abs_diff_eq!(touch.coords.dot(&(q - p)), 0.0, epsilon = 1e-9);
}

#[test]
fn two_curves_touch_at_free_parameters() {
    let mut s = Sketch::new();
    let lower = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 0.0),
                Point2::new(1.5, 1.4),
                Point2::new(2.5, 1.4),
                Point2::new(4.0, 0.0),
            ])
            .unwrap(),
        )
        .unwrap();
    let upper = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 2.5),
                Point2::new(1.5, 0.9),
                Point2::new(2.5, 0.9),
                Point2::new(4.0, 2.5),
            ])
            .unwrap(),
        )
        .unwrap();
    s.add_constraint(Fixed::entity(lower)).unwrap();
    let id = s
        .add_constraint(CurveCurveTangent {
            first: lower,
            u: Contact::Free(0.5),
            second: upper,
            v: Contact::Free(0.5),
            sense: Sense::Agree,
        })
        .unwrap();
    s.solve().unwrap();
    let Constraint::CurveCurveTangent(CurveCurveTangent { u, v, .. }) =
        s.constraint(id).unwrap().clone()
    else {
        panic!("constraint");
    };
    let (p1, t1) = bezier(&s, lower).point_and_derivative(u.value()).unwrap();
    let (p2, t2) = bezier(&s, upper).point_and_derivative(v.value()).unwrap();
    assert_abs_diff_eq!(p1, p2, epsilon = 1e-9);
    assert_abs_diff_eq!(
        (t1.x * t2.y - t1.y * t2.x) / (t1.norm() * t2.norm()),
        0.0,
        epsilon = 1e-9
    );
    assert!(t1.dot(&t2) > 0.0);
    // The start is symmetric about x = 2, so is the minimum-norm answer: u = v = ½.
    assert_abs_diff_eq!(p1.x, 2.0, epsilon = 1e-6);
    assert_abs_diff_eq!(u.value(), 0.5, epsilon = 1e-6);
}

#[test]
fn g2_join_matches_curvature() {
    let mut s = Sketch::new();
    let first = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 0.0),
                Point2::new(1.0, 1.0),
                Point2::new(2.0, 1.2),
                Point2::new(3.0, 0.8),
            ])
            .unwrap(),
        )
        .unwrap();
    let second = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(3.0, 0.8),
                Point2::new(4.0, 0.5),
                Point2::new(5.0, 0.8),
                Point2::new(6.0, 0.0),
            ])
            .unwrap(),
        )
        .unwrap();
    s.add_constraint(G2Join { first, second }).unwrap();
    s.solve().unwrap();
    let curvature = |c: &BezierCurve2<f64>, u: f64| {
        let [_, d1, d2] = c.second_order(u).unwrap();
        (d1.x * d2.y - d1.y * d2.x) / d1.norm().powi(3)
    };
    let (c1, c2) = (bezier(&s, first), bezier(&s, second));
    let (p1, t1) = c1.point_and_derivative(1.0).unwrap();
    let (p2, t2) = c2.point_and_derivative(0.0).unwrap();
    assert_abs_diff_eq!(p1, p2, epsilon = 1e-9);
    assert_abs_diff_eq!(
        (t1.x * t2.y - t1.y * t2.x) / (t1.norm() * t2.norm()),
        0.0,
        epsilon = 1e-9
    );
    assert!(t1.dot(&t2) > 0.0);
    assert_abs_diff_eq!(curvature(&c1, 1.0), curvature(&c2, 0.0), epsilon = 1e-8);
}
