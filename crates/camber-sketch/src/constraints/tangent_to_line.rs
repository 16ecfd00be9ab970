//! `tangent_to_line`: a curve touches a line entity (A, B), whose ends may be unknowns, at a
//! fixed or free contact parameter u:
//!
//! cross(C(u) − A, d)/|d| = 0 and cross(C′(u), d)/|d| = 0, d = B − A (two rows, in length
//! units).
//!
//! After every solve the contact must be honest: C′(u) keeps its recorded sense along d and
//! does not vanish (a cusp), and the curve stays on its recorded side of the line near the
//! contact; a crossing calls for a clearance row (crate::residuals::clearance). File form:
//! `{"kind": "tangent_to_line", "curve": 0, "line": 2, "u": {"at": 0}, "side": "right",
//! "sense": "agree"}`.

use std::sync::Arc;

use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{point_tangent, ContactSpec, ContactTarget, SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::curve_eval::CurveBasis;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::residuals::curve::{cross, curve_at, curve_block_sizes, curve_support, dot, sub, Param};
use crate::ground::vocabulary::{Contact, LineSide, Sense};

/// The curve touches the line entity (A, B) at u and runs along it with the given sense
/// relative to B − A, lying on `side` near the contact (two rows).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TangentToLine {
    /// The curve.
    pub curve: EntityId,
    /// The line entity (its ends may be unknowns).
    pub line: EntityId,
    /// The contact parameter.
    pub u: Contact,
    /// Which side of the line the curve stays on near the contact.
    pub side: LineSide,
    /// C′(u) along or against B − A.
    #[serde(default)]
    pub sense: Sense,
}

/// The curve touches the line through A and B at u: cross(C − A, d)/|d| = 0 and
/// cross(C′, d)/|d| = 0 with d = B − A (blocks: curve, u, A, B).
#[derive(Debug, Clone, PartialEq)]
pub struct LineContact {
    basis: CurveBasis,
    u: Param,
}

impl LineContact {
    /// The two rows of tangency to a line given by two point blocks.
    pub fn new(basis: CurveBasis, u: Param) -> Self {
        Self { basis, u }
    }
}

impl Residual for LineContact {
    fn name(&self) -> &str {
        TangentToLine::LABEL
    }
    fn dim(&self) -> usize {
        2
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        let mut sizes = curve_block_sizes(&self.basis, self.u);
        sizes.extend([2, 2]);
        Some(sizes)
    }
    fn depends_on(&self, x: &[&[f64]], blocks: &mut [bool]) {
        curve_support(&self.basis, self.u, x, blocks);
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (c, c1, k) = curve_at(&self.basis, self.u, x);
        let (a, b) = (x[k], x[k + 1]);
        let d = sub(b, a);
        let len = dot(d, d).sqrt();
        out[0] = cross(sub(&c, a), d) / len;
        out[1] = cross(c1, d) / len;
    }
}

impl ConstraintKind for TangentToLine {
    const TAG: &'static str = "tangent_to_line";
    const LABEL: &'static str = "tangent to line";

    fn entities(&self, out: &mut Entities) {
        out.add(self.curve);
        out.add(self.line);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        distinct(self.curve, self.line)?;
        cx.line(self.line)?;
        let (basis, mut slots, param) = cx.curve_contact(self.curve, self.u)?;
        slots.extend([Slot::Point(self.line, 0), Slot::Point(self.line, 1)]);
        cx.residual(LineContact::new(basis, param), slots, Some(Arc::new(*self)));
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![glyph::tangent_arrow(at, self.curve, self.u.value())?])
    }

    fn set_free_parameter(&mut self, k: usize, value: f64) {
        if k == 0 {
            self.u.set_free(value);
        }
    }

    fn contact(&self) -> Option<ContactSpec> {
        Some(ContactSpec {
            curve: self.curve,
            u: self.u,
            target: ContactTarget::Line {
                line: self.line,
                side: self.side,
                sense: self.sense,
            },
        })
    }
}

impl SolvedCheck for TangentToLine {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let u = state.parameter(self.u, &mut 0);
        let curve = state.entity(self.curve)?;
        let Entity::Line([a, b]) = state.entity(self.line)? else {
            return Err(Error::UnknownEntity { entity: self.line });
        };
        let d = [b.x - a.x, b.y - a.y];
        let len = d[0].hypot(d[1]);
        let (_, t) = point_tangent(curve, self.curve, u)?;
        state.not_cusp(t[0].hypot(t[1]), state.floor(self.curve)?)?;
        state.sense(self.sense.sign() * (t[0] * d[0] + t[1] * d[1]))?;
        let sign = match self.side {
            LineSide::Left => 1.0,
            LineSide::Right => -1.0,
        };
        let a = *a;
        state.no_crossing(self.curve, u, |q| {
            sign * (d[0] * (q[1] - a.y) - d[1] * (q[0] - a.x)) / len
        })
    }

    fn contact(&self) -> Option<ContactSpec> {
        ConstraintKind::contact(self)
    }
}
