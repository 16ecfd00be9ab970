//! Dimension edits: `Sketch::set_value` changes a constraint's value, and the next solve
//! re-solves only that constraint's component, on the problem an earlier solve prepared. Every
//! result is checked against a sketch built afresh with the new value and solved from the same
//! state (an independent path: compiled again, nothing kept).

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber_sketch::constraints::{Coincident, Distance, Fixed, Radius};
use camber_sketch::{ConstraintId, Error, PointRef, Sketch};
use camber_workloads::w5;
use nalgebra::Point2;

/// The distance constraint that sets the length of `line` (W5's widths and heights).
fn length_of(s: &Sketch, line: camber_sketch::EntityId) -> ConstraintId {
    s.constraints()
        .find_map(|(id, c)| match c {
            camber_sketch::Constraint::Distance(d) if d.a == PointRef::Start(line) => Some(id),
            _ => None,
        })
        .unwrap()
}

/// The same sketch built afresh (through its file) with `id`'s value set to `value`.
fn afresh(s: &Sketch, id: ConstraintId, value: f64) -> Sketch {
    let mut copy =
        camber_sketch::file::from_json(&camber_sketch::file::to_json(s).unwrap()).unwrap();
    let mut c = copy.remove_constraint(id).unwrap();
    if let camber_sketch::Constraint::Distance(d) = &mut c {
        d.distance = value;
    }
    copy.add_constraint_with_id(id, c).unwrap();
    copy
}

#[test]
fn a_width_edit_resolves_its_rectangle_alone_as_a_fresh_build_would() {
    let (mut s, rects) = w5(20).unwrap();
    s.solve().unwrap();
    for k in [0_usize, 7, 7, 19, 3] {
        let bottom = rects.lines[4 * k];
        let id = length_of(&s, bottom);
        let value = s.constraint(id).unwrap().value().unwrap() + 0.05;
        let mut reference = afresh(&s, id, value);
        let before = camber_sketch::file::to_json(&s).unwrap();
        s.set_value(id, value).unwrap();
        let report = s.solve().unwrap();
        // Only the edited rectangle was solved.
        assert_eq!(report.components.len(), 1, "edit of rectangle {k}");
        assert!(report.components[0].component.constraints.contains(&id));
        reference.solve().unwrap();
        // The same geometry as the fresh build, to rounding, and every residual met.
        for (e, a) in s.entities() {
            let b = reference.entity(e).unwrap();
            for (p, q) in a.points().iter().zip(b.points()) {
                assert!((p - q).norm() < 1e-12, "rectangle {k}, {e}: {p} {q}");
            }
        }
        let start = s.point(PointRef::Start(bottom)).unwrap();
        let end = s.point(PointRef::End(bottom)).unwrap();
        assert!(((end - start).norm() - value).abs() < 1e-9);
        // The other rectangles are bit for bit where they were.
        let after = camber_sketch::file::to_json(&s).unwrap();
        let untouched = |text: &str| -> Vec<String> {
            let v: serde_json::Value = serde_json::from_str(text).unwrap();
            v["entities"]
                .as_array()
                .unwrap()
                .iter()
                .filter(|e| {
                    let id = e["id"].as_u64().unwrap();
                    !rects.lines[4 * k..4 * k + 4].iter().any(|l| l.0 == id)
                })
                .map(|e| e.to_string())
                .collect()
        };
        assert_eq!(untouched(&before), untouched(&after), "rectangle {k}");
    }
}

#[test]
fn an_edit_after_other_changes_still_solves_as_a_fresh_build() {
    // A point pinned at a distance from a fixed one, on a circle of its own: value edits,
    // then a moved point (the prepared component is dropped), then a value edit again.
    let mut s = Sketch::new();
    let a = s.add_point(Point2::new(0.0, 0.0)).unwrap();
    let b = s.add_point(Point2::new(1.0, 0.2)).unwrap();
    let c = s.add_circle(Point2::new(3.0, 0.0), 0.5).unwrap();
    s.add_constraint(Fixed::point(PointRef::Point(a))).unwrap();
    let d = s
        .add_constraint(Distance {
            a: PointRef::Point(a),
            b: PointRef::Point(b),
            distance: 1.0,
        })
        .unwrap();
    s.add_constraint(Coincident {
        a: PointRef::Point(b),
        b: PointRef::Control(c, 0),
    })
    .unwrap();
    let r = s
        .add_constraint(Radius {
            circle: c,
            radius: 0.5,
        })
        .unwrap();
    s.solve().unwrap();
    let check = |s: &Sketch, reference: &mut Sketch| {
        reference.solve().unwrap();
        let (p, q) = (
            s.point(PointRef::Point(b)).unwrap(),
            reference.point(PointRef::Point(b)).unwrap(),
        );
        assert!((p - q).norm() < 1e-12, "{p} {q}");
    };
    for value in [1.5, 0.75, 2.0] {
        let mut reference = afresh(&s, d, value);
        s.set_value(d, value).unwrap();
        s.solve().unwrap();
        check(&s, &mut reference);
        assert!((s.point(PointRef::Point(b)).unwrap().coords.norm() - value).abs() < 1e-9);
    }
    s.set_point(PointRef::Point(b), Point2::new(0.0, 3.0))
        .unwrap();
    let mut reference = afresh(&s, d, 2.0);
    s.solve().unwrap();
    check(&s, &mut reference);
    let mut reference = afresh(&s, d, 1.25);
    s.set_value(d, 1.25).unwrap();
    s.solve().unwrap();
    check(&s, &mut reference);
    s.set_value(r, 0.8).unwrap();
    s.solve().unwrap();
    match s.entity(c).unwrap() {
        camber_sketch::Entity::Circle { radius, .. } => assert!((radius - 0.8).abs() < 1e-12),
        other => panic!("{other:?}"),
    }
}

#[test]
fn values_are_refused_for_kinds_without_one_and_when_invalid_leaving_the_sketch_as_it_was() {
    let mut s = Sketch::new();
    let a = s.add_point(Point2::new(0.0, 0.0)).unwrap();
    let b = s.add_point(Point2::new(1.0, 0.0)).unwrap();
    let fixed = s.add_constraint(Fixed::point(PointRef::Point(a))).unwrap();
    let d = s
        .add_constraint(Distance {
            a: PointRef::Point(a),
            b: PointRef::Point(b),
            distance: 1.0,
        })
        .unwrap();
    s.solve().unwrap();
    let before = camber_sketch::file::to_json(&s).unwrap();
    assert!(matches!(
        s.set_value(fixed, 2.0),
        Err(Error::NoValue { constraint, .. }) if constraint == fixed
    ));
    for bad in [f64::NAN, f64::INFINITY, -1.0] {
        assert!(s.set_value(d, bad).is_err(), "{bad}");
    }
    assert!(matches!(
        s.set_value(ConstraintId(999), 1.0),
        Err(Error::UnknownConstraint { .. })
    ));
    assert_eq!(camber_sketch::file::to_json(&s).unwrap(), before);
    assert_eq!(s.constraint(d).unwrap().value(), Some(1.0));
    // Nothing is dirty: the next solve has nothing to do.
    assert!(s.solve().unwrap().components.is_empty());
}

#[test]
fn a_dimension_bound_to_a_parameter_refuses_set_value_and_follows_its_parameter_still() {
    // b at `chord / 2` from a fixed a; a second distance, a to c, unbound.
    let mut s = Sketch::new();
    let a = s.add_point(Point2::new(0.0, 0.0)).unwrap();
    let b = s.add_point(Point2::new(1.0, 0.0)).unwrap();
    let c = s.add_point(Point2::new(0.0, 1.0)).unwrap();
    s.add_constraint(Fixed::point(PointRef::Point(a))).unwrap();
    s.define_parameter("chord", 3.0).unwrap();
    let bound = s
        .add_constraint(Distance {
            a: PointRef::Point(a),
            b: PointRef::Point(b),
            distance: 1.0,
        })
        .unwrap();
    let free = s
        .add_constraint(Distance {
            a: PointRef::Point(a),
            b: PointRef::Point(c),
            distance: 1.0,
        })
        .unwrap();
    s.bind_dimension(bound, "distance", "chord / 2").unwrap();
    s.solve().unwrap();
    let gap = |s: &Sketch, p| s.point(PointRef::Point(p)).unwrap().coords.norm();
    assert!((gap(&s, b) - 1.5).abs() < 1e-10);

    // The bound value is refused, naming the expression; nothing changes.
    let before = camber_sketch::file::to_json(&s).unwrap();
    match s.set_value(bound, 2.0) {
        Err(Error::ValueBound {
            constraint,
            path,
            expression,
        }) => {
            assert_eq!(constraint, bound);
            assert_eq!(path, "distance");
            assert_eq!(expression, "chord / 2");
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(camber_sketch::file::to_json(&s).unwrap(), before);
    // The value the expression gives is no change and is accepted.
    s.set_value(bound, 1.5).unwrap();
    s.solve().unwrap();
    assert!((gap(&s, b) - 1.5).abs() < 1e-10);

    // An unbound dimension of the same component takes set_value (on the kept problem),
    // and a parameter change afterwards still re-solves the bound one (its component's kept
    // problem is dropped and built again with the new value).
    s.set_value(free, 0.5).unwrap();
    s.solve().unwrap();
    assert!((gap(&s, c) - 0.5).abs() < 1e-10);
    s.set_parameter("chord", 5.0).unwrap();
    assert!((gap(&s, b) - 2.5).abs() < 1e-10);
    assert!((gap(&s, c) - 0.5).abs() < 1e-10);
    s.set_value(free, 0.75).unwrap();
    s.solve().unwrap();
    assert!((gap(&s, b) - 2.5).abs() < 1e-10);
    assert!((gap(&s, c) - 0.75).abs() < 1e-10);

    // Bound again to a constant expression, it still refuses other values; the saved file
    // keeps the binding's text.
    s.bind_dimension(bound, "distance", "2").unwrap();
    assert!(matches!(
        s.set_value(bound, 3.0),
        Err(Error::ValueBound { .. })
    ));
    assert!(camber_sketch::file::to_json(&s).unwrap().contains("\"2\""));
}
