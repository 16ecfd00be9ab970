//! What residuals over a curve share: where the contact parameter comes from ([`Param`]), the
//! curve's point and tangent read from the leading blocks, the blocks a residual at a free
//! parameter depends on, and small vector helpers in the scalar type.
//!
//! A residual over a curve reads the curve's control-point blocks first, then, when the
//! parameter is free ([`Param::Block`]), a block of one holding u, then the blocks of whatever
//! else it relates the curve to.
//!
//! Such a residual is a small function f of the curve's point and derivatives at u (and of the
//! other blocks' values): `Blocks` writes those inputs with their exact derivatives in floats
//! into a [`camber_solve::derive::composed::InnerMap`], so that the solver's Jacobians and Hessians
//! differentiate only f by dual numbers ([`camber_solve::derive::composed`]); `ComposedCurve`
//! names such a residual and gives it both structured derivatives.

use std::ops::RangeInclusive;

use camber_solve::derive::composed::{self, InnerMap, Outer};
use camber_solve::scalar::cst;
use camber_solve::Scalar;
use smallvec::SmallVec;

use crate::ground::curve_eval::CurveBasis;

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

/// A curve residual written as g = f(y(x)): a small outer function f ([`Outer`]) of a few
/// inputs y that its inner map gives, with their derivatives, from the blocks (a curve's point
/// and derivatives at a parameter, a circle's centre and radius). Its structured derivatives
/// are [`composed_jacobian`] and [`composed_hessian`].
pub(crate) trait ComposedCurve: Outer {
    /// Writes the inputs y and their derivatives into `map`; `None` when the blocks do not
    /// have the shape the residual reads.
    fn inner(&self, blocks: &Blocks<'_>, map: &mut InnerMap) -> Option<()>;
}

/// [`camber_solve::Residual::structured_jacobian`] of a [`ComposedCurve`] residual.
pub(crate) fn composed_jacobian<R: ComposedCurve>(
    residual: &R,
    x: &[&[f64]],
    active: &[bool],
    values: &mut [f64],
    jac: &mut [f64],
) -> bool {
    let Some(blocks) = Blocks::new(x, active) else {
        return false;
    };
    let mut map = blocks.map();
    residual.inner(&blocks, &mut map).is_some() && composed::jacobian(residual, &map, values, jac)
}

/// [`camber_solve::Residual::structured_hessian`] of a [`ComposedCurve`] residual.
pub(crate) fn composed_hessian<R: ComposedCurve>(
    residual: &R,
    x: &[&[f64]],
    weights: &[f64],
    active: &[bool],
    out: &mut [f64],
) -> bool {
    let Some(blocks) = Blocks::new(x, active) else {
        return false;
    };
    let mut map = blocks.map();
    residual.inner(&blocks, &mut map).is_some()
        && composed::weighted_hessian(residual, &map, weights, out)
}

/// The blocks of a residual seen by its inner map ([`InnerMap`]): the values, which blocks
/// move, and where each block's first column is among all the residual's columns.
pub(crate) struct Blocks<'a> {
    x: &'a [&'a [f64]],
    active: &'a [bool],
    offsets: SmallVec<[usize; 16]>,
}

impl<'a> Blocks<'a> {
    /// The blocks `x` with their `active` flags (one per block); `None` when the counts differ.
    pub(crate) fn new(x: &'a [&'a [f64]], active: &'a [bool]) -> Option<Self> {
        if x.len() != active.len() {
            return None;
        }
        let mut offsets = SmallVec::new();
        let mut at = 0;
        for b in x {
            offsets.push(at);
            at += b.len();
        }
        Some(Self { x, active, offsets })
    }

    /// An empty inner map over all the blocks' columns.
    pub(crate) fn map(&self) -> InnerMap {
        InnerMap::new(self.x.iter().map(|b| b.len()).sum())
    }

    /// Adds C⁽ᵏ⁾(u) for k in `orders` (at most 2; x then y of each) as inputs of `map`, the
    /// curve reading the blocks from `first` on (its parameter after them when it is
    /// [`Param::Block`]), with their derivatives in the control points and in u (see
    /// [`camber_solve::derive::composed`]); the same values as [`curve_at`] and
    /// [`CurveBasis::eval2`]. Returns the index of the block after the curve's (and u's), or
    /// `None` when the blocks are too few.
    pub(crate) fn curve(
        &self,
        basis: &CurveBasis,
        u: Param,
        first: usize,
        orders: RangeInclusive<usize>,
        map: &mut InnerMap,
    ) -> Option<usize> {
        let n = basis.count();
        let (uu, u_block) = match u {
            Param::Fixed(v) => (v, None),
            Param::Block => (*self.x.get(first + n)?.first()?, Some(first + n)),
        };
        let u_active = u_block.is_some_and(|b| self.active[b]);
        let top = (*orders.end()).min(2);
        let (weights, inside) = basis.block_weights(uu, if u_active { top + 2 } else { top });
        if weights.iter().any(|(j, _)| *j >= n) || self.x.len() < first + n {
            return None;
        }
        let u_col = u_block
            .filter(|_| u_active && inside)
            .map(|b| self.offsets[b]);
        for k in *orders.start()..=top {
            for c in 0..2 {
                let sum = |order: usize| -> f64 {
                    weights
                        .iter()
                        .map(|(j, a)| a[order] * self.x[first + j].get(c).copied().unwrap_or(0.0))
                        .sum()
                };
                let input = map.input(sum(k));
                for (j, a) in &weights {
                    if self.active[first + j] {
                        map.gradient(input, self.offsets[first + j] + c, a[k]);
                    }
                }
                if let Some(uc) = u_col {
                    map.gradient(input, uc, sum(k + 1));
                    map.curvature(input, uc, uc, sum(k + 2));
                    for (j, a) in &weights {
                        if self.active[first + j] {
                            map.curvature(input, self.offsets[first + j] + c, uc, a[k + 1]);
                        }
                    }
                }
            }
        }
        Some(first + n + usize::from(u_block.is_some()))
    }

    /// Adds every value of block `b` as an input of `map` (moving with itself when active).
    pub(crate) fn block(&self, b: usize, map: &mut InnerMap) -> Option<()> {
        let values = self.x.get(b)?;
        for (c, v) in values.iter().enumerate() {
            let input = map.input(*v);
            if self.active[b] {
                map.gradient(input, self.offsets[b] + c, 1.0);
            }
        }
        Some(())
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
