//! `camber batch SKETCH --parameters TABLE.csv`: one sketch solved for every row of a table of
//! parameter values, on `--jobs` threads, one JSON line per variant:
//! `{"row": 0, "ok": true, "max_residual": 3e-13, "parameters": {"chord": 1.2, …},
//! "free": {"11.s": 0.42, "8.u": 0.49}}` (the solved free parameters of the constraints, as
//! "constraint id.name"), or `{"row": 1, "ok": false, "error": "…", …}`. The command fails
//! (after printing every line) when any variant failed.

use std::path::Path;

use anyhow::{anyhow, bail, Context, Result};
use camber_sketch::parameters::sweep::{solve_variants, Table};
use serde_json::{json, Map, Value};

use crate::sketch_file;

/// The most variants one table may hold.
pub const MAX_VARIANTS: usize = 1_000_000;

/// Reads a CSV table: a header of parameter names, then rows of numbers.
pub fn read_table(path: &Path) -> Result<Table> {
    let mut reader = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_path(path)
        .with_context(|| format!("cannot read {}", path.display()))?;
    let names: Vec<String> = reader
        .headers()
        .with_context(|| format!("{}: no header row", path.display()))?
        .iter()
        .map(str::to_owned)
        .collect();
    let mut columns = vec![Vec::new(); names.len()];
    for (i, record) in reader.records().enumerate() {
        if i >= MAX_VARIANTS {
            bail!("{}: more than {MAX_VARIANTS} rows", path.display());
        }
        let record = record.with_context(|| format!("{}: row {}", path.display(), i + 1))?;
        for (k, field) in record.iter().enumerate() {
            let v: f64 = field.parse().map_err(|_| {
                anyhow!(
                    "{}: row {}, column `{}`: `{field}` is not a number",
                    path.display(),
                    i + 1,
                    names.get(k).map_or("?", String::as_str)
                )
            })?;
            if let Some(c) = columns.get_mut(k) {
                c.push(v);
            }
        }
    }
    Table::try_new(names.into_iter().zip(columns).collect())
        .map_err(|e| anyhow!("{}: {e}", path.display()))
}

/// Solves the sketch for every row and prints one line per variant.
pub fn run(sketch: &Path, table: &Path, jobs: Option<usize>) -> Result<()> {
    let base = sketch_file::load(sketch)?;
    let table = read_table(table)?;
    let rows = solve_variants(&base, &table, jobs).map_err(|e| anyhow!("{e}"))?;
    let failed = rows.iter().filter(|r| !r.ok).count();
    for r in &rows {
        let parameters: Map<String, Value> = table
            .row(r.row)
            .map(|(n, v)| (n.to_owned(), json!(v)))
            .collect();
        let free: Map<String, Value> = r
            .free
            .iter()
            .map(|(id, n, v)| (format!("{id}.{n}"), json!(v)))
            .collect();
        let line = if r.ok {
            json!({"row": r.row, "ok": true, "max_residual": r.max_residual,
                   "parameters": parameters, "free": free})
        } else {
            json!({"row": r.row, "ok": false, "error": r.error, "parameters": parameters})
        };
        crate::print_stdout(&line.to_string())?;
    }
    if failed > 0 {
        bail!("{failed} of {} variants failed", rows.len());
    }
    Ok(())
}
