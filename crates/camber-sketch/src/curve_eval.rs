//! Evaluating a sketch curve C(u) and its tangent C′(u) at a generic scalar, with the control
//! points and the parameter u both read from the solver's blocks.
//!
//! The constraints with a free contact parameter are not affine: u moves, so the basis values
//! Nⱼ(u) are themselves unknown. [`CurveBasis`] keeps degree, knots and weights (data, f64) and
//! evaluates, for the knot span k with u_k ≤ u < u_{k+1} (found on the real part of u),
//!
//! C(u) = Σⱼ Nⱼ,ₚ(u)·Pⱼ,  C′(u) = Σⱼ N′ⱼ,ₚ(u)·Pⱼ,
//! N′ⱼ,ₚ = p·Nⱼ,ₚ₋₁/(u_{j+p} − u_j) − p·Nⱼ₊₁,ₚ₋₁/(u_{j+p+1} − u_{j+1})  (0/0 read as 0),
//!
//! with the Cox–de Boor triangle run in the scalar type, so dual numbers carry ∂/∂u and
//! ∂/∂Pⱼ exactly. For NURBS with weights wⱼ, W = Σ wⱼNⱼ and W′ = Σ wⱼN′ⱼ:
//! C = Σ wⱼNⱼPⱼ / W and C′ = (Σ wⱼN′ⱼPⱼ − W′·C) / W. Lines and Bézier curves are B-splines on
//! clamped knots over [0, 1].
//!
//! When u is data (a contact at a given parameter, a joint at a curve's end), the weights being
//! data too, C(u), C′(u) and C″(u) are fixed linear combinations of the p + 1 control points of
//! u's span: [`CurveBasis::at`] precomputes those coefficients once and reads only the points
//! whose coefficient is not zero up to the derivative order asked for (at a clamped end, C and
//! C′ read two points), so a residual at a fixed parameter neither evaluates the basis again nor
//! carries the other control points through its derivatives.

use camber_solve::scalar::{cst, from_usize, re};
use camber_solve::Scalar;
use smallvec::SmallVec;

use crate::entity::Entity;

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
    knots: Vec<f64>,
    weights: Option<Vec<f64>>,
    count: usize,
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
        let count = entity.points().len();
        let clamped01 = |p: usize| {
            let mut k = vec![0.0; p + 1];
            k.extend(std::iter::repeat_n(1.0, p + 1));
            k
        };
        let (degree, knots, weights) = match entity {
            Entity::Line(_) => (1, clamped01(1), None),
            Entity::Bezier(c) => (c.degree(), clamped01(c.degree()), None),
            Entity::BSpline(c) => (c.degree(), c.knots().as_slice().to_vec(), None),
            Entity::Nurbs(c) => (
                c.degree(),
                c.knots().as_slice().to_vec(),
                Some(c.weights().to_vec()),
            ),
            Entity::Point(_) | Entity::Circle { .. } => return None,
        };
        Some(Self {
            degree,
            knots,
            weights,
            count,
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
        let p = self.degree;
        let order = order.min(2);
        let Some((first, [n0, n1, n2, _])) = self.basis_derivatives(u, false) else {
            return (self.clone(), (0..self.count).collect());
        };
        // Rᵣ = wᵣNᵣ/W and its derivatives (the rational basis; Nᵣ itself without weights).
        let (mut w0, mut w1, mut w2) = (0.0, 0.0, 0.0);
        for r in 0..=p {
            let w = self.weight(first + r);
            w0 += w * n0[r];
            w1 += w * n1[r];
            w2 += w * n2[r];
        }
        let mut coefficients: SmallVec<[[f64; 3]; 8]> = SmallVec::new();
        let mut points = SmallVec::new();
        for r in 0..=p {
            let w = self.weight(first + r);
            let r0 = w * n0[r] / w0;
            let r1 = (w * n1[r] - w1 * r0) / w0;
            let r2 = (w * n2[r] - 2.0 * w1 * r1 - w2 * r0) / w0;
            let mut c = [r0, r1, r2];
            c[order + 1..].fill(0.0);
            if c.iter().any(|v| *v != 0.0) {
                coefficients.push(c);
                points.push(first + r);
            }
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
            None => self.count,
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
        let k = self.span(u.clamp(a, b));
        k.saturating_sub(self.degree)..(k + 1).min(self.count)
    }

    /// C(u) alone in f64 (u clamped to the domain), by the Cox–de Boor triangle of the p + 1
    /// basis values without their derivatives: the cheap evaluation for dense sampling. Equal to
    /// `eval(points, u).0` up to rounding.
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
        let p = self.degree;
        if self.fixed.is_some()
            || self.count == 0
            || self.knots.len() < self.count + p + 1
            || points.len() < self.count
        {
            return self.eval(points, u).0;
        }
        let (a, b) = self.domain();
        let u = u.clamp(a, b);
        let k = self.span(u);
        let kn = &self.knots;
        let mut n: SmallVec<[f64; 8]> = smallvec::smallvec![0.0; p + 1];
        let mut left: SmallVec<[f64; 8]> = smallvec::smallvec![0.0; p + 1];
        let mut right: SmallVec<[f64; 8]> = smallvec::smallvec![0.0; p + 1];
        n[0] = 1.0;
        for j in 1..=p {
            left[j] = u - kn[k + 1 - j];
            right[j] = kn[k + j] - u;
            let mut saved = 0.0;
            for r in 0..j {
                let den = right[r + 1] + left[j - r];
                let temp = if den.abs() > 0.0 { n[r] / den } else { 0.0 };
                n[r] = saved + right[r + 1] * temp;
                saved = left[j - r] * temp;
            }
            n[j] = saved;
        }
        let first = k - p;
        let (mut c, mut w_sum) = ([0.0; 2], 0.0);
        for (r, nr) in n.iter().enumerate() {
            let w = self.weight(first + r) * nr;
            let q = points[first + r];
            c[0] += w * q[0];
            c[1] += w * q[1];
            w_sum += w;
        }
        if self.weights.is_some() {
            c[0] /= w_sum;
            c[1] /= w_sum;
        }
        c
    }

    /// The parametric domain [u_p, u_{n}] (n = number of control points).
    pub fn domain(&self) -> (f64, f64) {
        let a = self.knots.get(self.degree).copied().unwrap_or(0.0);
        let b = self.knots.get(self.count).copied().unwrap_or(1.0);
        (a, b)
    }

    /// The span k with u_k ≤ u < u_{k+1}, clamped to the domain (the last non-empty span at
    /// its end).
    fn span(&self, u: f64) -> usize {
        let (p, n) = (self.degree, self.count);
        let (a, b) = self.domain();
        if u >= b || u.is_nan() {
            return n - 1;
        }
        if u <= a {
            let mut k = p;
            while k + 1 < n && self.knots[k + 1] <= a {
                k += 1;
            }
            return k;
        }
        let (mut lo, mut hi) = (p, n);
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if u < self.knots[mid] {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        lo
    }

    /// C(u) and C′(u) with the control points `points[j] = [x, y]` (at least
    /// [`CurveBasis::count`] blocks). u is clamped to the domain (a contact parameter is
    /// bounded there; outside, the end span's polynomial would extrapolate).
    pub fn eval<T: Scalar>(&self, points: &[&[T]], u: T) -> ([T; 2], [T; 2]) {
        if let Some(f) = &self.fixed {
            let [c, c1, _] = Self::fixed_eval(f, points, 1);
            return (c, c1);
        }
        let zero = [T::zero(), T::zero()];
        let p = self.degree;
        if self.count == 0 || self.knots.len() < self.count + p + 1 || points.len() < self.count {
            return (zero, zero);
        }
        let (a, b) = self.domain();
        let u = if re(u) < a {
            cst(a)
        } else if re(u) > b {
            cst(b)
        } else {
            u
        };
        let k = self.span(re(u));
        let kn = &self.knots;
        // Cox–de Boor: n holds degree-j functions N_{k−j..k}; `low` keeps degree p − 1.
        let mut n: SmallVec<[T; 8]> = smallvec::smallvec![T::zero(); p + 1];
        let mut low: SmallVec<[T; 8]> = smallvec::smallvec![T::zero(); p + 1];
        let mut left: SmallVec<[T; 8]> = smallvec::smallvec![T::zero(); p + 1];
        let mut right: SmallVec<[T; 8]> = smallvec::smallvec![T::zero(); p + 1];
        n[0] = T::one();
        for j in 1..=p {
            if j == p {
                low.copy_from_slice(&n);
            }
            left[j] = u - cst(kn[k + 1 - j]);
            right[j] = cst::<T>(kn[k + j]) - u;
            let mut saved = T::zero();
            for r in 0..j {
                let den = right[r + 1] + left[j - r];
                let temp = if re(den).abs() > 0.0 {
                    n[r] / den
                } else {
                    T::zero()
                };
                n[r] = saved + right[r + 1] * temp;
                saved = left[j - r] * temp;
            }
            n[j] = saved;
        }
        if p == 0 {
            low[0] = T::zero();
        }
        let first = k - p;
        let pf: T = from_usize(p);
        let mut dn: SmallVec<[T; 8]> = smallvec::smallvec![T::zero(); p + 1];
        for r in 0..=p {
            let i = first + r;
            let mut d = T::zero();
            if r >= 1 {
                let den = kn[i + p] - kn[i];
                if den.abs() > 0.0 {
                    d += pf * low[r - 1] / cst(den);
                }
            }
            if r < p {
                let den = kn[i + p + 1] - kn[i + 1];
                if den.abs() > 0.0 {
                    d -= pf * low[r] / cst(den);
                }
            }
            dn[r] = d;
        }
        let (mut c, mut c1) = (zero, zero);
        match &self.weights {
            None => {
                for r in 0..=p {
                    let q = points[first + r];
                    for k2 in 0..2 {
                        c[k2] += n[r] * q[k2];
                        c1[k2] += dn[r] * q[k2];
                    }
                }
            }
            Some(w) => {
                let (mut big_w, mut big_w1) = (T::zero(), T::zero());
                for r in 0..=p {
                    let wr = cst::<T>(w.get(first + r).copied().unwrap_or(1.0));
                    big_w += wr * n[r];
                    big_w1 += wr * dn[r];
                    let q = points[first + r];
                    for k2 in 0..2 {
                        c[k2] += wr * n[r] * q[k2];
                        c1[k2] += wr * dn[r] * q[k2];
                    }
                }
                for k2 in 0..2 {
                    c[k2] /= big_w;
                    c1[k2] = (c1[k2] - big_w1 * c[k2]) / big_w;
                }
            }
        }
        (c, c1)
    }
}

impl CurveBasis {
    /// C(u), C′(u) and C″(u) (for curvature). The basis derivatives come from the Cox–de Boor
    /// triangle kept at degrees p − 2, p − 1 and p:
    /// N′ⱼ,ₚ = p·(Nⱼ,ₚ₋₁/Δⱼ − Nⱼ₊₁,ₚ₋₁/Δⱼ₊₁) with Δⱼ = u_{j+p} − u_j, applied twice for N″;
    /// for NURBS, C″ = (Σ wⱼN″ⱼPⱼ − 2W′·C′ − W″·C)/W. Same conventions as [`CurveBasis::eval`].
    pub fn eval2<T: Scalar>(&self, points: &[&[T]], u: T) -> [[T; 2]; 3] {
        if let Some(f) = &self.fixed {
            debug_assert!(f.order >= 2, "eval2 on a basis fixed at order {}", f.order);
            return Self::fixed_eval(f, points, 2);
        }
        let zero = [T::zero(), T::zero()];
        if points.len() < self.count {
            return [zero; 3];
        }
        let Some((first, [n0, n1, n2, _])) = self.basis_derivatives(u, false) else {
            return [zero; 3];
        };
        let mut c = [zero; 3];
        let (mut w0, mut w1, mut w2) = (T::zero(), T::zero(), T::zero());
        for r in 0..n0.len() {
            let wr = cst::<T>(self.weight(first + r));
            w0 += wr * n0[r];
            w1 += wr * n1[r];
            w2 += wr * n2[r];
            let q = points[first + r];
            for d in 0..2 {
                c[0][d] += wr * n0[r] * q[d];
                c[1][d] += wr * n1[r] * q[d];
                c[2][d] += wr * n2[r] * q[d];
            }
        }
        if self.weights.is_some() {
            // Per coordinate: C = A/W, C′ = (A′ − W′C)/W, C″ = (A″ − 2W′C′ − W″C)/W.
            let rational = |a0: T, a1: T, a2: T| {
                let c0 = a0 / w0;
                let c1 = (a1 - w1 * c0) / w0;
                (c0, c1, (a2 - cst::<T>(2.0) * w1 * c1 - w2 * c0) / w0)
            };
            let (x0, x1, x2) = rational(c[0][0], c[1][0], c[2][0]);
            let (y0, y1, y2) = rational(c[0][1], c[1][1], c[2][1]);
            return [[x0, y0], [x1, y1], [x2, y2]];
        }
        c
    }

    /// C(u), C′(u), C″(u) and C‴(u) (the third derivative from one more application of the
    /// derivative recursion, zero for degrees below 3; for NURBS,
    /// C‴ = (Σ wⱼN‴ⱼPⱼ − 3W′·C″ − 3W″·C′ − W‴·C)/W). Same conventions as
    /// [`CurveBasis::eval`]; a basis fixed by [`CurveBasis::at`] gives C‴ = 0 (it keeps
    /// coefficients up to C″ only).
    pub fn eval3<T: Scalar>(&self, points: &[&[T]], u: T) -> [[T; 2]; 4] {
        let zero = [T::zero(), T::zero()];
        if let Some(f) = &self.fixed {
            let [c0, c1, c2] = Self::fixed_eval(f, points, 2);
            return [c0, c1, c2, zero];
        }
        if points.len() < self.count {
            return [zero; 4];
        }
        let Some((first, n)) = self.basis_derivatives(u, true) else {
            return [zero; 4];
        };
        let mut c = [zero; 4];
        let mut w = [T::zero(); 4];
        for r in 0..n[0].len() {
            let wr = cst::<T>(self.weight(first + r));
            let q = points[first + r];
            for k in 0..4 {
                w[k] += wr * n[k][r];
                for d in 0..2 {
                    c[k][d] += wr * n[k][r] * q[d];
                }
            }
        }
        if self.weights.is_some() {
            // Per coordinate: C = A/W, C′ = (A′ − W′C)/W, C″ = (A″ − 2W′C′ − W″C)/W,
            // C‴ = (A‴ − 3W′C″ − 3W″C′ − W‴C)/W.
            let (two, three) = (cst::<T>(2.0), cst::<T>(3.0));
            let rational = |a: [T; 4]| {
                let c0 = a[0] / w[0];
                let c1 = (a[1] - w[1] * c0) / w[0];
                let c2 = (a[2] - two * w[1] * c1 - w[2] * c0) / w[0];
                let c3 = (a[3] - three * w[1] * c2 - three * w[2] * c1 - w[3] * c0) / w[0];
                [c0, c1, c2, c3]
            };
            let x = rational([c[0][0], c[1][0], c[2][0], c[3][0]]);
            let y = rational([c[0][1], c[1][1], c[2][1], c[3][1]]);
            return [[x[0], y[0]], [x[1], y[1]], [x[2], y[2]], [x[3], y[3]]];
        }
        c
    }

    /// The weight of control point j (1 for non-rational curves).
    fn weight(&self, j: usize) -> f64 {
        self.weights
            .as_ref()
            .and_then(|w| w.get(j).copied())
            .unwrap_or(1.0)
    }

    /// The index of the first of the p + 1 basis functions that can be non-zero at u (clamped
    /// to the domain) and their values, first and second derivatives (and third when `third`,
    /// else zeros), from the Cox–de Boor triangle kept at degrees p − 3 to p:
    /// N′ⱼ,ₚ = p·(Nⱼ,ₚ₋₁/Δⱼ − Nⱼ₊₁,ₚ₋₁/Δⱼ₊₁) with Δⱼ = u_{j+p} − u_j (0/0 read as 0),
    /// applied twice for N″ and three times for N‴. `None` for a basis without a valid knot
    /// vector.
    #[allow(clippy::type_complexity)] // four parallel arrays of p + 1 values
    fn basis_derivatives<T: Scalar>(
        &self,
        u: T,
        third: bool,
    ) -> Option<(usize, [SmallVec<[T; 8]>; 4])> {
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
        let k = self.span(re(u));
        let kn = &self.knots;
        // levels[d] holds the degree-d functions N_{k−d..k}.
        let mut levels: SmallVec<[SmallVec<[T; 8]>; 8]> = SmallVec::new();
        let mut n: SmallVec<[T; 8]> = smallvec::smallvec![T::zero(); p + 1];
        n[0] = T::one();
        levels.push(n.clone());
        for j in 1..=p {
            let mut next: SmallVec<[T; 8]> = smallvec::smallvec![T::zero(); p + 1];
            for r in 0..=j {
                // N_{i,j} with i = k − j + r, from N_{i,j−1} (index r − 1) and N_{i+1,j−1} (r).
                let i = k + r - j;
                let mut v = T::zero();
                if r >= 1 {
                    let den = kn[i + j] - kn[i];
                    if den.abs() > 0.0 {
                        v += (u - cst(kn[i])) / cst(den) * n[r - 1];
                    }
                }
                if r < j {
                    let den = kn[i + j + 1] - kn[i + 1];
                    if den.abs() > 0.0 {
                        v += (cst::<T>(kn[i + j + 1]) - u) / cst(den) * n[r];
                    }
                }
                next[r] = v;
            }
            n = next;
            levels.push(n.clone());
        }
        // The derivative of degree-d functions (d + 1 of them) from degree-(d − 1) values.
        let derive = |d: usize, lower: &[T]| -> SmallVec<[T; 8]> {
            let mut out: SmallVec<[T; 8]> = smallvec::smallvec![T::zero(); p + 1];
            if d == 0 {
                return out;
            }
            let df: T = from_usize(d);
            for r in 0..=d {
                let i = k + r - d;
                let mut v = T::zero();
                if r >= 1 {
                    let den = kn[i + d] - kn[i];
                    if den.abs() > 0.0 {
                        v += df * lower[r - 1] / cst(den);
                    }
                }
                if r < d {
                    let den = kn[i + d + 1] - kn[i + 1];
                    if den.abs() > 0.0 {
                        v -= df * lower[r] / cst(den);
                    }
                }
                out[r] = v;
            }
            out
        };
        let n0 = levels[p].clone();
        let n1 = if p >= 1 {
            derive(p, &levels[p - 1])
        } else {
            smallvec::smallvec![T::zero(); p + 1]
        };
        let n2 = if p >= 2 {
            let lower1 = derive(p - 1, &levels[p - 2]);
            derive(p, &lower1)
        } else {
            smallvec::smallvec![T::zero(); p + 1]
        };
        let n3 = if p >= 3 && third {
            let lower2 = derive(p - 2, &levels[p - 3]);
            let lower1 = derive(p - 1, &lower2);
            derive(p, &lower1)
        } else {
            smallvec::smallvec![T::zero(); p + 1]
        };
        Some((k - p, [n0, n1, n2, n3]))
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
