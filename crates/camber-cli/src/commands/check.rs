//! `camber check`: the DOF analysis of a sketch file, per component, without solving.

use std::path::PathBuf;

use anyhow::{anyhow, Context, Result};
use camber_sketch::Sketch;
use clap::Args;

use crate::sketch_file::{self, describe_constraints, describe_entities, describe_error};

/// Arguments of `camber check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// The sketch file.
    pub input: PathBuf,
}

/// Prints, per component, the free unknowns, the rank, the free DOF and the redundant and
/// conflicting constraints by id and kind. Conflicts are reported, not treated as a failure:
/// the exit code is 0 whenever the file loads.
pub fn run(args: &CheckArgs) -> Result<()> {
    let sketch = sketch_file::load(&args.input)?;
    let text = check(&sketch).with_context(|| args.input.display().to_string())?;
    crate::print_stdout(&text)
}

/// The report of [`run`].
///
/// ```
/// use camber_cli::{commands::check, sketch_file};
/// let s = sketch_file::parse(r#"{"version": 1,
///   "entities": [{"id": 0, "kind": "bezier", "control_points": [[0, 0], [1, 1], [2, 1], [3, 0]]}],
///   "constraints": [{"id": 1, "kind": "fixed", "target": {"point": {"start": 0}}},
///                   {"id": 2, "kind": "fixed", "target": {"point": {"end": 0}}}]}"#)?;
/// let text = check::check(&s)?;
/// assert!(text.contains("DOF 4"), "{text}");
/// # Ok::<(), anyhow::Error>(())
/// ```
pub fn check(sketch: &Sketch) -> Result<String> {
    let analyses = sketch
        .analyze()
        .map_err(|e| anyhow!("analysis failed: {}", describe_error(sketch, &e)))?;
    let mut lines = Vec::new();
    for (k, a) in analyses.iter().enumerate() {
        let d = &a.analysis;
        lines.push(format!(
            "component {} ({}, {} constraints): {} free unknowns, rank {}, DOF {}",
            k + 1,
            describe_entities(&a.component.entities),
            a.component.constraints.len(),
            d.free_unknowns,
            d.rank,
            d.dof
        ));
        lines.push(format!(
            "  redundant: {}",
            describe_constraints(sketch, &d.redundant)
        ));
        lines.push(format!(
            "  conflicting: {}",
            describe_constraints(sketch, &d.conflicting)
        ));
    }
    if lines.is_empty() {
        lines.push("empty sketch".to_owned());
    }
    Ok(lines.join("\n"))
}
