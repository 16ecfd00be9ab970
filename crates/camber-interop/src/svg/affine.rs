//! Affine maps of the plane, x ↦ A·x + t, as SVG's `transform` attributes write them
//! (`matrix(a b c d e f)`: A = [[a, c], [b, d]], t = (e, f)), composed from the outermost group
//! inwards, and the y flip that puts an SVG picture upright in camber's y-up frame.

use nalgebra::{Matrix2, Point2, Vector2};

/// An affine map x ↦ A·x + t of the plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Affine {
    /// The linear part A.
    pub(crate) linear: Matrix2<f64>,
    /// The translation t.
    pub(crate) translation: Vector2<f64>,
}

impl Affine {
    /// The identity.
    pub(crate) fn identity() -> Self {
        Self {
            linear: Matrix2::identity(),
            translation: Vector2::zeros(),
        }
    }

    /// The y flip (x, y) ↦ (x, −y).
    pub(crate) fn flip_y() -> Self {
        Self {
            linear: Matrix2::new(1.0, 0.0, 0.0, -1.0),
            translation: Vector2::zeros(),
        }
    }

    /// The map of SVG's `matrix(a b c d e f)`: (x, y) ↦ (a·x + c·y + e, b·x + d·y + f).
    pub(crate) fn from_svg(t: &svgtypes::Transform) -> Self {
        Self {
            linear: Matrix2::new(t.a, t.c, t.b, t.d),
            translation: Vector2::new(t.e, t.f),
        }
    }

    /// `self ∘ inner`: first `inner`, then `self` (a group's map composed with its child's).
    pub(crate) fn then_inner(&self, inner: &Affine) -> Affine {
        Affine {
            linear: self.linear * inner.linear,
            translation: self.linear * inner.translation + self.translation,
        }
    }

    /// A·p + t.
    pub(crate) fn apply(&self, p: Point2<f64>) -> Point2<f64> {
        Point2::from(self.linear * p.coords + self.translation)
    }

    /// det A: negative for a map that reflects (turns counter-clockwise travel clockwise).
    pub(crate) fn determinant(&self) -> f64 {
        self.linear.determinant()
    }

    /// Whether every entry is finite.
    pub(crate) fn is_finite(&self) -> bool {
        self.linear
            .iter()
            .chain(self.translation.iter())
            .all(|v| v.is_finite())
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use std::str::FromStr;

    #[test]
    fn an_svg_matrix_maps_points_as_the_spec_writes_it() {
        let t = svgtypes::Transform::from_str("matrix(1 2 3 4 5 6)").unwrap();
        let m = Affine::from_svg(&t);
        // (x, y) = (1, 1): (1 + 3 + 5, 2 + 4 + 6).
        assert_eq!(m.apply(Point2::new(1.0, 1.0)), Point2::new(9.0, 12.0));
    }

    #[test]
    fn composition_applies_the_inner_map_first() {
        let outer = Affine {
            linear: Matrix2::new(0.0, -1.0, 1.0, 0.0),
            translation: Vector2::zeros(),
        };
        let inner = Affine {
            linear: Matrix2::identity(),
            translation: Vector2::new(1.0, 0.0),
        };
        // Translate (0, 0) to (1, 0), then rotate a quarter turn: (0, 1).
        let p = outer.then_inner(&inner).apply(Point2::origin());
        assert!((p - Point2::new(0.0, 1.0)).norm() < 1e-15);
        assert!(Affine::flip_y().determinant() < 0.0);
    }
}
