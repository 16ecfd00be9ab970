//! Dragging the joint of a free-direction G1 join further than a short end leg: the least move
//! would shorten that leg to nothing (a cusp, where the angle row reads as met but the join has
//! no tangent left); the speed floor keeps the leg at a quarter of its length and the drag
//! goes through with the tangents still parallel.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber_geom::{BSplineCurve2, KnotVector};
use camber_sketch::constraints::{Fixed, G1JoinFree};
use camber_sketch::{EntityId, PointRef, Sketch};
use nalgebra::{Point2, Vector2};

fn spline(knots: &[f64], points: &[(f64, f64)]) -> BSplineCurve2<f64> {
    let points = points.iter().map(|(x, y)| Point2::new(*x, *y)).collect();
    BSplineCurve2::try_new(3, KnotVector::try_new(knots.to_vec()).unwrap(), points).unwrap()
}

/// The two sides of a NACA 2412 nose as a fit within 1e-4 chord splits them (upper from the
/// trailing edge to the leading edge, lower back), their trailing-edge ends fixed, joined G1
/// with a free direction at the origin. The end legs are steep (slope −10), already parallel,
/// and short: 0.0083 above the joint, 0.0069 below it, with the first interior knot of the
/// lower side at 0.0387.
fn nose() -> (Sketch, EntityId, EntityId) {
    let mut s = Sketch::new();
    let upper = s
        .add_bspline(spline(
            &[
                0.0,
                0.0,
                0.0,
                0.0,
                0.20731919410995936,
                0.4383244396138514,
                0.6049319174020674,
                0.779672556430253,
                0.8877110240955564,
                0.9541449099738736,
                1.0,
                1.0,
                1.0,
                1.0,
            ],
            &[
                (1.00008381395326, 0.001257209298899305),
                (0.9726050343437634, 0.007116981896226138),
                (0.8323219783798225, 0.034858663737026604),
                (0.5941338126141852, 0.06669960126237638),
                (0.35644009530562243, 0.08300487905616058),
                (0.1806097719766605, 0.07483465066572846),
                (0.06637293589067841, 0.049822382875045625),
                (0.013070673722293294, 0.025857454006355255),
                (-0.0008239282475147024, 0.008239296637184139),
                (0.0, 0.0),
            ],
        ))
        .unwrap();
    let lower = s
        .add_bspline(spline(
            &[
                0.0,
                0.0,
                0.0,
                0.0,
                0.03874398917019534,
                0.09652497098674226,
                0.19609606882462893,
                0.32656362388572385,
                0.4551415984766347,
                0.5862926070501849,
                0.7696995504222851,
                1.0,
                1.0,
                1.0,
                1.0,
            ],
            &[
                (0.0, 0.0),
                (0.0006860009118249937, -0.00686002090953201),
                (0.013328551253502371, -0.0201336492944996),
                (0.06044756385327856, -0.03436559541080635),
                (0.15029002519024448, -0.043037862115227296),
                (0.28273210748577865, -0.04236748982538461),
                (0.4366222832536307, -0.037070493165200044),
                (0.6190653409544968, -0.026951917736483363),
                (0.8288023621402544, -0.0131903670422856),
                (0.9684988114312432, -0.0036295732036698606),
                (0.99991618604674, -0.001257209298899305),
            ],
        ))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(upper)))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::End(lower)))
        .unwrap();
    s.add_constraint(G1JoinFree {
        first: upper,
        second: lower,
    })
    .unwrap();
    (s, upper, lower)
}

fn leg(s: &Sketch, from: PointRef, to: PointRef) -> Vector2<f64> {
    s.point(to).unwrap() - s.point(from).unwrap()
}

#[test]
fn a_joint_dragged_past_a_short_end_leg_keeps_a_tangent_on_both_sides() {
    let (mut s, upper, lower) = nose();
    s.solve().unwrap();
    let start = s.point(PointRef::End(upper)).unwrap();
    let lower_leg = leg(&s, PointRef::Start(lower), PointRef::Control(lower, 1)).norm();
    let controls = |s: &Sketch| -> Vec<Point2<f64>> {
        [upper, lower]
            .iter()
            .flat_map(|e| s.entity(*e).unwrap().points().to_vec())
            .collect()
    };
    let before = controls(&s);
    let mut drag = s.drag(PointRef::End(upper)).unwrap();
    for k in 1..=20 {
        let target = Point2::new(start.x, start.y - 0.01 * f64::from(k) / 20.0);
        drag.update(target)
            .unwrap_or_else(|e| panic!("step {k}: {e}"));
    }
    drag.finish(&mut s).unwrap();
    // A droop of 0.01 moves no control point by more than a few times that (without the
    // floor the leg ran through the cusp and the upper side's last leg swung a chord away).
    for (p, q) in before.iter().zip(controls(&s)) {
        assert!((q - p).norm() < 0.03, "{p} -> {q}");
    }

    let joint = s.point(PointRef::End(upper)).unwrap();
    assert!(
        (joint - Point2::new(start.x, start.y - 0.01)).norm() < 1e-12,
        "{joint}"
    );
    assert_eq!(s.point(PointRef::Start(lower)).unwrap(), joint);
    let a = leg(&s, PointRef::Control(upper, 8), PointRef::End(upper));
    let b = leg(&s, PointRef::Start(lower), PointRef::Control(lower, 1));
    // Still parallel and the same way, and the lower leg no shorter than its floor.
    let sine = (a.x * b.y - a.y * b.x) / (a.norm() * b.norm());
    assert!(sine.abs() < 1e-9, "{a} {b} {sine}");
    assert!(a.dot(&b) > 0.0);
    assert!(
        b.norm() >= 0.25 * lower_leg * (1.0 - 1e-5),
        "{} of {lower_leg}",
        b.norm()
    );
}

#[test]
fn a_clamped_spline_end_is_its_end_control_point_exactly() {
    // The recurrence gives the lower side's first basis function at u = 0 as right·(1/right)
    // with right = 0.0387…, which rounds to 0.999…9: the end is resolved to the control point
    // itself instead.
    let (s, upper, lower) = nose();
    for (e, r, j) in [
        (upper, PointRef::Start(upper), 0),
        (upper, PointRef::End(upper), 9),
        (lower, PointRef::Start(lower), 0),
        (lower, PointRef::End(lower), 10),
    ] {
        let terms = s.entity(e).unwrap().resolve(r).unwrap();
        assert_eq!(terms.as_slice(), &[(j, 1.0)], "{r:?}");
    }
    // The joint is then one merged point: one free unknown pair fewer than two rows would give.
    let analysis = s.analyze().unwrap();
    assert_eq!(analysis[0].analysis.rank, 1, "{:?}", analysis[0].analysis);
}
