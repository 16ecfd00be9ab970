//! Nothing a user types or gives camber crashes it, hangs it, prints a NaN as a result or
//! damages a file. One test (or more) per kind of hostile input, each run through the binary.

#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

use std::path::{Path, PathBuf};
use std::time::Duration;

use assert_cmd::Command;

fn camber() -> Command {
    let mut cmd = Command::cargo_bin("camber").expect("the camber binary is built");
    // No command here may run long: a hang is a failure, not a stuck CI job.
    cmd.timeout(Duration::from_secs(60));
    cmd
}

fn sketch(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/sketches")
        .join(name)
}

/// Writes `text` to `name` in `dir` and returns the path.
fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// Runs a command that must fail with code 2 and one plain line on stderr; returns the line.
fn failure(cmd: &mut Command) -> String {
    let out = cmd.assert().failure().get_output().clone();
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    for noise in ["panicked", "RUST_BACKTRACE", "Error {", "EntityId(", "NaN"] {
        assert!(!err.contains(noise), "{err}");
    }
    err
}

/// Runs a command line that clap must refuse (code 2, its own usage text); returns stderr.
fn usage_error(cmd: &mut Command) -> String {
    let out = cmd.assert().failure().get_output().clone();
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.starts_with("error: invalid value"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    err
}

/// Runs a command that must succeed and returns its stdout.
fn success(cmd: &mut Command) -> String {
    let out = cmd.assert().success().get_output().clone();
    String::from_utf8(out.stdout).unwrap()
}

const CUBIC: &str = r#"{"type": "bezier", "control_points": [[0, 0], [1, 2], [3, 2], [4, 0]]}"#;

// ------------------------------------------------------------ finding 3: unbounded counts

#[test]
fn eval_derivs_is_bounded() {
    let dir = tempfile::tempdir().unwrap();
    let curve = write(dir.path(), "c.json", CUBIC);
    for k in [
        "18446744073709551615",
        "18446744073709551614",
        "4294967296",
        "1000000000",
        "65",
    ] {
        let err = usage_error(
            camber()
                .arg("eval")
                .arg(&curve)
                .args(["--at", "0.5", "--derivs", k]),
        );
        assert!(err.contains("from 0 to 64"), "{k}: {err}");
    }
    // The cap itself works, and derivatives above the degree are zero.
    let out = success(
        camber()
            .arg("eval")
            .arg(&curve)
            .args(["--at", "0.5", "--derivs", "64"]),
    );
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let d = v[0]["derivatives"].as_array().unwrap();
    assert_eq!(d.len(), 64);
    assert!(
        (d[2][0].as_f64().unwrap() + 12.0).abs() < 1e-12,
        "C‴ = 6(P3 − 3P2 + 3P1 − P0)"
    );
    assert!(d[3..]
        .iter()
        .all(|p| p[0].as_f64() == Some(0.0) && p[1].as_f64() == Some(0.0)));
}

#[test]
fn bench_sizes_are_bounded() {
    for n in ["18446744073709551615", "4294967296", "100001", "0"] {
        let err = usage_error(camber().args(["bench", "--quick", "--only", "W3", "--sizes", n]));
        assert!(err.contains("outside 1..=100000"), "{n}: {err}");
    }
}

// ------------------------------------------------------------ finding 7: loading

#[test]
fn degenerate_sketch_entities_are_refused_at_load() {
    let dir = tempfile::tempdir().unwrap();
    let line = write(
        dir.path(),
        "line.json",
        r#"{"version": 1, "entities": [{"id": 4, "kind": "line", "from": [1, 1], "to": [1, 1]}],
            "constraints": [{"id": 5, "kind": "horizontal", "of": {"line": 4}}]}"#,
    );
    let curve = write(
        dir.path(),
        "curve.json",
        r#"{"version": 1, "entities": [{"id": 7, "kind": "bezier", "control_points": [[1, 1], [1, 1], [1, 1]]}],
            "constraints": [{"id": 8, "kind": "arc_length", "curve": 7, "length": 3}]}"#,
    );
    let zero = write(
        dir.path(),
        "zero.json",
        r#"{"version": 1, "entities": [{"id": 2, "kind": "bspline", "degree": 0, "knots": [0, 1, 2],
            "control_points": [[0, 0], [1, 2]]}]}"#,
    );
    for (path, words) in [
        (&line, "entity 4 (line): has zero length"),
        (
            &curve,
            "entity 7 (bezier): has all its control points at one place",
        ),
        (&zero, "entity 2 (bspline): has degree 0"),
    ] {
        for cmd in ["solve", "check"] {
            let mut c = camber();
            c.arg(cmd).arg(path);
            if cmd == "solve" {
                c.arg("-o").arg(dir.path().join("out.json"));
            }
            let err = failure(&mut c);
            assert!(err.contains(words), "{cmd}: {err}");
            assert!(!err.contains("not finite"), "{err}");
        }
    }
}

#[test]
fn curve_files_are_checked_like_sketch_files() {
    let dir = tempfile::tempdir().unwrap();
    let points = |n: usize| {
        let p: Vec<String> = (0..n).map(|i| format!("[{i}, 0]")).collect();
        p.join(",")
    };
    let cases = [
        (
            format!(r#"{{"type": "bezier", "control_points": [{}]}}"#, points(258)),
            "degree 257 is above the largest supported degree 256",
        ),
        (
            format!(r#"{{"type": "bezier", "control_points": [{}]}}"#, points(5001)),
            "largest supported degree",
        ),
        (
            r#"{"type": "bspline", "degree": 1, "knots": [0, 0, 0.5, 0.5, 0.5, 1, 1],
                "control_points": [[0, 0], [1, 2], [3, 3], [4, 4], [5, 5]]}"#
                .to_owned(),
            "knot 0.5 is repeated 3 times, more than degree + 1 = 2",
        ),
        (
            r#"{"type": "bspline", "degree": 0, "knots": [0, 1, 2], "control_points": [[0, 0], [1, 2]]}"#
                .to_owned(),
            "degree 0 is not supported",
        ),
        (
            r#"{"type": "bezier", "control_points": [[0, 0], [1, 2]], "closed": true}"#.to_owned(),
            "unknown field `closed`",
        ),
    ];
    for (i, (text, words)) in cases.iter().enumerate() {
        let path = write(dir.path(), &format!("c{i}.json"), text);
        let err = failure(camber().arg("eval").arg(&path).args(["--at", "0.5"]));
        assert!(err.contains(words), "{words}: {err}");
    }
    // Degree 256 (257 points) is still fine.
    let path = write(
        dir.path(),
        "ok.json",
        &format!(
            r#"{{"type": "bezier", "control_points": [{}]}}"#,
            points(257)
        ),
    );
    success(camber().arg("eval").arg(&path).args(["--at", "0.5"]));
}

#[test]
fn a_byte_order_mark_is_accepted() {
    let dir = tempfile::tempdir().unwrap();
    let curve = write(dir.path(), "bom.json", &format!("\u{feff}{CUBIC}"));
    let out = success(camber().arg("eval").arg(&curve).args(["--at", "0.5"]));
    assert!(out.contains("\"point\""));
    let blade = std::fs::read_to_string(sketch("blade_section.json")).unwrap();
    let path = write(dir.path(), "blade.json", &format!("\u{feff}{blade}"));
    success(camber().arg("check").arg(&path));
}

#[cfg(unix)]
#[test]
fn input_size_is_bounded() {
    let err = failure(camber().args(["eval", "/dev/zero", "--at", "0.5"]));
    assert!(err.contains("larger than 64 MiB"), "{err}");
    let err = failure(camber().args(["check", "/dev/zero"]));
    assert!(err.contains("larger than 64 MiB"), "{err}");
}

// ------------------------------------------------------------ finding 4: unrepresentable numbers

#[test]
fn unrepresentable_numbers_are_refused_or_computed() {
    let dir = tempfile::tempdir().unwrap();
    let spline = write(
        dir.path(),
        "s.json",
        r#"{"type": "bspline", "degree": 2, "knots": [0, 0, 0, 0.5, 1, 1, 1],
            "control_points": [[0, 0], [1, 1], [3, 0], [4, 2]]}"#,
    );
    let out = dir.path().join("r.json");
    for to in ["-1e308,1e308", "0,1e-320", "1e17,1.0000000000000002e17"] {
        let err = failure(
            camber()
                .arg("op")
                .arg(&spline)
                .args(["reparam", &format!("--to={to}")])
                .arg("-o")
                .arg(&out),
        );
        assert!(err.contains("cannot carry the knots"), "{to}: {err}");
        assert!(!out.exists(), "{to}");
    }
    let wide = write(
        dir.path(),
        "wide.json",
        r#"{"type": "bspline", "degree": 1, "knots": [-1e308, -1e308, 1e308, 1e308], "control_points": [[0, 0], [1, 1]]}"#,
    );
    let err = failure(camber().arg("eval").arg(&wide).args(["--at", "0"]));
    assert!(err.contains("wider than f64 can subtract"), "{err}");
    let uneven = write(
        dir.path(),
        "uneven.json",
        r#"{"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 1],
            "control_points": [[1, 0], [1, 1], [0, 1]], "weights": [1e-300, 1e300, 1e-300]}"#,
    );
    for cmd in [
        vec!["eval", "--at", "0.5"],
        vec!["render-curve", "--combs", "-o", "x.svg"],
    ] {
        let err = failure(
            camber()
                .current_dir(dir.path())
                .arg(cmd[0])
                .arg(&uneven)
                .args(&cmd[1..]),
        );
        assert!(
            err.contains("the weights range from 1e-300 to 1e300"),
            "{err}"
        );
    }
    // Weights all 1e308: the same quarter circle as weights (1, √½, 1), evaluated and drawn.
    let huge = write(
        dir.path(),
        "huge.json",
        r#"{"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 1],
            "control_points": [[1, 0], [1, 1], [0, 1]], "weights": [1e308, 7.071067811865476e307, 1e308]}"#,
    );
    let text = success(
        camber()
            .arg("eval")
            .arg(&huge)
            .args(["--at", "0,0.5,1", "--derivs", "3"]),
    );
    assert!(!text.contains("null") && !text.contains("NaN"), "{text}");
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    for e in v.as_array().unwrap() {
        let (x, y) = (
            e["point"][0].as_f64().unwrap(),
            e["point"][1].as_f64().unwrap(),
        );
        assert!((x.hypot(y) - 1.0).abs() < 1e-12, "on the unit circle: {e}");
        assert!((e["curvature"].as_f64().unwrap() - 1.0).abs() < 1e-9, "{e}");
    }
    let svg = dir.path().join("huge.svg");
    success(
        camber()
            .arg("render-curve")
            .arg(&huge)
            .arg("--combs")
            .arg("-o")
            .arg(&svg),
    );
    let picture = std::fs::read_to_string(&svg).unwrap();
    assert!(
        !picture.contains("NaN") && !picture.contains("inf"),
        "{picture}"
    );
}

#[test]
fn no_null_is_written_as_a_result() {
    // A Bézier curve near the top of f64: its elevation is representable, its derivatives are
    // not; eval refuses instead of printing null, and render refuses instead of drawing NaN.
    let dir = tempfile::tempdir().unwrap();
    let big = write(
        dir.path(),
        "big.json",
        r#"{"type": "bezier", "control_points": [[-1.7e308, 0], [1.7e308, 0]]}"#,
    );
    let err = failure(camber().arg("eval").arg(&big).args(["--at", "0.5"]));
    assert!(err.contains("derivative 1 is not finite"), "{err}");
    let err = failure(
        camber()
            .arg("render-curve")
            .arg(&big)
            .arg("--combs")
            .arg("-o")
            .arg(dir.path().join("b.svg")),
    );
    assert!(err.contains("not finite"), "{err}");
}

// ------------------------------------------------------------ finding 6: outputs

#[test]
fn outputs_never_overwrite_inputs_or_each_other() {
    let dir = tempfile::tempdir().unwrap();
    let blade = std::fs::read_to_string(sketch("blade_section.json")).unwrap();
    let input = write(dir.path(), "in.json", &blade);
    let d = |n: &str| dir.path().join(n);
    // solve IN -o O --svg IN: the input is kept.
    let err = failure(
        camber()
            .arg("solve")
            .arg(&input)
            .arg("-o")
            .arg(d("o.json"))
            .arg("--svg")
            .arg(&input),
    );
    assert!(err.contains("refusing to overwrite the input"), "{err}");
    assert_eq!(std::fs::read_to_string(&input).unwrap(), blade);
    assert!(!d("o.json").exists());
    // -o X --svg X: refused, nothing written.
    let err = failure(
        camber()
            .arg("solve")
            .arg(&input)
            .arg("-o")
            .arg(d("x.json"))
            .arg("--svg")
            .arg(d("x.json")),
    );
    assert!(
        err.contains("the same file is given for two outputs"),
        "{err}"
    );
    assert!(!d("x.json").exists());
    // -o ok.json --svg <unwritable>: ok.json is not left behind.
    let err = failure(
        camber()
            .arg("solve")
            .arg(&input)
            .arg("-o")
            .arg(d("ok.json"))
            .arg("--svg")
            .arg(d("no/such/dir/p.svg")),
    );
    assert!(err.contains("p.svg"), "{err}");
    assert!(!d("ok.json").exists());
    // op split -o A --second A, and -o onto the input curve.
    let curve = write(dir.path(), "c.json", CUBIC);
    let err = failure(
        camber()
            .arg("op")
            .arg(&curve)
            .args(["split", "--at", "0.5"])
            .arg("-o")
            .arg(d("a.json"))
            .arg("--second")
            .arg(d("a.json")),
    );
    assert!(
        err.contains("the same file is given for two outputs"),
        "{err}"
    );
    assert!(!d("a.json").exists());
    let err = failure(
        camber()
            .arg("op")
            .arg(&curve)
            .args(["split", "--at", "0.5"])
            .arg("-o")
            .arg(&curve)
            .arg("--second")
            .arg(d("b.json")),
    );
    assert!(err.contains("refusing to overwrite the input"), "{err}");
    assert_eq!(std::fs::read_to_string(&curve).unwrap(), CUBIC);
    assert!(!d("b.json").exists());
    // render onto its own input.
    let err = failure(camber().arg("render").arg(&input).arg("-o").arg(&input));
    assert!(err.contains("refusing to overwrite the input"), "{err}");
    // No temporary file is left anywhere.
    for e in std::fs::read_dir(dir.path()).unwrap() {
        let name = e.unwrap().file_name().to_string_lossy().into_owned();
        assert!(!name.contains("camber-tmp"), "{name}");
    }
}

#[cfg(unix)]
#[test]
fn editor_save_keeps_the_link_and_the_mode() {
    use std::os::unix::fs::PermissionsExt as _;
    let dir = tempfile::tempdir().unwrap();
    let real = write(
        dir.path(),
        "real.json",
        &std::fs::read_to_string(sketch("blade_section.json")).unwrap(),
    );
    std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o600)).unwrap();
    let link = dir.path().join("link.json");
    std::os::unix::fs::symlink(&real, &link).unwrap();
    let mut ed = camber_cli::editor::EditorState::load(&link, None).unwrap();
    let answer = ed.handle("POST", "/api/save", b"{}");
    assert_eq!(
        answer.status,
        200,
        "{}",
        String::from_utf8_lossy(&answer.body)
    );
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    let mode = std::fs::metadata(&real).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o600);
    camber_sketch::file::from_json(&std::fs::read_to_string(&real).unwrap()).unwrap();
}

// ------------------------------------------------------------ issue 16: solve/check --json

#[test]
fn solve_and_check_print_json_and_warnings() {
    let dir = tempfile::tempdir().unwrap();
    let text = success(
        camber()
            .arg("check")
            .arg(sketch("blade_section.json"))
            .arg("--json"),
    );
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let c = &v["components"][0];
    assert_eq!(c["component"]["entities"].as_array().unwrap().len(), 4);
    let a = &c["analysis"];
    assert_eq!(
        a["dof"].as_u64().unwrap() + a["rank"].as_u64().unwrap(),
        a["free_unknowns"].as_u64().unwrap()
    );
    assert!(v["warnings"].as_array().unwrap().is_empty());
    let out = dir.path().join("o.json");
    let text = success(
        camber()
            .arg("solve")
            .arg(sketch("blade_section.json"))
            .arg("-o")
            .arg(&out)
            .arg("--json"),
    );
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let r = &v["components"][0]["report"];
    assert_eq!(r["status"], "solved");
    assert!(r["residuals"]
        .as_array()
        .unwrap()
        .iter()
        .all(|g| g["max_abs"].as_f64().unwrap() < 1e-9));
    assert!(out.exists());
    // A sketch with a line a billionth of its size: check and solve name it, in text and JSON.
    let short = write(
        dir.path(),
        "short.json",
        r#"{"version": 1, "entities": [
            {"id": 0, "kind": "line", "from": [0, 0], "to": [10, 0]},
            {"id": 1, "kind": "line", "from": [0, 0], "to": [1e-8, 0]}],
          "constraints": [{"id": 2, "kind": "horizontal", "of": {"line": 0}}]}"#,
    );
    let text = success(camber().arg("check").arg(&short));
    let warning = text
        .lines()
        .find(|l| l.starts_with("warning: "))
        .expect(&text);
    assert!(warning.contains("entity 1"), "{warning}");
    let v: serde_json::Value =
        serde_json::from_str(&success(camber().arg("check").arg(&short).arg("--json"))).unwrap();
    assert_eq!(v["warnings"].as_array().unwrap().len(), 1, "{v}");
    let text = success(
        camber()
            .arg("solve")
            .arg(&short)
            .arg("-o")
            .arg(dir.path().join("s.json")),
    );
    assert!(
        text.lines()
            .any(|l| l.starts_with("warning: ") && l.contains("entity 1")),
        "{text}"
    );
}

// ------------------------------------------------------------ findings 2 and 9: the editor

fn editor_call(
    ed: &mut camber_cli::editor::EditorState,
    path: &str,
    body: &str,
) -> (u16, serde_json::Value) {
    let r = ed.handle("POST", path, body.as_bytes());
    (r.status, serde_json::from_slice(&r.body).unwrap())
}

#[test]
fn absurd_drag_targets_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    let mut ed =
        camber_cli::editor::EditorState::load(&sketch("blade_section.json"), Some(out.clone()))
            .unwrap();
    let before = camber_sketch::file::to_json(ed.sketch()).unwrap();
    let (status, _) = editor_call(&mut ed, "/api/drag/start", r#"{"entity": 1, "index": 2}"#);
    assert_eq!(status, 200);
    for to in ["[1e308, 1e308]", "[1e200, 0]", "[0, -1e10]"] {
        let (status, answer) =
            editor_call(&mut ed, "/api/drag/move", &format!(r#"{{"to": {to}}}"#));
        assert_eq!(status, 422, "{to}: {answer}");
        let reason = answer["error"].as_str().unwrap();
        assert!(reason.contains("too far from the sketch"), "{reason}");
        assert!(reason.len() < 200, "a short message: {reason}");
    }
    // A reasonable move still works, and the sketch stays finite and saved as such.
    let (status, answer) = editor_call(&mut ed, "/api/drag/move", r#"{"to": [0.3, 0.2]}"#);
    assert_eq!(status, 200, "{answer}");
    assert!(!answer.to_string().contains("null"), "{answer}");
    assert_eq!(editor_call(&mut ed, "/api/drag/cancel", "{}").0, 200);
    assert_eq!(camber_sketch::file::to_json(ed.sketch()).unwrap(), before);
}

#[test]
fn samples_are_sent_in_f64() {
    // Coordinates beyond f32 (3.4e38): samples sent as f32 were infinite, written as null.
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "big.json",
        r#"{"version": 1, "entities": [{"id": 0, "kind": "bezier", "control_points": [[0, 0], [1e39, 1e39], [2e39, 0]]}]}"#,
    );
    let mut ed = camber_cli::editor::EditorState::load(&path, None).unwrap();
    let r = ed.handle("GET", "/api/state", b"");
    assert_eq!(r.status, 200);
    let v: serde_json::Value = serde_json::from_slice(&r.body).unwrap();
    let samples = v["scene"]["entities"][0]["samples"].as_array().unwrap();
    assert!(
        samples.iter().all(|p| p[0].is_f64() && p[1].is_f64()),
        "{samples:?}"
    );
    assert!((samples[samples.len() / 2][0].as_f64().unwrap() - 1e39).abs() < 1e24);
}

#[test]
fn ids_the_page_cannot_address_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "ids.json",
        r#"{"version": 1, "entities": [{"id": 9007199254740993, "kind": "point", "at": [0, 0]}]}"#,
    );
    let err = camber_cli::editor::EditorState::load(&path, None)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("entity id 9007199254740993 is above 9007199254740991"),
        "{err}"
    );
    let err = failure(camber().arg("edit").arg(&path));
    assert!(err.contains("renumber"), "{err}");
    // 2^53 − 1 itself is fine.
    let ok = write(
        dir.path(),
        "ok.json",
        r#"{"version": 1, "entities": [{"id": 9007199254740991, "kind": "point", "at": [0, 0]}]}"#,
    );
    camber_cli::editor::EditorState::load(&ok, None).unwrap();
}

#[test]
fn a_remote_bind_needs_an_explicit_flag() {
    let err = failure(
        camber()
            .arg("edit")
            .arg(sketch("blade_section.json"))
            .args(["--bind", "0.0.0.0"]),
    );
    assert!(err.contains("--allow-remote"), "{err}");
}

// ------------------------------------------------------------ finding 8: messages

#[test]
fn numbers_in_messages_have_bounded_digits() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "tiny.json",
        r#"{"version": 1, "entities": [{"id": 3, "kind": "circle", "center": [0, 0], "radius": -1e-320}]}"#,
    );
    let err = failure(camber().arg("check").arg(&path));
    assert!(
        err.contains("entity 3 (circle)") && err.contains("-9.9999e-321"),
        "{err}"
    );
    assert!(err.len() < 120, "{err}");
    let curve = write(dir.path(), "c.json", CUBIC);
    let err = failure(camber().arg("eval").arg(&curve).args(["--at", "1e300"]));
    assert!(
        err.contains("parameter 1e300 is outside the domain [0, 1]"),
        "{err}"
    );
    let path = write(
        dir.path(),
        "field.json",
        r#"{"version": 1, "entities": [{"id": 0, "kind": "bezier", "control_points": [[0, 0], [1, 2, 3]]}]}"#,
    );
    let err = failure(camber().arg("check").arg(&path));
    assert!(
        err.contains("at entities[0].control_points[1]: invalid length 3"),
        "{err}"
    );
}

// ------------------------------------------------------------ finding 5: pictures

/// Renders `text` as a sketch and returns the SVG and its viewBox.
fn render(dir: &Path, name: &str, text: &str) -> (String, [f64; 4]) {
    let path = write(dir, name, text);
    let svg = dir.join(format!("{name}.svg"));
    success(camber().arg("render").arg(&path).arg("-o").arg(&svg));
    let picture = std::fs::read_to_string(&svg).unwrap();
    let doc = roxmltree::Document::parse(&picture).unwrap();
    let v: Vec<f64> = doc
        .root_element()
        .attribute("viewBox")
        .unwrap()
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect();
    assert!(
        !picture.contains("NaN") && !picture.contains("inf"),
        "{picture}"
    );
    (picture, [v[0], v[1], v[2], v[3]])
}

/// Whether SVG point (x, y) lies inside the viewBox.
fn inside([x0, y0, w, h]: [f64; 4], x: f64, y: f64) -> bool {
    x >= x0 && x <= x0 + w && y >= y0 && y <= y0 + h
}

#[test]
fn view_boxes_are_robust() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [5, 5]}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [3, -2]}, {"id": 1, "kind": "point", "at": [3, -2]}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [1e308, 1e308]}, {"id": 1, "kind": "point", "at": [-1e308, -1e308]}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [1e300, 0]}]}"#,
    ];
    for (i, text) in cases.iter().enumerate() {
        let (picture, vb) = render(dir.path(), &format!("p{i}"), text);
        assert!(
            vb.iter().all(|v| v.is_finite() && v.abs() < 1e6),
            "{i}: {vb:?}"
        );
        assert!(vb[2] > 0.0 && vb[3] > 0.0, "{vb:?}");
        // Every point dot is inside the box.
        let doc = roxmltree::Document::parse(&picture).unwrap();
        for c in doc.descendants().filter(|n| n.has_tag_name("circle")) {
            let (x, y): (f64, f64) = (
                c.attribute("cx").unwrap().parse().unwrap(),
                c.attribute("cy").unwrap().parse().unwrap(),
            );
            assert!(inside(vb, x, y), "{i}: ({x}, {y}) outside {vb:?}");
        }
    }
}

#[test]
fn glyphs_are_in_the_picture_and_thinned() {
    let dir = tempfile::tempdir().unwrap();
    // A target ring far from its curve (the constraint is not yet solved) is inside the box.
    let (picture, vb) = render(
        dir.path(),
        "ring",
        r#"{"version": 1, "entities": [{"id": 0, "kind": "bezier", "control_points": [[0, 0], [1, 1], [2, 0]]}],
            "constraints": [{"id": 1, "kind": "point_at_parameter", "curve": 0, "u": 0.5, "target": {"at": [1, 50]}}]}"#,
    );
    let doc = roxmltree::Document::parse(&picture).unwrap();
    let scale = 400.0 / 50.0; // the box's larger side is 50 model units → 400 SVG units
    assert!(inside(vb, 1.0 * scale, -50.0 * scale), "{vb:?}");
    let rings: Vec<_> = doc
        .descendants()
        .filter(|n| n.has_tag_name("circle") && n.attribute("fill") == Some("none"))
        .collect();
    assert!(!rings.is_empty());
    for c in rings {
        let x: f64 = c.attribute("cx").unwrap().parse().unwrap();
        let y: f64 = c.attribute("cy").unwrap().parse().unwrap();
        assert!(inside(vb, x, y), "ring at ({x}, {y}) outside {vb:?}");
    }
    // A radius constraint has a glyph.
    let (picture, _) = render(
        dir.path(),
        "radius",
        r#"{"version": 1, "entities": [{"id": 0, "kind": "circle", "center": [0, 0], "radius": 2}],
            "constraints": [{"id": 1, "kind": "radius", "circle": 0, "radius": 2}]}"#,
    );
    assert!(picture.contains(">R</text>"), "{picture}");
    // The 1,000-segment chain: at most a few hundred constraints carry glyphs in the picture.
    let svg = dir.path().join("chain.svg");
    success(
        camber()
            .arg("render")
            .arg(sketch("w3a_chain_1000.json"))
            .arg("-o")
            .arg(&svg),
    );
    let picture = std::fs::read_to_string(&svg).unwrap();
    let doc = roxmltree::Document::parse(&picture).unwrap();
    let glyph_colour = camber_cli::commands::render::GLYPH;
    let glyph_elements = doc
        .descendants()
        .filter(|n| {
            n.attribute("stroke") == Some(glyph_colour) || n.attribute("fill") == Some(glyph_colour)
        })
        .count();
    assert!(
        glyph_elements <= 3 * 200 * 2,
        "{glyph_elements} glyph elements"
    );
}

// ------------------------------------------------------------ finding 11: help and reports

#[test]
fn help_and_reports_read_plainly() {
    let help = success(camber().args(["surface", "--help"]));
    assert!(
        help.contains("\"face_edge\"") && help.contains("\"neighbour_edge\""),
        "{help}"
    );
    assert!(!help.contains("\"edge\""), "{help}");
    let mut seen = std::collections::BTreeSet::new();
    for op in ["split", "insert-knot", "elevate", "reverse", "reparam"] {
        let help = success(camber().args(["op", "x.json", op, "--help"]));
        let line = help
            .lines()
            .find(|l| l.trim_start().starts_with("-o, --output"))
            .unwrap()
            .to_owned();
        assert_eq!(line.contains("first piece"), op == "split", "{op}: {line}");
        assert!(
            seen.insert(line.clone()),
            "{op} repeats another -o help: {line}"
        );
    }
    // check's header lists entities and constraints apart; solve names its solver in words.
    let text = success(camber().arg("check").arg(sketch("blade_section.json")));
    assert!(
        text.starts_with("component 1 (entities 0, 1, 2, 3; constraints 4, 5, 6, 7, 8, 9): "),
        "{text}"
    );
    let dir = tempfile::tempdir().unwrap();
    let done = write(
        dir.path(),
        "done.json",
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0, 0]}],
            "constraints": [{"id": 1, "kind": "fixed", "target": {"point": {"point": 0}}}]}"#,
    );
    let text = success(
        camber()
            .arg("solve")
            .arg(&done)
            .arg("-o")
            .arg(dir.path().join("o.json")),
    );
    assert!(
        !text.contains("solver None") && !text.contains("DenseMinNorm"),
        "{text}"
    );
}
