//! Exact Jacobians of a [`Residual`] by forward-mode dual numbers (num-dual).
//!
//! With the unknowns of all blocks laid end to end (n columns in all), a residual g: ℝⁿ → ℝᵐ is
//! evaluated in a dual type whose derivative part is seeded with unit vectors; the derivative
//! parts of the outputs are then columns of J = ∂g/∂x. Three ways of seeding are offered
//! ([`JacobianMode`]):
//! - **columns**: n passes with `Dual64` (one derivative), pass k seeding column k;
//! - **per block**: one pass per parameter block b with `DualSVec64<n_b>` (n_b derivatives),
//!   for 1 ≤ n_b ≤ 8; larger blocks fall back to columns;
//! - **whole**: a single `DualSVec64<n>` pass over all columns when n ≤ 8, otherwise per block.
//!
//! The criterion bench `benches/jacobian.rs` compares them on five residual shapes. No mode wins
//! everywhere (columns on a 2×4 coincidence, the whole pass on a 1×8 tangency, per block on the
//! rest); per block is never more than about a quarter slower than the best and is what
//! [`JacobianMode::Auto`] uses. Small residuals (≤ 32 inputs, rows and blocks) keep their scratch in stack
//! arrays and do not allocate. The solvers call [`jacobian_active`], which skips the columns of
//! fixed blocks and packs the rest into as few vector passes as possible.

use num_dual::{Dual64, DualSVec64};

use crate::model::errors::{Error, Result};
use crate::model::residual::Residual;
use crate::model::scalar::Scalar;

/// Largest number of derivative directions carried by one vector dual pass.
pub const MAX_VECTOR_DIRECTIONS: usize = 8;

/// How the dual numbers are seeded when a Jacobian is computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum JacobianMode {
    /// The mode the bench found fastest or close to it on every residual shape measured
    /// (currently [`JacobianMode::PerBlock`]).
    #[default]
    Auto,
    /// One `Dual64` pass per column.
    Columns,
    /// One `DualSVec64<n_b>` pass per block (blocks longer than 8 fall back to columns).
    PerBlock,
    /// One `DualSVec64<n>` pass for all n columns when n ≤ 8, else per block.
    Whole,
}

/// Writes g(x) into `values` and J = ∂g/∂x into `jac` (row major, `dim` rows, Σ|x_b| columns,
/// block 0's columns first), seeding dual numbers as `mode` says.
///
/// ```
/// use camber_solve::{derive::autodiff::{jacobian_with, JacobianMode}, Residual, Scalar};
/// #[derive(Debug)]
/// struct Square;
/// impl Residual for Square {
///     fn name(&self) -> &str { "square" }
///     fn dim(&self) -> usize { 1 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) { out[0] = x[0][0] * x[0][0]; }
/// }
/// let (mut g, mut j) = ([0.0], [0.0]);
/// jacobian_with(&Square, &[&[3.0][..]], &mut g, &mut j, JacobianMode::Columns)?;
/// assert!((g[0] - 9.0).abs() < 1e-15 && (j[0] - 6.0).abs() < 1e-15);
/// # Ok::<(), camber_solve::Error>(())
/// ```
///
/// # Errors
/// [`Error::Dimension`] when `values` does not have `dim` entries or `jac` not `dim`·n.
pub fn jacobian_with<R: Residual>(
    residual: &R,
    x: &[&[f64]],
    values: &mut [f64],
    jac: &mut [f64],
    mode: JacobianMode,
) -> Result<()> {
    let dim = residual.dim();
    let ncols: usize = x.iter().map(|b| b.len()).sum();
    if values.len() != dim {
        return Err(Error::Dimension {
            what: "residual output",
            expected: dim,
            found: values.len(),
        });
    }
    if jac.len() != dim * ncols {
        return Err(Error::Dimension {
            what: "Jacobian output",
            expected: dim * ncols,
            found: jac.len(),
        });
    }
    jac.fill(0.0);
    if ncols == 0 || dim == 0 {
        residual.eval(x, values);
        return Ok(());
    }
    let mut out = Out { values, jac, ncols };
    match mode {
        JacobianMode::Columns => (0..ncols).for_each(|f| column_pass(residual, x, f, &mut out)),
        JacobianMode::PerBlock | JacobianMode::Auto => per_block(residual, x, &mut out),
        JacobianMode::Whole => {
            if ncols <= MAX_VECTOR_DIRECTIONS {
                vector_range(residual, x, 0, ncols, &mut out);
            } else {
                per_block(residual, x, &mut out);
            }
        }
    }
    Ok(())
}

/// Where a pass writes: the values and the row-major Jacobian with `ncols` columns.
struct Out<'a> {
    values: &'a mut [f64],
    jac: &'a mut [f64],
    ncols: usize,
}

/// Writes g(x) into `values` and the columns of J = ∂g/∂x that belong to blocks whose `active`
/// entry is true into `jac` (row major, `dim` rows, Σ|x_b| columns); the columns of inactive
/// blocks (fixed unknowns, whose derivatives no solver reads) and of blocks the residual says
/// it does not depend on ([`Residual::depends_on`]) are left at zero and cost nothing.
/// The active columns are packed into as few vector passes as the width allows
/// (`DualSVec64<k>`, k ≤ 8): a curve contact reading seven control points and a free parameter
/// (15 active columns) takes two passes, where one pass per block would take eight, each
/// repeating the basis evaluation. When `active` is all true and every block fits one pass this
/// is the per-block seeding of [`JacobianMode::PerBlock`] with fewer passes. A residual with a
/// cheaper exact form ([`Residual::structured_jacobian`]) gives it instead.
///
/// ```
/// use camber_solve::{derive::autodiff::jacobian_active, Residual, Scalar};
/// #[derive(Debug)]
/// struct Product;
/// impl Residual for Product {
///     fn name(&self) -> &str { "product" }
///     fn dim(&self) -> usize { 1 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) { out[0] = x[0][0] * x[1][0]; }
/// }
/// let (mut g, mut j) = ([0.0], [9.0, 9.0]);
/// jacobian_active(&Product, &[&[3.0][..], &[5.0][..]], &[false, true], &mut g, &mut j)?;
/// assert_eq!((g[0], j), (15.0, [0.0, 3.0]));
/// # Ok::<(), camber_solve::Error>(())
/// ```
///
/// # Errors
/// [`Error::Dimension`] for wrong lengths of `values`, `jac` or `active`.
pub fn jacobian_active<R: Residual>(
    residual: &R,
    x: &[&[f64]],
    active: &[bool],
    values: &mut [f64],
    jac: &mut [f64],
) -> Result<()> {
    let dim = residual.dim();
    let ncols: usize = x.iter().map(|b| b.len()).sum();
    for (what, expected, found) in [
        ("residual output", dim, values.len()),
        ("Jacobian output", dim * ncols, jac.len()),
        ("active blocks", x.len(), active.len()),
    ] {
        if expected != found {
            return Err(Error::Dimension {
                what,
                expected,
                found,
            });
        }
    }
    if residual.structured_jacobian(x, active, values, jac) {
        return Ok(());
    }
    jac.fill(0.0);
    let mut needed: smallvec::SmallVec<[bool; 16]> = active.iter().copied().collect();
    residual.depends_on(x, &mut needed);
    let mut columns: smallvec::SmallVec<[usize; 32]> = smallvec::SmallVec::new();
    let mut start = 0;
    for (block, on) in x.iter().zip(&needed) {
        if *on {
            columns.extend(start..start + block.len());
        }
        start += block.len();
    }
    if columns.is_empty() || dim == 0 {
        residual.eval(x, values);
        return Ok(());
    }
    // Balanced passes: 15 columns as 8 + 7, 17 as 6 + 6 + 5.
    let passes = columns.len().div_ceil(MAX_VECTOR_DIRECTIONS);
    let width = columns.len().div_ceil(passes);
    let mut out = Out { values, jac, ncols };
    for chunk in columns.chunks(width) {
        match chunk.len() {
            1 => packed_pass::<R, 1>(residual, x, chunk, &mut out),
            2 => packed_pass::<R, 2>(residual, x, chunk, &mut out),
            3 => packed_pass::<R, 3>(residual, x, chunk, &mut out),
            4 => packed_pass::<R, 4>(residual, x, chunk, &mut out),
            5 => packed_pass::<R, 5>(residual, x, chunk, &mut out),
            6 => packed_pass::<R, 6>(residual, x, chunk, &mut out),
            7 => packed_pass::<R, 7>(residual, x, chunk, &mut out),
            _ => packed_pass::<R, 8>(residual, x, chunk, &mut out),
        }
    }
    Ok(())
}

fn per_block<R: Residual>(residual: &R, x: &[&[f64]], out: &mut Out<'_>) {
    let mut start = 0;
    for block in x {
        vector_range(residual, x, start, block.len(), out);
        start += block.len();
    }
}

/// Differentiates with respect to the flat columns `start..start + n` in one vector pass when
/// 1 ≤ n ≤ 8, column by column otherwise.
fn vector_range<R: Residual>(
    residual: &R,
    x: &[&[f64]],
    start: usize,
    n: usize,
    out: &mut Out<'_>,
) {
    match n {
        0 => {}
        1 => vector_pass::<R, 1>(residual, x, start, out),
        2 => vector_pass::<R, 2>(residual, x, start, out),
        3 => vector_pass::<R, 3>(residual, x, start, out),
        4 => vector_pass::<R, 4>(residual, x, start, out),
        5 => vector_pass::<R, 5>(residual, x, start, out),
        6 => vector_pass::<R, 6>(residual, x, start, out),
        7 => vector_pass::<R, 7>(residual, x, start, out),
        8 => vector_pass::<R, 8>(residual, x, start, out),
        _ => (start..start + n).for_each(|f| column_pass(residual, x, f, out)),
    }
}

/// Evaluates the residual with every input converted by `seed(flat index, value)` and hands the
/// outputs to `take`. Small residuals use stack arrays sized to them (8, 16 or 32 inputs, rows and
/// blocks), and everything stays in this frame: moving, growing or zeroing larger inline
/// buffers costs more than the evaluation itself. Larger residuals use vectors.
pub(crate) fn eval_seeded<R: Residual, D: Scalar>(
    residual: &R,
    x: &[&[f64]],
    seed: impl Fn(usize, f64) -> D,
    take: impl FnOnce(&[D]),
) {
    let n: usize = x.iter().map(|b| b.len()).sum();
    let size = n.max(residual.dim()).max(x.len());
    if size <= 8 {
        eval_inline::<R, D, 8>(residual, x, seed, take);
    } else if size <= 16 {
        eval_inline::<R, D, 16>(residual, x, seed, take);
    } else if size <= 32 {
        eval_inline::<R, D, 32>(residual, x, seed, take);
    } else {
        let flat: Vec<D> = x
            .iter()
            .flat_map(|b| b.iter())
            .enumerate()
            .map(|(f, v)| seed(f, *v))
            .collect();
        let mut refs: Vec<&[D]> = vec![&[]; x.len()];
        split_into(&flat, x, &mut refs);
        let mut g = vec![D::zero(); residual.dim()];
        residual.eval(&refs, &mut g);
        take(&g);
    }
}

/// [`eval_seeded`] with stack arrays of `N` entries (inputs, rows and blocks all ≤ N).
fn eval_inline<R: Residual, D: Scalar, const N: usize>(
    residual: &R,
    x: &[&[f64]],
    seed: impl Fn(usize, f64) -> D,
    take: impl FnOnce(&[D]),
) {
    let mut flat = [D::zero(); N];
    let values = x.iter().flat_map(|b| b.iter());
    for (f, (slot, v)) in flat.iter_mut().zip(values).enumerate() {
        *slot = seed(f, *v);
    }
    let mut refs: [&[D]; N] = [&[]; N];
    split_into(&flat, x, &mut refs);
    let mut g = [D::zero(); N];
    let g = &mut g[..residual.dim()];
    residual.eval(&refs[..x.len()], g);
    take(g);
}

/// Cuts `flat` into one slice per block of `x` (same lengths), written to `refs`.
fn split_into<'a, D>(flat: &'a [D], x: &[&[f64]], refs: &mut [&'a [D]]) {
    let mut rest = flat;
    for (block, slot) in x.iter().zip(refs.iter_mut()) {
        // `flat` holds at least Σ|x_b| entries, so every split is in range.
        let (head, tail) = rest.split_at(block.len());
        *slot = head;
        rest = tail;
    }
}

fn column_pass<R: Residual>(residual: &R, x: &[&[f64]], column: usize, out: &mut Out<'_>) {
    let seed = |f, v| {
        if f == column {
            Dual64::new(v, 1.0)
        } else {
            Dual64::from_re(v)
        }
    };
    eval_seeded(residual, x, seed, |g: &[Dual64]| {
        let rows = out.jac.chunks_exact_mut(out.ncols);
        for ((gi, vi), row) in g.iter().zip(out.values.iter_mut()).zip(rows) {
            *vi = gi.re;
            if let Some(slot) = row.get_mut(column) {
                *slot = gi.eps;
            }
        }
    });
}

fn vector_pass<R: Residual, const N: usize>(
    residual: &R,
    x: &[&[f64]],
    start: usize,
    out: &mut Out<'_>,
) {
    let seed = |f, v| {
        let d = DualSVec64::<N>::from_re(v);
        if (start..start + N).contains(&f) {
            d.derivative(f - start)
        } else {
            d
        }
    };
    eval_seeded(residual, x, seed, |g: &[DualSVec64<N>]| {
        let rows = out.jac.chunks_exact_mut(out.ncols);
        for ((gi, vi), row) in g.iter().zip(out.values.iter_mut()).zip(rows) {
            *vi = gi.re;
            if let (Some(eps), Some(slots)) = (&gi.eps.0, row.get_mut(start..start + N)) {
                for (slot, e) in slots.iter_mut().zip(eps.iter()) {
                    *slot = *e;
                }
            }
        }
    });
}

/// One `DualSVec64<N>` pass seeding the flat columns `columns` (ascending, at most N of them,
/// not necessarily contiguous) with the unit directions 0, 1, ….
fn packed_pass<R: Residual, const N: usize>(
    residual: &R,
    x: &[&[f64]],
    columns: &[usize],
    out: &mut Out<'_>,
) {
    let seed = |f, v| {
        let d = DualSVec64::<N>::from_re(v);
        match columns.binary_search(&f) {
            Ok(k) => d.derivative(k),
            Err(_) => d,
        }
    };
    eval_seeded(residual, x, seed, |g: &[DualSVec64<N>]| {
        let rows = out.jac.chunks_exact_mut(out.ncols);
        for ((gi, vi), row) in g.iter().zip(out.values.iter_mut()).zip(rows) {
            *vi = gi.re;
            if let Some(eps) = &gi.eps.0 {
                for (c, e) in columns.iter().zip(eps.iter()) {
                    if let Some(slot) = row.get_mut(*c) {
                        *slot = *e;
                    }
                }
            }
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Rows: x·y·z over three blocks of sizes 2, 9 (beyond the vector limit) and 1.
    #[derive(Debug)]
    struct Wide;

    impl Residual for Wide {
        fn name(&self) -> &str {
            "wide"
        }
        fn dim(&self) -> usize {
            3
        }
        fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
            let s: T = x[1].iter().fold(T::zero(), |a, b| a + *b * *b);
            out[0] = x[0][0] * x[0][1] * x[2][0];
            out[1] = s.sqrt() + x[0][0].exp();
            out[2] = x[1][8] * x[2][0].sin();
        }
    }

    fn hand_jacobian(a: &[f64], b: &[f64], c: &[f64]) -> Vec<f64> {
        let n = 12;
        let mut j = vec![0.0; 3 * n];
        j[0] = a[1] * c[0];
        j[1] = a[0] * c[0];
        j[11] = a[0] * a[1];
        let norm = b.iter().map(|v| v * v).sum::<f64>().sqrt();
        j[n] = a[0].exp();
        for k in 0..9 {
            j[n + 2 + k] = b[k] / norm;
        }
        j[2 * n + 2 + 8] = c[0].sin();
        j[2 * n + 11] = b[8] * c[0].cos();
        j
    }

    #[test]
    fn every_mode_matches_the_hand_derivative() {
        let a = [0.3, -1.2];
        let b = [1.0, 2.0, -0.5, 0.25, 3.0, -2.0, 0.1, 0.7, 1.5];
        let c = [0.8];
        let x = [&a[..], &b[..], &c[..]];
        let want = hand_jacobian(&a, &b, &c);
        for mode in [
            JacobianMode::Auto,
            JacobianMode::Columns,
            JacobianMode::PerBlock,
            JacobianMode::Whole,
        ] {
            let mut g = [0.0; 3];
            let mut j = vec![0.0; 36];
            jacobian_with(&Wide, &x, &mut g, &mut j, mode).unwrap();
            assert_relative_eq!(g[0], a[0] * a[1] * c[0], epsilon = 1e-15);
            for (got, w) in j.iter().zip(&want) {
                assert_relative_eq!(*got, *w, epsilon = 1e-14);
            }
        }
    }

    #[test]
    fn active_blocks_get_the_hand_derivative_and_the_others_zero() {
        let a = [0.3, -1.2];
        let b = [1.0, 2.0, -0.5, 0.25, 3.0, -2.0, 0.1, 0.7, 1.5];
        let c = [0.8];
        let x = [&a[..], &b[..], &c[..]];
        let want = hand_jacobian(&a, &b, &c);
        let block_of = |col: usize| match col {
            0..=1 => 0,
            2..=10 => 1,
            _ => 2,
        };
        // Every subset of the three blocks: 12, 10, 3, … active columns in 2, 2, 1, … passes.
        for mask in 0..8_u8 {
            let active = [mask & 1 != 0, mask & 2 != 0, mask & 4 != 0];
            let mut g = [0.0; 3];
            let mut j = vec![f64::NAN; 36];
            jacobian_active(&Wide, &x, &active, &mut g, &mut j).unwrap();
            assert_relative_eq!(g[1], 21.0625_f64.sqrt() + a[0].exp(), epsilon = 1e-14);
            for (k, (got, w)) in j.iter().zip(&want).enumerate() {
                let w = if active[block_of(k % 12)] { *w } else { 0.0 };
                assert_relative_eq!(*got, w, epsilon = 1e-14);
            }
        }
    }

    /// 40 inputs (beyond the stack buffers): g = Σ xᵢ², ∂g/∂xᵢ = 2xᵢ, in five passes of 8.
    #[derive(Debug)]
    struct SumOfSquares;

    impl Residual for SumOfSquares {
        fn name(&self) -> &str {
            "sum of squares"
        }
        fn dim(&self) -> usize {
            1
        }
        fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
            out[0] = x
                .iter()
                .flat_map(|b| b.iter())
                .fold(T::zero(), |a, v| a + *v * *v);
        }
    }

    #[test]
    fn many_active_columns_are_packed_into_passes_of_eight() {
        let values: Vec<[f64; 2]> = (0..20)
            .map(|i| [f64::from(i), -0.5 * f64::from(i)])
            .collect();
        let x: Vec<&[f64]> = values.iter().map(|v| &v[..]).collect();
        let mut g = [0.0];
        let mut j = vec![0.0; 40];
        jacobian_active(&SumOfSquares, &x, &[true; 20], &mut g, &mut j).unwrap();
        for (k, got) in j.iter().enumerate() {
            assert_relative_eq!(*got, 2.0 * values[k / 2][k % 2], epsilon = 1e-15);
        }
        assert_eq!(
            jacobian_active(&SumOfSquares, &x, &[true; 19], &mut g, &mut j),
            Err(Error::Dimension {
                what: "active blocks",
                expected: 20,
                found: 19
            })
        );
    }

    #[test]
    fn wrong_jacobian_length_is_an_error() {
        let x = [&[0.0, 0.0][..], &[0.0; 9][..], &[0.0][..]];
        let mut g = [0.0; 3];
        let mut j = vec![0.0; 35];
        assert_eq!(
            jacobian_with(&Wide, &x, &mut g, &mut j, JacobianMode::Auto),
            Err(Error::Dimension {
                what: "Jacobian output",
                expected: 36,
                found: 35
            })
        );
    }
}
