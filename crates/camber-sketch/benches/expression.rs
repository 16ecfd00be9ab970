//! An expression constraint against the same residual written in Rust: values, exact
//! Jacobian (dual numbers) and weighted Hessian (hyper-dual numbers) through the solver's own
//! entry points (`DynResidual`), for a point distance (1 row, 2 points) and a curvature-like
//! row at a free curve parameter (a cubic B-spline of 6 control points, a circle, a point).
//!
//! `cargo bench -p camber-sketch --bench expression`; the target is the expression
//! within 2× of the Rust residual.

use camber_geom::{BSplineCurve2, KnotVector};
use camber_sketch::constraints::expression::{ExprArg, ExprBlock, Expression};
use camber_sketch::curve_eval::CurveBasis;
use camber_sketch::Sketch;
use camber_solve::scalar::cst;
use camber_solve::{DynResidual, Residual, Scalar};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use nalgebra::Point2;
use std::hint::black_box;

/// (|P − Q|² − 4)/4, written in Rust.
#[derive(Debug)]
struct Gap;

impl Residual for Gap {
    fn name(&self) -> &str {
        "gap"
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (dx, dy) = (x[0][0] - x[1][0], x[0][1] - x[1][1]);
        out[0] = (dx * dx + dy * dy - cst::<T>(4.0)) / cst::<T>(4.0);
    }
}

/// cross(C′(s), C(s) − c) − r·|C′(s)| and dot(C″(0.3), P − c) + sin(s)·r², in Rust over the
/// expression's block layout.
#[derive(Debug)]
struct Probe {
    basis: CurveBasis,
    controls: Vec<usize>,
    center: usize,
    radius: usize,
    point: usize,
    s: usize,
    sizes: Vec<usize>,
}

impl Residual for Probe {
    fn name(&self) -> &str {
        "probe"
    }
    fn dim(&self) -> usize {
        2
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(self.sizes.clone())
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let mut pts: [&[T]; 6] = [&[]; 6];
        for (p, b) in pts.iter_mut().zip(&self.controls) {
            *p = x[*b];
        }
        let s = x[self.s][0];
        let [c, d1, _] = self.basis.eval2(&pts, s);
        let [_, _, dd] = self.basis.eval2(&pts, cst(0.3));
        let (k, r, p) = (x[self.center], x[self.radius][0], x[self.point]);
        let cross = d1[0] * (c[1] - k[1]) - d1[1] * (c[0] - k[0]);
        out[0] = cross - r * (d1[0] * d1[0] + d1[1] * d1[1]).sqrt();
        out[1] = dd[0] * (p[0] - k[0]) + dd[1] * (p[1] - k[1]) + s.sin() * r * r;
    }
}

fn sketch() -> (Sketch, [camber_sketch::EntityId; 5]) {
    let mut s = Sketch::new();
    let pts = [
        [0.0, 0.0],
        [1.0, 1.5],
        [2.0, -0.5],
        [3.0, 1.0],
        [4.0, 0.5],
        [5.0, 0.0],
    ];
    let c = BSplineCurve2::try_new(
        3,
        KnotVector::clamped_uniform(3, pts.len()).expect("knots"),
        pts.iter().map(|p| Point2::new(p[0], p[1])).collect(),
    )
    .expect("curve");
    let curve = s.add_bspline(c).expect("curve");
    let circle = s.add_circle(Point2::new(2.0, 3.0), 0.8).expect("circle");
    let point = s.add_point(Point2::new(-1.0, 2.0)).expect("point");
    let p = s.add_point(Point2::new(0.1, 0.2)).expect("p");
    let q = s.add_point(Point2::new(1.9, 0.7)).expect("q");
    (s, [curve, circle, point, p, q])
}

fn values_of(s: &Sketch, layout: &[ExprBlock]) -> Vec<Vec<f64>> {
    layout
        .iter()
        .map(|b| match b {
            ExprBlock::Point(e, j) => {
                let p = s.entity(*e).expect("entity").points()[*j];
                vec![p.x, p.y]
            }
            ExprBlock::Radius(_) => vec![0.8],
            ExprBlock::Free { start, .. } => vec![*start],
        })
        .collect()
}

fn compare(
    c: &mut Criterion,
    group: &str,
    expr: &dyn DynResidual,
    rust: &dyn DynResidual,
    x: &[Vec<f64>],
) {
    let refs: Vec<&[f64]> = x.iter().map(Vec::as_slice).collect();
    let n: usize = x.iter().map(Vec::len).sum();
    let m = expr.dim();
    let active = vec![true; x.len()];
    let weights = vec![1.0; m];
    let mut g = c.benchmark_group(group);
    for (name, r) in [("expression", expr), ("rust", rust)] {
        let (mut v, mut j, mut h) = (vec![0.0; m], vec![0.0; m * n], vec![0.0; n * n]);
        g.bench_function(BenchmarkId::new("values", name), |b| {
            b.iter(|| r.values(black_box(&refs), &mut v))
        });
        g.bench_function(BenchmarkId::new("jacobian", name), |b| {
            b.iter(|| r.jacobian_active(black_box(&refs), &active, &mut v, &mut j))
        });
        g.bench_function(BenchmarkId::new("hessian", name), |b| {
            b.iter(|| r.weighted_hessian(black_box(&refs), &weights, &active, &mut h))
        });
    }
    g.finish();
}

fn bench(c: &mut Criterion) {
    let (s, [curve, circle, point, p, q]) = sketch();
    let gap = Expression::new("gap", &["(dot(P - Q, P - Q) - 4) / 4"])
        .with_arg("P", ExprArg::Point(p))
        .with_arg("Q", ExprArg::Point(q));
    let (expr, layout) = gap.residual_for(&s).expect("gap");
    compare(c, "distance", &expr, &Gap, &values_of(&s, &layout));

    let probe = Expression::new(
        "probe",
        &[
            "cross(C'(s), C(s) - K.center) - K.radius * norm(C'(s))",
            "dot(C''(0.3), P - K.center) + sin(s) * K.radius^2",
        ],
    )
    .with_arg("C", ExprArg::Curve(curve))
    .with_arg("K", ExprArg::Circle(circle))
    .with_arg("P", ExprArg::Point(point))
    .with_arg("s", ExprArg::Free(0.4));
    let (expr, layout) = probe.residual_for(&s).expect("probe");
    let find = |b: ExprBlock| layout.iter().position(|l| *l == b).expect("block");
    let rust = Probe {
        basis: CurveBasis::of(s.entity(curve).expect("curve")).expect("basis"),
        controls: (0..6).map(|j| find(ExprBlock::Point(curve, j))).collect(),
        center: find(ExprBlock::Point(circle, 0)),
        radius: find(ExprBlock::Radius(circle)),
        point: find(ExprBlock::Point(point, 0)),
        s: layout
            .iter()
            .position(|l| matches!(l, ExprBlock::Free { .. }))
            .expect("s"),
        sizes: layout
            .iter()
            .map(|l| {
                if matches!(l, ExprBlock::Point(..)) {
                    2
                } else {
                    1
                }
            })
            .collect(),
    };
    compare(c, "curve_probe", &expr, &rust, &values_of(&s, &layout));
}

criterion_group!(benches, bench);
criterion_main!(benches);
