//! The ground of the crate: ids, the vocabulary of sides and senses, errors, entities and the
//! evaluation of their curves, and the lookup of entities by id. It imports nothing above it:
//! residuals, constraint kinds, components, the sketch and its sessions all stand on it.

pub(crate) mod curve_ends;
pub mod curve_eval;
pub mod ellipse_blocks;
pub mod entity;
pub mod errors;
pub mod hermite_chain;
pub mod ids;
pub mod lookup;
pub mod vocabulary;
