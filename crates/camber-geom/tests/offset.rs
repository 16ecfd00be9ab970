//! Offsets: hand-derived offsets of lines and circles, and on random cubics the measured error
//! against a second method (the distance from the offset fit back to the curve).

// Test helpers outside #[test] functions unwrap too; a failed unwrap is a failed test.
#![allow(clippy::unwrap_used)]

use camber_geom::offset::offset;
use camber_geom::queries::closest_point;
use camber_geom::{BSplineCurve2, BezierCurve2, Error, KnotVector, NurbsCurve2, ParametricCurve};
use nalgebra::Point2;
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
