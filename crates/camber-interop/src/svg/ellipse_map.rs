//! The image of an ellipse under an affine map, and the camber entity of a mapped arc.
//!
//! An ellipse c + K·(cos θ, sin θ) maps under x ↦ A·x + t to the ellipse
//! (A·c + t) + (A·K)·(cos θ, sin θ), since an affine map of an ellipse is an ellipse. Its
//! semi-axes are the singular values σ₁ ≥ σ₂ of the 2×2 matrix M = A·K, and its a-axis is the
//! left singular vector of σ₁: the eigenvector of M·Mᵀ = [[p, q], [q, r]] for its larger
//! eigenvalue σ₁² = (p + r)/2 + √(((p − r)/2)² + q²), at the angle ½·atan2(2q, p − r);
//! σ₂ = |det M|/σ₁. M is scaled by its largest entry first, so no square overflows. The map
//! turns the traversal θ ↑ counter-clockwise when det M > 0 and clockwise when det M < 0 (a
//! reflection), which decides which mapped end a counter-clockwise camber arc starts at.

use nalgebra::{Matrix2, Point2, Rotation2, Vector2};

use super::affine::Affine;
use super::arc::CentreArc;

/// Radii within this fraction of each other make a circle (their ratio after a transform that
/// keeps circles round differs from 1 by rounding only).
pub const CIRCLE_TOLERANCE: f64 = 1e-9;

/// An ellipse in the sketch's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct MappedEllipse {
    /// The centre.
    pub(crate) centre: Point2<f64>,
    /// The semi-axis a (≥ b), along `a_axis`.
    pub(crate) a: f64,
    /// The semi-axis b.
    pub(crate) b: f64,
    /// The unit direction of the a-axis.
    pub(crate) a_axis: Vector2<f64>,
    /// det M: the sign says whether θ ↑ runs counter-clockwise (> 0) in the sketch.
    pub(crate) determinant: f64,
}

impl MappedEllipse {
    /// Whether the semi-axes are equal within [`CIRCLE_TOLERANCE`].
    pub(crate) fn is_circle(&self) -> bool {
        self.a - self.b <= CIRCLE_TOLERANCE * self.a
    }
}

/// The image under `map` of the ellipse c + R(φ)·diag(rx, ry)·(cos θ, sin θ); `None` when the
/// image is not a proper ellipse (a singular map, numbers out of range).
pub(crate) fn map_ellipse(
    map: &Affine,
    centre: Point2<f64>,
    rx: f64,
    ry: f64,
    rotation: f64,
) -> Option<MappedEllipse> {
    let k = map.linear * Rotation2::new(rotation).matrix() * Matrix2::new(rx, 0.0, 0.0, ry);
    let scale = k.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    if !(scale.is_finite() && scale > 0.0) {
        return None;
    }
    let m = k / scale;
    let mmt = m * m.transpose();
    let (p, q, r) = (mmt[(0, 0)], mmt[(0, 1)], mmt[(1, 1)]);
    let largest = (p + r) / 2.0 + ((p - r) / 2.0).hypot(q);
    let s1 = largest.sqrt();
    let det = m.determinant();
    let s2 = det.abs() / s1;
    let angle = (2.0 * q).atan2(p - r) / 2.0;
    let out = MappedEllipse {
        centre: map.apply(centre),
        a: scale * s1,
        b: scale * s2,
        a_axis: Vector2::new(angle.cos(), angle.sin()),
        determinant: det,
    };
    let finite = [out.centre.x, out.centre.y, out.a, out.b]
        .iter()
        .all(|v| v.is_finite());
    (finite && out.b > 0.0).then_some(out)
}

/// The image of an SVG arc under `map`: its ellipse and whether the camber arc (which runs
/// counter-clockwise) runs against the path, from the path's end to its start.
pub(crate) fn map_arc(map: &Affine, arc: &CentreArc) -> Option<(MappedEllipse, bool)> {
    let e = map_ellipse(map, arc.centre, arc.rx, arc.ry, arc.rotation)?;
    let counter_clockwise = (arc.sweep > 0.0) == (e.determinant > 0.0);
    Some((e, !counter_clockwise))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use std::f64::consts::FRAC_PI_6;

    fn linear(a: f64, b: f64, c: f64, d: f64) -> Affine {
        Affine {
            linear: Matrix2::new(a, b, c, d),
            translation: Vector2::new(1.0, 2.0),
        }
    }

    #[test]
    fn a_circle_under_a_rotation_stays_a_circle_of_the_same_radius() {
        let (s, c) = FRAC_PI_6.sin_cos();
        let e = map_ellipse(&linear(c, -s, s, c), Point2::new(3.0, 0.0), 2.0, 2.0, 0.4).unwrap();
        assert!(e.is_circle() && (e.a - 2.0).abs() < 1e-15 && e.determinant > 0.0);
        assert!((e.centre - Point2::new(1.0 + 3.0 * c, 2.0 + 3.0 * s)).norm() < 1e-15);
    }

    #[test]
    fn a_non_uniform_scale_stretches_the_circle_along_x() {
        let e = map_ellipse(&linear(3.0, 0.0, 0.0, 1.0), Point2::origin(), 2.0, 2.0, 0.0).unwrap();
        assert!(!e.is_circle());
        assert!((e.a - 6.0).abs() < 1e-15 && (e.b - 2.0).abs() < 1e-15);
        assert!((e.a_axis.x.abs() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn mapped_axes_hold_every_mapped_point_of_a_skewed_ellipse() {
        // The implicit equation of the image in its own frame, checked at mapped samples.
        let map = linear(1.0, 0.7, -0.2, 1.3);
        let e = map_ellipse(&map, Point2::new(1.0, -1.0), 3.0, 1.0, 0.3).unwrap();
        let v = Vector2::new(-e.a_axis.y, e.a_axis.x);
        for k in 0..64 {
            let t = f64::from(k) * 0.1;
            let p =
                Point2::new(1.0, -1.0) + Rotation2::new(0.3) * Vector2::new(3.0 * t.cos(), t.sin());
            let d = map.apply(p) - e.centre;
            let (x, y) = (d.dot(&e.a_axis) / e.a, d.dot(&v) / e.b);
            assert!(
                (x * x + y * y - 1.0).abs() < 1e-13,
                "{t}: {}",
                x * x + y * y
            );
        }
    }

    #[test]
    fn a_reflection_reverses_the_arc_and_a_singular_map_gives_none() {
        let arc = CentreArc {
            centre: Point2::origin(),
            rx: 1.0,
            ry: 1.0,
            rotation: 0.0,
            start_angle: 0.0,
            sweep: 1.0,
        };
        assert!(!map_arc(&Affine::identity(), &arc).unwrap().1);
        assert!(map_arc(&Affine::flip_y(), &arc).unwrap().1);
        assert!(
            map_ellipse(&linear(1.0, 2.0, 2.0, 4.0), Point2::origin(), 1.0, 1.0, 0.0).is_none()
        );
    }
}
