//! Cubic Hermite curves against hand-derived values: the two reparameterization exercises of the
//! lecture (truncation at u = 0.2, 0.7 and subdivision at u = 1/3, 2/3), the blending functions,
//! the U·M·B / blending / Bézier forms against each other, and proptest laws.

use approx::{assert_abs_diff_eq, assert_relative_eq};
use camber_geom::hermite::{
    blending_first_derivatives, blending_functions, blending_second_derivatives,
    blending_third_derivatives, HERMITE_BASIS,
};
use camber_geom::{
    BezierCurve, Error, HermiteCurve, HermiteCurve2, HermiteCurve3, ParametricCurve,
};
use nalgebra::{Point2, Point3, SVector, Vector2, Vector3};
use num_dual::Dual64;
use proptest::prelude::*;

fn curve3(b: [[f64; 3]; 4]) -> HermiteCurve3<f64> {
    HermiteCurve3::try_new(
        Point3::from(b[0]),
        Point3::from(b[1]),
        Vector3::from(b[2]),
        Vector3::from(b[3]),
    )
    .expect("finite test data")
}

/// Asserts that a curve's geometric form equals `expected` (rows p0, p1, t0, t1).
fn assert_geometric<const D: usize>(c: &HermiteCurve<f64, D>, expected: [[f64; D]; 4]) {
    for (row, want) in c.geometric().iter().zip(expected.iter()) {
        assert_relative_eq!(*row, SVector::<f64, D>::from(*want), epsilon = 1e-13);
    }
}

// ---------------------------------------------------------------------------------------------
// Exercise 1: truncate at u = 0.2 and u = 0.7, reparameterize to v ∈ [0, 1].
//
// q0 = p(0.2) = F(0.2)·B, q1 = p(0.7) = F(0.7)·B, and with uj − ui = 0.5,
// q0′ = 0.5·F′(0.2)·B, q1′ = 0.5·F′(0.7)·B. So B_new = R·B with rows:
//
// F(0.2):  u² = 0.04, u³ = 0.008
//   F1 = 0.016 − 0.12 + 1 = 0.896      F2 = −0.016 + 0.12 = 0.104
//   F3 = 0.008 − 0.08 + 0.2 = 0.128    F4 = 0.008 − 0.04 = −0.032
// F(0.7):  u² = 0.49, u³ = 0.343
//   F1 = 0.686 − 1.47 + 1 = 0.216      F2 = −0.686 + 1.47 = 0.784
//   F3 = 0.343 − 0.98 + 0.7 = 0.063    F4 = 0.343 − 0.49 = −0.147
// F′(0.2): F1′ = 0.24 − 1.2 = −0.96, F2′ = 0.96, F3′ = 0.12 − 0.8 + 1 = 0.32, F4′ = 0.12 − 0.4 = −0.28
//   × 0.5 → (−0.48, 0.48, 0.16, −0.14)
// F′(0.7): F1′ = 2.94 − 4.2 = −1.26, F2′ = 1.26, F3′ = 1.47 − 2.8 + 1 = −0.33, F4′ = 1.47 − 1.4 = 0.07
//   × 0.5 → (−0.63, 0.63, −0.165, 0.035)
// ---------------------------------------------------------------------------------------------
const EXERCISE_1_R: [[f64; 4]; 4] = [
    [0.896, 0.104, 0.128, -0.032],
    [0.216, 0.784, 0.063, -0.147],
    [-0.48, 0.48, 0.16, -0.14],
    [-0.63, 0.63, -0.165, 0.035],
];

#[test]
fn exercise_1_truncation_matrix() {
    // Position rows are affine combinations, tangent rows annihilate translations.
    for (i, row) in EXERCISE_1_R.iter().enumerate() {
        let expected = if i < 2 { 1.0 } else { 0.0 };
        assert_abs_diff_eq!(row[0] + row[1], expected, epsilon = 1e-15);
    }
    let b = [
        [1.0, 2.0, -1.0],
        [5.0, -3.0, 2.0],
        [4.0, 0.5, 1.0],
        [-2.0, 6.0, 3.0],
    ];
    let c = curve3(b);
    let t = c.truncated(0.2, 0.7).unwrap();
    let mut expected = [[0.0; 3]; 4];
    for (out, r) in expected.iter_mut().zip(EXERCISE_1_R.iter()) {
        for (k, coord) in out.iter_mut().enumerate() {
            *coord = (0..4).map(|j| r[j] * b[j][k]).sum();
        }
    }
    assert_geometric(&t, expected);
    for i in 0..=10 {
        let v = f64::from(i) / 10.0;
        assert_relative_eq!(
            t.point(v).unwrap(),
            c.point(0.2 + 0.5 * v).unwrap(),
            epsilon = 1e-13
        );
        // Tangents scale by the interval length: q′(v) = 0.5·p′(0.2 + 0.5v).
        assert_relative_eq!(
            t.derivative(v).unwrap(),
            c.derivative(0.2 + 0.5 * v).unwrap() * 0.5,
            epsilon = 1e-13
        );
    }
}

// ---------------------------------------------------------------------------------------------
// Exercise 2: B = [p0, p1, t0, t1] = [(1,1,1), (4,2,4), (1,1,0), (1,1,1)], three segments with
// joints at u = 1/3 and u = 2/3, each reparameterized to [0, 1] (tangents × 1/3).
//
// F(1/3)  = (20/27, 7/27, 4/27, −2/27)      F(2/3)  = (7/27, 20/27, 2/27, −4/27)
// F′(1/3) = (−4/3, 4/3, 0, −1/3)            F′(2/3) = (−4/3, 4/3, −1/3, 0)
//
// p(1/3)  = (20·p0 + 7·p1 + 4·t0 − 2·t1)/27 = (50/27, 36/27, 46/27)
// p(2/3)  = (7·p0 + 20·p1 + 2·t0 − 4·t1)/27 = (85/27, 45/27, 83/27)
// p′(0)   = t0 = (1, 1, 0);  p′(1) = t1 = (1, 1, 1)
// p′(1/3) = (4/3)(p1 − p0) − t1/3 = (11/3, 1, 11/3)
// p′(2/3) = (4/3)(p1 − p0) − t0/3 = (11/3, 1, 4)
// ---------------------------------------------------------------------------------------------
#[test]
fn exercise_2_three_segments() {
    let c = curve3([
        [1.0, 1.0, 1.0],
        [4.0, 2.0, 4.0],
        [1.0, 1.0, 0.0],
        [1.0, 1.0, 1.0],
    ]);
    let p_third = [50.0 / 27.0, 36.0 / 27.0, 46.0 / 27.0];
    let p_two_thirds = [85.0 / 27.0, 45.0 / 27.0, 83.0 / 27.0];
    let expected = [
        [
            [1.0, 1.0, 1.0],
            p_third,
            [1.0 / 3.0, 1.0 / 3.0, 0.0],
            [11.0 / 9.0, 1.0 / 3.0, 11.0 / 9.0],
        ],
        [
            p_third,
            p_two_thirds,
            [11.0 / 9.0, 1.0 / 3.0, 11.0 / 9.0],
            [11.0 / 9.0, 1.0 / 3.0, 4.0 / 3.0],
        ],
        [
            p_two_thirds,
            [4.0, 2.0, 4.0],
            [11.0 / 9.0, 1.0 / 3.0, 4.0 / 3.0],
            [1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0],
        ],
    ];
    let equal = c.subdivided(3).unwrap();
    let at = c.subdivided_at(&[1.0 / 3.0, 2.0 / 3.0]).unwrap();
    assert_eq!(equal.len(), 3);
    assert_eq!(at.len(), 3);
    for ((e, a), want) in equal.iter().zip(at.iter()).zip(expected.iter()) {
        assert_geometric(e, *want);
        assert_geometric(a, *want);
    }
}

#[test]
fn blending_function_values() {
    // At the ends: F(0) = (1, 0, 0, 0), F(1) = (0, 1, 0, 0), F′(0) = (0, 0, 1, 0),
    // F′(1) = (0, 0, 0, 1): the curve interpolates p0, p1, t0, t1.
    let cases = [
        (blending_functions(0.0), [1.0, 0.0, 0.0, 0.0]),
        (blending_functions(1.0), [0.0, 1.0, 0.0, 0.0]),
        (blending_first_derivatives(0.0), [0.0, 0.0, 1.0, 0.0]),
        (blending_first_derivatives(1.0), [0.0, 0.0, 0.0, 1.0]),
        // F(1/2) = (1/2, 1/2, 1/8, −1/8); F″(0) = (−6, 6, −4, −2).
        (blending_functions(0.5), [0.5, 0.5, 0.125, -0.125]),
        (blending_second_derivatives(0.0), [-6.0, 6.0, -4.0, -2.0]),
        (blending_third_derivatives(), [12.0, -12.0, 6.0, 6.0]),
    ];
    for (got, want) in cases {
        for (g, w) in got.iter().zip(want.iter()) {
            assert_abs_diff_eq!(*g, *w, epsilon = 1e-15);
        }
    }
    for i in 0..=20 {
        let u = f64::from(i) / 20.0;
        let f = blending_functions(u);
        assert_abs_diff_eq!(f[0] + f[1], 1.0, epsilon = 1e-15);
        // F3 ≥ 0 and F4 ≤ 0 on [0, 1].
        assert!(f[2] >= 0.0 && f[3] <= 0.0);
    }
}

#[test]
fn blending_derivatives_match_central_differences() {
    let h = 1e-5;
    for i in 0..=10 {
        let u = -0.2 + 1.4 * f64::from(i) / 10.0;
        let diff = |g: fn(f64) -> [f64; 4]| {
            let (a, b) = (g(u + h), g(u - h));
            [0, 1, 2, 3].map(|j| (a[j] - b[j]) / (2.0 * h))
        };
        let d1 = blending_first_derivatives(u);
        let d2 = blending_second_derivatives(u);
        let d3 = blending_third_derivatives::<f64>();
        let fd1 = diff(blending_functions);
        let fd2 = diff(blending_first_derivatives);
        let fd3 = diff(blending_second_derivatives);
        for j in 0..4 {
            assert_abs_diff_eq!(fd1[j], d1[j], epsilon = 1e-8);
            assert_abs_diff_eq!(fd2[j], d2[j], epsilon = 1e-8);
            assert_abs_diff_eq!(fd3[j], d3[j], epsilon = 1e-8);
        }
    }
}

#[test]
fn tangent_matches_dual_number_derivative() {
    let c = curve3([
        [0.0, 1.0, 2.0],
        [3.0, -1.0, 0.5],
        [2.0, 2.0, -1.0],
        [-4.0, 1.0, 0.0],
    ]);
    // The same curve in dual numbers; seeding u gives dp/du in the eps parts.
    let lift = |v: Vector3<f64>| v.map(Dual64::from_re);
    let g = c.geometric();
    let cd = HermiteCurve3::<Dual64>::try_new(
        Point3::from(lift(g[0])),
        Point3::from(lift(g[1])),
        lift(g[2]),
        lift(g[3]),
    )
    .unwrap();
    for &u in &[0.0, 0.25, 0.6, 1.0] {
        let p = cd.point(Dual64::from_re(u).derivative()).unwrap();
        let d = c.derivative(u).unwrap();
        let dd = cd.derivative(Dual64::from_re(u).derivative()).unwrap();
        let s = c.second_order(u).unwrap()[2];
        for k in 0..3 {
            assert_relative_eq!(p[k].eps, d[k], epsilon = 1e-13);
            assert_relative_eq!(dd[k].eps, s[k], epsilon = 1e-13);
        }
    }
}

/// The cubic Bernstein form, written out: Σ C(3, i) tⁱ (1 − t)³⁻ⁱ Pᵢ.
fn bernstein_point<const D: usize>(control: &[nalgebra::Point<f64, D>], t: f64) -> SVector<f64, D> {
    let s = 1.0 - t;
    let w = [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t];
    control
        .iter()
        .zip(w.iter())
        .fold(SVector::zeros(), |acc, (p, &wi)| acc + p.coords * wi)
}

#[test]
fn three_forms_agree() {
    let c = HermiteCurve2::try_new(
        Point2::new(0.0, 0.0),
        Point2::new(4.0, 1.0),
        Vector2::new(1.0, 6.0),
        Vector2::new(3.0, -2.0),
    )
    .unwrap();
    let bezier = c.to_bezier().unwrap();
    assert_eq!(bezier.degree(), 3);
    // P1 = p0 + t0/3, P2 = p1 − t1/3.
    assert_relative_eq!(
        bezier.control_points()[1],
        Point2::new(1.0 / 3.0, 2.0),
        epsilon = 1e-15
    );
    assert_relative_eq!(
        bezier.control_points()[2],
        Point2::new(3.0, 5.0 / 3.0),
        epsilon = 1e-15
    );
    // U·M·B with M written out from HERMITE_BASIS, independently of `algebraic`.
    let b = c.geometric();
    for i in 0..=8 {
        let u = f64::from(i) / 8.0;
        let uu = [u * u * u, u * u, u, 1.0];
        let mut umb = Vector2::zeros();
        for (r, &ur) in uu.iter().enumerate() {
            for (col, bc) in b.iter().enumerate() {
                umb += bc * (ur * HERMITE_BASIS[r][col]);
            }
        }
        let [a3, a2, a1, a0] = c.algebraic();
        let horner = ((a3 * u + a2) * u + a1) * u + a0;
        let p = c.point(u).unwrap().coords;
        assert_relative_eq!(p, umb, epsilon = 1e-13);
        assert_relative_eq!(p, horner, epsilon = 1e-13);
        assert_relative_eq!(
            p,
            bernstein_point(bezier.control_points(), u),
            epsilon = 1e-13
        );
    }
}

#[test]
fn non_cubic_bezier_is_rejected() {
    let quad = BezierCurve::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 1.0),
        Point2::new(2.0, 0.0),
    ])
    .unwrap();
    assert_eq!(
        HermiteCurve::from_bezier(&quad),
        Err(Error::DegreeMismatch {
            expected: 3,
            found: 2
        })
    );
}

#[test]
fn reversed_matches_lecture_form() {
    let c = curve3([
        [1.0, 0.0, 0.0],
        [2.0, 3.0, 1.0],
        [0.5, 1.0, 2.0],
        [1.0, -1.0, 0.0],
    ]);
    let r = c.reversed();
    // B₂ = [p1, p0, −p1′, −p0′].
    assert_geometric(
        &r,
        [
            [2.0, 3.0, 1.0],
            [1.0, 0.0, 0.0],
            [-1.0, 1.0, 0.0],
            [-0.5, -1.0, -2.0],
        ],
    );
}

fn coord() -> impl Strategy<Value = f64> {
    -10.0..10.0
}

fn arb_curve() -> impl Strategy<Value = HermiteCurve2<f64>> {
    prop::array::uniform8(coord()).prop_map(|c| {
        HermiteCurve2::try_new(
            Point2::new(c[0], c[1]),
            Point2::new(c[2], c[3]),
            Vector2::new(c[4], c[5]),
            Vector2::new(c[6], c[7]),
        )
        .expect("finite coordinates")
    })
}

proptest! {
    #[test]
    fn truncation_reproduces_the_curve(c in arb_curve(), a in 0.0..1.0f64, b in 0.0..1.0f64, v in 0.0..=1.0f64) {
        prop_assume!((a - b).abs() > 1e-3);
        let (ui, uj) = if a < b { (a, b) } else { (b, a) };
        let t = c.truncated(ui, uj).unwrap();
        let u = ui + (uj - ui) * v;
        prop_assert!((t.point(v).unwrap() - c.point(u).unwrap()).norm() < 1e-10);
        prop_assert!((t.derivative(v).unwrap() - c.derivative(u).unwrap() * (uj - ui)).norm() < 1e-10);
    }

    #[test]
    fn subdivision_reproduces_the_curve(c in arb_curve(), n in 1usize..8, v in 0.0..=1.0f64) {
        let pieces = c.subdivided(n).unwrap();
        prop_assert_eq!(pieces.len(), n);
        let nf = n as f64;
        for (i, piece) in pieces.iter().enumerate() {
            let u = (i as f64 + v) / nf;
            prop_assert!((piece.point(v).unwrap() - c.point(u).unwrap()).norm() < 1e-10);
            prop_assert!((piece.derivative(v).unwrap() - c.derivative(u).unwrap() / nf).norm() < 1e-10);
        }
    }

    #[test]
    fn subdivision_at_joints_reproduces_the_curve(
        c in arb_curve(),
        mut joints in prop::collection::vec(0.01..0.99f64, 0..5),
        v in 0.0..=1.0f64,
    ) {
        joints.sort_by(f64::total_cmp);
        joints.dedup_by(|a, b| (*a - *b).abs() < 1e-3);
        let pieces = c.subdivided_at(&joints).unwrap();
        prop_assert_eq!(pieces.len(), joints.len() + 1);
        let mut ends = vec![0.0];
        ends.extend_from_slice(&joints);
        ends.push(1.0);
        for (piece, w) in pieces.iter().zip(ends.windows(2)) {
            let u = w[0] + (w[1] - w[0]) * v;
            prop_assert!((piece.point(v).unwrap() - c.point(u).unwrap()).norm() < 1e-10);
            // Consecutive pieces join with C1 continuity in the original parameter.
            prop_assert!((piece.t0() / (w[1] - w[0]) - c.derivative(w[0]).unwrap()).norm() < 1e-9);
        }
    }

    #[test]
    fn reversed_twice_is_identity(c in arb_curve(), v in 0.0..=1.0f64) {
        let r = c.reversed();
        prop_assert!((r.point(v).unwrap() - c.point(1.0 - v).unwrap()).norm() < 1e-10);
        prop_assert!((r.derivative(v).unwrap() + c.derivative(1.0 - v).unwrap()).norm() < 1e-10);
        prop_assert_eq!(r.reversed(), c);
    }

    #[test]
    fn bezier_round_trip(c in arb_curve(), v in 0.0..=1.0f64) {
        let b = c.to_bezier().unwrap();
        let back = HermiteCurve::from_bezier(&b).unwrap();
        for (x, y) in back.geometric().iter().zip(c.geometric().iter()) {
            prop_assert!((x - y).norm() < 1e-12);
        }
        prop_assert!((bernstein_point(b.control_points(), v) - c.point(v).unwrap().coords).norm() < 1e-10);
    }

    #[test]
    fn algebraic_round_trip(c in arb_curve()) {
        let back = HermiteCurve2::from_algebraic(c.algebraic()).unwrap();
        for (x, y) in back.geometric().iter().zip(c.geometric().iter()) {
            prop_assert!((x - y).norm() < 1e-12);
        }
    }

    #[test]
    fn serde_round_trip(c in arb_curve()) {
        let json = serde_json::to_string(&c).unwrap();
        let back: HermiteCurve2<f64> = serde_json::from_str(&json).unwrap();
        // serde_json's default float parser may differ from the written value in the last bit.
        for (x, y) in back.geometric().iter().zip(c.geometric().iter()) {
            prop_assert!((x - y).norm() <= 1e-15 * (1.0 + y.norm()));
        }
    }
}

#[test]
fn serde_rejects_non_finite_and_wrong_dimension() {
    // JSON cannot carry NaN, but a huge literal overflows to infinity on parse.
    let inf = r#"{"p0":[0,0],"p1":[1e999,0],"t0":[1,0],"t1":[1,0]}"#;
    assert!(serde_json::from_str::<HermiteCurve2<f64>>(inf).is_err());
    let ok = r#"{"p0":[0,0,0],"p1":[1,0,0],"t0":[1,0,0],"t1":[1,0,0]}"#;
    assert!(serde_json::from_str::<HermiteCurve3<f64>>(ok).is_ok());
    assert!(serde_json::from_str::<HermiteCurve2<f64>>(ok).is_err());
}
