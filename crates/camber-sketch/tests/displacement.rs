//! Contact by iterative displacement (the blade-design method): an arc that misses a circle and
//! one that crosses it end touching it at the top (symmetry gives the contact point by hand),
//! an off-centre contact ends on the circle with its tangent perpendicular to the radius, the
//! diffuser from perturbed starts ends valid (SLSQP taking over where the rounds fail), and bad
//! input is refused with nothing changed.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_abs_diff_eq;
use camber_geom::BezierCurve2;
use camber_sketch::constraints::{Fixed, TangentToCircle};
use camber_sketch::displacement::DisplacementOptions;
use camber_sketch::{CircleSide, Constraint, Contact, EntityId, Error, PointRef, Rotation, Sketch};
use camber_workloads::{w2_bspline7, w2_perturbed, w2_valid};
use nalgebra::Point2;

/// A symmetric cubic arc over the unit circle with its top at height `top` (ends fixed), and
/// the contact "touch the circle from outside, clockwise" at a free parameter.
fn arc_over_circle(top: f64, fix_circle: bool) -> (Sketch, EntityId, EntityId) {
    let mut s = Sketch::new();
    // The Bézier's top is (P₀ + 3P₁ + 3P₂ + P₃)/8 at u = ½: inner points at (8·top − 2·1.3)/6.
    let inner = (8.0 * top - 2.0 * 1.3) / 6.0;
    let arc = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(-2.0, 1.3),
                Point2::new(-0.7, inner),
                Point2::new(0.7, inner),
                Point2::new(2.0, 1.3),
            ])
            .unwrap(),
        )
        .unwrap();
    let circle = s.add_circle(Point2::new(0.0, 0.0), 1.0).unwrap();
    if fix_circle {
        s.add_constraint(Fixed::entity(circle)).unwrap();
    }
    for end in [PointRef::Start(arc), PointRef::End(arc)] {
        s.add_constraint(Fixed::point(end)).unwrap();
    }
    s.add_constraint(TangentToCircle {
        curve: arc,
        circle,
        u: Contact::Free(0.4),
        side: CircleSide::Outside,
        rotation: Rotation::Clockwise,
    })
    .unwrap();
    (s, arc, circle)
}

fn contact_parameter(s: &Sketch) -> f64 {
    s.constraints()
        .find_map(|(_, c)| match c {
            Constraint::TangentToCircle(TangentToCircle {
                u: Contact::Free(u),
                ..
            }) => Some(*u),
            _ => None,
        })
        .unwrap()
}

#[test]
fn a_missing_and_a_crossing_arc_end_touching_at_the_top() {
    for top in [1.5, 0.8] {
        let (mut s, arc, _) = arc_over_circle(top, true);
        let r = s
            .solve_by_displacement(&DisplacementOptions::default())
            .unwrap();
        assert!(r.converged, "top {top}: {r:?}");
        assert!(r.rounds >= 1 && *r.history.last().unwrap() <= 1e-6);
        // By symmetry the arc touches the circle at its top, (0, 1), at u = ½.
        assert_abs_diff_eq!(contact_parameter(&s), 0.5, epsilon = 1e-6);
        assert_abs_diff_eq!(
            s.curve_point(arc, 0.5).unwrap(),
            Point2::new(0.0, 1.0),
            epsilon = 1e-8
        );
        // The validating solve had nothing left to move the contact by.
        let report = &r.report.components[0].report;
        assert!(report.residuals.iter().all(|c| c.max_abs <= 1e-9));
    }
}

#[test]
fn an_off_centre_contact_ends_on_the_circle_and_tangent() {
    let (mut s, arc, circle) = arc_over_circle(1.5, true);
    // Shift the circle right: the contact point is no longer given by symmetry, and each
    // round's guess of it is only approximate.
    let mut s2 = Sketch::new();
    for (id, e) in s.entities() {
        let e = match e {
            camber_sketch::Entity::Circle { radius, .. } => camber_sketch::Entity::Circle {
                center: Point2::new(0.4, 0.0),
                radius: *radius,
            },
            other => other.clone(),
        };
        s2.add_entity_with_id(id, e).unwrap();
    }
    for (id, c) in s.constraints() {
        s2.add_constraint_with_id(id, c.clone()).unwrap();
    }
    s = s2;
    let r = s
        .solve_by_displacement(&DisplacementOptions::default())
        .unwrap();
    assert!(r.converged && r.rounds >= 1, "{r:?}");
    assert_eq!(r.history.len(), r.rounds + 1);
    // Independent check: at the stored parameter the curve is on the circle and its tangent
    // is perpendicular to the radius.
    let u = contact_parameter(&s);
    let p = s.curve_point(arc, u).unwrap();
    let h = 1e-6;
    let t = (s.curve_point(arc, u + h).unwrap() - s.curve_point(arc, u - h).unwrap()) / (2.0 * h);
    let camber_sketch::Entity::Circle { center, radius } = s.entity(circle).unwrap() else {
        panic!("circle");
    };
    assert_abs_diff_eq!((p - center).norm(), *radius, epsilon = 1e-8);
    assert_abs_diff_eq!((p - center).dot(&t) / t.norm(), 0.0, epsilon = 1e-6);
}

#[test]
fn the_diffuser_ends_valid_from_perturbed_starts() {
    let (mut base, w) = w2_bspline7().unwrap();
    base.solve().unwrap();
    let mut by_rounds = 0;
    for start in w2_perturbed(&base, &w, 0.01, 10, 7).unwrap() {
        let mut s = start.clone();
        let r = s
            .solve_by_displacement(&DisplacementOptions::default())
            .unwrap();
        assert!(w2_valid(&s, &w), "{r:?}");
        by_rounds += usize::from(r.converged);
        if !r.converged {
            // Handed over: the sketch's own solve solved it from its own start (valid above).
            assert_eq!(r.history.len(), r.rounds + 1);
        }
    }
    // Measured: the rounds alone converge on 6 of these 10 starts; on the others a round
    // reverses the thickness contact's tangent and the usual solve takes over (still valid).
    assert!(
        by_rounds >= 4,
        "{by_rounds} of 10 converged by displacement"
    );
}

#[test]
fn moving_targets_and_bad_options_are_refused_and_nothing_changes() {
    let (mut s, _, circle) = arc_over_circle(1.5, false);
    let before: Vec<_> = s.entities().map(|(id, e)| (id, e.clone())).collect();
    match s.solve_by_displacement(&DisplacementOptions::default()) {
        Err(Error::TargetNotFixed { entity, .. }) => assert_eq!(entity, circle),
        other => panic!("expected TargetNotFixed, got {other:?}"),
    }
    let (mut s2, _, _) = arc_over_circle(1.5, true);
    for bad in [
        DisplacementOptions {
            max_rounds: 0,
            ..DisplacementOptions::default()
        },
        DisplacementOptions {
            tolerance: f64::NAN,
            ..DisplacementOptions::default()
        },
    ] {
        assert!(matches!(
            s2.solve_by_displacement(&bad),
            Err(Error::InvalidOption { .. })
        ));
    }
    let after: Vec<_> = s.entities().map(|(id, e)| (id, e.clone())).collect();
    assert_eq!(before, after);
}
