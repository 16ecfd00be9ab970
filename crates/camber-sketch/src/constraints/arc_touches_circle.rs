//! `arc_touches_circle`: a circular arc (centre C₁, radius r₁ = |S₁ − C₁|) touches a circle
//! or the circle of another arc (centre C₂, radius r₂) somewhere in its interior, externally
//! (|C₁ − C₂| = r₁ + r₂) or internally (|C₁ − C₂| = |r₁ − r₂|), as recorded. One row in length
//! units, free of square roots of the centre distance and of absolute values,
//!
//! g = (|C₁ − C₂|² − (r₁ ± r₂)²) / (2(r₁ + r₂)) = 0 (+ external, − internal),
//!
//! which near a solution reads |C₁ − C₂| − (r₁ + r₂) (external) and
//! (|r₁ − r₂|/(r₁ + r₂))·(|C₁ − C₂| − |r₁ − r₂|) (internal). External and internal contacts
//! cannot turn into each other without a radius going through zero. The contact lies on the
//! line of centres: in the direction u = (C₂ − C₁)/|C₁ − C₂| from C₁ for an external contact
//! and for an internal one with r₁ > r₂, in the direction −u when the arc lies inside the
//! larger circle. After every solve that direction must lie within the arc's sweep (and within
//! the other's, when it is an arc), to the solve's tolerance over the radius, else the solve
//! fails with [`Error::ContactOffArc`] naming the constraint and the arc, and the sketch is
//! left as it was. (Coincident circles, an internal contact with C₁ = C₂ and r₁ = r₂, touch
//! everywhere and pass.) For an arc end on a circle or on another arc's end,
//! `arc_tangent_to_arc` is the kind. File form:
//! `{"kind": "arc_touches_circle", "arc": 1, "circle": 2, "tangency": "external"}`.

use std::sync::Arc;

use camber_solve::{Residual, Scalar};
use nalgebra::{Point2, Vector2};
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::Glyph;
use super::shared::arc_span::outside_sweep;
use super::shared::radii::{radius_block_sizes, radius_of, Round};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::Tangency;
use crate::residuals::curve::{dot, sub};

/// The arc touches a circle (or another arc's circle) in its interior, externally or
/// internally (one row, and the contact checked within the sweeps after the solve).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArcTouchesCircle {
    /// The circular arc.
    pub arc: EntityId,
    /// The circle, or another arc.
    pub circle: EntityId,
    /// Each outside the other, or one inside the other.
    pub tangency: Tangency,
}

/// g of the module documentation over the blocks [C₁, S₁, C₂, r₂] (a circle) or
/// [C₁, S₁, C₂, S₂] (an arc).
///
/// ```
/// use camber_sketch::constraints::arc_touches_circle::RoundContact;
/// use camber_sketch::Tangency;
/// use camber_solve::Residual;
/// let mut g = [f64::NAN];
/// // An arc of radius 1 about (0, 0) and a circle of radius 2 about (3, 0): external contact.
/// let x: [&[f64]; 4] = [&[0.0, 0.0], &[1.0, 0.0], &[3.0, 0.0], &[2.0]];
/// RoundContact::new(Tangency::External, false).eval(&x, &mut g);
/// assert!(g[0].abs() < 1e-15);
/// // Internally it would need |C₁ − C₂| = 1: (9 − 1)/(2·3).
/// RoundContact::new(Tangency::Internal, false).eval(&x, &mut g);
/// assert!((g[0] - 4.0 / 3.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoundContact {
    tangency: Tangency,
    other_arc: bool,
}

impl RoundContact {
    /// The row for the `tangency` with a circle (`other_arc` false) or another arc.
    pub fn new(tangency: Tangency, other_arc: bool) -> Self {
        Self {
            tangency,
            other_arc,
        }
    }
}

impl Residual for RoundContact {
    fn name(&self) -> &str {
        ArcTouchesCircle::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        let mut sizes = vec![2, 2, 2];
        if self.other_arc {
            sizes.push(2);
        } else {
            radius_block_sizes(false, &mut sizes);
        }
        Some(sizes)
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (r1, _) = radius_of(true, x);
        let (r2, _) = radius_of(self.other_arc, if self.other_arc { &x[2..] } else { &x[3..] });
        let delta = sub(x[2], x[0]);
        let sum = r1 + r2;
        let target = match self.tangency {
            Tangency::External => sum,
            Tangency::Internal => r1 - r2,
        };
        out[0] = (dot(delta, delta) - target * target) / (sum + sum);
    }
}

/// A round entity's centre, radius and, for an arc, the arc.
fn round(e: &Entity) -> Option<(Point2<f64>, f64, Option<camber_geom::CircularArc<f64>>)> {
    match e {
        Entity::Circle { center, radius } => Some((*center, *radius, None)),
        Entity::Arc(b) => Some((b[0], (b[1] - b[0]).norm(), e.as_arc())),
        _ => None,
    }
}

impl ArcTouchesCircle {
    /// The contact point and the directions from each centre to it (unit vectors), in the
    /// state `at` gives; `None` for concentric circles (no single contact).
    #[allow(clippy::type_complexity)] // Three named results read plainer than a struct here.
    fn contact_point<'e>(
        &self,
        at: impl Fn(EntityId) -> Result<&'e Entity>,
    ) -> Result<Option<(Point2<f64>, Vector2<f64>, Vector2<f64>)>> {
        let wrong = |id: EntityId, e: &Entity| Error::WrongEntityKind {
            entity: id,
            expected: "circle or arc",
            found: e.kind_name(),
        };
        let (e1, e2) = (at(self.arc)?, at(self.circle)?);
        let (c1, r1, _) = round(e1).ok_or_else(|| wrong(self.arc, e1))?;
        let (c2, r2, _) = round(e2).ok_or_else(|| wrong(self.circle, e2))?;
        let delta = c2 - c1;
        let n = delta.norm();
        if n <= 1e-12 * (r1 + r2) {
            return Ok(None);
        }
        let u = delta / n;
        let w1 = match self.tangency {
            Tangency::Internal if r1 < r2 => -u,
            _ => u,
        };
        let x = c1 + r1 * w1;
        let w2 = (x - c2) / r2;
        Ok(Some((x, w1, w2)))
    }
}

impl ConstraintKind for ArcTouchesCircle {
    const TAG: &'static str = "arc_touches_circle";
    const LABEL: &'static str = "arc touches circle";

    fn entities(&self, out: &mut Entities) {
        out.add(self.arc);
        out.add(self.circle);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        Round::arc(cx, self.arc)?;
        distinct(self.arc, self.circle)?;
        let other = Round::of(cx, self.circle)?;
        let mut slots = vec![
            Slot::Point(self.arc, 0),
            Slot::Point(self.arc, 1),
            Slot::Point(self.circle, 0),
        ];
        slots.push(if other.is_arc() {
            Slot::Point(self.circle, 1)
        } else {
            Slot::Radius(self.circle)
        });
        cx.residual(
            RoundContact::new(self.tangency, other.is_arc()),
            slots,
            Some(Arc::new(*self)),
        );
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(match self.contact_point(|id| at.lookup(id))? {
            Some((x, w1, _)) => vec![
                Glyph::Arrow(x, Vector2::new(-w1.y, w1.x)),
                Glyph::Ring(x),
            ],
            None => Vec::new(),
        })
    }
}

impl SolvedCheck for ArcTouchesCircle {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let Some((_, w1, w2)) = self.contact_point(|id| state.entity(id))? else {
            return Ok(());
        };
        for (id, w) in [(self.arc, w1), (self.circle, w2)] {
            let Some((_, _, Some(arc))) = round(state.entity(id)?) else {
                continue;
            };
            if let Some(outside) = outside_sweep(&arc, w, state.penetration) {
                return Err(Error::ContactOffArc {
                    constraint: state.owner,
                    arc: id,
                    outside,
                });
            }
        }
        Ok(())
    }
}
