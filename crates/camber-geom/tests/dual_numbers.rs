//! One code path for f64 and dual numbers: derivatives of curve evaluations obtained by seeding
//! num-dual dual numbers agree with central differences of the plain f64 evaluation.

use approx::assert_relative_eq;
use camber_geom::{BSplineCurve2, BezierCurve2, KnotVector, NurbsCurve2, ParametricCurve, Scalar};
use nalgebra::{Const, Point2};
use num_dual::{Derivative, Dual64, DualSVec64};

const XS: [[f64; 2]; 6] = [
    [0.0, 0.0],
    [0.3, 0.4],
    [1.0, 0.9],
    [1.8, 0.7],
    [2.4, 0.1],
    [3.0, -0.2],
];
const WEIGHTS: [f64; 6] = [1.0, 0.7, 1.6, 1.1, 0.8, 1.0];
const KNOTS: [f64; 10] = [0.0, 0.0, 0.0, 0.0, 0.35, 0.6, 1.0, 1.0, 1.0, 1.0];

fn points<T: Scalar>(coords: &[T]) -> Vec<Point2<T>> {
    coords.chunks(2).map(|c| Point2::new(c[0], c[1])).collect()
}

fn flat() -> Vec<f64> {
    XS.iter().flatten().copied().collect()
}

/// C(u) of the cubic B-spline with the given (flattened) control points, for any scalar.
fn bspline_point<T: Scalar>(coords: &[T], u: T) -> Point2<T> {
    let knots = KnotVector::try_new(KNOTS.iter().map(|&k| nalgebra::convert(k)).collect())
        .expect("valid knots");
    let curve = BSplineCurve2::try_new(3, knots, points(coords)).expect("valid curve");
    curve.point(u).expect("u in domain")
}

fn nurbs_point<T: Scalar>(coords: &[T], u: T) -> Point2<T> {
    let knots = KnotVector::try_new(KNOTS.iter().map(|&k| nalgebra::convert(k)).collect())
        .expect("valid knots");
    let weights = WEIGHTS.iter().map(|&w| nalgebra::convert(w)).collect();
    let curve = NurbsCurve2::try_new(3, knots, points(coords), weights).expect("valid curve");
    curve.point(u).expect("u in domain")
}

fn bezier_point<T: Scalar>(coords: &[T], u: T) -> Point2<T> {
    BezierCurve2::try_new(points(coords))
        .expect("valid curve")
        .point(u)
        .expect("u in domain")
}

/// Checks ∂C/∂x_k (every control-point coordinate, one Dual64 pass each) and ∂C/∂u against
/// central differences of the f64 evaluation.
fn check_against_central_differences(
    eval_f64: fn(&[f64], f64) -> Point2<f64>,
    eval_dual: fn(&[Dual64], Dual64) -> Point2<Dual64>,
) {
    let x0 = flat();
    let h = 1e-6;
    for &u in &[0.0, 0.2, 0.35, 0.5, 0.77, 1.0] {
        for k in 0..x0.len() {
            let xd: Vec<Dual64> = x0
                .iter()
                .enumerate()
                .map(|(i, &v)| {
                    if i == k {
                        Dual64::from(v).derivative()
                    } else {
                        Dual64::from(v)
                    }
                })
                .collect();
            let p = eval_dual(&xd, Dual64::from(u));
            let (mut xp, mut xm) = (x0.clone(), x0.clone());
            xp[k] += h;
            xm[k] -= h;
            let fd = (eval_f64(&xp, u) - eval_f64(&xm, u)) / (2.0 * h);
            assert_relative_eq!(p.x.eps, fd.x, epsilon = 1e-8);
            assert_relative_eq!(p.y.eps, fd.y, epsilon = 1e-8);
            // The real part is the f64 evaluation itself.
            let plain = eval_f64(&x0, u);
            assert_relative_eq!(p.x.re, plain.x, epsilon = 1e-15);
        }
        // Derivative with respect to the parameter (one-sided at the domain ends).
        let xd: Vec<Dual64> = x0.iter().map(|&v| Dual64::from(v)).collect();
        let p = eval_dual(&xd, Dual64::from(u).derivative());
        // Central differences inside a polynomial piece; second-order one-sided differences at
        // the domain ends and, on the right-hand piece, at interior knots.
        let f = |v: f64| eval_f64(&x0, v);
        let at_break = [0.0, 0.35, 0.6].iter().any(|&k| (u - k).abs() < 1e-12);
        let fd = if (u - 1.0).abs() < 1e-12 {
            (f(u) * 3.0 - f(u - h) * 4.0 + f(u - 2.0 * h).coords) / (2.0 * h)
        } else if at_break {
            (f(u + h) * 4.0 - f(u) * 3.0 - f(u + 2.0 * h).coords) / (2.0 * h)
        } else {
            (f(u + h) - f(u - h)) / (2.0 * h)
        };
        assert_relative_eq!(p.x.eps, fd.x, epsilon = 1e-7, max_relative = 1e-7);
        assert_relative_eq!(p.y.eps, fd.y, epsilon = 1e-7, max_relative = 1e-7);
    }
}

#[test]
fn bspline_point_derivatives_match_central_differences() {
    check_against_central_differences(bspline_point::<f64>, bspline_point::<Dual64>);
}

#[test]
fn nurbs_point_derivatives_match_central_differences() {
    check_against_central_differences(nurbs_point::<f64>, nurbs_point::<Dual64>);
}

#[test]
fn bezier_point_derivatives_match_central_differences() {
    check_against_central_differences(bezier_point::<f64>, bezier_point::<Dual64>);
}

#[test]
fn one_vector_dual_pass_equals_four_scalar_passes() {
    // Seed the x and y of control points 2 and 3 in one DualSVec64<4> pass and compare with
    // the Dual64 column passes: the two ways to build a Jacobian must agree exactly.
    let x0 = flat();
    let seeded = [4usize, 5, 6, 7];
    let xv: Vec<DualSVec64<4>> = x0
        .iter()
        .enumerate()
        .map(|(i, &v)| match seeded.iter().position(|&s| s == i) {
            Some(k) => {
                DualSVec64::new(v, Derivative::derivative_generic(Const::<4>, Const::<1>, k))
            }
            None => DualSVec64::from(v),
        })
        .collect();
    let u = 0.47;
    let pv = bspline_point(&xv, DualSVec64::from(u));
    for (k, &i) in seeded.iter().enumerate() {
        let xd: Vec<Dual64> = x0
            .iter()
            .enumerate()
            .map(|(j, &v)| {
                if j == i {
                    Dual64::from(v).derivative()
                } else {
                    Dual64::from(v)
                }
            })
            .collect();
        let pd = bspline_point(&xd, Dual64::from(u));
        let gx = pv.x.eps.unwrap_generic(Const::<4>, Const::<1>)[k];
        let gy = pv.y.eps.unwrap_generic(Const::<4>, Const::<1>)[k];
        assert_relative_eq!(gx, pd.x.eps, epsilon = 1e-15);
        assert_relative_eq!(gy, pd.y.eps, epsilon = 1e-15);
    }
}
