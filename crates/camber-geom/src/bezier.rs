//! Bézier curves of any degree in D dimensions.

use nalgebra::Point;

use crate::curve::check_points;
use crate::errors::{Error, Result};
use crate::scalar::Scalar;

/// A Bézier curve C(t) = Σ B_{i,n}(t) P_i on t ∈ [0, 1], with n + 1 control points P_i.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierCurve<T: Scalar, const D: usize> {
    control_points: Vec<Point<T, D>>,
}

/// A planar Bézier curve.
pub type BezierCurve2<T> = BezierCurve<T, 2>;
/// A spatial Bézier curve.
pub type BezierCurve3<T> = BezierCurve<T, 3>;

/// # Construction
impl<T: Scalar, const D: usize> BezierCurve<T, D> {
    /// A Bézier curve of degree `control_points.len() − 1`: at least one control point, all
    /// coordinates finite.
    pub fn try_new(control_points: Vec<Point<T, D>>) -> Result<Self> {
        if control_points.is_empty() {
            return Err(Error::TooFewControlPoints {
                degree: 0,
                needed: 1,
                found: 0,
            });
        }
        check_points(&control_points)?;
        Ok(Self { control_points })
    }

    /// The control points P_0 … P_n.
    pub fn control_points(&self) -> &[Point<T, D>] {
        &self.control_points
    }

    /// The degree n (number of control points − 1).
    pub fn degree(&self) -> usize {
        self.control_points.len() - 1
    }
}
