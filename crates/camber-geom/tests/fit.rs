//! Interpolation and approximation: hand-derived interpolants, reproduction of curves the
//! spline space contains (a second method: the curve the data were sampled from), and
//! properties (interpolants pass through their points and meet their end derivatives, least
//! squares is optimal against perturbations, fits meet their tolerance).

// Test helpers outside #[test] functions unwrap too; a failed unwrap is a failed test.
#![allow(clippy::unwrap_used)]

use camber_geom::budget::Budget;
use camber_geom::composite::ContinuityTolerances;
use camber_geom::fit::{
    approximate, approximate_with, data_parameters, fit_split, fit_to_tolerance,
    fit_to_tolerance_with, interpolate, FitOptions, JointContinuity, KnotPlacement,
    ParameterMethod, SplitAt,
};
use camber_geom::queries::closest_point;
use camber_geom::{BezierCurve2, Continuity, Error, ParametricCurve};
use camber_workloads::airfoils::{naca, Spacing};
use nalgebra::{Point2, Vector2};
use proptest::prelude::*;

#[test]
fn a_quadratic_through_three_points_by_hand() {
    // Uniform parameters 0, 1/2, 1 and p = 2: one Bézier span with C(1/2) = (1, 1), so
    // P1 = 2 C(1/2) − (P0 + P2)/2 = (1, 2).
    let pts = [
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 1.0),
        Point2::new(2.0, 0.0),
    ];
    let fit = interpolate(&pts, 2, ParameterMethod::Uniform, None).unwrap();
    let cps = fit.curve.control_points();
    assert_eq!(cps.len(), 3);
    assert!((cps[1] - Point2::new(1.0, 2.0)).norm() < 1e-14, "{cps:?}");
    assert!(fit.max_error < 1e-14);
}

#[test]
fn a_cubic_is_reproduced_from_four_samples() {
    let bezier = BezierCurve2::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 3.0),
        Point2::new(2.0, -1.0),
        Point2::new(4.0, 1.0),
    ])
    .unwrap();
    let samples: Vec<_> = (0..4)
        .map(|i| bezier.point(f64::from(i) / 3.0).unwrap())
        .collect();
    let fit = interpolate(&samples, 3, ParameterMethod::Uniform, None).unwrap();
    for (a, b) in fit
        .curve
        .control_points()
        .iter()
        .zip(bezier.control_points())
    {
        assert!((a - b).norm() < 1e-12);
    }
    // Least squares over many samples recovers it too (the data lie in the spline space).
    let many: Vec<_> = (0..=30)
        .map(|i| bezier.point(f64::from(i) / 30.0).unwrap())
        .collect();
    let ls = approximate(&many, 3, 4, ParameterMethod::Uniform, false).unwrap();
    for (a, b) in ls
        .curve
        .control_points()
        .iter()
        .zip(bezier.control_points())
    {
        assert!((a - b).norm() < 1e-10);
    }
}

#[test]
fn end_derivatives_are_met() {
    let pts = [
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 1.0),
        Point2::new(2.0, 0.0),
        Point2::new(3.0, 1.0),
    ];
    let (d0, d1) = (Vector2::new(0.0, 5.0), Vector2::new(5.0, 0.0));
    let fit = interpolate(&pts, 3, ParameterMethod::ChordLength, Some((d0, d1))).unwrap();
    assert_eq!(fit.curve.control_points().len(), 6);
    assert!((fit.curve.derivative(0.0).unwrap() - d0).norm() < 1e-10);
    assert!((fit.curve.derivative(1.0).unwrap() - d1).norm() < 1e-10);
    assert!(fit.max_error < 1e-12);
}

/// Many points: the systems are assembled in band storage, so 20,000 points cost megabytes
/// (dense storage would take 3.2 GB and an n² scan). The interpolant still passes through
/// every point, and least squares on 2,000 control points stays within its data's spread.
#[test]
fn twenty_thousand_points_fit_in_band_storage() {
    let pts: Vec<Point2<f64>> = (0..20_000)
        .map(|k| {
            let t = k as f64 / 19_999.0;
            Point2::new(10.0 * t, (6.0 * t).sin() + 0.1 * (40.0 * t).cos())
        })
        .collect();
    let fit = interpolate(&pts, 3, ParameterMethod::ChordLength, None).unwrap();
    assert_eq!(fit.curve.control_points().len(), pts.len());
    assert!(fit.max_error < 1e-9, "{}", fit.max_error);
    for (q, &u) in pts.iter().zip(&fit.parameters).step_by(997) {
        assert!((fit.curve.point(u).unwrap() - q).norm() < 1e-9);
    }
    let ls = approximate(&pts, 3, 2_000, ParameterMethod::ChordLength, true).unwrap();
    assert_eq!(ls.curve.control_points().len(), 2_000);
    assert!(ls.max_error < 1e-6, "{}", ls.max_error);
}

#[test]
fn bad_data_is_typed() {
    let pts = [
        Point2::new(0.0, 0.0),
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 0.0),
    ];
    assert_eq!(
        interpolate(&pts, 2, ParameterMethod::ChordLength, None).unwrap_err(),
        Error::CoincidentDataPoints { index: 1 }
    );
    assert!(matches!(
        interpolate(&pts[..2], 2, ParameterMethod::Uniform, None),
        Err(Error::TooFewDataPoints {
            needed: 3,
            found: 2,
            ..
        })
    ));
    let line = [
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 0.0),
        Point2::new(2.0, 0.0),
    ];
    assert!(matches!(
        approximate(&line, 1, 5, ParameterMethod::Uniform, true),
        Err(Error::TooFewDataPoints { .. })
    ));
    assert!(matches!(
        fit_to_tolerance(&line, 1, 0.0, ParameterMethod::Uniform),
        Err(Error::NonPositiveTolerance { .. })
    ));
    assert!(matches!(
        data_parameters(
            &[Point2::new(f64::NAN, 0.0), Point2::new(1.0, 0.0)],
            ParameterMethod::Uniform
        ),
        Err(Error::NonFinite { .. })
    ));
}

fn data_strategy() -> impl Strategy<Value = (usize, Vec<Point2<f64>>)> {
    (1usize..=4, 0usize..12).prop_flat_map(|(p, extra)| {
        proptest::collection::vec((-10.0..10.0, -10.0..10.0), p + 1 + extra).prop_map(move |pts| {
            // Walk forward in x so consecutive points never coincide.
            let mut x = 0.0;
            let points = pts
                .into_iter()
                .map(|(dx, y): (f64, f64)| {
                    x += 0.5 + dx.abs();
                    Point2::new(x, y)
                })
                .collect();
            (p, points)
        })
    })
}

fn method(i: u8) -> ParameterMethod {
    [
        ParameterMethod::Uniform,
        ParameterMethod::ChordLength,
        ParameterMethod::Centripetal,
    ][usize::from(i % 3)]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn interpolation_passes_through_its_points((p, pts) in data_strategy(), m in 0u8..3, with_d in any::<bool>()) {
        let ends = with_d.then(|| (Vector2::new(1.0, 2.0) * 3.0, Vector2::new(2.0, -1.0) * 3.0));
        let fit = match interpolate(&pts, p, method(m), ends) {
            Ok(f) => f,
            Err(Error::SingularSystem { .. }) if with_d && p == 1 => return Ok(()),
            Err(e) => return Err(TestCaseError::fail(e.to_string())),
        };
        let scale = 1.0 + pts.iter().map(|q| q.coords.norm()).fold(0.0, f64::max);
        for (q, &u) in pts.iter().zip(&fit.parameters) {
            prop_assert!((fit.curve.point(u).unwrap() - q).norm() < 1e-8 * scale);
        }
        if let Some((d0, d1)) = ends {
            prop_assert!((fit.curve.derivative(0.0).unwrap() - d0).norm() < 1e-7 * scale);
            prop_assert!((fit.curve.derivative(1.0).unwrap() - d1).norm() < 1e-7 * scale);
        }
    }

    #[test]
    fn least_squares_beats_its_perturbations(
        (p, pts) in data_strategy(), m in 0u8..3, fixed in any::<bool>(), k in 0usize..8,
        dx in -0.1..0.1_f64, dy in -0.1..0.1_f64,
    ) {
        let n = (p + 1 + k).min(pts.len());
        let fit = approximate(&pts, p, n, method(m), fixed).unwrap();
        let sse = |c: &camber_geom::BSplineCurve2<f64>| -> f64 {
            pts.iter().zip(&fit.parameters).map(|(q, &u)| (c.point(u).unwrap() - q).norm_squared()).sum()
        };
        let base = sse(&fit.curve);
        let mut cps = fit.curve.control_points().to_vec();
        let lo = usize::from(fixed);
        let hi = cps.len() - usize::from(fixed);
        prop_assume!(lo < hi);
        let i = lo + k % (hi - lo);
        cps[i] += Vector2::new(dx, dy);
        let moved = fit.curve.with_control_points(cps).unwrap();
        prop_assert!(sse(&moved) >= base - 1e-9 * (1.0 + base), "{} < {base}", sse(&moved));
        if fixed {
            prop_assert!((fit.curve.point(0.0).unwrap() - pts[0]).norm() < 1e-12);
            prop_assert!((fit.curve.point(1.0).unwrap() - pts[pts.len() - 1]).norm() < 1e-12);
        }
    }

    #[test]
    fn fits_meet_their_tolerance((p, pts) in data_strategy(), m in 0u8..3, tol_exp in -6i32..0) {
        let tol = 10f64.powi(tol_exp);
        let fit = match fit_to_tolerance(&pts, p, tol, method(m)) {
            Ok(f) => f,
            // Only a tolerance below the interpolant's rounding may be out of reach.
            Err(Error::ToleranceNotMet { reached, .. }) if reached < 1e-9 => return Ok(()),
            Err(e) => return Err(TestCaseError::fail(e.to_string())),
        };
        prop_assert!(fit.max_error <= tol);
        prop_assert!(fit.curve.control_points().len() <= pts.len());
        // Measured again independently of the fit's own figure.
        for (q, &u) in pts.iter().zip(&fit.parameters) {
            prop_assert!((fit.curve.point(u).unwrap() - q).norm() <= tol * (1.0 + 1e-9));
        }
    }
}

/// Smooth random curves: a cubic Bézier arc plus a small wave, sampled at random increasing
/// parameters (20 to 120 points).
fn smooth_strategy() -> impl Strategy<Value = Vec<Point2<f64>>> {
    (
        proptest::collection::vec((-5.0..5.0_f64, -5.0..5.0_f64), 4),
        0.0..0.3_f64,
        1.0..6.0_f64,
        proptest::collection::vec(0.2..1.0_f64, 20..120),
    )
        .prop_map(|(cps, amp, freq, steps)| {
            let bez = BezierCurve2::try_new(
                cps.iter()
                    .enumerate()
                    .map(|(i, &(x, y))| Point2::new(3.0 * i as f64 + x * 0.3, y))
                    .collect(),
            )
            .unwrap();
            let total: f64 = steps.iter().sum();
            let mut t = 0.0;
            let mut out = vec![bez.point(0.0).unwrap()];
            for s in &steps {
                t = (t + s / total).min(1.0);
                let p = bez.point(t).unwrap();
                out.push(p + Vector2::new(0.0, amp * (freq * t * 6.0).sin()));
            }
            out.dedup_by(|a, b| (*a - *b).norm() < 1e-9);
            out
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// The reported error is the distance to the whole curve: no data point is farther from the
    /// curve (by the toolkit's closest point, searched on the whole curve) than the tolerance,
    /// and the largest such distance is the reported one.
    #[test]
    fn adaptive_fits_stay_within_tolerance_by_distance(pts in smooth_strategy(), tol_exp in -6i32..-1, centripetal in any::<bool>()) {
        let tol = 10f64.powi(tol_exp);
        let method = if centripetal { ParameterMethod::Centripetal } else { ParameterMethod::ChordLength };
        let fit = fit_to_tolerance_with(&pts, tol, &FitOptions::default().with_method(method), &Budget::default()).unwrap();
        prop_assert!(fit.max_error <= tol);
        let mut worst = 0.0_f64;
        for q in &pts {
            let d = closest_point(&fit.curve, q).unwrap().distance;
            prop_assert!(d <= tol * (1.0 + 1e-9), "{d} > {tol}");
            worst = worst.max(d);
        }
        // Equal up to the rounding of two closest-point searches (a few ulps of the data's
        // size: an interpolating fit's distances are themselves rounding, ~1e-15).
        let size = pts.iter().map(|q| q.coords.amax()).fold(1.0_f64, f64::max);
        let rounding = 64.0 * f64::EPSILON * size;
        prop_assert!((worst - fit.max_error).abs() <= 1e-9 * tol + rounding, "{worst} vs {}", fit.max_error);
        // Interpolation only when the tolerance asks for it: fewer control points than data
        // whenever a least-squares fit with one control point fewer meets the tolerance.
        if fit.curve.control_points().len() == pts.len() {
            let fewer = approximate_with(&pts, pts.len() - 1, &FitOptions::default().with_method(method)).unwrap();
            prop_assert!(fewer.max_error > tol);
        }
    }
}

#[test]
fn airfoils_fit_with_few_control_points_and_never_interpolate() {
    // NACA sections at 1e-4 chord: a few dozen control points, far fewer than points.
    for (code, n, spacing, most) in [
        ("2412", 201, Spacing::Cosine, 26),
        ("0012", 141, Spacing::Uniform, 32),
        ("23015", 400, Spacing::Cosine, 26),
        ("6409", 71, Spacing::Cosine, 30),
    ] {
        let pts = naca(code, n, spacing).unwrap();
        let fit =
            fit_to_tolerance_with(&pts, 1e-4, &FitOptions::default(), &Budget::default()).unwrap();
        let count = fit.curve.control_points().len();
        assert!(fit.max_error <= 1e-4, "{code}: {}", fit.max_error);
        assert!(count <= most, "{code}-{n}: {count} control points");
        for q in pts.iter().step_by(7) {
            assert!(closest_point(&fit.curve, q).unwrap().distance <= 1e-4);
        }
    }
}

#[test]
fn sparse_sections_at_a_fine_tolerance_keep_their_count_near_the_splprep_one() {
    // 71 points at equal steps of x: the nose holds a few points, which a fit within 1e-5
    // nearly interpolates, and the error density of that fit used to predict far too few knots
    // and spread them away from the nose (51 control points; FITPACK's splprep needs 30 at the
    // same measured deviation). Every span now counts as erring a few percent of the tolerance
    // at least.
    let pts = naca("2415", 71, Spacing::Uniform).unwrap();
    let fit =
        fit_to_tolerance_with(&pts, 1e-5, &FitOptions::default(), &Budget::default()).unwrap();
    let count = fit.curve.control_points().len();
    assert!(fit.max_error <= 1e-5, "{}", fit.max_error);
    assert!(count <= 46, "{count} control points");
    for q in &pts {
        assert!(closest_point(&fit.curve, q).unwrap().distance <= 1e-5);
    }
}

#[test]
fn adaptive_knots_beat_averaged_knots_at_a_sharp_leading_edge() {
    let pts = naca("0012", 201, Spacing::Cosine).unwrap();
    let opts = FitOptions::default();
    let averaged = approximate_with(&pts, 16, &opts.with_knots(KnotPlacement::Averaged)).unwrap();
    let adaptive = approximate_with(&pts, 16, &opts).unwrap();
    assert_eq!(adaptive.curve.control_points().len(), 16);
    assert!(
        adaptive.max_error < 0.5 * averaged.max_error,
        "{} vs {}",
        adaptive.max_error,
        averaged.max_error
    );
}

#[test]
fn split_airfoils_join_g1_or_g2_at_the_leading_edge() {
    let pts = naca("2412", 201, Spacing::Cosine).unwrap();
    // The cambered section's smallest x lies just above the chord line's origin.
    let le = (0..pts.len())
        .min_by(|&a, &b| pts[a].x.total_cmp(&pts[b].x))
        .unwrap();
    assert_eq!(le, 99);
    for joint in [JointContinuity::G1, JointContinuity::G2] {
        let fit = fit_split(
            &pts,
            1e-4,
            &FitOptions::default(),
            &SplitAt::LeadingEdge,
            joint,
            &Budget::default(),
        )
        .unwrap();
        assert_eq!(fit.joints, vec![le]);
        assert!(fit.max_error <= 1e-4);
        // The pieces share the leading-edge point.
        let a = fit.pieces[0].curve.point(1.0).unwrap();
        let b = fit.pieces[1].curve.point(0.0).unwrap();
        assert!((a - pts[le]).norm() < 1e-12 && (b - pts[le]).norm() < 1e-12);
        let report = fit.to_composite().unwrap().joints().unwrap()[0];
        let tol = ContinuityTolerances {
            angle: 1e-9,
            curvature: 1e-6,
            ..Default::default()
        };
        let want = if joint == JointContinuity::G1 {
            Continuity::G1
        } else {
            Continuity::G2
        };
        assert!(report.continuity(&tol) >= want, "{joint:?}: {report:?}");
        for (piece, range) in fit.pieces.iter().zip([&pts[..=le], &pts[le..]]) {
            for q in range {
                assert!(closest_point(&piece.curve, q).unwrap().distance <= 1e-4);
            }
        }
    }
}

#[test]
fn bad_splits_and_unreachable_tolerances_are_typed() {
    let pts = naca("0012", 41, Spacing::Cosine).unwrap();
    let opts = FitOptions::default();
    assert_eq!(
        fit_split(
            &pts,
            1e-4,
            &opts,
            &SplitAt::Indices(vec![0]),
            JointContinuity::G1,
            &Budget::default()
        )
        .unwrap_err(),
        Error::SplitPointAtEnd { index: 0, last: 40 }
    );
    assert!(matches!(
        fit_split(
            &pts,
            1e-4,
            &opts,
            &SplitAt::Parameters(vec![1.5]),
            JointContinuity::G1,
            &Budget::default()
        ),
        Err(Error::ParameterOutsideDomain { .. })
    ));
    assert!(matches!(
        fit_split(
            &pts,
            1e-4,
            &opts,
            &SplitAt::Parameters(vec![f64::NAN]),
            JointContinuity::G1,
            &Budget::default()
        ),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        fit_to_tolerance_with(&pts, 1e-300, &opts, &Budget::default()),
        Err(Error::ToleranceNotMet { .. })
    ));
    assert!(matches!(
        fit_to_tolerance_with(&pts, f64::INFINITY, &opts, &Budget::default()),
        Err(Error::NonFinite { .. })
    ));
    let one = [Point2::new(0.0, 0.0)];
    assert!(matches!(
        fit_to_tolerance_with(&one, 1e-3, &opts, &Budget::default()),
        Err(Error::TooFewDataPoints { .. })
    ));
    let empty: [Point2<f64>; 0] = [];
    assert!(matches!(
        fit_to_tolerance_with(&empty, 1e-3, &opts, &Budget::default()),
        Err(Error::TooFewDataPoints { .. })
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The banded solver against nalgebra's dense LU on random diagonally weighted band
    /// matrices (lower width 2, upper width 1).
    #[test]
    fn banded_elimination_agrees_with_dense_lu(
        n in 3usize..12, values in proptest::collection::vec(-1.0..1.0_f64, 48),
    ) {
        use nalgebra::DMatrix;
        let mut a = DMatrix::<f64>::zeros(n, n);
        let mut k = 0;
        for r in 0..n {
            for c in r.saturating_sub(2)..=(r + 1).min(n - 1) {
                a[(r, c)] = values[k % values.len()] + if r == c { 0.5 } else { 0.0 };
                k += 1;
            }
        }
        let b = DMatrix::from_fn(n, 2, |r, c| values[(r + 7 * c) % values.len()]);
        let dense = a.clone().lu().solve(&b);
        let banded = camber_geom::banded::solve_banded(a.clone(), b.clone());
        if let (Some(x), Some(y)) = (&dense, &banded) {
            let residual = (&a * y - &b).norm();
            prop_assume!((&a * x - &b).norm() < 1e-8);
            prop_assert!(residual < 1e-8 * (1.0 + x.norm()), "{residual}");
        }
    }
}
