//! SLSQP solves free everything they allocate: 10,000 of them in a row leave no allocation
//! behind, counted by a global allocator (stats_alloc). The published nlopt crate leaked each
//! constraint callback's box (8–16 bytes a solve); the workspace patches it (vendor/nlopt,
//! docs/decisions/0012-patched-nlopt.md). The file runs without libtest's harness
//! (`harness = false`): the count is of the whole process, and libtest's main thread, still
//! finishing the spawn of the test thread on a loaded machine, once allocated during the count.
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

fn main() {
    #[cfg(feature = "nlopt")]
    counted::ten_thousand_slsqp_solves_leave_no_allocation_behind();
    #[cfg(not(feature = "nlopt"))]
    println!("slsqp_alloc: skipped (built without the nlopt feature)");
}

#[cfg(feature = "nlopt")]
mod counted {
    use std::alloc::System;

    use camber_solve::scalar::cst;
    use camber_solve::{
        solve, ConstraintId, Options, Problem, Residual, Scalar, SolverChoice, SolverKind,
    };
    use stats_alloc::{Region, StatsAlloc, INSTRUMENTED_SYSTEM};

    #[global_allocator]
    static GLOBAL: &StatsAlloc<System> = &INSTRUMENTED_SYSTEM;

    /// |p − c|² − r² for a point block p.
    #[derive(Debug)]
    struct OnCircle {
        c: [f64; 2],
        r: f64,
    }

    impl Residual for OnCircle {
        fn name(&self) -> &str {
            "on circle"
        }
        fn dim(&self) -> usize {
            1
        }
        fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
            let dx = x[0][0] - cst(self.c[0]);
            let dy = x[0][1] - cst(self.c[1]);
            out[0] = dx * dx + dy * dy - cst(self.r * self.r);
        }
    }

    pub fn ten_thousand_slsqp_solves_leave_no_allocation_behind() {
        let start = [1.5, 0.5];
        let mut p = Problem::new();
        let b = p.add_block(&start).unwrap();
        p.add_residual(
            OnCircle {
                c: [0.0, 0.0],
                r: 1.0,
            },
            &[b],
            ConstraintId(1),
        )
        .unwrap();
        // SLSQP lands on the circle within 6 evaluations here, then its line search circles the
        // answer at the rounding limit for about 1,300 more (NLopt's RoundoffLimited): 30 keep the
        // 10,000 solves a short test and every result valid.
        let mut options = Options::default().with_force(Some(SolverChoice::Slsqp));
        options.nonlinear.slsqp_max_evaluations = 30;
        let run = |p: &mut Problem| {
            p.set_block_values(b, &start).unwrap();
            let report = solve(p, &options).unwrap();
            assert_eq!(report.solver, SolverKind::Slsqp);
        };
        // Warm up: thread-local spares and lazily built statics allocate once.
        for _ in 0..10 {
            run(&mut p);
        }
        let region = Region::new(GLOBAL);
        for _ in 0..10_000 {
            run(&mut p);
        }
        let change = region.change();
        let live = change.allocations as i64 - change.deallocations as i64;
        // stats_alloc books a reallocation's growth in bytes_allocated and its shrinkage in
        // bytes_deallocated (bytes_reallocated is their net, for information).
        let bytes = change.bytes_allocated as i64 - change.bytes_deallocated as i64;
        assert!(change.allocations >= 10_000, "the counter sees the solves");
        assert_eq!((live, bytes), (0, 0), "{change:?}");
        // The solve is right, too: the nearest point of the unit circle.
        let x = p.values();
        let (want_x, want_y) = (1.5 / 2.5_f64.sqrt(), 0.5 / 2.5_f64.sqrt());
        assert!(
            (x[0] - want_x).abs() < 1e-6 && (x[1] - want_y).abs() < 1e-6,
            "{x:?}"
        );
        println!("slsqp_alloc: 10,000 SLSQP solves left no allocation behind");
    }
}
