//! `ellipse_touches_circle`: an ellipse or elliptic arc touching a circle or circular arc at
//! a free parametric angle, solved against closed forms (a circle resting on a vertex or a
//! co-vertex of an axis-aligned ellipse, from outside, from inside, and around it) and against
//! a second method (the distance from a held centre to 200,000 points sampled on a turned
//! ellipse: its minimum, or its maximum for a circle around the ellipse, is the solved radius),
//! seeded random drags that keep the contact and its side, a contact off an elliptic or a
//! circular arc refused with nothing changed, DOF, bad inputs, the file form with the solved
//! angle, and the rows' autodiff Jacobian against central differences.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use approx::assert_relative_eq;
use camber_geom::{CircularArc, Ellipse, EllipticArc};
use camber_sketch::constraints::ellipse_touches_circle::EllipseCircleContact;
use camber_sketch::constraints::{
    EllipseTouchesCircle, Fixed, HorizontalDistance, Radius, VerticalDistance,
};
use camber_sketch::file::{from_json, to_json};
use camber_sketch::vocabulary::PointPair;
use camber_sketch::{
    Constraint, ConstraintId, Entity, EntityId, Error, PointRef, Sketch, Tangency,
};
use camber_solve::testing::check_jacobian;
use nalgebra::{Point2, Vector2};
use proptest::prelude::*;
use proptest::test_runner::{RngAlgorithm, TestRng};

fn dof(s: &Sketch) -> usize {
    s.analyze().unwrap().iter().map(|a| a.analysis.dof).sum()
}

fn circle(s: &mut Sketch, c: (f64, f64), r: f64) -> EntityId {
    s.add_entity(Entity::Circle {
        center: Point2::new(c.0, c.1),
        radius: r,
    })
    .unwrap()
}

fn centre_radius(s: &Sketch, id: EntityId) -> (Point2<f64>, f64) {
    match s.entity(id).unwrap() {
        Entity::Circle { center, radius } => (*center, *radius),
        Entity::Arc(b) => (b[0], (b[1] - b[0]).norm()),
        other => panic!("{other:?}"),
    }
}

fn touch(
    ellipse: EntityId,
    circle: EntityId,
    tangency: Tangency,
    theta: f64,
) -> EllipseTouchesCircle {
    EllipseTouchesCircle {
        ellipse,
        circle,
        tangency,
        theta,
    }
}

/// The solved contact angle of constraint `k`.
fn theta(s: &Sketch, k: ConstraintId) -> f64 {
    match s.constraint(k).unwrap() {
        Constraint::EllipseTouchesCircle(c) => c.theta,
        other => panic!("{other:?}"),
    }
}

/// Holds the offset of the circle's centre from the ellipse's centre along one axis.
fn hold_offset(s: &mut Sketch, e: EntityId, c: EntityId, horizontal: bool, distance: f64) {
    let of = PointPair::Points(PointRef::Control(e, 0), PointRef::Control(c, 0));
    if horizontal {
        s.add_constraint(HorizontalDistance { of, distance })
            .unwrap();
    } else {
        s.add_constraint(VerticalDistance { of, distance }).unwrap();
    }
}

/// Semi-axes a = 2 (along x) and b = 1 about the origin, held. A circle whose centre is held
/// on the y axis rests on the co-vertex (0, 1), and one held on the x axis on the vertex
/// (2, 0): from outside its centre is r beyond, from inside r short of it (a circle of radius
/// r below the radius of curvature there, a²/b = 4 and b²/a = ½), and a circle of radius 5
/// around the ellipse touching the co-vertex from inside has its centre at 1 − 5.
#[test]
fn a_circle_rests_on_a_vertex_of_an_axis_aligned_ellipse() {
    // (on the y axis?, tangency, r, start centre, start θ, expected centre coordinate, θ).
    let cases = [
        (
            true,
            Tangency::External,
            0.5,
            (0.0, 1.8),
            1.4,
            1.5,
            FRAC_PI_2,
        ),
        (
            true,
            Tangency::Internal,
            0.5,
            (0.0, 0.3),
            1.4,
            0.5,
            FRAC_PI_2,
        ),
        (
            true,
            Tangency::Internal,
            5.0,
            (0.0, -3.5),
            1.4,
            -4.0,
            FRAC_PI_2,
        ),
        (false, Tangency::External, 0.5, (2.8, 0.0), 0.2, 2.5, 0.0),
        (false, Tangency::Internal, 0.3, (1.5, 0.0), 0.2, 1.7, 0.0),
    ];
    for (on_y, tangency, r, start, theta0, expected, contact) in cases {
        let mut s = Sketch::new();
        let e = s
            .add_ellipse(&Ellipse::try_new(Point2::origin(), 2.0, 1.0, 0.0).unwrap())
            .unwrap();
        s.add_constraint(Fixed::entity(e)).unwrap();
        let c = circle(&mut s, start, r);
        s.add_constraint(Radius {
            circle: c,
            radius: r,
        })
        .unwrap();
        hold_offset(&mut s, e, c, on_y, 0.0);
        let k = s.add_constraint(touch(e, c, tangency, theta0)).unwrap();
        s.solve().unwrap();
        let (centre, _) = centre_radius(&s, c);
        let along = if on_y { centre.y } else { centre.x };
        assert_relative_eq!(along, expected, epsilon = 1e-10);
        assert_relative_eq!(theta(&s, k), contact, epsilon = 1e-9);
    }
}

/// The distances from `c` to 200,000 points of the ellipse: the least and the greatest.
fn sampled_distances(e: &Ellipse<f64>, c: Point2<f64>) -> (f64, f64) {
    (0..200_000)
        .map(|k| (e.point_at_angle(TAU * f64::from(k) / 200_000.0) - c).norm())
        .fold((f64::INFINITY, 0.0), |(lo, hi), d| (lo.min(d), hi.max(d)))
}

/// A turned ellipse held, a circle with its centre held and its radius free: from outside and
/// from inside (centre within the ellipse) the radius solves to the least sampled distance
/// from the centre to the ellipse, around the ellipse to the greatest. (The rows hold at every
/// foot of a normal from the centre; the start angle picks the one: near the minor axis's
/// lower end for the inside case, where the nearest foot is, and near the far vertex for the
/// circle around the ellipse.)
#[test]
fn a_turned_ellipse_touches_at_the_sampled_nearest_or_farthest_distance() {
    let ellipse = Ellipse::try_new(Point2::new(0.3, -0.2), 2.5, 1.0, 0.7).unwrap();
    let cases = [
        (Tangency::External, Point2::new(2.0, 3.0), 1.0, 1.2, false),
        (Tangency::External, Point2::new(-3.5, -1.0), 1.0, 3.0, false),
        (Tangency::Internal, Point2::new(0.6, 0.0), 0.3, 4.7, false),
        (Tangency::Internal, Point2::new(0.5, 0.1), 2.7, 3.0, true),
    ];
    for (tangency, centre, r0, theta0, farthest) in cases {
        let mut s = Sketch::new();
        let e = s.add_ellipse(&ellipse).unwrap();
        s.add_constraint(Fixed::entity(e)).unwrap();
        let c = circle(&mut s, (centre.x, centre.y), r0);
        s.add_constraint(Fixed::point(PointRef::Control(c, 0)))
            .unwrap();
        let k = s.add_constraint(touch(e, c, tangency, theta0)).unwrap();
        s.solve().unwrap();
        let (_, r) = centre_radius(&s, c);
        let (near, far) = sampled_distances(&ellipse, centre);
        let expected = if farthest { far } else { near };
        assert!(
            (r - expected).abs() < 1e-7,
            "{tangency:?} from {centre}: radius {r}, sampled {expected}"
        );
        // The contact point is at that distance too.
        let p = ellipse.point_at_angle(theta(&s, k));
        assert_relative_eq!((p - centre).norm(), r, epsilon = 1e-9);
    }
}

/// 100 seeded random drags of a circle's centre around a held turned ellipse, from outside and
/// from inside: after every committed drag the circle still touches (its radius is the sampled
/// least distance from its centre, so it neither crosses nor leaves) and its centre is on its
/// recorded side.
#[test]
fn random_drags_keep_the_contact_and_its_side() {
    let ellipse = Ellipse::try_new(Point2::new(0.0, 0.0), 2.0, 1.2, 0.4).unwrap();
    for (tangency, start, r, theta0) in [
        (Tangency::External, (1.0, 2.2), 0.6, 1.3),
        (Tangency::Internal, (0.4, 0.5), 0.5, 1.3),
    ] {
        let mut s = Sketch::new();
        let e = s.add_ellipse(&ellipse).unwrap();
        s.add_constraint(Fixed::entity(e)).unwrap();
        let c = circle(&mut s, start, r);
        s.add_constraint(Radius {
            circle: c,
            radius: r,
        })
        .unwrap();
        let k = s.add_constraint(touch(e, c, tangency, theta0)).unwrap();
        s.solve().unwrap();
        let mut rng = TestRng::from_seed(RngAlgorithm::ChaCha, &[29; 32]);
        let (mut kept, mut refused) = (0, 0);
        let handle = PointRef::Control(c, 0);
        for n in 0..100 {
            let from = s.point(handle).unwrap();
            let to = from + Vector2::new(rng.random_range(-0.3..0.3), rng.random_range(-0.3..0.3));
            let mut drag = s.drag(handle).unwrap();
            match drag.update(to) {
                Ok(_) => kept += 1,
                Err(_) => refused += 1,
            }
            drag.finish(&mut s).unwrap();
            let (centre, radius) = centre_radius(&s, c);
            let (near, _) = (0..20_000)
                .map(|k| (ellipse.point_at_angle(TAU * f64::from(k) / 20_000.0) - centre).norm())
                .fold((f64::INFINITY, 0.0), |(lo, hi): (f64, f64), d| {
                    (lo.min(d), hi.max(d))
                });
            assert!(
                (near - radius).abs() < 1e-5,
                "drag {n}: radius {radius}, nearest sampled {near}"
            );
            let outside = ellipse.implicit_value(&centre) > 0.0;
            assert_eq!(
                outside,
                tangency == Tangency::External,
                "drag {n}: side flipped"
            );
            let p = ellipse.point_at_angle(theta(&s, k));
            assert!(((p - centre).norm() - radius).abs() < 1e-9, "drag {n}");
        }
        assert!(
            kept > 80,
            "{tangency:?}: {kept} drags kept, {refused} refused"
        );
    }
}

/// The bottom of an ellipse is on its lower half arc, not on its upper one; the right of a
/// circle is on an arc facing right, not on one facing left. A contact off an arc fails the
/// solve naming the constraint and the arc, and the sketch is left as it was.
#[test]
fn a_contact_off_an_arc_is_refused_and_nothing_changes() {
    // (elliptic arc's angles, circular arc's angles or a full circle, which arc is refused:
    // the elliptic one or the circular one).
    type Angles = (f64, f64);
    let cases: [(Angles, Option<Angles>, Option<bool>); 4] = [
        ((PI, TAU), None, None),
        ((0.0, PI), None, Some(true)),
        ((PI, TAU), Some((PI / 4.0, 3.0 * PI / 4.0)), None),
        ((PI, TAU), Some((-3.0 * PI / 4.0, -PI / 4.0)), Some(false)),
    ];
    for ((a0, a1), round, refused) in cases {
        let mut s = Sketch::new();
        let arc = EllipticArc::try_new(Point2::new(0.0, 0.0), 2.0, 1.0, 0.0, a0, a1).unwrap();
        let e = s.add_elliptic_arc(&arc).unwrap();
        s.add_constraint(Fixed::entity(e)).unwrap();
        // A circle (or an arc of it) of radius 0.5 below the ellipse, centre on the y axis.
        let c = match round {
            None => circle(&mut s, (0.0, -1.7), 0.5),
            Some((b0, b1)) => s
                .add_arc(&CircularArc::try_new(Point2::new(0.0, -1.7), 0.5, b0, b1).unwrap())
                .unwrap(),
        };
        s.add_constraint(Radius {
            circle: c,
            radius: 0.5,
        })
        .unwrap();
        hold_offset(&mut s, e, c, true, 0.0);
        let k = s
            .add_constraint(touch(e, c, Tangency::External, 4.6))
            .unwrap();
        let before = to_json(&s).unwrap();
        match (s.solve(), refused) {
            (Ok(_), None) => {
                assert_relative_eq!(centre_radius(&s, c).0.y, -1.5, epsilon = 1e-10);
            }
            (
                Err(Error::ContactOffArc {
                    constraint,
                    arc,
                    outside,
                }),
                Some(elliptic),
            ) => {
                assert_eq!(constraint, k);
                assert_eq!(arc, if elliptic { e } else { c });
                assert!(outside > 0.5, "{outside}");
                assert_eq!(to_json(&s).unwrap(), before);
            }
            (other, _) => panic!("{a0} {a1} {round:?}: {other:?}"),
        }
    }
}

/// An ellipse has 5 DOF, an elliptic arc 7, a circle 3, an arc 5: each contact removes one
/// (two rows, one new unknown).
#[test]
fn each_contact_removes_one_dof() {
    let mut s = Sketch::new();
    let e = s
        .add_ellipse(&Ellipse::try_new(Point2::origin(), 2.0, 1.0, 0.0).unwrap())
        .unwrap();
    let c = circle(&mut s, (0.0, 1.5), 0.5);
    assert_eq!(dof(&s), 8);
    s.add_constraint(touch(e, c, Tangency::External, FRAC_PI_2))
        .unwrap();
    assert_eq!(dof(&s), 7);
    let f = s
        .add_elliptic_arc(
            &EllipticArc::try_new(Point2::new(5.0, 0.0), 2.0, 1.0, 0.3, 0.0, 2.0).unwrap(),
        )
        .unwrap();
    let a = s
        .add_arc(&CircularArc::try_new(Point2::new(5.0, 0.0), 3.0, 0.0, 1.5).unwrap())
        .unwrap();
    assert_eq!(dof(&s), 7 + 7 + 5);
    s.add_constraint(touch(f, a, Tangency::Internal, 1.0))
        .unwrap();
    assert_eq!(dof(&s), 7 + 7 + 5 - 1);
}

/// Entities of the wrong kind, an entity named twice, an unknown id, a non-finite angle:
/// typed errors naming the entity or the value, nothing added.
#[test]
fn bad_contacts_are_refused_with_typed_errors() {
    let mut s = Sketch::new();
    let e = s
        .add_ellipse(&Ellipse::try_new(Point2::origin(), 2.0, 1.0, 0.0).unwrap())
        .unwrap();
    let c = circle(&mut s, (0.0, 2.0), 1.0);
    let l = s
        .add_line(Point2::new(-2.0, -2.0), Point2::new(2.0, -2.0))
        .unwrap();
    let wrong = |entity, expected: &'static str, found: &'static str| Error::WrongEntityKind {
        entity,
        expected,
        found,
    };
    let cases = [
        (
            touch(c, e, Tangency::External, 0.0),
            wrong(c, "ellipse or elliptic arc", "circle"),
        ),
        (
            touch(l, c, Tangency::External, 0.0),
            wrong(l, "ellipse or elliptic arc", "line"),
        ),
        (
            touch(e, l, Tangency::External, 0.0),
            wrong(l, "circle or arc", "line"),
        ),
        (
            touch(e, e, Tangency::Internal, 0.0),
            Error::SameEntity { entity: e },
        ),
        (
            touch(e, EntityId(99), Tangency::External, 0.0),
            Error::UnknownEntity {
                entity: EntityId(99),
            },
        ),
        (
            touch(e, c, Tangency::External, f64::INFINITY),
            Error::NonFinite {
                what: "contact angle",
                index: 0,
                value: f64::INFINITY,
            },
        ),
    ];
    let before = to_json(&s).unwrap();
    for (k, expected) in cases {
        assert_eq!(s.add_constraint(k).unwrap_err(), expected, "{k:?}");
    }
    assert_eq!(to_json(&s).unwrap(), before);
    let text = r#"{"version":1,"entities":[
 {"id":0,"kind":"circle","center":[0,0],"radius":1},
 {"id":1,"kind":"circle","center":[3,0],"radius":1}],
"constraints":[{"id":2,"kind":"ellipse_touches_circle","ellipse":0,"circle":1,"tangency":"external","theta":0}]}"#;
    assert_eq!(
        from_json(text).unwrap_err().to_string(),
        "constraint 2 (ellipse_touches_circle): entity 0 is a circle, expected ellipse or elliptic arc"
    );
}

/// The file form carries the angle; after a solve it carries the solved one, and a sketch
/// read back from it is the same.
#[test]
fn the_contact_and_its_solved_angle_round_trip_through_files() {
    let mut s = Sketch::new();
    let e = s
        .add_ellipse(&Ellipse::try_new(Point2::origin(), 2.0, 1.0, 0.0).unwrap())
        .unwrap();
    s.add_constraint(Fixed::entity(e)).unwrap();
    let c = circle(&mut s, (0.0, 1.8), 0.5);
    s.add_constraint(Radius {
        circle: c,
        radius: 0.5,
    })
    .unwrap();
    hold_offset(&mut s, e, c, true, 0.0);
    let k = s
        .add_constraint(touch(e, c, Tangency::External, 1.25))
        .unwrap();
    let text = to_json(&s).unwrap();
    assert!(
        text.contains(r#""kind":"ellipse_touches_circle","ellipse":0,"circle":2,"tangency":"external","theta":1.25"#),
        "{text}"
    );
    s.solve().unwrap();
    let solved = to_json(&s).unwrap();
    let back = from_json(&solved).unwrap();
    assert_eq!(back.constraint(k).unwrap(), s.constraint(k).unwrap());
    assert_relative_eq!(theta(&back, k), FRAC_PI_2, epsilon = 1e-9);
    assert_eq!(to_json(&back).unwrap(), solved);
}

fn xy() -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-3.0..3.0f64, 2)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Both layouts ([c, r] and [c, S]) and both sides against central differences.
    #[test]
    fn the_contact_jacobian_matches_central_differences(
        c in xy(), v in xy(), minor in 0.2..3.0f64, theta in -7.0..7.0f64,
        o in xy(), s in xy(), r in 0.1..4.0f64, external in any::<bool>(),
    ) {
        let d = |p: &[f64], q: &[f64]| (p[0] - q[0]).hypot(p[1] - q[1]);
        prop_assume!(d(&v, &c) > 0.2 && d(&o, &s) > 0.1);
        let tangency = if external { Tangency::External } else { Tangency::Internal };
        let (m, t, r) = ([minor], [theta], [r]);
        for arc in [false, true] {
            let x: [&[f64]; 6] = [&c, &v, &m, &t, &o, if arc { &s } else { &r }];
            let check = check_jacobian(&EllipseCircleContact::new(tangency, arc), &x, 1e-6, 1.0).unwrap();
            prop_assert!(check.error < 1e-6, "{arc}: {}", check.error);
        }
    }
}

/// Touching from inside at one foot while crossing elsewhere is refused: a circle of radius 1.5
/// touching the top (0, 1) of x²/4 + y² = 1 from inside (below its radius of curvature 4 there)
/// pokes out through the bottom, 1 deep at θ = 3π/2; a circle of radius 1.5 around the vertex
/// (2, 0) (above its radius of curvature ½) leaves the far vertex (−2, 0) outside, 1 deep at
/// θ = π. Every row holds at the start; the check after the solve refuses both and the sketch
/// is left as it was. A circle of radius ½ under the top touches without crossing.
#[test]
fn an_internal_contact_that_crosses_elsewhere_is_refused() {
    for (centre, r, theta, crossing) in [
        ((0.0, -0.5), 1.5, FRAC_PI_2, 1.5 * PI),
        ((0.5, 0.0), 1.5, 0.0, PI),
        ((0.0, 0.5), 0.5, FRAC_PI_2, f64::NAN),
    ] {
        let mut s = Sketch::new();
        let e = s
            .add_ellipse(&Ellipse::try_new(Point2::origin(), 2.0, 1.0, 0.0).unwrap())
            .unwrap();
        s.add_constraint(Fixed::entity(e)).unwrap();
        let c = circle(&mut s, centre, r);
        s.add_constraint(Fixed::entity(c)).unwrap();
        let k = s
            .add_constraint(touch(e, c, Tangency::Internal, theta))
            .unwrap();
        let before = to_json(&s).unwrap();
        let result = s.solve();
        if crossing.is_nan() {
            result.unwrap();
            continue;
        }
        let err = result.unwrap_err();
        assert!(
            matches!(err, Error::ContactCrossed { constraint, parameter, depth }
                if constraint == k
                    && (parameter - crossing).abs() < 0.02
                    && (depth - 1.0).abs() < 1e-3),
            "{err}"
        );
        assert_eq!(to_json(&s).unwrap(), before);
    }
}
