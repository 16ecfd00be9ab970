//! Bézier curves through the public API: the two evaluation methods against each other,
//! derivatives against central differences and dual numbers, the laws of subdivision, degree
//! elevation, reversal and the hodograph, and the JSON form.

use approx::assert_relative_eq;
use camber_geom::bernstein::bernstein;
use camber_geom::{BezierCurve, BezierCurve2, BezierCurve3, Error, ParametricCurve};
use nalgebra::{Point, Point2, Point3, SVector};
use num_dual::Dual64;
use proptest::prelude::*;

/// Control points of a random curve of degree 0..=9 with coordinates in [−10, 10].
fn points<const D: usize>() -> impl Strategy<Value = Vec<Point<f64, D>>> {
    prop::collection::vec(prop::array::uniform::<_, D>(-10.0f64..10.0), 1..=10).prop_map(|raw| {
        raw.into_iter()
            .map(|c| Point::from(SVector::from(c)))
            .collect()
    })
}

fn curve<const D: usize>() -> impl Strategy<Value = BezierCurve<f64, D>> {
    // Every generated list is valid; the filter only avoids an unwrap outside a test.
    points::<D>().prop_filter_map("valid control points", |p| BezierCurve::try_new(p).ok())
}

/// Largest coordinate magnitude among the control points, at least 1.
fn scale<const D: usize>(c: &BezierCurve<f64, D>) -> f64 {
    c.control_points()
        .iter()
        .flat_map(|p| p.coords.iter().map(|v| v.abs()))
        .fold(1.0, f64::max)
}

fn distance<const D: usize>(a: Point<f64, D>, b: Point<f64, D>) -> f64 {
    (a - b).norm()
}

proptest! {
    #[test]
    fn bernstein_form_equals_de_casteljau(c in curve::<2>(), t in 0.0f64..=1.0) {
        let a = c.point_bernstein(t).unwrap();
        let b = c.point_de_casteljau(t).unwrap();
        let p = c.point(t).unwrap();
        prop_assert!(distance(a, b) < 1e-13 * scale(&c), "{a} vs {b}");
        prop_assert!(distance(p, b) < 1e-13 * scale(&c), "{p} vs {b}");
    }

    #[test]
    fn bernstein_form_equals_de_casteljau_3d(c in curve::<3>(), t in 0.0f64..=1.0) {
        let a = c.point_bernstein(t).unwrap();
        let b = c.point_de_casteljau(t).unwrap();
        prop_assert!(distance(a, b) < 1e-13 * scale(&c));
    }

    #[test]
    fn ends_interpolate_the_first_and_last_control_points(c in curve::<2>()) {
        let first = c.control_points()[0];
        let last = c.control_points()[c.degree()];
        prop_assert!(distance(c.point(0.0).unwrap(), first) < 1e-14 * scale(&c));
        prop_assert!(distance(c.point(1.0).unwrap(), last) < 1e-14 * scale(&c));
    }

    #[test]
    fn derivatives_match_central_differences(c in curve::<2>(), t in 0.01f64..0.99) {
        // Compare C⁽ᵏ⁾ with the central difference of C⁽ᵏ⁻¹⁾ for k = 1, 2, 3. The truncation
        // error is h²/6 |C⁽ᵏ⁺²⁾|, the rounding error about ε |C⁽ᵏ⁻¹⁾| / h.
        let h = 1e-4;
        let d = c.derivatives(t, 5).unwrap();
        let up = c.derivatives(t + h, 2).unwrap();
        let down = c.derivatives(t - h, 2).unwrap();
        for k in 1..=3 {
            let fd = (up[k - 1] - down[k - 1]) / (2.0 * h);
            let size: f64 = d[k - 1..=k + 2].iter().map(|v| v.norm()).sum();
            prop_assert!((fd - d[k]).norm() < 1e-7 * (1.0 + size), "k={k} fd={fd} exact={}", d[k]);
        }
    }

    #[test]
    fn derivatives_above_the_degree_vanish(c in curve::<2>(), t in 0.0f64..=1.0) {
        let n = c.degree();
        let d = c.derivatives(t, n + 3).unwrap();
        for v in &d[n + 1..] {
            prop_assert!(v.norm() < 1e-300);
        }
    }

    #[test]
    fn dual_numbers_agree_with_the_derivatives(pts in points::<2>(), t in 0.0f64..=1.0, pick in 0usize..10) {
        // With respect to t: the ε part of C(t + ε) is C′(t).
        let c = BezierCurve2::try_new(pts.clone()).unwrap();
        let dual_points: Vec<Point2<Dual64>> =
            pts.iter().map(|p| p.map(Dual64::from)).collect();
        let dual_curve = BezierCurve2::try_new(dual_points.clone()).unwrap();
        let p = dual_curve.point(Dual64::new(t, 1.0)).unwrap();
        let d1 = c.derivative(t).unwrap();
        prop_assert!((p.x.eps - d1.x).abs() < 1e-12 * (1.0 + d1.norm()));
        prop_assert!((p.y.eps - d1.y).abs() < 1e-12 * (1.0 + d1.norm()));
        // With respect to the x coordinate of control point i: ∂C/∂P_i = B_{i,n}(t).
        let i = pick % pts.len();
        let mut seeded = dual_points;
        seeded[i].x.eps = 1.0;
        let seeded = BezierCurve2::try_new(seeded).unwrap();
        let b = bernstein(c.degree(), i, t);
        for q in [
            seeded.point(Dual64::from(t)).unwrap(),
            seeded.point_bernstein(Dual64::from(t)).unwrap(),
            seeded.point_de_casteljau(Dual64::from(t)).unwrap(),
        ] {
            prop_assert!((q.x.eps - b).abs() < 1e-13);
            prop_assert!(q.y.eps.abs() < 1e-15);
        }
    }

    #[test]
    fn hodograph_is_the_derivative(c in curve::<2>(), s in 0.0f64..=1.0) {
        let d = c.derivatives(s, 2).unwrap();
        let h = c.hodograph();
        prop_assert_eq!(h.degree(), c.degree().saturating_sub(1));
        let size = (1.0 + d[1].norm() + d[2].norm()) * 1e-12;
        prop_assert!((h.point(s).unwrap().coords - d[1]).norm() < size);
        prop_assert!((h.hodograph().point(s).unwrap().coords - d[2]).norm() < size);
        prop_assert!((h.derivative(s).unwrap() - d[2]).norm() < size);
    }

    #[test]
    fn subdivision_halves_reproduce_the_curve(c in curve::<2>(), t in 0.01f64..0.99, s in 0.0f64..=1.0) {
        let (left, right) = c.subdivide(t).unwrap();
        prop_assert_eq!(left.degree(), c.degree());
        prop_assert_eq!(right.degree(), c.degree());
        let tol = 1e-12;
        prop_assert!(distance(left.point(s).unwrap(), c.point(t * s).unwrap()) < tol);
        prop_assert!(distance(right.point(s).unwrap(), c.point(t + (1.0 - t) * s).unwrap()) < tol);
        // The halves meet at C(t), and their control polygons are no longer than the curve's.
        prop_assert!(distance(left.control_points()[c.degree()], right.control_points()[0]) < tol);
        prop_assert!(
            left.control_polygon_length() + right.control_polygon_length()
                <= c.control_polygon_length() + 1e-12
        );
    }

    #[test]
    fn segment_reproduces_the_curve(c in curve::<2>(), a in 0.0f64..=1.0, b in 0.0f64..=1.0, s in 0.0f64..=1.0) {
        let (t0, t1) = (a.min(b), a.max(b));
        prop_assume!(t1 - t0 > 1e-3);
        let piece = c.segment(t0, t1).unwrap();
        let expected = c.point(t0 + (t1 - t0) * s).unwrap();
        prop_assert!(distance(piece.point(s).unwrap(), expected) < 1e-12);
    }

    #[test]
    fn degree_elevation_leaves_the_curve_unchanged(c in curve::<2>(), times in 0usize..=4, s in 0.0f64..=1.0) {
        let e = c.elevate_degree(times);
        prop_assert_eq!(e.degree(), c.degree() + times);
        prop_assert!(distance(e.point(s).unwrap(), c.point(s).unwrap()) < 1e-12);
        // Elevation keeps the ends and cuts corners: the polygon never gets longer.
        prop_assert_eq!(e.control_points()[0], c.control_points()[0]);
        prop_assert!(e.control_polygon_length() <= c.control_polygon_length() + 1e-12);
    }

    #[test]
    fn reversal(c in curve::<3>(), s in 0.0f64..=1.0) {
        let r = c.reversed();
        prop_assert_eq!(&r.reversed(), &c);
        prop_assert!(distance(r.point(s).unwrap(), c.point(1.0 - s).unwrap()) < 1e-12);
        prop_assert!((r.derivative(s).unwrap() + c.derivative(1.0 - s).unwrap()).norm() < 1e-11);
        prop_assert!((r.control_polygon_length() - c.control_polygon_length()).abs() < 1e-12);
    }

    #[test]
    fn control_polygon_bounds_the_chord(c in curve::<2>()) {
        let chord = distance(c.point(0.0).unwrap(), c.point(1.0).unwrap());
        prop_assert!(chord <= c.control_polygon_length() + 1e-12);
    }

    #[test]
    fn json_round_trip(c in curve::<2>()) {
        let json = serde_json::to_string(&c).unwrap();
        let back: BezierCurve2<f64> = serde_json::from_str(&json).unwrap();
        // serde_json without its `float_roundtrip` feature may parse a float one ulp off.
        prop_assert_eq!(back.degree(), c.degree());
        for (a, b) in back.control_points().iter().zip(c.control_points()) {
            prop_assert!(distance(*a, *b) <= 1e-15 * scale(&c));
        }
    }
}

#[test]
fn json_form() {
    let c = BezierCurve2::try_new(vec![Point2::new(0.0, 0.5), Point2::new(1.0, 2.0)]).unwrap();
    assert_eq!(
        serde_json::to_string(&c).unwrap(),
        r#"{"control_points":[[0.0,0.5],[1.0,2.0]]}"#
    );
    let c3: BezierCurve3<f64> =
        serde_json::from_str(r#"{"control_points": [[1, 2, 3], [4, 5, 6]]}"#).unwrap();
    assert_relative_eq!(c3.control_points()[1], Point3::new(4.0, 5.0, 6.0));
}

/// The message serde reports for a curve that `try_new` or the point reader rejects starts with
/// that `Error`'s own message (serde_json appends the position).
fn rejected_with(json: &str, expected: &Error) {
    let message = match serde_json::from_str::<BezierCurve2<f64>>(json) {
        Ok(c) => panic!("{json} was accepted as {c:?}"),
        Err(err) => err.to_string(),
    };
    assert!(
        message.starts_with(&expected.to_string()),
        "{message:?} does not start with {expected}"
    );
}

#[test]
fn json_rejects_bad_curves() {
    rejected_with(
        r#"{"control_points": [[0, 0], [1]]}"#,
        &Error::Dimension {
            index: 1,
            expected: 2,
            found: 1,
        },
    );
    rejected_with(
        r#"{"control_points": [[0, 0], [1, 2, 3]]}"#,
        &Error::Dimension {
            index: 1,
            expected: 2,
            found: 3,
        },
    );
    rejected_with(
        r#"{"control_points": []}"#,
        &Error::TooFewControlPoints {
            degree: 0,
            needed: 1,
            found: 0,
        },
    );
    assert!(serde_json::from_str::<BezierCurve2<f64>>(r#"{"points": [[0, 0]]}"#).is_err());
}

#[test]
fn deserialization_rejects_nan() {
    // JSON has no NaN, so feed the deserializer directly from serde's in-memory value types.
    use serde::de::value::{Error as ValueError, MapDeserializer};
    use serde::Deserialize;
    let entries = vec![("control_points", vec![vec![0.0, 0.0], vec![1.0, f64::NAN]])];
    let deserializer = MapDeserializer::<_, ValueError>::new(entries.into_iter());
    let err = BezierCurve2::<f64>::deserialize(deserializer).unwrap_err();
    let expected = Error::NonFinite {
        what: "control point coordinate of point",
        index: 1,
        value: f64::NAN,
    };
    assert_eq!(err.to_string(), expected.to_string());
}
