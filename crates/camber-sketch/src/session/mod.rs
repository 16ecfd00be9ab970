//! The sessions of a sketch with the solver: a solve of its dirty components (`solve`, with the
//! other contact starts of `starts`), an interactive drag (`drag`), the DOF analysis
//! (`analysis`) and the iterative displacement of contacts (`displacement`). They are thin
//! callers of the one solve policy.

pub mod analysis;
pub mod displacement;
pub mod drag;
pub mod solve;
pub(crate) mod starts;
