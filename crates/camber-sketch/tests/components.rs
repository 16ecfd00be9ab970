//! The graph: components, the dirty set, atomic solves, orientation checks, and every built-in
//! constraint on every curve kind, checked by evaluating the kernel's curves independently.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_abs_diff_eq;
use camber_geom::{BSplineCurve2, BezierCurve2, KnotVector, NurbsCurve2, ParametricCurve};
use camber_sketch::constraints::{
    Coincident, DirectionalTangentAt, EndTangent, Fixed, G1Join, PointAtParameter, TangentToLineAt,
    TangentVectorAt,
};
use camber_sketch::{
    Constraint, Entity, EntityId, Error, FixTarget, PointRef, Sense, Sketch, TangentForm, Target,
};
use nalgebra::{Point2, Vector2};

fn cubic(s: &mut Sketch, dx: f64) -> EntityId {
    s.add_bezier(
        BezierCurve2::try_new(vec![
            Point2::new(dx, 0.0),
            Point2::new(dx + 1.0, 1.0),
            Point2::new(dx + 2.0, 1.0),
            Point2::new(dx + 3.0, 0.0),
        ])
        .unwrap(),
    )
    .unwrap()
}

fn as_curve(e: &Entity) -> Box<dyn ParametricCurve<f64, 2>> {
    match e {
        Entity::Bezier(c) => Box::new(c.clone()),
        Entity::BSpline(c) => Box::new(c.clone()),
        Entity::Nurbs(c) => Box::new(c.clone()),
        other => panic!("not a curve: {other:?}"),
    }
}

#[test]
fn components_and_the_dirty_set() {
    let mut s = Sketch::new();
    let a = cubic(&mut s, 0.0);
    let b = cubic(&mut s, 5.0);
    let p = s.add_point(Point2::new(10.0, 10.0)).unwrap();
    s.add_constraint(Coincident {
        a: PointRef::End(a),
        b: PointRef::Point(p),
    })
    .unwrap();
    s.add_constraint(Fixed::entity(b)).unwrap();
    let comps = s.components();
    assert_eq!(comps.len(), 2);
    assert_eq!(comps[0].entities, vec![a, p]);
    assert_eq!(comps[1].entities, vec![b]);
    let r = s.solve().unwrap();
    assert_eq!(r.components.len(), 2);
    // End of a and the point meet halfway (both move by the same least amount).
    assert_abs_diff_eq!(
        s.point(PointRef::End(a)).unwrap(),
        Point2::new(6.5, 5.0),
        epsilon = 1e-12
    );
    assert_eq!(s.dirty().count(), 0);
    // Only the edited component is solved again.
    s.set_point(PointRef::Point(p), Point2::new(4.0, 1.0))
        .unwrap();
    let r = s.solve().unwrap();
    assert_eq!(r.components.len(), 1);
    assert_eq!(r.components[0].component.entities, vec![a, p]);
    assert!(s.solve().unwrap().components.is_empty());
}

#[test]
fn a_failing_component_leaves_every_component_unchanged() {
    let mut s = Sketch::new();
    let a = cubic(&mut s, 0.0);
    let b = cubic(&mut s, 5.0);
    s.add_constraint(PointAtParameter {
        curve: a,
        u: 0.5,
        target: Target::At(Point2::new(1.5, 2.0)),
    })
    .unwrap();
    s.add_constraint(Fixed::entity(b)).unwrap();
    let bad = s
        .add_constraint(PointAtParameter {
            curve: b,
            u: 0.5,
            target: Target::At(Point2::new(0.0, 0.0)),
        })
        .unwrap();
    let before: Vec<_> = s.entities().map(|(i, e)| (i, e.clone())).collect();
    assert!(
        matches!(s.solve(), Err(Error::Conflicting { constraints }) if constraints == vec![bad])
    );
    let after: Vec<_> = s.entities().map(|(i, e)| (i, e.clone())).collect();
    assert_eq!(before, after);
    // Once the bad constraint is gone, the other component solves.
    s.remove_constraint(bad).unwrap();
    s.solve().unwrap();
    assert_abs_diff_eq!(s.curve_point(a, 0.5).unwrap().y, 2.0, epsilon = 1e-12);
}

#[test]
fn a_solve_that_would_flip_a_tangent_is_refused() {
    let mut s = Sketch::new();
    let a = cubic(&mut s, 0.0);
    // C′(0) = 3(1, 1) points along (1, 1); asking for the opposite sense is a flip.
    let id = s
        .add_constraint(DirectionalTangentAt {
            curve: a,
            u: 0.0,
            direction: Vector2::new(1.0, 1.0),
            sense: Sense::Oppose,
        })
        .unwrap();
    let before = s.entity(a).unwrap().clone();
    assert!(matches!(
        s.solve(),
        Err(Error::OrientationFlipped { constraint, .. }) if constraint == id
    ));
    assert_eq!(s.entity(a).unwrap(), &before);
}

#[test]
fn every_constraint_on_splines_nurbs_lines_and_circles() {
    let mut s = Sketch::new();
    let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.4, 0.7, 1.0, 1.0, 1.0]).unwrap();
    let pts = vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 1.0),
        Point2::new(2.0, 1.5),
        Point2::new(3.0, 1.0),
        Point2::new(4.0, 0.0),
    ];
    let spline = s
        .add_bspline(BSplineCurve2::try_new(2, knots.clone(), pts.clone()).unwrap())
        .unwrap();
    let shifted: Vec<_> = pts.iter().map(|p| p + Vector2::new(4.5, 0.3)).collect();
    let nurbs = s
        .add_nurbs(NurbsCurve2::try_new(2, knots, shifted, vec![1.0, 2.0, 0.5, 1.5, 1.0]).unwrap())
        .unwrap();
    let line = s
        .add_line(Point2::new(0.0, -1.0), Point2::new(4.0, -1.5))
        .unwrap();
    let circle = s.add_circle(Point2::new(2.0, -3.0), 0.5).unwrap();
    let dir = Vector2::new(1.0, -0.2);
    let cons = [
        Constraint::Fixed(Fixed {
            target: FixTarget::Point(PointRef::Start(spline)),
        }),
        Constraint::G1Join(G1Join {
            first: spline,
            second: nurbs,
            direction: dir,
        }),
        Constraint::TangentVectorAt(TangentVectorAt {
            curve: spline,
            u: 0.3,
            vector: Vector2::new(3.0, 1.0),
        }),
        Constraint::TangentToLineAt(TangentToLineAt {
            curve: nurbs,
            u: 0.55,
            point: Point2::new(0.0, 2.0),
            direction: Vector2::new(1.0, 0.0),
            sense: Sense::Agree,
        }),
        Constraint::PointAtParameter(PointAtParameter {
            curve: line,
            u: 0.25,
            target: Target::Point(PointRef::Control(circle, 0)),
        }),
        Constraint::EndTangent(EndTangent {
            curve: nurbs,
            direction: Vector2::new(1.0, -1.0),
            sense: Sense::Agree,
            form: TangentForm::Elimination,
        }),
        Constraint::Coincident(Coincident {
            a: PointRef::Start(line),
            b: PointRef::Control(spline, 0),
        }),
    ];
    for c in cons {
        s.add_constraint(c).unwrap();
    }
    let r = s.solve().unwrap();
    assert_eq!(r.components.len(), 1);

    let sp = as_curve(s.entity(spline).unwrap());
    let nu = as_curve(s.entity(nurbs).unwrap());
    assert_abs_diff_eq!(
        sp.point(0.0).unwrap(),
        Point2::new(0.0, 0.0),
        epsilon = 1e-12
    );
    // G1 join: same point, both tangents along dir.
    let (pa, ta) = sp.point_and_derivative(1.0).unwrap();
    let (pb, tb) = nu.point_and_derivative(0.0).unwrap();
    assert_abs_diff_eq!(pa, pb, epsilon = 1e-10);
    for t in [ta, tb] {
        assert!((t.x * dir.y - t.y * dir.x).abs() < 1e-10 && t.dot(&dir) > 0.0);
    }
    assert_abs_diff_eq!(
        sp.derivative(0.3).unwrap(),
        Vector2::new(3.0, 1.0),
        epsilon = 1e-10
    );
    let (p, t) = nu.point_and_derivative(0.55).unwrap();
    assert!((p.y - 2.0).abs() < 1e-10 && t.y.abs() < 1e-10 && t.x > 0.0);
    let te = nu.derivative(1.0).unwrap();
    assert!((te.x + te.y).abs() < 1e-10 && te.x > 0.0);
    let l = s.entity(line).unwrap().points().to_vec();
    let on_line = l[0] + 0.25 * (l[1] - l[0]);
    assert_abs_diff_eq!(
        on_line,
        s.point(PointRef::Control(circle, 0)).unwrap(),
        epsilon = 1e-10
    );
    assert_abs_diff_eq!(l[0], Point2::new(0.0, 0.0), epsilon = 1e-10);
    if let Entity::Circle { radius, .. } = s.entity(circle).unwrap() {
        assert_abs_diff_eq!(*radius, 0.5, epsilon = 0.0);
    }
}
