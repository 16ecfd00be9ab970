//! Honest contact as an active set (camber_sketch::clearance): a curve whose nearest solution
//! would cross its line or circle beside the contact touches it instead (osculating at the
//! contact, or at a free second point), for a Bézier at a fixed parameter and a NURBS at a free
//! one; a contact whose tangent starts the wrong way keeps a quarter of its starting speed
//! instead of collapsing into a cusp; a crossing that no nearby curve avoids is refused with the
//! constraint named and nothing written. Each result is checked on the solved curve, densely,
//! over the whole curve.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber_geom::{BezierCurve2, KnotVector, NurbsCurve2, ParametricCurve};
use camber_sketch::constraints::{Fixed, TangentToCircle, TangentToLine};
use camber_sketch::residuals::clearance::SPEED_FLOOR;
use camber_sketch::{
    CircleSide, Constraint, Contact, Entity, Error, LineSide, PointRef, Rotation, Sense, Sketch,
};
use nalgebra::Point2;

/// min over a dense scan of the whole curve of `gap`, with the parameter where it is reached,
/// skipping |s − skip.0| < skip.1.
fn least(
    curve: &dyn ParametricCurve<f64, 2>,
    gap: impl Fn(Point2<f64>) -> f64,
    skip: (f64, f64),
) -> (f64, f64) {
    let (a, b) = curve.domain();
    let mut best = (f64::INFINITY, a);
    for i in 0..=20_000 {
        let s = a + (b - a) * f64::from(i) / 20_000.0;
        if (s - skip.0).abs() < skip.1 {
            continue;
        }
        let g = gap(curve.point(s).unwrap());
        if g < best.0 {
            best = (g, s);
        }
    }
    best
}

/// A cubic leaving the line y = 0 at u = 0 and bending below it: the contact rows alone put
/// P₀ and P₁ on the line and leave P₂ under it, so the curve crosses right after the contact.
/// The clearance row makes it osculate instead: the nearest curve that stays above has
/// y(s) = 3s²(1 − s)·y₂ + s³/2 ≥ 0 near 0, i.e. y₂ = 0.
#[test]
fn a_crossing_right_after_a_line_contact_becomes_an_osculation() {
    let mut s = Sketch::new();
    let c = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 0.05),
                Point2::new(0.3, 0.02),
                Point2::new(0.6, -0.3),
                Point2::new(1.0, 0.5),
            ])
            .unwrap(),
        )
        .unwrap();
    let line = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(1.0, 0.0))
        .unwrap();
    s.add_constraint(Fixed::entity(line)).unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(c, 3)))
        .unwrap();
    s.add_constraint(TangentToLine {
        curve: c,
        line,
        u: Contact::At(0.0),
        side: LineSide::Left,
        sense: Sense::Agree,
    })
    .unwrap();
    let report = s.solve().unwrap();
    assert!(
        report.components[0].report.reason.contains("active row"),
        "{}",
        report.components[0].report.reason
    );
    let Entity::Bezier(b) = s.entity(c).unwrap() else {
        panic!("Bézier");
    };
    let p = b.control_points();
    for (k, y) in [(0, 0.0), (1, 0.0), (2, 0.0)] {
        assert!((p[k].y - y).abs() < 1e-9, "P{k} = {:?}", p[k]);
    }
    assert!(p[1].x > p[0].x);
    let (g, _) = least(b, |q| q.y, (0.0, 0.0));
    assert!(g > -1e-9, "the curve dips to y = {g}");
}

/// A NURBS over the top of the unit circle, touching it at a free parameter, whose tail dips
/// into the circle: the solve without the clearance crosses after the contact; with it, the
/// curve touches the circle again at a second, free point and stays outside everywhere.
#[test]
fn a_nurbs_dipping_into_a_circle_touches_it_again_at_a_free_point() {
    let mut s = Sketch::new();
    let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0]).unwrap();
    let pts = vec![
        Point2::new(-1.5, 1.2),
        Point2::new(-0.5, 1.1),
        Point2::new(0.3, 1.05),
        Point2::new(0.6, 0.45),
        Point2::new(1.5, 0.9),
    ];
    let c = s
        .add_nurbs(NurbsCurve2::try_new(3, knots, pts, vec![1.0, 0.8, 1.2, 1.0, 1.0]).unwrap())
        .unwrap();
    let circle = s.add_circle(Point2::new(0.0, 0.0), 1.0).unwrap();
    s.add_constraint(Fixed::entity(circle)).unwrap();
    for j in [0, 4] {
        s.add_constraint(Fixed::point(PointRef::Control(c, j)))
            .unwrap();
    }
    let id = s
        .add_constraint(TangentToCircle {
            curve: c,
            circle,
            u: Contact::Free(0.35),
            side: CircleSide::Outside,
            rotation: Rotation::Clockwise,
        })
        .unwrap();
    let report = s.solve().unwrap();
    assert!(report.components[0].report.reason.contains("active row"));
    let Constraint::TangentToCircle(TangentToCircle { u, .. }) = s.constraint(id).unwrap() else {
        panic!("contact");
    };
    let u = u.value();
    let Entity::Nurbs(n) = s.entity(c).unwrap() else {
        panic!("NURBS");
    };
    let gap = |q: Point2<f64>| q.coords.norm() - 1.0;
    let (p, t) = n.point_and_derivative(u).unwrap();
    assert!(gap(p).abs() < 1e-8 && p.coords.dot(&t).abs() < 1e-8 * t.norm());
    let (everywhere, _) = least(n, gap, (u, 0.0));
    assert!(everywhere > -1e-8, "crosses by {everywhere}");
    let (away, at) = least(n, gap, (u, 0.05));
    assert!(away < 1e-6, "no second touch: least gap {away} at {at}");
}

/// A cubic whose start P₀ sits on the unit circle at −12° with P₁ straight above it: the
/// tangent points counter-clockwise while the contact asks clockwise. Turning it costs least by
/// shrinking it through zero (a cusp), which is no tangency; the solve keeps the floor
/// |C′(0)| ≥ ¼·|C′₀(0)| and slides P₀ round the circle instead.
#[test]
fn a_reversed_contact_keeps_a_quarter_of_its_tangent_speed() {
    let mut s = Sketch::new();
    let start = [
        Point2::new(0.95, -0.2),
        Point2::new(0.9, 0.8),
        Point2::new(2.0, 1.5),
        Point2::new(3.0, 1.0),
    ];
    let c = s
        .add_bezier(BezierCurve2::try_new(start.to_vec()).unwrap())
        .unwrap();
    let circle = s.add_circle(Point2::new(0.0, 0.0), 1.0).unwrap();
    s.add_constraint(Fixed::entity(circle)).unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(c, 3)))
        .unwrap();
    s.add_constraint(TangentToCircle {
        curve: c,
        circle,
        u: Contact::At(0.0),
        side: CircleSide::Outside,
        rotation: Rotation::Clockwise,
    })
    .unwrap();
    s.solve().unwrap();
    let Entity::Bezier(b) = s.entity(c).unwrap() else {
        panic!("Bézier");
    };
    let (p, t) = b.point_and_derivative(0.0).unwrap();
    assert!((p.coords.norm() - 1.0).abs() < 1e-9);
    assert!(p.coords.dot(&t).abs() < 1e-9 * t.norm());
    assert!(p.x * t.y - p.y * t.x < 0.0, "not clockwise");
    let speed0 = 3.0 * (start[1] - start[0]).norm();
    assert!(
        t.norm() >= SPEED_FLOOR * speed0 * (1.0 - 1e-9),
        "|C′(0)| = {} below the floor {}",
        t.norm(),
        SPEED_FLOOR * speed0
    );
    let (g, _) = least(b, |q| q.coords.norm() - 1.0, (0.0, 0.0));
    assert!(g > -1e-9, "crosses by {g}");
}

/// P₂ and P₃ fixed under the line y = 0 while the curve must leave it tangentially from above:
/// y(s) = 3s²(1 − s)·y₂ + s³·y₃ < 0 for small s whatever P₀ and P₁ do on the line, so the
/// clearance cannot be met. The solve is refused naming the contact, and nothing moves.
#[test]
fn a_crossing_no_nearby_curve_avoids_is_refused() {
    let mut s = Sketch::new();
    let c = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 0.1),
                Point2::new(0.3, 0.1),
                Point2::new(0.6, -1.0),
                Point2::new(1.0, -1.0),
            ])
            .unwrap(),
        )
        .unwrap();
    let line = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(1.0, 0.0))
        .unwrap();
    s.add_constraint(Fixed::entity(line)).unwrap();
    for j in [2, 3] {
        s.add_constraint(Fixed::point(PointRef::Control(c, j)))
            .unwrap();
    }
    let id = s
        .add_constraint(TangentToLine {
            curve: c,
            line,
            u: Contact::At(0.0),
            side: LineSide::Left,
            sense: Sense::Agree,
        })
        .unwrap();
    let before: Vec<_> = s.entities().map(|(i, e)| (i, e.clone())).collect();
    let err = s.solve().unwrap_err();
    assert!(
        matches!(&err, Error::Conflicting { constraints } if constraints.contains(&id))
            || matches!(err, Error::ContactCrossed { constraint, .. } if constraint == id),
        "{err:?}"
    );
    let after: Vec<_> = s.entities().map(|(i, e)| (i, e.clone())).collect();
    assert_eq!(before, after);
}
