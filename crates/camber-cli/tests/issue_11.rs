//! Issue 11: nothing a user types or gives camber crashes it, hangs it, prints a NaN as a
//! result or damages a file. One test (or more) per finding, each run through the binary.

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
fn issue_11_finding_3_eval_derivs_is_bounded() {
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
fn issue_11_finding_3_bench_sizes_are_bounded() {
    for n in ["18446744073709551615", "4294967296", "100001", "0"] {
        let err = usage_error(camber().args(["bench", "--quick", "--only", "W3", "--sizes", n]));
        assert!(err.contains("outside 1..=100000"), "{n}: {err}");
    }
}

// ------------------------------------------------------------ finding 7: loading

#[test]
fn issue_11_finding_7_degenerate_sketch_entities_are_refused_at_load() {
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
fn issue_11_finding_7_curve_files_are_checked_like_sketch_files() {
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
fn issue_11_finding_7_a_byte_order_mark_is_accepted() {
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
fn issue_11_finding_7_input_size_is_bounded() {
    let err = failure(camber().args(["eval", "/dev/zero", "--at", "0.5"]));
    assert!(err.contains("larger than 64 MiB"), "{err}");
    let err = failure(camber().args(["check", "/dev/zero"]));
    assert!(err.contains("larger than 64 MiB"), "{err}");
}
