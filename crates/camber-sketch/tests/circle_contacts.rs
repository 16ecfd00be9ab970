//! `circle_touches_circle`: two circles, or a circle and an arc in either order, touching from
//! outside or inside, solved against the closed forms (centre distance r₁ + r₂ and |r₁ − r₂|,
//! the free radius r₂ = d − r₁ or d + r₁), a contact off an arc refused naming the arc with
//! nothing changed, DOF, bad inputs, the file form, and the row's autodiff Jacobian against
//! central differences in all four layouts.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use std::f64::consts::PI;

use approx::assert_relative_eq;
use camber_geom::{CircularArc, Ellipse};
use camber_sketch::constraints::arc_touches_circle::RoundContact;
use camber_sketch::constraints::{CircleTouchesCircle, Fixed, Radius};
use camber_sketch::file::{from_json, to_json};
use camber_sketch::{Constraint, Entity, EntityId, Error, PointRef, Sketch, Tangency};
use camber_solve::testing::check_jacobian;
use nalgebra::Point2;
use proptest::prelude::*;

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

fn arc(s: &mut Sketch, c: (f64, f64), r: f64, a0: f64, a1: f64) -> EntityId {
    s.add_arc(&CircularArc::try_new(Point2::new(c.0, c.1), r, a0, a1).unwrap())
        .unwrap()
}

/// The centre and radius of a circle or an arc.
fn round(s: &Sketch, id: EntityId) -> (Point2<f64>, f64) {
    match s.entity(id).unwrap() {
        Entity::Circle { center, radius } => (*center, *radius),
        Entity::Arc(b) => (b[0], (b[1] - b[0]).norm()),
        other => panic!("{other:?}"),
    }
}

fn touch(first: EntityId, second: EntityId, tangency: Tangency) -> CircleTouchesCircle {
    CircleTouchesCircle {
        first,
        second,
        tangency,
    }
}

/// A fixed circle of radius 2 about the origin and a free circle of radius 0.5 starting
/// near it: the free one's centre ends 2.5 (outside) or 1.5 (inside) from the origin, in
/// either order of the pair.
#[test]
fn two_circles_touch_at_the_sum_or_the_difference_of_their_radii() {
    for (tangency, start, expected) in [
        (Tangency::External, (2.9, 0.7), 2.5),
        (Tangency::Internal, (1.2, 0.4), 1.5),
    ] {
        for swapped in [false, true] {
            let mut s = Sketch::new();
            let big = circle(&mut s, (0.0, 0.0), 2.0);
            s.add_constraint(Fixed::entity(big)).unwrap();
            let small = circle(&mut s, start, 0.5);
            s.add_constraint(Radius {
                circle: small,
                radius: 0.5,
            })
            .unwrap();
            let (first, second) = if swapped { (small, big) } else { (big, small) };
            s.add_constraint(touch(first, second, tangency)).unwrap();
            s.solve().unwrap();
            let (c, r) = round(&s, small);
            assert_relative_eq!(r, 0.5, epsilon = 1e-12);
            assert_relative_eq!(c.coords.norm(), expected, epsilon = 1e-10);
        }
    }
}

/// Centres held 3 apart and r₁ = 1: the free radius solves to 3 − 1 = 2 from outside and
/// 3 + 1 = 4 from inside (the second around the first).
#[test]
fn a_free_radius_solves_to_the_centre_distance_less_or_plus_the_other() {
    for (tangency, start, expected) in [
        (Tangency::External, 1.7, 2.0),
        (Tangency::Internal, 3.6, 4.0),
    ] {
        let mut s = Sketch::new();
        let a = circle(&mut s, (0.0, 0.0), 1.0);
        s.add_constraint(Fixed::entity(a)).unwrap();
        let b = circle(&mut s, (3.0, 0.0), start);
        s.add_constraint(Fixed::point(PointRef::Control(b, 0)))
            .unwrap();
        s.add_constraint(touch(b, a, tangency)).unwrap();
        s.solve().unwrap();
        assert_relative_eq!(round(&s, b).1, expected, epsilon = 1e-10);
    }
}

/// A circle with an arc, in either order: the arc's free centre moves to the closed-form
/// distance, and its contact (on the line of centres) lies within its sweep.
#[test]
fn a_circle_and_an_arc_touch_in_either_order() {
    for (tangency, expected) in [(Tangency::External, 3.0), (Tangency::Internal, 1.0)] {
        for arc_first in [false, true] {
            let mut s = Sketch::new();
            let c = circle(&mut s, (0.0, 0.0), 2.0);
            s.add_constraint(Fixed::entity(c)).unwrap();
            // An arc of radius 1 about (2.6, 0.2) facing the origin (external) or away from
            // it (internal: its contact is on the far side from the origin).
            let (a0, a1) = if tangency == Tangency::External {
                (PI - 0.8, PI + 0.8)
            } else {
                (-0.8, 0.8)
            };
            let start = if tangency == Tangency::External {
                (2.6, 0.2)
            } else {
                (1.3, 0.2)
            };
            let a = arc(&mut s, start, 1.0, a0, a1);
            s.add_constraint(Radius {
                circle: a,
                radius: 1.0,
            })
            .unwrap();
            let pair = if arc_first { (a, c) } else { (c, a) };
            s.add_constraint(touch(pair.0, pair.1, tangency)).unwrap();
            s.solve().unwrap();
            let (centre, r) = round(&s, a);
            assert_relative_eq!(r, 1.0, epsilon = 1e-10);
            assert_relative_eq!(centre.coords.norm(), expected, epsilon = 1e-10);
        }
    }
}

/// The contact on the line of centres falls outside an arc facing away: the solve fails
/// naming the constraint and that arc, and the sketch is left as it was.
#[test]
fn a_contact_off_the_arc_is_refused_and_nothing_changes() {
    for arc_first in [false, true] {
        let mut s = Sketch::new();
        let c = circle(&mut s, (0.0, 0.0), 1.0);
        s.add_constraint(Fixed::entity(c)).unwrap();
        let a = arc(&mut s, (3.0, 0.0), 1.8, -0.5, 0.5);
        s.add_constraint(Fixed::point(PointRef::Control(a, 0)))
            .unwrap();
        let pair = if arc_first { (a, c) } else { (c, a) };
        let k = s
            .add_constraint(touch(pair.0, pair.1, Tangency::External))
            .unwrap();
        let before = to_json(&s).unwrap();
        let err = s.solve().unwrap_err();
        assert!(
            matches!(err, Error::ContactOffArc { constraint, arc, outside }
                if constraint == k && arc == a && outside > 1.0),
            "{err}"
        );
        assert_eq!(to_json(&s).unwrap(), before);
    }
}

/// A circle has 3 DOF, an arc 5; each contact removes one.
#[test]
fn each_contact_removes_one_dof() {
    let mut s = Sketch::new();
    let a = circle(&mut s, (0.0, 0.0), 1.0);
    let b = circle(&mut s, (2.5, 0.0), 1.0);
    let c = arc(&mut s, (0.0, 3.0), 1.0, -2.0, -1.0);
    assert_eq!(dof(&s), 3 + 3 + 5);
    s.add_constraint(touch(a, b, Tangency::External)).unwrap();
    assert_eq!(dof(&s), 10);
    s.add_constraint(touch(c, a, Tangency::External)).unwrap();
    assert_eq!(dof(&s), 9);
    s.add_constraint(touch(b, c, Tangency::External)).unwrap();
    assert_eq!(dof(&s), 8);
}

/// Entities that are not round, an entity named twice, an unknown id: typed errors naming the
/// entity, nothing added; in a file, the error names the constraint.
#[test]
fn bad_contacts_are_refused_with_typed_errors() {
    let mut s = Sketch::new();
    let a = circle(&mut s, (0.0, 0.0), 1.0);
    let l = s
        .add_line(Point2::new(-2.0, -2.0), Point2::new(2.0, -2.0))
        .unwrap();
    let e = s
        .add_ellipse(&Ellipse::try_new(Point2::new(3.0, 0.0), 2.0, 1.0, 0.0).unwrap())
        .unwrap();
    let wrong = |entity, found: &'static str| Error::WrongEntityKind {
        entity,
        expected: "circle or arc",
        found,
    };
    let cases: Vec<(Constraint, Error)> = vec![
        (touch(a, l, Tangency::External).into(), wrong(l, "line")),
        (touch(l, a, Tangency::External).into(), wrong(l, "line")),
        (touch(e, a, Tangency::Internal).into(), wrong(e, "ellipse")),
        (
            touch(a, a, Tangency::External).into(),
            Error::SameEntity { entity: a },
        ),
        (
            touch(a, EntityId(99), Tangency::External).into(),
            Error::UnknownEntity {
                entity: EntityId(99),
            },
        ),
    ];
    let before = to_json(&s).unwrap();
    for (c, expected) in cases {
        assert_eq!(s.add_constraint(c.clone()).unwrap_err(), expected, "{c:?}");
    }
    assert_eq!(to_json(&s).unwrap(), before);

    let text = r#"{"version":1,"entities":[
 {"id":0,"kind":"circle","center":[0,0],"radius":1},
 {"id":1,"kind":"line","from":[0,-2],"to":[1,-2]}],
"constraints":[{"id":2,"kind":"circle_touches_circle","first":0,"second":1,"tangency":"external"}]}"#;
    assert_eq!(
        from_json(text).unwrap_err().to_string(),
        "constraint 2 (circle_touches_circle): entity 1 is a line, expected circle or arc"
    );
    let text = r#"{"version":1,"entities":[
 {"id":0,"kind":"circle","center":[0,0],"radius":1},
 {"id":1,"kind":"circle","center":[3,0],"radius":1}],
"constraints":[{"id":2,"kind":"circle_touches_circle","first":0,"second":1,"tangency":"sideways"}]}"#;
    assert!(from_json(text).is_err());
}

/// The kind round-trips through the file format and solves the same after.
#[test]
fn the_contact_round_trips_through_files() {
    let text = r#"{"version":1,"entities":[
 {"id":0,"kind":"circle","center":[0,0],"radius":2},
 {"id":1,"kind":"arc","center":[1.5,1.2],"radius":0.7,"start_angle":2,"end_angle":5},
 {"id":2,"kind":"circle","center":[4,0],"radius":1}],
"constraints":[
 {"id":3,"kind":"circle_touches_circle","first":0,"second":2,"tangency":"external"},
 {"id":4,"kind":"circle_touches_circle","first":1,"second":0,"tangency":"internal"}]}"#;
    let s = from_json(text).unwrap();
    let saved = to_json(&s).unwrap();
    for form in [
        r#""kind":"circle_touches_circle","first":0,"second":2,"tangency":"external""#,
        r#""kind":"circle_touches_circle","first":1,"second":0,"tangency":"internal""#,
    ] {
        assert!(saved.contains(form), "{form} in {saved}");
    }
    let back = from_json(&saved).unwrap();
    let kinds = |s: &Sketch| {
        s.constraints()
            .map(|(id, c)| (id, c.clone()))
            .collect::<Vec<_>>()
    };
    assert_eq!(kinds(&s), kinds(&back));
    assert_eq!(to_json(&back).unwrap(), saved);
}

fn xy() -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-5.0..5.0f64, 2)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Every layout ([C, r] or [C, S] for each of the two) against central differences.
    #[test]
    fn the_contact_jacobian_matches_central_differences(
        c1 in xy(), s1 in xy(), c2 in xy(), s2 in xy(),
        r1 in 0.2..4.0f64, r2 in 0.2..4.0f64, external in any::<bool>(),
    ) {
        let d = |p: &[f64], q: &[f64]| (p[0] - q[0]).hypot(p[1] - q[1]);
        prop_assume!(d(&c1, &s1) > 0.1 && d(&c2, &s2) > 0.1);
        let tangency = if external { Tangency::External } else { Tangency::Internal };
        let (r1, r2) = ([r1], [r2]);
        for first_arc in [false, true] {
            for second_arc in [false, true] {
                let x: [&[f64]; 4] = [
                    &c1,
                    if first_arc { &s1 } else { &r1 },
                    &c2,
                    if second_arc { &s2 } else { &r2 },
                ];
                let row = RoundContact::between(tangency, first_arc, second_arc);
                let check = check_jacobian(&row, &x, 1e-6, 1.0).unwrap();
                prop_assert!(check.error < 1e-6, "{first_arc} {second_arc}: {}", check.error);
            }
        }
    }
}
