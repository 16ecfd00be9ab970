//! The nonlinear solvers and the selection, on curve-free residuals written here.
#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

use approx::assert_abs_diff_eq;
use camber_solve::scalar::cst;
use camber_solve::{
    solve, solve_newton_from, ConstraintId, Error, NewtonWorkspace, NonlinearOptions, Options,
    Problem, Residual, Scalar, Selection, SolverChoice, SolverKind, Status, Var,
};

/// |p − c|² − r² for a point block p (c, r fixed).
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

/// External tangency of a circle block (cx, cy, r) with a fixed circle:
/// |c − c₁|² − (r + r₁)² = 0.
#[derive(Debug)]
struct TouchesCircle {
    c: [f64; 2],
    r: f64,
}

impl Residual for TouchesCircle {
    fn name(&self) -> &str {
        "touches circle"
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let dx = x[0][0] - cst(self.c[0]);
        let dy = x[0][1] - cst(self.c[1]);
        let s = x[0][2] + cst(self.r);
        out[0] = dx * dx + dy * dy - s * s;
    }
}

/// x_k = value (affine).
#[derive(Debug)]
struct Coordinate {
    k: usize,
    value: f64,
}

impl Residual for Coordinate {
    fn name(&self) -> &str {
        "coordinate"
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = x[0][self.k] - cst(self.value);
    }
    fn is_affine(&self) -> bool {
        true
    }
}

fn forced(choice: SolverChoice) -> Options {
    Options::default().with_force(Some(choice))
}

/// Tightly converged SLSQP options.
fn tight() -> Options {
    Options::default().with_tolerance(1e-12).with_nonlinear(
        NonlinearOptions::default()
            .with_slsqp_xtol_rel(1e-15)
            .with_slsqp_max_evaluations(5000),
    )
}

fn circle_problem(start: [f64; 2]) -> Problem {
    let mut p = Problem::new();
    let b = p.add_block(&start).unwrap();
    p.add_residual(
        OnCircle {
            c: [1.0, -2.0],
            r: 2.0,
        },
        &[b],
        ConstraintId(1),
    )
    .unwrap();
    p
}

#[test]
fn point_on_circle_goes_to_the_nearest_point() {
    // From (4, 2): the nearest point is c + r·(p − c)/|p − c| = (1, −2) + 2·(3, 4)/5.
    let expected = [1.0 + 1.2, -2.0 + 1.6];
    let mut newton = circle_problem([4.0, 2.0]);
    let r = solve(&mut newton, &Options::default()).unwrap();
    assert_eq!(r.solver, SolverKind::Newton);
    assert_eq!(r.status, Status::Solved);
    assert_abs_diff_eq!(newton.values()[0], expected[0], epsilon = 1e-10);
    assert_abs_diff_eq!(newton.values()[1], expected[1], epsilon = 1e-10);
    assert_abs_diff_eq!(r.displacement_norm, 3.0, epsilon = 1e-10);
    #[cfg(feature = "nlopt")]
    {
        let mut slsqp = circle_problem([4.0, 2.0]);
        let r = solve(&mut slsqp, &tight().with_force(Some(SolverChoice::Slsqp))).unwrap();
        assert_eq!(r.solver, SolverKind::Slsqp);
        for k in 0..2 {
            assert_abs_diff_eq!(slsqp.values()[k], newton.values()[k], epsilon = 1e-8);
        }
    }
}

/// A circle (cx, cy, r), all free, touching two fixed circles: two rows, three unknowns.
fn two_tangencies(start: [f64; 3]) -> Problem {
    let mut p = Problem::new();
    let b = p.add_block(&start).unwrap();
    p.add_residual(
        TouchesCircle {
            c: [0.0, 0.0],
            r: 1.0,
        },
        &[b],
        ConstraintId(10),
    )
    .unwrap();
    p.add_residual(
        TouchesCircle {
            c: [4.0, 0.0],
            r: 0.5,
        },
        &[b],
        ConstraintId(11),
    )
    .unwrap();
    p
}

#[test]
fn under_determined_tangencies_give_the_minimum_norm_solution() {
    let start = [1.7, 1.9, 0.8];
    let mut newton = two_tangencies(start);
    let r = solve(&mut newton, &Options::default()).unwrap();
    assert_eq!(r.solver, SolverKind::Newton);
    assert_eq!(r.dof, 1);
    // The result is a solution…
    let v = newton.values().to_vec();
    let d0 = (v[0] * v[0] + v[1] * v[1]).sqrt();
    let d1 = ((v[0] - 4.0).powi(2) + v[1] * v[1]).sqrt();
    assert_abs_diff_eq!(d0, v[2] + 1.0, epsilon = 1e-10);
    assert_abs_diff_eq!(d1, v[2] + 0.5, epsilon = 1e-10);
    #[cfg(feature = "nlopt")]
    {
        // …and the nearest one: tightly converged SLSQP agrees.
        let mut slsqp = two_tangencies(start);
        solve(&mut slsqp, &tight().with_force(Some(SolverChoice::Slsqp))).unwrap();
        for (a, b) in slsqp.values().iter().zip(&v) {
            assert_abs_diff_eq!(*a, *b, epsilon = 1e-8);
        }
    }
    // Without the pull-back a Newton iteration would stop anywhere on the solution curve; with
    // it, moving along the curve from the result only lengthens the move.
    let moved = |w: &[f64]| -> f64 { w.iter().zip(start).map(|(a, b)| (a - b).powi(2)).sum() };
    let base = moved(&v);
    for t in [-1e-3, 1e-3] {
        // Perturb along the curve: re-solve from a nudged start with the same reference.
        let mut q = two_tangencies([v[0] + t, v[1], v[2]]);
        let mut ws = NewtonWorkspace::new();
        let nudged = [v[0] + t, v[1], v[2]];
        // Pull toward the nudged point itself: lands on a nearby curve point.
        solve_newton_from(&mut q, &Options::default(), &mut ws, &nudged, &nudged).unwrap();
        assert!(moved(q.values()) >= base - 1e-12);
    }
}

#[test]
fn two_circles_meeting_point() {
    // p on two circles: a square nonlinear system with a unique nearby root.
    let mut p = Problem::new();
    let b = p.add_block(&[0.4, 1.3]).unwrap();
    p.add_residual(
        OnCircle {
            c: [-1.0, 0.0],
            r: 2f64.sqrt(),
        },
        &[b],
        ConstraintId(1),
    )
    .unwrap();
    p.add_residual(
        OnCircle {
            c: [1.0, 0.0],
            r: 2f64.sqrt(),
        },
        &[b],
        ConstraintId(2),
    )
    .unwrap();
    let r = solve(&mut p, &Options::default()).unwrap();
    assert_eq!((r.solver, r.dof), (SolverKind::Newton, 0));
    assert_abs_diff_eq!(p.values()[0], 0.0, epsilon = 1e-10);
    assert_abs_diff_eq!(p.values()[1], 1.0, epsilon = 1e-10);
}

#[cfg(feature = "nlopt")]
#[test]
fn rank_deficient_start_goes_to_slsqp() {
    // On the line through both centres the two gradients are parallel: J is singular.
    let mut p = Problem::new();
    let b = p.add_block(&[0.3, 0.0]).unwrap();
    for (id, c) in [(1, -1.0), (2, 1.0)] {
        p.add_residual(
            OnCircle {
                c: [c, 0.0],
                r: 2f64.sqrt(),
            },
            &[b],
            ConstraintId(id),
        )
        .unwrap();
    }
    let r = solve(&mut p, &Options::default()).unwrap();
    assert_eq!(r.solver, SolverKind::Slsqp, "{}", r.reason);
    assert_eq!(r.selection, Selection::RankDeficient, "{}", r.reason);
    assert!(r.reason.contains("rank deficient"), "{}", r.reason);
    assert_abs_diff_eq!(p.values()[0], 0.0, epsilon = 1e-9);
    assert_abs_diff_eq!(p.values()[1].abs(), 1.0, epsilon = 1e-9);
}

fn conflicting_circles() -> Problem {
    let mut p = Problem::new();
    let b = p.add_block(&[3.0, 0.5]).unwrap();
    p.add_residual(
        OnCircle {
            c: [0.0, 0.0],
            r: 1.0,
        },
        &[b],
        ConstraintId(7),
    )
    .unwrap();
    p.add_residual(
        OnCircle {
            c: [0.0, 0.0],
            r: 2.0,
        },
        &[b],
        ConstraintId(8),
    )
    .unwrap();
    p.add_residual(Coordinate { k: 1, value: 0.5 }, &[b], ConstraintId(9))
        .unwrap();
    p
}

#[test]
fn conflicting_constraints_are_named_and_nothing_moves() {
    let mut p = conflicting_circles();
    let before = p.values().to_vec();
    match solve(&mut p, &Options::default()) {
        Err(Error::Conflicting { constraints }) => {
            assert!(constraints.contains(&ConstraintId(7)), "{constraints:?}");
            assert!(constraints.contains(&ConstraintId(8)), "{constraints:?}");
            assert!(!constraints.contains(&ConstraintId(9)), "{constraints:?}");
        }
        other => panic!("expected a conflict, got {other:?}"),
    }
    assert_eq!(p.values(), &before[..]);

    // Affine conflicts are named from the start.
    let mut q = Problem::new();
    let b = q.add_block(&[0.0, 0.0]).unwrap();
    q.add_residual(Coordinate { k: 0, value: 1.0 }, &[b], ConstraintId(1))
        .unwrap();
    q.add_residual(Coordinate { k: 0, value: 2.0 }, &[b], ConstraintId(2))
        .unwrap();
    assert_eq!(
        solve(&mut q, &Options::default()),
        Err(Error::Conflicting {
            constraints: vec![ConstraintId(2)]
        })
    );
}

#[test]
fn soft_mode_reports_the_unsatisfied_constraints() {
    let mut p = conflicting_circles();
    let r = solve(&mut p, &Options::default().with_soft(true)).unwrap();
    assert_eq!(r.status, Status::Relaxed);
    assert_eq!(r.solver, SolverKind::LevenbergMarquardt);
    assert_eq!(r.conflicting, vec![ConstraintId(7), ConstraintId(8)]);
    // Least squares of (s − 1)² + (s − 4)² in s = |p|²: s = 2.5, and y = 0.5 is met.
    let v = p.values();
    assert_abs_diff_eq!(v[0] * v[0] + v[1] * v[1], 2.5, epsilon = 1e-6);
    assert_abs_diff_eq!(v[1], 0.5, epsilon = 1e-8);
    // Forcing the soft mode on a consistent system solves it.
    let mut q = circle_problem([4.0, 2.0]);
    let r = solve(&mut q, &forced(SolverChoice::Soft)).unwrap();
    assert_eq!(r.status, Status::Solved);
}

#[test]
fn bounds_are_respected() {
    // Nearest point (2.2, −0.4), but x ≤ 2: the constrained nearest point has x = 2.
    let run = |choice: Option<SolverChoice>| -> Vec<f64> {
        let mut p = Problem::new();
        let b = p.add_block(&[4.0, 2.0]).unwrap();
        p.add_residual(
            OnCircle {
                c: [1.0, -2.0],
                r: 2.0,
            },
            &[b],
            ConstraintId(1),
        )
        .unwrap();
        let x = p.unknown(b, 0).unwrap();
        p.set_bounds(Var::Unknown(x), f64::NEG_INFINITY, 2.0)
            .unwrap();
        solve(&mut p, &tight().with_tolerance(1e-10).with_force(choice)).unwrap();
        p.values().to_vec()
    };
    let y = -2.0 + (4.0_f64 - 1.0).sqrt();
    let v = run(None);
    assert_abs_diff_eq!(v[0], 2.0, epsilon = 1e-10);
    assert_abs_diff_eq!(v[1], y, epsilon = 1e-8);
    #[cfg(feature = "nlopt")]
    {
        let s = run(Some(SolverChoice::Slsqp));
        assert_abs_diff_eq!(s[0], 2.0, epsilon = 1e-10);
        assert_abs_diff_eq!(s[1], y, epsilon = 1e-8);
    }
}

#[test]
fn forcing_each_solver() {
    let mut p = circle_problem([4.0, 2.0]);
    let before = p.values().to_vec();
    assert!(matches!(
        solve(&mut p, &forced(SolverChoice::Linear)),
        Err(Error::NonlinearNotAvailable { .. })
    ));
    assert_eq!(p.values(), &before[..]);
    let r = solve(&mut p, &forced(SolverChoice::Newton)).unwrap();
    assert_eq!(r.solver, SolverKind::Newton);
    let mut q = circle_problem([4.0, 2.0]);
    let s = solve(&mut q, &forced(SolverChoice::Slsqp));
    #[cfg(feature = "nlopt")]
    assert_eq!(s.unwrap().solver, SolverKind::Slsqp);
    #[cfg(not(feature = "nlopt"))]
    {
        assert!(matches!(
            s,
            Err(Error::SolverUnavailable {
                solver: "SLSQP",
                ..
            })
        ));
        assert_eq!(q.values(), &before[..]);
    }
    // A forced Newton on a singular start fails and changes nothing.
    let mut c = circle_problem([1.0, -2.0]); // the centre: J = 0
    let before = c.values().to_vec();
    assert!(solve(&mut c, &forced(SolverChoice::Newton)).is_err());
    assert_eq!(c.values(), &before[..]);
}

#[test]
fn warm_started_drag_follows_the_mouse() {
    // A point dragged around the circle: each step starts at the previous solution and is
    // pulled toward the mouse; no step jumps.
    let mut p = circle_problem([3.0, -2.0]);
    let mut ws = NewtonWorkspace::new();
    let opts = Options::default();
    for k in 1..=50 {
        let a = 0.05 * f64::from(k);
        let mouse = [1.0 + 2.5 * a.cos(), -2.0 + 2.5 * a.sin()];
        let prev = p.values().to_vec();
        let r = solve_newton_from(&mut p, &opts, &mut ws, &prev, &mouse).unwrap();
        let v = p.values();
        assert_abs_diff_eq!(v[0], 1.0 + 2.0 * a.cos(), epsilon = 1e-9);
        assert_abs_diff_eq!(v[1], -2.0 + 2.0 * a.sin(), epsilon = 1e-9);
        assert!(r.displacement_norm < 0.2);
    }
}

#[test]
fn affine_problems_take_the_linear_path() {
    let mut p = Problem::new();
    let b = p.add_block(&[0.0, 0.0]).unwrap();
    p.add_residual(Coordinate { k: 0, value: 1.0 }, &[b], ConstraintId(1))
        .unwrap();
    let r = solve(&mut p, &Options::default()).unwrap();
    assert_eq!(r.solver, SolverKind::DenseMinNorm);
    assert_eq!(r.selection, Selection::Affine);
    assert!(r.reason.starts_with("all residuals affine"));
    let again = solve(&mut p, &Options::default()).unwrap();
    assert_eq!(again.status, Status::AlreadySatisfied);
}

/// Three circles through (1, 1) over one point: three rows, two unknowns, rank 2 at the
/// solution.
#[cfg(feature = "nlopt")]
fn three_circles_through_one_point() -> Problem {
    let mut p = Problem::new();
    let b = p.add_block(&[1.3, 0.8]).unwrap();
    for (id, c) in [(1, [0.0, 0.0]), (2, [2.0, 0.0]), (3, [1.0, 3.0])] {
        let r = ((1.0 - c[0]) * (1.0f64 - c[0]) + (1.0 - c[1]) * (1.0f64 - c[1])).sqrt();
        p.add_residual(OnCircle { c, r }, &[b], ConstraintId(id))
            .unwrap();
    }
    p
}

/// Issue 11: NLopt 2.9's SLSQP writes past its workspace when the equality rows outnumber the
/// unknowns (the process aborted with 7 or more circle contacts on one cubic). A forced SLSQP
/// on three rows over two unknowns gets an independent pair of rows and solves.
#[cfg(feature = "nlopt")]
#[test]
fn slsqp_gets_independent_rows_when_rows_outnumber_unknowns() {
    let mut p = three_circles_through_one_point();
    let r = solve(&mut p, &tight().with_force(Some(SolverChoice::Slsqp))).unwrap();
    assert_eq!(r.solver, SolverKind::Slsqp);
    assert_abs_diff_eq!(p.values()[0], 1.0, epsilon = 1e-8);
    assert_abs_diff_eq!(p.values()[1], 1.0, epsilon = 1e-8);
}

/// Without an analysis to choose the rows from, SLSQP is not called at all: a typed error
/// and an unchanged problem.
#[cfg(feature = "nlopt")]
#[test]
fn slsqp_is_refused_outside_its_limits() {
    let mut p = three_circles_through_one_point();
    let before = p.values().to_vec();
    let options = forced(SolverChoice::Slsqp).with_dense_analysis_max_entries(0);
    let e = solve(&mut p, &options).unwrap_err();
    assert!(
        matches!(
            e,
            Error::OutsideSolverLimits {
                unknowns: 2,
                rows: 3,
                ..
            }
        ),
        "{e}"
    );
    assert_eq!(
        p.values().iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
        before.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
    );
}

#[test]
fn slsqp_limits() {
    use camber_solve::{slsqp_supports, SLSQP_MAX_UNKNOWNS};
    assert!(slsqp_supports(3, 3).is_ok());
    assert!(slsqp_supports(SLSQP_MAX_UNKNOWNS, SLSQP_MAX_UNKNOWNS).is_ok());
    assert!(slsqp_supports(2, 3).is_err());
    assert!(slsqp_supports(SLSQP_MAX_UNKNOWNS + 1, 1).is_err());
    // NLopt 2.9 sizes SLSQP's workspace in 32-bit ints: at the cap (n = m = the cap) it must
    // fit, which is the reason the cap exists at all.
    let (n, m) = (SLSQP_MAX_UNKNOWNS as i128, SLSQP_MAX_UNKNOWNS as i128);
    // With equality rows only, NLopt's MINEQ = M − MEQ + 2·N1 is 2·N1.
    let n1 = n + 1;
    let mineq = 2 * n1;
    let len_w = (3 * n1 + m) * (n1 + 1)
        + (n1 - m + 1) * (mineq + 2)
        + 2 * mineq
        + (n1 + mineq) * (n1 - m)
        + 2 * m
        + n1
        + (n + 1) * n / 2
        + 2 * m
        + 3 * n
        + 3 * n1
        + 1;
    assert!(len_w < i128::from(i32::MAX) / 8, "{len_w}");
}

/// Issue 13: "conflicting" only when proven. Two circles that do meet, with every solver cut
/// to one iteration or evaluation: nothing solves, but the least-squares search stopped far
/// from a least-squares point, so the answer is NotSolved with each constraint's residual (and
/// nothing moves); with the iterations restored the same problem solves.
#[test]
fn a_solve_that_merely_failed_is_not_called_conflicting() {
    let meeting = || {
        let mut p = Problem::new();
        let b = p.add_block(&[3.0, 2.5]).unwrap();
        p.add_residual(
            OnCircle {
                c: [0.0, 0.0],
                r: 1.0,
            },
            &[b],
            ConstraintId(1),
        )
        .unwrap();
        p.add_residual(
            OnCircle {
                c: [1.5, 0.0],
                r: 1.0,
            },
            &[b],
            ConstraintId(2),
        )
        .unwrap();
        p
    };
    let starved = Options::default().with_nonlinear(
        NonlinearOptions::default()
            .with_max_iterations(1)
            .with_slsqp_max_evaluations(1),
    );
    let mut p = meeting();
    let before = p.values().to_vec();
    match solve(&mut p, &starved) {
        Err(Error::NotSolved {
            tried,
            residuals,
            best_effort,
        }) => {
            assert!(tried.contains("Levenberg"), "{tried}");
            let named: Vec<ConstraintId> = residuals.iter().map(|r| r.constraint).collect();
            assert_eq!(named, vec![ConstraintId(1), ConstraintId(2)]);
            assert!(residuals.iter().all(|r| r.max_abs > 1e-3), "{residuals:?}");
            assert_eq!(p.values(), &before[..]);
            // The best-effort state is offered, not written: applied, it has the residuals
            // the error reports.
            let map = p.reduced_map().unwrap();
            p.apply_reduced(&map, &best_effort).unwrap();
            let mut g = vec![0.0; 2];
            p.evaluate_at(p.values(), &mut g).unwrap();
            for (gi, r) in g.iter().zip(&residuals) {
                assert!(
                    (gi.abs() - r.max_abs).abs() < 1e-12,
                    "{g:?} vs {residuals:?}"
                );
            }
        }
        other => panic!("expected NotSolved, got {other:?}"),
    }
    let mut q = meeting();
    let solved = solve(&mut q, &Options::default()).unwrap();
    assert_eq!(
        (solved.solver, solved.selection),
        (SolverKind::Newton, Selection::FullRank)
    );
    let mut again = meeting();
    let forced = solve(&mut again, &forced(SolverChoice::Newton)).unwrap();
    assert_eq!(forced.selection, Selection::Forced);
    let json = serde_json::to_value(&solved).unwrap();
    assert_eq!(json["selection"], "full_rank");
}

/// |p − q|² − d² for two point blocks.
#[derive(Debug)]
struct PointDistance {
    d: f64,
}

impl Residual for PointDistance {
    fn name(&self) -> &str {
        "point distance"
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let dx = x[1][0] - x[0][0];
        let dy = x[1][1] - x[0][1];
        out[0] = dx * dx + dy * dy - cst(self.d * self.d);
    }
}

/// q_k − p_k = 0 for one coordinate k of two point blocks (k = 0: vertical, 1: horizontal).
#[derive(Debug)]
struct SameCoordinate {
    k: usize,
}

impl Residual for SameCoordinate {
    fn name(&self) -> &str {
        "same coordinate"
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = x[1][self.k] - x[0][self.k];
    }
    fn is_affine(&self) -> bool {
        true
    }
}

/// A ladder of `cells` cells as W5b draws it, on points alone: bottom points p₀…p_N, top
/// points q₀…q_N, p₀ fixed, rungs vertical, rails horizontal, bottom rails of widths 1.0,
/// 1.2, 1.4 cycling and the first rung of height 1: as many rows as free unknowns
/// (4N + 2). Every other coordinate starts up to 0.1 off its design value (a fixed LCG).
fn ladder(cells: usize) -> Problem {
    let mut state = 12345_u64;
    let mut offset = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        0.1 * (2.0 * ((state >> 11) as f64) / ((1_u64 << 53) as f64) - 1.0)
    };
    let width = |k: usize| 1.0 + 0.2 * (k % 3) as f64;
    let mut p = Problem::new();
    let mut x = 0.0;
    let (mut bottom, mut top) = (Vec::new(), Vec::new());
    for k in 0..=cells {
        let (dp, dq) = if k == 0 {
            ([0.0, 0.0], [offset(), offset()])
        } else {
            ([offset(), offset()], [offset(), offset()])
        };
        bottom.push(p.add_block(&[x + dp[0], dp[1]]).unwrap());
        top.push(p.add_block(&[x + dq[0], 1.0 + dq[1]]).unwrap());
        x += width(k);
    }
    p.fix_block(bottom[0]).unwrap();
    let mut id = 0;
    let mut next_id = || {
        id += 1;
        ConstraintId(id)
    };
    p.add_residual(PointDistance { d: 1.0 }, &[bottom[0], top[0]], next_id())
        .unwrap();
    for k in 0..=cells {
        p.add_residual(SameCoordinate { k: 0 }, &[bottom[k], top[k]], next_id())
            .unwrap();
    }
    for k in 0..cells {
        p.add_residual(
            SameCoordinate { k: 1 },
            &[bottom[k], bottom[k + 1]],
            next_id(),
        )
        .unwrap();
        p.add_residual(SameCoordinate { k: 1 }, &[top[k], top[k + 1]], next_id())
            .unwrap();
        p.add_residual(
            PointDistance { d: width(k) },
            &[bottom[k], bottom[k + 1]],
            next_id(),
        )
        .unwrap();
    }
    p
}

/// Checks that the ladder of [`ladder`] is solved: every residual met, rails at heights 0
/// and 1, rungs at the cumulated widths.
fn assert_ladder_solved(p: &Problem, cells: usize) {
    let mut g = vec![0.0; p.num_rows()];
    p.evaluate_at(p.values(), &mut g).unwrap();
    let worst = g.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    assert!(worst <= 1e-9, "max |g| = {worst}");
    let mut x = 0.0;
    for k in 0..=cells {
        let v = &p.values()[4 * k..4 * k + 4];
        assert_abs_diff_eq!(v[0], x, epsilon = 1e-9);
        assert_abs_diff_eq!(v[1], 0.0, epsilon = 1e-9);
        assert_abs_diff_eq!(v[2], x, epsilon = 1e-9);
        assert_abs_diff_eq!(v[3], 1.0, epsilon = 1e-9);
        x += 1.0 + 0.2 * (k % 3) as f64;
    }
}

/// W5b-like ladders solve with every residual met when their square Newton steps come from
/// the sparse LU: a small one (the sparse LU forced by a dense size of 0) reaches the point
/// the dense LU's steps reach, and a large one (above the default dense size) solves too.
#[test]
fn square_ladders_solve_by_the_sparse_lu_as_by_the_dense_one() {
    let cells = 30;
    let mut sparse = ladder(cells);
    let r = solve(&mut sparse, &Options::default().with_dense_max_unknowns(0)).unwrap();
    assert_eq!(
        (r.solver, r.status, r.dof),
        (SolverKind::Newton, Status::Solved, 0)
    );
    assert_ladder_solved(&sparse, cells);
    let mut dense = ladder(cells);
    let rd = solve(&mut dense, &Options::default()).unwrap();
    assert_eq!((rd.solver, rd.status), (SolverKind::Newton, Status::Solved));
    for (a, b) in sparse.values().iter().zip(dense.values()) {
        assert_abs_diff_eq!(a, b, epsilon = 1e-12);
    }
    let cells = 400;
    let mut large = ladder(cells);
    let r = solve(&mut large, &Options::default()).unwrap();
    assert_eq!(
        (r.solver, r.status, r.dof),
        (SolverKind::Newton, Status::Solved, 0)
    );
    assert_ladder_solved(&large, cells);
}

/// |p_{k+1} − p_k|² − 1 over one block of points (x₀, y₀, x₁, y₁, …).
#[derive(Debug)]
struct Link {
    k: usize,
}

impl Residual for Link {
    fn name(&self) -> &str {
        "link"
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let dx = x[0][2 * self.k + 2] - x[0][2 * self.k];
        let dy = x[0][2 * self.k + 3] - x[0][2 * self.k + 1];
        out[0] = dx * dx + dy * dy - cst(1.0);
    }
}

/// A step tolerance no f64 step can meet (1e-300·(1 + max |z|), far below the rounding of the
/// pull-back steps) stands for a large component whose rounding floor exceeds the tolerance
/// (a chain of 10⁴ points ran 100 iterations, 7.5 s): Newton stops once its steps stand still
/// with the rows met, instead of running to its iteration limit, and the point it stops at is
/// the one the default tolerance reaches.
#[test]
fn newton_stops_when_its_steps_stand_at_the_rounding_floor() {
    let chain = |options: &Options| {
        let n = 20;
        let start: Vec<f64> = (0..n)
            .flat_map(|k| [k as f64 * 1.01, 0.1 * (0.7 * k as f64).sin()])
            .collect();
        let mut p = Problem::new();
        let b = p.add_block(&start).unwrap();
        for k in 0..n - 1 {
            p.add_residual(Link { k }, &[b], ConstraintId(k as u64 + 1))
                .unwrap();
        }
        let r = solve(&mut p, options).unwrap();
        (r, p.values().to_vec())
    };
    let (usual, want) = chain(&Options::default());
    let options =
        Options::default().with_nonlinear(NonlinearOptions::default().with_step_tolerance(1e-300));
    let (r, got) = chain(&options);
    assert_eq!(r.solver, SolverKind::Newton);
    assert_eq!(r.status, Status::Solved);
    assert!(
        r.iterations <= usual.iterations + STALL_MARGIN,
        "{} iterations (default tolerance: {}): {}",
        r.iterations,
        usual.iterations,
        r.reason
    );
    assert!(!r.reason.contains("not fully converged"), "{}", r.reason);
    for (a, b) in got.iter().zip(&want) {
        assert_abs_diff_eq!(a, b, epsilon = 1e-9);
    }
}

/// Iterations a run may take past the usual stop to see that its steps stand still.
const STALL_MARGIN: usize = 6;
