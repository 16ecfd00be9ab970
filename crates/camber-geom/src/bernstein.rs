//! The Bernstein polynomials B_{i,n}(t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ and their derivatives.
//!
//! The n + 1 polynomials of degree n are the basis of the Bézier form: they are non-negative on
//! [0, 1] and sum to one there (partition of unity). The functions here are plain polynomials,
//! defined for every t; the curve types check that t lies in their domain. The slice routines
//! take the degree from the slice length (n = `out.len()` − 1), so they never index out of
//! bounds, and they allocate nothing.

use crate::scalar::{from_usize, Scalar};

/// The binomial coefficient C(n, k) = n! / (k! (n − k)!) as a scalar; zero when k > n.
///
/// Exact (computed in integers) while C(n, k) fits in 128 bits, which covers every degree a
/// curve reasonably has; beyond that it is the floating-point product formula.
///
/// ```
/// use camber_geom::bernstein::binomial;
/// assert!((binomial::<f64>(5, 2) - 10.0).abs() < 1e-15);
/// assert!(binomial::<f64>(2, 3).abs() < 1e-15);
/// ```
pub fn binomial<T: Scalar>(n: usize, k: usize) -> T {
    if k > n {
        return T::zero();
    }
    let k = k.min(n - k);
    // c = C(n − k + j, j) after step j; each step's product is divisible by j.
    let mut exact: Option<u128> = Some(1);
    for j in 1..=k {
        exact = exact.and_then(|c| c.checked_mul((n - k + j) as u128).map(|p| p / j as u128));
    }
    match exact {
        #[allow(clippy::cast_precision_loss)] // rounding to the nearest f64 is what we want here
        Some(c) => crate::scalar::cst(c as f64),
        None => {
            let mut c = T::one();
            for j in 1..=k {
                c = c * from_usize::<T>(n - k + j) / from_usize::<T>(j);
            }
            c
        }
    }
}

/// The Bernstein polynomial B_{i,n}(t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ; zero when i > n.
///
/// ```
/// use camber_geom::bernstein::bernstein;
/// // B_{1,2}(t) = 2t(1 − t) = 1/2 at t = 1/2.
/// assert!((bernstein(2, 1, 0.5_f64) - 0.5).abs() < 1e-15);
/// ```
pub fn bernstein<T: Scalar>(n: usize, i: usize, t: T) -> T {
    if i > n {
        return T::zero();
    }
    let s = T::one() - t;
    let mut value = binomial::<T>(n, i);
    for _ in 0..i {
        value *= t;
    }
    for _ in 0..(n - i) {
        value *= s;
    }
    value
}

/// All n + 1 Bernstein polynomials of degree n = `out.len()` − 1 at t:
/// `out[i]` = B_{i,n}(t). An empty slice is left alone.
///
/// Uses the triangular recurrence B_{i,m}(t) = (1 − t) B_{i,m−1}(t) + t B_{i−1,m−1}(t) from
/// B_{0,0} = 1 (The NURBS Book A1.3), in place, without allocating.
///
/// ```
/// use camber_geom::bernstein::bernstein_all;
/// let mut b = [0.0_f64; 4];
/// bernstein_all(0.5, &mut b);
/// // Cubic at t = 1/2: (1, 3, 3, 1) / 8.
/// for (v, e) in b.iter().zip([0.125, 0.375, 0.375, 0.125]) {
///     assert!((v - e).abs() < 1e-15);
/// }
/// ```
pub fn bernstein_all<T: Scalar>(t: T, out: &mut [T]) {
    let Some((first, _)) = out.split_first_mut() else {
        return;
    };
    *first = T::one();
    let s = T::one() - t;
    // Row m holds B_{0,m} … B_{m,m} in out[0..=m].
    for m in 1..out.len() {
        let mut saved = T::zero();
        for value in out.iter_mut().take(m) {
            let temp = *value;
            *value = saved + s * temp;
            saved = t * temp;
        }
        if let Some(last) = out.get_mut(m) {
            *last = saved;
        }
    }
}

/// The derivatives of order k of all n + 1 Bernstein polynomials of degree n = `out.len()` − 1
/// at t: `out[i]` = dᵏ/dtᵏ B_{i,n}(t). Order 0 gives the values; orders above n give zeros.
///
/// Applies B′_{i,m} = m (B_{i−1,m−1} − B_{i,m−1}) (with B_{−1,·} = B_{m,m−1} = 0) k times to the
/// values of degree n − k, which gives
/// dᵏ/dtᵏ B_{i,n} = n!/(n − k)! Σ_{j=0..k} (−1)^{k−j} C(k, j) B_{i−j,n−k}. In place, without
/// allocating.
///
/// ```
/// use camber_geom::bernstein::bernstein_derivatives;
/// let mut d = [0.0_f64; 3];
/// bernstein_derivatives(0.5, 1, &mut d);
/// // Quadratic: B′ = (−2(1 − t), 2 − 4t, 2t) = (−1, 0, 1) at t = 1/2.
/// assert!((d[0] + 1.0).abs() < 1e-15 && d[1].abs() < 1e-15 && (d[2] - 1.0).abs() < 1e-15);
/// ```
pub fn bernstein_derivatives<T: Scalar>(t: T, order: usize, out: &mut [T]) {
    let len = out.len();
    if order >= len {
        out.fill(T::zero());
        return;
    }
    let n = len - 1;
    let (low, high) = out.split_at_mut(n - order + 1);
    bernstein_all(t, low);
    high.fill(T::zero());
    // Raise the degree m = n − k … n − 1 by one per pass: new[i] = (m + 1)(old[i−1] − old[i]),
    // computed from the top down so every old value is read before it is overwritten.
    for m in (n - order)..n {
        let factor = from_usize::<T>(m + 1);
        for i in (0..=m + 1).rev() {
            let below = if i == 0 { T::zero() } else { out[i - 1] };
            out[i] = factor * (below - out[i]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use proptest::prelude::*;

    #[test]
    fn binomials_match_pascal_triangle() {
        let mut row = vec![1u128];
        for n in 0..=70usize {
            for (k, &c) in row.iter().enumerate() {
                #[allow(clippy::cast_precision_loss)] // test values, rounding is intended
                let expected = c as f64;
                assert_relative_eq!(binomial::<f64>(n, k), expected, max_relative = 1e-15);
            }
            let mut next = vec![1u128; n + 2];
            for k in 1..=n {
                next[k] = row[k - 1] + row[k];
            }
            row = next;
        }
        assert_relative_eq!(
            binomial::<f64>(200, 100),
            9.054_851_465_610_328e58,
            max_relative = 1e-12
        );
    }

    #[test]
    fn cubic_by_hand() {
        // B_{·,3}(1/4) = ((3/4)³, 3(1/4)(3/4)², 3(1/4)²(3/4), (1/4)³) = (27, 27, 9, 1) / 64.
        let mut b = [0.0; 4];
        bernstein_all(0.25, &mut b);
        for (i, e) in [27.0, 27.0, 9.0, 1.0].into_iter().enumerate() {
            assert_relative_eq!(b[i], e / 64.0, epsilon = 1e-15);
            assert_relative_eq!(bernstein(3, i, 0.25), e / 64.0, epsilon = 1e-15);
        }
        // Second derivatives of the cubic, expanded by hand: B_0 = (1−t)³ → 6(1−t);
        // B_1 = 3t − 6t² + 3t³ → 18t − 12; B_2 = 3t² − 3t³ → 6 − 18t; B_3 = t³ → 6t.
        let t = 0.25;
        let mut d2 = [0.0; 4];
        bernstein_derivatives(t, 2, &mut d2);
        let e2 = [6.0 * (1.0 - t), 18.0 * t - 12.0, 6.0 - 18.0 * t, 6.0 * t];
        for (a, e) in d2.iter().zip(e2) {
            assert_relative_eq!(*a, e, epsilon = 1e-14);
        }
        // Third derivatives are the constants (−6, 18, −18, 6); the fourth vanish.
        let mut d3 = [0.0; 4];
        bernstein_derivatives(t, 3, &mut d3);
        for (a, e) in d3.iter().zip([-6.0, 18.0, -18.0, 6.0]) {
            assert_relative_eq!(*a, e, epsilon = 1e-13);
        }
        let mut d4 = [1.0_f64; 4];
        bernstein_derivatives(t, 4, &mut d4);
        assert!(d4.iter().all(|v| v.abs() < 1e-15));
    }

    #[test]
    fn degenerate_slices() {
        let mut empty: [f64; 0] = [];
        bernstein_all(0.3, &mut empty);
        bernstein_derivatives(0.3, 2, &mut empty);
        let mut one = [5.0];
        bernstein_all(0.3, &mut one);
        assert_relative_eq!(one[0], 1.0);
        bernstein_derivatives(0.3, 1, &mut one);
        assert_relative_eq!(one[0], 0.0);
        assert_relative_eq!(bernstein(2, 3, 0.3), 0.0);
    }

    proptest! {
        #[test]
        fn partition_of_unity_and_direct_formula(n in 0usize..=20, t in 0.0f64..=1.0) {
            let mut b = vec![0.0; n + 1];
            bernstein_all(t, &mut b);
            let sum: f64 = b.iter().sum();
            prop_assert!((sum - 1.0).abs() < 1e-13);
            for (i, &v) in b.iter().enumerate() {
                prop_assert!(v >= 0.0);
                prop_assert!((v - bernstein(n, i, t)).abs() < 1e-13);
            }
        }

        #[test]
        fn derivatives_match_central_differences(n in 0usize..=9, t in 0.01f64..0.99, order in 1usize..=3) {
            let h = 1e-5;
            let mut d = vec![0.0; n + 1];
            let mut up = vec![0.0; n + 1];
            let mut down = vec![0.0; n + 1];
            bernstein_derivatives(t, order, &mut d);
            bernstein_derivatives(t + h, order - 1, &mut up);
            bernstein_derivatives(t - h, order - 1, &mut down);
            for i in 0..=n {
                let fd = (up[i] - down[i]) / (2.0 * h);
                prop_assert!((fd - d[i]).abs() < 1e-5 * (1.0 + d[i].abs()), "i={i} fd={fd} exact={}", d[i]);
            }
            // The derivatives of a partition of unity sum to zero.
            let sum: f64 = d.iter().sum();
            prop_assert!(sum.abs() < 1e-9 * (1.0 + d.iter().map(|v| v.abs()).sum::<f64>()));
        }
    }
}
