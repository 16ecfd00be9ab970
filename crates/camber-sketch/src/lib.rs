//! camber-sketch: planar sketches of points, lines, circles and Bézier, B-spline and NURBS
//! curves, held by affine and nonlinear constraints and solved by minimum-norm displacement.
//!
//! ```
//! use camber_sketch::constraints::{Fixed, StartTangent};
//! use camber_sketch::{PointRef, Sense, Sketch, TangentForm};
//! use camber_geom::BezierCurve2;
//! use nalgebra::{Point2, Vector2};
//!
//! // The W1 workload: a cubic whose start tangent keeps the direction D, end point fixed.
//! let d = Vector2::new(30f64.to_radians().cos(), 30f64.to_radians().sin());
//! let mut s = Sketch::new();
//! let c = s.add_bezier(BezierCurve2::try_new(vec![
//!     Point2::origin(), Point2::from(1.2 * d), Point2::new(2.2, 0.9), Point2::new(3.0, 0.0),
//! ])?)?;
//! s.add_constraint(Fixed::point(PointRef::Control(c, 3)))?;
//! s.add_constraint(StartTangent { curve: c, direction: d, sense: Sense::Agree, form: TangentForm::Row })?;
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
//! Add entities ([`Sketch::add_bezier`], …) and constraints (any kind of [`constraints`]
//! converts into a [`Constraint`]), then [`Sketch::solve`]: every connected component
//! containing an edited entity is solved on its own, and the result is written back only if
//! every component succeeds. [`Sketch::analyze`] reports the DOF and names redundant and
//! conflicting constraints. [`Sketch::drag`] starts an interactive [`DragSession`].
//!
//! # Design
//! The crate reads bottom to top, each layer using only the ones below it (a test reads the
//! sources to keep it so; docs/architecture.md draws it):
//!
//! - the ground (`ground/`): [`ids`], [`vocabulary`], [`errors`], [`entity`] and the evaluation of
//!   its curves ([`curve_eval`], [`hermite_chain`]), [`lookup`];
//! - [`residuals`]: residuals several kinds share;
//! - [`constraints`]: one module per constraint kind (its entities, validation, rows, checks,
//!   file form and glyph), what kinds compile to (pieces, checks of a solved state), helpers
//!   sibling kinds share, the [`Constraint`] enum generated from their list, and user kinds
//!   through [`Custom`];
//! - [`component`]: one connected component as a [`camber_solve::Problem`] built from the
//!   kinds' pieces, the active set of honest contact, and the one solve policy used by solves
//!   and drags;
//! - [`sketch`]: the graph (entities and constraints as petgraph nodes, an edge from a
//!   constraint to every entity it reads), components, the dirty set, editing, warnings;
//! - the sessions (`session/`): [`solve`], [`drag`], [`analysis`] and [`displacement`], the
//!   sketch's solving faces; [`mod@file`], its JSON form.
//!
//! Each entity point (control point, line end, circle centre) is one parameter block (x, y) of
//! the problem, a circle's radius a block of one; knots and weights are data. `Fixed` binds
//! unknowns; coincident points merge into one set of unknowns; start/end tangency comes in the
//! row form and in the paper's elimination form P₁ = P₀ + t·T, t > 0 ([`TangentForm`]).
//! Tangencies record their [`Sense`] and contacts their side and travel direction, checked after
//! every solve; a contact that crosses its target gets a clearance row (the curve must touch it
//! at a free second point instead) and the solve runs again
//! ([`residuals::clearance`], `component::policy`). An affine component takes the linear
//! path; any other goes to [`camber_solve::solve()`], whose DOF analysis picks Newton minimum
//! norm, SLSQP or least squares; the component report's `solver` and `reason` say which ran.
//! The standard benchmark sketches live in the `camber-workloads` crate.

mod ground;
mod session;

pub mod component;
pub mod constraints;
pub mod file;
pub mod residuals;
pub mod sketch;

/// Named parameters of a sketch, dimensions written as expressions of them, and sweeps over
/// tables of their values.
pub mod parameters {
    pub use crate::session::parameters::ParameterChange;
    pub use crate::session::sweep;
    pub use crate::sketch::parameters::*;
}

pub use batch::solve_many;
pub use ground::{
    curve_eval, ellipse_blocks, entity, errors, hermite_chain, ids, lookup, vocabulary,
};
pub use session::{analysis, batch, displacement, drag, solve};
pub use sketch::warnings;

pub use analysis::{ComponentAnalysis, EntityFreedom, ParameterFreedom};
pub use camber_solve::Priority;
pub use component::{Component, ComponentProblem, DRAG_CONSTRAINT};
pub use constraints::custom::{Arg, ArgKind, Args, CustomResidual};
pub use constraints::{Constraint, Custom, Glyph};
pub use drag::DragSession;
pub use entity::{Entity, Terms};
pub use errors::{Error, Result};
pub use hermite_chain::{HermiteChain, Join};
pub use ids::{ConstraintId, EntityId, PointRef};
pub use lookup::EntityLookup;
pub use sketch::{Sketch, MAX_TAG_LEN};
pub use solve::{ComponentReport, SketchReport};
pub use vocabulary::{
    CircleSide, Contact, FixTarget, LineSide, Rotation, Sense, Tangency, TangentForm, Target,
};
pub use warnings::Warning;
