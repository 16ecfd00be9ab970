//! What the fuzz targets in `fuzz/` run on one input, shared with the replay test
//! (`tests/fuzz_corpus.rs`) that runs every committed corpus file and crash reproducer as an
//! ordinary test, so both call exactly the same code.
//!
//! Each function takes the raw bytes libFuzzer made and returns normally for any input the
//! commands handle correctly: refused with an error, or accepted with a result that holds the
//! promises below. A broken promise panics, and libFuzzer records the input as a crash.
//!
//! - [`sketch`]: sketch file bytes → load → check (DOF analysis and warnings) → render →
//!   solve. A failed solve leaves the sketch exactly as it was; a successful one leaves every
//!   residual within tolerance and a sketch that solves again; a loaded or solved sketch saves
//!   to a file that loads again.
//! - [`curve`]: curve file bytes → load → evaluate, draw, and every `camber op` at a few
//!   parameters; every result saves to a file that loads again.
//! - [`surface`]: a surface case → G1 deformation → report and plot.
//! - [`expression()`]: rows of expression text compiled against a fixed sketch, evaluated,
//!   differentiated, added and solved.
//! - [`editor`]: a script of requests to [`EditorState::handle`] on a bundled sketch; no
//!   answer is a 500 (an internal failure), every answer to an API path is JSON, and the state
//!   stays readable.
//! - [`fit()`]: a point file (JSON, columns, Selig or Lednicer) parsed and fitted to a
//!   tolerance, whole and split at the leading edge; a fit is within its tolerance.
//! - [`dxf()`]: DXF bytes (text or binary) imported as a sketch, saved and loaded, exported
//!   and imported again; its documentation lists the promises checked.
//! - [`svg()`]: SVG path data or a whole document imported into a sketch; every coincident
//!   join holds as imported and the sketch saves to a file that loads again.
//! - [`toolkit()`]: one or two curves and some numbers through every curve-toolkit operation
//!   under a small work budget; its documentation lists the promises checked.
//!
//! The work per input is bounded here (input size, entity and constraint counts, degrees,
//! repeat counts, the evaluations a solve may spend), so that one input cannot take the
//! fuzzer's time.

use std::path::PathBuf;

use camber_surface::examples::DeformationCase;
use camber_surface::{deform_to_g1, DeformOptions};

use crate::commands::op::{Op, Output};
use crate::commands::{check, eval, render, render_curve, solve, surface as surface_cmd};
use crate::curve_file::Curve;
use crate::editor::EditorState;

mod expression;
pub use expression::expression;

mod dxf;
mod fit;
mod svg;
mod toolkit;
pub use dxf::dxf;
pub use fit::{fit, FIT_WORK};
pub use svg::svg;
pub use toolkit::{toolkit, TOOLKIT_WORK};

/// The largest input any target reads, in bytes (libFuzzer's `-max_len` should not exceed it).
pub const MAX_INPUT: usize = 64 * 1024;

/// The largest sketch solved: entities plus constraints.
pub const MAX_SKETCH_ITEMS: usize = 64;

/// The evaluations one sketch solve may spend
/// ([`camber_solve::NonlinearOptions::max_evaluations`]): a twenty-fifth of the library's
/// default, so that a sketch that cannot be solved fails within the fuzzer's time even under
/// AddressSanitizer.
pub const SKETCH_SOLVE_EVALUATIONS: usize = 2_000;

/// The most requests one editor script sends.
pub const MAX_REQUESTS: usize = 48;

fn text(data: &[u8]) -> Option<&str> {
    if data.len() > MAX_INPUT {
        return None;
    }
    std::str::from_utf8(data).ok()
}

/// A sketch file's bytes: load, check, render, solve (see the module documentation).
///
/// # Panics
/// When the commands break a promise on this input (the fuzzer's finding).
pub fn sketch(data: &[u8]) {
    let Some(text) = text(data) else { return };
    let Ok(mut s) = crate::sketch_file::parse(text) else {
        return;
    };
    if s.entities().count() + s.constraints().count() > MAX_SKETCH_ITEMS {
        return;
    }
    let mut options = s.options().clone();
    options.nonlinear = options
        .nonlinear
        .with_max_evaluations(Some(SKETCH_SOLVE_EVALUATIONS));
    s.set_options(options);
    let saved = reloads(&s, "the loaded sketch");
    let _ = s.warnings();
    let _ = check::check(&s);
    let _ = render::picture(&s, true);
    match solve::solve(&mut s) {
        Err(e) => {
            let after = camber_sketch::file::to_json(&s).ok();
            assert_eq!(
                after.as_deref(),
                Some(saved.as_str()),
                "a failed solve ({e:#}) changed the sketch"
            );
        }
        Ok(report) => {
            let _ = solve::format_report(&report);
            let tolerance = s.options().tolerance;
            for comp in &report.components {
                for r in &comp.report.residuals {
                    assert!(
                        r.max_abs <= tolerance,
                        "solve succeeded with constraint {} at {:e}",
                        r.constraint.0,
                        r.max_abs
                    );
                }
            }
            reloads(&s, "the solved sketch");
            let _ = render::picture(&s, false);
            // The written-back state is a solution: solving it again succeeds.
            if let Err(e) = solve::solve(&mut s) {
                panic!("the solved sketch fails its next solve: {e:#}");
            }
        }
    }
}

/// Saves the sketch and loads the text again; returns the text.
fn reloads(s: &camber_sketch::Sketch, what: &str) -> String {
    let json = match camber_sketch::file::to_json(s) {
        Ok(json) => json,
        Err(e) => panic!("{what} cannot be saved: {e}"),
    };
    if let Err(e) = crate::sketch_file::parse(&json) {
        panic!("{what} saves to a file that does not load: {e:#}\n{json}");
    }
    json
}

/// The highest degree of a curve that the ops below elevate or insert knots into.
const MAX_DEGREE: usize = 16;

/// A curve file's bytes: load, evaluate, draw, every op (see the module documentation).
///
/// # Panics
/// When the commands break a promise on this input (the fuzzer's finding).
pub fn curve(data: &[u8]) {
    let Some(text) = text(data) else { return };
    let Ok(c) = Curve::from_json(text) else {
        return;
    };
    let (a, b) = c.as_parametric().domain();
    let inside = [0.0, 0.25, 0.5, 0.999, 1.0].map(|t| a + (b - a) * t);
    let outside = [a - 1.0, b + 1.0, f64::NAN, f64::INFINITY];
    let degree = degree(&c);
    let _ = eval::evaluate(c.as_parametric(), &inside, (degree + 2).min(8));
    let _ = eval::evaluate(c.as_parametric(), &outside, 1);
    let _ = crate::curve_file::describe(&c);
    if degree <= MAX_DEGREE {
        let _ = render_curve::picture(&c, true);
    }
    let out = || Output {
        output: PathBuf::from("unused.json"),
    };
    let mut ops = vec![Op::Reverse { out: out() }];
    for u in [inside[1], inside[2], inside[3], a, b] {
        ops.push(Op::Split {
            at: u,
            out: out(),
            second: PathBuf::from("unused2.json"),
        });
    }
    if degree <= MAX_DEGREE {
        ops.push(Op::Elevate {
            times: 1,
            out: out(),
        });
        ops.push(Op::Elevate {
            times: 3,
            out: out(),
        });
        for (u, times) in [
            (inside[2], 1),
            (inside[1], degree + 1),
            (inside[3], degree + 2),
        ] {
            ops.push(Op::InsertKnot {
                at: u,
                times,
                out: out(),
            });
        }
    }
    for to in [
        (0.0, 1.0),
        (-2.5, 7.0),
        (1e-9, 2e-9),
        (5.0, 5.0),
        (3.0, -3.0),
    ] {
        ops.push(Op::Reparam { to, out: out() });
    }
    for op in &ops {
        let Ok(results) = op.apply(&c) else { continue };
        for r in &results {
            let json = match r.to_json() {
                Ok(json) => json,
                Err(e) => panic!("{} gave a curve that cannot be saved: {e:#}", op.name()),
            };
            if let Err(e) = Curve::from_json(&json) {
                panic!(
                    "{} gave a curve whose file does not load: {e:#}\n{json}",
                    op.name()
                );
            }
        }
    }
}

fn degree(c: &Curve) -> usize {
    match c {
        Curve::Bezier(c) => c.degree(),
        Curve::BSpline(c) => c.degree(),
        Curve::Nurbs(c) => c.degree(),
        Curve::Hermite(_) => 3,
    }
}

/// The largest face deformed: control points per direction, and neighbours.
const MAX_FACE_SIDE: usize = 12;
const MAX_NEIGHBOURS: usize = 4;

/// A surface case's bytes: deform the face, report and plot (see the module documentation).
///
/// # Panics
/// When the deformation breaks a promise on this input (the fuzzer's finding).
pub fn surface(data: &[u8]) {
    let Some(text) = text(data) else { return };
    let Ok(case) = serde_json::from_str::<DeformationCase>(text) else {
        return;
    };
    let (n, m) = case.face.counts();
    if n > MAX_FACE_SIDE || m > MAX_FACE_SIDE || case.neighbours.len() > MAX_NEIGHBOURS {
        return;
    }
    if let Ok((face, report)) =
        deform_to_g1(&case.face, &case.neighbours, &DeformOptions::default())
    {
        let _ = surface_cmd::report_text(&report);
        let _ = surface_cmd::plot(&report);
        let json = match serde_json::to_string(&face) {
            Ok(json) => json,
            Err(e) => panic!("the deformed face cannot be saved: {e}"),
        };
        if let Err(e) = serde_json::from_str::<camber_surface::NurbsSurface<f64>>(&json) {
            panic!("the deformed face saves to a file that does not load: {e}\n{json}");
        }
    }
}

/// The bundled sketches an editor script can start from (its first line `sketch NAME`).
const SKETCHES: [(&str, &str); 3] = [
    ("blade_section", crate::commands::demo::BLADE_SECTION),
    (
        "two_curves",
        include_str!("../../../examples/sketches/two_curves.json"),
    ),
    (
        "diffuser",
        include_str!("../../../examples/sketches/diffuser.json"),
    ),
];

/// An editor script: an optional first line `sketch NAME` (one of the bundled sketches
/// blade_section, two_curves, diffuser; blade_section otherwise), then one request per line,
/// `METHOD PATH BODY` (the body is the rest of the line). Saving writes to a file in the
/// temporary directory.
///
/// # Panics
/// When an answer breaks a promise (the fuzzer's finding).
pub fn editor(data: &[u8]) {
    let Some(text) = text(data) else { return };
    let mut lines = text.lines().peekable();
    let mut start = SKETCHES[0].1;
    if let Some(name) = lines.peek().and_then(|l| l.strip_prefix("sketch ")) {
        if let Some((_, s)) = SKETCHES.iter().find(|(n, _)| *n == name.trim()) {
            start = s;
        }
        lines.next();
    }
    let sketch = match crate::sketch_file::parse(start) {
        Ok(s) => s,
        Err(e) => panic!("a bundled sketch does not load: {e:#}"),
    };
    let file = std::env::temp_dir().join(format!("camber-fuzz-editor-{}.json", std::process::id()));
    let mut state = match EditorState::new(sketch, file.clone(), None) {
        Ok(state) => state,
        Err(e) => panic!("the editor refuses a bundled sketch: {e:#}"),
    };
    for line in lines.take(MAX_REQUESTS) {
        let mut parts = line.splitn(3, ' ');
        let method = parts.next().unwrap_or_default();
        let path = parts.next().unwrap_or_default();
        let body = parts.next().unwrap_or_default();
        let answer = state.handle(method, path, body.as_bytes());
        assert!(
            answer.status != 500,
            "{method} {path} {body}: internal failure: {}",
            answer.text()
        );
        if path.starts_with("/api/") {
            if let Err(e) = serde_json::from_slice::<serde_json::Value>(&answer.body) {
                panic!(
                    "{method} {path}: the answer is not JSON ({e}): {}",
                    answer.text()
                );
            }
        }
        let now = state.handle("GET", "/api/state", b"");
        assert_eq!(now.status, 200, "the state cannot be read: {}", now.text());
    }
    let _ = std::fs::remove_file(&file);
}
