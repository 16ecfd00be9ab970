//! `equal_radius`: two circles or arcs have the same radius, r₁ − r₂ = 0 (one row). Between
//! two circles it is affine in their radius unknowns; an arc's radius is |S − C| over its
//! centre and start blocks, which makes the row nonlinear. File form:
//! `{"kind": "equal_radius", "first": 1, "second": 2}`.

use camber_solve::{Residual, Scalar};
use nalgebra::Point2;
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::shared::radii::{radius_block_sizes, radius_of, Round};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::Slot;
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;

/// The two circles' (or arcs') radii are equal (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EqualRadius {
    /// The first circle or arc.
    pub first: EntityId,
    /// The second circle or arc.
    pub second: EntityId,
}

/// r₁ − r₂ = 0 (blocks r₁, r₂; affine).
#[derive(Debug, Clone, PartialEq)]
pub struct RadiiEqual;

impl Residual for RadiiEqual {
    fn name(&self) -> &str {
        EqualRadius::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![1, 1])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = x[0][0] - x[1][0];
    }
    fn is_affine(&self) -> bool {
        true
    }
}

/// r₁ − r₂ = 0 where either radius may be an arc's |S − C| (blocks: the first's radius blocks,
/// then the second's: `[r]` for a circle, `[C, S]` for an arc).
///
/// ```
/// use camber_sketch::constraints::equal_radius::RoundRadiiEqual;
/// use camber_solve::Residual;
/// let mut g = [0.0_f64];
/// // An arc of radius 5 (centre (0, 0), start (3, 4)) against a circle of radius 2.
/// RoundRadiiEqual { first_arc: true, second_arc: false }
///     .eval(&[&[0.0, 0.0][..], &[3.0, 4.0][..], &[2.0][..]], &mut g);
/// assert!((g[0] - 3.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoundRadiiEqual {
    /// Whether the first is an arc.
    pub first_arc: bool,
    /// Whether the second is an arc.
    pub second_arc: bool,
}

impl Residual for RoundRadiiEqual {
    fn name(&self) -> &str {
        EqualRadius::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        let mut out = Vec::with_capacity(4);
        radius_block_sizes(self.first_arc, &mut out);
        radius_block_sizes(self.second_arc, &mut out);
        Some(out)
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (r1, used) = radius_of(self.first_arc, x);
        let (r2, _) = radius_of(self.second_arc, &x[used..]);
        out[0] = r1 - r2;
    }
    fn is_affine(&self) -> bool {
        !self.first_arc && !self.second_arc
    }
}

impl ConstraintKind for EqualRadius {
    const TAG: &'static str = "equal_radius";
    const LABEL: &'static str = "equal radius";

    fn entities(&self, out: &mut Entities) {
        out.add(self.first);
        out.add(self.second);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        distinct(self.first, self.second)?;
        let (a, b) = (Round::of(cx, self.first)?, Round::of(cx, self.second)?);
        let mut slots: Vec<Slot> = a.radius_slots().to_vec();
        slots.extend(b.radius_slots());
        if a.is_arc() || b.is_arc() {
            let residual = RoundRadiiEqual {
                first_arc: a.is_arc(),
                second_arc: b.is_arc(),
            };
            cx.residual(residual, slots, None);
        } else {
            cx.residual(RadiiEqual, slots, None);
        }
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        [self.first, self.second]
            .into_iter()
            .map(|c| {
                let (centre, r) = glyph::circle(at, c)?;
                Ok(Glyph::Mark(Point2::new(centre.x, centre.y + r), "="))
            })
            .collect()
    }
}
