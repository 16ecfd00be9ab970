//! `angle`: the angle φ from one line entity's direction d₁ = B₁ − A₁ to another's
//! d₂ = B₂ − A₂ is θ (counter-clockwise positive). With
//!
//! s = cross(d₁, d₂)·cos θ − (d₁·d₂)·sin θ = |d₁||d₂|·sin(φ − θ) and
//! c = (d₁·d₂)·cos θ + cross(d₁, d₂)·sin θ = |d₁||d₂|·cos(φ − θ),
//!
//! the row is the angle itself, φ − θ = atan2(s, c) ∈ (−π, π] (radians), and after every solve
//! cos(φ − θ) > 0 is checked so the sense is the one asked. [`Parallel`](super::Parallel) and
//! [`Perpendicular`](super::Perpendicular) are the same row at θ = 0 and θ = π/2 for either
//! sense: the angle is folded into [−π/2, π/2] (atan2(s, c) when c ≥ 0, atan2(−s, −c)
//! otherwise), which vanishes at θ and at θ + π.
//!
//! Why the angle and not sin(φ − θ): the sine's gradient vanishes at φ − θ = ±π/2, so two lines
//! drawn at right angles and then asked to be parallel (or a G1 join whose tangents meet at a
//! right angle) gave a row that could not move to first order, which the analysis called a
//! singular configuration. The angle's gradient, (c·∇s − s·∇c)/(s² + c²), vanishes only with a
//! direction. Near the solution both rows agree to first order. File form:
//! `{"kind": "angle", "first": 1, "second": 2, "angle": 0.5236}`.

use std::sync::Arc;

use serde::{Deserialize, Serialize};

use super::compiler::finite;
use super::glyph::{self, Glyph};
use super::shared::angles::line_angle;
pub use super::shared::angles::LineAngle;
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;

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

impl ConstraintKind for Angle {
    const TAG: &'static str = "angle";
    const LABEL: &'static str = "angle";

    fn value(&self) -> Option<f64> {
        Some(self.angle)
    }

    fn value_field(&self) -> Option<&'static str> {
        Some("angle")
    }

    fn set_value(&mut self, value: f64) -> bool {
        self.angle = value;
        true
    }

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
