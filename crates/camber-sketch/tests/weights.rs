//! Point weights in the minimum-norm metric: a heavier point moves less, exactly as the
//! weighted least-move formula says, in solves and in drag sessions.

// Fixture helpers outside #[test] functions unwrap fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use camber_geom::BezierCurve2;
use camber_sketch::constraints::{Fixed, PointAtParameter};
use camber_sketch::{Error, PointRef, Sketch, Target};
use nalgebra::Point2;

/// A straight quadratic P0 = (0, 0), P1 = (1, 0), P2 = (2, 0) whose midpoint C(½) is pulled to
/// (1, 1): ¼ΔP0 + ½ΔP1 + ¼ΔP2 = (0, 1).
fn pulled_quadratic(weights: [f64; 3]) -> (Sketch, camber_sketch::EntityId) {
    let mut s = Sketch::new();
    let q = BezierCurve2::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 0.0),
        Point2::new(2.0, 0.0),
    ])
    .unwrap();
    let c = s.add_bezier(q).unwrap();
    for (i, w) in weights.into_iter().enumerate() {
        s.set_weight(PointRef::Control(c, i), w).unwrap();
    }
    s.add_constraint(PointAtParameter {
        curve: c,
        u: 0.5,
        target: Target::At(Point2::new(1.0, 1.0)),
    })
    .unwrap();
    (s, c)
}

#[test]
fn weighted_solve_matches_the_hand_derived_least_move() {
    // Minimise Σ wᵢ|ΔPᵢ|² subject to Σ bᵢΔPᵢ = d: ΔPᵢ = (bᵢ/wᵢ) d / Σ (bⱼ²/wⱼ).
    let weights = [2.0, 1.0, 8.0];
    let b = [0.25, 0.5, 0.25];
    let denominator: f64 = b.iter().zip(weights).map(|(b, w)| b * b / w).sum();
    let (mut s, c) = pulled_quadratic(weights);
    s.solve().unwrap();
    for i in 0..3 {
        let moved = s.point(PointRef::Control(c, i)).unwrap().y;
        assert_relative_eq!(moved, b[i] / weights[i] / denominator, epsilon = 1e-12);
    }
    // Equal weights give the unweighted answer: ΔPᵢ = bᵢ / Σ bⱼ².
    let (mut plain, c) = pulled_quadratic([3.0, 3.0, 3.0]);
    plain.solve().unwrap();
    assert_relative_eq!(
        plain.point(PointRef::Control(c, 1)).unwrap().y,
        0.5 / 0.375,
        epsilon = 1e-12
    );
}

#[test]
fn heavier_points_move_less_while_dragging() {
    // A cubic with P3 fixed; P1 is dragged. P0 and P2 share the move, P0 ten times heavier.
    let mut s = Sketch::new();
    let cubic = BezierCurve2::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 1.0),
        Point2::new(2.0, 1.0),
        Point2::new(3.0, 0.0),
    ])
    .unwrap();
    let c = s.add_bezier(cubic).unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(c, 3)))
        .unwrap();
    s.add_constraint(PointAtParameter {
        curve: c,
        u: 0.5,
        target: Target::At(Point2::new(1.5, 0.75)),
    })
    .unwrap();
    s.set_weight(PointRef::Control(c, 0), 10.0).unwrap();
    let mut drag = s.drag(PointRef::Control(c, 1)).unwrap();
    drag.update(Point2::new(1.2, 1.3)).unwrap();
    let p0 = drag.point(PointRef::Control(c, 0)).unwrap();
    let p2 = drag.point(PointRef::Control(c, 2)).unwrap();
    let moved0 = p0.coords.norm();
    let moved2 = (p2 - Point2::new(2.0, 1.0)).norm();
    assert!(
        moved0 > 0.0 && moved0 < moved2 / 5.0,
        "{moved0} vs {moved2}"
    );
}

#[test]
fn bad_weights_are_refused_and_change_nothing() {
    let (mut s, c) = pulled_quadratic([1.0, 1.0, 1.0]);
    for w in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let err = s.set_weight(PointRef::Control(c, 1), w).unwrap_err();
        assert!(
            matches!(err, Error::InvalidWeight { index: 1, .. }),
            "{err}"
        );
    }
    assert!(matches!(
        s.set_weight(PointRef::Control(c, 7), 2.0),
        Err(Error::UnknownPoint { index: 7, .. })
    ));
    s.solve().unwrap();
    assert_relative_eq!(
        s.point(PointRef::Control(c, 1)).unwrap().y,
        0.5 / 0.375,
        epsilon = 1e-12
    );
}
