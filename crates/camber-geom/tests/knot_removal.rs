//! Knot removal and degree reduction: exact round trips (insert then remove, elevate then
//! reduce leave the curve and its control points unchanged), the reported bounds against a
//! second method (dense sampling of the deviation), and the rational circle.

// Test helpers outside #[test] functions unwrap too; a failed unwrap is a failed test.
#![allow(clippy::unwrap_used)]

use camber_geom::{BSplineCurve2, BezierCurve2, Error, KnotVector, NurbsCurve2, ParametricCurve};
use nalgebra::Point2;
use proptest::prelude::*;
use std::f64::consts::TAU;

fn curve_strategy() -> impl Strategy<Value = BSplineCurve2<f64>> {
    (1usize..=4, 0usize..4).prop_flat_map(|(p, extra)| {
        let n = p + 1 + extra;
        proptest::collection::vec((-5.0..5.0, -5.0..5.0), n).prop_map(move |pts| {
            let points = pts.into_iter().map(|(x, y)| Point2::new(x, y)).collect();
            BSplineCurve2::try_new(p, KnotVector::clamped_uniform(p, n).unwrap(), points).unwrap()
        })
    })
}

/// The largest |a(u) − b(u)| over 400 samples per span of `a`.
fn dense_deviation(a: &dyn ParametricCurve<f64, 2>, b: &dyn ParametricCurve<f64, 2>) -> f64 {
    let mut worst = 0.0_f64;
    for w in a.breakpoints().windows(2) {
        for k in 0..=400 {
            let u = w[0] + (w[1] - w[0]) * f64::from(k) / 400.0;
            worst = worst.max((a.point(u).unwrap() - b.point(u).unwrap()).norm());
        }
    }
    worst
}

#[test]
fn removal_errors_are_typed() {
    let c = BSplineCurve2::try_new(
        2,
        KnotVector::clamped_uniform(2, 4).unwrap(),
        vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(2.0, 1.0),
            Point2::new(3.0, 0.0),
        ],
    )
    .unwrap();
    assert_eq!(
        c.remove_knot(0.25, 1, 1e-9).unwrap_err(),
        Error::KnotNotFound { value: 0.25 }
    );
    assert!(matches!(
        c.remove_knot(0.0, 1, 1e-9),
        Err(Error::KnotNotFound { .. })
    ));
    assert!(matches!(
        c.remove_knot(0.5, 1, -1.0),
        Err(Error::NonPositiveTolerance { .. })
    ));
    // The knot at 1/2 of this curve is genuine: nothing goes at a small tolerance.
    let kept = c.remove_knot(0.5, 1, 1e-6).unwrap();
    assert_eq!(kept.removed, 0);
    assert_eq!(kept.curve, c);
    let point = BezierCurve2::try_new(vec![Point2::new(1.0, 1.0)]).unwrap();
    assert!(matches!(
        point.reduce_degree(),
        Err(Error::TooFewControlPoints { .. })
    ));
}

#[test]
fn the_rational_circle_keeps_its_knots_and_loses_inserted_ones() {
    let circle = NurbsCurve2::try_circular_arc(Point2::origin(), 1.0, 0.0, TAU).unwrap();
    let busy = circle.insert_knot(0.6, 1).unwrap();
    let clean = busy.remove_knot(0.6, 1, 1e-10).unwrap();
    assert_eq!(clean.removed, 1);
    assert_eq!(clean.curve.control_points().len(), 9);
    assert!(clean.error_bound < 1e-10);
    let genuine = circle.remove_knot(0.25, 1, 1e-6).unwrap();
    assert_eq!(genuine.removed, 0);
    // Elevated and reduced, it is the circle again.
    let back = circle
        .elevate_degree(1)
        .unwrap()
        .reduce_degree(1e-10)
        .unwrap();
    assert_eq!(back.curve.degree(), 2);
    assert!(back.error_bound < 1e-10, "{}", back.error_bound);
    for i in 0..50 {
        let p = back.curve.point(f64::from(i) / 50.0).unwrap();
        assert!((p.coords.norm() - 1.0).abs() < 1e-10);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn inserted_knots_come_out_exactly(c in curve_strategy(), f in 0.05..0.95_f64, r in 1usize..4) {
        let (a, b) = c.domain();
        let u = a + (b - a) * f;
        prop_assume!(c.knots().multiplicity(u) == 0);
        let r = r.min(c.degree());
        let busy = c.insert_knot(u, r).unwrap();
        let out = busy.remove_knot(u, r, 0.0).unwrap();
        prop_assert_eq!(out.removed, r);
        prop_assert!(out.error_bound < 1e-9);
        prop_assert_eq!(out.curve.control_points().len(), c.control_points().len());
        for (x, y) in out.curve.control_points().iter().zip(c.control_points()) {
            prop_assert!((x - y).norm() < 1e-9);
        }
        // All at once, from a curve refined at several places.
        let mut extra = [a + (b - a) * 0.03, u, a + (b - a) * 0.97];
        extra.sort_by(f64::total_cmp);
        let many = c.refine(&extra).unwrap();
        let clean = many.remove_knots(0.0).unwrap();
        prop_assert!(clean.removed >= 3);
        prop_assert!(dense_deviation(&c, &clean.curve) < 1e-9);
    }

    #[test]
    fn removal_bounds_hold(c in curve_strategy(), tol_exp in -3i32..1) {
        let tol = 10f64.powi(tol_exp);
        let out = c.remove_knots(tol).unwrap();
        prop_assert!(out.error_bound <= tol * (1.0 + 1e-12));
        let measured = dense_deviation(&c, &out.curve);
        prop_assert!(measured <= out.error_bound + 1e-12, "{measured} > {}", out.error_bound);
    }

    #[test]
    fn elevated_curves_reduce_exactly(c in curve_strategy()) {
        let back = c.elevate_degree(1).unwrap().reduce_degree(0.0).unwrap();
        prop_assert!(back.error_bound < 1e-9, "{}", back.error_bound);
        prop_assert_eq!(back.curve.degree(), c.degree());
        prop_assert_eq!(back.curve.control_points().len(), c.control_points().len());
        prop_assert!(dense_deviation(&c, &back.curve) < 1e-9);
        let bez = BezierCurve2::try_new(c.control_points().to_vec()).unwrap();
        let again = bez.elevate_degree(1).reduce_degree().unwrap();
        for (x, y) in again.curve.control_points().iter().zip(bez.control_points()) {
            prop_assert!((x - y).norm() < 1e-9);
        }
    }

    #[test]
    fn reduction_bounds_hold(c in curve_strategy(), tol in 0.0..0.5_f64) {
        prop_assume!(c.degree() >= 2);
        let reduced = c.reduce_degree(tol).unwrap();
        prop_assert_eq!(reduced.curve.degree(), c.degree() - 1);
        let measured = dense_deviation(&c, &reduced.curve);
        prop_assert!(measured <= reduced.error_bound + 1e-12, "{measured} > {}", reduced.error_bound);
        let bez = BezierCurve2::try_new(c.control_points().to_vec()).unwrap();
        let r = bez.reduce_degree().unwrap();
        prop_assert!(dense_deviation(&bez, &r.curve) <= r.error_bound + 1e-12);
    }
}
