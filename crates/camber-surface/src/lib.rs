//! camber-surface: tensor-product NURBS surfaces and their minimal deformation to G1
//! continuity with neighbour faces.
//!
//! ```
//! use camber_surface::{deform_to_g1, examples::crease_pair, DeformOptions};
//! // Two bicubic patches meeting along an edge with a 10° crease.
//! let (face, neighbour) = crease_pair(10.0)?;
//! let (deformed, report) = deform_to_g1(&face, &[neighbour], &DeformOptions::default())?;
//! let edge = &report.edges[0];
//! assert!(edge.max_before_deg() > 9.0 && edge.max_after_deg() < 0.1);
//! assert!(report.max_boundary_deviation < 1e-3 * report.size);
//! assert_eq!(deformed.counts().0 >= 4, true);
//! # Ok::<(), camber_surface::Error>(())
//! ```
//!
//! # Usage
//! - [`NurbsSurface`]: evaluation (point, S_u, S_v, second derivatives, unit normal), knot
//!   insertion and refinement in u or v, isoparametric curves as camber-geom
//!   [`camber_geom::NurbsCurve3`], JSON for `f64` (validated on load). Generic over the scalar,
//!   so dual numbers give exact derivatives with respect to parameters or control points.
//! - [`deform_to_g1`]: moves a face's control points as little as possible so that its tangent
//!   planes meet its neighbours' along shared edges; the objective is a weighted least-squares
//!   problem of camber-solve ([`camber_solve::solve_least_squares`]), expressed as residual
//!   blocks. The [`DeformationReport`] gives the normal angles along each edge before and after.
//! - [`examples`]: the bundled creased cases.
//!
//! # Design
//! The deformation's unknowns enter linearly (weights fixed), so the normal equations are one
//! sparse symmetric positive-definite system, factorized by a sparse Cholesky. When a tolerance
//! is missed, knots are inserted in the initial surface near the worst samples and the solve is
//! repeated, a bounded number of times.

pub mod deform;
pub mod errors;
pub mod report;
mod residuals;
pub mod surface;

/// Bundled cases (generated in code).
pub mod examples {
    pub use crate::cases::{
        bumpy_face, crease_pair, creased_face, creased_neighbour, DeformationCase,
    };
}
mod cases;

pub use deform::{deform_to_g1, DeformOptions, Edge, Neighbour};
pub use errors::{Error, Result};
pub use report::{plane_angle_deg, DeformationReport, EdgeReport};
pub use surface::{Direction, NurbsSurface, SurfaceBasis, SurfaceDerivatives};
