//! Dimensions by their value: every kind with a value names the field of its file form that
//! holds it, and binding that field to an expression of the parameters drives the value.

use camber_sketch::file::{add_from_values, constraint_to_value};
use camber_sketch::{ConstraintId, Error, Sketch};
use serde_json::json;

/// A sketch holding one constraint of each dimension kind (ids 100…), on a line, a circle, an
/// arc, an ellipse and a Bézier curve.
fn dimensions() -> Sketch {
    let mut s = Sketch::new();
    add_from_values(
        &mut s,
        vec![
            json!({"id": 0, "kind": "line", "from": [0, 0], "to": [2, 0.2]}),
            json!({"id": 1, "kind": "line", "from": [0, 1], "to": [1, 2]}),
            json!({"id": 2, "kind": "circle", "center": [4, 0], "radius": 1.5}),
            json!({"id": 3, "kind": "arc", "center": [0, 4], "radius": 1, "start_angle": 0, "end_angle": 2}),
            json!({"id": 4, "kind": "ellipse", "center": [8, 0], "semi_axis_a": 2, "semi_axis_b": 1, "rotation": 0}),
            json!({"id": 5, "kind": "bezier", "control_points": [[0, -3], [1, -2], [2, -3]]}),
            json!({"id": 6, "kind": "point", "at": [3, 3]}),
        ],
        vec![
            json!({"id": 100, "kind": "distance", "a": {"start": 0}, "b": {"end": 0}, "distance": 2.1}),
            json!({"id": 101, "kind": "horizontal_distance", "of": {"a": {"start": 1}, "b": {"end": 1}}, "distance": 1.1}),
            json!({"id": 102, "kind": "vertical_distance", "of": {"a": {"start": 1}, "b": {"end": 1}}, "distance": 0.9}),
            json!({"id": 103, "kind": "radius", "circle": 2, "radius": 1.4}),
            json!({"id": 104, "kind": "arc_angle", "arc": 3, "angle": 1.9}),
            json!({"id": 105, "kind": "semi_axis", "ellipse": 4, "axis": "b", "length": 1.2}),
            json!({"id": 106, "kind": "arc_length", "curve": 5, "length": 2.5}),
            json!({"id": 107, "kind": "curvature_at", "curve": 5, "u": 0.5, "curvature": -1.5}),
            json!({"id": 108, "kind": "point_line_distance", "point": {"point": 6}, "line": 1, "distance": 0.7, "side": "left"}),
            json!({"id": 109, "kind": "angle", "first": 0, "second": 1, "angle": 0.8}),
        ],
    )
    .expect("the sketch of every dimension kind loads");
    s
}

#[test]
fn every_value_sits_in_the_field_its_kind_names() {
    let s = dimensions();
    let mut seen = 0;
    for (id, c) in s.constraints() {
        let value = c.value().unwrap_or_else(|| panic!("{id} has a value"));
        let field = c
            .value_field()
            .unwrap_or_else(|| panic!("{id} names its field"));
        let form = constraint_to_value(c).unwrap();
        assert_eq!(
            form[field].as_f64(),
            Some(value),
            "{id} ({}): {form}",
            c.tag()
        );
        seen += 1;
    }
    assert_eq!(seen, 10);
}

#[test]
fn a_bound_value_follows_its_parameters_until_unbound() {
    let mut s = dimensions();
    s.define_parameter("t", 0.5).unwrap();
    for (i, id) in (100..110).map(ConstraintId).enumerate() {
        let text = format!("t * {}", 2 + i);
        s.bind_value(id, &text).unwrap();
        let want = 0.5 * (2 + i) as f64;
        assert_eq!(s.constraint(id).unwrap().value(), Some(want), "{id}");
        assert_eq!(s.parameters().bindings(id)[0].text, text);
    }
    s.define_parameter("t", 0.25).unwrap();
    assert_eq!(
        s.constraint(ConstraintId(103)).unwrap().value(),
        Some(0.25 * 5.0)
    );
    // A bound value refuses a number; unbound, it takes one and stops following `t`.
    let r = ConstraintId(103);
    assert!(matches!(s.set_value(r, 2.0), Err(Error::ValueBound { .. })));
    s.unbind_value(r).unwrap();
    assert!(s.parameters().bindings(r).is_empty());
    s.set_value(r, 2.0).unwrap();
    s.define_parameter("t", 0.3).unwrap();
    assert_eq!(s.constraint(r).unwrap().value(), Some(2.0));
}

#[test]
fn kinds_without_a_value_refuse_to_be_bound() {
    let mut s = dimensions();
    add_from_values(
        &mut s,
        vec![],
        vec![json!({"id": 200, "kind": "horizontal", "of": {"line": 0}})],
    )
    .unwrap();
    let h = ConstraintId(200);
    assert!(matches!(s.bind_value(h, "1"), Err(Error::NoValue { .. })));
    assert!(matches!(s.unbind_value(h), Err(Error::NoValue { .. })));
    assert!(matches!(
        s.bind_value(ConstraintId(999), "1"),
        Err(Error::UnknownConstraint { .. })
    ));
}

#[test]
fn a_refused_fragment_leaves_the_sketch_as_it_was() {
    let mut s = dimensions();
    let before = camber_sketch::file::to_json(&s).unwrap();
    // The second constraint reads an entity that does not exist: the new point, the new
    // line and the first constraint go again.
    let refused = add_from_values(
        &mut s,
        vec![
            json!({"id": 50, "kind": "point", "at": [9, 9]}),
            json!({"id": 51, "kind": "line", "from": [9, 9], "to": [10, 9]}),
        ],
        vec![
            json!({"id": 300, "kind": "coincident", "a": {"point": 50}, "b": {"start": 51}}),
            json!({"id": 301, "kind": "horizontal", "of": {"line": 77}}),
        ],
    );
    let e = refused.unwrap_err().to_string();
    assert!(e.starts_with("constraint 301 (horizontal)"), "{e}");
    assert_eq!(camber_sketch::file::to_json(&s).unwrap(), before);
    // A taken id and a malformed entity are refused the same way.
    for (entities, constraints) in [
        (
            vec![json!({"id": 0, "kind": "point", "at": [0, 0]})],
            vec![],
        ),
        (
            vec![json!({"id": 60, "kind": "line", "from": [0, 0]})],
            vec![],
        ),
        (
            vec![],
            vec![json!({"id": 100, "kind": "horizontal", "of": {"line": 0}})],
        ),
    ] {
        assert!(add_from_values(&mut s, entities, constraints).is_err());
        assert_eq!(camber_sketch::file::to_json(&s).unwrap(), before);
    }
}
