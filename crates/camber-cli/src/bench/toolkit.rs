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

use std::time::{Duration, Instant};

use anyhow::Result;
use camber_geom::arc_length::{arc_length, arc_length_map};
use camber_geom::fit::{fit_to_tolerance, ParameterMethod};
use camber_geom::offset::offset;
use camber_geom::queries::{intersect_curves, CurveCurveOptions};
use camber_geom::{BSplineCurve2, KnotVector, ParametricCurve};
use indicatif::ProgressBar;
use nalgebra::Point2;

use super::{row, Plan, Row, Workload};

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

/// Runs of each case at size `n`: 3 up to 10,000 control points, 1 above (each is seconds).
fn repeats(plan: &Plan, n: usize) -> usize {
    if plan.mode == "quick" || n > 10_000 {
        1
    } else {
        3
    }
}

/// The number of timed runs, for the progress bar.
pub(super) fn steps(plan: &Plan) -> usize {
    CASES.len()
        * plan
            .toolkit_sizes
            .iter()
            .map(|&n| repeats(plan, n))
            .sum::<usize>()
}

/// T: every case at every size, the growth exponent of the median from the previous size.
pub(super) fn toolkit(plan: &Plan, bar: &ProgressBar) -> Result<Vec<Row>> {
    let mut rows = Vec::new();
    for (name, case) in CASES {
        let mut previous: Option<(usize, f64)> = None;
        for &n in &plan.toolkit_sizes {
            bar.set_message(format!("T {name} N={n}"));
            let (mut times, mut valid, mut failed) = (Vec::<Duration>::new(), 0, 0);
            for _ in 0..repeats(plan, n) {
                let t0 = Instant::now();
                let outcome = case(n);
                times.push(t0.elapsed());
                bar.inc(1);
                match outcome {
                    Ok(ok) => valid += usize::from(ok),
                    Err(_) => failed += 1,
                }
            }
            let mut r = row(Workload::T, format!("{name} N={n}"), &times, valid);
            r.size = Some(n);
            r.failed = failed;
            if let Some((m, t)) = previous {
                r.growth = Some((r.median_s / t).ln() / (n as f64 / m as f64).ln());
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
    fn every_case_is_valid_on_a_small_curve() {
        for (name, case) in CASES {
            assert!(case(200).unwrap(), "{name}");
        }
    }
}
