//! Exact derivatives: the tape evaluated with dual numbers against the same residual written
//! in Rust (evaluated with the same duals) and against central differences, at random points.

use camber_expr::{compile, Names, Program};
use camber_scalar::{cst, Scalar};
use nalgebra::{ComplexField, RealField};
use num_dual::{Dual64, HyperDual64};
use proptest::prelude::*;

/// Points p, q (blocks 0, 1) and scalars s, t (block 2).
fn names() -> Names {
    Names::new()
        .with_vector("p", 0)
        .with_vector("q", 1)
        .with_scalar("s", 2, 0)
        .with_scalar("t", 2, 1)
        .with_constant("k", 0.7)
}

/// Rows written in Rust over the flat x = [p, q, (s, t)].
type RustRows = fn(&[Dual64]) -> Vec<Dual64>;

/// Each case: expression rows, and the same rows in Rust.
fn cases() -> Vec<(&'static [&'static str], RustRows)> {
    fn d(c: f64) -> Dual64 {
        cst(c)
    }
    vec![
        (&["norm(p - q) = 2 * s"], |x| {
            let (dx, dy) = (x[0] - x[2], x[1] - x[3]);
            vec![(dx * dx + dy * dy).sqrt() - d(2.0) * x[4]]
        }),
        (&["cross(p - q, [cos(s), sin(s)])"], |x| {
            vec![(x[0] - x[2]) * x[4].sin() - (x[1] - x[3]) * x[4].cos()]
        }),
        (&["dot(p, q) / (1 + s^2) - k * t^3"], |x| {
            vec![(x[0] * x[2] + x[1] * x[3]) / (d(1.0) + x[4] * x[4]) - d(0.7) * x[5].powi(3)]
        }),
        (&["atan2(p.y - q.y, p.x - q.x) - angle(p, q)"], |x| {
            let a = (x[1] - x[3]).atan2(x[0] - x[2]);
            let b = (x[0] * x[3] - x[1] * x[2]).atan2(x[0] * x[2] + x[1] * x[3]);
            vec![a - b]
        }),
        (&["unit(p - q) * exp(s) - perp(q)"], |x| {
            let (dx, dy) = (x[0] - x[2], x[1] - x[3]);
            let n = (dx * dx + dy * dy).sqrt();
            vec![dx / n * x[4].exp() + x[3], dy / n * x[4].exp() - x[2]]
        }),
        (
            &["hypot(s, t) ^ 1.5 + ln(1 + s^2) * tan(t / 4)", "s ^ t"],
            |x| {
                let h = (x[4] * x[4] + x[5] * x[5]).sqrt();
                vec![
                    h.powf(d(1.5)) + (d(1.0) + x[4] * x[4]).ln() * (x[5] / d(4.0)).tan(),
                    x[4].powf(x[5]),
                ]
            },
        ),
    ]
}

fn blocks<T: Copy>(x: &[T]) -> [&[T]; 3] {
    [&x[0..2], &x[2..4], &x[4..6]]
}

fn eval<T: Scalar>(program: &Program, x: &[T]) -> Vec<T> {
    let mut out = vec![T::zero(); program.rows()];
    program.eval(&blocks(x), &(), &mut out);
    out
}

/// J by Dual64, one column at a time.
fn jacobian(f: impl Fn(&[Dual64]) -> Vec<Dual64>, x: &[f64]) -> Vec<Vec<f64>> {
    (0..x.len())
        .map(|k| {
            let seeded: Vec<Dual64> = x
                .iter()
                .enumerate()
                .map(|(j, v)| {
                    if j == k {
                        Dual64::new(*v, 1.0)
                    } else {
                        Dual64::from_re(*v)
                    }
                })
                .collect();
            f(&seeded).iter().map(|g| g.eps).collect()
        })
        .collect()
}

fn point() -> impl Strategy<Value = Vec<f64>> {
    // s > 0 keeps s^t real; p and q kept apart so that norms are smooth.
    (
        prop::array::uniform2(-3.0f64..3.0),
        prop::array::uniform2(-3.0f64..3.0),
        0.2f64..2.0,
        -1.5f64..1.5,
    )
        .prop_filter("p and q apart", |(p, q, _, _)| {
            (p[0] - q[0]).hypot(p[1] - q[1]) > 0.1
                && p[0].hypot(p[1]) > 0.1
                && q[0].hypot(q[1]) > 0.1
        })
        .prop_map(|(p, q, s, t)| vec![p[0], p[1], q[0], q[1], s, t])
}

proptest! {
    #[test]
    fn tape_jacobians_equal_the_rust_residuals_and_central_differences(x in point()) {
        for (rows, rust) in cases() {
            let program = compile(rows, &mut names()).unwrap_or_else(|e| panic!("{rows:?}: {e}"));
            let values: Vec<f64> = eval(&program, &x);
            let rust_values: Vec<f64> = rust(&x.iter().map(|v| Dual64::from_re(*v)).collect::<Vec<_>>())
                .iter().map(|g| g.re).collect();
            prop_assert_eq!(values.len(), rust_values.len());
            for (a, b) in values.iter().zip(&rust_values) {
                prop_assert!((a - b).abs() <= 1e-12 * (1.0 + b.abs()), "{:?}: {} vs {}", rows, a, b);
            }
            let tape = jacobian(|d| eval(&program, d), &x);
            let hand = jacobian(rust, &x);
            let h = 1e-6;
            for k in 0..x.len() {
                let (mut up, mut down) = (x.clone(), x.clone());
                up[k] += h;
                down[k] -= h;
                let (gu, gd): (Vec<f64>, Vec<f64>) = (eval(&program, &up), eval(&program, &down));
                for r in 0..values.len() {
                    let fd = (gu[r] - gd[r]) / (2.0 * h);
                    let (a, b) = (tape[k][r], hand[k][r]);
                    prop_assert!((a - b).abs() <= 1e-11 * (1.0 + b.abs()), "{:?} row {} col {}: {} vs rust {}", rows, r, k, a, b);
                    prop_assert!((a - fd).abs() <= 1e-5 * (1.0 + a.abs()), "{:?} row {} col {}: {} vs fd {}", rows, r, k, a, fd);
                }
            }
        }
    }

    #[test]
    fn tape_second_derivatives_equal_central_differences_of_the_first(x in point()) {
        // ∂²g/∂xᵢ∂xⱼ by hyper-dual numbers against differences of the dual Jacobian.
        let program = compile(&["norm(p - q) * sin(s) + dot(p, q) * t^2"], &mut names())
            .unwrap_or_else(|e| panic!("{e}"));
        let h = 1e-5;
        for i in 0..x.len() {
            for j in 0..x.len() {
                let seeded: Vec<HyperDual64> = x.iter().enumerate().map(|(k, v)| {
                    HyperDual64::new(*v, f64::from(u8::from(k == i)), f64::from(u8::from(k == j)), 0.0)
                }).collect();
                let exact = eval(&program, &seeded)[0].eps1eps2;
                let (mut up, mut down) = (x.clone(), x.clone());
                up[j] += h;
                down[j] -= h;
                let (ju, jd) = (jacobian(|d| eval(&program, d), &up), jacobian(|d| eval(&program, d), &down));
                let fd = (ju[i][0] - jd[i][0]) / (2.0 * h);
                prop_assert!((exact - fd).abs() <= 1e-5 * (1.0 + exact.abs()), "H[{}][{}]: {} vs {}", i, j, exact, fd);
            }
        }
    }
}
