//! The editor's request handler driven without a network: drag sessions on the bundled blade
//! section and diffuser through `EditorState::handle`, the geometry each answer returns checked
//! against the constraints by hand (G1 joins, fixed points, the W2 tangencies), commits, solves,
//! undo, saving and reloading, and the plain 4xx answers to bad requests.

#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

use std::path::{Path, PathBuf};

use camber_cli::editor::EditorState;
use camber_geom::ParametricCurve;
use camber_sketch::constraints::{Fixed, G1Join, TangentToCircle};
use camber_sketch::{Constraint, Entity, EntityId, FixTarget, PointRef, Sketch};
use camber_workloads::{w2_valid, W2};
use nalgebra::{Point2, Vector2};
use serde_json::{json, Value};

fn sketch_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/sketches")
        .join(name)
}

/// An editor on a bundled sketch that saves into `out`.
fn editor(name: &str, out: &Path) -> EditorState {
    EditorState::load(&sketch_path(name), Some(out.to_path_buf())).unwrap()
}

/// Sends a request; returns the status and the JSON body.
fn call(ed: &mut EditorState, method: &str, path: &str, body: &Value) -> (u16, Value) {
    let r = ed.handle(method, path, body.to_string().as_bytes());
    assert_eq!(r.content_type, "application/json", "{path}");
    let value = serde_json::from_slice(&r.body).unwrap();
    (r.status, value)
}

fn post(ed: &mut EditorState, path: &str, body: Value) -> (u16, Value) {
    call(ed, "POST", path, &body)
}

fn state(ed: &mut EditorState) -> Value {
    let (status, v) = call(ed, "GET", "/api/state", &Value::Null);
    assert_eq!(status, 200);
    v
}

fn point(v: &Value) -> Point2<f64> {
    Point2::new(v[0].as_f64().unwrap(), v[1].as_f64().unwrap())
}

/// Puts the entities of an answer (`entities: [{id, points}]`) into `sketch`, as the page
/// would draw them.
fn apply(sketch: &mut Sketch, answer: &Value) {
    for e in answer["entities"].as_array().unwrap() {
        let id = EntityId(e["id"].as_u64().unwrap());
        let is_point = matches!(sketch.entity(id).unwrap(), Entity::Point(_));
        for (i, p) in e["points"].as_array().unwrap().iter().enumerate() {
            let r = if is_point {
                PointRef::Point(id)
            } else {
                PointRef::Control(id, i)
            };
            // A tangent block is sent at its handle N ± t/3; its node comes earlier, so it is
            // already in place here.
            let block = sketch.entity(id).unwrap().block_for_handle(i, point(p));
            sketch.set_point(r, block).unwrap();
        }
    }
}

/// Every control point of every entity, for comparing geometry exactly.
fn geometry(s: &Sketch) -> Vec<(EntityId, Vec<Point2<f64>>)> {
    s.entities()
        .map(|(id, e)| (id, e.points().to_vec()))
        .collect()
}

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

fn curve(s: &Sketch, id: EntityId) -> &dyn ParametricCurve<f64, 2> {
    match s.entity(id).unwrap() {
        Entity::Bezier(c) => c,
        Entity::BSpline(c) => c,
        Entity::Nurbs(c) => c,
        other => panic!("{id} is a {}", other.kind_name()),
    }
}

/// The blade's constraints checked on the curves themselves: every G1 join closed with both
/// tangents along its direction, every fixed point where the original file has it.
fn assert_blade_valid(s: &Sketch, original: &Sketch) {
    for (id, c) in s.constraints() {
        match c {
            Constraint::G1Join(G1Join {
                first,
                second,
                direction,
            }) => {
                let end = curve(s, *first).domain().1;
                let start = curve(s, *second).domain().0;
                let (pa, ta) = curve(s, *first).point_and_derivative(end).unwrap();
                let (pb, tb) = curve(s, *second).point_and_derivative(start).unwrap();
                let d = direction.normalize();
                assert!((pa - pb).norm() < 1e-9, "{id}: gap {}", (pa - pb).norm());
                for t in [ta, tb] {
                    let t = t.normalize();
                    assert!(cross(t, d).abs() < 1e-9, "{id}: cross {}", cross(t, d));
                    assert!(t.dot(&d) > 0.0, "{id}: tangent flipped");
                }
            }
            Constraint::Fixed(Fixed {
                target: FixTarget::Point(r),
            }) => {
                let (now, then) = (s.point(*r).unwrap(), original.point(*r).unwrap());
                assert!((now - then).norm() < 1e-12, "{id}: fixed point moved");
            }
            other => panic!("unexpected constraint {}", other.kind_name()),
        }
    }
}

/// The bundled diffuser's ids as a W2 sketch (the same circles as the W2 workload).
const DIFFUSER: W2 = W2 {
    curve: EntityId(0),
    circles: [EntityId(1), EntityId(3), EntityId(5)],
};

#[test]
fn blade_drag_keeps_every_constraint_and_commits_saves_and_undoes() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("blade.json");
    let mut ed = editor("blade_section.json", &out);
    let original = ed.sketch().clone();
    let s0 = state(&mut ed);
    assert_eq!(s0["scene"]["entities"].as_array().unwrap().len(), 4);
    assert_eq!(s0["components"][0]["analysis"]["dof"], 24);
    assert_eq!(s0["unsaved"], false);
    // The file is not solved yet: the trailing-edge join is open.
    assert!(s0["components"][0]["residual"].as_f64().unwrap() > 1e-4);

    let (status, started) = post(&mut ed, "/api/drag/start", json!({"entity": 1, "index": 2}));
    assert_eq!(status, 200, "{started}");
    assert_eq!(started["linear"], true);
    let mut client = original.clone();
    let p = original.point(PointRef::Control(EntityId(1), 2)).unwrap();
    for k in 0..12 {
        let th = std::f64::consts::TAU * f64::from(k) / 12.0;
        let target = p + 0.006 * Vector2::new(th.cos(), th.sin());
        let (status, moved) = post(
            &mut ed,
            "/api/drag/move",
            json!({"to": [target.x, target.y]}),
        );
        assert_eq!(status, 200, "{moved}");
        assert!(moved["update_us"].as_f64().unwrap() >= 0.0);
        apply(&mut client, &moved);
        assert!((client.point(PointRef::Control(EntityId(1), 2)).unwrap() - target).norm() < 1e-12);
        assert_blade_valid(&client, &original);
        // Only the answer's entities changed; the committed sketch has not moved yet.
        assert_eq!(geometry(ed.sketch()), geometry(&original));
    }
    // The state during the drag shows the session's geometry.
    let during = state(&mut ed);
    assert_eq!(during["dragging"]["entity"], 1);
    let mut from_state = original.clone();
    apply(&mut from_state, &during["scene"]);
    assert_eq!(geometry(&from_state), geometry(&client));

    let (status, ended) = post(&mut ed, "/api/drag/end", json!({}));
    assert_eq!(status, 200, "{ended}");
    assert_eq!(geometry(ed.sketch()), geometry(&client));
    assert_eq!(ended["unsaved"], true);
    assert_eq!(ended["can_undo"], true);
    assert_eq!(ended["report"]["action"], "drag");
    let line = &ended["report"]["components"][0];
    assert!(
        line["solver"].as_str().unwrap().contains("linear"),
        "{line}"
    );
    assert!(line["residual"].as_f64().unwrap() < 1e-9, "{line}");
    assert!(ended["components"][0]["residual"].as_f64().unwrap() < 1e-9);

    // Save, reload: the same sketch, the same text.
    let (status, saved) = post(&mut ed, "/api/save", json!({}));
    assert_eq!(status, 200, "{saved}");
    assert_eq!(saved["state"]["unsaved"], false);
    let text = std::fs::read_to_string(&out).unwrap();
    assert_eq!(saved["bytes"].as_u64().unwrap() as usize, text.len());
    let reloaded = camber_sketch::file::from_json(&text).unwrap();
    assert_eq!(geometry(&reloaded), geometry(&client));
    assert_eq!(camber_sketch::file::to_json(&reloaded).unwrap(), text);
    assert_blade_valid(&reloaded, &original);

    // Undo brings the file's geometry back (and that differs from what was saved).
    let (status, undone) = post(&mut ed, "/api/undo", json!({}));
    assert_eq!(status, 200, "{undone}");
    assert_eq!(geometry(ed.sketch()), geometry(&original));
    assert_eq!(undone["can_undo"], false);
    assert_eq!(undone["unsaved"], true);
    assert_eq!(post(&mut ed, "/api/undo", json!({})).0, 409);
}

#[test]
fn diffuser_solves_then_drags_on_the_nonlinear_path_keeping_the_tangencies() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("diffuser.json");
    let mut ed = editor("diffuser.json", &out);
    let s0 = state(&mut ed);
    assert_eq!(s0["components"][0]["nonlinear"], true);
    assert_eq!(s0["components"][0]["analysis"]["dof"], 9);
    assert!(
        !w2_valid(ed.sketch(), &DIFFUSER),
        "the file is at its rough start"
    );
    // Drawn as the scene says: the B-spline sampled, three circles with radius.
    let kinds: Vec<&str> = s0["scene"]["entities"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e["kind"].as_str().unwrap())
        .collect();
    assert_eq!(kinds, ["bspline", "circle", "circle", "circle"]);
    assert_eq!(s0["scene"]["entities"][1]["radius"], 0.03);
    assert!(
        s0["scene"]["entities"][0]["samples"]
            .as_array()
            .unwrap()
            .len()
            > 100
    );

    let (status, solved) = post(&mut ed, "/api/solve", json!({}));
    assert_eq!(status, 200, "{solved}");
    assert_eq!(solved["report"]["action"], "solve");
    let line = &solved["report"]["components"][0];
    assert!(line["residual"].as_f64().unwrap() < 1e-9, "{line}");
    assert!(line["time_ms"].as_f64().unwrap() > 0.0);
    assert!(w2_valid(ed.sketch(), &DIFFUSER));

    // Drag the control point over the thickness circle upwards: the curve stays tangent to
    // all three circles at every step, as the answers draw it.
    let (status, started) = post(&mut ed, "/api/drag/start", json!({"entity": 0, "index": 3}));
    assert_eq!(status, 200, "{started}");
    assert_eq!(started["linear"], false);
    let mut client = ed.sketch().clone();
    let p = client.point(PointRef::Control(EntityId(0), 3)).unwrap();
    for k in 1..=6 {
        let target = p + Vector2::new(0.001 * f64::from(k), 0.003 * f64::from(k));
        let (status, moved) = post(
            &mut ed,
            "/api/drag/move",
            json!({"to": [target.x, target.y]}),
        );
        assert_eq!(status, 200, "step {k}: {moved}");
        apply(&mut client, &moved);
        assert!((client.point(PointRef::Control(EntityId(0), 3)).unwrap() - target).norm() < 1e-12);
        assert!(w2_valid(&client, &DIFFUSER), "step {k}");
        // The circles are fixed: only the curve is in the answer.
        let ids: Vec<u64> = moved["entities"]
            .as_array()
            .unwrap()
            .iter()
            .map(|e| e["id"].as_u64().unwrap())
            .collect();
        assert_eq!(ids, [0]);
    }
    let (status, ended) = post(&mut ed, "/api/drag/end", json!({}));
    assert_eq!(status, 200, "{ended}");
    assert!(ended["report"]["components"][0]["solver"]
        .as_str()
        .unwrap()
        .contains("Newton"));
    assert_eq!(geometry(ed.sketch()), geometry(&client));
    assert!(w2_valid(ed.sketch(), &DIFFUSER));

    // Round trip through the file.
    assert_eq!(post(&mut ed, "/api/save", json!({})).0, 200);
    let reloaded = camber_sketch::file::from_json(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(geometry(&reloaded), geometry(&client));
    assert!(w2_valid(&reloaded, &DIFFUSER));
}

/// A drag whose target the constraints cannot follow: the answer is 422 with the reason, the
/// session and the state keep the last valid geometry, and ending commits that geometry.
fn refused_move_keeps_the_last_valid_geometry(
    name: &str,
    prepare: &[&str],
    entity: u64,
    index: usize,
    good: Vector2<f64>,
    bad: Point2<f64>,
    reason: &str,
) {
    let dir = tempfile::tempdir().unwrap();
    let mut ed = editor(name, &dir.path().join("out.json"));
    for path in prepare {
        assert_eq!(post(&mut ed, path, json!({})).0, 200);
    }
    let r = PointRef::Control(EntityId(entity), index);
    let p = ed.sketch().point(r).unwrap();
    assert_eq!(
        post(
            &mut ed,
            "/api/drag/start",
            json!({"entity": entity, "index": index})
        )
        .0,
        200
    );
    let target = p + good;
    let (status, moved) = post(
        &mut ed,
        "/api/drag/move",
        json!({"to": [target.x, target.y]}),
    );
    assert_eq!(status, 200, "{moved}");
    let valid = state(&mut ed)["scene"].clone();
    let (status, refused) = post(&mut ed, "/api/drag/move", json!({"to": [bad.x, bad.y]}));
    assert_eq!(status, 422, "{refused}");
    let message = refused["error"].as_str().unwrap();
    assert!(
        message.starts_with("move refused: ") && message.contains(reason),
        "{message}"
    );
    assert_eq!(
        state(&mut ed)["scene"],
        valid,
        "the refused move changed the drawing"
    );
    // The session goes on from the valid state, and ends there.
    let (status, ended) = post(&mut ed, "/api/drag/end", json!({}));
    assert_eq!(status, 200, "{ended}");
    assert_eq!(ended["scene"], valid);
    assert!((ed.sketch().point(r).unwrap() - target).norm() < 1e-12);
    assert!(
        ended["report"]["summary"]
            .as_str()
            .unwrap()
            .contains("1 refused"),
        "{ended}"
    );
}

#[test]
fn a_move_that_would_flip_a_tangent_is_refused() {
    // The leading edge's second control point pulled back past the joint along the G1
    // direction: the tangent would reverse.
    refused_move_keeps_the_last_valid_geometry(
        "blade_section.json",
        &[],
        1,
        1,
        Vector2::new(0.0, 0.002),
        Point2::new(0.05 + 0.3, -0.03 - 0.045),
        "flip",
    );
}

/// Issue 13: a point held on a circle (the diffuser's first point, tangent to the
/// leading-edge circle at u = 0) follows the mouse along the circle instead of refusing a
/// target off it: it goes to the target's projection along its freedom, and stays tangent.
#[test]
fn a_point_on_a_tangent_circle_slides_along_it() {
    let dir = tempfile::tempdir().unwrap();
    let mut ed = editor("diffuser.json", &dir.path().join("out.json"));
    assert_eq!(post(&mut ed, "/api/solve", json!({})).0, 200);
    let r = PointRef::Control(EntityId(0), 0);
    let p = ed.sketch().point(r).unwrap();
    assert_eq!(
        post(&mut ed, "/api/drag/start", json!({"entity": 0, "index": 0})).0,
        200
    );
    // Off the circle, a little along its tangent at p.
    let (c, radius) = (Point2::new(0.03, 0.0), 0.03);
    let n = (p - c) / (p - c).norm();
    let target = p + Vector2::new(-n.y, n.x) * 0.004 + n * 0.01;
    let (status, moved) = post(
        &mut ed,
        "/api/drag/move",
        json!({"to": [target.x, target.y]}),
    );
    assert_eq!(status, 200, "{moved}");
    let (status, ended) = post(&mut ed, "/api/drag/end", json!({}));
    assert_eq!(status, 200, "{ended}");
    let q = ed.sketch().point(r).unwrap();
    assert!(
        ((q - c).norm() - radius).abs() < 1e-9,
        "off the circle: {q}"
    );
    assert!((q - p).norm() > 1e-3, "it did not slide: {q} {p}");
    assert!(w2_valid(ed.sketch(), &DIFFUSER));
}

#[test]
fn bad_requests_get_plain_4xx_answers_and_change_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let mut ed = editor("blade_section.json", &dir.path().join("out.json"));
    let original = geometry(ed.sketch());
    let cases: [(&str, &str, &[u8], u16, &str); 14] = [
        (
            "POST",
            "/api/drag/move",
            br#"{"to": [0, 0]}"#,
            409,
            "no drag in progress",
        ),
        ("POST", "/api/drag/end", b"{}", 409, "no drag in progress"),
        (
            "POST",
            "/api/drag/start",
            b"{\"entity\": 1,",
            400,
            "bad request body",
        ),
        (
            "POST",
            "/api/drag/start",
            br#"{"entity": 1}"#,
            400,
            "missing field `index`",
        ),
        (
            "POST",
            "/api/drag/start",
            br#"{"entity": 1, "index": 0, "x": 2}"#,
            400,
            "unknown field `x`",
        ),
        (
            "POST",
            "/api/drag/start",
            br#"{"entity": 99, "index": 0}"#,
            404,
            "entity 99 does not exist",
        ),
        (
            "POST",
            "/api/drag/start",
            br#"{"entity": 1, "index": 6}"#,
            404,
            "index 6 does not exist",
        ),
        (
            "POST",
            "/api/drag/start",
            br#"{"entity": 3, "index": 0}"#,
            422,
            "cannot be dragged",
        ),
        ("POST", "/api/undo", b"{}", 409, "nothing to undo"),
        (
            "GET",
            "/api/solve",
            b"",
            405,
            "GET is not allowed on /api/solve",
        ),
        ("DELETE", "/api/state", b"", 405, "not allowed"),
        ("GET", "/nope", b"", 404, "no such page: /nope"),
        ("GET", "/../Cargo.toml", b"", 404, "no such page"),
        (
            "POST",
            "/api/drag/move",
            br#"{"to": [1e999, 0]}"#,
            400,
            "bad request body",
        ),
    ];
    for (method, path, body, status, fragment) in cases {
        let r = ed.handle(method, path, body);
        let text = r.text();
        assert_eq!(r.status, status, "{method} {path}: {text}");
        let v: Value = serde_json::from_str(&text).unwrap();
        let message = v["error"].as_str().unwrap();
        assert!(
            message.contains(fragment) && !message.contains('\n'),
            "{method} {path}: {message}"
        );
    }
    // During a drag: a second start, a solve, a save and an undo are refused; a bad target
    // is refused without ending the drag.
    assert_eq!(
        post(&mut ed, "/api/drag/start", json!({"entity": 0, "index": 2})).0,
        200
    );
    for path in ["/api/drag/start", "/api/solve", "/api/save", "/api/undo"] {
        let (status, v) = post(&mut ed, path, json!({"entity": 1, "index": 2}));
        assert_eq!(status, 409, "{path}: {v}");
        assert!(v["error"]
            .as_str()
            .unwrap()
            .contains("end or cancel it first"));
    }
    assert_eq!(post(&mut ed, "/api/drag/move", json!({"to": "up"})).0, 400);
    let r = ed.handle("POST", "/api/drag/move", br#"{"x": 1}"#);
    assert_eq!(
        (r.status, r.text()),
        (
            400,
            r#"{"error":"bad request body: unknown field `x`, expected `to` at line 1 column 4"}"#
                .to_owned()
        )
    );
    let (status, cancelled) = post(&mut ed, "/api/drag/cancel", json!({}));
    assert_eq!(status, 200);
    assert_eq!(cancelled["dragging"], Value::Null);
    assert_eq!(cancelled["unsaved"], false);
    assert_eq!(geometry(ed.sketch()), original);
    assert!(!dir.path().join("out.json").exists());
}

#[test]
fn large_components_are_analysed_and_drag() {
    // A chain of 1,000 segments (beyond the 200 entities the editor once analysed densely):
    // the state carries its (sparse) DOF analysis, a drag starts at once (the library goes
    // straight to the sparse factorization) and keeps the chain's joints.
    let n = 1_000;
    let (sketch, segments) = camber_workloads::w3a_chain(n).unwrap();
    let mut ed = EditorState::new(sketch, "chain.json".into(), None).unwrap();
    let s = state(&mut ed);
    let analysis = &s["components"][0]["analysis"];
    assert!(analysis["dof"].as_u64().unwrap() > 0, "{analysis}");
    // What is free is named per entity (the chain's inner control points, say).
    assert!(
        !analysis["free"].as_array().unwrap().is_empty(),
        "{analysis}"
    );
    assert_eq!(analysis["conflicting"], json!([]));
    let (status, v) = post(
        &mut ed,
        "/api/drag/start",
        json!({"entity": segments[n / 2].0, "index": 1}),
    );
    assert_eq!(status, 200, "{v}");
    let p = ed
        .sketch()
        .point(camber_sketch::PointRef::Control(segments[n / 2], 1))
        .unwrap();
    let (status, v) = post(&mut ed, "/api/drag/move", json!({"to": [p.x, p.y + 0.02]}));
    assert_eq!(status, 200, "{v}");
    let (status, v) = post(&mut ed, "/api/drag/end", json!({}));
    assert_eq!(status, 200, "{v}");
    let moved = ed
        .sketch()
        .point(camber_sketch::PointRef::Control(segments[n / 2], 1))
        .unwrap();
    assert!((moved.y - (p.y + 0.02)).abs() < 1e-9);
    assert!(
        state(&mut ed)["components"][0]["residual"]
            .as_f64()
            .unwrap()
            < 1e-9
    );
}

#[test]
fn conflicting_constraints_are_named_and_their_glyphs_are_red() {
    let text = r#"{"version": 1,
      "entities": [{"id": 0, "kind": "bezier", "control_points": [[0, 0], [1, 1], [2, 0]]}],
      "constraints": [
        {"id": 1, "kind": "point_at_parameter", "curve": 0, "u": 0.5, "target": {"at": [1, 1]}},
        {"id": 2, "kind": "point_at_parameter", "curve": 0, "u": 0.5, "target": {"at": [1, 2]}}]}"#;
    let sketch = camber_cli::sketch_file::parse(text).unwrap();
    let mut ed = EditorState::new(sketch, "conflict.json".into(), None).unwrap();
    let s = state(&mut ed);
    let a = &s["components"][0]["analysis"];
    assert_eq!(
        a["conflicting"],
        json!([{"id": 2, "kind": "point at parameter"}])
    );
    let red: Vec<(u64, bool)> = s["scene"]["glyphs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|g| {
            (
                g["constraint"].as_u64().unwrap(),
                g["conflicting"].as_bool().unwrap(),
            )
        })
        .collect();
    assert_eq!(red, [(1, false), (1, false), (2, true), (2, true)]);
    // Solving fails plainly and leaves the sketch as it was.
    let before = geometry(ed.sketch());
    let (status, v) = post(&mut ed, "/api/solve", json!({}));
    assert_eq!(status, 422);
    assert!(
        v["error"].as_str().unwrap().starts_with(
            "solve failed: conflicting constraints: constraint 2 (point at parameter)"
        ),
        "{v}"
    );
    assert_eq!(geometry(ed.sketch()), before);
    // So does a drag on the conflicting component.
    let (status, v) = post(&mut ed, "/api/drag/start", json!({"entity": 0, "index": 0}));
    assert_eq!(status, 422, "{v}");
}

#[test]
fn the_page_and_its_assets_are_served() {
    let dir = tempfile::tempdir().unwrap();
    let mut ed = editor("two_curves.json", &dir.path().join("out.json"));
    for (path, kind, needle) in [
        ("/", "text/html", r#"<script src="/editor.js">"#),
        ("/index.html", "text/html", "<svg id=\"canvas\""),
        ("/editor.js?v=1", "text/javascript", "/api/drag/move"),
        ("/editor.css", "text/css", ".glyph.conflict"),
        // The sketcher's three scripts, joined: the model, the tools, the view.
        ("/sketcher.js", "text/javascript", "/api/create"),
        ("/sketcher.js?v=2", "text/javascript", "/api/fillet"),
        ("/sketcher.js", "text/javascript", "/api/dimension"),
    ] {
        let r = ed.handle("GET", path, b"");
        assert_eq!(r.status, 200, "{path}");
        assert!(
            r.content_type.starts_with(kind),
            "{path}: {}",
            r.content_type
        );
        assert!(r.text().contains(needle), "{path}");
    }
    assert_eq!(ed.handle("POST", "/sketcher.js", b"{}").status, 405);
    assert_eq!(ed.handle("GET", "/sketcher-tools.js", b"").status, 404);
    // The two-curve sketch: lines, circles, and a glyph for every contact.
    let s = state(&mut ed);
    let glyph_owners: std::collections::BTreeSet<u64> = s["scene"]["glyphs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|g| g["constraint"].as_u64().unwrap())
        .collect();
    assert_eq!(glyph_owners, (6..=14).collect());
}

/// Prints the time per drag update through the handler (request body in, JSON out) on the
/// blade section and the diffuser. A measurement, not a test: run it in release mode with
/// `cargo test --release -p camber-cli --test editor -- --ignored --nocapture`.
#[test]
#[ignore = "a timing run; see the doc comment"]
fn drag_round_trip_times() {
    let dir = tempfile::tempdir().unwrap();
    for (name, index, prepare) in [("blade_section.json", 2, false), ("diffuser.json", 3, true)] {
        let mut ed = editor(name, &dir.path().join("out.json"));
        if prepare {
            assert_eq!(post(&mut ed, "/api/solve", json!({})).0, 200);
        }
        let entity = u64::from(name == "blade_section.json");
        let p = ed
            .sketch()
            .point(PointRef::Control(EntityId(entity), index))
            .unwrap();
        assert_eq!(
            post(
                &mut ed,
                "/api/drag/start",
                json!({"entity": entity, "index": index})
            )
            .0,
            200
        );
        let mut total = Vec::new();
        let mut solver = Vec::new();
        let mut bytes = 0;
        for k in 0..400 {
            let th = std::f64::consts::TAU * f64::from(k) / 400.0;
            let t = p + 0.004 * Vector2::new(th.cos() - 1.0, th.sin());
            let body = format!(r#"{{"to": [{}, {}]}}"#, t.x, t.y);
            let start = std::time::Instant::now();
            let r = ed.handle("POST", "/api/drag/move", body.as_bytes());
            total.push(start.elapsed().as_secs_f64() * 1e6);
            assert_eq!(r.status, 200, "{}", r.text());
            let v: Value = serde_json::from_slice(&r.body).unwrap();
            solver.push(v["update_us"].as_f64().unwrap());
            bytes = r.body.len();
        }
        total.sort_by(f64::total_cmp);
        solver.sort_by(f64::total_cmp);
        println!(
            "{name}: median {:.1} µs per request through the handler ({:.1} µs in DragSession::update), {bytes} bytes per answer",
            total[total.len() / 2],
            solver[solver.len() / 2]
        );
    }
}

/// Issue 11, finding 1: the editor's Solve on a cubic touching 7 fixed circles at free
/// contact parameters aborted the whole editor (NLopt's SLSQP given more equality rows than
/// unknowns), losing unsaved work. It now answers, and the editor goes on serving.
#[test]
fn solve_with_seven_contacts_answers_and_the_editor_survives() {
    use camber_sketch::{CircleSide, Contact, Rotation};
    let mut s = Sketch::new();
    let curve = s
        .add_bezier(
            camber_geom::BezierCurve2::try_new(vec![
                Point2::new(0.0, 0.0),
                Point2::new(1.0, 1.5),
                Point2::new(2.0, 1.5),
                Point2::new(3.0, 0.0),
            ])
            .unwrap(),
        )
        .unwrap();
    for i in 0..7 {
        let c = s
            .add_circle(Point2::new(0.3 + 0.4 * f64::from(i), 1.5), 0.3)
            .unwrap();
        s.add_constraint(Fixed::entity(c)).unwrap();
        s.add_constraint(TangentToCircle {
            curve,
            circle: c,
            u: Contact::Free((f64::from(i) + 0.5) / 7.0),
            side: CircleSide::Outside,
            rotation: Rotation::Clockwise,
        })
        .unwrap();
    }
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("seven.json");
    std::fs::write(&input, camber_sketch::file::to_json(&s).unwrap()).unwrap();
    let mut ed = EditorState::load(&input, Some(dir.path().join("out.json"))).unwrap();
    let (status, solved) = post(&mut ed, "/api/solve", json!({}));
    assert_eq!(status, 200, "{solved}");
    let line = &solved["report"]["components"][0];
    assert!(line["residual"].as_f64().unwrap() < 1e-9, "{line}");
    // Still serving.
    assert_eq!(state(&mut ed)["components"][0]["nonlinear"], true);
}

/// Issue 16: a Hermite curve's tangent is dragged by its handle p1 − t1/3. The answer draws the
/// handle where it was pulled, the tangent block underneath is −3·(handle − p1), and the
/// constraints on the curve (its pinned end, the end tangent's direction) still hold.
#[test]
fn a_hermite_tangent_is_dragged_by_its_handle() {
    let dir = tempfile::tempdir().unwrap();
    let mut ed = editor("hermite_composite.json", &dir.path().join("out.json"));
    assert_eq!(post(&mut ed, "/api/solve", json!({})).0, 200);
    let solved = ed.sketch().clone();
    let scene = state(&mut ed);
    let drawn = scene["scene"]["entities"]
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e["id"] == 1)
        .unwrap()
        .clone();
    assert_eq!(drawn["kind"], "hermite");
    let Entity::Hermite(h) = solved.entity(EntityId(1)).unwrap() else {
        panic!("entity 1 is a Hermite curve");
    };
    let handle = point(&drawn["points"][3]);
    assert!((handle - h.handle(3).unwrap()).norm() < 1e-12);
    assert_eq!(drawn["polygon"].as_array().unwrap().len(), 4);

    let (status, started) = post(&mut ed, "/api/drag/start", json!({"entity": 1, "index": 3}));
    assert_eq!(status, 200, "{started}");
    let target = Point2::new(9.0, 1.6);
    let (status, moved) = post(
        &mut ed,
        "/api/drag/move",
        json!({"to": [target.x, target.y]}),
    );
    assert_eq!(status, 200, "{moved}");
    let mut client = solved.clone();
    apply(&mut client, &moved);
    let e = client.entity(EntityId(1)).unwrap();
    assert!(
        (e.handle(3).unwrap() - target).norm() < 1e-9,
        "{:?}",
        e.handle(3)
    );
    let (p1, t1) = e.point_tangent(1.0).unwrap();
    assert!((p1 - Point2::new(9.0, 0.5)).norm() < 1e-9);
    assert!(t1.x.abs() < 1e-9 && (t1.y + 3.3).abs() < 1e-9, "{t1}");
    assert_eq!(post(&mut ed, "/api/drag/end", json!({})).0, 200);
    let committed = ed.sketch().entity(EntityId(1)).unwrap();
    assert!((committed.handle(3).unwrap() - target).norm() < 1e-9);
}

/// Each constraint's max |g| in the component of `entity`, computed afresh from `sketch` (the
/// component's own problem, no drag session involved).
fn fresh_residuals(sketch: &Sketch, entity: u64) -> std::collections::BTreeMap<u64, f64> {
    let cp = sketch.component_problem(EntityId(entity)).unwrap();
    let lin = cp.problem().linearize().unwrap();
    let mut out = std::collections::BTreeMap::new();
    for (owner, g) in lin.row_owner.iter().zip(&lin.g) {
        let slot = out.entry(owner.0).or_insert(0.0_f64);
        *slot = slot.max(g.abs());
    }
    out
}

/// The residuals a drag/move answer carries, checked against `fresh` (largest, its owner, each
/// constraint).
fn assert_move_residuals(moved: &Value, fresh: &std::collections::BTreeMap<u64, f64>) {
    let sent: std::collections::BTreeMap<u64, f64> = moved["constraint_residuals"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| (c["id"].as_u64().unwrap(), c["residual"].as_f64().unwrap()))
        .collect();
    assert_eq!(
        sent.keys().collect::<Vec<_>>(),
        fresh.keys().collect::<Vec<_>>()
    );
    for (id, r) in &sent {
        assert!(
            (r - fresh[id]).abs() <= 1e-12,
            "constraint {id}: {r} vs {}",
            fresh[id]
        );
    }
    let largest = fresh.values().fold(0.0_f64, |m, r| m.max(*r));
    let residual = moved["residual"].as_f64().unwrap();
    assert!(
        (residual - largest).abs() <= 1e-12,
        "{residual} vs {largest}"
    );
    if largest > 0.0 {
        let worst = moved["worst"]["id"].as_u64().unwrap();
        assert!(
            sent[&worst].to_bits() == residual.to_bits(),
            "worst {worst}"
        );
    }
}

#[test]
fn every_move_answer_carries_the_residuals_of_the_geometry_it_draws() {
    let dir = tempfile::tempdir().unwrap();
    // Affine path: the blade starts with its trailing-edge join open (residual > 1e-4); the
    // first move closes it, and its answer must say so, not repeat the number from before.
    let mut ed = editor("blade_section.json", &dir.path().join("blade.json"));
    let before = state(&mut ed)["components"][0]["residual"]
        .as_f64()
        .unwrap();
    assert!(before > 1e-4);
    assert_eq!(
        post(&mut ed, "/api/drag/start", json!({"entity": 1, "index": 2})).0,
        200
    );
    let mut client = ed.sketch().clone();
    let p = client.point(PointRef::Control(EntityId(1), 2)).unwrap();
    let mut last = Value::Null;
    for k in 1..=4 {
        let target = p + Vector2::new(0.002 * f64::from(k), -0.001 * f64::from(k));
        let (status, moved) = post(
            &mut ed,
            "/api/drag/move",
            json!({"to": [target.x, target.y]}),
        );
        assert_eq!(status, 200, "{moved}");
        apply(&mut client, &moved);
        assert_move_residuals(&moved, &fresh_residuals(&client, 1));
        assert!(moved["residual"].as_f64().unwrap() < 1e-9, "{moved}");
        last = moved;
    }
    // Asked for the whole state during the drag, the component shows the drag's residual
    // and its worst constraint, not the open join from before the drag.
    let during = state(&mut ed);
    let component = &during["components"][0];
    assert!(during["dragging"].is_object(), "{during}");
    assert_eq!(
        component["residual"].as_f64().unwrap().to_bits(),
        last["residual"].as_f64().unwrap().to_bits(),
        "{component}"
    );
    assert_eq!(component["worst"], last["worst"], "{component}");
    // Ending commits the same state: the panel's component residual is the last answer's.
    let (status, ended) = post(&mut ed, "/api/drag/end", json!({}));
    assert_eq!(status, 200, "{ended}");
    assert_move_residuals(&last, &fresh_residuals(ed.sketch(), 1));
    let committed = ended["components"][0]["residual"].as_f64().unwrap();
    assert!((committed - last["residual"].as_f64().unwrap()).abs() <= 1e-12);

    // Nonlinear path with free contact parameters (the diffuser's tangencies): the answer's
    // residuals are those of the sketch the drag commits, parameters included.
    let mut ed = editor("diffuser.json", &dir.path().join("diffuser.json"));
    assert_eq!(post(&mut ed, "/api/solve", json!({})).0, 200);
    assert_eq!(
        post(&mut ed, "/api/drag/start", json!({"entity": 0, "index": 3})).0,
        200
    );
    let p = ed
        .sketch()
        .point(PointRef::Control(EntityId(0), 3))
        .unwrap();
    let mut last = Value::Null;
    for k in 1..=3 {
        let target = p + Vector2::new(0.001 * f64::from(k), 0.003 * f64::from(k));
        let (status, moved) = post(
            &mut ed,
            "/api/drag/move",
            json!({"to": [target.x, target.y]}),
        );
        assert_eq!(status, 200, "{moved}");
        last = moved;
    }
    // The three tangencies have rows (the fixed circles are bound, not residual rows).
    assert_eq!(
        last["constraint_residuals"].as_array().unwrap().len(),
        3,
        "{last}"
    );
    let (status, ended) = post(&mut ed, "/api/drag/end", json!({}));
    assert_eq!(status, 200, "{ended}");
    assert_move_residuals(&last, &fresh_residuals(ed.sketch(), 0));
    let committed = ended["components"][0]["residual"].as_f64().unwrap();
    assert!((committed - last["residual"].as_f64().unwrap()).abs() <= 1e-12);
}

/// The glyphs of one constraint in a scene.
fn glyphs_of(scene: &Value, constraint: u64) -> Vec<Value> {
    scene["glyphs"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|g| g["constraint"].as_u64() == Some(constraint))
        .cloned()
        .collect()
}

#[test]
fn expression_constraints_are_drawn_with_their_name_and_live_residual() {
    // The parametric diffuser with the middle circle's radius parameter moved from the
    // circle's 0.07 to 0.08: the "middle circle" rows K.center = [x3, y3], K.radius = r3 are
    // off by exactly 0.01 (the radius row) before a solve.
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(sketch_path("diffuser_parametric.json"))
        .unwrap()
        .replace("\"r3\":0.07", "\"r3\":0.08");
    let input = dir.path().join("diffuser.json");
    std::fs::write(&input, text).unwrap();
    let mut ed = EditorState::load(&input, Some(dir.path().join("out.json"))).unwrap();
    let before = state(&mut ed);
    let middle = glyphs_of(&before["scene"], 4);
    assert_eq!(middle.len(), 1, "{middle:?}");
    assert_eq!(middle[0]["label"], "middle circle");
    let r = middle[0]["residual"].as_f64().unwrap();
    assert!((r - 0.01).abs() < 1e-12, "{r}");
    let leading = glyphs_of(&before["scene"], 2);
    assert_eq!(leading[0]["label"], "leading circle");
    assert!(leading[0]["residual"].as_f64().unwrap() < 1e-15);
    // Built-in kinds carry no label.
    for g in glyphs_of(&before["scene"], 8) {
        assert!(
            g.get("label").is_none() && g.get("residual").is_none(),
            "{g}"
        );
    }
    // Solved, the label's residual is the solved one.
    let (status, solved) = post(&mut ed, "/api/solve", json!({}));
    assert_eq!(status, 200, "{solved}");
    let after = glyphs_of(&solved["scene"], 4);
    assert!(after[0]["residual"].as_f64().unwrap() < 1e-10, "{after:?}");

    // During a drag, the move answer's labelled glyphs carry the residual of the geometry
    // they are drawn on: the answer's own figure for that constraint.
    let text = r#"{"version": 1,
      "entities": [{"id": 0, "kind": "bezier", "control_points": [[0, 0], [1, 1], [2, 0]]}],
      "constraints": [
        {"id": 1, "kind": "fixed", "target": {"point": {"start": 0}}},
        {"id": 2, "kind": "expression", "name": "span", "rows": ["norm(C.end - C.start) = 2"],
         "args": {"C": {"curve": 0}}}]}"#;
    let sketch = camber_cli::sketch_file::parse(text).unwrap();
    let mut ed = EditorState::new(sketch, "span.json".into(), None).unwrap();
    assert_eq!(
        post(&mut ed, "/api/drag/start", json!({"entity": 0, "index": 2})).0,
        200
    );
    let (status, moved) = post(&mut ed, "/api/drag/move", json!({"to": [1.9, 0.5]}));
    assert_eq!(status, 200, "{moved}");
    let span = glyphs_of(&moved, 2);
    assert_eq!(span.len(), 1, "{moved}");
    assert_eq!(span[0]["label"], "span");
    let sent = moved["constraint_residuals"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["id"] == 2)
        .unwrap()["residual"]
        .as_f64()
        .unwrap();
    assert_eq!(
        span[0]["residual"].as_f64().unwrap().to_bits(),
        sent.to_bits()
    );
    // The whole state during the drag shows the same figure.
    let during = state(&mut ed);
    assert_eq!(
        glyphs_of(&during["scene"], 2)[0]["residual"],
        span[0]["residual"]
    );
}

/// The blade with an elliptic leading edge and a circular trailing edge: the page gets each
/// arc as samples along it (on the ellipse's implicit equation, from the start to the end
/// point), and a drag of the leading edge's a-axis vertex keeps both joints of the elliptic
/// arc closed and tangent.
#[test]
fn arcs_and_ellipses_are_drawn_along_themselves_and_drag() {
    let dir = tempfile::tempdir().unwrap();
    let mut ed = editor("blade_arcs.json", &dir.path().join("out.json"));
    assert_eq!(post(&mut ed, "/api/solve", json!({})).0, 200);
    let v = state(&mut ed);
    let mut round = 0;
    for e in v["scene"]["entities"].as_array().unwrap() {
        let kind = e["kind"].as_str().unwrap();
        let id = EntityId(e["id"].as_u64().unwrap());
        let samples: Vec<Point2<f64>> = e["samples"]
            .as_array()
            .map(|a| a.iter().map(point).collect())
            .unwrap_or_default();
        match kind {
            "elliptic_arc" => {
                let arc = ed.sketch().entity(id).unwrap().as_elliptic_arc().unwrap();
                assert_eq!(samples.len(), 65);
                for p in &samples {
                    assert!(arc.ellipse().implicit_value(p).abs() < 1e-12, "{p:?}");
                }
                assert!((samples[0] - arc.start_point()).norm() < 1e-12);
                assert!((samples[64] - arc.end_point()).norm() < 1e-12);
                round += 1;
            }
            "arc" => {
                let arc = ed.sketch().entity(id).unwrap().as_arc().unwrap();
                assert_eq!(samples.len(), 65);
                for p in &samples {
                    assert!(((p - arc.center()).norm() - arc.radius()).abs() < 1e-12);
                }
                round += 1;
            }
            _ => {}
        }
    }
    assert_eq!(round, 2, "the blade has one elliptic and one circular arc");
    // Drag the elliptic arc's vertex (its point 1) a little outwards.
    let le = EntityId(1);
    let vertex = ed.sketch().point(PointRef::Control(le, 1)).unwrap();
    assert_eq!(
        post(&mut ed, "/api/drag/start", json!({"entity": 1, "index": 1})).0,
        200
    );
    for k in 1..=5 {
        let t = vertex + Vector2::new(0.0008, 0.0004) * f64::from(k);
        let (status, answer) = post(&mut ed, "/api/drag/move", json!({"to": [t.x, t.y]}));
        assert_eq!(status, 200, "{answer}");
    }
    assert_eq!(post(&mut ed, "/api/drag/end", json!({})).0, 200);
    let s = ed.sketch();
    let arc = s.entity(le).unwrap().as_elliptic_arc().unwrap();
    assert!((s.point(PointRef::Control(le, 1)).unwrap() - vertex).norm() > 1e-3);
    // Both ends still on the sides, tangent to them (the sides are entities 0 and 2).
    for (end, side, at_end, t_arc) in [
        (
            arc.end_point(),
            EntityId(0),
            true,
            arc.derivative_at(1.0, 1),
        ),
        (
            arc.start_point(),
            EntityId(2),
            false,
            arc.derivative_at(0.0, 1),
        ),
    ] {
        let c = curve(s, side);
        let (lo, hi) = c.domain();
        let u = if at_end { hi } else { lo };
        let (p_side, t_side) = c.point_and_derivative(u).unwrap();
        assert!((p_side - end).norm() < 1e-9);
        let sin = cross(t_arc, t_side) / (t_arc.norm() * t_side.norm());
        assert!(sin.abs() < 1e-9, "the joint at {end:?} turned by {sin}");
    }
}
