//! What every arc of a component brings to its problem besides its blocks: its own row
//! |E − C| − |S − C| = 0 ([`crate::residuals::arc`]) and the check that a solve does not turn
//! it inside out.
//!
//! An arc's sweep is read from its blocks, φ = angle(E − C) − angle(S − C) reduced into
//! (0, 2π). The row and the point kinds see only the blocks, so a solve may carry the end past
//! the start (or the start past the end): the sweep then jumps from near 0 to near 2π or back,
//! and the arc becomes its complement on the circle. A solve never does that by a continuous
//! move of the drawing, so the check refuses a solve that changes the sweep by more than π,
//! with [`Error::ArcTurnedInsideOut`]; the sketch is then left as it was.

use std::sync::Arc;

use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::constraints::piece::{Piece, Slot};
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;

/// The arc's own row over its blocks, with the check of its sweep.
pub(crate) fn arc_row(arc: EntityId) -> Piece {
    Piece::General {
        residual: Arc::new(crate::residuals::arc::ArcEnds),
        slots: (0..3).map(|j| Slot::Point(arc, j)).collect(),
        check: Some(Arc::new(SweepKept { arc })),
    }
}

/// The sweep of an arc, circular or elliptic ([`crate::Entity::sweep`]), changes by at most π
/// in a solve (see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct SweepKept {
    /// The arc.
    pub(crate) arc: EntityId,
}

impl SolvedCheck for SweepKept {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let before = state.before.lookup(self.arc)?.sweep();
        let after = state.entity(self.arc)?.sweep();
        match (before, after) {
            (Some(b), Some(a)) if (a - b).abs() > std::f64::consts::PI => {
                Err(Error::ArcTurnedInsideOut {
                    entity: self.arc,
                    before: b,
                    after: a,
                })
            }
            _ => Ok(()),
        }
    }
}
