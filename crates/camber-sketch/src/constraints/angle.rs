//! `angle`: the angle φ from one line entity's direction d₁ = B₁ − A₁ to another's
//! d₂ = B₂ − A₂ is θ (counter-clockwise positive):
//!
//! (cross(d₁, d₂)·cos θ − (d₁·d₂)·sin θ)/(|d₁||d₂|) = sin(φ − θ) = 0 (one row),
//!
//! which also vanishes at θ + π; after every solve cos(φ − θ) > 0 is checked so the sense is
//! the one asked. [`Parallel`](super::Parallel) and [`Perpendicular`](super::Perpendicular) are
//! the same row at θ = 0 and θ = π/2 without the sense check. File form:
//! `{"kind": "angle", "first": 1, "second": 2, "angle": 0.5236}`.

use std::sync::Arc;

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::{distinct, finite};
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::component::check::{SolvedCheck, SolvedState};
use crate::component::piece::Slot;
use crate::entity::Entity;
use crate::errors::{Error, Result};
use crate::ids::EntityId;
use crate::lookup::EntityLookup;
use crate::residuals::curve::{cross, dot, sub};

/// The angle from the first line's direction to the second's is `angle` radians
/// (counter-clockwise positive; one row plus a check of the sense).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Angle {
    /// The first line.
    pub first: EntityId,
    /// The second line.
    pub second: EntityId,
    /// The angle θ in radians.
    pub angle: f64,
}

/// sin(φ − θ) = 0 for the angle φ from d₁ = B₁ − A₁ to d₂ = B₂ − A₂ (blocks A₁, B₁, A₂, B₂).
#[derive(Debug, Clone, PartialEq)]
pub struct LineAngle {
    name: &'static str,
    cos: f64,
    sin: f64,
}

impl LineAngle {
    /// The residual for the angle θ (radians), named `name` in reports.
    pub fn new(name: &'static str, angle: f64) -> Self {
        Self {
            name,
            cos: angle.cos(),
            sin: angle.sin(),
        }
    }
}

impl Residual for LineAngle {
    fn name(&self) -> &str {
        self.name
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2; 4])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (d1, d2) = (sub(x[1], x[0]), sub(x[3], x[2]));
        let scale = (dot(d1, d1) * dot(d2, d2)).sqrt();
        out[0] = (cross(d1, d2) * cst::<T>(self.cos) - dot(d1, d2) * cst::<T>(self.sin)) / scale;
    }
}

/// Compiles the angle row between two distinct lines, with an optional check of the solved
/// state.
pub(crate) fn line_angle(
    cx: &mut Compiler<'_>,
    name: &'static str,
    (first, second): (EntityId, EntityId),
    angle: f64,
    check: Option<Arc<dyn SolvedCheck>>,
) -> Result<()> {
    distinct(first, second)?;
    cx.line(first)?;
    cx.line(second)?;
    let slots = vec![
        Slot::Point(first, 0),
        Slot::Point(first, 1),
        Slot::Point(second, 0),
        Slot::Point(second, 1),
    ];
    cx.residual(LineAngle::new(name, angle), slots, check);
    Ok(())
}

impl ConstraintKind for Angle {
    const TAG: &'static str = "angle";
    const LABEL: &'static str = "angle";

    fn entities(&self, out: &mut Entities) {
        out.add(self.first);
        out.add(self.second);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let angle = finite("angle", self.angle)?;
        line_angle(
            cx,
            Self::LABEL,
            (self.first, self.second),
            angle,
            Some(Arc::new(*self)),
        )
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![
            glyph::line_arrow(at, self.first)?,
            glyph::line_arrow(at, self.second)?,
        ])
    }
}

impl SolvedCheck for Angle {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let (Entity::Line([a1, b1]), Entity::Line([a2, b2])) =
            (state.entity(self.first)?, state.entity(self.second)?)
        else {
            return Err(Error::UnknownEntity { entity: self.first });
        };
        let (d1, d2) = (b1 - a1, b2 - a2);
        let (dot, crs) = (d1.dot(&d2), d1.x * d2.y - d1.y * d2.x);
        state.sense(dot * self.angle.cos() + crs * self.angle.sin())
    }
}
