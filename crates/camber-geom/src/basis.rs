//! B-spline basis functions N_{i,p}(u) and their derivatives (The NURBS Book A2.2 and A2.3).
//!
//! At a parameter u in knot span i only the p + 1 functions N_{i−p,p}, …, N_{i,p} are non-zero;
//! both routines return exactly those, in that order. They write into caller-provided slices and
//! keep their triangular tables on the stack for degrees up to [`INLINE_DEGREE`], so evaluation
//! in a hot loop does not allocate.

use smallvec::{smallvec, SmallVec};

use crate::knots::KnotVector;
use crate::scalar::{cst, from_usize, Scalar};

/// Degrees up to this one evaluate with stack storage only; higher degrees still work but
/// allocate their scratch tables.
pub const INLINE_DEGREE: usize = 7;

const ROW: usize = INLINE_DEGREE + 1;

/// Scratch for one row of p + 1 values.
type Row<T> = SmallVec<[T; ROW]>;

impl<T: Scalar> KnotVector<T> {
    /// The p + 1 non-zero basis functions N_{span−p,p}(u) … N_{span,p}(u) into `out`
    /// (length p + 1), computed by the triangular Cox–de Boor recurrence. They are non-negative
    /// and sum to one inside the domain.
    ///
    /// # Panics
    /// When `span` is not a span of this knot vector for `degree` (p ≤ span < len − p − 1, as
    /// [`find_span`](Self::find_span) returns for a vector that passed
    /// [`check_for`](Self::check_for)) or `out` has fewer than p + 1 entries: these are
    /// programming errors, not bad input; the curve types never call it otherwise.
    ///
    /// ```
    /// use camber_geom::KnotVector;
    /// let k = KnotVector::try_new(vec![0., 0., 0., 1., 2., 3., 4., 4., 5., 5., 5.]).unwrap();
    /// let mut n = [0.0_f64; 3];
    /// k.basis_functions(4, 2.5, 2, &mut n);
    /// // The NURBS Book example 2.3: N = (1/8, 6/8, 1/8).
    /// assert!((n[0] - 0.125).abs() < 1e-15 && (n[1] - 0.75).abs() < 1e-15);
    /// ```
    pub fn basis_functions(&self, span: usize, u: T, degree: usize, out: &mut [T]) {
        values(self.as_slice(), |k| k, span, u, degree, out);
    }

    /// The non-zero basis functions and their derivatives up to order `n_derivs` at u:
    /// `out[k * (p + 1) + j]` = dᵏ/duᵏ N_{span−p+j,p}(u), for k = 0 … n_derivs (`out` has
    /// (n_derivs + 1)(p + 1) entries). Derivatives above the degree are zero.
    ///
    /// # Panics
    /// Under the same conditions as [`basis_functions`](Self::basis_functions), or when `out`
    /// is shorter than (n_derivs + 1)(p + 1).
    ///
    /// ```
    /// use camber_geom::KnotVector;
    /// let k = KnotVector::try_new(vec![0., 0., 0., 1., 1., 1.]).unwrap();
    /// let mut d = [0.0_f64; 6];
    /// k.basis_function_derivatives(2, 0.5, 2, 1, &mut d);
    /// // Bernstein basis of degree 2: B′ = (−2(1−u), 2 − 4u, 2u) = (−1, 0, 1) at u = 1/2.
    /// assert!((d[3] + 1.0).abs() < 1e-15 && d[4].abs() < 1e-15 && (d[5] - 1.0).abs() < 1e-15);
    /// ```
    pub fn basis_function_derivatives(
        &self,
        span: usize,
        u: T,
        degree: usize,
        n_derivs: usize,
        out: &mut [T],
    ) {
        derivatives(self.as_slice(), |k| k, span, u, degree, n_derivs, out);
    }
}

/// [`KnotVector::basis_functions`] for knots held as data (`f64`) at a parameter of any scalar
/// type: a dual-number u carries ∂Nⱼ/∂u exactly while the knots stay constants. This is how
/// residuals evaluate a curve whose contact parameter is an unknown.
///
/// # Panics
/// Under the same conditions as [`KnotVector::basis_functions`].
///
/// ```
/// use camber_geom::basis::basis_functions_at;
/// use num_dual::Dual64;
/// let knots = [0., 0., 0., 1., 2., 3., 4., 4., 5., 5., 5.];
/// let mut n = [Dual64::from(0.0); 3];
/// basis_functions_at(&knots, 4, Dual64::new(2.5, 1.0), 2, &mut n);
/// // N = (1/8, 6/8, 1/8) with dN/du = (−1/2, 0, 1/2) (The NURBS Book example 2.3).
/// assert!((n[0].re - 0.125).abs() < 1e-15 && (n[0].eps + 0.5).abs() < 1e-15);
/// ```
pub fn basis_functions_at<T: Scalar>(
    knots: &[f64],
    span: usize,
    u: T,
    degree: usize,
    out: &mut [T],
) {
    values(knots, cst::<T>, span, u, degree, out);
}

/// [`KnotVector::basis_function_derivatives`] for knots held as data (`f64`) at a parameter of
/// any scalar type (see [`basis_functions_at`]): `out[k * (p + 1) + j]` = dᵏ/duᵏ N_{span−p+j,p}(u).
///
/// # Panics
/// Under the same conditions as [`KnotVector::basis_function_derivatives`].
pub fn basis_function_derivatives_at<T: Scalar>(
    knots: &[f64],
    span: usize,
    u: T,
    degree: usize,
    n_derivs: usize,
    out: &mut [T],
) {
    derivatives(knots, cst::<T>, span, u, degree, n_derivs, out);
}

/// The rational basis Rⱼ = wⱼNⱼ/W (W = Σ wⱼNⱼ) and its derivatives from those of the B-spline
/// basis, in place: `ders` is laid out as [`KnotVector::basis_function_derivatives`] writes it
/// (rows k = 0 … `n_derivs` of p + 1 values, p + 1 = `weights.len()`), and each row becomes
/// dᵏRⱼ/duᵏ by the quotient rule R⁽ᵏ⁾ = (wN⁽ᵏ⁾ − Σᵢ₌₁ᵏ binom(k, i)·W⁽ⁱ⁾·R⁽ᵏ⁻ⁱ⁾)/W.
/// A NURBS curve is then C⁽ᵏ⁾ = Σ R⁽ᵏ⁾ⱼ·Pⱼ, the same sum as a B-spline's.
///
/// # Panics
/// When `ders` has fewer than (n_derivs + 1)·(p + 1) entries.
///
/// ```
/// use camber_geom::basis::rational_basis_derivatives;
/// // Degree 1 on [0, 1] at u = 1/2 with weights (1, 3): W = 2, R = (1/4, 3/4),
/// // W′ = 2, R′ = (w₀N′₀ − W′R₀)/W = (−1 − 1/2)/2 = −3/4 and +3/4.
/// let mut d = [0.5_f64, 0.5, -1.0, 1.0];
/// rational_basis_derivatives(&[1.0, 3.0], 1, &mut d);
/// assert!((d[0] - 0.25).abs() < 1e-15 && (d[2] + 0.75).abs() < 1e-15);
/// ```
pub fn rational_basis_derivatives<T: Scalar>(weights: &[f64], n_derivs: usize, ders: &mut [T]) {
    let w = weights.len();
    let mut big_w: Row<T> = smallvec![T::zero(); n_derivs + 1];
    for (k, wk) in big_w.iter_mut().enumerate() {
        for (j, &weight) in weights.iter().enumerate() {
            let weighted = ders[k * w + j] * cst::<T>(weight);
            ders[k * w + j] = weighted;
            *wk += weighted;
        }
    }
    let inv = T::one() / big_w[0];
    for k in 0..=n_derivs {
        for j in 0..w {
            let mut value = ders[k * w + j];
            let mut binom = T::one();
            for i in 1..=k {
                binom = binom * from_usize::<T>(k + 1 - i) / from_usize::<T>(i);
                value -= binom * big_w[i] * ders[(k - i) * w + j];
            }
            ders[k * w + j] = value * inv;
        }
    }
}

/// The triangular Cox–de Boor recurrence (The NURBS Book A2.2) over knots of any type `K`,
/// lifted into the scalar type by `knot`.
fn values<T: Scalar, K: Copy>(
    knots: &[K],
    knot: impl Fn(K) -> T,
    span: usize,
    u: T,
    degree: usize,
    out: &mut [T],
) {
    let p = degree;
    if p < ROW {
        // Plain stack arrays: this is the inner loop of every curve point, and a SmallVec
        // would test inline-or-heap at each index.
        let (mut left, mut right) = ([T::zero(); ROW], [T::zero(); ROW]);
        values_with(knots, knot, span, u, p, out, &mut left, &mut right);
    } else {
        let (mut left, mut right) = (vec![T::zero(); p + 1], vec![T::zero(); p + 1]);
        values_with(knots, knot, span, u, p, out, &mut left, &mut right);
    }
}

/// The recurrence of [`values`] with its scratch rows `left` and `right` (p + 1 entries each).
#[allow(clippy::too_many_arguments)] // values' signature plus its two scratch rows
#[inline]
fn values_with<T: Scalar, K: Copy>(
    knots: &[K],
    knot: impl Fn(K) -> T,
    span: usize,
    u: T,
    p: usize,
    out: &mut [T],
    left: &mut [T],
    right: &mut [T],
) {
    out[0] = T::one();
    for j in 1..=p {
        left[j] = u - knot(knots[span + 1 - j]);
        right[j] = knot(knots[span + j]) - u;
        let mut saved = T::zero();
        for r in 0..j {
            let temp = out[r] / (right[r + 1] + left[j - r]);
            out[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        out[j] = saved;
    }
}

/// The basis functions and their derivatives (The NURBS Book A2.3) over knots of any type `K`,
/// lifted into the scalar type by `knot`.
#[allow(clippy::too_many_arguments)] // the A2.3 signature plus the knot lift
fn derivatives<T: Scalar, K: Copy>(
    knots: &[K],
    knot: impl Fn(K) -> T,
    span: usize,
    u: T,
    degree: usize,
    n_derivs: usize,
    out: &mut [T],
) {
    let w = degree + 1;
    // Plain stack arrays sized for the common degrees (a SmallVec would test inline-or-heap
    // at each index of these inner loops); the table is (p + 1)², so cubics get a small one.
    let mut scratch = |ndu: &mut [T], row: &mut [T]| {
        let (left, rest) = row.split_at_mut(w);
        let (right, a) = rest.split_at_mut(w);
        derivatives_with(
            knots, &knot, span, u, degree, n_derivs, out, ndu, left, right, a,
        );
    };
    if w <= 4 {
        scratch(&mut [T::zero(); 16], &mut [T::zero(); 16]);
    } else if w <= ROW {
        scratch(&mut [T::zero(); ROW * ROW], &mut [T::zero(); 4 * ROW]);
    } else {
        scratch(&mut vec![T::zero(); w * w], &mut vec![T::zero(); 4 * w]);
    }
}

/// The algorithm of [`derivatives`] with its scratch: `ndu` of (p + 1)² entries, `left` and
/// `right` of p + 1, `a` of 2(p + 1).
#[allow(clippy::too_many_arguments)] // derivatives' signature plus its scratch
#[inline]
fn derivatives_with<T: Scalar, K: Copy>(
    knots: &[K],
    knot: &impl Fn(K) -> T,
    span: usize,
    u: T,
    degree: usize,
    n_derivs: usize,
    out: &mut [T],
    ndu: &mut [T],
    left: &mut [T],
    right: &mut [T],
    a: &mut [T],
) {
    let p = degree;
    let w = p + 1;
    // ndu[j][r] (row j, column r): basis functions in the upper triangle, knot differences
    // in the lower one.
    ndu[0] = T::one();
    for j in 1..=p {
        left[j] = u - knot(knots[span + 1 - j]);
        right[j] = knot(knots[span + j]) - u;
        let mut saved = T::zero();
        for r in 0..j {
            ndu[j * w + r] = right[r + 1] + left[j - r];
            let temp = ndu[r * w + j - 1] / ndu[j * w + r];
            ndu[r * w + j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j * w + j] = saved;
    }
    for j in 0..=p {
        out[j] = ndu[j * w + p];
    }
    let top = n_derivs.min(p);
    // Two alternating rows of coefficients a_{k,j} in `a`.
    for r in 0..=p {
        let (mut s1, mut s2) = (0usize, w);
        a[0] = T::one();
        for k in 1..=top {
            let mut d = T::zero();
            let rk = r as isize - k as isize;
            let pk = p - k;
            if r >= k {
                let rk = rk as usize;
                a[s2] = a[s1] / ndu[(pk + 1) * w + rk];
                d = a[s2] * ndu[rk * w + pk];
            }
            let j1 = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2 = if r as isize - 1 <= pk as isize {
                k - 1
            } else {
                p - r
            };
            for j in j1..=j2 {
                let idx = (rk + j as isize) as usize;
                a[s2 + j] = (a[s1 + j] - a[s1 + j - 1]) / ndu[(pk + 1) * w + idx];
                d += a[s2 + j] * ndu[idx * w + pk];
            }
            if r <= pk {
                a[s2 + k] = -a[s1 + k - 1] / ndu[(pk + 1) * w + r];
                d += a[s2 + k] * ndu[r * w + pk];
            }
            out[k * w + r] = d;
            std::mem::swap(&mut s1, &mut s2);
        }
    }
    // Multiply through by p! / (p − k)!.
    let mut factor = from_usize::<T>(p);
    for k in 1..=top {
        for j in 0..=p {
            out[k * w + j] *= factor;
        }
        factor *= from_usize::<T>(p - k);
    }
    for value in out.iter_mut().take((n_derivs + 1) * w).skip((top + 1) * w) {
        *value = T::zero();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use proptest::prelude::*;

    fn book_knots() -> KnotVector<f64> {
        KnotVector::try_new(vec![0., 0., 0., 1., 2., 3., 4., 4., 5., 5., 5.]).unwrap()
    }

    #[test]
    fn book_example_2_3_values_and_derivatives() {
        // At u = 5/2, span 4: N_{2,2} = 1/8, N_{3,2} = 6/8, N_{4,2} = 1/8 and the derivatives
        // -1/2, 0, 1/2; second derivatives 1, -2, 1 (hand-derived from the piecewise
        // quadratics (u−2)²/2 etc. on [2, 3]).
        let k = book_knots();
        let mut d = [0.0; 9];
        k.basis_function_derivatives(4, 2.5, 2, 2, &mut d);
        let expected = [0.125, 0.75, 0.125, -0.5, 0.0, 0.5, 1.0, -2.0, 1.0];
        for (a, b) in d.iter().zip(expected) {
            assert_relative_eq!(*a, b, epsilon = 1e-14);
        }
    }

    #[test]
    fn derivatives_above_degree_vanish() {
        let k = book_knots();
        let mut d = [1.0; 12];
        k.basis_function_derivatives(4, 2.5, 2, 3, &mut d);
        for v in &d[9..] {
            assert_relative_eq!(*v, 0.0);
        }
    }

    fn random_knots() -> impl Strategy<Value = (usize, Vec<f64>)> {
        // Degrees up to 10: the stack scratch for p ≤ 3 and p ≤ 7, and the heap above.
        (1usize..=10, prop::collection::vec(0.05f64..1.0, 1..6)).prop_map(|(p, gaps)| {
            // An unclamped, non-[0, 1] knot vector: p + 1 + interior + p + 1 knots with
            // strictly increasing values starting at -1.
            let mut knots = vec![-1.0];
            for i in 0..(2 * p + 1 + gaps.len()) {
                let g = gaps[i % gaps.len()];
                knots.push(knots.last().copied().unwrap_or(0.0) + g);
            }
            (p, knots)
        })
    }

    /// The f64-knot evaluator at a dual parameter: values equal to the knot-vector evaluator's,
    /// dual parts equal to its first derivatives; the rational basis summed with control points
    /// equals the NURBS kernel's derivatives.
    #[test]
    fn data_knots_at_a_dual_parameter_and_the_rational_basis() {
        use crate::{NurbsCurve2, ParametricCurve};
        use nalgebra::Point2;
        use num_dual::Dual64;
        let k = book_knots();
        let (p, w) = (2, 3);
        for u in [0.3, 1.0, 2.5, 3.99, 4.5] {
            let span = k.find_span(p, u);
            let mut reference = [0.0; 9];
            k.basis_function_derivatives(span, u, p, 2, &mut reference);
            let mut dual = [Dual64::from(0.0); 9];
            basis_function_derivatives_at(k.as_slice(), span, Dual64::new(u, 1.0), p, 2, &mut dual);
            for j in 0..w {
                assert_relative_eq!(dual[j].re, reference[j], epsilon = 1e-15);
                assert_relative_eq!(dual[j].eps, reference[w + j], epsilon = 1e-13);
                assert_relative_eq!(dual[w + j].eps, reference[2 * w + j], epsilon = 1e-12);
            }
            let mut values = [Dual64::from(0.0); 3];
            basis_functions_at(k.as_slice(), span, Dual64::new(u, 1.0), p, &mut values);
            for j in 0..w {
                assert_relative_eq!(values[j].re, reference[j], epsilon = 1e-15);
                assert_relative_eq!(values[j].eps, reference[w + j], epsilon = 1e-13);
            }
        }
        let points: Vec<Point2<f64>> = (0..8)
            .map(|i| Point2::new(f64::from(i), f64::from(i % 3) - 1.0))
            .collect();
        let weights = vec![1.0, 0.5, 2.0, 1.5, 0.7, 1.0, 3.0, 0.9];
        let curve = NurbsCurve2::try_new(p, k.clone(), points.clone(), weights.clone()).unwrap();
        for u in [0.3, 1.7, 2.5, 4.2, 5.0] {
            let span = k.find_span(p, u);
            let first = span - p;
            let mut ders = [0.0; 9];
            k.basis_function_derivatives(span, u, p, 2, &mut ders);
            rational_basis_derivatives(&weights[first..=span], 2, &mut ders);
            let kernel = curve.second_order(u).unwrap();
            for order in 0..=2 {
                let mut c = [0.0; 2];
                for j in 0..w {
                    c[0] += ders[order * w + j] * points[first + j].x;
                    c[1] += ders[order * w + j] * points[first + j].y;
                }
                assert_relative_eq!(c[0], kernel[order].x, epsilon = 1e-11, max_relative = 1e-12);
                assert_relative_eq!(c[1], kernel[order].y, epsilon = 1e-11, max_relative = 1e-12);
            }
            // The rational basis is a partition of unity; its derivatives sum to zero.
            let sums: Vec<f64> = (0..=2)
                .map(|o| ders[o * w..(o + 1) * w].iter().sum())
                .collect();
            assert_relative_eq!(sums[0], 1.0, epsilon = 1e-14);
            assert!(sums[1].abs() < 1e-12 && sums[2].abs() < 1e-11);
        }
    }

    proptest! {
        #[test]
        fn partition_of_unity_and_agreement((p, knots) in random_knots(), t in 0.0f64..=1.0) {
            let k = KnotVector::try_new(knots).unwrap();
            let (a, b) = k.domain(p);
            let u = a + (b - a) * t;
            let span = k.find_span(p, u);
            let mut n = vec![0.0; p + 1];
            k.basis_functions(span, u, p, &mut n);
            let sum: f64 = n.iter().sum();
            prop_assert!((sum - 1.0).abs() < 1e-12);
            prop_assert!(n.iter().all(|&v| v >= -1e-15));
            let mut d = vec![0.0; 2 * (p + 1)];
            k.basis_function_derivatives(span, u, p, 1, &mut d);
            for j in 0..=p {
                prop_assert!((d[j] - n[j]).abs() < 1e-13);
            }
            // Derivatives of a partition of unity sum to zero.
            let dsum: f64 = d[p + 1..].iter().sum();
            prop_assert!(dsum.abs() < 1e-9);
        }

        #[test]
        fn derivatives_match_central_differences((p, knots) in random_knots(), t in 0.05f64..0.95) {
            let k = KnotVector::try_new(knots).unwrap();
            let (a, b) = k.domain(p);
            let u = a + (b - a) * t;
            let span = k.find_span(p, u);
            let h = 1e-6;
            // Stay inside one span so the functions are polynomials on [u − h, u + h].
            let ks = k.as_slice();
            prop_assume!(u - h > ks[span] && u + h < ks[span + 1]);
            let order = p.min(3);
            let mut d = vec![0.0; (order + 1) * (p + 1)];
            k.basis_function_derivatives(span, u, p, order, &mut d);
            let mut dp = vec![0.0; (order + 1) * (p + 1)];
            let mut dm = vec![0.0; (order + 1) * (p + 1)];
            k.basis_function_derivatives(span, u + h, p, order, &mut dp);
            k.basis_function_derivatives(span, u - h, p, order, &mut dm);
            for kk in 1..=order {
                for j in 0..=p {
                    let fd = (dp[(kk - 1) * (p + 1) + j] - dm[(kk - 1) * (p + 1) + j]) / (2.0 * h);
                    let exact = d[kk * (p + 1) + j];
                    prop_assert!((fd - exact).abs() < 1e-5 * (1.0 + exact.abs()), "k={kk} j={j} fd={fd} exact={exact}");
                }
            }
        }
    }
}
