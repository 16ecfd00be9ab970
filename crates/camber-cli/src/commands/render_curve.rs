//! `camber render-curve`: an SVG picture of one curve file with its control polygon and,
//! optionally, its curvature comb.

use std::path::PathBuf;

use anyhow::{Context, Result};
use clap::Args;

use crate::curve_file;
use crate::draw::{self, Comb, SAMPLES_PER_PIECE, TEETH_PER_PIECE};
use crate::svg::{Anchor, BBox, Svg};

/// Arguments of `camber render-curve`.
#[derive(Debug, Args)]
pub struct RenderCurveArgs {
    /// The curve file.
    pub curve: PathBuf,
    /// The SVG file to write.
    #[arg(short, long, value_name = "PIC.svg")]
    pub output: PathBuf,
    /// Also draw the curvature comb (teeth on the convex side, length ∝ |curvature|).
    #[arg(long)]
    pub combs: bool,
}

/// Draws the curve (blue), its control polygon (grey, dashed, dots at the control points), the
/// comb when asked (purple) and a caption with the curve's description.
pub fn run(args: &RenderCurveArgs) -> Result<()> {
    let curve = curve_file::load(&args.curve)?;
    let svg = picture(&curve, args.combs).with_context(|| args.curve.display().to_string())?;
    crate::output::write_all(&[&args.curve], &[(args.output.clone(), svg)])?;
    println!("wrote {}", args.output.display());
    Ok(())
}

/// The SVG document of [`run`].
pub fn picture(curve: &curve_file::Curve, combs: bool) -> Result<String> {
    let samples = draw::sample_curve(curve.as_parametric(), SAMPLES_PER_PIECE)?;
    let polygon = curve.control_polygon();
    let mut bbox = BBox::of(samples.iter().chain(&polygon).copied());
    let comb = if combs {
        let (w, h) = bbox.size();
        let comb = Comb::of(curve.as_parametric(), TEETH_PER_PIECE, 0.2 * w.max(h))?;
        comb.points().for_each(|p| bbox.include(p));
        Some(comb)
    } else {
        None
    };
    let mut svg = Svg::new(bbox, 0.08);
    if let Some(comb) = &comb {
        comb.draw(&mut svg);
    }
    draw::draw_control_polygon(&mut svg, &polygon);
    draw::draw_curve(&mut svg, &samples, "#2471a3");
    let caption_at = nalgebra::Point2::new(bbox.min.x, bbox.min.y - 20.0 * svg.unit());
    svg.text(
        caption_at,
        &curve_file::describe(curve),
        12.0,
        Anchor::Start,
        "black",
    );
    Ok(svg.finish())
}
