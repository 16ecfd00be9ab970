//! The nonlinear residuals' autodiff Jacobians against central differences
//! (camber_solve::testing), at random control points, parameters, circles and lines. The
//! curve is a clamped cubic B-spline with an interior knot, so the contact parameter crosses a
//! knot in some cases (the residual is smooth within a span; the difference step is kept well
//! inside one by staying away from the knot).

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber_geom::{BSplineCurve2, KnotVector};
use camber_sketch::contact::{
    CircleContact, CurvatureMatch, CurveCurveContact, LineAngle, LineContact, OnCircle, OnCircleAt,
    OnCurve, OnLineAt, Param, PointDistance, RadiusValue, TangentsParallel,
};
use camber_sketch::curve_eval::CurveBasis;
use camber_sketch::Entity;
use camber_solve::testing::check_jacobian;
use nalgebra::Point2;
use proptest::prelude::*;

/// A 5-point cubic on knots [0,0,0,0, ½, 1,1,1,1] through the given coordinates.
fn basis() -> CurveBasis {
    let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0]).unwrap();
    let pts = (0..5).map(|i| Point2::new(f64::from(i), 0.0)).collect();
    CurveBasis::of(&Entity::BSpline(
        BSplineCurve2::try_new(3, knots, pts).unwrap(),
    ))
    .unwrap()
}

/// The curve's blocks (a wavy polygon so the tangent never vanishes), then `extra`.
fn curve_blocks(wave: &[f64], extra: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let mut out: Vec<Vec<f64>> = (0..5).map(|i| vec![f64::from(i as u8), wave[i]]).collect();
    out.extend(extra.iter().cloned());
    out
}

fn check<R: camber_solve::Residual>(r: &R, blocks: &[Vec<f64>]) -> f64 {
    let refs: Vec<&[f64]> = blocks.iter().map(|b| &b[..]).collect();
    check_jacobian(r, &refs, 1e-6, 1e-6).unwrap().error
}

/// A parameter away from the knot at ½ (and from the ends).
fn param() -> impl Strategy<Value = f64> {
    prop_oneof![0.05..0.45_f64, 0.55..0.95_f64]
}

proptest! {
    #[test]
    fn on_curve(wave in prop::collection::vec(-1.0..1.0_f64, 5), u in param(),
                q in prop::array::uniform2(-3.0..3.0_f64)) {
        let r = OnCurve::new(basis(), Param::Block);
        prop_assert!(check(&r, &curve_blocks(&wave, &[vec![u], q.to_vec()])) < 1e-6);
    }

    #[test]
    fn line_contact(wave in prop::collection::vec(-1.0..1.0_f64, 5), u in param(),
                    a in prop::array::uniform2(-3.0..3.0_f64), d in prop::array::uniform2(0.5..2.0_f64)) {
        let r = LineContact::new(basis(), Param::Block);
        let b = vec![a[0] + d[0], a[1] - d[1]];
        prop_assert!(check(&r, &curve_blocks(&wave, &[vec![u], a.to_vec(), b])) < 1e-6);
    }

    #[test]
    fn circle_contact(wave in prop::collection::vec(-1.0..1.0_f64, 5), u in param(),
                      c in prop::array::uniform2(-3.0..3.0_f64), r in 0.1..2.0_f64, cw in any::<bool>()) {
        let res = CircleContact::new(basis(), Param::Block, cw);
        prop_assert!(check(&res, &curve_blocks(&wave, &[vec![u], c.to_vec(), vec![r]])) < 1e-6);
        let fixed = CircleContact::new(basis(), Param::Fixed(u), cw);
        prop_assert!(check(&fixed, &curve_blocks(&wave, &[c.to_vec(), vec![r]])) < 1e-6);
    }

    #[test]
    fn push_backs(wave in prop::collection::vec(-1.0..1.0_f64, 5), s in param(),
                  c in prop::array::uniform2(-3.0..3.0_f64), r in 0.1..2.0_f64) {
        let on_circle = OnCircleAt::new(basis(), s);
        prop_assert!(check(&on_circle, &curve_blocks(&wave, &[c.to_vec(), vec![r]])) < 1e-6);
        let on_line = OnLineAt::new(basis(), s);
        let b = vec![c[0] + 1.0, c[1] + r];
        prop_assert!(check(&on_line, &curve_blocks(&wave, &[c.to_vec(), b])) < 1e-6);
    }

    #[test]
    fn points_and_circles(p in prop::array::uniform2(-3.0..3.0_f64), c in prop::array::uniform2(-3.0..3.0_f64),
                          r in 0.1..2.0_f64, d in 0.1..4.0_f64) {
        prop_assert!(check(&OnCircle, &[p.to_vec(), c.to_vec(), vec![r]]) < 1e-6);
        prop_assert!(check(&PointDistance::new(d), &[p.to_vec(), c.to_vec()]) < 1e-6);
        prop_assert!(check(&RadiusValue::new(d), &[vec![r]]) < 1e-6);
    }

    #[test]
    fn line_angles(xs in prop::collection::vec(-3.0..3.0_f64, 4), d in prop::collection::vec(0.3..2.0_f64, 4),
                   angle in -3.0..3.0_f64) {
        let blocks = vec![
            vec![xs[0], xs[1]], vec![xs[0] + d[0], xs[1] + d[1]],
            vec![xs[2], xs[3]], vec![xs[2] - d[2], xs[3] + d[3]],
        ];
        for r in [LineAngle::new("parallel", 0.0), LineAngle::new("angle", angle)] {
            prop_assert!(check(&r, &blocks) < 1e-6);
        }
    }

    #[test]
    fn tangents_parallel(w1 in prop::collection::vec(-1.0..1.0_f64, 5), w2 in prop::collection::vec(-1.0..1.0_f64, 5)) {
        let r = TangentsParallel::new((basis(), 1.0), (basis(), 0.0));
        let mut blocks = curve_blocks(&w1, &[]);
        blocks.extend(curve_blocks(&w2, &[]));
        prop_assert!(check(&r, &blocks) < 1e-6);
    }

    #[test]
    fn curve_curve_contact(w1 in prop::collection::vec(-1.0..1.0_f64, 5), w2 in prop::collection::vec(-1.0..1.0_f64, 5),
                           u in param(), v in param()) {
        let r = CurveCurveContact::new((basis(), Param::Block), (basis(), Param::Block));
        let mut blocks = curve_blocks(&w1, &[vec![u]]);
        blocks.extend(curve_blocks(&w2, &[vec![v]]));
        prop_assert!(check(&r, &blocks) < 1e-6);
    }

    #[test]
    fn curvature_match(w1 in prop::collection::vec(-1.0..1.0_f64, 5), w2 in prop::collection::vec(-1.0..1.0_f64, 5),
                       u in param(), v in param()) {
        let r = CurvatureMatch::new((basis(), u), (basis(), v));
        let mut blocks = curve_blocks(&w1, &[]);
        blocks.extend(curve_blocks(&w2, &[]));
        prop_assert!(check(&r, &blocks) < 1e-6);
    }
}
