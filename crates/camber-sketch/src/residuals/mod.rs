//! Residuals several constraint kinds share: the arc's own row ([`arc`]), a point on an ellipse
//! ([`ellipse`]: an elliptic arc's own rows), the constant-coefficient combinations of point
//! blocks every affine piece compiles to ([`affine`]), the active rows of honest contact
//! ([`clearance`]), and what every residual over a curve needs ([`curve`]). A residual that
//! belongs to one kind lives in that kind's module under [`crate::constraints`].

pub mod affine;
pub mod arc;
pub mod clearance;
pub mod curve;
pub mod ellipse;

pub use affine::{DirectionCross, LineTangency, PointCombination};
pub use curve::Param;
