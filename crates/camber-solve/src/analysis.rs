//! Rank and degree-of-freedom analysis of a linearized problem.
//!
//! The numerical rank r of J (m × n) is the number of singular values above
//! `rank_tolerance`·σ_max (SVD, dense). DOF = n − r, n being the reduced (free) unknowns.
//!
//! Which rows are dependent is decided greedily in row order by Gram–Schmidt on the rows of J
//! (a QR factorization of Jᵀ that rejects instead of pivoting), orthogonalizing twice for
//! stability: row i is independent when its distance from the span of the rows already accepted
//! exceeds `rank_tolerance`·σ_max. The right-hand side g is carried through the same
//! combinations, so for a dependent row i ≈ Σ λ_k·(accepted row k) the leftover
//! h_i = g_i − Σ λ_k·g_k is available at no extra cost: |h_i| ≤ `residual_tolerance` means the
//! row is **redundant** (consistent: J·Δz = −g stays solvable without it and then satisfies it);
//! otherwise it is **conflicting** (no Δz satisfies all rows).

use nalgebra::{DMatrix, DVector};

use crate::errors::Result;
use crate::ids::ConstraintId;
use crate::reduced::Linearization;
use crate::sparse::check_len;

/// A row found to depend on the rows before it.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DependentRow {
    /// The row of J.
    pub row: usize,
    /// |g_i − Σ λ_k·g_k|: zero (within tolerance) for a redundant row.
    pub mismatch: f64,
    /// Whether the row is consistent (redundant) rather than conflicting.
    pub consistent: bool,
}

/// The outcome of [`analyze_rows`].
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct RowAnalysis {
    /// Numerical rank of J by SVD.
    pub rank: usize,
    /// Largest singular value σ_max of J (the scale of the rank tolerance).
    pub sigma_max: f64,
    /// Rows kept, in order (independent of each other).
    pub independent: Vec<usize>,
    /// Rows dependent on earlier rows, in order.
    pub dependent: Vec<DependentRow>,
}

/// Rank of `j` and its dependent rows, classified against the right-hand side `g`
/// (see the module documentation for the tolerances).
///
/// ```
/// use camber_solve::analysis::analyze_rows;
/// use nalgebra::dmatrix;
/// // Rows: x = 1, x = 1 again (redundant), x = 2 (conflicting); residuals g = x₀ − b at x₀ = 0.
/// let j = dmatrix![1.0, 0.0; 1.0, 0.0; 1.0, 0.0];
/// let a = analyze_rows(&j, &[-1.0, -1.0, -2.0], 1e-10, 1e-10)?;
/// assert_eq!(a.rank, 1);
/// assert_eq!(a.independent, vec![0]);
/// assert!(a.dependent[0].consistent && !a.dependent[1].consistent);
/// # Ok::<(), camber_solve::Error>(())
/// ```
///
/// # Errors
/// [`crate::Error::Dimension`] when `g` does not have one entry per row.
pub fn analyze_rows(
    j: &DMatrix<f64>,
    g: &[f64],
    rank_tolerance: f64,
    residual_tolerance: f64,
) -> Result<RowAnalysis> {
    let (m, n) = j.shape();
    check_len("residual rows", m, g.len())?;
    let sigma = if m == 0 || n == 0 {
        DVector::zeros(0)
    } else {
        j.clone().singular_values()
    };
    let sigma_max = sigma.iter().copied().fold(0.0, f64::max);
    let threshold = rank_tolerance * sigma_max;
    let rank = sigma
        .iter()
        .filter(|s| **s > threshold && **s > 0.0)
        .count();

    // Orthonormal basis q_k of the accepted rows, with h_k carrying g through the same
    // combinations.
    let mut basis: Vec<(DVector<f64>, f64)> = Vec::new();
    let mut independent = Vec::new();
    let mut dependent = Vec::new();
    for (i, gi) in g.iter().enumerate() {
        let mut v: DVector<f64> = j.row(i).transpose();
        let mut h = *gi;
        for _ in 0..2 {
            for (q, hq) in &basis {
                let c = q.dot(&v);
                v.axpy(-c, q, 1.0);
                h -= c * hq;
            }
        }
        let norm = v.norm();
        if norm > threshold && norm > 0.0 {
            basis.push((v / norm, h / norm));
            independent.push(i);
        } else {
            dependent.push(DependentRow {
                row: i,
                mismatch: h.abs(),
                consistent: h.abs() <= residual_tolerance,
            });
        }
    }
    Ok(RowAnalysis {
        rank,
        sigma_max,
        independent,
        dependent,
    })
}

/// The DOF analysis of a problem, by constraint.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DofAnalysis {
    /// Reduced (free) unknowns n.
    pub free_unknowns: usize,
    /// Numerical rank r of J.
    pub rank: usize,
    /// n − r.
    pub dof: usize,
    /// Constraints owning a consistent dependent row (each once, in row order).
    pub redundant: Vec<ConstraintId>,
    /// Constraints owning an inconsistent dependent row (each once, in row order).
    pub conflicting: Vec<ConstraintId>,
    /// The row-level result.
    pub rows: RowAnalysis,
}

/// Runs [`analyze_rows`] on a linearization and names the constraints.
///
/// # Errors
/// As [`analyze_rows`].
pub fn analyze(
    lin: &Linearization,
    rank_tolerance: f64,
    residual_tolerance: f64,
) -> Result<DofAnalysis> {
    let rows = analyze_rows(
        &lin.jacobian.to_dense(),
        &lin.g,
        rank_tolerance,
        residual_tolerance,
    )?;
    let mut redundant = Vec::new();
    let mut conflicting = Vec::new();
    for d in &rows.dependent {
        let list = if d.consistent {
            &mut redundant
        } else {
            &mut conflicting
        };
        if let Some(owner) = lin.row_owner.get(d.row) {
            if !list.contains(owner) {
                list.push(*owner);
            }
        }
    }
    let free_unknowns = lin.map.len();
    Ok(DofAnalysis {
        free_unknowns,
        rank: rows.rank,
        dof: free_unknowns.saturating_sub(rows.rank),
        redundant,
        conflicting,
        rows,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::dmatrix;

    #[test]
    fn independent_rows_are_all_kept() {
        let j = dmatrix![1.0, 2.0, 0.0; 0.0, 1.0, 1.0];
        let a = analyze_rows(&j, &[0.3, -0.2], 1e-12, 1e-12).unwrap();
        assert_eq!(
            (a.rank, a.independent.clone(), a.dependent.len()),
            (2, vec![0, 1], 0)
        );
    }

    #[test]
    fn a_combination_of_earlier_rows_is_dependent() {
        // Row 2 = row 0 + 2·row 1; consistent when g2 = g0 + 2·g1.
        let j = dmatrix![1.0, 0.0, 1.0; 0.0, 1.0, -1.0; 1.0, 2.0, -1.0];
        let ok = analyze_rows(&j, &[1.0, 2.0, 5.0], 1e-12, 1e-12).unwrap();
        assert_eq!(ok.rank, 2);
        assert_eq!(ok.dependent.len(), 1);
        assert!(ok.dependent[0].consistent && ok.dependent[0].row == 2);
        let bad = analyze_rows(&j, &[1.0, 2.0, 5.5], 1e-12, 1e-12).unwrap();
        assert!(!bad.dependent[0].consistent);
        assert!((bad.dependent[0].mismatch - 0.5).abs() < 1e-12);
    }

    #[test]
    fn zero_rows_and_empty_matrices() {
        let j = dmatrix![0.0, 0.0; 1.0, 0.0];
        let a = analyze_rows(&j, &[0.0, 1.0], 1e-12, 1e-12).unwrap();
        assert_eq!(a.independent, vec![1]);
        assert!(a.dependent[0].consistent);
        let e = analyze_rows(&DMatrix::zeros(0, 3), &[], 1e-12, 1e-12).unwrap();
        assert_eq!(e.rank, 0);
    }
}
