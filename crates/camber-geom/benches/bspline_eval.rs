//! Evaluation cost of the geometry kernel's hot path: the point and first derivative of a cubic
//! B-spline with 10 control points, in f64 and through `DualSVec64<4>` (the scalar a constraint
//! Jacobian is computed with). Target: ≤ 60 ns per f64 evaluation.

// Fixed, valid inputs: a panic is the right way for a benchmark to fail.
#![allow(clippy::unwrap_used)]

use camber_geom::{BSplineCurve2, KnotVector, ParametricCurve};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use nalgebra::{Const, Point2};
use num_dual::{Derivative, DualSVec64};
use std::hint::black_box;

/// A blade-like cubic with 10 control points on the clamped uniform knots of [0, 1].
fn control_points() -> Vec<[f64; 2]> {
    (0..10)
        .map(|i| {
            let t = f64::from(i) / 9.0;
            [t, 0.12 * (std::f64::consts::PI * t).sin() + 0.02 * t]
        })
        .collect()
}

/// 64 parameters spread over the domain so every knot span is visited.
fn parameters() -> Vec<f64> {
    (0..64).map(|i| (f64::from(i) + 0.5) / 64.0).collect()
}

fn bench_eval(c: &mut Criterion) {
    let params = parameters();
    let mut group = c.benchmark_group("bspline_cubic_10/point_and_derivative");
    group.throughput(Throughput::Elements(params.len() as u64));

    let points: Vec<Point2<f64>> = control_points()
        .into_iter()
        .map(|[x, y]| Point2::new(x, y))
        .collect();
    let curve = BSplineCurve2::try_new(3, KnotVector::clamped_uniform(3, 10).unwrap(), points)
        .expect("valid curve");
    group.bench_function(BenchmarkId::new("f64", params.len()), |b| {
        b.iter(|| {
            for &u in &params {
                black_box(curve.point_and_derivative(black_box(u)).unwrap());
            }
        })
    });

    // Dual numbers with four seeded directions: the x and y of control points 4 and 5, as a
    // constraint Jacobian evaluation would seed them.
    type D4 = DualSVec64<4>;
    let seed = |k: usize| Derivative::derivative_generic(Const::<4>, Const::<1>, k);
    let dual_points: Vec<Point2<D4>> = control_points()
        .into_iter()
        .enumerate()
        .map(|(i, [x, y])| match i {
            4 => Point2::new(D4::new(x, seed(0)), D4::new(y, seed(1))),
            5 => Point2::new(D4::new(x, seed(2)), D4::new(y, seed(3))),
            _ => Point2::new(D4::from(x), D4::from(y)),
        })
        .collect();
    let dual_curve =
        BSplineCurve2::try_new(3, KnotVector::clamped_uniform(3, 10).unwrap(), dual_points)
            .expect("valid curve");
    let dual_params: Vec<D4> = params.iter().map(|&u| D4::from(u)).collect();
    group.bench_function(BenchmarkId::new("DualSVec64<4>", params.len()), |b| {
        b.iter(|| {
            for &u in &dual_params {
                black_box(dual_curve.point_and_derivative(black_box(u)).unwrap());
            }
        })
    });
    group.finish();
}

criterion_group!(benches, bench_eval);
criterion_main!(benches);
