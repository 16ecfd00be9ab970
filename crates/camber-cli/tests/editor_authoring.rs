//! The editor's authoring routes through `EditorState::handle`: adding what a user drew with
//! its constraints, deleting, typing a dimension or a parameter, saving under another name,
//! and opening a sketch solved. Every refusal leaves the sketch as it was.

#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

use camber_cli::editor::EditorState;
use camber_sketch::{file::to_json, EntityId, PointRef, Sketch};
use serde_json::{json, Value};

fn post(ed: &mut EditorState, path: &str, body: &Value) -> (u16, Value) {
    let r = ed.handle("POST", path, body.to_string().as_bytes());
    let v: Value = serde_json::from_slice(&r.body).expect("every answer is JSON");
    (r.status, v)
}

fn empty() -> EditorState {
    EditorState::new(Sketch::new(), "drawn.json".into(), None).unwrap()
}

fn file(ed: &EditorState) -> String {
    to_json(ed.sketch()).unwrap()
}

/// A rectangle drawn as four lines joined end to start, with the constraints a sketcher
/// infers (coincident corners, two horizontal and two vertical sides) and one fixed corner.
fn rectangle() -> Value {
    json!({
        "entities": [
            {"id": 0, "kind": "line", "from": [0, 0], "to": [2, 0.1]},
            {"id": 1, "kind": "line", "from": [2, 0.1], "to": [2.1, 1]},
            {"id": 2, "kind": "line", "from": [2.1, 1], "to": [0, 1.1]},
            {"id": 3, "kind": "line", "from": [0, 1.1], "to": [0, 0]}
        ],
        "constraints": [
            {"id": 10, "kind": "coincident", "a": {"end": 0}, "b": {"start": 1}},
            {"id": 11, "kind": "coincident", "a": {"end": 1}, "b": {"start": 2}},
            {"id": 12, "kind": "coincident", "a": {"end": 2}, "b": {"start": 3}},
            {"id": 13, "kind": "coincident", "a": {"end": 3}, "b": {"start": 0}},
            {"id": 14, "kind": "horizontal", "of": {"line": 0}},
            {"id": 15, "kind": "horizontal", "of": {"line": 2}},
            {"id": 16, "kind": "vertical", "of": {"line": 1}},
            {"id": 17, "kind": "vertical", "of": {"line": 3}},
            {"id": 18, "kind": "fixed", "target": {"point": {"start": 0}}}
        ]
    })
}

fn constraint(state: &Value, id: u64) -> &Value {
    state["constraints"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["id"] == id)
        .unwrap_or_else(|| panic!("constraint {id} listed"))
}

fn dof(state: &Value) -> u64 {
    state["components"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["analysis"]["dof"].as_u64().unwrap())
        .sum()
}

fn end(ed: &EditorState, line: u64) -> [f64; 2] {
    let p = ed.sketch().point(PointRef::End(EntityId(line))).unwrap();
    [p.x, p.y]
}

#[test]
fn a_drawn_rectangle_is_added_solved_and_dimensioned_to_no_freedom() {
    let mut ed = empty();
    let (status, state) = post(&mut ed, "/api/create", &rectangle());
    assert_eq!(status, 200, "{state}");
    assert_eq!(state["next_id"], 19);
    assert_eq!(state["report"]["action"], "create");
    assert!(state["report"]["summary"]
        .as_str()
        .unwrap()
        .ends_with("solved"));
    for c in state["constraints"].as_array().unwrap() {
        assert_eq!(c["status"], "ok", "{c}");
        // Merged coincidences own no rows, and so no residual.
        assert!(c["residual"].as_f64().unwrap_or(0.0) < 1e-9, "{c}");
    }
    // Width and height free: two dimensions take them.
    assert_eq!(dof(&state), 2);
    let dims = json!({"constraints": [
        {"id": 20, "kind": "horizontal_distance", "of": {"a": {"start": 0}, "b": {"end": 0}}, "distance": 2},
        {"id": 21, "kind": "vertical_distance", "of": {"a": {"start": 1}, "b": {"end": 1}}, "distance": 1}
    ]});
    let (status, state) = post(&mut ed, "/api/create", &dims);
    assert_eq!(status, 200, "{state}");
    assert_eq!(dof(&state), 0);
    assert_eq!(constraint(&state, 20)["value"], 2.0);
    // Typing a width re-solves: the right side follows.
    let (status, state) = post(
        &mut ed,
        "/api/dimension",
        &json!({"constraint": 20, "value": 3.5}),
    );
    assert_eq!(status, 200, "{state}");
    assert!((end(&ed, 0)[0] - 3.5).abs() < 1e-9, "{:?}", end(&ed, 0));
    assert_eq!(constraint(&state, 20)["value"], 3.5);
    // The same as an expression of a parameter, then the parameter changed.
    let (status, state) = post(
        &mut ed,
        "/api/parameter",
        &json!({"name": "w", "value": 1.5}),
    );
    assert_eq!(status, 200, "{state}");
    assert_eq!(state["parameters"][0]["name"], "w");
    let (status, state) = post(
        &mut ed,
        "/api/dimension",
        &json!({"constraint": 21, "value": "w / 3"}),
    );
    assert_eq!(status, 200, "{state}");
    assert_eq!(constraint(&state, 21)["expression"], "w / 3");
    assert!((end(&ed, 1)[1] - 0.5).abs() < 1e-9);
    let (status, state) = post(&mut ed, "/api/parameter", &json!({"name": "w", "value": 3}));
    assert_eq!(status, 200, "{state}");
    assert!((end(&ed, 1)[1] - 1.0).abs() < 1e-9);
    assert_eq!(state["parameters"][0]["readers"], json!([21]));
    // A number typed over the expression replaces it.
    let (status, state) = post(
        &mut ed,
        "/api/dimension",
        &json!({"constraint": 21, "value": "0.75"}),
    );
    assert_eq!(status, 200, "{state}");
    assert!(constraint(&state, 21).get("expression").is_none());
    assert!((end(&ed, 1)[1] - 0.75).abs() < 1e-9);
}

#[test]
fn refused_additions_and_dimensions_leave_the_sketch_as_it_was() {
    let mut ed = empty();
    assert_eq!(post(&mut ed, "/api/create", &rectangle()).0, 200);
    let before = file(&ed);
    let refusals = [
        ("/api/create", json!({}), 400, "nothing to add"),
        (
            "/api/create",
            json!({"entities": [{"id": 9, "kind": "line", "from": [0, 0]}]}),
            400,
            "entities[0]",
        ),
        (
            "/api/create",
            json!({"entities": [{"id": 2, "kind": "point", "at": [0, 0]}]}),
            422,
            "entity 2",
        ),
        (
            "/api/create",
            json!({"entities": [{"id": 30, "kind": "point", "at": [5, 5]}],
                   "constraints": [{"id": 31, "kind": "horizontal", "of": {"line": 77}}]}),
            422,
            "constraint 31",
        ),
        (
            "/api/create",
            json!({"entities": [{"id": 9_007_199_254_740_992_u64, "kind": "point", "at": [0, 0]}]}),
            400,
            "2^53",
        ),
        ("/api/create", json!({"shapes": []}), 400, "unknown field"),
        (
            "/api/dimension",
            json!({"constraint": 14, "value": 1}),
            422,
            "no value",
        ),
        (
            "/api/dimension",
            json!({"constraint": 99, "value": 1}),
            404,
            "99",
        ),
        ("/api/delete", json!({"entities": [99]}), 404, "entity 99"),
        (
            "/api/delete",
            json!({"constraints": [99]}),
            404,
            "constraint 99",
        ),
        ("/api/delete", json!({}), 400, "nothing to delete"),
        (
            "/api/parameter",
            json!({"name": "2x", "value": 1}),
            422,
            "2x",
        ),
        (
            "/api/parameter",
            json!({"name": "sin", "value": 1}),
            422,
            "sin",
        ),
    ];
    for (path, body, want, says) in refusals {
        let (status, answer) = post(&mut ed, path, &body);
        assert_eq!(status, want, "{path} {body}: {answer}");
        let error = answer["error"].as_str().unwrap();
        assert!(error.contains(says), "{path} {body}: {error}");
        assert_eq!(file(&ed), before, "{path} {body} changed the sketch");
    }
    // A dimension the geometry cannot take, a bad expression, an unknown name: refused with
    // the old value named, nothing changed.
    let dims = json!({"constraints": [
        {"id": 20, "kind": "distance", "a": {"start": 0}, "b": {"end": 0}, "distance": 2}
    ]});
    assert_eq!(post(&mut ed, "/api/create", &dims).0, 200);
    let before = file(&ed);
    for value in [json!(-1), json!("2 *"), json!("nope + 1"), json!("1 / 0")] {
        let (status, answer) = post(
            &mut ed,
            "/api/dimension",
            &json!({"constraint": 20, "value": value}),
        );
        assert_eq!(status, 422, "{value}: {answer}");
        assert!(
            answer["error"].as_str().unwrap().contains("it stays 2"),
            "{answer}"
        );
        assert_eq!(file(&ed), before, "{value}");
    }
    // Deeply nested JSON is a plain 400.
    let deep = format!(
        "{{\"entities\": {}{}}}",
        "[".repeat(10_000),
        "]".repeat(10_000)
    );
    let r = ed.handle("POST", "/api/create", deep.as_bytes());
    assert_eq!(r.status, 400, "{}", r.text());
    assert_eq!(file(&ed), before);
}

#[test]
fn a_conflicting_constraint_is_kept_unsolved_named_and_undone() {
    let mut ed = empty();
    assert_eq!(post(&mut ed, "/api/create", &rectangle()).0, 200);
    let before = file(&ed);
    // A side cannot be 2 and 3 long.
    let (status, state) = post(
        &mut ed,
        "/api/create",
        &json!({"constraints": [
            {"id": 20, "kind": "horizontal_distance", "of": {"a": {"start": 0}, "b": {"end": 0}}, "distance": 2},
            {"id": 21, "kind": "horizontal_distance", "of": {"a": {"start": 2}, "b": {"end": 2}}, "distance": 3}
        ]}),
    );
    assert_eq!(status, 200, "{state}");
    let summary = state["report"]["summary"].as_str().unwrap();
    assert!(summary.contains("the solve failed"), "{summary}");
    let listed = constraint(&state, 21);
    assert_ne!(listed["status"], "ok", "{listed}");
    assert!(listed["residual"].as_f64().unwrap() > 1e-3);
    let (status, state) = post(&mut ed, "/api/undo", &json!({}));
    assert_eq!(status, 200);
    assert_eq!(file(&ed), before);
    assert!(state["can_redo"].as_bool().unwrap());
}

#[test]
fn deleting_an_entity_takes_the_constraints_reading_it_and_undo_brings_all_back() {
    let mut ed = empty();
    assert_eq!(post(&mut ed, "/api/create", &rectangle()).0, 200);
    let before = file(&ed);
    let (status, state) = post(&mut ed, "/api/delete", &json!({"entities": [1]}));
    assert_eq!(status, 200, "{state}");
    // Line 1: two corners and its vertical go with it.
    assert_eq!(state["constraints"].as_array().unwrap().len(), 6);
    let summary = state["report"]["summary"].as_str().unwrap();
    assert_eq!(
        summary,
        "deleted 1 entity and 3 constraints (3 of them read what was deleted)"
    );
    assert_eq!(post(&mut ed, "/api/undo", &json!({})).0, 200);
    assert_eq!(file(&ed), before);
    // One constraint, then re-added under the same id: the sketch is whole again.
    let (status, _) = post(&mut ed, "/api/delete", &json!({"constraints": [14]}));
    assert_eq!(status, 200);
    let (status, state) = post(
        &mut ed,
        "/api/create",
        &json!({"constraints": [{"id": 14, "kind": "horizontal", "of": {"line": 0}}]}),
    );
    assert_eq!(status, 200, "{state}");
    assert_eq!(file(&ed), before);
    // Redo after undo replays the deletion exactly.
    assert_eq!(post(&mut ed, "/api/undo", &json!({})).0, 200);
    assert_eq!(post(&mut ed, "/api/undo", &json!({})).0, 200);
    assert_eq!(file(&ed), before);
    assert_eq!(post(&mut ed, "/api/redo", &json!({})).0, 200);
    assert!(ed
        .sketch()
        .constraint(camber_sketch::ConstraintId(14))
        .is_err());
}

#[test]
fn save_as_writes_beside_the_file_and_refuses_other_folders() {
    let dir = tempfile::tempdir().unwrap();
    let first = dir.path().join("first.json");
    let mut ed = EditorState::new(Sketch::new(), first.clone(), None).unwrap();
    assert_eq!(post(&mut ed, "/api/create", &rectangle()).0, 200);
    for (name, want) in [
        ("../out.json", 400),
        ("sub/out.json", 400),
        ("C:out.json", 400),
        (".hidden.json", 400),
        ("out.txt", 400),
        ("", 400),
    ] {
        let (status, answer) = post(&mut ed, "/api/save-as", &json!({"file": name}));
        assert_eq!(status, want, "{name}: {answer}");
    }
    let long = format!("{}.json", "a".repeat(300));
    assert_eq!(post(&mut ed, "/api/save-as", &json!({"file": long})).0, 400);
    let (status, answer) = post(&mut ed, "/api/save-as", &json!({"file": "second.json"}));
    assert_eq!(status, 200, "{answer}");
    let second = dir.path().join("second.json");
    assert_eq!(answer["saved"], second.display().to_string());
    assert_eq!(answer["state"]["output"], second.display().to_string());
    assert!(!answer["state"]["unsaved"].as_bool().unwrap());
    let saved = camber_cli::sketch_file::load(&second).unwrap();
    assert_eq!(to_json(&saved).unwrap(), file(&ed));
    // An existing file needs the overwrite flag.
    let (status, _) = post(&mut ed, "/api/save-as", &json!({"file": "second.json"}));
    assert_eq!(status, 409);
    let (status, _) = post(
        &mut ed,
        "/api/save-as",
        &json!({"file": "second.json", "overwrite": true}),
    );
    assert_eq!(status, 200);
    assert!(!first.exists(), "save-as never wrote the first name");
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    assert_eq!(names, ["second.json"]);
}

#[test]
fn a_sketch_opens_solved_and_undo_shows_the_file() {
    let text = r#"{"version": 1,
      "entities": [{"id": 0, "kind": "line", "from": [0, 0], "to": [1, 0.5]}],
      "constraints": [{"id": 1, "kind": "horizontal", "of": {"line": 0}}]}"#;
    let sketch = camber_cli::sketch_file::parse(text).unwrap();
    let as_loaded = to_json(&sketch).unwrap();
    let mut ed = EditorState::new(sketch, "s.json".into(), None).unwrap();
    ed.solve_on_open().unwrap();
    let state = ed.state().unwrap();
    let report = state.report.as_ref().unwrap();
    assert!(
        report.summary.starts_with("solved on opening"),
        "{}",
        report.summary
    );
    assert!(state.components[0].residual < 1e-12);
    assert!(state.unsaved && state.can_undo);
    assert_eq!(post(&mut ed, "/api/undo", &json!({})).0, 200);
    assert_eq!(file(&ed), as_loaded);
    // A solved sketch opens untouched.
    let mut again = EditorState::new(ed.sketch().clone(), "s.json".into(), None).unwrap();
    assert_eq!(post(&mut again, "/api/solve", &json!({})).0, 200);
    let solved = again.sketch().clone();
    let mut third = EditorState::new(solved, "s.json".into(), None).unwrap();
    third.solve_on_open().unwrap();
    let state = third.state().unwrap();
    assert!(state.report.is_none() && !state.can_undo);
}

#[test]
fn authoring_routes_want_post_and_no_drag_in_progress() {
    let mut ed = empty();
    for path in [
        "/api/create",
        "/api/delete",
        "/api/dimension",
        "/api/parameter",
        "/api/save-as",
    ] {
        assert_eq!(ed.handle("GET", path, b"").status, 405, "{path}");
    }
    assert_eq!(post(&mut ed, "/api/create", &rectangle()).0, 200);
    let (status, _) = post(
        &mut ed,
        "/api/create",
        &json!({"constraints": [{"id": 20, "kind": "distance", "a": {"start": 0}, "b": {"end": 0}, "distance": 2}]}),
    );
    assert_eq!(status, 200);
    assert_eq!(
        post(
            &mut ed,
            "/api/drag/start",
            &json!({"entity": 2, "index": 0})
        )
        .0,
        200
    );
    let before = file(&ed);
    for (path, body) in [
        (
            "/api/create",
            json!({"entities": [{"id": 30, "kind": "point", "at": [0, 0]}]}),
        ),
        ("/api/delete", json!({"entities": [0]})),
        ("/api/dimension", json!({"constraint": 20, "value": 1})),
        ("/api/parameter", json!({"name": "a", "value": 1})),
        ("/api/save-as", json!({"file": "x.json"})),
    ] {
        let (status, answer) = post(&mut ed, path, &body);
        assert_eq!(status, 409, "{path}: {answer}");
        assert!(answer["error"].as_str().unwrap().contains("during a drag"));
    }
    assert_eq!(file(&ed), before);
}

#[test]
fn four_fillets_round_a_drawn_rectangle_and_keep_it_whole() {
    let mut ed = empty();
    // The rectangle without its fixed corner: a fillet moves the corners.
    let mut drawn = rectangle();
    drawn["constraints"]
        .as_array_mut()
        .unwrap()
        .retain(|c| c["kind"] != "fixed");
    assert_eq!(post(&mut ed, "/api/create", &drawn).0, 200);
    for (first, second) in [(0, 1), (1, 2), (2, 3), (3, 0)] {
        let (status, state) = post(
            &mut ed,
            "/api/fillet",
            &json!({"first": first, "second": second, "radius": 0.3}),
        );
        assert_eq!(status, 200, "{first}-{second}: {state}");
    }
    let state = ed.state().unwrap();
    let arcs = state
        .scene
        .entities
        .iter()
        .filter(|e| e.kind == "arc")
        .count();
    assert_eq!(arcs, 4);
    // Every constraint holds; the four radii are dimensions of 0.3.
    let state = serde_json::to_value(&state).unwrap();
    let radii: Vec<f64> = state["constraints"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| c["kind"] == "radius")
        .map(|c| c["value"].as_f64().unwrap())
        .collect();
    assert_eq!(radii, [0.3; 4]);
    for c in state["constraints"].as_array().unwrap() {
        assert!(c["residual"].as_f64().unwrap_or(0.0) < 1e-9, "{c}");
    }
    // Placed, and dimensioned side to side: nothing is left free.
    let n = state["next_id"].as_u64().unwrap();
    let dims = json!({"constraints": [
        {"id": n, "kind": "fixed", "target": {"point": {"start": 0}}},
        {"id": n + 1, "kind": "horizontal_distance", "of": {"a": {"start": 3}, "b": {"start": 1}}, "distance": 4},
        {"id": n + 2, "kind": "vertical_distance", "of": {"a": {"start": 0}, "b": {"start": 2}}, "distance": 2}
    ]});
    let (status, state) = post(&mut ed, "/api/create", &dims);
    assert_eq!(status, 200, "{state}");
    let summary = state["report"]["summary"].as_str().unwrap();
    assert!(summary.ends_with("solved"), "{summary}");
    assert_eq!(dof(&state), 0, "{}", state["components"]);
    // The bottom side runs from its fixed start over the width less two radii.
    let p = ed.sketch().point(PointRef::Start(EntityId(0))).unwrap();
    let q = ed.sketch().point(PointRef::End(EntityId(0))).unwrap();
    assert!(((q - p).norm() - 3.4).abs() < 1e-9, "{p} {q}");
    // Parallel sides have no corner to round: refused, the sketch unchanged.
    let before = file(&ed);
    let (status, answer) = post(
        &mut ed,
        "/api/fillet",
        &json!({"first": 0, "second": 2, "radius": 0.3}),
    );
    assert_eq!(status, 422, "{answer}");
    assert_eq!(file(&ed), before);
}

#[test]
fn exports_are_the_render_and_the_dxf_of_the_sketch() {
    let mut ed = empty();
    assert_eq!(post(&mut ed, "/api/create", &rectangle()).0, 200);
    let svg = ed.handle("GET", "/api/export.svg", b"");
    assert_eq!((svg.status, svg.content_type), (200, "image/svg+xml"));
    assert_eq!(
        svg.body,
        camber_cli::commands::render::picture(ed.sketch(), false)
            .unwrap()
            .into_bytes()
    );
    let dxf = ed.handle("GET", "/api/export.dxf", b"");
    assert_eq!((dxf.status, dxf.content_type), (200, "application/dxf"));
    let back =
        camber_interop::dxf::read(&dxf.body, &camber_interop::dxf::ReadOptions::default()).unwrap();
    assert_eq!(back.sketch.entities().count(), 4);
    assert_eq!(ed.handle("POST", "/api/export.svg", b"{}").status, 405);
}

#[test]
fn a_looped_curve_is_warned_of_and_a_drag_into_a_cusp_says_so() {
    let mut ed = empty();
    let looped = json!({"entities": [
        {"id": 0, "kind": "bezier", "control_points": [[0, 0], [3, 2], [-1, 2], [2, 0]]},
        {"id": 1, "kind": "bezier", "control_points": [[5, 0], [7, 2], [6, 2], [7, 0]]}
    ]});
    let (status, state) = post(&mut ed, "/api/create", &looped);
    assert_eq!(status, 200, "{state}");
    let warnings = state["warnings"].as_array().unwrap();
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert_eq!(warnings[0]["entity"], 0);
    assert_eq!(warnings[0]["kind"], "self_crossing");
    // Curve 1's second control point dragged to where C′(½) vanishes: (0,2) of the cusp cubic
    // (0,0), (2,2), (0,2), (2,0), moved by 5 along x.
    assert_eq!(
        post(
            &mut ed,
            "/api/drag/start",
            &json!({"entity": 1, "index": 2})
        )
        .0,
        200
    );
    let (status, moved) = post(&mut ed, "/api/drag/move", &json!({"to": [5, 2]}));
    assert_eq!(status, 200, "{moved}");
    let warnings = moved["warnings"].as_array().unwrap();
    assert_eq!(warnings[0]["entity"], 1);
    assert_eq!(warnings[0]["kind"], "cusp");
    assert!((warnings[0]["at"][0].as_f64().unwrap() - 6.0).abs() < 1e-9);
    // Back to a fair shape: the answer carries no warnings.
    let (_, moved) = post(&mut ed, "/api/drag/move", &json!({"to": [6, 2]}));
    assert!(moved.get("warnings").is_none(), "{moved}");
    assert_eq!(post(&mut ed, "/api/drag/end", &json!({})).0, 200);
    // Combs: one per curve, 13 teeth per piece.
    let r = ed.handle("GET", "/api/combs", b"");
    assert_eq!(r.status, 200);
    let combs: Value = serde_json::from_slice(&r.body).unwrap();
    let combs = combs["combs"].as_array().unwrap();
    assert_eq!(combs.len(), 2);
    assert_eq!(combs[0]["teeth"].as_array().unwrap().len(), 13);
}
