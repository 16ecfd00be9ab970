//! One connected component of a sketch as a solver problem.
//!
//! The sketch compiles each constraint into pieces ([`crate::constraints`]); this module turns
//! a component's pieces into a [`camber_solve::Problem`] ([`problem`], with coincident points
//! merged by `merge`) with the policy's plan kept beside it, keeps contacts honest with an
//! active set of extra rows (`contact`), and solves it (`solve`: the plan, then the checks of
//! the solved geometry) for the sketch's solve and its drag sessions. The checks of a solved state ([`SolvedCheck`]) are the kinds' own, in
//! [`crate::constraints`].

pub(crate) mod arcs;
pub(crate) mod contact;
pub(crate) mod ellipses;
pub(crate) mod merge;
pub mod problem;
pub(crate) mod solve;

pub use crate::constraints::check::{ContactSpec, ContactTarget, SolvedCheck, SolvedState};
pub use problem::{ComponentProblem, DRAG_CONSTRAINT};

use crate::ground::ids::{ConstraintId, EntityId};

/// A connected component of the sketch graph: entities and the constraints between them,
/// each sorted by id.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct Component {
    /// The entities.
    pub entities: Vec<EntityId>,
    /// The constraints.
    pub constraints: Vec<ConstraintId>,
}
