//! The new operations run on dual numbers like every evaluator: derivatives of an extrapolated
//! point, of an interpolant and of a parameter at an arc length with respect to the input
//! points, checked against central differences.

// Test helpers outside #[test] functions unwrap too; a failed unwrap is a failed test.
#![allow(clippy::unwrap_used)]

use camber_geom::arc_length::parameter_at_length;
use camber_geom::extend::CurveEnd;
use camber_geom::fit::{interpolate, ParameterMethod};
use camber_geom::{BSplineCurve2, KnotVector, ParametricCurve, Scalar};
use nalgebra::Point2;
use num_dual::Dual64;

const POINTS: [[f64; 2]; 5] = [[0.0, 0.0], [1.0, 2.0], [2.5, 1.5], [3.0, -0.5], [4.5, 0.5]];

/// The points with coordinate `k` (flat index) seeded as the dual direction.
fn seeded(k: usize) -> Vec<Point2<Dual64>> {
    POINTS
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let c = |j: usize| {
                let v = Dual64::from(p[j]);
                if 2 * i + j == k {
                    v.derivative()
                } else {
                    v
                }
            };
            Point2::new(c(0), c(1))
        })
        .collect()
}

fn nudged(k: usize, h: f64) -> Vec<Point2<f64>> {
    POINTS
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let mut q = *p;
            if k / 2 == i {
                q[k % 2] += h;
            }
            Point2::new(q[0], q[1])
        })
        .collect()
}

fn spline<T: Scalar>(points: Vec<Point2<T>>) -> BSplineCurve2<T> {
    BSplineCurve2::try_new(
        3,
        KnotVector::clamped_uniform(3, points.len()).unwrap(),
        points,
    )
    .unwrap()
}

/// Checks a scalar function of the points against central differences for every coordinate.
fn check(
    f64_fn: impl Fn(Vec<Point2<f64>>) -> f64,
    dual_fn: impl Fn(Vec<Point2<Dual64>>) -> Dual64,
) {
    let h = 1e-6;
    for k in 0..2 * POINTS.len() {
        let d = dual_fn(seeded(k));
        let fd = (f64_fn(nudged(k, h)) - f64_fn(nudged(k, -h))) / (2.0 * h);
        assert!(
            (d.eps - fd).abs() < 1e-6 * (1.0 + fd.abs()),
            "coordinate {k}: {} vs {fd}",
            d.eps
        );
        assert!((d.re - f64_fn(nudged(k, 0.0))).abs() < 1e-12);
    }
}

#[test]
fn extrapolated_points_differentiate() {
    check(
        |p| {
            spline(p)
                .extrapolated(CurveEnd::End, 1.4)
                .unwrap()
                .point(1.3)
                .unwrap()
                .y
        },
        |p| {
            spline(p)
                .extrapolated(CurveEnd::End, Dual64::from(1.4))
                .unwrap()
                .point(Dual64::from(1.3))
                .unwrap()
                .y
        },
    );
}

#[test]
fn interpolants_differentiate() {
    check(
        |p| {
            let fit = interpolate(&p, 3, ParameterMethod::ChordLength, None).unwrap();
            fit.curve.point(0.37).unwrap().x
        },
        |p| {
            let fit = interpolate(&p, 3, ParameterMethod::ChordLength, None).unwrap();
            fit.curve.point(Dual64::from(0.37)).unwrap().x
        },
    );
}

#[test]
fn parameters_at_a_length_differentiate() {
    check(
        |p| parameter_at_length(&spline(p), 3.0, 1e-13).unwrap(),
        |p| parameter_at_length(&spline(p), Dual64::from(3.0), 1e-13).unwrap(),
    );
}
