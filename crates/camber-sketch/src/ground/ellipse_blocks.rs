//! Ellipses and elliptic arcs as sketch blocks.
//!
//! An ellipse entity ([`Entity::Ellipse`](crate::Entity::Ellipse)) is stored by two point
//! blocks [C, V] and one scalar block b: the centre C, the vertex V = C + a·u at the end of its
//! a-axis (so a = |V − C| and the rotation θ = atan2(V − C)), and the semi-axis b along
//! v = (−u_y, u_x). That is 2 + 2 + 1 = 5 unknowns and no row of its own: 5 DOF.
//!
//! An elliptic arc ([`Entity::EllipticArc`](crate::Entity::EllipticArc)) adds its end points:
//! blocks [C, V, S, E] and b. Its start and end parametric angles are read from where S and E
//! lie, φ = atan2(y′/b, x′/a) in the ellipse's frame, and it runs counter-clockwise from S to E
//! like a circular arc. Two rows of its own ([`crate::residuals::ellipse`]) hold S and E on
//! the ellipse, so it has 9 − 2 = 7 DOF: centre, semi-axes, rotation, two angles. Its ends are
//! point blocks, so every kind that reads a point reads them.
//!
//! ```
//! use camber_sketch::ellipse_blocks::{elliptic_arc_of_blocks, elliptic_arc_blocks};
//! use camber_geom::EllipticArc;
//! use nalgebra::Point2;
//! let arc = EllipticArc::try_new(Point2::new(1.0, 0.0), 2.0, 1.0, 0.5, 0.2, 2.0)?;
//! let (points, b) = elliptic_arc_blocks(&arc);
//! let back = elliptic_arc_of_blocks(&points, b)?;
//! assert!((back.sweep() - 1.8).abs() < 1e-14 && (back.ellipse().rotation() - 0.5).abs() < 1e-15);
//! # Ok::<(), camber_geom::Error>(())
//! ```

use camber_geom::{Ellipse, EllipticArc};
use nalgebra::{Point2, Vector2};

/// The ellipse of the blocks [C, V] and semi-axis b: a = |V − C|, rotation atan2(V − C).
///
/// # Errors
/// The kernel's: [`camber_geom::Error::NonPositiveSemiAxis`] for V = C (axis "a", 0) or
/// b ≤ 0, [`camber_geom::Error::NonFinite`] for a non-finite value.
pub fn ellipse_of_blocks(
    points: &[Point2<f64>; 2],
    b: f64,
) -> std::result::Result<Ellipse<f64>, camber_geom::Error> {
    let [c, v] = points;
    let w = v - c;
    Ellipse::try_new(*c, w.norm(), b, w.y.atan2(w.x))
}

/// The elliptic arc of the blocks [C, V, S, E] and semi-axis b: the ellipse of [C, V] and b,
/// from the parametric angle of S counter-clockwise to that of E.
///
/// # Errors
/// Those of [`ellipse_of_blocks`]; [`camber_geom::Error::ZeroLength`] when S or E lies at the
/// centre (it has no angle); [`camber_geom::Error::DegenerateSweep`] when S and E have one
/// angle.
pub fn elliptic_arc_of_blocks(
    points: &[Point2<f64>; 4],
    b: f64,
) -> std::result::Result<EllipticArc<f64>, camber_geom::Error> {
    let [c, v, s, e] = points;
    let ellipse = ellipse_of_blocks(&[*c, *v], b)?;
    if (s - c).norm_squared() <= 0.0 || (e - c).norm_squared() <= 0.0 {
        return Err(camber_geom::Error::ZeroLength {
            what: "elliptic arc's end from its centre",
        });
    }
    ellipse.arc(ellipse.angle_of(s), ellipse.angle_of(e))
}

/// The parametric angle atan2(y′/b, x′/a) ∈ (−π, π] of the point `p` in the frame of the
/// ellipse of blocks [C, V] and b (x′ = (p − C)·u, y′ = u × (p − C), u = (V − C)/a): for a
/// point on the ellipse, the φ with E(φ) = p.
pub fn frame_angle(c: &Point2<f64>, v: &Point2<f64>, b: f64, p: &Point2<f64>) -> f64 {
    let (w, d) = (v - c, p - c);
    let a2 = w.norm_squared();
    // x′/a = d·w/a², y′/b = (w × d)/(a·b).
    let x = d.dot(&w) / a2;
    let y = (w.x * d.y - w.y * d.x) / (a2.sqrt() * b);
    y.atan2(x)
}

/// The blocks [C, V] and b of an ellipse (V = C + a·u).
pub fn ellipse_blocks(e: &Ellipse<f64>) -> ([Point2<f64>; 2], f64) {
    let (u, _) = e.axes();
    (
        [*e.center(), e.center() + u * e.semi_axis_a()],
        e.semi_axis_b(),
    )
}

/// The blocks [C, V, S, E] and b of an elliptic arc.
pub fn elliptic_arc_blocks(arc: &EllipticArc<f64>) -> ([Point2<f64>; 4], f64) {
    let ([c, v], b) = ellipse_blocks(arc.ellipse());
    ([c, v, arc.start_point(), arc.end_point()], b)
}

/// The corners C ± (h_x, ±h_y) of the ellipse's axis-aligned bounding box, with
/// h_x = √(a² cos² θ + b² sin² θ) and h_y = √(a² sin² θ + b² cos² θ): points whose hull holds
/// the ellipse (and every arc of it).
pub(crate) fn box_corners(e: &Ellipse<f64>) -> Vec<Point2<f64>> {
    let (a, b, t) = (e.semi_axis_a(), e.semi_axis_b(), e.rotation());
    let (s, c) = (t.sin(), t.cos());
    let hx = (a * a * c * c + b * b * s * s).sqrt();
    let hy = (a * a * s * s + b * b * c * c).sqrt();
    let m = e.center();
    [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
        .iter()
        .map(|(x, y)| m + Vector2::new(x * hx, y * hy))
        .collect()
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use camber_geom::ParametricCurve;

    #[test]
    fn the_bounding_box_touches_the_ellipse_and_holds_it() {
        let e = Ellipse::try_new(Point2::new(1.0, -2.0), 3.0, 1.0, 0.7).unwrap();
        let corners = box_corners(&e);
        let (lo, hi) = (corners[0], corners[2]);
        let (mut min, mut max) = (
            Point2::new(f64::MAX, f64::MAX),
            Point2::new(f64::MIN, f64::MIN),
        );
        for k in 0..=20_000 {
            let p = e
                .point(std::f64::consts::TAU * f64::from(k) / 20_000.0)
                .unwrap();
            assert!(p.x >= lo.x - 1e-12 && p.y >= lo.y - 1e-12);
            assert!(p.x <= hi.x + 1e-12 && p.y <= hi.y + 1e-12);
            min = Point2::new(min.x.min(p.x), min.y.min(p.y));
            max = Point2::new(max.x.max(p.x), max.y.max(p.y));
        }
        assert!((min - lo).norm() < 1e-6 && (max - hi).norm() < 1e-6);
    }

    #[test]
    fn blocks_with_an_end_at_the_centre_or_no_axis_are_refused() {
        let c = Point2::new(0.0, 0.0);
        assert_eq!(
            ellipse_of_blocks(&[c, c], 1.0),
            Err(camber_geom::Error::NonPositiveSemiAxis {
                axis: "a",
                value: 0.0
            })
        );
        let v = Point2::new(2.0, 0.0);
        assert_eq!(
            ellipse_of_blocks(&[c, v], -1.0),
            Err(camber_geom::Error::NonPositiveSemiAxis {
                axis: "b",
                value: -1.0
            })
        );
        assert!(matches!(
            elliptic_arc_of_blocks(&[c, v, c, Point2::new(0.0, 1.0)], 1.0),
            Err(camber_geom::Error::ZeroLength { .. })
        ));
        assert!(matches!(
            elliptic_arc_of_blocks(&[c, v, v, v], 1.0),
            Err(camber_geom::Error::DegenerateSweep { .. })
        ));
    }
}
