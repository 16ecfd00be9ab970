//! `Sketch::fillet` between a line and a free-form curve and between two free-form curves at a
//! shared end: the centre against closed forms (circles drawn as exact NURBS arcs, where the
//! fillet circle touches them at distance R₀ ± R from their centres), tangency checked by
//! evaluating the trimmed legs and the arc independently of the constraints, the sketch solved
//! after, the DOF unchanged, and refused fillets leaving the sketch as it was.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use camber_geom::queries::closest_point;
use camber_geom::{BSplineCurve2, BezierCurve2, KnotVector, NurbsCurve2, ParametricCurve};
use camber_sketch::constraints::{Coincident, Fixed, PointAtParameter};
use camber_sketch::hermite_chain::HermiteChain;
use camber_sketch::{Entity, EntityId, Error, PointRef, Sketch, Target};
use nalgebra::{Point2, Vector2};

fn dof(s: &Sketch) -> usize {
    s.analyze().unwrap().iter().map(|a| a.analysis.dof).sum()
}

fn join(s: &mut Sketch, a: PointRef, b: PointRef) {
    s.add_constraint(Coincident { a, b }).unwrap();
}

fn cross(u: Vector2<f64>, v: Vector2<f64>) -> f64 {
    u.x * v.y - u.y * v.x
}

/// The signed angle from u to v.
fn angle(u: Vector2<f64>, v: Vector2<f64>) -> f64 {
    cross(u, v).atan2(u.dot(&v))
}

/// A leg's end nearest `p`, and the leg's direction of travel there pointing out of the leg
/// (towards the joint).
fn leg_end(e: &Entity, p: Point2<f64>) -> (Point2<f64>, Vector2<f64>) {
    let (lo, hi) = e.domain().unwrap();
    let (q0, d0) = e.point_tangent(lo).unwrap();
    let (q1, d1) = e.point_tangent(hi).unwrap();
    if (q0 - p).norm() < (q1 - p).norm() {
        (q0, -d0)
    } else {
        (q1, d1)
    }
}

/// Checks the path far end of `a` → arc → far end of `b` independently of the constraints:
/// each arc end lies on its leg's trimmed end (gap < 1e-9) and the travel turns by less than
/// 1e-9 radians at each joint. Returns the largest gap and the largest turn.
fn check_joints(s: &Sketch, arc: EntityId, a: EntityId, b: EntityId) -> (f64, f64) {
    let g = s.entity(arc).unwrap().as_arc().unwrap();
    let c = *g.center();
    let (p0, p1) = (g.start_point(), g.end_point());
    let ccw = |p: Point2<f64>| Vector2::new(-(p - c).y, (p - c).x);
    let (ea, eb) = (s.entity(a).unwrap(), s.entity(b).unwrap());
    // Which leg the arc leaves from: the one whose trimmed end is at the arc's start.
    let (from, to) = if (leg_end(ea, p0).0 - p0).norm() < (leg_end(eb, p0).0 - p0).norm() {
        (ea, eb)
    } else {
        (eb, ea)
    };
    let (q_from, d_from) = leg_end(from, p0);
    let (q_to, d_to) = leg_end(to, p1);
    // Along the path: into the arc at its start, out of it at its end, into the next leg.
    let turn_in = angle(d_from, ccw(p0)).abs();
    let turn_out = angle(ccw(p1), -d_to).abs();
    let gap = (q_from - p0).norm().max((q_to - p1).norm());
    let turn = turn_in.max(turn_out);
    assert!(gap < 1e-9, "gap {gap:e}");
    assert!(turn < 1e-9, "turn {turn:e}");
    (gap, turn)
}

/// The entities before a solve and after: the solve moves nothing by more than `tol`.
fn assert_solve_keeps(s: &mut Sketch, ids: &[EntityId], tol: f64) {
    let before: Vec<Entity> = ids
        .iter()
        .map(|id| s.entity(*id).unwrap().clone())
        .collect();
    s.solve().unwrap();
    for (id, e) in ids.iter().zip(before) {
        for (p, q) in e.points().iter().zip(s.entity(*id).unwrap().points()) {
            assert!((p - q).norm() < tol, "{id} moved {:e}", (p - q).norm());
        }
    }
}

/// The circle of radius 5 about (0, −3) as an exact NURBS arc from (4, 0) to (0, 2).
fn big_arc() -> NurbsCurve2<f64> {
    let start = 3f64.atan2(4.0);
    NurbsCurve2::try_circular_arc(
        Point2::new(0.0, -3.0),
        5.0,
        start,
        std::f64::consts::FRAC_PI_2,
    )
    .unwrap()
}

/// A line along y = 0 from (4, 0) to (10, 0) and the arc of radius 5 about O = (0, −3) leaving
/// (4, 0) towards (0, 2). The fillet circle of radius R above the line and outside the big
/// circle has its centre C = (x, R) with |C − O| = 5 + R: x² + (R + 3)² = (5 + R)², so
/// x = √(16 + 4R); it touches the line at (x, 0) and the circle at O + 5·(C − O)/(5 + R).
#[test]
fn a_line_and_a_circular_nurbs_arc_fillet_at_the_closed_form_centre() {
    let mut s = Sketch::new();
    let line = s
        .add_line(Point2::new(4.0, 0.0), Point2::new(10.0, 0.0))
        .unwrap();
    let curve = s.add_nurbs(big_arc()).unwrap();
    join(&mut s, PointRef::Start(line), PointRef::Start(curve));
    s.add_constraint(Fixed::point(PointRef::End(line))).unwrap();
    s.add_constraint(Fixed::point(PointRef::End(curve)))
        .unwrap();
    let before = dof(&s);
    let points_before = s.entity(curve).unwrap().points().len();
    let r = 1.0;
    let f = s.fillet(line, curve, r).unwrap();
    let x = (16.0 + 4.0 * r).sqrt();
    let center = Point2::new(x, r);
    assert_relative_eq!(*f.geometry.center(), center, epsilon = 1e-12);
    let o = Point2::new(0.0, -3.0);
    let on_circle = o + (center - o) * (5.0 / (5.0 + r));
    assert_relative_eq!(
        s.point(PointRef::Start(line)).unwrap(),
        Point2::new(x, 0.0),
        epsilon = 1e-12
    );
    assert_relative_eq!(
        s.point(PointRef::Start(curve)).unwrap(),
        on_circle,
        epsilon = 1e-12
    );
    // The trimmed curve is still the circle, with as many control points.
    let e = s.entity(curve).unwrap();
    assert_eq!(e.points().len(), points_before);
    let kept = e.as_curve().unwrap();
    let (lo, hi) = kept.domain();
    for k in 0..=50 {
        let p = kept.point(lo + (hi - lo) * f64::from(k) / 50.0).unwrap();
        assert!(((p - o).norm() - 5.0).abs() < 1e-12);
    }
    assert_eq!((f.added.len(), f.removed.len()), (5, 1));
    check_joints(&s, f.arc, line, curve);
    assert_eq!(dof(&s), before);
    assert_solve_keeps(&mut s, &[line, curve, f.arc], 1e-10);
    check_joints(&s, f.arc, line, curve);
}

/// Two circles of radius 5 about (∓3, 0) cross at (0, 4); arcs of them meeting there (the first
/// ending, the second starting) make a corner whose inside lies in both discs. The fillet
/// circle of radius R inside both touches them internally: |C − Oᵢ| = 5 − R, so by symmetry
/// C = (0, √((5 − R)² − 9)), and it touches circle i at Oᵢ + 5·(C − Oᵢ)/(5 − R).
#[test]
fn two_circular_nurbs_arcs_fillet_at_the_closed_form_centre() {
    let mut s = Sketch::new();
    let corner = 4f64.atan2(3.0);
    let o1 = Point2::new(-3.0, 0.0);
    let o2 = Point2::new(3.0, 0.0);
    let a = s
        .add_nurbs(NurbsCurve2::try_circular_arc(o1, 5.0, 0.0, corner).unwrap())
        .unwrap();
    let b = s
        .add_nurbs(
            NurbsCurve2::try_circular_arc(
                o2,
                5.0,
                std::f64::consts::PI - corner,
                std::f64::consts::PI,
            )
            .unwrap(),
        )
        .unwrap();
    join(&mut s, PointRef::End(a), PointRef::Start(b));
    s.add_constraint(Fixed::point(PointRef::Start(a))).unwrap();
    s.add_constraint(Fixed::point(PointRef::End(b))).unwrap();
    let before = dof(&s);
    for r in [0.5, 1.0, 1.5] {
        let mut t = s.clone();
        let f = t.fillet(a, b, r).unwrap();
        let center = Point2::new(0.0, ((5.0 - r) * (5.0 - r) - 9.0).sqrt());
        assert_relative_eq!(*f.geometry.center(), center, epsilon = 1e-12);
        assert_relative_eq!(
            t.point(PointRef::End(a)).unwrap(),
            o1 + (center - o1) * (5.0 / (5.0 - r)),
            epsilon = 1e-12
        );
        assert_relative_eq!(
            t.point(PointRef::Start(b)).unwrap(),
            o2 + (center - o2) * (5.0 / (5.0 - r)),
            epsilon = 1e-12
        );
        assert_eq!(f.removed.len(), 1);
        check_joints(&t, f.arc, a, b);
        assert_eq!(dof(&t), before);
        assert_solve_keeps(&mut t, &[a, b, f.arc], 1e-10);
        check_joints(&t, f.arc, a, b);
    }
}

/// A line and a parabola-shaped Bézier meeting at the origin: the fillet's centre is at
/// distance R from both legs with its feet the tangent points, checked by the kernel's closest
/// point on the untrimmed Bézier and the line's own distance formula.
#[test]
fn a_line_and_a_bezier_fillet_touches_both_where_the_centre_is_nearest() {
    let mut s = Sketch::new();
    let bezier = BezierCurve2::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 2.0),
        Point2::new(2.0, 0.0),
    ])
    .unwrap();
    let line = s
        .add_line(Point2::new(-3.0, 0.0), Point2::new(0.0, 0.0))
        .unwrap();
    let curve = s.add_bezier(bezier.clone()).unwrap();
    join(&mut s, PointRef::End(line), PointRef::Start(curve));
    let before = dof(&s);
    let r = 0.25;
    let f = s.fillet(curve, line, r).unwrap();
    let c = *f.geometry.center();
    // Distance to the line y = 0, above it.
    assert_relative_eq!(c.y, r, epsilon = 1e-12);
    let near = closest_point(&bezier, &c).unwrap();
    assert_relative_eq!(near.distance, r, epsilon = 1e-12);
    assert_relative_eq!(
        s.point(PointRef::Start(curve)).unwrap(),
        near.point,
        epsilon = 1e-9
    );
    // The kept Bézier piece lies on the original.
    let kept = s.entity(curve).unwrap().as_curve().unwrap();
    for k in 0..=20 {
        let p = kept.point(f64::from(k) / 20.0).unwrap();
        assert!(closest_point(&bezier, &p).unwrap().distance < 1e-12);
    }
    check_joints(&s, f.arc, line, curve);
    assert_eq!(dof(&s), before);
    assert_solve_keeps(&mut s, &[line, curve, f.arc], 1e-10);
}

/// A cubic B-spline and a Bézier at a shared end: the fillet trims both, the B-spline keeps
/// its number of control points (knots inserted in the kept piece), and the DOF is unchanged.
#[test]
fn a_bspline_and_a_bezier_fillet_keeps_the_dof() {
    let mut s = Sketch::new();
    let pts = vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 0.3),
        Point2::new(2.0, -0.2),
        Point2::new(3.0, 0.4),
        Point2::new(4.0, 0.0),
        Point2::new(5.0, 0.2),
    ];
    let spline =
        BSplineCurve2::try_new(3, KnotVector::clamped_uniform(3, 6).unwrap(), pts).unwrap();
    let a = s.add_bspline(spline.clone()).unwrap();
    let b = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 0.0),
                Point2::new(0.2, 1.5),
                Point2::new(1.0, 3.0),
                Point2::new(0.5, 4.0),
            ])
            .unwrap(),
        )
        .unwrap();
    join(&mut s, PointRef::Start(a), PointRef::Start(b));
    let before = dof(&s);
    let f = s.fillet(a, b, 0.3).unwrap();
    assert_eq!(s.entity(a).unwrap().points().len(), 6);
    let kept = s.entity(a).unwrap().as_curve().unwrap();
    let (lo, hi) = kept.domain();
    for k in 0..=20 {
        let u = lo + (hi - lo) * f64::from(k) / 20.0;
        assert!((kept.point(u).unwrap() - spline.point(u).unwrap()).norm() < 1e-12);
    }
    let c = *f.geometry.center();
    assert_relative_eq!(
        closest_point(&spline, &c).unwrap().distance,
        0.3,
        epsilon = 1e-12
    );
    check_joints(&s, f.arc, a, b);
    assert_eq!(dof(&s), before);
    assert_solve_keeps(&mut s, &[a, b, f.arc], 1e-10);
}

/// Fillets that cannot be made are refused with the entities and the radius named, and leave
/// the sketch as it was: a radius too large for the legs, legs sharing no end, legs tangent at
/// their shared end, a constraint on a curve that its trim cannot carry, a circle.
#[test]
fn impossible_curve_fillets_are_refused_and_change_nothing() {
    let mut s = Sketch::new();
    let line = s
        .add_line(Point2::new(4.0, 0.0), Point2::new(10.0, 0.0))
        .unwrap();
    let curve = s.add_nurbs(big_arc()).unwrap();
    join(&mut s, PointRef::Start(line), PointRef::Start(curve));
    // A Bézier continuing the line with its tangent: a smooth joint has no corner.
    let smooth = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(10.0, 0.0),
                Point2::new(12.0, 0.0),
                Point2::new(13.0, 2.0),
            ])
            .unwrap(),
        )
        .unwrap();
    let apart = s
        .add_bezier(
            BezierCurve2::try_new(vec![Point2::new(20.0, 5.0), Point2::new(21.0, 7.0)]).unwrap(),
        )
        .unwrap();
    let circle = s.add_circle(Point2::new(0.0, 9.0), 1.0).unwrap();
    let file = camber_sketch::file::to_json(&s).unwrap();
    let refused = |s: &mut Sketch, a, b, r: f64| match s.fillet(a, b, r) {
        Err(Error::FilletImpossible {
            first,
            second,
            radius,
            reason,
        }) => {
            assert_eq!((first, second), (a, b));
            assert_eq!(radius.to_bits(), r.to_bits());
            reason
        }
        other => panic!("{other:?}"),
    };
    assert!(refused(&mut s, line, curve, 40.0).contains("radius"));
    assert!(refused(&mut s, apart, curve, 0.1).contains("share no end"));
    assert!(refused(&mut s, line, smooth, 0.5).contains("tangent"));
    assert!(matches!(
        s.fillet(line, circle, 1.0),
        Err(Error::WrongEntityKind { entity, .. }) if entity == circle
    ));
    assert!(matches!(
        s.fillet(curve, curve, 1.0),
        Err(Error::SameEntity { .. })
    ));
    assert!(matches!(
        s.fillet(line, curve, f64::NAN),
        Err(Error::NotPositive { .. })
    ));
    assert_eq!(camber_sketch::file::to_json(&s).unwrap(), file);
    // A point held at a parameter of the curve would mean another point after the trim.
    let p = s.add_point(Point2::new(3.0, 1.0)).unwrap();
    let held = s
        .add_constraint(PointAtParameter {
            curve,
            u: 0.5,
            target: Target::Point(PointRef::Point(p)),
        })
        .unwrap();
    let file = camber_sketch::file::to_json(&s).unwrap();
    assert_eq!(
        s.fillet(line, curve, 1.0).unwrap_err(),
        Error::EntityConstrained {
            entity: curve,
            constraint: held,
            operation: "fillet"
        }
    );
    assert_eq!(camber_sketch::file::to_json(&s).unwrap(), file);
}

/// A line from (4, 0) to (0, 0) and a cubic Hermite curve leaving (0, 0) straight up to
/// (0, 4) with unequal end tangents (2 and 6 per unit u, so unevenly parametrized): the corner
/// is a right angle, so the fillet of radius 1 is centred at (1, 1) and touches at (1, 0) and
/// (0, 1). The Hermite curve keeps its four blocks and its shape (a piece of x = 0 from
/// (0, 1) to (0, 4)), the DOF is unchanged and a solve moves nothing.
#[test]
fn a_line_and_a_hermite_curve_fillet_at_the_closed_form_centre() {
    let mut s = Sketch::new();
    let line = s
        .add_line(Point2::new(4.0, 0.0), Point2::new(0.0, 0.0))
        .unwrap();
    let chain = HermiteChain::single(
        Point2::new(0.0, 0.0),
        Point2::new(0.0, 4.0),
        Vector2::new(0.0, 2.0),
        Vector2::new(0.0, 6.0),
    )
    .unwrap();
    let curve = s.add_entity(Entity::Hermite(chain)).unwrap();
    join(&mut s, PointRef::End(line), PointRef::Start(curve));
    s.add_constraint(Fixed::point(PointRef::Start(line)))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::End(curve)))
        .unwrap();
    let before = dof(&s);
    let f = s.fillet(line, curve, 1.0).unwrap();
    assert_relative_eq!(*f.geometry.center(), Point2::new(1.0, 1.0), epsilon = 1e-12);
    assert_relative_eq!(
        s.point(PointRef::End(line)).unwrap(),
        Point2::new(1.0, 0.0),
        epsilon = 1e-12
    );
    assert_relative_eq!(
        s.point(PointRef::Start(curve)).unwrap(),
        Point2::new(0.0, 1.0),
        epsilon = 1e-12
    );
    let e = s.entity(curve).unwrap();
    assert!(matches!(e, Entity::Hermite(_)));
    assert_eq!(e.points().len(), 4);
    let kept = e.as_curve().unwrap();
    for k in 0..=50 {
        let p = kept.point(f64::from(k) / 50.0).unwrap();
        assert!(
            p.x.abs() < 1e-12 && p.y > 1.0 - 1e-12 && p.y < 4.0 + 1e-12,
            "{p}"
        );
    }
    assert_relative_eq!(
        kept.point(1.0).unwrap(),
        Point2::new(0.0, 4.0),
        epsilon = 1e-12
    );
    check_joints(&s, f.arc, line, curve);
    assert_eq!(dof(&s), before);
    assert_solve_keeps(&mut s, &[line, curve, f.arc], 1e-10);
    check_joints(&s, f.arc, line, curve);
}
