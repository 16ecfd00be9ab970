//! `camber eval`: points, derivatives and curvature of a curve file at given parameters,
//! printed as JSON.

use std::path::PathBuf;

use anyhow::{Context, Result};
use camber_geom::queries::signed_curvature_from_derivatives;
use clap::Args;
use serde::Serialize;

use crate::curve_file;

/// Arguments of `camber eval`.
#[derive(Debug, Args)]
pub struct EvalArgs {
    /// The curve file (see `camber help` for the format).
    pub curve: PathBuf,
    /// Parameters to evaluate at, comma separated, inside the curve's domain.
    #[arg(
        long,
        value_delimiter = ',',
        required_unless_present = "arc_length",
        allow_negative_numbers = true,
        value_name = "U[,U...]"
    )]
    pub at: Vec<f64>,
    /// How many derivatives to report (C′ … C⁽ᴷ⁾), at most 64; those above a polynomial
    /// curve's degree are zero.
    #[arg(long, default_value_t = 1, value_name = "K", value_parser = derivative_count)]
    pub derivs: usize,
    /// Print the arc length instead (and, with --at, the length from the start to each U).
    #[arg(long)]
    pub arc_length: bool,
    /// The absolute tolerance of the arc length (length units).
    #[arg(
        long,
        default_value_t = 1e-10,
        value_name = "TOL",
        requires = "arc_length"
    )]
    pub tolerance: f64,
}

/// The most derivatives `eval` reports. Beyond a polynomial curve's degree they are zero, and a
/// rational curve's high derivatives soon leave the f64 range; the bound keeps the output and
/// its memory small whatever is typed.
pub const MAX_DERIVATIVES: usize = 64;

/// Parses `--derivs`: a whole number from 0 to [`MAX_DERIVATIVES`].
fn derivative_count(s: &str) -> std::result::Result<usize, String> {
    match s.trim().parse::<usize>() {
        Ok(k) if k <= MAX_DERIVATIVES => Ok(k),
        _ => Err(format!(
            "`{s}` is not a whole number from 0 to {MAX_DERIVATIVES}"
        )),
    }
}

/// Prints a JSON array with one object per parameter:
/// `{"u": u, "point": [x, y], "derivatives": [[x′, y′], …], "curvature": κ}`, where κ is the
/// signed curvature (positive when the curve turns left; `null` where the speed is zero).
pub fn run(args: &EvalArgs) -> Result<()> {
    let curve = curve_file::load(&args.curve)?;
    if args.arc_length {
        let report = super::arc_length::measure(curve.as_parametric(), &args.at, args.tolerance)
            .with_context(|| args.curve.display().to_string())?;
        if report.tolerance > args.tolerance {
            eprintln!(
                "note: --tolerance {:e} is below what f64 resolves on this curve; measured to \
                 {:e} instead (64 ulps of its length)",
                args.tolerance, report.tolerance
            );
        }
        return crate::print_stdout(&serde_json::to_string_pretty(&report)?);
    }
    let values = evaluate(curve.as_parametric(), &args.at, args.derivs)
        .with_context(|| args.curve.display().to_string())?;
    crate::print_stdout(&serde_json::to_string_pretty(&values)?)
}

/// The values at one parameter, in the order they are printed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Evaluation {
    /// The parameter.
    pub u: f64,
    /// C(u).
    pub point: [f64; 2],
    /// C′(u), …, C⁽ᴷ⁾(u).
    pub derivatives: Vec<[f64; 2]>,
    /// Signed curvature (x′y″ − y′x″)/|C′|³, `None` where C′(u) = 0.
    pub curvature: Option<f64>,
}

/// The evaluations of [`run`] for each parameter in `us`.
///
/// # Errors
/// A parameter outside the domain; more than [`MAX_DERIVATIVES`] derivatives; a value that
/// is not finite in f64 (a curve whose numbers overflow), so no NaN is ever returned.
pub fn evaluate(
    curve: &dyn camber_geom::ParametricCurve<f64, 2>,
    us: &[f64],
    derivs: usize,
) -> Result<Vec<Evaluation>> {
    if derivs > MAX_DERIVATIVES {
        anyhow::bail!("at most {MAX_DERIVATIVES} derivatives can be asked for, not {derivs}");
    }
    us.iter()
        .map(|&u| {
            let d = curve
                .derivatives(u, derivs.max(2))
                .with_context(|| format!("cannot evaluate at u = {u}"))?;
            if let Some((k, _)) = d
                .iter()
                .enumerate()
                .take(derivs + 1)
                .find(|(_, v)| !(v.x.is_finite() && v.y.is_finite()))
            {
                let what = if k == 0 {
                    "the point".to_owned()
                } else {
                    format!("derivative {k}")
                };
                anyhow::bail!(
                    "at u = {u}: {what} is not finite in f64 (the curve's numbers are too large \
                     or too unevenly weighted to evaluate)"
                );
            }
            let pair = |v: &nalgebra::Vector2<f64>| [v.x, v.y];
            let curvature = match (d.get(1), d.get(2)) {
                (Some(d1), Some(d2)) => signed_curvature_from_derivatives(d1, d2),
                _ => None,
            };
            Ok(Evaluation {
                u,
                point: d.first().map_or([f64::NAN; 2], pair),
                derivatives: d.iter().skip(1).take(derivs).map(pair).collect(),
                curvature,
            })
        })
        .collect()
}
