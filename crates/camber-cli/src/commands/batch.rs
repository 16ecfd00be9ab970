//! `camber batch`: solve every sketch file of a directory in parallel, one JSON line per file.
//!
//! The files (`*.json` directly in the directory, in name order) are independent, so they are
//! solved on a rayon pool of `--jobs` threads; each line is
//! `{"file": name, "ok": true, "report": {…}}` or `{"file": name, "ok": false, "error": "…"}`,
//! printed in name order once all are done. The command fails (after printing every line) when
//! any file failed.
//!
//! Everything a file costs runs on the pool: reading and parsing, solving (one
//! [`camber_sketch::solve_many`] call per group of files, so that files of one structure are
//! solved on one prepared problem per worker), and turning each report into the JSON text of
//! its line (a report lists every constraint's residual, tens of kilobytes for a large sketch),
//! writing the solved sketches (`--output`); the calling thread only writes the finished lines.

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

/// Files loaded and solved together: one `solve_many` call per group, so that the sketches in
/// memory at once stay bounded whatever the directory holds.
const GROUP: usize = 1024;

/// The name of a file, for its line.
fn file_name(path: &Path) -> String {
    path.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default()
}

/// Loads, solves (every component, by one [`camber_sketch::solve_many`] call, which reuses a
/// prepared problem for files of one structure) and optionally writes the files of `group`:
/// whether each solved, and its JSON line as text, in order.
fn solve_group(group: &[PathBuf], output: Option<&Path>) -> Vec<(bool, String)> {
    let loaded: Vec<Result<camber_sketch::Sketch>> =
        group.par_iter().map(|p| sketch_file::load(p)).collect();
    let mut sketches = Vec::with_capacity(loaded.len());
    let loaded: Vec<Result<()>> = loaded
        .into_iter()
        .map(|l| l.map(|sketch| sketches.push(sketch)))
        .collect();
    let results = camber_sketch::solve_many(&mut sketches);
    let mut solved = sketches.into_iter().zip(results);
    let files: Vec<(&PathBuf, Result<_>)> = group
        .iter()
        .zip(loaded)
        .map(|(path, l)| {
            let file = l.and_then(|()| solved.next().ok_or_else(|| anyhow!("lost the solve")));
            (path, file)
        })
        .collect();
    files
        .into_par_iter()
        .map(|(path, file)| {
            let name = file_name(path);
            let outcome = file.and_then(|(sketch, result)| {
                let report =
                    result.map_err(|e| anyhow!("solve failed: {}", describe_error(&sketch, &e)))?;
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
        })
        .collect()
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
    let lines: Vec<(bool, String)> = pool.install(|| {
        files
            .chunks(GROUP)
            .flat_map(|group| solve_group(group, output))
            .collect()
    });
    let failed = lines.iter().filter(|(ok, _)| !ok).count();
    for (_, line) in &lines {
        crate::print_stdout(line)?;
    }
    if failed > 0 {
        bail!("{failed} of {} sketch files failed", lines.len());
    }
    Ok(())
}
