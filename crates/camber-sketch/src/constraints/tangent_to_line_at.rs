//! `tangent_to_line_at`: at a given parameter the curve touches a fixed line (through a point
//! along a direction d) and runs along it: cross(C(u) − L₀, d) = 0 and cross(C′(u), d) = 0, two
//! rows affine in the control points, with the sense of C′(u) along d checked after the solve.
//! File form: `{"kind": "tangent_to_line_at", "curve": 0, "u": 1, "point": [0, 0],
//! "direction": [1, 0], "sense": "agree"}`.

use nalgebra::{Point2, Vector2};
use serde::{Deserialize, Serialize};

use super::compiler::check_direction;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::Piece;
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::{xy_point, xy_vector, Sense};

/// C(u) lies on the fixed line through `point` along `direction`, and C′(u) is parallel to it
/// with the given sense (two rows).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TangentToLineAt {
    /// The curve.
    pub curve: EntityId,
    /// The parameter.
    pub u: f64,
    /// A point of the line.
    #[serde(with = "xy_point")]
    pub point: Point2<f64>,
    /// The line direction d.
    #[serde(with = "xy_vector")]
    pub direction: Vector2<f64>,
    /// Along or against d.
    #[serde(default)]
    pub sense: Sense,
}

impl ConstraintKind for TangentToLineAt {
    const TAG: &'static str = "tangent_to_line_at";
    const LABEL: &'static str = "tangent to line at";

    fn entities(&self, out: &mut Entities) {
        out.add(self.curve);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let d = check_direction("line", &self.direction)?;
        crate::ground::entity::check_point("line point", 0, &self.point)?;
        let s = self.sense.sign();
        cx.push(Piece::Line {
            point: cx.curve_terms(self.curve, self.u, 0)?,
            tangent: cx.curve_terms(self.curve, self.u, 1)?,
            origin: [self.point.x, self.point.y],
            direction: d,
            orient: [s * d[0], s * d[1]],
        });
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![Glyph::Arrow(
            glyph::curve_point(at, self.curve, self.u)?,
            self.direction * self.sense.sign(),
        )])
    }
}
