//! `arc_angle`: the sweep of a circular or an elliptic arc equals θ ∈ (0, 2π) radians:
//!
//! φ − θ = 0 (one row, radians),
//!
//! with φ the counter-clockwise angle from S − C to E − C for a circular arc, and for an
//! elliptic arc the sweep of its parametric angle, from θ_S to θ_E where
//! (cos θ, sin θ) = (x′/a, y′/b) in the ellipse's frame (the angle the elliptic arc is defined
//! by; it equals the angle at the centre on a circle, and on an ellipse at the quarter points
//! between the vertices). Both are read from the arc's blocks, so the row holds whatever else
//! moves: a drag of an end with the centre fixed turns the other end with it. A dimension
//! (`Sketch::set_value`). File form: `{"kind": "arc_angle", "arc": 1, "angle": 1.5708}`.

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::glyph::{self, Glyph};
use super::shared::sweeps::SweptArc;
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;

/// The arc's sweep is `angle` radians (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArcAngle {
    /// The circular or elliptic arc.
    pub arc: EntityId,
    /// The sweep θ in radians, 0 < θ < 2π.
    pub angle: f64,
}

/// φ − θ over the arc's blocks ([C, S, E] for a circular arc, [C, V, b, S, E] for an
/// elliptic one).
///
/// ```
/// use camber_sketch::constraints::arc_angle::SweepValue;
/// use camber_solve::Residual;
/// // The arc about (0, 0) from (1, 0) to (−1, 1) sweeps 135°.
/// let mut g = [f64::NAN];
/// SweepValue::circular(0.75 * std::f64::consts::PI).eval(&[&[0.0, 0.0], &[1.0, 0.0], &[-1.0, 1.0]], &mut g);
/// assert!(g[0].abs() < 1e-15);
/// // From (0, −1) to (1, 0) it sweeps a quarter turn, counter-clockwise.
/// SweepValue::circular(0.5 * std::f64::consts::PI).eval(&[&[0.0, 0.0], &[0.0, -1.0], &[1.0, 0.0]], &mut g);
/// assert!(g[0].abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepValue {
    arc: SweptArc,
    angle: f64,
}

impl SweepValue {
    /// The row of a circular arc sweeping `angle` radians.
    pub fn circular(angle: f64) -> Self {
        Self {
            arc: SweptArc::Circular,
            angle,
        }
    }

    /// The row of an elliptic arc whose parametric angle sweeps `angle` radians.
    pub fn elliptic(angle: f64) -> Self {
        Self {
            arc: SweptArc::Elliptic,
            angle,
        }
    }
}

impl Residual for SweepValue {
    fn name(&self) -> &str {
        ArcAngle::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(self.arc.block_sizes())
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = self.arc.sweep(x) - cst::<T>(self.angle);
    }
}

impl ConstraintKind for ArcAngle {
    const TAG: &'static str = "arc_angle";
    const LABEL: &'static str = "arc angle";

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
        out.add(self.arc);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let turn = std::f64::consts::TAU;
        if !(self.angle > 0.0 && self.angle < turn) {
            return Err(Error::OutOfRange {
                what: "arc angle (radians)",
                value: self.angle,
                min: 0.0,
                max: turn,
            });
        }
        let arc = SweptArc::of(cx, self.arc)?;
        let row = SweepValue {
            arc,
            angle: self.angle,
        };
        cx.residual(row, arc.slots(self.arc), None);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let e = at.lookup(self.arc)?;
        Ok(glyph::arc_midpoint(e)
            .map(|mid| vec![Glyph::Mark(mid, "∠")])
            .unwrap_or_default())
    }
}
