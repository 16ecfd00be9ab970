//! A cheap certificate that a small Jacobian has full row rank, so the dense DOF analysis can
//! be skipped (its answer is then known: rank m, nothing redundant or conflicting).

use crate::analysis::rank as analysis;
use crate::linalg::reduced::Linearization;

/// [`certainly_full_row_rank`] for the Jacobian of a linearization, when it is small enough
/// for the dense analysis (m·n ≤ [`analysis::DENSE_ANALYSIS_MAX_ENTRIES`]) and has no more
/// rows than unknowns; `false` otherwise (the caller then runs the analysis).
pub(crate) fn certainly_full_row_rank_of(lin: &Linearization, rank_tolerance: f64) -> bool {
    let (m, n) = (lin.jacobian.nrows(), lin.jacobian.ncols());
    if m == 1 && n >= 1 {
        if let Some(certified) = one_row_certified(lin.jacobian.row(0).1, rank_tolerance) {
            return certified;
        }
    }
    m > 0
        && m <= n
        && m.saturating_mul(n) <= analysis::DENSE_ANALYSIS_MAX_ENTRIES
        && certainly_full_row_rank(&lin.jacobian.to_dense(), rank_tolerance)
}

/// Whether J (m ≤ n rows, m > 0) certainly passes the dense analysis' rank test with every
/// row independent: all singular values above `rank_tolerance`·σ_max.
///
/// With JJᵀ = LLᵀ (Cholesky), the singular values of L are those of J, and
/// σ_min(L) = 1/‖L⁻¹‖₂ ≥ 1/‖L⁻¹‖_F while σ_max(J) ≤ ‖J‖_F, so
/// 1/‖L⁻¹‖_F ≥ c·‖J‖_F proves σ_min ≥ c·σ_max. The margin c = max(10⁻⁵, 10³·tolerance) covers
/// the rounding of forming and factoring JJᵀ (relative error about m·ε in λ_min = σ_min², far
/// below c² = 10⁻¹⁰), so a certified J has the analysis' rank m and, every row being at least
/// σ_min from the span of the others, no dependent row. This costs m²·n/2 + m³/2 flops
/// against the singular value decomposition's much larger constant; a J that is not certified
/// (ill-conditioned, rank deficient, or Cholesky failing) goes through the full analysis.
pub(crate) fn certainly_full_row_rank(j: &nalgebra::DMatrix<f64>, rank_tolerance: f64) -> bool {
    let (m, n) = j.shape();
    if m == 0 || m > n {
        return false;
    }
    let frobenius = j.norm();
    if !(frobenius.is_finite() && frobenius > 0.0) {
        return false;
    }
    let margin = rank_margin(rank_tolerance);
    // J·Jᵀ by its lower triangle and symmetry (a general product costs more at these sizes).
    let mut gram = nalgebra::DMatrix::<f64>::zeros(m, m);
    for a in 0..m {
        for b in 0..=a {
            let v = j.row(a).dot(&j.row(b));
            gram[(a, b)] = v;
            gram[(b, a)] = v;
        }
    }
    let Some(chol) = nalgebra::linalg::Cholesky::new(gram) else {
        return false;
    };
    let mut inverse = nalgebra::DMatrix::<f64>::identity(m, m);
    if !chol.l_dirty().solve_lower_triangular_mut(&mut inverse) {
        return false;
    }
    // Only the lower triangle of the factor is L (the upper one holds leftovers), and the
    // lower-triangular solve reads only that part.
    let inverse_norm = inverse.norm();
    inverse_norm.is_finite() && 1.0 / inverse_norm >= margin * frobenius
}

/// [`certainly_full_row_rank`] for a J of one row (its non-zero values), without the dense
/// copy and factorization: L = ‖J‖, so the test reads ‖J‖ ≥ c·‖J‖, which holds for every
/// finite non-zero row when c ≤ ½ (no rounding can turn it). `None` for a larger margin.
fn one_row_certified(values: &[f64], rank_tolerance: f64) -> Option<bool> {
    if rank_margin(rank_tolerance) > 0.5 {
        return None;
    }
    let norm = values.iter().map(|v| v * v).sum::<f64>().sqrt();
    Some(norm.is_finite() && norm > 0.0)
}

/// The margin c of [`certainly_full_row_rank`]: max(10⁻⁵, 10³·tolerance).
fn rank_margin(rank_tolerance: f64) -> f64 {
    (1e3 * rank_tolerance).max(1e-5)
}

#[cfg(test)]
mod tests {
    use super::{certainly_full_row_rank, one_row_certified};
    use nalgebra::DMatrix;
    use proptest::prelude::*;
    #[test]
    fn a_well_conditioned_jacobian_is_certified() {
        // x₁ − x₀, y₁ − y₀ and a row in the first point alone.
        let j = DMatrix::from_row_slice(
            3,
            4,
            &[1.0, 0.0, -1.0, 0.0, 0.0, 1.0, 0.0, -1.0, 2.0, 0.5, 0.0, 0.0],
        );
        assert!(certainly_full_row_rank(&j, 1e-10));
    }

    #[test]
    fn dependent_or_nearly_dependent_rows_are_not_certified() {
        let duplicate = DMatrix::from_row_slice(2, 3, &[1.0, 2.0, 3.0, 1.0, 2.0, 3.0]);
        assert!(!certainly_full_row_rank(&duplicate, 1e-10));
        // σ_min/σ_max about 1e-9: above the rank tolerance, but inside the margin, so the full
        // analysis decides.
        let near = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 1.0, 1e-9]);
        assert!(!certainly_full_row_rank(&near, 1e-10));
        let zero = DMatrix::<f64>::zeros(2, 3);
        assert!(!certainly_full_row_rank(&zero, 1e-10));
        // More rows than unknowns can never have full row rank.
        let tall = DMatrix::from_row_slice(3, 2, &[1.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
        assert!(!certainly_full_row_rank(&tall, 1e-10));
    }

    proptest! {
        /// The one-row shortcut answers as the dense certificate does (rows with zeros,
        /// tiny and huge entries, and the zero row).
        #[test]
        fn one_row_shortcut_agrees_with_the_dense_certificate(
            entries in proptest::collection::vec(-1.0f64..1.0, 1..8),
            zeros in proptest::collection::vec(proptest::bool::ANY, 8),
            scale in -12i32..12,
            tolerance in prop_oneof![Just(1e-10), Just(1e-6), Just(1e-3), Just(0.1)],
        ) {
            let row: Vec<f64> = entries
                .iter()
                .zip(&zeros)
                .map(|(v, z)| if *z { 0.0 } else { v * 10f64.powi(scale) })
                .collect();
            let dense = DMatrix::from_row_slice(1, row.len(), &row);
            if let Some(certified) = one_row_certified(&row, tolerance) {
                prop_assert_eq!(certified, certainly_full_row_rank(&dense, tolerance));
            } else {
                prop_assert!(tolerance > 1e-4);
            }
        }

        /// Whenever the certificate holds, the singular values agree: every one above the
        /// margin times σ_max (so the analysis' rank test finds rank m).
        #[test]
        fn a_certified_matrix_has_full_rank_by_its_singular_values(
            entries in proptest::collection::vec(-1.0f64..1.0, 24),
            m in 1usize..=4,
            squash in 0usize..4,
        ) {
            let n = 6;
            let mut j = DMatrix::from_row_slice(4, n, &entries).rows(0, m).into_owned();
            // Make the last row nearly a copy of the first for some cases.
            if squash > 0 && m > 1 {
                let first = j.row(0).into_owned();
                let eps = 10f64.powi(-3 * squash as i32);
                let last = &first + j.row(m - 1) * eps;
                j.set_row(m - 1, &last);
            }
            let sigma = j.clone().singular_values();
            let max = sigma.max();
            let min = sigma.min();
            if certainly_full_row_rank(&j, 1e-10) {
                prop_assert!(min >= 0.999e-5 * max, "σ = {sigma}");
            }
            if min < 1e-6 * max {
                prop_assert!(!certainly_full_row_rank(&j, 1e-10));
            }
        }
    }
}
