//! Dimensions of arcs: `arc_angle` (the sweep of a circular arc, the parametric sweep of an
//! elliptic one) and `arc_length` on circular and elliptic arcs, solved against closed forms
//! (end points at the dimensioned angle, r·φ, the quarter perimeter of an ellipse from the
//! complete elliptic integral) and against camber-geom's own arc length (a second method),
//! with their refusals, DOF, file forms, `set_value` and autodiff Jacobians against central
//! differences.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use approx::assert_relative_eq;
use camber_geom::budget::Budget;
use camber_geom::{CircularArc, EllipticArc};
use camber_sketch::constraints::arc_angle::SweepValue;
use camber_sketch::constraints::arc_length::ArcLengthOfArc;
use camber_sketch::constraints::semi_axis::Axis;
use camber_sketch::constraints::{ArcAngle, ArcLength, Fixed, SemiAxis};
use camber_sketch::file::{from_json, to_json};
use camber_sketch::{Constraint, Entity, EntityId, Error, PointRef, Sketch};
use camber_solve::testing::check_jacobian;
use nalgebra::Point2;
use proptest::prelude::*;

fn arc(s: &mut Sketch, r: f64, a0: f64, a1: f64) -> EntityId {
    s.add_arc(&CircularArc::try_new(Point2::new(0.0, 0.0), r, a0, a1).unwrap())
        .unwrap()
}

fn elliptic_arc(s: &mut Sketch, a: f64, b: f64, rot: f64, a0: f64, a1: f64) -> EntityId {
    s.add_elliptic_arc(&EllipticArc::try_new(Point2::new(0.0, 0.0), a, b, rot, a0, a1).unwrap())
        .unwrap()
}

fn dof(s: &Sketch) -> usize {
    s.analyze().unwrap().iter().map(|a| a.analysis.dof).sum()
}

/// Fixes the centre and the start of an arc (circular or elliptic), and for an elliptic one
/// its vertex and b: only the end is left to move.
fn pin_all_but_the_end(s: &mut Sketch, a: EntityId, elliptic: bool) {
    s.add_constraint(Fixed::point(PointRef::Control(a, 0)))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(a))).unwrap();
    if elliptic {
        s.add_constraint(Fixed::point(PointRef::Control(a, 1)))
            .unwrap();
        let b = s.entity(a).unwrap().as_elliptic_arc().unwrap();
        s.add_constraint(SemiAxis {
            ellipse: a,
            axis: Axis::B,
            length: b.ellipse().semi_axis_b(),
        })
        .unwrap();
    }
}

/// Solves and checks every reported residual is below 1e-10.
fn solve_tight(s: &mut Sketch) {
    let report = s.solve().unwrap();
    for c in &report.components {
        for r in &c.report.residuals {
            assert!(r.max_abs < 1e-10, "{} left at {}", r.constraint, r.max_abs);
        }
    }
}

#[test]
fn arc_angle_turns_a_circular_arcs_end_to_the_dimensioned_sweep() {
    let mut s = Sketch::new();
    let a = arc(&mut s, 2.0, 0.3, 1.3);
    pin_all_but_the_end(&mut s, a, false);
    s.add_constraint(ArcAngle { arc: a, angle: 2.5 }).unwrap();
    solve_tight(&mut s);
    let end = s.point(PointRef::End(a)).unwrap();
    let expected = Point2::new(2.0 * 2.8_f64.cos(), 2.0 * 2.8_f64.sin());
    assert!((end - expected).norm() < 1e-10, "{end:?}");
    let solved = s.entity(a).unwrap().as_arc().unwrap();
    assert_relative_eq!(solved.sweep(), 2.5, epsilon = 1e-10);
}

#[test]
fn arc_angle_reaches_sweeps_beyond_a_half_turn() {
    // From 1 rad to 1.5π: the row's fold into (0, 2π) has no cut at π.
    let mut s = Sketch::new();
    let a = arc(&mut s, 1.0, 0.0, 2.0);
    pin_all_but_the_end(&mut s, a, false);
    s.add_constraint(ArcAngle {
        arc: a,
        angle: 1.5 * PI,
    })
    .unwrap();
    solve_tight(&mut s);
    let end = s.point(PointRef::End(a)).unwrap();
    assert!((end - Point2::new(0.0, -1.0)).norm() < 1e-10, "{end:?}");
}

#[test]
fn arc_angle_on_an_elliptic_arc_sets_its_parametric_sweep() {
    let (a_len, b_len, rot) = (2.0, 1.0, 0.3);
    let mut s = Sketch::new();
    let a = elliptic_arc(&mut s, a_len, b_len, rot, 0.2, 1.0);
    pin_all_but_the_end(&mut s, a, true);
    s.add_constraint(ArcAngle { arc: a, angle: 2.5 }).unwrap();
    solve_tight(&mut s);
    // The end at parametric angle 0.2 + 2.5 on the unchanged ellipse.
    let theta: f64 = 2.7;
    let (u, v) = (
        nalgebra::Vector2::new(rot.cos(), rot.sin()),
        nalgebra::Vector2::new(-rot.sin(), rot.cos()),
    );
    let expected = Point2::origin() + u * (a_len * theta.cos()) + v * (b_len * theta.sin());
    let end = s.point(PointRef::End(a)).unwrap();
    assert!((end - expected).norm() < 1e-10, "{end:?} {expected:?}");
}

#[test]
fn set_value_on_an_arc_angle_re_solves_to_the_new_sweep() {
    let mut s = Sketch::new();
    let a = arc(&mut s, 1.5, 0.0, 1.0);
    pin_all_but_the_end(&mut s, a, false);
    let c = s.add_constraint(ArcAngle { arc: a, angle: 1.2 }).unwrap();
    solve_tight(&mut s);
    s.set_value(c, 0.4).unwrap();
    assert_eq!(s.constraint(c).unwrap().value(), Some(0.4));
    solve_tight(&mut s);
    let solved = s.entity(a).unwrap().as_arc().unwrap();
    assert_relative_eq!(solved.sweep(), 0.4, epsilon = 1e-10);
}

#[test]
fn arc_length_of_a_circular_arc_is_radius_times_sweep() {
    let mut s = Sketch::new();
    let a = arc(&mut s, 2.0, 0.0, 1.0);
    pin_all_but_the_end(&mut s, a, false);
    s.add_constraint(ArcLength {
        curve: a,
        length: 3.0,
    })
    .unwrap();
    solve_tight(&mut s);
    let solved = s.entity(a).unwrap().as_arc().unwrap();
    assert_relative_eq!(solved.sweep(), 1.5, epsilon = 1e-10);
    assert_relative_eq!(solved.length(), 3.0, epsilon = 1e-10);
}

#[test]
fn arc_length_and_arc_angle_together_fix_the_radius() {
    // Centre fixed, sweep 1 rad, length 3: the radius must become 3.
    let mut s = Sketch::new();
    let a = arc(&mut s, 2.0, 0.2, 1.0);
    s.add_constraint(Fixed::point(PointRef::Control(a, 0)))
        .unwrap();
    s.add_constraint(ArcAngle { arc: a, angle: 1.0 }).unwrap();
    s.add_constraint(ArcLength {
        curve: a,
        length: 3.0,
    })
    .unwrap();
    solve_tight(&mut s);
    let solved = s.entity(a).unwrap().as_arc().unwrap();
    assert_relative_eq!(solved.radius(), 3.0, epsilon = 1e-10);
    assert_relative_eq!(solved.sweep(), 1.0, epsilon = 1e-10);
}

#[test]
fn a_quarter_ellipse_is_as_long_as_the_complete_elliptic_integral_says() {
    // a = 2, b = 1: the perimeter is 4·a·E(m) with m = 1 − b²/a² = 0.75, E(0.75) =
    // 1.2110560275684595 (tables of the complete elliptic integral of the second kind).
    let quarter = 2.0 * 1.211_056_027_568_459_5;
    let blocks: [&[f64]; 5] = [&[0.0, 0.0], &[2.0, 0.0], &[1.0], &[2.0, 0.0], &[0.0, 1.0]];
    let row = ArcLengthOfArc::elliptic(&blocks, quarter);
    assert_relative_eq!(row.length_of(&blocks), quarter, epsilon = 1e-13);
    assert!(row.nodes() >= 8);
}

#[test]
fn solving_an_elliptic_arcs_length_agrees_with_the_kernels_arc_length() {
    let mut s = Sketch::new();
    let a = elliptic_arc(&mut s, 3.0, 1.2, -0.4, 0.5, 1.5);
    pin_all_but_the_end(&mut s, a, true);
    s.add_constraint(ArcLength {
        curve: a,
        length: 4.0,
    })
    .unwrap();
    solve_tight(&mut s);
    let solved = s.entity(a).unwrap().as_elliptic_arc().unwrap();
    let length = solved.length_with(1e-12, &Budget::default()).unwrap();
    assert_relative_eq!(length.length, 4.0, epsilon = 1e-9);
}

#[test]
fn an_arc_angle_removes_one_degree_of_freedom() {
    let mut s = Sketch::new();
    let a = arc(&mut s, 1.0, 0.0, 1.0);
    let e = elliptic_arc(&mut s, 2.0, 1.0, 0.0, 0.0, 1.0);
    assert_eq!(dof(&s), 5 + 7);
    s.add_constraint(ArcAngle { arc: a, angle: 1.0 }).unwrap();
    s.add_constraint(ArcAngle { arc: e, angle: 1.0 }).unwrap();
    assert_eq!(dof(&s), 4 + 6);
    s.add_constraint(ArcLength {
        curve: a,
        length: 2.0,
    })
    .unwrap();
    assert_eq!(dof(&s), 3 + 6);
}

#[test]
fn arc_angles_outside_an_open_turn_are_refused_and_nothing_changes() {
    for angle in [0.0, -1.0, TAU, 7.0, f64::NAN, f64::INFINITY] {
        let mut s = Sketch::new();
        let a = arc(&mut s, 1.0, 0.0, 1.0);
        let before = to_json(&s).unwrap();
        match s.add_constraint(ArcAngle { arc: a, angle }) {
            Err(Error::OutOfRange { value, .. }) => assert_eq!(value.to_bits(), angle.to_bits()),
            other => panic!("{angle}: {other:?}"),
        }
        assert_eq!(to_json(&s).unwrap(), before);
    }
}

#[test]
fn arc_dimensions_on_entities_without_a_sweep_are_refused_by_kind() {
    let mut s = Sketch::new();
    let circle = s
        .add_entity(Entity::Circle {
            center: Point2::new(0.0, 0.0),
            radius: 1.0,
        })
        .unwrap();
    let line = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(1.0, 0.0))
        .unwrap();
    for id in [circle, line] {
        match s.add_constraint(ArcAngle {
            arc: id,
            angle: 1.0,
        }) {
            Err(Error::WrongEntityKind { entity, .. }) => assert_eq!(entity, id),
            other => panic!("{other:?}"),
        }
    }
    assert!(matches!(
        s.add_constraint(ArcLength {
            curve: circle,
            length: 1.0
        }),
        Err(Error::WrongEntityKind { .. })
    ));
    let a = arc(&mut s, 1.0, 0.0, 1.0);
    assert!(matches!(
        s.add_constraint(ArcLength {
            curve: a,
            length: -1.0
        }),
        Err(Error::NotPositive { .. })
    ));
}

#[test]
fn arc_angle_survives_a_file_round_trip() {
    let mut s = Sketch::new();
    let a = arc(&mut s, 1.0, 0.0, 1.0);
    let c = s.add_constraint(ArcAngle { arc: a, angle: 0.7 }).unwrap();
    let text = to_json(&s).unwrap();
    assert!(text.contains("\"arc_angle\""), "{text}");
    let back = from_json(&text).unwrap();
    assert_eq!(
        back.constraint(c).unwrap(),
        &Constraint::from(ArcAngle { arc: a, angle: 0.7 })
    );
}

fn xy() -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-3.0..3.0f64, 2)
}

fn away(p: &[f64], c: &[f64]) -> bool {
    (p[0] - c[0]).hypot(p[1] - c[1]) > 0.2
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn circular_sweep_and_length_jacobians_match_central_differences(
        c in xy(), p in xy(), q in xy(),
    ) {
        prop_assume!(away(&p, &c) && away(&q, &c));
        let refs: [&[f64]; 3] = [&c, &p, &q];
        // Away from a whole turn, where the sweep folds back to 0.
        let sweep = SweepValue::circular(0.0);
        let mut g = [0.0];
        camber_solve::Residual::eval(&sweep, &refs, &mut g);
        prop_assume!(g[0] > 0.05 && g[0] < TAU - 0.05);
        prop_assert!(check_jacobian(&sweep, &refs, 1e-6, 1.0).unwrap().error < 1e-6);
        let length = ArcLengthOfArc::circular(1.0);
        prop_assert!(check_jacobian(&length, &refs, 1e-6, 1.0).unwrap().error < 1e-6);
    }

    #[test]
    fn elliptic_sweep_and_length_jacobians_match_central_differences(
        c in xy(), v in xy(), p in xy(), q in xy(), minor in 0.3..2.0f64,
    ) {
        prop_assume!(away(&v, &c) && away(&p, &c) && away(&q, &c));
        let b = [minor];
        let refs: [&[f64]; 5] = [&c, &v, &b, &p, &q];
        let sweep = SweepValue::elliptic(0.0);
        let mut g = [0.0];
        camber_solve::Residual::eval(&sweep, &refs, &mut g);
        prop_assume!(g[0] > 0.05 && g[0] < TAU - 0.05);
        prop_assert!(check_jacobian(&sweep, &refs, 1e-6, 1.0).unwrap().error < 1e-6);
        let length = ArcLengthOfArc::elliptic(&refs, 1.0);
        prop_assert!(check_jacobian(&length, &refs, 1e-6, 1.0).unwrap().error < 1e-5);
    }

    #[test]
    fn the_elliptic_length_row_agrees_with_the_kernel_on_arcs_of_the_ellipse(
        a_len in 0.5..4.0f64, ratio in 0.1..1.0f64, rot in -PI..PI, a0 in -PI..PI,
        sweep in 0.1..(TAU - 0.1),
    ) {
        let b_len = a_len * ratio;
        let arc = EllipticArc::try_new(Point2::new(0.3, -0.2), a_len, b_len, rot, a0, a0 + sweep).unwrap();
        let e = arc.ellipse();
        let (u, _) = e.axes();
        let vertex = e.center() + u * a_len;
        let (p, q) = (arc.start_point(), arc.end_point());
        let blocks: [&[f64]; 5] = [
            e.center().coords.as_slice(), vertex.coords.as_slice(), &[b_len],
            p.coords.as_slice(), q.coords.as_slice(),
        ];
        let row = ArcLengthOfArc::elliptic(&blocks, 1.0);
        let kernel = arc.length_with(1e-12, &Budget::default()).unwrap().length;
        prop_assert!((row.length_of(&blocks) - kernel).abs() < 1e-9 * kernel.max(1.0));
        let mut g = [0.0];
        camber_solve::Residual::eval(&SweepValue::elliptic(sweep), &blocks, &mut g);
        prop_assert!(g[0].abs() < 1e-9, "sweep off by {}", g[0]);
    }
}

#[test]
fn a_half_turn_sweep_reads_as_pi_from_either_side() {
    let row = SweepValue::circular(PI);
    let mut g = [f64::NAN];
    camber_solve::Residual::eval(&row, &[&[0.0, 0.0], &[1.0, 0.0], &[-1.0, 0.0]], &mut g);
    assert!(g[0].abs() < 1e-15);
    camber_solve::Residual::eval(&row, &[&[0.0, 0.0], &[1.0, 0.0], &[-1.0, 1e-9]], &mut g);
    assert!((g[0] + 1e-9).abs() < 1e-12);
    camber_solve::Residual::eval(&row, &[&[0.0, 0.0], &[1.0, 0.0], &[-1.0, -1e-9]], &mut g);
    assert!((g[0] - 1e-9).abs() < 1e-12);
    let quarter = SweepValue::circular(FRAC_PI_2);
    camber_solve::Residual::eval(&quarter, &[&[0.0, 0.0], &[0.0, 1.0], &[-1.0, 0.0]], &mut g);
    assert!(g[0].abs() < 1e-15);
}
