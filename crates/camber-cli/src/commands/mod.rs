//! One module per subcommand; each has an `…Args` struct (clap derive) and a `run` function.

pub mod arc_length;
pub mod batch;
pub mod bench;
pub mod check;
pub mod demo;
pub mod edit;
pub mod eval;
pub mod export;
pub mod fit;
pub mod geometry_op;
pub mod import;
pub mod intersect;
pub mod op;
pub mod render;
pub mod render_curve;
pub mod solve;
pub mod surface;
pub mod sweep;
