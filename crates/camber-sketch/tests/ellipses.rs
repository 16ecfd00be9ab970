//! Ellipses and elliptic arcs in sketches: their DOF (5 and 7), their ends read by the classic
//! point kinds, the ellipse kinds (point on ellipse, semi-axis, tangency of an arc end with a
//! line) solved against closed forms, the checks that refuse a solve and leave the sketch as
//! it was, and every ellipse residual's autodiff Jacobian against central differences.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use camber_geom::{Ellipse, EllipticArc};
use camber_sketch::constraints::arc_tangent_to_line::ArcEnd;
use camber_sketch::constraints::elliptic_arc_tangent_to_line::EllipseLineTangency;
use camber_sketch::constraints::semi_axis::{Axis, SemiAxisA};
use camber_sketch::constraints::{
    Coincident, EllipticArcTangentToLine, Fixed, PointOnEllipse, PointOnLine, SemiAxis,
};
use camber_sketch::residuals::ellipse::OnEllipse;
use camber_sketch::{Entity, EntityId, Error, PointRef, Sense, Sketch};
use camber_solve::testing::check_jacobian;
use nalgebra::{Point2, Vector2};
use proptest::prelude::*;

fn elliptic_arc(s: &mut Sketch, a: f64, b: f64, rot: f64, a0: f64, a1: f64) -> EntityId {
    s.add_elliptic_arc(&EllipticArc::try_new(Point2::new(0.0, 0.0), a, b, rot, a0, a1).unwrap())
        .unwrap()
}

fn dof(s: &Sketch) -> usize {
    s.analyze().unwrap().iter().map(|a| a.analysis.dof).sum()
}

fn solved(s: &Sketch, a: EntityId) -> EllipticArc<f64> {
    s.entity(a).unwrap().as_elliptic_arc().unwrap()
}

/// Solves and checks every residual the solver reports is below 1e-10.
fn solve_tight(s: &mut Sketch) {
    let report = s.solve().unwrap();
    for c in &report.components {
        for r in &c.report.residuals {
            assert!(r.max_abs < 1e-10, "{} left at {}", r.constraint, r.max_abs);
        }
    }
}

/// Both ends of a solved arc satisfy the implicit equation of its ellipse.
fn ends_on_ellipse(arc: &EllipticArc<f64>) {
    let e = arc.ellipse();
    assert!(e.implicit_value(&arc.start_point()).abs() < 1e-10);
    assert!(e.implicit_value(&arc.end_point()).abs() < 1e-10);
}

/// The centre and the a-axis vertex of an entity held by `fixed` constraints.
fn fix_axis(s: &mut Sketch, a: EntityId) {
    s.add_constraint(Fixed::point(PointRef::Control(a, 0)))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(a, 1)))
        .unwrap();
}

#[test]
fn a_free_ellipse_has_five_dof_and_an_elliptic_arc_seven() {
    let mut s = Sketch::new();
    let e = s
        .add_ellipse(&Ellipse::try_new(Point2::new(5.0, 5.0), 2.0, 1.0, 0.4).unwrap())
        .unwrap();
    assert_eq!(dof(&s), 5);
    let a = elliptic_arc(&mut s, 2.0, 1.0, 0.3, 0.2, 2.5);
    assert_eq!(dof(&s), 12);
    fix_axis(&mut s, a);
    // The ellipse's 5, and the arc's b and two angles.
    assert_eq!(dof(&s), 8);
    let report = s.analyze().unwrap();
    let arc_report = report
        .iter()
        .find(|r| r.component.entities.contains(&a))
        .unwrap();
    assert_eq!(arc_report.freedom.len(), 1);
    assert_eq!(arc_report.freedom[0].points, vec![2, 3]);
    assert_eq!(arc_report.freedom[0].scalars, vec![0]);
    // A wholly fixed arc and ellipse are determined, with nothing redundant.
    s.add_constraint(Fixed::entity(a)).unwrap();
    s.add_constraint(Fixed::entity(e)).unwrap();
    let report = s.analyze().unwrap();
    assert_eq!(dof(&s), 0);
    assert!(report.iter().all(|r| r.analysis.redundant.is_empty()));
    s.solve().unwrap();
}

/// The arc's end pinned at (1, 1) on the ellipse of centre 0 and vertex (2, 0): b follows
/// from (1/2)² + (1/b)² = 1, b = 2/√3, and the start stays on the new ellipse.
#[test]
fn an_end_pinned_by_coincident_sets_the_other_semi_axis() {
    let mut s = Sketch::new();
    let a = elliptic_arc(&mut s, 2.0, 1.0, 0.0, -0.5, 0.9);
    fix_axis(&mut s, a);
    let p = s.add_point(Point2::new(1.0, 1.0)).unwrap();
    s.add_constraint(Fixed::entity(p)).unwrap();
    s.add_constraint(Coincident {
        a: PointRef::End(a),
        b: PointRef::Point(p),
    })
    .unwrap();
    solve_tight(&mut s);
    let arc = solved(&s, a);
    assert_relative_eq!(
        arc.ellipse().semi_axis_b(),
        2.0 / 3f64.sqrt(),
        epsilon = 1e-10
    );
    assert_relative_eq!(arc.end_point(), Point2::new(1.0, 1.0), epsilon = 1e-10);
    assert_relative_eq!(
        s.point(PointRef::End(a)).unwrap(),
        Point2::new(1.0, 1.0),
        epsilon = 1e-10
    );
    ends_on_ellipse(&arc);
}

/// The line y = c is tangent to the ellipse x²/a² + y²/b² = 1 at its top (0, b), so an arc
/// end held on the line y = 1.5 and tangent to it, with the a-axis fixed, gives b = 1.5 and
/// the end at (0, 1.5); the start angle is left free.
#[test]
fn the_tangent_point_of_a_horizontal_line_is_the_top_of_the_ellipse() {
    let mut s = Sketch::new();
    let a = elliptic_arc(&mut s, 2.0, 1.0, 0.0, 0.2, 1.3);
    fix_axis(&mut s, a);
    let l = s
        .add_line(Point2::new(-4.0, 1.5), Point2::new(4.0, 1.5))
        .unwrap();
    s.add_constraint(Fixed::entity(l)).unwrap();
    s.add_constraint(PointOnLine {
        point: PointRef::End(a),
        line: l,
    })
    .unwrap();
    // At the top the counter-clockwise travel runs to −x, against the line's direction.
    s.add_constraint(EllipticArcTangentToLine {
        arc: a,
        end: ArcEnd::End,
        line: l,
        sense: Sense::Oppose,
    })
    .unwrap();
    assert_eq!(dof(&s), 1);
    solve_tight(&mut s);
    let arc = solved(&s, a);
    assert_relative_eq!(arc.ellipse().semi_axis_b(), 1.5, epsilon = 1e-10);
    assert_relative_eq!(arc.end_point(), Point2::new(0.0, 1.5), epsilon = 1e-9);
    ends_on_ellipse(&arc);
}

/// A rotated ellipse (a = 3, b = 1, θ = 0.5) with fixed shape and a fixed slanted line at its
/// support distance h = √(a²n′ₓ² + b²n′ᵧ²) (n′ the line's unit normal in the ellipse's frame):
/// the end held on the line and tangent to it lands on the support point
/// (a²n′ₓ, b²n′ᵧ)/h of the frame.
#[test]
fn a_slanted_tangent_line_touches_at_the_support_point() {
    let (a_len, b_len, rot) = (3.0_f64, 1.0_f64, 0.5_f64);
    let ellipse = Ellipse::try_new(Point2::new(0.0, 0.0), a_len, b_len, rot).unwrap();
    let (u, v) = ellipse.axes();
    let d = Vector2::new(2.0_f64.cos(), 2.0_f64.sin());
    let n = Vector2::new(-d.y, d.x);
    let (nx, ny) = (n.dot(&u), n.dot(&v));
    let h = (a_len * a_len * nx * nx + b_len * b_len * ny * ny).sqrt();
    let touch = Point2::origin() + u * (a_len * a_len * nx / h) + v * (b_len * b_len * ny / h);
    let phi = ellipse.angle_of(&touch);
    // The travel there decides the sense the drawing has.
    let travel = ellipse.derivative_at_angle(phi, 1);
    let sense = if travel.dot(&d) > 0.0 {
        Sense::Agree
    } else {
        Sense::Oppose
    };
    let mut s = Sketch::new();
    let arc = s
        .add_elliptic_arc(&ellipse.arc(phi - 1.0, phi - 0.2).unwrap())
        .unwrap();
    fix_axis(&mut s, arc);
    s.add_constraint(SemiAxis {
        ellipse: arc,
        axis: Axis::B,
        length: b_len,
    })
    .unwrap();
    let foot = Point2::origin() + n * h;
    let l = s.add_line(foot - d * 5.0, foot + d * 5.0).unwrap();
    s.add_constraint(Fixed::entity(l)).unwrap();
    s.add_constraint(PointOnLine {
        point: PointRef::End(arc),
        line: l,
    })
    .unwrap();
    s.add_constraint(EllipticArcTangentToLine {
        arc,
        end: ArcEnd::End,
        line: l,
        sense,
    })
    .unwrap();
    solve_tight(&mut s);
    let solved_arc = solved(&s, arc);
    assert_relative_eq!(solved_arc.end_point(), touch, epsilon = 1e-9);
    ends_on_ellipse(&solved_arc);
    // The other sense cannot be kept there: the solve fails and changes nothing.
    let mut t = Sketch::new();
    let arc2 = t
        .add_elliptic_arc(&ellipse.arc(phi - 1.0, phi - 0.2).unwrap())
        .unwrap();
    fix_axis(&mut t, arc2);
    t.add_constraint(SemiAxis {
        ellipse: arc2,
        axis: Axis::B,
        length: b_len,
    })
    .unwrap();
    let l2 = t.add_line(foot - d * 5.0, foot + d * 5.0).unwrap();
    t.add_constraint(Fixed::entity(l2)).unwrap();
    t.add_constraint(PointOnLine {
        point: PointRef::End(arc2),
        line: l2,
    })
    .unwrap();
    let flipped = if sense == Sense::Agree {
        Sense::Oppose
    } else {
        Sense::Agree
    };
    t.add_constraint(EllipticArcTangentToLine {
        arc: arc2,
        end: ArcEnd::End,
        line: l2,
        sense: flipped,
    })
    .unwrap();
    let before = t.entity(arc2).unwrap().clone();
    assert!(t.solve().is_err());
    assert_eq!(t.entity(arc2).unwrap(), &before);
}

/// Both semi-axes set (3 and 1.5) with the centre fixed leave the rotation free; a fixed
/// point at distance 2 on the ellipse then sets it: the point's direction makes an angle α
/// with the a-axis with 4cos²α/9 + 4sin²α/2.25 = 1, cos²α = 7/12.
#[test]
fn semi_axes_and_a_point_on_the_ellipse_set_its_rotation() {
    let mut s = Sketch::new();
    let e = s
        .add_ellipse(&Ellipse::try_new(Point2::new(0.0, 0.0), 2.5, 1.0, 0.7).unwrap())
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(e, 0)))
        .unwrap();
    for (axis, length) in [(Axis::A, 3.0), (Axis::B, 1.5)] {
        s.add_constraint(SemiAxis {
            ellipse: e,
            axis,
            length,
        })
        .unwrap();
    }
    assert_eq!(dof(&s), 1);
    let p = s.add_point(Point2::new(0.0, 2.0)).unwrap();
    s.add_constraint(Fixed::entity(p)).unwrap();
    s.add_constraint(PointOnEllipse {
        point: PointRef::Point(p),
        ellipse: e,
    })
    .unwrap();
    assert_eq!(dof(&s), 0);
    solve_tight(&mut s);
    let solved = s.entity(e).unwrap().as_ellipse().unwrap();
    assert_relative_eq!(solved.semi_axis_a(), 3.0, epsilon = 1e-10);
    assert_relative_eq!(solved.semi_axis_b(), 1.5, epsilon = 1e-10);
    let (u, _) = solved.axes();
    let cos = u.dot(&Vector2::new(0.0, 1.0));
    assert_relative_eq!(cos * cos, 7.0 / 12.0, epsilon = 1e-10);
    assert!(solved.implicit_value(&Point2::new(0.0, 2.0)).abs() < 1e-10);
}

/// A point held on an elliptic arc and pinned beyond its end: the rows hold on the ellipse,
/// but the sweep check refuses the solve and nothing changes.
#[test]
fn a_point_on_an_elliptic_arc_pushed_past_its_end_is_refused() {
    let mut s = Sketch::new();
    let a = elliptic_arc(&mut s, 2.0, 1.0, 0.0, 0.0, 1.0);
    s.add_constraint(Fixed::entity(a)).unwrap();
    let ellipse = solved(&s, a).ellipse().to_owned();
    let p = s.add_point(ellipse.point_at_angle(2.5)).unwrap();
    s.add_constraint(Fixed::entity(p)).unwrap();
    s.add_constraint(PointOnEllipse {
        point: PointRef::Point(p),
        ellipse: a,
    })
    .unwrap();
    let before = s.entity(a).unwrap().clone();
    let err = s.solve().unwrap_err();
    assert!(matches!(err, Error::PointOffArc { .. }), "{err}");
    assert_eq!(s.entity(a).unwrap(), &before);
    // Within the sweep it solves.
    let mut t = Sketch::new();
    let a = elliptic_arc(&mut t, 2.0, 1.0, 0.0, 0.0, 1.0);
    let q = t.add_point(Point2::new(1.5, 1.0)).unwrap();
    t.add_constraint(Fixed::entity(q)).unwrap();
    t.add_constraint(PointOnEllipse {
        point: PointRef::Point(q),
        ellipse: a,
    })
    .unwrap();
    solve_tight(&mut t);
    let arc = solved(&t, a);
    assert!(arc.ellipse().implicit_value(&Point2::new(1.5, 1.0)).abs() < 1e-10);
    ends_on_ellipse(&arc);
}

/// An end pinned just before the start makes the rows hold with the complementary sweep: the
/// check refuses it and the sketch is unchanged; pinned after the start, it solves.
#[test]
fn a_solve_that_would_turn_an_elliptic_arc_inside_out_is_refused() {
    let pinned = |angle: f64| {
        let mut s = Sketch::new();
        let a = elliptic_arc(&mut s, 2.0, 1.0, 0.0, 0.0, 0.3);
        fix_axis(&mut s, a);
        s.add_constraint(SemiAxis {
            ellipse: a,
            axis: Axis::B,
            length: 1.0,
        })
        .unwrap();
        s.add_constraint(Fixed::point(PointRef::Start(a))).unwrap();
        let p = s
            .add_point(Point2::new(2.0 * angle.cos(), angle.sin()))
            .unwrap();
        s.add_constraint(Fixed::entity(p)).unwrap();
        s.add_constraint(Coincident {
            a: PointRef::End(a),
            b: PointRef::Point(p),
        })
        .unwrap();
        (s, a)
    };
    let (mut s, a) = pinned(-0.3);
    let before = s.entity(a).unwrap().clone();
    let err = s.solve().unwrap_err();
    assert!(
        matches!(err, Error::ArcTurnedInsideOut { entity, .. } if entity == a),
        "{err}"
    );
    assert_eq!(s.entity(a).unwrap(), &before);
    let (mut s, a) = pinned(0.6);
    solve_tight(&mut s);
    assert_relative_eq!(solved(&s, a).sweep(), 0.6, epsilon = 1e-9);
}

#[test]
fn ellipse_kinds_refuse_entities_of_the_wrong_kind() {
    let mut s = Sketch::new();
    let c = s.add_circle(Point2::new(0.0, 0.0), 1.0).unwrap();
    let e = s
        .add_ellipse(&Ellipse::try_new(Point2::new(5.0, 0.0), 2.0, 1.0, 0.0).unwrap())
        .unwrap();
    let l = s
        .add_line(Point2::new(0.0, 3.0), Point2::new(1.0, 3.0))
        .unwrap();
    let p = s.add_point(Point2::new(0.0, 0.0)).unwrap();
    let err = s
        .add_constraint(PointOnEllipse {
            point: PointRef::Point(p),
            ellipse: c,
        })
        .unwrap_err();
    assert_eq!(
        err,
        Error::WrongEntityKind {
            entity: c,
            expected: "ellipse or elliptic arc",
            found: "circle"
        }
    );
    let err = s
        .add_constraint(EllipticArcTangentToLine {
            arc: e,
            end: ArcEnd::Start,
            line: l,
            sense: Sense::Agree,
        })
        .unwrap_err();
    assert_eq!(
        err,
        Error::WrongEntityKind {
            entity: e,
            expected: "elliptic arc",
            found: "ellipse"
        }
    );
    let err = s
        .add_constraint(SemiAxis {
            ellipse: e,
            axis: Axis::A,
            length: -1.0,
        })
        .unwrap_err();
    assert!(err.to_string().contains("-1"), "{err}");
    // A full ellipse has no ends.
    assert!(s.point(PointRef::Start(e)).is_err());
}

#[test]
fn degenerate_ellipses_are_refused_naming_the_entity_and_value() {
    let mut s = Sketch::new();
    let c = Point2::new(0.0, 0.0);
    let err = s
        .add_entity(Entity::EllipticArc {
            points: [
                c,
                Point2::new(2.0, 0.0),
                Point2::new(2.0, 0.0),
                Point2::new(2.0, 0.0),
            ],
            semi_axis_b: 1.0,
        })
        .unwrap_err();
    assert!(matches!(
        err,
        Error::InvalidEllipse {
            entity: EntityId(0),
            reason: camber_geom::Error::DegenerateSweep { .. }
        }
    ));
    let err = s
        .add_entity(Entity::Ellipse {
            points: [c, c],
            semi_axis_b: 1.0,
        })
        .unwrap_err();
    assert_eq!(
        err,
        Error::InvalidEllipse {
            entity: EntityId(0),
            reason: camber_geom::Error::NonPositiveSemiAxis {
                axis: "a",
                value: 0.0
            }
        }
    );
    assert_eq!(s.entities().count(), 0);
}

/// Dragging an elliptic arc's end with its axis and b fixed slides it along the ellipse.
#[test]
fn dragging_an_elliptic_arc_end_keeps_it_on_its_ellipse() {
    let mut s = Sketch::new();
    let a = elliptic_arc(&mut s, 2.0, 1.0, 0.3, 0.0, 1.0);
    fix_axis(&mut s, a);
    s.add_constraint(SemiAxis {
        ellipse: a,
        axis: Axis::B,
        length: 1.0,
    })
    .unwrap();
    let mut drag = s.drag(PointRef::End(a)).unwrap();
    drag.update(Point2::new(-0.5, 1.5)).unwrap();
    drag.finish(&mut s).unwrap();
    let arc = solved(&s, a);
    ends_on_ellipse(&arc);
    assert_relative_eq!(arc.ellipse().semi_axis_b(), 1.0, epsilon = 1e-9);
    // The end moved towards the cursor, up the ellipse.
    assert!(arc.end_angle() > 1.5, "{}", arc.end_angle());
}

fn check<R: camber_solve::Residual>(r: &R, blocks: &[Vec<f64>]) -> f64 {
    let refs: Vec<&[f64]> = blocks.iter().map(|b| &b[..]).collect();
    check_jacobian(r, &refs, 1e-6, 1.0).unwrap().error
}

fn xy() -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-5.0..5.0f64, 2)
}

fn away(from: &[f64], p: &[f64]) -> bool {
    (p[0] - from[0]).hypot(p[1] - from[1]) > 0.1
}

proptest! {
    #[test]
    fn ellipse_residual_jacobians_match_central_differences(
        c in xy(), v in xy(), p in xy(), a in xy(), b in xy(), minor in 0.2..4.0f64,
        length in 0.2..4.0f64,
    ) {
        prop_assume!(away(&c, &v) && away(&a, &b));
        prop_assert!(check(&OnEllipse, &[c.clone(), v.clone(), vec![minor], p.clone()]) < 1e-6);
        prop_assert!(check(&SemiAxisA(length), &[c.clone(), v.clone()]) < 1e-6);
        let blocks = [c.clone(), v.clone(), vec![minor], p.clone(), a.clone(), b.clone()];
        prop_assert!(check(&EllipseLineTangency, &blocks) < 1e-6);
    }
}
