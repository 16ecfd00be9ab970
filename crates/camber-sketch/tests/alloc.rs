//! No heap allocation per drag update once the session is warm (W1 in both forms and the blade section), shown by a
//! counting global allocator (stats_alloc). The file runs without libtest's harness
//! (`harness = false`): the count is of the whole process, and libtest's own threads could
//! allocate while it counts.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use std::alloc::System;

use camber_sketch::{PointRef, TangentForm};
use camber_workloads::{blade, w1, w1_targets};
use nalgebra::Vector2;
use stats_alloc::{Region, StatsAlloc, INSTRUMENTED_SYSTEM};

#[global_allocator]
static GLOBAL: &StatsAlloc<System> = &INSTRUMENTED_SYSTEM;

/// Allocations (and reallocations) since `region` began.
fn allocations(region: &Region<'_, System>) -> usize {
    let s = region.change();
    s.allocations + s.reallocations
}

fn main() {
    drag_updates_do_not_allocate();
    println!("alloc: warm drag updates made no allocation");
}

fn drag_updates_do_not_allocate() {
    for form in [TangentForm::Row, TangentForm::Elimination] {
        let (s, c, _) = w1(form).unwrap();
        let p1 = PointRef::Control(c, 1);
        let targets = w1_targets(s.point(p1).unwrap());
        let mut drag = s.drag(p1).unwrap();
        // Warm up: the first updates size the session's buffers and, at the second step on a
        // kept factorization, write out the dense gain.
        for t in &targets[..3] {
            drag.update(*t).unwrap();
        }
        let region = Region::new(GLOBAL);
        for t in &targets {
            drag.update(*t).unwrap();
        }
        assert_eq!(allocations(&region), 0, "W1 {form:?}");
    }

    let (s, b) = blade().unwrap();
    let p = PointRef::Control(b.leading, 2);
    let start = s.point(p).unwrap();
    let mut drag = s.drag(p).unwrap();
    for k in 0..3 {
        drag.update(start + 0.001 * f64::from(k) * Vector2::new(1.0, 0.5))
            .unwrap();
    }
    let region = Region::new(GLOBAL);
    for k in 0..200 {
        let th = std::f64::consts::TAU * k as f64 / 200.0;
        drag.update(start + 0.01 * Vector2::new(th.cos() - 1.0, th.sin()))
            .unwrap();
    }
    assert_eq!(allocations(&region), 0, "blade");

    // The counter does see allocations.
    let region = Region::new(GLOBAL);
    let v: Vec<u64> = std::hint::black_box(vec![1, 2, 3]);
    assert!(allocations(&region) >= 1 && v.len() == 3);
}
