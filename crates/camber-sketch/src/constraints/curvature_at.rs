//! `curvature_at`: a curve's signed curvature at a given parameter equals k:
//!
//! κ(u) − k = 0 with κ = cross(C′, C″)/|C′|³ (one row, in 1/length; positive where the curve
//! turns left). u is data, so the row reads only the control points of u's span. File form:
//! `{"kind": "curvature_at", "curve": 0, "u": 0.5, "curvature": -1.2}`.

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::finite;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::Slot;
use crate::ground::curve_eval::CurveBasis;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::residuals::curve::curvature;

/// κ(u) = `curvature` (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CurvatureAt {
    /// The curve.
    pub curve: EntityId,
    /// The parameter, inside the domain.
    pub u: f64,
    /// The signed curvature k (1/length).
    pub curvature: f64,
}

/// κ(u) − k at a fixed parameter (blocks: the control points the basis reads).
#[derive(Debug, Clone, PartialEq)]
pub struct CurvatureValue {
    basis: CurveBasis,
    u: f64,
    curvature: f64,
}

impl CurvatureValue {
    /// The residual for a basis fixed at u up to order 2 ([`CurveBasis::at`]).
    pub fn new(basis: CurveBasis, u: f64, curvature: f64) -> Self {
        Self {
            basis,
            u,
            curvature,
        }
    }
}

impl Residual for CurvatureValue {
    fn name(&self) -> &str {
        CurvatureAt::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2; self.basis.count()])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = curvature(self.basis.eval2(x, cst(self.u))) - cst::<T>(self.curvature);
    }
}

impl ConstraintKind for CurvatureAt {
    const TAG: &'static str = "curvature_at";
    const LABEL: &'static str = "curvature at";

    fn value(&self) -> Option<f64> {
        Some(self.curvature)
    }

    fn value_field(&self) -> Option<&'static str> {
        Some("curvature")
    }

    fn set_value(&mut self, value: f64) -> bool {
        self.curvature = value;
        true
    }

    fn entities(&self, out: &mut Entities) {
        out.add(self.curve);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let k = finite("curvature", self.curvature)?;
        let u = finite("parameter", self.u)?;
        let (full, _) = cx.curve_basis(self.curve)?;
        let (lo, hi) = full.domain();
        if u < lo || u > hi {
            return Err(Error::ParameterOutsideDomain {
                entity: self.curve,
                value: u,
                min: lo,
                max: hi,
            });
        }
        let (basis, points) = full.at(u, 2);
        let slots = points.iter().map(|j| Slot::Point(self.curve, *j)).collect();
        cx.residual(CurvatureValue::new(basis, u, k), slots, None);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let p = glyph::curve_point(at, self.curve, self.u)?;
        Ok(vec![Glyph::Ring(p), Glyph::Mark(p, "κ")])
    }
}
