//! The geometry operations of `camber op`: extend, fit, interpolate, remove-knot,
//! reduce-degree and offset. Each writes one curve file and prints one line saying what it
//! wrote and, where the operation approximates, its measured error or bound.
//!
//! | operation     | input                  | result  |
//! |---------------|------------------------|---------|
//! | extend        | bezier, bspline, nurbs, hermite | same kind (bezier → bspline by length; hermite as its bezier) |
//! | fit           | a points file          | bspline |
//! | interpolate   | a points file          | bspline |
//! | remove-knot   | bspline, nurbs         | same kind |
//! | reduce-degree | bezier, bspline, nurbs | same kind |
//! | offset        | any curve              | bspline |
//!
//! A points file is a JSON array of [x, y] pairs, or an object `{"points": [[x, y], …]}`.

use std::path::Path;

use anyhow::{anyhow, bail, Context, Result};
use camber_geom::extend::{CurveEnd, ExtensionContinuity};
use camber_geom::fit::{approximate, fit_to_tolerance, interpolate, Fit, ParameterMethod};
use camber_geom::offset::offset;
use camber_geom::BezierCurve2;
use clap::{Subcommand, ValueEnum};
use nalgebra::{Point2, Vector2};
use serde_json::Value;

use super::op::Output;
use crate::curve_file::{self, Curve};

/// Which end to extend.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum EndArg {
    /// The start of the domain.
    Start,
    /// The end of the domain.
    End,
}

/// The continuity of an extension by a length.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ContinuityArg {
    /// A straight piece along the end tangent.
    G1,
    /// The end piece continued naturally.
    G2,
}

/// How data points get parameters.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ParamsArg {
    /// Evenly spaced.
    Uniform,
    /// Proportional to chord length.
    Chord,
    /// Proportional to the square roots of the chord lengths.
    Centripetal,
}

impl From<ParamsArg> for ParameterMethod {
    fn from(p: ParamsArg) -> Self {
        match p {
            ParamsArg::Uniform => ParameterMethod::Uniform,
            ParamsArg::Chord => ParameterMethod::ChordLength,
            ParamsArg::Centripetal => ParameterMethod::Centripetal,
        }
    }
}

/// The geometry operations (flattened into `camber op`'s list).
#[derive(Debug, Subcommand)]
pub enum GeometryOp {
    /// Extend the curve beyond one end: to a parameter (--to, natural extrapolation) or by a
    /// length (--length, with --continuity g1 or g2).
    Extend {
        /// Which end.
        #[arg(long, value_enum, default_value_t = EndArg::End)]
        end: EndArg,
        /// The new domain end (below the start or above the end).
        #[arg(
            long,
            allow_negative_numbers = true,
            value_name = "U",
            conflicts_with = "length"
        )]
        to: Option<f64>,
        /// The length to add (length units).
        #[arg(long, value_name = "L", required_unless_present = "to")]
        length: Option<f64>,
        /// The continuity of an extension by a length.
        #[arg(long, value_enum, default_value_t = ContinuityArg::G2)]
        continuity: ContinuityArg,
        /// The output file.
        #[command(flatten)]
        out: Output,
    },
    /// Fit a B-spline to the points file: within --tolerance with automatic knots, or with
    /// --control-points N by least squares.
    Fit {
        /// The degree.
        #[arg(long, default_value_t = 3, value_name = "P")]
        degree: usize,
        /// The largest distance from a point to the curve (at its parameter).
        #[arg(long, value_name = "TOL", required_unless_present = "control_points")]
        tolerance: Option<f64>,
        /// Least squares with this many control points instead of a tolerance.
        #[arg(long, value_name = "N", conflicts_with = "tolerance")]
        control_points: Option<usize>,
        /// With --control-points: the curve starts and ends on the first and last points.
        #[arg(long, requires = "control_points")]
        fixed_ends: bool,
        /// How the points are parameterized.
        #[arg(long, value_enum, default_value_t = ParamsArg::Chord)]
        params: ParamsArg,
        /// The output file.
        #[command(flatten)]
        out: Output,
    },
    /// Interpolate the points file with a B-spline through every point.
    Interpolate {
        /// The degree.
        #[arg(long, default_value_t = 3, value_name = "P")]
        degree: usize,
        /// How the points are parameterized.
        #[arg(long, value_enum, default_value_t = ParamsArg::Chord)]
        params: ParamsArg,
        /// The derivative at the start (per unit of the [0, 1] parameter), with --end-derivative.
        #[arg(long, value_parser = parse_pair, allow_hyphen_values = true, value_name = "X,Y",
            requires = "end_derivative")]
        start_derivative: Option<(f64, f64)>,
        /// The derivative at the end, with --start-derivative.
        #[arg(long, value_parser = parse_pair, allow_hyphen_values = true, value_name = "X,Y",
            requires = "start_derivative")]
        end_derivative: Option<(f64, f64)>,
        /// The output file.
        #[command(flatten)]
        out: Output,
    },
    /// Remove an interior knot (--at U, up to --times R) or every removable knot (--all),
    /// moving the curve by at most --tolerance (B-spline; NURBS with --at).
    RemoveKnot {
        /// The knot to remove.
        #[arg(
            long,
            allow_negative_numbers = true,
            value_name = "U",
            required_unless_present = "all"
        )]
        at: Option<f64>,
        /// How many times to remove it.
        #[arg(long, default_value_t = 1, value_name = "R")]
        times: usize,
        /// Remove every knot as often as the tolerance allows.
        #[arg(long, conflicts_with = "at")]
        all: bool,
        /// How far the curve may move (0: only exactly removable knots).
        #[arg(long, default_value_t = 0.0, value_name = "TOL")]
        tolerance: f64,
        /// The output file.
        #[command(flatten)]
        out: Output,
    },
    /// Lower the degree by one (exact for elevated curves); prints the error bound.
    ReduceDegree {
        /// The tolerance for restoring the knots' continuity (B-spline, NURBS).
        #[arg(long, default_value_t = 0.0, value_name = "TOL")]
        tolerance: f64,
        /// The output file.
        #[command(flatten)]
        out: Output,
    },
    /// The offset curve at signed --distance (positive to the left) as a cubic B-spline.
    Offset {
        /// The signed distance.
        #[arg(long, allow_negative_numbers = true, value_name = "D")]
        distance: f64,
        /// The largest distance between the result and the exact offset.
        #[arg(long, default_value_t = 1e-6, value_name = "TOL")]
        tolerance: f64,
        /// The output file.
        #[command(flatten)]
        out: Output,
    },
}

/// Parses `X,Y`.
fn parse_pair(s: &str) -> std::result::Result<(f64, f64), String> {
    let parts: Vec<&str> = s.split(',').collect();
    let [a, b] = parts.as_slice() else {
        return Err(format!("expected two numbers X,Y, found \"{s}\""));
    };
    let number = |t: &str| {
        t.trim()
            .parse::<f64>()
            .map_err(|_| format!("\"{t}\" is not a number"))
    };
    Ok((number(a)?, number(b)?))
}

impl GeometryOp {
    /// The operation's name on the command line.
    pub fn name(&self) -> &'static str {
        match self {
            GeometryOp::Extend { .. } => "extend",
            GeometryOp::Fit { .. } => "fit",
            GeometryOp::Interpolate { .. } => "interpolate",
            GeometryOp::RemoveKnot { .. } => "remove-knot",
            GeometryOp::ReduceDegree { .. } => "reduce-degree",
            GeometryOp::Offset { .. } => "offset",
        }
    }

    /// Where the result goes.
    pub fn output(&self) -> &Path {
        match self {
            GeometryOp::Extend { out, .. }
            | GeometryOp::Fit { out, .. }
            | GeometryOp::Interpolate { out, .. }
            | GeometryOp::RemoveKnot { out, .. }
            | GeometryOp::ReduceDegree { out, .. }
            | GeometryOp::Offset { out, .. } => &out.output,
        }
    }

    /// Whether the input file is a points file rather than a curve file.
    pub fn reads_points(&self) -> bool {
        matches!(
            self,
            GeometryOp::Fit { .. } | GeometryOp::Interpolate { .. }
        )
    }

    /// The result curve and a note (error, bound, count) for the printed line.
    pub fn apply_to_points(&self, points: &[Point2<f64>]) -> Result<(Curve, String)> {
        let fit: Fit<f64, 2> = match self {
            GeometryOp::Fit {
                degree,
                tolerance,
                control_points,
                fixed_ends,
                params,
                ..
            } => match (tolerance, control_points) {
                (_, Some(n)) => approximate(points, *degree, *n, (*params).into(), *fixed_ends)?,
                (Some(tol), None) => fit_to_tolerance(points, *degree, *tol, (*params).into())?,
                (None, None) => bail!("fit needs --tolerance or --control-points"),
            },
            GeometryOp::Interpolate {
                degree,
                params,
                start_derivative,
                end_derivative,
                ..
            } => {
                let ends = match (start_derivative, end_derivative) {
                    (Some((a, b)), Some((c, d))) => {
                        Some((Vector2::new(*a, *b), Vector2::new(*c, *d)))
                    }
                    _ => None,
                };
                interpolate(points, *degree, (*params).into(), ends)?
            }
            _ => bail!("{} works on a curve file, not on points", self.name()),
        };
        let note = format!("max error {:e}", fit.max_error);
        Ok((Curve::BSpline(fit.curve), note))
    }

    /// The result curve and a note for the printed line.
    pub fn apply(&self, curve: &Curve) -> Result<(Curve, String)> {
        use Curve::{BSpline, Bezier, Hermite, Nurbs};
        let unsupported = |why: &str| -> Result<(Curve, String)> {
            bail!(
                "{} is not available for {} curves ({why})",
                self.name(),
                curve.type_name()
            )
        };
        let out = match self {
            GeometryOp::Extend {
                end,
                to,
                length,
                continuity,
                ..
            } => {
                let end = match end {
                    EndArg::Start => CurveEnd::Start,
                    EndArg::End => CurveEnd::End,
                };
                let cont = match continuity {
                    ContinuityArg::G1 => ExtensionContinuity::G1,
                    ContinuityArg::G2 => ExtensionContinuity::G2,
                };
                let bezier: Option<BezierCurve2<f64>> = match curve {
                    Bezier(c) => Some(c.clone()),
                    Hermite(c) => Some(c.to_bezier()?),
                    _ => None,
                };
                let result = match (to, length, curve, bezier) {
                    (Some(u), _, BSpline(c), _) => BSpline(c.extrapolated(end, *u)?),
                    (Some(u), _, Nurbs(c), _) => Nurbs(c.extrapolated(end, *u)?),
                    (Some(u), _, _, Some(b)) => Bezier(b.extrapolated(end, *u)?),
                    (None, Some(l), BSpline(c), _) => BSpline(c.extended_by_length(end, *l, cont)?),
                    (None, Some(l), Nurbs(c), _) => Nurbs(c.extended_by_length(end, *l, cont)?),
                    (None, Some(l), _, Some(b)) => BSpline(b.extended_by_length(end, *l, cont)?),
                    _ => bail!("extend needs --to or --length"),
                };
                let (a, b) = result.as_parametric().domain();
                (result, format!("new domain [{a}, {b}]"))
            }
            GeometryOp::RemoveKnot {
                at,
                times,
                all,
                tolerance,
                ..
            } => {
                let (result, removed, bound) = match (curve, at, all) {
                    (BSpline(c), Some(u), _) => {
                        let r = c.remove_knot(*u, *times, *tolerance)?;
                        (BSpline(r.curve), r.removed, r.error_bound)
                    }
                    (BSpline(c), None, true) => {
                        let r = c.remove_knots(*tolerance)?;
                        (BSpline(r.curve), r.removed, r.error_bound)
                    }
                    (Nurbs(c), Some(u), _) => {
                        let r = c.remove_knot(*u, *times, *tolerance)?;
                        (Nurbs(r.curve), r.removed, r.error_bound)
                    }
                    (Nurbs(_), None, _) => return unsupported("--all works on B-splines only"),
                    (BSpline(_), None, false) => bail!("remove-knot needs --at or --all"),
                    _ => return unsupported("it has no knots"),
                };
                (result, format!("removed {removed}, error bound {bound:e}"))
            }
            GeometryOp::ReduceDegree { tolerance, .. } => {
                let (result, bound) = match curve {
                    Bezier(c) => {
                        let r = c.reduce_degree()?;
                        (Bezier(r.curve), r.error_bound)
                    }
                    BSpline(c) => {
                        let r = c.reduce_degree(*tolerance)?;
                        (BSpline(r.curve), r.error_bound)
                    }
                    Nurbs(c) => {
                        let r = c.reduce_degree(*tolerance)?;
                        (Nurbs(r.curve), r.error_bound)
                    }
                    Hermite(_) => return unsupported("a Hermite curve is always cubic"),
                };
                (result, format!("error bound {bound:e}"))
            }
            GeometryOp::Offset {
                distance,
                tolerance,
                ..
            } => {
                let o = offset(curve.as_parametric(), *distance, *tolerance)?;
                (BSpline(o.curve), format!("max error {:e}", o.max_error))
            }
            GeometryOp::Fit { .. } | GeometryOp::Interpolate { .. } => {
                bail!("{} reads a points file, not a curve file", self.name())
            }
        };
        Ok(out)
    }
}

/// Reads a points file: a JSON array of [x, y], or `{"points": [...]}`.
pub fn load_points(path: &Path) -> Result<Vec<Point2<f64>>> {
    let text = curve_file::read_text(path)?;
    parse_points(&text).with_context(|| path.display().to_string())
}

/// Parses the text of a points file.
pub fn parse_points(text: &str) -> Result<Vec<Point2<f64>>> {
    let value: Value = serde_json::from_str(text).map_err(curve_file::json_syntax_error)?;
    let list = match &value {
        Value::Array(a) => a,
        Value::Object(o) => match o.get("points") {
            Some(Value::Array(a)) => a,
            _ => bail!("a points file holds an array of [x, y] or {{\"points\": [...]}}"),
        },
        _ => bail!("a points file holds an array of [x, y] or {{\"points\": [...]}}"),
    };
    list.iter()
        .enumerate()
        .map(|(i, p)| {
            let pair = p
                .as_array()
                .filter(|a| a.len() == 2)
                .ok_or_else(|| anyhow!("point {i} is not a pair [x, y]"))?;
            let x = pair[0]
                .as_f64()
                .ok_or_else(|| anyhow!("point {i}: x is not a number"))?;
            let y = pair[1]
                .as_f64()
                .ok_or_else(|| anyhow!("point {i}: y is not a number"))?;
            Ok(Point2::new(x, y))
        })
        .collect()
}

/// Runs a geometry operation on the input file and writes the result.
pub fn run(input: &Path, op: &GeometryOp) -> Result<()> {
    let context = || input.display().to_string();
    let (result, note) = if op.reads_points() {
        let points = load_points(input)?;
        op.apply_to_points(&points).with_context(context)?
    } else {
        let curve = curve_file::load(input)?;
        op.apply(&curve).with_context(context)?
    };
    let path = op.output();
    let text = result
        .to_json()
        .with_context(|| path.display().to_string())?;
    crate::output::write_all(&[input], &[(path.to_path_buf(), text)])?;
    println!(
        "wrote {}: {}; {note}",
        path.display(),
        curve_file::describe(&result)
    );
    Ok(())
}
