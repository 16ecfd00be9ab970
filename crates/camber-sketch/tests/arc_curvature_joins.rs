//! `arc_curvature_to_curve`, the curvature half of a G2 join between an arc end and a curve
//! end: solved against closed forms (a cubic's end curvature 2(X − x₁)/(3h²) meeting 1/r of a
//! circle and b²/a of an ellipse at its vertex, with either sense), a whole G2 join of an arc
//! and a cubic checked by independent evaluation (camber-geom's derivatives), its refusals,
//! DOF, file form and autodiff Jacobians against central differences.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use std::f64::consts::{FRAC_PI_2, PI};

use approx::assert_relative_eq;
use camber_geom::{BezierCurve2, CircularArc, EllipticArc, ParametricCurve};
use camber_sketch::constraints::arc_curvature_to_curve::CurvatureMatch;
use camber_sketch::constraints::arc_tangent_to_line::ArcEnd;
use camber_sketch::constraints::{
    ArcCurvatureToCurve, ArcTangentToCurve, Coincident, Fixed, Radius,
};
use camber_sketch::curve_eval::CurveBasis;
use camber_sketch::file::{from_json, to_json};
use camber_sketch::{Constraint, Entity, EntityId, Error, PointRef, Sense, Sketch};
use camber_solve::testing::check_jacobian;
use nalgebra::Point2;
use proptest::prelude::*;

fn cubic(s: &mut Sketch, pts: [(f64, f64); 4]) -> EntityId {
    let points = pts.iter().map(|p| Point2::new(p.0, p.1)).collect();
    s.add_entity(Entity::Bezier(BezierCurve2::try_new(points).unwrap()))
        .unwrap()
}

fn control(s: &Sketch, e: EntityId, i: usize) -> Point2<f64> {
    s.point(PointRef::Control(e, i)).unwrap()
}

fn fix_points(s: &mut Sketch, e: EntityId, which: &[usize]) {
    for i in which {
        s.add_constraint(Fixed::point(PointRef::Control(e, *i)))
            .unwrap();
    }
}

/// The signed curvature of a solved Bézier at u, from camber-geom's derivatives.
fn bezier_curvature(s: &Sketch, e: EntityId, u: f64) -> f64 {
    let Entity::Bezier(c) = s.entity(e).unwrap() else {
        panic!("not a Bézier")
    };
    let [_, d1, d2] = c.second_order(u).unwrap();
    (d1.x * d2.y - d1.y * d2.x) / d1.norm().powi(3)
}

/// A fixed quarter of the circle of radius `r` about (0, 0) from (r, 0), and a cubic ending at
/// (r, 0) heading +y with P₂ = (r, −h) and P₀ fixed; P₁ is free.
fn cubic_into_a_circle(r: f64, h: f64) -> (Sketch, EntityId, EntityId) {
    let mut s = Sketch::new();
    let a = s
        .add_arc(&CircularArc::try_new(Point2::new(0.0, 0.0), r, 0.0, FRAC_PI_2).unwrap())
        .unwrap();
    s.add_constraint(Fixed::entity(a)).unwrap();
    let c = cubic(&mut s, [(0.0, -1.5), (r - 0.1, -0.9), (r, -h), (r, 0.0)]);
    fix_points(&mut s, c, &[0, 2, 3]);
    (s, a, c)
}

#[test]
fn a_cubic_takes_the_curvature_of_the_circle_it_runs_into() {
    for (r, h) in [(1.0, 0.4), (2.5, 0.3), (0.5, 0.2)] {
        let (mut s, a, c) = cubic_into_a_circle(r, h);
        let before = control(&s, c, 1);
        s.add_constraint(ArcCurvatureToCurve {
            arc: a,
            end: ArcEnd::Start,
            curve: c,
            curve_end: ArcEnd::End,
            sense: Sense::Agree,
        })
        .unwrap();
        s.solve().unwrap();
        // κ(1) = 2(X − x₁)/(3h²) = 1/r gives x₁ = X − 1.5h²/r; the row does not read y₁.
        let p1 = control(&s, c, 1);
        assert_relative_eq!(p1.x, r - 1.5 * h * h / r, epsilon = 1e-10);
        assert_relative_eq!(p1.y, before.y, epsilon = 1e-12);
        assert_relative_eq!(bezier_curvature(&s, c, 1.0), 1.0 / r, epsilon = 1e-9);
    }
}

#[test]
fn a_cubic_leaving_an_arc_backwards_turns_the_other_way() {
    // The cubic starts at the arc's start (1, 0) heading −y, against the arc's travel: its
    // curvature there must be −1, which is x₂ = 1 − 1.5h² for P₁ = (1, −h).
    let h = 0.35;
    let mut s = Sketch::new();
    let a = s
        .add_arc(&CircularArc::try_new(Point2::new(0.0, 0.0), 1.0, 0.0, FRAC_PI_2).unwrap())
        .unwrap();
    s.add_constraint(Fixed::entity(a)).unwrap();
    let c = cubic(&mut s, [(1.0, 0.0), (1.0, -h), (0.8, -0.8), (0.0, -1.4)]);
    fix_points(&mut s, c, &[0, 1, 3]);
    s.add_constraint(ArcCurvatureToCurve {
        arc: a,
        end: ArcEnd::Start,
        curve: c,
        curve_end: ArcEnd::Start,
        sense: Sense::Oppose,
    })
    .unwrap();
    s.solve().unwrap();
    assert_relative_eq!(control(&s, c, 2).x, 1.0 - 1.5 * h * h, epsilon = 1e-10);
    assert_relative_eq!(bezier_curvature(&s, c, 0.0), -1.0, epsilon = 1e-9);
}

#[test]
fn a_cubic_takes_the_curvature_of_an_ellipse_at_its_vertex() {
    // a = 2, b = 1: at the vertex (2, 0) the radius of curvature is b²/a = 0.5, so a cubic
    // ending there heading +y needs κ = 2(X − x₁)/(3h²) = 2, x₁ = 2 − 3h².
    let h = 0.3;
    let mut s = Sketch::new();
    let e = s
        .add_elliptic_arc(
            &EllipticArc::try_new(Point2::new(0.0, 0.0), 2.0, 1.0, 0.0, 0.0, FRAC_PI_2).unwrap(),
        )
        .unwrap();
    s.add_constraint(Fixed::entity(e)).unwrap();
    let c = cubic(&mut s, [(1.5, -1.5), (1.8, -0.9), (2.0, -h), (2.0, 0.0)]);
    fix_points(&mut s, c, &[0, 2, 3]);
    s.add_constraint(ArcCurvatureToCurve {
        arc: e,
        end: ArcEnd::Start,
        curve: c,
        curve_end: ArcEnd::End,
        sense: Sense::Agree,
    })
    .unwrap();
    s.solve().unwrap();
    assert_relative_eq!(control(&s, c, 1).x, 2.0 - 3.0 * h * h, epsilon = 1e-10);
    assert_relative_eq!(bezier_curvature(&s, c, 1.0), 2.0, epsilon = 1e-9);
}

#[test]
fn a_g2_join_of_an_elliptic_arc_and_a_cubic_matches_the_ellipses_own_curvature() {
    // Away from the vertices: the ellipse's curvature at the joint from camber-geom's
    // derivatives (a second method) equals the solved cubic's.
    let mut s = Sketch::new();
    let arc = EllipticArc::try_new(Point2::new(0.0, 0.0), 2.0, 1.0, 0.4, 0.3, 1.2).unwrap();
    let e = s.add_elliptic_arc(&arc).unwrap();
    s.add_constraint(Fixed::entity(e)).unwrap();
    let p = arc.end_point();
    let t = arc.derivative_at(1.0, 1).normalize();
    let q = |d: f64, n: f64| (p.x + d * t.x - n * t.y, p.y + d * t.y + n * t.x);
    let c = cubic(
        &mut s,
        [(p.x, p.y), q(0.4, 0.0), q(0.8, -0.1), q(1.2, -0.3)],
    );
    fix_points(&mut s, c, &[0, 1, 3]);
    s.add_constraint(ArcCurvatureToCurve {
        arc: e,
        end: ArcEnd::End,
        curve: c,
        curve_end: ArcEnd::Start,
        sense: Sense::Agree,
    })
    .unwrap();
    s.solve().unwrap();
    let (d1, d2) = (arc.derivative_at(1.0, 1), arc.derivative_at(1.0, 2));
    let kappa = (d1.x * d2.y - d1.y * d2.x) / d1.norm().powi(3);
    assert_relative_eq!(bezier_curvature(&s, c, 0.0), kappa, epsilon = 1e-9);
}

#[test]
fn a_whole_g2_join_of_a_free_arc_and_a_cubic_holds_position_tangent_and_curvature() {
    let mut s = Sketch::new();
    let a = s
        .add_arc(&CircularArc::try_new(Point2::new(0.1, 0.05), 1.05, -0.1, 1.6).unwrap())
        .unwrap();
    s.add_constraint(Radius {
        circle: a,
        radius: 1.0,
    })
    .unwrap();
    let c = cubic(&mut s, [(0.0, -1.5), (0.7, -0.9), (1.0, -0.4), (1.0, 0.0)]);
    fix_points(&mut s, c, &[0, 1]);
    s.add_constraint(Coincident {
        a: PointRef::Start(a),
        b: PointRef::End(c),
    })
    .unwrap();
    s.add_constraint(ArcTangentToCurve {
        arc: a,
        end: ArcEnd::Start,
        curve: c,
        curve_end: ArcEnd::End,
        sense: Sense::Agree,
    })
    .unwrap();
    s.add_constraint(ArcCurvatureToCurve {
        arc: a,
        end: ArcEnd::Start,
        curve: c,
        curve_end: ArcEnd::End,
        sense: Sense::Agree,
    })
    .unwrap();
    s.solve().unwrap();
    let solved = s.entity(a).unwrap().as_arc().unwrap();
    let Entity::Bezier(curve) = s.entity(c).unwrap() else {
        panic!()
    };
    let (p, q) = (solved.start_point(), curve.point(1.0).unwrap());
    assert!((p - q).norm() < 1e-10);
    let (t_arc, t_curve) = (solved.derivative(0.0), curve.derivative(1.0).unwrap());
    let sin = (t_arc.x * t_curve.y - t_arc.y * t_curve.x) / (t_arc.norm() * t_curve.norm());
    assert!(sin.abs() < 1e-10 && t_arc.dot(&t_curve) > 0.0);
    assert_relative_eq!(
        bezier_curvature(&s, c, 1.0),
        1.0 / solved.radius(),
        epsilon = 1e-9
    );
    assert_relative_eq!(solved.radius(), 1.0, epsilon = 1e-10);
}

#[test]
fn curvature_matches_take_only_an_arc_and_a_free_form_curve() {
    let mut s = Sketch::new();
    let circle = s
        .add_entity(Entity::Circle {
            center: Point2::new(0.0, 0.0),
            radius: 1.0,
        })
        .unwrap();
    let a = s
        .add_arc(&CircularArc::try_new(Point2::new(0.0, 0.0), 1.0, 0.0, PI).unwrap())
        .unwrap();
    let c = cubic(&mut s, [(0.0, 0.0), (1.0, 0.0), (2.0, 1.0), (3.0, 1.0)]);
    let row = |arc, curve| ArcCurvatureToCurve {
        arc,
        end: ArcEnd::End,
        curve,
        curve_end: ArcEnd::Start,
        sense: Sense::Agree,
    };
    let before = to_json(&s).unwrap();
    assert!(matches!(
        s.add_constraint(row(circle, c)),
        Err(Error::WrongEntityKind { entity, .. }) if entity == circle
    ));
    assert!(matches!(
        s.add_constraint(row(c, a)),
        Err(Error::WrongEntityKind { entity, .. }) if entity == c
    ));
    assert!(matches!(
        s.add_constraint(row(a, a)),
        Err(Error::SameEntity { .. }) | Err(Error::WrongEntityKind { .. })
    ));
    assert_eq!(to_json(&s).unwrap(), before);
}

#[test]
fn a_curvature_match_removes_one_degree_of_freedom_and_survives_a_file() {
    let (mut s, a, c) = cubic_into_a_circle(1.0, 0.4);
    let dof = |s: &Sketch| -> usize { s.analyze().unwrap().iter().map(|x| x.analysis.dof).sum() };
    assert_eq!(dof(&s), 2);
    let k = s
        .add_constraint(ArcCurvatureToCurve {
            arc: a,
            end: ArcEnd::Start,
            curve: c,
            curve_end: ArcEnd::End,
            sense: Sense::Agree,
        })
        .unwrap();
    assert_eq!(dof(&s), 1);
    let text = to_json(&s).unwrap();
    assert!(text.contains("\"arc_curvature_to_curve\""), "{text}");
    let back = from_json(&text).unwrap();
    assert_eq!(back.constraint(k).unwrap(), s.constraint(k).unwrap());
    assert!(matches!(
        back.constraint(k).unwrap(),
        Constraint::ArcCurvatureToCurve(_)
    ));
}

fn xy() -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-3.0..3.0f64, 2)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn curvature_match_jacobians_match_central_differences(
        c in xy(), v in xy(), p in xy(), q0 in xy(), q1 in xy(), q2 in xy(), q3 in xy(),
        minor in 0.3..2.0f64, at_end in any::<bool>(), agree in any::<bool>(),
        elliptic in any::<bool>(),
    ) {
        let d = |a: &[f64], b: &[f64]| (a[0] - b[0]).hypot(a[1] - b[1]);
        prop_assume!(d(&v, &c) > 0.2 && d(&p, &c) > 0.2);
        prop_assume!(d(&q0, &q1) > 0.2 && d(&q2, &q3) > 0.2);
        let pts = [&q0, &q1, &q2, &q3].map(|q| Point2::new(q[0], q[1]));
        let full = CurveBasis::of(&Entity::Bezier(BezierCurve2::try_new(pts.to_vec()).unwrap())).unwrap();
        let u = if at_end { 1.0 } else { 0.0 };
        let (basis, used) = full.at(u, 2);
        let sense = if agree { 1.0 } else { -1.0 };
        let b = [minor];
        let mut refs: Vec<&[f64]> = if elliptic { vec![&c, &v, &b, &p] } else { vec![&c, &p] };
        let all = [&q0, &q1, &q2, &q3];
        refs.extend(used.iter().map(|j| &all[*j][..]));
        let row = if elliptic {
            CurvatureMatch::elliptic(basis, u, sense)
        } else {
            CurvatureMatch::circular(basis, u, sense)
        };
        let mut g = [0.0];
        camber_solve::Residual::eval(&row, &refs, &mut g);
        prop_assume!(g[0].is_finite() && g[0].abs() < 1e3);
        prop_assert!(check_jacobian(&row, &refs, 1e-6, 1.0).unwrap().error < 1e-5);
    }
}
