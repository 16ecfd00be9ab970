//! Independent evaluations for the SVG import tests: SVG segments sampled by their own
//! definitions (de Casteljau for Béziers; arcs by picking, of the two centres through both
//! ends, the one whose sweep satisfies both flags), and camber entities sampled through the
//! kernel.
#![allow(dead_code)] // each test file uses a part
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

use camber_sketch::Entity;
use nalgebra::{Point2, Rotation2, Vector2};
use std::f64::consts::{PI, TAU};

/// B(t) by de Casteljau's repeated interpolation.
pub fn bezier(points: &[Point2<f64>], t: f64) -> Point2<f64> {
    let mut p: Vec<Point2<f64>> = points.to_vec();
    while p.len() > 1 {
        p = p.windows(2).map(|w| w[0] + (w[1] - w[0]) * t).collect();
    }
    p[0]
}

/// The SVG arc `A rx ry φ fA fS` from `from` to `to` as a function of t ∈ [0, 1], found
/// geometrically: in the frame where the ellipse is the unit circle, the centre lies on the
/// chord's perpendicular bisector at distance √(1 − h²) (h the half chord; radii scaled up when
/// h > 1); of the two candidates, the one whose sweep in the fS direction is larger than π
/// exactly when fA is set.
pub fn svg_arc(
    from: Point2<f64>,
    to: Point2<f64>,
    (rx, ry): (f64, f64),
    phi_degrees: f64,
    large: bool,
    sweep: bool,
) -> impl Fn(f64) -> Point2<f64> {
    let (rx, ry) = (rx.abs(), ry.abs());
    let rot = Rotation2::new(phi_degrees.to_radians());
    let to_unit = |p: Point2<f64>, rx: f64, ry: f64| {
        let q = rot.inverse() * p.coords;
        Vector2::new(q.x / rx, q.y / ry)
    };
    let (a0, b0) = (to_unit(from, rx, ry), to_unit(to, rx, ry));
    let half = (b0 - a0).norm() / 2.0;
    let scale = half.max(1.0);
    let (rx, ry) = (rx * scale, ry * scale);
    let (a, b) = (a0 / scale, b0 / scale);
    let mid = (a + b) / 2.0;
    let chord = b - a;
    let normal = Vector2::new(-chord.y, chord.x).normalize();
    let offset = (1.0 - (chord.norm() / 2.0).powi(2)).max(0.0).sqrt();
    let mut chosen = None;
    for side in [1.0, -1.0] {
        let c = mid + normal * (offset * side);
        let (ta, tb) = ((a - c).y.atan2((a - c).x), (b - c).y.atan2((b - c).x));
        let mut d = tb - ta;
        if sweep {
            while d <= 0.0 {
                d += TAU;
            }
        } else {
            while d >= 0.0 {
                d -= TAU;
            }
        }
        let big = d.abs() > PI + 1e-12;
        let half_turn = (d.abs() - PI).abs() <= 1e-9;
        if big == large || half_turn {
            chosen = Some((c, ta, d));
            break;
        }
    }
    let (c, ta, d) = chosen.unwrap();
    move |t: f64| {
        let th = ta + d * t;
        let u = c + Vector2::new(th.cos(), th.sin());
        Point2::from(rot * Vector2::new(u.x * rx, u.y * ry))
    }
}

/// The entity's point at t ∈ [0, 1] of its own parameter.
pub fn entity_point(e: &Entity, t: f64) -> Point2<f64> {
    match e {
        Entity::Line([a, b]) => a + (b - a) * t,
        Entity::Arc(_) => e.as_arc().unwrap().point(t),
        Entity::EllipticArc { .. } => e.as_elliptic_arc().unwrap().point_at(t),
        other => other.point_tangent(t).unwrap().0,
    }
}

/// The largest distance between the SVG curve `svg` mapped by `map` and the entity, over
/// `n` + 1 samples of each, the entity taken backwards when it runs against the path (its
/// start at the path's end).
pub fn max_deviation(
    e: &Entity,
    svg: impl Fn(f64) -> Point2<f64>,
    map: impl Fn(Point2<f64>) -> Point2<f64>,
    n: usize,
) -> f64 {
    let forward = (entity_point(e, 0.0) - map(svg(0.0))).norm();
    let backward = (entity_point(e, 1.0) - map(svg(0.0))).norm();
    let reversed = backward < forward;
    (0..=n)
        .map(|k| {
            let t = k as f64 / n as f64;
            let s = if reversed { 1.0 - t } else { t };
            (entity_point(e, s) - map(svg(t))).norm()
        })
        .fold(0.0, f64::max)
}

/// The entities of a sketch in id order.
pub fn entities(s: &camber_sketch::Sketch) -> Vec<Entity> {
    s.entities().map(|(_, e)| e.clone()).collect()
}

/// (x, y) ↦ (x, −y).
pub fn flip(p: Point2<f64>) -> Point2<f64> {
    Point2::new(p.x, -p.y)
}

pub fn p(x: f64, y: f64) -> Point2<f64> {
    Point2::new(x, y)
}
