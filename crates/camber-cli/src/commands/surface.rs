//! `camber surface`: deform a face to G1 continuity with its neighbours (camber-surface's
//! `deform_to_g1`), write the deformed face, print the report and optionally plot the normal
//! angle along each shared edge before and after.

use std::fmt::Write as _;
use std::path::PathBuf;

use anyhow::{anyhow, Context, Result};
use camber_surface::examples::DeformationCase;
use camber_surface::{deform_to_g1, DeformOptions, DeformationReport};
use clap::Args;
use nalgebra::Point2;

use crate::curve_file::read_text;
use crate::svg::{Anchor, BBox, Style, Svg};

/// Arguments of `camber surface`.
#[derive(Debug, Args)]
pub struct SurfaceArgs {
    /// The deformation case: `{"face": SURFACE, "neighbours": [{"surface": SURFACE,
    /// "face_edge": "VMax", "neighbour_edge": "VMin"}]}`, where SURFACE is `{"degree_u",
    /// "degree_v", "knots_u", "knots_v", "control_points": [[x, y, z], …] (v fastest),
    /// "weights"}` and edges are UMin, UMax, VMin or VMax; see docs/cli.md and
    /// examples/data/surface_crease10.json.
    pub case: PathBuf,
    /// Where to write the deformed face (a NURBS surface in the same JSON form).
    #[arg(short, long, value_name = "OUT.json")]
    pub output: PathBuf,
    /// Also write an SVG plot of the normal angle along each shared edge, before and after.
    #[arg(long, value_name = "PIC.svg")]
    pub plot: Option<PathBuf>,
}

/// Loads the case, deforms, writes the face (and the plot), prints the report.
pub fn run(args: &SurfaceArgs) -> Result<()> {
    let name = args.case.display().to_string();
    let text = read_text(&args.case)?;
    let case: DeformationCase = parse_case(&text).with_context(|| name.clone())?;
    let (face, report) = deform_to_g1(&case.face, &case.neighbours, &DeformOptions::default())
        .map_err(|e| anyhow!("{name}: deformation failed: {e}"))?;
    let mut json = serde_json::to_string_pretty(&face).context("cannot encode the face")?;
    json.push('\n');
    let mut outputs = vec![(args.output.clone(), json)];
    if let Some(plot_path) = &args.plot {
        outputs.push((plot_path.clone(), plot(&report)));
    }
    crate::output::write_all(&[&args.case], &outputs)?;
    print!("{}", report_text(&report));
    println!(
        "deformed face ({} × {} control points) written to {}",
        face.counts().0,
        face.counts().1,
        args.output.display()
    );
    if let Some(plot_path) = &args.plot {
        println!("plot written to {}", plot_path.display());
    }
    Ok(())
}

/// Parses a case, naming the JSON path of a bad field.
fn parse_case(text: &str) -> Result<DeformationCase> {
    let mut de = serde_json::Deserializer::from_str(text);
    serde_path_to_error::deserialize(&mut de).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner();
        if path == "." {
            anyhow!("{inner}")
        } else {
            anyhow!("at {path}: {inner}")
        }
    })
}

/// The printed report: one line per edge, then the global measures.
pub fn report_text(report: &DeformationReport) -> String {
    let mut s = String::new();
    for e in &report.edges {
        let _ = writeln!(
            s,
            "edge {:?} (neighbour {}): normal angle before max {:.4}° mean {:.4}°, after max {:.5}° mean {:.5}°",
            e.edge,
            e.neighbour,
            e.max_before_deg(),
            e.mean_before_deg(),
            e.max_after_deg(),
            e.mean_after_deg()
        );
    }
    let _ = writeln!(
        s,
        "boundary deviation {:.3e} ({:.3e} of the size {:.4})",
        report.max_boundary_deviation,
        report.max_boundary_deviation / report.size,
        report.size
    );
    let _ = writeln!(
        s,
        "largest control point movement {:.4e}",
        report.max_control_point_movement
    );
    let _ = writeln!(
        s,
        "refinement rounds {}, knots inserted {}, tolerances {}",
        report.refinement_rounds,
        report.knots_inserted,
        if report.met_tolerances {
            "met"
        } else {
            "NOT met"
        }
    );
    s
}

/// Chart width in model units of the plot (the height is 1).
const CHART_WIDTH: f64 = 1.6;

/// The SVG plot: the normal angle (degrees, linear) against the normalized edge parameter, one
/// polyline per edge before (red) and after (blue), with axes and labels.
pub fn plot(report: &DeformationReport) -> String {
    let top = report
        .max_angle_before_deg()
        .max(report.max_angle_after_deg())
        .max(1e-9)
        * 1.1;
    let frame = BBox::of([Point2::new(-0.12, -0.12), Point2::new(CHART_WIDTH, 1.12)]);
    let mut svg = Svg::new(frame, 0.03);
    let axis = Style::stroke("black", 1.0);
    svg.line(Point2::origin(), Point2::new(CHART_WIDTH, 0.0), &axis);
    svg.line(Point2::origin(), Point2::new(0.0, 1.0), &axis);
    let label = |svg: &mut Svg, x: f64, y: f64, t: &str, a: Anchor, c: &str| {
        svg.text(Point2::new(x, y), t, 12.0, a, c);
    };
    label(
        &mut svg,
        0.0,
        1.07,
        "Normal angle along the shared edge (degrees)",
        Anchor::Start,
        "black",
    );
    label(
        &mut svg,
        CHART_WIDTH,
        -0.08,
        "edge parameter",
        Anchor::End,
        "black",
    );
    label(
        &mut svg,
        -0.02,
        1.0,
        &format!("{top:.2}"),
        Anchor::End,
        "black",
    );
    label(&mut svg, -0.02, 0.0, "0", Anchor::End, "black");
    for e in &report.edges {
        let (t0, t1) = match (e.parameters.first(), e.parameters.last()) {
            (Some(&a), Some(&b)) if b > a => (a, b),
            _ => (0.0, 1.0),
        };
        let curve = |angles: &[f64]| -> Vec<Point2<f64>> {
            e.parameters
                .iter()
                .zip(angles)
                .map(|(t, a)| Point2::new((t - t0) / (t1 - t0) * CHART_WIDTH, a / top))
                .collect()
        };
        svg.polyline(&curve(&e.angles_before_deg), &Style::stroke("#c0392b", 2.0));
        svg.polyline(&curve(&e.angles_after_deg), &Style::stroke("#2471a3", 2.0));
    }
    let before = format!("before: max {:.3}°", report.max_angle_before_deg());
    let after = format!("after: max {:.4}°", report.max_angle_after_deg());
    label(&mut svg, CHART_WIDTH, 0.75, &before, Anchor::End, "#c0392b");
    label(&mut svg, CHART_WIDTH, 0.69, &after, Anchor::End, "#2471a3");
    svg.finish()
}
