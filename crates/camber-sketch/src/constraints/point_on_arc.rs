//! `point_on_arc`: a point lies on an arc, |P − C| − |S − C| = 0 (one row in length units on
//! the point and the arc's centre and start blocks), and after every solve its direction from
//! the centre must lie within the arc's sweep (to the solve's tolerance over the radius), else
//! the solve fails with [`Error::PointOffArc`] and the sketch is left as it was. File form:
//! `{"kind": "point_on_arc", "point": {"point": 3}, "arc": 1}`.

use std::sync::Arc;

use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::shared::arc_span::outside_sweep;
use super::shared::radii::{radius_of, Round};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::entity::combine;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;
use crate::residuals::curve::{dot, sub};

/// The point lies on the arc (one row, and the sweep checked after the solve).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointOnArc {
    /// The point (a single block, of another entity).
    pub point: PointRef,
    /// The arc entity.
    pub arc: EntityId,
}

/// |P − C| − |S − C| = 0 over the blocks [P, C, S].
///
/// ```
/// use camber_sketch::constraints::point_on_arc::OnArc;
/// use camber_solve::Residual;
/// let mut g = [0.0_f64];
/// // Centre (0, 0), start (0, 2): radius 2; P = (3, 0) is 1 outside.
/// OnArc.eval(&[&[3.0, 0.0][..], &[0.0, 0.0][..], &[0.0, 2.0][..]], &mut g);
/// assert!((g[0] - 1.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OnArc;

impl Residual for OnArc {
    fn name(&self) -> &str {
        PointOnArc::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let v = sub(x[0], x[1]);
        out[0] = dot(v, v).sqrt() - radius_of(true, &x[1..]).0;
    }
}

impl ConstraintKind for PointOnArc {
    const TAG: &'static str = "point_on_arc";
    const LABEL: &'static str = "point on arc";

    fn entities(&self, out: &mut Entities) {
        out.add_point(self.point);
        out.add(self.arc);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let arc = Round::of(cx, self.arc)?;
        if !arc.is_arc() {
            return Err(Error::WrongEntityKind {
                entity: self.arc,
                expected: "arc",
                found: "circle",
            });
        }
        let (e, j) = cx.single_block(self.point)?;
        distinct(e, self.arc)?;
        let slots = vec![
            Slot::Point(e, j),
            Slot::Point(self.arc, 0),
            Slot::Point(self.arc, 1),
        ];
        cx.residual(OnArc, slots, Some(Arc::new(*self)));
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![Glyph::Ring(glyph::point(at, self.point)?)])
    }
}

impl SolvedCheck for PointOnArc {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let Some(arc) = state.entity(self.arc)?.as_arc() else {
            return Err(Error::WrongEntityKind {
                entity: self.arc,
                expected: "arc",
                found: state.entity(self.arc)?.kind_name(),
            });
        };
        let e = state.entity(self.point.entity())?;
        let v = combine(e.points(), &e.resolve(self.point)?);
        let p = nalgebra::Point2::new(v[0], v[1]);
        let Some(outside) = outside_sweep(&arc, p - arc.center(), state.penetration) else {
            return Ok(());
        };
        Err(Error::PointOffArc {
            constraint: state.owner,
            outside,
        })
    }
}
