//! Surface evaluation against independent values: central differences, dual numbers, knot
//! insertion (the surface must not change), isocurves, and the JSON form.

use approx::assert_relative_eq;
use camber_geom::scalar::cst;
use camber_geom::{KnotVector, ParametricCurve, Scalar};
use camber_surface::{Direction, Error, NurbsSurface};
use nalgebra::{Point3, Vector3};
use num_dual::Dual64;
use proptest::prelude::*;

/// A rational biquadratic × cubic surface with an interior knot in each direction, in any
/// scalar type.
fn sample_surface<T: Scalar>() -> camber_surface::Result<NurbsSurface<T>> {
    let ku: Vec<T> = [0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0].map(cst::<T>).to_vec();
    let kv: Vec<T> = [0.0, 0.0, 0.0, 0.0, 0.6, 1.0, 1.0, 1.0, 1.0]
        .map(cst::<T>)
        .to_vec();
    let (nu, nv) = (4, 5);
    let mut pts = Vec::new();
    let mut w = Vec::new();
    for i in 0..nu {
        for j in 0..nv {
            let (x, y) = (i as f64, j as f64);
            let z = ((i * 3 + j * 5) % 7) as f64 / 5.0;
            pts.push(Point3::new(cst::<T>(x), cst::<T>(y + 0.2 * x), cst::<T>(z)));
            w.push(cst::<T>(1.0 + ((i + 2 * j) % 3) as f64 * 0.4));
        }
    }
    NurbsSurface::try_new(
        2,
        KnotVector::try_new(ku)?,
        3,
        KnotVector::try_new(kv)?,
        pts,
        w,
    )
}

#[test]
fn derivatives_match_central_differences() {
    let s = sample_surface::<f64>().unwrap();
    let h = 1e-5;
    for &(u, v) in &[(0.2, 0.3), (0.55, 0.7), (0.9, 0.1), (0.35, 0.95)] {
        let d = s.derivatives(u, v).unwrap();
        let p = |u: f64, v: f64| s.point(u, v).unwrap().coords;
        let su = (p(u + h, v) - p(u - h, v)) / (2.0 * h);
        let sv = (p(u, v + h) - p(u, v - h)) / (2.0 * h);
        assert_relative_eq!(d.su, su, epsilon = 1e-7, max_relative = 1e-7);
        assert_relative_eq!(d.sv, sv, epsilon = 1e-7, max_relative = 1e-7);
        let du = |u: f64, v: f64| s.derivatives(u, v).unwrap();
        let suu = (du(u + h, v).su - du(u - h, v).su) / (2.0 * h);
        let suv = (du(u, v + h).su - du(u, v - h).su) / (2.0 * h);
        let svv = (du(u, v + h).sv - du(u, v - h).sv) / (2.0 * h);
        assert_relative_eq!(d.suu, suu, epsilon = 1e-5, max_relative = 1e-6);
        assert_relative_eq!(d.suv, suv, epsilon = 1e-5, max_relative = 1e-6);
        assert_relative_eq!(d.svv, svv, epsilon = 1e-5, max_relative = 1e-6);
        let n = s.normal(u, v).unwrap();
        assert_relative_eq!(n.norm(), 1.0, epsilon = 1e-14);
        assert!(n.dot(&d.su).abs() < 1e-12 && n.dot(&d.sv).abs() < 1e-12);
    }
}

#[test]
fn derivatives_match_dual_numbers() {
    // The same surface evaluated in Dual64 with u (then v) seeded: the derivative part of S is
    // S_u (S_v), that of S_u is S_uu (S_uv), that of S_v is S_vv.
    let s = sample_surface::<Dual64>().unwrap();
    let plain = sample_surface::<f64>().unwrap();
    let eps = |v: &Vector3<Dual64>| v.map(|c| c.eps);
    for &(u, v) in &[(0.2, 0.3), (0.55, 0.7), (0.9, 0.1)] {
        let d = plain.derivatives(u, v).unwrap();
        let by_u = s
            .derivatives(Dual64::from_re(u).derivative(), Dual64::from_re(v))
            .unwrap();
        assert_relative_eq!(eps(&by_u.point.coords), d.su, epsilon = 1e-12);
        assert_relative_eq!(eps(&by_u.su), d.suu, epsilon = 1e-10);
        assert_relative_eq!(eps(&by_u.sv), d.suv, epsilon = 1e-10);
        let by_v = s
            .derivatives(Dual64::from_re(u), Dual64::from_re(v).derivative())
            .unwrap();
        assert_relative_eq!(eps(&by_v.point.coords), d.sv, epsilon = 1e-12);
        assert_relative_eq!(eps(&by_v.sv), d.svv, epsilon = 1e-10);
        assert_relative_eq!(eps(&by_v.su), d.suv, epsilon = 1e-10);
    }
}

proptest! {
    #[test]
    fn knot_insertion_leaves_the_surface_unchanged(
        t in 0.01_f64..0.99, times in 1_usize..3, along_u in any::<bool>(),
        u in 0.0_f64..=1.0, v in 0.0_f64..=1.0,
    ) {
        let s = sample_surface::<f64>().unwrap();
        let dir = if along_u { Direction::U } else { Direction::V };
        let times = if along_u { times.min(2) } else { times };
        let r = s.insert_knot(dir, t, times).unwrap();
        let (nu, nv) = s.counts();
        let expected = if along_u { (nu + times, nv) } else { (nu, nv + times) };
        prop_assert_eq!(r.counts(), expected);
        let (a, b) = (s.derivatives(u, v).unwrap(), r.derivatives(u, v).unwrap());
        prop_assert!((a.point - b.point).norm() < 1e-12);
        prop_assert!((a.su - b.su).norm() < 1e-9 * (1.0 + a.su.norm()));
        prop_assert!((a.sv - b.sv).norm() < 1e-9 * (1.0 + a.sv.norm()));
    }

    #[test]
    fn isocurves_agree_with_surface_points(t in 0.0_f64..=1.0, s_ in 0.0_f64..=1.0) {
        let s = sample_surface::<f64>().unwrap();
        let cu = s.isocurve(Direction::U, t).unwrap(); // v ↦ S(t, v)
        let cv = s.isocurve(Direction::V, t).unwrap(); // u ↦ S(u, t)
        let d1 = s.derivatives(t, s_).unwrap();
        let (p1, t1) = cu.point_and_derivative(s_).unwrap();
        prop_assert!((p1 - d1.point).norm() < 1e-12);
        prop_assert!((t1 - d1.sv).norm() < 1e-9 * (1.0 + d1.sv.norm()));
        let d2 = s.derivatives(s_, t).unwrap();
        let (p2, t2) = cv.point_and_derivative(s_).unwrap();
        prop_assert!((p2 - d2.point).norm() < 1e-12);
        prop_assert!((t2 - d2.su).norm() < 1e-9 * (1.0 + d2.su.norm()));
    }
}

#[test]
fn refinement_in_both_directions() {
    let s = sample_surface::<f64>().unwrap();
    let r = s
        .refine(Direction::U, &[0.1, 0.4, 0.7])
        .unwrap()
        .refine(Direction::V, &[0.2, 0.2])
        .unwrap();
    assert_eq!(r.counts(), (7, 7));
    for &(u, v) in &[(0.05, 0.5), (0.4, 0.2), (1.0, 1.0), (0.0, 0.0)] {
        assert_relative_eq!(
            r.point(u, v).unwrap(),
            s.point(u, v).unwrap(),
            epsilon = 1e-12
        );
    }
    assert!(matches!(
        s.insert_knot(Direction::U, 0.4, 2),
        Err(Error::Geom(camber_geom::Error::KnotMultiplicity { .. }))
    ));
}

#[test]
fn json_round_trip_and_validation() {
    let s = sample_surface::<f64>().unwrap();
    let text = serde_json::to_string(&s).unwrap();
    let back: NurbsSurface<f64> = serde_json::from_str(&text).unwrap();
    assert_eq!(back, s);
    let bad = text.replacen("\"weights\":[1.0", "\"weights\":[-1.0", 1);
    let err = serde_json::from_str::<NurbsSurface<f64>>(&bad).unwrap_err();
    assert!(
        err.to_string().contains("weight 0 is not positive"),
        "{err}"
    );
    let short = text.replacen("\"degree_u\":2", "\"degree_u\":3", 1);
    assert!(serde_json::from_str::<NurbsSurface<f64>>(&short).is_err());
}

#[test]
fn an_absurd_degree_in_a_file_is_an_error_not_an_overflow() {
    let s = sample_surface::<f64>().unwrap();
    let text = serde_json::to_string(&s).unwrap();
    for (field, value) in [("degree_u", 2), ("degree_v", 3)] {
        let huge = text.replacen(
            &format!("\"{field}\":{value}"),
            &format!("\"{field}\":{}", usize::MAX),
            1,
        );
        assert_ne!(huge, text);
        assert!(serde_json::from_str::<NurbsSurface<f64>>(&huge).is_err());
    }
}

#[test]
fn rational_quarter_cylinder_by_hand() {
    // u: the rational quadratic quarter circle of radius 2 from (2, 0) to (0, 2), weights
    // 1, √2/2, 1; v: linear from z = 0 to z = 3. Every point lies on x² + y² = 4 with z = 3v;
    // S_v = (0, 0, 3); the unit normal is radial; S(1/2, v) = (√2, √2, 3v); at u = 0,
    // S_u = p·(w₁/w₀)·(P₁ − P₀) = 2·(√2/2)·(0, 2, 0) = (0, 2√2, 0); the u-isocurves have
    // curvature 1/2.
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let ring = [(2.0, 0.0, 1.0), (2.0, 2.0, h), (0.0, 2.0, 1.0)];
    let mut points = Vec::new();
    let mut weights = Vec::new();
    for (x, y, w) in ring {
        for z in [0.0, 3.0] {
            points.push(Point3::new(x, y, z));
            weights.push(w);
        }
    }
    let s = NurbsSurface::try_new(
        2,
        KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]).unwrap(),
        1,
        KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0]).unwrap(),
        points,
        weights,
    )
    .unwrap();
    for i in 0..=10 {
        for j in 0..=4 {
            let (u, v) = (f64::from(i) / 10.0, f64::from(j) / 4.0);
            let d = s.derivatives(u, v).unwrap();
            let p = d.point;
            assert_relative_eq!(p.x * p.x + p.y * p.y, 4.0, epsilon = 1e-13);
            assert_relative_eq!(p.z, 3.0 * v, epsilon = 1e-14);
            assert_relative_eq!(d.sv, Vector3::new(0.0, 0.0, 3.0), epsilon = 1e-13);
            assert_relative_eq!(d.svv, Vector3::zeros(), epsilon = 1e-13);
            assert_relative_eq!(d.suv, Vector3::zeros(), epsilon = 1e-12);
            let radial = Vector3::new(p.x, p.y, 0.0) / 2.0;
            let n = s.normal(u, v).unwrap();
            assert_relative_eq!(n.dot(&radial).abs(), 1.0, epsilon = 1e-13);
            let kappa = d.su.cross(&d.suu).norm() / d.su.norm().powi(3);
            assert_relative_eq!(kappa, 0.5, epsilon = 1e-12);
        }
    }
    let mid = s.point(0.5, 0.5).unwrap();
    assert_relative_eq!(
        mid,
        Point3::new(2.0_f64.sqrt(), 2.0_f64.sqrt(), 1.5),
        epsilon = 1e-14
    );
    let start = s.derivatives(0.0, 0.2).unwrap();
    assert_relative_eq!(
        start.su,
        Vector3::new(0.0, 2.0 * 2.0_f64.sqrt(), 0.0),
        epsilon = 1e-13
    );
}
