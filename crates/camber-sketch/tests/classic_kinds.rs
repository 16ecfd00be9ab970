//! The classic sketch constraints (issue 12): horizontal, vertical, equal length, equal radius,
//! concentric, point on an infinite line, point–line distance, midpoint, symmetric, horizontal
//! and vertical distance, arc length, curvature at a parameter, C1 and C2 joins.
//!
//! Each kind is checked three ways: its rows' exact Jacobian (through the component problem the
//! sketch builds, so the whole path from the kind to the residuals is covered) against central
//! differences; a solve from a start that violates it, with the result checked from the solved
//! geometry by an independent formula; and a drag that keeps it. Its file form round-trips.

#![allow(clippy::unwrap_used)] // fixture helpers unwrap like the tests do

use camber_geom::{BSplineCurve2, BezierCurve2, KnotVector, ParametricCurve};
use camber_sketch::constraints::{
    ArcLength, C1Join, C2Join, Concentric, CurvatureAt, EqualLength, EqualRadius, Fixed,
    Horizontal, HorizontalDistance, Midpoint, PointLineDistance, PointOnLine, Symmetric, Vertical,
    VerticalDistance,
};
use camber_sketch::file::{from_json, to_json};
use camber_sketch::{Constraint, Entity, EntityId, LineSide, PointRef, Sketch};
use nalgebra::{Point2, Vector2};

/// The component Jacobian (autodiff, over the reduced unknowns) against central differences of
/// the problem's residuals at its current point.
fn jacobian_matches_differences(s: &Sketch, entity: EntityId) {
    let cp = s.component_problem(entity).unwrap();
    let p = cp.problem();
    let lin = p.linearize().unwrap();
    let (m, n) = (lin.g.len(), lin.map.len());
    let z0 = lin.map.z0().to_vec();
    let mut x = vec![0.0; lin.x.len()];
    let (mut gp, mut gm) = (vec![0.0; m], vec![0.0; m]);
    let h = 1e-6;
    for k in 0..n {
        let mut z = z0.clone();
        z[k] = z0[k] + h;
        lin.map.expand(&z, &mut x).unwrap();
        p.evaluate_at(&x, &mut gp).unwrap();
        z[k] = z0[k] - h;
        lin.map.expand(&z, &mut x).unwrap();
        p.evaluate_at(&x, &mut gm).unwrap();
        for i in 0..m {
            let central = (gp[i] - gm[i]) / (2.0 * h);
            let exact = lin.jacobian.get(i, k);
            assert!(
                (exact - central).abs() <= 1e-6 * exact.abs().max(1.0),
                "row {i} column {k}: autodiff {exact}, differences {central}"
            );
        }
    }
}

/// Saving and loading gives the same sketch, and saving again the same text.
fn round_trips(s: &Sketch) {
    let text = to_json(s).unwrap();
    let back = from_json(&text).unwrap();
    assert_eq!(to_json(&back).unwrap(), text);
    for ((_, a), (_, b)) in s.constraints().zip(back.constraints()) {
        assert_eq!(a, b);
    }
}

fn p(x: f64, y: f64) -> Point2<f64> {
    Point2::new(x, y)
}

fn pt(s: &Sketch, r: PointRef) -> Point2<f64> {
    s.point(r).unwrap()
}

/// Solves, checks `holds` on the result, then drags `handle` to `to` and checks it again on
/// the dragged state.
fn solve_and_drag(
    s: &mut Sketch,
    holds: impl Fn(&dyn Fn(PointRef) -> Point2<f64>) -> bool,
    handle: PointRef,
    to: Point2<f64>,
) {
    s.solve().unwrap();
    assert!(holds(&|r| pt(s, r)), "after the solve");
    let mut d = s.drag(handle).unwrap();
    d.update(to).unwrap();
    assert!(holds(&|r| d.point(r).unwrap()), "after the drag");
    assert!((d.point(handle).unwrap() - to).norm() < 1e-9);
    d.finish(s).unwrap();
    assert!(holds(&|r| pt(s, r)), "after finishing the drag");
}

#[test]
fn horizontal_and_vertical_lines_and_point_pairs() {
    let mut s = Sketch::new();
    let a = s.add_line(p(0.0, 0.0), p(2.0, 0.3)).unwrap();
    let b = s.add_line(p(2.1, 0.1), p(2.3, 1.5)).unwrap();
    let q = s.add_point(p(-1.0, 2.0)).unwrap();
    // A corner: the horizontal line ends where the vertical one starts.
    s.add_constraint(camber_sketch::constraints::Coincident {
        a: PointRef::End(a),
        b: PointRef::Start(b),
    })
    .unwrap();
    s.add_constraint(Horizontal::line(a)).unwrap();
    s.add_constraint(Vertical::line(b)).unwrap();
    s.add_constraint(Horizontal {
        of: camber_sketch::vocabulary::PointPair::Points(PointRef::Point(q), PointRef::End(b)),
    })
    .unwrap();
    jacobian_matches_differences(&s, a);
    jacobian_matches_differences(&s, b);
    round_trips(&s);
    let (a0, a1, b0, b1, qr) = (
        PointRef::Start(a),
        PointRef::End(a),
        PointRef::Start(b),
        PointRef::End(b),
        PointRef::Point(q),
    );
    solve_and_drag(
        &mut s,
        |at| {
            (at(a0).y - at(a1).y).abs() < 1e-12
                && (at(b0).x - at(b1).x).abs() < 1e-12
                && (at(qr).y - at(b1).y).abs() < 1e-12
        },
        PointRef::Control(b, 1),
        p(2.5, 2.0),
    );
}

#[test]
fn equal_length_of_two_lines() {
    let mut s = Sketch::new();
    let a = s.add_line(p(0.0, 0.0), p(2.0, 0.5)).unwrap();
    let b = s.add_line(p(0.0, 1.0), p(1.0, 1.3)).unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(a))).unwrap();
    s.add_constraint(EqualLength {
        first: camber_sketch::vocabulary::PointPair::Line(a),
        second: camber_sketch::vocabulary::PointPair::Line(b),
    })
    .unwrap();
    jacobian_matches_differences(&s, a);
    round_trips(&s);
    let len = |at: &dyn Fn(PointRef) -> Point2<f64>, l| {
        (at(PointRef::End(l)) - at(PointRef::Start(l))).norm()
    };
    solve_and_drag(
        &mut s,
        |at| (len(at, a) - len(at, b)).abs() < 1e-9,
        PointRef::Control(b, 1),
        p(2.0, 2.0),
    );
}

#[test]
fn equal_radius_and_concentric_circles() {
    let mut s = Sketch::new();
    let c1 = s.add_circle(p(0.0, 0.0), 1.0).unwrap();
    let c2 = s.add_circle(p(0.2, -0.1), 1.5).unwrap();
    let c3 = s.add_circle(p(3.0, 0.0), 0.5).unwrap();
    s.add_constraint(Concentric {
        first: c1,
        second: c2,
    })
    .unwrap();
    s.add_constraint(EqualRadius {
        first: c1,
        second: c3,
    })
    .unwrap();
    jacobian_matches_differences(&s, c1);
    round_trips(&s);
    s.solve().unwrap();
    let circle = |s: &Sketch, c| match s.entity(c).unwrap() {
        Entity::Circle { center, radius } => (*center, *radius),
        _ => unreachable!(),
    };
    let ((o1, r1), (o2, _), (_, r3)) = (circle(&s, c1), circle(&s, c2), circle(&s, c3));
    assert!((o1 - o2).norm() < 1e-12);
    assert!((r1 - r3).abs() < 1e-12);
    // Minimum norm: both radii meet halfway, both centres meet halfway.
    assert!((r1 - 0.75).abs() < 1e-12 && (o1 - p(0.1, -0.05)).norm() < 1e-12);
    let mut d = s.drag(PointRef::Control(c2, 0)).unwrap();
    d.update(p(1.0, 1.0)).unwrap();
    assert!((d.point(PointRef::Control(c1, 0)).unwrap() - p(1.0, 1.0)).norm() < 1e-12);
}

#[test]
fn point_on_an_infinite_line_beyond_the_segment() {
    let mut s = Sketch::new();
    let l = s.add_line(p(0.0, 0.0), p(1.0, 1.0)).unwrap();
    let q = s.add_point(p(3.0, 2.0)).unwrap();
    s.add_constraint(Fixed::entity(l)).unwrap();
    s.add_constraint(PointOnLine {
        point: PointRef::Point(q),
        line: l,
    })
    .unwrap();
    jacobian_matches_differences(&s, l);
    round_trips(&s);
    let on = |at: &dyn Fn(PointRef) -> Point2<f64>| {
        let v = at(PointRef::Point(q));
        (v.x - v.y).abs() < 1e-9
    };
    s.solve().unwrap();
    // The foot of (3, 2) on y = x, outside the segment [0, 1]².
    assert!((pt(&s, PointRef::Point(q)) - p(2.5, 2.5)).norm() < 1e-9);
    assert!(on(&|r| pt(&s, r)));
    let mut d = s.drag(PointRef::Point(q)).unwrap();
    // The drag target is off the line: the point can only follow along it.
    assert!(d.update(p(-4.0, -3.0)).is_err() || on(&|r| d.point(r).unwrap()));
}

#[test]
fn point_line_distance_on_either_side() {
    for (side, sign) in [(LineSide::Left, 1.0), (LineSide::Right, -1.0)] {
        let mut s = Sketch::new();
        let l = s.add_line(p(0.0, 0.0), p(2.0, 0.0)).unwrap();
        let q = s.add_point(p(1.0, 0.3 * sign)).unwrap();
        s.add_constraint(Fixed::entity(l)).unwrap();
        s.add_constraint(PointLineDistance {
            point: PointRef::Point(q),
            line: l,
            distance: 0.75,
            side,
        })
        .unwrap();
        jacobian_matches_differences(&s, l);
        round_trips(&s);
        s.solve().unwrap();
        assert!((pt(&s, PointRef::Point(q)) - p(1.0, 0.75 * sign)).norm() < 1e-9);
        let mut d = s.drag(PointRef::Point(q)).unwrap();
        d.update(p(1.8, 0.75 * sign)).unwrap();
        assert!((d.point(PointRef::Point(q)).unwrap().y - 0.75 * sign).abs() < 1e-9);
    }
}

#[test]
fn midpoint_of_a_line() {
    let mut s = Sketch::new();
    let l = s.add_line(p(0.0, 0.0), p(4.0, 2.0)).unwrap();
    let m = s.add_point(p(1.0, 2.0)).unwrap();
    s.add_constraint(Midpoint {
        point: PointRef::Point(m),
        of: camber_sketch::vocabulary::PointPair::Line(l),
    })
    .unwrap();
    jacobian_matches_differences(&s, l);
    round_trips(&s);
    let mid = |at: &dyn Fn(PointRef) -> Point2<f64>| {
        (at(PointRef::Point(m)) - nalgebra::center(&at(PointRef::Start(l)), &at(PointRef::End(l))))
            .norm()
            < 1e-12
    };
    solve_and_drag(&mut s, mid, PointRef::Control(l, 1), p(5.0, 5.0));
}

#[test]
fn symmetric_points_about_a_line() {
    let mut s = Sketch::new();
    let axis = s.add_line(p(0.0, -1.0), p(0.0, 1.0)).unwrap();
    let a = s.add_point(p(-1.0, 0.2)).unwrap();
    let b = s.add_point(p(1.3, 0.5)).unwrap();
    s.add_constraint(Fixed::entity(axis)).unwrap();
    s.add_constraint(Symmetric {
        a: PointRef::Point(a),
        b: PointRef::Point(b),
        line: axis,
    })
    .unwrap();
    jacobian_matches_differences(&s, axis);
    round_trips(&s);
    let mirrored = |at: &dyn Fn(PointRef) -> Point2<f64>| {
        let (u, v) = (at(PointRef::Point(a)), at(PointRef::Point(b)));
        (u.x + v.x).abs() < 1e-9 && (u.y - v.y).abs() < 1e-9
    };
    solve_and_drag(&mut s, mirrored, PointRef::Point(a), p(-2.0, 1.0));
}

#[test]
fn horizontal_and_vertical_distances() {
    let mut s = Sketch::new();
    let a = s.add_point(p(0.0, 0.0)).unwrap();
    let b = s.add_point(p(1.0, 1.0)).unwrap();
    let pair = camber_sketch::vocabulary::PointPair::Points(PointRef::Point(a), PointRef::Point(b));
    s.add_constraint(HorizontalDistance {
        of: pair,
        distance: 2.5,
    })
    .unwrap();
    s.add_constraint(VerticalDistance {
        of: pair,
        distance: -0.5,
    })
    .unwrap();
    jacobian_matches_differences(&s, a);
    round_trips(&s);
    let apart = |at: &dyn Fn(PointRef) -> Point2<f64>| {
        let d = at(PointRef::Point(b)) - at(PointRef::Point(a));
        (d - Vector2::new(2.5, -0.5)).norm() < 1e-12
    };
    solve_and_drag(&mut s, apart, PointRef::Point(a), p(-1.0, 3.0));
}

/// The length of a curve by composite Simpson on 2¹⁷ intervals per knot span (an independent
/// method: error O(h⁴), far below the tolerances checked).
fn length(c: &dyn ParametricCurve<f64, 2>, breaks: &[f64]) -> f64 {
    let speed = |u: f64| c.point_and_derivative(u).unwrap().1.norm();
    let n = 1 << 17;
    breaks
        .windows(2)
        .map(|w| {
            let h = (w[1] - w[0]) / f64::from(n);
            let mut sum = speed(w[0]) + speed(w[1]);
            for i in 1..n {
                sum += speed(w[0] + h * f64::from(i)) * if i % 2 == 1 { 4.0 } else { 2.0 };
            }
            sum * h / 3.0
        })
        .sum()
}

#[test]
fn arc_length_of_a_bspline() {
    let mut s = Sketch::new();
    let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0, 1.0]).unwrap();
    let pts = vec![
        p(0.0, 0.0),
        p(1.0, 1.0),
        p(2.0, -0.5),
        p(3.0, 1.0),
        p(4.0, 0.0),
    ];
    let c = s
        .add_bspline(BSplineCurve2::try_new(3, knots, pts).unwrap())
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(c))).unwrap();
    s.add_constraint(Fixed::point(PointRef::End(c))).unwrap();
    s.add_constraint(ArcLength {
        curve: c,
        length: 6.0,
    })
    .unwrap();
    jacobian_matches_differences(&s, c);
    round_trips(&s);
    let len = |s: &Sketch| length(s.entity(c).unwrap().as_curve().unwrap(), &[0.0, 0.4, 1.0]);
    assert!((len(&s) - 6.0).abs() > 0.1, "the start violates it");
    s.solve().unwrap();
    assert!((len(&s) - 6.0).abs() < 1e-9, "{}", len(&s));
    let mut d = s.drag(PointRef::Control(c, 2)).unwrap();
    d.update(p(2.0, -1.0)).unwrap();
    d.finish(&mut s).unwrap();
    assert!((len(&s) - 6.0).abs() < 1e-9, "{}", len(&s));
}

#[test]
fn arc_length_of_a_straight_bezier_is_its_chord() {
    let mut s = Sketch::new();
    let c = s
        .add_bezier(BezierCurve2::try_new(vec![p(0.0, 0.0), p(0.3, 0.0), p(2.0, 0.0)]).unwrap())
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(c))).unwrap();
    s.add_constraint(Horizontal {
        of: camber_sketch::vocabulary::PointPair::Points(
            PointRef::Control(c, 0),
            PointRef::Control(c, 1),
        ),
    })
    .unwrap();
    s.add_constraint(Horizontal {
        of: camber_sketch::vocabulary::PointPair::Points(
            PointRef::Control(c, 1),
            PointRef::Control(c, 2),
        ),
    })
    .unwrap();
    s.add_constraint(ArcLength {
        curve: c,
        length: 3.0,
    })
    .unwrap();
    s.solve().unwrap();
    // A straight monotone Bézier's length is the distance between its ends.
    assert!((pt(&s, PointRef::End(c)).x - 3.0).abs() < 1e-10);
}

#[test]
fn curvature_at_a_parameter() {
    let mut s = Sketch::new();
    let c = s
        .add_bezier(
            BezierCurve2::try_new(vec![p(0.0, 0.0), p(1.0, 1.0), p(2.0, 1.0), p(3.0, 0.0)])
                .unwrap(),
        )
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(c))).unwrap();
    s.add_constraint(Fixed::point(PointRef::End(c))).unwrap();
    s.add_constraint(CurvatureAt {
        curve: c,
        u: 0.5,
        curvature: -1.2,
    })
    .unwrap();
    jacobian_matches_differences(&s, c);
    round_trips(&s);
    let kappa = |s: &Sketch| {
        camber_geom::queries::signed_curvature(s.entity(c).unwrap().as_curve().unwrap(), 0.5)
            .unwrap()
    };
    s.solve().unwrap();
    assert!((kappa(&s) + 1.2).abs() < 1e-9);
    let mut d = s.drag(PointRef::Control(c, 1)).unwrap();
    d.update(p(0.8, 1.4)).unwrap();
    d.finish(&mut s).unwrap();
    assert!((kappa(&s) + 1.2).abs() < 1e-9);
}

#[test]
fn c1_and_c2_joins_match_derivatives() {
    for order in [1, 2] {
        let mut s = Sketch::new();
        let a = s
            .add_bezier(
                BezierCurve2::try_new(vec![p(0.0, 0.0), p(1.0, 1.0), p(2.0, 1.0), p(3.0, 0.0)])
                    .unwrap(),
            )
            .unwrap();
        let b = s
            .add_bezier(
                BezierCurve2::try_new(vec![p(3.2, 0.1), p(4.0, 0.5), p(5.0, -1.0), p(6.0, 0.0)])
                    .unwrap(),
            )
            .unwrap();
        s.add_constraint(Fixed::point(PointRef::Start(a))).unwrap();
        let join: Constraint = if order == 1 {
            C1Join {
                first: a,
                second: b,
            }
            .into()
        } else {
            C2Join {
                first: a,
                second: b,
            }
            .into()
        };
        s.add_constraint(join).unwrap();
        jacobian_matches_differences(&s, a);
        round_trips(&s);
        let check = |s: &Sketch| {
            let (ca, cb) = (
                s.entity(a)
                    .unwrap()
                    .as_curve()
                    .unwrap()
                    .second_order(1.0)
                    .unwrap(),
                s.entity(b)
                    .unwrap()
                    .as_curve()
                    .unwrap()
                    .second_order(0.0)
                    .unwrap(),
            );
            (ca[0] - cb[0]).norm() < 1e-10
                && (ca[1] - cb[1]).norm() < 1e-10
                && (order < 2 || (ca[2] - cb[2]).norm() < 1e-9)
        };
        s.solve().unwrap();
        assert!(check(&s), "order {order}");
        let mut d = s.drag(PointRef::Control(b, 2)).unwrap();
        d.update(p(5.0, 1.0)).unwrap();
        d.finish(&mut s).unwrap();
        assert!(check(&s), "order {order} after the drag");
    }
}
