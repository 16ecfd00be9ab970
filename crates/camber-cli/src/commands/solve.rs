//! `camber solve`: solve a sketch file, write the result, print a report per component.

use std::path::PathBuf;

use anyhow::{anyhow, Context, Result};
use camber_sketch::{Sketch, SketchReport};
use clap::Args;

use crate::commands::render;
use crate::sketch_file::{self, describe_entities, describe_error};

/// Arguments of `camber solve`.
#[derive(Debug, Args)]
pub struct SolveArgs {
    /// The sketch file.
    pub input: PathBuf,
    /// Where to write the solved sketch file.
    #[arg(short, long, value_name = "OUT.json")]
    pub output: PathBuf,
    /// Also draw the solved sketch as SVG.
    #[arg(long, value_name = "PIC.svg")]
    pub svg: Option<PathBuf>,
    /// Solve contacts with fixed circles and lines by iterative displacement on the linear path
    /// (the blade-design method, for comparison; the usual solve takes over when its rounds stall).
    #[arg(long)]
    pub displacement: bool,
    /// Print the report as JSON (`{"components": [{"component", "report"}], "warnings"}`,
    /// the serde form of the sketch report) instead of text.
    #[arg(long)]
    pub json: bool,
}

/// Loads, solves every component, writes the result (and the picture), prints the report. A
/// failed solve writes nothing and names the constraints at fault; the files are written all
/// or nothing, never over the input ([`crate::output`]).
pub fn run(args: &SolveArgs) -> Result<()> {
    let mut sketch = sketch_file::load(&args.input)?;
    let report = if args.displacement {
        let run = sketch
            .solve_by_displacement(&camber_sketch::displacement::DisplacementOptions::default())
            .map_err(|e| anyhow!("solve failed: {}", describe_error(&sketch, &e)))
            .with_context(|| args.input.display().to_string())?;
        let line = if run.history.is_empty() {
            // No curve touches a fixed circle or line: nothing for the method to move.
            "iterative displacement: 0 round(s), no contacts with fixed circles or lines, \
             solved by the usual solve"
                .to_owned()
        } else {
            format!(
                "iterative displacement: {} round(s), {}",
                run.rounds,
                if run.converged {
                    "converged, validated by the sketch's solve"
                } else {
                    "not converged, solved by the usual solve from the start"
                }
            )
        };
        if !args.json {
            crate::print_stdout(&line)?;
        }
        run.report
    } else {
        solve(&mut sketch).with_context(|| args.input.display().to_string())?
    };
    let text = camber_sketch::file::to_json(&sketch)
        .map_err(|e| anyhow!("{e}"))
        .with_context(|| args.output.display().to_string())?;
    let mut outputs = vec![(args.output.clone(), text)];
    if let Some(pic) = &args.svg {
        let svg =
            render::picture(&sketch, false).with_context(|| args.input.display().to_string())?;
        outputs.push((pic.clone(), svg));
    }
    crate::output::write_all(&[&args.input], &outputs)?;
    if args.json {
        let text =
            serde_json::to_string_pretty(&report).context("cannot write the report as JSON")?;
        return crate::print_stdout(&text);
    }
    crate::print_stdout(&format_report(&report))?;
    crate::print_stdout(&format!("wrote {}", args.output.display()))?;
    Ok(())
}

/// Solves every component; the error names the failing constraints by id and kind.
pub fn solve(sketch: &mut Sketch) -> Result<SketchReport> {
    sketch
        .solve_all()
        .map_err(|e| anyhow!("solve failed: {}", describe_error(sketch, &e)))
}

/// One line per component: entities, solver, DOF, largest residual, time.
///
/// ```
/// use camber_cli::{commands::solve, sketch_file};
/// let mut s = sketch_file::parse(r#"{"version": 1,
///   "entities": [{"id": 0, "kind": "point", "at": [0, 0]}, {"id": 1, "kind": "point", "at": [1, 0]}],
///   "constraints": [{"id": 2, "kind": "coincident", "a": {"point": 0}, "b": {"point": 1}}]}"#)?;
/// let report = solve::solve(&mut s)?;
/// assert!(solve::format_report(&report).starts_with("component 1 (entities 0, 1): solver dense_min_norm, DOF 2"));
/// # Ok::<(), anyhow::Error>(())
/// ```
pub fn format_report(report: &SketchReport) -> String {
    let mut lines = Vec::new();
    for (k, c) in report.components.iter().enumerate() {
        let r = &c.report;
        let residual = r.residuals.iter().fold(0.0_f64, |m, g| m.max(g.max_abs));
        lines.push(format!(
            "component {} ({}): solver {}, DOF {}, residual {residual:.3e}, time {:.3} ms",
            k + 1,
            describe_entities(&c.component.entities),
            sketch_file::solver_name(r.solver),
            r.dof,
            r.elapsed.as_secs_f64() * 1e3
        ));
        // Priority tiers, when some had to give way: never silently.
        for tier in &r.priorities {
            let what = if tier.met {
                "met".to_owned()
            } else {
                let named: Vec<String> = tier
                    .relaxed
                    .iter()
                    .map(|id| {
                        let g = r
                            .residuals
                            .iter()
                            .find(|g| g.constraint == *id)
                            .map_or(f64::NAN, |g| g.max_abs);
                        format!("constraint {} (residual {g:.3e})", id.0)
                    })
                    .collect();
                format!("relaxed {}", named.join(", "))
            };
            lines.push(format!("  priority {}: {what}", tier.priority));
        }
    }
    if lines.is_empty() {
        lines.push("nothing to solve (no constraints)".to_owned());
    }
    lines.extend(report.warnings.iter().map(|w| format!("warning: {w}")));
    lines.join("\n")
}
