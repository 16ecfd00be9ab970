//! The fit fuzz target: a point file's bytes (JSON, two columns, a Selig or Lednicer airfoil
//! file) → parse → fit to a tolerance, whole and split at the leading edge, under a small work
//! budget.
//!
//! The promises checked are listed on [`fit`].

use camber_geom::budget::Budget;
use camber_geom::fit::{fit_split, fit_to_tolerance_with, FitOptions, JointContinuity, SplitAt};
use camber_geom::queries::closest_point;
use nalgebra::Point2;

use crate::commands::fit::parse_point_file;

/// The work each fit may spend on one input (a few hundred trial fits of a small file).
pub const FIT_WORK: u64 = 200_000;

/// The most points fitted from one input (larger files are only parsed).
const MAX_FITTED: usize = 400;

/// Parses `data` as a point file and fits the points. Promises: the parser returns an error
/// or at least one point, all finite; a fit either fails with a typed error or is within its
/// tolerance, measured again here as the distance of sampled points to the curve; a split
/// fit's pieces meet at the joints' data points.
pub fn fit(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(points) = parse_point_file(text) else {
        return;
    };
    assert!(!points.is_empty(), "a parsed point file holds points");
    assert!(
        points.iter().all(|p| p.x.is_finite() && p.y.is_finite()),
        "a parsed point file holds finite points"
    );
    if points.len() > MAX_FITTED {
        return;
    }
    let size = points
        .iter()
        .fold(0.0_f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
    if !(size.is_finite() && size < 1e150) {
        return;
    }
    let tolerance = 1e-3 * (1.0 + size);
    let budget = Budget::default().with_max_work(FIT_WORK);
    let options = FitOptions::default();
    if let Ok(fit) = fit_to_tolerance_with(&points, tolerance, &options, &budget) {
        assert!(
            fit.max_error <= tolerance,
            "{} > {tolerance}",
            fit.max_error
        );
        check_within(&fit.curve, &points, tolerance);
    }
    let split = fit_split(
        &points,
        tolerance,
        &options,
        &SplitAt::LeadingEdge,
        JointContinuity::G1,
        &budget,
    );
    if let Ok(split) = split {
        assert!(split.max_error <= tolerance);
        assert_eq!(split.pieces.len(), split.joints.len() + 1);
        for (i, piece) in split.pieces.iter().enumerate() {
            let from = if i == 0 { 0 } else { split.joints[i - 1] };
            let to = split.joints.get(i).copied().unwrap_or(points.len() - 1);
            check_within(&piece.curve, &points[from..=to], tolerance);
        }
    }
}

/// Every seventh point within `tolerance` (and a rounding margin) of `curve`.
fn check_within(curve: &camber_geom::BSplineCurve2<f64>, points: &[Point2<f64>], tolerance: f64) {
    for q in points.iter().step_by(7) {
        if let Ok(foot) = closest_point(curve, q) {
            assert!(
                foot.distance <= tolerance * (1.0 + 1e-6) + 1e-12,
                "point {q:?} is {} from the fit, tolerance {tolerance}",
                foot.distance
            );
        }
    }
}
