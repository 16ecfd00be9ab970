//! Removes a 10° crease between two bicubic patches by deforming one of them as little as
//! possible, and plots the angle between their normals along the shared edge before and after.
//!
//! Run with `cargo run --example surface_g1 [-- PLOT.svg]` (default `surface_g1.svg` in the
//! system's temporary folder; a folder given in PLOT.svg is created).
//! The case is read from `examples/data/surface_crease10.json`, which is written from
//! `camber::surface::examples::crease_pair(10.0)` when it is missing.

use std::error::Error;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use camber::surface::examples::{crease_pair, DeformationCase};
use camber::surface::{deform_to_g1, DeformOptions, EdgeReport};

/// Where the plot goes without an argument: the system's temporary folder, never the source tree
/// or the build's target folder (wherever CARGO_TARGET_DIR points).
pub(crate) fn default_plot_path() -> PathBuf {
    std::env::temp_dir().join("surface_g1.svg")
}

/// Deforms the case, prints the report and writes the plot to `out` (creating its folder);
/// returns the file written, if the report has an edge to plot.
pub(crate) fn run(out: &Path) -> Result<Option<PathBuf>, Box<dyn Error>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let case_path = root.join("examples/data/surface_crease10.json");
    let case: DeformationCase = if case_path.exists() {
        serde_json::from_str(&std::fs::read_to_string(&case_path)?)?
    } else {
        // The bundled file is the same case (a test keeps them in sync); build it in memory.
        let (face, neighbour) = crease_pair(10.0)?;
        DeformationCase {
            face,
            neighbours: vec![neighbour],
        }
    };
    let (deformed, report) = deform_to_g1(&case.face, &case.neighbours, &DeformOptions::default())?;
    for e in &report.edges {
        println!(
            "edge {:?} (neighbour {}): normal angle max {:.4}° mean {:.4}° before, max {:.5}° mean {:.5}° after",
            e.edge,
            e.neighbour,
            e.max_before_deg(),
            e.mean_before_deg(),
            e.max_after_deg(),
            e.mean_after_deg()
        );
    }
    println!(
        "boundary deviation {:.3e} ({:.3e} of the size {:.3}), largest control point move {:.4}, \
         refinement rounds {}, knots inserted {}, net {:?}",
        report.max_boundary_deviation,
        report.max_boundary_deviation / report.size,
        report.size,
        report.max_control_point_movement,
        report.refinement_rounds,
        report.knots_inserted,
        deformed.counts()
    );
    let Some(edge) = report.edges.first() else {
        return Ok(None);
    };
    // Wherever the build puts its target folder (CARGO_TARGET_DIR), the plot's folder exists:
    // the temporary folder, or the one given, created if needed.
    if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)?;
    }
    std::fs::write(out, plot(edge))?;
    println!("plot written to {}", out.display());
    Ok(Some(out.to_path_buf()))
}

/// A small SVG: angle (degrees, linear) against the edge parameter, before in red, after in blue.
fn plot(e: &EdgeReport) -> String {
    let (w, h, m) = (640.0, 360.0, 50.0);
    let top = e.max_before_deg().max(e.max_after_deg()).max(1e-9) * 1.1;
    let (t0, t1) = match (e.parameters.first(), e.parameters.last()) {
        (Some(a), Some(b)) if b > a => (*a, *b),
        _ => (0.0, 1.0),
    };
    let x = |t: f64| m + (t - t0) / (t1 - t0) * (w - 2.0 * m);
    let y = |a: f64| h - m - a / top * (h - 2.0 * m);
    let line = |angles: &[f64]| {
        e.parameters
            .iter()
            .zip(angles)
            .map(|(t, a)| format!("{:.1},{:.1}", x(*t), y(*a)))
            .collect::<Vec<_>>()
            .join(" ")
    };
    let mut s = String::new();
    let _ = write!(
        s,
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="12">
<rect width="100%" height="100%" fill="white"/>
<text x="{m}" y="24" font-size="14">Normal angle along the shared edge (degrees)</text>
<line x1="{m}" y1="{b}" x2="{r}" y2="{b}" stroke="black"/>
<line x1="{m}" y1="{m}" x2="{m}" y2="{b}" stroke="black"/>
<text x="{r}" y="{lb}" text-anchor="end">edge parameter</text>
<text x="{lx}" y="{m}" text-anchor="end">{top:.1}</text>
<text x="{lx}" y="{b}" text-anchor="end">0</text>
<polyline fill="none" stroke="#c0392b" stroke-width="2" points="{before}"/>
<polyline fill="none" stroke="#2471a3" stroke-width="2" points="{after}"/>
<text x="{r}" y="{l1}" text-anchor="end" fill="#c0392b">before: max {mb:.3}°</text>
<text x="{r}" y="{l2}" text-anchor="end" fill="#2471a3">after: max {ma:.4}°</text>
</svg>
"##,
        b = h - m,
        r = w - m,
        lb = h - m + 30.0,
        lx = m - 6.0,
        before = line(&e.angles_before_deg),
        after = line(&e.angles_after_deg),
        l1 = m + 20.0,
        l2 = m + 38.0,
        mb = e.max_before_deg(),
        ma = e.max_after_deg(),
    );
    s
}

fn main() {
    let out = std::env::args()
        .nth(1)
        .map_or_else(default_plot_path, PathBuf::from);
    if let Err(e) = run(&out) {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}
