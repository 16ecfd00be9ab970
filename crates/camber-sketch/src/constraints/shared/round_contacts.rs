//! The contact of two round entities (circles and circular arcs) touching externally or
//! internally, as `arc_touches_circle` and `circle_touches_circle` read it: the contact point
//! on the line of centres, the directions from each centre to it, and the check after a solve
//! that the contact lies within the sweep of each entity that is an arc.
//!
//! With u = (C₂ − C₁)/|C₂ − C₁| the contact is X = C₁ + r₁·w₁, w₁ = u for an external contact
//! and for an internal one with r₁ ≥ r₂, w₁ = −u when the first lies inside the second
//! (r₁ < r₂); w₂ = (X − C₂)/r₂.
//!
//! [`RoundContact`] is the row both kinds write.

use camber_geom::CircularArc;
use camber_solve::{Residual, Scalar};
use nalgebra::{Point2, Vector2};

use super::arc_span::outside_sweep;
use super::radii::radius_of;
use crate::constraints::check::SolvedState;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::vocabulary::Tangency;
use crate::residuals::curve::{dot, sub};

/// The row of two round entities touching, over the blocks [C₁, S₁, C₂, r₂] (an arc and a
/// circle) or [C₁, S₁, C₂, S₂] (two arcs):
///
/// g = (|C₁ − C₂|² − (r₁ ± r₂)²) / (2(r₁ + r₂)) = 0 (+ external, − internal),
///
/// in length units near a solution (see `arc_touches_circle`).
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
///
/// [`RoundContact::between`] gives the same row for a circle or an arc first, over the blocks
/// [C₁, r₁] or [C₁, S₁] followed by those of the second.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoundContact {
    name: &'static str,
    tangency: Tangency,
    first_arc: bool,
    other_arc: bool,
}

impl RoundContact {
    /// The row for the `tangency` of an arc with a circle (`other_arc` false) or another arc.
    pub fn new(tangency: Tangency, other_arc: bool) -> Self {
        Self {
            name: "arc touches circle",
            ..Self::between(tangency, true, other_arc)
        }
    }

    /// The row for the `tangency` of two round entities, each a circle or an arc.
    ///
    /// ```
    /// use camber_sketch::constraints::arc_touches_circle::RoundContact;
    /// use camber_sketch::Tangency;
    /// use camber_solve::Residual;
    /// let mut g = [f64::NAN];
    /// // Circles of radii 3 and 1 about (0, 0) and (2, 0): the small one inside, touching.
    /// let x: [&[f64]; 4] = [&[0.0, 0.0], &[3.0], &[2.0, 0.0], &[1.0]];
    /// RoundContact::between(Tangency::Internal, false, false).eval(&x, &mut g);
    /// assert!(g[0].abs() < 1e-15);
    /// ```
    pub fn between(tangency: Tangency, first_arc: bool, other_arc: bool) -> Self {
        Self {
            name: "circle touches circle",
            tangency,
            first_arc,
            other_arc,
        }
    }
}

impl Residual for RoundContact {
    fn name(&self) -> &str {
        self.name
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        // [C₁, S₁] or [C₁, r₁], then [C₂, S₂] or [C₂, r₂].
        let radius = |arc: bool| if arc { 2 } else { 1 };
        Some(vec![2, radius(self.first_arc), 2, radius(self.other_arc)])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        // Both layouts of the first take two blocks: [C₁, S₁] or [C₁, r₁].
        let r1 = if self.first_arc {
            radius_of(true, x).0
        } else {
            x[1][0]
        };
        let (r2, _) = radius_of(
            self.other_arc,
            if self.other_arc { &x[2..] } else { &x[3..] },
        );
        let delta = sub(x[2], x[0]);
        let sum = r1 + r2;
        let target = match self.tangency {
            Tangency::External => sum,
            Tangency::Internal => r1 - r2,
        };
        out[0] = (dot(delta, delta) - target * target) / (sum + sum);
    }
}

/// A round entity's centre, radius and, for an arc, the arc; `None` for any other entity.
pub(crate) fn round(e: &Entity) -> Option<(Point2<f64>, f64, Option<CircularArc<f64>>)> {
    match e {
        Entity::Circle { center, radius } => Some((*center, *radius, None)),
        Entity::Arc(b) => Some((b[0], (b[1] - b[0]).norm(), e.as_arc())),
        _ => None,
    }
}

/// The contact point X of the round entities `first` and `second` and the unit directions
/// w₁, w₂ from their centres to it (module documentation), in the state `at` gives; `None`
/// for concentric entities (no single contact).
///
/// # Errors
/// Unknown ids; [`Error::WrongEntityKind`] for an entity that is not round.
#[allow(clippy::type_complexity)] // Three named results read plainer than a struct here.
pub(crate) fn contact_point<'e>(
    (first, second): (EntityId, EntityId),
    tangency: Tangency,
    at: impl Fn(EntityId) -> Result<&'e Entity>,
) -> Result<Option<(Point2<f64>, Vector2<f64>, Vector2<f64>)>> {
    let wrong = |id: EntityId, e: &Entity| Error::WrongEntityKind {
        entity: id,
        expected: "circle or arc",
        found: e.kind_name(),
    };
    let (e1, e2) = (at(first)?, at(second)?);
    let (c1, r1, _) = round(e1).ok_or_else(|| wrong(first, e1))?;
    let (c2, r2, _) = round(e2).ok_or_else(|| wrong(second, e2))?;
    let delta = c2 - c1;
    let n = delta.norm();
    if n <= 1e-12 * (r1 + r2) {
        return Ok(None);
    }
    let u = delta / n;
    let w1 = match tangency {
        Tangency::Internal if r1 < r2 => -u,
        _ => u,
    };
    let x = c1 + r1 * w1;
    let w2 = (x - c2) / r2;
    Ok(Some((x, w1, w2)))
}

/// Fails with [`Error::ContactOffArc`] (naming the owner and the arc) when the contact of the
/// solved state lies outside the sweep of `first` or `second`, whichever is an arc, by more
/// than the solve's tolerance over the radius. Concentric entities pass.
///
/// # Errors
/// That one, and those of [`contact_point`].
pub(crate) fn verify_on_arcs(
    (first, second): (EntityId, EntityId),
    tangency: Tangency,
    state: &SolvedState<'_>,
) -> Result<()> {
    let Some((_, w1, w2)) = contact_point((first, second), tangency, |id| state.entity(id))? else {
        return Ok(());
    };
    for (id, w) in [(first, w1), (second, w2)] {
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
