//! `camber export`: a sketch file's geometry in another format (DXF).

use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Result};
use camber_interop::dxf;
use clap::Args;

/// Arguments of `camber export`.
#[derive(Debug, Args)]
pub struct ExportArgs {
    /// The sketch file.
    pub input: PathBuf,
    /// The file to write: a DXF file (`.dxf`).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Write binary DXF (numbers as their f64 bits) instead of text (each number in its
    /// shortest exact decimal form); both round trips are exact.
    #[arg(long)]
    pub binary: bool,
}

/// Writes the sketch's entities (constraints are not part of a DXF file).
pub fn run(args: &ExportArgs) -> Result<()> {
    let ext = args
        .output
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    if ext != "dxf" {
        bail!(
            "{}: unknown output format {ext:?}: camber export writes .dxf files",
            args.output.display()
        );
    }
    let sketch = crate::sketch_file::load(&args.input)?;
    let form = if args.binary {
        dxf::Form::Binary
    } else {
        dxf::Form::Text
    };
    let bytes = dxf::write(&sketch, form).map_err(|e| anyhow!("{}: {e}", args.input.display()))?;
    crate::output::write_all_bytes(&[Path::new(&args.input)], &[(args.output.clone(), bytes)])?;
    crate::print_stdout(&format!(
        "wrote {} entities to {}",
        sketch.entities().count(),
        args.output.display()
    ))
}
