//! Arc length: hand-derived lengths (circle, parabola, straight lines with uneven speed), a
//! second method (dense chord sums), properties (additivity, the parameter at a length inverts
//! the length) and the measured error of the arc-length map.

// Test helpers outside #[test] functions unwrap too; a failed unwrap is a failed test.
#![allow(clippy::unwrap_used)]

use camber_geom::arc_length::{
    arc_length, arc_length_between, arc_length_map, parameter_at_length,
};
use camber_geom::{BSplineCurve2, BezierCurve2, Error, KnotVector, NurbsCurve2, ParametricCurve};
use nalgebra::Point2;
use num_dual::Dual64;
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, TAU};

#[test]
fn the_rational_circle_is_two_pi_long() {
    let c = NurbsCurve2::try_circular_arc(Point2::origin(), 1.0, 0.0, TAU).unwrap();
    let l = arc_length(&c, 1e-12).unwrap();
    assert!((l.length - TAU).abs() < 1e-11, "{l:?}");
    assert!(l.error_estimate <= 1e-12);
    let q = arc_length_between(&c, 0.25, 0.5, 1e-12).unwrap();
    assert!((q.length - FRAC_PI_2).abs() < 1e-11);
    // The parameter a quarter of the way round is the joint u = 1/4.
    let u = parameter_at_length(&c, FRAC_PI_2, 1e-12).unwrap();
    assert!((u - 0.25).abs() < 1e-11, "{u}");
}

#[test]
fn the_parabola_by_hand() {
    // x = t, y = t²: L = √5/2 + asinh(2)/4.
    let c = BezierCurve2::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(0.5, 0.0),
        Point2::new(1.0, 1.0),
    ])
    .unwrap();
    let exact = 5.0_f64.sqrt() / 2.0 + 2.0_f64.asinh() / 4.0;
    let l = arc_length(&c, 1e-13).unwrap();
    assert!((l.length - exact).abs() < 1e-12, "{} vs {exact}", l.length);
}

/// The length of a cubic Bézier curve that runs back and forth along the x axis: the total
/// variation of x(u), the sum of |x(rᵢ₊₁) − x(rᵢ)| between 0, the roots rᵢ of x′ in (0, 1)
/// (a quadratic, solved by its formula) and 1.
fn back_and_forth_length(x: [f64; 4]) -> f64 {
    let at = |u: f64| {
        let v = 1.0 - u;
        v * v * v * x[0] + 3.0 * v * v * u * x[1] + 3.0 * v * u * u * x[2] + u * u * u * x[3]
    };
    // x′(u)/3 = A u² + B u + C with A = d0 − 2d1 + d2, B = 2(d1 − d0), C = d0.
    let (d0, d1, d2) = (x[1] - x[0], x[2] - x[1], x[3] - x[2]);
    let (a, b, c) = (d0 - 2.0 * d1 + d2, 2.0 * (d1 - d0), d0);
    let mut roots = vec![0.0];
    let disc = b * b - 4.0 * a * c;
    if a.abs() > 1e-300 && disc > 0.0 {
        let mut r = [
            (-b - disc.sqrt()) / (2.0 * a),
            (-b + disc.sqrt()) / (2.0 * a),
        ];
        r.sort_by(f64::total_cmp);
        roots.extend(r.into_iter().filter(|r| *r > 0.0 && *r < 1.0));
    }
    roots.push(1.0);
    roots.windows(2).map(|w| (at(w[1]) - at(w[0])).abs()).sum()
}

#[test]
fn a_curve_turning_back_on_itself_is_measured_across_its_cusps() {
    // Found by the Python suite's property test: the curve backs up 0.03125 → ≈0.03 near u = 0,
    // runs out to ≈1.8 and comes back to 0; both turns are cusps of the speed |x′(u)|, one of
    // them between the outermost nodes of every rule that spans it.
    for x in [
        [0.03125, 0.0, 4.0, 0.0],
        [0.25, 0.0, 4.0, 0.0],
        [0.0, 1.0, -1.0, 0.5],
        [1.0, -3.0, 5.0, -2.0],
    ] {
        let c = BezierCurve2::try_new(x.iter().map(|&v| Point2::new(v, 0.0)).collect()).unwrap();
        let exact = back_and_forth_length(x);
        let l = arc_length(&c, 1e-12).unwrap();
        assert!(
            (l.length - exact).abs() < 1e-10,
            "{x:?}: {} vs {exact}",
            l.length
        );
        let half = parameter_at_length(&c, 0.5 * exact, 1e-12).unwrap();
        let back = arc_length_between(&c, 0.0, half, 1e-12).unwrap().length;
        assert!((back - 0.5 * exact).abs() < 1e-10, "{x:?}: {back}");
    }
}

/// Parabolas (δu, u²/2), u ∈ [0, 1], whose speed √(δ² + u²) has complex singularities ±iδ
/// just off the start: L = ½(√(1 + δ²) + δ²·asinh(1/δ)). For some δ the 8-point rule on a
/// leaf and on its halves used to be wrong by the same amount, so their difference, the only
/// error estimate then, promised 1e-11 and delivered 5.6e-10 (δ = 0.0611), or 1e-8 and
/// delivered 1.2e-8 (δ ≈ 0.0053). The sweep is log-uniform over δ ∈ [10⁻³, 10].
#[test]
fn near_singular_speeds_meet_the_tolerance_asked() {
    let count = 4000;
    for tolerance in [1e-8, 1e-11] {
        for k in 0..count {
            let delta = 10_f64.powf(-3.0 + 4.0 * f64::from(k) / f64::from(count));
            let c = BezierCurve2::try_new(vec![
                Point2::new(0.0, 0.0),
                Point2::new(0.5 * delta, 0.0),
                Point2::new(delta, 0.5),
            ])
            .unwrap();
            let exact =
                0.5 * ((1.0 + delta * delta).sqrt() + delta * delta * (1.0 / delta).asinh());
            let l = arc_length(&c, tolerance).unwrap();
            assert!(
                (l.length - exact).abs() <= tolerance,
                "δ = {delta:e}, tolerance {tolerance:e}: {} vs {exact}, estimate {:e}",
                l.length,
                l.error_estimate
            );
        }
    }
}

#[test]
fn bad_input_is_typed() {
    let c = BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(2.0, 0.0)]).unwrap();
    assert_eq!(
        arc_length(&c, -1.0).unwrap_err(),
        Error::NonPositiveTolerance { value: -1.0 }
    );
    assert!(matches!(
        arc_length(&c, f64::NAN),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        arc_length_between(&c, 0.6, 0.4, 1e-9),
        Err(Error::InvalidInterval { .. })
    ));
    assert!(matches!(
        parameter_at_length(&c, -0.5, 1e-9),
        Err(Error::LengthOutsideCurve { .. })
    ));
    assert!(matches!(
        parameter_at_length(&c, f64::INFINITY, 1e-9),
        Err(Error::NonFinite { .. })
    ));
    // A point curve has length 0 and every length 0 maps to the start.
    let dot =
        BezierCurve2::<f64>::try_new(vec![Point2::new(1.0, 1.0), Point2::new(1.0, 1.0)]).unwrap();
    assert!(arc_length(&dot, 1e-9).unwrap().length.abs() < 1e-300);
    assert!(parameter_at_length(&dot, 0.0, 1e-9).unwrap().abs() < 1e-15);
}

#[test]
fn dual_numbers_give_the_derivative_of_the_length() {
    // Scaling every control point by (1 + ε) scales the length: dL/dε = L.
    let pts = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)];
    let c = BezierCurve2::try_new(
        pts.iter()
            .map(|&(x, y)| Point2::new(Dual64::new(x, x), Dual64::new(y, y)))
            .collect(),
    )
    .unwrap();
    let l = arc_length(&c, 1e-12).unwrap().length;
    assert!((l.eps - l.re).abs() < 1e-10, "{l:?}");
}

fn curve_strategy() -> impl Strategy<Value = BSplineCurve2<f64>> {
    (1usize..=4, 0usize..4).prop_flat_map(|(p, extra)| {
        let n = p + 1 + extra;
        proptest::collection::vec((-5.0..5.0, -5.0..5.0), n).prop_map(move |pts| {
            let points = pts.into_iter().map(|(x, y)| Point2::new(x, y)).collect();
            BSplineCurve2::try_new(p, KnotVector::clamped_uniform(p, n).unwrap(), points).unwrap()
        })
    })
}

/// The chord sum over `n` equal parameter steps per knot span (so that corners are polygon
/// vertices): a lower bound that converges to the length.
fn chord_sum(c: &BSplineCurve2<f64>, n: usize) -> f64 {
    let mut sum = 0.0;
    for span in c.breakpoints().windows(2) {
        let (a, b) = (span[0], span[1]);
        let mut last = c.point(a).unwrap();
        for i in 1..=n {
            let p = c.point(a + (b - a) * i as f64 / n as f64).unwrap();
            sum += (p - last).norm();
            last = p;
        }
    }
    sum
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn quadrature_agrees_with_dense_chords(c in curve_strategy()) {
        let l = arc_length(&c, 1e-10).unwrap();
        let chords = chord_sum(&c, 5_000);
        prop_assert!(chords <= l.length + 1e-9);
        // The chord error is O(h²·curvature); 20 000 steps on these curves stays below 1e-5.
        prop_assert!(l.length - chords < 1e-5 * (1.0 + l.length), "{} vs {chords}", l.length);
    }

    #[test]
    fn lengths_add_and_invert(c in curve_strategy(), f in 0.05..0.95_f64) {
        let (a, b) = c.domain();
        let m = a + (b - a) * f;
        let whole = arc_length(&c, 1e-11).unwrap().length;
        let left = arc_length_between(&c, a, m, 1e-11).unwrap().length;
        let right = arc_length_between(&c, m, b, 1e-11).unwrap().length;
        prop_assert!((left + right - whole).abs() < 1e-9);
        prop_assume!(whole > 1e-6);
        let u = parameter_at_length(&c, left, 1e-11).unwrap();
        let back = arc_length_between(&c, a, u, 1e-11).unwrap().length;
        prop_assert!((back - left).abs() < 1e-8, "{back} vs {left}");
    }

    #[test]
    fn the_map_meets_its_tolerance(c in curve_strategy(), f in 0.0..1.0_f64) {
        let map = arc_length_map(&c, 1e-6).unwrap();
        prop_assert!(map.max_error() <= 1e-6 || map.node_count() > 1000);
        prop_assume!(map.length() > 1e-3);
        // A second check away from the midpoints where the error was measured.
        let s = map.length() * f;
        let u = map.parameter(s).unwrap();
        let (a, _) = c.domain();
        let along = arc_length_between(&c, a, u, 1e-12).unwrap().length;
        prop_assert!((along - s).abs() < 1e-5, "{along} vs {s}");
    }
}
