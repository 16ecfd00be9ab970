//! The sessions of a sketch with the solver: a solve of its dirty components (`solve`, with the
//! other contact starts of `starts`), an interactive drag (`drag`), the DOF analysis
//! (`analysis`), the iterative displacement of contacts (`displacement`), named parameters
//! changed and re-solved (`parameters`), sweeps over tables of them (`sweep`) and many sketches
//! solved by one call (`batch`). They are thin
//! callers of the one solve policy.

pub mod analysis;
pub mod batch;
pub mod displacement;
pub mod drag;
pub mod parameters;
pub mod solve;
pub(crate) mod starts;
pub mod sweep;
