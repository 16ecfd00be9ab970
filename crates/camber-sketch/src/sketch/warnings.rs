//! Warnings about near-degenerate input: geometry and constraints that are valid but close to
//! what cannot be solved well, named so a designer can fix them before a solve goes astray.
//!
//! All lengths are compared with the sketch's scale S, the diagonal of the bounding box of
//! every entity point (circles with their radius), at least 1:
//!
//! - a line shorter than [`SHORT`]·S (its direction, used by tangency and angle rows, is
//!   rounding noise);
//! - two consecutive control points of a curve closer than [`SHORT`]·S (the tangent at a
//!   clamped end there vanishes: a cusp in waiting);
//! - a circle whose radius is below [`SHORT`]·S;
//! - an angle constraint within [`ANGLE`] radians of 0 or π (the sine row has a double root
//!   there: `parallel` says the same thing with a simple root);
//! - a distance or length constraint below [`SHORT`]·S.

use std::f64::consts::PI;

use crate::constraints::Constraint;
use crate::ground::entity::Entity;
use crate::ground::ids::{ConstraintId, EntityId};
use crate::sketch::Sketch;

/// Relative size below which a length counts as near zero.
pub const SHORT: f64 = 1e-6;

/// Radians within which an angle counts as parallel.
pub const ANGLE: f64 = 1e-6;

/// A near-degenerate piece of input (see the module documentation). Serializes as
/// `{"kind": "short_line", "entity": 3, "length": 1e-9, "message": "…"}`.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Warning {
    /// A line almost of zero length.
    ShortLine {
        /// The line.
        entity: EntityId,
        /// Its length.
        length: f64,
    },
    /// Two consecutive control points almost coincide.
    CoincidentControlPoints {
        /// The curve.
        entity: EntityId,
        /// The index of the first of the two.
        index: usize,
        /// Their distance.
        distance: f64,
    },
    /// A circle of almost zero radius.
    TinyRadius {
        /// The circle.
        entity: EntityId,
        /// Its radius.
        radius: f64,
    },
    /// An angle constraint of almost 0 or π: parallel was meant.
    ParallelAngle {
        /// The constraint.
        constraint: ConstraintId,
        /// Its angle (radians).
        angle: f64,
    },
    /// A distance or length constraint of almost zero.
    TinyDistance {
        /// The constraint.
        constraint: ConstraintId,
        /// Its value.
        value: f64,
    },
}

impl std::fmt::Display for Warning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Warning::ShortLine { entity, length } => write!(
                f,
                "{entity} is a line of length {length:.3e}: its direction is rounding noise"
            ),
            Warning::CoincidentControlPoints {
                entity,
                index,
                distance,
            } => write!(
                f,
                "control points {index} and {} of {entity} are {distance:.3e} apart: the tangent there almost vanishes",
                index + 1
            ),
            Warning::TinyRadius { entity, radius } => {
                write!(f, "{entity} is a circle of radius {radius:.3e}")
            }
            Warning::ParallelAngle { constraint, angle } => write!(
                f,
                "{constraint} asks an angle of {angle:.3e} rad: use a parallel constraint (the angle row is flat there)"
            ),
            Warning::TinyDistance { constraint, value } => {
                write!(f, "{constraint} asks a length of {value:.3e}")
            }
        }
    }
}

/// # Warnings
impl Sketch {
    /// The sketch's scale S: the diagonal of the bounding box of every entity point (circles
    /// with their radius), at least 1.
    pub fn scale(&self) -> f64 {
        let (lo, hi) = self.extent.bounds();
        let d = (hi[0] - lo[0]).hypot(hi[1] - lo[1]);
        if d.is_finite() {
            d.max(1.0)
        } else {
            1.0
        }
    }

    /// The centre of the bounding box of every entity point (circles with their radius), the
    /// origin for an empty sketch (or one whose box is not finite): with [`Sketch::scale`], what
    /// a drag target is measured against ([`crate::drag::MAX_DRAG_REACH`]).
    ///
    /// ```
    /// use camber_sketch::Sketch;
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// s.add_line(Point2::new(0.0, 0.0), Point2::new(4.0, 2.0))?;
    /// assert_eq!(s.centre(), Point2::new(2.0, 1.0));
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    pub fn centre(&self) -> nalgebra::Point2<f64> {
        let (lo, hi) = self.extent.bounds();
        let c = nalgebra::Point2::new(0.5 * lo[0] + 0.5 * hi[0], 0.5 * lo[1] + 0.5 * hi[1]);
        if c.x.is_finite() && c.y.is_finite() {
            c
        } else {
            nalgebra::Point2::origin()
        }
    }

    /// The near-degenerate pieces of the sketch (see the module documentation), entities first,
    /// then constraints, each in id order.
    ///
    /// ```
    /// use camber_sketch::warnings::Warning;
    /// use camber_sketch::Sketch;
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let l = s.add_line(Point2::new(0.0, 0.0), Point2::new(1e-9, 0.0))?;
    /// s.add_line(Point2::new(0.0, 0.0), Point2::new(3.0, 4.0))?;
    /// assert!(matches!(s.warnings().as_slice(), [Warning::ShortLine { entity, .. }] if *entity == l));
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    pub fn warnings(&self) -> Vec<Warning> {
        let near = SHORT * self.scale();
        let mut out = Vec::new();
        for (id, e) in self.entities() {
            entity_warnings(id, e, near, &mut out);
        }
        for (id, c) in self.constraints() {
            constraint_warnings(id, c, near, &mut out);
        }
        out
    }

    /// [`Sketch::warnings`] about the given entities and constraints only (the threshold still
    /// from the whole sketch's scale), entities first, then constraints, each in id order: what
    /// a solve of the components holding them reports, at the cost of their size.
    pub(crate) fn warnings_in(
        &self,
        entities: impl Iterator<Item = EntityId>,
        constraints: impl Iterator<Item = ConstraintId>,
    ) -> Vec<Warning> {
        let near = SHORT * self.scale();
        let mut entities: Vec<EntityId> = entities.collect();
        entities.sort_unstable();
        let mut constraints: Vec<ConstraintId> = constraints.collect();
        constraints.sort_unstable();
        let mut out = Vec::new();
        for id in entities {
            if let Ok(e) = self.entity(id) {
                entity_warnings(id, e, near, &mut out);
            }
        }
        for id in constraints {
            if let Ok(c) = self.constraint(id) {
                constraint_warnings(id, c, near, &mut out);
            }
        }
        out
    }
}

/// The warnings about entity `id` (a line, circle radius or neighbouring control points shorter
/// than `near`), appended to `out`.
fn entity_warnings(id: EntityId, e: &Entity, near: f64, out: &mut Vec<Warning>) {
    match e {
        Entity::Line([a, b]) => {
            let length = (b - a).norm();
            if length < near {
                out.push(Warning::ShortLine { entity: id, length });
            }
        }
        Entity::Circle { radius, .. } => {
            if *radius < near {
                out.push(Warning::TinyRadius {
                    entity: id,
                    radius: *radius,
                });
            }
        }
        Entity::Point(_) => {}
        _ => {
            // Hermite and composite curves: neighbouring nodes (their other blocks are
            // tangent vectors, not positions).
            let positions = match e {
                Entity::Hermite(c) | Entity::Composite(c) => c.nodes(),
                _ => e.points(),
            };
            for (index, w) in positions.windows(2).enumerate() {
                let distance = (w[1] - w[0]).norm();
                if distance < near {
                    out.push(Warning::CoincidentControlPoints {
                        entity: id,
                        index,
                        distance,
                    });
                }
            }
        }
    }
}

/// The warnings about constraint `id` (an angle near 0 or π, a length below `near`), appended
/// to `out`.
fn constraint_warnings(id: ConstraintId, c: &Constraint, near: f64, out: &mut Vec<Warning>) {
    match c {
        Constraint::Angle(a) => {
            let folded = a.angle.rem_euclid(PI);
            if folded.min(PI - folded) < ANGLE {
                out.push(Warning::ParallelAngle {
                    constraint: id,
                    angle: a.angle,
                });
            }
        }
        Constraint::Distance(d) if d.distance < near => out.push(Warning::TinyDistance {
            constraint: id,
            value: d.distance,
        }),
        Constraint::ArcLength(l) if l.length < near => out.push(Warning::TinyDistance {
            constraint: id,
            value: l.length,
        }),
        Constraint::PointLineDistance(d) if d.distance < near => out.push(Warning::TinyDistance {
            constraint: id,
            value: d.distance,
        }),
        _ => {}
    }
}

/// The fields of a warning with its kind and message, for its JSON form.
#[derive(serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
enum WarningForm<'a> {
    ShortLine {
        entity: EntityId,
        length: f64,
        message: &'a str,
    },
    CoincidentControlPoints {
        entity: EntityId,
        index: usize,
        distance: f64,
        message: &'a str,
    },
    TinyRadius {
        entity: EntityId,
        radius: f64,
        message: &'a str,
    },
    ParallelAngle {
        constraint: ConstraintId,
        angle: f64,
        message: &'a str,
    },
    TinyDistance {
        constraint: ConstraintId,
        value: f64,
        message: &'a str,
    },
}

impl serde::Serialize for Warning {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        let message = self.to_string();
        let message = message.as_str();
        match *self {
            Warning::ShortLine { entity, length } => WarningForm::ShortLine {
                entity,
                length,
                message,
            },
            Warning::CoincidentControlPoints {
                entity,
                index,
                distance,
            } => WarningForm::CoincidentControlPoints {
                entity,
                index,
                distance,
                message,
            },
            Warning::TinyRadius { entity, radius } => WarningForm::TinyRadius {
                entity,
                radius,
                message,
            },
            Warning::ParallelAngle { constraint, angle } => WarningForm::ParallelAngle {
                constraint,
                angle,
                message,
            },
            Warning::TinyDistance { constraint, value } => WarningForm::TinyDistance {
                constraint,
                value,
                message,
            },
        }
        .serialize(s)
    }
}
