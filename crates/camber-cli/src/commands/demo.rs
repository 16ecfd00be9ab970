//! `camber demo`: solves the bundled blade section (embedded in the binary, so it runs from any
//! directory), writes `blade_section.svg` and prints the report.

use std::path::PathBuf;

use anyhow::{Context, Result};
use clap::Args;

use crate::commands::{render, solve};
use crate::sketch_file;

/// The bundled blade section sketch (examples/sketches/blade_section.json).
pub const BLADE_SECTION: &str = include_str!("../../../../examples/sketches/blade_section.json");

/// Arguments of `camber demo`.
#[derive(Debug, Args)]
pub struct DemoArgs {
    /// The directory to write blade_section.svg into.
    #[arg(short, long, value_name = "DIR", default_value = ".")]
    pub output: PathBuf,
}

/// Solves the blade section, draws it with curvature combs and prints the report.
pub fn run(args: &DemoArgs) -> Result<()> {
    let mut sketch = sketch_file::parse(BLADE_SECTION).context("bundled blade_section.json")?;
    let report = solve::solve(&mut sketch).context("bundled blade_section.json")?;
    let svg = render::picture(&sketch, true).context("bundled blade_section.json")?;
    let path = args.output.join("blade_section.svg");
    crate::output::write_all(&[], &[(path.clone(), svg)])?;
    crate::print_stdout(
        "blade section: pressure side, leading edge, suction side and trailing edge, \
         joined G1 with fixed joint directions",
    )?;
    crate::print_stdout(&solve::format_report(&report))?;
    crate::print_stdout(&format!("wrote {}", path.display()))
}
