//! Affine substitutions verified by hand: fixed, merged and eliminated unknowns.
#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

mod common;

use approx::assert_relative_eq;
use camber_solve::{solve_linear, ConstraintId, Error, Options, Problem, Var};
use common::row;

#[test]
fn fixed_unknowns_do_not_move() {
    // x + y = 4 from (1, 1) with x fixed: y = 3.
    let mut p = Problem::new();
    let b = p.add_block(&[1.0, 1.0]).unwrap();
    p.fix(p.unknown(b, 0).unwrap()).unwrap();
    p.add_residual(row(&[1.0, 1.0], 4.0), &[b], ConstraintId(1))
        .unwrap();
    let r = solve_linear(&mut p, &Options::default()).unwrap();
    assert_relative_eq!(p.values()[0], 1.0);
    assert_relative_eq!(p.values()[1], 3.0, epsilon = 1e-14);
    assert_eq!(r.dof, 0);
}

#[test]
fn merged_unknowns_share_one_move() {
    // Blocks p = (0, 0), q = (2, 0) with q_x merged into p_x, and p_x + p_y = 3.
    // Reduced unknowns z = (p_x, p_y, q_y); the merge imposes q_x = p_x, so moving z₀ moves two
    // unknowns and its weight is 1 + 1 = 2: min 2·Δp_x² + Δp_y² with Δp_x + Δp_y = 3 gives
    // Δp_x = 1, Δp_y = 2 (the least ‖Δx‖ over p and q together), and q_x = p_x = 1.
    let mut p = Problem::new();
    let a = p.add_block(&[0.0, 0.0]).unwrap();
    let b = p.add_block(&[2.0, 0.0]).unwrap();
    let (px, qx) = (p.unknown(a, 0).unwrap(), p.unknown(b, 0).unwrap());
    p.merge(qx, px).unwrap();
    assert_relative_eq!(p.reduced_map().unwrap().weights()[0], 2.0);
    p.add_residual(row(&[1.0, 1.0], 3.0), &[a], ConstraintId(1))
        .unwrap();
    let r = solve_linear(&mut p, &Options::default()).unwrap();
    assert_relative_eq!(p.values()[0], 1.0, epsilon = 1e-14);
    assert_relative_eq!(p.values()[1], 2.0, epsilon = 1e-14);
    assert_relative_eq!(p.values()[2], 1.0, epsilon = 1e-14);
    assert_relative_eq!(p.values()[3], 0.0);
    assert_eq!((r.rank, r.dof), (1, 2));
}

#[test]
fn a_merged_group_starts_at_its_weighted_mean() {
    // Two points merged as a group with weights 1 and 3: the shared unknown starts at
    // (1·0 + 3·4)/4 = 3 with weight 4, which is where the least weighted move of the pair with
    // nothing else to satisfy puts them.
    let mut p = Problem::new();
    let a = p.add_block(&[0.0]).unwrap();
    let b = p.add_block(&[4.0]).unwrap();
    let (ua, ub) = (p.unknown(a, 0).unwrap(), p.unknown(b, 0).unwrap());
    p.set_weight(Var::Unknown(ub), 3.0).unwrap();
    p.merge_group(ua, &[ub]).unwrap();
    let map = p.reduced_map().unwrap();
    assert_relative_eq!(map.z0()[0], 3.0, epsilon = 1e-15);
    assert_relative_eq!(map.weights()[0], 4.0);
    solve_linear(&mut p, &Options::default()).unwrap();
    assert_relative_eq!(p.values()[0], 3.0, epsilon = 1e-15);
    assert_relative_eq!(p.values()[1], 3.0, epsilon = 1e-15);
}

#[test]
fn a_merge_is_imposed_even_without_residuals() {
    let mut p = Problem::new();
    let a = p.add_block(&[1.0]).unwrap();
    let b = p.add_block(&[5.0]).unwrap();
    p.merge(p.unknown(b, 0).unwrap(), p.unknown(a, 0).unwrap())
        .unwrap();
    solve_linear(&mut p, &Options::default()).unwrap();
    assert_eq!(p.values(), &[1.0, 1.0]);
}

#[test]
fn elimination_moves_along_the_tangent() {
    // P0 = (0, 0) free, P1 = P0 + t·T with T = (1, 0), t₀ = 1; require P1_x = 3 (row on P1).
    // z = (P0x, P0y, t); x(P1) = (P0x + t, P0y). Row: P0x + t = 3 → min ‖Δz‖: ΔP0x = Δt = 1.
    let mut p = Problem::new();
    let p0 = p.add_block(&[0.0, 0.0]).unwrap();
    let p1 = p.add_block(&[7.0, 7.0]).unwrap(); // not on the tangent yet: the map imposes it
    let targets = [p.unknown(p1, 0).unwrap(), p.unknown(p1, 1).unwrap()];
    let bases = [p.unknown(p0, 0).unwrap(), p.unknown(p0, 1).unwrap()];
    let t = p.eliminate(&targets, &bases, &[1.0, 0.0], 1.0).unwrap();
    p.add_residual(row(&[1.0, 0.0], 3.0), &[p1], ConstraintId(1))
        .unwrap();
    let r = solve_linear(&mut p, &Options::default()).unwrap();
    assert_relative_eq!(p.values()[0], 1.0, epsilon = 1e-14);
    assert_relative_eq!(p.values()[1], 0.0);
    assert_relative_eq!(p.values()[2], 3.0, epsilon = 1e-14);
    assert_relative_eq!(p.values()[3], 0.0);
    assert_relative_eq!(p.aux_value(t).unwrap(), 2.0, epsilon = 1e-14);
    assert_eq!((r.rank, r.dof), (1, 2));
}

#[test]
fn weights_and_bounds_apply_to_auxiliary_unknowns() {
    // As above but t costs 4 times more: ΔP0x = 4·Δt, ΔP0x + Δt = 2 → Δt = 0.4.
    let mut p = Problem::new();
    let p0 = p.add_block(&[0.0, 0.0]).unwrap();
    let p1 = p.add_block(&[1.0, 0.0]).unwrap();
    let targets = [p.unknown(p1, 0).unwrap(), p.unknown(p1, 1).unwrap()];
    let bases = [p.unknown(p0, 0).unwrap(), p.unknown(p0, 1).unwrap()];
    let t = p.eliminate(&targets, &bases, &[1.0, 0.0], 1.0).unwrap();
    p.set_weight(Var::Aux(t), 4.0).unwrap();
    p.add_residual(row(&[1.0, 0.0], 3.0), &[p1], ConstraintId(1))
        .unwrap();
    solve_linear(&mut p, &Options::default()).unwrap();
    assert_relative_eq!(p.aux_value(t).unwrap(), 1.4, epsilon = 1e-14);
    assert_relative_eq!(p.values()[0], 1.6, epsilon = 1e-14);

    // Keeping t > 0: a target behind P0 would need t < 0, which the bound refuses.
    let mut r = Problem::new();
    let p0 = r.add_block(&[0.0, 0.0]).unwrap();
    let p1 = r.add_block(&[1.0, 0.0]).unwrap();
    let targets = [r.unknown(p1, 0).unwrap(), r.unknown(p1, 1).unwrap()];
    let bases = [r.unknown(p0, 0).unwrap(), r.unknown(p0, 1).unwrap()];
    let t = r.eliminate(&targets, &bases, &[1.0, 0.0], 1.0).unwrap();
    r.set_bounds(Var::Aux(t), 1e-9, f64::INFINITY).unwrap();
    r.fix(bases[0]).unwrap();
    r.add_residual(row(&[1.0, 0.0], -2.0), &[p1], ConstraintId(1))
        .unwrap();
    let err = solve_linear(&mut r, &Options::default()).unwrap_err();
    assert!(matches!(err, Error::OutOfBounds { value, .. } if (value + 2.0).abs() < 1e-12));
    assert_eq!(r.values(), &[0.0, 0.0, 1.0, 0.0]);
    assert_relative_eq!(r.aux_value(t).unwrap(), 1.0);
}

#[test]
fn substitutions_do_not_chain() {
    let mut p = Problem::new();
    let b = p.add_block(&[0.0, 0.0, 0.0]).unwrap();
    let (x, y, z) = (
        p.unknown(b, 0).unwrap(),
        p.unknown(b, 1).unwrap(),
        p.unknown(b, 2).unwrap(),
    );
    p.merge(y, x).unwrap();
    p.merge(z, y).unwrap();
    assert_eq!(
        p.reduced_map().unwrap_err(),
        Error::SubstitutionChain {
            unknown: 2,
            referenced: 1
        }
    );
}

#[test]
fn the_reduced_map_is_a_times_z_plus_c() {
    let mut p = Problem::new();
    let b = p.add_block(&[1.0, 2.0, 3.0]).unwrap();
    let (x, y, z) = (
        p.unknown(b, 0).unwrap(),
        p.unknown(b, 1).unwrap(),
        p.unknown(b, 2).unwrap(),
    );
    let t = p.add_aux(0.5).unwrap();
    p.fix(y).unwrap();
    p.substitute(z, &[(Var::Unknown(x), 2.0), (Var::Aux(t), -1.0)], 10.0)
        .unwrap();
    let map = p.reduced_map().unwrap();
    assert_eq!(map.vars(), &[Var::Unknown(x), Var::Aux(t)]);
    assert_eq!(map.z0(), &[1.0, 0.5]);
    let mut out = [0.0; 3];
    map.expand(&[4.0, 1.0], &mut out).unwrap();
    for (got, want) in out.iter().zip([4.0, 2.0, 2.0 * 4.0 - 1.0 + 10.0]) {
        assert_relative_eq!(*got, want);
    }
}
