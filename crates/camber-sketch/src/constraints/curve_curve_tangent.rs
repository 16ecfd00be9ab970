//! `curve_curve_tangent`: two curves touch: C₁(u) − C₂(v) = 0 (two rows) and their tangents are
//! parallel there with the sense σ = ±1 asked (same or opposite travel): the angle from C₁′(u)
//! to σ·C₂′(v), atan2(σ·cross(C₁′, C₂′), σ·C₁′·C₂′) = 0 (one row, in radians; see
//! [`Angle`](super::Angle) for why the angle and not its sine), with the parameters fixed or
//! free and the sense σ·C₁′·C₂′ > 0 checked after every solve, along with both tangents'
//! speeds (no cusp). File form: `{"kind": "curve_curve_tangent",
//! "first": 0, "u": {"free": 0.5}, "second": 1, "v": {"free": 0.5}, "sense": "agree"}`.

use std::sync::Arc;

use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{point_tangent, SolvedCheck, SolvedState};
use crate::ground::curve_eval::CurveBasis;
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use super::shared::angles::angle_between;
use crate::residuals::curve::{curve_at, curve_block_sizes, curve_support, Param};
use crate::ground::vocabulary::{Contact, Sense};

/// Two curves touch: C₁(u) = C₂(v) and their tangents there are parallel with the given sense
/// (C₁′·C₂′ > 0 for [`Sense::Agree`]); u and v may be free (three rows).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CurveCurveTangent {
    /// The first curve.
    pub first: EntityId,
    /// Its contact parameter.
    pub u: Contact,
    /// The second curve.
    pub second: EntityId,
    /// Its contact parameter.
    pub v: Contact,
    /// Same or opposite travel directions at the contact.
    #[serde(default)]
    pub sense: Sense,
}

/// C₁(u) − C₂(v) = 0 (two rows) and atan2(σ·cross(C₁′(u), C₂′(v)), σ·C₁′·C₂′) = 0 (one row).
/// Blocks: the first curve's control points, u if free, the second curve's control points, v if
/// free.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveCurveContact {
    first: (CurveBasis, Param),
    second: (CurveBasis, Param),
    /// σ: +1 when the tangents travel the same way, −1 when opposite.
    sense: f64,
}

impl CurveCurveContact {
    /// Contact of `first` at its parameter with `second` at its parameter, the tangents
    /// travelling the same way.
    pub fn new(first: (CurveBasis, Param), second: (CurveBasis, Param)) -> Self {
        Self {
            first,
            second,
            sense: 1.0,
        }
    }

    /// The same contact with the tangents travelling with `sense`.
    pub fn with_sense(self, sense: Sense) -> Self {
        Self {
            sense: sense.sign(),
            ..self
        }
    }
}

impl Residual for CurveCurveContact {
    fn name(&self) -> &str {
        CurveCurveTangent::LABEL
    }
    fn dim(&self) -> usize {
        3
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        let mut sizes = curve_block_sizes(&self.first.0, self.first.1);
        sizes.extend(curve_block_sizes(&self.second.0, self.second.1));
        Some(sizes)
    }
    fn depends_on(&self, x: &[&[f64]], blocks: &mut [bool]) {
        let k = curve_support(&self.first.0, self.first.1, x, blocks);
        if let (Some(rest), Some(flags)) = (x.get(k..), blocks.get_mut(k..)) {
            curve_support(&self.second.0, self.second.1, rest, flags);
        }
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (c1, t1, k) = curve_at(&self.first.0, self.first.1, x);
        let (c2, t2, _) = curve_at(&self.second.0, self.second.1, &x[k..]);
        out[0] = c1[0] - c2[0];
        out[1] = c1[1] - c2[1];
        out[2] = angle_between(t1, t2, self.sense);
    }
}

impl ConstraintKind for CurveCurveTangent {
    const TAG: &'static str = "curve_curve_tangent";
    const LABEL: &'static str = "curve-curve tangent";

    fn entities(&self, out: &mut Entities) {
        out.add(self.first);
        out.add(self.second);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        distinct(self.first, self.second)?;
        let (b1, mut slots, p1) = cx.curve_contact(self.first, self.u)?;
        let (b2, s2, p2) = cx.curve_contact(self.second, self.v)?;
        slots.extend(s2);
        cx.residual(
            CurveCurveContact::new((b1, p1), (b2, p2)).with_sense(self.sense),
            slots,
            Some(Arc::new(*self)),
        );
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![
            glyph::tangent_arrow(at, self.first, self.u.value())?,
            Glyph::Ring(glyph::curve_point(at, self.second, self.v.value())?),
        ])
    }

    fn set_free_parameter(&mut self, k: usize, value: f64) {
        // The k-th free one of (u, v).
        let mut free = [&mut self.u, &mut self.v]
            .into_iter()
            .filter(|c| c.is_free());
        if let Some(c) = free.nth(k) {
            c.set_free(value);
        }
    }
}

impl SolvedCheck for CurveCurveTangent {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let mut next = 0;
        let u = state.parameter(self.u, &mut next);
        let v = state.parameter(self.v, &mut next);
        let (_, t1) = point_tangent(state.entity(self.first)?, self.first, u)?;
        let (_, t2) = point_tangent(state.entity(self.second)?, self.second, v)?;
        let (s1, s2) = (t1[0].hypot(t1[1]), t2[0].hypot(t2[1]));
        let (f1, f2) = (state.floor(self.first)?, state.floor(self.second)?);
        if s1.is_nan() || s2.is_nan() || s1 <= f1 || s2 <= f2 {
            state.not_cusp(s1.min(s2), f64::INFINITY)?;
        }
        state.sense(self.sense.sign() * (t1[0] * t2[0] + t1[1] * t2[1]))
    }
}
