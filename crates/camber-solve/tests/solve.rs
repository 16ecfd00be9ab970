//! solve_linear end to end: refusals, failures that change nothing, the report, and Jacobians of
//! a nonlinear residual against central differences.
#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

mod common;

use approx::assert_relative_eq;
use camber_solve::scalar::cst;
use camber_solve::{
    solve_linear, ConstraintId, Error, Options, Problem, Residual, Scalar, SolverKind, Status,
};
use common::{row, Nonlinear};

/// x² − 4 = 0, falsely declared affine: the linear step cannot satisfy it.
#[derive(Debug)]
struct LyingSquare;

impl Residual for LyingSquare {
    fn name(&self) -> &str {
        "lying square"
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = x[0][0] * x[0][0] - cst(4.0);
    }
    fn is_affine(&self) -> bool {
        true
    }
}

/// log(x), declared affine, evaluated where it is NaN.
#[derive(Debug)]
struct Log;

impl Residual for Log {
    fn name(&self) -> &str {
        "log"
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = x[0][0].ln();
    }
    fn is_affine(&self) -> bool {
        true
    }
}

#[test]
fn nonlinear_residuals_are_refused_plainly() {
    let mut p = Problem::new();
    let a = p.add_block(&[0.0, 0.0]).unwrap();
    let b = p.add_block(&[1.0, 0.0]).unwrap();
    p.add_residual(row(&[1.0, 0.0], 0.0), &[a], ConstraintId(1))
        .unwrap();
    p.add_residual(Nonlinear { d: 2.0 }, &[a, b], ConstraintId(2))
        .unwrap();
    let err = solve_linear(&mut p, &Options::default()).unwrap_err();
    assert_eq!(
        err,
        Error::NonlinearNotAvailable {
            constraint: ConstraintId(2),
            name: "nonlinear".into()
        }
    );
    assert!(err.to_string().contains("not available yet"));
    assert_eq!(p.values(), &[0.0, 0.0, 1.0, 0.0]);
}

#[test]
fn a_failed_solve_leaves_values_unchanged() {
    let mut p = Problem::new();
    let a = p.add_block(&[1.0]).unwrap();
    let b = p.add_block(&[0.0, 0.0]).unwrap();
    p.add_residual(LyingSquare, &[a], ConstraintId(5)).unwrap();
    p.add_residual(row(&[1.0, 1.0], 1.0), &[b], ConstraintId(6))
        .unwrap();
    let err = solve_linear(&mut p, &Options::default()).unwrap_err();
    match err {
        Error::NotSatisfied { failed } => {
            assert_eq!(failed.len(), 1);
            assert_eq!(failed[0].0, ConstraintId(5));
            // One Newton-like step from 1: x = 1 + 3/2 = 2.5, g = 2.25.
            assert_relative_eq!(failed[0].1, 2.25, epsilon = 1e-12);
        }
        other => panic!("unexpected {other:?}"),
    }
    assert_eq!(p.values(), &[1.0, 0.0, 0.0]);
}

#[test]
fn a_non_finite_residual_is_named() {
    let mut p = Problem::new();
    let a = p.add_block(&[-1.0]).unwrap();
    p.add_residual(Log, &[a], ConstraintId(8)).unwrap();
    let err = solve_linear(&mut p, &Options::default()).unwrap_err();
    assert!(matches!(
        err,
        Error::NonFiniteResidual {
            constraint: ConstraintId(8),
            row: 0,
            ..
        }
    ));
    assert_eq!(p.values(), &[-1.0]);
}

#[test]
fn the_report_describes_the_solve() {
    let mut p = Problem::new();
    let a = p.add_block(&[0.0, 0.0]).unwrap();
    p.add_residual(row(&[1.0, 0.0], 1.0), &[a], ConstraintId(1))
        .unwrap();
    p.add_residual(row(&[0.0, 1.0], 2.0), &[a], ConstraintId(2))
        .unwrap();
    let r = solve_linear(&mut p, &Options::default()).unwrap();
    assert_eq!(r.status, Status::Solved);
    assert_eq!(r.solver, SolverKind::DenseMinNorm);
    assert!(r.reason.contains("dense"));
    assert_eq!((r.iterations, r.rank, r.dof), (1, 2, 0));
    assert_eq!(r.residuals.len(), 2);
    assert_eq!(r.residuals[1].constraint, ConstraintId(2));
    assert_relative_eq!(r.displacement_norm, 5.0_f64.sqrt(), epsilon = 1e-14);
    assert!(r.redundant.is_empty() && r.conflicting.is_empty());
    // A second solve has nothing to do.
    let again = solve_linear(&mut p, &Options::default()).unwrap();
    assert_eq!(again.status, Status::AlreadySatisfied);
    assert_eq!((again.solver, again.iterations), (SolverKind::None, 0));
}

#[test]
fn bad_options_are_errors() {
    let mut p = Problem::new();
    let err = solve_linear(&mut p, &Options::default().with_tolerance(f64::NAN)).unwrap_err();
    assert!(matches!(
        err,
        Error::NonFinite {
            what: "tolerance",
            ..
        }
    ));
    let err = solve_linear(&mut p, &Options::default().with_rank_tolerance(0.0)).unwrap_err();
    assert!(matches!(
        err,
        Error::NonFinite {
            what: "tolerance",
            index: 1,
            ..
        }
    ));
}

#[test]
fn assembled_jacobian_of_a_nonlinear_residual_matches_central_differences() {
    // Blocks p = (0.3, −0.7), q = (1.1, 0.4); q_y fixed, so z = (p_x, p_y, q_x).
    let mut p = Problem::new();
    let a = p.add_block(&[0.3, -0.7]).unwrap();
    let b = p.add_block(&[1.1, 0.4]).unwrap();
    p.fix(p.unknown(b, 1).unwrap()).unwrap();
    p.add_residual(Nonlinear { d: 0.5 }, &[a, b], ConstraintId(1))
        .unwrap();
    let lin = p.linearize().unwrap();
    assert!(!lin.affine);
    let j = lin.jacobian.to_dense();
    assert_eq!(j.shape(), (2, 3));
    let h = 1e-6;
    let unknown_of_z = [0, 1, 2];
    for (col, u) in unknown_of_z.iter().enumerate() {
        let (mut xp, mut xm) = (p.values().to_vec(), p.values().to_vec());
        xp[*u] += h;
        xm[*u] -= h;
        let (mut gp, mut gm) = ([0.0; 2], [0.0; 2]);
        p.evaluate_at(&xp, &mut gp).unwrap();
        p.evaluate_at(&xm, &mut gm).unwrap();
        for r in 0..2 {
            assert_relative_eq!(j[(r, col)], (gp[r] - gm[r]) / (2.0 * h), epsilon = 1e-8);
        }
    }
}

#[cfg(feature = "testing")]
#[test]
fn testing_module_accepts_the_nonlinear_residual() {
    let worst = camber_solve::testing::check_jacobian(
        &Nonlinear { d: 0.5 },
        &[&[0.3, -0.7][..], &[1.1, 0.4][..]],
        1e-6,
        1e-8,
    )
    .unwrap();
    assert!(worst.error < 1e-8);
}

/// |p − q|² − 1 over two declared point blocks.
#[derive(Debug)]
struct DeclaredDistance;

impl Residual for DeclaredDistance {
    fn name(&self) -> &str {
        "declared distance"
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (dx, dy) = (x[1][0] - x[0][0], x[1][1] - x[0][1]);
        out[0] = dx * dx + dy * dy - T::one();
    }
}

/// Issue 12: a residual given fewer (or other) blocks than it reads is refused when it is
/// added, with a typed error naming it, instead of panicking inside its `eval` later.
#[test]
fn declared_block_shapes_are_checked_on_add() {
    let mut p = Problem::new();
    let a = p.add_block(&[0.0, 0.0]).unwrap();
    let s = p.add_block(&[1.0]).unwrap();
    assert_eq!(
        p.add_residual(DeclaredDistance, &[a], ConstraintId(4)),
        Err(Error::BlockShape {
            residual: "declared distance".into(),
            owner: ConstraintId(4),
            expected: vec![2, 2],
            found: vec![2],
        })
    );
    assert!(matches!(
        p.add_residual(DeclaredDistance, &[a, s], ConstraintId(4)),
        Err(Error::BlockShape { .. })
    ));
    assert_eq!(p.num_rows(), 0);
    let b = p.add_block(&[3.0, 4.0]).unwrap();
    p.add_residual(DeclaredDistance, &[a, b], ConstraintId(4))
        .unwrap();
    assert_eq!(p.num_rows(), 1);
}
