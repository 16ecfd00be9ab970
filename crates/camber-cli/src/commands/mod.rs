//! One module per subcommand; each has an `…Args` struct (clap derive) and a `run` function.
//! The sketch commands (solve, check, render, demo, bench) slot in here as they land.

pub mod eval;
pub mod op;
pub mod render_curve;
pub mod surface;
