//! `camber bench`: run the standard workloads W1–W5b and print medians, p95 and valid counts
//! as a table, as JSON with `--json`, or beside a saved report with `--compare FILE`. See
//! [`crate::bench`] for what is measured.

use std::io::IsTerminal as _;
use std::time::Duration;

use anyhow::{Context, Result};
use clap::Args;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use crate::bench::{self, Plan, Report, Workload};

/// Arguments of `camber bench`.
#[derive(Debug, Args)]
pub struct BenchArgs {
    /// Run only these workloads (repeat the flag or give a comma list: `--only W2,W3a`).
    #[arg(long, value_enum, value_delimiter = ',', value_name = "W")]
    pub only: Vec<Workload>,
    /// A small run (fewer trials and sizes; labelled "quick"), for smoke tests.
    #[arg(long)]
    pub quick: bool,
    /// Sizes N for W3, W3a (segments), W5, W5r (rectangles) and W5b (cells) instead of
    /// 10,100,1000,10000; each from 1 to 100000.
    #[arg(long, value_delimiter = ',', value_name = "N", value_parser = chain_size)]
    pub sizes: Vec<usize>,
    /// Print JSON (the plan and one object per case) instead of the table.
    #[arg(long)]
    pub json: bool,
    /// Compare with a saved `--json` report (benches/baseline.json, say): print each case's
    /// median now and then and their ratio, marking cases more than 20 % slower or with fewer
    /// valid results.
    #[arg(long, value_name = "FILE", conflicts_with = "json")]
    pub compare: Option<std::path::PathBuf>,
    /// Write the sketch of one chain workload (`--only W3` or `W3a`, the default W3) at one
    /// size (`--sizes N`, the default 1000) as a sketch file, unsolved, instead of running
    /// anything: the input `camber edit`, `camber check` and `camber solve` read.
    #[arg(long, value_name = "OUT.json", conflicts_with_all = ["json", "compare", "quick"])]
    pub write_sketch: Option<std::path::PathBuf>,
}

/// The chain size `--write-sketch` writes when `--sizes` is not given.
pub const DEFAULT_SKETCH_SIZE: usize = 1000;

/// `--write-sketch`: the W3 or W3a chain of one size, as sketch file text.
///
/// # Errors
/// More than one workload or size, a workload that is not a chain, or a chain the workload
/// cannot build.
pub fn chain_sketch(only: &[Workload], sizes: &[usize]) -> Result<String> {
    let workload = match only {
        [] => Workload::W3,
        [w @ (Workload::W3 | Workload::W3a)] => *w,
        _ => anyhow::bail!(
            "--write-sketch writes one chain: give --only W3 or --only W3a (or neither, for W3)"
        ),
    };
    let n = match sizes {
        [] => DEFAULT_SKETCH_SIZE,
        [n] => *n,
        _ => anyhow::bail!("--write-sketch writes one chain: give one --sizes N"),
    };
    let (sketch, _) = match workload {
        Workload::W3a => camber_workloads::w3a_chain(n)?,
        _ => camber_workloads::w3_chain(n)?,
    };
    camber_sketch::file::to_json(&sketch)
        .with_context(|| format!("cannot write the {} chain", workload.name()))
}

/// The largest size `--sizes` accepts: ten times the standard plan's largest chain, which
/// already takes minutes; a larger one would only exhaust memory.
pub const MAX_CHAIN_SIZE: usize = 100_000;

/// Parses one `--sizes` entry: a whole number from 1 to [`MAX_CHAIN_SIZE`].
fn chain_size(s: &str) -> std::result::Result<usize, String> {
    let n: usize = s
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a whole number"))?;
    if n == 0 || n > MAX_CHAIN_SIZE {
        return Err(format!("{n} is outside 1..={MAX_CHAIN_SIZE}"));
    }
    Ok(n)
}

/// Runs the chosen workloads and prints the table or the JSON. The progress bar goes to
/// stderr, and only when stderr is a terminal and the output is not JSON.
pub fn run(args: &BenchArgs) -> Result<()> {
    if let Some(&n) = args.sizes.iter().find(|&&n| n == 0 || n > MAX_CHAIN_SIZE) {
        anyhow::bail!("--sizes: {n} is outside 1..={MAX_CHAIN_SIZE}");
    }
    if let Some(path) = &args.write_sketch {
        let text = chain_sketch(&args.only, &args.sizes)?;
        return crate::output::write_all(&[], &[(path.clone(), text)]);
    }
    let plan = if args.quick {
        Plan::quick()
    } else {
        Plan::standard()
    }
    .with_only(&args.only)
    .with_chain_sizes(&args.sizes);
    let bar = if args.json || !std::io::stderr().is_terminal() {
        ProgressBar::hidden()
    } else {
        let bar = ProgressBar::with_draw_target(Some(plan.steps()), ProgressDrawTarget::stderr());
        if let Ok(style) =
            ProgressStyle::with_template("{bar:30} {pos}/{len} solves, {elapsed} {msg}")
        {
            bar.set_style(style);
        }
        bar.enable_steady_tick(Duration::from_millis(200));
        bar
    };
    let baseline = match &args.compare {
        Some(path) => {
            let text = crate::curve_file::read_text(path)?;
            let b: bench::Baseline = serde_json::from_str(&text).with_context(|| {
                format!("{} is not a camber bench --json report", path.display())
            })?;
            Some(b)
        }
        None => None,
    };
    let rows = bench::run(&plan, &bar);
    bar.finish_and_clear();
    let rows = rows?;
    let text = if let Some(b) = &baseline {
        bench::compare(&plan, &rows, b, 1.2)
    } else if args.json {
        serde_json::to_string_pretty(&Report {
            plan: &plan,
            rows: &rows,
        })
        .context("cannot write the report as JSON")?
    } else {
        bench::table(&plan, &rows)
    };
    crate::print_stdout(&text)
}
