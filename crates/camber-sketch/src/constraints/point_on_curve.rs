//! `point_on_curve`: a point lies on a curve, C(u) − Q = 0 (two rows), at a fixed parameter or
//! at a free one (an unknown bounded to the curve's domain, stored back after a solve). File
//! form: `{"kind": "point_on_curve", "point": {"point": 4}, "curve": 0, "u": {"free": 0.5}}`.

use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::Slot;
use crate::ground::curve_eval::CurveBasis;
use crate::ground::errors::Result;
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;
use crate::residuals::curve::{curve_at, curve_block_sizes, curve_support, Param};
use crate::ground::vocabulary::Contact;

/// The point lies on the curve: C(u) = P (two rows, nonlinear when u is free).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointOnCurve {
    /// The point (a single block: a point, control point or clamped curve end).
    pub point: PointRef,
    /// The curve.
    pub curve: EntityId,
    /// The parameter.
    pub u: Contact,
}

/// C(u) = Q: the point block Q (after the curve's blocks and u) lies on the curve.
///
/// ```
/// use camber_sketch::constraints::point_on_curve::OnCurve;
/// use camber_sketch::residuals::Param;
/// use camber_sketch::{curve_eval::CurveBasis, Entity};
/// use camber_solve::Residual;
/// use nalgebra::Point2;
/// let line = Entity::Line([Point2::new(0.0, 0.0), Point2::new(2.0, 0.0)]);
/// let r = OnCurve::new(CurveBasis::of(&line).ok_or("curve")?, Param::Block);
/// let mut g = [0.0; 2];
/// r.eval::<f64>(&[&[0.0, 0.0][..], &[2.0, 0.0][..], &[0.5][..], &[1.0, 0.0][..]], &mut g);
/// assert!(g[0].abs() < 1e-15 && g[1].abs() < 1e-15);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct OnCurve {
    basis: CurveBasis,
    u: Param,
}

impl OnCurve {
    /// The residual C(u) − Q.
    pub fn new(basis: CurveBasis, u: Param) -> Self {
        Self { basis, u }
    }
}

impl Residual for OnCurve {
    fn name(&self) -> &str {
        PointOnCurve::LABEL
    }
    fn dim(&self) -> usize {
        2
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        let mut sizes = curve_block_sizes(&self.basis, self.u);
        sizes.push(2);
        Some(sizes)
    }
    fn depends_on(&self, x: &[&[f64]], blocks: &mut [bool]) {
        curve_support(&self.basis, self.u, x, blocks);
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (c, _, k) = curve_at(&self.basis, self.u, x);
        let q = x[k];
        out[0] = c[0] - q[0];
        out[1] = c[1] - q[1];
    }
}

impl ConstraintKind for PointOnCurve {
    const TAG: &'static str = "point_on_curve";
    const LABEL: &'static str = "point on curve";

    fn entities(&self, out: &mut Entities) {
        out.add_point(self.point);
        out.add(self.curve);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let (basis, mut slots, param) = cx.curve_contact(self.curve, self.u)?;
        let (e, j) = cx.single_block(self.point)?;
        distinct(e, self.curve)?;
        slots.push(Slot::Point(e, j));
        cx.residual(OnCurve::new(basis, param), slots, None);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![Glyph::Ring(glyph::point(at, self.point)?)])
    }

    fn set_free_parameter(&mut self, k: usize, value: f64) {
        if k == 0 {
            self.u.set_free(value);
        }
    }
}
