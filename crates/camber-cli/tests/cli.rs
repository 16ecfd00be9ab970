//! The `camber` binary end to end: every subcommand on the bundled files, numbers checked
//! against the library, SVG output parsed, and bad input failing with one plain line and exit
//! code 2.

#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

use std::path::{Path, PathBuf};

use approx::assert_relative_eq;
use assert_cmd::Command;
use camber_cli::curve_file::{self, Curve};
use camber_geom::queries::signed_curvature;
use camber_surface::NurbsSurface;
use predicates::prelude::*;

const CURVES: [&str; 4] = [
    "bezier_cubic.json",
    "bspline_camber_line.json",
    "nurbs_quarter_circle.json",
    "hermite_s.json",
];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn curve_path(name: &str) -> PathBuf {
    root().join("examples/data/curves").join(name)
}

fn bad_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn camber() -> Command {
    Command::cargo_bin("camber").expect("the camber binary is built")
}

fn stdout_json(cmd: &mut Command) -> serde_json::Value {
    let out = cmd.assert().success().get_output().stdout.clone();
    serde_json::from_slice(&out).expect("stdout is JSON")
}

/// Parameters spread over a curve's domain, ends included.
fn spread(c: &Curve, n: usize) -> Vec<f64> {
    let (a, b) = c.as_parametric().domain();
    (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect()
}

fn point_of(c: &Curve, u: f64) -> nalgebra::Point2<f64> {
    c.as_parametric().point(u).expect("inside the domain")
}

/// Runs a failing command and returns its single stderr line after checking the exit code,
/// the `error: ` prefix and the absence of debug dumps.
fn failure(cmd: &mut Command) -> String {
    let out = cmd.assert().failure().code(2).get_output().clone();
    let err = String::from_utf8(out.stderr).expect("utf-8");
    assert_eq!(err.lines().count(), 1, "one line: {err}");
    assert!(err.starts_with("error: "), "{err}");
    for noise in ["panicked", "Error {", "RUST_BACKTRACE", "Caused by"] {
        assert!(!err.contains(noise), "{err}");
    }
    err
}

// ---------------------------------------------------------------- eval

#[test]
fn eval_matches_the_library_on_every_bundled_curve() {
    for name in CURVES {
        let path = curve_path(name);
        let curve = curve_file::load(&path).unwrap();
        let us = spread(&curve, 4);
        let at: Vec<String> = us.iter().map(|u| u.to_string()).collect();
        let v = stdout_json(camber().arg("eval").arg(&path).args([
            "--at",
            &at.join(","),
            "--derivs",
            "3",
        ]));
        let items = v.as_array().unwrap();
        assert_eq!(items.len(), us.len(), "{name}");
        for (item, &u) in items.iter().zip(&us) {
            assert_relative_eq!(item["u"].as_f64().unwrap(), u);
            let d = curve.as_parametric().derivatives(u, 3).unwrap();
            let p = &item["point"];
            assert_relative_eq!(p[0].as_f64().unwrap(), d[0].x, epsilon = 1e-12);
            assert_relative_eq!(p[1].as_f64().unwrap(), d[0].y, epsilon = 1e-12);
            let derivs = item["derivatives"].as_array().unwrap();
            assert_eq!(derivs.len(), 3);
            for (k, dk) in derivs.iter().enumerate() {
                assert_relative_eq!(dk[0].as_f64().unwrap(), d[k + 1].x, epsilon = 1e-9);
                assert_relative_eq!(dk[1].as_f64().unwrap(), d[k + 1].y, epsilon = 1e-9);
            }
            let kappa = signed_curvature(curve.as_parametric(), u).unwrap();
            assert_relative_eq!(item["curvature"].as_f64().unwrap(), kappa, epsilon = 1e-9);
        }
    }
}

#[test]
fn eval_hand_values() {
    // Cubic Bézier (0,0) (1,2) (3,2) (4,0) at 1/2: C = (2, 1.5), C′ = (4.5, 0), C″ = (0, −12),
    // κ = (x′y″ − y′x″)/|C′|³ = −54/91.125 = −16/27.
    let v = stdout_json(
        camber()
            .arg("eval")
            .arg(curve_path(CURVES[0]))
            .args(["--at", "0.5", "--derivs", "2"]),
    );
    let e = &v[0];
    assert_relative_eq!(e["point"][0].as_f64().unwrap(), 2.0, epsilon = 1e-15);
    assert_relative_eq!(e["point"][1].as_f64().unwrap(), 1.5, epsilon = 1e-15);
    assert_relative_eq!(
        e["derivatives"][1][1].as_f64().unwrap(),
        -12.0,
        epsilon = 1e-12
    );
    assert_relative_eq!(
        e["curvature"].as_f64().unwrap(),
        -16.0 / 27.0,
        epsilon = 1e-12
    );
    // The rational quarter circle of radius 1 has curvature 1 everywhere, turning left.
    let v = stdout_json(
        camber()
            .arg("eval")
            .arg(curve_path(CURVES[2]))
            .args(["--at", "0,0.3,1"]),
    );
    for e in v.as_array().unwrap() {
        assert_relative_eq!(e["curvature"].as_f64().unwrap(), 1.0, epsilon = 1e-12);
        let p = &e["point"];
        assert_relative_eq!(
            p[0].as_f64().unwrap().hypot(p[1].as_f64().unwrap()),
            1.0,
            epsilon = 1e-14
        );
        assert_eq!(e["derivatives"].as_array().unwrap().len(), 1);
    }
}

#[test]
fn eval_outside_the_domain_fails_plainly() {
    let err = failure(
        camber()
            .arg("eval")
            .arg(curve_path(CURVES[0]))
            .args(["--at", "0.5,1.5"]),
    );
    assert!(err.contains("bezier_cubic.json"), "{err}");
    assert!(
        err.contains("parameter 1.5 is outside the domain [0, 1]"),
        "{err}"
    );
}

// ---------------------------------------------------------------- op

fn run_op(input: &Path, op: &[&str], out: &Path) -> Curve {
    camber()
        .arg("op")
        .arg(input)
        .args(op)
        .arg("-o")
        .arg(out)
        .assert()
        .success();
    curve_file::load(out).unwrap()
}

#[test]
fn split_pieces_cover_the_curve() {
    let dir = tempfile::tempdir().unwrap();
    for name in CURVES {
        let input = curve_path(name);
        let curve = curve_file::load(&input).unwrap();
        let (a, b) = curve.as_parametric().domain();
        let u = a + 0.37 * (b - a);
        let (first, second) = (
            dir.path().join("first.json"),
            dir.path().join("second.json"),
        );
        camber()
            .arg("op")
            .arg(&input)
            .args(["split", "--at", &u.to_string(), "-o"])
            .arg(&first)
            .arg("--second")
            .arg(&second)
            .assert()
            .success()
            .stdout(
                predicate::str::contains("first.json").and(predicate::str::contains("second.json")),
            );
        let (c1, c2) = (
            curve_file::load(&first).unwrap(),
            curve_file::load(&second).unwrap(),
        );
        assert_eq!(c1.type_name(), curve.type_name());
        // Each piece, walked over its own domain, retraces its part of the original.
        for (piece, (lo, hi)) in [(&c1, (a, u)), (&c2, (u, b))] {
            let (pa, pb) = piece.as_parametric().domain();
            for s in [0.0, 0.25, 0.5, 0.75, 1.0] {
                let here = point_of(piece, pa + s * (pb - pa));
                let there = point_of(&curve, lo + s * (hi - lo));
                assert!((here - there).norm() < 1e-12, "{name} at {s}");
            }
        }
    }
}

#[test]
fn shape_preserving_ops_keep_the_points() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.json");
    for name in ["bspline_camber_line.json", "nurbs_quarter_circle.json"] {
        let input = curve_path(name);
        let curve = curve_file::load(&input).unwrap();
        for op in [
            &["insert-knot", "--at", "0.4", "--times", "2"][..],
            &["elevate", "--times", "2"][..],
        ] {
            let result = run_op(&input, op, &out);
            for u in spread(&curve, 8) {
                assert!(
                    (point_of(&result, u) - point_of(&curve, u)).norm() < 1e-12,
                    "{name} {op:?}"
                );
            }
        }
        let result = run_op(&input, &["reparam", "--to", "-2,3"], &out);
        let (a, b) = result.as_parametric().domain();
        assert!((a + 2.0).abs() < 1e-15 && (b - 3.0).abs() < 1e-15);
        for s in [0.0, 0.3, 1.0] {
            assert!((point_of(&result, -2.0 + 5.0 * s) - point_of(&curve, s)).norm() < 1e-12);
        }
    }
    // A Bézier curve elevates too, and reports its new degree.
    camber()
        .arg("op")
        .arg(curve_path(CURVES[0]))
        .args(["elevate", "-o"])
        .arg(&out)
        .assert()
        .success()
        .stdout(predicate::str::contains(
            "bezier, degree 4, 5 control points",
        ));
}

#[test]
fn reverse_runs_backwards_for_every_type() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("rev.json");
    for name in CURVES {
        let input = curve_path(name);
        let curve = curve_file::load(&input).unwrap();
        let rev = run_op(&input, &["reverse"], &out);
        let (a, b) = curve.as_parametric().domain();
        for u in spread(&curve, 5) {
            assert!(
                (point_of(&rev, a + b - u) - point_of(&curve, u)).norm() < 1e-12,
                "{name}"
            );
        }
    }
}

#[test]
fn ops_that_do_not_apply_say_so() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("x.json");
    let cases = [
        (
            "bezier_cubic.json",
            &["insert-knot", "--at", "0.5"][..],
            "insert-knot is not available for bezier",
        ),
        (
            "hermite_s.json",
            &["elevate"][..],
            "elevate is not available for hermite",
        ),
        (
            "hermite_s.json",
            &["reparam", "--to", "0,2"][..],
            "reparam is not available for hermite",
        ),
        (
            "bezier_cubic.json",
            &["split", "--at", "1", "--second", "y.json"][..],
            "cannot split at 1",
        ),
        (
            "bezier_cubic.json",
            &["elevate", "--times", "1000000000000"][..],
            "degree 1000000000003 is above the largest supported degree",
        ),
    ];
    for (name, op, message) in cases {
        let err = failure(
            camber()
                .arg("op")
                .arg(curve_path(name))
                .args(op)
                .arg("-o")
                .arg(&out),
        );
        assert!(err.contains(name) && err.contains(message), "{err}");
    }
    assert!(!out.exists());
}

// ---------------------------------------------------------------- render-curve

fn view_box(doc: &roxmltree::Document) -> [f64; 4] {
    let vb: Vec<f64> = doc
        .root_element()
        .attribute("viewBox")
        .expect("a viewBox")
        .split_whitespace()
        .map(|t| t.parse().unwrap())
        .collect();
    [vb[0], vb[1], vb[2], vb[3]]
}

fn count(doc: &roxmltree::Document, tag: &str) -> usize {
    doc.descendants().filter(|n| n.has_tag_name(tag)).count()
}

/// Every polyline vertex of the document, in SVG coordinates.
fn polyline_points(doc: &roxmltree::Document) -> Vec<(f64, f64)> {
    doc.descendants()
        .filter(|n| n.has_tag_name("polyline"))
        .flat_map(|n| {
            n.attribute("points")
                .unwrap()
                .split_whitespace()
                .map(|xy| {
                    let (x, y) = xy.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect::<Vec<_>>()
        })
        .collect()
}

#[test]
fn render_curve_writes_a_parsable_picture() {
    let dir = tempfile::tempdir().unwrap();
    for name in CURVES {
        let curve = curve_file::load(&curve_path(name)).unwrap();
        let n_ctrl = curve.control_polygon().len();
        let pieces = curve.as_parametric().breakpoints().len() - 1;
        for combs in [false, true] {
            let pic = dir.path().join("pic.svg");
            let mut cmd = camber();
            cmd.arg("render-curve")
                .arg(curve_path(name))
                .arg("-o")
                .arg(&pic);
            if combs {
                cmd.arg("--combs");
            }
            cmd.assert().success();
            let text = std::fs::read_to_string(&pic).unwrap();
            let doc = roxmltree::Document::parse(&text).expect("well-formed SVG");
            assert!(doc.root_element().has_tag_name("svg"));
            // Curve + control polygon (+ comb envelope); one dot per control point; a caption.
            assert_eq!(count(&doc, "polyline"), if combs { 3 } else { 2 }, "{name}");
            assert_eq!(count(&doc, "circle"), n_ctrl, "{name}");
            assert_eq!(count(&doc, "text"), 1);
            let teeth = if combs {
                pieces * camber_cli::draw::TEETH_PER_PIECE + 1
            } else {
                0
            };
            assert_eq!(count(&doc, "line"), teeth, "{name}");
            // The viewBox has a positive size and holds everything drawn.
            let [x, y, w, h] = view_box(&doc);
            assert!(w > 0.0 && h > 0.0);
            for (px, py) in polyline_points(&doc) {
                assert!(
                    px >= x && px <= x + w && py >= y && py <= y + h,
                    "{name}: ({px}, {py})"
                );
            }
        }
    }
}

#[test]
fn render_curve_flips_y() {
    // The Bézier arch bulges upwards (y up to 1.5), so in SVG its middle is above (smaller y
    // than) its ends.
    let dir = tempfile::tempdir().unwrap();
    let pic = dir.path().join("arch.svg");
    camber()
        .arg("render-curve")
        .arg(curve_path(CURVES[0]))
        .arg("-o")
        .arg(&pic)
        .assert()
        .success();
    let text = std::fs::read_to_string(&pic).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let curve = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline"))
        .find(|n| n.attribute("stroke-dasharray").is_none())
        .unwrap();
    let pts: Vec<(f64, f64)> = curve
        .attribute("points")
        .unwrap()
        .split_whitespace()
        .map(|xy| {
            let (x, y) = xy.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect();
    let (first, mid) = (pts[0], pts[pts.len() / 2]);
    assert!(mid.1 < first.1);
    // The arch is 4 wide and 1.5 high: the SVG extents keep that ratio.
    let xs = pts.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max) - first.0;
    let ys = first.1 - mid.1;
    assert_relative_eq!(xs / ys, 4.0 / 1.5, epsilon = 1e-4);
}

// ---------------------------------------------------------------- surface

#[test]
fn surface_removes_the_crease_and_plots() {
    let dir = tempfile::tempdir().unwrap();
    let (out, plot) = (dir.path().join("face.json"), dir.path().join("plot.svg"));
    let case = root().join("examples/data/surface_crease10.json");
    let assert = camber()
        .arg("surface")
        .arg(&case)
        .arg("-o")
        .arg(&out)
        .arg("--plot")
        .arg(&plot)
        .assert()
        .success();
    let stdout = String::from_utf8(assert.get_output().stdout.clone()).unwrap();
    assert!(stdout.contains("before max 10.0000°"), "{stdout}");
    assert!(stdout.contains("tolerances met"), "{stdout}");
    // The after angle printed on the edge line is below 0.1°.
    let after: f64 = stdout
        .split("after max ")
        .nth(1)
        .and_then(|s| s.split('°').next())
        .and_then(|s| s.parse().ok())
        .expect("an after angle");
    assert!(after < 0.1, "{after}");
    // The written face is a valid surface of the same net size as the input face.
    let face: NurbsSurface<f64> =
        serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let input: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&case).unwrap()).unwrap();
    let input_face: NurbsSurface<f64> = serde_json::from_value(input["face"].clone()).unwrap();
    assert_eq!(face.counts(), input_face.counts());
    // The plot: axes (2 lines), before and after per edge (2 polylines), labels.
    let text = std::fs::read_to_string(&plot).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    assert_eq!(count(&doc, "polyline"), 2);
    assert_eq!(count(&doc, "line"), 2);
    assert!(count(&doc, "text") >= 4);
    let [_, _, w, h] = view_box(&doc);
    assert!(w > h && h > 0.0);
}

#[test]
fn surface_with_a_bad_case_fails_plainly() {
    let dir = tempfile::tempdir().unwrap();
    let case = dir.path().join("case.json");
    std::fs::write(&case, r#"{"face": {"degree_u": 3}, "neighbours": []}"#).unwrap();
    let err = failure(
        camber()
            .arg("surface")
            .arg(&case)
            .arg("-o")
            .arg(dir.path().join("o.json")),
    );
    assert!(err.contains("case.json") && err.contains("face"), "{err}");
}

// ---------------------------------------------------------------- bad files and usage

#[test]
fn bad_curve_files_fail_with_one_plain_line() {
    let cases = [
        ("malformed.json", "malformed JSON"),
        ("non_finite.json", "non-finite number"),
        ("wrong_knot_count.json", "need 7 knots, found 6"),
        ("unknown_type.json", "unknown curve type \"clothoid\""),
    ];
    let dir = tempfile::tempdir().unwrap();
    for (name, message) in cases {
        let path = bad_path(name);
        for args in [
            vec![
                "eval".to_owned(),
                path.display().to_string(),
                "--at".into(),
                "0.5".into(),
            ],
            vec![
                "render-curve".to_owned(),
                path.display().to_string(),
                "-o".into(),
                dir.path().join("p.svg").display().to_string(),
            ],
            vec![
                "op".to_owned(),
                path.display().to_string(),
                "reverse".into(),
                "-o".into(),
                dir.path().join("r.json").display().to_string(),
            ],
        ] {
            let err = failure(camber().args(&args));
            assert!(err.contains(name) && err.contains(message), "{err}");
        }
    }
}

#[test]
fn a_bad_field_is_named_by_its_path() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("typo.json");
    std::fs::write(&path, r#"{"type": "nurbs", "degree": 1, "knots": [0, 0, 1, 1], "control_points": [[0, 0], [1, 1]], "weights": [1, "heavy"]}"#).unwrap();
    let err = failure(camber().arg("eval").arg(&path).args(["--at", "0"]));
    assert!(err.contains("at weights[1]"), "{err}");
}

#[test]
fn a_missing_file_is_named() {
    let err = failure(camber().args(["eval", "no/such/curve.json", "--at", "0"]));
    assert!(err.contains("no/such/curve.json: cannot read"), "{err}");
}

#[test]
fn usage_errors_exit_2_and_help_exits_0() {
    camber()
        .arg("eval")
        .arg(curve_path(CURVES[0]))
        .assert()
        .failure()
        .code(2);
    camber().args(["frobnicate"]).assert().failure().code(2);
    camber()
        .arg("--help")
        .assert()
        .success()
        .stdout(predicate::str::contains("\"type\": \"bspline\""));
    camber()
        .args(["op", "--help"])
        .assert()
        .success()
        .stdout(predicate::str::contains("--second"));
}
