//! Replays every committed fuzz input (fuzz/corpus/<target>/: the seeds and every crash
//! reproducer) through the same function the fuzz target runs (camber_cli::fuzz_support), as
//! an ordinary test: a fixed finding stays fixed without cargo-fuzz or a nightly toolchain.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;

use camber_cli::fuzz_support;

/// Runs `target` on every file of fuzz/corpus/`name`/, naming every file that panics.
fn replay(name: &str, target: fn(&[u8])) {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../fuzz/corpus")
        .join(name);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .map(|entry| entry.map(|e| e.path()))
        .collect::<Result<_, _>>()
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()));
    files.sort();
    assert!(!files.is_empty(), "{} holds no inputs", dir.display());
    let mut failed = Vec::new();
    for file in &files {
        let data = std::fs::read(file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        if catch_unwind(AssertUnwindSafe(|| target(&data))).is_err() {
            failed.push(file.display().to_string());
        }
    }
    assert!(
        failed.is_empty(),
        "{} of {} {name} inputs fail: {failed:?}",
        failed.len(),
        files.len()
    );
}

#[test]
fn sketch_corpus_replays() {
    replay("sketch", fuzz_support::sketch);
}

#[test]
fn curve_corpus_replays() {
    replay("curve", fuzz_support::curve);
}

#[test]
fn surface_corpus_replays() {
    replay("surface", fuzz_support::surface);
}

#[test]
fn editor_corpus_replays() {
    replay("editor", fuzz_support::editor);
}

#[test]
fn expression_corpus_replays() {
    replay("expression", fuzz_support::expression);
}

#[test]
fn fit_corpus_replays() {
    replay("fit", fuzz_support::fit);
}

#[test]
fn toolkit_corpus_replays() {
    replay("toolkit", fuzz_support::toolkit);
}

#[test]
fn dxf_corpus_replays() {
    replay("dxf", fuzz_support::dxf);
}

#[test]
fn svg_corpus_replays() {
    replay("svg", fuzz_support::svg);
}
