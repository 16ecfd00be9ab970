//! The diffuser airfoil through the facade: W2 `bspline7` (a clamped cubic B-spline with 7
//! control points tangent to the leading-edge circle at its start, the trailing-edge circle at
//! its end and the thickness circle at a free interior contact) built from the public API,
//! solved from the rough start, then from seeded perturbations of the solution. Every result
//! is checked by the workload's validity test, written here from its definition.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber::geom::queries::closest_point;
use camber::geom::{BSplineCurve2, KnotVector, ParametricCurve};
use camber::sketch::constraints::{Fixed, TangentToCircle};
use camber::sketch::{CircleSide, Contact, Entity, EntityId, PointRef, Rotation, Sketch};
use nalgebra::Point2;

const CIRCLES: [([f64; 2], f64); 3] = [
    ([0.03, 0.0], 0.03),
    ([0.38, 0.04], 0.07),
    ([0.985, 0.01], 0.015),
];

fn on(k: usize, degrees: f64) -> Point2<f64> {
    let ((c, r), a) = (CIRCLES[k], degrees.to_radians());
    Point2::new(c[0] + r * a.cos(), c[1] + r * a.sin())
}

/// The rough start and its constraints; the TH contact starts at u = 0.45.
fn sketch() -> (Sketch, EntityId) {
    let pts = vec![
        on(0, 110.0),
        Point2::new(0.07, 0.06),
        Point2::new(0.18, 0.115),
        Point2::new(0.38, 0.125),
        Point2::new(0.62, 0.10),
        Point2::new(0.86, 0.045),
        on(2, 70.0),
    ];
    let knots = KnotVector::try_new(vec![
        0.0, 0.0, 0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0, 1.0, 1.0,
    ])
    .unwrap();
    let mut s = Sketch::new();
    let curve = s
        .add_bspline(BSplineCurve2::try_new(3, knots, pts).unwrap())
        .unwrap();
    for (k, u) in [Contact::At(0.0), Contact::Free(0.45), Contact::At(1.0)]
        .into_iter()
        .enumerate()
    {
        let (c, r) = CIRCLES[k];
        let circle = s.add_circle(Point2::new(c[0], c[1]), r).unwrap();
        s.add_constraint(Fixed::entity(circle)).unwrap();
        s.add_constraint(TangentToCircle {
            curve,
            circle,
            u,
            side: CircleSide::Outside,
            rotation: Rotation::Clockwise,
        })
        .unwrap();
    }
    (s, curve)
}

/// W2's validity check at tolerance 1e-6.
fn valid(s: &Sketch, curve: EntityId) -> bool {
    let Entity::BSpline(c) = s.entity(curve).unwrap() else {
        return false;
    };
    let tol = 1e-6;
    let ends_ok = [(0, 0.0), (2, 1.0)].iter().all(|&(k, u)| {
        let (centre, r) = CIRCLES[k];
        let (p, t) = c.point_and_derivative(u).unwrap();
        let v = p - Point2::new(centre[0], centre[1]);
        (v.norm() - r).abs() <= tol && (v.dot(&t) / (v.norm() * t.norm())).abs() <= tol
    });
    let distances_ok = CIRCLES.iter().enumerate().all(|(k, (centre, r))| {
        let cp = closest_point(c, &Point2::new(centre[0], centre[1])).unwrap();
        if k == 1 {
            (cp.distance - r).abs() <= tol && cp.point.y >= centre[1]
        } else {
            cp.distance - r >= -tol
        }
    });
    ends_ok && distances_ok
}

#[test]
fn the_diffuser_airfoil_solves_and_stays_valid_under_perturbations() {
    let (mut s, curve) = sketch();
    let report = s.solve().unwrap();
    assert!(report.components[0].report.reason.contains("Newton"));
    assert!(valid(&s, curve));

    // Seeded perturbations (a linear congruential generator), 30 per size here; the crate's
    // own test runs 100 per size.
    let mut state = 12345_u64;
    let mut noise = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    for (delta, need) in [(0.01, 30), (0.05, 28)] {
        let mut ok = 0;
        for _ in 0..30 {
            let mut t = s.clone();
            for j in 0..7 {
                let p = t.point(PointRef::Control(curve, j)).unwrap();
                let q = Point2::new(p.x + delta * noise(), p.y + delta * noise());
                t.set_point(PointRef::Control(curve, j), q).unwrap();
            }
            let before = t.entity(curve).unwrap().clone();
            match t.solve() {
                Ok(_) => ok += usize::from(valid(&t, curve)),
                // A refused solve writes nothing.
                Err(_) => assert_eq!(t.entity(curve).unwrap(), &before),
            }
        }
        assert!(ok >= need, "δ = {delta}: {ok} of 30 valid");
    }
}
