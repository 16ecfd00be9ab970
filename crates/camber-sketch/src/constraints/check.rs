//! Checks of a solved state beyond the residuals: the honesty of contacts (no cusp, the travel
//! direction kept, no crossing near the contact), the sense of free joins and angles.
//!
//! A constraint kind that needs one implements [`SolvedCheck`] (in its own module) and hands
//! itself to the builder with its residual (a general piece). After every
//! solve, before anything is written back, each check runs on the solved entities with the
//! solved values of its constraint's free parameters; the first failure is the solve's error.
//! The helpers here are what several checks share: curve evaluation on solved entities, the
//! speed floor below which a tangent counts as a cusp, and the sampled crossing test.

use std::collections::HashMap;
use std::fmt::Debug;

use camber_solve::ConstraintId;

use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::{CircleSide, Contact, LineSide, Rotation, Sense};

/// Samples of the crossing check on each side of a contact.
const SIDE_SAMPLES: usize = 24;

/// A circle or line a curve touches at a contact parameter: what the active set of honest
/// contact (the active set of the solve policy) and iterative displacement need to know of a contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactSpec {
    /// The curve.
    pub curve: EntityId,
    /// Where on the curve.
    pub u: Contact,
    /// What it touches, on which side, running which way.
    pub target: ContactTarget,
}

/// The target of a [`ContactSpec`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ContactTarget {
    /// A circle entity.
    Circle {
        /// The circle.
        circle: EntityId,
        /// Outside or inside near the contact.
        side: CircleSide,
        /// The direction of travel around it.
        rotation: Rotation,
    },
    /// An ellipse or elliptic arc entity.
    Ellipse {
        /// The ellipse.
        ellipse: EntityId,
        /// Outside or inside near the contact.
        side: CircleSide,
        /// The direction of travel around it.
        rotation: Rotation,
    },
    /// A line entity (A, B).
    Line {
        /// The line.
        line: EntityId,
        /// Left or right of A→B near the contact.
        side: LineSide,
        /// Along or against B − A.
        sense: Sense,
    },
}

/// The solved state a check looks at.
pub struct SolvedState<'a> {
    /// The constraint checked (named in the errors).
    pub owner: ConstraintId,
    /// The component's entities as solved.
    pub solved: &'a HashMap<EntityId, &'a Entity>,
    /// The entities before the solve (the speed floors are measured on them).
    pub before: &'a dyn EntityLookup,
    /// The solved values of the constraint's free parameters, in order.
    pub free: &'a [f64],
    /// How far (length units) a curve may lie past its target before it counts as crossing.
    pub penetration: f64,
}

impl std::fmt::Debug for SolvedState<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SolvedState")
            .field("owner", &self.owner)
            .field("solved", &self.solved.len())
            .field("free", &self.free)
            .field("penetration", &self.penetration)
            .finish()
    }
}

impl SolvedState<'_> {
    /// A solved entity.
    ///
    /// # Errors
    /// [`Error::UnknownEntity`] for an entity outside the component.
    pub fn entity(&self, id: EntityId) -> Result<&Entity> {
        self.solved
            .get(&id)
            .copied()
            .ok_or(Error::UnknownEntity { entity: id })
    }

    /// The solved value of a contact parameter: its fixed value, or the next of the
    /// constraint's free parameters (`next` counts them; a missing one reads as NaN, which
    /// every check then fails on).
    pub fn parameter(&self, u: Contact, next: &mut usize) -> f64 {
        match u {
            Contact::At(v) => v,
            Contact::Free(_) => {
                let v = self.free.get(*next).copied().unwrap_or(f64::NAN);
                *next += 1;
                v
            }
        }
    }

    /// The tangent speed below which a contact on `curve` counts as a cusp (
    /// the speed floor: a millionth of its mean speed), measured on the curve before the solve.
    ///
    /// # Errors
    /// [`Error::UnknownEntity`].
    pub fn floor(&self, curve: EntityId) -> Result<f64> {
        Ok(speed_floor(self.before.lookup(curve)?))
    }

    /// The error of a tangent that turned against its recorded orientation, unless `dot` > 0.
    ///
    /// # Errors
    /// [`Error::OrientationFlipped`].
    pub fn sense(&self, dot: f64) -> Result<()> {
        if dot > 0.0 {
            Ok(())
        } else {
            Err(Error::OrientationFlipped {
                constraint: self.owner,
                dot,
            })
        }
    }

    /// The error of a vanished tangent, unless `speed` lies above `floor`.
    ///
    /// # Errors
    /// [`Error::Cusp`].
    pub fn not_cusp(&self, speed: f64, floor: f64) -> Result<()> {
        if speed.is_nan() || speed <= floor {
            Err(Error::Cusp {
                constraint: self.owner,
                speed,
            })
        } else {
            Ok(())
        }
    }

    /// The deepest sample of the window around u where the signed clearance `gap` (positive
    /// on the intended side) is below −penetration, as [`Error::ContactCrossed`].
    ///
    /// # Errors
    /// [`Error::ContactCrossed`]; [`Error::WrongEntityKind`] for a non-curve.
    pub fn no_crossing(
        &self,
        curve: EntityId,
        u: f64,
        gap: impl Fn([f64; 2]) -> f64,
    ) -> Result<()> {
        let e = self.entity(curve)?;
        if !e.is_curve() {
            return Err(Error::WrongEntityKind {
                entity: curve,
                expected: "curve",
                found: e.kind_name(),
            });
        }
        let mut worst: Option<(f64, f64)> = None;
        for s in window(e, u) {
            // Samples lie in the domain; a kernel error (none expected) counts as a crossing.
            let d = e
                .point_tangent(s)
                .map_or(f64::NEG_INFINITY, |(q, _)| gap([q.x, q.y]));
            if d < -self.penetration && worst.is_none_or(|(_, w)| d < w) {
                worst = Some((s, d));
            }
        }
        match worst {
            Some((parameter, d)) => Err(Error::ContactCrossed {
                constraint: self.owner,
                parameter,
                depth: -d,
            }),
            None => Ok(()),
        }
    }
}

/// What a constraint verifies on the solved state (see the module documentation).
pub trait SolvedCheck: Debug + Send + Sync {
    /// Passes, or says what the solve broke.
    ///
    /// # Errors
    /// The check's failure ([`Error::OrientationFlipped`], [`Error::Cusp`],
    /// [`Error::ContactCrossed`], …).
    fn verify(&self, state: &SolvedState<'_>) -> Result<()>;

    /// The curves of the free-direction join this check guards, (the one ending at the joint,
    /// the one starting there): a cusp at the joint gets a speed floor on the collapsed side.
    fn joint(&self) -> Option<(EntityId, EntityId)> {
        None
    }

    /// The contact this check guards, when it is one with a circle, an ellipse or a line (the active set
    /// of honest contact adds its clearance rows and speed floors from it).
    fn contact(&self) -> Option<ContactSpec> {
        None
    }
}

/// The tangent speed |C′| below which a solved contact counts as a cusp: a millionth of the
/// curve's mean speed before the solve (its control-polygon length over its parameter span).
/// A solve that shrinks a curve a million times over has collapsed it, not touched anything.
pub(crate) fn speed_floor(e: &Entity) -> f64 {
    let length: f64 = e
        .hull_points()
        .windows(2)
        .map(|w| (w[1] - w[0]).norm())
        .sum();
    let (a, b) = e.domain().unwrap_or((0.0, 1.0));
    1e-6 * length / (b - a).max(f64::MIN_POSITIVE)
}

/// C(s) and C′(s) of a solved curve entity (s clamped to its domain).
///
/// # Errors
/// [`Error::WrongEntityKind`] for a point or circle.
pub(crate) fn point_tangent(e: &Entity, id: EntityId, s: f64) -> Result<([f64; 2], [f64; 2])> {
    let (a, b) = e.domain().unwrap_or((0.0, 1.0));
    let (p, t) = e
        .point_tangent(s.clamp(a, b))
        .ok_or(Error::WrongEntityKind {
            entity: id,
            expected: "curve",
            found: e.kind_name(),
        })?;
    Ok(([p.x, p.y], [t.x, t.y]))
}

/// The half-width w = (b − a)/5 of the window beside a contact on the domain [a, b], where the
/// crossing check samples and a clearance row looks.
pub(crate) fn side_width((a, b): (f64, f64)) -> f64 {
    (b - a) / 5.0
}

/// Parameters sampled on [u − w, u + w] ∩ [a, b].
fn window(e: &Entity, u: f64) -> impl Iterator<Item = f64> {
    let (a, b) = e.domain().unwrap_or((0.0, 1.0));
    let w = side_width((a, b));
    let (lo, hi) = ((u - w).max(a), (u + w).min(b));
    let n = 2 * SIDE_SAMPLES;
    (0..=n).map(move |i| lo + (hi - lo) * i as f64 / n as f64)
}
