//! Messages name the user's own ids and fields in plain words: no Rust
//! Debug text, no internal ids, and the JSON path inside an entity.

use camber_sketch::{file, ConstraintId, EntityId, Error, PointRef, DRAG_CONSTRAINT};

#[test]
fn messages_have_no_debug_text_or_internal_ids() {
    let e = Error::NotDraggable {
        point: PointRef::Control(EntityId(0), 1),
    };
    assert_eq!(
        e.to_string(),
        "control point 1 of entity 0 cannot be dragged: it is fixed or determined by the constraints"
    );
    let e = Error::NotSatisfied {
        failed: vec![(ConstraintId(4), 1e-3), (DRAG_CONSTRAINT, 2.0)],
    };
    let text = e.to_string();
    assert_eq!(
        text,
        "constraints not satisfied: constraint 4 (|g| = 1.000e-3), the drag target (|g| = 2.000e0)"
    );
    let e = Error::Conflicting {
        constraints: vec![ConstraintId(2), ConstraintId(3)],
    };
    assert_eq!(
        e.to_string(),
        "conflicting constraints: constraint 2, constraint 3"
    );
}

#[test]
fn entity_errors_name_the_field_inside_the_entity() {
    let cases = [
        (
            r#"{"id": 0, "kind": "bezier", "control_points": [[0, 0], [1, 2, 3]]}"#,
            "at entities[0].control_points[1]: invalid length 3, expected a point [x, y] of 2 numbers",
        ),
        (
            r#"{"id": 0, "kind": "line", "from": [0, 0], "to": "x"}"#,
            "at entities[0].to: invalid type: string \"x\"",
        ),
        (
            r#"{"id": 0, "kind": "line", "from": [0, 0], "to": [1, 1], "z": 1}"#,
            "at entities[0].z: unknown field `z`",
        ),
        (r#"{"id": 0, "kind": "spiral"}"#, "at entities[0].kind: unknown entity kind `spiral`"),
        (r#"{"kind": "point", "at": [0, 0]}"#, "at entities[0]: missing field `id`"),
    ];
    for (entity, words) in cases {
        let text = format!(r#"{{"version": 1, "entities": [{entity}]}}"#);
        let err = file::from_json(&text).unwrap_err().to_string();
        assert!(err.starts_with(words), "{err}");
    }
}
