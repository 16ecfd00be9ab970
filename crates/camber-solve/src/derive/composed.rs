//! Exact first and second derivatives of a composed residual g(x) = f(y(x)), where f is a
//! small function of a few numbers y ∈ ℝᴷ and y(x) is an inner map whose derivatives are known
//! in floating point.
//!
//! A curve residual is the typical case: at a parameter u, the point C(u) and its derivatives
//! are linear in the control points P (C⁽ᵈ⁾(u) = Σⱼ R⁽ᵈ⁾ⱼ(u)·Pⱼ, the basis weights R⁽ᵈ⁾ⱼ being
//! data), and the residual itself (parallel tangents, a circle contact) is a short formula in
//! those few numbers. Differentiating the whole residual with hyper-dual numbers over every
//! control point evaluates the basis inside every dual operation; by the chain rule
//!
//! ∇g = ∇f·J,  ∇²(λ·g) = Jᵀ·∇²(λ·f)·J + Σₖ (λ·∂f/∂yₖ)·∇²yₖ,
//!
//! with J = ∂y/∂x, only f is differentiated by dual numbers (one `Dual2SVec64<K>` pass over
//! its K inputs), and J and the second derivatives ∇²yₖ are plain floats the caller writes
//! into an [`InnerMap`]. For y linear in x (a fixed parameter) ∇²yₖ = 0; with u an unknown,
//! ∂²C⁽ᵈ⁾/∂u² = C⁽ᵈ⁺²⁾ and ∂²C⁽ᵈ⁾/∂u∂Pⱼ = R⁽ᵈ⁺¹⁾ⱼ.
//!
//! Inputs that no unknown moves (a fixed circle's centre) enter f as constants, so K counts only
//! the moving ones; at most [`MAX_MOVING_INPUTS`] are supported (the functions return `false`
//! beyond, and the caller falls back to differentiating the whole residual).
//!
//! ```
//! use camber_solve::derive::composed::{self, InnerMap, Outer};
//! use camber_solve::Scalar;
//! /// f(y) = y₀·y₁, with y₀ = 2a + b and y₁ = a − b over the unknowns x = (a, b).
//! struct Product;
//! impl Outer for Product {
//!     fn outer<T: Scalar>(&self, y: &[T], out: &mut [T]) { out[0] = y[0] * y[1]; }
//! }
//! let (a, b) = (1.0, 3.0);
//! let mut map = InnerMap::new(2);
//! let y0 = map.input(2.0 * a + b);
//! map.gradient(y0, 0, 2.0);
//! map.gradient(y0, 1, 1.0);
//! let y1 = map.input(a - b);
//! map.gradient(y1, 0, 1.0);
//! map.gradient(y1, 1, -1.0);
//! // g = (2a + b)(a − b) = 2a² − ab − b²: ∇²g = [[4, −1], [−1, −2]].
//! let mut h = [0.0; 4];
//! assert!(composed::weighted_hessian(&Product, &map, &[1.0], &mut h));
//! assert_eq!(h, [4.0, -1.0, -1.0, -2.0]);
//! ```

use num_dual::{Dual2SVec64, DualSVec64};
use smallvec::SmallVec;

use crate::model::scalar::Scalar;

/// The largest number of moving inputs of f differentiated in one dual pass.
pub const MAX_MOVING_INPUTS: usize = 8;

/// The outer function f of a composed residual: writes one value per row into `out` from the
/// inputs `y` (as many as the [`InnerMap`] has).
pub trait Outer {
    /// f(y) into `out`.
    fn outer<T: Scalar>(&self, y: &[T], out: &mut [T]);
    /// Hand-written first derivatives, when f is simple enough: f(y) into `values` and ∂fᵢ/∂yₖ
    /// into `jacobian` (row major, one row per value, one column per input). Returns `false`
    /// (the default) to have them by dual numbers.
    fn first_derivatives(&self, y: &[f64], values: &mut [f64], jacobian: &mut [f64]) -> bool {
        let _ = (y, values, jacobian);
        false
    }
    /// Hand-written weighted derivatives: Σᵢ λᵢ·∇fᵢ into `gradient` (one per input) and
    /// Σᵢ λᵢ·∇²fᵢ into `hessian` (row major, inputs × inputs), `weights` holding λ. Returns
    /// `false` (the default) to have them by hyper-dual numbers.
    fn weighted_second_derivatives(
        &self,
        y: &[f64],
        weights: &[f64],
        gradient: &mut [f64],
        hessian: &mut [f64],
    ) -> bool {
        let _ = (y, weights, gradient, hessian);
        false
    }
}

/// The most inputs a hand-written [`Outer`] derivative is offered.
const HAND_WRITTEN_MAX: usize = 8;

/// The inner map y(x) at one point x: each input's value, its non-zero first derivatives in the
/// flat columns of x, and its non-zero second derivatives.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct InnerMap {
    columns: usize,
    values: SmallVec<[f64; 8]>,
    /// (input, column, ∂yₖ/∂x_col).
    gradient: SmallVec<[(usize, usize, f64); 32]>,
    /// (input, column i, column j, ∂²yₖ/∂xᵢ∂xⱼ), each unordered pair once.
    curvature: SmallVec<[(usize, usize, usize, f64); 16]>,
}

impl InnerMap {
    /// An empty map over `columns` unknowns (the flat columns of the residual's blocks).
    pub fn new(columns: usize) -> Self {
        Self {
            columns,
            ..Self::default()
        }
    }

    /// Adds an input of value `value` (constant until derivatives are added); returns its index.
    pub fn input(&mut self, value: f64) -> usize {
        self.values.push(value);
        self.values.len() - 1
    }

    /// ∂y_input/∂x_column = `d` (zeros are skipped; repeated entries add up).
    pub fn gradient(&mut self, input: usize, column: usize, d: f64) {
        if d != 0.0 {
            self.gradient.push((input, column, d));
        }
    }

    /// ∂²y_input/∂xᵢ∂xⱼ = `d` for the unordered pair {i, j} (written once; zeros are skipped).
    pub fn curvature(&mut self, input: usize, i: usize, j: usize, d: f64) {
        if d != 0.0 {
            self.curvature.push((input, i, j, d));
        }
    }

    /// The inputs' values y(x).
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// The number of columns (unknowns) the map reads.
    pub fn columns(&self) -> usize {
        self.columns
    }

    /// For each input, its position among the moving inputs (`None` for a constant), and how
    /// many move.
    fn moving(&self) -> (SmallVec<[Option<usize>; 16]>, usize) {
        let mut slot: SmallVec<[Option<usize>; 16]> = smallvec::smallvec![None; self.values.len()];
        let mut count = 0;
        let touched = self
            .gradient
            .iter()
            .map(|g| g.0)
            .chain(self.curvature.iter().map(|c| c.0));
        for k in touched {
            if let Some(s @ None) = slot.get_mut(k) {
                *s = Some(count);
                count += 1;
            }
        }
        (slot, count)
    }
}

/// Writes H = Σᵢ λᵢ·∇²gᵢ(x) for g = f(y(x)) into `out` (row major, N × N with N =
/// [`InnerMap::columns`], both triangles, overwritten), `weights` holding λ (one per row of f).
/// Returns `false` (and leaves `out` zero) when more than [`MAX_MOVING_INPUTS`] inputs move
/// or `out` does not have N² entries.
pub fn weighted_hessian<F: Outer + ?Sized>(
    f: &F,
    map: &InnerMap,
    weights: &[f64],
    out: &mut [f64],
) -> bool {
    out.fill(0.0);
    let n = map.columns;
    if out.len() != n * n {
        return false;
    }
    let inputs = map.values.len();
    if inputs <= HAND_WRITTEN_MAX {
        let mut mu = [0.0; HAND_WRITTEN_MAX];
        let mut hf = [0.0; HAND_WRITTEN_MAX * HAND_WRITTEN_MAX];
        if f.weighted_second_derivatives(
            &map.values,
            weights,
            &mut mu[..inputs],
            &mut hf[..inputs * inputs],
        ) {
            let every: SmallVec<[Option<usize>; 16]> = (0..inputs).map(Some).collect();
            chain_hessian(map, &every, &hf[..inputs * inputs], &mu[..inputs], out);
            return true;
        }
    }
    let (slot, k) = map.moving();
    match k {
        0 => true,
        1 => hessian_pass::<F, 1>(f, map, &slot, weights, out),
        2 => hessian_pass::<F, 2>(f, map, &slot, weights, out),
        3 => hessian_pass::<F, 3>(f, map, &slot, weights, out),
        4 => hessian_pass::<F, 4>(f, map, &slot, weights, out),
        5 => hessian_pass::<F, 5>(f, map, &slot, weights, out),
        6 => hessian_pass::<F, 6>(f, map, &slot, weights, out),
        7 => hessian_pass::<F, 7>(f, map, &slot, weights, out),
        8 => hessian_pass::<F, 8>(f, map, &slot, weights, out),
        _ => false,
    }
}

/// One `Dual2SVec64<K>` pass of f over its K moving inputs, then the chain rule.
fn hessian_pass<F: Outer + ?Sized, const K: usize>(
    f: &F,
    map: &InnerMap,
    slot: &[Option<usize>],
    weights: &[f64],
    out: &mut [f64],
) -> bool {
    let y: SmallVec<[Dual2SVec64<K>; 16]> = map
        .values
        .iter()
        .zip(slot)
        .map(|(v, s)| {
            let d = Dual2SVec64::<K>::from_re(*v);
            match s {
                Some(i) => d.derivative(*i),
                None => d,
            }
        })
        .collect();
    let mut g: SmallVec<[Dual2SVec64<K>; 4]> =
        smallvec::smallvec![Dual2SVec64::<K>::from_re(0.0); weights.len()];
    f.outer(&y, &mut g);
    // F = Σ λᵢ·∇²fᵢ and μ = Σ λᵢ·∇fᵢ over the moving inputs.
    let mut hf = [0.0; HESSIAN_SCRATCH];
    let hf = &mut hf[..K * K];
    let mut mu = [0.0; K];
    for (gi, w) in g.iter().zip(weights) {
        if *w == 0.0 {
            continue;
        }
        if let Some(m) = &gi.v2.0 {
            for (a, row) in hf.chunks_exact_mut(K).enumerate() {
                for (b, slot) in row.iter_mut().enumerate() {
                    *slot += w * m[(a, b)];
                }
            }
        }
        if let Some(v) = &gi.v1.0 {
            for (a, slot) in mu.iter_mut().enumerate() {
                *slot += w * v[a];
            }
        }
    }
    chain_hessian(map, slot, hf, &mu, out);
    true
}

/// Room for F over at most [`MAX_MOVING_INPUTS`] inputs.
const HESSIAN_SCRATCH: usize = MAX_MOVING_INPUTS * MAX_MOVING_INPUTS;

/// out += Jᵀ·F·J + Σₖ μₖ·∇²yₖ, with F (k × k, row major) and μ over the inputs' `slot`s.
fn chain_hessian(map: &InnerMap, slot: &[Option<usize>], hf: &[f64], mu: &[f64], out: &mut [f64]) {
    let n = map.columns;
    let k = mu.len();
    // Jᵀ·F·J over the non-zero entries of J.
    for &(ka, i, ga) in &map.gradient {
        let Some(sa) = slot[ka] else { continue };
        let row = &hf[sa * k..(sa + 1) * k];
        for &(kb, j, gb) in &map.gradient {
            let Some(sb) = slot[kb] else { continue };
            if let Some(o) = out.get_mut(i * n + j) {
                *o += ga * row[sb] * gb;
            }
        }
    }
    // Σₖ μₖ·∇²yₖ.
    for &(input, i, j, d) in &map.curvature {
        let Some(s) = slot[input] else { continue };
        let v = mu[s] * d;
        if let Some(o) = out.get_mut(i * n + j) {
            *o += v;
        }
        if i != j {
            if let Some(o) = out.get_mut(j * n + i) {
                *o += v;
            }
        }
    }
}

/// Writes g = f(y(x)) into `values` and J_g = ∇f·J into `jac` (row major, `values.len()` rows,
/// N columns, overwritten). Returns `false` when more than [`MAX_MOVING_INPUTS`] inputs move
/// or a slice has the wrong length (the outputs are then unspecified).
///
/// ```
/// use camber_solve::derive::composed::{self, InnerMap, Outer};
/// use camber_solve::Scalar;
/// struct Square;
/// impl Outer for Square {
///     fn outer<T: Scalar>(&self, y: &[T], out: &mut [T]) { out[0] = y[0] * y[0]; }
/// }
/// // y = 3x over one unknown x = 2: g = 9x² = 36, g′ = 18x = 36.
/// let mut map = InnerMap::new(1);
/// let y = map.input(6.0);
/// map.gradient(y, 0, 3.0);
/// let (mut g, mut j) = ([0.0], [0.0]);
/// assert!(composed::jacobian(&Square, &map, &mut g, &mut j));
/// assert_eq!((g[0], j[0]), (36.0, 36.0));
/// ```
pub fn jacobian<F: Outer + ?Sized>(
    f: &F,
    map: &InnerMap,
    values: &mut [f64],
    jac: &mut [f64],
) -> bool {
    jac.fill(0.0);
    let n = map.columns;
    if jac.len() != n * values.len() {
        return false;
    }
    let inputs = map.values.len();
    if inputs <= HAND_WRITTEN_MAX && values.len() <= HAND_WRITTEN_MAX {
        let mut df = [0.0; HAND_WRITTEN_MAX * HAND_WRITTEN_MAX];
        let df = &mut df[..values.len() * inputs];
        if f.first_derivatives(&map.values, values, df) {
            for (row, d_row) in df.chunks_exact(inputs).enumerate() {
                for &(k, col, d) in &map.gradient {
                    if let Some(o) = jac.get_mut(row * n + col) {
                        *o += d_row[k] * d;
                    }
                }
            }
            return true;
        }
    }
    let (slot, k) = map.moving();
    match k {
        0 => {
            f.outer(&map.values, values);
            true
        }
        1 => jacobian_pass::<F, 1>(f, map, &slot, values, jac),
        2 => jacobian_pass::<F, 2>(f, map, &slot, values, jac),
        3 => jacobian_pass::<F, 3>(f, map, &slot, values, jac),
        4 => jacobian_pass::<F, 4>(f, map, &slot, values, jac),
        5 => jacobian_pass::<F, 5>(f, map, &slot, values, jac),
        6 => jacobian_pass::<F, 6>(f, map, &slot, values, jac),
        7 => jacobian_pass::<F, 7>(f, map, &slot, values, jac),
        8 => jacobian_pass::<F, 8>(f, map, &slot, values, jac),
        _ => false,
    }
}

/// One `DualSVec64<K>` pass of f over its K moving inputs, then ∇f·J.
fn jacobian_pass<F: Outer + ?Sized, const K: usize>(
    f: &F,
    map: &InnerMap,
    slot: &[Option<usize>],
    values: &mut [f64],
    jac: &mut [f64],
) -> bool {
    let y: SmallVec<[DualSVec64<K>; 16]> = map
        .values
        .iter()
        .zip(slot)
        .map(|(v, s)| {
            let d = DualSVec64::<K>::from_re(*v);
            match s {
                Some(i) => d.derivative(*i),
                None => d,
            }
        })
        .collect();
    let mut g: SmallVec<[DualSVec64<K>; 4]> =
        smallvec::smallvec![DualSVec64::<K>::from_re(0.0); values.len()];
    f.outer(&y, &mut g);
    let n = map.columns;
    for (row, (gi, v)) in g.iter().zip(values.iter_mut()).enumerate() {
        *v = gi.re;
        let Some(df) = &gi.eps.0 else { continue };
        for &(k, col, d) in &map.gradient {
            let Some(s) = slot[k] else { continue };
            if let Some(o) = jac.get_mut(row * n + col) {
                *o += df[s] * d;
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// f(y) = (y₀·y₁/y₂, sin(y₀) + y₂²) with an inner map of curvature: y₀ = a·b,
    /// y₁ = a + 2b + c (linear), y₂ = 5 (constant).
    struct Rows;

    impl Outer for Rows {
        fn outer<T: Scalar>(&self, y: &[T], out: &mut [T]) {
            out[0] = y[0] * y[1] / y[2];
            out[1] = y[0].sin() + y[2] * y[2];
        }
    }

    fn map_at(x: [f64; 3]) -> InnerMap {
        let [a, b, c] = x;
        let mut m = InnerMap::new(3);
        let y0 = m.input(a * b);
        m.gradient(y0, 0, b);
        m.gradient(y0, 1, a);
        m.curvature(y0, 0, 1, 1.0);
        let y1 = m.input(a + 2.0 * b + c);
        m.gradient(y1, 0, 1.0);
        m.gradient(y1, 1, 2.0);
        m.gradient(y1, 2, 1.0);
        m.input(5.0);
        m
    }

    /// The same g written directly, for central differences.
    fn g(x: [f64; 3]) -> [f64; 2] {
        let [a, b, c] = x;
        let (y0, y1) = (a * b, a + 2.0 * b + c);
        [y0 * y1 / 5.0, y0.sin() + 25.0]
    }

    #[test]
    fn jacobian_and_hessian_match_central_differences() {
        let x = [0.7, -1.3, 0.4];
        let w = [1.5, -0.5];
        let map = map_at(x);
        let (mut v, mut j) = ([0.0; 2], [0.0; 6]);
        assert!(jacobian(&Rows, &map, &mut v, &mut j));
        let want = g(x);
        assert_relative_eq!(v[0], want[0], epsilon = 1e-15);
        assert_relative_eq!(v[1], want[1], epsilon = 1e-15);
        let h = 1e-6;
        let weighted = |x: [f64; 3]| {
            let v = g(x);
            w[0] * v[0] + w[1] * v[1]
        };
        for c in 0..3 {
            let (mut p, mut m) = (x, x);
            p[c] += h;
            m[c] -= h;
            let (gp, gm) = (g(p), g(m));
            for r in 0..2 {
                assert_relative_eq!(j[r * 3 + c], (gp[r] - gm[r]) / (2.0 * h), epsilon = 1e-8);
            }
        }
        let mut hess = [0.0; 9];
        assert!(weighted_hessian(&Rows, &map, &w, &mut hess));
        let step = 1e-4;
        for r in 0..3 {
            for c in 0..3 {
                let at = |dr: f64, dc: f64| {
                    let mut y = x;
                    y[r] += dr;
                    y[c] += dc;
                    weighted(y)
                };
                let fd = (at(step, step) - at(step, -step) - at(-step, step) + at(-step, -step))
                    / (4.0 * step * step);
                assert_relative_eq!(hess[r * 3 + c], fd, epsilon = 1e-6);
            }
        }
    }

    /// f(y) = y₀²·y₁ with its derivatives by hand (and a deliberate flag to break them).
    struct Hand(f64);

    impl Outer for Hand {
        fn outer<T: Scalar>(&self, y: &[T], out: &mut [T]) {
            out[0] = y[0] * y[0] * y[1];
        }
        fn first_derivatives(&self, y: &[f64], values: &mut [f64], jacobian: &mut [f64]) -> bool {
            values[0] = y[0] * y[0] * y[1];
            jacobian[0] = self.0 * 2.0 * y[0] * y[1];
            jacobian[1] = y[0] * y[0];
            true
        }
        fn weighted_second_derivatives(
            &self,
            y: &[f64],
            weights: &[f64],
            gradient: &mut [f64],
            hessian: &mut [f64],
        ) -> bool {
            let w = weights[0];
            gradient.copy_from_slice(&[w * 2.0 * y[0] * y[1], w * y[0] * y[0]]);
            let cross = w * 2.0 * y[0];
            hessian.copy_from_slice(&[self.0 * w * 2.0 * y[1], cross, cross, 0.0]);
            true
        }
    }

    /// The same f without hand-written derivatives (dual numbers).
    struct ByDuals;

    impl Outer for ByDuals {
        fn outer<T: Scalar>(&self, y: &[T], out: &mut [T]) {
            Hand(1.0).outer(y, out);
        }
    }

    /// g, J and H (weight 0.7) of a one-row f over two columns.
    fn both<F: Outer>(f: &F, map: &InnerMap) -> ([f64; 1], [f64; 2], [f64; 4]) {
        let (mut v, mut j, mut h) = ([0.0], [0.0; 2], [0.0; 4]);
        assert!(jacobian(f, map, &mut v, &mut j));
        assert!(weighted_hessian(f, map, &[0.7], &mut h));
        (v, j, h)
    }

    #[test]
    fn hand_written_derivatives_are_used_and_agree_with_dual_numbers() {
        // y₀ = a·b (curved), y₁ = a − 2b over x = (a, b).
        let (a, b) = (0.6, -1.4);
        let mut map = InnerMap::new(2);
        let y0 = map.input(a * b);
        map.gradient(y0, 0, b);
        map.gradient(y0, 1, a);
        map.curvature(y0, 0, 1, 1.0);
        let y1 = map.input(a - 2.0 * b);
        map.gradient(y1, 0, 1.0);
        map.gradient(y1, 1, -2.0);
        let duals = both(&ByDuals, &map);
        let hand = both(&Hand(1.0), &map);
        for (x, y) in duals
            .1
            .iter()
            .chain(&duals.2)
            .zip(hand.1.iter().chain(&hand.2))
        {
            assert_relative_eq!(*x, *y, epsilon = 1e-13);
        }
        assert_relative_eq!(duals.0[0], hand.0[0], epsilon = 1e-15);
        // A wrong hand-written derivative shows: the hand path is the one taken.
        let wrong = both(&Hand(3.0), &map);
        assert!((wrong.1[0] - duals.1[0]).abs() > 1e-3 && (wrong.2[0] - duals.2[0]).abs() > 1e-3);
    }

    #[test]
    fn too_many_moving_inputs_or_wrong_lengths_are_refused() {
        let mut map = InnerMap::new(9);
        for c in 0..9 {
            let k = map.input(1.0);
            map.gradient(k, c, 1.0);
        }
        let mut h = [1.0; 81];
        assert!(!weighted_hessian(&Rows, &map, &[1.0, 1.0], &mut h));
        assert!(h.iter().all(|v| *v == 0.0));
        let small = map_at([1.0, 2.0, 3.0]);
        assert!(!weighted_hessian(&Rows, &small, &[1.0, 1.0], &mut [0.0; 8]));
        assert!(!jacobian(&Rows, &small, &mut [0.0; 2], &mut [0.0; 5]));
    }
}
