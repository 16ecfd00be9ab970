//! `arc_tangent_to_curve`: at one end P of a circular arc (centre C), the arc's direction of
//! travel runs along a free-form curve's tangent at one end of the curve's domain, the sense
//! kept. The arc's counter-clockwise travel there is t = rot₉₀(P − C) = (−(P − C)_y,
//! (P − C)_x); with the curve's tangent C′ at its end, one row
//!
//! g = atan2(σ·(t × C′), σ·(t·C′)) = 0 (radians; σ = +1 for `agree`, −1 for `oppose`),
//!
//! whose gradient vanishes only with a tangent (as [`G1JoinFree`](super::G1JoinFree)'s), and
//! σ·t·C′ > 0 checked after every solve. The row says nothing of where the ends lie: with
//! `coincident` (the arc's end at the curve's end) it makes a G1 join — the circular leading
//! or trailing edge of a blade section between its two sides. File form:
//! `{"kind": "arc_tangent_to_curve", "arc": 1, "end": "end", "curve": 2, "curve_end":
//! "start", "sense": "agree"}`.

use std::sync::Arc;

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::shared::angles::angle_between;
use super::shared::arc_ends::{verify_curve_end_sense, ArcEnd};
use super::shared::radii::Round;
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::curve_eval::CurveBasis;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::Sense;
use crate::residuals::curve::sub;

/// The circular arc's travel at one end runs along a curve's tangent at one of its ends, with
/// a sense (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArcTangentToCurve {
    /// The circular arc.
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

/// g of the module documentation over the blocks [C, P] and the curve's control points.
///
/// ```
/// use camber_sketch::constraints::arc_tangent_to_curve::ArcCurveTangency;
/// use camber_sketch::curve_eval::CurveBasis;
/// use camber_sketch::Entity;
/// use camber_geom::BezierCurve2;
/// use camber_solve::Residual;
/// use nalgebra::Point2;
/// // Centre (0, 0), end (1, 0): the counter-clockwise travel there is +y, along the straight
/// // Bézier from (1, 0) to (1, 2) at its start.
/// let line = BezierCurve2::try_new(vec![Point2::new(1.0, 0.0), Point2::new(1.0, 2.0)])?;
/// let basis = CurveBasis::of(&Entity::Bezier(line)).expect("a Bézier has a basis");
/// let g = ArcCurveTangency::new(basis, 0.0, 1.0);
/// let mut out = [f64::NAN];
/// let blocks: [&[f64]; 4] = [&[0.0, 0.0], &[1.0, 0.0], &[1.0, 0.0], &[1.0, 2.0]];
/// g.eval(&blocks, &mut out);
/// assert!(out[0].abs() < 1e-15);
/// # Ok::<(), camber_geom::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ArcCurveTangency {
    basis: CurveBasis,
    u: f64,
    sense: f64,
}

impl ArcCurveTangency {
    /// The row at the curve parameter `u` of the curve of `basis`, for the sense ±1.
    pub fn new(basis: CurveBasis, u: f64, sense: f64) -> Self {
        Self { basis, u, sense }
    }
}

impl Residual for ArcCurveTangency {
    fn name(&self) -> &str {
        ArcTangentToCurve::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        let mut sizes = vec![2, 2];
        sizes.extend(std::iter::repeat_n(2, self.basis.count()));
        Some(sizes)
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let r = sub(x[1], x[0]);
        let t = [-r[1], r[0]];
        let c1 = self.basis.tangent(&x[2..], cst(self.u));
        out[0] = angle_between(t, c1, self.sense);
    }
}

impl ConstraintKind for ArcTangentToCurve {
    const TAG: &'static str = "arc_tangent_to_curve";
    const LABEL: &'static str = "arc tangent to curve";

    fn entities(&self, out: &mut Entities) {
        out.add(self.arc);
        out.add(self.curve);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        Round::arc(cx, self.arc)?;
        distinct(self.arc, self.curve)?;
        let (basis, curve_slots, u) =
            cx.curve_end_contact(self.curve, self.curve_end == ArcEnd::End)?;
        let mut slots = vec![Slot::Point(self.arc, 0), Slot::Point(self.arc, self.end.block())];
        slots.extend(curve_slots);
        cx.residual(
            ArcCurveTangency::new(basis, u, self.sense.sign()),
            slots,
            Some(Arc::new(*self)),
        );
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let (p, t) = travel(at.lookup(self.arc)?, self.arc, self.end)?;
        let u = glyph::domain_end(at, self.curve, self.curve_end == ArcEnd::End)?;
        Ok(vec![
            Glyph::Arrow(p, t),
            glyph::tangent_arrow(at, self.curve, u)?,
        ])
    }
}

/// The arc's end point and its counter-clockwise travel there, rot₉₀(P − C).
fn travel(
    e: &Entity,
    arc: EntityId,
    end: ArcEnd,
) -> Result<(nalgebra::Point2<f64>, Vector2<f64>)> {
    let Entity::Arc(blocks) = e else {
        return Err(Error::WrongEntityKind {
            entity: arc,
            expected: "arc",
            found: e.kind_name(),
        });
    };
    let p = blocks[end.block()];
    let r = p - blocks[0];
    Ok((p, Vector2::new(-r.y, r.x)))
}

impl SolvedCheck for ArcTangentToCurve {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let (_, t) = travel(state.entity(self.arc)?, self.arc, self.end)?;
        verify_curve_end_sense(state, t, self.curve, self.curve_end, self.sense)
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use camber_geom::{BSplineCurve2, CircularArc, KnotVector};
    use nalgebra::Point2;

    use super::*;
    use crate::constraints::piece::Piece;
    use crate::Sketch;

    /// At a clamped end C′ = p/(u₁ − u₀)·(P₁ − P₀): the row reads the arc's centre and end and
    /// the curve's first two control points, never the other six, so its Hessian stays 8 × 8.
    #[test]
    fn the_row_reads_only_the_control_points_of_the_curve_end() {
        let mut s = Sketch::new();
        let arc = s
            .add_arc(&CircularArc::try_new(Point2::new(0.0, 0.0), 1.0, 0.0, 1.0).unwrap())
            .unwrap();
        let points: Vec<Point2<f64>> = (0..8)
            .map(|k| Point2::new(1.0 + 0.5 * f64::from(k), 0.2 * f64::from(k % 3)))
            .collect();
        let knots = KnotVector::clamped_uniform(3, points.len()).unwrap();
        let curve = s
            .add_bspline(BSplineCurve2::try_new(3, knots, points).unwrap())
            .unwrap();
        let c = ArcTangentToCurve {
            arc,
            end: ArcEnd::Start,
            curve,
            curve_end: ArcEnd::Start,
            sense: Sense::Agree,
        };
        let pieces = crate::Constraint::from(c).compile(&s).unwrap();
        let [Piece::General { slots, .. }] = pieces.as_slice() else {
            panic!("one general piece expected, found {pieces:?}");
        };
        assert_eq!(
            slots.as_slice(),
            &[
                Slot::Point(arc, 0),
                Slot::Point(arc, 1),
                Slot::Point(curve, 0),
                Slot::Point(curve, 1),
            ]
        );
    }
}
