//! `camber render`: an SVG picture of a sketch file — curves, control polygons, points, lines,
//! circles, constraint glyphs (tangency arrows, fixed triangles, coincidence rings), optional
//! curvature combs, and the constraints the DOF analysis finds conflicting drawn in red.

use std::collections::BTreeSet;
use std::path::PathBuf;

use anyhow::{anyhow, Context, Result};
use camber_sketch::{ConstraintId, Entity, Sketch};
use clap::Args;
use nalgebra::Vector2;

use crate::draw::{self, Comb, SAMPLES_PER_PIECE, TEETH_PER_PIECE};
use crate::scene::{glyphs, Glyph, View};
use crate::sketch_file::{self, describe_error};
use crate::svg::{BBox, Style, Svg};

/// Colour of constraint glyphs.
pub const GLYPH: &str = "#1e8449";
/// Colour of the glyphs of conflicting constraints.
pub const CONFLICT: &str = "#c0392b";
/// Colour of curves, lines and circles.
pub const CURVE: &str = "#2471a3";
/// Colour of point entities.
pub const POINT: &str = "#34495e";

/// Arguments of `camber render`.
#[derive(Debug, Args)]
pub struct RenderArgs {
    /// The sketch file.
    pub input: PathBuf,
    /// The SVG file to write.
    #[arg(short, long, value_name = "PIC.svg")]
    pub output: PathBuf,
    /// Also draw curvature combs on the curves.
    #[arg(long)]
    pub combs: bool,
}

/// Draws the sketch as it is in the file (not solved).
pub fn run(args: &RenderArgs) -> Result<()> {
    let sketch = sketch_file::load(&args.input)?;
    let svg = picture(&sketch, args.combs).with_context(|| args.input.display().to_string())?;
    crate::output::write_all(&[&args.input], &[(args.output.clone(), svg)])?;
    crate::print_stdout(&format!("wrote {}", args.output.display()))
}

/// The most constraints whose glyphs a picture draws; above it every k-th is drawn (and every
/// conflicting one), so a 1,000-segment chain shows its curve rather than a band of glyphs.
pub const MAX_GLYPH_CONSTRAINTS: usize = 200;

/// Where a glyph sits, for the picture's box.
fn glyph_anchor(g: &Glyph) -> nalgebra::Point2<f64> {
    match g {
        Glyph::Arrow(p, _) | Glyph::Fixed(p) | Glyph::Ring(p) | Glyph::Mark(p, _) => *p,
    }
}

fn draw_glyph(svg: &mut Svg, g: &Glyph, size: f64, colour: &str) {
    match g {
        Glyph::Arrow(a, d) => {
            let n = d.norm();
            if !(n > 0.0 && n.is_finite()) {
                return;
            }
            let t = d / n * size * 3.0;
            let b = a + t;
            let side = Vector2::new(-t.y, t.x) * 0.25;
            let style = Style::stroke(colour, 1.2);
            svg.line(*a, b, &style);
            svg.polyline(&[b - t * 0.3 + side, b, b - t * 0.3 - side], &style);
        }
        Glyph::Fixed(q) => {
            let s = size * 0.8;
            svg.polyline(
                &[
                    *q,
                    q + Vector2::new(-s, -1.5 * s),
                    q + Vector2::new(s, -1.5 * s),
                    *q,
                ],
                &Style::filled(colour),
            );
        }
        Glyph::Ring(q) => svg.circle(*q, size * 0.7, &Style::stroke(colour, 1.2)),
        Glyph::Mark(q, text) => {
            let at = q + Vector2::new(size * 0.6, size * 0.6);
            svg.text(at, text, 11.0, crate::svg::Anchor::Start, colour);
        }
    }
}

/// The SVG document of [`run`]. Conflicting constraints are those the DOF analysis names (sparse
/// for large components, so every sketch is analysed).
///
/// # Errors
/// Evaluation failures and analysis failures (which name the constraints).
pub fn picture(sketch: &Sketch, combs: bool) -> Result<String> {
    let conflicting: BTreeSet<ConstraintId> = sketch
        .analyze()
        .map_err(|e| anyhow!("analysis failed: {}", describe_error(sketch, &e)))?
        .into_iter()
        .flat_map(|a| a.analysis.conflicting)
        .collect();
    // Sample first, so the box holds everything.
    let mut bbox = BBox::empty();
    let mut curves = Vec::new();
    for (_, e) in sketch.entities() {
        e.hull_points().iter().for_each(|p| bbox.include(*p));
        if let Entity::Circle { center, radius } = e {
            bbox.include(center + Vector2::new(*radius, *radius));
            bbox.include(center - Vector2::new(*radius, *radius));
        }
        if let Some(arc) = e.as_arc() {
            draw::arc_extremes(&arc).for_each(|p| bbox.include(p));
        }
        if let Some(c) = e.as_curve() {
            let samples = draw::sample_curve(c, SAMPLES_PER_PIECE)?;
            samples.iter().for_each(|p| bbox.include(*p));
            // Hermite and composite curves: the polygon through nodes and tangent handles.
            curves.push((c, samples, e.hull_points().to_vec()));
        }
    }
    // Glyphs too: a target ring away from its curve (a conflicting target) must be in the
    // picture. On large sketches only every k-th constraint's glyphs are drawn (all the
    // conflicting ones), so the curves stay visible.
    let view = View::new(sketch);
    let mut marks = Vec::new();
    for (id, c) in sketch.constraints() {
        let list = glyphs(&view, c)?;
        if !list.is_empty() {
            marks.push((id, list));
        }
    }
    let every = marks.len().div_ceil(MAX_GLYPH_CONSTRAINTS).max(1);
    let marks: Vec<_> = marks
        .into_iter()
        .enumerate()
        .filter(|(k, (id, _))| k % every == 0 || conflicting.contains(id))
        .map(|(_, m)| m)
        .collect();
    for (_, list) in &marks {
        for g in list {
            bbox.include(glyph_anchor(g));
        }
    }
    let mut comb_list = Vec::new();
    if combs {
        let (w, h) = bbox.size();
        for (c, _, _) in &curves {
            let comb = Comb::of(*c, TEETH_PER_PIECE, 0.1 * w.max(h))?;
            comb.points().for_each(|p| bbox.include(p));
            comb_list.push(comb);
        }
    }
    let mut svg = Svg::new(bbox, 0.08);
    let size = 6.0 * svg.unit();
    for comb in &comb_list {
        comb.draw(&mut svg);
    }
    for (_, samples, polygon) in &curves {
        draw::draw_control_polygon(&mut svg, polygon);
        draw::draw_curve(&mut svg, samples, CURVE);
    }
    for (_, e) in sketch.entities() {
        match e {
            Entity::Point(p) => draw::draw_point(&mut svg, *p, POINT),
            Entity::Line([a, b]) => svg.line(*a, *b, &Style::stroke(CURVE, 2.0)),
            Entity::Circle { center, radius } => {
                svg.circle(*center, *radius, &Style::stroke(CURVE, 2.0));
            }
            Entity::Arc(_) => {
                if let Some(arc) = e.as_arc() {
                    svg.arc(&arc, &Style::stroke(CURVE, 2.0));
                }
            }
            Entity::Ellipse { .. } => {
                if let Some(ellipse) = e.as_ellipse() {
                    svg.ellipse(&ellipse, &Style::stroke(CURVE, 2.0));
                }
            }
            Entity::EllipticArc { .. } => {
                if let Some(arc) = e.as_elliptic_arc() {
                    svg.elliptic_arc(&arc, &Style::stroke(CURVE, 2.0));
                }
            }
            _ => {}
        }
    }
    for (id, list) in &marks {
        let colour = if conflicting.contains(id) {
            CONFLICT
        } else {
            GLYPH
        };
        for g in list {
            draw_glyph(&mut svg, g, size, colour);
        }
    }
    Ok(svg.finish())
}
