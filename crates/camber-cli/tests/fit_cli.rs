//! `camber fit` end to end: airfoil point files in the Selig and Lednicer layouts and as two
//! columns, fitted within the tolerance (checked by projecting every point on the written
//! curve), split at the leading edge into pieces that meet with one tangent, and bad point
//! files refused with one line naming the line and exit code 2.

#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use assert_cmd::Command;
use camber_cli::curve_file::{self, Curve};
use camber_geom::queries::closest_point;
use camber_geom::{BSplineCurve2, ParametricCurve};
use camber_workloads::airfoils::{naca, Spacing};
use nalgebra::Point2;

fn camber() -> Command {
    Command::cargo_bin("camber").expect("the camber binary is built")
}

fn failure(cmd: &mut Command) -> String {
    let out = cmd.assert().failure().code(2).get_output().clone();
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.starts_with("error: "), "{err}");
    err
}

/// The NACA 2412 section with 161 points (cosine spacing), Selig order.
fn section() -> Vec<Point2<f64>> {
    naca("2412", 161, Spacing::Cosine).unwrap()
}

fn selig(dir: &Path, points: &[Point2<f64>]) -> PathBuf {
    let mut text = String::from("NACA 2412\n");
    for p in points {
        writeln!(text, "  {:.7}  {:.7}", p.x, p.y).unwrap();
    }
    let path = dir.join("naca2412.dat");
    std::fs::write(&path, text).unwrap();
    path
}

/// The same points in the Lednicer layout: counts, then each surface from the leading edge.
fn lednicer(dir: &Path, points: &[Point2<f64>]) -> PathBuf {
    let le = points
        .iter()
        .enumerate()
        .min_by(|a, b| a.1.x.total_cmp(&b.1.x))
        .unwrap()
        .0;
    let upper: Vec<_> = points[..=le].iter().rev().collect();
    let lower: Vec<_> = points[le..].iter().collect();
    let mut text = format!("NACA 2412\n{}. {}.\n\n", upper.len(), lower.len());
    for p in upper {
        writeln!(text, "{:.7} {:.7}", p.x, p.y).unwrap();
    }
    text.push('\n');
    for p in lower {
        writeln!(text, "{:.7} {:.7}", p.x, p.y).unwrap();
    }
    let path = dir.join("naca2412_lednicer.dat");
    std::fs::write(&path, text).unwrap();
    path
}

fn bspline(path: &Path) -> BSplineCurve2<f64> {
    match curve_file::load(path).unwrap() {
        Curve::BSpline(c) => c,
        other => panic!("expected a bspline, got {}", other.type_name()),
    }
}

/// The largest distance from `points` (as written, rounded to 7 decimals) to `curve`.
fn worst_distance(curve: &BSplineCurve2<f64>, points: &[Point2<f64>]) -> f64 {
    points
        .iter()
        .map(|q| {
            let q = Point2::new((q.x * 1e7).round() / 1e7, (q.y * 1e7).round() / 1e7);
            closest_point(curve, &q).unwrap().distance
        })
        .fold(0.0, f64::max)
}

#[test]
fn an_airfoil_file_is_fitted_within_the_tolerance_with_few_control_points() {
    let dir = tempfile::tempdir().unwrap();
    let points = section();
    let input = selig(dir.path(), &points);
    let out = dir.path().join("fit.json");
    let assert = camber()
        .args(["fit", input.to_str().unwrap(), "--tolerance", "1e-4", "-o"])
        .arg(&out)
        .assert()
        .success();
    let stdout = String::from_utf8(assert.get_output().stdout.clone()).unwrap();
    assert!(stdout.contains("control points, max error"), "{stdout}");
    let curve = bspline(&out);
    assert!(worst_distance(&curve, &points) <= 1e-4 * (1.0 + 1e-6));
    assert!(
        curve.control_points().len() < points.len() / 3,
        "{} control points for {} points",
        curve.control_points().len(),
        points.len()
    );
}

#[test]
fn lednicer_and_selig_files_give_the_same_curve() {
    let dir = tempfile::tempdir().unwrap();
    let points = section();
    let a = dir.path().join("a.json");
    let b = dir.path().join("b.json");
    for (input, out) in [
        (selig(dir.path(), &points), &a),
        (lednicer(dir.path(), &points), &b),
    ] {
        camber()
            .args(["fit", input.to_str().unwrap(), "--tolerance", "1e-4", "-o"])
            .arg(out)
            .assert()
            .success();
    }
    assert_eq!(bspline(&a), bspline(&b));
}

#[test]
fn a_split_fit_writes_pieces_that_meet_with_one_tangent_at_the_leading_edge() {
    let dir = tempfile::tempdir().unwrap();
    let points = section();
    let input = selig(dir.path(), &points);
    let out = dir.path().join("split.json");
    camber()
        .args(["fit", input.to_str().unwrap(), "--tolerance", "1e-4"])
        .args(["--split", "leading-edge", "--joint", "g2", "-o"])
        .arg(&out)
        .assert()
        .success();
    let value: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(value["continuity"], "G2");
    let le = points
        .iter()
        .enumerate()
        .min_by(|a, b| a.1.x.total_cmp(&b.1.x))
        .unwrap()
        .0;
    assert_eq!(value["joints"], serde_json::json!([le]));
    let pieces: Vec<BSplineCurve2<f64>> = value["pieces"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| match Curve::from_json(&p.to_string()).unwrap() {
            Curve::BSpline(c) => c,
            other => panic!("expected a bspline piece, got {}", other.type_name()),
        })
        .collect();
    assert_eq!(pieces.len(), 2);
    assert!(worst_distance(&pieces[0], &points[..=le]) <= 1e-4 * (1.0 + 1e-6));
    assert!(worst_distance(&pieces[1], &points[le..]) <= 1e-4 * (1.0 + 1e-6));
    let end = pieces[0].derivatives(1.0, 1).unwrap();
    let start = pieces[1].derivatives(0.0, 1).unwrap();
    assert!((end[0] - start[0]).norm() < 1e-12, "the pieces meet");
    let (t0, t1) = (end[1].normalize(), start[1].normalize());
    assert!(
        (t0 - t1).norm() < 1e-9,
        "one tangent direction: {t0} vs {t1}"
    );
}

#[test]
fn bad_point_files_and_options_are_refused_with_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    let run = |text: &str, tolerance: &str| {
        let input = dir.path().join("bad.dat");
        std::fs::write(&input, text).unwrap();
        failure(
            camber()
                .args([
                    "fit",
                    input.to_str().unwrap(),
                    "--tolerance",
                    tolerance,
                    "-o",
                ])
                .arg(&out),
        )
    };
    let good = "0 0\n1 1\n2 0\n3 1\n4 0\n5 1\n";
    assert!(run("0 0\n1 nan\n2 0\n", "1e-3").contains("line 2"));
    assert!(run("name\n0 0\n1 2 3\n", "1e-3").contains("line 3"));
    assert!(run("# nothing\n", "1e-3").contains("no points"));
    assert!(run(good, "-1").contains("tolerance"));
    assert!(run(good, "0").contains("tolerance"));
    assert!(!out.exists(), "nothing written on failure");
}
