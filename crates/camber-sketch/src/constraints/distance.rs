//! `distance`: two points are D > 0 apart, (|a − b|² − D²)/(2D) = 0 (one row in length units;
//! smooth at the solution, unlike |a − b| − D at a = b). File form:
//! `{"kind": "distance", "a": {"point": 1}, "b": {"point": 2}, "distance": 3}`.

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::positive;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::Slot;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::PointRef;
use crate::ground::lookup::EntityLookup;
use crate::residuals::curve::{dot, sub};

/// Two points are `distance` (> 0) apart (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Distance {
    /// The first point (a single block).
    pub a: PointRef,
    /// The second point (a single block).
    pub b: PointRef,
    /// The distance.
    pub distance: f64,
}

/// (|a − b|² − D²)/(2D) = 0: two points D apart (blocks: a, b; D > 0).
#[derive(Debug, Clone, PartialEq)]
pub struct PointDistance {
    distance: f64,
}

impl PointDistance {
    /// The distance residual for D = `distance` (> 0, checked by the constraint).
    pub fn new(distance: f64) -> Self {
        Self { distance }
    }
}

impl Residual for PointDistance {
    fn name(&self) -> &str {
        Distance::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2])
    }
    /// Two points, checked without building the list.
    fn accepts_block_sizes(&self, sizes: &[usize]) -> bool {
        sizes == [2, 2]
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let v = sub(x[0], x[1]);
        let d = cst::<T>(self.distance);
        out[0] = (dot(v, v) - d * d) / (cst::<T>(2.0) * d);
    }
    /// ∂g/∂a = v/d and ∂g/∂b = −v/d with v = a − b, by hand.
    fn structured_jacobian(
        &self,
        x: &[&[f64]],
        active: &[bool],
        values: &mut [f64],
        jac: &mut [f64],
    ) -> bool {
        let ([a, b], [on_a, on_b]) = (x, active) else {
            return false;
        };
        if a.len() != 2 || b.len() != 2 || jac.len() != 4 || values.len() != 1 {
            return false;
        }
        let d = self.distance;
        let v = sub(a, b);
        values[0] = (dot(v, v) - d * d) / (2.0 * d);
        let (sa, sb) = (f64::from(u8::from(*on_a)), f64::from(u8::from(*on_b)));
        jac.copy_from_slice(&[sa * v[0] / d, sa * v[1] / d, -sb * v[0] / d, -sb * v[1] / d]);
        true
    }
    /// g is quadratic: ∇²g = [[I, −I], [−I, I]]/d over the moving blocks, by hand.
    fn structured_hessian(
        &self,
        x: &[&[f64]],
        weights: &[f64],
        active: &[bool],
        out: &mut [f64],
    ) -> bool {
        let ([a, b], [w], [on_a, on_b]) = (x, weights, active) else {
            return false;
        };
        if a.len() != 2 || b.len() != 2 || out.len() != 16 {
            return false;
        }
        let sign = [1.0, 1.0, -1.0, -1.0];
        let on = [*on_a, *on_a, *on_b, *on_b];
        for (i, row) in out.chunks_exact_mut(4).enumerate() {
            for (j, slot) in row.iter_mut().enumerate() {
                *slot = if i % 2 == j % 2 && on[i] && on[j] {
                    w * sign[i] * sign[j] / self.distance
                } else {
                    0.0
                };
            }
        }
        true
    }
}

impl ConstraintKind for Distance {
    const TAG: &'static str = "distance";
    const LABEL: &'static str = "distance";

    fn value(&self) -> Option<f64> {
        Some(self.distance)
    }

    fn value_field(&self) -> Option<&'static str> {
        Some("distance")
    }

    fn set_value(&mut self, value: f64) -> bool {
        self.distance = value;
        true
    }

    fn entities(&self, out: &mut Entities) {
        out.add_point(self.a);
        out.add_point(self.b);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let d = positive("distance", self.distance)?;
        let (ea, ja) = cx.single_block(self.a)?;
        let (eb, jb) = cx.single_block(self.b)?;
        if (ea, ja) == (eb, jb) {
            return Err(Error::SameEntity { entity: ea });
        }
        let slots = vec![Slot::Point(ea, ja), Slot::Point(eb, jb)];
        cx.residual(PointDistance::new(d), slots, None);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![
            Glyph::Ring(glyph::point(at, self.a)?),
            Glyph::Ring(glyph::point(at, self.b)?),
        ])
    }
}
