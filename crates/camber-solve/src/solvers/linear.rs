//! The linear solver: the weighted minimum-norm step Δz = −W⁻¹·Jᵀ·(J·W⁻¹·Jᵀ)⁻¹·g of the
//! selected rows of a constant J, over a factorization kept for any number of right-hand sides.
//!
//! It is built once per J ([`LinearSolver::factorize`]) and then answers every g in two
//! triangular solves and a product with Jᵀ, refined until the rows are met to rounding
//! (`linalg::min_norm`). For a small J that is used again and again (a drag: J stays while the
//! target moves), the step is written out once as a dense gain K, n × k with column j the refined
//! step for the unit right-hand side eⱼ; the step being linear in g, Δz = K·g is then one small
//! product ([`LinearSolver::with_gain`]). A step the gain gives that misses its rows is redone
//! by the factorization ([`LinearSolver::step_refined`]).
//!
//! Which rows are selected, when J is refactorized and whether the result is kept is the
//! policy's business.

use crate::linalg::min_norm::{self, MinNormFactorization};
use crate::linalg::normal::NormalCache;
use crate::linalg::sparse::SparseMatrix;
use crate::model::errors::{Error, Result};

/// Rounds of iterative refinement after a step (see
/// [`MinNormFactorization::solve_refined`]).
pub(crate) const REFINEMENT_STEPS: usize = 3;

/// The most entries of the dense gain K (n × k) and of J (m × n) for which it is written out.
pub(crate) const GAIN_MAX_ENTRIES: usize = 4096;

/// The minimum-norm solver of one J (see the module documentation).
#[derive(Debug)]
pub(crate) struct LinearSolver {
    /// The rows of J the steps satisfy (`None`: all of them).
    rows: Option<Vec<usize>>,
    /// The factorization of the selected rows (`None` when no row is selected).
    factorization: Option<MinNormFactorization>,
    /// K, n × k row major (row i gives Δzᵢ), when written out.
    gain: Option<Vec<f64>>,
    /// The selected rows of the right-hand side.
    g_sel: Vec<f64>,
}

impl LinearSolver {
    /// Factorizes the rows `rows` of J (all when `None`) with the weights W: dense when
    /// `dense`, sparse otherwise (reusing `cache`'s ordering and pattern).
    ///
    /// # Errors
    /// [`Error::RankDeficient`] when the selected rows are dependent; weight errors.
    pub(crate) fn factorize(
        j: &SparseMatrix,
        weights: &[f64],
        rows: Option<Vec<usize>>,
        dense: bool,
        cache: &mut NormalCache,
    ) -> Result<Self> {
        let selected = match &rows {
            Some(rows) if rows.len() < j.nrows() => Some(j.select_rows(rows)),
            _ => None,
        };
        let j_sel = selected.as_ref().unwrap_or(j);
        let k = j_sel.nrows();
        let factorization = if k == 0 {
            None
        } else if dense {
            Some(MinNormFactorization::try_dense(j_sel, weights)?)
        } else {
            Some(MinNormFactorization::try_sparse_cached(
                j_sel, weights, cache,
            )?)
        };
        Ok(Self {
            rows: rows.filter(|r| r.len() < j.nrows()),
            factorization,
            gain: None,
            g_sel: vec![0.0; k],
        })
    }

    /// Writes the step out as the dense gain K when it is small enough (n·k and m·n at most
    /// [`GAIN_MAX_ENTRIES`]); nothing otherwise.
    ///
    /// # Errors
    /// Those of the refined solves.
    pub(crate) fn with_gain(&mut self, m: usize) -> Result<()> {
        let Some(f) = self.factorization.as_mut() else {
            return Ok(());
        };
        let (n, k) = (f.cols(), f.rows());
        if self.gain.is_some()
            || n.saturating_mul(k) > GAIN_MAX_ENTRIES
            || m.saturating_mul(n) > GAIN_MAX_ENTRIES
        {
            return Ok(());
        }
        let mut gain = vec![0.0; n * k];
        let (mut unit, mut col) = (vec![0.0; k], vec![0.0; n]);
        for j in 0..k {
            unit[j] = 1.0;
            f.solve_refined(&unit, &mut col, REFINEMENT_STEPS, 0.0)?;
            unit[j] = 0.0;
            for (i, v) in col.iter().enumerate() {
                gain[i * k + j] = *v;
            }
        }
        self.gain = Some(gain);
        Ok(())
    }

    /// Whether the gain is written out.
    pub(crate) fn has_gain(&self) -> bool {
        self.gain.is_some()
    }

    /// Copies the selected rows of `g` into the solver's right-hand side.
    fn select(&mut self, g: &[f64]) {
        match &self.rows {
            Some(rows) => {
                for (s, r) in self.g_sel.iter_mut().zip(rows) {
                    *s = g.get(*r).copied().unwrap_or(f64::NAN);
                }
            }
            None => {
                let k = self.g_sel.len();
                self.g_sel.copy_from_slice(&g[..k]);
            }
        }
    }

    /// Δz by the gain when it is written out, by the refined factorization otherwise.
    ///
    /// # Errors
    /// Dimension errors.
    pub(crate) fn step(&mut self, g: &[f64], dz: &mut [f64], tolerance: f64) -> Result<()> {
        if self.factorization.is_none() {
            dz.fill(0.0);
            return Ok(());
        }
        self.select(g);
        match &self.gain {
            Some(k) => {
                let width = self.g_sel.len();
                for (d, row) in dz.iter_mut().zip(k.chunks_exact(width)) {
                    *d = row.iter().zip(&self.g_sel).map(|(a, b)| a * b).sum();
                }
                Ok(())
            }
            None => self.step_refined(g, dz, tolerance),
        }
    }

    /// Δz by the refined factorization (never by the gain).
    ///
    /// # Errors
    /// Dimension errors.
    pub(crate) fn step_refined(&mut self, g: &[f64], dz: &mut [f64], tolerance: f64) -> Result<()> {
        if self.factorization.is_none() {
            dz.fill(0.0);
            return Ok(());
        }
        self.select(g);
        match self.factorization.as_mut() {
            Some(f) => f.solve_refined(&self.g_sel, dz, REFINEMENT_STEPS, tolerance),
            None => Ok(()),
        }
    }
}

/// [`LinearSolver`]'s step for a one-off solve of a small dense J (at most
/// `min_norm::SMALL_ROWS` selected rows), factorized on the stack and not kept: for the many
/// small components of a sketch solved once, building a solver costs more than the arithmetic.
///
/// # Errors
/// [`Error::RankDeficient`] for dependent rows; dimension and weight errors.
pub(crate) fn small_step(
    j: &SparseMatrix,
    weights: &[f64],
    g: &[f64],
    dz: &mut [f64],
    tolerance: f64,
) -> Result<()> {
    if j.nrows() > min_norm::SMALL_ROWS {
        return Err(Error::Dimension {
            what: "rows of a small minimum-norm system",
            expected: min_norm::SMALL_ROWS,
            found: j.nrows(),
        });
    }
    min_norm::solve_small_refined(j, weights, g, dz, REFINEMENT_STEPS, tolerance)
}
