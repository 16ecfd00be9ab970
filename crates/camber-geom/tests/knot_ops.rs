//! Knot operations on control nets: hand-derived cases (The NURBS Book example 5.1, simple
//! degree elevations, clamping a uniform cubic) and proptest invariants on random unclamped nets
//! off [0, 1]: every operation leaves the curve unchanged.

// Test helpers outside #[test] functions unwrap too; a failed unwrap is a failed test.
#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use camber_geom::knot_ops::ControlNet;
use camber_geom::{Error, KnotVector};
use proptest::prelude::*;

fn net(degree: usize, knots: Vec<f64>, dim: usize, coords: Vec<f64>) -> ControlNet<f64> {
    ControlNet::try_new(degree, KnotVector::try_new(knots).unwrap(), dim, coords).unwrap()
}

fn eval(n: &ControlNet<f64>, u: f64) -> Vec<f64> {
    let mut out = vec![0.0; n.dim];
    n.evaluate_into(u, &mut out).unwrap();
    out
}

/// Bézier evaluation by de Casteljau's algorithm, independent of the code under test.
fn de_casteljau(coords: &[f64], dim: usize, t: f64) -> Vec<f64> {
    let mut pts = coords.to_vec();
    let count = coords.len() / dim;
    for level in 1..count {
        for i in 0..count - level {
            for c in 0..dim {
                pts[i * dim + c] = (1.0 - t) * pts[i * dim + c] + t * pts[(i + 1) * dim + c];
            }
        }
    }
    pts.truncate(dim);
    pts
}

fn assert_close(x: &[f64], y: &[f64], tol: f64) {
    assert_eq!(x.len(), y.len());
    for (a, b) in x.iter().zip(y) {
        assert!((a - b).abs() < tol, "{x:?} vs {y:?}");
    }
}

fn same_curve(a: &ControlNet<f64>, b: &ControlNet<f64>) {
    let (u0, u1) = a.domain();
    let (v0, v1) = b.domain();
    assert_relative_eq!(u0, v0, epsilon = 1e-15);
    assert_relative_eq!(u1, v1, epsilon = 1e-15);
    for i in 0..=40 {
        let u = (u0 + (u1 - u0) * f64::from(i) / 40.0).min(u1);
        assert_close(&eval(a, u), &eval(b, u), 1e-12);
    }
}

#[test]
fn book_example_5_1_single_insertion() {
    // Cubic, U = {0,0,0,0,1,2,3,4,5,5,5,5}, insert u = 5/2: α₃ = 5/6, α₄ = 1/2, α₅ = 1/6 and
    // Q_i = α_i P_i + (1 − α_i) P_{i−1}; the other points are kept.
    let knots = vec![0., 0., 0., 0., 1., 2., 3., 4., 5., 5., 5., 5.];
    let p: Vec<f64> = (0..8).map(|i| f64::from(i * i)).collect();
    let n = net(3, knots, 1, p.clone());
    let q = n.insert_knot(2.5, 1).unwrap();
    let expected = [
        p[0],
        p[1],
        p[2],
        5.0 / 6.0 * p[3] + 1.0 / 6.0 * p[2],
        0.5 * p[4] + 0.5 * p[3],
        1.0 / 6.0 * p[5] + 5.0 / 6.0 * p[4],
        p[5],
        p[6],
        p[7],
    ];
    assert_close(&q.coords, &expected, 1e-13);
    assert_eq!(q.knots.multiplicity(2.5), 1);
    assert_eq!(q.knots.len(), 13);
    same_curve(&n, &q);
}

#[test]
fn elevation_of_simple_cases() {
    // Quadratic Bézier (0, 1, 0) → cubic (0, 2/3, 2/3, 0).
    let b = net(2, vec![0., 0., 0., 1., 1., 1.], 1, vec![0., 1., 0.]);
    let e = b.elevate_degree(1).unwrap();
    assert_eq!(e.degree, 3);
    assert_close(&e.coords, &[0.0, 2.0 / 3.0, 2.0 / 3.0, 0.0], 1e-15);
    // Polyline (0, 1, 0) on [0, 2] → quadratic with a double knot at 1.
    let l = net(1, vec![0., 0., 1., 2., 2.], 1, vec![0., 1., 0.]);
    let e = l.elevate_degree(1).unwrap();
    assert_close(e.knots.as_slice(), &[0., 0., 0., 1., 1., 2., 2., 2.], 1e-15);
    assert_close(&e.coords, &[0.0, 0.5, 1.0, 0.5, 0.0], 1e-15);
    // A break (interior multiplicity p + 1) stays a break.
    let d = net(1, vec![0., 0., 1., 1., 2., 2.], 1, vec![0., 1., 5., 6.]);
    let e = d.elevate_degree(1).unwrap();
    assert_close(
        e.knots.as_slice(),
        &[0., 0., 0., 1., 1., 1., 2., 2., 2.],
        1e-15,
    );
    assert_close(&e.coords, &[0.0, 0.5, 1.0, 5.0, 5.5, 6.0], 1e-15);
    same_curve(&d, &e);
    // Degree 0 → degree 2: each constant piece repeated.
    let c = net(0, vec![0., 1., 2.], 1, vec![3., 4.]);
    let e = c.elevate_degree(2).unwrap();
    assert_close(&e.coords, &[3., 3., 3., 4., 4., 4.], 1e-15);
    same_curve(&c, &e);
}

#[test]
fn clamping_an_unclamped_uniform_cubic() {
    // Uniform cubic on [3, 4]: clamped, its end points are the curve's end points,
    // (P0 + 4 P1 + P2) / 6 = 6 and (P1 + 4 P2 + P3) / 6 = 10.
    let n = net(3, (0..8).map(f64::from).collect(), 1, vec![0., 6., 12., 6.]);
    let c = n.clamped();
    assert_close(c.knots.as_slice(), &[3., 3., 3., 3., 4., 4., 4., 4.], 1e-15);
    assert_relative_eq!(c.coords[0], 6.0, epsilon = 1e-14);
    assert_relative_eq!(c.coords[3], 10.0, epsilon = 1e-14);
    same_curve(&n, &c);
    assert_eq!(c.decompose().len(), 1);
}

#[test]
fn errors_name_the_problem() {
    let n = net(2, vec![0., 0., 0., 1., 2., 2., 2.], 2, vec![0.0; 8]);
    assert_eq!(
        n.insert_knot(1.0, 2),
        Err(Error::KnotMultiplicity {
            value: 1.0,
            multiplicity: 1,
            times: 2,
            degree: 2
        })
    );
    assert!(matches!(
        n.insert_knot(2.5, 1),
        Err(Error::ParameterOutsideDomain { .. })
    ));
    assert!(matches!(
        n.refine(&[0.5, 0.2]),
        Err(Error::DecreasingKnots { index: 1, .. })
    ));
    assert!(matches!(
        n.refine(&[0.5, f64::NAN]),
        Err(Error::NonFinite { index: 1, .. })
    ));
    assert!(matches!(
        n.refine(&[0.5, 0.5, 0.5]),
        Err(Error::KnotMultiplicity { times: 3, .. })
    ));
    assert!(matches!(
        n.split(0.0),
        Err(Error::ParameterOutsideDomain { .. })
    ));
    assert!(matches!(
        n.reparameterized(1.0, 1.0),
        Err(Error::InvalidInterval { .. })
    ));
    let bad = ControlNet {
        dim: 0,
        ..n.clone()
    };
    assert!(bad.check().is_err());
    assert_eq!(bad.reversed(), bad);
    assert!(bad.decompose().is_empty());
    assert_eq!(n.point(99), &[] as &[f64]);
}

/// Random nets of degree 1 to 4: unclamped or partly clamped knot vectors off [0, 1],
/// interior knots of multiplicity ≤ p (so the curve is continuous), 1 to 3 coordinates per
/// point. (Degree 0 is discontinuous at every knot; it is covered by the hand tests.)
fn random_net() -> impl Strategy<Value = ControlNet<f64>> {
    (1usize..=4, 1usize..=3, 0usize..=6, -2.0f64..2.0).prop_flat_map(|(p, dim, extra, start)| {
        let count = p + 1 + extra;
        let knots = count + p + 1;
        (
            prop::collection::vec(prop_oneof![3 => 0.1f64..1.0, 1 => Just(0.0)], knots - 1),
            prop::collection::vec(-5.0f64..5.0, count * dim),
        )
            .prop_filter_map("degenerate knots", move |(gaps, coords)| {
                let mut knots = vec![start];
                for g in gaps {
                    knots.push(knots[knots.len() - 1] + g);
                }
                let kv = KnotVector::try_new(knots).ok()?;
                let (a, b) = kv.domain(p);
                let interior_ok = kv
                    .as_slice()
                    .iter()
                    .all(|&k| k <= a || k >= b || kv.multiplicity(k) <= p);
                interior_ok.then_some(())?;
                ControlNet::try_new(p, kv, dim, coords).ok()
            })
    })
}

fn at(n: &ControlNet<f64>, s: f64) -> f64 {
    let (a, b) = n.domain();
    (a + (b - a) * s).min(b)
}

proptest! {
    #[test]
    fn clamping_and_insertion_keep_the_curve(n in random_net(), s in 0.0f64..=1.0, times in 1usize..=4) {
        let c = n.clamped();
        let p = n.degree;
        prop_assert!(c.knots.as_slice()[..=p].iter().all(|&k| (k - c.domain().0).abs() < 1e-300));
        same_curve(&n, &c);
        let u = at(&n, s);
        let room = p.saturating_sub(n.knots.multiplicity(u));
        prop_assume!(room > 0);
        let q = n.insert_knot(u, times.min(room)).unwrap();
        prop_assert_eq!(q.point_count(), n.point_count() + times.min(room));
        same_curve(&n, &q);
    }

    #[test]
    fn refinement_equals_repeated_insertion(n in random_net(), mut xs in prop::collection::vec(0.0f64..=1.0, 1..6)) {
        prop_assume!(n.degree > 0);
        xs.sort_by(f64::total_cmp);
        let mut x: Vec<f64> = xs.iter().map(|&s| at(&n, s)).collect();
        // Keep multiplicities legal: drop values that would exceed the degree.
        let mut one_by_one = n.clone();
        x.retain(|&u| match one_by_one.insert_knot(u, 1) {
            Ok(next) => { one_by_one = next; true }
            Err(_) => false,
        });
        let r = n.refine(&x).unwrap();
        same_curve(&n, &r);
        assert_close(r.knots.as_slice(), one_by_one.knots.as_slice(), 1e-15);
        assert_close(&r.coords, &one_by_one.coords, 1e-12);
    }

    #[test]
    fn split_decompose_and_elevate_keep_the_curve(n in random_net(), s in 0.01f64..0.99, t in 1usize..=3) {
        let u = at(&n, s);
        let (l, r) = n.split(u).unwrap();
        prop_assert!((l.domain().1 - u).abs() < 1e-300 && (r.domain().0 - u).abs() < 1e-300);
        for i in 0..=20 {
            let f = f64::from(i) / 20.0;
            assert_close(&eval(&l, at(&l, f)), &eval(&n, at(&l, f)), 1e-12);
            assert_close(&eval(&r, at(&r, f)), &eval(&n, at(&r, f)), 1e-12);
        }
        let pieces = n.decompose();
        let spans = n.knots.breakpoints(n.degree).len() - 1;
        prop_assert_eq!(pieces.len(), spans);
        for piece in &pieces {
            prop_assert_eq!(piece.coords.len(), (n.degree + 1) * n.dim);
            for i in 0..=10 {
                let f = f64::from(i) / 10.0;
                let u = piece.start + (piece.end - piece.start) * f;
                assert_close(&de_casteljau(&piece.coords, n.dim, f), &eval(&n, u), 1e-12);
            }
        }
        let e = n.elevate_degree(t).unwrap();
        prop_assert_eq!(e.degree, n.degree + t);
        e.check().unwrap();
        same_curve(&n, &e);
        let c = n.clamped();
        for v in c.knots.breakpoints(c.degree) {
            prop_assert_eq!(e.knots.multiplicity(v), c.knots.multiplicity(v) + t);
        }
    }

    #[test]
    fn reversal_and_reparameterization(n in random_net(), a in -3.0f64..3.0, len in 0.1f64..4.0) {
        let (u0, u1) = n.domain();
        let r = n.reversed();
        r.check().unwrap();
        for i in 0..=20 {
            let u = at(&n, f64::from(i) / 20.0);
            assert_close(&eval(&r, (u0 + u1 - u).clamp(u0, u1)), &eval(&n, u), 1e-12);
        }
        let rr = r.reversed();
        assert_close(&rr.coords, &n.coords, 1e-300);
        assert_close(rr.knots.as_slice(), n.knots.as_slice(), 1e-12);
        let m = n.reparameterized(a, a + len).unwrap();
        m.check().unwrap();
        prop_assert!((m.domain().0 - a).abs() < 1e-300 && (m.domain().1 - (a + len)).abs() < 1e-300);
        for i in 0..=20 {
            let f = f64::from(i) / 20.0;
            assert_close(&eval(&m, at(&m, f)), &eval(&n, at(&n, f)), 1e-12);
        }
    }
}
