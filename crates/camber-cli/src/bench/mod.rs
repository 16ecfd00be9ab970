//! The standard workloads of `shared/benchmarks/WORKLOADS.md`, run and measured for
//! `camber bench`: what to run ([`Plan`]), one result row per case ([`Row`]), the statistics
//! (median and p95 by nearest rank) and the plain-text table.
//!
//! The sketches come from [`camber_workloads`], and so do the validity checks: every
//! result is judged by reading the solved geometry, never by the solver's status, so a solve
//! that reports success on a wrong answer counts as invalid, and a failed solve (which leaves
//! the sketch as it was) counts as invalid unless its start was already valid.
//!
//! ```
//! use camber_cli::bench::{run, Plan, Workload};
//! let plan = Plan::quick().with_only(&[Workload::W4]);
//! let rows = run(&plan, &indicatif::ProgressBar::hidden())?;
//! assert_eq!(rows.len(), 1);
//! assert_eq!(rows[0].valid, rows[0].samples); // every whole-sketch solve is valid
//! # Ok::<(), anyhow::Error>(())
//! ```

mod runners;
mod toolkit;

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::time::Duration;

use anyhow::Result;
use indicatif::ProgressBar;
use serde::{Deserialize, Serialize};

/// A standard workload.
#[derive(
    Debug,
    Clone,
    Copy,
    PartialEq,
    Eq,
    PartialOrd,
    Ord,
    Hash,
    clap::ValueEnum,
    Serialize,
    Deserialize,
)]
#[value(rename_all = "verbatim")]
pub enum Workload {
    /// W1: drag the second control point of a cubic with a directional start tangent.
    #[value(alias = "w1")]
    W1,
    /// W2: a curve tangent to three circles, as one B-spline and as two cubics, and the
    /// B-spline's drag update.
    #[value(alias = "w2")]
    W2,
    /// W3: the G1 chain along a sine wave with free joint directions and fixed chords.
    #[value(alias = "w3")]
    W3,
    /// W3a: the same chain with the joint directions fixed (affine).
    #[value(alias = "w3a", alias = "W3A")]
    W3a,
    /// W4: many independent small components in one sketch.
    #[value(alias = "w4")]
    W4,
    /// W5: many independent rectangles (lines, coincidences, horizontals, verticals, lengths).
    #[value(alias = "w5")]
    W5,
    /// W5b: one ladder of cells (the rectangles' constraints in one component).
    #[value(alias = "w5b", alias = "W5B")]
    W5b,
    /// W5r: W5's rectangles with their four corners rounded by fillet arcs (4 lines, 4 arcs
    /// tangent at both ends, each rectangle fully constrained).
    #[value(alias = "w5r", alias = "W5R")]
    W5r,
    /// W6: W5 with 1,000 rectangles solved, then one rectangle's width edited and the sketch
    /// re-solved (the edit and the re-solve timed).
    #[value(alias = "w6")]
    W6,
    /// W7: a drag of an interior control point of the W3 chain, N = 1,000 and 10,000 (each
    /// update timed).
    #[value(alias = "w7")]
    W7,
    /// W8: 10,000 variants of the W2 B-spline sketch (other circle radii) solved by one
    /// `solve_many` call (total / variants timed).
    #[value(alias = "w8")]
    W8,
    /// A: the DOF analysis (what `camber check` runs) of the W3 chain of N segments, of a
    /// chain of 10·N points held by distances and of the fully constrained W5b ladder of N
    /// cells.
    #[value(alias = "a", alias = "analysis")]
    A,
    /// T: the curve toolkit (arc length, arc-length map, knot removal, intersection, offset,
    /// fitting) on curves of N control points.
    #[value(alias = "t", alias = "toolkit")]
    T,
}

impl Workload {
    /// Every workload, in table order.
    pub const ALL: [Workload; 13] = [
        Workload::W1,
        Workload::W2,
        Workload::W3,
        Workload::W3a,
        Workload::W4,
        Workload::W5,
        Workload::W5b,
        Workload::W5r,
        Workload::W6,
        Workload::W7,
        Workload::W8,
        Workload::A,
        Workload::T,
    ];

    /// "W1", "W2", "W3", "W3a", "W4", "W5", "W5b", "W5r", "W6", "W7", "W8", "A", "T".
    pub fn name(self) -> &'static str {
        match self {
            Workload::W1 => "W1",
            Workload::W2 => "W2",
            Workload::W3 => "W3",
            Workload::W3a => "W3a",
            Workload::W4 => "W4",
            Workload::W5 => "W5",
            Workload::W5b => "W5b",
            Workload::W5r => "W5r",
            Workload::W6 => "W6",
            Workload::W7 => "W7",
            Workload::W8 => "W8",
            Workload::A => "A",
            Workload::T => "T",
        }
    }

    /// The workload of a name as [`Workload::name`] writes it.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|w| w.name() == name)
    }
}

/// What `camber bench` runs: the workloads and their sizes and repetitions. [`Plan::standard`]
/// is WORKLOADS.md as written; [`Plan::quick`] is a smaller run for tests and smoke checks
/// (the same procedures on fewer trials and smaller sizes, labelled "quick" in the output).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Plan {
    /// "standard" or "quick".
    pub mode: &'static str,
    /// The workloads to run, in table order.
    pub only: Vec<Workload>,
    /// W1 and the W2 drag: runs of the 200 drag targets.
    pub w1_runs: usize,
    /// W2: perturbed starts per representation and δ.
    pub w2_trials: usize,
    /// W3, W3a, W5, W5b and W5r: chain lengths, rectangle and cell counts N.
    pub chain_sizes: Vec<usize>,
    /// W4: independent components in the sketch.
    pub w4_components: usize,
    /// W4: solves of the whole sketch.
    pub w4_repeats: usize,
    /// W6: rectangles in the sketch.
    pub w6_rectangles: usize,
    /// W6: width edits, each re-solved.
    pub w6_edits: usize,
    /// W7: chain lengths N dragged.
    pub w7_sizes: Vec<usize>,
    /// W8: variants per batch.
    pub w8_variants: usize,
    /// W8: batches timed (one sample each: total / variants).
    pub w8_runs: usize,
    /// T: control points N of the toolkit's curves.
    pub toolkit_sizes: Vec<usize>,
}

impl Plan {
    /// WORKLOADS.md as written: W1 200 targets × 5 runs, W2 100 trials per representation and
    /// δ, W3, W3a, W5, W5b and W5r for N = 10, 100, 1,000, 10,000, W4 with 10,000 components; and
    /// the toolkit workload T at N = 1,000, 10,000, 100,000 control points.
    pub fn standard() -> Self {
        Plan {
            mode: "standard",
            only: Workload::ALL.to_vec(),
            w1_runs: 5,
            w2_trials: 100,
            chain_sizes: vec![10, 100, 1_000, 10_000],
            w4_components: 10_000,
            w4_repeats: 5,
            w6_rectangles: 1_000,
            w6_edits: 200,
            w7_sizes: vec![1_000, 10_000],
            w8_variants: 10_000,
            w8_runs: 3,
            toolkit_sizes: vec![1_000, 10_000, 100_000],
        }
    }

    /// A small run: W1 200 targets × 1 run, W2 10 trials, chains and rectangles N = 10 and 100,
    /// W4 with 100 components, the toolkit at N = 100 and 1,000.
    pub fn quick() -> Self {
        Plan {
            mode: "quick",
            only: Workload::ALL.to_vec(),
            w1_runs: 1,
            w2_trials: 10,
            chain_sizes: vec![10, 100],
            w4_components: 100,
            w4_repeats: 2,
            w6_rectangles: 100,
            w6_edits: 20,
            w7_sizes: vec![100],
            w8_variants: 100,
            w8_runs: 1,
            toolkit_sizes: vec![100, 1_000],
        }
    }

    /// Keeps only `only` (all when empty), in table order.
    pub fn with_only(mut self, only: &[Workload]) -> Self {
        if !only.is_empty() {
            self.only = Workload::ALL
                .into_iter()
                .filter(|w| only.contains(w))
                .collect();
        }
        self
    }

    /// Replaces the sizes N of W3, W3a, W5, W5b and W5r.
    pub fn with_chain_sizes(mut self, sizes: &[usize]) -> Self {
        if !sizes.is_empty() {
            self.chain_sizes = sizes.to_vec();
        }
        self
    }

    /// Solves timed for a chain of `n` segments (or `n` rectangles, cells): 20 up to N = 100,
    /// 5 up to 1,000, 3 above (2 in the quick mode).
    pub fn chain_repeats(&self, n: usize) -> usize {
        if self.mode == "quick" {
            2
        } else if n <= 100 {
            20
        } else if n <= 1_000 {
            5
        } else {
            3
        }
    }

    /// The number of timed solves or updates, for the progress bar.
    pub fn steps(&self) -> u64 {
        let mut n = 0;
        for w in &self.only {
            n += match w {
                Workload::W1 => 2 * self.w1_runs * 200,
                Workload::W2 => 4 * self.w2_trials + self.w1_runs * 200,
                Workload::W3 | Workload::W3a | Workload::W5 | Workload::W5b | Workload::W5r => self
                    .chain_sizes
                    .iter()
                    .map(|&s| self.chain_repeats(s))
                    .sum(),
                Workload::W4 => self.w4_repeats,
                Workload::W6 => self.w6_edits,
                Workload::W7 => self.w7_sizes.len() * 200,
                Workload::W8 => self.w8_runs * self.w8_variants,
                Workload::A => {
                    4 * self
                        .chain_sizes
                        .iter()
                        .map(|&s| self.chain_repeats(s))
                        .sum::<usize>()
                }
                Workload::T => toolkit::steps(self),
            };
        }
        n as u64
    }
}

/// "moved / min-norm" over W1's updates: the displacement of the free points divided by the
/// least displacement that meets the constraints (1.00 is minimum-norm behaviour).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Ratio {
    /// The median over the updates.
    pub median: f64,
    /// The largest.
    pub max: f64,
}

/// One measured case: a workload at one representation, perturbation or size.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Row {
    /// The workload.
    pub workload: Workload,
    /// The case within it ("row form", "bspline7 δ=0.05", "N=1000", …).
    pub case: String,
    /// The problem size where it varies (W3/W3a segments, W4 components).
    pub size: Option<usize>,
    /// Timed solves or drag updates.
    pub samples: usize,
    /// Median time, seconds.
    pub median_s: f64,
    /// 95th percentile time (nearest rank), seconds.
    pub p95_s: f64,
    /// Samples whose result passed the workload's own validity check.
    pub valid: usize,
    /// Samples whose solve or update returned an error.
    pub failed: usize,
    /// Which solver finished each component, counted over the samples.
    pub solvers: BTreeMap<String, usize>,
    /// W3/W3a/W5/W5b/T: the growth exponent log(t₂/t₁)/log(N₂/N₁) of the median from the previous size.
    pub growth: Option<f64>,
    /// The size is that of the row before (`--sizes 10,10`): there is no growth to measure.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub same_size_as_previous: bool,
    /// W1: moved / min-norm.
    pub moved_over_min_norm: Option<Ratio>,
    /// W1: the median time of an empty timed section (two clock reads), seconds. Each W1
    /// sample is one update between two clock reads, so its time includes this much that is
    /// not the update's; it is reported, not subtracted.
    #[serde(default)]
    pub timer_s: Option<f64>,
    /// T: the times are the process's CPU time, not wall time.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub cpu_time: bool,
}

/// The q-quantile (0 < q ≤ 1) of `sorted` by nearest rank: the ⌈q·n⌉-th smallest.
///
/// ```
/// let v = [1.0, 2.0, 3.0, 4.0];
/// assert_eq!(camber_cli::bench::quantile(&v, 0.5), 2.0);
/// assert_eq!(camber_cli::bench::quantile(&v, 0.95), 4.0);
/// ```
pub fn quantile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let rank = (q * sorted.len() as f64).ceil() as usize;
    sorted[rank.clamp(1, sorted.len()) - 1]
}

/// Sorted seconds of `times`.
fn seconds(times: &[Duration]) -> Vec<f64> {
    let mut s: Vec<f64> = times.iter().map(Duration::as_secs_f64).collect();
    s.sort_by(f64::total_cmp);
    s
}

/// A row with the times' median and p95 filled in and no extras.
fn row(workload: Workload, case: String, times: &[Duration], valid: usize) -> Row {
    let s = seconds(times);
    Row {
        workload,
        case,
        size: None,
        samples: times.len(),
        median_s: quantile(&s, 0.5),
        p95_s: quantile(&s, 0.95),
        valid,
        failed: 0,
        solvers: BTreeMap::new(),
        growth: None,
        same_size_as_previous: false,
        moved_over_min_norm: None,
        timer_s: None,
        cpu_time: false,
    }
}

/// Sets `r.growth` to the growth exponent log(t₂/t₁)/log(N₂/N₁) of its median from the row of
/// size `previous_size` and median `previous_median`; between equal sizes there is none (the
/// quotient would be ±∞ or NaN), and the row says so. No exponent either when a median is not
/// a positive time.
///
/// ```
/// use camber_cli::bench::{set_growth, Row, Workload};
/// let mut r: Row = serde_json::from_str(r#"{"workload": "W3", "case": "N=100", "size": 100,
///     "samples": 1, "median_s": 0.4, "p95_s": 0.4, "valid": 1, "failed": 0, "solvers": {},
///     "growth": null, "moved_over_min_norm": null}"#)?;
/// set_growth(&mut r, 10, 0.04);
/// assert!((r.growth.unwrap() - 1.0).abs() < 1e-12);
/// set_growth(&mut r, 100, 0.3);
/// assert!(r.growth.is_none() && r.same_size_as_previous);
/// # Ok::<(), serde_json::Error>(())
/// ```
pub fn set_growth(r: &mut Row, previous_size: usize, previous_median: f64) {
    r.growth = None;
    r.same_size_as_previous = false;
    let Some(size) = r.size else {
        return;
    };
    if size == previous_size {
        r.same_size_as_previous = true;
        return;
    }
    if r.median_s > 0.0 && previous_median > 0.0 && previous_size > 0 {
        let g = (r.median_s / previous_median).ln() / (size as f64 / previous_size as f64).ln();
        r.growth = g.is_finite().then_some(g);
    }
}

/// Runs the plan's workloads in table order, ticking `bar` once per timed sample.
///
/// # Errors
/// A workload sketch that cannot be built, or a W2 rough start that does not solve (the base
/// every trial starts from).
pub fn run(plan: &Plan, bar: &ProgressBar) -> Result<Vec<Row>> {
    let mut rows = Vec::new();
    for w in &plan.only {
        match w {
            Workload::W1 => rows.extend(runners::w1(plan, bar)?),
            Workload::W2 => rows.extend(runners::w2(plan, bar)?),
            Workload::W3 => rows.extend(runners::chains(plan, false, bar)?),
            Workload::W3a => rows.extend(runners::chains(plan, true, bar)?),
            Workload::W4 => rows.push(runners::w4(plan, bar)?),
            Workload::W5 => rows.extend(runners::rectangles(plan, false, bar)?),
            Workload::W5b => rows.extend(runners::rectangles(plan, true, bar)?),
            Workload::W5r => rows.extend(runners::rounded_rectangles(plan, bar)?),
            Workload::W6 => rows.push(runners::w6(plan, bar)?),
            Workload::W7 => rows.extend(runners::w7(plan, bar)?),
            Workload::W8 => rows.push(runners::w8(plan, bar)?),
            Workload::A => rows.extend(runners::analysis(plan, bar)?),
            Workload::T => rows.extend(toolkit::toolkit(plan, bar)?),
        }
    }
    Ok(rows)
}

/// A duration in seconds as "87 ns", "12.3 µs", "4.56 ms" or "1.23 s".
///
/// ```
/// assert_eq!(camber_cli::bench::human(8.7e-8), "87 ns");
/// assert_eq!(camber_cli::bench::human(2.5e-6), "2.5 µs");
/// assert_eq!(camber_cli::bench::human(0.0123), "12.30 ms");
/// assert_eq!(camber_cli::bench::human(4.0), "4.00 s");
/// ```
pub fn human(s: f64) -> String {
    if !s.is_finite() {
        "-".to_owned()
    } else if s < 1e-6 {
        format!("{:.0} ns", s * 1e9)
    } else if s < 1e-3 {
        format!("{:.1} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.2} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

/// The notes column: solver counts, failures, growth, the W1 ratio.
fn notes(r: &Row) -> String {
    let mut parts = Vec::new();
    if let Some(ratio) = r.moved_over_min_norm {
        parts.push(format!(
            "moved/min-norm {:.3} (max {:.3})",
            ratio.median, ratio.max
        ));
    }
    if let Some(t) = r.timer_s {
        parts.push(format!("timer {} included", human(t)));
    }
    if r.cpu_time {
        parts.push("CPU time".to_owned());
    }
    if let Some(g) = r.growth {
        parts.push(format!("growth {g:.2}"));
    }
    if r.same_size_as_previous {
        parts.push("no growth (same N as the row before)".to_owned());
    }
    if !r.solvers.is_empty() {
        let list: Vec<String> = r.solvers.iter().map(|(k, n)| format!("{k} {n}")).collect();
        parts.push(format!("solver: {}", list.join(", ")));
    }
    if r.failed > 0 {
        parts.push(format!("{} failed", r.failed));
    }
    parts.join("; ")
}

/// The plain-text table: one line per row with median, p95, valid count and notes.
pub fn table(plan: &Plan, rows: &[Row]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "camber bench ({} plan; times per solve or drag update)",
        plan.mode
    );
    let _ = writeln!(
        out,
        "{:<5} {:<22} {:>7} {:>11} {:>11} {:>11}  notes",
        "load", "case", "samples", "median", "p95", "valid"
    );
    for r in rows {
        let _ = writeln!(
            out,
            "{:<5} {:<22} {:>7} {:>11} {:>11} {:>11}  {}",
            r.workload.name(),
            r.case,
            r.samples,
            human(r.median_s),
            human(r.p95_s),
            format!("{}/{}", r.valid, r.samples),
            notes(r)
        );
    }
    out.trim_end().to_owned()
}

/// The JSON document of `camber bench --json`: the plan and the rows.
#[derive(Debug, Serialize)]
pub struct Report<'a> {
    /// What was run.
    pub plan: &'a Plan,
    /// One per case.
    pub rows: &'a [Row],
}

/// The rows of a saved `camber bench --json` report (its plan is not needed to compare).
#[derive(Debug, Deserialize)]
pub struct Baseline {
    /// One per case.
    pub rows: Vec<Row>,
}

/// The table of a run beside a baseline: per case the median now, the baseline's, their ratio
/// (now / baseline: below 1 is faster) and both valid counts. Cases missing from the baseline
/// show "-"; a ratio above `flag` (e.g. 1.2) is marked "slower", and a valid count that fell is
/// marked "fewer valid".
///
/// ```
/// use camber_cli::bench::{compare, run, Baseline, Plan, Workload};
/// let plan = Plan::quick().with_only(&[Workload::W4]);
/// let rows = run(&plan, &indicatif::ProgressBar::hidden())?;
/// let baseline = Baseline { rows: rows.clone() };
/// let text = compare(&plan, &rows, &baseline, 1.2);
/// assert!(text.contains("1.00"));
/// # Ok::<(), anyhow::Error>(())
/// ```
pub fn compare(plan: &Plan, rows: &[Row], baseline: &Baseline, flag: f64) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "camber bench ({} plan) against a baseline: ratio = median now / median then",
        plan.mode
    );
    let _ = writeln!(
        out,
        "{:<5} {:<22} {:>11} {:>11} {:>7} {:>11} {:>11}  notes",
        "load", "case", "now", "then", "ratio", "valid now", "valid then"
    );
    for r in rows {
        let then = baseline
            .rows
            .iter()
            .find(|b| b.workload == r.workload && b.case == r.case);
        let (then_median, ratio, then_valid, notes) = match then {
            Some(b) => {
                let ratio = r.median_s / b.median_s;
                let mut notes = Vec::new();
                if ratio > flag {
                    notes.push("slower");
                }
                if r.valid * b.samples < b.valid * r.samples {
                    notes.push("fewer valid");
                }
                (
                    human(b.median_s),
                    format!("{ratio:.2}"),
                    format!("{}/{}", b.valid, b.samples),
                    notes.join(", "),
                )
            }
            None => (
                "-".into(),
                "-".into(),
                "-".into(),
                "not in the baseline".into(),
            ),
        };
        let _ = writeln!(
            out,
            "{:<5} {:<22} {:>11} {:>11} {:>7} {:>11} {:>11}  {}",
            r.workload.name(),
            r.case,
            human(r.median_s),
            then_median,
            ratio,
            format!("{}/{}", r.valid, r.samples),
            then_valid,
            notes
        );
    }
    out.trim_end().to_owned()
}
