//! Regression tests of sketches found by the solve property (`solve_property.rs`) and the
//! fuzzers (`fuzz/`), named after what they caught.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber_geom::{BezierCurve2, KnotVector, NurbsCurve2};
use camber_sketch::constraints::G1Join;
use camber_sketch::{Error, Sketch};
use nalgebra::{Point2, Vector2};

/// Two G1 joins into the start of one NURBS curve with different joint directions can only
/// hold with the curve's start tangent collapsed (P₁ = P₀). The linear solve found that state
/// and its orientation check passed on a tangent of 2e-15 (rounding, whose sign means nothing);
/// the written-back sketch then failed its next solve. The collapse is a cusp, refused with the
/// sketch unchanged, and a solve of the unchanged sketch says the same.
#[test]
fn collapsed_joint_tangent_is_a_cusp_not_a_solution() {
    let mut s = Sketch::new();
    let knots = KnotVector::clamped_uniform(2, 3).unwrap();
    let nurbs = NurbsCurve2::try_new(
        2,
        knots,
        vec![
            Point2::new(1.9835620768464033, -1.675558405199677),
            Point2::new(-0.18745414104706304, -2.92138867851491),
            Point2::new(0.0, 0.0),
        ],
        vec![0.5, 1.066837707065448, 0.5],
    )
    .unwrap();
    let n = s.add_nurbs(nurbs).unwrap();
    let line = |a: [f64; 2], b: [f64; 2]| {
        BezierCurve2::try_new(vec![Point2::new(a[0], a[1]), Point2::new(b[0], b[1])]).unwrap()
    };
    let b1 = s
        .add_bezier(line(
            [-0.4725505327327804, -2.155848716708899],
            [-1.468901841222039, -0.009679303531416618],
        ))
        .unwrap();
    let b2 = s
        .add_bezier(line(
            [0.6251416727449193, -2.0308304815736213],
            [1.1634900487054083, 0.4563499451505765],
        ))
        .unwrap();
    let first = s
        .add_constraint(G1Join {
            first: b1,
            second: n,
            direction: Vector2::new(0.2374557118346763, 0.04379962614755181),
        })
        .unwrap();
    s.add_constraint(G1Join {
        first: b2,
        second: n,
        direction: Vector2::new(0.7831403765414345, 0.3915036225142956),
    })
    .unwrap();
    let saved = camber_sketch::file::to_json(&s).unwrap();
    for _ in 0..2 {
        match s.solve_all() {
            Err(Error::Cusp { constraint, speed }) => {
                assert_eq!(constraint, first);
                assert!(speed < 1e-12, "speed {speed}");
            }
            other => panic!("expected a cusp, got {other:?}"),
        }
        assert_eq!(camber_sketch::file::to_json(&s).unwrap(), saved);
    }
}
