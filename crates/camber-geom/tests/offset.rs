//! Offsets: hand-derived offsets of lines and circles, and on random cubics the measured error
//! against a second method (the distance from the offset fit back to the curve).

// Test helpers outside #[test] functions unwrap too; a failed unwrap is a failed test.
#![allow(clippy::unwrap_used)]

use camber_geom::budget::Budget;
use camber_geom::offset::{offset, offset_with};
use camber_geom::queries::closest_point;
use camber_geom::{BSplineCurve2, BezierCurve2, Error, KnotVector, NurbsCurve2, ParametricCurve};
use nalgebra::{Point2, Vector2};
use proptest::prelude::*;

#[test]
fn a_line_shifts_sideways() {
    // Travelling +x, the left side is +y.
    let line = BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(4.0, 0.0)]).unwrap();
    let o = offset(&line, 2.0, 1e-9).unwrap();
    assert!(o.max_error <= 1e-9);
    for i in 0..=10 {
        let p = o.curve.point(f64::from(i) / 10.0).unwrap();
        assert!(
            (p - Point2::new(0.4 * f64::from(i), 2.0)).norm() < 1e-9,
            "{p}"
        );
    }
}

#[test]
fn circles_stay_concentric() {
    let circle = NurbsCurve2::try_circular_arc(Point2::new(1.0, 1.0), 2.0, 0.0, 3.0).unwrap();
    for d in [0.5, -0.5, 1.5] {
        let o = offset(&circle, d, 1e-7).unwrap();
        assert!(o.max_error <= 1e-7, "{d}: {}", o.max_error);
        for i in 0..=50 {
            let p = o.curve.point(f64::from(i) / 50.0).unwrap();
            let r = (p - Point2::new(1.0, 1.0)).norm();
            // Counter-clockwise: left is inwards.
            assert!((r - (2.0 - d)).abs() < 1e-7, "{d}: {r}");
        }
    }
}

#[test]
fn bad_input_is_typed() {
    let line = BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(4.0, 0.0)]).unwrap();
    assert!(matches!(
        offset(&line, 1.0, 0.0),
        Err(Error::NonPositiveTolerance { .. })
    ));
    assert!(matches!(
        offset(&line, f64::NAN, 1e-3),
        Err(Error::NonFinite { .. })
    ));
    // A cusp (zero tangent at the start) has no normal there.
    let cusp = BezierCurve2::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 1.0),
    ])
    .unwrap();
    assert!(matches!(
        offset(&cusp, 0.1, 1e-3),
        Err(Error::ZeroLength { .. })
    ));
}

fn smooth_cubic() -> impl Strategy<Value = BSplineCurve2<f64>> {
    // Gentle curves: x strictly increasing control points, small y variation.
    proptest::collection::vec(-0.5..0.5_f64, 6).prop_map(|ys| {
        let points = ys
            .iter()
            .enumerate()
            .map(|(i, &y)| Point2::new(i as f64, y))
            .collect();
        BSplineCurve2::try_new(3, KnotVector::clamped_uniform(3, 6).unwrap(), points).unwrap()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn offsets_meet_their_tolerance(c in smooth_cubic(), d in -0.3..0.3_f64, f in 0.0..1.0_f64) {
        let tol = 1e-5;
        let o = offset(&c, d, tol).unwrap();
        prop_assert!(o.max_error <= tol, "{}", o.max_error);
        // Second method: the fit point's distance back to the curve is |d| (these curves bend
        // gently, so the nearest point is the one it was offset from).
        let p = o.curve.point(f).unwrap();
        let back = closest_point(&c, &p).unwrap();
        prop_assert!((back.distance - d.abs()).abs() < 2.0 * tol, "{} vs {d}", back.distance);
    }
}

/// A cubic B-spline wave through `n` control points a tenth apart (self-similar pieces), with
/// control point `spike` (if any) lifted by 0.3: a sharp bump the offset needs more samples for.
fn wave(n: usize, spike: Option<usize>) -> BSplineCurve2<f64> {
    let points = (0..n)
        .map(|i| {
            let x = i as f64 / 10.0;
            let lift = if spike == Some(i) { 0.3 } else { 0.0 };
            Point2::new(x, (1.3 * x).sin() + 0.3 * (3.1 * x).cos() + lift)
        })
        .collect();
    BSplineCurve2::try_new(3, KnotVector::clamped_uniform(3, n).unwrap(), points).unwrap()
}

/// The fewest work units `offset_with` succeeds with (to 1 %), by bisection on the budget.
fn work_needed(c: &BSplineCurve2<f64>, distance: f64, tol: f64) -> u64 {
    let ok = |w: u64| offset_with(c, distance, tol, &Budget::default().with_max_work(w)).is_ok();
    let (mut lo, mut hi) = (1u64, 10_000 * c.control_points().len() as u64);
    let first = offset_with(c, distance, tol, &Budget::default().with_max_work(hi));
    assert!(first.is_ok(), "no success within {hi} units: {first:?}");
    while hi - lo > hi / 100 {
        let mid = lo + (hi - lo) / 2;
        if ok(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

#[test]
fn one_hard_piece_costs_the_same_extra_work_on_a_short_and_a_long_curve() {
    // The work a sharp bump adds must stay near the bump: when one piece that misses the
    // tolerance made every piece be resampled and refitted, the extra work grew with the
    // length of the curve (4× here).
    let (d, tol) = (0.05, 1e-6);
    let extra = |n: usize| {
        let plain = work_needed(&wave(n, None), d, tol);
        let hard = work_needed(&wave(n, Some(40)), d, tol);
        assert!(
            hard > plain,
            "the bump costs nothing at n = {n}: {hard} vs {plain}"
        );
        (hard - plain) as f64
    };
    let (short, long) = (extra(160), extra(640));
    assert!(
        long < 1.5 * short,
        "extra work {long} at 640 control points against {short} at 160"
    );
}

#[test]
fn a_long_offset_is_smooth_across_its_chunks_and_within_tolerance() {
    // 300 pieces: the fit is cut into chunks held to the exact offset's position and
    // derivatives where they meet, so the result has no triple knot and no kink there.
    let c = wave(303, Some(150));
    let (d, tol) = (0.05, 1e-6);
    let o = offset(&c, d, tol).unwrap();
    assert!(o.max_error <= tol, "{}", o.max_error);
    let f = &o.curve;
    let knots = f.knots().as_slice();
    for w in knots[4..knots.len() - 4].windows(3) {
        assert!(w[2] - w[0] > 0.0, "triple knot at {}", w[0]);
    }
    // C1 at every interior knot: the derivative just before equals the one at it.
    for &k in &knots[4..knots.len() - 4] {
        // The left limit, from just before the knot to second order.
        let mut before = [Vector2::zeros(); 3];
        f.derivatives_into(k - 1e-9, &mut before).unwrap();
        let left = before[1] + before[2] * 1e-9;
        let right = f.derivative(k).unwrap();
        assert!(
            (left - right).norm() < 1e-5 * right.norm(),
            "kink at {k}: {left} vs {right}"
        );
    }
    // The error measured again, independently, at parameters the fit never sampled.
    let (a, b) = c.domain();
    for i in 0..=20_000 {
        let s = (f64::from(i) + 0.37) / 20_001.0;
        let u = a + (b - a) * s;
        let (p, t) = c.point_and_derivative(u).unwrap();
        let exact = p + Vector2::new(-t.y, t.x) * (d / t.norm());
        let e = (f.point(s).unwrap() - exact).norm();
        assert!(e <= tol, "error {e} at s = {s}");
    }
}
