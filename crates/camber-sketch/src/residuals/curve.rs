//! What residuals over a curve share: where the contact parameter comes from ([`Param`]), the
//! curve's point and tangent read from the leading blocks, the blocks a residual at a free
//! parameter depends on, and small vector helpers in the scalar type.
//!
//! A residual over a curve reads the curve's control-point blocks first, then, when the
//! parameter is free ([`Param::Block`]), a block of one holding u, then the blocks of whatever
//! else it relates the curve to.

use camber_solve::scalar::cst;
use camber_solve::Scalar;

use crate::curve_eval::CurveBasis;

/// Where a curve residual takes its parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Param {
    /// A fixed parameter value.
    Fixed(f64),
    /// The block after the control points holds u (an unknown).
    Block,
}

/// The block lengths of a curve read with its parameter: one point block (2) per control point
/// the basis reads, then the block of u when it is free.
pub(crate) fn curve_block_sizes(basis: &CurveBasis, u: Param) -> Vec<usize> {
    let mut sizes = vec![2; basis.count()];
    if u == Param::Block {
        sizes.push(1);
    }
    sizes
}

/// C(u) and C′(u) from the first blocks, and the index of the next block.
pub(crate) fn curve_at<T: Scalar>(
    basis: &CurveBasis,
    u: Param,
    x: &[&[T]],
) -> ([T; 2], [T; 2], usize) {
    let n = basis.count();
    let (uu, next) = match u {
        Param::Fixed(v) => (cst::<T>(v), n),
        Param::Block => (x.get(n).map_or(T::zero(), |b| b[0]), n + 1),
    };
    let (c, c1) = basis.eval(x, uu);
    (c, c1, next)
}

/// Clears the flags of the curve's control-point blocks (the first `basis.count()`) outside
/// the knot span of a free parameter u (read from the block after them); returns the index of
/// the block after the curve's (and u's).
pub(crate) fn curve_support(
    basis: &CurveBasis,
    u: Param,
    x: &[&[f64]],
    blocks: &mut [bool],
) -> usize {
    let n = basis.count();
    match u {
        Param::Fixed(_) => n,
        Param::Block => {
            if let Some(uu) = x.get(n).and_then(|b| b.first()) {
                let keep = basis.support(*uu);
                for (j, flag) in blocks.iter_mut().enumerate().take(n) {
                    if !keep.contains(&j) {
                        *flag = false;
                    }
                }
            }
            n + 1
        }
    }
}

/// a_x·b_y − a_y·b_x.
pub(crate) fn cross<T: Scalar>(a: [T; 2], b: [T; 2]) -> T {
    a[0] * b[1] - a[1] * b[0]
}

/// a·b.
pub(crate) fn dot<T: Scalar>(a: [T; 2], b: [T; 2]) -> T {
    a[0] * b[0] + a[1] * b[1]
}

/// a − b for two blocks of two.
pub(crate) fn sub<T: Scalar>(a: &[T], b: &[T]) -> [T; 2] {
    [a[0] - b[0], a[1] - b[1]]
}

/// κ = cross(C′, C″)/|C′|³, the signed curvature from [C, C′, C″].
pub(crate) fn curvature<T: Scalar>(c: [[T; 2]; 3]) -> T {
    let speed2 = dot(c[1], c[1]);
    cross(c[1], c[2]) / (speed2 * speed2.sqrt())
}
