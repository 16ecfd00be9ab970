//! Issue 17: sketches at any scale and any size — here the warnings for near-degenerate
//! input, which reports carry and `camber check` prints.

#![allow(clippy::unwrap_used)] // fixture helpers unwrap like the tests do

use camber_geom::BezierCurve2;
use camber_sketch::constraints::{Angle, Fixed};
use camber_sketch::{PointRef, Sketch, Warning};
use nalgebra::Point2;

#[test]
fn issue_17_near_degenerate_input_is_named() {
    let mut s = Sketch::new();
    // A curve 10 long whose first two control points almost coincide.
    let c = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 0.0),
                Point2::new(1e-8, 0.0),
                Point2::new(5.0, 3.0),
                Point2::new(10.0, 0.0),
            ])
            .unwrap(),
        )
        .unwrap();
    let short = s
        .add_line(Point2::new(2.0, 2.0), Point2::new(2.0, 2.0 + 3e-6))
        .unwrap();
    let long = s
        .add_line(Point2::new(0.0, 5.0), Point2::new(4.0, 5.0))
        .unwrap();
    let other = s
        .add_line(Point2::new(0.0, 6.0), Point2::new(4.0, 6.1))
        .unwrap();
    let angle = s
        .add_constraint(Angle {
            first: long,
            second: other,
            angle: 1e-9,
        })
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(c))).unwrap();
    let w = s.warnings();
    assert!(w.contains(&Warning::CoincidentControlPoints {
        entity: c,
        index: 0,
        distance: 1e-8
    }));
    assert!(w
        .iter()
        .any(|x| matches!(x, Warning::ShortLine { entity, .. } if *entity == short)));
    assert!(w
        .iter()
        .any(|x| matches!(x, Warning::ParallelAngle { constraint, .. } if *constraint == angle)));
    assert_eq!(w.len(), 3, "{w:?}");
    // Messages name the entity or constraint in words.
    assert!(w.iter().all(|x| {
        let t = x.to_string();
        t.contains("entity") || t.contains("constraint")
    }));
    // A solve's report carries them.
    let report = s.solve().unwrap();
    assert_eq!(report.warnings, w);
}

#[test]
fn a_clean_sketch_has_no_warnings() {
    let (s, _) = camber_workloads::blade().unwrap();
    assert_eq!(s.warnings(), vec![]);
    let (s, _) = camber_workloads::w2_bspline7().unwrap();
    assert_eq!(s.warnings(), vec![]);
}
