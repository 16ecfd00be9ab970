//! Rational Bézier pieces of every curve kind, for searches that subdivide: each piece knows
//! its parameter interval on the curve, its homogeneous control points and the bounding box of
//! its projected control points, which contains the piece (all weights are positive, so each
//! point of the piece is a convex combination of the projected control points).
//!
//! Segments and circles become curves here too: a segment is parameterized by t ∈ [0, 1]
//! from its start to its end, a circle by its angle θ ∈ [0, 2π] counter-clockwise from +x.

use nalgebra::{Point, Point2, SVector, Vector2};

use crate::bezier::BezierCurve;
use crate::bspline::BSplineCurve;
use crate::curve::{check_parameter, ParametricCurve};
use crate::errors::Result;
use crate::hermite::HermiteCurve;
use crate::nurbs::NurbsCurve;
use crate::primitives::{Circle, Segment};
use crate::scalar::Scalar;

/// One rational Bézier piece: C(s) for s ∈ [start, end] of the curve's parameter is the
/// projection of Σ B_{i,n}(t) (w_i P_i, w_i), with t mapping [start, end] onto [0, 1] (exactly
/// linearly for polynomial and NURBS pieces; monotonically for circle quarters).
#[derive(Debug, Clone, PartialEq)]
pub struct RationalPiece<const D: usize> {
    /// Start of the piece's parameter interval on its curve.
    pub start: f64,
    /// End of the piece's parameter interval.
    pub end: f64,
    /// Homogeneous control points, D + 1 values each: (w·P, w).
    pub homogeneous: Vec<f64>,
}

impl<const D: usize> RationalPiece<D> {
    /// A piece from Euclidean control points and their weights.
    pub fn new(start: f64, end: f64, points: &[Point<f64, D>], weights: &[f64]) -> Self {
        let mut homogeneous = Vec::with_capacity(points.len() * (D + 1));
        for (p, &w) in points.iter().zip(weights) {
            homogeneous.extend(p.coords.iter().map(|&c| c * w));
            homogeneous.push(w);
        }
        Self {
            start,
            end,
            homogeneous,
        }
    }

    /// The projected control points.
    pub fn points(&self) -> impl Iterator<Item = SVector<f64, D>> + '_ {
        self.homogeneous
            .chunks_exact(D + 1)
            .map(|c| SVector::<f64, D>::from_fn(|i, _| c[i] / c[D]))
    }

    /// The bounding box (min, max) of the projected control points; it contains the piece.
    pub fn bounding_box(&self) -> (SVector<f64, D>, SVector<f64, D>) {
        let mut lo = SVector::<f64, D>::repeat(f64::INFINITY);
        let mut hi = SVector::<f64, D>::repeat(f64::NEG_INFINITY);
        for p in self.points() {
            lo = lo.inf(&p);
            hi = hi.sup(&p);
        }
        (lo, hi)
    }

    /// The first and last control points, which lie on the curve.
    pub fn end_points(&self) -> (SVector<f64, D>, SVector<f64, D>) {
        let mut it = self.points();
        let first = it.next().unwrap_or_else(SVector::zeros);
        let last = it.last().unwrap_or(first);
        (first, last)
    }

    /// The two halves at t = 1/2 (de Casteljau on the homogeneous points).
    pub fn halves(&self) -> (Self, Self) {
        let dim = D + 1;
        let count = self.homogeneous.len() / dim;
        let mut column = self.homogeneous.clone();
        let mut left = Vec::with_capacity(column.len());
        let mut right = Vec::with_capacity(column.len());
        left.extend_from_slice(&column[..dim]);
        right.extend_from_slice(&column[(count - 1) * dim..]);
        for round in 1..count {
            let top = count - round;
            for i in 0..top {
                for c in 0..dim {
                    column[i * dim + c] = 0.5 * (column[i * dim + c] + column[(i + 1) * dim + c]);
                }
            }
            left.extend_from_slice(&column[..dim]);
            right.extend_from_slice(&column[(top - 1) * dim..top * dim]);
        }
        // `right` was gathered from the last point inwards.
        let mut ordered = Vec::with_capacity(right.len());
        for chunk in right.chunks_exact(dim).rev() {
            ordered.extend_from_slice(chunk);
        }
        let mid = 0.5 * (self.start + self.end);
        (
            Self {
                start: self.start,
                end: mid,
                homogeneous: left,
            },
            Self {
                start: mid,
                end: self.end,
                homogeneous: ordered,
            },
        )
    }
}

/// Curves that can be cut into rational Bézier pieces.
pub trait BezierPieces<const D: usize>: ParametricCurve<f64, D> {
    /// The pieces, in parameter order, covering the whole domain.
    fn bezier_pieces(&self) -> Vec<RationalPiece<D>>;
}

impl<const D: usize> BezierPieces<D> for BezierCurve<f64, D> {
    fn bezier_pieces(&self) -> Vec<RationalPiece<D>> {
        let weights = vec![1.0; self.control_points().len()];
        vec![RationalPiece::new(
            0.0,
            1.0,
            self.control_points(),
            &weights,
        )]
    }
}

impl<const D: usize> BezierPieces<D> for BSplineCurve<f64, D> {
    fn bezier_pieces(&self) -> Vec<RationalPiece<D>> {
        self.to_bezier_segments()
            .into_iter()
            .map(|(a, b, piece)| {
                let weights = vec![1.0; piece.control_points().len()];
                RationalPiece::new(a, b, piece.control_points(), &weights)
            })
            .collect()
    }
}

impl<const D: usize> BezierPieces<D> for NurbsCurve<f64, D> {
    fn bezier_pieces(&self) -> Vec<RationalPiece<D>> {
        self.to_bezier_segments()
            .into_iter()
            .map(|(a, b, piece)| RationalPiece::new(a, b, piece.control_points(), piece.weights()))
            .collect()
    }
}

impl<const D: usize> BezierPieces<D> for HermiteCurve<f64, D> {
    fn bezier_pieces(&self) -> Vec<RationalPiece<D>> {
        match self.to_bezier() {
            Ok(b) => b.bezier_pieces(),
            Err(_) => Vec::new(),
        }
    }
}

impl<T: Scalar> ParametricCurve<T, 2> for Segment<T> {
    /// [0, 1], from the start to the end.
    fn domain(&self) -> (T, T) {
        (T::zero(), T::one())
    }

    fn derivatives_into(&self, u: T, out: &mut [SVector<T, 2>]) -> Result<()> {
        check_parameter(u, (T::zero(), T::one()))?;
        for (k, slot) in out.iter_mut().enumerate() {
            *slot = match k {
                0 => self.point_at(u).coords,
                1 => self.direction(),
                _ => Vector2::zeros(),
            };
        }
        Ok(())
    }
}

impl BezierPieces<2> for Segment<f64> {
    fn bezier_pieces(&self) -> Vec<RationalPiece<2>> {
        vec![RationalPiece::new(
            0.0,
            1.0,
            &[*self.start(), *self.end()],
            &[1.0, 1.0],
        )]
    }
}

impl<T: Scalar> ParametricCurve<T, 2> for Circle<T> {
    /// [0, 2π]: the angle from +x, counter-clockwise.
    fn domain(&self) -> (T, T) {
        (T::zero(), T::two_pi())
    }

    /// The k-th derivative with respect to the angle is r·(cos(θ + kπ/2), sin(θ + kπ/2)).
    fn derivatives_into(&self, u: T, out: &mut [SVector<T, 2>]) -> Result<()> {
        check_parameter(u, (T::zero(), T::two_pi()))?;
        let (s, c) = (u.sin(), u.cos());
        for (k, slot) in out.iter_mut().enumerate() {
            let (x, y) = match k % 4 {
                0 => (c, s),
                1 => (-s, c),
                2 => (-c, -s),
                _ => (s, -c),
            };
            *slot = Vector2::new(x, y) * self.radius();
            if k == 0 {
                *slot += self.center().coords;
            }
        }
        Ok(())
    }

    /// The quarter angles, where the rational pieces join.
    fn breakpoints(&self) -> Vec<T> {
        (0..=4)
            .map(|k| T::frac_pi_2() * crate::scalar::from_usize::<T>(k))
            .collect()
    }
}

impl BezierPieces<2> for Circle<f64> {
    /// Four rational quadratic quarters, (1, 1/√2, 1) weights, over the quarter angles.
    fn bezier_pieces(&self) -> Vec<RationalPiece<2>> {
        let (c, r) = (*self.center(), self.radius());
        let w = std::f64::consts::FRAC_1_SQRT_2;
        let corner = |x: f64, y: f64| Point2::new(c.x + r * x, c.y + r * y);
        let quarter = std::f64::consts::FRAC_PI_2;
        let dirs = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0), (1.0, 0.0)];
        (0..4)
            .map(|k| {
                let (a, b) = (dirs[k], dirs[k + 1]);
                let pts = [
                    corner(a.0, a.1),
                    corner(a.0 + b.0, a.1 + b.1),
                    corner(b.0, b.1),
                ];
                let start = quarter * k as f64;
                RationalPiece::new(start, start + quarter, &pts, &[1.0, w, 1.0])
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn halves_of_a_quadratic_by_hand() {
        let piece = RationalPiece::<2>::new(
            0.0,
            2.0,
            &[
                Point2::new(0.0, 0.0),
                Point2::new(1.0, 2.0),
                Point2::new(2.0, 0.0),
            ],
            &[1.0, 1.0, 1.0],
        );
        let (l, r) = piece.halves();
        let lp: Vec<_> = l.points().collect();
        let rp: Vec<_> = r.points().collect();
        assert_eq!(lp[1], Vector2::new(0.5, 1.0));
        assert_eq!(lp[2], Vector2::new(1.0, 1.0));
        assert_eq!(rp[0], Vector2::new(1.0, 1.0));
        assert_eq!(rp[2], Vector2::new(2.0, 0.0));
        assert!((l.end - 1.0).abs() < 1e-15 && (r.start - 1.0).abs() < 1e-15);
    }

    #[test]
    fn circle_quarters_lie_on_the_circle() {
        let circle = Circle::try_new(Point2::new(1.0, -1.0), 2.0).unwrap();
        for piece in circle.bezier_pieces() {
            let (a, b) = piece.end_points();
            assert!(((a - Vector2::new(1.0, -1.0)).norm() - 2.0).abs() < 1e-15);
            assert!(((b - Vector2::new(1.0, -1.0)).norm() - 2.0).abs() < 1e-15);
            let (l, _) = piece.halves();
            let (_, mid) = l.end_points();
            assert!(((mid - Vector2::new(1.0, -1.0)).norm() - 2.0).abs() < 1e-14);
        }
    }
}
