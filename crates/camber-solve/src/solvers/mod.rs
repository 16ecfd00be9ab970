//! The solvers, one struct or entry each: the linear minimum-norm step ([`linear`]), Newton
//! minimum norm with the pull-back toward the start ([`newton`]), SLSQP through NLopt
//! (`slsqp`, feature `nlopt`, with its [`objective`]), weighted least squares ([`lsq`]), the
//! soft compromise by Levenberg–Marquardt ([`soft`]) and priority tiers met in order
//! ([`lexicographic`]).
//!
//! A solver runs the method it is given and validates nothing beyond its own convergence;
//! which one runs, from where, and what is written back is the policy's decision.

pub(crate) mod lexicographic;
pub(crate) mod linear;
pub(crate) mod lsq;
pub(crate) mod newton;
pub(crate) mod objective;
#[cfg(feature = "nlopt")]
pub(crate) mod slsqp;
pub(crate) mod soft;
