//! Extension: hand-derived extrapolations, agreement with the original on its domain, the
//! extrapolated part against a second method (the Taylor series of the end piece), the NURBS
//! circle staying on its circle, and length extensions with their continuity and length.

// Test helpers outside #[test] functions unwrap too; a failed unwrap is a failed test.
#![allow(clippy::unwrap_used)]

use camber_geom::arc_length::arc_length_between;
use camber_geom::extend::{CurveEnd, ExtensionContinuity};
use camber_geom::queries::signed_curvature;
use camber_geom::{BSplineCurve2, BezierCurve2, Error, KnotVector, NurbsCurve2, ParametricCurve};
use nalgebra::{Point2, Vector2};
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, TAU};

#[test]
fn bezier_extrapolation_by_hand() {
    // x = 2t, y = 2t(1 − t) continued back to t = −1: Q0 = C(−1) = (−2, −4),
    // Q1 = f(−1, 1) = (0, 2), Q2 = C(1) = (2, 0).
    let c = BezierCurve2::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 1.0),
        Point2::new(2.0, 0.0),
    ])
    .unwrap();
    let e = c.extrapolated(CurveEnd::Start, -1.0).unwrap();
    let expected = [(-2.0, -4.0), (0.0, 2.0), (2.0, 0.0)];
    for (p, (x, y)) in e.control_points().iter().zip(expected) {
        assert!((p - Point2::new(x, y)).norm() < 1e-14, "{p}");
    }
    assert!(matches!(
        c.extrapolated(CurveEnd::Start, 0.5),
        Err(Error::ExtensionInsideDomain { .. })
    ));
    assert!(matches!(
        c.extrapolated(CurveEnd::End, f64::NAN),
        Err(Error::NonFinite { .. })
    ));
}

#[test]
fn the_nurbs_circle_continues_on_its_circle() {
    let arc = NurbsCurve2::try_circular_arc(Point2::new(1.0, 2.0), 3.0, 0.0, FRAC_PI_2).unwrap();
    for end in [CurveEnd::Start, CurveEnd::End] {
        let target = if end == CurveEnd::End { 1.4 } else { -0.4 };
        let e = arc.extrapolated(end, target).unwrap();
        for i in 0..=20 {
            let u = target.min(0.0) + (target.max(1.0) - target.min(0.0)) * f64::from(i) / 20.0;
            let r = (e.point(u).unwrap() - Point2::new(1.0, 2.0)).norm();
            assert!((r - 3.0).abs() < 1e-12, "{u}: {r}");
        }
    }
    // By a length with G2: a quarter arc of radius 3 extended by 3·π/4 ends at 135°.
    let e = arc
        .extended_by_length(
            CurveEnd::End,
            3.0 * FRAC_PI_2 / 2.0,
            ExtensionContinuity::G2,
        )
        .unwrap();
    let end = e.point(e.domain().1).unwrap();
    let angle = 0.75 * std::f64::consts::PI;
    let expected = Point2::new(1.0 + 3.0 * angle.cos(), 2.0 + 3.0 * angle.sin());
    assert!((end - expected).norm() < 1e-10, "{end} vs {expected}");
}

#[test]
fn g1_attaches_a_tangent_line() {
    let c = BSplineCurve2::try_new(
        3,
        KnotVector::clamped_uniform(3, 5).unwrap(),
        vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 2.0),
            Point2::new(2.0, -1.0),
            Point2::new(3.0, 1.0),
            Point2::new(4.0, 0.0),
        ],
    )
    .unwrap();
    // At the start the tangent is along (1, 2); going back by √5 reaches (−1, −2).
    let e = c
        .extended_by_length(CurveEnd::Start, 5.0_f64.sqrt(), ExtensionContinuity::G1)
        .unwrap();
    let (a, _) = e.domain();
    assert!((e.point(a).unwrap() - Point2::new(-1.0, -2.0)).norm() < 1e-12);
    // C1 at the joint: the derivative from the left equals the original's.
    let d_left = e.derivative(-1e-9).unwrap();
    assert!((d_left - c.derivative(0.0).unwrap()).norm() < 1e-6);
    for i in 0..=10 {
        let u = f64::from(i) / 10.0;
        assert!((e.point(u).unwrap() - c.point(u).unwrap()).norm() < 1e-13);
    }
}

fn curve_strategy() -> impl Strategy<Value = BSplineCurve2<f64>> {
    (1usize..=4, 0usize..4).prop_flat_map(|(p, extra)| {
        let n = p + 1 + extra;
        (
            proptest::collection::vec((-5.0..5.0, -5.0..5.0), n),
            proptest::collection::vec(0.1..1.0, extra + 1),
        )
            .prop_map(move |(pts, gaps)| {
                // Random interior knots from cumulative gaps.
                let mut knots = vec![0.0; p + 1];
                let mut t = 0.0;
                for g in &gaps[..extra] {
                    t += g;
                    knots.push(t);
                }
                t += gaps[extra];
                knots.extend(std::iter::repeat_n(t, p + 1));
                let points = pts.into_iter().map(|(x, y)| Point2::new(x, y)).collect();
                BSplineCurve2::try_new(p, KnotVector::try_new(knots).unwrap(), points).unwrap()
            })
    })
}

/// Σ_k C⁽ᵏ⁾(u) δᵏ / k!: the end piece's polynomial by its Taylor series.
fn taylor(c: &BSplineCurve2<f64>, u: f64, delta: f64) -> Point2<f64> {
    let d = c.derivatives(u, c.degree()).unwrap();
    let mut sum = Vector2::zeros();
    let mut factor = 1.0;
    for (k, dk) in d.iter().enumerate() {
        if k > 0 {
            factor *= delta / k as f64;
        }
        sum += dk * factor;
    }
    Point2::from(sum)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn extrapolation_keeps_the_curve_and_continues_its_end_piece(
        c in curve_strategy(), reach in 0.05..1.5_f64, f in 0.0..1.0_f64,
    ) {
        let (a, b) = c.domain();
        let after = c.extrapolated(CurveEnd::End, b + reach).unwrap();
        let before = c.extrapolated(CurveEnd::Start, a - reach).unwrap();
        let u = a + (b - a) * f;
        let p = c.point(u).unwrap();
        prop_assert!((after.point(u).unwrap() - p).norm() < 1e-9);
        prop_assert!((before.point(u).unwrap() - p).norm() < 1e-9);
        let delta = reach * f;
        let scale = 1.0 + c.control_points().iter().map(|q| q.coords.norm()).fold(0.0, f64::max);
        let err_end = (after.point(b + delta).unwrap() - taylor(&c, b, delta)).norm();
        let err_start = (before.point(a - delta).unwrap() - taylor(&c, a, -delta)).norm();
        prop_assert!(err_end < 1e-8 * scale * (1.0 + reach).powi(4), "{err_end}");
        prop_assert!(err_start < 1e-8 * scale * (1.0 + reach).powi(4), "{err_start}");
    }

    #[test]
    fn length_extensions_add_the_length(
        c in curve_strategy(), length in 0.1..3.0_f64, g2 in any::<bool>(), start in any::<bool>(),
    ) {
        let (a, b) = c.domain();
        let end = if start { CurveEnd::Start } else { CurveEnd::End };
        let (pa, va) = c.point_and_derivative(if start { a } else { b }).unwrap();
        prop_assume!(va.norm() > 1e-3);
        let continuity = if g2 { ExtensionContinuity::G2 } else { ExtensionContinuity::G1 };
        let e = match c.extended_by_length(end, length, continuity) {
            Ok(e) => e,
            // A natural extrapolation whose speed dies out cannot always reach the length.
            Err(Error::ZeroLength { .. }) if g2 => return Ok(()),
            Err(other) => return Err(TestCaseError::fail(format!("{other}"))),
        };
        let (ea, eb) = e.domain();
        let added = if start {
            arc_length_between(&e, ea, a, 1e-12).unwrap().length
        } else {
            arc_length_between(&e, b, eb, 1e-12).unwrap().length
        };
        prop_assert!((added - length).abs() < 1e-8 * (1.0 + length), "{added} vs {length}");
        let u = a + (b - a) * 0.37;
        prop_assert!((e.point(u).unwrap() - c.point(u).unwrap()).norm() < 1e-9);
        if !g2 {
            let tip = e.point(if start { ea } else { eb }).unwrap();
            let dir = if start { -va.normalize() } else { va.normalize() };
            prop_assert!((tip - (pa + dir * length)).norm() < 1e-9);
        } else if c.degree() >= 2 {
            // Curvature continuity at the joint, from both sides.
            let j = if start { a } else { b };
            let eps = (b - a) * 1e-7;
            let (k1, k2) = if start {
                (signed_curvature(&e, j - eps).unwrap(), signed_curvature(&c, j).unwrap())
            } else {
                (signed_curvature(&e, j + eps).unwrap(), signed_curvature(&c, j).unwrap())
            };
            prop_assume!(k2.abs() < 1e3);
            prop_assert!((k1 - k2).abs() < 1e-4 * (1.0 + k2.abs()), "{k1} vs {k2}");
        }
    }
}

#[test]
fn full_circle_length_check() {
    // Guard against a sign slip in the start-side extension of a closed NURBS curve.
    let c = NurbsCurve2::try_circular_arc(Point2::origin(), 1.0, 0.0, TAU).unwrap();
    let e = c
        .extended_by_length(CurveEnd::Start, 0.5, ExtensionContinuity::G1)
        .unwrap();
    let tip = e.point(e.domain().0).unwrap();
    assert!((tip - Point2::new(1.0, -0.5)).norm() < 1e-12, "{tip}");
}
