//! Sketch files for the sketch commands: loading and saving through [`camber_sketch::file`]
//! with the file name in front of every error, and plain descriptions of constraints and of
//! solver failures (ids with their kinds).
//!
//! The format itself is described in docs/file-format.md and in [`camber_sketch::file`].

use std::path::Path;

use anyhow::{anyhow, Context, Result};
use camber_sketch::{ConstraintId, Error, Sketch};

use crate::curve_file::read_text;

/// Reads and validates a sketch file; errors start with the file name.
pub fn load(path: &Path) -> Result<Sketch> {
    let text = read_text(path)?;
    parse(&text).with_context(|| path.display().to_string())
}

/// Parses sketch file text (no custom kinds are registered on the command line).
pub fn parse(text: &str) -> Result<Sketch> {
    camber_sketch::file::from_json(text).map_err(|e| anyhow!("{e}"))
}

/// Writes a sketch file.
pub fn save(path: &Path, sketch: &Sketch) -> Result<()> {
    let text = camber_sketch::file::to_json(sketch)
        .map_err(|e| anyhow!("{e}"))
        .with_context(|| path.display().to_string())?;
    crate::output::write_all(&[], &[(path.to_path_buf(), text)])
}

/// "constraint 4 (G1 join)", "the drag target" for the drag's own pin, or "constraint 4" when
/// the id is not in the sketch ([`Sketch::describe_constraint`]).
pub fn describe_constraint(sketch: &Sketch, id: ConstraintId) -> String {
    sketch.describe_constraint(id)
}

/// A comma-separated list of [`describe_constraint`], or "none".
pub fn describe_constraints(sketch: &Sketch, ids: &[ConstraintId]) -> String {
    sketch.describe_constraints(ids)
}

/// A sketch error in plain words, naming constraints by id and kind
/// ([`Sketch::describe_error`]).
pub fn describe_error(sketch: &Sketch, e: &Error) -> String {
    sketch.describe_error(e)
}

/// The solver of a report in the words the reports print (the JSON names): `dense_min_norm`,
/// `sparse_min_norm`, `newton`, `slsqp`, `levenberg_marquardt`, and `none (nothing to solve)`
/// when no solver had to run.
pub fn solver_name(kind: camber_solve::SolverKind) -> &'static str {
    use camber_solve::SolverKind as K;
    match kind {
        K::None => "none (nothing to solve)",
        K::DenseMinNorm => "dense_min_norm",
        K::SparseMinNorm => "sparse_min_norm",
        K::Newton => "newton",
        K::Slsqp => "slsqp",
        K::LevenbergMarquardt => "levenberg_marquardt",
        K::Prioritized => "prioritized",
    }
}

/// "constraints 4, 5" (or "constraint 4", "no constraints", "1000 constraints: 4, 5, 6, …")
/// for a component header.
pub fn describe_constraint_ids(ids: &[ConstraintId]) -> String {
    let list: Vec<String> = ids.iter().map(|c| c.0.to_string()).collect();
    match list.as_slice() {
        [] => "no constraints".to_owned(),
        [one] => format!("constraint {one}"),
        [a, b, c, .., last] if list.len() > 8 => {
            format!("{} constraints: {a}, {b}, {c}, …, {last}", list.len())
        }
        _ => format!("constraints {}", list.join(", ")),
    }
}

/// "entities 0, 1, 2" for a component header; long lists are cut to "1000 entities: 0, 1, 2, …, 999";
/// "no entities" for the component of a constraint that reads none.
pub fn describe_entities(ids: &[camber_sketch::EntityId]) -> String {
    let list: Vec<String> = ids.iter().map(|e| e.0.to_string()).collect();
    match list.as_slice() {
        [] => "no entities".to_owned(),
        [one] => format!("entity {one}"),
        [a, b, c, .., last] if list.len() > 8 => {
            format!("{} entities: {a}, {b}, {c}, …, {last}", list.len())
        }
        _ => format!("entities {}", list.join(", ")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use camber_solve::{ConstraintId, ConstraintResidual};

    #[test]
    fn not_solved_lists_every_constraint_left_above_tolerance_by_kind() {
        let s = parse(
            r#"{"version": 1,
              "entities": [{"id": 0, "kind": "point", "at": [0, 0]}, {"id": 1, "kind": "point", "at": [1, 0]}],
              "constraints": [{"id": 2, "kind": "distance", "a": {"point": 0}, "b": {"point": 1}, "distance": 2},
                              {"id": 3, "kind": "horizontal", "of": {"a": {"point": 0}, "b": {"point": 1}}}]}"#,
        )
        .unwrap();
        let residual = |c: u64, g: f64| ConstraintResidual {
            constraint: ConstraintId(c),
            max_abs: g,
        };
        let e = Error::Solve(camber_solve::Error::NotSolved {
            tried: "Newton failed".to_owned(),
            residuals: vec![residual(3, 1e-3), residual(2, 0.5)],
            best_effort: vec![],
        });
        let text = describe_error(&s, &e);
        assert!(
            text.starts_with("not solved (nothing proves a conflict): Newton failed; residual per constraint: constraint 2 (distance) |g| = 5.000e-1, constraint 3 (horizontal) |g| = 1.000e-3"),
            "{text}"
        );
    }
}
