//! `elliptic_arc_tangent_to_line`: at one end P of an elliptic arc (centre C, a-axis vertex
//! V, semi-axis b), the arc's tangent runs along a line entity (A, B). With u = (V − C)/a,
//! v = rot₉₀(u), the end's frame coordinates x′ = (P − C)·u, y′ = (P − C)·v and the line's unit
//! direction d̂ = (B − A)/|B − A|, the ellipse's normal there is ∝ (x′/a²)·u + (y′/b²)·v, so
//! the tangent is along the line when
//!
//! g = (b²·x′·(u·d̂) + a²·y′·(v·d̂))/(a·b) = 0 (one row, length units),
//!
//! and the arc's direction of travel there, its counter-clockwise tangent
//! E′ = −(a/b)·y′·u + (b/a)·x′·v, keeps its recorded sense along B − A (checked after every
//! solve: `agree` means E′·(B − A) > 0). The row says nothing of where the end lies: with
//! `coincident` (the end at a line end) it makes a G1 join, with `point_on_line` the arc
//! touches the line at its end. File form:
//! `{"kind": "elliptic_arc_tangent_to_line", "arc": 1, "end": "start", "line": 0, "sense": "agree"}`.

use std::sync::Arc;

use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::shared::arc_ends::ArcEnd;
use super::shared::ellipses::{end_block, travel};
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::Sense;
use crate::residuals::curve::{cross, dot, sub};

/// The elliptic arc's tangent at one end runs along the line, with a sense (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EllipticArcTangentToLine {
    /// The elliptic arc.
    pub arc: EntityId,
    /// Which end of it.
    pub end: ArcEnd,
    /// The line entity (its ends may be unknowns).
    pub line: EntityId,
    /// Whether the arc's counter-clockwise travel at that end agrees with B − A or opposes it.
    #[serde(default)]
    pub sense: Sense,
}

/// g of the module documentation over the blocks [C, V, b, P, A, B].
///
/// ```
/// use camber_sketch::constraints::elliptic_arc_tangent_to_line::EllipseLineTangency;
/// use camber_solve::Residual;
/// let mut g = [0.0_f64];
/// // Centre (0, 0), vertex (2, 0), b = 1: at the top (0, 1) a horizontal line is tangent.
/// let top = [&[0.0, 0.0][..], &[2.0, 0.0][..], &[1.0][..], &[0.0, 1.0][..], &[-1.0, 1.0][..], &[3.0, 1.0][..]];
/// EllipseLineTangency.eval(&top, &mut g);
/// assert!(g[0].abs() < 1e-15);
/// // At the vertex (2, 0) a horizontal line is a normal: g = b·x′/a·… = 1.
/// let vertex = [&[0.0, 0.0][..], &[2.0, 0.0][..], &[1.0][..], &[2.0, 0.0][..], &[-1.0, 0.0][..], &[3.0, 0.0][..]];
/// EllipseLineTangency.eval(&vertex, &mut g);
/// assert!((g[0] - 1.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipseLineTangency;

impl Residual for EllipseLineTangency {
    fn name(&self) -> &str {
        EllipticArcTangentToLine::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2, 1, 2, 2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (w, p, d) = (sub(x[1], x[0]), sub(x[3], x[0]), sub(x[5], x[4]));
        let b = x[2][0];
        let a2 = dot(w, w);
        let a = a2.sqrt();
        let d_len = dot(d, d).sqrt();
        // x′·a = p·w, y′·a = w × p, (u·d̂)·a·|d| = w·d, (v·d̂)·a·|d| = w × d.
        let (xa, ya) = (dot(p, w), cross(w, p));
        let (ud, vd) = (dot(w, d), cross(w, d));
        out[0] = (b * b * xa * ud + a2 * ya * vd) / (a2 * a * b * d_len);
    }
}

impl ConstraintKind for EllipticArcTangentToLine {
    const TAG: &'static str = "elliptic_arc_tangent_to_line";
    const LABEL: &'static str = "elliptic arc tangent to line";

    fn entities(&self, out: &mut Entities) {
        out.add(self.arc);
        out.add(self.line);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let e = cx.entity(self.arc)?;
        if !matches!(e, Entity::EllipticArc { .. }) {
            return Err(Error::WrongEntityKind {
                entity: self.arc,
                expected: "elliptic arc",
                found: e.kind_name(),
            });
        }
        cx.line(self.line)?;
        let slots = vec![
            Slot::Point(self.arc, 0),
            Slot::Point(self.arc, 1),
            Slot::Radius(self.arc),
            Slot::Point(self.arc, end_block(self.end)),
            Slot::Point(self.line, 0),
            Slot::Point(self.line, 1),
        ];
        cx.residual(EllipseLineTangency, slots, Some(Arc::new(*self)));
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let Entity::EllipticArc {
            points,
            semi_axis_b,
        } = at.lookup(self.arc)?
        else {
            return Err(Error::WrongEntityKind {
                entity: self.arc,
                expected: "elliptic arc",
                found: at.lookup(self.arc)?.kind_name(),
            });
        };
        let p = points[end_block(self.end)];
        Ok(vec![
            Glyph::Arrow(p, travel(&points[0], &points[1], *semi_axis_b, &p)),
            glyph::line_arrow(at, self.line)?,
        ])
    }
}

impl SolvedCheck for EllipticArcTangentToLine {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let (
            Entity::EllipticArc {
                points,
                semi_axis_b,
            },
            Entity::Line([a, b]),
        ) = (state.entity(self.arc)?, state.entity(self.line)?)
        else {
            return Err(Error::UnknownEntity { entity: self.arc });
        };
        let p = points[end_block(self.end)];
        let t = travel(&points[0], &points[1], *semi_axis_b, &p);
        state.sense(self.sense.sign() * t.dot(&(b - a)))
    }
}
