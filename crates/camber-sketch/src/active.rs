//! The active-set bookkeeping of honest contact (the mathematics is in [`crate::clearance`]):
//! which row answers a failed contact check, which contacts start reversed, the multipliers
//! that say whether an active row binds, and adding a row to a component's problem.

use std::sync::Arc;

use camber_solve::ConstraintId;

use crate::build::ComponentProblem;
use crate::clearance::{Clearance, TangentSpeed, Target, SPEED_FLOOR};
use crate::compile::{EntityLookup, Piece};
use crate::constraint::{CircleSide, LineSide, Rotation};
use crate::contact::Param;
use crate::errors::{Error, Result};
use crate::general::{curve_basis, point_tangent, side_width, Check, CheckParam, Slot};

/// A row the solve adds to a component after a failed contact check.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum ActiveRow {
    /// The clearance h = 0 of a contact on the side after (or before) its parameter.
    Clearance {
        /// The contact constraint.
        owner: ConstraintId,
        /// The side.
        after: bool,
    },
    /// The speed floor |C′(u)| = κ·|C′₀(u)| of a contact.
    SpeedFloor {
        /// The contact constraint.
        owner: ConstraintId,
    },
}

impl Check {
    /// The curve and contact parameter of a circle or line contact, with the target's blocks,
    /// its kind and whether the intended side is the positive one.
    fn contact(&self) -> Option<(crate::ids::EntityId, CheckParam, [Slot; 2], Target, bool)> {
        match *self {
            Check::Circle {
                curve,
                circle,
                u,
                side,
                ..
            } => Some((
                curve,
                u,
                [Slot::Point(circle, 0), Slot::Radius(circle)],
                Target::Circle,
                side == CircleSide::Outside,
            )),
            Check::Line {
                curve,
                line,
                u,
                side,
                ..
            } => Some((
                curve,
                u,
                [Slot::Point(line, 0), Slot::Point(line, 1)],
                Target::Line,
                side == LineSide::Left,
            )),
            Check::Join { .. } | Check::Angle { .. } | Check::Curves { .. } => None,
        }
    }
}

impl ComponentProblem {
    /// The circle or line contact check owned by `owner`.
    fn contact_check(&self, owner: ConstraintId) -> Option<Check> {
        self.checks
            .iter()
            .find(|(c, check)| *c == owner && check.contact().is_some())
            .map(|(_, k)| *k)
    }

    /// The active row that answers a failed check at the solved unknowns `x`: a crossing gets
    /// the clearance on its side of the contact, a cusp the speed floor. `None` for other
    /// errors and for contacts that are not with a circle or a line.
    pub(crate) fn active_row_for(&self, e: &Error, x: &[f64]) -> Result<Option<ActiveRow>> {
        Ok(match *e {
            Error::ContactCrossed {
                constraint,
                parameter,
                ..
            } => match self.contact_check(constraint).and_then(|c| c.contact()) {
                Some((_, u, ..)) => Some(ActiveRow::Clearance {
                    owner: constraint,
                    after: parameter > self.check_param(x, u)?,
                }),
                None => None,
            },
            Error::Cusp { constraint, .. } => self
                .contact_check(constraint)
                .map(|_| ActiveRow::SpeedFloor { owner: constraint }),
            _ => None,
        })
    }

    /// The speed floors a start calls for: every circle or line contact whose tangent at the
    /// start points against its recorded travel direction (rotation about the circle, sense
    /// along the line). To reach a valid curve the tangent must turn through more than a right
    /// angle against the target's normal, and the minimum-norm path turns it by shrinking it:
    /// it runs into the cusp, or stalls beside it. With the floor the tangent turns at a fixed
    /// length; [`ComponentProblem::active_multipliers`] drops the floor again when it is not
    /// binding at the solution.
    pub(crate) fn reversed_contacts<L: EntityLookup>(&self, lookup: &L) -> Result<Vec<ActiveRow>> {
        let x = self.problem.values().to_vec();
        let mut out = Vec::new();
        let mut entities = None;
        for (owner, check) in &self.checks {
            let reversed = match *check {
                Check::Circle {
                    curve,
                    circle,
                    u,
                    rotation,
                    ..
                } => {
                    let solved = entities.get_or_insert(self.entities_at(lookup, &x)?);
                    let (Some((_, e)), Some((_, crate::Entity::Circle { center, .. }))) = (
                        solved.iter().find(|(id, _)| *id == curve),
                        solved.iter().find(|(id, _)| *id == circle),
                    ) else {
                        continue;
                    };
                    let (p, t) = point_tangent(e, curve, self.check_param(&x, u)?)?;
                    let turn = (p[0] - center.x) * t[1] - (p[1] - center.y) * t[0];
                    match rotation {
                        Rotation::CounterClockwise => turn < 0.0,
                        Rotation::Clockwise => turn > 0.0,
                    }
                }
                Check::Line {
                    curve,
                    line,
                    u,
                    sense,
                    ..
                } => {
                    let solved = entities.get_or_insert(self.entities_at(lookup, &x)?);
                    let (Some((_, e)), Some((_, crate::Entity::Line([a, b])))) = (
                        solved.iter().find(|(id, _)| *id == curve),
                        solved.iter().find(|(id, _)| *id == line),
                    ) else {
                        continue;
                    };
                    let (_, t) = point_tangent(e, curve, self.check_param(&x, u)?)?;
                    sense.sign() * (t[0] * (b.x - a.x) + t[1] * (b.y - a.y)) < 0.0
                }
                Check::Join { .. } | Check::Angle { .. } | Check::Curves { .. } => false,
            };
            if reversed {
                out.push(ActiveRow::SpeedFloor { owner: *owner });
            }
        }
        Ok(out)
    }

    /// The multipliers μ of the last `count` rows (the active rows, one row each) at the
    /// solved values z*, from the first-order conditions of min ½‖z − z₀‖²_W subject to the
    /// rows: W·(z* − z₀) = Jᵀμ, solved in the least-squares sense as
    /// (J·W⁻¹·Jᵀ)·μ = J·(z* − z₀). An active row stands for the inequality h ≥ 0, which binds
    /// only when its μ ≥ 0: with μ < 0, letting h grow would bring the curve closer to the
    /// start, so the row should be dropped.
    pub(crate) fn active_multipliers(&self, z_start: &[f64], count: usize) -> Result<Vec<f64>> {
        let lin = self.problem.linearize()?;
        let j = lin.jacobian.to_dense();
        let (m, n) = (j.nrows(), j.ncols());
        let z = lin.map.z0();
        if z.len() != z_start.len() || count > m {
            return Ok(vec![0.0; count]);
        }
        let w = lin.map.weights();
        let mut jw = j.clone();
        for c in 0..n {
            let scale = 1.0 / w[c];
            for r in 0..m {
                jw[(r, c)] *= scale;
            }
        }
        let a = &jw * j.transpose();
        let moved = nalgebra::DVector::from_iterator(n, z.iter().zip(z_start).map(|(a, b)| a - b));
        let b = &j * moved;
        let mu = match a.svd(true, true).solve(&b, 1e-12) {
            Ok(mu) => mu,
            Err(_) => return Ok(vec![0.0; count]),
        };
        Ok(mu.iter().skip(m - count).copied().collect())
    }

    /// Adds an active row, built against the problem's starting values (owned by the contact
    /// constraint). Returns false when it does not apply (no such contact, or a vanishing
    /// starting tangent for a speed floor).
    pub(crate) fn add_active_row<L: EntityLookup>(
        &mut self,
        lookup: &L,
        row: ActiveRow,
    ) -> Result<bool> {
        let owner = match row {
            ActiveRow::Clearance { owner, .. } | ActiveRow::SpeedFloor { owner } => owner,
        };
        let Some((curve, u, target_slots, target, positive)) =
            self.contact_check(owner).and_then(|c| c.contact())
        else {
            return Ok(false);
        };
        let (basis, mut slots) = curve_basis(lookup, curve)?;
        let width = side_width(basis.domain());
        let (name, residual): (&'static str, Arc<dyn camber_solve::DynResidual>) = match row {
            ActiveRow::Clearance { after, .. } => {
                let param = match u {
                    CheckParam::Fixed(v) => Param::Fixed(v),
                    CheckParam::Block(b) => {
                        slots.push(Slot::Existing(b));
                        Param::Block
                    }
                    CheckParam::Slot(_) => return Ok(false),
                };
                slots.extend(target_slots);
                let h = Clearance::new(basis, param, target, positive, after, width);
                ("clearance", Arc::new(h))
            }
            ActiveRow::SpeedFloor { .. } => {
                let x = self.problem.values().to_vec();
                let at = self.check_param(&x, u)?;
                let entities = self.entities_at(lookup, &x)?;
                let Some((_, e)) = entities.iter().find(|(id, _)| *id == curve) else {
                    return Ok(false);
                };
                let (_, t) = point_tangent(e, curve, at)?;
                let speed = SPEED_FLOOR * t[0].hypot(t[1]);
                if !(speed.is_finite() && speed > 0.0) {
                    return Ok(false);
                }
                let (basis, param) = match u {
                    CheckParam::Fixed(v) => {
                        let (fixed, points) = basis.at(v, 1);
                        slots = points.iter().map(|j| Slot::Point(curve, *j)).collect();
                        (fixed, Param::Fixed(v))
                    }
                    CheckParam::Block(b) => {
                        slots.push(Slot::Existing(b));
                        (basis, Param::Block)
                    }
                    CheckParam::Slot(_) => return Ok(false),
                };
                let f = TangentSpeed::new(basis, param, speed, width);
                ("tangent speed floor", Arc::new(f))
            }
        };
        let piece = Piece::General {
            name,
            residual,
            slots,
            check: None,
        };
        self.add_piece(owner, &piece)?;
        Ok(true)
    }
}
