//! `semi_axis`: one semi-axis of an ellipse or elliptic arc equals a length L > 0. For the
//! a-axis, |V − C| − L = 0 (one row on the centre and vertex blocks); for the b-axis,
//! b − L = 0 (one affine row on the scalar block b). File form:
//! `{"kind": "semi_axis", "ellipse": 1, "axis": "a", "length": 2.5}`.

use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::positive;
use super::glyph::Glyph;
use super::shared::ellipses::ellipse_kind;
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::Slot;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::residuals::affine::RadiusValue;
use crate::residuals::curve::{dot, sub};

/// Which semi-axis: `"a"` (from the centre to the vertex block) or `"b"` (the scalar).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Axis {
    /// The a-axis, |V − C|.
    A,
    /// The b-axis, the scalar block b.
    B,
}

/// The semi-axis equals the length (> 0; one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SemiAxis {
    /// The ellipse or elliptic arc entity.
    pub ellipse: EntityId,
    /// Which semi-axis.
    pub axis: Axis,
    /// Its length.
    pub length: f64,
}

/// |V − C| − L = 0 over the blocks [C, V] (one row, length units).
///
/// ```
/// use camber_sketch::constraints::semi_axis::SemiAxisA;
/// use camber_solve::Residual;
/// let mut g = [0.0_f64];
/// SemiAxisA(2.0).eval(&[&[1.0, 1.0][..], &[4.0, 5.0][..]], &mut g);
/// assert!((g[0] - 3.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SemiAxisA(pub f64);

impl Residual for SemiAxisA {
    fn name(&self) -> &str {
        SemiAxis::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let w = sub(x[1], x[0]);
        out[0] = dot(w, w).sqrt() - nalgebra::convert::<f64, T>(self.0);
    }
}

impl ConstraintKind for SemiAxis {
    const TAG: &'static str = "semi_axis";
    const LABEL: &'static str = "semi-axis";

    fn value(&self) -> Option<f64> {
        Some(self.length)
    }

    fn value_field(&self) -> Option<&'static str> {
        Some("length")
    }

    fn set_value(&mut self, value: f64) -> bool {
        self.length = value;
        true
    }

    fn entities(&self, out: &mut Entities) {
        out.add(self.ellipse);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        ellipse_kind(cx.entity(self.ellipse)?, self.ellipse)?;
        let length = positive("semi-axis", self.length)?;
        match self.axis {
            Axis::A => cx.residual(
                SemiAxisA(length),
                vec![Slot::Point(self.ellipse, 0), Slot::Point(self.ellipse, 1)],
                None,
            ),
            Axis::B => cx.residual(
                RadiusValue::new(length),
                vec![Slot::Radius(self.ellipse)],
                None,
            ),
        }
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        // "a" at the vertex, "b" at the end of the b-axis.
        let e = at.lookup(self.ellipse)?;
        let Some(ellipse) = e.as_ellipse() else {
            return Err(Error::WrongEntityKind {
                entity: self.ellipse,
                expected: "ellipse or elliptic arc",
                found: e.kind_name(),
            });
        };
        Ok(vec![match self.axis {
            Axis::A => Glyph::Mark(ellipse.point_at_angle(0.0), "a"),
            Axis::B => Glyph::Mark(ellipse.point_at_angle(std::f64::consts::FRAC_PI_2), "b"),
        }])
    }
}
