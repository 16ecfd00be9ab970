//! `camber bench` end to end on the quick plan: the JSON parsed and its numbers checked, the
//! table's shape, `--only` and `--sizes`, and usage errors.

use assert_cmd::Command;
use predicates::prelude::*;
use serde_json::Value;

fn camber() -> Command {
    Command::cargo_bin("camber").expect("the camber binary is built")
}

/// Runs `camber bench ARGS --json` and parses stdout (nothing is printed on stderr: the
/// progress bar is off with --json and without a terminal).
fn bench_json(args: &[&str]) -> Value {
    let out = camber()
        .arg("bench")
        .args(args)
        .arg("--json")
        .assert()
        .success()
        .stderr(predicate::str::is_empty())
        .get_output()
        .stdout
        .clone();
    serde_json::from_slice(&out).expect("bench --json prints JSON")
}

fn rows(v: &Value) -> &Vec<Value> {
    v["rows"].as_array().expect("rows is an array")
}

fn f(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} is a number in {v}"))
}

fn n(v: &Value, key: &str) -> u64 {
    v[key]
        .as_u64()
        .unwrap_or_else(|| panic!("{key} is a count in {v}"))
}

#[test]
fn w1_and_w4_quick_json() {
    let v = bench_json(&["--quick", "--only", "W4", "--only", "w1"]);
    assert_eq!(v["plan"]["mode"], "quick");
    let rows = rows(&v);
    // Table order whatever the order of --only: W1 (two forms), then W4.
    let names: Vec<&str> = rows
        .iter()
        .map(|r| r["workload"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["W1", "W1", "W4"]);
    for r in rows {
        let (median, p95) = (f(r, "median_s"), f(r, "p95_s"));
        assert!(median > 0.0 && p95 >= median, "{r}");
        assert!(n(r, "valid") <= n(r, "samples"));
    }
    // W1: 200 targets × 1 run, every update valid; the row form moves by the minimum norm.
    let row_form = &rows[0];
    assert_eq!(row_form["case"], "drag, row form");
    assert_eq!(n(row_form, "samples"), 200);
    assert_eq!(n(row_form, "valid"), 200);
    assert_eq!(n(row_form, "failed"), 0);
    let ratio = &row_form["moved_over_min_norm"];
    assert!((f(ratio, "median") - 1.0).abs() < 1e-6, "{ratio}");
    assert!((f(ratio, "max") - 1.0).abs() < 1e-6, "{ratio}");
    // The elimination form minimises over (P₀, t), not over the points: at least as far.
    let elim = &rows[1]["moved_over_min_norm"];
    assert!(f(elim, "median") >= 1.0 - 1e-9, "{elim}");
    // W4: 100 components, solved twice, valid both times; every component counted.
    let w4 = &rows[2];
    assert_eq!(w4["size"], 100);
    assert_eq!(n(w4, "samples"), 2);
    assert_eq!(n(w4, "valid"), 2);
    let counted: u64 = w4["solvers"]
        .as_object()
        .unwrap()
        .values()
        .map(|c| c.as_u64().unwrap())
        .sum();
    assert_eq!(counted, 200);
}

#[test]
fn chains_report_growth_between_sizes() {
    let v = bench_json(&["--quick", "--only", "W3,W3a", "--sizes", "4,8"]);
    let rows = rows(&v);
    let cases: Vec<(&str, &str)> = rows
        .iter()
        .map(|r| (r["workload"].as_str().unwrap(), r["case"].as_str().unwrap()))
        .collect();
    assert_eq!(
        cases,
        [("W3", "N=4"), ("W3", "N=8"), ("W3a", "N=4"), ("W3a", "N=8")]
    );
    for (k, r) in rows.iter().enumerate() {
        assert_eq!(n(r, "valid"), n(r, "samples"), "{r}");
        // The growth exponent is on the second size of each workload only.
        if k % 2 == 0 {
            assert!(r["growth"].is_null());
        } else {
            let g = f(r, "growth");
            let expected = (f(r, "median_s") / f(&rows[k - 1], "median_s")).ln() / 2f64.ln();
            assert!((g - expected).abs() < 1e-9, "{g} vs {expected}");
        }
    }
}

/// W5r (rectangles rounded by fillet arcs) runs at the given sizes beside W5, every solve valid
/// by its own check (radii, quarter-turn sweeps, tangency senses, W5's line check), each
/// rectangle a component of its own solved by Newton.
#[test]
fn rounded_rectangles_are_reported_beside_rectangles() {
    let v = bench_json(&["--quick", "--only", "W5,w5r", "--sizes", "4,8"]);
    let rows = rows(&v);
    let cases: Vec<(&str, &str)> = rows
        .iter()
        .map(|r| (r["workload"].as_str().unwrap(), r["case"].as_str().unwrap()))
        .collect();
    assert_eq!(
        cases,
        [("W5", "N=4"), ("W5", "N=8"), ("W5r", "N=4"), ("W5r", "N=8")]
    );
    for r in &rows[2..] {
        assert_eq!(n(r, "valid"), n(r, "samples"), "{r}");
        assert_eq!(n(r, "failed"), 0, "{r}");
        let size = n(r, "size");
        let components: u64 = r["solvers"]
            .as_object()
            .unwrap()
            .values()
            .map(|c| c.as_u64().unwrap())
            .sum();
        assert_eq!(components, size * n(r, "samples"), "{r}");
    }
}

#[test]
fn the_analysis_workload_checks_four_sketches() {
    let v = bench_json(&["--quick", "--only", "A", "--sizes", "4,8"]);
    let rows = rows(&v);
    let cases: Vec<(&str, &str)> = rows
        .iter()
        .map(|r| (r["workload"].as_str().unwrap(), r["case"].as_str().unwrap()))
        .collect();
    assert_eq!(
        cases,
        [
            ("A", "W3 N=4"),
            ("A", "W3 N=8"),
            ("A", "points N=40"),
            ("A", "points N=80"),
            ("A", "ladder N=4"),
            ("A", "ladder N=8"),
            ("A", "free points N=40"),
            ("A", "free points N=80")
        ]
    );
    // Every analysis has the DOF its construction gives; the ladder is fully constrained and
    // settled by its blocks, with no free-unknown projection; every free point is a component
    // of DOF 2.
    for r in rows {
        assert_eq!(n(r, "samples"), 2, "{r}");
        assert_eq!(n(r, "valid"), n(r, "samples"), "{r}");
    }
}

#[test]
fn w8_solves_every_variant_in_one_batch() {
    let v = bench_json(&["--quick", "--only", "W8"]);
    let rows = rows(&v);
    assert_eq!(rows.len(), 1);
    let r = &rows[0];
    assert_eq!(r["case"], "100 bspline7 variants");
    // One time per batch (one batch in the quick mode), every variant checked.
    assert_eq!(n(r, "samples"), 100, "{r}");
    assert_eq!(n(r, "valid"), 100, "{r}");
    assert_eq!(n(r, "failed"), 0, "{r}");
    assert!(f(r, "median_s") > 0.0);
}

#[test]
fn w2_quick_counts_valid_results() {
    let v = bench_json(&["--quick", "--only", "W2"]);
    let rows = rows(&v);
    let cases: Vec<&str> = rows.iter().map(|r| r["case"].as_str().unwrap()).collect();
    assert_eq!(
        cases,
        [
            "bspline7 δ=0.01",
            "bspline7 δ=0.05",
            "bspline7 drag update",
            "2cubic δ=0.01",
            "2cubic δ=0.05"
        ]
    );
    for (k, r) in rows.iter().enumerate() {
        // The drag row: one run of 200 targets (the quick plan's W1 run count).
        let samples = if k == 2 { 200 } else { 10 };
        assert_eq!(n(r, "samples"), samples, "{r}");
        assert!(n(r, "valid") <= samples);
    }
    // The small perturbations are all recovered, and every drag update holds.
    assert_eq!(n(&rows[0], "valid"), 10);
    assert_eq!(n(&rows[2], "valid"), 200);
    assert_eq!(n(&rows[2], "failed"), 0);
    assert_eq!(n(&rows[3], "valid"), 10);
}

#[test]
fn the_table_has_a_line_per_case() {
    let out = camber()
        .args(["bench", "--quick", "--only", "W1"])
        .assert()
        .success()
        .stderr(predicate::str::is_empty())
        .get_output()
        .stdout
        .clone();
    let text = String::from_utf8(out).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 4, "{text}");
    assert!(lines[0].contains("quick plan"));
    assert!(lines[1].contains("median") && lines[1].contains("p95") && lines[1].contains("valid"));
    assert!(lines[2].starts_with("W1") && lines[2].contains("200/200"));
    assert!(lines[2].contains("moved/min-norm 1.000"));
}

#[test]
fn bad_bench_arguments_exit_2() {
    camber()
        .args(["bench", "--only", "W9"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("W9"));
    camber()
        .args(["bench", "--quick", "--only", "W3", "--sizes", "0"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("outside 1..=100000"));
}

#[test]
fn equal_sizes_have_no_growth_and_say_so() {
    // log(t₂/t₁)/log(10/10) used to print "growth -inf" (or NaN).
    let v = bench_json(&["--quick", "--only", "W3", "--sizes", "10,10"]);
    let rows = rows(&v);
    assert_eq!(rows.len(), 2);
    assert!(rows[1]["growth"].is_null(), "{}", rows[1]);
    assert_eq!(rows[1]["same_size_as_previous"], true, "{}", rows[1]);
    let out = camber()
        .args(["bench", "--quick", "--only", "W3", "--sizes", "10,10"])
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let text = String::from_utf8(out).unwrap();
    assert!(
        text.contains("no growth (same N as the row before)"),
        "{text}"
    );
    assert!(!text.contains("inf") && !text.contains("NaN"), "{text}");
}

#[test]
fn write_sketch_writes_the_w3_chain_the_editor_opens() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("chain.json");
    camber()
        .args(["bench", "--only", "W3", "--sizes", "20", "--write-sketch"])
        .arg(&path)
        .assert()
        .success()
        .stdout(predicate::str::is_empty());
    let file: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    let kinds = |kind: &str| {
        file["constraints"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["kind"] == kind)
            .count()
    };
    assert_eq!(file["entities"].as_array().unwrap().len(), 20);
    assert_eq!(
        (kinds("g1_join_free"), kinds("distance"), kinds("fixed")),
        (19, 20, 2)
    );
    // The editor opens it: one component of 20 segments, analysed (8·20 unknowns less the
    // two fixed points, 19·3 join rows and 20 chords: DOF 160 − 4 − 57 − 20 = 79).
    let mut ed = camber_cli::editor::EditorState::load(&path, None).unwrap();
    let state: Value = serde_json::from_slice(&ed.handle("GET", "/api/state", b"").body).unwrap();
    let comps = state["components"].as_array().unwrap();
    assert_eq!(comps.len(), 1);
    assert_eq!(comps[0]["entities"].as_array().unwrap().len(), 20);
    assert_eq!(comps[0]["analysis"]["dof"], 79, "{}", comps[0]["analysis"]);
    assert_eq!(state["scene"]["entities"].as_array().unwrap().len(), 20);
    // W3a the same way; the default size is 1000; anything else is refused.
    camber()
        .args(["bench", "--only", "W3a", "--write-sketch"])
        .arg(dir.path().join("w3a.json"))
        .assert()
        .success();
    let w3a: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("w3a.json")).unwrap())
            .unwrap();
    assert_eq!(w3a["entities"].as_array().unwrap().len(), 1000);
    camber()
        .args(["bench", "--only", "W4", "--write-sketch"])
        .arg(dir.path().join("w4.json"))
        .assert()
        .failure()
        .stderr(predicate::str::contains("--write-sketch writes one chain"));
    camber()
        .args(["bench", "--sizes", "10,20", "--write-sketch"])
        .arg(dir.path().join("two.json"))
        .assert()
        .failure()
        .stderr(predicate::str::contains("one --sizes N"));
}
