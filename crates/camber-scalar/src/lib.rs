//! The one numeric bound every camber evaluator and residual is generic over, and small helpers
//! around it.
//!
//! It lives in its own crate so that the geometry kernel (camber-geom) and the solver
//! (camber-solve) share one bound without either depending on the other; both re-export it.
//!
//! [`Scalar`] is blanket-implemented for every `nalgebra::RealField + Copy` type, so `f64` and the
//! forward-mode dual numbers of an automatic-differentiation crate (for example num-dual's
//! `Dual64` or `DualSVec64<N>`) run through exactly the same code. Branches (span search, domain
//! checks) compare values with `PartialOrd`, which for dual numbers compares real parts only.

use nalgebra::RealField;

/// The scalar type of every geometric evaluation: real numbers and dual numbers alike.
///
/// ```
/// use camber_scalar::Scalar;
/// fn square<T: Scalar>(x: T) -> T { x * x }
/// assert!((square(3.0_f64) - 9.0).abs() < 1e-15);
/// ```
pub trait Scalar: RealField + Copy {}

impl<T: RealField + Copy> Scalar for T {}

/// Converts an `f64` constant into the scalar type `T` (a dual number gets zero derivative part).
///
/// ```
/// let half: f64 = camber_scalar::cst(0.5);
/// assert!((half - 0.5).abs() < 1e-15);
/// ```
#[inline]
pub fn cst<T: Scalar>(c: f64) -> T {
    nalgebra::convert::<f64, T>(c)
}

/// Converts a small count (a degree, an index) into the scalar type `T`.
#[inline]
pub fn from_usize<T: Scalar>(n: usize) -> T {
    // Degrees and counts are far below 2^53, so the conversion is exact.
    #[allow(clippy::cast_precision_loss)] // exact for every count this crate handles (< 2^53)
    let v = n as f64;
    cst(v)
}

/// The real part of a scalar as `f64` (the value itself for `f64`; the real part of a dual
/// number). Used for error messages and for branches that must not depend on derivative parts.
///
/// ```
/// assert!((camber_scalar::re(2.5_f64) - 2.5).abs() < 1e-15);
/// ```
#[inline]
pub fn re<T: Scalar>(x: T) -> f64 {
    x.to_subset().unwrap_or(f64::NAN)
}

/// Whether the real part of `x` is finite.
#[inline]
pub fn is_finite<T: Scalar>(x: T) -> bool {
    re(x).is_finite()
}

/// A number for messages in its shortest readable form: the fewest digits that read back as the
/// same `f64` (Rust's own shortest round trip), in plain notation from 1e-5 up to 1e16 and in
/// scientific notation outside, as Python's `repr` does. `format!("{}", 1e308)` writes 309
/// digits; `Readable(1e308)` writes `1e308`.
///
/// ```
/// use camber_scalar::Readable;
/// assert_eq!(Readable(1e308).to_string(), "1e308");
/// assert_eq!(Readable(-2.5e-7).to_string(), "-2.5e-7");
/// assert_eq!(Readable(0.1).to_string(), "0.1");
/// assert_eq!(Readable(123456.75).to_string(), "123456.75");
/// assert_eq!(Readable(f64::NAN).to_string(), "NaN");
/// assert_eq!(Readable(f64::NEG_INFINITY).to_string(), "-inf");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Readable(pub f64);

impl std::fmt::Display for Readable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let v = self.0;
        let a = v.abs();
        let zero = a.classify() == std::num::FpCategory::Zero;
        if !v.is_finite() || zero || (1e-5..1e16).contains(&a) {
            write!(f, "{v}")
        } else {
            write!(f, "{v:e}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_dual::Dual64;

    #[test]
    fn dual_numbers_are_scalars_and_constants_carry_no_derivative() {
        let x = Dual64::new(2.0, 1.0);
        let y = x * x + cst::<Dual64>(3.0);
        assert!((y.re - 7.0).abs() < 1e-15);
        assert!((y.eps - 4.0).abs() < 1e-15);
        assert!((re(y) - 7.0).abs() < 1e-15);
        assert!(is_finite(y));
        assert!(!is_finite(cst::<f64>(f64::NAN)));
        assert!((re(from_usize::<Dual64>(5)) - 5.0).abs() < 1e-15);
    }

    #[test]
    fn readable_numbers_read_back_exactly_and_stay_short() {
        for v in [
            1e308,
            f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            -1e-300,
            1e16,
            9.999_999_999_999_998e15,
            1e-5,
            9.99e-6,
            0.3,
            -123.456,
            2.0_f64.powi(60),
        ] {
            let text = Readable(v).to_string();
            assert_eq!(
                text.parse::<f64>().map(f64::to_bits),
                Ok(v.to_bits()),
                "{text}"
            );
            assert!(text.len() <= 24, "{text}");
        }
    }
}
