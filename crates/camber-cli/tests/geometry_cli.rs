//! The geometry commands end to end: `camber op extend|fit|interpolate|remove-knot|
//! reduce-degree|offset`, `camber eval --arc-length` and `camber intersect`, their files and
//! numbers checked against the library, and bad input failing with one line and exit code 2.

#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use camber_cli::curve_file::{self, Curve};
use camber_geom::arc_length::arc_length;
use nalgebra::Point2;

fn curve_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/data/curves")
        .join(name)
}

fn camber() -> Command {
    Command::cargo_bin("camber").expect("the camber binary is built")
}

fn stdout_json(cmd: &mut Command) -> serde_json::Value {
    let out = cmd.assert().success().get_output().stdout.clone();
    serde_json::from_slice(&out).expect("stdout is JSON")
}

fn failure(cmd: &mut Command) -> String {
    let out = cmd.assert().failure().code(2).get_output().clone();
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.starts_with("error: "), "{err}");
    err
}

fn points_file(dir: &Path, points: &[[f64; 2]]) -> PathBuf {
    let path = dir.join("points.json");
    std::fs::write(&path, serde_json::to_string(points).unwrap()).unwrap();
    path
}

#[test]
fn eval_arc_length_matches_the_library() {
    let path = curve_path("nurbs_quarter_circle.json");
    let v = stdout_json(
        camber()
            .arg("eval")
            .arg(&path)
            .args(["--arc-length", "--at", "0.5"]),
    );
    let curve = curve_file::load(&path).unwrap();
    let expected = arc_length(curve.as_parametric(), 1e-10).unwrap().length;
    let length = v["length"].as_f64().unwrap();
    assert!((length - expected).abs() < 1e-12);
    assert!(v["error_estimate"].as_f64().unwrap() <= 1e-10);
    assert!(v["at"][0]["length"].as_f64().unwrap() > 0.0);
    // --tolerance without --arc-length is a usage error.
    camber()
        .arg("eval")
        .arg(&path)
        .args(["--at", "0.5", "--tolerance", "1e-3"])
        .assert()
        .failure();
}

#[test]
fn extend_keeps_the_curve_and_reaches_further() {
    let dir = tempfile::tempdir().unwrap();
    let input = curve_path("bspline_camber_line.json");
    let out = dir.path().join("longer.json");
    camber()
        .arg("op")
        .arg(&input)
        .args([
            "extend",
            "--end",
            "end",
            "--length",
            "0.2",
            "--continuity",
            "g1",
            "-o",
        ])
        .arg(&out)
        .assert()
        .success();
    let (a, b) = (
        curve_file::load(&input).unwrap(),
        curve_file::load(&out).unwrap(),
    );
    for i in 0..=10 {
        let u = f64::from(i) / 10.0;
        let (p, q) = (
            a.as_parametric().point(u).unwrap(),
            b.as_parametric().point(u).unwrap(),
        );
        assert!((p - q).norm() < 1e-12);
    }
    let added = camber_geom::arc_length::arc_length_between(
        b.as_parametric(),
        1.0,
        b.as_parametric().domain().1,
        1e-12,
    )
    .unwrap();
    assert!((added.length - 0.2).abs() < 1e-10);
    // By parameter, on a Bézier curve.
    let bez = dir.path().join("bez.json");
    camber()
        .arg("op")
        .arg(curve_path("bezier_cubic.json"))
        .args(["extend", "--to", "1.5", "-o"])
        .arg(&bez)
        .assert()
        .success();
    assert!(matches!(curve_file::load(&bez).unwrap(), Curve::Bezier(_)));
    let err = failure(
        camber()
            .arg("op")
            .arg(curve_path("bezier_cubic.json"))
            .args(["extend", "--to", "0.5", "-o"])
            .arg(dir.path().join("x.json")),
    );
    assert!(err.contains("does not lie beyond"), "{err}");
}

#[test]
fn interpolate_and_fit_a_points_file() {
    let dir = tempfile::tempdir().unwrap();
    let pts = [
        [0.0, 0.0],
        [1.0, 1.0],
        [2.0, 0.5],
        [3.0, 1.5],
        [4.0, 0.0],
        [5.0, 0.3],
    ];
    let input = points_file(dir.path(), &pts);
    let out = dir.path().join("through.json");
    camber()
        .arg("op")
        .arg(&input)
        .args(["interpolate", "--params", "centripetal", "-o"])
        .arg(&out)
        .assert()
        .success();
    let Curve::BSpline(c) = curve_file::load(&out).unwrap() else {
        panic!("a B-spline")
    };
    let lib = camber_geom::fit::interpolate(
        &pts.map(|[x, y]| Point2::new(x, y)),
        3,
        camber_geom::fit::ParameterMethod::Centripetal,
        None,
    )
    .unwrap();
    assert_eq!(c, lib.curve);
    let fitted = dir.path().join("fit.json");
    let line = camber()
        .arg("op")
        .arg(&input)
        .args(["fit", "--tolerance", "0.05", "--degree", "2", "-o"])
        .arg(&fitted)
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    assert!(String::from_utf8(line).unwrap().contains("max error"));
    let ls = dir.path().join("ls.json");
    camber()
        .arg("op")
        .arg(&input)
        .args(["fit", "--control-points", "4", "--fixed-ends", "-o"])
        .arg(&ls)
        .assert()
        .success();
    let Curve::BSpline(l) = curve_file::load(&ls).unwrap() else {
        panic!("a B-spline")
    };
    assert_eq!(l.control_points().len(), 4);
    assert_eq!(l.control_points()[0], Point2::new(0.0, 0.0));
    // A points file that is not one.
    let bad = dir.path().join("bad.json");
    std::fs::write(&bad, r#"{"points": [[0, 0], [1]]}"#).unwrap();
    let err = failure(
        camber()
            .arg("op")
            .arg(&bad)
            .args(["interpolate", "-o"])
            .arg(dir.path().join("y.json")),
    );
    assert!(err.contains("point 1"), "{err}");
}

#[test]
fn remove_knot_and_reduce_degree_undo_insertion_and_elevation() {
    let dir = tempfile::tempdir().unwrap();
    let input = curve_path("bspline_camber_line.json");
    let busy = dir.path().join("busy.json");
    camber()
        .arg("op")
        .arg(&input)
        .args(["insert-knot", "--at", "0.4", "--times", "2", "-o"])
        .arg(&busy)
        .assert()
        .success();
    let clean = dir.path().join("clean.json");
    camber()
        .arg("op")
        .arg(&busy)
        .args(["remove-knot", "--at", "0.4", "--times", "2", "-o"])
        .arg(&clean)
        .assert()
        .success();
    let (a, b) = (
        curve_file::load(&input).unwrap(),
        curve_file::load(&clean).unwrap(),
    );
    assert_eq!(a.control_polygon().len(), b.control_polygon().len());
    let elevated = dir.path().join("up.json");
    camber()
        .arg("op")
        .arg(&input)
        .args(["elevate", "-o"])
        .arg(&elevated)
        .assert()
        .success();
    let down = dir.path().join("down.json");
    camber()
        .arg("op")
        .arg(&elevated)
        .args(["reduce-degree", "-o"])
        .arg(&down)
        .assert()
        .success();
    let d = curve_file::load(&down).unwrap();
    for i in 0..=20 {
        let u = f64::from(i) / 20.0;
        let (p, q) = (
            a.as_parametric().point(u).unwrap(),
            d.as_parametric().point(u).unwrap(),
        );
        assert!((p - q).norm() < 1e-9);
    }
    assert_eq!(d.control_polygon().len(), a.control_polygon().len());
    let err = failure(
        camber()
            .arg("op")
            .arg(curve_path("hermite_s.json"))
            .args(["remove-knot", "--all", "-o"])
            .arg(dir.path().join("z.json")),
    );
    assert!(err.contains("no knots"), "{err}");
}

#[test]
fn offset_writes_a_bspline_within_tolerance() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("offset.json");
    camber()
        .arg("op")
        .arg(curve_path("nurbs_quarter_circle.json"))
        .args(["offset", "--distance", "-0.5", "--tolerance", "1e-6", "-o"])
        .arg(&out)
        .assert()
        .success();
    let o = curve_file::load(&out).unwrap();
    // The file's arc is the unit quarter circle about the origin, counter-clockwise: −0.5 is
    // outwards.
    let (centre, radius) = (Point2::new(0.0, 0.0), 1.0);
    for i in 0..=20 {
        let p = o.as_parametric().point(f64::from(i) / 20.0).unwrap();
        assert!(((p - centre).norm() - (radius + 0.5)).abs() < 1e-6);
    }
}

#[test]
fn intersect_reports_both_parameters() {
    let a = curve_path("bezier_cubic.json");
    let b = curve_path("hermite_s.json");
    let v = stdout_json(camber().arg("intersect").arg(&a).arg(&b));
    let hits = v["intersections"].as_array().unwrap();
    assert!(!hits.is_empty());
    let (ca, cb) = (curve_file::load(&a).unwrap(), curve_file::load(&b).unwrap());
    for h in hits {
        let pa = ca
            .as_parametric()
            .point(h["u_a"].as_f64().unwrap())
            .unwrap();
        let pb = cb
            .as_parametric()
            .point(h["u_b"].as_f64().unwrap())
            .unwrap();
        assert!((pa - pb).norm() < 1e-9);
    }
    assert!(v["closest"]["distance"].as_f64().unwrap() < 1e-9);
    let err = failure(
        camber()
            .arg("intersect")
            .arg(&a)
            .arg(&b)
            .args(["--tolerance", "-1"]),
    );
    assert!(err.contains("tolerance"), "{err}");
}

#[test]
fn intersect_reports_a_coincident_stretch_as_intervals() {
    // A curve against itself: one stretch over the whole domain, no list of points along it.
    let a = curve_path("bspline_camber_line.json");
    let v = stdout_json(camber().arg("intersect").arg(&a).arg(&a));
    assert!(v["intersections"].as_array().unwrap().is_empty(), "{v}");
    let overlaps = v["overlaps"].as_array().unwrap();
    assert_eq!(overlaps.len(), 1, "{v}");
    let (lo, hi) = curve_file::load(&a).unwrap().as_parametric().domain();
    let u_a = overlaps[0]["u_a"].as_array().unwrap();
    assert!((u_a[0].as_f64().unwrap() - lo).abs() < 1e-9, "{v}");
    assert!((u_a[1].as_f64().unwrap() - hi).abs() < 1e-9, "{v}");
}

#[test]
fn split_refuses_what_eval_could_not_evaluate() {
    let dir = tempfile::tempdir().unwrap();
    let curve = curve_path("bspline_camber_line.json");
    let (left, right) = (dir.path().join("l.json"), dir.path().join("r.json"));
    // A parameter 5e-324 after the start would make a knot span f64 cannot divide by.
    let err = failure(
        camber()
            .arg("op")
            .arg(&curve)
            .args(["split", "--at=5e-324", "-o"])
            .arg(&left)
            .arg("--second")
            .arg(&right),
    );
    assert!(err.contains("knot span"), "{err}");
    assert!(!left.exists() && !right.exists());
    // What split writes, eval evaluates at both ends of both pieces.
    camber()
        .arg("op")
        .arg(&curve)
        .args(["split", "--at=1e-9", "-o"])
        .arg(&left)
        .arg("--second")
        .arg(&right)
        .assert()
        .success();
    for piece in [&left, &right] {
        let (lo, hi) = curve_file::load(piece).unwrap().as_parametric().domain();
        let v = stdout_json(
            camber()
                .arg("eval")
                .arg(piece)
                .arg(format!("--at={lo:e},{hi:e}"))
                .args(["--derivs", "2"]),
        );
        assert_eq!(v.as_array().unwrap().len(), 2, "{v}");
    }
}

#[test]
fn eval_arc_length_says_when_it_raises_the_tolerance() {
    let path = curve_path("nurbs_quarter_circle.json");
    let out = camber()
        .arg("eval")
        .arg(&path)
        .args(["--arc-length", "--tolerance", "1e-300"])
        .assert()
        .success()
        .get_output()
        .clone();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let tolerance = v["tolerance"].as_f64().unwrap();
    assert!(tolerance > 1e-300 && tolerance < 1e-13, "{v}");
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("below what f64 resolves"), "{err}");
}
