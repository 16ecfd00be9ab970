//! Control-point counts, errors and times of `fit_to_tolerance_with` on the NACA benchmark
//! sections (15 codes × 6 point counts × cosine and uniform spacing) at 1e-3, 1e-4 and 1e-5
//! chord: the camber side of the comparison in crates/camber-py/bench/fit_airfoils.py.
//!
//!     cargo run --release -p camber-geom --example fit_airfoils [centripetal|chord|uniform] [-v]

use std::time::Instant;

use camber_geom::budget::Budget;
use camber_geom::fit::{fit_to_tolerance_with, FitOptions, ParameterMethod};
use camber_workloads::airfoils::{naca, Spacing, BENCH_CODES, BENCH_COUNTS};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let method = match std::env::args().nth(1).as_deref() {
        Some("chord") => ParameterMethod::ChordLength,
        Some("uniform") => ParameterMethod::Uniform,
        _ => ParameterMethod::Centripetal,
    };
    let verbose = std::env::args().any(|a| a == "-v");
    let only = std::env::var("FITONLY").ok();
    let options = FitOptions::default().with_method(method);
    for tol in [1e-3, 1e-4, 1e-5] {
        let (mut counts, mut times, mut interpolated, mut worst) =
            (Vec::new(), Vec::new(), 0, 0.0_f64);
        for code in BENCH_CODES {
            for n in BENCH_COUNTS {
                for spacing in [Spacing::Cosine, Spacing::Uniform] {
                    let name = format!("{code}-{n}-{spacing:?}@{tol:e}");
                    if only.as_ref().is_some_and(|o| *o != name) {
                        continue;
                    }
                    let pts = naca(code, n, spacing).ok_or("bad section")?;
                    let t0 = Instant::now();
                    let fit = fit_to_tolerance_with(&pts, tol, &options, &Budget::default())?;
                    times.push(t0.elapsed().as_secs_f64() * 1e3);
                    let c = fit.curve.control_points().len();
                    interpolated += usize::from(c == pts.len());
                    worst = worst.max(fit.max_error / tol);
                    counts.push(c);
                    if verbose {
                        println!(
                            "{code}-{n}-{spacing:?}@{tol:e} {c} {:.3e} {:.2} ms",
                            fit.max_error,
                            times[times.len() - 1]
                        );
                    }
                }
            }
        }
        if counts.is_empty() {
            continue;
        }
        counts.sort_unstable();
        times.sort_by(f64::total_cmp);
        println!(
            "tol {tol:e}: median {} control points (mean {:.1}), {interpolated} interpolated, \
             largest error/tol {worst:.3}, median {:.2} ms, slowest {:.2} ms",
            counts[counts.len() / 2],
            counts.iter().sum::<usize>() as f64 / counts.len() as f64,
            times[times.len() / 2],
            times[times.len() - 1]
        );
    }
    Ok(())
}
