//! The linear minimum-norm solve against hand-derived cases and an independent SVD
//! pseudo-inverse.
#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

mod common;

use approx::assert_relative_eq;
use camber_solve::{solve_linear, ConstraintId, Options, Problem, SolverKind, Var};
use common::{row, Affine};
use nalgebra::{DMatrix, DVector};
use proptest::prelude::*;

#[test]
fn one_linear_equation_moves_along_its_normal() {
    // a·x = b from x₀: Δx = a(b − a·x₀)/|a|².
    let a = [2.0, -1.0, 0.5];
    let x0 = [1.0, 1.0, 1.0];
    let b = 4.0;
    let mut p = Problem::new();
    let blk = p.add_block(&x0).unwrap();
    p.add_residual(row(&a, b), &[blk], ConstraintId(1)).unwrap();
    let report = solve_linear(&mut p, &Options::default()).unwrap();
    let ax0: f64 = a.iter().zip(&x0).map(|(p, q)| p * q).sum();
    let norm2: f64 = a.iter().map(|v| v * v).sum();
    for k in 0..3 {
        assert_relative_eq!(
            p.values()[k],
            x0[k] + a[k] * (b - ax0) / norm2,
            epsilon = 1e-14
        );
    }
    assert_eq!(report.solver, SolverKind::DenseMinNorm);
    assert_eq!((report.rank, report.dof, report.iterations), (1, 2, 1));
    assert_relative_eq!(
        report.displacement_norm,
        (b - ax0).abs() / norm2.sqrt(),
        epsilon = 1e-14
    );
    assert!(report.residuals[0].max_abs < 1e-12);
}

#[test]
fn weights_change_the_split() {
    // x + y = 3 from (0, 0): with W = diag(1, w) the move is (w, 1)·3/(1 + w).
    for w in [1.0, 2.0, 9.0] {
        let mut p = Problem::new();
        let blk = p.add_block(&[0.0, 0.0]).unwrap();
        let y = p.unknown(blk, 1).unwrap();
        p.set_weight(Var::Unknown(y), w).unwrap();
        p.add_residual(row(&[1.0, 1.0], 3.0), &[blk], ConstraintId(1))
            .unwrap();
        solve_linear(&mut p, &Options::default()).unwrap();
        assert_relative_eq!(p.values()[0], 3.0 * w / (1.0 + w), epsilon = 1e-13);
        assert_relative_eq!(p.values()[1], 3.0 / (1.0 + w), epsilon = 1e-13);
    }
}

/// A random affine problem: `blocks` blocks of 2 unknowns, rows M·x = b with m ≤ n.
/// (x₀, M, b, a random vector v, weights w).
type Case = (Vec<f64>, DMatrix<f64>, Vec<f64>, Vec<f64>, Vec<f64>);

fn problem_strategy() -> impl Strategy<Value = Case> {
    (1_usize..5).prop_flat_map(|blocks| {
        let n = 2 * blocks;
        (1..=n).prop_flat_map(move |m| {
            (
                prop::collection::vec(-3.0..3.0_f64, n),
                prop::collection::vec(-2.0..2.0_f64, m * n),
                prop::collection::vec(-3.0..3.0_f64, m),
                prop::collection::vec(-1.0..1.0_f64, n),
                prop::collection::vec(0.2..5.0_f64, n),
            )
                .prop_map(move |(x0, mm, b, v, w)| {
                    (x0, DMatrix::from_row_slice(m, n, &mm), b, v, w)
                })
        })
    })
}

fn build(x0: &[f64], m: &DMatrix<f64>, b: &[f64], weights: Option<&[f64]>) -> Problem {
    let mut p = Problem::new();
    let ids: Vec<_> = x0.chunks(2).map(|c| p.add_block(c).unwrap()).collect();
    // One constraint per row, each reading every block.
    for (i, bi) in b.iter().enumerate() {
        let r = Affine {
            m: m.rows(i, 1).into_owned(),
            b: vec![*bi],
        };
        p.add_residual(r, &ids, ConstraintId(i as u64)).unwrap();
    }
    if let Some(w) = weights {
        for (k, wk) in w.iter().enumerate() {
            let u = p.unknown(ids[k / 2], k % 2).unwrap();
            p.set_weight(Var::Unknown(u), *wk).unwrap();
        }
    }
    p
}

fn well_conditioned(m: &DMatrix<f64>) -> bool {
    let s = m.clone().singular_values();
    let (lo, hi) = (s.min(), s.max());
    hi > 0.0 && lo / hi > 1e-3
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn displacement_is_the_pseudo_inverse_step((x0, m, b, v, _w) in problem_strategy()) {
        prop_assume!(well_conditioned(&m));
        let mut p = build(&x0, &m, &b, None);
        solve_linear(&mut p, &Options::default()).unwrap();
        let x0v = DVector::from_column_slice(&x0);
        let x1 = DVector::from_column_slice(p.values());
        let dx = &x1 - &x0v;
        // The constraints hold.
        let r = &m * &x1 - DVector::from_column_slice(&b);
        prop_assert!(r.amax() < 1e-9, "residual {}", r.amax());
        // The independent SVD pseudo-inverse gives the same step.
        let pinv = m.clone().pseudo_inverse(1e-12).unwrap();
        let want = &pinv * (DVector::from_column_slice(&b) - &m * &x0v);
        prop_assert!((&dx - &want).amax() < 1e-9);
        // Adding any null-space vector never shortens it.
        let v = DVector::from_column_slice(&v);
        let null = &v - &pinv * (&m * &v);
        prop_assert!((&m * &null).amax() < 1e-9);
        // (Relative: for a square, nearly singular M the null-space vector is rounding noise.)
        prop_assert!(dx.norm() <= (&dx + &null).norm() + 1e-12 * (1.0 + dx.norm()));
    }

    #[test]
    fn weighted_step_matches_the_rescaled_pseudo_inverse((x0, m, b, _v, w) in problem_strategy()) {
        prop_assume!(well_conditioned(&m));
        let mut p = build(&x0, &m, &b, Some(&w));
        solve_linear(&mut p, &Options::default()).unwrap();
        // With y = W^½·x the weighted problem is the plain one for M·W^-½.
        let s = DVector::from_iterator(w.len(), w.iter().map(|wk| 1.0 / wk.sqrt()));
        let ms = &m * DMatrix::from_diagonal(&s);
        let x0v = DVector::from_column_slice(&x0);
        let g = DVector::from_column_slice(&b) - &m * &x0v;
        let dy = ms.clone().pseudo_inverse(1e-12).unwrap() * g;
        let want = dy.component_mul(&s);
        let dx = DVector::from_column_slice(p.values()) - x0v;
        prop_assert!((&dx - &want).amax() < 1e-8);
    }

    #[test]
    fn sparse_and_dense_paths_agree((x0, m, b, _v, w) in problem_strategy()) {
        prop_assume!(well_conditioned(&m));
        let mut dense = build(&x0, &m, &b, Some(&w));
        let mut sparse = build(&x0, &m, &b, Some(&w));
        let rd = solve_linear(&mut dense, &Options::default()).unwrap();
        let rs = solve_linear(&mut sparse, &Options::default().with_dense_max_unknowns(0)).unwrap();
        prop_assert_eq!(rd.solver, SolverKind::DenseMinNorm);
        prop_assert_eq!(rs.solver, SolverKind::SparseMinNorm);
        for (a, c) in dense.values().iter().zip(sparse.values()) {
            prop_assert!((a - c).abs() < 1e-9 * (1.0 + a.abs()));
        }
    }
}

#[test]
fn sparse_path_on_a_long_chain() {
    // x_{k+1} − x_k = 1 for a chain of 2,000 scalars with x₀ fixed: the unique solution x_k = k,
    // far above the dense threshold and the dense analysis limit.
    let n = 2000;
    let mut p = Problem::new();
    let ids: Vec<_> = (0..n).map(|_| p.add_block(&[0.0]).unwrap()).collect();
    p.fix_block(ids[0]).unwrap();
    for k in 0..n - 1 {
        p.add_residual(
            row(&[-1.0, 1.0], 1.0),
            &[ids[k], ids[k + 1]],
            ConstraintId(k as u64),
        )
        .unwrap();
    }
    let opts = Options::default().with_dense_analysis_max_entries(1000);
    let report = solve_linear(&mut p, &opts).unwrap();
    assert_eq!(report.solver, SolverKind::SparseMinNorm);
    assert_eq!(report.dof, 0);
    for (k, v) in p.values().iter().enumerate() {
        assert_relative_eq!(*v, k as f64, epsilon = 1e-8);
    }
}
