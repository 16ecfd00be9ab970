//! The NURBS Book A2.1–A2.3 semantics against the textbook recursions written here: on random
//! knot vectors that are unclamped, off [0, 1] and have repeated interior knots, the span index
//! satisfies u_i ≤ u < u_{i+1} (at the end of the domain: the last non-empty span, evaluated
//! as the left limit, which on an unclamped vector differs from the right-continuous value), the p + 1
//! values are N_{i−p,p} … N_{i,p} of the Cox–de Boor recursion, every other function vanishes
//! there, and the derivatives of every order equal the recursive derivative formula
//! N^{(k)}_{i,p} = p (N^{(k−1)}_{i,p−1}/(u_{i+p} − u_i) − N^{(k−1)}_{i+1,p−1}/(u_{i+p+1} − u_{i+1})).

use camber_geom::KnotVector;
use proptest::prelude::*;

/// N_{i,p}(u) by the recursion from the degree-0 indicators of [u_i, u_{i+1}), or of
/// (u_i, u_{i+1}] when `left` (the left limit: how a curve is evaluated at the end of its
/// domain, which for an unclamped vector is not the right-continuous value).
fn cox_de_boor(knots: &[f64], i: usize, p: usize, u: f64, left: bool) -> f64 {
    if p == 0 {
        let (a, b) = (knots[i], knots[i + 1]);
        let inside = if left {
            a < u && u <= b
        } else {
            a <= u && u < b
        };
        return if inside { 1.0 } else { 0.0 };
    }
    let mut value = 0.0;
    let d1 = knots[i + p] - knots[i];
    if d1 > 0.0 {
        value += (u - knots[i]) / d1 * cox_de_boor(knots, i, p - 1, u, left);
    }
    let d2 = knots[i + p + 1] - knots[i + 1];
    if d2 > 0.0 {
        value += (knots[i + p + 1] - u) / d2 * cox_de_boor(knots, i + 1, p - 1, u, left);
    }
    value
}

/// The k-th derivative of N_{i,p} at u by the recursive formula (zero for k > p).
fn derivative(knots: &[f64], i: usize, p: usize, k: usize, u: f64, left: bool) -> f64 {
    if k == 0 {
        return cox_de_boor(knots, i, p, u, left);
    }
    if k > p {
        return 0.0;
    }
    let mut value = 0.0;
    let d1 = knots[i + p] - knots[i];
    if d1 > 0.0 {
        value += derivative(knots, i, p - 1, k - 1, u, left) / d1;
    }
    let d2 = knots[i + p + 1] - knots[i + 1];
    if d2 > 0.0 {
        value -= derivative(knots, i + 1, p - 1, k - 1, u, left) / d2;
    }
    p as f64 * value
}

/// Degree 1–5, n + 1 = p + 1 + extra control points, knots from a random start (−5 … 5) with
/// gaps of 0.2–1 or 0 (interior multiplicities up to p, so the domain is never empty).
fn knot_vector() -> impl Strategy<Value = (usize, Vec<f64>)> {
    (1usize..=5, 0usize..=5, -5.0f64..5.0).prop_flat_map(|(p, extra, start)| {
        let count = p + 1 + extra;
        prop::collection::vec(prop_oneof![3 => 0.2f64..1.0, 1 => Just(0.0)], count + p).prop_map(
            move |gaps| {
                let mut knots = vec![start];
                let mut run = 1;
                for g in gaps {
                    // Cap every multiplicity at p (p + 1 equal knots would leave an empty
                    // domain or a break, which are other tests' business).
                    let g = if g == 0.0 && run >= p { 0.5 } else { g };
                    run = if g == 0.0 { run + 1 } else { 1 };
                    knots.push(knots[knots.len() - 1] + g);
                }
                (p, knots)
            },
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn spans_values_and_derivatives_follow_the_recursions(
        (p, knots) in knot_vector(),
        t in 0.0f64..=1.0,
        on_knot in any::<bool>(),
        pick in 0usize..16,
    ) {
        let kv = KnotVector::try_new(knots.clone()).unwrap();
        let n = knots.len() - p - 1; // control points
        // A repeated knot can still empty a short domain [u_p, u_{n}]: not this test's case.
        prop_assume!(kv.check_for(p, n).is_ok());
        let (a, b) = kv.domain(p);
        prop_assert!(a < b);
        let mut u = (a + (b - a) * t).clamp(a, b);
        if on_knot {
            // Exactly on a knot inside (or at the ends of) the domain.
            let inside: Vec<f64> = knots.iter().copied().filter(|&k| k >= a && k <= b).collect();
            u = inside[pick % inside.len()];
        }
        let span = kv.find_span(p, u);
        prop_assert!(span >= p && span < n);
        prop_assert!(knots[span] <= u);
        prop_assert!(u < knots[span + 1] || (u >= b && knots[span] < knots[span + 1]));

        // At the end of the domain the span is the last one, evaluated from the left.
        let left = u >= b;
        let order = p;
        let w = p + 1;
        let mut ders = vec![f64::NAN; (order + 1) * w];
        kv.basis_function_derivatives(span, u, p, order, &mut ders);
        let mut values = vec![f64::NAN; w];
        kv.basis_functions(span, u, p, &mut values);
        for j in 0..w {
            let i = span - p + j;
            let exact = cox_de_boor(&knots, i, p, u, left);
            prop_assert!((values[j] - exact).abs() < 1e-13, "N_{i},{p}: {} vs {exact}", values[j]);
            for k in 0..=order {
                let want = derivative(&knots, i, p, k, u, left);
                let got = ders[k * w + j];
                // Each order divides by knot gaps ≥ 0.2 once more.
                let tol = 1e-11 * 5f64.powi(k as i32) * (1.0 + want.abs());
                prop_assert!((got - want).abs() < tol, "d^{k} N_{i},{p}(u = {u}): {got} vs {want}");
            }
        }
        // Every function outside the window vanishes at u.
        for i in (0..n).filter(|&i| i + p < span || i > span) {
            prop_assert!(cox_de_boor(&knots, i, p, u, left).abs() < 1e-300);
        }
    }
}
