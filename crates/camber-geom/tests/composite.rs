//! Composite curves of test-only polynomial pieces: evaluation under the global parameter, the
//! joint reports of C2, C1, G2, G1, C0 and broken joints, and queries across joints.

// Fixture helpers outside #[test] functions unwrap constructors of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::{assert_abs_diff_eq, assert_relative_eq};
use camber_geom::composite::ContinuityTolerances;
use camber_geom::curve::check_parameter;
use camber_geom::queries::{closest_point, distance_to_line, intersect_line};
use camber_geom::{
    CompositeCurve, CompositeCurve2, Continuity, Error, Line, ParametricCurve, Result,
};
use nalgebra::{Point2, SVector, Vector2};
use proptest::prelude::*;

/// C(u) = Σ_k c_k u^k on a given domain, with optional interior breakpoints to report.
struct Poly {
    coeffs: Vec<SVector<f64, 2>>,
    domain: (f64, f64),
    breaks: Vec<f64>,
}

impl ParametricCurve<f64, 2> for Poly {
    fn domain(&self) -> (f64, f64) {
        self.domain
    }

    fn derivatives_into(&self, u: f64, out: &mut [SVector<f64, 2>]) -> Result<()> {
        check_parameter(u, self.domain)?;
        for (k, o) in out.iter_mut().enumerate() {
            *o = SVector::zeros();
            for (j, c) in self.coeffs.iter().enumerate().skip(k) {
                let falling: f64 = (j - k + 1..=j).map(|m| m as f64).product();
                *o += c * (falling * u.powi((j - k) as i32));
            }
        }
        Ok(())
    }

    fn breakpoints(&self) -> Vec<f64> {
        let mut out = vec![self.domain.0];
        out.extend(&self.breaks);
        out.push(self.domain.1);
        out
    }
}

fn poly(coeffs: &[[f64; 2]], domain: (f64, f64)) -> Box<dyn ParametricCurve<f64, 2>> {
    Box::new(Poly {
        coeffs: coeffs.iter().map(|c| SVector::from(*c)).collect(),
        domain,
        breaks: Vec::new(),
    })
}

fn chain(pieces: Vec<Box<dyn ParametricCurve<f64, 2>>>) -> CompositeCurve2<f64> {
    CompositeCurve::try_new(pieces).unwrap()
}

/// One cubic, P(u) = (u, 1 − u + u³/2 … ), used split into two pieces.
const CUBIC: [[f64; 2]; 4] = [[0.0, 1.0], [1.0, -1.0], [0.5, 0.0], [-0.2, 0.5]];

#[test]
fn evaluation_maps_each_piece_affinely() {
    // P on [0, 0.5] and P on [0.5, 2]: s ∈ [0, 1] ↦ u = s/2, s ∈ [1, 2] ↦ u = 0.5 + 1.5(s − 1).
    let whole = Poly {
        coeffs: CUBIC.iter().map(|c| SVector::from(*c)).collect(),
        domain: (0.0, 2.0),
        breaks: Vec::new(),
    };
    let c = chain(vec![poly(&CUBIC, (0.0, 0.5)), poly(&CUBIC, (0.5, 2.0))]);
    assert_eq!(c.domain(), (0.0, 2.0));
    assert_eq!(c.len(), 2);
    for (s, u, scale) in [
        (0.0, 0.0, 0.5),
        (0.6, 0.3, 0.5),
        (1.0, 0.5, 1.5),
        (1.4, 1.1, 1.5),
        (2.0, 2.0, 1.5),
    ] {
        let got = c.derivatives(s, 2).unwrap();
        let want = whole.derivatives(u, 2).unwrap();
        assert_relative_eq!(got[0], want[0], epsilon = 1e-14);
        assert_relative_eq!(got[1], want[1] * scale, epsilon = 1e-14);
        assert_relative_eq!(got[2], want[2] * scale * scale, epsilon = 1e-14);
    }
    assert!(matches!(
        c.point(2.5),
        Err(Error::ParameterOutsideDomain { .. })
    ));
    // A finite-difference check of the first derivative across a piece.
    let h = 1e-6;
    let fd = (c.point(1.3 + h).unwrap() - c.point(1.3 - h).unwrap()) / (2.0 * h);
    assert_relative_eq!(fd, c.derivative(1.3).unwrap(), epsilon = 1e-8);
}

#[test]
fn breakpoints_include_joints_and_piece_knots() {
    let inner = Poly {
        coeffs: vec![SVector::from([0.0, 0.0]), SVector::from([1.0, 0.0])],
        domain: (2.0, 6.0),
        breaks: vec![3.0, 5.0],
    };
    let c = chain(vec![
        poly(&CUBIC, (0.0, 1.0)),
        Box::new(inner),
        poly(&CUBIC, (1.0, 2.0)),
    ]);
    let b = c.breakpoints();
    let want = [0.0, 1.0, 1.25, 1.75, 2.0, 3.0];
    assert_eq!(b.len(), want.len());
    for (x, y) in b.iter().zip(want) {
        assert_abs_diff_eq!(*x, y, epsilon = 1e-15);
    }
}

#[test]
fn empty_chain_is_an_error() {
    assert_eq!(
        CompositeCurve::<f64, 2>::try_new(Vec::new()).unwrap_err(),
        Error::ZeroCount {
            what: "pieces of a composite curve"
        }
    );
}

#[test]
fn a_split_cubic_is_c2() {
    let c = chain(vec![poly(&CUBIC, (0.0, 0.5)), poly(&CUBIC, (0.5, 2.0))]);
    let joints = c.joints().unwrap();
    assert_eq!(joints.len(), 1);
    let j = &joints[0];
    assert_eq!(j.index, 0);
    assert_abs_diff_eq!(j.position_gap, 0.0);
    assert_abs_diff_eq!(j.tangent_angle, 0.0);
    assert_abs_diff_eq!(j.first_derivative_mismatch, 0.0);
    assert_abs_diff_eq!(j.curvature_difference, 0.0);
    assert_abs_diff_eq!(j.second_derivative_mismatch, 0.0);
    assert_eq!(
        j.continuity(&ContinuityTolerances::default()),
        Continuity::C2
    );
}

#[test]
fn joint_reports_by_hand() {
    let tol = ContinuityTolerances::default();
    // Left: the straight line (u, 0) on [0, 1], ending at (1, 0) with C′ = (1, 0), C″ = 0.
    let left = || poly(&[[0.0, 0.0], [1.0, 0.0]], (0.0, 1.0));

    // (1 + 2u, u²): same direction, twice the speed, κ = |2·2|/2³ = 1/2. G1 only.
    let c = chain(vec![
        left(),
        poly(&[[1.0, 0.0], [2.0, 0.0], [0.0, 1.0]], (0.0, 1.0)),
    ]);
    let j = c.joints().unwrap()[0];
    assert_abs_diff_eq!(j.position_gap, 0.0);
    assert_abs_diff_eq!(j.tangent_angle, 0.0);
    assert_abs_diff_eq!(j.first_derivative_mismatch, 1.0);
    assert_abs_diff_eq!(j.curvature_difference, 0.5);
    assert_abs_diff_eq!(j.curvature_vector_difference, 0.5);
    assert_abs_diff_eq!(j.second_derivative_mismatch, 2.0);
    assert_eq!(j.continuity(&tol), Continuity::G1);

    // (1 + u, u²): same derivative, κ = 2. C1, not G2.
    let c = chain(vec![
        left(),
        poly(&[[1.0, 0.0], [1.0, 0.0], [0.0, 1.0]], (0.0, 1.0)),
    ]);
    let j = c.joints().unwrap()[0];
    assert_abs_diff_eq!(j.curvature_difference, 2.0);
    assert_eq!(j.continuity(&tol), Continuity::C1);

    // (1 + 3u, 0): straight on at a different speed. G2, not C1.
    let c = chain(vec![left(), poly(&[[1.0, 0.0], [3.0, 0.0]], (0.0, 1.0))]);
    assert_eq!(c.joints().unwrap()[0].continuity(&tol), Continuity::G2);

    // (1 + u, u) : a 45° corner. C0.
    let c = chain(vec![left(), poly(&[[1.0, 0.0], [1.0, 1.0]], (0.0, 1.0))]);
    let j = c.joints().unwrap()[0];
    assert_abs_diff_eq!(
        j.tangent_angle,
        std::f64::consts::FRAC_PI_4,
        epsilon = 1e-15
    );
    assert_eq!(j.continuity(&tol), Continuity::C0);

    // Starting at (1, 0.1): a gap.
    let c = chain(vec![left(), poly(&[[1.0, 0.1], [1.0, 0.0]], (0.0, 1.0))]);
    let j = c.joints().unwrap()[0];
    assert_abs_diff_eq!(j.position_gap, 0.1, epsilon = 1e-15);
    assert_eq!(j.continuity(&tol), Continuity::None);
    // … which a looser position tolerance accepts.
    let loose = ContinuityTolerances {
        position: 0.2,
        ..tol
    };
    assert_eq!(j.continuity(&loose), Continuity::C2);
}

#[test]
fn an_inflection_at_the_joint_is_not_g2() {
    // (u, u²/2) on [−1, 0] then (u, −u²/2) on [0, 1]: equal |κ| = 1 but opposite sides.
    let c = chain(vec![
        poly(&[[0.0, 0.0], [1.0, 0.0], [0.0, 0.5]], (-1.0, 0.0)),
        poly(&[[0.0, 0.0], [1.0, 0.0], [0.0, -0.5]], (0.0, 1.0)),
    ]);
    let j = c.joints().unwrap()[0];
    assert_abs_diff_eq!(j.curvature_difference, 0.0);
    assert_abs_diff_eq!(j.curvature_vector_difference, 2.0);
    assert_eq!(
        j.continuity(&ContinuityTolerances::default()),
        Continuity::C1
    );
}

#[test]
fn a_stationary_end_has_no_tangent() {
    // (u², 0) on [−1, 0] ends with C′ = 0.
    let c = chain(vec![
        poly(&[[0.0, 0.0], [0.0, 0.0], [1.0, 0.0]], (-1.0, 0.0)),
        poly(&[[0.0, 0.0], [1.0, 0.0]], (0.0, 1.0)),
    ]);
    let j = c.joints().unwrap()[0];
    assert_abs_diff_eq!(j.tangent_angle, std::f64::consts::PI);
    assert!(j.curvature_difference.is_infinite());
    assert_eq!(
        j.continuity(&ContinuityTolerances::default()),
        Continuity::C0
    );
}

#[test]
fn queries_see_the_corner_of_an_l_shape() {
    // (0,0) → (1,0) → (1,1), the second leg on its own domain [2, 4].
    let c = chain(vec![
        poly(&[[0.0, 0.0], [1.0, 0.0]], (0.0, 1.0)),
        poly(&[[1.0, -1.0], [0.0, 0.5]], (2.0, 4.0)),
    ]);
    let near = closest_point(&c, &Point2::new(2.0, -1.0)).unwrap();
    assert_abs_diff_eq!(near.parameter, 1.0, epsilon = 1e-12);
    assert_abs_diff_eq!(near.distance, 2.0_f64.sqrt(), epsilon = 1e-14);
    let near = closest_point(&c, &Point2::new(3.0, 0.5)).unwrap();
    assert_abs_diff_eq!(near.parameter, 1.5, epsilon = 1e-12);
    assert_abs_diff_eq!(near.distance, 2.0, epsilon = 1e-14);
    // The line x + y = 1 passes through the corner: one intersection, at s = 1 (and touches
    // the other ends: (0,0) has g < 0, (1,1) g > 0, so it is a crossing).
    let line = Line::through(Point2::new(0.0, 1.0), Point2::new(1.0, 0.0)).unwrap();
    let hits = intersect_line(&c, &line).unwrap();
    assert_eq!(hits.len(), 1, "{hits:?}");
    assert_abs_diff_eq!(hits[0].parameter, 1.0, epsilon = 1e-12);
    // A vertical line x = 0.5 crosses the first leg only.
    let line = Line::try_new(Point2::new(0.5, 0.0), Vector2::new(0.0, 1.0)).unwrap();
    let hits = intersect_line(&c, &line).unwrap();
    assert_eq!(hits.len(), 1);
    assert_abs_diff_eq!(hits[0].parameter, 0.5, epsilon = 1e-14);
}

#[test]
fn a_line_through_a_gap_is_not_an_intersection() {
    // (u, −1) on [0, 1] ends at (1, −1); the next piece starts at (1, 1). The sign change of y across the joint is a jump, not a crossing.
    let c = chain(vec![
        poly(&[[0.0, -1.0], [1.0, 0.0]], (0.0, 1.0)),
        poly(&[[1.0, 1.0], [1.0, 0.0]], (0.0, 1.0)),
    ]);
    let x_axis = Line::try_new(Point2::new(0.0, 0.0), Vector2::new(1.0, 0.0)).unwrap();
    assert!(intersect_line(&c, &x_axis).unwrap().is_empty());
    let d = distance_to_line(&c, &x_axis).unwrap();
    assert_abs_diff_eq!(d.distance, 1.0, epsilon = 1e-14);
}

proptest! {
    #[test]
    fn derivatives_match_central_differences(
        coeffs in prop::collection::vec(prop::array::uniform2(-2.0..2.0_f64), 4),
        split in 0.2..0.8_f64,
        s in 0.05..1.95_f64,
    ) {
        prop_assume!((s - 1.0).abs() > 1e-3);
        let c = chain(vec![poly(&coeffs, (0.0, split)), poly(&coeffs, (split, 1.0))]);
        let h = 1e-6;
        let d = c.derivatives(s, 2).unwrap();
        let fd1 = (c.point(s + h).unwrap() - c.point(s - h).unwrap()) / (2.0 * h);
        let fd2 = (c.derivative(s + h).unwrap() - c.derivative(s - h).unwrap()) / (2.0 * h);
        prop_assert!((fd1 - d[1]).norm() < 1e-6 * (1.0 + d[1].norm()));
        prop_assert!((fd2 - d[2]).norm() < 1e-6 * (1.0 + d[2].norm()));
        // The split cubic is always C2 at its joint.
        let j = c.joints().unwrap()[0];
        prop_assert!(j.position_gap < 1e-12 && j.second_derivative_mismatch < 1e-12);
    }
}

#[test]
fn piece_at_names_the_piece_and_its_own_parameter() {
    // Pieces on [0, 0.5] and [0.5, 2]: s = 1.5 is u = 0.5 + 1.5 · 0.5 = 1.25 on piece 1.
    let c = chain(vec![poly(&CUBIC, (0.0, 0.5)), poly(&CUBIC, (0.5, 2.0))]);
    assert_eq!(c.piece_at(0.0).unwrap(), (0, 0.0));
    assert_eq!(c.piece_at(0.5).unwrap(), (0, 0.25));
    assert_eq!(c.piece_at(1.0).unwrap(), (1, 0.5));
    assert_eq!(c.piece_at(1.5).unwrap(), (1, 1.25));
    assert_eq!(c.piece_at(2.0).unwrap(), (1, 2.0));
    assert!(matches!(
        c.piece_at(2.5),
        Err(Error::ParameterOutsideDomain { .. })
    ));
    assert!(c.piece_at(f64::NAN).is_err());
}

#[test]
fn a_chain_of_one_concrete_piece_type_is_cloneable_and_shareable_across_threads() {
    use camber_geom::BezierCurve2;
    fn send_sync<T: Send + Sync + Clone>(_: &T) {}
    let seg = |a: [f64; 2], b: [f64; 2]| {
        BezierCurve2::try_new(vec![Point2::from(a), Point2::from(b)]).unwrap()
    };
    let c: CompositeCurve<f64, 2, BezierCurve2<f64>> = CompositeCurve::try_from_pieces(vec![
        seg([0.0, 0.0], [1.0, 0.0]),
        seg([1.0, 0.0], [1.0, 2.0]),
    ])
    .unwrap();
    send_sync(&c);
    let copy = c.clone();
    let p = std::thread::scope(|scope| scope.spawn(|| copy.point(1.25)).join().unwrap()).unwrap();
    assert_abs_diff_eq!(p, Point2::new(1.0, 0.5), epsilon = 1e-15);
    assert_eq!(c.pieces().len(), 2);
    assert_eq!(
        c.into_pieces()[1].control_points()[1],
        Point2::new(1.0, 2.0)
    );
}
