//! `arc_touches_line`: a circular arc (centre C, radius r = |S − C|) touches the infinite line
//! of a line entity (A, B) somewhere in its interior, lying on a recorded side of A→B. With
//! d = B − A, one row in length units,
//!
//! cross(d, C − A)/|d| − s·r = 0 (s = +1 for `left`, −1 for `right`),
//!
//! the signed distance of the centre from the line equal to the radius on that side: the
//! classic |(C − A) × d|/|d| = r with the side kept, so the arc cannot pass through the line to
//! the other side without its radius going through zero. The contact is the foot of the
//! perpendicular from C, F = C − s·r·n̂ with n̂ = rot₉₀(d)/|d|; after every solve its direction
//! from the centre must lie within the arc's sweep (to the solve's tolerance over the radius),
//! else the solve fails with [`Error::ContactOffArc`] naming the constraint and the sketch is
//! left as it was (the arc's circle would touch the line, the arc would not). For an arc end
//! on a line, `arc_tangent_to_line` is the kind. File form:
//! `{"kind": "arc_touches_line", "arc": 1, "line": 0, "side": "left"}`.

use std::sync::Arc;

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use nalgebra::{Point2, Vector2};
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::shared::arc_span::outside_sweep;
use super::shared::radii::{radius_of, Round};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::LineSide;
use crate::residuals::curve::{cross, dot, sub};

/// The arc touches the line in its interior, on a recorded side (one row, and the contact
/// checked within the sweep after the solve).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArcTouchesLine {
    /// The circular arc.
    pub arc: EntityId,
    /// The line entity (its ends may be unknowns).
    pub line: EntityId,
    /// The side of A→B the arc (and its centre) lies on.
    pub side: LineSide,
}

/// cross(d, C − A)/|d| − s·|S − C| = 0 over the blocks [C, S, A, B].
///
/// ```
/// use camber_sketch::constraints::arc_touches_line::ArcLineContact;
/// use camber_sketch::LineSide;
/// use camber_solve::Residual;
/// let mut g = [f64::NAN];
/// // Centre (0, 2), radius 2 (start (2, 2)), the x axis run left to right: the arc lies on
/// // its left at distance 2, touching it at (0, 0).
/// let x: [&[f64]; 4] = [&[0.0, 2.0], &[2.0, 2.0], &[-1.0, 0.0], &[3.0, 0.0]];
/// ArcLineContact::new(LineSide::Left).eval(&x, &mut g);
/// assert!(g[0].abs() < 1e-15);
/// // On the right it would need a centre at y = −2: the row reads 2 − (−2).
/// ArcLineContact::new(LineSide::Right).eval(&x, &mut g);
/// assert!((g[0] - 4.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArcLineContact {
    side: f64,
}

impl ArcLineContact {
    /// The row for an arc on `side` of the line.
    pub fn new(side: LineSide) -> Self {
        Self {
            side: side_sign(side),
        }
    }
}

/// +1 for the left of A→B, −1 for the right.
fn side_sign(side: LineSide) -> f64 {
    match side {
        LineSide::Left => 1.0,
        LineSide::Right => -1.0,
    }
}

impl Residual for ArcLineContact {
    fn name(&self) -> &str {
        ArcTouchesLine::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2, 2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (r, _) = radius_of(true, x);
        let d = sub(x[3], x[2]);
        let offset = cross(d, sub(x[0], x[2])) / dot(d, d).sqrt();
        out[0] = offset - cst::<T>(self.side) * r;
    }
}

impl ArcTouchesLine {
    /// The contact F (foot of the perpendicular from the centre) and the line's direction, in
    /// the state `at` gives.
    fn contact_point<'e>(
        &self,
        at: impl Fn(EntityId) -> Result<&'e Entity>,
    ) -> Result<(Point2<f64>, Vector2<f64>)> {
        let (Entity::Arc(blocks), Entity::Line([a, b])) = (at(self.arc)?, at(self.line)?) else {
            return Err(Error::WrongEntityKind {
                entity: self.arc,
                expected: "arc and line",
                found: at(self.arc)?.kind_name(),
            });
        };
        let (c, d) = (blocks[0], b - a);
        let n = Vector2::new(-d.y, d.x) / d.norm();
        let offset = n.dot(&(c - a));
        Ok((c - offset * n, d))
    }
}

impl ConstraintKind for ArcTouchesLine {
    const TAG: &'static str = "arc_touches_line";
    const LABEL: &'static str = "arc touches line";

    fn entities(&self, out: &mut Entities) {
        out.add(self.arc);
        out.add(self.line);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        Round::arc(cx, self.arc)?;
        distinct(self.arc, self.line)?;
        cx.line(self.line)?;
        let slots = vec![
            Slot::Point(self.arc, 0),
            Slot::Point(self.arc, 1),
            Slot::Point(self.line, 0),
            Slot::Point(self.line, 1),
        ];
        cx.residual(
            ArcLineContact::new(self.side),
            slots,
            Some(Arc::new(*self)),
        );
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let (f, d) = self.contact_point(|id| at.lookup(id))?;
        Ok(vec![Glyph::Arrow(f, d), glyph::line_arrow(at, self.line)?])
    }
}

impl SolvedCheck for ArcTouchesLine {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let (f, _) = self.contact_point(|id| state.entity(id))?;
        let Some(arc) = state.entity(self.arc)?.as_arc() else {
            return Err(Error::UnknownEntity { entity: self.arc });
        };
        match outside_sweep(&arc, f - arc.center(), state.penetration) {
            None => Ok(()),
            Some(outside) => Err(Error::ContactOffArc {
                constraint: state.owner,
                arc: self.arc,
                outside,
            }),
        }
    }
}
