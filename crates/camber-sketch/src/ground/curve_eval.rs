//! Evaluating a sketch curve C(u) and its derivatives at a generic scalar, with the control
//! points and the parameter u both read from the solver's blocks.
//!
//! The constraints with a free contact parameter are not affine: u moves, so the basis values
//! Nⱼ(u) are themselves unknown. [`CurveBasis`] keeps degree, knots and weights (data, f64) and
//! evaluates
//!
//! C⁽ᵏ⁾(u) = Σⱼ R⁽ᵏ⁾ⱼ(u)·Pⱼ
//!
//! over the p + 1 control points of u's knot span, where Rⱼ = Nⱼ for B-splines (Bézier curves and
//! lines being B-splines on the knots of [`KnotVector::bezier`]) and Rⱼ = wⱼNⱼ/W, W = Σ wⱼNⱼ,
//! for NURBS. The basis functions, their derivatives and the rational quotient come from the
//! geometry kernel ([`camber_geom::basis`]): one evaluator, run in the scalar type so that dual
//! numbers carry ∂/∂u and ∂/∂Pⱼ exactly. This module only adapts it to blocks and adds the
//! fixed-parameter shortcut below.
//!
//! When u is data (a contact at a given parameter, a joint at a curve's end), the weights being
//! data too, C(u), C′(u) and C″(u) are fixed linear combinations of the p + 1 control points of
//! u's span: [`CurveBasis::at`] precomputes those coefficients once and reads only the points
//! whose coefficient is not zero up to the derivative order asked for (at a clamped end, C and
//! C′ read two points), so a residual at a fixed parameter neither evaluates the basis again nor
//! carries the other control points through its derivatives.
//!
//! Hermite and composite curves are cubic B-splines whose control points Q are a fixed linear
//! map Q = M·X of their blocks X (nodes and tangents, [`crate::ground::hermite_chain`]). The basis keeps
//! M and reads the blocks: C⁽ᵏ⁾(u) = Σᵣ N⁽ᵏ⁾ᵣ(u)·Σⱼ Mᵣⱼ·Xⱼ, and at a fixed parameter the
//! coefficient of block j is Σᵣ N⁽ᵏ⁾ᵣ(u)·Mᵣⱼ — still constants, so those constraints stay
//! affine.

use camber_geom::basis::{
    basis_function_derivatives_at, rational_basis_derivatives, INLINE_DEGREE,
};
use camber_geom::KnotVector;
use camber_solve::scalar::{cst, re};
use camber_solve::Scalar;
use smallvec::SmallVec;
use std::sync::Arc;

use crate::ground::entity::Entity;
use crate::ground::hermite_chain::MapRow;

/// The basis values of one evaluation: rows k = 0 … order of p + 1 derivatives dᵏRⱼ/duᵏ.
type BasisRows<T> = SmallVec<[T; 32]>;

/// Per block read, the weights of C, C′, …, C⁗ at one parameter ([`CurveBasis::block_weights`]).
pub(crate) type BlockWeights = SmallVec<[(usize, [f64; 5]); 8]>;

/// Degree, knots and weights of a curve entity, for evaluation at generic scalars.
///
/// ```
/// use camber_sketch::{curve_eval::CurveBasis, Entity};
/// use nalgebra::Point2;
/// let line = Entity::Line([Point2::new(0.0, 0.0), Point2::new(2.0, 4.0)]);
/// let b = CurveBasis::of(&line).ok_or("not a curve")?;
/// let (p, t) = b.eval::<f64>(&[&[0.0, 0.0][..], &[2.0, 4.0][..]], 0.25);
/// // C(¼) = (0.5, 1), C′ = P₁ − P₀ = (2, 4).
/// assert!((p[0] - 0.5).abs() < 1e-15 && (p[1] - 1.0).abs() < 1e-15);
/// assert!((t[0] - 2.0).abs() < 1e-15 && (t[1] - 4.0).abs() < 1e-15);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CurveBasis {
    degree: usize,
    knots: KnotVector<f64>,
    weights: Option<Vec<f64>>,
    /// The number of B-spline control points Q.
    count: usize,
    /// For Hermite and composite curves: row r gives Qᵣ as a combination of blocks.
    map: Option<Arc<[MapRow]>>,
    /// The number of blocks the evaluation reads over the whole curve (`count` without a map).
    blocks: usize,
    /// Set by [`CurveBasis::at`]: the evaluation is at a fixed parameter and reads only the
    /// control points of its span.
    fixed: Option<FixedParameter>,
}

/// C(u) = Σ aᵣ·Qᵣ, C′(u) = Σ bᵣ·Qᵣ and (for `order` 2) C″(u) = Σ cᵣ·Qᵣ at a fixed u, where
/// Qᵣ are the control points the basis reads, with (aᵣ, bᵣ, cᵣ) in `coefficients`.
#[derive(Debug, Clone, PartialEq)]
struct FixedParameter {
    order: usize,
    coefficients: SmallVec<[[f64; 3]; 8]>,
}

impl CurveBasis {
    /// For a basis made by [`CurveBasis::at`]: the coefficients of C, C′ and C″ at its
    /// parameter, one `[c, c′, c″]` per control point it reads (in the order of the indices
    /// `at` returned); `None` for a basis over the whole curve.
    pub fn fixed_coefficients(&self) -> Option<&[[f64; 3]]> {
        self.fixed.as_ref().map(|f| f.coefficients.as_slice())
    }
}

impl CurveBasis {
    /// The basis of a curve entity (`None` for points and circles).
    pub fn of(entity: &Entity) -> Option<Self> {
        let blocks = entity.points().len();
        if let Entity::Hermite(c) | Entity::Composite(c) = entity {
            let map: Arc<[MapRow]> = c.bezier_map().into();
            return Some(Self {
                degree: 3,
                knots: c.knots(),
                weights: None,
                count: map.len(),
                map: Some(map),
                blocks,
                fixed: None,
            });
        }
        let count = blocks;
        let (degree, knots, weights) = match entity {
            Entity::Line(_) => (1, KnotVector::bezier(1), None),
            Entity::Bezier(c) => (c.degree(), KnotVector::bezier(c.degree()), None),
            Entity::BSpline(c) => (c.degree(), c.knots().clone(), None),
            Entity::Nurbs(c) => (c.degree(), c.knots().clone(), Some(c.weights().to_vec())),
            Entity::Point(_) | Entity::Circle { .. } | Entity::Arc(_) => return None,
            Entity::Ellipse { .. } | Entity::EllipticArc { .. } => return None,
            Entity::Hermite(_) | Entity::Composite(_) => return None,
        };
        Some(Self {
            degree,
            knots,
            weights,
            count,
            map: None,
            blocks,
            fixed: None,
        })
    }

    /// The evaluation at the fixed parameter u (clamped to the domain) up to the derivative
    /// `order` (1: C and C′, 2: also C″): the returned basis reads only the control points
    /// whose coefficient in one of those is not zero, listed in the returned indices, and
    /// ignores the parameter passed to [`CurveBasis::eval`] and [`CurveBasis::eval2`]
    /// ([`CurveBasis::eval2`] needs `order` 2).
    ///
    /// ```
    /// use camber_sketch::{curve_eval::CurveBasis, Entity};
    /// use camber_geom::BezierCurve2;
    /// use nalgebra::Point2;
    /// let c = Entity::Bezier(BezierCurve2::try_new(vec![
    ///     Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(2.0, 1.0), Point2::new(3.0, 0.0),
    /// ])?);
    /// let full = CurveBasis::of(&c).ok_or("curve")?;
    /// let (end, points) = full.at(1.0, 1);
    /// assert_eq!(points.as_slice(), &[2, 3]); // C(1) = P₃, C′(1) = 3·(P₃ − P₂)
    /// let (p, t) = end.eval::<f64>(&[&[2.0, 1.0][..], &[3.0, 0.0][..]], 0.0); // u is ignored
    /// assert!((p[0] - 3.0).abs() < 1e-15 && (t[0] - 3.0).abs() < 1e-15 && (t[1] + 3.0).abs() < 1e-15);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn at(&self, u: f64, order: usize) -> (CurveBasis, SmallVec<[usize; 8]>) {
        let order = order.min(2);
        let Some((first, rows)) = self.basis_rows(u, 2) else {
            return (self.clone(), (0..self.blocks).collect());
        };
        let w = self.degree + 1;
        let mut coefficients: SmallVec<[[f64; 3]; 8]> = SmallVec::new();
        let mut points: SmallVec<[usize; 8]> = SmallVec::new();
        for r in 0..w {
            let mut c = [rows[r], rows[w + r], rows[2 * w + r]];
            c[order + 1..].fill(0.0);
            if c.iter().all(|v| *v == 0.0) {
                continue;
            }
            match self.map.as_deref().and_then(|m| m.get(first + r)) {
                None => {
                    coefficients.push(c);
                    points.push(first + r);
                }
                Some(row) => {
                    for (j, m) in row {
                        let k = match points.iter().position(|q| q == j) {
                            Some(k) => k,
                            None => {
                                points.push(*j);
                                coefficients.push([0.0; 3]);
                                coefficients.len() - 1
                            }
                        };
                        for (acc, ck) in coefficients[k].iter_mut().zip(c) {
                            *acc += m * ck;
                        }
                    }
                }
            }
        }
        if self.map.is_some() {
            // Blocks in increasing order, without those whose terms cancelled.
            let mut pairs: SmallVec<[(usize, [f64; 3]); 8]> = points
                .iter()
                .copied()
                .zip(coefficients.iter().copied())
                .collect();
            pairs.retain(|(_, c)| c.iter().any(|v| *v != 0.0));
            pairs.sort_by_key(|(j, _)| *j);
            points = pairs.iter().map(|(j, _)| *j).collect();
            coefficients = pairs.iter().map(|(_, c)| *c).collect();
        }
        let basis = CurveBasis {
            fixed: Some(FixedParameter {
                order,
                coefficients,
            }),
            ..self.clone()
        };
        (basis, points)
    }

    /// The number of control points the evaluation reads: all of them, or the p + 1 of the span
    /// for a basis made by [`CurveBasis::at`].
    pub fn count(&self) -> usize {
        match &self.fixed {
            Some(f) => f.coefficients.len(),
            None => self.blocks,
        }
    }

    /// C′(u) alone: the same as `eval(points, u).1`, without the point's own sum at a fixed
    /// parameter (residuals that only compare directions).
    pub fn tangent<T: Scalar>(&self, points: &[&[T]], u: T) -> [T; 2] {
        match &self.fixed {
            Some(f) => {
                let mut t = [T::zero(); 2];
                for (q, c) in points.iter().zip(&f.coefficients) {
                    if c[1] != 0.0 {
                        let ck = cst::<T>(c[1]);
                        t[0] += ck * q[0];
                        t[1] += ck * q[1];
                    }
                }
                t
            }
            None => self.eval(points, u).1,
        }
    }

    /// C, C′ and (up to the basis' order) C″ at a fixed parameter from the points it reads.
    fn fixed_eval<T: Scalar>(f: &FixedParameter, points: &[&[T]], order: usize) -> [[T; 2]; 3] {
        let mut out = [[T::zero(); 2]; 3];
        for (q, c) in points.iter().zip(&f.coefficients) {
            for (o, ck) in out.iter_mut().zip(c).take(order + 1) {
                if *ck != 0.0 {
                    let ck = cst::<T>(*ck);
                    o[0] += ck * q[0];
                    o[1] += ck * q[1];
                }
            }
        }
        out
    }

    /// The weights of C⁽ᵏ⁾(u) = Σⱼ aⱼₖ·Xⱼ for k = 0 … `order` (at most 4) in plain floats, one
    /// `(j, [aⱼ₀, …, aⱼ₄])` per block j that the evaluation reads with a non-zero weight (the
    /// span's control points, or the blocks they are mapped from), and whether C moves with u
    /// there: false for a basis made by [`CurveBasis::at`] (which ignores u) and outside the
    /// domain (where u is clamped). The derivatives in u of the evaluation at a free parameter
    /// are read from the higher orders: ∂C⁽ᵏ⁾/∂u = C⁽ᵏ⁺¹⁾.
    pub(crate) fn block_weights(&self, u: f64, order: usize) -> (BlockWeights, bool) {
        let mut out = BlockWeights::new();
        if let Some(f) = &self.fixed {
            for (j, c) in f.coefficients.iter().enumerate() {
                out.push((j, [c[0], c[1], c[2], 0.0, 0.0]));
            }
            return (out, false);
        }
        let order = order.min(4);
        let Some((first, rows)) = self.basis_rows(u, order) else {
            return (out, false);
        };
        let (a, b) = self.domain();
        let moves = (a..=b).contains(&u);
        let w = self.degree + 1;
        for r in 0..w {
            let mut c = [0.0; 5];
            for (k, ck) in c.iter_mut().enumerate().take(order + 1) {
                *ck = rows[k * w + r];
            }
            match self.map.as_deref() {
                None => out.push((first + r, c)),
                Some(map) => {
                    for (j, m) in map.get(first + r).into_iter().flatten() {
                        let k = match out.iter().position(|(q, _)| q == j) {
                            Some(k) => k,
                            None => {
                                out.push((*j, [0.0; 5]));
                                out.len() - 1
                            }
                        };
                        for (acc, ck) in out[k].1.iter_mut().zip(c) {
                            *acc += m * ck;
                        }
                    }
                }
            }
        }
        (out, moves)
    }

    /// The control points C(u) and C′(u) depend on at the parameter u (clamped to the domain):
    /// the p + 1 of u's knot span, or every point the basis reads for a basis made by
    /// [`CurveBasis::at`]. Derivatives with respect to the others are zero near u.
    ///
    /// ```
    /// use camber_geom::{BSplineCurve2, KnotVector};
    /// use camber_sketch::{curve_eval::CurveBasis, Entity};
    /// use nalgebra::Point2;
    /// let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0, 1.0, 1.0])?;
    /// let points = (0..7).map(|i| Point2::new(f64::from(i), 0.0)).collect();
    /// let c = Entity::BSpline(BSplineCurve2::try_new(3, knots, points)?);
    /// let b = CurveBasis::of(&c).ok_or("curve")?;
    /// assert_eq!(b.support(0.3), 1..5); // span [0.25, 0.5): P₁ … P₄
    /// assert_eq!(b.support(1.0), 3..7);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn support(&self, u: f64) -> std::ops::Range<usize> {
        if self.fixed.is_some()
            || self.count == 0
            || self.knots.len() < self.count + self.degree + 1
        {
            return 0..self.count();
        }
        let (a, b) = self.domain();
        let k = self.knots.find_span(self.degree, u.clamp(a, b));
        let span = k.saturating_sub(self.degree)..(k + 1).min(self.count);
        match self.map.as_deref() {
            None => span,
            Some(map) => {
                // The blocks the span's control points read, as one range (a superset).
                let touched = map[span].iter().flat_map(|row| row.iter().map(|(j, _)| *j));
                let (lo, hi) = touched.fold((usize::MAX, 0), |(lo, hi), j| (lo.min(j), hi.max(j)));
                if lo > hi {
                    0..self.blocks
                } else {
                    lo..hi + 1
                }
            }
        }
    }

    /// C(u) alone in f64 (u clamped to the domain): the cheap evaluation for dense sampling,
    /// equal to `eval(points, u).0`.
    ///
    /// ```
    /// use camber_sketch::{curve_eval::CurveBasis, Entity};
    /// use nalgebra::Point2;
    /// let line = Entity::Line([Point2::new(0.0, 0.0), Point2::new(2.0, 4.0)]);
    /// let b = CurveBasis::of(&line).ok_or("not a curve")?;
    /// assert_eq!(b.point(&[&[0.0, 0.0][..], &[2.0, 4.0][..]], 0.25), [0.5, 1.0]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn point(&self, points: &[&[f64]], u: f64) -> [f64; 2] {
        if self.fixed.is_some() {
            return self.eval(points, u).0;
        }
        let p = self.degree;
        if p > INLINE_DEGREE
            || points.len() < self.blocks
            || self.count == 0
            || self.knots.len() < self.count + p + 1
        {
            return self.derivatives::<f64, 1>(points, u)[0];
        }
        // The values alone (The NURBS Book A2.2) into a stack row: the same arithmetic as the
        // first row of `basis_rows`, without the derivative table or a returned buffer (this
        // is the inner loop of the clearance scan).
        let (a, b) = self.domain();
        let u = if u < a {
            a
        } else if u > b {
            b
        } else {
            u
        };
        let span = self.knots.find_span(p, u);
        let first = span - p;
        let mut n = [0.0; INLINE_DEGREE + 1];
        self.knots.basis_functions(span, u, p, &mut n[..=p]);
        if let Some(weights) = self.weights.as_deref().and_then(|w| w.get(first..=span)) {
            let mut total = 0.0;
            for (nj, wj) in n.iter_mut().zip(weights) {
                *nj *= *wj;
                total += *nj;
            }
            let inv = 1.0 / total;
            for nj in &mut n[..=p] {
                *nj *= inv;
            }
        }
        let mut c = [0.0; 2];
        for (r, nr) in n[..=p].iter().enumerate() {
            let q = match self.map.as_deref() {
                Some(map) => {
                    let mut q = [0.0; 2];
                    for (j, m) in map.get(first + r).into_iter().flatten() {
                        q[0] += m * points[*j][0];
                        q[1] += m * points[*j][1];
                    }
                    q
                }
                None => [points[first + r][0], points[first + r][1]],
            };
            c[0] += nr * q[0];
            c[1] += nr * q[1];
        }
        c
    }

    /// The parametric domain [u_p, u_{n}] (n = number of control points).
    pub fn domain(&self) -> (f64, f64) {
        let k = self.knots.as_slice();
        let a = k.get(self.degree).copied().unwrap_or(0.0);
        let b = k.get(self.count).copied().unwrap_or(1.0);
        (a, b)
    }

    /// C(u) and C′(u) with the control points `points[j] = [x, y]` (at least
    /// [`CurveBasis::count`] blocks). u is clamped to the domain (a contact parameter is
    /// bounded there; outside, the end span's polynomial would extrapolate).
    pub fn eval<T: Scalar>(&self, points: &[&[T]], u: T) -> ([T; 2], [T; 2]) {
        if let Some(f) = &self.fixed {
            let [c, c1, _] = Self::fixed_eval(f, points, 1);
            return (c, c1);
        }
        let [c, c1] = self.derivatives::<T, 2>(points, u);
        (c, c1)
    }

    /// C(u), C′(u) and C″(u) (for curvature). Same conventions as [`CurveBasis::eval`].
    pub fn eval2<T: Scalar>(&self, points: &[&[T]], u: T) -> [[T; 2]; 3] {
        if let Some(f) = &self.fixed {
            debug_assert!(f.order >= 2, "eval2 on a basis fixed at order {}", f.order);
            return Self::fixed_eval(f, points, 2);
        }
        self.derivatives::<T, 3>(points, u)
    }

    /// C(u), C′(u), C″(u) and C‴(u) (zero for degrees below 3). Same conventions as
    /// [`CurveBasis::eval`]; a basis fixed by [`CurveBasis::at`] gives C‴ = 0 (it keeps
    /// coefficients up to C″ only).
    pub fn eval3<T: Scalar>(&self, points: &[&[T]], u: T) -> [[T; 2]; 4] {
        if let Some(f) = &self.fixed {
            let [c0, c1, c2] = Self::fixed_eval(f, points, 2);
            return [c0, c1, c2, [T::zero(); 2]];
        }
        self.derivatives::<T, 4>(points, u)
    }

    /// C⁽ᵏ⁾(u) = Σⱼ R⁽ᵏ⁾ⱼ(u)·Pⱼ for k = 0 … N − 1 over the whole curve (zeros when the points
    /// or the knots are too few).
    fn derivatives<T: Scalar, const N: usize>(&self, points: &[&[T]], u: T) -> [[T; 2]; N] {
        let mut out = [[T::zero(); 2]; N];
        if points.len() < self.blocks {
            return out;
        }
        let Some((first, rows)) = self.basis_rows(u, N - 1) else {
            return out;
        };
        let w = self.degree + 1;
        let mapped: Option<SmallVec<[[T; 2]; 4]>> = self.map.as_deref().map(|map| {
            (0..w)
                .map(|r| {
                    let mut q = [T::zero(); 2];
                    for (j, m) in map.get(first + r).into_iter().flatten() {
                        let m = cst::<T>(*m);
                        q[0] += m * points[*j][0];
                        q[1] += m * points[*j][1];
                    }
                    q
                })
                .collect()
        });
        for (k, c) in out.iter_mut().enumerate() {
            for (r, n) in rows[k * w..(k + 1) * w].iter().enumerate() {
                let q: &[T] = match &mapped {
                    Some(m) => &m[r],
                    None => points[first + r],
                };
                c[0] += *n * q[0];
                c[1] += *n * q[1];
            }
        }
        out
    }

    /// The index of the first of the p + 1 basis functions that can be non-zero at u (clamped
    /// to the domain) and their derivatives up to `order` (rational for NURBS), by the geometry
    /// kernel's evaluator with the knots as data. `None` without a valid knot vector.
    fn basis_rows<T: Scalar>(&self, u: T, order: usize) -> Option<(usize, BasisRows<T>)> {
        let p = self.degree;
        if self.count == 0 || self.knots.len() < self.count + p + 1 {
            return None;
        }
        let (a, b) = self.domain();
        let u = if re(u) < a {
            cst(a)
        } else if re(u) > b {
            cst(b)
        } else {
            u
        };
        let span = self.knots.find_span(p, re(u));
        let first = span - p;
        let mut rows: BasisRows<T> = smallvec::smallvec![T::zero(); (order + 1) * (p + 1)];
        basis_function_derivatives_at(self.knots.as_slice(), span, u, p, order, &mut rows);
        if let Some(weights) = self.weights.as_deref().and_then(|w| w.get(first..=span)) {
            rational_basis_derivatives(weights, order, &mut rows);
        }
        Some((first, rows))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use camber_geom::{BSplineCurve2, KnotVector, NurbsCurve2, ParametricCurve};
    use nalgebra::Point2;

    fn blocks(pts: &[Point2<f64>]) -> Vec<[f64; 2]> {
        pts.iter().map(|p| [p.x, p.y]).collect()
    }

    #[test]
    fn matches_the_kernel_for_bsplines_and_nurbs() -> Result<(), Box<dyn std::error::Error>> {
        let pts = vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 2.0),
            Point2::new(2.0, -1.0),
            Point2::new(3.0, 1.0),
            Point2::new(4.0, 0.5),
        ];
        let knots = vec![0.0, 0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0, 1.0];
        let bs = BSplineCurve2::try_new(3, KnotVector::try_new(knots.clone())?, pts.clone())?;
        let nu = NurbsCurve2::try_new(
            3,
            KnotVector::try_new(knots)?,
            pts.clone(),
            vec![1.0, 0.5, 2.0, 1.0, 0.8],
        )?;
        let raw = blocks(&pts);
        let refs: Vec<&[f64]> = raw.iter().map(|b| &b[..]).collect();
        for e in [Entity::BSpline(bs), Entity::Nurbs(nu)] {
            let basis = CurveBasis::of(&e).ok_or("curve")?;
            for u in [0.0, 0.1, 0.4, 0.55, 0.99, 1.0] {
                let (c, c1) = basis.eval::<f64>(&refs, u);
                let (p, d) = match &e {
                    Entity::BSpline(b) => (b.point(u)?, b.derivative(u)?),
                    Entity::Nurbs(b) => (b.point(u)?, b.derivative(u)?),
                    _ => return Err("kind".into()),
                };
                assert_relative_eq!(c[0], p.x, epsilon = 1e-12);
                assert_relative_eq!(c[1], p.y, epsilon = 1e-12);
                let point_only = basis.point(&refs, u);
                assert_relative_eq!(point_only[0], p.x, epsilon = 1e-12);
                assert_relative_eq!(point_only[1], p.y, epsilon = 1e-12);
                assert_relative_eq!(c1[0], d.x, epsilon = 1e-10);
                assert_relative_eq!(c1[1], d.y, epsilon = 1e-10);
                let second = match &e {
                    Entity::BSpline(b) => b.second_order(u)?,
                    Entity::Nurbs(b) => b.second_order(u)?,
                    _ => return Err("kind".into()),
                };
                let [e0, e1, e2] = basis.eval2::<f64>(&refs, u);
                for (mine, theirs) in [(e0, second[0]), (e1, second[1]), (e2, second[2])] {
                    assert_relative_eq!(mine[0], theirs.x, epsilon = 1e-8, max_relative = 1e-9);
                    assert_relative_eq!(mine[1], theirs.y, epsilon = 1e-8, max_relative = 1e-9);
                }
            }
        }
        Ok(())
    }

    /// C‴ of [`CurveBasis::eval3`] against central differences of C″ (inside the spans, for a
    /// B-spline and a NURBS), and its lower derivatives equal to [`CurveBasis::eval2`]'s.
    #[test]
    fn the_third_derivative_matches_differences_of_the_second(
    ) -> Result<(), Box<dyn std::error::Error>> {
        let pts = vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 2.0),
            Point2::new(2.0, -1.0),
            Point2::new(3.0, 1.0),
            Point2::new(4.0, 0.5),
        ];
        let knots = vec![0.0, 0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0, 1.0];
        let bs = BSplineCurve2::try_new(3, KnotVector::try_new(knots.clone())?, pts.clone())?;
        let nu = NurbsCurve2::try_new(
            3,
            KnotVector::try_new(knots)?,
            pts.clone(),
            vec![1.0, 0.5, 2.0, 1.0, 0.8],
        )?;
        let raw = blocks(&pts);
        let refs: Vec<&[f64]> = raw.iter().map(|b| &b[..]).collect();
        for e in [Entity::BSpline(bs), Entity::Nurbs(nu)] {
            let basis = CurveBasis::of(&e).ok_or("curve")?;
            for u in [0.1, 0.3, 0.55, 0.9] {
                let c = basis.eval3::<f64>(&refs, u);
                let d = basis.eval2::<f64>(&refs, u);
                for k in 0..3 {
                    for i in 0..2 {
                        assert_relative_eq!(
                            c[k][i],
                            d[k][i],
                            epsilon = 1e-12,
                            max_relative = 1e-12
                        );
                    }
                }
                let h = 1e-5;
                let plus = basis.eval2::<f64>(&refs, u + h)[2];
                let minus = basis.eval2::<f64>(&refs, u - h)[2];
                for i in 0..2 {
                    let central = (plus[i] - minus[i]) / (2.0 * h);
                    assert_relative_eq!(c[3][i], central, epsilon = 1e-5, max_relative = 1e-6);
                }
            }
        }
        Ok(())
    }

    /// The point-only evaluation of the clearance scan equals C of the full evaluation for a
    /// composite curve (control points mapped from nodes and tangents), inside and beyond the
    /// domain (clamped).
    #[test]
    fn the_point_alone_agrees_with_the_full_evaluation_through_the_map(
    ) -> Result<(), Box<dyn std::error::Error>> {
        use crate::ground::hermite_chain::{HermiteChain, Join};
        use nalgebra::Vector2;
        let nodes = vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(2.5, 0.5),
        ];
        let tangents = vec![
            Vector2::new(1.0, 2.0),
            Vector2::new(1.5, -0.5),
            Vector2::new(0.5, -1.0),
        ];
        let chain = HermiteChain::try_new(nodes, tangents, vec![Join::Smooth])?;
        let e = Entity::Composite(chain);
        let basis = CurveBasis::of(&e).ok_or("curve")?;
        let raw: Vec<[f64; 2]> = e.points().iter().map(|p| [p.x, p.y]).collect();
        let refs: Vec<&[f64]> = raw.iter().map(|b| &b[..]).collect();
        let (a, b) = basis.domain();
        for u in [a - 0.5, a, 0.3, 1.0, 1.7, b, b + 1.0] {
            let full = basis.eval::<f64>(&refs, u).0;
            let alone = basis.point(&refs, u);
            assert_relative_eq!(alone[0], full[0], epsilon = 1e-14);
            assert_relative_eq!(alone[1], full[1], epsilon = 1e-14);
        }
        // The curve passes through its middle node at u = 1.
        let mid = basis.point(&refs, 1.0);
        assert_relative_eq!(mid[0], 1.0, epsilon = 1e-14);
        assert_relative_eq!(mid[1], 1.0, epsilon = 1e-14);
        Ok(())
    }

    #[test]
    fn a_fixed_parameter_reads_its_span_and_agrees_with_the_full_evaluation(
    ) -> Result<(), Box<dyn std::error::Error>> {
        let pts = vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 2.0),
            Point2::new(2.0, -1.0),
            Point2::new(3.0, 1.0),
            Point2::new(4.0, 0.5),
            Point2::new(5.0, 1.5),
        ];
        let knots = vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.6, 1.0, 1.0, 1.0, 1.0];
        let nu = NurbsCurve2::try_new(
            3,
            KnotVector::try_new(knots)?,
            pts.clone(),
            vec![1.0, 0.5, 2.0, 1.0, 0.8, 1.2],
        )?;
        let raw = blocks(&pts);
        let refs: Vec<&[f64]> = raw.iter().map(|b| &b[..]).collect();
        let full = CurveBasis::of(&Entity::Nurbs(nu)).ok_or("curve")?;
        // (u, points read for C and C′, for C″ too): clamped ends need fewer points, and at the
        // simple knot 0.6 the function starting there is zero with its first two derivatives.
        let cases: [(f64, &[usize], &[usize]); 4] = [
            (0.0, &[0, 1], &[0, 1, 2]),
            (0.45, &[1, 2, 3, 4], &[1, 2, 3, 4]),
            (0.6, &[2, 3, 4], &[2, 3, 4]),
            (1.0, &[4, 5], &[3, 4, 5]),
        ];
        for (u, first_order, second_order) in cases {
            let [a0, a1, a2] = full.eval2::<f64>(&refs, u);
            let (fixed, points) = full.at(u, 2);
            assert_eq!(points.as_slice(), second_order, "u = {u}");
            assert_eq!(fixed.count(), second_order.len());
            let read: Vec<&[f64]> = points.iter().map(|j| refs[*j]).collect();
            let [b0, b1, b2] = fixed.eval2::<f64>(&read, 0.77);
            for (x, y) in [(a0, b0), (a1, b1), (a2, b2)] {
                assert_relative_eq!(x[0], y[0], epsilon = 1e-10, max_relative = 1e-12);
                assert_relative_eq!(x[1], y[1], epsilon = 1e-10, max_relative = 1e-12);
            }
            let (fixed, points) = full.at(u, 1);
            assert_eq!(points.as_slice(), first_order, "u = {u}");
            let read: Vec<&[f64]> = points.iter().map(|j| refs[*j]).collect();
            let (c, c1) = fixed.eval::<f64>(&read, 0.0);
            assert_relative_eq!(c[0], a0[0], epsilon = 1e-12);
            assert_relative_eq!(c[1], a0[1], epsilon = 1e-12);
            assert_relative_eq!(c1[0], a1[0], epsilon = 1e-10, max_relative = 1e-12);
            assert_relative_eq!(c1[1], a1[1], epsilon = 1e-10, max_relative = 1e-12);
        }
        Ok(())
    }
}
