//! Sketches at any scale and any size: the warnings for near-degenerate
//! input, which reports carry and `camber check` prints.

#![allow(clippy::unwrap_used)] // fixture helpers unwrap like the tests do

use camber_geom::BezierCurve2;
use camber_sketch::constraints::{Angle, Fixed};
use camber_sketch::{PointRef, Sketch, Warning};
use nalgebra::Point2;

#[test]
fn near_degenerate_input_is_named() {
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
fn rectangles_far_from_the_origin_solve_alike() {
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

/// Item 3: the analysis names what is still free, per entity. A line whose start is fixed and
/// which is horizontal: its start is determined, its end can slide. A circle with a fixed
/// centre and a free radius: only the radius. A point fixed outright: nothing (not listed).
#[test]
fn free_unknowns_are_named_per_entity() {
    use camber_sketch::constraints::Horizontal;
    let mut s = Sketch::new();
    let line = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(2.0, 0.3))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(line)))
        .unwrap();
    s.add_constraint(Horizontal::line(line)).unwrap();
    let circle = s.add_circle(Point2::new(5.0, 5.0), 1.0).unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(circle, 0)))
        .unwrap();
    let point = s.add_point(Point2::new(-3.0, 1.0)).unwrap();
    s.add_constraint(Fixed::entity(point)).unwrap();
    let analyses = s.analyze().unwrap();
    let find = |e| {
        analyses
            .iter()
            .find(|a| a.component.entities.contains(&e))
            .unwrap()
    };
    let l = find(line);
    assert_eq!(l.analysis.dof, 1);
    assert_eq!(l.freedom.len(), 1);
    assert_eq!(
        (l.freedom[0].entity, l.freedom[0].points.clone()),
        (line, vec![1])
    );
    let c = find(circle);
    assert_eq!(c.freedom.len(), 1);
    assert!(c.freedom[0].points.is_empty() && c.freedom[0].scalars == vec![0]);
    let p = find(point);
    assert!(p.freedom.is_empty() && p.is_determined(point));
    assert!(!l.is_determined(line));
}

#[test]
fn contact_parameters_that_can_slide_are_named() {
    use camber_sketch::constraints::TangentToCircle;
    use camber_sketch::ParameterFreedom;
    use camber_sketch::{CircleSide, Contact, Rotation};
    // A cubic with fixed ends touching a fixed circle: the curve keeps interior freedom, so
    // the contact can slide along it (its parameter is free).
    let build = |fix_interior: bool| {
        let mut s = Sketch::new();
        let curve = s
            .add_bezier(
                BezierCurve2::try_new(vec![
                    Point2::new(-3.0, 0.0),
                    Point2::new(-1.0, 2.0),
                    Point2::new(1.0, 2.0),
                    Point2::new(3.0, 0.0),
                ])
                .unwrap(),
            )
            .unwrap();
        let circle = s.add_circle(Point2::new(0.0, 3.0), 1.5).unwrap();
        s.add_constraint(Fixed::entity(circle)).unwrap();
        s.add_constraint(Fixed::point(PointRef::Start(curve)))
            .unwrap();
        s.add_constraint(Fixed::point(PointRef::End(curve)))
            .unwrap();
        if fix_interior {
            s.add_constraint(Fixed::point(PointRef::Control(curve, 2)))
                .unwrap();
        }
        let touch = s
            .add_constraint(TangentToCircle {
                curve,
                circle,
                u: Contact::Free(0.5),
                side: CircleSide::Outside,
                rotation: Rotation::Clockwise,
            })
            .unwrap();
        (s, touch)
    };
    let (s, touch) = build(false);
    let a = &s.analyze().unwrap()[0];
    assert_eq!(a.analysis.dof, 3, "{:?}", a.analysis);
    assert_eq!(
        a.free_parameters,
        vec![ParameterFreedom {
            constraint: touch,
            parameter: 0
        }]
    );
    // With P₂ fixed too, P₁ (2 unknowns) and the parameter meet the 2 contact rows: 1 DOF
    // left, still able to slide (P₁ moves along with it).
    let (s, _) = build(true);
    let a = &s.analyze().unwrap()[0];
    assert_eq!(a.analysis.dof, 1, "{:?}", a.analysis);
    assert_eq!(a.free_parameters.len(), 1);
}
