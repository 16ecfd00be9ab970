//! The analysis of a linearized problem before it is solved: how many degrees of freedom it has,
//! which rows are redundant or conflicting, which unknowns can still move.
//!
//! - `rank`: the DOF analysis (dense SVD and Gram–Schmidt for small Jacobians, a row-by-row
//!   Givens QR for large ones), run block by block;
//! - `structure`: the sparsity pattern alone (maximum matching, Dulmage–Mendelsohn blocks);
//!   `blocks` runs the numeric tests inside them and `free_columns` finds the unknowns that
//!   can still move;
//! - `accidental`: rows dependent only at the current values of a nonlinear problem, checked
//!   again at a nearby configuration;
//! - `certificate`: a cheap proof of full row rank that lets the analysis be skipped;
//! - `mobility`: what the constraints leave free of a few combinations of unknowns (a dragged
//!   point), and the multipliers of the rows at a solution.
//!
//! It stands on `model` and `linalg` and knows nothing of the solvers.

pub(crate) mod accidental;
pub(crate) mod blocks;
pub(crate) mod certificate;
pub(crate) mod free_columns;
pub(crate) mod mobility;
pub(crate) mod rank;
pub mod structure;

pub use mobility::{mobility, multipliers, Mobility};
pub use rank::{
    analyze, analyze_rows, analyze_rows_sparse, Dependency, DependentRow, DofAnalysis, RowAnalysis,
    StructureSummary, DENSE_ANALYSIS_MAX_ENTRIES,
};
pub(crate) use rank::{
    analyze_rows_by_blocks, dense_null_projection, dense_rows, free_columns_of, kernel_for,
    largest_row_norm, random_draws, sparse_null_projection, sparse_rows, KernelRows,
};

use crate::model::errors::Result;
use crate::model::options::Options;
use crate::model::problem::Problem;

/// # Analysis
impl Problem {
    /// The DOF analysis at the current values (see [`analyze`]). For a nonlinear problem whose
    /// rows are dependent here, the dependence is checked again at a nearby configuration on
    /// the constraint manifold: rows dependent only here are reported as
    /// [`DofAnalysis::accidental`], and the rank and DOF are the nearby ones (see the
    /// `accidental` module).
    ///
    /// # Errors
    /// Those of [`Problem::linearize`].
    pub fn analyze(&self, options: &Options) -> Result<DofAnalysis> {
        options.validate()?;
        let lin = self.linearize()?;
        let analysis = analyze(&lin, options.rank_tolerance, options.tolerance)?;
        accidental::reclassify(self, &lin, analysis, options)
    }
}
