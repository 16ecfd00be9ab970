//! Settings of the nonlinear solvers (Newton, SLSQP, the soft least-squares mode) and of the
//! selection between them, carried in [`crate::Options::nonlinear`].

use crate::model::objective::Objective;

/// A solver the caller may force instead of the automatic selection (for comparisons).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum SolverChoice {
    /// The linear minimum-norm step ([`crate::solve_linear`]); refuses nonlinear residuals.
    Linear,
    /// Newton minimum-norm iterations with the pull-back toward the start.
    Newton,
    /// SLSQP (NLopt); [`crate::model::errors::Error::SolverUnavailable`] without the `nlopt` feature.
    Slsqp,
    /// The soft least-squares compromise (Levenberg–Marquardt), written back even when some
    /// constraints stay unsatisfied.
    Soft,
}

/// The most unknowns a problem may have to be handed to SLSQP.
///
/// SLSQP is dense: NLopt sizes its workspace as about (3n + m)·(n + 2) doubles plus the m × n
/// constraint Jacobian, and solves a dense least-squares subproblem of that size at every
/// iteration (O(n³) work). At 2,000 unknowns that is about 130 MB and seconds per iteration;
/// far beyond it NLopt's 32-bit workspace arithmetic overflows and the process is corrupted.
/// Larger components stay on the sparse paths (Newton, Levenberg–Marquardt).
pub const SLSQP_MAX_UNKNOWNS: usize = 2_000;

/// Checks that a problem of `unknowns` unknowns and `rows` equality rows lies within what
/// SLSQP supports: at least one unknown, no more equality rows than unknowns (NLopt 2.9's
/// SLSQP writes past its workspace otherwise), and at most [`SLSQP_MAX_UNKNOWNS`] unknowns.
///
/// ```
/// use camber_solve::{slsqp_supports, SLSQP_MAX_UNKNOWNS};
/// assert!(slsqp_supports(15, 14).is_ok());
/// assert!(slsqp_supports(15, 21).is_err());
/// assert!(slsqp_supports(SLSQP_MAX_UNKNOWNS + 1, 10).is_err());
/// ```
///
/// # Errors
/// [`crate::model::errors::Error::OutsideSolverLimits`] naming the limit exceeded.
pub fn slsqp_supports(unknowns: usize, rows: usize) -> crate::model::errors::Result<()> {
    let why = if rows > unknowns {
        Some("more equality rows than unknowns")
    } else if unknowns > SLSQP_MAX_UNKNOWNS {
        Some("more unknowns than the dense SLSQP takes (camber_solve::SLSQP_MAX_UNKNOWNS)")
    } else {
        None
    };
    match why {
        Some(why) => Err(crate::model::errors::Error::OutsideSolverLimits {
            solver: "SLSQP",
            unknowns,
            rows,
            why,
        }),
        None => Ok(()),
    }
}

/// Tolerances, limits and choices of the nonlinear solvers.
///
/// ```
/// use camber_solve::{NonlinearOptions, Options, SolverChoice};
/// let o = Options::default()
///     .with_nonlinear(NonlinearOptions::default().with_max_iterations(20))
///     .with_force(Some(SolverChoice::Newton));
/// assert_eq!(o.nonlinear.max_iterations, 20);
/// assert_eq!(o.nonlinear.force, Some(SolverChoice::Newton));
/// ```
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct NonlinearOptions {
    /// Newton and Levenberg–Marquardt iterations at most.
    pub max_iterations: usize,
    /// Newton stops once the residuals are within tolerance and the step (including the
    /// pull-back) has max |Δz_k| ≤ `step_tolerance`·(1 + max |z_k|).
    pub step_tolerance: f64,
    /// SLSQP objective and constraint evaluations at most.
    pub slsqp_max_evaluations: u32,
    /// SLSQP stops when an iteration changes every z_k by less than this relative amount.
    pub slsqp_xtol_rel: f64,
    /// Half-width of the box around the start z₀ that SLSQP searches in (intersected with the
    /// problem's bounds), in the units of the unknowns; infinite means no box beyond the
    /// relative one below.
    pub search_box: f64,
    /// The box's half-width relative to the start's scale: SLSQP never moves an unknown by
    /// more than `search_box_relative`·(1 + max_k |z₀_k|) (default 1,000). A minimum-norm
    /// solution lies within a few sketch sizes of the start; the relative box keeps SLSQP's
    /// quasi-Newton model from running an unknown that the constraints no longer hold at the
    /// last iterate (a control point whose basis function vanishes at a free contact) off to
    /// 10⁴⁷ and calling that feasible point a solution. Infinite means no relative box.
    pub search_box_relative: f64,
    /// What SLSQP minimises.
    pub objective: Objective,
    /// Run this solver instead of the automatic selection.
    pub force: Option<SolverChoice>,
    /// When the constraints cannot all be met, write back the soft least-squares compromise
    /// (minimising Σ g_i² + ε‖z − z₀‖²_W) instead of failing.
    pub soft: bool,
    /// The ε of the soft mode (relative weight of staying near the start).
    pub soft_epsilon: f64,
    /// The most evaluations (of the residuals, their Jacobian or a Hessian, each counting one)
    /// one solve may spend over every path it tries ([`crate::Problem::start_budget`]); `None`
    /// leaves each path's own limits only. Most solves that succeed spend a few dozen to a few
    /// hundred, hard ones from far starts up to a few tens of thousands (a contact found only
    /// from a later contact start); the default, [`DEFAULT_MAX_EVALUATIONS`], bounds what a
    /// failing one costs.
    pub max_evaluations: Option<usize>,
}

/// The default [`NonlinearOptions::search_box_relative`].
pub const DEFAULT_SEARCH_BOX_RELATIVE: f64 = 1_000.0;

/// The default [`NonlinearOptions::max_evaluations`].
pub const DEFAULT_MAX_EVALUATIONS: usize = 50_000;

impl Default for NonlinearOptions {
    fn default() -> Self {
        Self {
            max_iterations: 100,
            step_tolerance: 1e-12,
            slsqp_max_evaluations: 2000,
            slsqp_xtol_rel: 1e-14,
            search_box: f64::INFINITY,
            search_box_relative: DEFAULT_SEARCH_BOX_RELATIVE,
            objective: Objective::Displacement,
            force: None,
            soft: false,
            soft_epsilon: 1e-8,
            max_evaluations: Some(DEFAULT_MAX_EVALUATIONS),
        }
    }
}

impl NonlinearOptions {
    /// Sets [`NonlinearOptions::max_iterations`].
    pub fn with_max_iterations(mut self, n: usize) -> Self {
        self.max_iterations = n;
        self
    }

    /// Sets [`NonlinearOptions::step_tolerance`].
    pub fn with_step_tolerance(mut self, t: f64) -> Self {
        self.step_tolerance = t;
        self
    }

    /// Sets [`NonlinearOptions::slsqp_max_evaluations`].
    pub fn with_slsqp_max_evaluations(mut self, n: u32) -> Self {
        self.slsqp_max_evaluations = n;
        self
    }

    /// Sets [`NonlinearOptions::slsqp_xtol_rel`].
    pub fn with_slsqp_xtol_rel(mut self, t: f64) -> Self {
        self.slsqp_xtol_rel = t;
        self
    }

    /// Sets [`NonlinearOptions::search_box`].
    pub fn with_search_box(mut self, half_width: f64) -> Self {
        self.search_box = half_width;
        self
    }

    /// Sets [`NonlinearOptions::search_box_relative`].
    pub fn with_search_box_relative(mut self, factor: f64) -> Self {
        self.search_box_relative = factor;
        self
    }

    /// The half-width of SLSQP's box around `start` (see [`NonlinearOptions::search_box`] and
    /// [`NonlinearOptions::search_box_relative`]).
    ///
    /// ```
    /// use camber_solve::NonlinearOptions;
    /// let o = NonlinearOptions::default().with_search_box_relative(10.0);
    /// assert_eq!(o.search_box_half_width(&[0.5, -3.0]), 40.0);
    /// let o = o.with_search_box(5.0);
    /// assert_eq!(o.search_box_half_width(&[0.5, -3.0]), 5.0);
    /// ```
    pub fn search_box_half_width(&self, start: &[f64]) -> f64 {
        let scale = start.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        self.search_box
            .min(self.search_box_relative * (1.0 + scale))
    }

    /// Sets [`NonlinearOptions::objective`].
    pub fn with_objective(mut self, objective: Objective) -> Self {
        self.objective = objective;
        self
    }

    /// Sets [`NonlinearOptions::max_evaluations`].
    pub fn with_max_evaluations(mut self, n: Option<usize>) -> Self {
        self.max_evaluations = n;
        self
    }

    /// Sets [`NonlinearOptions::soft_epsilon`].
    pub fn with_soft_epsilon(mut self, epsilon: f64) -> Self {
        self.soft_epsilon = epsilon;
        self
    }

    /// Checks that the numbers make sense.
    pub(crate) fn validate(&self) -> crate::model::errors::Result<()> {
        let checks = [
            ("step tolerance", self.step_tolerance, false),
            ("SLSQP x tolerance", self.slsqp_xtol_rel, false),
            ("search box", self.search_box, true),
            ("relative search box", self.search_box_relative, true),
            ("soft epsilon", self.soft_epsilon, false),
        ];
        for (index, (what, v, infinite_ok)) in checks.into_iter().enumerate() {
            let finite_ok = v.is_finite() || (infinite_ok && v.is_infinite());
            if !(finite_ok && v > 0.0) {
                return Err(crate::model::errors::Error::NonFinite {
                    what,
                    index,
                    value: v,
                });
            }
        }
        Ok(())
    }
}
