//! A fitted B-spline as one polynomial per knot span in powers of the distance from the span's
//! start, for the foot-point passes of a fit, which evaluate C, C′ and C″ several times per
//! data point and trial.
//!
//! On span j, [s_j, s_{j+1}), a B-spline of degree p is the polynomial
//! C(u) = Σ_{k=0}^{p} a_{j,k} t^k with t = u − s_j and a_{j,k} = C⁽ᵏ⁾(s_j⁺)/k! (its Taylor
//! expansion at the span's start, derivatives of the piece to the right). Nested
//! multiplication (Horner's rule with two derivative accumulators) then gives C, C′ and C″ in
//! 3p multiply–adds per coordinate, with the span found by a walk from the span of the
//! previous data point (the parameters of a fit increase along the data), instead of a binary
//! search and the Cox–de Boor triangle per evaluation.
//!
//! The two evaluations agree to rounding, not bit for bit; where a distance is reported
//! ([`exact_point`](PowerForm::exact_point)) the B-spline's own evaluation at the located knot
//! span is used, so a reported distance is that of a point the curve's `point` returns.

use nalgebra::SVector;

use crate::bspline::BSplineCurve;
use crate::curve::ParametricCurve;
use crate::errors::Result;
use crate::scalar::{from_usize, re, Scalar};

/// A B-spline's spans in power form (see the module header).
#[derive(Debug, Clone)]
pub(crate) struct PowerForm<'a, T: Scalar, const D: usize> {
    curve: &'a BSplineCurve<T, D>,
    degree: usize,
    /// The start s_j of every non-empty span.
    starts: Vec<T>,
    /// The end of the domain.
    end: T,
    /// The knot-span index (as `KnotVector::find_span` numbers it) of every span.
    knot_spans: Vec<usize>,
    /// a_{j,k} at `j * (degree + 1) + k`.
    coefficients: Vec<SVector<T, D>>,
}

impl<'a, T: Scalar, const D: usize> PowerForm<'a, T, D> {
    /// The power form of `curve`: p + 1 derivatives at the start of each of its spans.
    ///
    /// Errors: those of the curve's evaluation (none for a valid curve).
    pub fn new(curve: &'a BSplineCurve<T, D>) -> Result<Self> {
        let p = curve.degree();
        let breaks = curve.breakpoints();
        let spans = breaks.len().saturating_sub(1).max(1);
        let mut starts = Vec::with_capacity(spans);
        let mut knot_spans = Vec::with_capacity(spans);
        let mut coefficients = Vec::with_capacity(spans * (p + 1));
        let mut derivatives = vec![SVector::<T, D>::zeros(); p + 1];
        for &s in breaks.iter().take(spans) {
            curve.derivatives_into(s, &mut derivatives)?;
            let mut factorial = T::one();
            for (k, d) in derivatives.iter().enumerate() {
                if k > 1 {
                    factorial *= from_usize::<T>(k);
                }
                coefficients.push(d / factorial);
            }
            starts.push(s);
            knot_spans.push(curve.knots().find_span(p, s));
        }
        let end = breaks.last().copied().unwrap_or_else(T::one);
        Ok(Self {
            curve,
            degree: p,
            starts,
            end,
            knot_spans,
            coefficients,
        })
    }

    /// The number of spans.
    pub fn spans(&self) -> usize {
        self.starts.len()
    }

    /// The parameter interval [s_j, s_{j+1}] of span `span`.
    pub fn span_bounds(&self, span: usize) -> (T, T) {
        let end = self.starts.get(span + 1).copied().unwrap_or(self.end);
        (self.starts[span], end)
    }

    /// The span holding `u` (the last one from its start on, the first one before its end),
    /// walking from `hint`.
    pub fn locate(&self, u: T, hint: usize) -> usize {
        let last = self.starts.len() - 1;
        let mut j = hint.min(last);
        while j < last && re(u) >= re(self.starts[j + 1]) {
            j += 1;
        }
        while j > 0 && re(u) < re(self.starts[j]) {
            j -= 1;
        }
        j
    }

    /// C(u), C′(u) and C″(u) on span `span` (see [`locate`](Self::locate)).
    pub fn second_order(&self, span: usize, u: T) -> [SVector<T, D>; 3] {
        let p = self.degree;
        let a = &self.coefficients[span * (p + 1)..(span + 1) * (p + 1)];
        let t = u - self.starts[span];
        let mut c0 = a[p];
        let mut c1 = SVector::<T, D>::zeros();
        let mut c2 = SVector::<T, D>::zeros();
        for k in (0..p).rev() {
            c2 = c2 * t + c1;
            c1 = c1 * t + c0;
            c0 = c0 * t + a[k];
        }
        [c0, c1, c2 * from_usize::<T>(2)]
    }

    /// C(u) by the B-spline's own evaluation on the knot span of `span` (the value the curve's
    /// `point` gives, without its span search).
    pub fn exact_point(&self, span: usize, u: T) -> SVector<T, D> {
        self.curve.point_in_span(self.knot_spans[span], u)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::knots::KnotVector;
    use nalgebra::Point2;
    use proptest::prelude::*;

    /// A clamped B-spline of `degree` through the given ordinates at x = i, interior knots
    /// at the given (sorted, distinct) positions in (0, 1).
    fn curve(degree: usize, interior: &[f64], ys: &[f64]) -> BSplineCurve<f64, 2> {
        let mut knots = vec![0.0; degree + 1];
        knots.extend_from_slice(interior);
        knots.extend(std::iter::repeat_n(1.0, degree + 1));
        let count = knots.len() - degree - 1;
        let points = (0..count)
            .map(|i| Point2::new(i as f64, ys[i % ys.len()]))
            .collect();
        BSplineCurve::try_new(degree, KnotVector::try_new(knots).unwrap(), points).unwrap()
    }

    proptest! {
        /// C, C′ and C″ of the power form agree with the B-spline's evaluation everywhere in
        /// the domain, from any hint, and its exact point is the curve's point.
        #[test]
        fn the_power_form_is_the_curve(
            degree in 1usize..=5,
            mut interior in proptest::collection::vec(0.01f64..0.99, 0..12),
            ys in proptest::collection::vec(-3.0f64..3.0, 1..20),
            us in proptest::collection::vec(0.0f64..=1.0, 1..20),
            hint in 0usize..20,
        ) {
            interior.sort_by(f64::total_cmp);
            interior.dedup_by(|a, b| (*a - *b).abs() < 1e-3);
            let c = curve(degree, &interior, &ys);
            let form = PowerForm::new(&c).unwrap();
            for &u in us.iter().chain([0.0, 1.0].iter()).chain(interior.iter()) {
                let span = form.locate(u, hint);
                let fast = form.second_order(span, u);
                let slow = c.second_order(u).unwrap();
                for (k, (f, s)) in fast.iter().zip(&slow).enumerate() {
                    let scale = 1.0 + s.norm();
                    prop_assert!((f - s).norm() <= 1e-9 * scale, "order {k} at {u}: {f} vs {s}");
                }
                let exact = form.exact_point(span, u);
                prop_assert!((exact - c.point(u).unwrap().coords).norm() <= 1e-14 * (1.0 + exact.norm()));
            }
        }
    }

    #[test]
    fn locate_walks_to_the_span_of_the_parameter() {
        let c = curve(3, &[0.25, 0.5, 0.75], &[0.0, 1.0]);
        let form = PowerForm::new(&c).unwrap();
        assert_eq!(form.locate(0.0, 3), 0);
        assert_eq!(form.locate(0.25, 0), 1);
        assert_eq!(form.locate(0.6, 0), 2);
        assert_eq!(form.locate(0.6, 3), 2);
        assert_eq!(form.locate(1.0, 0), 3);
    }
}
