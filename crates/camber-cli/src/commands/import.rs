//! `camber import`: geometry from another format (DXF, SVG) into a sketch file.

use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Result};
use camber_interop::{dxf, svg, Imported};
use clap::Args;

use crate::curve_file::read_bytes;

/// Arguments of `camber import`.
#[derive(Debug, Args)]
pub struct ImportArgs {
    /// The file to import: a DXF file (`.dxf`, text or binary) or an SVG document (`.svg`:
    /// its paths, basic shapes and `use` references, the picture kept upright).
    pub input: PathBuf,
    /// The sketch file to write.
    #[arg(short, long)]
    pub output: PathBuf,
    /// DXF: end points of different entities at most this far apart (drawing units) are
    /// joined by coincident constraints; 0 joins only equal points, a negative value none.
    /// (SVG joins follow the paths: each segment to the next.)
    #[arg(long, default_value_t = 1e-9, allow_negative_numbers = true)]
    pub join_tolerance: f64,
    /// SVG: the sketch's units: `user` (the default: the root's user units, the numbers
    /// written in the file) or a physical unit, `mm`, `cm`, `in`, `pt`, `pc` or `px` (the
    /// root's viewBox placed on its width × height, at 96 px per inch).
    #[arg(long, default_value = "user", value_parser = parse_svg_units)]
    pub svg_units: svg::SketchUnits,
    /// Fail (and write nothing) when any item of the file is left out.
    #[arg(long)]
    pub strict: bool,
}

/// `user` or a unit's symbol.
fn parse_svg_units(text: &str) -> Result<svg::SketchUnits, String> {
    if text == "user" {
        return Ok(svg::SketchUnits::User);
    }
    svg::Unit::from_symbol(text)
        .map(svg::SketchUnits::Physical)
        .ok_or_else(|| format!("{text:?} is not user, mm, cm, in, pt, pc or px"))
}

/// The input formats `camber import` reads, by file extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Format {
    Dxf,
    Svg,
}

fn format_of(path: &Path) -> Result<Format> {
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    match ext.as_str() {
        "dxf" => Ok(Format::Dxf),
        "svg" => Ok(Format::Svg),
        _ => bail!(
            "{}: unknown input format {:?}: camber import reads .dxf and .svg files",
            path.display(),
            ext
        ),
    }
}

/// Imports the file, writes the sketch, lists what was left out on stderr and prints a
/// summary line on stdout.
pub fn run(args: &ImportArgs) -> Result<()> {
    let imported = import(&args.input, args.join_tolerance, args.svg_units)?;
    for s in &imported.skipped {
        eprintln!("skipped: {}: {s}", args.input.display());
    }
    if args.strict && !imported.skipped.is_empty() {
        bail!(
            "{}: {} items left out (see above); nothing written (--strict)",
            args.input.display(),
            imported.skipped.len()
        );
    }
    crate::sketch_file::save(&args.output, &imported.sketch)?;
    crate::print_stdout(&summary(&imported))
}

/// Reads and imports one file (`svg_units` for an SVG document).
///
/// # Errors
/// An unknown extension, an unreadable or malformed file; messages start with the file name.
pub fn import(path: &Path, join_tolerance: f64, svg_units: svg::SketchUnits) -> Result<Imported> {
    let format = format_of(path)?;
    let bytes = read_bytes(path)?;
    match format {
        Format::Dxf => {
            let options = dxf::ReadOptions {
                join_tolerance,
                ..dxf::ReadOptions::default()
            };
            dxf::read(&bytes, &options).map_err(|e| anyhow!("{}: {e}", path.display()))
        }
        Format::Svg => {
            let text = std::str::from_utf8(&bytes).map_err(|e| {
                anyhow!(
                    "{}: not UTF-8 text (at byte {})",
                    path.display(),
                    e.valid_up_to()
                )
            })?;
            let text = text.strip_prefix('\u{feff}').unwrap_or(text);
            svg::import_document(text, &svg::SvgOptions::default().with_units(svg_units))
                .map_err(|e| anyhow!("{}: {e}", path.display()))
        }
    }
}

/// `imported 12 entities and 11 joins; 2 items skipped`.
fn summary(imported: &Imported) -> String {
    let entities = imported.sketch.entities().count();
    let joins = imported.sketch.constraints().count();
    format!(
        "imported {entities} entities and {joins} joins; {} items skipped",
        imported.skipped.len()
    )
}
