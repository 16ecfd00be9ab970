//! The `blade_arcs` example, run in-process (its code is compiled into this test with
//! `#[path]`), and 200 random drags of the section's points: after each drag (whose refused
//! steps keep the last good state) every arc–side joint is closed and tangent with the sense
//! it was given — no flip — checked by the example's independent evaluation of the ends.

#![allow(clippy::unwrap_used)]

#[allow(dead_code)] // its `main` is not called here
#[path = "../examples/blade_arcs.rs"]
mod blade_arcs;

use blade_arcs::{check_joints, run, BLADE, LEADING_EDGE, TRAILING_EDGE};
use camber::sketch::{file, EntityId, PointRef};
use nalgebra::Vector2;
use proptest::prelude::*;

#[test]
fn the_example_drags_its_leading_edge_with_every_joint_held() {
    run().unwrap();
}

/// The points a designer grabs: the leading edge's centre, vertex and ends, the trailing
/// edge's ends, and the middle control points of both sides.
fn grabbed(which: usize) -> PointRef {
    let (pressure, suction) = (EntityId(0), EntityId(2));
    [
        PointRef::Control(LEADING_EDGE, 0),
        PointRef::Control(LEADING_EDGE, 1),
        PointRef::Start(LEADING_EDGE),
        PointRef::End(LEADING_EDGE),
        PointRef::Start(TRAILING_EDGE),
        PointRef::End(TRAILING_EDGE),
        PointRef::Control(pressure, 2),
        PointRef::Control(pressure, 4),
        PointRef::Control(suction, 1),
        PointRef::Control(suction, 3),
    ][which]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn random_drags_keep_every_arc_joint_closed_tangent_and_unflipped(
        which in 0..10usize, dx in -0.02..0.02f64, dy in -0.02..0.02f64,
    ) {
        let mut s = file::from_json(BLADE).unwrap();
        let point = grabbed(which);
        let start = s.point(point).unwrap();
        let mut drag = s.drag(point).unwrap();
        let mut refused = 0;
        // Two steps per drag: a move of up to 0.02 (the leading edge is 0.07 thick) in halves.
        for k in 1..=2 {
            let to = start + Vector2::new(dx, dy) * (f64::from(k) / 2.0);
            if drag.update(to).is_err() {
                refused += 1;
            }
        }
        drag.finish(&mut s).unwrap();
        let (gap, sin, joints) = check_joints(&s).unwrap();
        prop_assert_eq!(joints, 4);
        prop_assert!(gap < 1e-9 && sin < 1e-9, "{point}: gap {gap:e}, sin {sin:e}, {refused} refused");
    }
}
