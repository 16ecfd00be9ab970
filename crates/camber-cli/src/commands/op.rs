//! `camber op`: one editing operation on a curve file, written to new curve files.
//!
//! | operation   | bezier | bspline | nurbs | hermite |
//! |-------------|--------|---------|-------|---------|
//! | split       | yes    | yes     | yes   | yes (truncation, each piece over [0, 1]) |
//! | insert-knot | no     | yes     | yes   | no      |
//! | elevate     | yes    | yes     | yes   | no (always cubic) |
//! | reverse     | yes    | yes     | yes   | yes     |
//! | reparam     | no     | yes     | yes   | no (domain fixed to [0, 1]) |

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use camber_geom::curve::check_interior_parameter;
use clap::{Args, Subcommand};

use super::geometry_op::{self, GeometryOp};
use crate::curve_file::{self, Curve};

/// Arguments of `camber op`.
#[derive(Debug, Args)]
pub struct OpArgs {
    /// The curve file to transform.
    pub curve: PathBuf,
    /// The operation.
    #[command(subcommand)]
    pub op: Op,
}

/// Where the result goes.
#[derive(Debug, Args)]
pub struct Output {
    /// The result curve file.
    #[arg(short, long, value_name = "OUT.json")]
    pub output: PathBuf,
}

/// The editing operations; each writes the same geometry in a new representation, except
/// split, which writes the two pieces.
#[derive(Debug, Subcommand)]
pub enum Op {
    /// Split at U: the piece before U goes to -o, the piece after U to --second.
    #[command(mut_arg("output", |a| a.help("The curve file for the first piece (the one before U)")))]
    Split {
        /// The parameter to split at, strictly inside the domain.
        #[arg(long, allow_negative_numbers = true, value_name = "U")]
        at: f64,
        /// The output file.
        #[command(flatten)]
        out: Output,
        /// The curve file for the second piece (the one after U).
        #[arg(long, value_name = "OUT2.json")]
        second: PathBuf,
    },
    /// Insert the knot U R times (B-spline and NURBS); the shape does not change.
    #[command(mut_arg("output", |a| a.help("The curve file written: the curve with the knot inserted")))]
    InsertKnot {
        /// The knot value, inside the domain.
        #[arg(long, allow_negative_numbers = true, value_name = "U")]
        at: f64,
        /// How many times to insert it.
        #[arg(long, default_value_t = 1, value_name = "R")]
        times: usize,
        /// The output file.
        #[command(flatten)]
        out: Output,
    },
    /// Raise the degree T times (Bézier, B-spline, NURBS); the shape does not change.
    #[command(mut_arg("output", |a| a.help("The curve file written: the curve of raised degree")))]
    Elevate {
        /// How many degrees to add.
        #[arg(long, default_value_t = 1, value_name = "T")]
        times: usize,
        /// The output file.
        #[command(flatten)]
        out: Output,
    },
    /// Traverse the curve the other way: the new curve at a + b − u is the old one at u.
    #[command(mut_arg("output", |a| a.help("The curve file written: the reversed curve")))]
    Reverse {
        /// The output file.
        #[command(flatten)]
        out: Output,
    },
    /// Map the domain linearly onto [A, B] (B-spline and NURBS); the shape does not change.
    #[command(mut_arg("output", |a| a.help("The curve file written: the curve on its new domain")))]
    Reparam {
        /// The new domain, A < B.
        #[arg(long, value_parser = parse_interval, allow_hyphen_values = true, value_name = "A,B")]
        to: (f64, f64),
        /// The output file.
        #[command(flatten)]
        out: Output,
    },
    /// Extension, fitting, interpolation, knot removal, degree reduction and offsets
    /// (see [`geometry_op`]).
    #[command(flatten)]
    Geometry(GeometryOp),
}

/// Parses `A,B` into two numbers.
fn parse_interval(s: &str) -> std::result::Result<(f64, f64), String> {
    let parts: Vec<&str> = s.split(',').collect();
    let [a, b] = parts.as_slice() else {
        return Err(format!("expected two numbers A,B, found \"{s}\""));
    };
    let number = |t: &str| {
        t.trim()
            .parse::<f64>()
            .map_err(|_| format!("\"{t}\" is not a number"))
    };
    Ok((number(a)?, number(b)?))
}

impl Op {
    /// The operation's name on the command line.
    pub fn name(&self) -> &'static str {
        match self {
            Op::Split { .. } => "split",
            Op::InsertKnot { .. } => "insert-knot",
            Op::Elevate { .. } => "elevate",
            Op::Reverse { .. } => "reverse",
            Op::Reparam { .. } => "reparam",
            Op::Geometry(g) => g.name(),
        }
    }

    /// The result curves: one, or two for split.
    pub fn apply(&self, curve: &Curve) -> Result<Vec<Curve>> {
        use Curve::{BSpline, Bezier, Hermite, Nurbs};
        let unsupported = |why: &str| -> Result<Vec<Curve>> {
            bail!(
                "{} is not available for {} curves ({why})",
                self.name(),
                curve.type_name()
            )
        };
        let out = match (self, curve) {
            (Op::Geometry(g), c) => vec![g.apply(c)?.0],
            (Op::Split { at, .. }, c) => {
                check_interior_parameter(*at, c.as_parametric().domain())
                    .with_context(|| format!("cannot split at {at}"))?;
                match c {
                    Bezier(c) => pair(c.subdivide(*at)?, Bezier),
                    BSpline(c) => pair(c.split(*at)?, BSpline),
                    Nurbs(c) => pair(c.split(*at)?, Nurbs),
                    Hermite(c) => pair((c.truncated(0.0, *at)?, c.truncated(*at, 1.0)?), Hermite),
                }
            }
            (Op::InsertKnot { at, times, .. }, c) => match c {
                BSpline(c) => vec![BSpline(c.insert_knot(*at, *times)?)],
                Nurbs(c) => vec![Nurbs(c.insert_knot(*at, *times)?)],
                _ => return unsupported("it has no knots"),
            },
            (Op::Elevate { times, .. }, c) => match c {
                Bezier(c) => vec![Bezier(c.try_elevate_degree(*times)?)],
                BSpline(c) => vec![BSpline(c.elevate_degree(*times)?)],
                Nurbs(c) => vec![Nurbs(c.elevate_degree(*times)?)],
                Hermite(_) => return unsupported("a Hermite curve is always cubic"),
            },
            (Op::Reverse { .. }, c) => vec![match c {
                Bezier(c) => Bezier(c.reversed()),
                BSpline(c) => BSpline(c.try_reversed()?),
                Nurbs(c) => Nurbs(c.try_reversed()?),
                Hermite(c) => Hermite(c.reversed()),
            }],
            (Op::Reparam { to: (a, b), .. }, c) => match c {
                BSpline(c) => vec![BSpline(c.reparameterized(*a, *b)?)],
                Nurbs(c) => vec![Nurbs(c.reparameterized(*a, *b)?)],
                _ => return unsupported("its domain is always [0, 1]"),
            },
        };
        Ok(out)
    }

    /// The files the results go to, in the order of [`Op::apply`]'s curves.
    pub fn outputs(&self) -> Vec<&Path> {
        match self {
            Op::Split { out, second, .. } => vec![&out.output, second],
            Op::InsertKnot { out, .. }
            | Op::Elevate { out, .. }
            | Op::Reverse { out }
            | Op::Reparam { out, .. } => vec![&out.output],
            Op::Geometry(g) => vec![g.output()],
        }
    }
}

fn pair<C>((a, b): (C, C), wrap: fn(C) -> Curve) -> Vec<Curve> {
    vec![wrap(a), wrap(b)]
}

/// Loads the curve, applies the operation, writes the result file(s) and prints one line per
/// file written.
pub fn run(args: &OpArgs) -> Result<()> {
    if let Op::Geometry(g) = &args.op {
        return geometry_op::run(&args.curve, g);
    }
    let curve = curve_file::load(&args.curve)?;
    let results = args
        .op
        .apply(&curve)
        .with_context(|| args.curve.display().to_string())?;
    let mut files = Vec::new();
    for (result, path) in results.iter().zip(args.op.outputs()) {
        let text = result
            .to_json()
            .with_context(|| path.display().to_string())?;
        files.push((path.to_path_buf(), text));
    }
    crate::output::write_all(&[&args.curve], &files)?;
    for (result, path) in results.iter().zip(args.op.outputs()) {
        println!("wrote {}: {}", path.display(), curve_file::describe(result));
    }
    Ok(())
}
