//! `ellipse_touches_line`: an ellipse or elliptic arc touching a line in its interior, solved
//! against the closed form of the support function (the centre √(a²sin²θ + b²cos²θ) above a
//! horizontal line for an ellipse turned by θ) and against a second method (the lowest of
//! 200,000 points sampled on the solved ellipse lies on the line), the side kept over seeded
//! random drags, the contact off an elliptic arc refused with nothing changed, DOF, bad
//! inputs, the file form and the autodiff Jacobian against central differences.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use std::f64::consts::{PI, TAU};

use approx::assert_relative_eq;
use camber_geom::{Ellipse, EllipticArc};
use camber_sketch::constraints::ellipse_touches_line::EllipseLineContact;
use camber_sketch::constraints::semi_axis::Axis;
use camber_sketch::constraints::{
    EllipseTouchesLine, Fixed, HorizontalDistance, SemiAxis, VerticalDistance,
};
use camber_sketch::file::{from_json, to_json};
use camber_sketch::vocabulary::PointPair;
use camber_sketch::{Entity, EntityId, Error, LineSide, PointRef, Sketch};
use camber_solve::testing::check_jacobian;
use nalgebra::{Point2, Vector2};
use proptest::prelude::*;
use proptest::test_runner::{RngAlgorithm, TestRng};

fn dof(s: &Sketch) -> usize {
    s.analyze().unwrap().iter().map(|a| a.analysis.dof).sum()
}

/// The x axis from (−5, 0) to (5, 0), fixed.
fn floor(s: &mut Sketch) -> EntityId {
    let l = s
        .add_line(Point2::new(-5.0, 0.0), Point2::new(5.0, 0.0))
        .unwrap();
    s.add_constraint(Fixed::entity(l)).unwrap();
    l
}

/// Holds an ellipse's shape and turn: b and the vertex's offset from the centre (a, θ) fixed,
/// the centre free.
fn rigid(s: &mut Sketch, e: EntityId, a: f64, b: f64, theta: f64) {
    let (c, v) = (PointRef::Control(e, 0), PointRef::Control(e, 1));
    s.add_constraint(HorizontalDistance {
        of: PointPair::Points(c, v),
        distance: a * theta.cos(),
    })
    .unwrap();
    s.add_constraint(VerticalDistance {
        of: PointPair::Points(c, v),
        distance: a * theta.sin(),
    })
    .unwrap();
    s.add_constraint(SemiAxis {
        ellipse: e,
        axis: Axis::B,
        length: b,
    })
    .unwrap();
}

/// The lowest y over 200,000 points of the ellipse, and where.
fn lowest(e: &Ellipse<f64>) -> (f64, f64) {
    (0..200_000)
        .map(|k| e.point_at_angle(TAU * f64::from(k) / 200_000.0))
        .map(|p| (p.y, p.x))
        .fold((f64::INFINITY, 0.0), |m, p| if p.0 < m.0 { p } else { m })
}

#[test]
fn a_turned_ellipse_rests_on_a_line_at_its_support_distance() {
    for (a, b, theta) in [
        (2.0, 1.0, 0.0),
        (2.0, 1.0, 0.5),
        (3.0, 0.4, -1.2),
        (1.0, 1.5, 2.0),
    ] {
        let mut s = Sketch::new();
        let l = floor(&mut s);
        let e = s
            .add_ellipse(&Ellipse::try_new(Point2::new(0.3, 2.5), a, b, theta).unwrap())
            .unwrap();
        rigid(&mut s, e, a, b, theta);
        s.add_constraint(EllipseTouchesLine {
            ellipse: e,
            line: l,
            side: LineSide::Left,
        })
        .unwrap();
        s.solve().unwrap();
        let solved = s.entity(e).unwrap().as_ellipse().unwrap();
        let h = (a * a * theta.sin().powi(2) + b * b * theta.cos().powi(2)).sqrt();
        assert_relative_eq!(solved.center().y, h, epsilon = 1e-10);
        let (y, _) = lowest(&solved);
        assert!(y.abs() < 1e-8, "the lowest point is {y} off the line");
    }
}

#[test]
fn an_ellipse_below_a_line_touches_it_from_the_right() {
    // The line runs left to right; its right side is below. A tilted line checks the support
    // function off the axes: the distance from the line to the nearest sampled point is zero.
    let mut s = Sketch::new();
    let l = s
        .add_line(Point2::new(-3.0, -1.0), Point2::new(3.0, 1.0))
        .unwrap();
    s.add_constraint(Fixed::entity(l)).unwrap();
    let e = s
        .add_ellipse(&Ellipse::try_new(Point2::new(1.0, -3.0), 2.0, 0.7, 0.9).unwrap())
        .unwrap();
    rigid(&mut s, e, 2.0, 0.7, 0.9);
    s.add_constraint(EllipseTouchesLine {
        ellipse: e,
        line: l,
        side: LineSide::Right,
    })
    .unwrap();
    s.solve().unwrap();
    let solved = s.entity(e).unwrap().as_ellipse().unwrap();
    let n = Vector2::new(-1.0, 3.0).normalize();
    let signed = |p: Point2<f64>| (p - Point2::new(-3.0, -1.0)).dot(&n);
    let nearest = (0..200_000)
        .map(|k| signed(solved.point_at_angle(TAU * f64::from(k) / 200_000.0)))
        .fold(f64::NEG_INFINITY, f64::max);
    assert!(
        nearest.abs() < 1e-8,
        "the ellipse reaches {nearest} past the line"
    );
    assert!(signed(*solved.center()) < 0.0);
}

#[test]
fn an_elliptic_arc_touches_only_where_its_sweep_reaches() {
    // The lower half of the ellipse touches the floor at its bottom (θ = 3π/2); an upper half
    // cannot: its contact would be off the arc, and the sketch stays as it was.
    for (a0, a1, ok) in [(PI, TAU, true), (0.0, PI, false)] {
        let mut s = Sketch::new();
        let l = floor(&mut s);
        let arc = EllipticArc::try_new(Point2::new(0.0, 2.0), 2.0, 1.0, 0.0, a0, a1).unwrap();
        let e = s.add_elliptic_arc(&arc).unwrap();
        rigid(&mut s, e, 2.0, 1.0, 0.0);
        let c = s
            .add_constraint(EllipseTouchesLine {
                ellipse: e,
                line: l,
                side: LineSide::Left,
            })
            .unwrap();
        let before = to_json(&s).unwrap();
        match s.solve() {
            Ok(_) => {
                assert!(ok, "the upper half was reported touching");
                let solved = s.entity(e).unwrap().as_elliptic_arc().unwrap();
                assert_relative_eq!(solved.ellipse().center().y, 1.0, epsilon = 1e-10);
            }
            Err(Error::ContactOffArc {
                constraint,
                arc: which,
                outside,
            }) => {
                assert!(!ok, "the lower half was refused");
                assert_eq!((constraint, which), (c, e));
                assert!(outside > 0.5, "{outside}");
                assert_eq!(to_json(&s).unwrap(), before);
            }
            Err(other) => panic!("{other}"),
        }
    }
}

#[test]
fn drags_of_the_line_keep_the_ellipse_on_its_side_touching() {
    let mut s = Sketch::new();
    let l = s
        .add_line(Point2::new(-4.0, 0.0), Point2::new(4.0, 0.0))
        .unwrap();
    let e = s
        .add_ellipse(&Ellipse::try_new(Point2::new(0.0, 1.2), 2.0, 1.0, 0.3).unwrap())
        .unwrap();
    s.add_constraint(Fixed::entity(e)).unwrap();
    s.add_constraint(EllipseTouchesLine {
        ellipse: e,
        line: l,
        side: LineSide::Left,
    })
    .unwrap();
    s.solve().unwrap();
    let ellipse = s.entity(e).unwrap().as_ellipse().unwrap();
    let mut rng = TestRng::from_seed(RngAlgorithm::ChaCha, &[29; 32]);
    let (mut kept, mut refused) = (0, 0);
    for n in 0..100 {
        let end = if rng.random_bool(0.5) {
            PointRef::Start(l)
        } else {
            PointRef::End(l)
        };
        let p = s.point(end).unwrap();
        let to = p + Vector2::new(rng.random_range(-0.3..0.3), rng.random_range(-0.3..0.3));
        let mut drag = s.drag(end).unwrap();
        match drag.update(to) {
            Ok(_) => kept += 1,
            Err(_) => refused += 1,
        }
        drag.finish(&mut s).unwrap();
        let Entity::Line([a, b]) = s.entity(l).unwrap() else {
            panic!()
        };
        let d = b - a;
        let normal = Vector2::new(-d.y, d.x) / d.norm();
        let (u, v) = ellipse.axes();
        let h = (4.0 * normal.dot(&u).powi(2) + normal.dot(&v).powi(2)).sqrt();
        let centre = (ellipse.center() - a).dot(&normal);
        assert!(
            (centre - h).abs() < 1e-9,
            "drag {n}: centre {centre} from the line, reach {h}"
        );
    }
    assert!(kept > 80, "{kept} drags kept, {refused} refused");
}

#[test]
fn a_contact_removes_one_degree_of_freedom_and_survives_a_file() {
    let mut s = Sketch::new();
    let l = s
        .add_line(Point2::new(-5.0, 0.0), Point2::new(5.0, 0.0))
        .unwrap();
    let e = s
        .add_elliptic_arc(
            &EllipticArc::try_new(Point2::new(0.0, 1.0), 2.0, 1.0, 0.0, PI, TAU).unwrap(),
        )
        .unwrap();
    assert_eq!(dof(&s), 4 + 7);
    let c = s
        .add_constraint(EllipseTouchesLine {
            ellipse: e,
            line: l,
            side: LineSide::Left,
        })
        .unwrap();
    assert_eq!(dof(&s), 4 + 7 - 1);
    let text = to_json(&s).unwrap();
    assert!(text.contains("\"ellipse_touches_line\""), "{text}");
    let back = from_json(&text).unwrap();
    assert_eq!(back.constraint(c).unwrap(), s.constraint(c).unwrap());
}

#[test]
fn contacts_between_the_wrong_entities_are_refused_and_nothing_changes() {
    let mut s = Sketch::new();
    let l = s
        .add_line(Point2::new(-5.0, 0.0), Point2::new(5.0, 0.0))
        .unwrap();
    let m = s
        .add_line(Point2::new(-5.0, 1.0), Point2::new(5.0, 1.0))
        .unwrap();
    let e = s
        .add_ellipse(&Ellipse::try_new(Point2::new(0.0, 3.0), 2.0, 1.0, 0.0).unwrap())
        .unwrap();
    let circle = s
        .add_entity(Entity::Circle {
            center: Point2::new(0.0, 3.0),
            radius: 1.0,
        })
        .unwrap();
    let before = to_json(&s).unwrap();
    let touch = |ellipse, line| EllipseTouchesLine {
        ellipse,
        line,
        side: LineSide::Left,
    };
    for (bad, named) in [
        (touch(circle, l), circle),
        (touch(m, l), m),
        (touch(e, circle), circle),
    ] {
        match s.add_constraint(bad) {
            Err(Error::WrongEntityKind { entity, .. }) => assert_eq!(entity, named),
            other => panic!("{other:?}"),
        }
    }
    assert!(matches!(
        s.add_constraint(touch(e, EntityId(99))),
        Err(Error::UnknownEntity { .. })
    ));
    assert_eq!(to_json(&s).unwrap(), before);
}

fn xy() -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-3.0..3.0f64, 2)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn the_contact_jacobian_matches_central_differences(
        c in xy(), v in xy(), a in xy(), b in xy(), minor in 0.2..3.0f64, left in any::<bool>(),
    ) {
        let d = |p: &[f64], q: &[f64]| (p[0] - q[0]).hypot(p[1] - q[1]);
        prop_assume!(d(&v, &c) > 0.2 && d(&a, &b) > 0.2);
        let side = if left { LineSide::Left } else { LineSide::Right };
        let m = [minor];
        let refs: [&[f64]; 5] = [&c, &v, &m, &a, &b];
        prop_assert!(check_jacobian(&EllipseLineContact::new(side), &refs, 1e-6, 1.0).unwrap().error < 1e-6);
    }

    #[test]
    fn the_row_vanishes_exactly_at_the_sampled_support_distance(
        a_len in 0.3..3.0f64, ratio in 0.1..3.0f64, rot in -PI..PI,
    ) {
        // An ellipse about the origin and the horizontal line through its lowest sampled point.
        let e = Ellipse::try_new(Point2::new(0.0, 0.0), a_len, a_len * ratio, rot).unwrap();
        let (y, x) = lowest(&e);
        let (u, _) = e.axes();
        let vertex = u * a_len;
        let m = [a_len * ratio];
        let refs: [&[f64]; 5] = [&[0.0, 0.0], vertex.as_slice(), &m, &[x - 1.0, y], &[x + 1.0, y]];
        let mut g = [f64::NAN];
        camber_solve::Residual::eval(&EllipseLineContact::new(LineSide::Left), &refs, &mut g);
        prop_assert!(g[0].abs() < 1e-8, "{}", g[0]);
    }
}
