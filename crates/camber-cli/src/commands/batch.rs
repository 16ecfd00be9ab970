//! `camber batch`: solve every sketch file of a directory in parallel, one JSON line per file.
//!
//! The files (`*.json` directly in the directory, in name order) are independent, so they are
//! solved on a rayon pool of `--jobs` threads; each line is
//! `{"file": name, "ok": true, "report": {…}}` or `{"file": name, "ok": false, "error": "…"}`,
//! printed in name order once all are done. The command fails (after printing every line) when
//! any file failed.
//!
//! Everything a file costs runs on the pool: reading, parsing, solving, writing the solved
//! sketch and turning its report into the JSON text of its line (a report lists every
//! constraint's residual, tens of kilobytes for a large sketch); the calling thread only writes
//! the finished lines.

use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Context, Result};
use clap::Args;
use rayon::prelude::*;
use serde_json::{json, Value};

use crate::sketch_file::{self, describe_error};

/// Arguments of `camber batch`.
#[derive(Debug, Args)]
pub struct BatchArgs {
    /// The directory of sketch files (`*.json`, not recursive); with `--parameters`, one
    /// sketch file.
    pub dir: PathBuf,
    /// A CSV table of parameter values (a header of parameter names, one variant per row):
    /// the sketch is solved once per row, one JSON line per variant.
    #[arg(short, long, value_name = "TABLE.csv")]
    pub parameters: Option<PathBuf>,
    /// Worker threads (default: every core).
    #[arg(short, long, value_name = "N")]
    pub jobs: Option<usize>,
    /// Also write each solved sketch into this directory, under its own name.
    #[arg(short, long, value_name = "DIR")]
    pub output: Option<PathBuf>,
}

/// The sketch files of `dir`, in name order.
pub fn sketch_files(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .with_context(|| format!("cannot read directory {}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    Ok(files)
}

/// Loads, solves (every component) and optionally writes one file: whether it solved, and
/// its JSON line as text.
fn solve_one(path: &Path, output: Option<&Path>) -> (bool, String) {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let outcome = sketch_file::load(path).and_then(|mut sketch| {
        let report = sketch
            .solve_all()
            .map_err(|e| anyhow!("solve failed: {}", describe_error(&sketch, &e)))?;
        if let Some(dir) = output {
            sketch_file::save(&dir.join(&name), &sketch)?;
        }
        Ok(report)
    });
    let (ok, line): (bool, Value) = match outcome {
        Ok(report) => (true, json!({"file": name, "ok": true, "report": report})),
        Err(e) => (
            false,
            json!({"file": name, "ok": false, "error": format!("{e:#}")}),
        ),
    };
    (ok, line.to_string())
}

/// Solves every file of the directory on `--jobs` threads and prints one line per file.
pub fn run(args: &BatchArgs) -> Result<()> {
    if args.jobs == Some(0) {
        bail!("--jobs must be at least 1");
    }
    if let Some(table) = &args.parameters {
        return super::sweep::run(&args.dir, table, args.jobs);
    }
    let files = sketch_files(&args.dir)?;
    if let Some(out) = &args.output {
        std::fs::create_dir_all(out)
            .with_context(|| format!("cannot create directory {}", out.display()))?;
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.jobs.unwrap_or(0))
        .build()
        .map_err(|e| anyhow!("cannot start {} threads: {e}", args.jobs.unwrap_or(0)))?;
    let output = args.output.as_deref();
    let lines: Vec<(bool, String)> =
        pool.install(|| files.par_iter().map(|f| solve_one(f, output)).collect());
    let failed = lines.iter().filter(|(ok, _)| !ok).count();
    for (_, line) in &lines {
        crate::print_stdout(line)?;
    }
    if failed > 0 {
        bail!("{failed} of {} sketch files failed", lines.len());
    }
    Ok(())
}
