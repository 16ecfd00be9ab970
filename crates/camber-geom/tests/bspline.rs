//! B-spline curves through the public API: hand-derived values, agreement with Bernstein
//! polynomials written here, derivatives against central differences and dual numbers, the
//! representation-changing operations (proptest: the curve never moves), serde.

// Test helpers outside #[test] functions unwrap too; a failed unwrap is a failed test.
#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use camber_geom::{
    BSplineCurve, BSplineCurve2, BSplineCurve3, BezierCurve2, Error, KnotVector, ParametricCurve,
};
use nalgebra::{Point2, Point3, Vector2};
use num_dual::Dual64;
use proptest::prelude::*;

fn curve2(degree: usize, knots: &[f64], points: &[[f64; 2]]) -> BSplineCurve2<f64> {
    let points = points.iter().map(|p| Point2::new(p[0], p[1])).collect();
    BSplineCurve2::try_new(degree, KnotVector::try_new(knots.to_vec()).unwrap(), points).unwrap()
}

fn assert_vec_close(a: &Vector2<f64>, b: &Vector2<f64>, tol: f64) {
    assert!((a - b).norm() < tol, "{a:?} vs {b:?}");
}

#[test]
fn clamped_cubic_with_one_interior_knot_by_hand() {
    // U = {0,0,0,0,1/2,1,1,1,1}. By Cox–de Boor at u = 1/2 (span 4):
    // N_{1,3} = 1/4, N_{2,3} = 1/2, N_{3,3} = 1/4, N_{4,3} = 0, so C = (P1 + 2 P2 + P3) / 4;
    // C′ = Σ 3 (P_{i+1} − P_i) / (u_{i+4} − u_{i+1}) N_{i+1,2} with N_{2,2} = N_{3,2} = 1/2,
    // so C′(1/2) = 3/2 (P3 − P1).
    let p = [[0.0, 0.0], [1.0, 3.0], [2.0, -1.0], [4.0, 2.0], [5.0, 0.0]];
    let c = curve2(3, &[0., 0., 0., 0., 0.5, 1., 1., 1., 1.], &p);
    let (pt, d) = c.point_and_derivative(0.5).unwrap();
    assert_relative_eq!(pt.x, (1.0 + 4.0 + 4.0) / 4.0, epsilon = 1e-15);
    assert_relative_eq!(pt.y, (3.0 - 2.0 + 2.0) / 4.0, epsilon = 1e-15);
    // P3 − P1 = (3, −1).
    assert_vec_close(&d, &Vector2::new(4.5, -1.5), 1e-14);
    // The clamped ends interpolate the end points, with end tangents 3 (P1 − P0) / (1/2).
    assert_relative_eq!(
        c.point(1.0).unwrap(),
        Point2::new(5.0, 0.0),
        epsilon = 1e-15
    );
    let d0 = c.derivative(0.0).unwrap();
    assert_vec_close(&d0, &Vector2::new(6.0, 18.0), 1e-13);
}

#[test]
fn book_example_2_3_quadratic() {
    // U = {0,0,0,1,2,3,4,4,5,5,5}: at u = 5/2, N = (1/8, 6/8, 1/8) on P2, P3, P4, the first
    // derivatives (−1/2, 0, 1/2) and the second (1, −2, 1).
    let p: Vec<[f64; 2]> = (0..8)
        .map(|i| [f64::from(i), f64::from(i * i % 5)])
        .collect();
    let c = curve2(2, &[0., 0., 0., 1., 2., 3., 4., 4., 5., 5., 5.], &p);
    let [pt, d1, d2] = c.second_order(2.5).unwrap();
    let v = |i: usize| Vector2::new(p[i][0], p[i][1]);
    assert_vec_close(&pt, &((v(2) + v(3) * 6.0 + v(4)) / 8.0), 1e-14);
    assert_vec_close(&d1, &((v(4) - v(2)) * 0.5), 1e-14);
    assert_vec_close(&d2, &(v(2) - v(3) * 2.0 + v(4)), 1e-13);
    assert_eq!(c.breakpoints(), vec![0., 1., 2., 3., 4., 5.]);
    // Derivatives above the degree vanish.
    assert_vec_close(
        &c.derivatives(2.5, 3).unwrap()[3],
        &Vector2::zeros(),
        1e-300,
    );
}

#[test]
fn unclamped_uniform_cubic_off_the_unit_interval() {
    // Knots 0..7, domain [3, 4]. At u = 3 the uniform cubic B-spline gives
    // C = (P0 + 4 P1 + P2) / 6, C′ = (P2 − P0) / 2, C″ = P0 − 2 P1 + P2.
    let p = [[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 0.0]];
    let c = curve2(3, &[0., 1., 2., 3., 4., 5., 6., 7.], &p);
    assert_eq!(c.domain(), (3.0, 4.0));
    let [pt, d1, d2] = c.second_order(3.0).unwrap();
    assert_vec_close(&pt, &Vector2::new(7.0 / 6.0, 11.0 / 6.0), 1e-14);
    assert_vec_close(&d1, &Vector2::new(1.5, 1.5), 1e-14);
    assert_vec_close(&d2, &Vector2::new(1.0, -1.0), 1e-14);
    // Clamping keeps the curve and makes the end points control points.
    let cl = c.clamped();
    assert_relative_eq!(
        cl.control_points()[0],
        Point2::new(7.0 / 6.0, 11.0 / 6.0),
        epsilon = 1e-14
    );
    for i in 0..=10 {
        let u = 3.0 + f64::from(i) / 10.0;
        assert_relative_eq!(cl.point(u).unwrap(), c.point(u).unwrap(), epsilon = 1e-14);
    }
}

#[test]
fn evaluation_outside_the_domain_is_an_error() {
    let c = curve2(1, &[0., 1., 2., 3.], &[[0.0, 0.0], [1.0, 1.0]]);
    assert_eq!(
        c.point(0.5),
        Err(Error::ParameterOutsideDomain {
            value: 0.5,
            min: 1.0,
            max: 2.0
        })
    );
    assert!(c.point(2.000_001).is_err());
    assert!(matches!(
        c.derivatives(f64::NAN, 2),
        Err(Error::NonFinite { .. })
    ));
    assert!(c.point(2.0).is_ok());
}

#[test]
fn construction_errors() {
    let k = || KnotVector::try_new(vec![0., 0., 1., 1.]).unwrap();
    let pts = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 0.0)];
    assert!(BSplineCurve2::try_new(1, k(), pts.clone()).is_ok());
    assert!(matches!(
        BSplineCurve2::try_new(2, k(), pts.clone()),
        Err(Error::TooFewControlPoints { .. })
    ));
    assert!(matches!(
        BSplineCurve2::try_new(1, k(), vec![Point2::new(0.0, f64::INFINITY), pts[1]]),
        Err(Error::NonFinite { index: 0, .. })
    ));
    let nan = KnotVector::new_unchecked(vec![0., 0., f64::NAN, 1.]);
    assert!(matches!(
        BSplineCurve2::try_new(1, nan, pts.clone()),
        Err(Error::NonFinite { index: 2, .. })
    ));
    let unchecked = KnotVector::new_unchecked(vec![0., 1., 0.5, 1.]);
    assert!(matches!(
        BSplineCurve2::try_new(1, unchecked, pts),
        Err(Error::DecreasingKnots { index: 2, .. })
    ));
}

#[test]
fn degree_zero_and_high_degree() {
    // Degree 0: piecewise constant, right-continuous at the knot, zero derivative.
    let c = curve2(0, &[0., 1., 2.], &[[1.0, 1.0], [2.0, 2.0]]);
    assert_relative_eq!(c.point(0.5).unwrap(), Point2::new(1.0, 1.0));
    assert_relative_eq!(c.point(1.0).unwrap(), Point2::new(2.0, 2.0));
    assert_relative_eq!(c.point(2.0).unwrap(), Point2::new(2.0, 2.0));
    let d = c.derivatives(0.5, 3).unwrap();
    assert!(d[1..].iter().all(|v| v.norm() < 1e-300));
    // Degree 9 (above the inline scratch): a degree-7 curve elevated twice must give the same
    // derivatives through the heap-scratch path, and agree with central differences.
    let pts: Vec<[f64; 2]> = (0..10)
        .map(|i| [f64::from(i), f64::from((i * 3) % 7)])
        .collect();
    let low = curve2(
        7,
        &[
            0., 0., 0., 0., 0., 0., 0., 0., 0.4, 0.7, 1., 1., 1., 1., 1., 1., 1., 1.,
        ],
        &pts,
    );
    let high = low.elevate_degree(2).unwrap();
    assert_eq!(high.degree(), 9);
    for u in [0.1, 0.5, 0.55, 0.9] {
        let a = low.derivatives(u, 3).unwrap();
        let b = high.derivatives(u, 3).unwrap();
        for k in 0..=3 {
            assert!(
                (a[k] - b[k]).norm() < 1e-8 * (1.0 + a[k].norm()),
                "u = {u}, order {k}"
            );
        }
        let h = 1e-6;
        let fd = (high.point(u + h).unwrap() - high.point(u - h).unwrap()) / (2.0 * h);
        assert!((fd - b[1]).norm() < 1e-5 * (1.0 + b[1].norm()));
    }
}

fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}

proptest! {
    #[test]
    fn single_span_equals_bernstein_form(
        pts in prop::collection::vec((-5.0f64..5.0, -5.0f64..5.0), 1..12),
        a in -3.0f64..3.0, len in 0.2f64..3.0, s in 0.0f64..=1.0,
    ) {
        // One span on [a, b]: C(u) = Σ C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ P_i, t = (u − a) / (b − a).
        let n = pts.len() - 1;
        let b = a + len;
        let mut knots = vec![a; n + 1];
        knots.extend(std::iter::repeat_n(b, n + 1));
        let points: Vec<Point2<f64>> = pts.iter().map(|&(x, y)| Point2::new(x, y)).collect();
        let c = BSplineCurve2::try_new(n, KnotVector::try_new(knots).unwrap(), points.clone()).unwrap();
        let u = (a + len * s).min(b);
        let t = (u - a) / len;
        let mut expected = Vector2::zeros();
        for (i, p) in points.iter().enumerate() {
            expected += p.coords * (binomial(n, i) * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32));
        }
        prop_assert!((c.point(u).unwrap().coords - expected).norm() < 1e-12);
        // And from_bezier agrees on [0, 1].
        let bez = BSplineCurve2::from_bezier(&BezierCurve2::try_new(points).unwrap());
        prop_assert!((bez.point(t).unwrap().coords - expected).norm() < 1e-12);
    }
}

/// Random 2D curves of degree 1 to 5 on unclamped (or partly clamped) knot vectors off [0, 1],
/// interior multiplicities ≤ p.
fn random_curve() -> impl Strategy<Value = BSplineCurve2<f64>> {
    random_curve_of(1..=5)
}

/// As [`random_curve`] with the degree drawn from `degrees`.
fn random_curve_of(
    degrees: std::ops::RangeInclusive<usize>,
) -> impl Strategy<Value = BSplineCurve2<f64>> {
    (degrees, 0usize..=6, -2.0f64..2.0).prop_flat_map(|(p, extra, start)| {
        let count = p + 1 + extra;
        (
            prop::collection::vec(prop_oneof![4 => 0.1f64..1.0, 1 => Just(0.0)], count + p),
            prop::collection::vec((-5.0f64..5.0, -5.0f64..5.0), count),
        )
            .prop_filter_map("degenerate knots", move |(gaps, pts)| {
                let mut knots = vec![start];
                for g in gaps {
                    knots.push(knots[knots.len() - 1] + g);
                }
                let kv = KnotVector::try_new(knots).ok()?;
                let (a, b) = kv.domain(p);
                let ok = kv
                    .as_slice()
                    .iter()
                    .all(|&k| k <= a || k >= b || kv.multiplicity(k) <= p);
                ok.then_some(())?;
                let points = pts.iter().map(|&(x, y)| Point2::new(x, y)).collect();
                BSplineCurve2::try_new(p, kv, points).ok()
            })
    })
}

fn at<C: ParametricCurve<f64, 2>>(c: &C, s: f64) -> f64 {
    let (a, b) = c.domain();
    (a + (b - a) * s).clamp(a, b)
}

/// Both curves have (about) the same domain and agree at 41 parameters.
fn same_curve(a: &BSplineCurve2<f64>, b: &BSplineCurve2<f64>) -> Result<(), TestCaseError> {
    prop_assert!((a.domain().0 - b.domain().0).abs() < 1e-12);
    prop_assert!((a.domain().1 - b.domain().1).abs() < 1e-12);
    for i in 0..=40 {
        let u = at(a, f64::from(i) / 40.0);
        let d = (a.point(u).unwrap() - b.point(u).unwrap()).norm();
        prop_assert!(d < 1e-12, "u = {u}: distance {d}");
    }
    Ok(())
}

proptest! {
    #[test]
    fn derivatives_match_central_differences(c in random_curve(), s in 0.02f64..0.98) {
        let u = at(&c, s);
        let h = 1e-5;
        let knots = c.knots().as_slice();
        // Stay inside one polynomial piece.
        prop_assume!(knots.iter().all(|&k| (k - u).abs() > 2.0 * h));
        let (a, b) = c.domain();
        prop_assume!(u - h > a && u + h < b);
        let d = c.derivatives(u, 4).unwrap();
        let dp = c.derivatives(u + h, 3).unwrap();
        let dm = c.derivatives(u - h, 3).unwrap();
        for k in 1..=3 {
            let fd = (dp[k - 1] - dm[k - 1]) / (2.0 * h);
            let scale = 1.0 + d[k].norm();
            prop_assert!((fd - d[k]).norm() < 1e-5 * scale * 1e2_f64.powi(k as i32 - 1), "k = {k}: {fd:?} vs {:?}", d[k]);
        }
        // The fast order-1 path agrees with the general one.
        let (pt, t) = c.point_and_derivative(u).unwrap();
        prop_assert!((pt.coords - d[0]).norm() < 1e-12 && (t - d[1]).norm() < 1e-10);
        // Derivatives above the degree vanish.
        if c.degree() < 4 {
            prop_assert!(d[4].norm() < 1e-300);
        }
    }

    #[test]
    fn dual_numbers_give_the_tangent(c in random_curve(), s in 0.0f64..=1.0) {
        let u = at(&c, s);
        let points = c.control_points().iter().map(|p| p.map(Dual64::from)).collect();
        let knots = KnotVector::try_new(c.knots().as_slice().iter().map(|&k| Dual64::from(k)).collect()).unwrap();
        let dual = BSplineCurve2::try_new(c.degree(), knots, points).unwrap();
        let p = dual.point(Dual64::new(u, 1.0)).unwrap();
        let t = c.derivative(u).unwrap();
        prop_assert!((p.x.eps - t.x).abs() < 1e-10 * (1.0 + t.norm()));
        prop_assert!((p.y.eps - t.y).abs() < 1e-10 * (1.0 + t.norm()));
    }

    #[test]
    fn knot_insertion_and_refinement_keep_the_curve(c in random_curve(), s in 0.0f64..=1.0, r in 1usize..=5, xs in prop::collection::vec(0.0f64..=1.0, 1..8)) {
        let u = at(&c, s);
        let room = c.degree().saturating_sub(c.knots().multiplicity(u));
        prop_assume!(room > 0);
        same_curve(&c, &c.insert_knot(u, 1).unwrap())?;
        let times = r.min(room);
        let inserted = c.insert_knot(u, times).unwrap();
        prop_assert_eq!(inserted.knots().multiplicity(u), c.knots().multiplicity(u) + times);
        same_curve(&c, &inserted)?;
        let too_many = matches!(c.insert_knot(u, room + 1), Err(Error::KnotMultiplicity { .. }));
        prop_assert!(too_many);
        let mut x: Vec<f64> = xs.iter().map(|&s| at(&c, s)).collect();
        x.sort_by(f64::total_cmp);
        x.retain(|&v| c.knots().multiplicity(v) == 0);
        x.dedup_by(|a, b| (*a - *b).abs() < 1e-300);
        prop_assume!(!x.is_empty());
        let refined = c.refine(&x).unwrap();
        prop_assert_eq!(refined.control_points().len(), c.control_points().len() + x.len());
        same_curve(&c, &refined)?;
    }

    #[test]
    fn splitting_keeps_the_curve(c in random_curve(), s in 0.01f64..0.99) {
        let u = at(&c, s);
        let (a, b) = c.domain();
        prop_assume!(u > a && u < b);
        let (left, right) = c.split(u).unwrap();
        prop_assert!((left.domain().0 - a).abs() < 1e-300 && (left.domain().1 - u).abs() < 1e-300);
        prop_assert!((right.domain().0 - u).abs() < 1e-300 && (right.domain().1 - b).abs() < 1e-300);
        for i in 0..=20 {
            let f = f64::from(i) / 20.0;
            let (ul, ur) = (at(&left, f), at(&right, f));
            prop_assert!((left.point(ul).unwrap() - c.point(ul).unwrap()).norm() < 1e-12);
            prop_assert!((right.point(ur).unwrap() - c.point(ur).unwrap()).norm() < 1e-12);
        }
        // Clamped at u: the joint is shared control point.
        let last = left.control_points()[left.control_points().len() - 1];
        prop_assert!((last - right.control_points()[0]).norm() < 1e-300 + 1e-12);
    }

    #[test]
    fn split_joint_of_a_cubic_is_c2(c in random_curve_of(3..=3), s in 0.05f64..0.95) {
        let u = at(&c, s);
        // Away from knots: a tiny last span makes second derivatives ill-conditioned
        // (round-off grows like 1/h²), which is not what this test is about.
        prop_assume!(c.knots().as_slice().iter().all(|&k| (k - u).abs() > 0.02));
        let (left, right) = c.split(u).unwrap();
        let l = left.derivatives(u, 2).unwrap();
        let r = right.derivatives(u, 2).unwrap();
        let o = c.derivatives(u, 2).unwrap();
        for k in 0..=2 {
            let tol = 1e-10 * (1.0 + o[k].norm());
            prop_assert!((l[k] - r[k]).norm() < tol && (l[k] - o[k]).norm() < tol, "order {k}");
        }
    }

    #[test]
    fn degree_elevation_keeps_the_curve(c in random_curve(), t in 1usize..=3) {
        let e = c.elevate_degree(t).unwrap();
        prop_assert_eq!(e.degree(), c.degree() + t);
        same_curve(&c, &e)?;
        let clamped = c.clamped();
        for v in clamped.breakpoints() {
            prop_assert_eq!(e.knots().multiplicity(v), clamped.knots().multiplicity(v) + t);
        }
    }

    #[test]
    fn reversal(c in random_curve()) {
        let r = c.reversed();
        let (a, b) = c.domain();
        prop_assert!((r.domain().0 - a).abs() < 1e-300 && (r.domain().1 - b).abs() < 1e-300);
        for i in 0..=20 {
            let u = at(&c, f64::from(i) / 20.0);
            let mirrored = (a + b - u).clamp(a, b);
            prop_assert!((r.point(mirrored).unwrap() - c.point(u).unwrap()).norm() < 1e-12);
        }
        let rr = r.reversed();
        prop_assert_eq!(rr.control_points(), c.control_points());
        for (x, y) in rr.knots().as_slice().iter().zip(c.knots().as_slice()) {
            prop_assert!((x - y).abs() < 1e-12);
        }
        same_curve(&c, &rr)?;
    }

    #[test]
    fn bezier_pieces_reproduce_the_curve(c in random_curve()) {
        let segments = c.to_bezier_segments();
        prop_assert_eq!(segments.len(), c.breakpoints().len() - 1);
        for (start, end, piece) in &segments {
            prop_assert_eq!(piece.degree(), c.degree());
            for i in 0..=10 {
                let t = f64::from(i) / 10.0;
                let u = (start + (end - start) * t).min(*end);
                // de Casteljau on the piece's control points, written here.
                let mut pts: Vec<Vector2<f64>> = piece.control_points().iter().map(|p| p.coords).collect();
                for level in 1..pts.len() {
                    for j in 0..pts.len() - level {
                        pts[j] = pts[j] * (1.0 - t) + pts[j + 1] * t;
                    }
                }
                prop_assert!((pts[0] - c.point(u).unwrap().coords).norm() < 1e-12);
            }
        }
    }

    #[test]
    fn reparameterization(c in random_curve(), a in -4.0f64..4.0, len in 0.1f64..5.0, s in 0.0f64..=1.0) {
        let m = c.reparameterized(a, a + len).unwrap();
        prop_assert!((m.domain().0 - a).abs() < 1e-300 && (m.domain().1 - (a + len)).abs() < 1e-300);
        let (u0, u1) = c.domain();
        let ratio = (u1 - u0) / len;
        let original = c.derivatives(at(&c, s), 2).unwrap();
        let mapped = m.derivatives(at(&m, s), 2).unwrap();
        for k in 0..=2 {
            let expected = original[k] * ratio.powi(k as i32);
            prop_assert!((mapped[k] - expected).norm() < 1e-9 * (1.0 + expected.norm()), "order {k}");
        }
    }
}

#[test]
fn serde_round_trip_and_rejections() {
    let c = curve2(
        2,
        &[0., 0., 0., 0.5, 1., 1., 1.],
        &[[0., 0.], [1., 2.], [2., 2.], [3., 0.]],
    );
    let json = serde_json::to_string(&c).unwrap();
    assert_eq!(
        json,
        r#"{"degree":2,"knots":[0.0,0.0,0.0,0.5,1.0,1.0,1.0],"control_points":[[0.0,0.0],[1.0,2.0],[2.0,2.0],[3.0,0.0]]}"#
    );
    let back: BSplineCurve2<f64> = serde_json::from_str(&json).unwrap();
    assert_eq!(back, c);
    let three = BSplineCurve3::try_new(
        1,
        KnotVector::try_new(vec![0., 0., 1., 1.]).unwrap(),
        vec![Point3::new(0., 0., 0.), Point3::new(1., 2., 3.)],
    )
    .unwrap();
    let back3: BSplineCurve3<f64> =
        serde_json::from_str(&serde_json::to_string(&three).unwrap()).unwrap();
    assert_eq!(back3, three);

    let reject = |text: &str, expected: Error| {
        let err = serde_json::from_str::<BSplineCurve<f64, 2>>(text).unwrap_err();
        assert!(
            err.to_string().contains(&expected.to_string()),
            "{err} should mention {expected}"
        );
    };
    reject(
        r#"{"degree":2,"knots":[0,0,0,1,1,1],"control_points":[[0,0],[1,2],[2,2],[3,0]]}"#,
        Error::KnotCount {
            expected: 7,
            found: 6,
            degree: 2,
            control_points: 4,
        },
    );
    reject(
        r#"{"degree":1,"knots":[0,0,1,0.5,1],"control_points":[[0,0],[1,2],[2,2]]}"#,
        Error::DecreasingKnots {
            index: 3,
            value: 0.5,
            previous: 1.0,
        },
    );
    reject(
        r#"{"degree":1,"knots":[0,0,1,1],"control_points":[[0,0],[1,2,3]]}"#,
        Error::Dimension {
            index: 1,
            expected: 2,
            found: 3,
        },
    );
    // JSON has no NaN; a huge literal parses as infinity and must be rejected.
    let err = serde_json::from_str::<BSplineCurve2<f64>>(
        r#"{"degree":1,"knots":[0,0,1,1],"control_points":[[0,0],[1e999,0]]}"#,
    );
    assert!(err.is_err());
    let err = serde_json::from_str::<BSplineCurve2<f64>>(
        r#"{"degree":1,"knots":[0,0,1e999,1e999],"control_points":[[0,0],[1,0]]}"#,
    );
    assert!(err.is_err());
}

#[test]
fn split_at_a_simple_knot_keeps_c2_and_the_third_derivative_jump() {
    // U = {0,0,0,0,1/2,1,1,1,1}, P = (0,0), (1,2), (2,−1), (3,1), (4,0); split at the knot 1/2.
    // Hodograph points Q_i = 3(P_{i+1} − P_i)/(u_{i+4} − u_{i+1}):
    //   Q = (6,12), (3,−9), (3,6), (6,−6) on {0,0,0,1/2,1,1,1};
    // second: R_i = 2(Q_{i+1} − Q_i)/(u′_{i+3} − u′_{i+1}) = (−12,−84), (0,30), (12,−48);
    // third: S_i = (R_{i+1} − R_i)/(u″_{i+2} − u″_{i+1}) = (24,228) on [0,1/2), (24,−156) after.
    // At 1/2: C = (P1 + 2P2 + P3)/4 = (2, 1/4), C′ = (Q1 + Q2)/2 = (3, −3/2), C″ = R1 = (0, 30).
    let c = curve2(
        3,
        &[0., 0., 0., 0., 0.5, 1., 1., 1., 1.],
        &[[0., 0.], [1., 2.], [2., -1.], [3., 1.], [4., 0.]],
    );
    let (left, right) = c.split(0.5).unwrap();
    assert_eq!((left.domain(), right.domain()), ((0.0, 0.5), (0.5, 1.0)));
    let l = left.derivatives(0.5, 3).unwrap();
    let r = right.derivatives(0.5, 3).unwrap();
    let shared = [
        Vector2::new(2.0, 0.25),
        Vector2::new(3.0, -1.5),
        Vector2::new(0.0, 30.0),
    ];
    for k in 0..3 {
        assert_vec_close(&l[k], &shared[k], 1e-12);
        assert_vec_close(&r[k], &shared[k], 1e-12);
    }
    assert_vec_close(&l[3], &Vector2::new(24.0, 228.0), 1e-11);
    assert_vec_close(&r[3], &Vector2::new(24.0, -156.0), 1e-11);
    // The halves are clamped Bézier pieces here: 4 control points each, sharing C(1/2).
    assert_eq!(left.control_points().len(), 4);
    assert_eq!(right.control_points().len(), 4);
    assert_vec_close(
        &left.control_points()[3].coords,
        &right.control_points()[0].coords,
        1e-15,
    );
}

proptest! {
    /// Split exactly at an interior knot of multiplicity m: the halves agree at the joint in
    /// every derivative of order ≤ p − m (where the original is C^{p−m}), cubic and quartic.
    #[test]
    fn split_at_a_knot_keeps_the_continuity_the_original_had(c in random_curve_of(3..=4), pick in 0usize..8) {
        let (a, b) = c.domain();
        let interior: Vec<f64> = c.breakpoints().into_iter().filter(|&k| k > a && k < b).collect();
        prop_assume!(!interior.is_empty());
        let u = interior[pick % interior.len()];
        let order = c.degree() - c.knots().multiplicity(u);
        let (left, right) = c.split(u).unwrap();
        let l = left.derivatives(u, order).unwrap();
        let r = right.derivatives(u, order).unwrap();
        let o = c.derivatives(u, order).unwrap();
        for k in 0..=order {
            let tol = 1e-9 * (1.0 + o[k].norm());
            prop_assert!((l[k] - r[k]).norm() < tol && (r[k] - o[k]).norm() < tol, "order {}: {:?} {:?} {:?}", k, l[k], r[k], o[k]);
        }
    }
}
