//! camber keeps geometric constraints on parametric curves satisfied while a designer edits them.
//!
//! This facade re-exports the library crates:
//! - [`geom`] (camber-geom): Bézier, B-spline, NURBS and Hermite curves, primitives and queries,
//!   generic over the scalar type so dual numbers give exact derivatives.
//! - [`solve`] (camber-solve): problems over parameter blocks, residuals written once
//!   generically with exact Jacobians by automatic differentiation, the minimum-norm solve and
//!   the DOF analysis.
//! - [`sketch`] (camber-sketch): sketches of entities and affine constraints in a petgraph
//!   graph, solved per connected component, with drag sessions.
//! - [`surface`] (camber-surface): NURBS surfaces and their minimal deformation to G1 continuity
//!   with neighbour faces.
//!
//! ```
//! use camber::geom::{BezierCurve2, ParametricCurve};
//! use nalgebra::Point2;
//! let c = BezierCurve2::try_new(vec![Point2::new(0.0_f64, 0.0), Point2::new(1.0, 1.0)])?;
//! assert!((c.point(0.5)?.x - 0.5).abs() < 1e-15);
//! # Ok::<(), camber::geom::Error>(())
//! ```

pub use camber_geom as geom;
pub use camber_sketch as sketch;
pub use camber_solve as solve;
pub use camber_surface as surface;
