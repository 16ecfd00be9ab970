//! B-spline basis functions N_{i,p}(u) and their derivatives (The NURBS Book A2.2 and A2.3).
//!
//! At a parameter u in knot span i only the p + 1 functions N_{i−p,p}, …, N_{i,p} are non-zero;
//! both routines return exactly those, in that order. They write into caller-provided slices and
//! keep their triangular tables on the stack for degrees up to [`INLINE_DEGREE`], so evaluation
//! in a hot loop does not allocate.

use smallvec::{smallvec, SmallVec};

use crate::knots::KnotVector;
use crate::scalar::{from_usize, Scalar};

/// Degrees up to this one evaluate with stack storage only; higher degrees still work but
/// allocate their scratch tables.
pub const INLINE_DEGREE: usize = 7;

const ROW: usize = INLINE_DEGREE + 1;

/// Scratch for one row of p + 1 values.
type Row<T> = SmallVec<[T; ROW]>;
/// Scratch for a (p + 1) × (p + 1) table, row-major.
type Table<T> = SmallVec<[T; ROW * ROW]>;

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
        let knots = self.as_slice();
        let p = degree;
        let mut left: Row<T> = smallvec![T::zero(); p + 1];
        let mut right: Row<T> = smallvec![T::zero(); p + 1];
        out[0] = T::one();
        for j in 1..=p {
            left[j] = u - knots[span + 1 - j];
            right[j] = knots[span + j] - u;
            let mut saved = T::zero();
            for r in 0..j {
                let temp = out[r] / (right[r + 1] + left[j - r]);
                out[r] = saved + right[r + 1] * temp;
                saved = left[j - r] * temp;
            }
            out[j] = saved;
        }
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
        let knots = self.as_slice();
        let p = degree;
        let w = p + 1;
        let mut left: Row<T> = smallvec![T::zero(); w];
        let mut right: Row<T> = smallvec![T::zero(); w];
        // ndu[j][r] (row j, column r): basis functions in the upper triangle, knot differences
        // in the lower one.
        let mut ndu: Table<T> = smallvec![T::zero(); w * w];
        ndu[0] = T::one();
        for j in 1..=p {
            left[j] = u - knots[span + 1 - j];
            right[j] = knots[span + j] - u;
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
        // Two alternating rows of coefficients a_{k,j}.
        let mut a: Row<T> = smallvec![T::zero(); 2 * w];
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
        (1usize..=5, prop::collection::vec(0.05f64..1.0, 1..6)).prop_map(|(p, gaps)| {
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
