//! Whether a direction from an arc's centre falls within the arc's sweep, and by how much it
//! misses: the check after a solve of the kinds that put a point or a contact on an arc's
//! circle and need it on the arc itself (`point_on_arc`, `arc_touches_line`,
//! `arc_touches_circle`), and the same for a parametric angle of an elliptic arc
//! (`point_on_ellipse`, `ellipse_touches_line`).

use camber_geom::{CircularArc, EllipticArc};
use nalgebra::Vector2;

/// How far (radians) the direction `w` from the centre of `arc` lies outside its sweep, or
/// `None` when it lies within it up to `penetration` (length units) along the circle.
pub(crate) fn outside_sweep(
    arc: &CircularArc<f64>,
    w: Vector2<f64>,
    penetration: f64,
) -> Option<f64> {
    let angle = w.y.atan2(w.x);
    let tolerance = penetration / arc.radius() + 1e-12;
    if arc.contains_angle(angle, tolerance) {
        return None;
    }
    // How far past the nearer end.
    let d = (angle - arc.start_angle()).rem_euclid(std::f64::consts::TAU);
    Some((d - arc.sweep()).min(std::f64::consts::TAU - d))
}

/// How far (radians of the parametric angle) `angle` lies outside the sweep of the elliptic
/// `arc`, or `None` when it lies within it up to `penetration` (length units, taken over the
/// smaller semi-axis).
pub(crate) fn outside_elliptic_sweep(
    arc: &EllipticArc<f64>,
    angle: f64,
    penetration: f64,
) -> Option<f64> {
    let e = arc.ellipse();
    let tolerance = penetration / e.semi_axis_a().min(e.semi_axis_b()) + 1e-12;
    if arc.contains_angle(angle, tolerance) {
        return None;
    }
    // How far past the nearer end.
    let d = (angle - arc.start_angle()).rem_euclid(std::f64::consts::TAU);
    Some((d - arc.sweep()).min(std::f64::consts::TAU - d))
}
