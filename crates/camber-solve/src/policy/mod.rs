//! The policy: the one place that decides how a problem is solved (linear, Newton, SLSQP, least
//! squares, priority tiers), validates the result and writes it back, and keeps what it learnt
//! for the next solve of the same problem ([`Plan`]).

pub(crate) mod linear;
pub(crate) mod plan;
pub(crate) mod selection;

pub use linear::solve_linear;
pub use plan::{Plan, Start};
pub use selection::{solve, solve_newton, solve_newton_from};
