//! Ellipses and elliptic arcs in sketch files: `{"kind": "ellipse", "center", "semi_axis_a",
//! "semi_axis_b", "rotation"}` and `"elliptic_arc"` with `"start_angle"`, `"end_angle"`
//! round-trip with the ellipse kinds, and hostile values are refused with the entity's id and
//! the value.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use camber_sketch::file::{from_json, to_json};
use camber_sketch::{Constraint, Sketch};

const FILE: &str = r#"{"version":1,"entities":[
 {"id":0,"kind":"elliptic_arc","center":[1,2],"semi_axis_a":3,"semi_axis_b":1.5,"rotation":0.4,"start_angle":5.5,"end_angle":0.5},
 {"id":1,"kind":"line","from":[-5,6],"to":[5,6]},
 {"id":2,"kind":"ellipse","center":[-4,0],"semi_axis_a":1,"semi_axis_b":2,"rotation":-2.5},
 {"id":3,"kind":"point","at":[-4,2.2]}],
"constraints":[
 {"id":4,"kind":"point_on_ellipse","point":{"point":3},"ellipse":2},
 {"id":5,"kind":"semi_axis","ellipse":0,"axis":"b","length":1.5},
 {"id":6,"kind":"semi_axis","ellipse":0,"axis":"a","length":3},
 {"id":7,"kind":"elliptic_arc_tangent_to_line","arc":0,"end":"end","line":1,"sense":"oppose"},
 {"id":8,"kind":"point_on_line","point":{"end":0},"line":1},
 {"id":9,"kind":"fixed","target":{"entity":1}}]}"#;

#[test]
fn an_ellipse_file_loads_and_round_trips() {
    let s = from_json(FILE).unwrap();
    let arc = s.entities().next().unwrap().1.as_elliptic_arc().unwrap();
    assert_relative_eq!(arc.ellipse().semi_axis_a(), 3.0, epsilon = 1e-15);
    assert_relative_eq!(arc.ellipse().semi_axis_b(), 1.5, epsilon = 1e-15);
    assert_relative_eq!(arc.ellipse().rotation(), 0.4, epsilon = 1e-15);
    assert_relative_eq!(
        arc.sweep(),
        0.5 + std::f64::consts::TAU - 5.5,
        epsilon = 1e-13
    );
    let full = s.entities().nth(2).unwrap().1.as_ellipse().unwrap();
    // A rotation of −2.5 rad with a = 1: the same ellipse, its vertex at angle −2.5.
    assert_relative_eq!(full.rotation(), -2.5, epsilon = 1e-14);
    let text = to_json(&s).unwrap();
    assert!(text.contains(r#""kind":"elliptic_arc""#) && text.contains(r#""kind":"ellipse""#));
    let back = from_json(&text).unwrap();
    for ((i, a), (j, b)) in s.entities().zip(back.entities()) {
        assert_eq!(i, j);
        assert_eq!(a.kind_name(), b.kind_name());
        for (p, q) in a.points().iter().zip(b.points()) {
            assert_relative_eq!(p, q, epsilon = 1e-13);
        }
        assert_eq!(a.scalars().len(), b.scalars().len());
        for (p, q) in a.scalars().iter().zip(b.scalars().iter()) {
            assert_relative_eq!(p, q, epsilon = 1e-15);
        }
    }
    let kinds = |s: &Sketch| {
        s.constraints()
            .map(|(id, c)| (id, c.clone()))
            .collect::<Vec<(_, Constraint)>>()
    };
    assert_eq!(kinds(&s), kinds(&back));
}

#[test]
fn a_loaded_ellipse_sketch_solves_to_its_rows() {
    let mut s = from_json(FILE).unwrap();
    let report = s.solve().map_err(|e| s.describe_error(&e)).unwrap();
    for c in &report.components {
        for r in &c.report.residuals {
            assert!(r.max_abs < 1e-10, "{r:?}");
        }
    }
    let arc = s.entities().next().unwrap().1.as_elliptic_arc().unwrap();
    let e = arc.ellipse();
    assert!(e.implicit_value(&arc.start_point()).abs() < 1e-10);
    assert!(e.implicit_value(&arc.end_point()).abs() < 1e-10);
    // The end is on y = 6 and the line is tangent there.
    assert_relative_eq!(arc.end_point().y, 6.0, epsilon = 1e-10);
    let full = s.entities().nth(2).unwrap().1.as_ellipse().unwrap();
    let p = s.entities().nth(3).unwrap().1.points()[0];
    assert!(full.implicit_value(&p).abs() < 1e-10);
}

fn load_err(entity: &str) -> String {
    let text = format!(r#"{{"version":1,"entities":[{entity}],"constraints":[]}}"#);
    from_json(&text).unwrap_err().to_string()
}

#[test]
fn hostile_ellipses_are_refused_with_the_entity_and_value() {
    let ellipse = |a: &str, b: &str, rot: &str| {
        format!(
            r#"{{"id":7,"kind":"ellipse","center":[0,0],"semi_axis_a":{a},"semi_axis_b":{b},"rotation":{rot}}}"#
        )
    };
    assert_eq!(
        load_err(&ellipse("2", "-1", "0")),
        "entity 7 (ellipse): geometry: semi-axis b of the ellipse (-1) is not positive"
    );
    assert_eq!(
        load_err(&ellipse("0", "1", "0")),
        "entity 7 (ellipse): geometry: semi-axis a of the ellipse (0) is not positive"
    );
    assert_eq!(
        load_err(&ellipse("1", "1", "1e300")),
        "entity 7 (ellipse): geometry: ellipse rotation 1e300 rad is larger in magnitude than 6434.0 rad"
    );
    let e = load_err(&ellipse("1e999", "1", "0"));
    assert!(e.starts_with("invalid JSON: non-finite number"), "{e}");
    let arc = |a0: &str, a1: &str| {
        format!(
            r#"{{"id":7,"kind":"elliptic_arc","center":[0,0],"semi_axis_a":2,"semi_axis_b":1,"rotation":0,"start_angle":{a0},"end_angle":{a1}}}"#
        )
    };
    let e = load_err(&arc("2", "2"));
    assert!(
        e.starts_with("entity 7 (elliptic_arc): geometry: the arc from angle 2 to angle 2"),
        "{e}"
    );
    let e = load_err(&arc("0", "-1e9"));
    assert!(e.contains("elliptic arc end angle -1e9"), "{e}");
    let e = load_err(
        r#"{"id":7,"kind":"elliptic_arc","center":[0,0],"semi_axis_a":2,"semi_axis_b":1,"rotation":0,"start_angle":0}"#,
    );
    assert!(e.contains("end_angle"), "{e}");
}

#[test]
fn ellipse_kinds_on_other_entities_fail_to_load() {
    let text = r#"{"version":1,"entities":[{"id":0,"kind":"point","at":[0,0]},{"id":1,"kind":"circle","center":[0,0],"radius":1}],
"constraints":[{"id":2,"kind":"point_on_ellipse","point":{"point":0},"ellipse":1}]}"#;
    assert_eq!(
        from_json(text).unwrap_err().to_string(),
        "constraint 2 (point_on_ellipse): entity 1 is a circle, expected ellipse or elliptic arc"
    );
}

/// A solved ellipse sketch saved and loaded is the same sketch bit for bit: the file holds the
/// a-axis vertex and the arc's end points beside the numbers (which alone would round).
#[test]
fn a_solved_ellipse_sketch_saves_and_loads_exactly() {
    let mut s = from_json(FILE).unwrap();
    s.solve().unwrap();
    let text = to_json(&s).unwrap();
    assert!(text.contains(r#""vertex""#), "{text}");
    let back = from_json(&text).unwrap();
    assert_eq!(to_json(&back).unwrap(), text);
    for ((_, a), (_, b)) in s.entities().zip(back.entities()) {
        assert_eq!(a, b);
    }
}

/// The point form alone loads; numbers that disagree with the points, or half a point form,
/// are refused at the field with the value.
#[test]
fn ellipse_forms_must_be_complete_and_agree() {
    let load = |kind: &str, fields: &str| {
        from_json(&format!(
            r#"{{"version":1,"entities":[{{"id":0,"kind":"{kind}",{fields}}}]}}"#
        ))
        .map_err(|e| e.to_string())
    };
    // a = 2 along +y (rotation π/2), b = 1; the arc from the vertex (φ = 0) to φ = π/2.
    let points = r#""center":[1,1],"semi_axis_b":1,"vertex":[1,3],"start":[1,3],"end":[0,1]"#;
    let s = load("elliptic_arc", points).unwrap();
    let arc = s.entities().next().unwrap().1.as_elliptic_arc().unwrap();
    assert_relative_eq!(arc.ellipse().semi_axis_a(), 2.0, epsilon = 1e-15);
    assert_relative_eq!(
        arc.ellipse().rotation(),
        std::f64::consts::FRAC_PI_2,
        epsilon = 1e-15
    );
    assert_relative_eq!(arc.sweep(), std::f64::consts::FRAC_PI_2, epsilon = 1e-15);
    assert!(load(
        "ellipse",
        r#""center":[1,1],"semi_axis_b":1,"vertex":[1,3]"#
    )
    .is_ok());
    let agreeing = format!(
        r#"{points},"semi_axis_a":2,"rotation":1.5707963267948966,"start_angle":0,"end_angle":1.5707963267948966"#
    );
    assert!(load("elliptic_arc", &agreeing).is_ok());
    for (kind, fields, path, words) in [
        (
            "ellipse",
            r#""center":[1,1],"semi_axis_b":1,"vertex":[1,3],"semi_axis_a":2.5"#.to_owned(),
            "entities[0].semi_axis_a",
            "semi_axis_a 2.5 disagrees",
        ),
        (
            "ellipse",
            r#""center":[1,1],"semi_axis_b":1,"vertex":[1,3],"rotation":0"#.to_owned(),
            "entities[0].rotation",
            "rotation 0 disagrees",
        ),
        (
            "elliptic_arc",
            format!(r#"{points},"end_angle":3"#),
            "entities[0].end_angle",
            "end_angle 3 disagrees",
        ),
        (
            "elliptic_arc",
            r#""center":[1,1],"semi_axis_b":1,"vertex":[1,3],"start":[1,3]"#.to_owned(),
            "entities[0].end",
            "missing field `end`",
        ),
        (
            "ellipse",
            r#""center":[1,1],"semi_axis_b":1,"semi_axis_a":2"#.to_owned(),
            "entities[0].rotation",
            "missing field `rotation`",
        ),
    ] {
        let e = load(kind, &fields).unwrap_err();
        assert!(e.contains(path) && e.contains(words), "{fields}: {e}");
    }
}
