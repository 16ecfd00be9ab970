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

/// Item 2: the tolerance is relative to the sketch's coordinates. The same perturbed rectangle
/// at offsets 10⁻⁶ … 10⁷ solves on the same path in as many Newton iterations (one fewer far
/// out, where the looser tolerance is met one quadratic step earlier; before, it took 100
/// Newton iterations and SLSQP at 10⁶ and was "conflicting" at 10⁷), and the report says which
/// tolerance it used.
#[test]
fn issue_17_rectangles_far_from_the_origin_solve_alike() {
    let mut paths = Vec::new();
    for offset in [0.0, 1e-6, 1e-3, 1.0, 1e3, 1e5, 1e6, 1e7] {
        let (mut s, r) =
            camber_workloads::w5_at(1, nalgebra::Vector2::new(offset, offset)).unwrap();
        let report = s.solve().unwrap_or_else(|e| panic!("offset {offset}: {e}"));
        assert!(
            camber_workloads::w5_valid(&s, &r, 1e-6),
            "offset {offset}: not valid"
        );
        let c = &report.components[0].report;
        paths.push((offset, c.solver, c.iterations));
        let floor = 256.0 * f64::EPSILON * (offset + 2.0);
        assert!(report.tolerance >= s.options().tolerance);
        assert!(
            report.tolerance <= s.options().tolerance.max(floor),
            "offset {offset}"
        );
    }
    let (_, solver, iterations) = paths[0];
    for (offset, s, i) in &paths {
        assert_eq!(*s, solver, "offset {offset}: {paths:?}");
        assert!(
            *i == iterations || *i + 1 == iterations,
            "offset {offset}: {paths:?}"
        );
    }
}
