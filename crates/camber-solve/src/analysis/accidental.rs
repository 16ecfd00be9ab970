//! Dependence that holds only at the configuration: the generic rank of a nonlinear problem.
//!
//! The rank test of [`crate::analysis`] runs at the current values. A nonlinear problem can be
//! singular there without any constraint being implied by the others: a circle touching a line
//! by design (the point on both has parallel normals), or a start that happens to line two rows
//! up. Deleting such a "redundant" constraint would change the solution set, and a "conflict"
//! found there may solve. So when the rows at the configuration are dependent, the analysis is
//! repeated at a nearby configuration z₁ reached by a small move along the constraint manifold:
//!
//! 1. t = a random vector projected onto the null space of the independent rows (so the
//!    independent rows stay satisfied to first order); z₁ = z₀ + δ·t with δ = 10⁻³ of the
//!    configuration's scale;
//! 2. when the configuration satisfies its constraints, z₁ is pulled back onto the manifold of
//!    the independent rows by minimum-norm Newton corrections (a dependence implied by the
//!    constraints, such as a point on two lines through the same two constrained points, keeps
//!    holding there, while a tangency by design does not);
//! 3. the rows are analysed again at z₁ (block by block, as at z₀). A row dependent at z₀ but not at z₁ is *accidental*:
//!    its constraint is reported as singular here, neither redundant nor conflicting, and the
//!    rank and DOF become those at z₁ (the generic ones).
//!
//! Affine problems are skipped: their Jacobian is the same everywhere.

use std::collections::HashSet;

use crate::analysis::{analyze_rows_by_blocks, DofAnalysis};
use crate::linalg::evaluator::{max_abs, Evaluator};
use crate::linalg::min_norm::MinNormFactorization;
use crate::linalg::reduced::Linearization;
use crate::linalg::sparse::SparseMatrix;
use crate::model::errors::Result;
use crate::model::ids::ConstraintId;
use crate::model::options::Options;
use crate::model::problem::Problem;

/// The move along the manifold, relative to max(1, max |z₀|).
const MOVE: f64 = 1e-3;

/// Newton corrections back onto the manifold, at most.
const CORRECTIONS: usize = 30;

/// Reclassifies the dependent rows of `analysis` (taken at the problem's current values, `lin`)
/// by the analysis at a nearby configuration on the manifold (see the module documentation).
///
/// # Errors
/// Evaluation and factorization errors.
pub(crate) fn reclassify(
    problem: &Problem,
    lin: &Linearization,
    mut analysis: DofAnalysis,
    options: &Options,
) -> Result<DofAnalysis> {
    if lin.affine || analysis.rows.dependent.is_empty() {
        return Ok(analysis);
    }
    let n = lin.map.len();
    let z0 = lin.map.z0().to_vec();
    let weights = lin.map.weights().to_vec();
    let independent = analysis.rows.independent.clone();
    let on_manifold = max_abs(&lin.g) <= options.tolerance;

    // 1. A small random move along the independent rows' null space.
    let mut ev = Evaluator::new(problem)?;
    let Some(mut z) = moved_along(problem, &mut ev, &z0, &independent, options)? else {
        // No room to move: the dependence at z₀ is all there is to see.
        return Ok(analysis);
    };

    // 2. Back onto the manifold of the independent rows.
    let mut g = vec![0.0; ev.rows()];
    if on_manifold && !independent.is_empty() {
        let mut step = vec![0.0; n];
        for _ in 0..CORRECTIONS {
            ev.linearize(problem, &z, &mut g)?;
            let gi: Vec<f64> = independent.iter().map(|i| g[*i]).collect();
            if max_abs(&gi) <= options.tolerance {
                break;
            }
            let j = ev.jacobian(&[])?.select_rows(&independent);
            let Ok(mut f) =
                MinNormFactorization::try_auto(&j, &weights, options.dense_max_unknowns)
            else {
                break;
            };
            f.solve(&gi, &mut step)?;
            for (zk, s) in z.iter_mut().zip(&step) {
                *zk += s;
            }
            ev.clamp(&mut z);
        }
    }

    // 3. The rows at z₁.
    ev.linearize(problem, &z, &mut g)?;
    let j: SparseMatrix = ev.jacobian(&[])?;
    let nearby = analyze_rows_by_blocks(&j, &g, options.rank_tolerance, f64::INFINITY, true)?.rows;
    if nearby.rank <= analysis.rank {
        return Ok(analysis);
    }
    let still: HashSet<ConstraintId> = nearby
        .dependent
        .iter()
        .filter_map(|d| lin.row_owner.get(d.row).copied())
        .collect();
    let mut accidental = Vec::new();
    let mut seen = HashSet::new();
    for d in &analysis.rows.dependent {
        if let Some(owner) = lin.row_owner.get(d.row) {
            if !still.contains(owner) && seen.insert(*owner) {
                accidental.push(*owner);
            }
        }
    }
    for list in [
        &mut analysis.redundant,
        &mut analysis.partly_redundant,
        &mut analysis.conflicting,
    ] {
        list.retain(|c| !seen.contains(c));
    }
    analysis
        .depends_on
        .retain(|d| !seen.contains(&d.constraint));
    analysis.accidental = accidental;
    analysis.rank = nearby.rank;
    analysis.dof = analysis.free_unknowns.saturating_sub(nearby.rank);
    analysis.rows.free_columns = nearby.free_columns;
    Ok(analysis)
}

/// z₀ + δ·t, t a random vector projected onto the null space of the rows `rows` of J at z₀ (in
/// the metric of the weights), δ = [`MOVE`]·max(1, max |z₀|)/max |t|, clamped to the bounds:
/// a nearby configuration that keeps those rows to first order. `None` when that null space
/// is empty.
///
/// # Errors
/// Evaluation and factorization errors.
pub(crate) fn moved_along(
    problem: &Problem,
    ev: &mut Evaluator,
    z0: &[f64],
    rows: &[usize],
    options: &Options,
) -> Result<Option<Vec<f64>>> {
    let n = z0.len();
    let draws = crate::analysis::random_draws(7, n);
    let mut direction = vec![0.0; n];
    if rows.is_empty() {
        direction.copy_from_slice(&draws);
    } else {
        let mut g = vec![0.0; ev.rows()];
        ev.linearize(problem, z0, &mut g)?;
        let j = ev.jacobian(&[])?.select_rows(rows);
        let weights = ev.map.weights().to_vec();
        let mut f = MinNormFactorization::try_auto(&j, &weights, options.dense_max_unknowns)?;
        let mut multipliers = vec![0.0; rows.len()];
        f.project(&draws, &mut direction, &mut multipliers)?;
    }
    let top = max_abs(&direction);
    if top <= 1e-12 * max_abs(&draws) {
        return Ok(None);
    }
    let scale = z0.iter().fold(1.0_f64, |m, v| m.max(v.abs()));
    let delta = MOVE * scale / top;
    let mut z: Vec<f64> = z0
        .iter()
        .zip(&direction)
        .map(|(a, t)| a + delta * t)
        .collect();
    ev.clamp(&mut z);
    Ok(Some(z))
}
