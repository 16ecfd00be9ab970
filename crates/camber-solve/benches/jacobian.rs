//! Jacobian of one residual block by autodiff: `Dual64` column passes against one
//! `DualSVec64<N>` pass per block and one pass for the whole residual.
#![allow(missing_docs)] // criterion's macros generate undocumented items

use camber_solve::derive::autodiff::{jacobian_with, JacobianMode};
use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;

/// Coincident points: p − q = 0 (2 rows, blocks 2 + 2).
#[derive(Debug)]
struct Coincident;

impl Residual for Coincident {
    fn name(&self) -> &str {
        "coincident"
    }
    fn dim(&self) -> usize {
        2
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = x[0][0] - x[1][0];
        out[1] = x[0][1] - x[1][1];
    }
    fn is_affine(&self) -> bool {
        true
    }
}

/// Directional tangency of a cubic Bézier at u: cross(C′(u), T) = 0 (1 row, 4 blocks of 2).
#[derive(Debug)]
struct BezierTangent {
    u: f64,
    t: [f64; 2],
}

impl Residual for BezierTangent {
    fn name(&self) -> &str {
        "bezier tangent"
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let u = self.u;
        let w = [
            3.0 * (1.0 - u) * (1.0 - u),
            6.0 * u * (1.0 - u),
            3.0 * u * u,
        ];
        let (mut dx, mut dy) = (T::zero(), T::zero());
        for k in 0..3 {
            dx += cst::<T>(w[k]) * (x[k + 1][0] - x[k][0]);
            dy += cst::<T>(w[k]) * (x[k + 1][1] - x[k][1]);
        }
        out[0] = dx * cst(self.t[1]) - dy * cst(self.t[0]);
    }
    fn is_affine(&self) -> bool {
        true
    }
}

/// Distance between two 3D points equals d (nonlinear, 1 row, blocks 3 + 3).
#[derive(Debug)]
struct Distance3 {
    d: f64,
}

impl Residual for Distance3 {
    fn name(&self) -> &str {
        "distance"
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let mut s = T::zero();
        for (a, b) in x[0].iter().zip(x[1]) {
            let d = *b - *a;
            s += d * d;
        }
        out[0] = s.sqrt() - cst(self.d);
    }
}

/// A point of a degree-3 curve at fixed weights, from one block of n control coordinates
/// (x₀, y₀, x₁, y₁, …) minus a target (2 rows, one block of n).
#[derive(Debug)]
struct CurvePoint {
    weights: Vec<f64>,
}

impl Residual for CurvePoint {
    fn name(&self) -> &str {
        "curve point"
    }
    fn dim(&self) -> usize {
        2
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (mut px, mut py) = (cst::<T>(-1.0), cst::<T>(-2.0));
        for (k, w) in self.weights.iter().enumerate() {
            px += cst::<T>(*w) * x[0][2 * k];
            py += cst::<T>(*w) * x[0][2 * k + 1];
        }
        out[0] = px;
        out[1] = py;
    }
    fn is_affine(&self) -> bool {
        true
    }
}

fn run<R: Residual>(c: &mut Criterion, group: &str, r: &R, blocks: &[Vec<f64>]) {
    let x: Vec<&[f64]> = blocks.iter().map(|b| b.as_slice()).collect();
    let n: usize = blocks.iter().map(Vec::len).sum();
    let mut values = vec![0.0; r.dim()];
    let mut jac = vec![0.0; r.dim() * n];
    let mut g = c.benchmark_group(group);
    for (label, mode) in [
        ("dual64_columns", JacobianMode::Columns),
        ("dualsvec_per_block", JacobianMode::PerBlock),
        ("dualsvec_whole", JacobianMode::Whole),
    ] {
        g.bench_function(BenchmarkId::new(label, n), |b| {
            b.iter(|| {
                jacobian_with(r, black_box(&x), &mut values, &mut jac, mode).ok();
                black_box(&jac);
            })
        });
    }
    g.finish();
}

fn benches(c: &mut Criterion) {
    run(
        c,
        "coincident_2x(2+2)",
        &Coincident,
        &[vec![0.1, 0.2], vec![0.3, 0.4]],
    );
    run(
        c,
        "bezier_tangent_1x(2+2+2+2)",
        &BezierTangent {
            u: 0.3,
            t: [0.6, 0.8],
        },
        &[
            vec![0.0, 0.0],
            vec![1.0, 2.0],
            vec![3.0, 2.0],
            vec![4.0, 0.0],
        ],
    );
    run(
        c,
        "distance_1x(3+3)",
        &Distance3 { d: 2.0 },
        &[vec![0.0, 0.1, 0.2], vec![1.0, 1.5, -0.5]],
    );
    run(
        c,
        "curve_point_2x8",
        &CurvePoint {
            weights: vec![0.1, 0.4, 0.4, 0.1],
        },
        &[vec![0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0]],
    );
    run(
        c,
        "curve_point_2x16",
        &CurvePoint {
            weights: vec![0.05, 0.1, 0.15, 0.2, 0.2, 0.15, 0.1, 0.05],
        },
        &[(0..16).map(|k| f64::from(k) * 0.25).collect()],
    );
}

criterion_group!(jacobian, benches);
criterion_main!(jacobian);
