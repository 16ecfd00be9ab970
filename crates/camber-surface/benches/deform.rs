//! One G1 deformation solve on a 20 × 20 bicubic net with 3 creased neighbours and 200 samples
//! per edge (setup of the samples, residual assembly, normal equations, sparse Cholesky and the
//! measurement), no refinement round; the 4 × 4 bundled case for comparison.
#![allow(missing_docs)] // criterion's macros generate undocumented items

use camber_surface::examples::{crease_pair, creased_face};
use camber_surface::{deform_to_g1, DeformOptions};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("g1_deformation");
    let case = creased_face(20, 3).expect("benchmark case");
    let options = DeformOptions::default()
        .with_samples_per_edge(200)
        .with_max_refinements(0);
    group.bench_function("net20x20_3neighbours_200samples", |b| {
        b.iter(|| deform_to_g1(black_box(&case.face), black_box(&case.neighbours), &options))
    });
    let (face, nb) = crease_pair(10.0).expect("bundled case");
    let neighbours = [nb];
    let options = DeformOptions::default();
    group.bench_function("net4x4_crease10", |b| {
        b.iter(|| deform_to_g1(black_box(&face), black_box(&neighbours), &options))
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
