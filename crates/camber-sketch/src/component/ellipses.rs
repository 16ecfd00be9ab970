//! What every elliptic arc of a component brings to its problem besides its blocks: its two
//! rows holding the start and the end on its ellipse ([`crate::residuals::ellipse`]) and the
//! check that a solve does not turn it inside out.
//!
//! As for a circular arc ([`super::arcs`]), the sweep is read from the blocks (the parametric
//! angles of S and E, reduced into (0, 2π)), and the rows see only the blocks, so a solve could
//! carry one end past the other and make the arc its complement on the ellipse. The check
//! refuses a solve that changes the sweep by more than π, with
//! [`crate::Error::ArcTurnedInsideOut`]; the sketch is then left as it was (the check is
//! [`super::arcs`]' own, read through [`crate::Entity::sweep`]).

use std::sync::Arc;

use super::arcs::SweepKept;
use crate::constraints::check::SolvedCheck;
use crate::constraints::piece::{Piece, Slot};
use crate::ground::ids::EntityId;

/// The rows of an elliptic arc: its end `end` (block 2 the start, 3 the end) on its ellipse,
/// over [C, V, b, P]; the start's row carries the sweep check.
pub(crate) fn elliptic_arc_rows(arc: EntityId) -> [Piece; 2] {
    let row = |point: usize, check: Option<Arc<dyn SolvedCheck>>| Piece::General {
        residual: Arc::new(crate::residuals::ellipse::OnEllipse),
        slots: vec![
            Slot::Point(arc, 0),
            Slot::Point(arc, 1),
            Slot::Radius(arc),
            Slot::Point(arc, point),
        ],
        check,
    };
    [row(2, Some(Arc::new(SweepKept { arc }))), row(3, None)]
}
