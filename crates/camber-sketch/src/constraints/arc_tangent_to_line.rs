//! `arc_tangent_to_line`: at one end P of an arc (centre C), the arc's tangent runs along a
//! line entity (A, B): the radius to that end is perpendicular to the line,
//!
//! (P − C)·d/|d| = 0, d = B − A (one row, length units),
//!
//! and the arc's direction of travel there, the counter-clockwise tangent rot₉₀(P − C) =
//! (−(P − C)_y, (P − C)_x), keeps its recorded sense along d (checked after every solve:
//! `agree` means rot₉₀(P − C)·d > 0). The row says nothing of where the end lies: with
//! `coincident` (the arc end at a line end) it makes a G1 join — a fillet, the corner of a
//! rounded rectangle —, with `point_on_line` the arc touches the line's infinite line at its
//! end; neither adds a redundant row. File form:
//! `{"kind": "arc_tangent_to_line", "arc": 1, "end": "start", "line": 0, "sense": "agree"}`.

use std::sync::Arc;

use camber_solve::{Residual, Scalar};
use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

pub use super::shared::arc_ends::ArcEnd;
use super::glyph::{self, Glyph};
use super::shared::radii::Round;
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::Sense;
use crate::residuals::curve::{dot, sub};

/// The arc's tangent at one end runs along the line, with a sense (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArcTangentToLine {
    /// The arc.
    pub arc: EntityId,
    /// Which end of it.
    pub end: ArcEnd,
    /// The line entity (its ends may be unknowns).
    pub line: EntityId,
    /// Whether the arc's counter-clockwise travel at that end agrees with B − A or opposes it.
    #[serde(default)]
    pub sense: Sense,
}

/// (P − C)·(B − A)/|B − A| = 0 over the blocks [C, P, A, B].
///
/// ```
/// use camber_sketch::constraints::arc_tangent_to_line::ArcLineTangency;
/// use camber_solve::Residual;
/// let mut g = [0.0_f64];
/// // Centre (0, 0), end (0, 1), a horizontal line: tangent there.
/// ArcLineTangency.eval(&[&[0.0, 0.0][..], &[0.0, 1.0][..], &[-1.0, 1.0][..], &[2.0, 1.0][..]], &mut g);
/// assert!(g[0].abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArcLineTangency;

impl Residual for ArcLineTangency {
    fn name(&self) -> &str {
        ArcTangentToLine::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2, 2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (radial, d) = (sub(x[1], x[0]), sub(x[3], x[2]));
        out[0] = dot(radial, d) / dot(d, d).sqrt();
    }
}

impl ConstraintKind for ArcTangentToLine {
    const TAG: &'static str = "arc_tangent_to_line";
    const LABEL: &'static str = "arc tangent to line";

    fn entities(&self, out: &mut Entities) {
        out.add(self.arc);
        out.add(self.line);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        Round::arc(cx, self.arc)?;
        cx.line(self.line)?;
        let slots = vec![
            Slot::Point(self.arc, 0),
            Slot::Point(self.arc, self.end.block()),
            Slot::Point(self.line, 0),
            Slot::Point(self.line, 1),
        ];
        cx.residual(ArcLineTangency, slots, Some(Arc::new(*self)));
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let Entity::Arc(blocks) = at.lookup(self.arc)? else {
            return Err(Error::WrongEntityKind {
                entity: self.arc,
                expected: "arc",
                found: at.lookup(self.arc)?.kind_name(),
            });
        };
        let (c, p) = (blocks[0], blocks[self.end.block()]);
        let r = p - c;
        Ok(vec![
            Glyph::Arrow(p, Vector2::new(-r.y, r.x)),
            glyph::line_arrow(at, self.line)?,
        ])
    }
}

impl SolvedCheck for ArcTangentToLine {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let (Entity::Arc(blocks), Entity::Line([a, b])) =
            (state.entity(self.arc)?, state.entity(self.line)?)
        else {
            return Err(Error::UnknownEntity { entity: self.arc });
        };
        let r = blocks[self.end.block()] - blocks[0];
        let travel = Vector2::new(-r.y, r.x);
        state.sense(self.sense.sign() * travel.dot(&(b - a)))
    }
}
