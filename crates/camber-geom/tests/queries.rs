//! Curve queries against test-only curves whose answers are known by hand: an explicit
//! polynomial curve, a circular arc (r cos σu, r sin σu) and a helix.

// Fixture helpers outside #[test] functions unwrap constructors of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use std::f64::consts::{FRAC_PI_2, FRAC_PI_3, FRAC_PI_6, PI, TAU};

use approx::{assert_abs_diff_eq, assert_relative_eq};
use camber_geom::curve::check_parameter;
use camber_geom::queries::{
    closest_point, closest_point_with, curvature, curvature_vector, distance_to_circle,
    distance_to_line, intersect_circle, intersect_line, intersect_line_with, signed_curvature,
    signed_distance_to_circle, QueryOptions,
};
use camber_geom::scalar::{cst, from_usize};
use camber_geom::{Circle, Error, Line, ParametricCurve, Result, Scalar};
use nalgebra::{Point2, SVector, Vector2};
use num_dual::Dual64;
use proptest::prelude::*;

/// C(u) = Σ_k c_k u^k on a given domain.
struct Poly<T: Scalar, const D: usize> {
    coeffs: Vec<SVector<T, D>>,
    domain: (T, T),
}

impl<T: Scalar, const D: usize> ParametricCurve<T, D> for Poly<T, D> {
    fn domain(&self) -> (T, T) {
        self.domain
    }

    fn derivatives_into(&self, u: T, out: &mut [SVector<T, D>]) -> Result<()> {
        check_parameter(u, self.domain)?;
        for (k, o) in out.iter_mut().enumerate() {
            *o = SVector::zeros();
            for (j, c) in self.coeffs.iter().enumerate().skip(k) {
                // j!/(j−k)! · u^(j−k)
                let falling = (j - k + 1..=j).fold(T::one(), |acc, m| acc * from_usize::<T>(m));
                let power = (0..j - k).fold(T::one(), |acc, _| acc * u);
                *o += c * (falling * power);
            }
        }
        Ok(())
    }
}

fn poly2(coeffs: &[[f64; 2]], domain: (f64, f64)) -> Poly<f64, 2> {
    Poly {
        coeffs: coeffs.iter().map(|c| SVector::from(*c)).collect(),
        domain,
    }
}

/// C(u) = centre + r (cos σu, sin σu): counter-clockwise for σ = 1, clockwise for σ = −1.
struct Arc<T: Scalar> {
    center: Vector2<T>,
    radius: T,
    sigma: T,
    domain: (T, T),
}

impl<T: Scalar> ParametricCurve<T, 2> for Arc<T> {
    fn domain(&self) -> (T, T) {
        self.domain
    }

    fn derivatives_into(&self, u: T, out: &mut [SVector<T, 2>]) -> Result<()> {
        check_parameter(u, self.domain)?;
        let mut factor = self.radius;
        for (k, o) in out.iter_mut().enumerate() {
            let angle = self.sigma * u + cst::<T>(FRAC_PI_2) * from_usize::<T>(k);
            *o = Vector2::new(angle.cos(), angle.sin()) * factor;
            if k == 0 {
                *o += self.center;
            }
            factor *= self.sigma;
        }
        Ok(())
    }
}

fn unit_circle() -> Arc<f64> {
    Arc {
        center: Vector2::zeros(),
        radius: 1.0,
        sigma: 1.0,
        domain: (0.0, TAU),
    }
}

fn horizontal(y: f64) -> Line<f64> {
    Line::try_new(Point2::new(0.0, y), Vector2::new(1.0, 0.0)).unwrap()
}

#[test]
fn unit_circle_and_a_line_at_distance_one_half() {
    let hits = intersect_line(&unit_circle(), &horizontal(0.5)).unwrap();
    assert_eq!(hits.len(), 2);
    assert_abs_diff_eq!(hits[0].parameter, FRAC_PI_6, epsilon = 1e-14);
    assert_abs_diff_eq!(hits[1].parameter, 5.0 * FRAC_PI_6, epsilon = 1e-14);
    assert_abs_diff_eq!(
        hits[0].point,
        Point2::new(0.75_f64.sqrt(), 0.5),
        epsilon = 1e-14
    );

    // The same geometry turned by 1 rad: a line at distance 0.5 from the origin with normal
    // (cos 1, sin 1) meets the circle at angles 1 ± π/3.
    let n = Vector2::new(1.0_f64.cos(), 1.0_f64.sin());
    let line = Line::try_new(Point2::from(n * 0.5), Vector2::new(-n.y, n.x)).unwrap();
    let hits = intersect_line(&unit_circle(), &line).unwrap();
    assert_eq!(hits.len(), 2);
    assert_abs_diff_eq!(hits[0].parameter, 1.0 + FRAC_PI_3, epsilon = 1e-13);
    assert_abs_diff_eq!(hits[1].parameter, 1.0 - FRAC_PI_3 + TAU, epsilon = 1e-13);
    assert_abs_diff_eq!(
        distance_to_line(&unit_circle(), &line).unwrap().distance,
        0.0
    );
}

#[test]
fn tangent_line_touches_once_and_far_line_misses() {
    let hits = intersect_line(&unit_circle(), &horizontal(1.0)).unwrap();
    assert_eq!(hits.len(), 1);
    assert_abs_diff_eq!(hits[0].parameter, FRAC_PI_2, epsilon = 1e-8);
    assert_abs_diff_eq!(hits[0].point, Point2::new(0.0, 1.0), epsilon = 1e-12);

    let far = horizontal(2.0);
    assert!(intersect_line(&unit_circle(), &far).unwrap().is_empty());
    let d = distance_to_line(&unit_circle(), &far).unwrap();
    assert_abs_diff_eq!(d.distance, 1.0, epsilon = 1e-14);
    assert_abs_diff_eq!(d.parameter, FRAC_PI_2, epsilon = 1e-12);
    // Below the circle, on the right-hand side of the line: the distance is unsigned.
    let d = distance_to_line(&unit_circle(), &horizontal(-3.0)).unwrap();
    assert_abs_diff_eq!(d.distance, 2.0, epsilon = 1e-14);
    assert_abs_diff_eq!(d.parameter, 3.0 * FRAC_PI_2, epsilon = 1e-12);
}

#[test]
fn line_through_the_start_of_a_closed_curve() {
    // y = 0 meets (cos u, sin u) at u = 0, π and 2π (the same point twice: two parameters).
    let hits = intersect_line(&unit_circle(), &horizontal(0.0)).unwrap();
    let params: Vec<f64> = hits.iter().map(|h| h.parameter).collect();
    assert_eq!(params.len(), 3, "{params:?}");
    assert_abs_diff_eq!(params[0], 0.0, epsilon = 1e-14);
    assert_abs_diff_eq!(params[1], PI, epsilon = 1e-14);
    assert_abs_diff_eq!(params[2], TAU, epsilon = 1e-14);
}

#[test]
fn closest_point_on_the_parabola() {
    // (u, u²) to (0, 1): f(u) = u + 2u³ − 2u = 0 gives u = ±√(1/2), distance √3/2.
    let parabola = poly2(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], (-2.0, 2.0));
    let near = closest_point(&parabola, &Point2::new(0.0, 1.0)).unwrap();
    assert_abs_diff_eq!(near.parameter.abs(), 0.5_f64.sqrt(), epsilon = 1e-12);
    assert_abs_diff_eq!(near.distance, 0.75_f64.sqrt(), epsilon = 1e-14);
    // Only the right branch: the minimum is at +√(1/2).
    let right = poly2(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], (0.1, 2.0));
    let near = closest_point(&right, &Point2::new(0.0, 1.0)).unwrap();
    assert_abs_diff_eq!(near.parameter, 0.5_f64.sqrt(), epsilon = 1e-12);
    // Below the vertex the vertex is closest; beyond the end of the domain the end is.
    let near = closest_point(&parabola, &Point2::new(0.0, -1.0)).unwrap();
    assert_abs_diff_eq!(near.parameter, 0.0, epsilon = 1e-12);
    assert_abs_diff_eq!(near.distance, 1.0, epsilon = 1e-14);
    let near = closest_point(&parabola, &Point2::new(5.0, 4.0)).unwrap();
    assert_abs_diff_eq!(near.parameter, 2.0);
    assert_abs_diff_eq!(near.distance, 3.0, epsilon = 1e-14);
}

#[test]
fn curvature_of_circles_lines_and_a_helix() {
    for (radius, sigma) in [(2.0, 1.0), (0.5, -1.0), (3.0, 2.0_f64)] {
        let arc = Arc {
            center: Vector2::new(1.0, -2.0),
            radius,
            sigma,
            domain: (-1.0, 4.0),
        };
        for u in [-1.0, 0.3, 2.0, 4.0] {
            assert_relative_eq!(curvature(&arc, u).unwrap(), 1.0 / radius, epsilon = 1e-14);
            let signed = signed_curvature(&arc, u).unwrap();
            assert_relative_eq!(signed, sigma.signum() / radius, epsilon = 1e-14);
            // The curvature vector points to the centre.
            let k = curvature_vector(&arc, u).unwrap();
            let p = arc.point(u).unwrap();
            assert_relative_eq!(
                p + k * radius * radius,
                Point2::new(1.0, -2.0),
                epsilon = 1e-13
            );
        }
    }
    let line = poly2(&[[1.0, 2.0], [3.0, -1.0]], (0.0, 1.0));
    assert_abs_diff_eq!(curvature(&line, 0.4).unwrap(), 0.0);
    assert_abs_diff_eq!(signed_curvature(&line, 0.4).unwrap(), 0.0);
    // A line traversed at a non-constant speed is still straight.
    let slow = poly2(&[[0.0, 0.0], [1.0, 2.0], [1.0, 2.0]], (0.0, 1.0));
    assert_abs_diff_eq!(curvature(&slow, 0.7).unwrap(), 0.0);

    // Helix (r cos u, r sin u, c u): κ = r / (r² + c²).
    let (r, c) = (2.0, 0.5);
    struct Helix(f64, f64);
    impl ParametricCurve<f64, 3> for Helix {
        fn domain(&self) -> (f64, f64) {
            (0.0, 10.0)
        }
        fn derivatives_into(&self, u: f64, out: &mut [SVector<f64, 3>]) -> Result<()> {
            let (r, c) = (self.0, self.1);
            let all = [
                SVector::from([r * u.cos(), r * u.sin(), c * u]),
                SVector::from([-r * u.sin(), r * u.cos(), c]),
                SVector::from([-r * u.cos(), -r * u.sin(), 0.0]),
            ];
            for (k, o) in out.iter_mut().enumerate() {
                *o = all[k];
            }
            Ok(())
        }
    }
    assert_relative_eq!(
        curvature(&Helix(r, c), 1.3).unwrap(),
        r / (r * r + c * c),
        epsilon = 1e-14
    );

    // A cusp: (u², u³) at u = 0 has no tangent.
    let cusp = poly2(
        &[[0.0, 0.0], [0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
        (-1.0, 1.0),
    );
    assert!(matches!(
        curvature(&cusp, 0.0),
        Err(Error::ZeroLength { .. })
    ));
    assert!(matches!(
        curvature(&cusp, 2.0),
        Err(Error::ParameterOutsideDomain { .. })
    ));
}

#[test]
fn curvature_holds_at_the_ends_of_the_f64_range() {
    // |C′|³ and |C′ × C″|² overflow (or underflow) for circles of radius 1e±120 and beyond,
    // where κ = 1/radius is an ordinary f64: the evaluation must not meet them.
    for radius in [1e-300, 1e-150, 1e-120, 1.0, 1e120, 1e150, 1e300] {
        let arc = Arc {
            center: Vector2::new(0.0, 0.0),
            radius,
            sigma: -1.5,
            domain: (0.0, 1.0),
        };
        for u in [0.0, 0.35, 1.0] {
            assert_relative_eq!(
                curvature(&arc, u).unwrap(),
                1.0 / radius,
                max_relative = 1e-14
            );
            assert_relative_eq!(
                signed_curvature(&arc, u).unwrap(),
                -1.0 / radius,
                max_relative = 1e-14
            );
            let k = curvature_vector(&arc, u).unwrap();
            let towards_centre = -arc.point(u).unwrap().coords / radius;
            assert_relative_eq!(k * radius, towards_centre, epsilon = 1e-14);
        }
    }
}

#[test]
fn circle_intersections_touches_and_distances() {
    let curve = unit_circle();
    // Unit circles centred 1 apart meet at angles ±π/3.
    let other = Circle::try_new(Point2::new(1.0, 0.0), 1.0).unwrap();
    let hits = intersect_circle(&curve, &other).unwrap();
    assert_eq!(hits.len(), 2);
    assert_abs_diff_eq!(hits[0].parameter, FRAC_PI_3, epsilon = 1e-14);
    assert_abs_diff_eq!(hits[1].parameter, TAU - FRAC_PI_3, epsilon = 1e-14);

    // Touch from outside at the top.
    let above = Circle::try_new(Point2::new(0.0, 2.0), 1.0).unwrap();
    let hits = intersect_circle(&curve, &above).unwrap();
    assert_eq!(hits.len(), 1);
    assert_abs_diff_eq!(hits[0].parameter, FRAC_PI_2, epsilon = 1e-8);
    assert_abs_diff_eq!(distance_to_circle(&curve, &above).unwrap().distance, 0.0);
    let signed = signed_distance_to_circle(&curve, &above).unwrap();
    assert_abs_diff_eq!(signed.distance, 0.0, epsilon = 1e-14);
    assert_abs_diff_eq!(signed.parameter, FRAC_PI_2, epsilon = 1e-12);

    // Crossing: the signed distance is negative.
    let crossing = Circle::try_new(Point2::new(0.0, 1.5), 1.0).unwrap();
    assert_eq!(intersect_circle(&curve, &crossing).unwrap().len(), 2);
    let signed = signed_distance_to_circle(&curve, &crossing).unwrap();
    assert_abs_diff_eq!(signed.distance, -0.5, epsilon = 1e-14);

    // Apart: distance 1 at u = 0, no intersections.
    let apart = Circle::try_new(Point2::new(3.0, 0.0), 1.0).unwrap();
    assert!(intersect_circle(&curve, &apart).unwrap().is_empty());
    let d = distance_to_circle(&curve, &apart).unwrap();
    assert_abs_diff_eq!(d.distance, 1.0, epsilon = 1e-14);
    assert_abs_diff_eq!(d.point, Point2::new(1.0, 0.0), epsilon = 1e-12);

    // Enclosing circle of radius 3: the curve is 2 inside everywhere.
    let big = Circle::try_new(Point2::new(0.0, 0.0), 3.0).unwrap();
    assert!(intersect_circle(&curve, &big).unwrap().is_empty());
    assert_abs_diff_eq!(
        distance_to_circle(&curve, &big).unwrap().distance,
        2.0,
        epsilon = 1e-14
    );
    assert_abs_diff_eq!(
        signed_distance_to_circle(&curve, &big).unwrap().distance,
        -2.0,
        epsilon = 1e-14
    );
}

#[test]
fn bad_options_are_errors() {
    let opts = QueryOptions::default().with_samples_per_piece(0);
    assert_eq!(
        closest_point_with(&unit_circle(), &Point2::new(0.0, 0.0), &opts),
        Err(Error::ZeroCount {
            what: "samples per piece"
        })
    );
    let opts = QueryOptions::default().with_touch_tolerance(f64::NAN);
    assert!(intersect_line_with(&unit_circle(), &horizontal(0.0), &opts).is_err());
}

#[test]
fn dual_numbers_give_implicit_derivatives() {
    let d = |x: f64| Dual64::from(x);
    let circle = Arc {
        center: Vector2::zeros(),
        radius: d(1.0),
        sigma: d(1.0),
        domain: (d(0.0), d(TAU)),
    };
    // Closest point to (x, 3): u = atan2(3, x), du/dx = −3/(x² + 9) = −1/3 at x = 0.
    let p = Point2::new(d(0.0).derivative(), d(3.0));
    let near = closest_point(&circle, &p).unwrap();
    assert_abs_diff_eq!(near.parameter.re, FRAC_PI_2, epsilon = 1e-12);
    assert_abs_diff_eq!(near.parameter.eps, -1.0 / 3.0, epsilon = 1e-9);
    // The line y = c meets the circle at u = asin c: du/dc = 1/√(1 − c²).
    let line = Line::try_new(
        Point2::new(d(0.0), d(0.5).derivative()),
        Vector2::new(d(1.0), d(0.0)),
    )
    .unwrap();
    let hits = intersect_line(&circle, &line).unwrap();
    assert_eq!(hits.len(), 2);
    assert_abs_diff_eq!(hits[0].parameter.re, FRAC_PI_6, epsilon = 1e-14);
    assert_abs_diff_eq!(hits[0].parameter.eps, 1.0 / 0.75_f64.sqrt(), epsilon = 1e-9);
    assert_abs_diff_eq!(
        hits[1].parameter.eps,
        -1.0 / 0.75_f64.sqrt(),
        epsilon = 1e-9
    );
}

/// Signed distance of a curve point to a line, and power with respect to a circle.
fn line_g(line: &Line<f64>, p: &Point2<f64>) -> f64 {
    line.signed_distance(p)
}

fn arb_coeffs(count: usize) -> impl Strategy<Value = Vec<[f64; 2]>> {
    prop::collection::vec(prop::array::uniform2(-3.0..3.0_f64), count)
}

proptest! {
    #[test]
    fn closest_point_beats_a_fine_grid(
        coeffs in arb_coeffs(4),
        px in -4.0..4.0_f64,
        py in -4.0..4.0_f64,
    ) {
        let curve = poly2(&coeffs, (0.0, 1.0));
        let p = Point2::new(px, py);
        let near = closest_point(&curve, &p).unwrap();
        prop_assert!((near.distance - (near.point - p).norm()).abs() < 1e-14);
        for i in 0..=2000 {
            let q = curve.point(f64::from(i) / 2000.0).unwrap();
            prop_assert!(near.distance <= (q - p).norm() + 1e-12);
        }
    }

    #[test]
    fn reported_intersections_lie_on_the_line_and_circle(
        coeffs in arb_coeffs(4),
        qx in -2.0..2.0_f64,
        qy in -2.0..2.0_f64,
        angle in 0.0..PI,
        radius in 0.1..3.0_f64,
    ) {
        let curve = poly2(&coeffs, (0.0, 1.0));
        let line = Line::try_new(Point2::new(qx, qy), Vector2::new(angle.cos(), angle.sin())).unwrap();
        let hits = intersect_line(&curve, &line).unwrap();
        for w in hits.windows(2) {
            prop_assert!(w[0].parameter < w[1].parameter);
        }
        for h in &hits {
            prop_assert!(line_g(&line, &h.point).abs() < 1e-9);
            prop_assert!((curve.point(h.parameter).unwrap() - h.point).norm() < 1e-15);
        }
        let circle = Circle::try_new(Point2::new(qx, qy), radius).unwrap();
        let hits = intersect_circle(&curve, &circle).unwrap();
        for w in hits.windows(2) {
            prop_assert!(w[0].parameter < w[1].parameter);
        }
        for h in &hits {
            let w = h.point - circle.center();
            prop_assert!((w.norm_squared() - radius * radius).abs() < 1e-9);
        }
        // Distances agree with intersections and with a fine grid.
        let d = distance_to_circle(&curve, &circle).unwrap();
        prop_assert_eq!(d.distance.abs() < 1e-300, !hits.is_empty());
        for i in 0..=500 {
            let q = curve.point(f64::from(i) / 500.0).unwrap();
            prop_assert!(d.distance <= circle.distance(&q) + 1e-12);
        }
    }

    #[test]
    fn every_crossing_of_a_quadratic_is_found(
        coeffs in arb_coeffs(3),
        qy in -2.0..2.0_f64,
        angle in 0.0..PI,
    ) {
        // g(u) is quadratic: every sign change on a fine grid brackets a reported root.
        let curve = poly2(&coeffs, (0.0, 1.0));
        let line = Line::try_new(Point2::new(0.0, qy), Vector2::new(angle.cos(), angle.sin())).unwrap();
        let hits = intersect_line(&curve, &line).unwrap();
        let g = |u: f64| line_g(&line, &curve.point(u).unwrap());
        let grid = 1000;
        for i in 0..grid {
            let (u0, u1) = (f64::from(i) / f64::from(grid), f64::from(i + 1) / f64::from(grid));
            let (g0, g1) = (g(u0), g(u1));
            if g0 * g1 < 0.0 && g0.abs() > 1e-6 && g1.abs() > 1e-6 {
                prop_assert!(
                    hits.iter().any(|h| h.parameter >= u0 && h.parameter <= u1),
                    "no root in [{}, {}]: {:?}", u0, u1, hits
                );
            }
        }
        let d = distance_to_line(&curve, &line).unwrap();
        prop_assert_eq!(d.distance.abs() < 1e-300, !hits.is_empty());
    }
}
