//! T: the curve toolkit at growing sizes — arc length, the arc-length map, knot removal,
//! curve–curve intersection, offsets and fitting — each on a curve (or data) of N control
//! points, N from [`Plan::toolkit_sizes`](super::Plan), with the growth exponent of the median
//! time between consecutive sizes (near-linear work means an exponent near 1).
//!
//! The curves are built in index space, so a curve of 10N control points is ten curves of N
//! end to end and the work per piece does not change with N: a clamped cubic B-spline through
//! (i/10, sin(1.3x) + 0.3 cos(3.1x)), and for the intersection its mirror image in y = 0.05,
//! which it crosses about once every 25 control points. Tolerances are absolute (the curve's
//! height is about 1.3 whatever N); every result is checked:
//!
//! | case | operation | valid when |
//! | --- | --- | --- |
//! | arc length | `arc_length`, tolerance 1e-9 | within 1e-6 relative of the control polygon's chord sum bound from below, error estimate ≤ tolerance |
//! | arc-length map | `arc_length_map`, 1e-8 | max_error ≤ 1e-8 |
//! | knot removal | `remove_knots`, 1e-4 | bound ≤ 1e-4 and some knots removed |
//! | intersection | `intersect_curves` with the mirror image | every contact within 1e-9, as many as sign changes of y − 0.05 along the curve |
//! | offset | `offset` by 0.05, 1e-6 | max_error ≤ 1e-6 |
//! | fitting | `fit_to_tolerance` of 4N points on the curve, 1e-4 | max_error ≤ 1e-4 with fewer than 2N control points |
//!
//! The times are the process's CPU time (`CLOCK_PROCESS_CPUTIME_ID`, all threads), not wall
//! time: a run at N = 1,000 takes a fraction of a millisecond, and on a shared machine the
//! wall time of so short a run measures the other processes as much as the toolkit. Each size
//! is run until its runs add up to [`MIN_TOTAL`] of CPU time and at least [`MIN_RUNS`] runs
//! (runs longer than [`LONG_TOTAL`] together stop earlier), and the median run is reported, so
//! the growth exponent compares like with like. The `--quick` plan runs each size once.

use std::time::Duration;

use anyhow::Result;
use camber_geom::arc_length::{arc_length, arc_length_map};
use camber_geom::fit::{fit_to_tolerance, ParameterMethod};
use camber_geom::offset::offset;
use camber_geom::queries::{intersect_curves, CurveCurveOptions};
use camber_geom::{BSplineCurve2, KnotVector, ParametricCurve};
use indicatif::ProgressBar;
use nalgebra::Point2;

use super::{row, set_growth, Plan, Row, Workload};

/// The wave through N control points (see the module documentation), reflected in
/// y = 0.05 when `mirror`.
fn wave(n: usize, mirror: bool) -> Result<BSplineCurve2<f64>> {
    let points = (0..n)
        .map(|i| {
            let x = i as f64 / 10.0;
            let y = (1.3 * x).sin() + 0.3 * (3.1 * x).cos();
            Point2::new(x, if mirror { 0.1 - y } else { y })
        })
        .collect();
    Ok(BSplineCurve2::try_new(
        3,
        KnotVector::clamped_uniform(3, n)?,
        points,
    )?)
}

/// The toolkit cases in table order, each a name and a run returning whether its result is
/// valid.
type Case = (&'static str, fn(usize) -> Result<bool>);

const CASES: [Case; 6] = [
    ("arc length", arc_length_case),
    ("arc-length map", map_case),
    ("knot removal", removal_case),
    ("intersection", intersection_case),
    ("offset", offset_case),
    ("fitting", fitting_case),
];

fn arc_length_case(n: usize) -> Result<bool> {
    let c = wave(n, false)?;
    let l = arc_length(&c, 1e-9)?;
    // The chord sum through 8 points per span bounds the length from below and is within
    // about h²κ of it.
    let mut chords = 0.0;
    for w in c.breakpoints().windows(2) {
        let mut last = c.point(w[0])?;
        for k in 1..=8 {
            let p = c.point(w[0] + (w[1] - w[0]) * f64::from(k) / 8.0)?;
            chords += (p - last).norm();
            last = p;
        }
    }
    Ok(l.error_estimate <= l.tolerance
        && chords <= l.length + 1e-9
        && l.length - chords < 1e-4 * l.length)
}

fn map_case(n: usize) -> Result<bool> {
    let map = arc_length_map(&wave(n, false)?, 1e-8)?;
    Ok(map.max_error() <= 1e-8)
}

fn removal_case(n: usize) -> Result<bool> {
    let r = wave(n, false)?.remove_knots(1e-4)?;
    Ok(r.error_bound <= 1e-4 && r.removed > 0)
}

fn intersection_case(n: usize) -> Result<bool> {
    let (c, mirror) = (wave(n, false)?, wave(n, true)?);
    let hits = intersect_curves(&c, &mirror, &CurveCurveOptions::default())?;
    // Both curves have x(u) the same increasing function, so they meet exactly where
    // y(u) = 0.05: count the sign changes of y − 0.05 on 16 samples per span.
    let mut crossings = 0;
    let mut last: Option<bool> = None;
    for w in c.breakpoints().windows(2) {
        for k in 0..16 {
            let above = c.point(w[0] + (w[1] - w[0]) * f64::from(k) / 16.0)?.y > 0.05;
            crossings += usize::from(last.is_some_and(|l| l != above));
            last = Some(above);
        }
    }
    Ok(hits.iter().all(|h| h.distance <= 1e-9) && hits.len() == crossings)
}

fn offset_case(n: usize) -> Result<bool> {
    Ok(offset(&wave(n, false)?, 0.05, 1e-6)?.max_error <= 1e-6)
}

fn fitting_case(n: usize) -> Result<bool> {
    let c = wave(n, false)?;
    let (a, b) = c.domain();
    let m = 4 * n;
    let points = (0..=m)
        .map(|i| c.point(a + (b - a) * i as f64 / m as f64))
        .collect::<camber_geom::Result<Vec<_>>>()?;
    let fit = fit_to_tolerance(&points, 3, 1e-4, ParameterMethod::ChordLength)?;
    Ok(fit.max_error <= 1e-4 && fit.curve.control_points().len() < 2 * n)
}

/// Runs of one size: at least this many (unless they take [`LONG_TOTAL`] together) …
const MIN_RUNS: usize = 3;
/// … and until they add up to this much CPU time, so the median of sub-millisecond runs is
/// not one scheduler tick's noise.
const MIN_TOTAL: Duration = Duration::from_millis(300);
/// Runs that add up to this much stop even before [`MIN_RUNS`] (a run of seconds is measured
/// well once; the 10⁵ maps and offsets would otherwise take minutes).
const LONG_TOTAL: Duration = Duration::from_secs(2);
/// At most this many runs of one size, whatever their times.
const MAX_RUNS: usize = 100_000;

/// The process's CPU time so far: user and system time of all its threads.
#[cfg(unix)]
fn cpu_time() -> Duration {
    let t = rustix::time::clock_gettime(rustix::time::ClockId::ProcessCPUTime);
    // The clock counts from the start of the process: never negative.
    Duration::new(
        u64::try_from(t.tv_sec).unwrap_or(0),
        u32::try_from(t.tv_nsec).unwrap_or(0),
    )
}

/// Elsewhere, wall time since the first call (the rows then do not say "CPU time").
#[cfg(not(unix))]
fn cpu_time() -> Duration {
    static START: std::sync::OnceLock<std::time::Instant> = std::sync::OnceLock::new();
    START.get_or_init(std::time::Instant::now).elapsed()
}

/// Whether the times are CPU time ([`cpu_time`] is a wall clock off unix).
const CPU_CLOCK: bool = cfg!(unix);

/// Whether another run of a size is due after `runs` runs taking `total` together.
fn another_run(quick: bool, runs: usize, total: Duration) -> bool {
    if runs == 0 {
        return true;
    }
    if quick || runs >= MAX_RUNS {
        return false;
    }
    (runs < MIN_RUNS && total < LONG_TOTAL) || total < MIN_TOTAL
}

/// The number of progress steps: one per case and size.
pub(super) fn steps(plan: &Plan) -> usize {
    CASES.len() * plan.toolkit_sizes.len()
}

/// The CPU time of every run of `case` at size `n` (see the module documentation for how
/// many), with the count of valid results and of failed runs.
fn measure(
    case: fn(usize) -> Result<bool>,
    n: usize,
    quick: bool,
) -> (Vec<Duration>, usize, usize) {
    let (mut times, mut valid, mut failed) = (Vec::new(), 0, 0);
    let mut total = Duration::ZERO;
    while another_run(quick, times.len(), total) {
        let t0 = cpu_time();
        let outcome = case(n);
        let t = cpu_time().saturating_sub(t0);
        total += t;
        times.push(t);
        match outcome {
            Ok(ok) => valid += usize::from(ok),
            Err(_) => failed += 1,
        }
    }
    (times, valid, failed)
}

/// T: every case at every size, the growth exponent of the median from the previous size.
pub(super) fn toolkit(plan: &Plan, bar: &ProgressBar) -> Result<Vec<Row>> {
    let mut rows = Vec::new();
    for (name, case) in CASES {
        let mut previous: Option<(usize, f64)> = None;
        for &n in &plan.toolkit_sizes {
            bar.set_message(format!("T {name} N={n}"));
            let (times, valid, failed) = measure(case, n, plan.mode == "quick");
            bar.inc(1);
            let mut r = row(Workload::T, format!("{name} N={n}"), &times, valid);
            r.size = Some(n);
            r.failed = failed;
            r.cpu_time = CPU_CLOCK;
            if let Some((m, t)) = previous {
                set_growth(&mut r, m, t);
            }
            previous = Some((n, r.median_s));
            rows.push(r);
        }
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_runs_repeat_until_they_add_up_and_long_ones_stop_early() {
        let ms = Duration::from_millis;
        // Sub-millisecond runs: three are not enough, 0.3 s of them are.
        assert!(another_run(false, 3, ms(1)));
        assert!(another_run(false, 1_000, ms(299)));
        assert!(!another_run(false, 1_000, ms(300)));
        // Runs of 0.5 s: three of them.
        assert!(another_run(false, 2, ms(1_000)));
        assert!(!another_run(false, 3, ms(1_500)));
        // One run of 5 s is enough; every size runs at least once; quick runs once.
        assert!(!another_run(false, 1, ms(5_000)));
        assert!(another_run(false, 0, ms(0)) && another_run(true, 0, ms(0)));
        assert!(!another_run(true, 1, ms(0)));
        assert!(!another_run(false, MAX_RUNS, ms(0)));
    }

    #[test]
    fn the_cpu_clock_counts_work_done() {
        let t0 = cpu_time();
        let mut x = 0.0_f64;
        for i in 0..2_000_000 {
            x = std::hint::black_box(x + f64::from(i).sqrt());
        }
        assert!(x > 0.0);
        assert!(cpu_time() > t0);
    }

    #[test]
    fn every_case_is_valid_on_a_small_curve() {
        for (name, case) in CASES {
            assert!(case(200).unwrap(), "{name}");
        }
    }
}
