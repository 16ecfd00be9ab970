//! Issue 11, finding 1: a cubic touching 7 or more fixed circles at free contact parameters
//! aborted the process (`double free or corruption`). The clearance rows made the equality rows
//! outnumber the unknowns, and NLopt 2.9's SLSQP writes past its workspace then. SLSQP now gets
//! an independent subset of rows or is not called; these sketches solve, on the usual path and
//! by iterative displacement, or fail plainly with the sketch unchanged.

#![allow(clippy::unwrap_used)]

use camber_geom::{BezierCurve2, ParametricCurve};
use camber_sketch::constraints::{Fixed, TangentToCircle};
use camber_sketch::displacement::DisplacementOptions;
use camber_sketch::file::to_json;
use camber_sketch::{CircleSide, Contact, Entity, EntityId, Rotation, Sketch};
use nalgebra::Point2;

/// A cubic under `k` fixed circles of radius 0.3 in a row at height 1.5, each touched from
/// outside, clockwise, at a free contact parameter.
fn under_circles(k: usize) -> (Sketch, EntityId, Vec<EntityId>) {
    let mut s = Sketch::new();
    let curve = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 0.0),
                Point2::new(1.0, 1.5),
                Point2::new(2.0, 1.5),
                Point2::new(3.0, 0.0),
            ])
            .unwrap(),
        )
        .unwrap();
    let mut circles = Vec::new();
    for i in 0..k {
        let x = 0.3 + 2.4 * i as f64 / (k - 1).max(1) as f64;
        let c = s.add_circle(Point2::new(x, 1.5), 0.3).unwrap();
        s.add_constraint(Fixed::entity(c)).unwrap();
        s.add_constraint(TangentToCircle {
            curve,
            circle: c,
            u: Contact::Free((i as f64 + 0.5) / k as f64),
            side: CircleSide::Outside,
            rotation: Rotation::Clockwise,
        })
        .unwrap();
        circles.push(c);
    }
    (s, curve, circles)
}

/// Every circle is touched: the curve's least distance to each centre is its radius (sampled
/// finely, then the curve never comes closer than the radius less a sampling allowance).
fn touches_every_circle(s: &Sketch, curve: EntityId, circles: &[EntityId]) -> bool {
    let Entity::Bezier(b) = s.entity(curve).unwrap() else {
        panic!("not a Bézier")
    };
    circles.iter().all(|&c| {
        let Entity::Circle { center, radius } = *s.entity(c).unwrap() else {
            panic!("not a circle")
        };
        let least = (0..=4000)
            .map(|i| {
                let p = b.point(i as f64 / 4000.0).unwrap();
                (p - center).norm()
            })
            .fold(f64::INFINITY, f64::min);
        (least - radius).abs() < 1e-5
    })
}

#[test]
fn seven_to_twenty_contacts_solve_without_abort() {
    for k in 2..=20 {
        let (mut s, curve, circles) = under_circles(k);
        let report = s.solve().unwrap_or_else(|e| panic!("{k} circles: {e}"));
        for c in &report.components {
            assert!(
                c.report.residuals.iter().all(|r| r.max_abs < 1e-9),
                "{k} circles: {c:?}"
            );
        }
        assert!(touches_every_circle(&s, curve, &circles), "{k} circles");
    }
}

#[test]
fn many_contacts_by_displacement_solve_or_fail_plainly() {
    for k in [7, 11, 20] {
        let (mut s, curve, circles) = under_circles(k);
        let before = to_json(&s).unwrap();
        match s.solve_by_displacement(&DisplacementOptions::default()) {
            Ok(_) => assert!(touches_every_circle(&s, curve, &circles), "{k} circles"),
            Err(_) => assert_eq!(to_json(&s).unwrap(), before, "{k} circles: sketch changed"),
        }
    }
}
