//! Every built-in residual's autodiff Jacobian against central differences
//! (camber_solve::testing), at random coefficients, directions and points.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber_sketch::residuals::{DirectionCross, LineTangency, PointCombination};
use camber_solve::testing::check_jacobian;
use proptest::prelude::*;

fn blocks(v: &[f64]) -> Vec<&[f64]> {
    v.chunks(2).collect()
}

proptest! {
    #[test]
    fn point_combination(
        coeffs in prop::collection::vec(-3.0..3.0_f64, 1..7),
        xs in prop::collection::vec(-5.0..5.0_f64, 14),
        target in prop::array::uniform2(-5.0..5.0_f64),
    ) {
        let n = coeffs.len();
        let r = PointCombination::new("combination", coeffs, target);
        let worst = check_jacobian(&r, &blocks(&xs[..2 * n]), 1e-6, 1e-7).unwrap();
        prop_assert!(worst.error < 1e-7);
    }

    #[test]
    fn direction_cross(
        coeffs in prop::collection::vec(-3.0..3.0_f64, 1..7),
        xs in prop::collection::vec(-5.0..5.0_f64, 14),
        d in prop::array::uniform2(-2.0..2.0_f64),
    ) {
        let n = coeffs.len();
        let r = DirectionCross::new("cross", coeffs, d);
        let worst = check_jacobian(&r, &blocks(&xs[..2 * n]), 1e-6, 1e-7).unwrap();
        prop_assert!(worst.error < 1e-7);
    }

    #[test]
    fn line_tangency(
        a in prop::collection::vec(-3.0..3.0_f64, 4),
        b in prop::collection::vec(-3.0..3.0_f64, 4),
        xs in prop::collection::vec(-5.0..5.0_f64, 8),
        origin in prop::array::uniform2(-5.0..5.0_f64),
        d in prop::array::uniform2(-2.0..2.0_f64),
    ) {
        let r = LineTangency::new(a, b, origin, d);
        let worst = check_jacobian(&r, &blocks(&xs), 1e-6, 1e-7).unwrap();
        prop_assert!(worst.error < 1e-7);
    }
}
