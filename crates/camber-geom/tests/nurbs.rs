//! NURBS curves through the public API: conics by hand, agreement with an independently written
//! B-spline evaluator, derivatives against finite differences and dual numbers, knot operations
//! that must not change the curve, validation and serde.

// Test helpers outside `#[test]` functions unwrap too: a failed unwrap is a failed test.
#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use camber_geom::{Error, KnotVector, NurbsCurve2, NurbsCurve3, ParametricCurve};
use nalgebra::{Point2, Point3, Vector2};
use num_dual::Dual64;
use proptest::prelude::*;
use std::f64::consts::FRAC_1_SQRT_2;

fn quarter_circle() -> NurbsCurve2<f64> {
    let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]).unwrap();
    let points = vec![
        Point2::new(1.0, 0.0),
        Point2::new(1.0, 1.0),
        Point2::new(0.0, 1.0),
    ];
    NurbsCurve2::try_new(2, knots, points, vec![1.0, FRAC_1_SQRT_2, 1.0]).unwrap()
}

/// The unit circle from 9 control points on the square [-1, 1]², four quarter arcs.
fn nine_point_circle() -> NurbsCurve2<f64> {
    let knots = KnotVector::try_new(vec![
        0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
    ])
    .unwrap();
    let xy = [
        (1., 0.),
        (1., 1.),
        (0., 1.),
        (-1., 1.),
        (-1., 0.),
        (-1., -1.),
        (0., -1.),
        (1., -1.),
        (1., 0.),
    ];
    let points = xy.iter().map(|&(x, y)| Point2::new(x, y)).collect();
    let weights = (0..9)
        .map(|i| if i % 2 == 0 { 1.0 } else { FRAC_1_SQRT_2 })
        .collect();
    NurbsCurve2::try_new(2, knots, points, weights).unwrap()
}

/// The unit circle from the equilateral triangle around it: 7 points, weights 1, 1/2, …
fn seven_point_circle() -> NurbsCurve2<f64> {
    let third = 1.0 / 3.0;
    let knots = KnotVector::try_new(vec![
        0.0,
        0.0,
        0.0,
        third,
        third,
        2.0 * third,
        2.0 * third,
        1.0,
        1.0,
        1.0,
    ])
    .unwrap();
    let s = 3.0_f64.sqrt();
    let points = vec![
        Point2::new(1.0, 0.0),
        Point2::new(1.0, s),
        Point2::new(-0.5, s / 2.0),
        Point2::new(-2.0, 0.0),
        Point2::new(-0.5, -s / 2.0),
        Point2::new(1.0, -s),
        Point2::new(1.0, 0.0),
    ];
    let weights = vec![1.0, 0.5, 1.0, 0.5, 1.0, 0.5, 1.0];
    NurbsCurve2::try_new(2, knots, points, weights).unwrap()
}

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// Checks that `c` traces the unit circle around the origin: |C| = 1, C′ ⟂ C and curvature 1.
fn assert_unit_circle(c: &NurbsCurve2<f64>) {
    for k in 0..=200 {
        let u = f64::from(k) / 200.0;
        let [p, d1, d2] = c.second_order(u).unwrap();
        assert_relative_eq!(p.norm(), 1.0, epsilon = 1e-14);
        assert!(p.dot(&d1).abs() < 1e-13 * d1.norm(), "u = {u}");
        assert_relative_eq!(cross(d1, d2) / d1.norm().powi(3), 1.0, epsilon = 1e-12);
    }
}

#[test]
fn quarter_circle_lies_on_the_unit_circle() {
    let c = quarter_circle();
    assert_unit_circle(&c);
    assert_eq!(c.domain(), (0.0, 1.0));
    assert_eq!(c.breakpoints(), vec![0.0, 1.0]);
}

#[test]
fn full_circles_lie_on_the_unit_circle() {
    let nine = nine_point_circle();
    assert_unit_circle(&nine);
    assert_eq!(nine.breakpoints(), vec![0.0, 0.25, 0.5, 0.75, 1.0]);
    assert_relative_eq!(
        nine.point(0.5).unwrap(),
        Point2::new(-1.0, 0.0),
        epsilon = 1e-15
    );
    let seven = seven_point_circle();
    assert_unit_circle(&seven);
    assert_relative_eq!(
        seven.point(1.0 / 6.0).unwrap(),
        Point2::new(0.5, 3.0_f64.sqrt() / 2.0),
        epsilon = 1e-14
    );
}

#[test]
fn three_dimensional_arc() {
    // The quarter circle lifted to the plane z = 2 and rotated: still radius 1 around (0, 0, 2).
    let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]).unwrap();
    let points = vec![
        Point3::new(1.0, 0.0, 2.0),
        Point3::new(1.0, 1.0, 2.0),
        Point3::new(0.0, 1.0, 2.0),
    ];
    let c = NurbsCurve3::try_new(2, knots, points, vec![1.0, FRAC_1_SQRT_2, 1.0]).unwrap();
    for k in 0..=20 {
        let p = c.point(f64::from(k) / 20.0).unwrap();
        assert_relative_eq!(p.z, 2.0, epsilon = 1e-15);
        assert_relative_eq!(p.xy().coords.norm(), 1.0, epsilon = 1e-14);
    }
}

/// N_{i,p}(u) by the textbook recursion, a second implementation independent of the crate's.
fn cox_de_boor(knots: &[f64], i: usize, p: usize, u: f64) -> f64 {
    if p == 0 {
        return if knots[i] <= u && u < knots[i + 1] {
            1.0
        } else {
            0.0
        };
    }
    let mut value = 0.0;
    let left = knots[i + p] - knots[i];
    if left > 0.0 {
        value += (u - knots[i]) / left * cox_de_boor(knots, i, p - 1, u);
    }
    let right = knots[i + p + 1] - knots[i + 1];
    if right > 0.0 {
        value += (knots[i + p + 1] - u) / right * cox_de_boor(knots, i + 1, p - 1, u);
    }
    value
}

/// A random planar NURBS curve: degree 1–4, clamped or not, interior knots of multiplicity up to
/// the degree, a domain that is not [0, 1], weights in [0.2, 5].
fn nurbs_curve() -> impl Strategy<Value = NurbsCurve2<f64>> {
    (
        1usize..=4,
        0usize..6,
        any::<bool>(),
        prop::collection::vec((0.1f64..1.0, 1usize..=4), 16),
        prop::collection::vec((-10.0f64..10.0, -10.0f64..10.0, 0.2f64..5.0), 10),
        -2.0f64..2.0,
    )
        .prop_filter_map(
            "the domain must not be empty",
            |(p, extra, clamped, gaps, data, start)| {
                let n = p + 1 + extra;
                let total = n + p + 1;
                // Distinct values with multiplicities, enough of them for any layout.
                let mut values = Vec::new();
                let mut x = start;
                for &(gap, mult) in &gaps {
                    x += gap;
                    values.extend(std::iter::repeat_n(x, mult.min(p)));
                }
                let knots = if clamped {
                    let interior = &values[..n - p - 1];
                    let end = values[n - p - 1] + 0.5;
                    let mut k = vec![start; p + 1];
                    k.extend_from_slice(interior);
                    k.extend(std::iter::repeat_n(end, p + 1));
                    k
                } else {
                    values.truncate(total);
                    values
                };
                let points = data[..n]
                    .iter()
                    .map(|&(x, y, _)| Point2::new(x, y))
                    .collect();
                let weights = data[..n].iter().map(|&(_, _, w)| w).collect();
                let knots = KnotVector::try_new(knots).ok()?;
                NurbsCurve2::try_new(p, knots, points, weights).ok()
            },
        )
}

fn at(c: &NurbsCurve2<f64>, t: f64) -> f64 {
    let (a, b) = c.domain();
    // Clamped: a + (b − a)·1 may round past b.
    (a + (b - a) * t).clamp(a, b)
}

fn assert_same_curve(a: &NurbsCurve2<f64>, b: &NurbsCurve2<f64>) -> Result<(), TestCaseError> {
    let (a0, a1) = a.domain();
    let (b0, b1) = b.domain();
    prop_assert!((a0 - b0).abs() < 1e-12 && (a1 - b1).abs() < 1e-12);
    for k in 0..=20 {
        let u = at(a, f64::from(k) / 20.0).clamp(b0, b1);
        let (pa, pb) = (a.point(u).unwrap(), b.point(u).unwrap());
        prop_assert!(
            (pa - pb).norm() < 1e-12 * (1.0 + pa.coords.norm()),
            "u={u} {pa} {pb}"
        );
    }
    Ok(())
}

proptest! {
    #[test]
    fn unit_weights_reproduce_the_bspline(curve in nurbs_curve(), t in 0.0f64..1.0, scale in 0.1f64..10.0) {
        // The same knots and points with unit weights, and with all weights equal to `scale`:
        // both are the non-rational B-spline Σ N_{i,p} P_i.
        let p = curve.degree();
        let points = curve.control_points().to_vec();
        let unit = NurbsCurve2::try_with_unit_weights(p, curve.knots().clone(), points.clone()).unwrap();
        let scaled = NurbsCurve2::try_new(p, curve.knots().clone(), points.clone(), vec![scale; points.len()]).unwrap();
        prop_assert!(unit.is_polynomial() && scaled.is_polynomial());
        let u = at(&unit, t);
        let knots = unit.knots().as_slice();
        let mut expected = Vector2::zeros();
        for (i, pt) in points.iter().enumerate() {
            expected += pt.coords * cox_de_boor(knots, i, p, u);
        }
        for c in [&unit, &scaled] {
            let got = c.point(u).unwrap();
            prop_assert!((got.coords - expected).norm() < 1e-12 * (1.0 + expected.norm()));
        }
    }

    #[test]
    fn derivatives_match_central_differences(curve in nurbs_curve(), t in 0.05f64..0.95) {
        let u = at(&curve, t);
        let h = 1e-5;
        // Stay inside one knot span, where the curve is smooth.
        prop_assume!(curve.breakpoints().iter().all(|&k| (k - u).abs() > 2.0 * h));
        let d = curve.derivatives(u, 3).unwrap();
        let plus = curve.derivatives(u + h, 2).unwrap();
        let minus = curve.derivatives(u - h, 2).unwrap();
        for k in 1..=3 {
            let fd = (plus[k - 1] - minus[k - 1]) / (2.0 * h);
            let scale = 1.0 + d[k].norm() + d[k - 1].norm();
            prop_assert!((fd - d[k]).norm() < 1e-4 * scale, "k={k} fd={fd} exact={}", d[k]);
        }
        // The convenience methods agree with the general one.
        let [p0, p1, p2] = curve.second_order(u).unwrap();
        prop_assert!((p0 - d[0]).norm() < 1e-14 * (1.0 + p0.norm()));
        prop_assert!((p1 - d[1]).norm() < 1e-14 * (1.0 + p1.norm()));
        prop_assert!((p2 - d[2]).norm() < 1e-14 * (1.0 + p2.norm()));
    }

    #[test]
    fn derivatives_match_dual_numbers(curve in nurbs_curve(), t in 0.0f64..=1.0, order in 1usize..4) {
        // Evaluating at u + ε gives d/du of C⁽ᵏ⁾ in the dual part, for every k below the top.
        let dual_curve = NurbsCurve2::try_new(
            curve.degree(),
            KnotVector::try_new(curve.knots().as_slice().iter().map(|&k| Dual64::from(k)).collect()).unwrap(),
            curve.control_points().iter().map(|p| p.map(Dual64::from)).collect(),
            curve.weights().iter().map(|&w| Dual64::from(w)).collect(),
        ).unwrap();
        let u = at(&curve, t);
        // At the end of the domain the seeded u must not leave it: differentiate to the left.
        let seed = if t >= 1.0 { -1.0 } else { 1.0 };
        let du = Dual64::new(u, seed);
        let d = curve.derivatives(u, order + 1).unwrap();
        let dd = dual_curve.derivatives(du, order).unwrap();
        for k in 0..=order {
            let scale = 1.0 + d[k + 1].norm();
            for c in 0..2 {
                prop_assert!((dd[k][c].re - d[k][c]).abs() < 1e-12 * (1.0 + d[k].norm()));
                prop_assert!((dd[k][c].eps * seed - d[k + 1][c]).abs() < 1e-9 * scale);
            }
        }
    }

    #[test]
    fn knot_insertion_keeps_the_curve(curve in nurbs_curve(), t in 0.0f64..=1.0, times in 1usize..3) {
        let u = at(&curve, t);
        let m = curve.knots().multiplicity(u);
        prop_assume!(m + times <= curve.degree());
        let inserted = curve.insert_knot(u, times).unwrap();
        prop_assert_eq!(inserted.control_points().len(), curve.control_points().len() + times);
        prop_assert_eq!(inserted.knots().multiplicity(u), m + times);
        assert_same_curve(&curve, &inserted)?;
    }

    #[test]
    fn refinement_keeps_the_curve(curve in nurbs_curve(), ts in prop::collection::vec(0.0f64..=1.0, 0..5)) {
        let mut new_knots: Vec<f64> = ts.iter().map(|&t| at(&curve, t)).collect();
        new_knots.sort_by(f64::total_cmp);
        let refined = curve.refine(&new_knots).unwrap();
        prop_assert_eq!(refined.control_points().len(), curve.control_points().len() + new_knots.len());
        assert_same_curve(&curve, &refined)?;
    }

    #[test]
    fn split_halves_keep_their_domains(curve in nurbs_curve(), t in 0.05f64..0.95) {
        let u = at(&curve, t);
        let (a, b) = curve.domain();
        let (left, right) = curve.split(u).unwrap();
        prop_assert!((left.domain().0 - a).abs() < 1e-15 && (left.domain().1 - u).abs() < 1e-15);
        prop_assert!((right.domain().0 - u).abs() < 1e-15 && (right.domain().1 - b).abs() < 1e-15);
        for k in 0..=10 {
            let s = f64::from(k) / 10.0;
            for half in [&left, &right] {
                let v = at(half, s);
                let (p, q) = (half.point(v).unwrap(), curve.point(v).unwrap());
                prop_assert!((p - q).norm() < 1e-12 * (1.0 + q.coords.norm()));
            }
        }
    }

    #[test]
    fn bezier_pieces_reproduce_the_curve(curve in nurbs_curve()) {
        let pieces = curve.to_bezier_segments();
        let breaks = curve.breakpoints();
        prop_assert_eq!(pieces.len(), breaks.len() - 1);
        for ((start, end, piece), w) in pieces.iter().zip(breaks.windows(2)) {
            prop_assert!((start - w[0]).abs() < 1e-15 && (end - w[1]).abs() < 1e-15);
            prop_assert_eq!(piece.degree(), curve.degree());
            prop_assert_eq!(piece.control_points().len(), curve.degree() + 1);
            prop_assert!(piece.weights().iter().all(|&w| w > 0.0));
            for k in 0..=8 {
                let u = start + (end - start) * f64::from(k) / 8.0;
                // At a discontinuity (full multiplicity) the curve takes the right-hand piece.
                if k == 8 && curve.knots().multiplicity(*end) > curve.degree() {
                    continue;
                }
                let (p, q) = (piece.point(u).unwrap(), curve.point(u).unwrap());
                prop_assert!((p - q).norm() < 1e-12 * (1.0 + q.coords.norm()));
            }
        }
    }

    #[test]
    fn degree_elevation_keeps_the_curve(curve in nurbs_curve(), times in 1usize..3) {
        let elevated = curve.elevate_degree(times).unwrap();
        prop_assert_eq!(elevated.degree(), curve.degree() + times);
        assert_same_curve(&curve, &elevated)?;
    }

    #[test]
    fn reversal_and_reparameterization(curve in nurbs_curve(), t in 0.0f64..=1.0, a in -3.0f64..3.0, len in 0.1f64..4.0) {
        let (c0, c1) = curve.domain();
        let reversed = curve.reversed();
        let u = at(&curve, t);
        let (p, q) = (reversed.point(c0 + c1 - u).unwrap(), curve.point(u).unwrap());
        prop_assert!((p - q).norm() < 1e-12 * (1.0 + q.coords.norm()));
        assert_same_curve(&curve, &reversed.reversed())?;
        let moved = curve.reparameterized(a, a + len).unwrap();
        prop_assert!((moved.domain().0 - a).abs() < 1e-12 && (moved.domain().1 - a - len).abs() < 1e-12);
        let p = moved.point(a + len * t).unwrap();
        prop_assert!((p - q).norm() < 1e-12 * (1.0 + q.coords.norm()));
        assert_same_curve(&curve, &curve.clamped())?;
    }

    #[test]
    fn serde_round_trip(curve in nurbs_curve()) {
        let json = serde_json::to_string(&curve).unwrap();
        let back: NurbsCurve2<f64> = serde_json::from_str(&json).unwrap();
        // serde_json parses floats to within one unit in the last place.
        prop_assert_eq!(back.degree(), curve.degree());
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-15 * (1.0 + a.abs());
        let pairs = back.knots().as_slice().iter().zip(curve.knots().as_slice())
            .chain(back.weights().iter().zip(curve.weights()))
            .chain(back.control_points().iter().flat_map(|p| p.coords.iter())
                .zip(curve.control_points().iter().flat_map(|p| p.coords.iter())));
        for (a, b) in pairs {
            prop_assert!(close(*a, *b), "{a} vs {b}");
        }
        prop_assert_eq!(back.knots().len(), curve.knots().len());
        prop_assert_eq!(back.control_points().len(), curve.control_points().len());
    }
}

proptest! {
    /// A rational curve split away from its knots: the two halves meet with equal position,
    /// first and second derivatives (the original is C∞ there, so the joint is C2).
    #[test]
    fn split_joint_is_c2_where_the_original_was(curve in nurbs_curve(), t in 0.05f64..0.95) {
        prop_assume!(curve.degree() >= 2);
        let u = at(&curve, t);
        // A tiny span next to the joint makes second derivatives ill-conditioned (round-off
        // grows like 1/h²), which is not what this test is about.
        prop_assume!(curve.knots().as_slice().iter().all(|&k| (k - u).abs() > 0.02));
        let (left, right) = curve.split(u).unwrap();
        let l = left.derivatives(u, 2).unwrap();
        let r = right.derivatives(u, 2).unwrap();
        let o = curve.derivatives(u, 2).unwrap();
        for k in 0..=2 {
            let tol = 1e-9 * (1.0 + o[k].norm());
            prop_assert!((l[k] - r[k]).norm() < tol && (l[k] - o[k]).norm() < tol, "order {}", k);
        }
    }
}

#[test]
fn validation_names_the_offending_weight() {
    let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]).unwrap();
    let points = quarter_circle().control_points().to_vec();
    let make = |w: Vec<f64>| NurbsCurve2::try_new(2, knots.clone(), points.clone(), w);
    assert_eq!(
        make(vec![1.0, 0.0, 1.0]),
        Err(Error::NonPositiveWeight {
            index: 1,
            value: 0.0
        })
    );
    assert_eq!(
        make(vec![1.0, 1.0, -0.5]),
        Err(Error::NonPositiveWeight {
            index: 2,
            value: -0.5
        })
    );
    assert_eq!(
        make(vec![1.0, 1.0]),
        Err(Error::WeightCount {
            expected: 3,
            found: 2
        })
    );
    assert!(matches!(
        make(vec![f64::NAN, 1.0, 1.0]),
        Err(Error::NonFinite {
            what: "weight",
            index: 0,
            ..
        })
    ));
    assert!(matches!(
        make(vec![1.0, f64::INFINITY, 1.0]),
        Err(Error::NonFinite {
            what: "weight",
            index: 1,
            ..
        })
    ));
    let mut bad_points = points.clone();
    bad_points[2].y = f64::NAN;
    assert!(matches!(
        NurbsCurve2::try_new(2, knots.clone(), bad_points, vec![1.0; 3]),
        Err(Error::NonFinite { index: 2, .. })
    ));
    assert_eq!(
        NurbsCurve2::try_new(2, knots, points[..2].to_vec(), vec![1.0; 2]),
        Err(Error::TooFewControlPoints {
            degree: 2,
            needed: 3,
            found: 2
        })
    );
}

#[test]
fn parameters_outside_the_domain_are_errors() {
    let c = quarter_circle();
    assert_eq!(
        c.point(-0.1),
        Err(Error::ParameterOutsideDomain {
            value: -0.1,
            min: 0.0,
            max: 1.0
        })
    );
    assert!(matches!(
        c.derivatives(1.0 + 1e-9, 2),
        Err(Error::ParameterOutsideDomain { .. })
    ));
    assert!(matches!(
        c.insert_knot(2.0, 1),
        Err(Error::ParameterOutsideDomain { .. })
    ));
    assert!(matches!(
        c.split(0.0),
        Err(Error::ParameterOutsideDomain { .. })
    ));
    assert!(matches!(
        c.split(1.0),
        Err(Error::ParameterOutsideDomain { .. })
    ));
    assert!(matches!(
        c.reparameterized(1.0, 1.0),
        Err(Error::InvalidInterval { .. })
    ));
}

#[test]
fn serde_format_and_validation() {
    let c = quarter_circle();
    let value = serde_json::to_value(&c).unwrap();
    assert_eq!(value["degree"], 2);
    assert_eq!(
        value["knots"],
        serde_json::json!([0.0, 0.0, 0.0, 1.0, 1.0, 1.0])
    );
    assert_eq!(
        value["control_points"],
        serde_json::json!([[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    );
    assert_eq!(value["weights"][1], FRAC_1_SQRT_2);
    let bad_weight = r#"{"degree": 1, "knots": [0, 0, 1, 1],
        "control_points": [[0, 0], [1, 0]], "weights": [1, -1]}"#;
    let err = serde_json::from_str::<NurbsCurve2<f64>>(bad_weight).unwrap_err();
    assert!(
        err.to_string().contains("weight 1 is not positive"),
        "{err}"
    );
    let bad_dimension = r#"{"degree": 1, "knots": [0, 0, 1, 1],
        "control_points": [[0, 0], [1, 0, 2]], "weights": [1, 1]}"#;
    let err = serde_json::from_str::<NurbsCurve2<f64>>(bad_dimension).unwrap_err();
    assert!(
        err.to_string().contains("point 1 has 3 coordinates"),
        "{err}"
    );
    let bad_knots = r#"{"degree": 1, "knots": [0, 1, 0, 1],
        "control_points": [[0, 0], [1, 0]], "weights": [1, 1]}"#;
    assert!(serde_json::from_str::<NurbsCurve2<f64>>(bad_knots).is_err());
}

#[test]
fn derivative_with_respect_to_a_weight_matches_a_difference() {
    // Seeding the middle weight of the quarter circle: the point moves along the circle's
    // chord bisector, and the dual part agrees with a central difference in the weight.
    let knots: Vec<Dual64> = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0]
        .iter()
        .map(|&k| Dual64::from(k))
        .collect();
    let points: Vec<_> = quarter_circle()
        .control_points()
        .iter()
        .map(|p| p.map(Dual64::from))
        .collect();
    let w = FRAC_1_SQRT_2;
    let weights = vec![Dual64::from(1.0), Dual64::new(w, 1.0), Dual64::from(1.0)];
    let c = NurbsCurve2::try_new(2, KnotVector::try_new(knots).unwrap(), points, weights).unwrap();
    let p = c.point(Dual64::from(0.3)).unwrap();
    let h = 1e-6;
    let with = |w: f64| {
        let base = quarter_circle();
        NurbsCurve2::try_new(
            2,
            base.knots().clone(),
            base.control_points().to_vec(),
            vec![1.0, w, 1.0],
        )
        .unwrap()
        .point(0.3)
        .unwrap()
    };
    let fd = (with(w + h) - with(w - h)) / (2.0 * h);
    assert_relative_eq!(p.x.eps, fd.x, epsilon = 1e-8);
    assert_relative_eq!(p.y.eps, fd.y, epsilon = 1e-8);
}

proptest! {
    #[test]
    fn circular_arcs_lie_on_their_circle(
        cx in -5.0f64..5.0, cy in -5.0f64..5.0, r in 0.1f64..10.0,
        start in -7.0f64..7.0, sweep in 0.01f64..=std::f64::consts::TAU,
    ) {
        let center = Point2::new(cx, cy);
        let arc = NurbsCurve2::try_circular_arc(center, r, start, start + sweep).unwrap();
        let arcs = (arc.control_points().len() - 1) / 2;
        // One piece per started quarter turn.
        prop_assert!((1..=4).contains(&arcs));
        prop_assert!(sweep <= std::f64::consts::FRAC_PI_2 * arcs as f64 * (1.0 + 1e-9));
        let first = arc.point(0.0).unwrap();
        let last = arc.point(1.0).unwrap();
        prop_assert!((first - (center + Vector2::new(start.cos(), start.sin()) * r)).norm() < 1e-12 * r);
        let e = start + sweep;
        prop_assert!((last - (center + Vector2::new(e.cos(), e.sin()) * r)).norm() < 1e-12 * (1.0 + r));
        for k in 0..=40 {
            let u = f64::from(k) / 40.0;
            let [p, d1, _] = arc.second_order(u).unwrap();
            let radial = p - center.coords;
            prop_assert!((radial.norm() - r).abs() < 1e-12 * (1.0 + r));
            prop_assert!(radial.dot(&d1).abs() < 1e-11 * (1.0 + r) * d1.norm());
            // Counterclockwise.
            prop_assert!(cross(radial, d1) > 0.0);
        }
    }
}

#[test]
fn circular_arc_errors_and_full_circle() {
    let o = Point2::new(0.0, 0.0);
    assert_eq!(
        NurbsCurve2::try_circular_arc(o, -1.0, 0.0, 1.0),
        Err(Error::NonPositiveRadius { value: -1.0 })
    );
    assert!(matches!(
        NurbsCurve2::try_circular_arc(o, f64::NAN, 0.0, 1.0),
        Err(Error::NonPositiveRadius { .. })
    ));
    assert!(matches!(
        NurbsCurve2::try_circular_arc(o, 1.0, 1.0, 1.0),
        Err(Error::InvalidInterval { .. })
    ));
    assert!(matches!(
        NurbsCurve2::try_circular_arc(o, 1.0, 0.0, 7.0),
        Err(Error::InvalidInterval { .. })
    ));
    assert!(matches!(
        NurbsCurve2::try_circular_arc(Point2::new(f64::NAN, 0.0), 1.0, 0.0, 1.0),
        Err(Error::NonFinite { .. })
    ));
    // A full unit circle from angle 0 is exactly the 9-point construction.
    let full = NurbsCurve2::try_circular_arc(o, 1.0, 0.0, std::f64::consts::TAU).unwrap();
    let nine = nine_point_circle();
    assert_eq!(full.knots(), nine.knots());
    for (a, b) in full.control_points().iter().zip(nine.control_points()) {
        assert_relative_eq!(a, b, epsilon = 1e-15);
    }
    for (a, b) in full.weights().iter().zip(nine.weights()) {
        assert_relative_eq!(a, b, epsilon = 1e-15);
    }
}
