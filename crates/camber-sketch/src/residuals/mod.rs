//! Residuals several constraint kinds share: the arc's own row ([`arc`]), the constant-coefficient combinations of point
//! blocks every affine piece compiles to ([`affine`]), the active rows of honest contact
//! ([`clearance`]), and what every residual over a curve needs ([`curve`]). A residual that
//! belongs to one kind lives in that kind's module under [`crate::constraints`].

pub mod affine;
pub mod arc;
pub mod clearance;
pub mod curve;

pub use affine::{DirectionCross, LineTangency, PointCombination};
pub use curve::Param;
