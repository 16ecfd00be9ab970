//! A circular arc joined G1 to free-form curves: `coincident` at the ends plus
//! `arc_tangent_to_curve`, solved against closed forms (a curve's leg taking the arc's tangent,
//! a blade's trailing-edge arc centred between its two sides), the sense kept or the solve
//! refused with the sketch unchanged, and the row's autodiff Jacobian against central
//! differences.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use camber_geom::{BezierCurve2, CircularArc};
use camber_sketch::constraints::arc_tangent_to_curve::ArcCurveTangency;
use camber_sketch::constraints::arc_tangent_to_line::ArcEnd;
use camber_sketch::constraints::{ArcTangentToCurve, Coincident, Fixed};
use camber_sketch::curve_eval::CurveBasis;
use camber_sketch::{Entity, EntityId, Error, PointRef, Sense, Sketch};
use camber_solve::testing::check_jacobian;
use nalgebra::Point2;
use proptest::prelude::*;
use std::f64::consts::FRAC_PI_2;

fn bezier(s: &mut Sketch, pts: &[[f64; 2]]) -> EntityId {
    s.add_bezier(BezierCurve2::try_new(pts.iter().map(|p| Point2::from(*p)).collect()).unwrap())
        .unwrap()
}

/// A fixed quarter of the unit circle ending at the top (0, 1), and a cubic starting there
/// whose second control point starts at (−0.5, 1.4) and is the only thing free.
fn joined(sense: Sense) -> (Sketch, EntityId, EntityId) {
    let mut s = Sketch::new();
    let arc = s
        .add_arc(&CircularArc::try_new(Point2::new(0.0, 0.0), 1.0, 0.0, FRAC_PI_2).unwrap())
        .unwrap();
    s.add_constraint(Fixed::entity(arc)).unwrap();
    let bez = bezier(&mut s, &[[0.0, 1.0], [-0.5, 1.4], [-1.5, 1.2], [-2.0, 0.5]]);
    for j in [0, 2, 3] {
        s.add_constraint(Fixed::point(PointRef::Control(bez, j)))
            .unwrap();
    }
    s.add_constraint(Coincident {
        a: PointRef::End(arc),
        b: PointRef::Start(bez),
    })
    .unwrap();
    s.add_constraint(ArcTangentToCurve {
        arc,
        end: ArcEnd::End,
        curve: bez,
        curve_end: ArcEnd::Start,
        sense,
    })
    .unwrap();
    (s, arc, bez)
}

fn assert_solved(s: &mut Sketch) {
    let report = s.solve().unwrap();
    for c in &report.components {
        for r in &c.report.residuals {
            assert!(r.max_abs < 1e-10, "{r:?}");
        }
    }
}

/// At the top the arc travels towards −x, so the cubic's first leg P₁ − P₀ must lie along −x:
/// P₁ lands on y = 1 at the foot of its start, (−0.5, 1).
#[test]
fn a_curve_joined_g1_to_an_arc_end_takes_its_tangent() {
    let (mut s, _, bez) = joined(Sense::Agree);
    let dof: usize = s.analyze().unwrap().iter().map(|a| a.analysis.dof).sum();
    assert_eq!(dof, 1);
    assert_solved(&mut s);
    let Entity::Bezier(c) = s.entity(bez).unwrap() else {
        panic!("not a Bézier curve")
    };
    assert_relative_eq!(c.control_points()[1].y, 1.0, epsilon = 1e-10);
    assert_relative_eq!(c.control_points()[1].x, -0.5, epsilon = 1e-6);
}

/// The opposite sense needs P₁ on the +x side of the joint: if the solve swings the leg there
/// it keeps the sense, and if it does not it fails and changes nothing.
#[test]
fn the_opposite_sense_is_kept_or_the_solve_changes_nothing() {
    let (mut s, _, bez) = joined(Sense::Oppose);
    let before = s.entity(bez).unwrap().clone();
    match s.solve() {
        Ok(_) => {
            let Entity::Bezier(c) = s.entity(bez).unwrap() else {
                panic!("not a Bézier curve")
            };
            let p = c.control_points();
            assert!(p[1].x > p[0].x, "{:?}", p[1]);
            assert_relative_eq!(p[1].y, 1.0, epsilon = 1e-9);
        }
        Err(e) => {
            assert!(
                matches!(
                    e,
                    Error::OrientationFlipped { .. } | Error::Solve(_) | Error::NotSatisfied { .. }
                ),
                "{e}"
            );
            assert_eq!(s.entity(bez).unwrap(), &before);
        }
    }
}

/// Two fixed sides ending at (1, ∓0.1) with horizontal tangents (the lower running towards
/// +x, the upper starting towards −x) and a free arc from the lower end to the upper end: the
/// only arc tangent to both is the half circle of radius 0.1 about (1, 0).
#[test]
fn a_trailing_edge_arc_between_two_sides_is_the_half_circle_between_them() {
    let mut s = Sketch::new();
    let upper = bezier(&mut s, &[[1.0, 0.1], [0.6, 0.1], [0.2, 0.15], [0.0, 0.0]]);
    let lower = bezier(
        &mut s,
        &[[0.0, 0.0], [0.2, -0.12], [0.6, -0.1], [1.0, -0.1]],
    );
    for c in [upper, lower] {
        s.add_constraint(Fixed::entity(c)).unwrap();
    }
    let arc = s
        .add_arc(&CircularArc::try_new(Point2::new(1.03, 0.01), 0.12, -1.2, 1.3).unwrap())
        .unwrap();
    s.add_constraint(Coincident {
        a: PointRef::Start(arc),
        b: PointRef::End(lower),
    })
    .unwrap();
    s.add_constraint(Coincident {
        a: PointRef::End(arc),
        b: PointRef::Start(upper),
    })
    .unwrap();
    s.add_constraint(ArcTangentToCurve {
        arc,
        end: ArcEnd::Start,
        curve: lower,
        curve_end: ArcEnd::End,
        sense: Sense::Agree,
    })
    .unwrap();
    let dof: usize = s.analyze().unwrap().iter().map(|a| a.analysis.dof).sum();
    assert_eq!(dof, 0);
    assert_solved(&mut s);
    let Entity::Arc(blocks) = s.entity(arc).unwrap() else {
        panic!("not an arc")
    };
    assert_relative_eq!(blocks[0], Point2::new(1.0, 0.0), epsilon = 1e-10);
    assert_relative_eq!((blocks[1] - blocks[0]).norm(), 0.1, epsilon = 1e-10);
    // Its other end is tangent to the upper side too, with the sense the constraint would ask.
    let r = blocks[2] - blocks[0];
    let travel = nalgebra::Vector2::new(-r.y, r.x);
    assert!(travel.x < 0.0 && travel.y.abs() < 1e-10, "{travel:?}");
    assert_relative_eq!(blocks[1], Point2::new(1.0, -0.1), epsilon = 1e-10);
    assert_relative_eq!(blocks[2], Point2::new(1.0, 0.1), epsilon = 1e-10);
}

#[test]
fn the_tangency_refuses_a_circle_a_point_or_the_arc_itself() {
    let (mut s, arc, bez) = joined(Sense::Agree);
    let p = s.add_point(Point2::new(3.0, 3.0)).unwrap();
    let circle = s.add_circle(Point2::new(5.0, 5.0), 1.0).unwrap();
    let tangency = |arc, curve| ArcTangentToCurve {
        arc,
        end: ArcEnd::Start,
        curve,
        curve_end: ArcEnd::Start,
        sense: Sense::Agree,
    };
    let err = s.add_constraint(tangency(arc, p)).unwrap_err();
    assert!(
        matches!(err, Error::WrongEntityKind { entity, .. } if entity == p),
        "{err}"
    );
    let err = s.add_constraint(tangency(circle, bez)).unwrap_err();
    assert!(
        matches!(err, Error::WrongEntityKind { entity, .. } if entity == circle),
        "{err}"
    );
    assert!(s.add_constraint(tangency(arc, arc)).is_err());
}

#[test]
fn the_file_form_round_trips() {
    let (s, _, _) = joined(Sense::Oppose);
    let text = camber_sketch::file::to_json(&s).unwrap();
    assert!(text.contains("\"arc_tangent_to_curve\""), "{text}");
    let back = camber_sketch::file::from_json(&text).unwrap();
    assert_eq!(
        camber_sketch::file::to_json(&back).unwrap(),
        text,
        "the reloaded sketch writes the same file"
    );
}

fn xy() -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-5.0..5.0f64, 2)
}

proptest! {
    #[test]
    fn the_curve_tangency_jacobian_matches_central_differences(
        c in xy(), p in xy(), q0 in xy(), q1 in xy(), q2 in xy(),
        at_end in any::<bool>(), agree in any::<bool>(),
    ) {
        prop_assume!((p[0] - c[0]).hypot(p[1] - c[1]) > 0.1);
        let pts = [&q0, &q1, &q2].map(|q| Point2::new(q[0], q[1]));
        prop_assume!((pts[1] - pts[0]).norm() > 0.1 && (pts[2] - pts[1]).norm() > 0.1);
        let curve = Entity::Bezier(BezierCurve2::try_new(pts.to_vec()).unwrap());
        let basis = CurveBasis::of(&curve).unwrap();
        let u = if at_end { 1.0 } else { 0.0 };
        let row = ArcCurveTangency::new(basis, u, if agree { 1.0 } else { -1.0 });
        let blocks = [c.clone(), p.clone(), q0.clone(), q1.clone(), q2.clone()];
        let refs: Vec<&[f64]> = blocks.iter().map(|b| &b[..]).collect();
        // Away from the branch cut of atan2 (the tangents nearly opposite for the sense).
        let mut g = [0.0];
        camber_solve::Residual::eval(&row, &refs, &mut g);
        prop_assume!(g[0].abs() < 3.0);
        prop_assert!(check_jacobian(&row, &refs, 1e-6, 1.0).unwrap().error < 1e-6);
    }
}
