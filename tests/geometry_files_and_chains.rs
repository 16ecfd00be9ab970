//! Facade-level checks of the geometry kernel: every f64 curve and primitive type saves to JSON
//! and loads back bit for bit, bad files are rejected with the constructor's error, and a chain
//! mixing curve types reports its joints.

use camber::geom::{
    BSplineCurve2, BezierCurve2, Circle, CompositeCurve2, Continuity, HermiteCurve2, KnotVector,
    Line, NurbsCurve2, ParametricCurve, Segment,
};
use nalgebra::{Point2, Vector2};
use serde::{de::DeserializeOwned, Serialize};

/// save ∘ load is the identity, exactly (serde_json runs with `float_roundtrip`).
fn round_trip<V: Serialize + DeserializeOwned + PartialEq + std::fmt::Debug>(value: &V) {
    let json = serde_json::to_string(value).expect("serializes");
    let back: V = serde_json::from_str(&json).expect("loads back");
    assert_eq!(&back, value, "round trip changed {json}");
    assert_eq!(serde_json::to_string(&back).expect("serializes"), json);
}

fn awkward_points() -> Vec<Point2<f64>> {
    // Values with long binary expansions, to catch any loss in the last place.
    vec![
        Point2::new(0.1, 1.0 / 3.0),
        Point2::new(0.7, -2.0 / 7.0),
        Point2::new(1.3, std::f64::consts::PI / 10.0),
        Point2::new(2.0 / 3.0 + 1.0, 1e-17),
    ]
}

#[test]
fn every_type_round_trips_exactly() {
    let bezier = BezierCurve2::try_new(awkward_points()).unwrap();
    round_trip(&bezier);
    let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.3, 1.0, 1.0, 1.0]).unwrap();
    round_trip(&BSplineCurve2::try_new(2, knots.clone(), awkward_points()).unwrap());
    let weights = vec![1.0, 0.1, 2.0 / 3.0, 1.7];
    round_trip(&NurbsCurve2::try_new(2, knots, awkward_points(), weights).unwrap());
    let hermite = HermiteCurve2::from_bezier(&BezierCurve2::try_new(awkward_points()).unwrap());
    round_trip(&hermite.unwrap());
    round_trip(&Line::try_new(Point2::new(0.1, 0.2), Vector2::new(1.0 / 3.0, 0.3)).unwrap());
    round_trip(&Segment::try_new(Point2::new(0.1, 0.2), Point2::new(1.0 / 7.0, 3.0)).unwrap());
    round_trip(&Circle::try_new(Point2::new(0.03, 0.0), 0.015).unwrap());
}

#[test]
fn bad_files_fail_with_the_constructor_error() {
    let cases = [
        (
            r#"{"degree": 1, "knots": [0, 0, 0, 1, 1, 1], "control_points": [[0, 0], [1, 1]]}"#,
            "need 4 knots, found 6",
        ),
        (
            r#"{"degree": 2, "knots": [0, 0, 0, 1, 1, 1], "control_points": [[0, 0], [1, 1]]}"#,
            "at least 3 control points",
        ),
        (
            r#"{"degree": 1, "knots": [0, 1, 0.5, 1], "control_points": [[0, 0], [1, 1]]}"#,
            "smaller",
        ),
        (
            r#"{"degree": 1, "knots": [0, 0, 1, 1], "control_points": [[0, 0], [1]]}"#,
            "coordinates",
        ),
    ];
    for (json, needle) in cases {
        let err = serde_json::from_str::<BSplineCurve2<f64>>(json)
            .unwrap_err()
            .to_string();
        assert!(err.contains(needle), "{err} does not mention {needle}");
    }
    let err = serde_json::from_str::<Circle<f64>>(r#"{"center": [0, 0], "radius": -1}"#)
        .unwrap_err()
        .to_string();
    assert!(err.contains("radius"), "{err}");
    let weights = r#"{"degree": 1, "knots": [0, 0, 1, 1], "control_points": [[0, 0], [1, 1]],
                      "weights": [1, 0]}"#;
    let err = serde_json::from_str::<NurbsCurve2<f64>>(weights)
        .unwrap_err()
        .to_string();
    assert!(err.contains("weight 1"), "{err}");
}

#[test]
fn a_mixed_chain_reports_each_joint() {
    // A Bézier lead-in, a B-spline made from a Bézier that continues it with equal first
    // derivatives (C1), then a NURBS piece that starts at the same point in the same direction
    // at a different speed (G1 only), then one that leaves a gap.
    let first = BezierCurve2::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 1.0),
        Point2::new(2.0, 1.0),
    ])
    .unwrap();
    // first'(1) = 2·(P2 − P1) = (2, 0); the next Bézier's start derivative 3·(Q1 − Q0) = (2, 0).
    let second = BSplineCurve2::from_bezier(
        &BezierCurve2::try_new(vec![
            Point2::new(2.0, 1.0),
            Point2::new(2.0 + 2.0 / 3.0, 1.0),
            Point2::new(3.5, 0.5),
            Point2::new(4.0, 0.0),
        ])
        .unwrap(),
    );
    let end = second.derivative(1.0).unwrap();
    let knots = KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0]).unwrap();
    let third = NurbsCurve2::try_new(
        1,
        knots.clone(),
        vec![Point2::new(4.0, 0.0), Point2::new(4.0, 0.0) + end * 2.0],
        vec![1.0, 1.0],
    )
    .unwrap();
    let fourth = NurbsCurve2::try_new(
        1,
        knots,
        vec![Point2::new(9.0, 9.0), Point2::new(10.0, 9.0)],
        vec![1.0, 1.0],
    )
    .unwrap();
    let chain = CompositeCurve2::try_new(vec![
        Box::new(first),
        Box::new(second),
        Box::new(third),
        Box::new(fourth),
    ])
    .unwrap();
    let joints = chain.joints().unwrap();
    let tolerances = Default::default();
    assert_eq!(joints.len(), 3);
    assert!(joints[0].continuity(&tolerances) >= Continuity::C1);
    assert!(joints[0].first_derivative_mismatch < 1e-12);
    assert_eq!(joints[1].continuity(&tolerances), Continuity::G1);
    assert!(joints[1].tangent_angle < 1e-12 && joints[1].first_derivative_mismatch > 1.0);
    assert_eq!(joints[2].continuity(&tolerances), Continuity::None);
    // second′(1) = 3·(Q3 − Q2) = (1.5, −1.5), so the third piece ends at (4, 0) + 2·(1.5, −1.5)
    // = (7, −3), and the fourth starts at (9, 9).
    assert!((joints[2].position_gap - (2.0_f64 * 2.0 + 12.0 * 12.0).sqrt()).abs() < 1e-12);
}
