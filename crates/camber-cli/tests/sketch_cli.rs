//! The sketch commands end to end: `solve`, `check`, `render` and `demo` on the bundled
//! sketches, SVG output parsed (viewBox, element counts by colour), and bad sketch files
//! failing with one plain line naming the problem and exit code 2.

#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use camber_cli::commands::render::{CONFLICT, GLYPH};
use predicates::prelude::*;

fn sketch(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/sketches")
        .join(name)
}

fn camber() -> Command {
    Command::cargo_bin("camber").expect("the camber binary is built")
}

/// Elements of `tag` whose `attr` is `value`.
fn count(doc: &roxmltree::Document, tag: &str, attr: &str, value: &str) -> usize {
    doc.descendants()
        .filter(|n| n.has_tag_name(tag) && n.attribute(attr) == Some(value))
        .count()
}

fn view_box(doc: &roxmltree::Document) -> Vec<f64> {
    doc.root_element()
        .attribute("viewBox")
        .unwrap()
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect()
}

/// The blade picture: four curves, four G1 arrows (a shaft and a head each), two fixed marks.
fn check_blade_svg(text: &str) {
    let doc = roxmltree::Document::parse(text).unwrap();
    let vb = view_box(&doc);
    assert_eq!(vb.len(), 4);
    assert!(vb[2] > 0.0 && vb[3] > 0.0);
    assert_eq!(count(&doc, "polyline", "stroke", "#2471a3"), 4);
    assert_eq!(count(&doc, "line", "stroke", GLYPH), 4);
    assert_eq!(count(&doc, "polyline", "stroke", GLYPH), 4);
    assert_eq!(count(&doc, "polyline", "fill", GLYPH), 2);
    assert_eq!(count(&doc, "line", "stroke", CONFLICT), 0);
}

#[test]
fn demo_solves_the_blade_and_writes_its_picture() {
    let dir = tempfile::tempdir().unwrap();
    camber()
        .current_dir(dir.path())
        .arg("demo")
        .assert()
        .success()
        .stdout(predicate::str::contains(
            "component 1 (entities 0, 1, 2, 3)",
        ))
        .stdout(predicate::str::contains("DOF 24"))
        .stdout(predicate::str::contains("residual"));
    let text = std::fs::read_to_string(dir.path().join("blade_section.svg")).unwrap();
    check_blade_svg(&text);
    // The combs are on in the demo.
    let doc = roxmltree::Document::parse(&text).unwrap();
    assert!(count(&doc, "line", "stroke", "#9b59b6") >= 4 * 13);
    // -o picks the directory.
    let other = dir.path().join("out");
    std::fs::create_dir(&other).unwrap();
    camber().args(["demo", "-o"]).arg(&other).assert().success();
    assert!(other.join("blade_section.svg").exists());
}

#[test]
fn solve_by_displacement_says_when_there_is_nothing_to_displace() {
    // The blade section has no curve touching a fixed circle or line: no round runs, and the
    // line says why instead of calling it a stall.
    let dir = tempfile::tempdir().unwrap();
    camber()
        .arg("solve")
        .arg(sketch("blade_section.json"))
        .arg("--displacement")
        .arg("-o")
        .arg(dir.path().join("solved.json"))
        .assert()
        .success()
        .stdout(predicate::str::contains(
            "iterative displacement: 0 round(s), no contacts with fixed circles or lines",
        ))
        .stdout(predicate::str::contains("stalled").not());
}

#[test]
fn solve_by_displacement_reports_its_rounds_and_writes_a_valid_diffuser() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("solved.json");
    camber()
        .arg("solve")
        .arg(sketch("diffuser.json"))
        .arg("--displacement")
        .arg("-o")
        .arg(&out)
        .assert()
        .success()
        .stdout(predicate::str::is_match("iterative displacement: [0-9]+ round\\(s\\), ").unwrap());
    // The written sketch holds every constraint: solving it again changes nothing.
    let mut after =
        camber_sketch::file::from_json(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let report = after.solve_all().unwrap();
    for c in &report.components {
        for r in &c.report.residuals {
            assert!(r.max_abs < 1e-9, "{r:?}");
        }
    }
}

#[test]
fn solve_writes_a_solved_file_with_the_same_ids_and_a_report() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("solved.json");
    let pic = dir.path().join("solved.svg");
    camber()
        .arg("solve")
        .arg(sketch("blade_section.json"))
        .arg("-o")
        .arg(&out)
        .arg("--svg")
        .arg(&pic)
        .assert()
        .success()
        .stdout(
            predicate::str::is_match("solver \\w+, DOF 24, residual [0-9.e+-]+, time [0-9.]+ ms")
                .unwrap(),
        );
    let before = camber_sketch::file::from_json(
        &std::fs::read_to_string(sketch("blade_section.json")).unwrap(),
    )
    .unwrap();
    let mut after =
        camber_sketch::file::from_json(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let ids = |s: &camber_sketch::Sketch| {
        (
            s.entities().map(|(id, _)| id).collect::<Vec<_>>(),
            s.constraints().map(|(id, _)| id).collect::<Vec<_>>(),
        )
    };
    assert_eq!(ids(&before), ids(&after));
    // Already solved: solving again moves nothing measurable and leaves no residual.
    let report = after.solve_all().unwrap();
    for r in &report.components[0].report.residuals {
        assert!(r.max_abs < 1e-12);
    }
    check_blade_svg(&std::fs::read_to_string(&pic).unwrap());
}

#[test]
fn solve_handles_the_large_chain() {
    let dir = tempfile::tempdir().unwrap();
    camber()
        .arg("solve")
        .arg(sketch("w3a_chain_1000.json"))
        .arg("-o")
        .arg(dir.path().join("chain.json"))
        .assert()
        .success()
        .stdout(predicate::str::contains("1000 entities: 0, 1, 2, …, 999"));
}

const CONFLICTING: &str = r#"{"version": 1,
  "entities": [{"id": 0, "kind": "bezier", "control_points": [[0, 0], [1, 1], [2, 0]]}],
  "constraints": [
    {"id": 1, "kind": "point_at_parameter", "curve": 0, "u": 0.5, "target": {"at": [1, 1]}},
    {"id": 2, "kind": "point_at_parameter", "curve": 0, "u": 0.5, "target": {"at": [1, 2]}}
  ]}"#;

#[test]
fn check_reports_dof_and_names_conflicts() {
    camber()
        .arg("check")
        .arg(sketch("blade_section.json"))
        .assert()
        .success()
        .stdout(predicate::str::contains("32 free unknowns, rank 8, DOF 24"))
        .stdout(predicate::str::contains("conflicting: none"));
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("conflict.json");
    std::fs::write(&bad, CONFLICTING).unwrap();
    camber()
        .arg("check")
        .arg(&bad)
        .assert()
        .success()
        .stdout(predicate::str::contains(
            "conflicting: constraint 2 (point at parameter)",
        ));
    // Solving it fails plainly, and writes nothing.
    let out = dir.path().join("out.json");
    camber()
        .arg("solve")
        .arg(&bad)
        .arg("-o")
        .arg(&out)
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "solve failed: conflicting constraints: constraint 2 (point at parameter)",
        ));
    assert!(!out.exists());
}

#[test]
fn render_draws_conflicts_in_red_and_optional_combs() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("conflict.json");
    std::fs::write(&bad, CONFLICTING).unwrap();
    let pic = dir.path().join("c.svg");
    camber()
        .arg("render")
        .arg(&bad)
        .arg("-o")
        .arg(&pic)
        .assert()
        .success();
    let text = std::fs::read_to_string(&pic).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    // Constraint 2's two rings are red, constraint 1's two are green.
    assert_eq!(count(&doc, "circle", "stroke", CONFLICT), 2);
    assert_eq!(count(&doc, "circle", "stroke", GLYPH), 2);
    assert_eq!(count(&doc, "line", "stroke", "#9b59b6"), 0);
    camber()
        .arg("render")
        .arg(sketch("blade_section.json"))
        .arg("-o")
        .arg(&pic)
        .arg("--combs")
        .assert()
        .success();
    let text = std::fs::read_to_string(&pic).unwrap();
    check_blade_svg(&text);
    let doc = roxmltree::Document::parse(&text).unwrap();
    assert!(count(&doc, "line", "stroke", "#9b59b6") >= 4 * 13);
}

/// Each bad file, and a fragment its one-line message must contain.
const BAD: [(&str, &str, &str); 6] = [
    (
        "malformed.json",
        r#"{"version": 1, "entities": ["#,
        "invalid JSON",
    ),
    (
        "unknown_id.json",
        r#"{"version": 1, "entities": [{"id": 0, "kind": "bezier", "control_points": [[0, 0], [1, 0]]}],
           "constraints": [{"id": 5, "kind": "g1_join", "first": 0, "second": 9, "direction": [1, 0]}]}"#,
        "constraint 5 (g1_join): entity 9 does not exist",
    ),
    (
        "non_finite.json",
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [1e999, 0]}]}"#,
        "non-finite number",
    ),
    (
        "knot_count.json",
        r#"{"version": 1, "entities": [{"id": 3, "kind": "bspline", "degree": 2, "knots": [0, 0, 0, 1, 1],
            "control_points": [[0, 0], [1, 1], [2, 0]]}]}"#,
        "entity 3 (bspline): geometry:",
    ),
    (
        "wrong_type.json",
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0, "y"]}]}"#,
        "at entities[0].at[1]: invalid type: string \"y\", expected a number",
    ),
    (
        "null.json",
        "null",
        "expected a sketch: an object with \"version\", \"entities\" and \"constraints\", found null",
    ),
];

#[test]
fn bad_files_fail_with_one_plain_line_and_code_2() {
    let dir = tempfile::tempdir().unwrap();
    for (name, text, expected) in BAD {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        let pic = dir.path().join("x.svg");
        let out = dir.path().join("x.json");
        let runs: [Vec<std::ffi::OsString>; 3] = [
            vec!["solve".into(), path.clone().into(), "-o".into(), out.into()],
            vec!["check".into(), path.clone().into()],
            vec![
                "render".into(),
                path.clone().into(),
                "-o".into(),
                pic.into(),
            ],
        ];
        for args in runs {
            let assert = camber().args(&args).assert().code(2);
            let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
            assert_eq!(stderr.lines().count(), 1, "{stderr}");
            assert!(
                stderr.starts_with("error: ") && stderr.contains(name) && stderr.contains(expected),
                "{name}: {stderr}"
            );
        }
    }
}

#[test]
fn render_draws_points_lines_circles_and_their_glyphs() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("prims.json");
    std::fs::write(
        &file,
        r#"{"version": 1,
  "entities": [{"id": 0, "kind": "point", "at": [0, 2]},
               {"id": 1, "kind": "line", "from": [0, 0], "to": [2, 1]},
               {"id": 2, "kind": "circle", "center": [3, 3], "radius": 0.5}],
  "constraints": [{"id": 3, "kind": "fixed", "target": {"entity": 2}},
                  {"id": 4, "kind": "coincident", "a": {"point": 0}, "b": {"control": [1, 0]}}]}"#,
    )
    .unwrap();
    let pic = dir.path().join("prims.svg");
    camber()
        .arg("render")
        .arg(&file)
        .arg("-o")
        .arg(&pic)
        .assert()
        .success();
    let text = std::fs::read_to_string(&pic).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let curve = camber_cli::commands::render::CURVE;
    let point = camber_cli::commands::render::POINT;
    assert_eq!(count(&doc, "line", "stroke", curve), 1);
    assert_eq!(count(&doc, "circle", "stroke", curve), 1);
    assert_eq!(count(&doc, "circle", "fill", point), 1);
    assert_eq!(count(&doc, "polyline", "fill", GLYPH), 1);
    assert_eq!(count(&doc, "circle", "stroke", GLYPH), 2);
    // The box holds the whole circle: its right edge x = 3.5 lies inside the viewBox.
    let vb = view_box(&doc);
    let scale = 400.0 / 3.5; // the larger side of the box is 3.5 (x from 0 to 3.5)
    assert!(vb[0] + vb[2] > 3.5 * scale);
}

#[test]
fn every_bundled_sketch_solves_and_draws_from_the_command_line() {
    let dir = tempfile::tempdir().unwrap();
    let curve = camber_cli::commands::render::CURVE;
    // (file, curves drawn as polylines, lines, circles)
    let expected = [
        ("blade_section.json", 4, 0, 0),
        ("diffuser.json", 1, 0, 3),
        ("two_curves.json", 2, 2, 2),
        ("w3a_chain_1000.json", 1000, 0, 0),
    ];
    for (name, curves, lines, circles) in expected {
        let out = dir.path().join(name);
        let pic = dir.path().join(format!("{name}.svg"));
        camber()
            .arg("solve")
            .arg(sketch(name))
            .arg("-o")
            .arg(&out)
            .arg("--svg")
            .arg(&pic)
            .assert()
            .success()
            .stdout(predicate::str::contains("component 1"))
            .stdout(predicate::str::contains("wrote"));
        // The solved file loads, and solving it again leaves nothing to move.
        let mut solved =
            camber_sketch::file::from_json(&std::fs::read_to_string(&out).unwrap()).unwrap();
        for c in solved.solve_all().unwrap().components {
            for r in &c.report.residuals {
                assert!(r.max_abs < 1e-9, "{name}: {r:?}");
            }
        }
        let text = std::fs::read_to_string(&pic).unwrap();
        let doc = roxmltree::Document::parse(&text).unwrap();
        let vb = view_box(&doc);
        assert!(
            vb.len() == 4 && vb[2] > 0.0 && vb[3] > 0.0,
            "{name}: {vb:?}"
        );
        assert_eq!(count(&doc, "polyline", "stroke", curve), curves, "{name}");
        assert_eq!(count(&doc, "line", "stroke", curve), lines, "{name}");
        assert_eq!(count(&doc, "circle", "stroke", curve), circles, "{name}");
        assert_eq!(count(&doc, "line", "stroke", CONFLICT), 0, "{name}");
    }
}

/// Issue 16: the bundled Hermite/composite sketch solves, and its picture draws both curves
/// with their Bézier polygons — nodes and tangent handles (3n + 1 points for n segments), not
/// the tangent vectors read as positions.
#[test]
fn hermite_and_composite_curves_solve_and_render() {
    let dir = tempfile::tempdir().unwrap();
    let solved = dir.path().join("solved.json");
    camber()
        .arg("solve")
        .arg(sketch("hermite_composite.json"))
        .arg("-o")
        .arg(&solved)
        .assert()
        .success();
    let svg = dir.path().join("hc.svg");
    camber()
        .arg("render")
        .arg(&solved)
        .arg("-o")
        .arg(&svg)
        .assert()
        .success();
    let text = std::fs::read_to_string(&svg).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    assert_eq!(count(&doc, "polyline", "stroke", "#2471a3"), 2);
    let mut polygons: Vec<usize> = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke-dasharray").is_some())
        .map(|n| n.attribute("points").unwrap().split_whitespace().count())
        .collect();
    polygons.sort_unstable();
    assert_eq!(polygons, vec![4, 10]);
}

#[test]
fn solve_names_every_constraint_a_priority_let_go() {
    // examples/sketches/priorities.json: C(½) wanted at (1.5, 1) (priority 1) and at (1.5, 2)
    // (priority 2), C(¼) at (0.5, 1) (priority 2). The first and the last can be met together;
    // the second cannot and is the one named.
    let out = tempfile::tempdir().unwrap();
    let solved = out.path().join("solved.json");
    camber()
        .args(["solve"])
        .arg(sketch("priorities.json"))
        .arg("-o")
        .arg(&solved)
        .assert()
        .success()
        .stdout(predicate::str::contains("solver prioritized"))
        .stdout(predicate::str::contains("priority 1: met"))
        .stdout(predicate::str::contains(
            "priority 2: relaxed constraint 4 (residual 1.000e0)\n",
        ));
    // The priorities are kept in the written file, and the JSON report carries the tiers.
    let text = std::fs::read_to_string(&solved).unwrap();
    assert!(text.contains(r#""id":4,"priority":2"#), "{text}");
    let json = camber()
        .args(["solve", "--json"])
        .arg(sketch("priorities.json"))
        .arg("-o")
        .arg(out.path().join("again.json"))
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let v: serde_json::Value = serde_json::from_slice(&json).unwrap();
    let report = &v["components"][0]["report"];
    assert_eq!(report["status"], "relaxed");
    assert_eq!(report["priorities"][2]["relaxed"], serde_json::json!([4]));
}

#[test]
fn the_input_size_limit_is_a_default_that_can_be_raised() {
    // A valid sketch of 2 MiB (whitespace pads it): read by default, refused under a 1 MiB
    // limit with a message that names the limit and the option, read again when raised.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("padded.json");
    let text = format!(
        "{{\"version\": 1, \"entities\": [{{\"id\": 0, \"kind\": \"point\", \"at\": [0, 0]}}]{}}}",
        " ".repeat(2 << 20)
    );
    std::fs::write(&path, text).unwrap();
    camber().arg("check").arg(&path).assert().success();
    let assert = camber()
        .args(["--max-input-mib", "1", "check"])
        .arg(&path)
        .assert()
        .code(2);
    let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
    assert!(
        stderr.contains("larger than 1 MiB") && stderr.contains("--max-input-mib"),
        "{stderr}"
    );
    // The option is global: after the subcommand too.
    camber()
        .arg("check")
        .arg(&path)
        .args(["--max-input-mib", "3"])
        .assert()
        .success();
    // Out of range values are usage errors.
    for bad in ["0", "1048577", "-1", "x"] {
        camber()
            .args(["--max-input-mib", bad, "check"])
            .arg(&path)
            .assert()
            .code(2);
    }
}

#[cfg(unix)]
#[test]
fn a_raised_input_limit_reads_beyond_64_mib() {
    // 65 MiB of whitespace around a one-point sketch: the default refuses it, 100 MiB reads it.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("big.json");
    let text = format!(
        "{{\"version\": 1, \"entities\": [{{\"id\": 0, \"kind\": \"point\", \"at\": [0, 0]}}]{}}}",
        " ".repeat(65 << 20)
    );
    std::fs::write(&path, text).unwrap();
    let assert = camber().arg("check").arg(&path).assert().code(2);
    let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
    assert!(stderr.contains("larger than 64 MiB"), "{stderr}");
    camber()
        .args(["--max-input-mib", "100", "check"])
        .arg(&path)
        .assert()
        .success()
        .stdout(predicate::str::contains(
            "component 1 (entity 0; no constraints)",
        ));
}
