//! The curve residuals' structured derivatives (the chain rule through the curve's point and
//! derivatives, camber_solve::derive::composed) against the hyper-dual reference over every unknown and
//! against central differences, at random control points, weights, parameters (inside spans, on
//! knots, at and beyond the ends), multipliers and fixed/moving block patterns, for B-splines,
//! NURBS and composite (Hermite-mapped) curves.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber_geom::{BSplineCurve2, KnotVector, NurbsCurve2};
use camber_sketch::constraints::distance::PointDistance;
use camber_sketch::constraints::g1_join_free::TangentsParallel;
use camber_sketch::constraints::tangent_to_circle::CircleContact;
use camber_sketch::curve_eval::CurveBasis;
use camber_sketch::residuals::Param;
use camber_sketch::{Entity, HermiteChain, Join};
use camber_solve::derive::autodiff::{jacobian_active, jacobian_with, JacobianMode};
use camber_solve::derive::hessian::{hyper_dual_hessian, weighted_hessian};
use camber_solve::Residual;
use nalgebra::{Point2, Vector2};
use proptest::prelude::*;

/// A curve of one of three kinds with `wave` (7 numbers) shaping its control data; its blocks.
fn curve(kind: u8, wave: &[f64]) -> (CurveBasis, Vec<Vec<f64>>) {
    let pts: Vec<Point2<f64>> = (0..5)
        .map(|i| Point2::new(f64::from(i as u8), wave[i]))
        .collect();
    let knots = || KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0]).unwrap();
    let entity = match kind % 3 {
        0 => Entity::BSpline(BSplineCurve2::try_new(3, knots(), pts).unwrap()),
        1 => {
            let w = (0..5)
                .map(|i| 1.0 + 0.4 * wave[(i + 2) % 7].abs())
                .collect();
            Entity::Nurbs(NurbsCurve2::try_new(3, knots(), pts, w).unwrap())
        }
        _ => {
            let nodes = vec![pts[0], pts[2], pts[4]];
            let tangents = vec![
                Vector2::new(1.0, wave[5]),
                Vector2::new(1.5, wave[6]),
                Vector2::new(0.8, -wave[5]),
            ];
            Entity::Composite(HermiteChain::try_new(nodes, tangents, vec![Join::Smooth]).unwrap())
        }
    };
    let blocks = entity.points().iter().map(|p| vec![p.x, p.y]).collect();
    (CurveBasis::of(&entity).unwrap(), blocks)
}

/// Structured Jacobian and Hessian against the dual-number references (and the Hessian's
/// symmetry); `active` picks the moving blocks. Returns the worst scaled differences.
fn compare<R: Residual>(
    r: &R,
    blocks: &[Vec<f64>],
    active: &[bool],
    weights: &[f64],
) -> (f64, f64) {
    let refs: Vec<&[f64]> = blocks.iter().map(|b| &b[..]).collect();
    let n: usize = blocks.iter().map(Vec::len).sum();
    let dim = r.dim();
    let (mut v, mut j) = (vec![0.0; dim], vec![0.0; dim * n]);
    jacobian_active(r, &refs, active, &mut v, &mut j).unwrap();
    let (mut v_ref, mut j_ref) = (vec![0.0; dim], vec![0.0; dim * n]);
    jacobian_with(r, &refs, &mut v_ref, &mut j_ref, JacobianMode::Columns).unwrap();
    // The reference differentiates every column: keep the active ones.
    let mut col = 0;
    for (b, on) in blocks.iter().zip(active) {
        if !on {
            for c in col..col + b.len() {
                for row in 0..dim {
                    j_ref[row * n + c] = 0.0;
                }
            }
        }
        col += b.len();
    }
    let scale_j = j_ref
        .iter()
        .chain(&v_ref)
        .fold(1.0_f64, |m, x| m.max(x.abs()));
    let dj = v
        .iter()
        .zip(&v_ref)
        .chain(j.iter().zip(&j_ref))
        .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()))
        / scale_j;
    let (mut h, mut h_ref) = (vec![0.0; n * n], vec![0.0; n * n]);
    weighted_hessian(r, &refs, weights, active, &mut h).unwrap();
    hyper_dual_hessian(r, &refs, weights, active, &mut h_ref).unwrap();
    let scale_h = h_ref.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
    let mut dh = h
        .iter()
        .zip(&h_ref)
        .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()))
        / scale_h;
    for a in 0..n {
        for b in 0..n {
            dh = dh.max((h[a * n + b] - h[b * n + a]).abs() / scale_h);
        }
    }
    (dj, dh)
}

/// Central differences of the (dual-number) gradient of λ·g against the structured Hessian.
fn hessian_vs_differences<R: Residual>(r: &R, blocks: &[Vec<f64>], weights: &[f64]) -> f64 {
    let n: usize = blocks.iter().map(Vec::len).sum();
    let lens: Vec<usize> = blocks.iter().map(Vec::len).collect();
    let refs: Vec<&[f64]> = blocks.iter().map(|b| &b[..]).collect();
    let grad = |flat: &[f64]| {
        let mut bs = Vec::new();
        let mut at = 0;
        for l in &lens {
            bs.push(&flat[at..at + l]);
            at += l;
        }
        let (mut v, mut j) = (vec![0.0; r.dim()], vec![0.0; r.dim() * n]);
        jacobian_with(r, &bs, &mut v, &mut j, JacobianMode::Columns).unwrap();
        (0..n)
            .map(|c| {
                (0..r.dim())
                    .map(|row| weights[row] * j[row * n + c])
                    .sum::<f64>()
            })
            .collect::<Vec<f64>>()
    };
    let mut h = vec![0.0; n * n];
    weighted_hessian(r, &refs, weights, &vec![true; blocks.len()], &mut h).unwrap();
    let flat: Vec<f64> = blocks.iter().flatten().copied().collect();
    let step = 1e-6;
    let scale = h.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
    let mut worst = 0.0_f64;
    for c in 0..n {
        let (mut p, mut m) = (flat.clone(), flat.clone());
        p[c] += step;
        m[c] -= step;
        let (gp, gm) = (grad(&p), grad(&m));
        for row in 0..n {
            let fd = (gp[row] - gm[row]) / (2.0 * step);
            worst = worst.max((h[row * n + c] - fd).abs() / scale);
        }
    }
    worst
}

/// Contact parameters: inside either span, on the knot, at the ends and beyond them.
fn parameter() -> impl Strategy<Value = f64> {
    prop_oneof![
        0.02..0.48_f64,
        0.52..0.98_f64,
        Just(0.0),
        Just(0.5),
        Just(1.0),
        Just(-0.2),
        Just(1.3)
    ]
}

proptest! {
    #[test]
    fn circle_contacts_match_the_dual_reference(
        kind in 0u8..3, wave in prop::collection::vec(-1.0..1.0_f64, 7), u in parameter(),
        c in prop::array::uniform2(-3.0..3.0_f64), radius in 0.1..2.0_f64, cw in any::<bool>(),
        moving in prop::collection::vec(any::<bool>(), 8), w in prop::array::uniform2(-2.0..2.0_f64),
    ) {
        let (basis, mut blocks) = curve(kind, &wave);
        let count = blocks.len();
        // At a free parameter: curve, u, centre, radius.
        let free = CircleContact::new(basis.clone(), Param::Block, cw);
        let mut all = blocks.clone();
        all.extend([vec![u], c.to_vec(), vec![radius]]);
        let mut active: Vec<bool> = (0..all.len()).map(|b| moving[b % moving.len()] || b == count).collect();
        let (dj, dh) = compare(&free, &all, &active, &w);
        prop_assert!(dj < 1e-12 && dh < 1e-10, "free: {dj:e} {dh:e}");
        active.fill(true);
        let (dj, dh) = compare(&free, &all, &active, &w);
        prop_assert!(dj < 1e-12 && dh < 1e-10, "free, all moving: {dj:e} {dh:e}");
        // At a fixed parameter over the whole curve, and over the points `at` keeps.
        let u_fixed = u.clamp(0.0, 1.0);
        blocks.extend([c.to_vec(), vec![radius]]);
        let fixed = CircleContact::new(basis.clone(), Param::Fixed(u_fixed), cw);
        let active: Vec<bool> = (0..blocks.len()).map(|b| moving[b % moving.len()]).collect();
        let (dj, dh) = compare(&fixed, &blocks, &active, &w);
        prop_assert!(dj < 1e-12 && dh < 1e-10, "fixed: {dj:e} {dh:e}");
        let (at, read) = basis.at(u_fixed, 1);
        let mut few: Vec<Vec<f64>> = read.iter().map(|j| blocks[*j].clone()).collect();
        few.extend([c.to_vec(), vec![radius]]);
        let narrow = CircleContact::new(at, Param::Fixed(u_fixed), cw);
        let (dj, dh) = compare(&narrow, &few, &vec![true; few.len()], &w);
        prop_assert!(dj < 1e-12 && dh < 1e-10, "at: {dj:e} {dh:e}");
    }

    #[test]
    fn parallel_tangents_match_the_dual_reference(
        k1 in 0u8..3, k2 in 0u8..3, w1 in prop::collection::vec(-1.0..1.0_f64, 7),
        w2 in prop::collection::vec(-1.0..1.0_f64, 7), moving in prop::collection::vec(any::<bool>(), 8),
        lambda in -2.0..2.0_f64,
    ) {
        let (b1, p1) = curve(k1, &w1);
        let (b2, p2) = curve(k2, &w2);
        let ((a1, r1), (a2, r2)) = (b1.at(b1.domain().1, 1), b2.at(b2.domain().0, 1));
        let mut blocks: Vec<Vec<f64>> = r1.iter().map(|j| p1[*j].clone()).collect();
        blocks.extend(r2.iter().map(|j| p2[*j].clone()));
        let r = TangentsParallel::new((a1, 1.0), (a2, 0.0));
        let active: Vec<bool> = (0..blocks.len()).map(|b| moving[b % moving.len()]).collect();
        let (dj, dh) = compare(&r, &blocks, &active, &[lambda]);
        prop_assert!(dj < 1e-12 && dh < 1e-10, "{dj:e} {dh:e}");
        // Over whole curves at interior parameters too.
        let whole = TangentsParallel::new((b1, 0.3), (b2, 0.7));
        let mut all = p1.clone();
        all.extend(p2.iter().cloned());
        let (dj, dh) = compare(&whole, &all, &vec![true; all.len()], &[lambda]);
        prop_assert!(dj < 1e-12 && dh < 1e-10, "whole: {dj:e} {dh:e}");
    }

    #[test]
    fn point_distances_match_the_dual_reference(
        p in prop::array::uniform2(-3.0..3.0_f64), q in prop::array::uniform2(-3.0..3.0_f64),
        d in 0.1..4.0_f64, on in prop::array::uniform2(any::<bool>()), lambda in -2.0..2.0_f64,
    ) {
        let r = PointDistance::new(d);
        let (dj, dh) = compare(&r, &[p.to_vec(), q.to_vec()], &on, &[lambda]);
        prop_assert!(dj < 1e-12 && dh < 1e-12, "{dj:e} {dh:e}");
    }

    #[test]
    fn structured_hessians_match_central_differences(
        kind in 0u8..3, wave in prop::collection::vec(-1.0..1.0_f64, 7), u in 0.05..0.45_f64,
        c in prop::array::uniform2(-3.0..3.0_f64), radius in 0.1..2.0_f64,
    ) {
        let (basis, mut blocks) = curve(kind, &wave);
        blocks.extend([vec![u], c.to_vec(), vec![radius]]);
        let free = CircleContact::new(basis, Param::Block, true);
        prop_assert!(hessian_vs_differences(&free, &blocks, &[0.8, -1.1]) < 1e-6);
    }
}
