//! The structure of a Jacobian's sparsity pattern, before any number is looked at.
//!
//! [`maximum_matching`] pairs rows with unknowns (its size is the structural rank) and
//! [`Decomposition`] splits the pattern into its Dulmage–Mendelsohn parts and blocks. The rank
//! analysis runs its numeric tests inside these blocks.

mod dulmage_mendelsohn;
mod matching;

pub use dulmage_mendelsohn::{Block, Decomposition, Part};
pub use matching::{maximum_matching, Matching};
