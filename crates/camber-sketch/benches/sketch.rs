//! Benchmarks of the standard workloads on the linear path: W1 (drag update), the blade
//! section (drag update, Jacobian assembly), W3a (G1 chain with fixed tangents, full solve) and
//! W4 (10,000 independent components, one solve); and on the nonlinear path W2 `bspline7`
//! and `2cubic` (three-circle tangency, one solve from each of 100 perturbed starts per δ, valid
//! counts printed), a drag update on the solved diffuser, and W3 (the G1 chain with free joint
//! directions and chord lengths, N = 1,000 and 10,000); and the DOF analysis of large
//! components (the W3 chain, a 100,000-point chain, the fully constrained W5b ladder); and W6,
//! one rectangle's width edited and re-solved among 1,000 solved rectangles.
#![allow(missing_docs)] // criterion's macros generate undocumented items

use camber_sketch::{PointRef, Sketch, TangentForm};
use camber_workloads::{
    blade, w1, w1_targets, w2_2cubic, w2_2cubic_perturbed, w2_2cubic_valid, w2_bspline7,
    w2_perturbed, w2_valid, w3_chain, w3a_chain, w4, w5, w5b,
};
use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion};
use nalgebra::{Point2, Vector2};
use std::hint::black_box;

fn bench_w1(c: &mut Criterion) {
    let mut group = c.benchmark_group("w1_drag_update");
    for (name, form) in [
        ("row", TangentForm::Row),
        ("elimination", TangentForm::Elimination),
    ] {
        let (s, curve, _) = w1(form).expect("valid workload");
        let p1 = PointRef::Control(curve, 1);
        let targets = w1_targets(s.point(p1).expect("point"));
        let mut session = s.drag(p1).expect("draggable");
        let mut k = 0;
        group.bench_function(name, |b| {
            b.iter(|| {
                k = (k + 1) % targets.len();
                session.update(black_box(targets[k])).expect("update");
            })
        });
    }
    group.finish();
}

fn bench_blade(c: &mut Criterion) {
    let (s, b) = blade().expect("valid blade");
    let dragged = PointRef::Control(b.leading, 2);
    let start = s.point(dragged).expect("point");
    let mut session = s.drag(dragged).expect("draggable");
    let mut k = 0_usize;
    c.bench_function("blade_drag_update", |bch| {
        bch.iter(|| {
            k = (k + 1) % 200;
            let th = std::f64::consts::TAU * k as f64 / 200.0;
            let target: Point2<f64> = start + 0.01 * Vector2::new(th.cos() - 1.0, th.sin());
            session.update(black_box(target)).expect("update");
        })
    });
    let cp = s.component_problem(b.leading).expect("problem");
    c.bench_function("blade_jacobian_assembly", |bch| {
        bch.iter(|| black_box(cp.problem().linearize().expect("linearize")))
    });
}

fn bench_w3a(c: &mut Criterion) {
    let mut group = c.benchmark_group("w3a_full_solve");
    group.sample_size(10);
    for n in [100_usize, 1_000, 10_000] {
        let (s, _) = w3a_chain(n).expect("valid chain");
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter_batched(
                || s.clone(),
                |mut s| black_box(s.solve().expect("solve")),
                BatchSize::LargeInput,
            )
        });
    }
    group.finish();
}

fn bench_w4(c: &mut Criterion) {
    let mut group = c.benchmark_group("w4_components");
    group.sample_size(10);
    let (s, _) = w4(10_000).expect("valid workload");
    group.bench_function("10000", |b| {
        b.iter_batched(
            || s.clone(),
            |mut s| black_box(s.solve().expect("solve")),
            BatchSize::LargeInput,
        )
    });
    group.finish();
}

fn bench_w2(c: &mut Criterion) {
    let (mut base, w) = w2_bspline7().expect("valid workload");
    base.solve().expect("the rough start solves");
    bench_w2_solves(
        c,
        "w2_bspline7_solve",
        |delta, seed| w2_perturbed(&base, &w, delta, 100, seed).expect("perturbed starts"),
        |s| w2_valid(s, &w),
    );

    // A drag update on the solved diffuser (nonlinear: warm-started Newton).
    let dragged = PointRef::Control(w.curve, 3);
    let start = base.point(dragged).expect("point");
    let mut session = base.drag(dragged).expect("draggable");
    let mut k = 0_u32;
    c.bench_function("w2_bspline7_drag_update", |b| {
        b.iter(|| {
            k = (k + 1) % 200;
            let dy = 0.0002 * f64::from(k.min(200 - k));
            let _ = session.update(black_box(Point2::new(start.x, start.y + dy)));
        })
    });
}

fn bench_w2_2cubic(c: &mut Criterion) {
    let (mut base, curves, _) = w2_2cubic().expect("valid workload");
    base.solve().expect("the rough start solves");
    bench_w2_solves(
        c,
        "w2_2cubic_solve",
        |delta, seed| {
            w2_2cubic_perturbed(&base, curves, delta, 100, seed).expect("perturbed starts")
        },
        |s| w2_2cubic_valid(s, curves),
    );
}

/// One solve from each of the 100 perturbed starts `starts(δ, seed)` of a W2 representation,
/// for δ = 0.01 and 0.05, with the valid count printed (`valid` is the workload's check).
fn bench_w2_solves(
    c: &mut Criterion,
    group_name: &str,
    starts: impl Fn(f64, u64) -> Vec<Sketch>,
    valid: impl Fn(&Sketch) -> bool,
) {
    let mut group = c.benchmark_group(group_name);
    for (name, delta, seed) in [("delta_0.01", 0.01, 1), ("delta_0.05", 0.05, 2)] {
        let starts = starts(delta, seed);
        let count = starts
            .iter()
            .filter(|s| {
                let mut s = (*s).clone();
                s.solve().is_ok() && valid(&s)
            })
            .count();
        eprintln!("{group_name} {name}: {count} of {} valid", starts.len());
        let mut k = 0;
        group.bench_function(name, |b| {
            b.iter_batched(
                || {
                    k = (k + 1) % starts.len();
                    starts[k].clone()
                },
                |mut s| black_box(s.solve().is_ok()),
                BatchSize::SmallInput,
            )
        });
    }
    group.finish();
}

fn bench_w3(c: &mut Criterion) {
    let mut group = c.benchmark_group("w3_chain_solve");
    group.sample_size(10);
    for n in [1_000_usize, 10_000] {
        let (s, _) = w3_chain(n).expect("valid chain");
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter_batched(
                || s.clone(),
                |mut s| black_box(s.solve().expect("solve")),
                BatchSize::LargeInput,
            )
        });
    }
    group.finish();
}

/// The DOF analysis of large components (issue 13: `check` of W3 at N = 10,000 within 0.5 s,
/// a 100,000-point distance chain within 5 s): the sparse analysis, no dense matrix; and of the
/// fully constrained W5b ladder of 10,000 cells, settled by its blocks with no free-unknown
/// projection.
fn bench_analysis(c: &mut Criterion) {
    let mut group = c.benchmark_group("analyze");
    group.sample_size(10);
    let (w3, _) = w3_chain(10_000).expect("valid chain");
    group.bench_function("w3_chain_10000", |b| {
        b.iter(|| black_box(w3.analyze().expect("analysis")))
    });
    let chain = point_chain(100_000);
    group.bench_function("point_chain_100000", |b| {
        b.iter(|| black_box(chain.analyze().expect("analysis")))
    });
    let (ladder, _) = w5b(10_000).expect("valid ladder");
    group.bench_function("w5b_ladder_10000", |b| {
        b.iter(|| black_box(ladder.analyze().expect("analysis")))
    });
    group.finish();
}

/// `n` points, the first fixed, each at its distance from the next: one component of 2n
/// unknowns and n − 1 nonlinear rows.
fn point_chain(n: usize) -> camber_sketch::Sketch {
    use camber_sketch::constraints::{Distance, Fixed};
    use camber_sketch::PointRef;
    let mut s = camber_sketch::Sketch::new();
    let points: Vec<_> = (0..n)
        .map(|i| {
            let t = i as f64;
            s.add_point(nalgebra::Point2::new(t, 0.1 * (t * 0.7).sin()))
                .expect("finite point")
        })
        .collect();
    s.add_constraint(Fixed::entity(points[0])).expect("fixed");
    for pair in points.windows(2) {
        let (a, b) = (PointRef::Point(pair[0]), PointRef::Point(pair[1]));
        let distance = (s.point(b).expect("point") - s.point(a).expect("point")).norm();
        s.add_constraint(Distance { a, b, distance })
            .expect("distance");
    }
    s
}

fn bench_w6(c: &mut Criterion) {
    let (mut s, layout) = w5(1000).expect("valid workload");
    s.solve().expect("solved");
    let bottom = layout.lines[4 * 500];
    let (width, value) = s
        .constraints()
        .find_map(|(id, c)| match c {
            camber_sketch::Constraint::Distance(d) if d.a == PointRef::Start(bottom) => {
                Some((id, d.distance))
            }
            _ => None,
        })
        .expect("a width");
    let mut k = 0usize;
    c.bench_function("w6_width_edit_1000", |b| {
        b.iter(|| {
            k += 1;
            let w = if k.is_multiple_of(2) {
                value
            } else {
                value + 0.05
            };
            s.set_value(width, black_box(w)).expect("value");
            s.solve().expect("re-solved")
        })
    });
}

criterion_group!(
    benches,
    bench_w6,
    bench_analysis,
    bench_w1,
    bench_blade,
    bench_w2,
    bench_w2_2cubic,
    bench_w3a,
    bench_w3,
    bench_w4
);
criterion_main!(benches);
