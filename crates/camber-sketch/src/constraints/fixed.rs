//! `fixed`: a whole entity (every point and radius) or one point stays where it is.
//!
//! Fixed unknowns leave the problem (bindings, not rows). A point that is a combination of
//! control points (the end of an unclamped curve) is held by two rows Σ c·P = its current
//! location instead. File form: `{"kind": "fixed", "target": {"entity": 3}}` or
//! `{"target": {"point": {"start": 3}}}`.

use serde::{Deserialize, Serialize};

use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::{ETerms, Piece};
use crate::ground::errors::Result;
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::FixTarget;

/// The target does not move.
///
/// ```
/// use camber_sketch::constraints::Fixed;
/// use camber_sketch::{PointRef, Sketch, Target};
/// use camber_geom::BezierCurve2;
/// use nalgebra::Point2;
/// let mut s = Sketch::new();
/// let c = s.add_bezier(BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(2.0, 0.0)])?)?;
/// s.add_constraint(Fixed::point(PointRef::Start(c)))?;
/// s.add_constraint(camber_sketch::constraints::PointAtParameter { curve: c, u: 1.0, target: Target::At(Point2::new(2.0, 1.0)) })?;
/// s.solve()?;
/// assert_eq!(s.point(PointRef::Start(c))?, Point2::new(0.0, 0.0));
/// # Ok::<(), camber_sketch::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Fixed {
    /// What stays.
    pub target: FixTarget,
}

impl Fixed {
    /// Every point (and the radius) of an entity stays.
    pub fn entity(entity: EntityId) -> Self {
        Self {
            target: FixTarget::Entity(entity),
        }
    }

    /// One point stays.
    pub fn point(point: PointRef) -> Self {
        Self {
            target: FixTarget::Point(point),
        }
    }
}

impl ConstraintKind for Fixed {
    const TAG: &'static str = "fixed";
    const LABEL: &'static str = "fixed";

    fn entities(&self, out: &mut Entities) {
        match self.target {
            FixTarget::Entity(e) => out.add(e),
            FixTarget::Point(p) => out.add_point(p),
        }
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        match self.target {
            FixTarget::Entity(e) => {
                cx.entity(e)?;
                cx.push(Piece::FixEntity(e));
            }
            FixTarget::Point(r) => {
                let t = cx.entity(r.entity())?.resolve(r)?;
                match t.as_slice() {
                    [(j, c)] if (c - 1.0).abs() <= 0.0 => cx.push(Piece::FixPoint(r.entity(), *j)),
                    _ => {
                        let mut terms = ETerms::new();
                        cx.point_terms(r, 1.0, &mut terms)?;
                        let target = cx.current(&terms)?;
                        cx.combination(Self::LABEL, terms, target);
                    }
                }
            }
        }
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(match self.target {
            FixTarget::Point(r) => vec![Glyph::Fixed(glyph::point(at, r)?)],
            FixTarget::Entity(e) => at
                .lookup(e)?
                .points()
                .iter()
                .map(|q| Glyph::Fixed(*q))
                .collect(),
        })
    }
}
