//! Arcs in sketch files: `{"kind": "arc", "center", "radius", "start_angle", "end_angle"}`
//! round-trips with the arc kinds, and hostile values (a non-finite number, a radius that is
//! not positive, an absurd angle, a sweep of zero, a missing field) are refused with the
//! entity's id and the value.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use camber_sketch::file::{from_json, to_json};
use camber_sketch::{Constraint, Entity, Sketch};

const FILE: &str = r#"{"version":1,"entities":[
 {"id":0,"kind":"arc","center":[1,2],"radius":1.5,"start_angle":5.5,"end_angle":0.5},
 {"id":1,"kind":"line","from":[0,0],"to":[4,0]},
 {"id":2,"kind":"circle","center":[1,2],"radius":1},
 {"id":3,"kind":"point","at":[2.5,2.5]},
 {"id":4,"kind":"arc","center":[-2,0],"radius":0.5,"start_angle":-3,"end_angle":3}],
"constraints":[
 {"id":5,"kind":"point_on_arc","point":{"point":3},"arc":0},
 {"id":6,"kind":"arc_tangent_to_line","arc":0,"end":"end","line":1,"sense":"oppose"},
 {"id":7,"kind":"concentric","first":0,"second":2},
 {"id":8,"kind":"equal_radius","first":4,"second":2},
 {"id":9,"kind":"radius","circle":0,"radius":1.5},
 {"id":10,"kind":"coincident","a":{"start":4},"b":{"end":1}}]}"#;

#[test]
fn an_arc_file_loads_with_its_angles_and_round_trips() {
    let s = from_json(FILE).unwrap();
    let arc = s.entities().next().unwrap().1.as_arc().unwrap();
    assert_relative_eq!(arc.radius(), 1.5, epsilon = 1e-15);
    // 5.5 rad to 0.5 rad counter-clockwise: a sweep of 0.5 + 2π − 5.5.
    assert_relative_eq!(
        arc.sweep(),
        0.5 + std::f64::consts::TAU - 5.5,
        epsilon = 1e-14
    );
    let text = to_json(&s).unwrap();
    let back = from_json(&text).unwrap();
    for ((i, a), (j, b)) in s.entities().zip(back.entities()) {
        assert_eq!(i, j);
        assert_eq!(a.kind_name(), b.kind_name());
        for (p, q) in a.points().iter().zip(b.points()) {
            assert_relative_eq!(p, q, epsilon = 1e-14);
        }
    }
    let kinds = |s: &Sketch| {
        s.constraints()
            .map(|(id, c)| (id, c.clone()))
            .collect::<Vec<(_, Constraint)>>()
    };
    assert_eq!(kinds(&s), kinds(&back));
    // Saved angles are reduced: atan2 of the blocks, in (−π, π].
    assert!(text.contains(r#""kind":"arc""#));
    assert_eq!(to_json(&back).unwrap().len(), text.len());
}

#[test]
fn a_loaded_arc_sketch_solves_to_its_rows() {
    let mut s = from_json(FILE).unwrap();
    let report = s.solve().map_err(|e| e.to_string()).unwrap();
    for c in &report.components {
        for r in &c.report.residuals {
            assert!(r.max_abs < 1e-10, "{r:?}");
        }
    }
    for (_, e) in s.entities() {
        if let Entity::Arc([c, p, q]) = e {
            assert!(((q - c).norm() - (p - c).norm()).abs() < 1e-10);
        }
    }
}

fn load_err(entity: &str) -> String {
    let text = format!(r#"{{"version":1,"entities":[{entity}],"constraints":[]}}"#);
    from_json(&text).unwrap_err().to_string()
}

#[test]
fn hostile_arcs_are_refused_with_the_entity_and_value() {
    let arc = |r: &str, a0: &str, a1: &str| {
        format!(
            r#"{{"id":7,"kind":"arc","center":[0,0],"radius":{r},"start_angle":{a0},"end_angle":{a1}}}"#
        )
    };
    assert_eq!(
        load_err(&arc("-1", "0", "1")),
        "entity 7 (arc): geometry: radius -1 is not positive"
    );
    assert_eq!(
        load_err(&arc("0", "0", "1")),
        "entity 7 (arc): geometry: radius 0 is not positive"
    );
    assert_eq!(
        load_err(&arc("1", "0", "1e300")),
        "entity 7 (arc): geometry: arc end angle 1e300 rad is larger in magnitude than 6434.0 rad"
    );
    let e = load_err(&arc("1", "2", "2"));
    assert!(
        e.starts_with("entity 7 (arc): geometry: the arc from angle 2 to angle 2"),
        "{e}"
    );
    // A whole turn is a circle.
    let e = load_err(&arc("1", "0", "6.283185307179586"));
    assert!(e.contains("sweeps no angle"), "{e}");
    let e = load_err(&arc("1e999", "0", "1"));
    assert!(e.starts_with("invalid JSON: non-finite number"), "{e}");
    let e = load_err(r#"{"id":7,"kind":"arc","center":[0,0],"radius":1,"start_angle":0}"#);
    assert!(e.contains("end_angle"), "{e}");
    let e = load_err(
        r#"{"id":7,"kind":"arc","center":[0,0],"radius":1,"start_angle":"x","end_angle":1}"#,
    );
    assert!(e.contains("start_angle"), "{e}");
}

/// Kinds that read arcs refuse what is not one, naming the constraint.
#[test]
fn arc_kinds_on_other_entities_fail_to_load() {
    let text = r#"{"version":1,"entities":[{"id":0,"kind":"point","at":[0,0]},{"id":1,"kind":"circle","center":[0,0],"radius":1}],
"constraints":[{"id":2,"kind":"point_on_arc","point":{"point":0},"arc":1}]}"#;
    assert_eq!(
        from_json(text).unwrap_err().to_string(),
        "constraint 2 (point_on_arc): entity 1 is a circle, expected arc"
    );
}

/// A solved arc sketch saved and loaded is the same sketch bit for bit: the file holds the
/// arc's end points as well as its radius and angles (which alone would round).
#[test]
fn a_solved_arc_sketch_saves_and_loads_exactly() {
    let mut s = from_json(FILE).unwrap();
    s.solve().unwrap();
    let text = to_json(&s).unwrap();
    let back = from_json(&text).unwrap();
    assert_eq!(to_json(&back).unwrap(), text);
    for ((_, a), (_, b)) in s.entities().zip(back.entities()) {
        assert_eq!(a, b);
    }
}

/// The end-point form alone loads; an arc whose radius or angles disagree with its end
/// points, or that gives half of a form, is refused at the field with the values.
#[test]
fn arc_forms_must_be_complete_and_agree() {
    let load = |arc: &str| {
        from_json(&format!(
            r#"{{"version":1,"entities":[{{"id":0,"kind":"arc",{arc}}}]}}"#
        ))
        .map_err(|e| e.to_string())
    };
    let s = load(r#""center":[1,1],"start":[2,1],"end":[1,2]"#).unwrap();
    let arc = s.entities().next().unwrap().1.as_arc().unwrap();
    assert_relative_eq!(arc.radius(), 1.0, epsilon = 1e-15);
    assert_relative_eq!(arc.sweep(), std::f64::consts::FRAC_PI_2, epsilon = 1e-15);
    let both = r#""center":[1,1],"radius":1,"start_angle":0,"end_angle":1.5707963267948966,"start":[2,1],"end":[1,2]"#;
    assert!(load(both).is_ok());
    for (arc, path, words) in [
        (
            r#""center":[1,1],"radius":1.5,"start_angle":0,"end_angle":1.5707963267948966,"start":[2,1],"end":[1,2]"#,
            "entities[0].radius",
            "radius 1.5 disagrees",
        ),
        (
            r#""center":[1,1],"radius":1,"start_angle":0,"end_angle":3,"start":[2,1],"end":[1,2]"#,
            "entities[0].end_angle",
            "end_angle 3 disagrees",
        ),
        (
            r#""center":[1,1],"start":[2,1]"#,
            "entities[0].end",
            "not its end point",
        ),
        (
            r#""center":[1,1],"radius":1,"end_angle":1"#,
            "entities[0].start_angle",
            "missing field `start_angle`",
        ),
    ] {
        let e = load(arc).unwrap_err();
        assert!(e.contains(path) && e.contains(words), "{arc}: {e}");
    }
}
