//! Ellipses and elliptic arcs against independent values: derivatives by dual numbers against
//! finite differences, the rational form against the parametric form, arc lengths against
//! series of the complete elliptic integral and a second quadrature rule, closest points and
//! intersections against closed forms.

use approx::assert_relative_eq;
use camber_geom::arc_length::{arc_length, arc_length_with};
use camber_geom::budget::Budget;
use camber_geom::queries::{intersect_curves, intersect_line, CurveCurveOptions};
use camber_geom::{Circle, Ellipse, EllipticArc, Error, Line, ParametricCurve};
use nalgebra::{Point2, Vector2};
use num_dual::Dual64;
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// The arc's parameters in order: centre x, y, a, b, rotation, start angle, end angle.
type Shape = [f64; 7];

fn arc_of<T: camber_geom::Scalar>(x: &[T]) -> EllipticArc<T> {
    EllipticArc::try_new(Point2::new(x[0], x[1]), x[2], x[3], x[4], x[5], x[6])
        .expect("a valid arc")
}

/// ∂A(t)/∂(every shape parameter) by one Dual64 pass each, against central differences; and
/// ∂A/∂t by a dual parameter against the closed-form first derivative.
#[test]
fn dual_number_derivatives_match_finite_differences() {
    let shape: Shape = [0.3, -1.2, 2.5, 0.8, 0.6, -0.7, 2.2];
    let h = 1e-6;
    for t in [0.0, 0.25, 0.5, 0.8, 1.0] {
        for k in 0..7 {
            let xd: Vec<Dual64> = shape
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
            let p = arc_of(&xd).point_at(Dual64::from(t));
            let (mut xp, mut xm) = (shape, shape);
            xp[k] += h;
            xm[k] -= h;
            let fd = (arc_of(&xp).point_at(t) - arc_of(&xm).point_at(t)) / (2.0 * h);
            assert_relative_eq!(p.x.eps, fd.x, epsilon = 1e-8);
            assert_relative_eq!(p.y.eps, fd.y, epsilon = 1e-8);
            assert_relative_eq!(p.x.re, arc_of(&shape).point_at(t).x, epsilon = 1e-15);
        }
        let arc = arc_of(&shape);
        let pd = arc_of(&shape.map(Dual64::from)).point_at(Dual64::from(t).derivative());
        let d = arc.derivative_at(t, 1);
        assert_relative_eq!(pd.x.eps, d.x, epsilon = 1e-13);
        assert_relative_eq!(pd.y.eps, d.y, epsilon = 1e-13);
    }
}

/// The angle of the NURBS point at global parameter u in closed form: piece k = ⌊u·n⌋, local
/// s = u·n − k, angle φ₀ + kΔ + α + 2·atan((2s − 1)·tan(α/2)) with α = Δ/2 of the piece.
fn nurbs_angle(arc: &EllipticArc<f64>, u: f64) -> f64 {
    let n = ((arc.sweep() / FRAC_PI_2).ceil() as usize).clamp(1, 4);
    let k = ((u * n as f64).floor() as usize).min(n - 1);
    let s = u * n as f64 - k as f64;
    let delta = arc.sweep() / n as f64;
    let alpha = delta / 2.0;
    arc.start_angle()
        + delta * k as f64
        + alpha
        + 2.0 * ((2.0 * s - 1.0) * (alpha / 2.0).tan()).atan()
}

#[test]
fn the_rational_form_matches_the_arc_at_many_parameters() {
    for sweep in [
        0.3,
        FRAC_PI_2,
        2.0,
        PI,
        4.0,
        3.0 * FRAC_PI_2 + 0.01,
        TAU - 1e-6,
    ] {
        let arc =
            EllipticArc::try_new(Point2::new(2.0, -1.0), 0.75, 2.5, 0.4, 1.2, 1.2 + sweep).unwrap();
        let n = arc.to_nurbs().unwrap();
        for k in 0..=400 {
            let u = f64::from(k) / 400.0;
            let p = n.point(u).unwrap();
            assert!(arc.ellipse().implicit_value(&p).abs() < 1e-14);
            let q = arc.ellipse().point_at_angle(nurbs_angle(&arc, u));
            assert_relative_eq!(p, q, epsilon = 1e-13);
        }
    }
}

proptest! {
    /// The NURBS form equals the parametric form up to a reparameterisation: every NURBS point
    /// satisfies the implicit equation, is the ellipse's point at the closed-form angle, its
    /// tangent runs the arc's way, and the ends agree.
    #[test]
    fn the_rational_form_is_the_arc(
        cx in -50.0..50.0f64, cy in -50.0..50.0f64, a in 1e-3..1e3f64, ratio in 0.05..20.0f64,
        rot in -7.0..7.0f64, a0 in -20.0..20.0f64, sweep in 1e-3..(TAU - 1e-3), u in 0.0..1.0f64,
    ) {
        let b = a * ratio;
        let arc = EllipticArc::try_new(Point2::new(cx, cy), a, b, rot, a0, a0 + sweep).unwrap();
        let n = arc.to_nurbs().unwrap();
        let scale = a.max(b).max(cx.abs()).max(cy.abs());
        let (p, d) = n.point_and_derivative(u).unwrap();
        prop_assert!(arc.ellipse().implicit_value(&p).abs() <= 1e-12 * scale / a.min(b));
        let phi = nurbs_angle(&arc, u);
        let q = arc.ellipse().point_at_angle(phi);
        prop_assert!((p - q).norm() <= 1e-12 * scale, "{p} vs {q}");
        let e1 = arc.ellipse().derivative_at_angle(phi, 1);
        prop_assert!((e1.x * d.y - e1.y * d.x).abs() <= 1e-9 * e1.norm() * d.norm());
        prop_assert!(e1.dot(&d) > 0.0);
        prop_assert!((n.point(0.0).unwrap() - arc.start_point()).norm() <= 1e-12 * scale);
        prop_assert!((n.point(1.0).unwrap() - arc.end_point()).norm() <= 1e-12 * scale);
    }

    /// The length of an arc split at an interior angle is the sum of its parts, and equals the
    /// length of its NURBS form.
    #[test]
    fn arc_lengths_add_up_and_agree_with_the_rational_form(
        a in 0.1..10.0f64, ratio in 0.05..20.0f64, rot in -3.0..3.0f64,
        a0 in -7.0..7.0f64, sweep in 0.01..(TAU - 0.01), cut in 0.05..0.95f64,
    ) {
        let e = Ellipse::try_new(Point2::new(1.0, 2.0), a, a * ratio, rot).unwrap();
        let whole = e.arc(a0, a0 + sweep).unwrap();
        let mid = a0 + cut * sweep;
        let (first, second) = (e.arc(a0, mid).unwrap(), e.arc(mid, a0 + sweep).unwrap());
        let tol = 1e-11;
        let lw = arc_length(&whole, tol).unwrap().length;
        let l1 = arc_length(&first, tol).unwrap().length;
        let l2 = arc_length(&second, tol).unwrap().length;
        prop_assert!((lw - l1 - l2).abs() <= 4.0 * tol, "{lw} vs {l1} + {l2}");
        let ln = arc_length(&whole.to_nurbs().unwrap(), tol).unwrap().length;
        prop_assert!((lw - ln).abs() <= 3.0 * tol, "{lw} vs NURBS {ln}");
    }
}

/// A CI draw of the property above: a long, narrow elliptic arc whose NURBS form was measured
/// 4e-11 short at a tolerance of 1e-11 (one leaf next to the minor-axis end, where the rational
/// speed is near-singular, passed its whole-versus-halves check by accident).
#[test]
fn a_narrow_elliptic_arc_and_its_nurbs_form_have_one_length() {
    let (a, ratio, a0, sweep) = (
        0.816_715_001_401_415_8,
        17.496_062_924_784_15,
        -5.607_676_202_621_344,
        5.304_080_332_326_179,
    );
    let e = Ellipse::try_new(Point2::new(1.0, 2.0), a, a * ratio, 0.0).unwrap();
    let whole = e.arc(a0, a0 + sweep).unwrap();
    let reference: f64 = arc_length(&whole, 1e-14).unwrap().length;
    for tol in [1e-9, 1e-11, 1e-13] {
        let lw = arc_length(&whole, tol).unwrap().length;
        let ln = arc_length(&whole.to_nurbs().unwrap(), tol).unwrap().length;
        assert!(
            (lw - reference).abs() <= tol,
            "{tol:e}: {lw} vs {reference}"
        );
        assert!(
            (ln - reference).abs() <= tol,
            "{tol:e}: NURBS {ln} vs {reference}"
        );
    }
}

/// The circumference by the arithmetic–geometric mean (Gauss, Legendre):
/// P = 2π/M(a, b) · (a² − Σₙ 2ⁿ⁻¹ cₙ²), c₀² = a² − b², cₙ₊₁ = (aₙ − bₙ)/2, quadratically
/// convergent.
fn agm_circumference(a: f64, b: f64) -> f64 {
    let (mut an, mut bn) = (a.max(b), a.min(b));
    let mut sum = 0.5 * (an * an - bn * bn);
    let mut power = 1.0;
    for _ in 0..40 {
        let c = 0.5 * (an - bn);
        (an, bn) = (0.5 * (an + bn), (an * bn).sqrt());
        sum += power * c * c;
        power *= 2.0;
        if c.abs() < 1e-300 || c * c * power < 1e-30 * a * a {
            break;
        }
    }
    2.0 * PI / an * (a.max(b).powi(2) - sum)
}

/// The Gauss–Kummer series P = π(a + b)·Σₙ C(½, n)²·hⁿ, h = ((a − b)/(a + b))².
fn gauss_kummer(a: f64, b: f64) -> f64 {
    let h = ((a - b) / (a + b)).powi(2);
    let (mut term, mut binom, mut sum) = (1.0, 1.0_f64, 1.0);
    for n in 1..400 {
        let nf = f64::from(n);
        binom *= (0.5 - (nf - 1.0)) / nf;
        term *= h;
        sum += binom * binom * term;
    }
    PI * (a + b) * sum
}

#[test]
fn a_round_ellipse_has_the_circumference_of_its_circle() {
    for (r, rot) in [(1.0, 0.0), (2.5, 0.7), (1e-3, -2.0), (400.0, 3.0)] {
        let e = Ellipse::try_new(Point2::new(3.0, -4.0), r, r, rot).unwrap();
        let got = e.circumference(1e-12 * r).unwrap();
        assert_relative_eq!(got.length, TAU * r, epsilon = 2e-12 * r);
    }
}

#[test]
fn circumferences_match_the_agm_and_gauss_kummer_series() {
    for (a, b) in [
        (2.0, 1.0),
        (1.0, 3.0),
        (5.0, 4.9),
        (1.0, 0.2),
        (10.0, 0.5),
        (1.0, 0.01),
    ] {
        let e = Ellipse::try_new(Point2::new(0.0, 0.0), a, b, 0.3).unwrap();
        let got = e.circumference(1e-12).unwrap().length;
        let agm = agm_circumference(a, b);
        assert!(
            (got - agm).abs() < 1e-11 * agm,
            "{a}, {b}: {got} vs AGM {agm}"
        );
        // The series converges fast for h well below 1 only.
        if a.min(b) / a.max(b) >= 0.2 {
            let gk = gauss_kummer(a, b);
            assert!((got - gk).abs() < 1e-11 * gk, "{a}, {b}: {got} vs GK {gk}");
        }
    }
}

/// Ramanujan's second approximation P_R = π(a + b)(1 + 3h/(10 + √(4 − 3h))) underestimates,
/// with a relative error whose series in h starts at h⁵ with positive coefficients, so it
/// lies in [0, h⁵·(1 − 7π/22)] (its value at h = 1, the flat ellipse of perimeter 4a).
#[test]
fn circumferences_lie_within_ramanujans_error_bound() {
    for ratio in [1.0_f64, 0.9, 0.7, 0.5, 0.3, 0.1, 0.02] {
        let (a, b): (f64, f64) = (3.0, 3.0 * ratio);
        let e = Ellipse::try_new(Point2::new(1.0, 1.0), a, b, -1.0).unwrap();
        let p = e.circumference(1e-13).unwrap().length;
        let h = ((a - b) / (a + b)).powi(2);
        let ramanujan = PI * (a + b) * (1.0 + 3.0 * h / (10.0 + (4.0 - 3.0 * h).sqrt()));
        let relative = (p - ramanujan) / p;
        let bound = h.powi(5) * (1.0 - 7.0 * PI / 22.0);
        assert!(
            relative >= -1e-13 && relative <= bound + 1e-13,
            "b/a {ratio}: {relative} vs {bound}"
        );
    }
}

/// Partial arcs against composite Simpson's rule on the closed-form speed
/// |A′(t)| = Δ·√(a² sin² φ + b² cos² φ) — a second rule, written here, not the toolkit's.
#[test]
fn arc_lengths_match_a_second_quadrature_rule() {
    let simpson = |a: f64, b: f64, phi0: f64, sweep: f64| {
        let n = 20_000;
        let speed = |t: f64| {
            let phi = phi0 + t * sweep;
            sweep * (a * a * phi.sin().powi(2) + b * b * phi.cos().powi(2)).sqrt()
        };
        let h = 1.0 / f64::from(n);
        let mut sum = speed(0.0) + speed(1.0);
        for k in 1..n {
            sum += speed(f64::from(k) * h) * if k % 2 == 1 { 4.0 } else { 2.0 };
        }
        sum * h / 3.0
    };
    for (a, b, phi0, sweep) in [
        (2.0, 1.0, 0.0, FRAC_PI_2),
        (0.5, 3.0, -1.0, 4.0),
        (4.0, 0.3, 2.0, 0.2),
    ] {
        let arc =
            EllipticArc::try_new(Point2::new(-1.0, 0.5), a, b, 1.1, phi0, phi0 + sweep).unwrap();
        let got = arc.length_with(1e-12, &Budget::default()).unwrap().length;
        let reference = simpson(a, b, phi0, sweep);
        assert!((got - reference).abs() < 1e-10, "{got} vs {reference}");
    }
    // A quarter of the full ellipse is a quarter of its circumference (symmetry).
    let e = Ellipse::try_new(Point2::new(0.0, 0.0), 2.0, 0.7, 0.0).unwrap();
    let quarter = arc_length(&e.arc(0.0, FRAC_PI_2).unwrap(), 1e-13)
        .unwrap()
        .length;
    assert_relative_eq!(4.0 * quarter, agm_circumference(2.0, 0.7), epsilon = 1e-11);
}

#[test]
fn arc_length_stops_at_its_budget() {
    let arc = EllipticArc::try_new(Point2::new(0.0, 0.0), 1.0, 0.001, 0.0, 0.1, 6.0).unwrap();
    assert_eq!(
        arc_length_with(&arc, 1e-12, &Budget::default().with_max_work(10)).unwrap_err(),
        Error::BudgetExhausted {
            operation: "arc length",
            limit: 10
        }
    );
}

/// For a point (x₀, 0) inside the ellipse x²/a² + y²/b² = 1 with |x₀| < a − b²/a, the nearest
/// points are off the axis at x = a²x₀/(a² − b²); outside that stretch, at the vertex.
#[test]
fn closest_points_match_the_closed_forms_on_the_major_axis() {
    let (a, b) = (2.0, 1.0);
    let rot = 0.8;
    let e = Ellipse::try_new(Point2::new(1.0, -1.0), a, b, rot).unwrap();
    let (u, v) = e.axes();
    let world = |x: f64, y: f64| e.center() + u * x + v * y;
    let x0 = 0.5;
    let near = e.closest_point(&world(x0, 0.0)).unwrap();
    let x = a * a * x0 / (a * a - b * b);
    let y = b * (1.0 - (x / a).powi(2)).sqrt();
    let expected = ((x - x0).powi(2) + y * y).sqrt();
    assert_relative_eq!(near.distance, expected, epsilon = 1e-12);
    let q = e.to_frame(&near.point);
    assert_relative_eq!(q.x, x, epsilon = 1e-10);
    assert_relative_eq!(q.y.abs(), y, epsilon = 1e-10);
    // Beyond a − b²/a = 1.5 along the axis the vertex is nearest.
    for x0 in [1.7, 2.5, 10.0] {
        let near = e.closest_point(&world(x0, 0.0)).unwrap();
        assert_relative_eq!(near.point, world(a, 0.0), epsilon = 1e-10);
        assert_relative_eq!(near.distance, (x0 - a).abs(), epsilon = 1e-10);
    }
    // Points on the curve are on it; points off it by more than the tolerance are not.
    let p = e.point_at_angle(2.0);
    assert!(e.contains_point(&p, 1e-12).unwrap());
    let off = p + e
        .derivative_at_angle(2.0, 1)
        .yx()
        .component_mul(&Vector2::new(1.0, -1.0))
        .normalize()
        * 1e-6;
    assert!(!e.contains_point(&off, 1e-9).unwrap());
}

/// Against dense sampling: the found distance is no larger than any sample's, and the foot
/// satisfies the normal condition (p − A(t))·A′(t) = 0 or lies at an end.
#[test]
fn closest_points_on_arcs_beat_dense_sampling_and_are_feet_or_ends() {
    let arc = EllipticArc::try_new(Point2::new(0.5, 0.2), 3.0, 1.2, -0.4, 0.3, 4.0).unwrap();
    let queries = [
        Point2::new(0.0, 0.0),
        Point2::new(4.0, 3.0),
        Point2::new(-3.0, -2.0),
        Point2::new(2.5, -1.5),
        Point2::new(10.0, -7.0),
    ];
    for p in queries {
        let near = arc.closest_point(&p).unwrap();
        let best = (0..=20_000)
            .map(|k| (arc.point_at(f64::from(k) / 20_000.0) - p).norm())
            .fold(f64::INFINITY, f64::min);
        assert!(
            near.distance <= best + 1e-12,
            "{p}: {} vs {best}",
            near.distance
        );
        assert!(near.distance >= best - 1e-3);
        let t = near.parameter;
        let d = arc.derivative_at(t, 1);
        let foot = (p - near.point).dot(&d).abs() <= 1e-9 * d.norm() * (1.0 + near.distance);
        assert!(foot || t <= 0.0 || t >= 1.0, "{p}: t = {t}");
    }
    // A point by the missing part of the ellipse is nearest to an end of the arc.
    let gap = arc.ellipse().point_at_angle(5.5) * 1.0;
    let near = arc.closest_point(&gap).unwrap();
    let to_ends = (arc.start_point() - gap)
        .norm()
        .min((arc.end_point() - gap).norm());
    assert_relative_eq!(near.distance, to_ends, epsilon = 1e-12);
    assert!(!arc.contains_point(&gap, 1e-6).unwrap());
}

/// The line y = c meets the ellipse x²/a² + y²/b² = 1 at x = ±a·√(1 − c²/b²); the circle
/// x² + y² = r² (b < r < a) meets it at x² = a²(r² − b²)/(a² − b²).
#[test]
fn intersections_with_lines_and_circles_match_the_closed_forms() {
    let (a, b) = (2.0_f64, 1.0_f64);
    let e = Ellipse::try_new(Point2::new(0.0, 0.0), a, b, 0.0).unwrap();
    let c = 0.6_f64;
    let line = Line::try_new(Point2::new(0.0, c), Vector2::new(1.0, 0.0)).unwrap();
    let hits = intersect_line(&e, &line).unwrap();
    assert_eq!(hits.len(), 2);
    let x = a * (1.0 - c * c / (b * b)).sqrt();
    let mut xs: Vec<f64> = hits.iter().map(|h| h.point.x).collect();
    xs.sort_by(f64::total_cmp);
    assert_relative_eq!(xs[0], -x, epsilon = 1e-12);
    assert_relative_eq!(xs[1], x, epsilon = 1e-12);
    // The tangent line y = b touches at the top, E(π/2).
    let top = Line::try_new(Point2::new(0.0, b), Vector2::new(1.0, 0.0)).unwrap();
    let touch = intersect_line(&e, &top).unwrap();
    assert_eq!(touch.len(), 1);
    assert_relative_eq!(touch[0].point, Point2::new(0.0, b), epsilon = 1e-7);
    // Against a circle, through the rational pieces (curve–curve subdivision).
    let r = 1.5;
    let circle = Circle::try_new(Point2::new(0.0, 0.0), r).unwrap();
    let meets = intersect_curves(&e, &circle, &CurveCurveOptions::default()).unwrap();
    assert_eq!(meets.len(), 4);
    let x2 = a * a * (r * r - b * b) / (a * a - b * b);
    for m in &meets {
        assert_relative_eq!(m.point_a.x * m.point_a.x, x2, epsilon = 1e-9);
        assert!(m.distance < 1e-9);
        assert_relative_eq!(e.point(m.parameter_a).unwrap(), m.point_a, epsilon = 1e-9);
    }
    // An arc of it, the upper half, meets the circle twice.
    let upper = e.arc(0.0, PI).unwrap();
    let meets = intersect_curves(&upper, &circle, &CurveCurveOptions::default()).unwrap();
    assert_eq!(meets.len(), 2);
    assert!(meets.iter().all(|m| m.point_a.y > 0.0));
}
