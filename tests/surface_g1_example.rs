//! The `surface_g1` example writes its plot where it says (issue 11, finding 10): a folder
//! given on the command line is created, the default is the system's temporary folder, and
//! nothing goes into the repository's `target/` folder, wherever `CARGO_TARGET_DIR` points.
//!
//! The example's own code is compiled into this test (`#[path]`), so the test runs what
//! `cargo run --example surface_g1` runs; when `cargo test` has built the example binary too,
//! it is also run as a process with `CARGO_TARGET_DIR`, `TMPDIR` and the working folder all
//! pointing to fresh temporary folders.

#![allow(clippy::unwrap_used)]

#[allow(dead_code)] // its `main` is not called here
#[path = "../examples/surface_g1.rs"]
mod surface_g1;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// The names directly in the repository's `target/` folder (empty when there is none).
fn repo_target_entries() -> BTreeSet<String> {
    let target = Path::new(env!("CARGO_MANIFEST_DIR")).join("target");
    std::fs::read_dir(target)
        .map(|d| {
            d.filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default()
}

/// The plot is an SVG with the before and after polylines, each with points.
fn assert_plot(path: &Path) {
    let text = std::fs::read_to_string(path).unwrap();
    assert!(text.starts_with("<svg"), "{}", path.display());
    let polylines = text.matches("<polyline").count();
    assert_eq!(polylines, 2, "{text}");
    assert!(!text.contains("points=\"\""), "{text}");
}

#[test]
fn the_plot_goes_into_a_folder_it_creates_and_never_into_target() {
    let before = repo_target_entries();
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("not/there/yet/plot.svg");
    assert!(!out.parent().unwrap().exists());
    let written = surface_g1::run(&out).unwrap();
    assert_eq!(written.as_deref(), Some(out.as_path()));
    assert_plot(&out);
    let after = repo_target_entries();
    assert!(
        after.is_subset(&before) || after.difference(&before).all(|n| !n.contains("surface")),
        "new in target/: {:?}",
        after.difference(&before).collect::<Vec<_>>()
    );
    assert!(!Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("target/surface_g1.svg")
        .exists());
}

#[test]
fn the_default_plot_goes_to_the_temporary_folder() {
    let path = surface_g1::default_plot_path();
    assert_eq!(path.parent(), Some(std::env::temp_dir().as_path()));
    assert!(!path.starts_with(env!("CARGO_MANIFEST_DIR")));
}

/// The example binary `cargo test` built next to this test's own binary, if any.
fn example_binary() -> Option<PathBuf> {
    let exe = std::env::current_exe().ok()?;
    let debug = exe.parent()?.parent()?;
    let name = format!("surface_g1{}", std::env::consts::EXE_SUFFIX);
    let path = debug.join("examples").join(name);
    path.is_file().then_some(path)
}

#[test]
fn the_built_example_runs_with_the_target_folder_elsewhere() {
    let Some(binary) = example_binary() else {
        // `cargo test --test surface_g1_example` alone does not build examples; the tests
        // above run the same code.
        eprintln!("surface_g1 example binary not built; skipped the process run");
        return;
    };
    let before = repo_target_entries();
    let (target, tmp, cwd) = (
        tempfile::tempdir().unwrap(),
        tempfile::tempdir().unwrap(),
        tempfile::tempdir().unwrap(),
    );
    let run = |args: &[&Path]| {
        let out = std::process::Command::new(&binary)
            .args(args)
            .env("CARGO_TARGET_DIR", target.path())
            .env("TMPDIR", tmp.path())
            .current_dir(cwd.path())
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    };
    // Without an argument: the plot lands in the temporary folder.
    run(&[]);
    assert_plot(&tmp.path().join("surface_g1.svg"));
    // With a path in folders that do not exist yet: they are created.
    let given = cwd.path().join("plots/new/g1.svg");
    run(&[given.as_path()]);
    assert_plot(&given);
    // Nothing else was written: not in the fresh target folder, not beside the binary's cwd.
    assert_eq!(std::fs::read_dir(target.path()).unwrap().count(), 0);
    assert_eq!(std::fs::read_dir(cwd.path()).unwrap().count(), 1); // plots/
    assert_eq!(std::fs::read_dir(tmp.path()).unwrap().count(), 1);
    let after = repo_target_entries();
    assert!(
        after.difference(&before).all(|n| !n.contains("surface")),
        "new in target/: {:?}",
        after.difference(&before).collect::<Vec<_>>()
    );
}
