//! A point on an ellipse stored by its blocks (see [`crate::ellipse_blocks`]): centre C,
//! a-axis vertex V, semi-axis b, and the point P. With w = V − C, a = |w|, d = P − C, the
//! point's frame coordinates are x′ = d·w/a and y′ = (w × d)/a, and
//!
//! g = ((x′/a)² + (y′/b)² − 1)·a·b/(a + b) = 0 (one row, length units).
//!
//! The implicit equation is scaled by ab/(a + b) so that g changes by between 2b/(a + b) and
//! 2a/(a + b) per unit of normal distance on the ellipse (|∇F| lies between 2/a and 2/b
//! there): a row in length units like the other kinds', smooth wherever a > 0 and b > 0 (an
//! ellipse with a zero semi-axis is refused). An elliptic arc holds both its ends on its
//! ellipse with two of these rows (owner [`ELLIPSE_ROW`]); the point-on-ellipse kind uses the
//! same row.
//!
//! ```
//! use camber_sketch::residuals::ellipse::OnEllipse;
//! use camber_solve::Residual;
//! let mut g = [0.0_f64];
//! // Centre (0, 0), vertex (2, 0), b = 1: the co-vertex (0, 1) is on it, (0, 2) is not.
//! OnEllipse.eval(&[&[0.0, 0.0][..], &[2.0, 0.0][..], &[1.0][..], &[0.0, 1.0][..]], &mut g);
//! assert!(g[0].abs() < 1e-15);
//! OnEllipse.eval(&[&[0.0, 0.0][..], &[2.0, 0.0][..], &[1.0][..], &[0.0, 2.0][..]], &mut g);
//! assert!((g[0] - 3.0 * 2.0 / 3.0).abs() < 1e-15);
//! ```

use camber_solve::{Residual, Scalar};

use crate::residuals::curve::{cross, dot, sub};

pub use crate::ground::ids::ELLIPSE_ROW;

/// g = ((x′/a)² + (y′/b)² − 1)·ab/(a + b) over the blocks [C, V, b, P] (see the module
/// documentation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OnEllipse;

/// g of the module documentation from the centre, the vertex, b and the point.
pub(crate) fn on_ellipse<T: Scalar>(c: &[T], v: &[T], b: T, p: &[T]) -> T {
    let (w, d) = (sub(v, c), sub(p, c));
    let a2 = dot(w, w);
    let a = a2.sqrt();
    // x′/a = d·w/a², y′/b = (w × d)/(a·b).
    let x = dot(d, w) / a2;
    let y = cross(w, d) / (a * b);
    (x * x + y * y - T::one()) * a * b / (a + b)
}

impl Residual for OnEllipse {
    fn name(&self) -> &str {
        "point on ellipse"
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2, 1, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = on_ellipse(x[0], x[1], x[2][0], x[3]);
    }
}
