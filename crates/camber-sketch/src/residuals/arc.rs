//! The arc's own row: an arc entity is stored by its blocks [C, S, E] (centre, start, end), and
//! its end must lie on the circle its centre and start make,
//!
//! g = |E − C| − |S − C| = 0 (one row, length units),
//!
//! smooth wherever the radius is not zero (an arc of radius zero is refused). The component
//! builder adds this row for every arc of the component (owned by [`ARC_ROW`]), so an arc has
//! 6 − 1 = 5 DOF: centre, radius, start and end angle.
//!
//! ```
//! use camber_sketch::residuals::arc::ArcEnds;
//! use camber_solve::Residual;
//! let mut g = [0.0_f64];
//! // Centre (0, 0), start (3, 0), end (0, 4): the end is 1 too far out.
//! ArcEnds.eval(&[&[0.0, 0.0][..], &[3.0, 0.0][..], &[0.0, 4.0][..]], &mut g);
//! assert!((g[0] - 1.0).abs() < 1e-15);
//! ```

use camber_solve::{Residual, Scalar};

use crate::residuals::curve::{dot, sub};

pub use crate::ground::ids::ARC_ROW;

/// |E − C| − |S − C| = 0 over the blocks [C, S, E] (see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArcEnds;

impl Residual for ArcEnds {
    fn name(&self) -> &str {
        "arc end on its circle"
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (s, e) = (sub(x[1], x[0]), sub(x[2], x[0]));
        out[0] = dot(e, e).sqrt() - dot(s, s).sqrt();
    }
}
