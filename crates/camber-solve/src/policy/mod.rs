//! The policy: the one place that decides how a problem is solved (linear, Newton, SLSQP, least
//! squares, priority tiers), validates the result and writes it back.

pub(crate) mod selection;

pub use selection::{solve, solve_newton, solve_newton_from};
