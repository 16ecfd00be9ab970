//! DOF analysis on known cases: free counts, redundant and conflicting constraints by name.
#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

mod common;

use camber_solve::{solve_linear, ConstraintId, Error, Options, Problem};
use common::row;

/// Two 2D points p and q (blocks) in a fresh problem.
fn two_points() -> (Problem, camber_solve::BlockId, camber_solve::BlockId) {
    let mut p = Problem::new();
    let a = p.add_block(&[0.0, 0.0]).unwrap();
    let b = p.add_block(&[1.0, 1.0]).unwrap();
    (p, a, b)
}

#[test]
fn free_points_have_full_dof() {
    let (p, _, _) = two_points();
    let a = p.analyze(&Options::default()).unwrap();
    assert_eq!((a.free_unknowns, a.rank, a.dof), (4, 0, 4));
}

#[test]
fn fixing_and_constraining_removes_dof() {
    let (mut p, a, b) = two_points();
    p.fix_block(a).unwrap();
    // q_x − p_x = 2 (one row over both blocks; p is fixed so only q_x moves).
    p.add_residual(row(&[-1.0, 0.0, 1.0, 0.0], 2.0), &[a, b], ConstraintId(1))
        .unwrap();
    let d = p.analyze(&Options::default()).unwrap();
    assert_eq!((d.free_unknowns, d.rank, d.dof), (2, 1, 1));
    assert!(d.redundant.is_empty() && d.conflicting.is_empty());
}

#[test]
fn duplicated_row_is_redundant_and_named() {
    let (mut p, a, b) = two_points();
    p.add_residual(row(&[1.0, 0.0, -1.0, 0.0], 0.0), &[a, b], ConstraintId(10))
        .unwrap();
    p.add_residual(row(&[0.0, 1.0], 3.0), &[a], ConstraintId(11))
        .unwrap();
    // The same as constraint 10, scaled: consistent.
    p.add_residual(row(&[-2.0, 0.0, 2.0, 0.0], 0.0), &[a, b], ConstraintId(12))
        .unwrap();
    let d = p.analyze(&Options::default()).unwrap();
    assert_eq!((d.rank, d.dof), (2, 2));
    assert_eq!(d.redundant, vec![ConstraintId(12)]);
    assert!(d.conflicting.is_empty());
    // The solve drops it and reports it …
    let report = solve_linear(&mut p, &Options::default()).unwrap();
    assert_eq!(report.redundant, vec![ConstraintId(12)]);
    assert!(report.reason.contains("redundant"));
    assert!(report.residuals.iter().all(|r| r.max_abs < 1e-12));
    // … or refuses when asked not to drop.
    let (mut q, a, b) = two_points();
    q.add_residual(row(&[1.0, 0.0, -1.0, 0.0], 0.0), &[a, b], ConstraintId(10))
        .unwrap();
    q.add_residual(row(&[1.0, 0.0, -1.0, 0.0], 0.0), &[a, b], ConstraintId(13))
        .unwrap();
    let err = solve_linear(&mut q, &Options::default().with_drop_redundant(false)).unwrap_err();
    assert_eq!(
        err,
        Error::Redundant {
            constraints: vec![ConstraintId(13)]
        }
    );
    assert_eq!(q.values(), &[0.0, 0.0, 1.0, 1.0]);
}

#[test]
fn contradictory_rows_conflict_and_are_named() {
    let (mut p, a, b) = two_points();
    p.add_residual(row(&[1.0, 0.0], 1.0), &[a], ConstraintId(20))
        .unwrap();
    p.add_residual(row(&[1.0, 0.0], 2.0), &[a], ConstraintId(21))
        .unwrap();
    p.add_residual(row(&[0.0, 0.0, 0.0, 1.0], 5.0), &[a, b], ConstraintId(22))
        .unwrap();
    let d = p.analyze(&Options::default()).unwrap();
    assert_eq!(d.conflicting, vec![ConstraintId(21)]);
    assert!(d.redundant.is_empty());
    let before = p.values().to_vec();
    let err = solve_linear(&mut p, &Options::default()).unwrap_err();
    assert_eq!(
        err,
        Error::Conflicting {
            constraints: vec![ConstraintId(21)]
        }
    );
    assert_eq!(p.values(), before.as_slice());
}

#[test]
fn a_violated_constraint_on_fixed_unknowns_conflicts() {
    let (mut p, a, _) = two_points();
    p.fix_block(a).unwrap();
    p.add_residual(row(&[1.0, 1.0], 1.0), &[a], ConstraintId(30))
        .unwrap();
    let d = p.analyze(&Options::default()).unwrap();
    assert_eq!((d.rank, d.conflicting.clone()), (0, vec![ConstraintId(30)]));
}

#[test]
fn a_dependent_constraint_names_the_constraints_it_depends_on() {
    // Over one point (x, y): x = 1 (constraint 1), y = 2 (2), x + y = 3 (3)
    // and 2x = 2 (4). Row 3 is row 1 + row 2; row 4 is 2 × row 1.
    let mut p = Problem::new();
    let b = p.add_block(&[0.0, 0.0]).unwrap();
    p.add_residual(row(&[1.0, 0.0], 1.0), &[b], ConstraintId(1))
        .unwrap();
    p.add_residual(row(&[0.0, 1.0], 2.0), &[b], ConstraintId(2))
        .unwrap();
    p.add_residual(row(&[1.0, 1.0], 3.0), &[b], ConstraintId(3))
        .unwrap();
    p.add_residual(row(&[2.0, 0.0], 2.0), &[b], ConstraintId(4))
        .unwrap();
    let d = p.analyze(&Options::default()).unwrap();
    assert_eq!(d.redundant, vec![ConstraintId(3), ConstraintId(4)]);
    let on = |c: u64| {
        d.depends_on
            .iter()
            .find(|x| x.constraint == ConstraintId(c))
            .unwrap()
            .on
            .clone()
    };
    assert_eq!(on(3), vec![ConstraintId(1), ConstraintId(2)]);
    assert_eq!(on(4), vec![ConstraintId(1)]);
}

#[test]
fn structure_names_the_over_determined_constraints() {
    let (mut p, a, b) = two_points();
    // p_x = 1 twice (over-determined by structure), p_y + q_x + q_y = 3 (under-determined).
    p.add_residual(row(&[1.0, 0.0], 1.0), &[a], ConstraintId(1))
        .unwrap();
    p.add_residual(row(&[1.0, 0.0], 1.0), &[a], ConstraintId(2))
        .unwrap();
    p.add_residual(row(&[0.0, 1.0, 1.0, 1.0], 3.0), &[a, b], ConstraintId(3))
        .unwrap();
    let d = p.analyze(&Options::default()).unwrap();
    assert_eq!(d.redundant, vec![ConstraintId(2)]);
    let s = &d.structure;
    assert_eq!(s.structural_rank, 2);
    assert_eq!(s.over_determined_rows, vec![0, 1]);
    assert_eq!(
        s.over_determined_constraints,
        vec![ConstraintId(1), ConstraintId(2)]
    );
    assert_eq!(s.under_determined_unknowns, vec![1, 2, 3]);
    assert_eq!((s.well_determined_rows, s.square_blocks), (0, 0));
    // Only the two rows on p_x needed a numeric test together.
    assert_eq!((s.coupled_rows, s.largest_coupled_piece), (2, 2));
}
