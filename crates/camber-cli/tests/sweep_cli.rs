//! `camber batch SKETCH --parameters TABLE.csv`: one line per row of the table, each variant's
//! dimensions following its values, and clean failures for bad tables.

#![allow(clippy::unwrap_used)] // test helpers unwrap like the tests do

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use serde_json::Value;

fn blade() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/sketches/blade_parametric.json")
}

fn camber() -> Command {
    Command::cargo_bin("camber").expect("the camber binary is built")
}

fn table(text: &str) -> tempfile::NamedTempFile {
    let f = tempfile::NamedTempFile::new().unwrap();
    std::fs::write(f.path(), text).unwrap();
    f
}

#[test]
fn every_row_of_the_table_is_one_solved_variant() {
    let t = table("chord,t_max\n1.0,0.12\n1.3,0.10\n0.9, 0.15\n");
    let out = camber()
        .args([
            "batch",
            blade().to_str().unwrap(),
            "--jobs",
            "2",
            "--parameters",
        ])
        .arg(t.path())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let lines: Vec<Value> = String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines.len(), 3);
    for (i, (line, chord)) in lines.iter().zip([1.0, 1.3, 0.9]).enumerate() {
        assert_eq!(line["row"], i);
        assert_eq!(line["ok"], true);
        assert_eq!(line["parameters"]["chord"], chord);
        assert!(line["max_residual"].as_f64().unwrap() < 1e-9);
    }
}

#[test]
fn bad_tables_fail_plainly() {
    for (text, message) in [
        (
            "chord,span\n1.0,2\n",
            "the table's column `span` names no parameter of the sketch",
        ),
        (
            "chord\nwide\n",
            "row 1, column `chord`: `wide` is not a number",
        ),
        ("chord,t_max\n1.0\n", "row 1"),
    ] {
        let t = table(text);
        let out = camber()
            .args(["batch", blade().to_str().unwrap(), "--parameters"])
            .arg(t.path())
            .output()
            .unwrap();
        assert!(!out.status.success());
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(message), "{text:?}: {err}");
    }
    // A variant the sketch cannot meet fails its own line, and the command after all lines.
    let t = table("t_max\n0.1\n-0.2\n");
    let out = camber()
        .args(["batch", blade().to_str().unwrap(), "--parameters"])
        .arg(t.path())
        .output()
        .unwrap();
    assert!(!out.status.success());
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert_eq!(stdout.lines().count(), 2);
    assert!(stdout.contains("\"ok\":false"));
}
