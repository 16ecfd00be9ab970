//! The nonlinear residuals' autodiff Jacobians against central differences
//! (camber_solve::testing), at random control points, parameters, circles and lines. The
//! curve is a clamped cubic B-spline with an interior knot, so the contact parameter crosses a
//! knot in some cases (the residual is smooth within a span; the difference step is kept well
//! inside one by staying away from the knot).

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber_geom::{BSplineCurve2, KnotVector};
use camber_sketch::constraints::angle::LineAngle;
use camber_sketch::constraints::curve_curve_tangent::CurveCurveContact;
use camber_sketch::constraints::distance::PointDistance;
use camber_sketch::constraints::g1_join_free::TangentsParallel;
use camber_sketch::constraints::g2_join::CurvatureMatch;
use camber_sketch::constraints::point_on_circle::OnCircle;
use camber_sketch::constraints::point_on_curve::OnCurve;
use camber_sketch::constraints::radius::RadiusValue;
use camber_sketch::constraints::tangent_to_circle::CircleContact;
use camber_sketch::constraints::tangent_to_line::LineContact;
use camber_sketch::curve_eval::CurveBasis;
use camber_sketch::residuals::clearance::{Clearance, TangentSpeed, Target};
use camber_sketch::residuals::Param;
use camber_sketch::Entity;
use camber_solve::testing::check_jacobian;
use nalgebra::Point2;
use proptest::prelude::*;

/// A 5-point cubic on knots [0,0,0,0, ½, 1,1,1,1] through the given coordinates.
fn basis() -> CurveBasis {
    let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0]).unwrap();
    let pts = (0..5).map(|i| Point2::new(f64::from(i), 0.0)).collect();
    CurveBasis::of(&Entity::BSpline(
        BSplineCurve2::try_new(3, knots, pts).unwrap(),
    ))
    .unwrap()
}

/// The curve's blocks (a wavy polygon so the tangent never vanishes), then `extra`.
fn curve_blocks(wave: &[f64], extra: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let mut out: Vec<Vec<f64>> = (0..5).map(|i| vec![f64::from(i as u8), wave[i]]).collect();
    out.extend(extra.iter().cloned());
    out
}

fn check<R: camber_solve::Residual>(r: &R, blocks: &[Vec<f64>]) -> f64 {
    check_step(r, blocks, 1e-6)
}

/// The scaled Jacobian error against central differences of step `step`.
fn check_step<R: camber_solve::Residual>(r: &R, blocks: &[Vec<f64>], step: f64) -> f64 {
    let refs: Vec<&[f64]> = blocks.iter().map(|b| &b[..]).collect();
    check_jacobian(r, &refs, step, 1.0).unwrap().error
}

/// Whether the autodiff Jacobian jumps (by more than 1e-4, scaled) between x − δ·eᵢ and
/// x + δ·eᵢ along some coordinate i: a kink at x, where no difference quotient is a reference.
/// Smooth residuals change by about 2δ·|∂²r| there, far below the threshold.
fn kinked<R: camber_solve::Residual>(r: &R, blocks: &[Vec<f64>], delta: f64) -> bool {
    use camber_solve::derive::autodiff::{jacobian_with, JacobianMode};
    let dim = r.dim();
    let n: usize = blocks.iter().map(Vec::len).sum();
    let jac_at = |moved: &[Vec<f64>]| -> Vec<f64> {
        let refs: Vec<&[f64]> = moved.iter().map(|b| &b[..]).collect();
        let (mut values, mut jac) = (vec![0.0; dim], vec![0.0; dim * n]);
        jacobian_with(r, &refs, &mut values, &mut jac, JacobianMode::Columns)
            .expect("Jacobian dimensions");
        jac
    };
    for (bi, block) in blocks.iter().enumerate() {
        for ci in 0..block.len() {
            let shifted = |sign: f64| {
                let mut moved = blocks.to_vec();
                moved[bi][ci] += sign * delta;
                jac_at(&moved)
            };
            let (minus, plus) = (shifted(-1.0), shifted(1.0));
            if minus
                .iter()
                .zip(&plus)
                .any(|(a, b)| (a - b).abs() > 1e-4 * a.abs().max(1.0))
            {
                return true;
            }
        }
    }
    false
}

/// Whether Q(s) = [G(s) − G(u) − G′(u)(s − u)]/(s − u)² (written out here from the curve's
/// points; G the signed gap to the target, squared form for a circle) has one clear least
/// local minimum over the bracket of [`Clearance`] (u to the end of the domain on its side),
/// the bracket's ends included:
/// the second-lowest local minimum of a dense scan is higher by more than 1e-3 (relative). A
/// flat Q, such as a cubic span against a line with G‴ ≈ 0, ties everywhere.
fn unique_minimum(
    points: &[&[f64]],
    u: f64,
    target: Target,
    blocks: &[Vec<f64>],
    positive: bool,
    after: bool,
) -> bool {
    let sign = if positive { 1.0 } else { -1.0 };
    let gap = |s: f64| -> (f64, f64) {
        let (p, t) = basis().eval::<f64>(points, s);
        match target {
            Target::Circle | Target::Arc => {
                let c = &blocks[0];
                let r = if target == Target::Arc {
                    (blocks[1][0] - c[0]).hypot(blocks[1][1] - c[1])
                } else {
                    blocks[1][0]
                };
                let v = [p[0] - c[0], p[1] - c[1]];
                let g = (v[0] * v[0] + v[1] * v[1] - r * r) / (2.0 * r);
                (sign * g, sign * (v[0] * t[0] + v[1] * t[1]) / r)
            }
            Target::Ellipse => {
                // In the ellipse's frame: G = k·((x/a)² + (y/b)² − 1), k = ab/(a + b).
                let (c, v, b) = (&blocks[0], &blocks[1], blocks[2][0]);
                let w = [v[0] - c[0], v[1] - c[1]];
                let a = w[0].hypot(w[1]);
                let (ux, uy) = (w[0] / a, w[1] / a);
                let d = [p[0] - c[0], p[1] - c[1]];
                let (x, y) = (d[0] * ux + d[1] * uy, d[1] * ux - d[0] * uy);
                let (x1, y1) = (t[0] * ux + t[1] * uy, t[1] * ux - t[0] * uy);
                let k = a * b / (a + b);
                let g = k * ((x / a).powi(2) + (y / b).powi(2) - 1.0);
                let g1 = 2.0 * k * (x * x1 / (a * a) + y * y1 / (b * b));
                (sign * g, sign * g1)
            }
            Target::Line => {
                let (a, b) = (&blocks[0], &blocks[1]);
                let d = [b[0] - a[0], b[1] - a[1]];
                let len = d[0].hypot(d[1]);
                let g = (d[0] * (p[1] - a[1]) - d[1] * (p[0] - a[0])) / len;
                (sign * g, sign * (d[0] * t[1] - d[1] * t[0]) / len)
            }
        }
    };
    let (g0, g1) = gap(u);
    let (dir, len) = if after { (1.0, 1.0 - u) } else { (-1.0, u) };
    // From 1e-5 beside the contact (the quotient's limit there) to the far end.
    let n = 4000;
    let q: Vec<f64> = (0..=n)
        .map(|i| u + dir * (1e-5 + (len - 1e-5) * f64::from(i) / f64::from(n)))
        .map(|s| (gap(s).0 - g0 - g1 * (s - u)) / ((s - u) * (s - u)))
        .collect();
    let mut minima: Vec<f64> = (0..q.len())
        .filter(|&i| (i == 0 || q[i] <= q[i - 1]) && (i + 1 == q.len() || q[i] <= q[i + 1]))
        .map(|i| q[i])
        .collect();
    minima.sort_by(f64::total_cmp);
    minima.len() < 2 || minima[1] - minima[0] > 1e-3 * (1.0 + minima[0].abs())
}

/// A parameter away from the knot at ½ (and from the ends).
fn param() -> impl Strategy<Value = f64> {
    prop_oneof![0.05..0.45_f64, 0.55..0.95_f64]
}

proptest! {
    #[test]
    fn on_curve(wave in prop::collection::vec(-1.0..1.0_f64, 5), u in param(),
                q in prop::array::uniform2(-3.0..3.0_f64)) {
        let r = OnCurve::new(basis(), Param::Block);
        prop_assert!(check(&r, &curve_blocks(&wave, &[vec![u], q.to_vec()])) < 1e-6);
    }

    #[test]
    fn line_contact(wave in prop::collection::vec(-1.0..1.0_f64, 5), u in param(),
                    a in prop::array::uniform2(-3.0..3.0_f64), d in prop::array::uniform2(0.5..2.0_f64)) {
        let r = LineContact::new(basis(), Param::Block);
        let b = vec![a[0] + d[0], a[1] - d[1]];
        prop_assert!(check(&r, &curve_blocks(&wave, &[vec![u], a.to_vec(), b])) < 1e-6);
    }

    #[test]
    fn circle_contact(wave in prop::collection::vec(-1.0..1.0_f64, 5), u in param(),
                      c in prop::array::uniform2(-3.0..3.0_f64), r in 0.1..2.0_f64, cw in any::<bool>()) {
        let res = CircleContact::new(basis(), Param::Block, cw);
        prop_assert!(check(&res, &curve_blocks(&wave, &[vec![u], c.to_vec(), vec![r]])) < 1e-6);
        let fixed = CircleContact::new(basis(), Param::Fixed(u), cw);
        prop_assert!(check(&fixed, &curve_blocks(&wave, &[c.to_vec(), vec![r]])) < 1e-6);
    }

    /// The clearance h = w²·min Q is differentiable where its minimiser is unique (Danskin):
    /// against circles, arcs, ellipses and lines, on both sides, at a free and at a fixed
    /// contact parameter.
    /// The target passes near C(u) with the curve's tangent (up to `off`), the regime the row
    /// is used in. The value carries a rounding noise of about 1e-11 (the remainder quotient
    /// loses ε·|G(u)|/(s − u)² to cancellation, and the minimiser is searched afresh at every
    /// point), so the differences take a step of 1e-5, and draws where differences at nearby
    /// steps disagree with each other are skipped (see the comment inside).
    #[test]
    fn clearances(wave in prop::collection::vec(-1.0..1.0_f64, 5), u in param(),
                  off in prop::array::uniform3(-0.05..0.05_f64), r in 0.1..2.0_f64,
                  after in any::<bool>(), positive in any::<bool>()) {
        let blocks0 = curve_blocks(&wave, &[]);
        let refs: Vec<&[f64]> = blocks0.iter().map(|b| &b[..]).collect();
        let (p, t) = basis().eval::<f64>(&refs, u);
        let len = t[0].hypot(t[1]);
        let n = [-t[1] / len, t[0] / len];
        let c = vec![p[0] - r * n[0] + off[0], p[1] - r * n[1] + off[1]];
        let a = vec![p[0] + off[0], p[1] + off[1]];
        let b = vec![a[0] + t[0] + off[2], a[1] + t[1]];
        // An arc's circle: its start S at radius r from the centre.
        let start = vec![c[0] + r * 0.3_f64.cos(), c[1] + r * 0.3_f64.sin()];
        // An ellipse with semi-axes 1.5r along the tangent and r across it, its co-vertex at
        // C(u) (up to `off`).
        let t_unit = [t[0] / len, t[1] / len];
        let e = vec![p[0] - r * n[0] + off[0], p[1] - r * n[1] + off[1]];
        let vertex = vec![e[0] + 1.5 * r * t_unit[0], e[1] + 1.5 * r * t_unit[1]];
        let targets = [
            (Target::Circle, vec![c.clone(), vec![r]]),
            (Target::Arc, vec![c.clone(), start]),
            (Target::Ellipse, vec![e, vertex, vec![r]]),
            (Target::Line, vec![a, b]),
        ];
        for (target, blocks) in targets {
            // h is a minimum over s: where two local minima of Q tie it has a kink, and
            // differences across it say nothing about the gradient. Such draws are skipped.
            prop_assume!(unique_minimum(&refs, u, target, &blocks, positive, after));
            let free = Clearance::new(basis(), Param::Block, target, positive, after, 0.2);
            let mut all = vec![vec![u]];
            all.extend(blocks.iter().cloned());
            let fixed = Clearance::new(basis(), Param::Fixed(u), target, positive, after, 0.2);
            for (r, b) in [(&free, curve_blocks(&wave, &all)), (&fixed, curve_blocks(&wave, &blocks))] {
                // The differences are only a reference where they agree with themselves: near
                // a minimiser that changes branch (the contact end against an interior
                // minimum) the search's rounding reaches 1e-9 and central differences at
                // nearby steps scatter more than the tolerance. Such draws are skipped.
                let errors = [1e-5, 2e-5, 4e-5].map(|h| check_step(r, &b, h));
                let spread = errors.iter().fold(0.0_f64, |m, e| m.max(*e))
                    - errors.iter().fold(f64::INFINITY, |m, e| m.min(*e));
                prop_assume!(spread < 1e-5);
                // A minimiser switching branch exactly at this configuration puts a kink at
                // x itself: central differences of every step then average the two one-sided
                // slopes and agree with each other, but not with either side. Such draws are
                // skipped too (the Jacobian jumps between x − δ and x + δ).
                // (Checked only for a draw that would fail: the check costs 2n Jacobians.)
                prop_assume!(errors[0] < 1e-5 || !kinked(r, &b, 1e-7));
                prop_assert!(errors[0] < 1e-5, "{errors:?}");
            }
        }
    }

    #[test]
    fn tangent_speed(wave in prop::collection::vec(-1.0..1.0_f64, 5), u in param(), f in 0.1..3.0_f64) {
        let free = TangentSpeed::new(basis(), Param::Block, f, 0.2);
        prop_assert!(check(&free, &curve_blocks(&wave, &[vec![u]])) < 1e-6);
        let fixed = TangentSpeed::new(basis(), Param::Fixed(u), f, 0.2);
        prop_assert!(check(&fixed, &curve_blocks(&wave, &[])) < 1e-6);
    }

    #[test]
    fn points_and_circles(p in prop::array::uniform2(-3.0..3.0_f64), c in prop::array::uniform2(-3.0..3.0_f64),
                          r in 0.1..2.0_f64, d in 0.1..4.0_f64) {
        prop_assert!(check(&OnCircle, &[p.to_vec(), c.to_vec(), vec![r]]) < 1e-6);
        prop_assert!(check(&PointDistance::new(d), &[p.to_vec(), c.to_vec()]) < 1e-6);
        prop_assert!(check(&RadiusValue::new(d), &[vec![r]]) < 1e-6);
    }

    #[test]
    fn line_angles(xs in prop::collection::vec(-3.0..3.0_f64, 4), d in prop::collection::vec(0.3..2.0_f64, 4),
                   angle in -3.0..3.0_f64) {
        let blocks = vec![
            vec![xs[0], xs[1]], vec![xs[0] + d[0], xs[1] + d[1]],
            vec![xs[2], xs[3]], vec![xs[2] - d[2], xs[3] + d[3]],
        ];
        for r in [LineAngle::new("parallel", 0.0), LineAngle::new("angle", angle)] {
            prop_assert!(check(&r, &blocks) < 1e-6);
        }
    }

    #[test]
    fn tangents_parallel(w1 in prop::collection::vec(-1.0..1.0_f64, 5), w2 in prop::collection::vec(-1.0..1.0_f64, 5)) {
        let r = TangentsParallel::new((basis(), 1.0), (basis(), 0.0));
        let mut blocks = curve_blocks(&w1, &[]);
        blocks.extend(curve_blocks(&w2, &[]));
        prop_assert!(check(&r, &blocks) < 1e-6);
    }

    #[test]
    fn curve_curve_contact(w1 in prop::collection::vec(-1.0..1.0_f64, 5), w2 in prop::collection::vec(-1.0..1.0_f64, 5),
                           u in param(), v in param()) {
        let r = CurveCurveContact::new((basis(), Param::Block), (basis(), Param::Block));
        let mut blocks = curve_blocks(&w1, &[vec![u]]);
        blocks.extend(curve_blocks(&w2, &[vec![v]]));
        prop_assert!(check(&r, &blocks) < 1e-6);
    }

    #[test]
    fn curvature_match(w1 in prop::collection::vec(-1.0..1.0_f64, 5), w2 in prop::collection::vec(-1.0..1.0_f64, 5),
                       u in param(), v in param()) {
        let r = CurvatureMatch::new((basis(), u), (basis(), v));
        let mut blocks = curve_blocks(&w1, &[]);
        blocks.extend(curve_blocks(&w2, &[]));
        prop_assert!(check(&r, &blocks) < 1e-6);
    }
}

/// A residual without its `depends_on`: derivatives over every block it reads.
#[derive(Debug)]
struct Unnarrowed<R>(R);

impl<R: camber_solve::Residual> camber_solve::Residual for Unnarrowed<R> {
    fn name(&self) -> &str {
        self.0.name()
    }
    fn dim(&self) -> usize {
        self.0.dim()
    }
    fn eval<T: camber_solve::Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        self.0.eval(x, out);
    }
}

/// The weighted Hessian over the blocks a residual says it depends on (the p + 1 control points
/// of u's span) equals the one over every block, exactly: the others contribute zeros.
fn same_hessian<R: camber_solve::Residual>(r: R, blocks: &[Vec<f64>]) -> bool {
    use camber_solve::derive::hessian::weighted_hessian;
    let refs: Vec<&[f64]> = blocks.iter().map(|b| &b[..]).collect();
    let n: usize = blocks.iter().map(Vec::len).sum();
    let weights: Vec<f64> = (0..r.dim()).map(|i| 0.7 - 0.4 * i as f64).collect();
    let active = vec![true; blocks.len()];
    let (mut narrow, mut full) = (vec![0.0; n * n], vec![0.0; n * n]);
    weighted_hessian(&r, &refs, &weights, &active, &mut narrow).unwrap();
    weighted_hessian(&Unnarrowed(r), &refs, &weights, &active, &mut full).unwrap();
    narrow
        .iter()
        .zip(&full)
        .all(|(a, b)| (a - b).abs() <= 1e-12 * (1.0 + b.abs()))
}

proptest! {
    #[test]
    fn span_narrowed_hessians_match(wave in prop::collection::vec(-1.0..1.0_f64, 5), u in 0.0..=1.0_f64,
                                    c in prop::array::uniform2(-3.0..3.0_f64), r in 0.1..2.0_f64) {
        let circle = CircleContact::new(basis(), Param::Block, true);
        prop_assert!(same_hessian(circle, &curve_blocks(&wave, &[vec![u], c.to_vec(), vec![r]])));
        let line = LineContact::new(basis(), Param::Block);
        let b = vec![c[0] + 1.0, c[1] - 0.5];
        prop_assert!(same_hessian(line, &curve_blocks(&wave, &[vec![u], c.to_vec(), b])));
        let speed = TangentSpeed::new(basis(), Param::Block, r, 0.2);
        prop_assert!(same_hessian(speed, &curve_blocks(&wave, &[vec![u]])));
    }
}

// The residuals of the classic kinds (issue 12), at random configurations.
proptest! {
    #[test]
    fn equal_length(xs in prop::collection::vec(-3.0..3.0_f64, 8)) {
        use camber_sketch::constraints::equal_length::LengthsEqual;
        let blocks: Vec<Vec<f64>> = xs.chunks(2).map(<[f64]>::to_vec).collect();
        // Away from a zero-length segment (the norm is not differentiable there).
        prop_assume!((xs[2] - xs[0]).hypot(xs[3] - xs[1]) > 0.1);
        prop_assume!((xs[6] - xs[4]).hypot(xs[7] - xs[5]) > 0.1);
        prop_assert!(check(&LengthsEqual, &blocks) < 1e-6);
    }

    #[test]
    fn line_offset(xs in prop::collection::vec(-3.0..3.0_f64, 6), offset in -2.0..2.0_f64) {
        use camber_sketch::constraints::point_on_line::LineOffset;
        let blocks: Vec<Vec<f64>> = xs.chunks(2).map(<[f64]>::to_vec).collect();
        prop_assume!((xs[4] - xs[2]).hypot(xs[5] - xs[3]) > 0.1);
        prop_assert!(check(&LineOffset::new("offset", offset), &blocks) < 1e-6);
    }

    #[test]
    fn mirror(xs in prop::collection::vec(-3.0..3.0_f64, 8)) {
        use camber_sketch::constraints::symmetric::Mirror;
        let blocks: Vec<Vec<f64>> = xs.chunks(2).map(<[f64]>::to_vec).collect();
        prop_assume!((xs[6] - xs[4]).hypot(xs[7] - xs[5]) > 0.1);
        prop_assert!(check(&Mirror, &blocks) < 1e-6);
    }

    #[test]
    fn arc_length(wave in prop::collection::vec(-1.0..1.0_f64, 5), length in 1.0..9.0_f64) {
        use camber_sketch::constraints::arc_length::LengthOf;
        let blocks = curve_blocks(&wave, &[]);
        let refs: Vec<&[f64]> = blocks.iter().map(|b| &b[..]).collect();
        let r = LengthOf::new(basis(), &[0.0, 0.5, 1.0], &refs, length);
        prop_assert!(check(&r, &blocks) < 1e-6);
    }

    #[test]
    fn curvature_value(wave in prop::collection::vec(-1.0..1.0_f64, 5), u in 0.05..0.95_f64, k in -2.0..2.0_f64) {
        use camber_sketch::constraints::curvature_at::CurvatureValue;
        let (fixed, points) = basis().at(u, 2);
        let all = curve_blocks(&wave, &[]);
        let blocks: Vec<Vec<f64>> = points.iter().map(|j| all[*j].clone()).collect();
        prop_assert!(check(&CurvatureValue::new(fixed, u, k), &blocks) < 1e-5);
    }
}

/// The arc-length rule against the closed form of a parabola's length: C(u) = (u, u²) on
/// [0, 1] (the quadratic Bézier (0, 0), (½, 0), (1, 1)) is ∫√(1 + 4u²) du
/// = √5/2 + asinh(2)/4.
#[test]
fn arc_length_of_a_parabola_matches_its_closed_form() {
    use camber_sketch::constraints::arc_length::LengthOf;
    let e = Entity::Bezier(
        camber_geom::BezierCurve2::try_new(vec![
            Point2::new(0.0, 0.0),
            Point2::new(0.5, 0.0),
            Point2::new(1.0, 1.0),
        ])
        .unwrap(),
    );
    let b = CurveBasis::of(&e).unwrap();
    let pts = [[0.0, 0.0], [0.5, 0.0], [1.0, 1.0]];
    let refs: Vec<&[f64]> = pts.iter().map(|p| &p[..]).collect();
    let r = LengthOf::new(b, &[0.0, 1.0], &refs, 1.0);
    let exact = 5f64.sqrt() / 2.0 + 2f64.asinh() / 4.0;
    assert!(
        (r.integral(&refs) - exact).abs() < 1e-14,
        "{}",
        r.integral(&refs) - exact
    );
}

/// The rule on a rational curve and on a Hermite curve (whose control points are a map of its
/// blocks), against closed forms: the quarter circle of radius 2 as a quadratic NURBS is π long,
/// and a Hermite segment from (0, 0) to (3, 0) with tangents (3, 0) at both ends is the
/// straight segment traversed at constant speed, 3 long.
#[test]
fn arc_length_of_a_rational_and_a_hermite_curve_match_their_closed_forms() {
    use camber_sketch::constraints::arc_length::LengthOf;
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let quarter = Entity::Nurbs(
        camber_geom::NurbsCurve2::try_new(
            2,
            camber_geom::KnotVector::bezier(2),
            vec![
                Point2::new(2.0, 0.0),
                Point2::new(2.0, 2.0),
                Point2::new(0.0, 2.0),
            ],
            vec![1.0, h, 1.0],
        )
        .unwrap(),
    );
    let b = CurveBasis::of(&quarter).unwrap();
    let pts = [[2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
    let refs: Vec<&[f64]> = pts.iter().map(|p| &p[..]).collect();
    let r = LengthOf::new(b, &[0.0, 1.0], &refs, 1.0);
    let err = r.integral(&refs) - std::f64::consts::PI;
    assert!(err.abs() < 1e-13, "quarter circle: {err}");

    let segment = Entity::Hermite(
        camber_sketch::hermite_chain::HermiteChain::try_new(
            vec![Point2::new(0.0, 0.0), Point2::new(3.0, 0.0)],
            vec![nalgebra::Vector2::new(3.0, 0.0); 2],
            vec![],
        )
        .unwrap(),
    );
    let (a, z) = segment.domain().unwrap();
    let b = CurveBasis::of(&segment).unwrap();
    let blocks: Vec<[f64; 2]> = segment.points().iter().map(|p| [p.x, p.y]).collect();
    let refs: Vec<&[f64]> = blocks.iter().map(|p| &p[..]).collect();
    let r = LengthOf::new(b, &[a, z], &refs, 1.0);
    let err = r.integral(&refs) - 3.0;
    assert!(err.abs() < 1e-13, "Hermite segment: {err}");
}
