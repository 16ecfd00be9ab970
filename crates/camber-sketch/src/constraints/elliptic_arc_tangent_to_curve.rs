//! `elliptic_arc_tangent_to_curve`: at one end P of an elliptic arc, the arc's direction of
//! travel runs along a free-form curve's tangent at one end of the curve's domain, the sense
//! kept. With the arc's counter-clockwise tangent there,
//! t = −(a/b)·y′·u + (b/a)·x′·v (as for `elliptic_arc_tangent_to_line`; computed as the
//! positive multiple −(w × d)·w + (b²(d·w)/a²)·rot₉₀(w), w = V − C, d = P − C), and the curve's
//! tangent C′ at its end, one row
//!
//! g = atan2(σ·(t × C′), σ·(t·C′)) = 0 (radians; σ = +1 for `agree`, −1 for `oppose`),
//!
//! whose gradient vanishes only with a tangent (as [`G1JoinFree`](super::G1JoinFree)'s), and
//! σ·t·C′ > 0 checked after every solve. The row says nothing of where the ends lie: with
//! `coincident` (the arc's end at the curve's end) it makes a G1 join. File form:
//! `{"kind": "elliptic_arc_tangent_to_curve", "arc": 1, "end": "end", "curve": 2,
//! "curve_end": "start", "sense": "agree"}`.

use std::sync::Arc;

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::shared::arc_ends::{verify_curve_end_sense, ArcEnd};
use super::compiler::distinct;
use super::shared::ellipses::{end_block, travel};
use super::glyph::{self, Glyph};
use super::shared::angles::angle_between;
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::curve_eval::CurveBasis;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::Sense;
use crate::residuals::curve::{cross, dot, sub};

/// The elliptic arc's travel at one end runs along a curve's tangent at one of its ends, with
/// a sense (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EllipticArcTangentToCurve {
    /// The elliptic arc.
    pub arc: EntityId,
    /// Which end of the arc.
    pub end: ArcEnd,
    /// The curve (Bézier, B-spline, NURBS, Hermite, composite or line).
    pub curve: EntityId,
    /// Which end of the curve's domain.
    pub curve_end: ArcEnd,
    /// Whether the arc's counter-clockwise travel agrees with the curve's C′ there or opposes it.
    #[serde(default)]
    pub sense: Sense,
}

/// g of the module documentation over the blocks [C, V, b, P] and the curve's control points.
#[derive(Debug, Clone, PartialEq)]
pub struct EllipseCurveTangency {
    basis: CurveBasis,
    u: f64,
    sense: f64,
}

impl EllipseCurveTangency {
    /// The row at the curve parameter `u` of the curve of `basis`, for the sense ±1.
    pub fn new(basis: CurveBasis, u: f64, sense: f64) -> Self {
        Self { basis, u, sense }
    }
}

impl Residual for EllipseCurveTangency {
    fn name(&self) -> &str {
        EllipticArcTangentToCurve::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        let mut sizes = vec![2, 2, 1, 2];
        sizes.extend(std::iter::repeat_n(2, self.basis.count()));
        Some(sizes)
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (w, d) = (sub(x[1], x[0]), sub(x[3], x[0]));
        let b = x[2][0];
        let scale = b * b * dot(d, w) / dot(w, w);
        let across = cross(w, d);
        let t = [-across * w[0] - scale * w[1], -across * w[1] + scale * w[0]];
        let c1 = self.basis.tangent(&x[4..], cst(self.u));
        out[0] = angle_between(t, c1, self.sense);
    }
}

impl ConstraintKind for EllipticArcTangentToCurve {
    const TAG: &'static str = "elliptic_arc_tangent_to_curve";
    const LABEL: &'static str = "elliptic arc tangent to curve";

    fn entities(&self, out: &mut Entities) {
        out.add(self.arc);
        out.add(self.curve);
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
        distinct(self.arc, self.curve)?;
        let (basis, curve_slots, u) =
            cx.curve_end_contact(self.curve, self.curve_end == ArcEnd::End)?;
        let mut slots = vec![
            Slot::Point(self.arc, 0),
            Slot::Point(self.arc, 1),
            Slot::Radius(self.arc),
            Slot::Point(self.arc, end_block(self.end)),
        ];
        slots.extend(curve_slots);
        cx.residual(
            EllipseCurveTangency::new(basis, u, self.sense.sign()),
            slots,
            Some(Arc::new(*self)),
        );
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
        let u = glyph::domain_end(at, self.curve, self.curve_end == ArcEnd::End)?;
        Ok(vec![
            Glyph::Arrow(p, travel(&points[0], &points[1], *semi_axis_b, &p)),
            glyph::tangent_arrow(at, self.curve, u)?,
        ])
    }
}

impl SolvedCheck for EllipticArcTangentToCurve {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let Entity::EllipticArc {
            points,
            semi_axis_b,
        } = state.entity(self.arc)?
        else {
            return Err(Error::UnknownEntity { entity: self.arc });
        };
        let p = points[end_block(self.end)];
        let t = travel(&points[0], &points[1], *semi_axis_b, &p);
        verify_curve_end_sense(state, t, self.curve, self.curve_end, self.sense)
    }
}
