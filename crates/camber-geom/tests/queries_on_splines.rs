//! Curve queries on the kernel's own multi-span curves (NURBS circles, B-splines, Bézier
//! curves) rather than on test polynomials: hand-derived intersections, distances and closest
//! points on the rational unit circle, and on random cubic B-splines the crossings of a line
//! and the closest point against an independent dense scan.

// Test helpers outside #[test] functions unwrap too; a failed unwrap is a failed test.
#![allow(clippy::unwrap_used)]

use camber_geom::queries::{
    closest_point, closest_point_with, curvature, distance_to_circle, distance_to_line,
    intersect_circle, intersect_line, signed_curvature, QueryOptions,
};
use camber_geom::{
    BSplineCurve2, BezierCurve2, Circle, KnotVector, Line, NurbsCurve2, ParametricCurve,
};
use nalgebra::{Point2, Vector2};
use proptest::prelude::*;
use std::f64::consts::{FRAC_1_SQRT_2, SQRT_2, TAU};

/// The unit circle as the 9-point rational quadratic (four 90° spans, double knots).
fn unit_circle() -> NurbsCurve2<f64> {
    NurbsCurve2::try_circular_arc(Point2::origin(), 1.0, 0.0, TAU).unwrap()
}

fn horizontal(y: f64) -> Line<f64> {
    Line::try_new(Point2::new(0.0, y), Vector2::new(1.0, 0.0)).unwrap()
}

fn close(a: Point2<f64>, b: Point2<f64>, tol: f64) -> bool {
    (a - b).norm() < tol
}

#[test]
fn the_rational_circle_meets_lines_where_y_equals_c() {
    let c = unit_circle();
    // y = 1/2 crosses at (±√3/2, 1/2): one hit in the first span, one in the second.
    let hits = intersect_line(&c, &horizontal(0.5)).unwrap();
    assert_eq!(hits.len(), 2, "{hits:?}");
    let h = 3.0_f64.sqrt() / 2.0;
    assert!(close(hits[0].point, Point2::new(h, 0.5), 1e-12));
    assert!(close(hits[1].point, Point2::new(-h, 0.5), 1e-12));
    for hit in &hits {
        assert!(close(c.point(hit.parameter).unwrap(), hit.point, 1e-15));
    }
    // y = −0.9 crosses in the third and fourth spans.
    let low = intersect_line(&c, &horizontal(-0.9)).unwrap();
    let x = (1.0_f64 - 0.81).sqrt();
    assert_eq!(low.len(), 2);
    assert!(close(low[0].point, Point2::new(-x, -0.9), 1e-12));
    assert!(close(low[1].point, Point2::new(x, -0.9), 1e-12));
    // y = 1 touches at the top (a span joint, u = 1/4): one tangential contact.
    let top = intersect_line(&c, &horizontal(1.0)).unwrap();
    assert_eq!(top.len(), 1, "{top:?}");
    assert!(close(top[0].point, Point2::new(0.0, 1.0), 1e-8));
    // y = 1.5 misses.
    assert!(intersect_line(&c, &horizontal(1.5)).unwrap().is_empty());
}

#[test]
fn the_rational_circle_meets_a_circle_at_sixty_degrees() {
    // |p| = 1 and |p − (1, 0)| = 1 meet at (1/2, ±√3/2).
    let c = unit_circle();
    let other = Circle::try_new(Point2::new(1.0, 0.0), 1.0).unwrap();
    let hits = intersect_circle(&c, &other).unwrap();
    assert_eq!(hits.len(), 2, "{hits:?}");
    let h = 3.0_f64.sqrt() / 2.0;
    assert!(close(hits[0].point, Point2::new(0.5, h), 1e-12));
    assert!(close(hits[1].point, Point2::new(0.5, -h), 1e-12));
    // Concentric and larger: no intersection, distance 1 everywhere.
    let outer = Circle::try_new(Point2::origin(), 2.0).unwrap();
    assert!(intersect_circle(&c, &outer).unwrap().is_empty());
    assert!((distance_to_circle(&c, &outer).unwrap().distance - 1.0).abs() < 1e-12);
}

#[test]
fn distances_and_closest_points_on_the_rational_circle() {
    let c = unit_circle();
    // From (2, 2) the nearest point is (√2/2, √2/2), at distance 2√2 − 1.
    let near = closest_point(&c, &Point2::new(2.0, 2.0)).unwrap();
    assert!(close(
        near.point,
        Point2::new(FRAC_1_SQRT_2, FRAC_1_SQRT_2),
        1e-10
    ));
    assert!((near.distance - (2.0 * SQRT_2 - 1.0)).abs() < 1e-12);
    assert!((near.parameter - 0.125).abs() < 1e-12, "{}", near.parameter);
    // The line y = 3 is 2 away, nearest at the top (0, 1), u = 1/4.
    let to_line = distance_to_line(&c, &horizontal(3.0)).unwrap();
    assert!((to_line.distance - 2.0).abs() < 1e-12);
    assert!(close(to_line.point, Point2::new(0.0, 1.0), 1e-7));
    assert!((to_line.parameter - 0.25).abs() < 1e-7);
    // The circle of radius 1 around (3, 0) is 1 away, nearest at (1, 0): u = 0 or u = 1.
    let far = Circle::try_new(Point2::new(3.0, 0.0), 1.0).unwrap();
    let d = distance_to_circle(&c, &far).unwrap();
    assert!((d.distance - 1.0).abs() < 1e-12);
    assert!(close(d.point, Point2::new(1.0, 0.0), 1e-7));
    // Curvature 1 everywhere, positive (counterclockwise).
    for k in 0..=16 {
        let u = f64::from(k) / 16.0;
        assert!((curvature(&c, u).unwrap() - 1.0).abs() < 1e-12);
        assert!((signed_curvature(&c, u).unwrap() - 1.0).abs() < 1e-12);
    }
}

#[test]
fn a_point_beyond_the_end_clamps_to_the_end() {
    // The cubic Bézier (0,0), (1,1), (2,1), (3,0): the point (5, −1) lies past the end, where
    // the squared distance still decreases: the search stops at u = 1 exactly.
    let c = BezierCurve2::<f64>::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 1.0),
        Point2::new(2.0, 1.0),
        Point2::new(3.0, 0.0),
    ])
    .unwrap();
    let near = closest_point(&c, &Point2::new(5.0, -1.0)).unwrap();
    assert!((near.parameter - 1.0).abs() < 1e-300);
    assert!(close(near.point, Point2::new(3.0, 0.0), 1e-15));
    let before = closest_point(&c, &Point2::new(-2.0, -1.0)).unwrap();
    assert!(before.parameter.abs() < 1e-300);
}

/// A clamped cubic B-spline with 8 control points at x = 0 … 7 and random heights, on the
/// domain [−1, 2] (not [0, 1]) with uneven interior knots.
fn wavy_spline() -> impl Strategy<Value = BSplineCurve2<f64>> {
    (
        prop::collection::vec(-1.0f64..1.0, 8),
        prop::collection::vec(0.2f64..1.0, 5),
    )
        .prop_map(|(ys, gaps)| {
            let total: f64 = gaps.iter().sum();
            let mut knots = vec![-1.0; 4];
            let mut at = -1.0;
            for g in &gaps[..4] {
                at += 3.0 * g / total;
                knots.push(at);
            }
            knots.extend([2.0; 4]);
            let points = ys
                .iter()
                .enumerate()
                .map(|(i, &y)| Point2::new(i as f64, y))
                .collect();
            BSplineCurve2::try_new(3, KnotVector::try_new(knots).unwrap(), points).unwrap()
        })
}

/// Parameters where y(u) − c changes sign on a grid of `n` steps, and the smallest |y − c| at
/// a grid point (to skip near-tangent lines, where counting is ill-posed).
fn grid_crossings(c: &BSplineCurve2<f64>, level: f64, n: usize) -> (Vec<f64>, f64) {
    let (a, b) = c.domain();
    let mut crossings = Vec::new();
    let mut closest = f64::INFINITY;
    let mut previous: Option<(f64, f64)> = None;
    for k in 0..=n {
        let u = (a + (b - a) * k as f64 / n as f64).min(b);
        let h = c.point(u).unwrap().y - level;
        closest = closest.min(h.abs());
        if let Some((u0, h0)) = previous {
            if h0 * h < 0.0 {
                crossings.push(0.5 * (u0 + u));
            }
        }
        previous = Some((u, h));
    }
    (crossings, closest)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Every crossing of a horizontal line found by a 10,000-step scan is reported (within
    /// one step), on the line, and nothing else is.
    #[test]
    fn every_crossing_of_a_random_spline_is_found(c in wavy_spline(), level in -0.8f64..0.8) {
        let n = 10_000;
        let (grid, closest) = grid_crossings(&c, level, n);
        // Stay away from tangential contacts and from ends on the line.
        prop_assume!(closest > 1e-3);
        let hits = intersect_line(&c, &horizontal(level)).unwrap();
        prop_assert_eq!(hits.len(), grid.len(), "{:?} vs {:?}", hits, grid);
        let step = 3.0 / n as f64;
        for (hit, g) in hits.iter().zip(&grid) {
            prop_assert!((hit.point.y - level).abs() < 1e-9);
            prop_assert!((hit.parameter - g).abs() <= step);
            prop_assert!((c.point(hit.parameter).unwrap() - hit.point).norm() < 1e-15);
        }
    }

    /// The closest point is never beaten by a dense scan, and is a foot point: the chord to
    /// the query point is normal to the curve there (or the point is a domain end).
    #[test]
    fn closest_point_on_a_random_spline(c in wavy_spline(), qx in -1.0f64..8.0, qy in -2.0f64..2.0) {
        let q = Point2::new(qx, qy);
        let near = closest_point(&c, &q).unwrap();
        let (a, b) = c.domain();
        prop_assert!(near.parameter >= a && near.parameter <= b);
        prop_assert!(((near.point - q).norm() - near.distance).abs() < 1e-12);
        let n = 3000;
        let best = (0..=n)
            .map(|k| (c.point((a + (b - a) * k as f64 / n as f64).min(b)).unwrap() - q).norm())
            .fold(f64::INFINITY, f64::min);
        prop_assert!(near.distance <= best + 1e-12, "{} > {}", near.distance, best);
        let at_end = near.parameter <= a || near.parameter >= b;
        if !at_end {
            let t = c.derivative(near.parameter).unwrap();
            let normality = (near.point - q).dot(&t) / (t.norm() * near.distance.max(1e-300));
            prop_assert!(normality.abs() < 1e-8, "cos = {normality}");
        }
    }

    /// The minimum distance to a line above the curve, with its parameter, against a scan.
    #[test]
    fn distance_to_a_line_above_a_random_spline(c in wavy_spline(), slope in -0.1f64..0.1) {
        let line = Line::try_new(Point2::new(0.0, 2.0), Vector2::new(1.0, slope)).unwrap();
        let found = distance_to_line(&c, &line).unwrap();
        let (a, b) = c.domain();
        let n = 3000;
        let best = (0..=n)
            .map(|k| line.distance(&c.point((a + (b - a) * k as f64 / n as f64).min(b)).unwrap()))
            .fold(f64::INFINITY, f64::min);
        prop_assert!(found.distance <= best + 1e-12);
        prop_assert!((line.distance(&c.point(found.parameter).unwrap()) - found.distance).abs() < 1e-12);
    }
}

/// A point whose nearest curve point lies between a minimum and a maximum of the distance
/// inside one long span: even with two samples per piece (every sign change of the slope
/// between them missed) the closest point is found, from the Bernstein form of the slope.
#[test]
fn the_closest_point_is_found_between_sparse_samples() {
    let mut knots = vec![0.0; 4];
    knots.extend([
        0.01,
        0.027121738044469584,
        0.28526827169043995,
        0.303316016572566,
    ]);
    knots.extend([0.5917319398779204, 0.5942620620472083]);
    knots.extend([1.0; 4]);
    let ys = [
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        1.0725285608532373,
        -1.687239379087265,
        0.0,
        0.0,
        0.0,
    ];
    let points = ys
        .iter()
        .enumerate()
        .map(|(i, &y)| Point2::new(i as f64, y))
        .collect();
    let c = BSplineCurve2::try_new(3, KnotVector::try_new(knots).unwrap(), points).unwrap();
    let u = 0.3374011316497048;
    let (p, d) = c.point_and_derivative(u).unwrap();
    let q = p - Vector2::new(-d.y, d.x) / d.norm() * 0.21895743841899049;
    let sparse = QueryOptions::default().with_samples_per_piece(2);
    let near = closest_point_with(&c, &q, &sparse).unwrap();
    assert!(
        (near.distance - 0.21895743841899049).abs() < 1e-12,
        "{}",
        near.distance
    );
    assert!((near.parameter - u).abs() < 1e-7, "{}", near.parameter);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// On a wiggly Bézier curve of degree up to 9 with only two samples per piece, the closest
    /// point is never beaten by a 4,000-step scan.
    #[test]
    fn sparse_samples_still_give_the_closest_point_of_a_bezier(
        ys in proptest::collection::vec(-2.0f64..2.0, 3..11),
        qx in -1.0f64..1.0,
        qy in -2.5f64..2.5,
    ) {
        let n = ys.len() - 1;
        let points = ys.iter().enumerate().map(|(i, &y)| Point2::new(i as f64 / n as f64, y)).collect();
        let c = BezierCurve2::try_new(points).unwrap();
        let q = Point2::new(qx, qy);
        let near = closest_point_with(&c, &q, &QueryOptions::default().with_samples_per_piece(2)).unwrap();
        let scan = (0..=4000)
            .map(|k| (c.point(k as f64 / 4000.0).unwrap() - q).norm())
            .fold(f64::INFINITY, f64::min);
        prop_assert!(near.distance <= scan + 1e-12, "{} > {}", near.distance, scan);
    }

    /// The same for a wiggly rational Bézier curve (one NURBS span, weights in [0.2, 3]): its
    /// piece is searched through the numerator of (C − q)·C′, not by its two samples.
    #[test]
    fn sparse_samples_still_give_the_closest_point_of_a_rational_curve(
        ys in proptest::collection::vec((-2.0f64..2.0, 0.2f64..3.0), 3..9),
        qx in -1.0f64..1.0,
        qy in -2.5f64..2.5,
    ) {
        let n = ys.len() - 1;
        let points = ys.iter().enumerate().map(|(i, &(y, _))| Point2::new(i as f64 / n as f64, y)).collect();
        let weights = ys.iter().map(|&(_, w)| w).collect();
        let knots = KnotVector::try_new([vec![0.0; n + 1], vec![1.0; n + 1]].concat()).unwrap();
        let c = NurbsCurve2::try_new(n, knots, points, weights).unwrap();
        let q = Point2::new(qx, qy);
        let near = closest_point_with(&c, &q, &QueryOptions::default().with_samples_per_piece(2)).unwrap();
        let scan = (0..=4000)
            .map(|k| (c.point(k as f64 / 4000.0).unwrap() - q).norm())
            .fold(f64::INFINITY, f64::min);
        prop_assert!(near.distance <= scan + 1e-12, "{} > {}", near.distance, scan);
    }
}
