//! `camber fit`: a B-spline (or, split at features, a chain of B-splines) within a tolerance
//! of the points of a point file, with adaptive knots.
//!
//! ```text
//! camber fit POINTS --tolerance TOL [--degree P] [--params centripetal|chord|uniform]
//!     [--knots adaptive|averaged] [--split leading-edge | --split-at U,…] [--joint g1|g2]
//!     -o OUT.json
//! ```
//!
//! A point file is JSON (an array of [x, y], or `{"points": [...]}`), two columns of numbers
//! (blank lines and lines starting with `#` skipped), or an airfoil `.dat` file: the Selig
//! layout (a name line, then x y from the trailing edge over the upper surface to the leading
//! edge and back) or the Lednicer layout (a name line, a line with the point counts of the two
//! surfaces, then each surface from the leading edge to the trailing edge), which is turned into
//! the Selig order. Without a split the output is a curve file (`bspline`); with one it is a
//! composite file `{"pieces": [curve, …], "joints": [k, …], "continuity": "G1", "max_error": e}`.

use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Context, Result};
use camber_geom::fit::{
    fit_split, fit_to_tolerance_with, FitOptions, JointContinuity, KnotPlacement, SplitAt,
};
use camber_geom::Budget;
use clap::{Args, ValueEnum};
use nalgebra::Point2;
use serde_json::json;

use super::geometry_op::{parse_points, ParamsArg};
use crate::curve_file::{self, Curve};

/// The most points a point file may hold (the file size limit bounds it too).
pub const MAX_POINTS: usize = 1_000_000;

/// How the knots are placed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum KnotsArg {
    /// Spread by the errors of trial fits (the fewest control points).
    Adaptive,
    /// Averaged from the data parameters.
    Averaged,
}

/// Where to split.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SplitArg {
    /// At the point of smallest x.
    LeadingEdge,
}

/// How split pieces meet.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum JointArg {
    /// Same point and tangent direction.
    G1,
    /// Same point, tangent direction and curvature.
    G2,
}

/// Arguments of `camber fit`.
#[derive(Debug, Args)]
pub struct FitArgs {
    /// The point file (JSON, two columns, or a Selig or Lednicer airfoil .dat file).
    pub points: PathBuf,
    /// The largest distance from a point to the curve (length units).
    #[arg(long, value_name = "TOL", allow_negative_numbers = true)]
    pub tolerance: f64,
    /// The degree.
    #[arg(long, default_value_t = 3, value_name = "P")]
    pub degree: usize,
    /// How the points get their first parameters.
    #[arg(long, value_enum, default_value_t = ParamsArg::Centripetal)]
    pub params: ParamsArg,
    /// How the knots are placed.
    #[arg(long, value_enum, default_value_t = KnotsArg::Adaptive)]
    pub knots: KnotsArg,
    /// Split at a feature: each side gets its own curve.
    #[arg(long, value_enum, conflicts_with = "split_at")]
    pub split: Option<SplitArg>,
    /// Split at the points nearest these data parameters in (0, 1).
    #[arg(long, value_delimiter = ',', value_name = "U,…")]
    pub split_at: Option<Vec<f64>>,
    /// How split pieces meet.
    #[arg(long, value_enum, default_value_t = JointArg::G1)]
    pub joint: JointArg,
    /// The output file: a curve file, or a composite file when split.
    #[arg(short, long, value_name = "OUT.json")]
    pub output: PathBuf,
}

/// Parses one line of numbers.
fn numbers(line: &str) -> Option<Vec<f64>> {
    line.split(|c: char| c.is_whitespace() || c == ',')
        .filter(|t| !t.is_empty())
        .map(|t| t.parse::<f64>().ok())
        .collect()
}

/// Parses the text of a point file (see the module header).
pub fn parse_point_file(text: &str) -> Result<Vec<Point2<f64>>> {
    let trimmed = text.trim_start();
    if trimmed.starts_with('[') || trimmed.starts_with('{') {
        return parse_points(text);
    }
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'))
        .peekable();
    // A first line that is not two numbers is the name of a .dat file.
    if let Some((_, first)) = lines.peek() {
        if numbers(first).is_none_or(|v| v.len() != 2) {
            lines.next();
        }
    }
    let mut rows: Vec<(usize, f64, f64)> = Vec::new();
    for (number, line) in lines {
        let values = numbers(line)
            .filter(|v| v.len() == 2)
            .ok_or_else(|| anyhow!("line {number}: expected two numbers, found \"{line}\""))?;
        if let Some(bad) = values.iter().find(|v| !v.is_finite()) {
            bail!("line {number}: {bad} is not a finite number");
        }
        if rows.len() >= MAX_POINTS {
            bail!("more than {MAX_POINTS} points");
        }
        rows.push((number, values[0], values[1]));
    }
    if rows.is_empty() {
        bail!("no points");
    }
    // Lednicer: the first row holds the two surfaces' point counts, which add up to the rows
    // that follow (a column file whose first point happens to be two whole numbers does not
    // add up, and stays a column file).
    let (_, a, b) = rows[0];
    let is_count = |v: f64| (1.0..=MAX_POINTS as f64).contains(&v) && v.fract() == 0.0;
    if is_count(a) && is_count(b) && (a + b) as usize == rows.len() - 1 {
        let upper = a as usize;
        let pts: Vec<Point2<f64>> = rows[1..]
            .iter()
            .map(|&(_, x, y)| Point2::new(x, y))
            .collect();
        let (up, low) = pts.split_at(upper);
        let mut out: Vec<Point2<f64>> = up.iter().rev().copied().collect();
        // The lower surface starts at the same leading-edge point: keep it once.
        let skip = usize::from(low.first().zip(up.first()).is_some_and(|(l, u)| l == u));
        out.extend(low.iter().skip(skip));
        return Ok(out);
    }
    Ok(rows
        .into_iter()
        .map(|(_, x, y)| Point2::new(x, y))
        .collect())
}

/// Reads a point file.
pub fn load_point_file(path: &Path) -> Result<Vec<Point2<f64>>> {
    let text = curve_file::read_text(path)?;
    parse_point_file(&text).with_context(|| path.display().to_string())
}

/// Runs `camber fit`.
pub fn run(args: &FitArgs) -> Result<()> {
    let points = load_point_file(&args.points)?;
    let options = FitOptions {
        degree: args.degree,
        method: args.params.into(),
        knots: match args.knots {
            KnotsArg::Adaptive => KnotPlacement::Adaptive,
            KnotsArg::Averaged => KnotPlacement::Averaged,
        },
        fixed_ends: true,
    };
    let split = match (&args.split, &args.split_at) {
        (Some(SplitArg::LeadingEdge), _) => Some(SplitAt::LeadingEdge),
        (None, Some(list)) => Some(SplitAt::Parameters(list.clone())),
        (None, None) => None,
    };
    let context = || args.points.display().to_string();
    let (text, note) = match split {
        None => {
            let fit = fit_to_tolerance_with(&points, args.tolerance, &options, &Budget::default())
                .with_context(context)?;
            let note = format!(
                "{} control points, max error {:e}",
                fit.curve.control_points().len(),
                fit.max_error
            );
            (Curve::BSpline(fit.curve).to_json()?, note)
        }
        Some(at) => {
            let joint = match args.joint {
                JointArg::G1 => JointContinuity::G1,
                JointArg::G2 => JointContinuity::G2,
            };
            let fit = fit_split(
                &points,
                args.tolerance,
                &options,
                &at,
                joint,
                &Budget::default(),
            )
            .with_context(context)?;
            let counts: Vec<String> = fit
                .pieces
                .iter()
                .map(|p| p.curve.control_points().len().to_string())
                .collect();
            let pieces = fit
                .pieces
                .into_iter()
                .map(|p| {
                    serde_json::from_str(&Curve::BSpline(p.curve).to_json()?).map_err(Into::into)
                })
                .collect::<Result<Vec<serde_json::Value>>>()?;
            let value = json!({
                "pieces": pieces,
                "joints": fit.joints,
                "continuity": if joint == JointContinuity::G1 { "G1" } else { "G2" },
                "max_error": fit.max_error,
            });
            let note = format!(
                "{} pieces of {} control points, max error {:e}",
                counts.len(),
                counts.join(" + "),
                fit.max_error
            );
            (serde_json::to_string_pretty(&value)?, note)
        }
    };
    crate::output::write_all(&[&args.points], &[(args.output.clone(), text)])?;
    println!("wrote {}: {note}", args.output.display());
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn selig_lednicer_and_columns_give_the_same_points() {
        let selig = "NACA test\n 1.0 0.01\n 0.5 0.05\n 0.0 0.0\n 0.5 -0.05\n 1.0 -0.01\n";
        let lednicer = "NACA test\n 3. 3.\n\n 0.0 0.0\n 0.5 0.05\n 1.0 0.01\n\n 0.0 0.0\n 0.5 -0.05\n 1.0 -0.01\n";
        let columns = "# x y\n1 0.01\n0.5 0.05\n0 0\n0.5 -0.05\n1 -0.01\n";
        let a = parse_point_file(selig).unwrap();
        assert_eq!(a.len(), 5);
        assert_eq!(parse_point_file(lednicer).unwrap(), a);
        assert_eq!(parse_point_file(columns).unwrap(), a);
        assert_eq!(
            parse_point_file("[[1, 0.01], [0.5, 0.05], [0, 0], [0.5, -0.05], [1, -0.01]]").unwrap(),
            a
        );
    }

    #[test]
    fn whole_numbers_that_do_not_count_the_rows_are_a_point() {
        // "2 3" cannot be Lednicer counts of the two rows after it: three points.
        let pts = parse_point_file("2 3\n4 5\n6 7\n").unwrap();
        assert_eq!(
            pts,
            vec![
                Point2::new(2.0, 3.0),
                Point2::new(4.0, 5.0),
                Point2::new(6.0, 7.0)
            ]
        );
    }

    #[test]
    fn bad_point_files_name_the_line() {
        let err = |t: &str| parse_point_file(t).unwrap_err().to_string();
        assert_eq!(err(""), "no points");
        assert_eq!(err("name only\n"), "no points");
        assert!(
            err("1 2\n3 nan\n").contains("line 2"),
            "{}",
            err("1 2\n3 nan\n")
        );
        assert!(err("1 2\n3 4 5\n").contains("line 2: expected two numbers"));
        assert!(err("1 2\n1e999 0\n").contains("line 2"));
    }
}
