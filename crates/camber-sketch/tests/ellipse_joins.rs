//! An elliptic arc joined G1 to a free-form curve: `coincident` at the ends plus
//! `elliptic_arc_tangent_to_curve`, solved against the closed form, the sense kept or the solve
//! refused, and the row's autodiff Jacobian against central differences.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use camber_geom::{BezierCurve2, EllipticArc};
use camber_sketch::constraints::arc_tangent_to_line::ArcEnd;
use camber_sketch::constraints::elliptic_arc_tangent_to_curve::EllipseCurveTangency;
use camber_sketch::constraints::{Coincident, EllipticArcTangentToCurve, Fixed};
use camber_sketch::curve_eval::CurveBasis;
use camber_sketch::{Entity, EntityId, Error, PointRef, Sense, Sketch};
use camber_solve::testing::check_jacobian;
use nalgebra::Point2;
use proptest::prelude::*;
use std::f64::consts::FRAC_PI_2;

/// A fixed quarter of x²/4 + y² = 1 ending at the top (0, 1), and a cubic starting there whose
/// second control point starts at (−0.5, 1.4) and is the only thing free.
fn joined(sense: Sense) -> (Sketch, EntityId, EntityId) {
    let mut s = Sketch::new();
    let arc = s
        .add_elliptic_arc(
            &EllipticArc::try_new(Point2::new(0.0, 0.0), 2.0, 1.0, 0.0, 0.0, FRAC_PI_2).unwrap(),
        )
        .unwrap();
    s.add_constraint(Fixed::entity(arc)).unwrap();
    let bez = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 1.0),
                Point2::new(-0.5, 1.4),
                Point2::new(-1.5, 1.2),
                Point2::new(-2.0, 0.5),
            ])
            .unwrap(),
        )
        .unwrap();
    for j in [0, 2, 3] {
        s.add_constraint(Fixed::point(PointRef::Control(bez, j)))
            .unwrap();
    }
    s.add_constraint(Coincident {
        a: PointRef::End(arc),
        b: PointRef::Start(bez),
    })
    .unwrap();
    s.add_constraint(EllipticArcTangentToCurve {
        arc,
        end: ArcEnd::End,
        curve: bez,
        curve_end: ArcEnd::Start,
        sense,
    })
    .unwrap();
    (s, arc, bez)
}

/// At the top the arc travels towards −x, so the cubic's first leg P₁ − P₀ must lie along −x:
/// P₁ lands on y = 1, at the foot of its start (−0.5, 1).
#[test]
fn a_curve_joined_g1_to_an_elliptic_arc_end_takes_its_tangent() {
    let (mut s, _, bez) = joined(Sense::Agree);
    assert_eq!(
        s.analyze()
            .unwrap()
            .iter()
            .map(|a| a.analysis.dof)
            .sum::<usize>(),
        1
    );
    let report = s.solve().unwrap();
    for c in &report.components {
        for r in &c.report.residuals {
            assert!(r.max_abs < 1e-10, "{r:?}");
        }
    }
    let Entity::Bezier(c) = s.entity(bez).unwrap() else {
        panic!("not a Bézier curve")
    };
    assert_relative_eq!(c.control_points()[1].y, 1.0, epsilon = 1e-10);
    assert_relative_eq!(c.control_points()[1].x, -0.5, epsilon = 1e-6);
}

/// The opposite sense would need P₁ on the +x side of the joint: from where it starts the
/// solve would have to swing the leg half a turn; if it gets there it keeps the sense, and if
/// it does not, it fails and changes nothing.
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

#[test]
fn the_tangency_refuses_a_curve_that_is_the_arc_or_not_a_curve() {
    let (mut s, arc, _) = joined(Sense::Agree);
    let p = s.add_point(Point2::new(3.0, 3.0)).unwrap();
    let err = s
        .add_constraint(EllipticArcTangentToCurve {
            arc,
            end: ArcEnd::Start,
            curve: p,
            curve_end: ArcEnd::Start,
            sense: Sense::Agree,
        })
        .unwrap_err();
    assert!(
        matches!(err, Error::WrongEntityKind { entity, .. } if entity == p),
        "{err}"
    );
}

fn xy() -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-5.0..5.0f64, 2)
}

proptest! {
    #[test]
    fn the_curve_tangency_jacobian_matches_central_differences(
        c in xy(), v in xy(), p in xy(), q0 in xy(), q1 in xy(), q2 in xy(), minor in 0.2..4.0f64,
        at_end in any::<bool>(), agree in any::<bool>(),
    ) {
        prop_assume!((v[0] - c[0]).hypot(v[1] - c[1]) > 0.1);
        prop_assume!((p[0] - c[0]).hypot(p[1] - c[1]) > 0.1);
        let pts = [&q0, &q1, &q2].map(|q| Point2::new(q[0], q[1]));
        prop_assume!((pts[1] - pts[0]).norm() > 0.1 && (pts[2] - pts[1]).norm() > 0.1);
        let curve = Entity::Bezier(BezierCurve2::try_new(pts.to_vec()).unwrap());
        let basis = CurveBasis::of(&curve).unwrap();
        let u = if at_end { 1.0 } else { 0.0 };
        let row = EllipseCurveTangency::new(basis, u, if agree { 1.0 } else { -1.0 });
        let blocks = [c.clone(), v.clone(), vec![minor], p.clone(), q0.clone(), q1.clone(), q2.clone()];
        let refs: Vec<&[f64]> = blocks.iter().map(|b| &b[..]).collect();
        // Away from the branch cut of atan2 (the tangents nearly opposite for the sense).
        let mut g = [0.0];
        camber_solve::Residual::eval(&row, &refs, &mut g);
        prop_assume!(g[0].abs() < 3.0);
        prop_assert!(check_jacobian(&row, &refs, 1e-6, 1.0).unwrap().error < 1e-6);
    }
}
