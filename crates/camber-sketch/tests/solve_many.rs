//! `solve_many`: many sketches solved by one call, kept problems reused between sketches of
//! one structure. Every result is checked against `solve_all` on a copy of the same sketch: the
//! same solved geometry (to 1e-9), the same status, the same error for a failing sketch, and a
//! failing sketch left exactly as it was.

#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

use camber_sketch::constraints::{ArcLength, Distance, Fixed};
use camber_sketch::file::to_json;
use camber_sketch::{solve_many, EntityId, PointRef, Sketch};
use nalgebra::Point2;

/// The largest difference between the points and scalars of two sketches' entities.
fn largest_gap(a: &Sketch, b: &Sketch) -> f64 {
    let mut gap = 0.0_f64;
    for ((ia, ea), (ib, eb)) in a.entities().zip(b.entities()) {
        assert_eq!(ia, ib);
        for (p, q) in ea.points().iter().zip(eb.points()) {
            gap = gap.max((p - q).norm());
        }
        for (s, t) in ea.scalars().iter().zip(eb.scalars().iter()) {
            gap = gap.max((s - t).abs());
        }
    }
    gap
}

/// Solves `variants` by `solve_many` in a pool of `threads` and each copy by `solve_all`, and
/// checks that they agree (see the module documentation); returns how many failed.
fn agree_with_solve_all(variants: &[Sketch], threads: usize) -> usize {
    let mut batch = variants.to_vec();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    let results = pool.install(|| solve_many(&mut batch));
    assert_eq!(results.len(), variants.len());
    let mut failed = 0;
    for ((alone, solved), result) in variants.iter().zip(&batch).zip(&results) {
        let mut alone_solved = alone.clone();
        match (alone_solved.solve_all(), result) {
            (Ok(a), Ok(b)) => {
                assert_eq!(a.components.len(), b.components.len());
                for (ca, cb) in a.components.iter().zip(&b.components) {
                    assert_eq!(ca.component, cb.component);
                    assert_eq!(ca.report.status, cb.report.status);
                    assert_eq!(ca.report.dof, cb.report.dof);
                }
                let gap = largest_gap(&alone_solved, solved);
                assert!(gap <= 1e-9, "solved geometry differs by {gap:e}");
            }
            (Err(a), Err(b)) => {
                assert_eq!(&a, b);
                // Left exactly as it was.
                assert_eq!(to_json(solved).unwrap(), to_json(alone).unwrap());
                failed += 1;
            }
            (a, b) => panic!("alone: {a:?}\nin the batch: {b:?}"),
        }
    }
    failed
}

#[test]
fn diffuser_variants_solve_as_each_alone_on_one_and_two_threads() {
    let (variants, w) = camber_workloads::w8_variants(12).unwrap();
    let sketches: Vec<Sketch> = variants.iter().map(|(s, _)| s.clone()).collect();
    for threads in [1, 2] {
        assert_eq!(agree_with_solve_all(&sketches, threads), 0);
    }
    let mut batch = sketches.clone();
    assert!(solve_many(&mut batch).iter().all(Result::is_ok));
    for (s, (_, circles)) in batch.iter().zip(&variants) {
        assert!(camber_workloads::w2_valid_with(s, &w, circles));
    }
}

/// A point P at distance 1 from a fixed A = (0, 0) and at distance 1 from a fixed B = (d, 0):
/// solvable for d < 2, conflicting beyond.
fn two_circles(d: f64) -> Sketch {
    let mut s = Sketch::new();
    let a = s.add_point(Point2::new(0.0, 0.0)).unwrap();
    let b = s.add_point(Point2::new(d, 0.0)).unwrap();
    let p = s.add_point(Point2::new(0.5 * d, 0.3)).unwrap();
    for fixed in [a, b] {
        s.add_constraint(Fixed::point(PointRef::Point(fixed)))
            .unwrap();
        s.add_constraint(Distance {
            a: PointRef::Point(fixed),
            b: PointRef::Point(p),
            distance: 1.0,
        })
        .unwrap();
    }
    s
}

#[test]
fn failing_variants_get_their_own_error_and_stay_as_they_were() {
    let ds = [1.0, 1.5, 3.0, 1.2, 2.5, 0.5, 1.9, 4.0, 1.1];
    let variants: Vec<Sketch> = ds.iter().map(|d| two_circles(*d)).collect();
    for threads in [1, 2] {
        assert_eq!(agree_with_solve_all(&variants, threads), 3);
    }
}

#[test]
fn variants_of_other_structures_are_built_again() {
    // Other constraint data (a distance of 0.8), an extra entity, another component count:
    // each differs in structure from the sketch before it.
    let mut variants = vec![two_circles(1.0), two_circles(1.5)];
    let mut other = two_circles(1.5);
    let id = EntityId(2);
    let c = other
        .constraints()
        .find(|(_, c)| matches!(c, camber_sketch::Constraint::Distance(_)))
        .map(|(id, _)| id)
        .unwrap();
    other.set_value(c, 0.8).unwrap();
    variants.push(other);
    let mut extra = two_circles(1.2);
    let q = extra.add_point(Point2::new(3.0, 3.0)).unwrap();
    extra
        .add_constraint(Distance {
            a: PointRef::Point(id),
            b: PointRef::Point(q),
            distance: 2.0,
        })
        .unwrap();
    variants.push(extra);
    variants.push(two_circles(1.4));
    let mut far = two_circles(1.4);
    far.add_point(Point2::new(9.0, 9.0)).unwrap();
    variants.push(far);
    variants.push(two_circles(1.3));
    assert_eq!(agree_with_solve_all(&variants, 1), 0);
}

#[test]
fn a_component_whose_pieces_read_the_points_is_never_refreshed() {
    // The arc-length rule keeps reference points from the curve it was compiled on, and a
    // fixed curve point off the control points is held at its current place: the variants
    // move the curve, so each must be compiled again and solve as it does alone.
    let variants: Vec<Sketch> = (0..6)
        .map(|k| {
            let lift = 0.1 * f64::from(k);
            let mut s = Sketch::new();
            let c = s
                .add_bezier(
                    camber_geom::BezierCurve2::try_new(vec![
                        Point2::new(0.0, 0.0),
                        Point2::new(1.0, 1.0 + lift),
                        Point2::new(2.0, -lift),
                        Point2::new(3.0, 0.0),
                    ])
                    .unwrap(),
                )
                .unwrap();
            s.add_constraint(Fixed::point(PointRef::Start(c))).unwrap();
            s.add_constraint(ArcLength {
                curve: c,
                length: 4.0,
            })
            .unwrap();
            s
        })
        .collect();
    assert_eq!(agree_with_solve_all(&variants, 1), 0);
}
