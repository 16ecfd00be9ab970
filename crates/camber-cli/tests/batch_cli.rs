//! `camber batch` end to end: a directory of bundled sketches (and one bad file) solved on two
//! threads, one JSON line per file in name order, each report equal to the one `camber solve`
//! gives, and the command failing after its lines when a file fails.

#![allow(clippy::unwrap_used)] // test helpers unwrap like the tests do

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use serde_json::Value;

fn sketch(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/sketches")
        .join(name)
}

fn camber() -> Command {
    Command::cargo_bin("camber").expect("the camber binary is built")
}

fn lines(stdout: &[u8]) -> Vec<Value> {
    String::from_utf8(stdout.to_vec())
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// A directory with copies of the bundled diffuser, blade section and two-curves sketches.
fn good_dir() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for (i, name) in ["diffuser.json", "blade_section.json", "two_curves.json"]
        .iter()
        .enumerate()
    {
        std::fs::copy(sketch(name), dir.path().join(format!("{i}_{name}"))).unwrap();
    }
    std::fs::write(dir.path().join("notes.txt"), "not a sketch").unwrap();
    dir
}

#[test]
fn every_file_gets_one_line_in_name_order() {
    let dir = good_dir();
    let out = camber()
        .args(["batch", dir.path().to_str().unwrap(), "--jobs", "2"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let lines = lines(&out.stdout);
    let names: Vec<&str> = lines.iter().map(|l| l["file"].as_str().unwrap()).collect();
    assert_eq!(
        names,
        [
            "0_diffuser.json",
            "1_blade_section.json",
            "2_two_curves.json"
        ]
    );
    for l in &lines {
        assert_eq!(l["ok"], true, "{l}");
        let comps = l["report"]["components"].as_array().unwrap();
        assert!(!comps.is_empty());
        for c in comps {
            for r in c["report"]["residuals"].as_array().unwrap() {
                assert!(r["max_abs"].as_f64().unwrap() < 1e-6, "{l}");
            }
        }
    }
}

#[test]
fn one_and_two_jobs_give_the_same_solutions() {
    let dir = good_dir();
    let (one, two) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    for (jobs, out) in [("1", &one), ("2", &two)] {
        camber()
            .args([
                "batch",
                dir.path().to_str().unwrap(),
                "--jobs",
                jobs,
                "--output",
            ])
            .arg(out.path())
            .assert()
            .success();
    }
    for name in [
        "0_diffuser.json",
        "1_blade_section.json",
        "2_two_curves.json",
    ] {
        let a = std::fs::read_to_string(one.path().join(name)).unwrap();
        let b = std::fs::read_to_string(two.path().join(name)).unwrap();
        assert_eq!(a, b, "{name}");
    }
}

#[test]
fn a_bad_file_is_reported_on_its_line_and_fails_the_command() {
    let dir = good_dir();
    std::fs::write(
        dir.path().join("9_bad.json"),
        r#"{"version": 1, "entities": [}"#,
    )
    .unwrap();
    let out = camber()
        .args(["batch", dir.path().to_str().unwrap(), "--jobs", "2"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    let lines = lines(&out.stdout);
    assert_eq!(lines.len(), 4);
    assert_eq!(lines[3]["file"], "9_bad.json");
    assert_eq!(lines[3]["ok"], false);
    assert!(lines[3]["error"].as_str().unwrap().contains("invalid JSON"));
    assert!(String::from_utf8_lossy(&out.stderr).contains("1 of 4 sketch files failed"));
}

#[test]
fn zero_jobs_is_refused() {
    let dir = good_dir();
    camber()
        .args(["batch", dir.path().to_str().unwrap(), "--jobs", "0"])
        .assert()
        .failure();
}
