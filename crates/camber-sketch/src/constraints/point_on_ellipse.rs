//! `point_on_ellipse`: a point lies on an ellipse or an elliptic arc. One row in length units
//! on the point and the ellipse's blocks [C, V, b] ([`crate::residuals::ellipse`]):
//!
//! g = ((x′/a)² + (y′/b)² − 1)·ab/(a + b) = 0,
//!
//! and for an elliptic arc, after every solve, the point's parametric angle must lie within
//! the arc's sweep (to the solve's tolerance over the smaller semi-axis), else the solve fails
//! with [`Error::PointOffArc`] and the sketch is left as it was. File form:
//! `{"kind": "point_on_ellipse", "point": {"point": 3}, "ellipse": 1}`.

use std::sync::Arc;

use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::shared::ellipses::ellipse_kind;
use super::glyph::{self, Glyph};
use super::shared::arc_span::outside_elliptic_sweep;
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::entity::combine;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;
pub use crate::residuals::ellipse::OnEllipse;

/// The point lies on the ellipse or elliptic arc (one row; for an arc, the sweep checked
/// after the solve).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointOnEllipse {
    /// The point (a single block, of another entity).
    pub point: PointRef,
    /// The ellipse or elliptic arc entity.
    pub ellipse: EntityId,
}

impl ConstraintKind for PointOnEllipse {
    const TAG: &'static str = "point_on_ellipse";
    const LABEL: &'static str = "point on ellipse";

    fn entities(&self, out: &mut Entities) {
        out.add_point(self.point);
        out.add(self.ellipse);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let is_arc = ellipse_kind(cx.entity(self.ellipse)?, self.ellipse)?;
        let (e, j) = cx.single_block(self.point)?;
        distinct(e, self.ellipse)?;
        let slots = vec![
            Slot::Point(self.ellipse, 0),
            Slot::Point(self.ellipse, 1),
            Slot::Radius(self.ellipse),
            Slot::Point(e, j),
        ];
        let check: Option<Arc<dyn SolvedCheck>> = if is_arc {
            Some(Arc::new(*self))
        } else {
            None
        };
        cx.residual(OnEllipse, slots, check);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![Glyph::Ring(glyph::point(at, self.point)?)])
    }
}

impl SolvedCheck for PointOnEllipse {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let Some(arc) = state.entity(self.ellipse)?.as_elliptic_arc() else {
            return Err(Error::WrongEntityKind {
                entity: self.ellipse,
                expected: "elliptic arc",
                found: state.entity(self.ellipse)?.kind_name(),
            });
        };
        let e = state.entity(self.point.entity())?;
        let v = combine(e.points(), &e.resolve(self.point)?);
        let angle = arc.ellipse().angle_of(&nalgebra::Point2::new(v[0], v[1]));
        match outside_elliptic_sweep(&arc, angle, state.penetration) {
            None => Ok(()),
            Some(outside) => Err(Error::PointOffArc {
                constraint: state.owner,
                outside,
            }),
        }
    }
}
