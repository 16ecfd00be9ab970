//! Objectives for the optimizing solvers: what "the solution nearest the start" means.
//!
//! SLSQP minimises an objective f over the reduced unknowns z subject to g(x(z)) = 0. The
//! default is the weighted displacement ½‖z − z₀‖²_W = ½ Σ w_k (z_k − z₀,k)², the same metric
//! the minimum-norm steps use, so Newton and SLSQP aim at the same point. Two other choices
//! exist: the length of a polyline through some point blocks (for a curve, its control
//! polygon: a "simpler shape" objective), and any objective a user writes over the unknowns x.
//! Objectives over x are carried to z by the chain rule, ∇_z f = Aᵀ·∇_x f.

use std::fmt::Debug;
use std::sync::Arc;

use crate::model::ids::BlockId;

/// A user objective F(x) over the problem's unknowns x (the full vector, as
/// [`crate::Problem::values`]), with its exact gradient.
///
/// ```
/// use camber_solve::UserObjective;
/// /// F(x) = Σ x_i², gradient 2x.
/// #[derive(Debug)]
/// struct SumOfSquares;
/// impl UserObjective for SumOfSquares {
///     fn value(&self, x: &[f64], gradient: Option<&mut [f64]>) -> f64 {
///         if let Some(g) = gradient {
///             for (gi, xi) in g.iter_mut().zip(x) { *gi = 2.0 * xi; }
///         }
///         x.iter().map(|v| v * v).sum()
///     }
/// }
/// let mut g = [0.0; 2];
/// assert!((SumOfSquares.value(&[1.0, 2.0], Some(&mut g)) - 5.0).abs() < 1e-15);
/// assert!((g[1] - 4.0).abs() < 1e-15);
/// ```
pub trait UserObjective: Debug + Send + Sync {
    /// F(x); when `gradient` is given (one entry per unknown), writes ∂F/∂x into it. It must
    /// not panic (it runs inside the optimizer's callbacks); return NaN for a point where F is
    /// undefined.
    fn value(&self, x: &[f64], gradient: Option<&mut [f64]>) -> f64;
}

/// What the optimizing solver minimises while it keeps every constraint satisfied.
#[derive(Debug, Clone, Default)]
#[non_exhaustive]
pub enum Objective {
    /// ½‖z − z₀‖²_W: the weighted displacement from the start (the default).
    #[default]
    Displacement,
    /// Σ_k ‖P_{k+1} − P_k‖₂ over the listed blocks, each read as a point (all the same
    /// dimension): the length of the polyline through them, e.g. a control polygon.
    PolylineLength(Vec<BlockId>),
    /// A user objective over x.
    User(Arc<dyn UserObjective>),
}

impl PartialEq for Objective {
    fn eq(&self, other: &Self) -> bool {
        match (self, other) {
            (Self::Displacement, Self::Displacement) => true,
            (Self::PolylineLength(a), Self::PolylineLength(b)) => a == b,
            (Self::User(a), Self::User(b)) => Arc::ptr_eq(a, b),
            _ => false,
        }
    }
}
