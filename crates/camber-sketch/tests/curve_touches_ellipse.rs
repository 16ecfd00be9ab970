//! A free-form curve touching an ellipse or an elliptic arc in its interior (`tangent_to_ellipse`,
//! a free curve parameter and a free parametric angle): the symmetric closed form, the tangent
//! from an outside point, a contact from inside, crossings and contacts off an arc refused with
//! the sketch unchanged, the file round trip, the exact derivatives of the rows, and drags of
//! the ellipse that keep the curve on its side without crossing.

#![allow(clippy::unwrap_used)]

use std::f64::consts::{FRAC_PI_2, PI};

use camber_geom::{BezierCurve2, Ellipse, EllipticArc, KnotVector, NurbsCurve2, ParametricCurve};
use camber_sketch::constraints::tangent_to_ellipse::EllipseContact;
use camber_sketch::constraints::{Fixed, TangentToEllipse};
use camber_sketch::curve_eval::CurveBasis;
use camber_sketch::file::{from_json, to_json};
use camber_sketch::residuals::Param;
use camber_sketch::{
    CircleSide, Constraint, ConstraintId, Contact, Entity, EntityId, Error, PointRef, Rotation,
    Sketch,
};
use camber_solve::testing::check_jacobian;
use nalgebra::{Point2, Vector2};

/// The ellipse x²/4 + y² = 1.
fn ellipse() -> Ellipse<f64> {
    Ellipse::try_new(Point2::origin(), 2.0, 1.0, 0.0).unwrap()
}

/// A cubic through `points` with its ends fixed, touching `round` (an ellipse or elliptic arc
/// entity added by `add`) on `side`, running clockwise over it, the contact starting at u = ½
/// and θ = `theta`.
fn touching(
    points: [[f64; 2]; 4],
    add: impl FnOnce(&mut Sketch) -> EntityId,
    side: CircleSide,
    theta: f64,
) -> (Sketch, EntityId, EntityId, ConstraintId) {
    let mut s = Sketch::new();
    let c = s
        .add_bezier(
            BezierCurve2::try_new(points.iter().map(|p| Point2::new(p[0], p[1])).collect())
                .unwrap(),
        )
        .unwrap();
    for j in [0, 3] {
        s.add_constraint(Fixed::point(PointRef::Control(c, j)))
            .unwrap();
    }
    let e = add(&mut s);
    let k = s
        .add_constraint(TangentToEllipse {
            curve: c,
            ellipse: e,
            u: Contact::Free(0.5),
            theta,
            side,
            rotation: Rotation::Clockwise,
        })
        .unwrap();
    (s, c, e, k)
}

/// The fixed whole ellipse.
fn fixed_ellipse(s: &mut Sketch) -> EntityId {
    let e = s.add_ellipse(&ellipse()).unwrap();
    s.add_constraint(Fixed::entity(e)).unwrap();
    e
}

/// A flat cubic at height 1.5 over the ellipse.
const OVER: [[f64; 2]; 4] = [[-3.0, 1.5], [-1.0, 1.5], [1.0, 1.5], [3.0, 1.5]];

/// The contact parameter and angle of constraint `k`.
fn contact(s: &Sketch, k: ConstraintId) -> (f64, f64) {
    let Constraint::TangentToEllipse(t) = s.constraint(k).unwrap() else {
        panic!("not a tangency");
    };
    (t.u.value(), t.theta)
}

/// The Bézier curve `c`.
fn curve(s: &Sketch, c: EntityId) -> BezierCurve2<f64> {
    let Entity::Bezier(curve) = s.entity(c).unwrap() else {
        panic!("not a Bézier curve");
    };
    curve.clone()
}

/// The signed distance from `q` to `e` (positive outside) to first order, F/|∇F| with
/// F = (x/a)² + (y/b)² − 1 in the ellipse's frame: exact in sign, close near the ellipse.
fn signed_distance(e: &Ellipse<f64>, q: Point2<f64>) -> f64 {
    let local = e.to_frame(&q);
    let (a, b) = (e.semi_axis_a(), e.semi_axis_b());
    let gradient = Vector2::new(2.0 * local.x / (a * a), 2.0 * local.y / (b * b)).norm();
    e.implicit_value(&q) / gradient
}

/// The least and largest signed distance to `e` over 2,000 samples of the curve.
fn gaps(curve: &BezierCurve2<f64>, e: &Ellipse<f64>) -> (f64, f64) {
    (0..=2000)
        .map(|i| signed_distance(e, curve.point(i as f64 / 2000.0).unwrap()))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), d| {
            (lo.min(d), hi.max(d))
        })
}

/// Started at u = ½ and θ = π/2, everything is symmetric about x = 0 and the least move keeps
/// it so: the contact is the top vertex (0, 1), and the curve stays outside the ellipse.
#[test]
fn a_curve_over_an_ellipse_touches_its_top_vertex() {
    let (mut s, c, _, k) = touching(OVER, fixed_ellipse, CircleSide::Outside, FRAC_PI_2);
    s.solve().unwrap();
    let (u, theta) = contact(&s, k);
    assert!((u - 0.5).abs() < 1e-9, "u = {u}");
    assert!((theta - FRAC_PI_2).abs() < 1e-9, "θ = {theta}");
    let curve = curve(&s, c);
    let p = curve.point(u).unwrap();
    assert!((p - Point2::new(0.0, 1.0)).norm() < 1e-9, "{p}");
    let (least, _) = gaps(&curve, &ellipse());
    assert!(least > -1e-9 && least < 1e-6, "{least}");
}

/// Started off the symmetric answer (θ = 1.3), the solve settles on another honest contact:
/// C(u) = P(θ), C′(u) along −P′(θ) (clockwise), the curve outside the ellipse everywhere.
#[test]
fn an_asymmetric_start_settles_on_an_honest_contact() {
    let (mut s, c, _, k) = touching(OVER, fixed_ellipse, CircleSide::Outside, 1.3);
    s.solve().unwrap();
    let (u, theta) = contact(&s, k);
    let curve = curve(&s, c);
    let e = ellipse();
    let p = curve.point(u).unwrap();
    assert!((p - e.point_at_angle(theta)).norm() < 1e-9, "{p}");
    let (t, travel) = (
        curve.derivative(u).unwrap(),
        e.derivative_at_angle(theta, 1),
    );
    let sine = t.perp(&travel) / (t.norm() * travel.norm());
    assert!(
        sine.abs() < 1e-9 && t.dot(&travel) < 0.0,
        "{t} against {travel}"
    );
    let (least, _) = gaps(&curve, &e);
    assert!(least > -1e-9 && least < 1e-6, "{least}");
}

/// A segment from the fixed point (0, 2) touching x²/4 + y² = 1: the tangent line at (x₀, y₀),
/// x·x₀/4 + y·y₀ = 1, passes through (0, 2) when y₀ = ½, so the contact is (√3, ½) at
/// θ = π/6, wherever the segment's free end settles.
#[test]
fn a_segment_from_an_outside_point_touches_at_the_closed_form_tangent_point() {
    let mut s = Sketch::new();
    let l = s
        .add_entity(Entity::Line([
            Point2::new(0.0, 2.0),
            Point2::new(3.0, -0.2),
        ]))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(l, 0)))
        .unwrap();
    let e = fixed_ellipse(&mut s);
    let k = s
        .add_constraint(TangentToEllipse {
            curve: l,
            ellipse: e,
            u: Contact::Free(0.6),
            theta: 0.4,
            side: CircleSide::Outside,
            rotation: Rotation::Clockwise,
        })
        .unwrap();
    s.solve().unwrap();
    let (u, theta) = contact(&s, k);
    assert!((theta - PI / 6.0).abs() < 1e-9, "θ = {theta}");
    let Entity::Line([a, b]) = s.entity(l).unwrap() else {
        panic!("not a line");
    };
    let p = a + (b - a) * u;
    assert!((p - Point2::new(3f64.sqrt(), 0.5)).norm() < 1e-9, "{p}");
}

/// A cubic inside the ellipse, pushed up against its top from below (side inside): it touches
/// (0, 1) and stays inside everywhere.
#[test]
fn a_curve_inside_an_ellipse_touches_it_from_within() {
    let under = [[-1.0, 0.3], [-0.4, 0.8], [0.4, 0.8], [1.0, 0.3]];
    let (mut s, c, _, k) = touching(under, fixed_ellipse, CircleSide::Inside, FRAC_PI_2);
    s.solve().unwrap();
    let (u, theta) = contact(&s, k);
    assert!((u - 0.5).abs() < 1e-9 && (theta - FRAC_PI_2).abs() < 1e-9);
    let (_, largest) = gaps(&curve(&s, c), &ellipse());
    assert!(largest < 1e-9 && largest > -1e-6, "{largest}");
}

/// The parabola y = 1 − x²/2 (a quadratic Bézier, its ends held) touches the top of the
/// ellipse but bends more sharply (curvature 1 against ¼), so it lies inside near the contact.
/// Recorded as outside, no curve through its held ends (both inside the ellipse) can touch it
/// from outside: the clearance rows the solve adds conflict with the contact, the solve fails
/// naming the tangency and changes nothing. Recorded as inside, it solves.
#[test]
fn a_contact_on_the_wrong_side_is_refused_and_nothing_changes() {
    let build = |side| {
        let mut s = Sketch::new();
        let points = vec![
            Point2::new(-1.0, 0.5),
            Point2::new(0.0, 1.5),
            Point2::new(1.0, 0.5),
        ];
        let c = s
            .add_bezier(BezierCurve2::try_new(points).unwrap())
            .unwrap();
        for j in [0, 2] {
            s.add_constraint(Fixed::point(PointRef::Control(c, j)))
                .unwrap();
        }
        let e = fixed_ellipse(&mut s);
        let k = s
            .add_constraint(TangentToEllipse {
                curve: c,
                ellipse: e,
                u: Contact::Free(0.5),
                theta: FRAC_PI_2,
                side,
                rotation: Rotation::Clockwise,
            })
            .unwrap();
        (s, k)
    };
    let (mut s, k) = build(CircleSide::Outside);
    let before = to_json(&s).unwrap();
    let err = s.solve().unwrap_err();
    assert!(
        matches!(&err, Error::Conflicting { constraints } if constraints.contains(&k)),
        "{err}"
    );
    assert_eq!(to_json(&s).unwrap(), before);
    let (mut s, _) = build(CircleSide::Inside);
    s.solve().unwrap();
}

/// The NURBS of the circle clearance test stretched twice along x, against x²/4 + y² = 1 (the
/// unit circle stretched the same way): its nearest touching curve would dip into the ellipse
/// beside the contact, so the solve adds a clearance row against the ellipse and the curve
/// touches it again at a free second point instead of crossing.
#[test]
fn a_nurbs_dipping_into_an_ellipse_touches_it_again_at_a_free_point() {
    let mut s = Sketch::new();
    let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0]).unwrap();
    let pts = vec![
        Point2::new(-3.0, 1.2),
        Point2::new(-1.0, 1.1),
        Point2::new(0.6, 1.05),
        Point2::new(1.2, 0.45),
        Point2::new(3.0, 0.9),
    ];
    let c = s
        .add_nurbs(NurbsCurve2::try_new(3, knots, pts, vec![1.0, 0.8, 1.2, 1.0, 1.0]).unwrap())
        .unwrap();
    for j in [0, 4] {
        s.add_constraint(Fixed::point(PointRef::Control(c, j)))
            .unwrap();
    }
    let e = fixed_ellipse(&mut s);
    let k = s
        .add_constraint(TangentToEllipse {
            curve: c,
            ellipse: e,
            u: Contact::Free(0.35),
            theta: 1.7,
            side: CircleSide::Outside,
            rotation: Rotation::Clockwise,
        })
        .unwrap();
    let report = s.solve().unwrap();
    assert!(
        report.components[0].report.reason.contains("active row"),
        "{}",
        report.components[0].report.reason
    );
    let (u, theta) = contact(&s, k);
    let Entity::Nurbs(n) = s.entity(c).unwrap() else {
        panic!("NURBS");
    };
    let el = ellipse();
    let (p, t) = n.point_and_derivative(u).unwrap();
    assert!((p - el.point_at_angle(theta)).norm() < 1e-8, "{p}");
    let travel = el.derivative_at_angle(theta, 1);
    assert!(t.perp(&travel).abs() < 1e-8 * t.norm() * travel.norm());
    let samples: Vec<(f64, f64)> = (0..=4000)
        .map(|i| f64::from(i) / 4000.0)
        .map(|s| (s, signed_distance(&el, n.point(s).unwrap())))
        .collect();
    let everywhere = samples
        .iter()
        .map(|(_, d)| *d)
        .fold(f64::INFINITY, f64::min);
    assert!(everywhere > -1e-8, "crosses by {everywhere}");
    let away = samples
        .iter()
        .filter(|(s, _)| (s - u).abs() > 0.05)
        .map(|(_, d)| *d)
        .fold(f64::INFINITY, f64::min);
    assert!(away < 1e-6, "no second touch: least gap {away}");
}

/// The lower half of the ellipse as an arc: its ellipse would touch the curve at the top, the
/// arc does not. The solve fails naming the constraint and the arc and changes nothing; the
/// upper half solves to the top vertex.
#[test]
fn a_contact_off_an_elliptic_arc_is_refused_and_nothing_changes() {
    let arc = |start: f64, end: f64| {
        move |s: &mut Sketch| {
            let a = EllipticArc::try_new(Point2::origin(), 2.0, 1.0, 0.0, start, end).unwrap();
            let e = s.add_elliptic_arc(&a).unwrap();
            s.add_constraint(Fixed::entity(e)).unwrap();
            e
        }
    };
    let (mut s, _, e, k) = touching(
        OVER,
        arc(PI + 0.2, 2.0 * PI - 0.2),
        CircleSide::Outside,
        1.3,
    );
    let before = to_json(&s).unwrap();
    let err = s.solve().unwrap_err();
    assert!(
        matches!(err, Error::ContactOffArc { constraint, arc, outside }
            if constraint == k && arc == e && outside > 1.0),
        "{err}"
    );
    assert_eq!(to_json(&s).unwrap(), before);
    let (mut s, _, _, k) = touching(OVER, arc(0.2, PI - 0.2), CircleSide::Outside, FRAC_PI_2);
    s.solve().unwrap();
    assert!((contact(&s, k).1 - FRAC_PI_2).abs() < 1e-9);
}

/// Saved and loaded, the sketch solves to the same contact, bit for bit.
#[test]
fn the_ellipse_contact_survives_a_file_round_trip() {
    let (s, c, _, k) = touching(OVER, fixed_ellipse, CircleSide::Outside, 1.3);
    let mut loaded = from_json(&to_json(&s).unwrap()).unwrap();
    let mut original = s;
    original.solve().unwrap();
    loaded.solve().unwrap();
    let (ua, ta) = contact(&original, k);
    let (ub, tb) = contact(&loaded, k);
    assert_eq!((ua.to_bits(), ta.to_bits()), (ub.to_bits(), tb.to_bits()));
    assert_eq!(
        curve(&original, c).control_points(),
        curve(&loaded, c).control_points()
    );
}

/// The rows' Jacobian (dual numbers, and the structured one) against central differences,
/// with the contact parameter, a rotated ellipse's centre, vertex, semi-axis and angle.
#[test]
fn the_ellipse_contact_rows_have_exact_derivatives() {
    let cubic = Entity::Bezier(
        BezierCurve2::try_new(vec![
            Point2::new(-1.0, 1.1),
            Point2::new(-0.2, 1.6),
            Point2::new(0.5, 0.7),
            Point2::new(1.2, 0.9),
        ])
        .unwrap(),
    );
    for clockwise in [true, false] {
        let rows = EllipseContact::new(CurveBasis::of(&cubic).unwrap(), Param::Block, clockwise);
        let x: [&[f64]; 9] = [
            &[-1.0, 1.1],
            &[-0.2, 1.6],
            &[0.5, 0.7],
            &[1.2, 0.9],
            &[0.45],
            &[0.1, -0.05],
            &[1.8, 0.7],
            &[0.8],
            &[1.2],
        ];
        check_jacobian(&rows, &x, 1e-6, 1e-7).unwrap();
    }
}

/// The ellipse, free to move with its shape held, is dragged by its centre in 40 steps along a
/// wavy path: the curve keeps touching it from outside, never crossing it, running clockwise.
#[test]
fn dragging_the_ellipse_keeps_the_curve_touching_it_from_outside() {
    let free_ellipse = |s: &mut Sketch| s.add_ellipse(&ellipse()).unwrap();
    let (mut s, c, e, _) = touching(OVER, free_ellipse, CircleSide::Outside, 1.3);
    s.solve().unwrap();
    let centre = PointRef::Control(e, 0);
    let start = s.point(centre).unwrap();
    let mut drag = s.drag(centre).unwrap();
    for i in 1..=40 {
        let t = i as f64 / 40.0;
        let target = start + Vector2::new(0.4 * (2.0 * PI * t).sin(), -0.2 * t);
        drag.update(target).unwrap();
        let entities = drag.entities().unwrap();
        let find = |id| {
            entities
                .iter()
                .find(|(k, _)| *k == id)
                .map(|(_, e)| e.clone())
        };
        let Some(Entity::Bezier(curve)) = find(c) else {
            panic!("curve");
        };
        let ellipse = find(e).and_then(|e| e.as_ellipse()).unwrap();
        let (least, _) = gaps(&curve, &ellipse);
        assert!(least > -1e-7, "step {i}: the curve crosses by {least}");
        assert!(least < 1e-6, "step {i}: the contact is lost ({least})");
    }
}
