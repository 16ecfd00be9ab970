//! camber-sketch: planar sketches of points, lines, circles and Bézier, B-spline and NURBS
//! curves, held by affine and nonlinear constraints and solved by minimum-norm displacement.
//!
//! ```
//! use camber_sketch::{Constraint, FixTarget, PointRef, Sense, Sketch, TangentForm};
//! use camber_geom::BezierCurve2;
//! use nalgebra::{Point2, Vector2};
//!
//! // The W1 workload: a cubic whose start tangent keeps the direction D, end point fixed.
//! let d = Vector2::new(30f64.to_radians().cos(), 30f64.to_radians().sin());
//! let mut s = Sketch::new();
//! let c = s.add_bezier(BezierCurve2::try_new(vec![
//!     Point2::origin(), Point2::from(1.2 * d), Point2::new(2.2, 0.9), Point2::new(3.0, 0.0),
//! ])?)?;
//! s.add_constraint(Constraint::Fixed(FixTarget::Point(PointRef::Control(c, 3))))?;
//! s.add_constraint(Constraint::StartTangent { curve: c, direction: d, sense: Sense::Agree, form: TangentForm::Row })?;
//! let mut drag = s.drag(PointRef::Control(c, 1))?;
//! drag.update(Point2::from(1.2 * d) + Vector2::new(0.0, 0.1))?;
//! let (p0, p1) = (drag.point(PointRef::Control(c, 0))?, drag.point(PointRef::Control(c, 1))?);
//! let t = p1 - p0;
//! assert!((t.x * d.y - t.y * d.x).abs() < 1e-12 && t.dot(&d) > 0.0);
//! drag.finish(&mut s)?;
//! # Ok::<(), camber_sketch::Error>(())
//! ```
//!
//! # Usage
//! Add entities ([`Sketch::add_bezier`], …) and [`Constraint`]s, then [`Sketch::solve`]: every
//! connected component containing an edited entity is solved on its own, and the result is
//! written back only if every component succeeds. [`Sketch::analyze`] reports the DOF and names
//! redundant and conflicting constraints. [`Sketch::drag`] starts an interactive
//! [`DragSession`].
//!
//! # Design
//! - Each entity point (control point, line end, circle centre) is one parameter block (x, y)
//!   of a [`camber_solve::Problem`]; knots and weights are data. With them fixed, curve points
//!   and tangents at a given parameter are constant linear combinations of control points
//!   ([`Entity::coefficients`]), so every built-in constraint is affine ([`residuals`]).
//! - Entities and constraints are nodes of a petgraph graph; a constraint has an edge to every
//!   entity it reads; connected components are independent problems.
//! - `Fixed` binds unknowns (they leave the problem); start/end tangency comes in the row form
//!   and in the paper's elimination form P₁ = P₀ + t·T, t > 0 ([`TangentForm`]).
//! - Tangencies record their [`Sense`]; a solve that flips one is rejected.
//! - Users add their own residuals with [`Constraint::Custom`].
//! - A component whose residuals are all affine takes the linear path above. Any other goes to
//!   [`camber_solve::solve()`], which picks Newton minimum norm, SLSQP or the least-squares
//!   rescue from the DOF analysis; the component report's `solver` and `reason` say which ran
//!   and why. The nonlinear constraints ([`Constraint::PointOnCurve`],
//!   [`Constraint::TangentToLine`], [`Constraint::TangentToCircle`], circles and lines as
//!   unknowns, [`Constraint::G1JoinFree`], …) are residuals of [`contact`]; a free contact
//!   parameter ([`Contact::Free`]) is an unknown of its own bounded to the curve's domain,
//!   stored back into the constraint after a successful solve.
//! - Contact is honest: after a solve every contact must keep its recorded travel direction,
//!   have a non-vanishing tangent, and stay on its recorded side near the contact (sampled on
//!   the solved curve). A crossing adds a clearance row on its side of the contact (the curve
//!   must touch the target there at a free second point instead of crossing it), a collapsed
//!   tangent a floor on its speed ([`clearance`]), and the solve restarts (see
//!   [`solve::MAX_ACTIVE_ROWS`]); if that fails, the error names the constraint and nothing is
//!   written.
//! - Drag sessions on nonlinear components fix the dragged point in the problem and move it at
//!   each update; Newton starts from the previous step and pulls toward it
//!   ([`camber_solve::solve_newton_from`]), with the full selection as fallback.
//! - Small components are solved densely after a full rank analysis; large ones go straight to
//!   the sparse factorization and are analysed only when it meets dependent rows
//!   ([`solve::default_options`]).
//! - [`workloads`] builds the standard benchmark sketches (W1, the blade section, W2, W3a, W4).

mod active;
pub mod build;
pub mod clearance;
mod compile;
pub mod constraint;
pub mod contact;
pub mod curve_eval;
pub mod displacement;
pub mod drag;
pub mod entity;
pub mod errors;
pub mod file;
mod general;
pub mod ids;
mod merge;
pub mod residuals;
pub mod sketch;
pub mod solve;
pub mod workloads;

pub use build::{Component, ComponentProblem, DRAG_CONSTRAINT};
pub use constraint::{
    CircleSide, Constraint, Contact, Custom, FixTarget, LineSide, Rotation, Sense, TangentForm,
    Target,
};
pub use drag::DragSession;
pub use entity::{Entity, Terms};
pub use errors::{Error, Result};
pub use ids::{ConstraintId, EntityId, PointRef};
pub use sketch::Sketch;
pub use solve::{ComponentAnalysis, ComponentReport, SketchReport};
