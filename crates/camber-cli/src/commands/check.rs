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
    /// Print JSON instead of text: `{"components": [{"component": {"entities",
    /// "constraints"}, "analysis": {"free_unknowns", "rank", "dof", "redundant",
    /// "conflicting", "structure"}}], "warnings": [...]}`.
    #[arg(long)]
    pub json: bool,
}

/// Prints, per component, the free unknowns, the rank, the free DOF, the redundant and
/// conflicting constraints by id and kind, what can move and the structural summary (the
/// Dulmage–Mendelsohn parts of the Jacobian's pattern), then the sketch's warnings. Conflicts are
/// reported, not treated as a failure: the exit code is 0 when the file loads and its analysis
/// runs, 2 otherwise.
pub fn run(args: &CheckArgs) -> Result<()> {
    let sketch = sketch_file::load(&args.input)?;
    let text = if args.json {
        check_json(&sketch)
    } else {
        check(&sketch)
    }
    .with_context(|| args.input.display().to_string())?;
    crate::print_stdout(&text)
}

/// The JSON report of `check --json`: each component with its DOF analysis (the serde forms
/// of [`camber_sketch::Component`] and [`camber_solve::DofAnalysis`]) and the warnings.
///
/// ```
/// use camber_cli::{commands::check, sketch_file};
/// let s = sketch_file::parse(r#"{"version": 1,
///   "entities": [{"id": 0, "kind": "point", "at": [0, 0]}],
///   "constraints": [{"id": 1, "kind": "fixed", "target": {"point": {"point": 0}}}]}"#)?;
/// let v: serde_json::Value = serde_json::from_str(&check::check_json(&s)?)?;
/// assert_eq!(v["components"][0]["analysis"]["dof"], 0);
/// assert_eq!(v["warnings"].as_array().map(Vec::len), Some(0));
/// # Ok::<(), anyhow::Error>(())
/// ```
pub fn check_json(sketch: &Sketch) -> Result<String> {
    let analyses = sketch
        .analyze()
        .map_err(|e| anyhow!("analysis failed: {}", describe_error(sketch, &e)))?;
    let components: Vec<serde_json::Value> = analyses
        .iter()
        .map(|a| {
            Ok(serde_json::json!({
                "component": serde_json::to_value(&a.component)?,
                "analysis": serde_json::to_value(&a.analysis)?,
                "free": serde_json::to_value(&a.freedom)?,
                "free_parameters": serde_json::to_value(&a.free_parameters)?,
            }))
        })
        .collect::<serde_json::Result<_>>()?;
    let doc = serde_json::json!({
        "components": components,
        "warnings": serde_json::to_value(sketch.warnings())?,
    });
    Ok(serde_json::to_string_pretty(&doc)?)
}

/// What can still move, entity by entity, then the contact parameters that can slide:
/// `entity 3 (line): point 1; entity 5 (circle): radius; constraint 7 (tangent_to_circle):
/// parameter 0`, or `nothing (fully constrained)`.
fn describe_freedom(sketch: &Sketch, analysis: &camber_sketch::ComponentAnalysis) -> String {
    let (freedom, parameters) = (&analysis.freedom, &analysis.free_parameters);
    if freedom.is_empty() && parameters.is_empty() {
        return "nothing (fully constrained)".to_owned();
    }
    let parameters = parameters.iter().map(|p| {
        let kind = sketch
            .constraint(p.constraint)
            .map(|c| c.tag())
            .unwrap_or("constraint");
        format!(
            "constraint {} ({kind}): parameter {}",
            p.constraint.0, p.parameter
        )
    });
    freedom
        .iter()
        .map(|f| {
            let kind = sketch
                .entity(f.entity)
                .map(|e| e.kind_name())
                .unwrap_or("entity");
            let mut parts = Vec::new();
            if !f.points.is_empty() {
                let list: Vec<String> = f.points.iter().map(usize::to_string).collect();
                let noun = if f.points.len() == 1 {
                    "point"
                } else {
                    "points"
                };
                parts.push(format!("{noun} {}", list.join(", ")));
            }
            if !f.scalars.is_empty() {
                parts.push("radius".to_owned());
            }
            format!("entity {} ({kind}): {}", f.entity.0, parts.join(", "))
        })
        .chain(parameters)
        .collect::<Vec<_>>()
        .join("; ")
}

/// At most this many over-determined constraints are named in the structure line.
const STRUCTURE_NAMES: usize = 8;

/// The structural summary of a component in one line: `structural rank 6; over-determined:
/// 2 rows (constraint 3 (distance), constraint 5 (distance)); under-determined: 1 unknown;
/// square: 4 blocks, largest 2 rows; rank tests on 2 coupled rows, largest piece 2`.
///
/// ```
/// use camber_cli::{commands::check, sketch_file};
/// // Both points fixed (eliminated from the unknowns): the distance row reads no unknown left,
/// // so it is over-determined by structure alone.
/// let s = sketch_file::parse(r#"{"version": 1,
///   "entities": [{"id": 0, "kind": "point", "at": [0, 0]}, {"id": 1, "kind": "point", "at": [1, 0]}],
///   "constraints": [{"id": 2, "kind": "fixed", "target": {"point": {"point": 0}}},
///                   {"id": 3, "kind": "fixed", "target": {"point": {"point": 1}}},
///                   {"id": 4, "kind": "distance", "a": {"point": 0}, "b": {"point": 1}, "distance": 2}]}"#)?;
/// let text = check::check(&s)?;
/// assert!(text.contains("structure: structural rank 0; over-determined: 1 row (constraint 4 (distance))"), "{text}");
/// assert!(text.contains("rank tests on 1 coupled row, largest piece 1"), "{text}");
/// # Ok::<(), anyhow::Error>(())
/// ```
fn describe_structure(sketch: &Sketch, d: &camber_solve::DofAnalysis) -> String {
    let s = &d.structure;
    let plural = |k: usize, one: &str, many: &str| {
        if k == 1 {
            format!("{k} {one}")
        } else {
            format!("{k} {many}")
        }
    };
    let over = if s.over_determined_rows.is_empty() {
        "none".to_owned()
    } else {
        let named = &s.over_determined_constraints;
        let mut list = describe_constraints(sketch, &named[..named.len().min(STRUCTURE_NAMES)]);
        if named.len() > STRUCTURE_NAMES {
            list.push_str(&format!(" and {} more", named.len() - STRUCTURE_NAMES));
        }
        format!(
            "{} ({list})",
            plural(s.over_determined_rows.len(), "row", "rows")
        )
    };
    let under = match s.under_determined_unknowns.len() {
        0 => "none".to_owned(),
        k => plural(k, "unknown", "unknowns"),
    };
    let coupled = if s.coupled_rows == 0 {
        "none coupled (every block settled alone)".to_owned()
    } else {
        format!(
            "on {}, largest piece {}",
            plural(s.coupled_rows, "coupled row", "coupled rows"),
            s.largest_coupled_piece
        )
    };
    let square = match s.square_blocks {
        0 => "none".to_owned(),
        k => format!(
            "{}, largest {}",
            plural(k, "block", "blocks"),
            plural(s.largest_square_block, "row", "rows")
        ),
    };
    format!(
        "structural rank {}; over-determined: {over}; under-determined: {under}; square: {square}; rank tests {coupled}",
        s.structural_rank,
    )
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
/// assert!(text.contains("free: entity 0 (Bézier curve): points 1, 2"), "{text}");
/// // The fixed ends leave the unknowns; no row reads the two inner points.
/// assert!(text.contains("structure: structural rank 0; over-determined: none; under-determined: 4 unknowns"), "{text}");
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
            "component {} ({}; {}): {} free unknowns, rank {}, DOF {}",
            k + 1,
            describe_entities(&a.component.entities),
            crate::sketch_file::describe_constraint_ids(&a.component.constraints),
            d.free_unknowns,
            d.rank,
            d.dof
        ));
        lines.push(format!(
            "  redundant: {}",
            describe_constraints(sketch, &d.redundant)
        ));
        if !d.partly_redundant.is_empty() {
            lines.push(format!(
                "  partly redundant (some rows repeat others, still needed): {}",
                describe_constraints(sketch, &d.partly_redundant)
            ));
        }
        lines.push(format!(
            "  conflicting: {}",
            describe_constraints(sketch, &d.conflicting)
        ));
        for dep in d.depends_on.iter().filter(|dep| !dep.on.is_empty()) {
            lines.push(format!(
                "  constraint {} depends on {}",
                dep.constraint.0,
                describe_constraints(sketch, &dep.on)
            ));
        }
        if !d.accidental.is_empty() {
            lines.push(format!(
                "  dependent only here (singular configuration, not redundant): {}",
                describe_constraints(sketch, &d.accidental)
            ));
        }
        lines.push(format!("  free: {}", describe_freedom(sketch, a)));
        lines.push(format!("  structure: {}", describe_structure(sketch, d)));
    }
    if lines.is_empty() {
        lines.push("empty sketch".to_owned());
    }
    lines.extend(sketch.warnings().iter().map(|w| format!("warning: {w}")));
    Ok(lines.join("\n"))
}
