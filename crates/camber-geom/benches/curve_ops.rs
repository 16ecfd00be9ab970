//! Cost of the curve toolkit's searches and fits: curve–curve intersection and distance
//! (cubic Bézier pairs, 10-point cubic B-splines crossing several times, a composite curve of a
//! Bézier, a NURBS arc and a B-spline against a B-spline, a parabola facing a NURBS circle), and
//! interpolation, least squares and fitting to a tolerance through 100 and 1000 points.

// Fixed, valid inputs: a panic is the right way for a benchmark to fail.
#![allow(clippy::unwrap_used)]

use camber_geom::budget::Budget;
use camber_geom::fit::{
    approximate, fit_to_tolerance, fit_to_tolerance_with, interpolate, FitOptions, ParameterMethod,
};
use camber_geom::queries::{curve_distance, intersect_curves, CurveCurveOptions};
use camber_geom::{
    BSplineCurve2, BezierCurve2, CompositeCurve, CompositeCurve2, KnotVector, NurbsCurve2,
};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use nalgebra::Point2;
use std::hint::black_box;

/// A wave y = amplitude·sin(k·x) on x ∈ [0, 1] as a cubic B-spline through 10 points.
fn wave(amplitude: f64, k: f64, shift: f64) -> BSplineCurve2<f64> {
    let points = (0..10)
        .map(|i| {
            let x = f64::from(i) / 9.0;
            Point2::new(x, amplitude * (k * x + shift).sin())
        })
        .collect();
    BSplineCurve2::try_new(3, KnotVector::clamped_uniform(3, 10).unwrap(), points).unwrap()
}

/// A cubic Bézier from (0, 0) to (3, 0), the quarter circle about (3, 1) up to (4, 1) (NURBS) and
/// a wave from (4, 1) (B-spline): three kinds under one parameter [0, 3].
fn composite() -> CompositeCurve2<f64> {
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let arc = NurbsCurve2::try_new(
        2,
        KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]).unwrap(),
        vec![
            Point2::new(3.0, 0.0),
            Point2::new(4.0, 0.0),
            Point2::new(4.0, 1.0),
        ],
        vec![1.0, w, 1.0],
    )
    .unwrap();
    let tail = wave(0.2, 12.0, 0.0);
    let tail = BSplineCurve2::try_new(
        3,
        tail.knots().clone(),
        tail.control_points()
            .iter()
            .map(|p| Point2::new(p.x + 4.0, p.y + 1.0))
            .collect(),
    )
    .unwrap();
    CompositeCurve::try_new(vec![
        Box::new(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 0.0),
                Point2::new(1.0, 3.0),
                Point2::new(2.0, -3.0),
                Point2::new(3.0, 0.0),
            ])
            .unwrap(),
        ),
        Box::new(arc),
        Box::new(tail),
    ])
    .unwrap()
}

/// The full circle about `c` of radius `r` as a rational quadratic NURBS of nine points.
fn circle(c: (f64, f64), r: f64) -> NurbsCurve2<f64> {
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let dirs = [
        (1.0, 0.0),
        (1.0, 1.0),
        (0.0, 1.0),
        (-1.0, 1.0),
        (-1.0, 0.0),
        (-1.0, -1.0),
        (0.0, -1.0),
        (1.0, -1.0),
        (1.0, 0.0),
    ];
    let points = dirs
        .iter()
        .map(|&(x, y)| Point2::new(c.0 + r * x, c.1 + r * y))
        .collect();
    let weights = (0..9).map(|i| if i % 2 == 0 { 1.0 } else { w }).collect();
    let knots = vec![
        0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
    ];
    NurbsCurve2::try_new(2, KnotVector::try_new(knots).unwrap(), points, weights).unwrap()
}

fn bench_intersection(c: &mut Criterion) {
    let opts = CurveCurveOptions::default();
    let mut group = c.benchmark_group("intersect");
    let a = BezierCurve2::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 3.0),
        Point2::new(2.0, -3.0),
        Point2::new(3.0, 0.0),
    ])
    .unwrap();
    let b = BezierCurve2::try_new(vec![
        Point2::new(0.0, 1.0),
        Point2::new(1.0, -2.0),
        Point2::new(2.0, 2.0),
        Point2::new(3.0, -1.0),
    ])
    .unwrap();
    let hits = intersect_curves(&a, &b, &opts).unwrap().len();
    group.bench_function(
        BenchmarkId::new("bezier_cubics", format!("{hits}_hits")),
        |bench| bench.iter(|| intersect_curves(black_box(&a), black_box(&b), &opts).unwrap()),
    );
    let (s, t) = (wave(0.2, 12.0, 0.0), wave(0.2, 12.0, 1.0));
    let hits = intersect_curves(&s, &t, &opts).unwrap().len();
    group.bench_function(
        BenchmarkId::new("bspline_waves", format!("{hits}_hits")),
        |bench| bench.iter(|| intersect_curves(black_box(&s), black_box(&t), &opts).unwrap()),
    );
    let chain = composite();
    let across = BSplineCurve2::try_new(
        3,
        KnotVector::clamped_uniform(3, 10).unwrap(),
        (0..10)
            .map(|i| {
                let x = 5.0 * f64::from(i) / 9.0;
                Point2::new(x, 0.8 * (3.0 * x).sin() + 0.5)
            })
            .collect(),
    )
    .unwrap();
    let hits = intersect_curves(&chain, &across, &opts).unwrap().len();
    group.bench_function(
        BenchmarkId::new("composite_vs_bspline", format!("{hits}_hits")),
        |bench| {
            bench.iter(|| intersect_curves(black_box(&chain), black_box(&across), &opts).unwrap())
        },
    );
    group.finish();

    let mut group = c.benchmark_group("distance");
    // The closest stretches nearly parallel: the case the boxes alone could not settle.
    let parabola = BezierCurve2::try_new(vec![
        Point2::new(1.0, 1.0),
        Point2::new(1.5, 1.0),
        Point2::new(2.0, 2.0),
    ])
    .unwrap();
    let round = circle((3.0, 0.0), 0.5);
    group.bench_function("parabola_facing_circle", |bench| {
        bench.iter(|| curve_distance(black_box(&parabola), black_box(&round), &opts).unwrap())
    });
    let apart = wave(0.2, 12.0, 0.0);
    let lifted = BSplineCurve2::try_new(
        3,
        apart.knots().clone(),
        apart
            .control_points()
            .iter()
            .map(|p| Point2::new(p.x, p.y + 0.7))
            .collect(),
    )
    .unwrap();
    group.bench_function("bspline_waves_apart", |bench| {
        bench.iter(|| curve_distance(black_box(&apart), black_box(&lifted), &opts).unwrap())
    });
    group.finish();
}

/// `n` samples of a blade-like profile.
fn samples(n: usize) -> Vec<Point2<f64>> {
    (0..n)
        .map(|i| {
            let t = i as f64 / (n - 1) as f64;
            Point2::new(
                t,
                0.12 * (std::f64::consts::PI * t).sin() + 0.01 * (9.0 * t).sin(),
            )
        })
        .collect()
}

fn bench_fitting(c: &mut Criterion) {
    let mut group = c.benchmark_group("fit");
    group.sample_size(20);
    for n in [100, 1000] {
        let pts = samples(n);
        group.bench_with_input(BenchmarkId::new("interpolate_cubic", n), &pts, |b, pts| {
            b.iter(|| interpolate(black_box(pts), 3, ParameterMethod::ChordLength, None).unwrap())
        });
        group.bench_with_input(BenchmarkId::new("least_squares_20cp", n), &pts, |b, pts| {
            b.iter(|| {
                approximate(black_box(pts), 3, 20, ParameterMethod::ChordLength, true).unwrap()
            })
        });
        group.bench_with_input(BenchmarkId::new("to_tolerance_1e-5", n), &pts, |b, pts| {
            b.iter(|| {
                fit_to_tolerance(black_box(pts), 3, 1e-5, ParameterMethod::ChordLength).unwrap()
            })
        });
    }
    // A 400-point NACA section (the target: at most 5 ms per section) at the three tolerances
    // of the airfoil benchmark.
    let section =
        camber_workloads::airfoils::naca("2412", 400, camber_workloads::airfoils::Spacing::Cosine)
            .unwrap();
    for tol in [1e-3, 1e-4, 1e-5] {
        group.bench_with_input(
            BenchmarkId::new("naca2412_400", format!("{tol:e}")),
            &section,
            |b, pts| {
                b.iter(|| {
                    fit_to_tolerance_with(
                        black_box(pts),
                        tol,
                        &FitOptions::default(),
                        &Budget::default(),
                    )
                    .unwrap()
                })
            },
        );
    }
    group.finish();
}

criterion_group!(benches, bench_intersection, bench_fitting);
criterion_main!(benches);
