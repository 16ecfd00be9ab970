//! The `camber` command line as a library: the argument definitions, one module per
//! subcommand, the curve file format, the SVG writer (which the sketch commands reuse), the
//! scene that `render` and the editor both draw, the editor's request handling, and
//! [`output`], through which every command writes its files all or nothing.
//!
//! The binary (`src/main.rs`) only parses the arguments, calls [`run`] and turns an error into
//! one line on stderr with exit code 2. The commands:
//!
//! ```text
//! camber eval CURVE.json --at 0,0.5,1 [--derivs K]      points, derivatives, curvature as JSON
//! camber eval CURVE.json --arc-length [--at U,…]       length (and length to each U) as JSON
//! camber op CURVE.json split --at U -o A.json --second B.json
//! camber op CURVE.json insert-knot --at U [--times R] -o OUT.json
//! camber op CURVE.json elevate [--times T] -o OUT.json
//! camber op CURVE.json reverse -o OUT.json
//! camber op CURVE.json reparam --to A,B -o OUT.json
//! camber op CURVE.json extend [--end start|end] (--to U | --length L [--continuity g1|g2]) -o OUT.json
//! camber op POINTS.json fit [--degree P] (--tolerance TOL | --control-points N [--fixed-ends]) -o OUT.json
//! camber op POINTS.json interpolate [--degree P] [--params uniform|chord|centripetal] -o OUT.json
//! camber op CURVE.json remove-knot (--at U [--times R] | --all) [--tolerance TOL] -o OUT.json
//! camber op CURVE.json reduce-degree [--tolerance TOL] -o OUT.json
//! camber op CURVE.json offset --distance D [--tolerance TOL] -o OUT.json
//! camber intersect A.json B.json [--tolerance TOL]     intersections and closest pair as JSON
//! camber render-curve CURVE.json -o PIC.svg [--combs]
//! camber surface CASE.json -o FACE.json [--plot PIC.svg]
//! camber solve SKETCH.json -o OUT.json [--svg PIC.svg] [--json]   solve, write, report
//! camber check SKETCH.json [--json]                     DOF, redundant and conflicting constraints
//! camber render SKETCH.json -o PIC.svg [--combs]        draw a sketch with constraint glyphs
//! camber edit SKETCH.json [--port N] [--bind ADDR --allow-remote] [-o OUT.json] [--open]
//! camber import DRAWING.dxf|PICTURE.svg -o SKETCH.json [--join-tolerance T] [--svg-units U] [--strict]
//! camber export SKETCH.json -o DRAWING.dxf [--binary]   a sketch's geometry as DXF
//! camber demo [-o DIR]                                  solve the bundled blade section
//! camber bench [--only W2,W3] [--quick] [--sizes N,…] [--json]   the standard workloads
//! ```
//!
//! Every failure prints one line `error: <file>: <problem>` on stderr and exits with code 2;
//! success exits with 0. The curve file format is described in [`curve_file`], the sketch file
//! format in [`camber_sketch::file`] (and docs/file-format.md).
//!
//! ```
//! use camber_cli::{commands::eval::evaluate, curve_file::Curve};
//! let line = Curve::from_json(r#"{"type": "bezier", "control_points": [[0, 0], [4, 2]]}"#)?;
//! let e = evaluate(line.as_parametric(), &[0.25], 1)?;
//! assert!((e[0].point[0] - 1.0).abs() < 1e-15 && (e[0].derivatives[0][1] - 2.0).abs() < 1e-15);
//! # Ok::<(), anyhow::Error>(())
//! ```

pub mod bench;
pub mod commands;
pub mod curve_file;
pub mod draw;
pub mod editor;
// The fuzz targets' entry points (fuzz/), shared with their corpus replay test; not an API.
#[doc(hidden)]
pub mod fuzz_support;
pub mod output;
pub mod scene;
pub mod sketch_file;
pub mod svg;

use anyhow::Result;
use clap::{Parser, Subcommand};

use commands::{
    batch, bench as bench_cmd, check, demo, edit, eval, export, fit, import, intersect, op, render,
    render_curve, solve, surface,
};

/// The camber command line: curve files, surface deformation and SVG pictures.
#[derive(Debug, Parser)]
#[command(name = "camber", version, about, after_help = CURVE_FILE_HELP)]
pub struct Cli {
    /// The largest input file read, in MiB (default 64; at most 1048576). A 100,000-cell
    /// ladder sketch is 95 MB of JSON: `camber --max-input-mib 200 solve ladder.json …`.
    #[arg(long, global = true, value_name = "MIB", value_parser = clap::value_parser!(u64).range(1..=curve_file::MAX_INPUT_MIB_LIMIT))]
    pub max_input_mib: Option<u64>,
    /// The subcommand to run.
    #[command(subcommand)]
    pub command: Command,
}

/// The curve file format, shown under `camber --help`.
const CURVE_FILE_HELP: &str = "\
Curve files are JSON objects tagged by \"type\" (2D points as [x, y]):
  {\"type\": \"bezier\",  \"control_points\": [[0, 0], [1, 2], [3, 2], [4, 0]]}
  {\"type\": \"bspline\", \"degree\": 2, \"knots\": [0, 0, 0, 1, 1, 1], \"control_points\": [...]}
  {\"type\": \"nurbs\",   \"degree\": 2, \"knots\": [...], \"control_points\": [...], \"weights\": [...]}
  {\"type\": \"hermite\", \"p0\": [0, 0], \"p1\": [1, 0], \"t0\": [1, 1], \"t1\": [1, -1]}
Errors print one line `error: ...` and exit with code 2. Output files are written all or
nothing, never over an input. Full reference: docs/cli.md.";

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Evaluate a curve file: point, derivatives and signed curvature per parameter, as JSON.
    Eval(eval::EvalArgs),
    /// Edit a curve file: split, insert-knot, elevate, reverse, reparam, extend, remove-knot,
    /// reduce-degree, offset; fit and interpolate a points file.
    #[command(after_help = OP_HELP)]
    Op(op::OpArgs),
    /// Fit a B-spline (or, split at the leading edge, a chain of them) within a tolerance of a
    /// point file: JSON, two columns, or a Selig or Lednicer airfoil .dat file.
    Fit(fit::FitArgs),
    /// Where two curve files meet (both parameters, tangential or not) and their closest pair.
    Intersect(intersect::IntersectArgs),
    /// Draw a curve file as SVG: the curve, its control polygon, optionally curvature combs.
    RenderCurve(render_curve::RenderCurveArgs),
    /// Deform a face to G1 continuity with its neighbours; write the face, print the report.
    Surface(surface::SurfaceArgs),
    /// Solve a sketch file: write the result, print solver, DOF, residual and time per component.
    Solve(solve::SolveArgs),
    /// The DOF analysis of a sketch file: free DOF, redundant and conflicting constraints,
    /// warnings; exit 0 when the analysis runs (conflicts included), 2 otherwise.
    Check(check::CheckArgs),
    /// Draw a sketch file as SVG with constraint glyphs; conflicting constraints in red.
    Render(render::RenderArgs),
    /// Serve the interactive editor for a sketch file on this machine: drag points, solve, save.
    Edit(edit::EditArgs),
    /// Solve the bundled blade section, write blade_section.svg, print the report.
    Demo(demo::DemoArgs),
    /// Run the standard workloads W1–W5b: median, p95 and valid counts per case.
    Bench(bench_cmd::BenchArgs),
    /// Solve every sketch file of a directory in parallel: one JSON line per file.
    Batch(batch::BatchArgs),
    /// Import a DXF file or an SVG document as a sketch: lines, circles, arcs, ellipses,
    /// polylines, splines and paths, with their joins; what is left out is listed.
    Import(import::ImportArgs),
    /// Export a sketch's geometry as a DXF file (text, or binary with --binary).
    Export(export::ExportArgs),
}

/// Which operation works on which curve type, shown under `camber op --help`.
const OP_HELP: &str = "\
Supported:  split (all types; Hermite pieces are reparameterized to [0, 1]),
            insert-knot (bspline, nurbs), elevate (bezier, bspline, nurbs),
            reverse (all), reparam (bspline, nurbs), extend (all), remove-knot (bspline,
            nurbs), reduce-degree (bezier, bspline, nurbs), offset (all);
            fit and interpolate read a points file ([[x, y], ...]) instead of a curve.
split writes the piece before U to -o and the piece after U to --second.
Example:    camber op blade.json split --at 0.5 -o front.json --second back.json";

/// Runs one parsed command line.
pub fn run(cli: &Cli) -> Result<()> {
    if let Some(mib) = cli.max_input_mib {
        curve_file::set_input_limit(mib << 20);
    }
    match &cli.command {
        Command::Eval(a) => eval::run(a),
        Command::Op(a) => op::run(a),
        Command::Fit(a) => fit::run(a),
        Command::Intersect(a) => intersect::run(a),
        Command::RenderCurve(a) => render_curve::run(a),
        Command::Surface(a) => surface::run(a),
        Command::Solve(a) => solve::run(a),
        Command::Check(a) => check::run(a),
        Command::Render(a) => render::run(a),
        Command::Edit(a) => edit::run(a),
        Command::Demo(a) => demo::run(a),
        Command::Bench(a) => bench_cmd::run(a),
        Command::Batch(a) => batch::run(a),
        Command::Import(a) => import::run(a),
        Command::Export(a) => export::run(a),
    }
}

/// Prints `text` and a newline on stdout. A closed pipe (`camber eval … | head`) is not an
/// error: the reader has what it wanted.
pub fn print_stdout(text: &str) -> Result<()> {
    use std::io::Write as _;
    let mut out = std::io::stdout().lock();
    match writeln!(out, "{text}").and_then(|()| out.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
            Err(anyhow::anyhow!("cannot write to stdout: {e}"))
        }
        _ => Ok(()),
    }
}

/// `text` with every long number (more than 24 digits, such as the 300 digits Rust prints for
/// 1e-300 in plain notation) rewritten by [`short_number`], so messages stay readable
/// whatever values they quote.
///
/// ```
/// use camber_cli::tidy_numbers;
/// let long = format!("radius {} is not positive", -1e-300);
/// assert_eq!(tidy_numbers(&long), "radius -1e-300 is not positive");
/// assert_eq!(tidy_numbers("entity 12 at u = 0.25"), "entity 12 at u = 0.25");
/// ```
pub fn tidy_numbers(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let starts_number = bytes[i].is_ascii_digit()
            && (i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_'));
        if !starts_number {
            let c = text[i..].chars().next().unwrap_or(' ');
            out.push(c);
            i += c.len_utf8();
            continue;
        }
        let mut j = i;
        while j < bytes.len() && (bytes[j].is_ascii_digit() || bytes[j] == b'.') {
            j += 1;
        }
        if j < bytes.len() && (bytes[j] == b'e' || bytes[j] == b'E') {
            let mut k = j + 1;
            if k < bytes.len() && (bytes[k] == b'-' || bytes[k] == b'+') {
                k += 1;
            }
            if k < bytes.len() && bytes[k].is_ascii_digit() {
                while k < bytes.len() && bytes[k].is_ascii_digit() {
                    k += 1;
                }
                j = k;
            }
        }
        let token = &text[i..j];
        let digits = token.bytes().filter(u8::is_ascii_digit).count();
        match token.parse::<f64>() {
            // f64's shortest form has at most 17 significant digits, so only a plain-notation
            // number of extreme size is this long (an id of u64 has at most 20 digits).
            Ok(v) if digits > 24 => out.push_str(&short_number(v)),
            _ => out.push_str(token),
        }
        i = j;
    }
    out
}

/// A number for messages, with a bounded number of digits: up to 6 significant digits in
/// plain notation between 1e-4 and 1e6, otherwise scientific with up to 5 (`1e308`,
/// `-9.9999e-321` for a subnormal -1e-320), and the words for non-finite values.
///
/// ```
/// use camber_cli::short_number;
/// assert_eq!(short_number(0.5), "0.5");
/// assert_eq!(short_number(1e308), "1e308");
/// assert_eq!(short_number(-1.25e-7), "-1.25e-7");
/// assert_eq!(short_number(1234.56789), "1234.57");
/// assert_eq!(short_number(f64::NAN), "NaN (not a number)");
/// ```
pub fn short_number(v: f64) -> String {
    if v.is_nan() {
        return "NaN (not a number)".to_owned();
    }
    if v.is_infinite() {
        return if v > 0.0 { "infinity" } else { "-infinity" }.to_owned();
    }
    if v.classify() == std::num::FpCategory::Zero {
        return "0".to_owned();
    }
    let a = v.abs();
    if (1e-4..1e6).contains(&a) {
        // Six significant digits: decimals = 5 − floor(log10 |v|).
        let decimals = (5 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{v:.decimals$}");
        let s = if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_owned()
        } else {
            s
        };
        return s;
    }
    let s = format!("{v:.4e}");
    match s.split_once('e') {
        Some((mantissa, exp)) => {
            let m = if mantissa.contains('.') {
                mantissa.trim_end_matches('0').trim_end_matches('.')
            } else {
                mantissa
            };
            format!("{m}e{exp}")
        }
        None => s,
    }
}
