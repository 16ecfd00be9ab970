//! Exact second derivatives of a [`Residual`] by hyper-dual numbers (num-dual).
//!
//! The sequential-quadratic Newton step needs the Hessian of the Lagrangian's constraint part,
//! H = Σᵢ λᵢ·∇²gᵢ(x), for a residual block g: ℝⁿ → ℝᵐ and multipliers λ ∈ ℝᵐ. With the
//! unknowns grouped in the residual's parameter blocks x₁, …, x_k, the Hessian is made of the
//! mixed blocks ∂²gᵢ/∂x_a∂x_b. One evaluation in a vector hyper-dual number
//! `HyperDualSVec64<|x_a|, |x_b|>`, whose first derivative part is seeded with the unit vectors
//! of block a and whose second with those of block b, gives that whole mixed block for every
//! row at once (its ε₁ε₂ part). So a residual reading k blocks costs k(k + 1)/2 evaluations,
//! and blocks a residual does not move (fixed points, fixed circles) cost nothing.
//!
//! A residual with at most 8 unknowns in its active blocks (a joint between two curve ends, a
//! distance, a point on a circle) is evaluated once instead, in `Dual2SVec64<N>`, whose second
//! derivative part is the whole N × N Hessian of every row: one pass costs less than the
//! k(k + 1)/2 passes once k > 2. Otherwise blocks of 1 to 3 unknowns (parameters, planar and
//! spatial points) use the mixed vector form; larger blocks fall back to scalar `HyperDual64`
//! evaluations per pair of columns. Affine residuals have H = 0 and are not evaluated at all.
//!
//! A residual that knows a cheaper exact form ([`Residual::structured_hessian`], a curve
//! residual composed of a small function of the curve's point and derivatives,
//! [`crate::derive::composed`]) gives it instead; [`hyper_dual_hessian`] always takes the passes above.

use num_dual::{Dual2SVec64, HyperDual64, HyperDualSVec64};

use crate::derive::autodiff::eval_seeded;
use crate::model::errors::{Error, Result};
use crate::model::residual::Residual;

/// Writes H = Σᵢ λᵢ·∇²gᵢ(x) into `out` (row major, N × N with N = Σ|x_b|, block 0's columns
/// first, both triangles). `weights` holds λ (one per row); blocks whose `active` entry is
/// false, and blocks the residual does not depend on ([`Residual::depends_on`]), are treated as
/// constants (their rows and columns of H are left zero).
///
/// ```
/// use camber_solve::{derive::hessian::weighted_hessian, Residual, Scalar};
/// /// g = (x·y², x + y): ∇²g₀ = [[0, 2y], [2y, 2x]], ∇²g₁ = 0.
/// #[derive(Debug)]
/// struct Xy2;
/// impl Residual for Xy2 {
///     fn name(&self) -> &str { "x·y²" }
///     fn dim(&self) -> usize { 2 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
///         out[0] = x[0][0] * x[1][0] * x[1][0];
///         out[1] = x[0][0] + x[1][0];
///     }
/// }
/// let mut h = [0.0; 4];
/// weighted_hessian(&Xy2, &[&[3.0][..], &[2.0][..]], &[0.5, 7.0], &[true, true], &mut h)?;
/// // 0.5·[[0, 4], [4, 6]]
/// let want = [0.0, 2.0, 2.0, 3.0];
/// assert!(h.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-14));
/// # Ok::<(), camber_solve::Error>(())
/// ```
///
/// # Errors
/// [`Error::Dimension`] when `weights` does not have `dim()` entries, `active` one per block,
/// or `out` N² entries.
pub fn weighted_hessian<R: Residual>(
    residual: &R,
    x: &[&[f64]],
    weights: &[f64],
    active: &[bool],
    out: &mut [f64],
) -> Result<()> {
    let n = checked_columns(residual, x, weights, active, out)?;
    out.fill(0.0);
    if residual.is_affine() || weights.iter().all(|w| *w == 0.0) {
        return Ok(());
    }
    if residual.structured_hessian(x, weights, active, out) {
        return Ok(());
    }
    out.fill(0.0);
    hyper_dual_passes(residual, x, weights, active, Square { h: out, n });
    Ok(())
}

/// [`weighted_hessian`] by hyper-dual numbers alone, ignoring
/// [`Residual::structured_hessian`] (the reference the structured forms are tested against).
///
/// # Errors
/// As [`weighted_hessian`].
pub fn hyper_dual_hessian<R: Residual>(
    residual: &R,
    x: &[&[f64]],
    weights: &[f64],
    active: &[bool],
    out: &mut [f64],
) -> Result<()> {
    let n = checked_columns(residual, x, weights, active, out)?;
    out.fill(0.0);
    if residual.is_affine() || weights.iter().all(|w| *w == 0.0) {
        return Ok(());
    }
    hyper_dual_passes(residual, x, weights, active, Square { h: out, n });
    Ok(())
}

/// The number of columns N, once the lengths of `weights`, `active` and `out` are checked.
fn checked_columns<R: Residual>(
    residual: &R,
    x: &[&[f64]],
    weights: &[f64],
    active: &[bool],
    out: &[f64],
) -> Result<usize> {
    let n: usize = x.iter().map(|b| b.len()).sum();
    for (what, expected, found) in [
        ("Hessian weights", residual.dim(), weights.len()),
        ("Hessian active blocks", x.len(), active.len()),
        ("Hessian output", n * n, out.len()),
    ] {
        if expected != found {
            return Err(Error::Dimension {
                what,
                expected,
                found,
            });
        }
    }
    Ok(n)
}

/// The hyper-dual evaluations of [`weighted_hessian`] into a zeroed `out`.
fn hyper_dual_passes<R: Residual>(
    residual: &R,
    x: &[&[f64]],
    weights: &[f64],
    active: &[bool],
    mut out: Square<'_>,
) {
    let mut needed: smallvec::SmallVec<[bool; 16]> = active.iter().copied().collect();
    residual.depends_on(x, &mut needed);
    let active = &needed[..];
    // The flat columns of the active blocks.
    let mut columns: [usize; WHOLE_MAX] = [0; WHOLE_MAX];
    let mut count = 0;
    let mut start = 0;
    for (block, on) in x.iter().zip(active) {
        if *on {
            for c in start..start + block.len() {
                if count < WHOLE_MAX {
                    columns[count] = c;
                }
                count += 1;
            }
        }
        start += block.len();
    }
    if count <= WHOLE_MAX {
        whole(residual, x, weights, &columns[..count], &mut out);
        return;
    }
    let mut start_a = 0;
    for (a, block_a) in x.iter().enumerate() {
        let mut start_b = start_a;
        for (b, block_b) in x.iter().enumerate().skip(a) {
            if active[a] && active[b] {
                let pair = Pair {
                    a: (start_a, block_a.len()),
                    b: (start_b, block_b.len()),
                };
                mixed_block(residual, x, weights, pair, &mut out);
            }
            start_b += block_b.len();
        }
        start_a += block_a.len();
    }
}

/// The flat column ranges (start, length) of two blocks, a before or equal to b.
#[derive(Debug, Clone, Copy)]
struct Pair {
    a: (usize, usize),
    b: (usize, usize),
}

/// The N × N output, written symmetrically.
struct Square<'a> {
    h: &'a mut [f64],
    n: usize,
}

impl Square<'_> {
    fn set(&mut self, i: usize, j: usize, v: f64) {
        let n = self.n;
        if let Some(slot) = self.h.get_mut(i * n + j) {
            *slot = v;
        }
        if let Some(slot) = self.h.get_mut(j * n + i) {
            *slot = v;
        }
    }
}

fn mixed_block<R: Residual>(
    residual: &R,
    x: &[&[f64]],
    weights: &[f64],
    pair: Pair,
    out: &mut Square<'_>,
) {
    match (pair.a.1, pair.b.1) {
        (1, 1) => vector_pair::<R, 1, 1>(residual, x, weights, pair, out),
        (1, 2) => vector_pair::<R, 1, 2>(residual, x, weights, pair, out),
        (1, 3) => vector_pair::<R, 1, 3>(residual, x, weights, pair, out),
        (2, 1) => vector_pair::<R, 2, 1>(residual, x, weights, pair, out),
        (2, 2) => vector_pair::<R, 2, 2>(residual, x, weights, pair, out),
        (2, 3) => vector_pair::<R, 2, 3>(residual, x, weights, pair, out),
        (3, 1) => vector_pair::<R, 3, 1>(residual, x, weights, pair, out),
        (3, 2) => vector_pair::<R, 3, 2>(residual, x, weights, pair, out),
        (3, 3) => vector_pair::<R, 3, 3>(residual, x, weights, pair, out),
        _ => scalar_pairs(residual, x, weights, pair, out),
    }
}

/// Active unknowns up to this many are differentiated twice in one `Dual2SVec64` pass.
const WHOLE_MAX: usize = 8;

fn whole<R: Residual>(
    residual: &R,
    x: &[&[f64]],
    weights: &[f64],
    columns: &[usize],
    out: &mut Square<'_>,
) {
    match columns.len() {
        0 => {}
        1 => whole_pass::<R, 1>(residual, x, weights, columns, out),
        2 => whole_pass::<R, 2>(residual, x, weights, columns, out),
        3 => whole_pass::<R, 3>(residual, x, weights, columns, out),
        4 => whole_pass::<R, 4>(residual, x, weights, columns, out),
        5 => whole_pass::<R, 5>(residual, x, weights, columns, out),
        6 => whole_pass::<R, 6>(residual, x, weights, columns, out),
        7 => whole_pass::<R, 7>(residual, x, weights, columns, out),
        _ => whole_pass::<R, 8>(residual, x, weights, columns, out),
    }
}

/// One `Dual2SVec64<N>` evaluation seeding the N flat `columns`.
fn whole_pass<R: Residual, const N: usize>(
    residual: &R,
    x: &[&[f64]],
    weights: &[f64],
    columns: &[usize],
    out: &mut Square<'_>,
) {
    let seed = |f: usize, v: f64| {
        let d = Dual2SVec64::<N>::from_re(v);
        match columns.iter().position(|c| *c == f) {
            Some(i) => d.derivative(i),
            None => d,
        }
    };
    eval_seeded(residual, x, seed, |g: &[Dual2SVec64<N>]| {
        let mut acc = [[0.0; N]; N];
        for (gi, w) in g.iter().zip(weights) {
            if let Some(m) = &gi.v2.0 {
                for (i, row) in acc.iter_mut().enumerate() {
                    for (j, slot) in row.iter_mut().enumerate().skip(i) {
                        *slot += w * m[(i, j)];
                    }
                }
            }
        }
        for (i, row) in acc.iter().enumerate() {
            for (j, v) in row.iter().enumerate().skip(i) {
                out.set(columns[i], columns[j], *v);
            }
        }
    });
}

fn vector_pair<R: Residual, const M: usize, const N: usize>(
    residual: &R,
    x: &[&[f64]],
    weights: &[f64],
    pair: Pair,
    out: &mut Square<'_>,
) {
    let (sa, sb) = (pair.a.0, pair.b.0);
    let seed = |f: usize, v: f64| {
        let mut d = HyperDualSVec64::<M, N>::from_re(v);
        if (sa..sa + M).contains(&f) {
            d = d.derivative1(f - sa);
        }
        if (sb..sb + N).contains(&f) {
            d = d.derivative2(f - sb);
        }
        d
    };
    eval_seeded(residual, x, seed, |g: &[HyperDualSVec64<M, N>]| {
        let mut acc = [[0.0; N]; M];
        for (gi, w) in g.iter().zip(weights) {
            if let Some(m) = &gi.eps1eps2.0 {
                for (i, row) in acc.iter_mut().enumerate() {
                    for (j, slot) in row.iter_mut().enumerate() {
                        *slot += w * m[(i, j)];
                    }
                }
            }
        }
        for (i, row) in acc.iter().enumerate() {
            for (j, v) in row.iter().enumerate() {
                out.set(sa + i, sb + j, *v);
            }
        }
    });
}

fn scalar_pairs<R: Residual>(
    residual: &R,
    x: &[&[f64]],
    weights: &[f64],
    pair: Pair,
    out: &mut Square<'_>,
) {
    let same = pair.a == pair.b;
    for i in pair.a.0..pair.a.0 + pair.a.1 {
        let first_j = if same { i } else { pair.b.0 };
        for j in first_j..pair.b.0 + pair.b.1 {
            let seed = |f: usize, v: f64| {
                let e1 = if f == i { 1.0 } else { 0.0 };
                let e2 = if f == j { 1.0 } else { 0.0 };
                HyperDual64::new(v, e1, e2, 0.0)
            };
            eval_seeded(residual, x, seed, |g: &[HyperDual64]| {
                let v: f64 = g.iter().zip(weights).map(|(gi, w)| w * gi.eps1eps2).sum();
                out.set(i, j, v);
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::scalar::Scalar;
    use approx::assert_relative_eq;

    /// Three blocks of sizes 2, 4 (beyond the vector forms) and 1, with cross terms everywhere.
    #[derive(Debug)]
    struct Tangle;

    impl Residual for Tangle {
        fn name(&self) -> &str {
            "tangle"
        }
        fn dim(&self) -> usize {
            2
        }
        fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
            let s: T = x[1].iter().fold(T::zero(), |a, b| a + *b * *b);
            out[0] = x[0][0] * x[0][1] * x[2][0] + s.sqrt();
            out[1] = (x[0][0] * x[1][3]).sin() + x[2][0] * x[2][0] * x[1][0];
        }
    }

    /// Central differences of the exact gradient Σ wᵢ∇gᵢ (itself by dual numbers).
    fn fd_hessian(x: &[f64], w: &[f64]) -> Vec<f64> {
        let n = x.len();
        let grad = |x: &[f64]| {
            let blocks = [&x[0..2], &x[2..6], &x[6..7]];
            let mut g = [0.0; 2];
            let mut j = vec![0.0; 2 * n];
            crate::derive::autodiff::jacobian_with(
                &Tangle,
                &blocks,
                &mut g,
                &mut j,
                crate::derive::autodiff::JacobianMode::Columns,
            )
            .unwrap();
            (0..n)
                .map(|c| w[0] * j[c] + w[1] * j[n + c])
                .collect::<Vec<_>>()
        };
        let h = 1e-6;
        let mut out = vec![0.0; n * n];
        for c in 0..n {
            let (mut xp, mut xm) = (x.to_vec(), x.to_vec());
            xp[c] += h;
            xm[c] -= h;
            let (gp, gm) = (grad(&xp), grad(&xm));
            for r in 0..n {
                out[r * n + c] = (gp[r] - gm[r]) / (2.0 * h);
            }
        }
        out
    }

    #[test]
    fn matches_central_differences_of_the_gradient() {
        let x = [0.3, -1.2, 1.0, 2.0, -0.5, 0.25, 0.8];
        let w = [1.5, -0.75];
        let blocks = [&x[0..2], &x[2..6], &x[6..7]];
        let mut h = vec![0.0; 49];
        weighted_hessian(&Tangle, &blocks, &w, &[true; 3], &mut h).unwrap();
        let want = fd_hessian(&x, &w);
        for (got, want) in h.iter().zip(&want) {
            assert_relative_eq!(*got, *want, epsilon = 1e-7, max_relative = 1e-7);
        }
        // Symmetric, exactly.
        for r in 0..7 {
            for c in 0..7 {
                assert_relative_eq!(h[r * 7 + c], h[c * 7 + r], epsilon = 0.0);
            }
        }
    }

    /// Ten unknowns (beyond the single pass): the block-pair forms must agree with central
    /// differences too.
    #[derive(Debug)]
    struct Wide;

    impl Residual for Wide {
        fn name(&self) -> &str {
            "wide"
        }
        fn dim(&self) -> usize {
            1
        }
        fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
            let s: T = x[1].iter().fold(T::zero(), |a, b| a + *b * *b);
            out[0] = x[0][0] * x[0][1] * x[2][0] + s.sqrt() * x[3][1] + (x[1][0] * x[1][5]).sin();
        }
    }

    #[test]
    fn block_pairs_match_central_differences() {
        let x = [0.3, -1.2, 1.0, 2.0, -0.5, 0.25, 0.8, -0.3, 0.7, 0.4, -0.9];
        let blocks = [&x[0..2], &x[2..8], &x[8..9], &x[9..11]];
        let n = 11;
        let mut h = vec![0.0; n * n];
        weighted_hessian(&Wide, &blocks, &[1.5], &[true; 4], &mut h).unwrap();
        let grad = |x: &[f64]| {
            let b = [&x[0..2], &x[2..8], &x[8..9], &x[9..11]];
            let (mut g, mut j) = ([0.0], vec![0.0; n]);
            crate::derive::autodiff::jacobian_with(
                &Wide,
                &b,
                &mut g,
                &mut j,
                crate::derive::autodiff::JacobianMode::Columns,
            )
            .unwrap();
            j.iter().map(|v| 1.5 * v).collect::<Vec<_>>()
        };
        let step = 1e-6;
        for c in 0..n {
            let (mut xp, mut xm) = (x.to_vec(), x.to_vec());
            xp[c] += step;
            xm[c] -= step;
            let (gp, gm) = (grad(&xp), grad(&xm));
            for r in 0..n {
                let fd = (gp[r] - gm[r]) / (2.0 * step);
                assert_relative_eq!(h[r * n + c], fd, epsilon = 1e-7, max_relative = 1e-7);
            }
        }
    }

    #[test]
    fn inactive_blocks_leave_zeros() {
        let x = [0.3, -1.2, 1.0, 2.0, -0.5, 0.25, 0.8];
        let blocks = [&x[0..2], &x[2..6], &x[6..7]];
        let mut h = vec![0.0; 49];
        weighted_hessian(&Tangle, &blocks, &[1.0, 1.0], &[true, false, true], &mut h).unwrap();
        for r in 2..6 {
            for c in 0..7 {
                assert_relative_eq!(h[r * 7 + c], 0.0, epsilon = 0.0);
                assert_relative_eq!(h[c * 7 + r], 0.0, epsilon = 0.0);
            }
        }
        // The active cross term x₀x₂ of row 0: ∂²/∂x₀₀∂x₂₀ = x₀₁.
        assert_relative_eq!(h[6], -1.2, epsilon = 1e-15);
    }

    #[test]
    fn wrong_lengths_are_errors() {
        let x = [0.0; 7];
        let blocks = [&x[0..2], &x[2..6], &x[6..7]];
        let mut h = vec![0.0; 48];
        assert_eq!(
            weighted_hessian(&Tangle, &blocks, &[1.0, 1.0], &[true; 3], &mut h),
            Err(Error::Dimension {
                what: "Hessian output",
                expected: 49,
                found: 48
            })
        );
    }
}
