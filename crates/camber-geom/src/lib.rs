//! camber-geom: the scalar-generic geometry kernel of camber.
//!
//! Bézier, B-spline, NURBS and cubic Hermite curves, lines, segments, circles, circular arcs,
//! ellipses and elliptic arcs, composite curves and curve queries. Every evaluator is generic
//! over one bound, [`Scalar`] (`nalgebra::RealField + Copy`), so the same code evaluates with
//! `f64` and with forward-mode dual numbers: differentiating a curve point with respect to its
//! control points needs no derivative code of its own. This crate knows nothing of constraints
//! or solvers.
//!
//! ```
//! use camber_geom::{BSplineCurve2, KnotVector, ParametricCurve};
//! use nalgebra::Point2;
//!
//! let points = vec![
//!     Point2::new(0.0_f64, 0.0),
//!     Point2::new(1.0, 2.0),
//!     Point2::new(3.0, 2.0),
//!     Point2::new(4.0, 0.0),
//! ];
//! let knots = KnotVector::clamped_uniform(3, points.len())?;
//! let curve = BSplineCurve2::try_new(3, knots, points)?;
//! let (p, d) = curve.point_and_derivative(0.5)?;
//! assert!((p.x - 2.0).abs() < 1e-12 && (p.y - 1.5).abs() < 1e-12);
//! assert!((d.x - 4.5).abs() < 1e-12 && d.y.abs() < 1e-12);
//! # Ok::<(), camber_geom::Error>(())
//! ```
//!
//! # Design
//! - Curves own their control points as `nalgebra::Point<T, D>` with a const dimension D
//!   (aliases `…2` and `…3` for the planar and spatial cases).
//! - Fallible constructors are `try_new`; every error is an [`Error`] variant naming the
//!   offending index and value. Nothing panics on user input.
//! - Evaluation writes into caller slices and keeps its scratch on the stack
//!   (see [`basis::INLINE_DEGREE`]), so hot loops do not allocate.
//!
//! # Operations
//! - [`arc_length`]: length with an error estimate, parameter at a length, arc-length map;
//! - [`extend`]: natural extrapolation beyond either end, extension by a length (G1, G2);
//! - [`fit`]: interpolation, least squares, fitting to a tolerance;
//! - [`knot_removal`] and [`degree_reduction`]: exact when the curve allows, with a bound;
//! - [`queries::intersect_curves`] and [`queries::curve_distance`]: any two curve kinds;
//! - [`offset`]: offsets of planar curves as B-splines, error measured.

pub mod arc;
pub mod arc_length;
pub mod banded;
pub mod basis;
pub mod bernstein;
pub mod bezier;
pub mod bspline;
pub mod budget;
pub mod composite;
pub mod curve;
pub mod degree_reduction;
pub mod ellipse;
pub mod errors;
pub mod extend;
pub mod fit;
pub mod hermite;
pub mod knot_ops;
pub mod knot_removal;
pub mod knots;
pub mod nurbs;
pub mod offset;
pub mod primitives;
pub mod queries;
pub mod scalar;
pub mod serde_support;

pub use arc::CircularArc;
pub use bezier::{BezierCurve, BezierCurve2, BezierCurve3};
pub use bspline::{BSplineCurve, BSplineCurve2, BSplineCurve3};
pub use budget::Budget;
pub use composite::{CompositeCurve, CompositeCurve2, CompositeCurve3, Continuity, JointReport};
pub use curve::ParametricCurve;
pub use ellipse::{Ellipse, EllipticArc};
pub use errors::{Error, Result};
pub use hermite::{HermiteCurve, HermiteCurve2, HermiteCurve3};
pub use knot_ops::{BezierPiece, ControlNet};
pub use knots::KnotVector;
pub use nurbs::{NurbsCurve, NurbsCurve2, NurbsCurve3};
pub use primitives::{Circle, Line, Segment};
pub use queries::{ClosestPoint, Intersection, QueryOptions};
pub use scalar::Scalar;
