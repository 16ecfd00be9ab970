//! The curve toolkit held to its limits: absurd orders and tolerances, far control points,
//! NaN queries, overlapping curves, splits next to a knot, and every iterative routine under a
//! work budget and a stop flag. Each answer is a typed error, a bounded run, or a right answer
//! checked against an independent reference (tests/reference: fixed-grid 5-point
//! Gauss–Legendre).

// Test helpers outside #[test] functions unwrap too; a failed unwrap is a failed test.
#![allow(clippy::unwrap_used)]

mod reference;

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use camber_geom::arc_length::{
    arc_length, arc_length_map, arc_length_map_with, arc_length_with, floor,
    parameter_at_length_with, parameters_at_lengths,
};
use camber_geom::budget::Budget;
use camber_geom::curve::MAX_DERIVATIVE_ORDER;
use camber_geom::fit::{fit_to_tolerance_with, FitOptions, ParameterMethod};
use camber_geom::offset::{offset, offset_with};
use camber_geom::queries::{
    closest_point, closest_point_with, curve_distance, intersect_curves,
    intersect_curves_with_overlaps, CurveCurveOptions, QueryOptions,
};
use camber_geom::{
    BSplineCurve2, BezierCurve2, Error, HermiteCurve2, KnotVector, NurbsCurve2, ParametricCurve,
};
use nalgebra::{Point2, Vector2};
use reference::Reference;

/// A wavy clamped B-spline of `degree` through `n` control points on x ∈ [0, n/4].
fn wave(degree: usize, n: usize) -> BSplineCurve2<f64> {
    let points = (0..n)
        .map(|i| {
            let x = i as f64 / 4.0;
            Point2::new(x, (1.3 * x).sin() + 0.3 * (3.1 * x).cos())
        })
        .collect();
    BSplineCurve2::try_new(
        degree,
        KnotVector::clamped_uniform(degree, n).unwrap(),
        points,
    )
    .unwrap()
}

#[test]
fn huge_orders_and_counts_are_refused_before_allocating() {
    // Sample counts and subdivisions from outside are checked before anything is sized.
    let h = HermiteCurve2::try_new(
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 0.0),
        Vector2::new(1.0, 1.0),
        Vector2::new(1.0, -1.0),
    )
    .unwrap();
    assert!(matches!(h.subdivided(1 << 40), Err(Error::TooLarge { .. })));
    let many = QueryOptions::default().with_samples_per_piece(usize::MAX);
    assert!(matches!(
        closest_point_with(&h, &Point2::new(0.5, 1.0), &many),
        Err(Error::TooLarge { .. })
    ));
    let c = wave(3, 8);
    // 2⁴⁰ orders would be 17 TB of vectors; the order is checked first.
    assert_eq!(
        c.derivatives(0.5, 1 << 40).unwrap_err(),
        Error::TooLarge {
            what: "derivative order",
            value: 1 << 40,
            max: MAX_DERIVATIVE_ORDER
        }
    );
    assert!(c.derivatives(0.5, usize::MAX).is_err());
    let d = c.derivatives(0.5, MAX_DERIVATIVE_ORDER).unwrap();
    assert_eq!(d.len(), MAX_DERIVATIVE_ORDER + 1);
    assert!(
        d[4].norm() < 1e-300,
        "above the degree every derivative is zero"
    );
}

#[test]
fn map_tolerances_below_f64_are_clamped_and_say_so() {
    let c = wave(3, 12);
    let length = arc_length(&c, 1e-12).unwrap().length;
    // A small explicit budget: each of these must finish in bounded work, not hang.
    let budget = Budget::default().with_max_work(5_000_000);
    for tol in [1e-15, 1e-16, 1e-17, 1e-300] {
        let map = arc_length_map_with(&c, tol, &budget).unwrap();
        assert!(
            map.tolerance() > tol,
            "{tol}: clamped to {}",
            map.tolerance()
        );
        assert!(
            map.tolerance() < 1e-11 * length,
            "{tol}: {}",
            map.tolerance()
        );
        assert!(
            map.max_error() <= map.tolerance(),
            "{tol}: {}",
            map.max_error()
        );
    }
    // A reachable tolerance is kept as asked.
    let map = arc_length_map(&c, 1e-9).unwrap();
    assert!((map.tolerance() - 1e-9).abs() < 1e-24);
    // The same for the length itself.
    let l = arc_length(&c, 1e-300).unwrap();
    assert!((l.tolerance - floor(l.length)).abs() <= 1e-3 * l.tolerance);
}

/// The Bézier (0, 0), (x, 1), (2, 1), (3, 0) and the roots of its x′ in (0, 1), where its speed
/// has a sharp minimum (the reference splits there).
fn far_bezier(x: f64) -> (BezierCurve2<f64>, Vec<f64>) {
    let c = BezierCurve2::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(x, 1.0),
        Point2::new(2.0, 1.0),
        Point2::new(3.0, 0.0),
    ])
    .unwrap();
    // x′/3 = d0 (1 − t)² + 2 d1 t(1 − t) + d2 t², d = differences of the x coordinates.
    let (d0, d1, d2) = (x, 2.0 - x, 1.0);
    let (qa, qb, qc) = (d0 - 2.0 * d1 + d2, 2.0 * (d1 - d0), d0);
    let disc = (qb * qb - 4.0 * qa * qc).max(0.0).sqrt();
    let q = -0.5 * (qb + qb.signum() * disc);
    let roots = [q / qa, qc / q]
        .into_iter()
        .filter(|t| *t > 0.0 && *t < 1.0)
        .collect();
    (c, roots)
}

#[test]
fn a_far_control_point_is_measured_with_little_work() {
    for x in [1e7, 1e10, 1e12, 1e15] {
        let (c, roots) = far_bezier(x);
        // The old per-interval share of an absolute 1e-10 never converged here; a relative
        // floor and global adaptivity need a few thousand evaluations.
        let budget = Budget::default().with_max_work(200_000);
        let l = arc_length_with(&c, 1e-10, &budget).unwrap();
        let reference = Reference::new(&c, &roots, 4_000).total();
        let relative = (l.length - reference).abs() / reference;
        assert!(
            relative < 1e-10,
            "x = {x:e}: {} vs {reference} ({relative:e})",
            l.length
        );
        assert!(l.tolerance >= floor(l.length) * 0.999, "{l:?}");
        // The parameter at half the length, checked by the reference.
        let u = parameter_at_length_with(&c, 0.5 * l.length, 1e-10, &budget).unwrap();
        let back = Reference::new(&c, &roots, 4_000).length_to(&c, u);
        assert!(
            (back - 0.5 * l.length).abs() < 1e-9 * l.length,
            "x = {x:e}: {back} vs {}",
            0.5 * l.length
        );
    }
}

/// Rational curves with uneven weights, most uneven in the last spans (where the reported
/// error used to miss the true one).
fn uneven_nurbs(seed: u64) -> NurbsCurve2<f64> {
    let n = 9;
    let mut state = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
    let mut next = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let points = (0..n)
        .map(|i| Point2::new(i as f64 + next() - 0.5, 3.0 * next() - 1.5))
        .collect();
    let weights = (0..n)
        .map(|i| 0.2 + next() * (1.0 + 4.0 * i as f64 / n as f64))
        .collect();
    NurbsCurve2::try_new(
        3,
        KnotVector::clamped_uniform(3, n).unwrap(),
        points,
        weights,
    )
    .unwrap()
}

#[test]
fn the_map_error_meets_the_request_against_an_independent_quadrature() {
    let tol = 4.6e-5;
    for seed in 0..6 {
        let c = uneven_nurbs(seed);
        let map = arc_length_map(&c, tol).unwrap();
        assert!(map.max_error() <= tol, "seed {seed}: {}", map.max_error());
        let reference = Reference::new(&c, &[], 400);
        let total = map.length();
        assert!((total - reference.total()).abs() < 1e-9, "seed {seed}");
        // Every 1/3000 of the length, not only where the map measured itself.
        let mut truth = 0.0_f64;
        for k in 0..=3_000 {
            let s = total * f64::from(k) / 3_000.0;
            let u = map.parameter(s).unwrap();
            truth = truth.max((reference.length_to(&c, u) - s).abs());
        }
        assert!(truth <= tol, "seed {seed}: true error {truth:e} > {tol:e}");
        // The report is an honest maximum: no smaller than what the dense check finds.
        assert!(
            truth <= 1.05 * map.max_error() + 1e-12,
            "seed {seed}: {truth:e} vs {:e}",
            map.max_error()
        );
    }
}

#[test]
fn quadratic_spline_offsets_meet_the_tolerance_with_few_points() {
    // A degree-2 B-spline: its curvature jumps at every knot, so its offset's derivative does.
    let c = wave(2, 24);
    let (d, tol) = (0.1, 1e-6);
    let o = offset(&c, d, tol).unwrap();
    assert!(o.max_error <= tol, "{}", o.max_error);
    let count = o.curve.control_points().len();
    assert!(count < 1_000, "{count} control points");
    // Second method: every point of the fit lies |d| from the curve (the closest point).
    let (a, b) = c.domain();
    for k in 0..=500 {
        let s = f64::from(k) / 500.0;
        let p = o.curve.point(s).unwrap();
        let back = closest_point(&c, &p).unwrap();
        assert!(
            (back.distance - d).abs() < 2.0 * tol,
            "s = {s}: {}",
            back.distance
        );
        // And it is the exact offset point at the matching parameter.
        let u = a + (b - a) * s;
        let (q, t) = c.point_and_derivative(u).unwrap();
        let exact = q + Vector2::new(-t.y, t.x) * (d / t.norm());
        assert!((p - exact).norm() <= tol, "s = {s}");
    }
}

#[test]
fn far_query_points_are_measured_without_overflow() {
    // |p − C|² overflows f64 beyond ~1.3e154: the distance came back infinite.
    let c: BezierCurve2<f64> = BezierCurve2::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 2.0),
        Point2::new(3.0, -1.0),
        Point2::new(4.0, 0.0),
    ])
    .unwrap();
    for p in [
        Point2::new(0.0, 1.3407807929942597e154),
        Point2::new(1e300, 1e300),
        Point2::new(-1.7e308, 2.0_f64),
    ] {
        let near = closest_point(&c, &p).unwrap();
        assert!(near.distance.is_finite(), "{p}: {}", near.distance);
        // From that far every point of the curve is at |p| to within the curve's size.
        let expected = p.coords.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        assert!(
            near.distance >= expected * (1.0 - 1e-9),
            "{p}: {}",
            near.distance
        );
        assert!(near.distance <= expected * 1.5, "{p}: {}", near.distance);
    }
    // A distance beyond the largest f64 is refused, not answered as infinity.
    let beyond = closest_point(&c, &Point2::new(1.3e308, 1.3e308));
    assert!(
        matches!(beyond, Err(Error::NonFinite { value, .. }) if value.is_infinite()),
        "{beyond:?}"
    );
    // A point near the curve gets the same answer as before the scaling (σ = 1 there).
    let near = closest_point(&c, &Point2::new(2.0, 3.0)).unwrap();
    let brute = (0..=100_000)
        .map(|i| (c.point(f64::from(i) / 1e5).unwrap() - Point2::new(2.0, 3.0)).norm())
        .fold(f64::INFINITY, f64::min);
    assert!(
        (near.distance - brute).abs() < 1e-8,
        "{} vs {brute}",
        near.distance
    );
}

#[test]
fn nan_queries_are_typed_errors() {
    let c = wave(3, 8);
    assert!(matches!(
        closest_point(&c, &Point2::new(f64::NAN, 0.0)),
        Err(Error::NonFinite { index: 0, .. })
    ));
    assert!(matches!(
        closest_point(&c, &Point2::new(0.0, f64::INFINITY)),
        Err(Error::NonFinite { index: 1, .. })
    ));
    let map = arc_length_map(&c, 1e-8).unwrap();
    assert!(matches!(
        map.parameter(f64::NAN),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        map.parameter(f64::NEG_INFINITY),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        parameters_at_lengths(&c, &[0.0, f64::NAN], 1e-9, &Budget::default()),
        Err(Error::NonFinite { index: 1, .. })
    ));
}

#[test]
fn overlapping_curves_are_reported_as_intervals() {
    // A B-spline and its middle stretch, split out of it: they coincide on [0.3, 0.7].
    let c = wave(3, 16);
    let (_, right) = c.split(0.3).unwrap();
    let (middle, _) = right.split(0.7).unwrap();
    let opts = CurveCurveOptions::default();
    let found = intersect_curves_with_overlaps(&c, &middle, &opts).unwrap();
    assert_eq!(found.overlaps.len(), 1, "{found:?}");
    let o = found.overlaps[0];
    assert!(
        (o.a.0 - 0.3).abs() < 1e-7 && (o.a.1 - 0.7).abs() < 1e-7,
        "{o:?}"
    );
    assert!(
        (o.b.0 - 0.3).abs() < 1e-7 && (o.b.1 - 0.7).abs() < 1e-7,
        "{o:?}"
    );
    assert!(found.points.is_empty(), "{:?}", found.points);
    // The point search names the stretch instead of returning a thousand points along it.
    assert!(matches!(
        intersect_curves(&c, &middle, &opts),
        Err(Error::CurvesOverlap { .. })
    ));
    // Traced backwards, the interval on the second curve runs backwards.
    let back = middle.reversed();
    let o = intersect_curves_with_overlaps(&c, &back, &opts)
        .unwrap()
        .overlaps[0];
    assert!(
        (o.b.0 - 0.7).abs() < 1e-7 && (o.b.1 - 0.3).abs() < 1e-7,
        "{o:?}"
    );
}

#[test]
fn splits_next_to_a_knot_are_refused() {
    let c = wave(2, 6);
    let (a, b) = c.domain();
    for u in [5e-324, 1e-300, 1e-17, b - 1e-16] {
        assert!(
            matches!(c.split(u), Err(Error::DegenerateSpan { .. })),
            "{u}: {:?}",
            c.split(u).map(|_| ())
        );
        assert!(matches!(
            c.insert_knot(u, 1),
            Err(Error::DegenerateSpan { .. })
        ));
    }
    // Next to an interior knot too, and between two new knots.
    let knot = c.breakpoints()[1];
    assert!(matches!(
        c.insert_knot(knot + 1e-15, 1),
        Err(Error::DegenerateSpan { .. })
    ));
    assert!(matches!(
        c.refine(&[0.3, 0.3 + 1e-15]),
        Err(Error::DegenerateSpan { .. })
    ));
    // An existing knot makes no new span: raising its multiplicity is fine.
    assert!(c.insert_knot(knot, 1).is_ok());
    // What a split does accept evaluates everywhere on both pieces.
    for u in [a + 1e-12, 0.5 * (a + b), b - 1e-12] {
        let (l, r) = c.split(u).unwrap();
        for piece in [l, r] {
            let (p0, p1) = piece.domain();
            for t in [p0, 0.5 * (p0 + p1), p1] {
                let d = piece.derivatives(t, 2).unwrap();
                assert!(
                    d.iter().all(|v| v.iter().all(|x| x.is_finite())),
                    "{u}: {d:?}"
                );
            }
        }
    }
    // NURBS the same way.
    let nurbs = NurbsCurve2::try_circular_arc(Point2::origin(), 1.0, 0.0, 3.0).unwrap();
    assert!(matches!(
        nurbs.split(5e-324),
        Err(Error::DegenerateSpan { .. })
    ));
}

/// Every budgeted routine, run under `budget`; the result's error if any.
fn run_all(budget: &Budget) -> Vec<(&'static str, Option<Error>)> {
    let c = wave(3, 40);
    // The same wave 0.4 higher: it crosses `c` a few times.
    let lifted = c
        .control_points()
        .iter()
        .map(|p| Point2::new(p.x, p.y + 0.4));
    let shifted = BSplineCurve2::try_new(3, c.knots().clone(), lifted.collect()).unwrap();
    let points: Vec<Point2<f64>> = (0..400)
        .map(|i| {
            let x = f64::from(i) / 40.0;
            Point2::new(x, x.sin())
        })
        .collect();
    let opts = CurveCurveOptions::default().with_budget(budget.clone());
    let err = |r: Result<(), Error>| r.err();
    vec![
        (
            "arc length",
            err(arc_length_with(&c, 1e-12, budget).map(|_| ())),
        ),
        (
            "arc-length map",
            err(arc_length_map_with(&c, 1e-10, budget).map(|_| ())),
        ),
        (
            "parameter at length",
            err(parameters_at_lengths(&c, &[0.1, 0.2, 0.3], 1e-12, budget).map(|_| ())),
        ),
        (
            "offset",
            err(offset_with(&c, 0.1, 1e-7, budget).map(|_| ())),
        ),
        (
            "fitting",
            err(fit_to_tolerance_with(
                &points,
                1e-8,
                &FitOptions::default().with_method(ParameterMethod::ChordLength),
                budget,
            )
            .map(|_| ())),
        ),
        (
            "knot removal",
            err(c.remove_knots_with(1e-3, budget).map(|_| ())),
        ),
        (
            "curve intersection",
            err(intersect_curves(&c, &shifted, &opts).map(|_| ())),
        ),
        (
            "curve distance",
            err(curve_distance(&c, &shifted, &opts).map(|_| ())),
        ),
    ]
}

#[test]
fn every_routine_stops_on_its_flag() {
    let stop = Arc::new(AtomicBool::new(true));
    let budget = Budget::default().with_stop(stop.clone());
    for (name, e) in run_all(&budget) {
        assert!(matches!(e, Some(Error::Cancelled { .. })), "{name}: {e:?}");
    }
    stop.store(false, Ordering::Relaxed);
    for (name, e) in run_all(&budget) {
        assert!(e.is_none(), "{name}: {e:?}");
    }
}

#[test]
fn every_routine_names_itself_when_its_budget_is_spent() {
    for (name, e) in run_all(&Budget::default().with_max_work(20)) {
        match e {
            Some(Error::BudgetExhausted { operation, limit }) => {
                assert_eq!(limit, 20);
                // The quadrature under the map and the parameter search reports itself.
                assert!(
                    operation == name || operation == "arc length",
                    "{name}: {operation}"
                );
            }
            other => panic!("{name}: {other:?}"),
        }
    }
}

#[test]
fn a_flag_set_from_another_thread_stops_a_long_run() {
    // A map of a long curve to a tight tolerance runs for seconds in a debug build; a flag set
    // after 20 ms ends it with Cancelled.
    let c = wave(3, 20_000);
    let stop = Arc::new(AtomicBool::new(false));
    let budget = Budget::default().with_stop(stop.clone());
    let worker = std::thread::spawn(move || arc_length_map_with(&c, 1e-10, &budget).map(|_| ()));
    std::thread::sleep(std::time::Duration::from_millis(20));
    stop.store(true, Ordering::Relaxed);
    let outcome = worker.join().unwrap();
    assert!(
        matches!(outcome, Err(Error::Cancelled { .. })),
        "{outcome:?}"
    );
}
