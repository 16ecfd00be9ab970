//! What a solve reports: outcome, solver and why, residual per constraint, DOF, time.

use std::time::Duration;

use serde::Serialize;

use crate::model::ids::ConstraintId;

/// How a successful solve ended (failures are [`crate::Error`]s and change nothing).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// The values were moved and every residual is now within tolerance.
    Solved,
    /// Every residual was already within tolerance and no substitution had to be imposed;
    /// nothing was moved.
    AlreadySatisfied,
    /// The constraints could not all be met; the least-squares compromise was written back and
    /// [`SolveReport::conflicting`] lists the constraints left above tolerance: the soft mode,
    /// or constraints of a lower priority relaxed ([`SolveReport::priorities`] says which).
    Relaxed,
}

/// Which solver produced the result.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SolverKind {
    /// No solver ran (nothing to do).
    None,
    /// Linear minimum-norm step, dense Cholesky of J·W⁻¹·Jᵀ.
    DenseMinNorm,
    /// Linear minimum-norm step, sparse Cholesky of J·W⁻¹·Jᵀ.
    SparseMinNorm,
    /// Newton minimum-norm iterations with the pull-back toward the start.
    Newton,
    /// SLSQP (NLopt) minimising the objective subject to every residual = 0.
    Slsqp,
    /// Levenberg–Marquardt on Σ g_i² + ε‖z − z₀‖²_W (the soft mode, or a rescue before a
    /// Newton polish).
    LevenbergMarquardt,
    /// Priority tiers in order, each by least squares within the tiers before it
    /// (the lexicographic solve of priority tiers).
    Prioritized,
}

/// Why the solve took its path: the selection's decision, typed (the report's `reason` adds the
/// details in words: ranks, iterations, what failed before).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum Selection {
    /// Every residual was already within tolerance: nothing ran.
    AlreadySatisfied,
    /// Every residual is affine: one linear minimum-norm step.
    Affine,
    /// Nonlinear with J of full row rank at the start: Newton minimum norm.
    FullRank,
    /// Nonlinear with consistent dependent rows at the start: Newton without them.
    DependentRowsLeftOut,
    /// Nonlinear with J rank deficient at the start: SLSQP.
    RankDeficient,
    /// The first choice failed and a later path (SLSQP after Newton, Levenberg–Marquardt then
    /// Newton) succeeded.
    Fallback,
    /// The soft compromise, asked for in the options.
    Soft,
    /// A solver forced in the options.
    Forced,
    /// A warm-started Newton step of a drag session.
    WarmStart,
    /// The whole set could not be met and constraints have priorities: tiers in order
    /// (the lexicographic solve of priority tiers).
    Prioritized,
}

/// How one priority tier came out of a prioritized solve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TierOutcome {
    /// The tier (0 required; higher tiers were relaxed first).
    pub priority: crate::model::priority::Priority,
    /// Whether every constraint of the tier is within tolerance.
    pub met: bool,
    /// The tier's constraints left above tolerance (empty when met).
    pub relaxed: Vec<ConstraintId>,
    /// max |g| over the tier's rows at the answer.
    pub max_residual: f64,
}

/// The largest absolute residual of one constraint (over all rows it owns).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ConstraintResidual {
    /// The constraint.
    pub constraint: ConstraintId,
    /// max |g| over its rows.
    pub max_abs: f64,
}

/// The report of a successful solve. Serializes with `elapsed` in seconds.
///
/// ```
/// use camber_solve::{solve_linear, ConstraintId, Options, Problem, Residual, Scalar};
/// #[derive(Debug)]
/// struct XIs3;
/// impl Residual for XIs3 {
///     fn name(&self) -> &str { "x = 3" }
///     fn dim(&self) -> usize { 1 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) { out[0] = x[0][0] - camber_solve::scalar::cst(3.0); }
///     fn is_affine(&self) -> bool { true }
/// }
/// let mut p = Problem::new();
/// let b = p.add_block(&[0.0])?;
/// p.add_residual(XIs3, &[b], ConstraintId(5))?;
/// let report = solve_linear(&mut p, &Options::default())?;
/// let json = serde_json::to_value(&report).map_err(|e| e.to_string()).unwrap();
/// assert_eq!(json["status"], "solved");
/// assert_eq!(json["residuals"][0]["constraint"], 5);
/// # Ok::<(), camber_solve::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SolveReport {
    /// How the solve ended.
    pub status: Status,
    /// The solver used.
    pub solver: SolverKind,
    /// Why that solver, typed.
    pub selection: Selection,
    /// Why that solver, in words (ranks, iterations, what failed before).
    pub reason: String,
    /// Iterations (1 for the linear solve, 0 when nothing ran).
    pub iterations: usize,
    /// Residual per constraint after the solve, in order of first appearance.
    pub residuals: Vec<ConstraintResidual>,
    /// ‖Δz‖₂, the Euclidean length of the move of the reduced unknowns (equal to ‖Δx‖₂ when
    /// nothing is substituted).
    pub displacement_norm: f64,
    /// Numerical rank of the Jacobian.
    pub rank: usize,
    /// Degrees of freedom left: reduced unknowns − rank.
    pub dof: usize,
    /// Constraints with consistent dependent rows (dropped from the solve).
    pub redundant: Vec<ConstraintId>,
    /// Constraints with inconsistent dependent rows (always empty for the linear solver, which
    /// fails on them; kept for the soft solvers to come).
    pub conflicting: Vec<ConstraintId>,
    /// Per priority tier, in order, whether it was met (only when the prioritized path ran:
    /// the whole set could not be met and some constraints have priorities; empty otherwise).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub priorities: Vec<TierOutcome>,
    /// Wall-clock time of the solve.
    #[serde(serialize_with = "seconds")]
    pub elapsed: Duration,
}

/// A duration as seconds (f64).
fn seconds<S: serde::Serializer>(d: &Duration, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_f64(d.as_secs_f64())
}

/// max |g| per owning constraint, in order of first appearance.
pub(crate) fn per_constraint(owners: &[ConstraintId], g: &[f64]) -> Vec<ConstraintResidual> {
    let mut out = Vec::new();
    per_constraint_into(owners, g, &mut out);
    out
}

/// [`per_constraint`] into `out` (cleared first; its storage is reused, so a small component
/// solved again and again allocates nothing here).
pub(crate) fn per_constraint_into(
    owners: &[ConstraintId],
    g: &[f64],
    out: &mut Vec<ConstraintResidual>,
) {
    // The rows of one constraint are nearly always consecutive: one entry per run of rows
    // first, then runs of the same constraint folded into its first (the maximum does not
    // depend on the grouping).
    out.clear();
    for (owner, gi) in owners.iter().zip(g) {
        match out.last_mut() {
            Some(last) if last.constraint == *owner => last.max_abs = last.max_abs.max(gi.abs()),
            _ => out.push(ConstraintResidual {
                constraint: *owner,
                max_abs: 0.0_f64.max(gi.abs()),
            }),
        }
    }
    // A few runs (a small component): distinct owners are checked pairwise, without sorting.
    if out.len() <= 16
        && out
            .iter()
            .enumerate()
            .all(|(k, r)| out[..k].iter().all(|q| q.constraint != r.constraint))
    {
        return;
    }
    let mut order: Vec<(ConstraintId, usize)> = out
        .iter()
        .enumerate()
        .map(|(k, r)| (r.constraint, k))
        .collect();
    order.sort_unstable();
    if order.windows(2).all(|w| w[0].0 != w[1].0) {
        return;
    }
    let mut keep = vec![true; out.len()];
    for group in order.chunk_by(|a, b| a.0 == b.0) {
        let Some(((_, first), rest)) = group.split_first() else {
            continue;
        };
        for (_, k) in rest {
            let m = out[*k].max_abs;
            out[*first].max_abs = out[*first].max_abs.max(m);
            keep[*k] = false;
        }
    }
    let mut flags = keep.iter();
    out.retain(|_| flags.next().copied().unwrap_or(true));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn residuals_are_grouped_by_owner() {
        let owners = [ConstraintId(4), ConstraintId(2), ConstraintId(4)];
        let r = per_constraint(&owners, &[0.1, -0.5, -0.3]);
        assert_eq!(r.len(), 2);
        assert_eq!(r[0].constraint, ConstraintId(4));
        assert!((r[0].max_abs - 0.3).abs() < 1e-15);
        assert!((r[1].max_abs - 0.5).abs() < 1e-15);
    }

    /// Runs of one owner, interleaved with others, fold into the owner's first appearance;
    /// a NaN row is ignored by the maximum, as one row after another.
    #[test]
    fn interleaved_runs_fold_in_first_appearance_order() {
        let c = ConstraintId;
        let owners = [c(7), c(7), c(3), c(9), c(7), c(3), c(3), c(1), c(9)];
        let g = [0.1, -0.2, 0.05, f64::NAN, -0.9, 0.4, -0.01, 2.0, -0.3];
        let r = per_constraint(&owners, &g);
        let got: Vec<(u64, f64)> = r.iter().map(|x| (x.constraint.0, x.max_abs)).collect();
        assert_eq!(got, vec![(7, 0.9), (3, 0.4), (9, 0.3), (1, 2.0)]);
        assert!(per_constraint(&[], &[]).is_empty());
    }
}
