//! The paper's blade leading-edge case through the facade: a leading-edge quintic whose ends
//! coincide with the pressure-side end and the suction-side start and whose end tangents are
//! parallel to those curves' end tangents (G1 joins with the joint directions fixed), outer
//! ends fixed. Interior leading-edge control points are dragged through 200 steps; after every
//! step the constraints hold to 1e-10 and the move equals −J⁺g with J and g written out here
//! from the Bézier end formulas and J⁺ taken from an SVD.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_abs_diff_eq;
use camber::geom::{BezierCurve2, ParametricCurve};
use camber::sketch::{EntityId, PointRef};
use camber_workloads::blade;
use nalgebra::{DMatrix, DVector, Point2, Vector2};

/// Free unknowns in this order: pressure P₁…P₅, leading P₀…P₅, suction P₀…P₄ (x, y each).
fn slots(b: &camber_workloads::Blade) -> Vec<(EntityId, usize)> {
    let mut v: Vec<(EntityId, usize)> = (1..6).map(|k| (b.pressure, k)).collect();
    v.extend((0..6).map(|k| (b.leading, k)));
    v.extend((0..5).map(|k| (b.suction, k)));
    v
}

fn col(slots: &[(EntityId, usize)], e: EntityId, k: usize) -> usize {
    2 * slots.iter().position(|s| *s == (e, k)).expect("free slot")
}

/// Rows of the blade's constraints plus the pin: J (10 × 32) and g at the points `at`.
fn system(
    b: &camber_workloads::Blade,
    at: &dyn Fn(EntityId, usize) -> Point2<f64>,
    dragged: usize,
    target: Point2<f64>,
) -> (DMatrix<f64>, DVector<f64>) {
    let s = slots(b);
    let (d1, d2) = (Vector2::new(-0.1, 0.015), Vector2::new(0.05, 0.01));
    let mut j = DMatrix::zeros(10, s.len() * 2);
    let mut g = DVector::zeros(10);
    // Joint points: pressure P₅ − leading P₀, leading P₅ − suction P₀.
    for (r, (e1, k1, e2, k2)) in [(b.pressure, 5, b.leading, 0), (b.leading, 5, b.suction, 0)]
        .into_iter()
        .enumerate()
    {
        let (p, q) = (at(e1, k1), at(e2, k2));
        for c in 0..2 {
            j[(2 * r + c, col(&s, e1, k1) + c)] = 1.0;
            j[(2 * r + c, col(&s, e2, k2) + c)] = -1.0;
        }
        g[2 * r] = p.x - q.x;
        g[2 * r + 1] = p.y - q.y;
    }
    // End tangents of a quintic are 5(P₅ − P₄) and 5(P₁ − P₀); the factor 5 scales a row,
    // which does not change the minimum-norm move, so rows are cross(P_b − P_a, d) here.
    let tangents = [
        (b.pressure, 4, 5, d1),
        (b.leading, 0, 1, d1),
        (b.leading, 4, 5, d2),
        (b.suction, 0, 1, d2),
    ];
    for (r, (e, ka, kb, d)) in tangents.into_iter().enumerate() {
        let row = 4 + r;
        let v = at(e, kb) - at(e, ka);
        g[row] = v.x * d.y - v.y * d.x;
        for (k, sign) in [(kb, 1.0), (ka, -1.0)] {
            j[(row, col(&s, e, k))] += sign * d.y;
            j[(row, col(&s, e, k) + 1)] -= sign * d.x;
        }
    }
    let p = at(b.leading, dragged);
    for c in 0..2 {
        j[(8 + c, col(&s, b.leading, dragged) + c)] = 1.0;
    }
    g[8] = p.x - target.x;
    g[9] = p.y - target.y;
    (j, g)
}

/// The largest violation of the blade's constraints, evaluated by the kernel's curves from the
/// control points given by `at` (joint gaps and |cross(C′, d)|/|C′|).
fn max_residual(at: &dyn Fn(EntityId, usize) -> Point2<f64>, b: &camber_workloads::Blade) -> f64 {
    let curve = |e| BezierCurve2::try_new((0..6).map(|k| at(e, k)).collect()).unwrap();
    let (ps, le, ss) = (curve(b.pressure), curve(b.leading), curve(b.suction));
    let cross = |v: Vector2<f64>, d: Vector2<f64>| (v.x * d.y - v.y * d.x).abs() / v.norm();
    let (d1, d2) = (Vector2::new(-0.1, 0.015), Vector2::new(0.05, 0.01));
    [
        (ps.point(1.0).unwrap() - le.point(0.0).unwrap()).norm(),
        (le.point(1.0).unwrap() - ss.point(0.0).unwrap()).norm(),
        cross(ps.derivative(1.0).unwrap(), d1),
        cross(le.derivative(0.0).unwrap(), d1),
        cross(le.derivative(1.0).unwrap(), d2),
        cross(ss.derivative(0.0).unwrap(), d2),
    ]
    .into_iter()
    .fold(0.0, f64::max)
}

#[test]
fn blade_leading_edge_drag_matches_the_dense_pseudo_inverse() {
    let (mut sketch, b) = blade().unwrap();
    let fixed = (
        sketch.point(PointRef::Start(b.pressure)).unwrap(),
        sketch.point(PointRef::End(b.suction)).unwrap(),
    );
    let s = slots(&b);
    let mut step = 0;
    for dragged in [2_usize, 3, 1] {
        let r = PointRef::Control(b.leading, dragged);
        let start = sketch.point(r).unwrap();
        let mut drag = sketch.drag(r).unwrap();
        let steps = if dragged == 1 { 66 } else { 67 };
        for k in 1..=steps {
            step += 1;
            let th = std::f64::consts::TAU * k as f64 / steps as f64;
            let target = start + 0.008 * Vector2::new(th.cos() - 1.0, (2.0 * th).sin());
            let before: Vec<Point2<f64>> = s
                .iter()
                .map(|(e, k)| drag.point(PointRef::Control(*e, *k)).unwrap())
                .collect();
            let at = |e: EntityId, k: usize| match s.iter().position(|x| *x == (e, k)) {
                Some(i) => before[i],
                None => sketch.point(PointRef::Control(e, k)).unwrap(),
            };
            let (j, g) = system(&b, &at, dragged, target);
            let pinv = j.clone().svd(true, true).pseudo_inverse(1e-13).unwrap();
            let expected = -pinv * g;

            drag.update(target).unwrap();
            for (i, (e, k)) in s.iter().enumerate() {
                let now = drag.point(PointRef::Control(*e, *k)).unwrap();
                let moved = now - before[i];
                assert!(
                    (moved.x - expected[2 * i]).abs() < 1e-10
                        && (moved.y - expected[2 * i + 1]).abs() < 1e-10,
                    "step {step}: point {e} {k} moved {moved:?}, expected ({}, {})",
                    expected[2 * i],
                    expected[2 * i + 1]
                );
            }
            assert!((drag.point(r).unwrap() - target).norm() < 1e-12);
            let now = |e: EntityId, k: usize| drag.point(PointRef::Control(e, k)).unwrap();
            assert!(max_residual(&now, &b) < 1e-10, "step {step}");
        }
        drag.finish(&mut sketch).unwrap();
        let committed = |e: EntityId, k: usize| sketch.point(PointRef::Control(e, k)).unwrap();
        assert!(
            max_residual(&committed, &b) < 1e-10,
            "after dragging {dragged}"
        );
    }
    assert_eq!(step, 200);
    assert_abs_diff_eq!(
        sketch.point(PointRef::Start(b.pressure)).unwrap(),
        fixed.0,
        epsilon = 0.0
    );
    assert_abs_diff_eq!(
        sketch.point(PointRef::End(b.suction)).unwrap(),
        fixed.1,
        epsilon = 0.0
    );
}
