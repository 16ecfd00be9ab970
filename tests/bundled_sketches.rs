//! The bundled sketches in examples/sketches/ that come from workload builders: each file is
//! exactly its builder's output (rerun with CAMBER_BLESS=1 to rewrite it), loads, round-trips
//! (save∘load is the identity, before and after solving) and solves to a result that passes
//! the workload's own validity check.

#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

use std::path::PathBuf;

use camber::sketch::file::{from_json, to_json};
use camber::sketch::Sketch;
use camber_workloads::{
    rounded_plate, two_curves, two_curves_valid, w2_bspline7, w2_valid, w3a_chain, w3a_valid,
    w5r_valid,
};

fn path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("examples/sketches")
        .join(name)
}

/// Checks (or, with CAMBER_BLESS=1, writes) a bundled file against its builder, and returns
/// the sketch loaded from the file.
fn bundled(name: &str, built: &Sketch) -> Sketch {
    let text = to_json(built).unwrap();
    if std::env::var_os("CAMBER_BLESS").is_some() {
        std::fs::write(path(name), &text).unwrap();
    }
    let on_disk = std::fs::read_to_string(path(name)).unwrap();
    assert_eq!(
        on_disk, text,
        "{name} is out of date: rerun with CAMBER_BLESS=1"
    );
    let loaded = from_json(&on_disk).unwrap();
    assert_eq!(to_json(&loaded).unwrap(), on_disk, "{name}: save∘load");
    loaded
}

/// Solves and checks that the solved sketch round-trips too.
fn solve_and_round_trip(name: &str, s: &mut Sketch) {
    let report = s.solve().unwrap();
    assert!(!report.components.is_empty(), "{name}");
    let solved = to_json(s).unwrap();
    assert_eq!(
        to_json(&from_json(&solved).unwrap()).unwrap(),
        solved,
        "{name}: solved save∘load"
    );
}

#[test]
fn diffuser_is_w2_bspline7_and_solves_valid() {
    let (built, w) = w2_bspline7().unwrap();
    let mut s = bundled("diffuser.json", &built);
    // Ids are kept, so the builder's ids name the loaded entities.
    assert!(!w2_valid(&s, &w), "the rough start is not yet tangent");
    solve_and_round_trip("diffuser.json", &mut s);
    assert!(w2_valid(&s, &w));
}

#[test]
fn two_curves_is_the_builder_and_solves_valid() {
    let (built, t) = two_curves().unwrap();
    let mut s = bundled("two_curves.json", &built);
    assert!(!two_curves_valid(&s, &t, 1e-6), "the curves start apart");
    solve_and_round_trip("two_curves.json", &mut s);
    assert!(two_curves_valid(&s, &t, 1e-6));
}

#[test]
fn the_large_chain_is_w3a_and_solves_valid() {
    let (built, segs) = w3a_chain(1000).unwrap();
    let mut s = bundled("w3a_chain_1000.json", &built);
    solve_and_round_trip("w3a_chain_1000.json", &mut s);
    assert!(w3a_valid(&s, &segs, 1e-9));
}

#[test]
fn the_rounded_plate_is_its_builder_and_stays_valid_when_solved() {
    let (built, r) = rounded_plate().unwrap();
    let mut s = bundled("rounded_plate.json", &built);
    assert!(w5r_valid(&s, &r, 1e-9), "drawn satisfied");
    solve_and_round_trip("rounded_plate.json", &mut s);
    assert!(w5r_valid(&s, &r, 1e-9));
}

#[test]
fn every_bundled_sketch_round_trips_and_solves() {
    let mut names: Vec<String> = std::fs::read_dir(path(""))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".json"))
        .collect();
    names.sort();
    for name in &names {
        let text = std::fs::read_to_string(path(name)).unwrap();
        let mut s = from_json(&text).unwrap();
        assert_eq!(to_json(&s).unwrap(), text, "{name}: save∘load");
        solve_and_round_trip(name, &mut s);
    }
    for expected in [
        "blade_section.json",
        "diffuser.json",
        "rounded_plate.json",
        "two_curves.json",
        "w3a_chain_1000.json",
    ] {
        assert!(names.iter().any(|n| n == expected), "{expected} is bundled");
    }
}
