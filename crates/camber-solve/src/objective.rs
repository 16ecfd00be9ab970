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

use crate::ids::BlockId;
use crate::problem::Problem;
use crate::reduced::ReducedMap;

/// A user objective F(x) over the problem's unknowns x (the full vector, as
/// [`Problem::values`]), with its exact gradient.
///
/// ```
/// use camber_solve::objective::UserObjective;
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

/// Scratch for evaluating an objective over z.
#[cfg_attr(not(feature = "nlopt"), allow(dead_code))] // used by SLSQP only
#[derive(Debug, Clone)]
pub(crate) struct ObjectiveEval {
    x: Vec<f64>,
    gx: Vec<f64>,
}

#[cfg_attr(not(feature = "nlopt"), allow(dead_code))] // used by SLSQP only
impl ObjectiveEval {
    pub(crate) fn new(problem: &Problem) -> Self {
        let n = problem.num_unknowns();
        Self {
            x: vec![0.0; n],
            gx: vec![0.0; n],
        }
    }

    /// f(z), and ∇_z f into `gradient` when given. NaN when the lengths do not match.
    pub(crate) fn value(
        &mut self,
        objective: &Objective,
        problem: &Problem,
        map: &ReducedMap,
        reference: &[f64],
        z: &[f64],
        gradient: Option<&mut [f64]>,
    ) -> f64 {
        if let Objective::Displacement = objective {
            let w = map.weights();
            let mut f = 0.0;
            for k in 0..z.len().min(reference.len()).min(w.len()) {
                f += 0.5 * w[k] * (z[k] - reference[k]).powi(2);
            }
            if let Some(g) = gradient {
                for (k, gk) in g.iter_mut().enumerate() {
                    *gk = match (z.get(k), reference.get(k), w.get(k)) {
                        (Some(a), Some(b), Some(wk)) => wk * (a - b),
                        _ => f64::NAN,
                    };
                }
            }
            return f;
        }
        if map.expand(z, &mut self.x).is_err() {
            return f64::NAN;
        }
        let want = gradient.is_some();
        let f = match objective {
            Objective::PolylineLength(blocks) => {
                polyline(problem, blocks, &self.x, want.then_some(&mut self.gx[..]))
            }
            Objective::User(u) => u.value(&self.x, want.then_some(&mut self.gx[..])),
            Objective::Displacement => f64::NAN,
        };
        if let Some(g) = gradient {
            // ∇_z f = Aᵀ·∇_x f.
            g.fill(0.0);
            for (i, gxi) in self.gx.iter().enumerate() {
                let (terms, _) = map.row(i);
                for (col, a) in terms {
                    if let Some(slot) = g.get_mut(*col) {
                        *slot += a * gxi;
                    }
                }
            }
        }
        f
    }
}

/// Length of the polyline through the blocks, with its gradient over x.
#[cfg_attr(not(feature = "nlopt"), allow(dead_code))] // used by SLSQP only
fn polyline(problem: &Problem, blocks: &[BlockId], x: &[f64], mut gx: Option<&mut [f64]>) -> f64 {
    if let Some(g) = gx.as_deref_mut() {
        g.fill(0.0);
    }
    let mut total = 0.0;
    for pair in blocks.windows(2) {
        let (Ok((s0, l0)), Ok((s1, l1))) =
            (problem.block_range(pair[0]), problem.block_range(pair[1]))
        else {
            return f64::NAN;
        };
        if l0 != l1 || s0 + l0 > x.len() || s1 + l1 > x.len() {
            return f64::NAN;
        }
        let len = (0..l0)
            .map(|k| (x[s1 + k] - x[s0 + k]).powi(2))
            .sum::<f64>()
            .sqrt();
        total += len;
        if let Some(g) = gx.as_deref_mut() {
            if len > 0.0 {
                for k in 0..l0 {
                    let u = (x[s1 + k] - x[s0 + k]) / len;
                    g[s1 + k] += u;
                    g[s0 + k] -= u;
                }
            }
        }
    }
    total
}
