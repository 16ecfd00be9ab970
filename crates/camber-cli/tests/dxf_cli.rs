//! `camber import` and `camber export` on DXF files (and `camber import` on an SVG document):
//! a bundled sketch out and back in, skipped items on stderr, `--strict`, and refused formats.
#![allow(clippy::unwrap_used)] // helpers outside #[test] functions unwrap like the tests do

use std::path::PathBuf;

use assert_cmd::Command;
use predicates::prelude::*;

fn camber() -> Command {
    Command::cargo_bin("camber").expect("the camber binary is built")
}

fn bundled(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/sketches")
        .join(name)
}

#[test]
fn a_bundled_sketch_exports_and_imports_back_with_its_geometry() {
    let dir = tempfile::tempdir().unwrap();
    for binary in [false, true] {
        let dxf = dir.path().join(format!("plate{binary}.dxf"));
        let back = dir.path().join(format!("plate{binary}.json"));
        let mut export = camber();
        export
            .arg("export")
            .arg(bundled("rounded_plate.json"))
            .arg("-o")
            .arg(&dxf);
        if binary {
            export.arg("--binary");
        }
        export
            .assert()
            .success()
            .stdout(predicate::str::starts_with("wrote 8 entities"));
        camber()
            .arg("import")
            .arg(&dxf)
            .arg("-o")
            .arg(&back)
            .assert()
            .success()
            .stdout(predicate::str::contains(
                "imported 8 entities and 8 joins; 0 items skipped",
            ));
        let original = camber_sketch::file::from_json(
            &std::fs::read_to_string(bundled("rounded_plate.json")).unwrap(),
        )
        .unwrap();
        let imported =
            camber_sketch::file::from_json(&std::fs::read_to_string(&back).unwrap()).unwrap();
        let (a, b): (Vec<_>, Vec<_>) = (
            original.entities().map(|(_, e)| e.clone()).collect(),
            imported.entities().map(|(_, e)| e.clone()).collect(),
        );
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(&b) {
            assert_eq!(
                std::mem::discriminant(x),
                std::mem::discriminant(y),
                "{x:?} vs {y:?}"
            );
        }
        // The imported plate is closed and consistent: checking it finds no conflict.
        camber().arg("check").arg(&back).assert().success();
    }
}

#[test]
fn skipped_items_are_listed_on_stderr_and_strict_refuses_them() {
    let dir = tempfile::tempdir().unwrap();
    let dxf = dir.path().join("mixed.dxf");
    std::fs::write(
        &dxf,
        "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\n\
         0\nTEXT\n5\n2F\n10\n0\n20\n0\n40\n1\n1\nhello\n0\nENDSEC\n0\nEOF\n",
    )
    .unwrap();
    let out = dir.path().join("mixed.json");
    camber()
        .arg("import")
        .arg(&dxf)
        .arg("-o")
        .arg(&out)
        .assert()
        .success()
        .stderr(
            predicate::str::contains("skipped:")
                .and(predicate::str::contains("TEXT 1 (handle 2F)")),
        )
        .stdout(predicate::str::contains(
            "imported 1 entities and 0 joins; 1 items skipped",
        ));
    let strict = dir.path().join("strict.json");
    camber()
        .arg("import")
        .arg(&dxf)
        .arg("-o")
        .arg(&strict)
        .arg("--strict")
        .assert()
        .code(2)
        .stderr(predicate::str::contains("nothing written"));
    assert!(!strict.exists());
}

#[test]
fn unknown_formats_and_bad_files_are_refused_plainly() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("a.step");
    std::fs::write(&svg, "x").unwrap();
    camber()
        .arg("import")
        .arg(&svg)
        .arg("-o")
        .arg(dir.path().join("a.json"))
        .assert()
        .code(2)
        .stderr(predicate::str::contains("unknown input format"));
    let bad = dir.path().join("bad.dxf");
    std::fs::write(
        &bad,
        "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\nx\n0\nENDSEC\n0\nEOF\n",
    )
    .unwrap();
    camber()
        .arg("import")
        .arg(&bad)
        .arg("-o")
        .arg(dir.path().join("b.json"))
        .assert()
        .code(2)
        .stderr(predicate::str::contains("bad.dxf: not a readable DXF file"));
    camber()
        .arg("export")
        .arg(bundled("rounded_plate.json"))
        .arg("-o")
        .arg(dir.path().join("out.svg"))
        .assert()
        .code(2)
        .stderr(predicate::str::contains("unknown output format"));
}

#[test]
fn an_svg_document_imports_with_its_joins() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("slot.svg");
    // A slot: two lines and two half circles, closed; every join smooth.
    std::fs::write(
        &svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg"><path d="M 0 0 L 4 0 A 1 1 0 0 0 4 -2 L 0 -2 A 1 1 0 0 0 0 0 Z"/><text>note</text></svg>"#,
    )
    .unwrap();
    let out = dir.path().join("slot.json");
    camber()
        .arg("import")
        .arg(&svg)
        .arg("-o")
        .arg(&out)
        .assert()
        .success()
        .stdout(predicate::str::contains("imported 4 entities"))
        .stderr(predicate::str::contains("skipped:").and(predicate::str::contains("text")));
    camber().arg("check").arg(&out).assert().success();
}

#[test]
fn an_svg_in_millimetres_imports_in_user_units_or_millimetres() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("plate.svg");
    // 100 mm × 50 mm drawn in a 200 × 100 viewBox: the line to (200, 100) ends at (100, −50) mm
    // upright.
    std::fs::write(
        &svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 200 100"><line x1="0" y1="0" x2="200" y2="100"/></svg>"#,
    )
    .unwrap();
    let line_end = |units: &str| {
        let out = dir.path().join(format!("{units}.json"));
        camber()
            .arg("import")
            .arg(&svg)
            .arg("-o")
            .arg(&out)
            .arg("--svg-units")
            .arg(units)
            .assert()
            .success()
            .stdout(predicate::str::contains("imported 1 entities"));
        let sketch =
            camber_sketch::file::from_json(&std::fs::read_to_string(&out).unwrap()).unwrap();
        let (_, line) = sketch.entities().next().unwrap();
        line.points()[1]
    };
    let user = line_end("user");
    assert!(
        (user - nalgebra::Point2::new(200.0, -100.0)).norm() < 1e-12,
        "{user}"
    );
    let mm = line_end("mm");
    assert!(
        (mm - nalgebra::Point2::new(100.0, -50.0)).norm() < 1e-12,
        "{mm}"
    );
    camber()
        .arg("import")
        .arg(&svg)
        .arg("-o")
        .arg(dir.path().join("x.json"))
        .arg("--svg-units")
        .arg("furlong")
        .assert()
        .code(2)
        .stderr(predicate::str::contains("furlong"));
}
