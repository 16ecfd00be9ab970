//! No panic on user input: absurd degrees from a file, knot vectors built unchecked, and random
//! (mostly invalid) curve data and parameters all come back as typed errors. A panic anywhere in
//! these tests fails them (proptest reports a panicking case as a failure).

use camber_geom::{
    BSplineCurve2, BSplineCurve3, BezierCurve2, Error, HermiteCurve2, KnotVector, NurbsCurve2,
    NurbsCurve3, ParametricCurve,
};
use nalgebra::{Point2, Vector2};
use proptest::prelude::*;

const HUGE: usize = usize::MAX;

/// Issue 11 finding 7: a Bézier curve is capped at the B-splines' degree (256), through the
/// constructor and its file form.
#[test]
fn bezier_degree_is_capped_like_bsplines() {
    let points = |n: usize| {
        (0..n)
            .map(|i| Point2::new(i as f64, 0.0))
            .collect::<Vec<_>>()
    };
    assert_eq!(BezierCurve2::try_new(points(257)).unwrap().degree(), 256);
    assert_eq!(
        BezierCurve2::try_new(points(258)).unwrap_err(),
        Error::DegreeTooHigh {
            degree: 257,
            max: 256
        }
    );
    let many: Vec<[f64; 2]> = (0..5001).map(|i| [f64::from(i), 0.0]).collect();
    let text = serde_json::json!({ "control_points": many }).to_string();
    let err = serde_json::from_str::<BezierCurve2<f64>>(&text).unwrap_err();
    assert!(
        err.to_string().contains("largest supported degree"),
        "{err}"
    );
}

/// Issue 11 finding 7: a knot repeated more than degree + 1 times is refused (the basis around
/// it vanishes), and files with degree 0 or unknown fields are refused.
#[test]
fn knot_multiplicity_degree_zero_and_unknown_fields() {
    let k = KnotVector::try_new(vec![0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0]).unwrap();
    let points: Vec<Point2<f64>> = (0..5).map(|i| Point2::new(f64::from(i), 0.0)).collect();
    assert_eq!(
        BSplineCurve2::try_new(1, k.clone(), points.clone()).unwrap_err(),
        Error::KnotMultiplicityTooHigh {
            value: 0.5,
            multiplicity: 3,
            max: 2
        }
    );
    // Multiplicity p + 1 inside is allowed (a break in the curve).
    let k = KnotVector::try_new(vec![0.0, 0.0, 0.5, 0.5, 1.0, 1.0]).unwrap();
    assert!(BSplineCurve2::try_new(1, k, points[..4].to_vec()).is_ok());
    let ends = KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]).unwrap();
    assert_eq!(
        BSplineCurve2::try_new(1, ends, points[..4].to_vec()).unwrap_err(),
        Error::KnotMultiplicityTooHigh {
            value: 0.0,
            multiplicity: 3,
            max: 2
        }
    );
    let zero = r#"{"degree":0,"knots":[0,1,2],"control_points":[[0,0],[1,2]]}"#;
    let err = serde_json::from_str::<BSplineCurve2<f64>>(zero).unwrap_err();
    assert!(err.to_string().contains("degree 0"), "{err}");
    let zero = r#"{"degree":0,"knots":[0,1,2],"control_points":[[0,0],[1,2]],"weights":[1,1]}"#;
    assert!(serde_json::from_str::<NurbsCurve2<f64>>(zero).is_err());
    let extra = r#"{"control_points":[[0,0],[1,2]],"colour":"red"}"#;
    let err = serde_json::from_str::<BezierCurve2<f64>>(extra).unwrap_err();
    assert!(err.to_string().contains("unknown field `colour`"), "{err}");
    let extra = r#"{"p0":[0,0],"p1":[1,0],"t0":[1,0],"t1":[1,0],"tension":2}"#;
    assert!(serde_json::from_str::<HermiteCurve2<f64>>(extra).is_err());
}

/// Issue 11 finding 4: knots whose span overflows f64 are refused (a B-spline on
/// [−1e308, 1e308] evaluated to (0, 0)), and a reparameterization that cannot be carried
/// faithfully is refused instead of changing the shape.
#[test]
fn unrepresentable_knots_are_refused() {
    assert_eq!(
        KnotVector::try_new(vec![-1e308, -1e308, 1e308, 1e308]).unwrap_err(),
        Error::KnotRangeTooWide {
            first: -1e308,
            last: 1e308
        }
    );
    assert!(KnotVector::try_new(vec![-1e307, -1e307, 1e307, 1e307]).is_ok());
    let points = vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 1.0),
        Point2::new(3.0, 0.0),
        Point2::new(4.0, 2.0),
    ];
    let k = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]).unwrap();
    let c = BSplineCurve2::try_new(2, k, points).unwrap();
    // The interior knot 0.5 would land on 1e17 + 8, between two f64 neighbours 16 apart.
    for (a, b) in [(-1e308, 1e308), (0.0, 1e-320), (1e17, 1e17 + 16.0)] {
        assert_eq!(
            c.reparameterized(a, b).unwrap_err(),
            Error::ReparamNotRepresentable { start: a, end: b },
            "[{a}, {b}]"
        );
    }
    // A wide but representable interval keeps the shape.
    let r = c.reparameterized(-1e300, 1e300).unwrap();
    let (p, q) = (c.point(0.25).unwrap(), r.point(-5e299).unwrap());
    assert!((p - q).norm() < 1e-12, "{p} vs {q}");
}

#[test]
fn an_absurd_degree_in_a_file_is_an_error_not_an_overflow() {
    // 2⁶⁴ − 1 fits a usize: before the fix `degree + 1` overflowed (a panic in debug builds).
    let spline = format!(r#"{{"degree":{HUGE},"knots":[0,0,1,1],"control_points":[[0,0],[1,0]]}}"#);
    let err = serde_json::from_str::<BSplineCurve2<f64>>(&spline).unwrap_err();
    assert!(
        err.to_string().contains("largest supported degree"),
        "{err}"
    );
    let spline3 =
        format!(r#"{{"degree":{HUGE},"knots":[0,0,1,1],"control_points":[[0,0,0],[1,0,0]]}}"#);
    assert!(serde_json::from_str::<BSplineCurve3<f64>>(&spline3).is_err());
    let nurbs = format!(
        r#"{{"degree":{HUGE},"knots":[0,0,1,1],"control_points":[[0,0],[1,0]],"weights":[1,1]}}"#
    );
    assert!(serde_json::from_str::<NurbsCurve2<f64>>(&nurbs).is_err());
    let half = usize::MAX / 2 + 1;
    let nurbs3 = format!(
        r#"{{"degree":{half},"knots":[0,0,1,1],"control_points":[[0,0,0],[1,0,0]],"weights":[1,1]}}"#
    );
    assert!(serde_json::from_str::<NurbsCurve3<f64>>(&nurbs3).is_err());
}

#[test]
fn knot_vector_helpers_take_any_degree() {
    assert!(matches!(
        KnotVector::<f64>::clamped_uniform(HUGE, 3),
        Err(Error::DegreeTooHigh { degree: HUGE, .. })
    ));
    assert!(matches!(
        KnotVector::from_parameters(HUGE, &[0.0_f64, 1.0]),
        Err(Error::DegreeTooHigh { degree: HUGE, .. })
    ));
    let k = KnotVector::try_new(vec![0.0_f64, 0.0, 1.0, 1.0]).unwrap();
    assert!(k.check_for(HUGE, 2).is_err());
    assert!(k.check_for(HUGE / 2 + 1, usize::MAX / 2).is_err());
    assert_eq!(k.find_span(HUGE, 0.5), HUGE);
    assert_eq!(k.domain(HUGE / 2 + 1), (0.0, 1.0));
    // The unchecked constructor says it skips checks; the empty vector still must not panic.
    let empty = KnotVector::<f64>::new_unchecked(Vec::new());
    assert!(empty.reversed().is_empty());
}

#[test]
fn curves_recheck_knots_built_unchecked() {
    // Non-decreasing except at index 3, with a non-empty domain [0, 1] for degree 1.
    let bad = KnotVector::new_unchecked(vec![0.0, 0.0, 1.0, 0.5, 1.0, 1.0]);
    let points = vec![Point2::new(0.0, 0.0); 4];
    let expected = Error::DecreasingKnots {
        index: 3,
        value: 0.5,
        previous: 1.0,
    };
    assert_eq!(
        BSplineCurve2::try_new(1, bad.clone(), points.clone()),
        Err(expected.clone())
    );
    assert_eq!(
        NurbsCurve2::try_new(1, bad, points, vec![1.0; 4]),
        Err(expected)
    );
}

#[test]
fn insertion_counts_do_not_overflow() {
    let k = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]).unwrap();
    let c = BSplineCurve2::try_new(2, k, vec![Point2::new(0.0, 0.0); 4]).unwrap();
    assert!(matches!(
        c.insert_knot(0.5, HUGE),
        Err(Error::KnotMultiplicity {
            multiplicity: 1,
            times: HUGE,
            ..
        })
    ));
}

#[test]
fn degrees_above_the_cap_are_refused_before_any_allocation() {
    use camber_geom::knots::MAX_DEGREE;
    use camber_geom::BezierCurve2;
    let too_high = |degree| Error::DegreeTooHigh {
        degree,
        max: MAX_DEGREE,
    };
    // A file asking for degree 10⁶ on 10⁶ + 1 points would need ~10¹² scratch values per
    // evaluation; it is refused by the knot-count check's degree test first.
    let k = KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0]).unwrap();
    assert_eq!(k.check_for(1_000_000, 1_000_001), Err(too_high(1_000_000)));
    let spline = format!(
        r#"{{"degree":{},"knots":[0,0,1,1],"control_points":[[0,0],[1,0]]}}"#,
        MAX_DEGREE + 1
    );
    let err = serde_json::from_str::<BSplineCurve2<f64>>(&spline).unwrap_err();
    assert!(
        err.to_string().contains("largest supported degree"),
        "{err}"
    );
    // Elevation by an untrusted count: an error, not an overflow or an endless loop.
    let c = BSplineCurve2::try_new(1, k.clone(), vec![Point2::new(0.0, 0.0); 2]).unwrap();
    assert_eq!(c.elevate_degree(HUGE), Err(too_high(HUGE)));
    assert_eq!(c.elevate_degree(MAX_DEGREE), Err(too_high(MAX_DEGREE + 1)));
    assert_eq!(
        c.elevate_degree(MAX_DEGREE - 1).unwrap().degree(),
        MAX_DEGREE
    );
    let n = NurbsCurve2::try_new(1, k, vec![Point2::new(0.0, 0.0); 2], vec![1.0, 2.0]).unwrap();
    assert_eq!(n.elevate_degree(HUGE), Err(too_high(HUGE)));
    let b = BezierCurve2::try_new(vec![Point2::new(0.0, 0.0); 3]).unwrap();
    assert_eq!(b.try_elevate_degree(HUGE), Err(too_high(HUGE)));
    assert_eq!(b.try_elevate_degree(0).unwrap(), b);
}

/// Any f64, with the awkward ones (NaN, ±∞, huge, tiny) drawn often.
fn any_number() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -3.0f64..3.0,
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(f64::NEG_INFINITY),
        1 => Just(1e300),
        1 => Just(0.0),
        1 => any::<f64>(),
    ]
}

fn any_degree() -> impl Strategy<Value = usize> {
    prop_oneof![8 => 0usize..6, 1 => Just(HUGE), 1 => Just(HUGE / 2 + 1)]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    /// Random degree, knots, points, weights and parameters: construction either fails with an
    /// error or gives a curve on which every operation returns a result; a parameter outside
    /// the domain (or not finite) is always an error.
    #[test]
    fn random_curve_data_never_panics(
        degree in any_degree(),
        knots in prop::collection::vec(any_number(), 0..12),
        coords in prop::collection::vec(any_number(), 0..16),
        weights in prop::collection::vec(any_number(), 0..8),
        u in any_number(),
        v in any_number(),
        times in prop_oneof![0usize..4, Just(HUGE)],
    ) {
        let points: Vec<Point2<f64>> = coords.chunks_exact(2).map(|c| Point2::new(c[0], c[1])).collect();
        let checked = KnotVector::try_new(knots.clone());
        let unchecked = KnotVector::new_unchecked(knots);
        let _ = unchecked.check_for(degree, points.len());
        let _ = unchecked.find_span(degree, u);
        let _ = unchecked.domain(degree);
        let _ = unchecked.multiplicity(u);
        let _ = unchecked.reversed();
        for kv in [checked.ok(), Some(unchecked)].into_iter().flatten() {
            if let Ok(c) = BSplineCurve2::try_new(degree, kv.clone(), points.clone()) {
                let (a, b) = c.domain();
                let inside = u.is_finite() && u >= a && u <= b;
                prop_assert_eq!(c.derivatives(u, 3).is_ok(), inside);
                let _ = c.insert_knot(u, times);
                let _ = c.split(u);
                let _ = c.refine(&[u, v]);
                let _ = c.reparameterized(u, v);
                let _ = c.elevate_degree(times.min(2));
                let _ = c.reversed().point(u);
                let _ = c.to_bezier_segments();
            }
            if let Ok(c) = NurbsCurve2::try_new(degree, kv, points.clone(), weights.clone()) {
                let (a, b) = c.domain();
                let inside = u.is_finite() && u >= a && u <= b;
                prop_assert_eq!(c.derivatives(u, 3).is_ok(), inside);
                let _ = c.insert_knot(u, times);
                let _ = c.split(u);
                let _ = c.refine(&[v]);
                let _ = c.reparameterized(u, v);
                let _ = c.elevate_degree(times.min(2));
                let _ = c.to_bezier_segments();
            }
        }
    }

    /// Hermite curves from random data: construction, evaluation, truncation and subdivision
    /// at random (often invalid) parameters return results.
    #[test]
    fn random_hermite_data_never_panics(
        c in prop::collection::vec(any_number(), 8),
        u in any_number(),
        v in any_number(),
        n in 0usize..6,
    ) {
        let made = HermiteCurve2::try_new(
            Point2::new(c[0], c[1]),
            Point2::new(c[2], c[3]),
            Vector2::new(c[4], c[5]),
            Vector2::new(c[6], c[7]),
        );
        prop_assert_eq!(made.is_ok(), c.iter().all(|x| x.is_finite()));
        if let Ok(h) = made {
            prop_assert_eq!(h.point(u).is_ok(), (0.0..=1.0).contains(&u));
            let _ = h.truncated(u, v);
            let _ = h.subdivided(n);
            let _ = h.subdivided_at(&[u, v]);
            let _ = h.to_bezier();
        }
    }
}

/// Issue 11 finding 4: NURBS weights all scaled to 1e308 describe the same curve as unit
/// weights and evaluate like them; weights 1e600 apart are refused.
#[test]
fn nurbs_weights_at_the_edge_of_f64() {
    let knots = KnotVector::clamped_uniform(2, 3).unwrap();
    let points = vec![
        Point2::new(1.0, 0.0),
        Point2::new(1.0, 1.0),
        Point2::new(0.0, 1.0),
    ];
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let unit = NurbsCurve2::try_new(2, knots.clone(), points.clone(), vec![1.0, w, 1.0]).unwrap();
    let huge = NurbsCurve2::try_new(
        2,
        knots.clone(),
        points.clone(),
        vec![1e308, w * 1e308, 1e308],
    )
    .unwrap();
    for u in [0.0, 0.3, 0.5, 1.0] {
        let (a, b) = (
            unit.derivatives(u, 3).unwrap(),
            huge.derivatives(u, 3).unwrap(),
        );
        for k in 0..=3 {
            assert!(
                (a[k] - b[k]).norm() < 1e-12 * (1.0 + a[k].norm()),
                "u = {u}, k = {k}"
            );
        }
    }
    assert!(matches!(
        NurbsCurve2::try_new(2, knots, points, vec![1e-300, 1e300, 1e-300]),
        Err(Error::WeightRatio { .. })
    ));
}
