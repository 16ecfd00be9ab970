//! The error type of camber-surface: one enum whose variants carry the offending values.
//!
//! Errors of the geometry kernel and of the solver pass through unchanged
//! ([`Error::Geom`], [`Error::Solve`]); the rest are specific to surfaces and deformation.

/// Everything that can go wrong when building, evaluating or deforming a surface.
///
/// ```
/// use camber_geom::KnotVector;
/// use camber_surface::{Error, NurbsSurface};
/// use nalgebra::Point3;
/// let k = KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0]).unwrap();
/// // A bilinear patch needs 2 × 2 control points.
/// let err = NurbsSurface::try_with_unit_weights(1, k.clone(), 1, k, vec![Point3::origin(); 3]);
/// assert_eq!(err.unwrap_err(), Error::ControlPointCount { count_u: 2, count_v: 2, found: 3 });
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// An error of the geometry kernel (knots, weights, parameters, curves).
    #[error(transparent)]
    Geom(#[from] camber_geom::Error),
    /// An error of the solver.
    #[error(transparent)]
    Solve(#[from] camber_solve::Error),
    /// The control points do not fill the count_u × count_v net the knots call for.
    #[error("the knots call for {count_u} × {count_v} control points, found {found}")]
    ControlPointCount {
        /// Control points in u (knots in u − degree in u − 1).
        count_u: usize,
        /// Control points in v.
        count_v: usize,
        /// Points given.
        found: usize,
    },
    /// S_u × S_v vanishes: the surface has no normal at (u, v).
    #[error("the surface has no normal at (u, v) = ({u}, {v})")]
    DegenerateNormal {
        /// Parameter u.
        u: f64,
        /// Parameter v.
        v: f64,
    },
    /// A weight, tolerance or count of the deformation options is out of its range.
    #[error("option {what} = {value} is out of range")]
    InvalidOption {
        /// Which option ("alpha", "samples_per_edge", …).
        what: &'static str,
        /// The value given (counts converted to f64).
        value: f64,
    },
    /// A neighbour's edge does not run along the face's edge it is said to share.
    #[error("neighbour {neighbour} is {gap} away from the face's edge (tolerance {tolerance})")]
    NotAdjacent {
        /// Index of the neighbour.
        neighbour: usize,
        /// Largest distance found from a face edge sample to the neighbour's edge.
        gap: f64,
        /// The allowed gap.
        tolerance: f64,
    },
}

/// The result type of camber-surface.
pub type Result<T> = std::result::Result<T, Error>;
