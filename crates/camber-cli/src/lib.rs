//! The `camber` command line as a library: the argument definitions, one module per
//! subcommand, the curve file format, the SVG writer (which the sketch commands reuse), the
//! scene that `render` and the editor both draw, and the editor's request handling.
//!
//! The binary (`src/main.rs`) only parses the arguments, calls [`run`] and turns an error into
//! one line on stderr with exit code 2. The commands:
//!
//! ```text
//! camber eval CURVE.json --at 0,0.5,1 [--derivs K]      points, derivatives, curvature as JSON
//! camber op CURVE.json split --at U -o A.json --second B.json
//! camber op CURVE.json insert-knot --at U [--times R] -o OUT.json
//! camber op CURVE.json elevate [--times T] -o OUT.json
//! camber op CURVE.json reverse -o OUT.json
//! camber op CURVE.json reparam --to A,B -o OUT.json
//! camber render-curve CURVE.json -o PIC.svg [--combs]
//! camber surface CASE.json -o FACE.json [--plot PIC.svg]
//! camber solve SKETCH.json -o OUT.json [--svg PIC.svg]   solve, write, report per component
//! camber check SKETCH.json                              DOF, redundant and conflicting constraints
//! camber render SKETCH.json -o PIC.svg [--combs]        draw a sketch with constraint glyphs
//! camber edit SKETCH.json [--port N] [--bind ADDR] [-o OUT.json] [--open]   the web editor
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
pub mod scene;
pub mod sketch_file;
pub mod svg;

use anyhow::Result;
use clap::{Parser, Subcommand};

use commands::{
    batch, bench as bench_cmd, check, demo, edit, eval, op, render, render_curve, solve, surface,
};

/// The camber command line: curve files, surface deformation and SVG pictures.
#[derive(Debug, Parser)]
#[command(name = "camber", version, about, after_help = CURVE_FILE_HELP)]
pub struct Cli {
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
Errors print one line `error: ...` and exit with code 2.";

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Evaluate a curve file: point, derivatives and signed curvature per parameter, as JSON.
    Eval(eval::EvalArgs),
    /// Edit a curve file: split, insert-knot, elevate, reverse, reparam.
    #[command(after_help = OP_HELP)]
    Op(op::OpArgs),
    /// Draw a curve file as SVG: the curve, its control polygon, optionally curvature combs.
    RenderCurve(render_curve::RenderCurveArgs),
    /// Deform a face to G1 continuity with its neighbours; write the face, print the report.
    Surface(surface::SurfaceArgs),
    /// Solve a sketch file: write the result, print solver, DOF, residual and time per component.
    Solve(solve::SolveArgs),
    /// The DOF analysis of a sketch file: free DOF, redundant and conflicting constraints.
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
}

/// Which operation works on which curve type, shown under `camber op --help`.
const OP_HELP: &str = "\
Supported:  split (all types; Hermite pieces are reparameterized to [0, 1]),
            insert-knot (bspline, nurbs), elevate (bezier, bspline, nurbs),
            reverse (all), reparam (bspline, nurbs).
split writes the piece before U to -o and the piece after U to --second.
Example:    camber op blade.json split --at 0.5 -o front.json --second back.json";

/// Runs one parsed command line.
pub fn run(cli: &Cli) -> Result<()> {
    match &cli.command {
        Command::Eval(a) => eval::run(a),
        Command::Op(a) => op::run(a),
        Command::RenderCurve(a) => render_curve::run(a),
        Command::Surface(a) => surface::run(a),
        Command::Solve(a) => solve::run(a),
        Command::Check(a) => check::run(a),
        Command::Render(a) => render::run(a),
        Command::Edit(a) => edit::run(a),
        Command::Demo(a) => demo::run(a),
        Command::Bench(a) => bench_cmd::run(a),
        Command::Batch(a) => batch::run(a),
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
