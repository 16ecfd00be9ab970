//! The derivatives of a clamped polynomial curve at the ends of its domain, in closed form.
//!
//! A joint or an end tangent reads C⁽ᵏ⁾ at u = a or u = b. For a B-spline of degree p with
//! control points P₀ … Pₙ and knots t₀ … tₙ₊ₚ₊₁ (Bézier curves and lines on the knots
//! 0ᵖ⁺¹ 1ᵖ⁺¹), the k-th derivative is again a B-spline whose control points follow from those
//! of the (k − 1)-th,
//!
//! P⁽ᵏ⁾ᵢ = (p − k + 1)·(P⁽ᵏ⁻¹⁾ᵢ₊₁ − P⁽ᵏ⁻¹⁾ᵢ) / (tᵢ₊ₚ₊₁ − tᵢ₊ₖ),  P⁽⁰⁾ᵢ = Pᵢ,
//!
//! on the knots with k fewer at each end. When the first p + 1 knots are equal (a clamped
//! start) every derivative curve is clamped there too, so C⁽ᵏ⁾(a) = P⁽ᵏ⁾₀; at a clamped end
//! C⁽ᵏ⁾(b) = P⁽ᵏ⁾ₙ₋ₖ. Either reads k + 1 control points, and every knot difference in the
//! recursion spans an end knot and an interior one, so none is zero on a valid knot vector
//! (checked anyway). This replaces a general evaluation of the basis and its derivatives at
//! the end, which the constraint compiler would otherwise run for every joint.
//!
//! Rational curves (the quotient rule mixes the weights in), Hermite and composite curves
//! (their blocks are mapped to control points) and unclamped ends are left to the general
//! evaluation ([`crate::ground::curve_eval::CurveBasis::at`]): [`end_derivative`] answers `None`.

use crate::ground::entity::{Entity, Terms};

/// The highest derivative order computed here (the joints read up to C″).
pub(crate) const MAX_ORDER: usize = 2;

/// The coefficients cⱼ of C⁽ᵏ⁾ = Σ cⱼ·Pⱼ at the start (`at_end` false) or the end of the
/// domain of a line, Bézier curve or B-spline clamped there, k = `order` ≤ [`MAX_ORDER`], as
/// (control point index, cⱼ) in increasing index order without zero coefficients (empty for
/// k > p, where the derivative vanishes). `None` for any other entity, end or order.
pub(crate) fn end_derivative(entity: &Entity, at_end: bool, order: usize) -> Option<Terms> {
    let (degree, knots) = match entity {
        Entity::Line(_) => (1, None),
        Entity::Bezier(c) => (c.degree(), None),
        Entity::BSpline(c) => (c.degree(), Some(c.knots().as_slice())),
        _ => return None,
    };
    if order > MAX_ORDER || !entity.is_clamped(at_end) {
        return None;
    }
    if order > degree {
        return Some(Terms::new());
    }
    let last = entity.points().len().checked_sub(1)?;
    let base = if at_end { last.checked_sub(order)? } else { 0 };
    // Knot tᵢ; a Bézier curve's knots are p + 1 zeros, then p + 1 ones.
    let knot = |i: usize| -> Option<f64> {
        match knots {
            Some(k) => k.get(i).copied(),
            None => Some(if i <= degree { 0.0 } else { 1.0 }),
        }
    };
    // window[r][s]: the coefficient of P_{base+r+s} in P⁽ˡ⁾_{base+r}, for the derivative
    // level l reached so far (r = 0 … order − l, s = 0 … l).
    let mut window = [[0.0_f64; MAX_ORDER + 1]; MAX_ORDER + 1];
    for row in window.iter_mut().take(order + 1) {
        row[0] = 1.0;
    }
    for l in 1..=order {
        let factor = (degree + 1 - l) as f64;
        for r in 0..=order - l {
            let i = base + r;
            let span = knot(i + degree + 1)? - knot(i + l)?;
            if span.is_nan() || span <= 0.0 {
                return None;
            }
            let f = factor / span;
            // window[r + 1] still holds level l − 1: it is updated after window[r].
            let mut next = [0.0_f64; MAX_ORDER + 1];
            for (s, v) in next.iter_mut().enumerate().take(l + 1) {
                let up = if s >= 1 { window[r + 1][s - 1] } else { 0.0 };
                let here = if s < l { window[r][s] } else { 0.0 };
                *v = f * (up - here);
            }
            window[r] = next;
        }
    }
    Some(
        window[0]
            .iter()
            .take(order + 1)
            .enumerate()
            .filter(|(_, c)| **c != 0.0)
            .map(|(s, c)| (base + s, *c))
            .collect(),
    )
}

/// Which end of `entity`'s domain u is: `Some(false)` at the start, `Some(true)` at the end,
/// `None` inside (or for an entity without a domain).
pub(crate) fn which_end(entity: &Entity, u: f64) -> Option<bool> {
    let (a, b) = entity.domain()?;
    // Exactly at an end: the closed form holds there only.
    if (u - a).abs() <= 0.0 {
        Some(false)
    } else if (u - b).abs() <= 0.0 {
        Some(true)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use crate::ground::curve_eval::CurveBasis;
    use camber_geom::{BSplineCurve2, BezierCurve2, KnotVector, NurbsCurve2};
    use nalgebra::Point2;
    use proptest::prelude::*;

    /// The coefficients of C⁽ᵏ⁾ at u by the general evaluation of the basis
    /// ([`CurveBasis::at`]), zeros dropped.
    fn general(e: &Entity, u: f64, order: usize) -> Vec<(usize, f64)> {
        let (at, points) = CurveBasis::of(e).unwrap().at(u, 2);
        points
            .iter()
            .zip(at.fixed_coefficients().unwrap())
            .map(|(j, c)| (*j, c[order]))
            .filter(|(_, c)| *c != 0.0)
            .collect()
    }

    /// Both lists name the same control points, with coefficients equal to a relative 1e-12.
    fn assert_same(fast: &[(usize, f64)], slow: &[(usize, f64)]) {
        let scale = slow.iter().map(|(_, c)| c.abs()).fold(1.0, f64::max);
        assert_eq!(
            fast.iter().map(|t| t.0).collect::<Vec<_>>(),
            slow.iter()
                .filter(|(_, c)| c.abs() > 1e-13 * scale)
                .map(|t| t.0)
                .collect::<Vec<_>>(),
            "fast {fast:?} general {slow:?}"
        );
        for ((_, a), (_, b)) in fast
            .iter()
            .zip(slow.iter().filter(|(_, c)| c.abs() > 1e-13 * scale))
        {
            assert!(
                (a - b).abs() <= 1e-12 * scale,
                "fast {fast:?} general {slow:?}"
            );
        }
    }

    fn points(n: usize) -> Vec<Point2<f64>> {
        (0..n)
            .map(|i| Point2::new(i as f64, (i * i) as f64 * 0.1))
            .collect()
    }

    /// A cubic Bézier by hand: C′(0) = 3(P₁ − P₀), C″(0) = 6(P₀ − 2P₁ + P₂),
    /// C′(1) = 3(P₃ − P₂), C″(1) = 6(P₁ − 2P₂ + P₃).
    #[test]
    fn a_cubic_bezier_by_hand() {
        let e = Entity::Bezier(BezierCurve2::try_new(points(4)).unwrap());
        let t = |at_end, k| end_derivative(&e, at_end, k).unwrap().to_vec();
        assert_eq!(t(false, 0), vec![(0, 1.0)]);
        assert_eq!(t(false, 1), vec![(0, -3.0), (1, 3.0)]);
        assert_eq!(t(false, 2), vec![(0, 6.0), (1, -12.0), (2, 6.0)]);
        assert_eq!(t(true, 0), vec![(3, 1.0)]);
        assert_eq!(t(true, 1), vec![(2, -3.0), (3, 3.0)]);
        assert_eq!(t(true, 2), vec![(1, 6.0), (2, -12.0), (3, 6.0)]);
    }

    /// A line has C′ = P₁ − P₀ and no second derivative; a quadratic B-spline with knots
    /// (0, 0, 0, 1, 3, 3, 3) by hand: C″(0) = P⁽²⁾₀ = 1·(P⁽¹⁾₁ − P⁽¹⁾₀)/(t₃ − t₂) with
    /// P⁽¹⁾₀ = 2(P₁ − P₀)/(t₃ − t₁) = 2(P₁ − P₀) and P⁽¹⁾₁ = 2(P₂ − P₁)/(t₄ − t₂) = ⅔(P₂ − P₁).
    #[test]
    fn a_line_and_a_quadratic_bspline_by_hand() {
        let line = Entity::Line([Point2::origin(), Point2::new(1.0, 2.0)]);
        assert_eq!(
            end_derivative(&line, true, 1).unwrap().to_vec(),
            vec![(0, -1.0), (1, 1.0)]
        );
        assert!(end_derivative(&line, false, 2).unwrap().is_empty());
        let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 3.0, 3.0, 3.0]).unwrap();
        let e = Entity::BSpline(BSplineCurve2::try_new(2, knots, points(4)).unwrap());
        let c2 = end_derivative(&e, false, 2).unwrap().to_vec();
        // ⅔(P₂ − P₁) − 2(P₁ − P₀) = 2P₀ − (2 + ⅔)P₁ + ⅔P₂.
        let want = [(0, 2.0), (1, -2.0 - 2.0 / 3.0), (2, 2.0 / 3.0)];
        assert_eq!(c2.len(), 3);
        for ((j, c), (wj, wc)) in c2.iter().zip(want) {
            assert_eq!(*j, wj);
            assert!((c - wc).abs() < 1e-15);
        }
        assert_same(&c2, &general(&e, 0.0, 2));
    }

    /// Rational curves, unclamped ends and orders past the supported ones are left to the
    /// general evaluation.
    #[test]
    fn what_is_left_to_the_general_evaluation() {
        let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]).unwrap();
        let nurbs = Entity::Nurbs(
            NurbsCurve2::try_new(3, knots, points(4), vec![1.0, 2.0, 2.0, 1.0]).unwrap(),
        );
        assert!(end_derivative(&nurbs, false, 1).is_none());
        let open = KnotVector::try_new((0..8).map(f64::from).collect()).unwrap();
        let e = Entity::BSpline(BSplineCurve2::try_new(3, open, points(4)).unwrap());
        assert!(end_derivative(&e, false, 1).is_none() && end_derivative(&e, true, 0).is_none());
        let bezier = Entity::Bezier(BezierCurve2::try_new(points(4)).unwrap());
        assert!(end_derivative(&bezier, false, MAX_ORDER + 1).is_none());
        assert!(end_derivative(&Entity::Point(Point2::origin()), false, 0).is_none());
        assert_eq!(which_end(&bezier, 0.0), Some(false));
        assert_eq!(which_end(&bezier, 1.0), Some(true));
        assert_eq!(which_end(&bezier, 0.5), None);
    }

    proptest! {
        /// Against the general evaluation of the basis and its derivatives at the end, for
        /// clamped B-splines of degree 1–5 with random interior knots (repeated up to p
        /// times), Bézier curves of degree 1–7, both ends and orders 0–2.
        #[test]
        fn agrees_with_the_general_basis_evaluation(
            degree in 1_usize..=5,
            extra in 0_usize..6,
            gaps in proptest::collection::vec(0.05_f64..2.0, 8),
            repeats in proptest::collection::vec(1_usize..=5, 8),
            start in -3.0_f64..3.0,
            bezier_degree in 1_usize..=7,
        ) {
            // Interior knots: `extra` of them, each distinct value repeated up to p times.
            let mut interior = Vec::new();
            let mut t = start;
            let mut k = 0;
            while interior.len() < extra {
                t += gaps[k % gaps.len()];
                let times = repeats[k % repeats.len()].min(degree).min(extra - interior.len());
                interior.extend(std::iter::repeat_n(t, times));
                k += 1;
            }
            let end = t + gaps[(k + 3) % gaps.len()];
            let mut knots = vec![start; degree + 1];
            knots.extend(&interior);
            knots.extend(std::iter::repeat_n(end, degree + 1));
            let n = degree + 1 + extra;
            let e = Entity::BSpline(
                BSplineCurve2::try_new(degree, KnotVector::try_new(knots).unwrap(), points(n))
                    .unwrap(),
            );
            let b = Entity::Bezier(BezierCurve2::try_new(points(bezier_degree + 1)).unwrap());
            for curve in [&e, &b] {
                let (lo, hi) = curve.domain().unwrap();
                for (at_end, u) in [(false, lo), (true, hi)] {
                    for order in 0..=MAX_ORDER {
                        let fast = end_derivative(curve, at_end, order).unwrap();
                        assert_same(&fast, &general(curve, u, order));
                    }
                }
            }
        }
    }
}
