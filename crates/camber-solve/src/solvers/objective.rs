//! The evaluation of an [`Objective`] over the reduced unknowns z, with its gradient carried
//! from x to z by the chain rule ∇_z f = Aᵀ·∇_x f (SLSQP's objective).

use crate::linalg::reduced::ReducedMap;
use crate::model::ids::BlockId;
use crate::model::objective::Objective;
use crate::model::problem::Problem;

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
