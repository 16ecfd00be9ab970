//! `Sketch::split_at_intersection`: a line, an arc or a free-form curve cut where it crosses
//! another entity. The pieces are sampled against the original curve, the joint is checked on
//! the other entity by its own closed form, the sketch is solved after, the constraints at the
//! entity's end follow the second piece, and bad inputs are refused with the sketch unchanged.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use camber_geom::queries::closest_point;
use camber_geom::{BSplineCurve2, BezierCurve2, CircularArc, KnotVector, ParametricCurve};
use camber_sketch::constraints::{Coincident, Fixed, PointAtParameter};
use camber_sketch::{Constraint, Entity, EntityId, Error, FixTarget, PointRef, Sketch, Target};
use nalgebra::Point2;

fn json(s: &Sketch) -> String {
    camber_sketch::file::to_json(s).unwrap()
}

fn s_curve() -> BezierCurve2<f64> {
    BezierCurve2::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 2.0),
        Point2::new(2.0, -1.0),
        Point2::new(3.0, 1.0),
    ])
    .unwrap()
}

/// Every sample of `piece` lies on `original` (closest-point distance below 1e-12).
fn lies_on(piece: &Entity, original: &dyn ParametricCurve<f64, 2>) {
    let c = piece.as_curve().unwrap();
    let (lo, hi) = c.domain();
    for k in 0..=40 {
        let p = c.point(lo + (hi - lo) * f64::from(k) / 40.0).unwrap();
        let d = closest_point(original, &p).unwrap().distance;
        assert!(d < 1e-12, "sample {k} is {d:e} off the curve");
    }
}

/// A cubic Bézier crossing the vertical line x = 1.5 once: both pieces lie on the original,
/// meet at the crossing, which lies on x = 1.5 before and after a solve.
#[test]
fn a_bezier_split_at_a_line_keeps_its_shape_and_meets_on_the_line() {
    let mut s = Sketch::new();
    let curve = s.add_bezier(s_curve()).unwrap();
    let line = s
        .add_line(Point2::new(1.5, -3.0), Point2::new(1.5, 3.0))
        .unwrap();
    let split = s.split_at_intersection(curve, line, None).unwrap();
    assert_eq!(split.first, curve);
    assert_relative_eq!(split.point.x, 1.5, epsilon = 1e-12);
    let original = s_curve();
    lies_on(s.entity(curve).unwrap(), &original);
    lies_on(s.entity(split.second).unwrap(), &original);
    let end = s.point(PointRef::End(curve)).unwrap();
    let start = s.point(PointRef::Start(split.second)).unwrap();
    assert!((end - start).norm() < 1e-12);
    assert_relative_eq!(end.x, 1.5, epsilon = 1e-12);
    assert_eq!(split.added.len(), 2);
    assert!(matches!(
        s.constraint(split.added[1]).unwrap(),
        Constraint::PointOnLine(_)
    ));
    s.solve().unwrap();
    let end = s.point(PointRef::End(curve)).unwrap();
    assert!((s.point(PointRef::Start(split.second)).unwrap() - end).norm() < 1e-10);
    assert!((end.x - 1.5).abs() < 1e-10);
}

/// A cubic B-spline crossing a circle twice: without a point the split is ambiguous, with one
/// it cuts at the nearer crossing; both pieces agree with the original at the same parameters
/// (a B-spline split keeps its parameterization).
#[test]
fn a_bspline_split_at_a_circle_takes_the_crossing_nearest_the_point() {
    let mut s = Sketch::new();
    let pts = (0..6)
        .map(|i| Point2::new(f64::from(i), if i % 2 == 0 { 0.0 } else { 0.5 }))
        .collect();
    let spline =
        BSplineCurve2::try_new(3, KnotVector::clamped_uniform(3, 6).unwrap(), pts).unwrap();
    let curve = s.add_bspline(spline.clone()).unwrap();
    let circle = s.add_circle(Point2::new(2.5, 0.2), 1.0).unwrap();
    let file = json(&s);
    assert_eq!(
        s.split_at_intersection(curve, circle, None).unwrap_err(),
        Error::AmbiguousIntersection {
            entity: curve,
            other: circle,
            count: 2
        }
    );
    assert_eq!(json(&s), file);
    let split = s
        .split_at_intersection(curve, circle, Some(Point2::new(4.0, 0.0)))
        .unwrap();
    assert!(split.point.x > 2.5);
    assert_relative_eq!(
        (split.point - Point2::new(2.5, 0.2)).norm(),
        1.0,
        epsilon = 1e-12
    );
    for id in [curve, split.second] {
        let piece = s.entity(id).unwrap().as_curve().unwrap();
        let (lo, hi) = piece.domain();
        for k in 0..=20 {
            let u = lo + (hi - lo) * f64::from(k) / 20.0;
            assert!((piece.point(u).unwrap() - spline.point(u).unwrap()).norm() < 1e-12);
        }
    }
    assert!(matches!(
        s.constraint(split.added[1]).unwrap(),
        Constraint::PointOnCircle(_)
    ));
    s.solve().unwrap();
}

/// An arc of radius 2 about the origin from 0° to 180° split by the line x = 1: two arcs on
/// the same circle meeting at (1, √3), the first sweeping 60°, the second 120°.
#[test]
fn an_arc_split_at_a_line_gives_two_arcs_of_its_circle() {
    let mut s = Sketch::new();
    let arc = s
        .add_arc(&CircularArc::try_new(Point2::origin(), 2.0, 0.0, std::f64::consts::PI).unwrap())
        .unwrap();
    let line = s
        .add_line(Point2::new(1.0, -3.0), Point2::new(1.0, 3.0))
        .unwrap();
    let split = s.split_at_intersection(arc, line, None).unwrap();
    let (a, b) = (
        s.entity(arc).unwrap().as_arc().unwrap(),
        s.entity(split.second).unwrap().as_arc().unwrap(),
    );
    let x = Point2::new(1.0, 3f64.sqrt());
    assert_relative_eq!(a.end_point(), x, epsilon = 1e-12);
    assert_relative_eq!(b.start_point(), x, epsilon = 1e-12);
    assert_relative_eq!(a.sweep(), std::f64::consts::FRAC_PI_3, epsilon = 1e-12);
    assert_relative_eq!(
        b.sweep(),
        2.0 * std::f64::consts::FRAC_PI_3,
        epsilon = 1e-12
    );
    assert_relative_eq!(*b.center(), Point2::origin(), epsilon = 1e-15);
    assert_relative_eq!(b.radius(), 2.0, epsilon = 1e-12);
    s.solve().unwrap();
}

/// A `fixed` and a `coincident` at a line's end follow the end to the second piece; one at its
/// start stays with the first.
#[test]
fn constraints_at_the_end_move_to_the_second_piece() {
    let mut s = Sketch::new();
    let a = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(4.0, 0.0))
        .unwrap();
    let b = s
        .add_line(Point2::new(4.0, 0.0), Point2::new(4.0, 3.0))
        .unwrap();
    let cut = s
        .add_line(Point2::new(1.0, -1.0), Point2::new(1.0, 1.0))
        .unwrap();
    let start = s.add_constraint(Fixed::point(PointRef::Start(a))).unwrap();
    let end = s.add_constraint(Fixed::point(PointRef::End(a))).unwrap();
    let corner = s
        .add_constraint(Coincident {
            a: PointRef::End(a),
            b: PointRef::Start(b),
        })
        .unwrap();
    let split = s.split_at_intersection(a, cut, None).unwrap();
    assert_eq!(split.moved.len(), 2);
    assert!(s.constraint(start).is_ok());
    assert!(s.constraint(end).is_err() && s.constraint(corner).is_err());
    let moved: Vec<Constraint> = split
        .moved
        .iter()
        .map(|(_, id)| s.constraint(*id).unwrap().clone())
        .collect();
    assert!(moved.contains(&Constraint::Fixed(Fixed {
        target: FixTarget::Point(PointRef::End(split.second))
    })));
    assert!(moved.contains(&Constraint::Coincident(Coincident {
        a: PointRef::End(split.second),
        b: PointRef::Start(b),
    })));
    s.solve().unwrap();
    assert_relative_eq!(
        s.point(PointRef::End(split.second)).unwrap(),
        Point2::new(4.0, 0.0),
        epsilon = 1e-12
    );
}

/// A constraint at the cut entity's end moves to the second piece with its priority; the one
/// at the start keeps its own.
#[test]
fn a_moved_constraint_keeps_its_priority() {
    let mut s = Sketch::new();
    let a = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(4.0, 0.0))
        .unwrap();
    let cut = s
        .add_line(Point2::new(1.0, -1.0), Point2::new(1.0, 1.0))
        .unwrap();
    let start = s.add_constraint(Fixed::point(PointRef::Start(a))).unwrap();
    let end = s.add_constraint(Fixed::point(PointRef::End(a))).unwrap();
    s.set_priority(start, 2).unwrap();
    s.set_priority(end, 7).unwrap();
    let split = s.split_at_intersection(a, cut, None).unwrap();
    let moved = split.moved.iter().find(|(was, _)| *was == end).unwrap().1;
    assert_eq!(s.priority(moved), 7);
    assert_eq!(s.priority(start), 2);
}

/// Bad inputs: typed errors naming the entities, the sketch unchanged.
#[test]
fn bad_splits_are_refused_and_change_nothing() {
    let mut s = Sketch::new();
    let a = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(4.0, 0.0))
        .unwrap();
    let far = s
        .add_line(Point2::new(0.0, 5.0), Point2::new(4.0, 6.0))
        .unwrap();
    let p = s.add_point(Point2::new(1.0, 0.0)).unwrap();
    let circle = s.add_circle(Point2::new(2.0, 0.0), 1.0).unwrap();
    // A line touching `a` only at its end is no cut.
    let at_end = s
        .add_line(Point2::new(4.0, 0.0), Point2::new(5.0, 1.0))
        .unwrap();
    let curve = s.add_bezier(s_curve()).unwrap();
    let across = s
        .add_line(Point2::new(1.5, -3.0), Point2::new(1.5, 3.0))
        .unwrap();
    let held = s
        .add_constraint(PointAtParameter {
            curve,
            u: 0.5,
            target: Target::At(Point2::new(1.5, 0.5)),
        })
        .unwrap();
    let file = json(&s);
    let none = |e: EntityId, o: EntityId| Error::NoIntersection {
        entity: e,
        other: o,
    };
    assert_eq!(
        s.split_at_intersection(a, far, None).unwrap_err(),
        none(a, far)
    );
    assert_eq!(
        s.split_at_intersection(a, at_end, None).unwrap_err(),
        none(a, at_end)
    );
    assert!(matches!(
        s.split_at_intersection(a, p, None),
        Err(Error::WrongEntityKind { entity, .. }) if entity == p
    ));
    assert!(matches!(
        s.split_at_intersection(circle, a, None),
        Err(Error::WrongEntityKind { entity, .. }) if entity == circle
    ));
    assert_eq!(
        s.split_at_intersection(a, a, None).unwrap_err(),
        Error::SameEntity { entity: a }
    );
    assert!(matches!(
        s.split_at_intersection(a, circle, Some(Point2::new(f64::NAN, 0.0))),
        Err(Error::NonFinite { .. })
    ));
    assert_eq!(
        s.split_at_intersection(curve, across, None).unwrap_err(),
        Error::EntityConstrained {
            entity: curve,
            constraint: held,
            operation: "split"
        }
    );
    assert_eq!(json(&s), file);
}

/// The upper half of the ellipse x²/4 + y² = 1 split by the line x = 1: two elliptic arcs of
/// the same ellipse meeting at (1, √3/2), the parametric angle π/3; the first runs from 0 to
/// π/3, the second from π/3 to π; the sketch solves after. Trimmed instead, the kept start
/// piece ends at the crossing.
#[test]
fn an_elliptic_arc_split_at_a_line_gives_two_arcs_of_its_ellipse() {
    use camber_geom::EllipticArc;
    use camber_sketch::sketch::split::Keep;
    use std::f64::consts::{FRAC_PI_3, PI};
    let build = || {
        let mut s = Sketch::new();
        let arc = s
            .add_elliptic_arc(
                &EllipticArc::try_new(Point2::origin(), 2.0, 1.0, 0.0, 0.0, PI).unwrap(),
            )
            .unwrap();
        let line = s
            .add_line(Point2::new(1.0, -3.0), Point2::new(1.0, 3.0))
            .unwrap();
        (s, arc, line)
    };
    let x = Point2::new(1.0, 3f64.sqrt() / 2.0);
    let (mut s, arc, line) = build();
    // The end's control point 3 is the end: its constraint follows it to the second piece.
    s.add_constraint(Fixed::point(PointRef::Control(arc, 3)))
        .unwrap();
    let split = s.split_at_intersection(arc, line, None).unwrap();
    assert_eq!(split.moved.len(), 1);
    let (_, moved) = split.moved[0];
    let Constraint::Fixed(Fixed {
        target: FixTarget::Point(p),
    }) = s.constraint(moved).unwrap()
    else {
        panic!("{:?}", s.constraint(moved));
    };
    assert_eq!(p.entity(), split.second, "{p:?}");
    assert_relative_eq!(
        s.point(*p).unwrap(),
        Point2::new(-2.0, 0.0),
        epsilon = 1e-12
    );
    let (a, b) = (
        s.entity(arc).unwrap().as_elliptic_arc().unwrap(),
        s.entity(split.second).unwrap().as_elliptic_arc().unwrap(),
    );
    assert_relative_eq!(a.end_point(), x, epsilon = 1e-12);
    assert_relative_eq!(b.start_point(), x, epsilon = 1e-12);
    assert_relative_eq!(a.sweep(), FRAC_PI_3, epsilon = 1e-12);
    assert_relative_eq!(b.sweep(), PI - FRAC_PI_3, epsilon = 1e-12);
    assert_relative_eq!(b.ellipse().semi_axis_a(), 2.0, epsilon = 1e-15);
    assert_relative_eq!(b.ellipse().semi_axis_b(), 1.0, epsilon = 1e-15);
    s.solve().unwrap();
    assert_relative_eq!(
        s.point(PointRef::End(arc)).unwrap(),
        s.point(PointRef::Start(split.second)).unwrap(),
        epsilon = 1e-9
    );

    let (mut s, arc, line) = build();
    s.trim(arc, line, Keep::Start, None).unwrap();
    let kept = s.entity(arc).unwrap().as_elliptic_arc().unwrap();
    assert_relative_eq!(kept.end_point(), x, epsilon = 1e-12);
    assert_relative_eq!(kept.start_point(), Point2::new(2.0, 0.0), epsilon = 1e-12);
}

/// A cubic Hermite curve with uneven end tangents crossing the line x = 1: both pieces are
/// Hermite curves of four blocks lying on the original, meeting on x = 1 before and after a
/// solve; a composite curve cannot be cut (its smooth joins share tangent blocks) and is
/// refused with the sketch unchanged.
#[test]
fn a_hermite_curve_split_at_a_line_keeps_its_shape_and_a_composite_is_refused() {
    use camber_sketch::{HermiteChain, Join};
    use nalgebra::Vector2;
    let mut s = Sketch::new();
    let chain = HermiteChain::single(
        Point2::new(0.0, 0.0),
        Point2::new(3.0, 1.0),
        Vector2::new(4.0, 5.0),
        Vector2::new(-1.0, 2.0),
    )
    .unwrap();
    let original = chain.segment(0).unwrap();
    let curve = s.add_entity(Entity::Hermite(chain)).unwrap();
    let line = s
        .add_line(Point2::new(1.0, -3.0), Point2::new(1.0, 5.0))
        .unwrap();
    let split = s.split_at_intersection(curve, line, None).unwrap();
    for id in [curve, split.second] {
        let e = s.entity(id).unwrap();
        assert!(matches!(e, Entity::Hermite(_)) && e.points().len() == 4);
        lies_on(e, &original);
    }
    let end = s.point(PointRef::End(curve)).unwrap();
    assert!((s.point(PointRef::Start(split.second)).unwrap() - end).norm() < 1e-12);
    assert_relative_eq!(end.x, 1.0, epsilon = 1e-12);
    s.solve().unwrap();
    let end = s.point(PointRef::End(curve)).unwrap();
    assert!((end.x - 1.0).abs() < 1e-10);

    let composite = HermiteChain::try_new(
        vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.5, 1.0),
            Point2::new(3.0, 0.0),
        ],
        vec![
            Vector2::new(1.0, 1.0),
            Vector2::new(1.5, 0.0),
            Vector2::new(1.0, -1.0),
        ],
        vec![Join::Smooth],
    )
    .unwrap();
    let c = s.add_entity(Entity::Composite(composite)).unwrap();
    let before = json(&s);
    let err = s.split_at_intersection(c, line, None).unwrap_err();
    assert!(
        matches!(err, Error::WrongEntityKind { entity, .. } if entity == c),
        "{err}"
    );
    assert_eq!(json(&s), before);
}
