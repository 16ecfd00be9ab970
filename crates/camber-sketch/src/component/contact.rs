//! The active-set bookkeeping of honest contact (the mathematics is in
//! [`crate::residuals::clearance`]): which row answers a failed contact check, which contacts
//! start reversed, the multipliers that say whether an active row binds, and adding a row to a
//! component's problem.

use std::sync::Arc;

use camber_solve::{BlockId, ConstraintId};
use smallvec::{smallvec, SmallVec};

use super::problem::ComponentProblem;
use crate::constraints::check::{point_tangent, side_width, ContactSpec, ContactTarget};
use crate::constraints::piece::{curve_slots, Piece, Slot};
use crate::constraints::shared::joins::join_speed_floor;
use crate::constraints::shared::round_contacts::round;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::{CircleSide, Contact, LineSide, Rotation};
use crate::residuals::clearance::{Clearance, TangentSpeed, Target, SPEED_FLOOR};
use crate::residuals::Param;

/// Components with at most this many reduced unknowns factorize J·W⁻¹·Jᵀ densely for the
/// multipliers.
const DENSE_MAX_UNKNOWNS: usize = 256;

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
    /// The speed floor |C′(u)| = κ·|C′₀(u)| at one end u of a curve of a free-direction join
    /// (C′₀ measured before the solve; in a drag, before the session).
    JoinSpeedFloor {
        /// The join constraint.
        owner: ConstraintId,
        /// The curve whose end tangent collapsed.
        curve: EntityId,
        /// Whether it is the curve's end (else its start).
        at_end: bool,
    },
}

impl ActiveRow {
    /// The contact constraint the row belongs to.
    pub(crate) fn owner(self) -> ConstraintId {
        match self {
            ActiveRow::Clearance { owner, .. }
            | ActiveRow::SpeedFloor { owner }
            | ActiveRow::JoinSpeedFloor { owner, .. } => owner,
        }
    }
}

/// A circle or line contact of a built component: what it touches, and where its parameter
/// lives (a fixed value, or the block of the free one).
#[derive(Debug, Clone, Copy)]
struct BuiltContact {
    spec: ContactSpec,
    u: ContactParam,
}

#[derive(Debug, Clone, Copy)]
enum ContactParam {
    Fixed(f64),
    Block(BlockId),
}

impl ComponentProblem {
    /// The circle or line contact owned by `owner`.
    fn built_contact(&self, owner: ConstraintId) -> Option<BuiltContact> {
        let entry = self
            .checks
            .iter()
            .find(|e| e.owner == owner && e.check.contact().is_some())?;
        let spec = entry.check.contact()?;
        let u = match spec.u {
            Contact::At(v) => ContactParam::Fixed(v),
            Contact::Free(_) => ContactParam::Block(*entry.free.first()?),
        };
        Some(BuiltContact { spec, u })
    }

    /// The contact parameter's value at the unknowns `x`.
    fn contact_value(&self, x: &[f64], u: ContactParam) -> Result<f64> {
        match u {
            ContactParam::Fixed(v) => Ok(v),
            ContactParam::Block(b) => self.block_value(x, b),
        }
    }

    /// The free-direction join owned by `owner`: (the curve ending at the joint, the curve
    /// starting there).
    fn built_join(&self, owner: ConstraintId) -> Option<(EntityId, EntityId)> {
        self.checks
            .iter()
            .find(|e| e.owner == owner)
            .and_then(|e| e.check.joint())
    }

    /// The side of a join whose tangent at the joint fell furthest below its floor
    /// ([`join_speed_floor`], measured on the curves in `before`) in the `solved` entities.
    fn collapsed_side(
        (first, second): (EntityId, EntityId),
        solved: &[(EntityId, Entity)],
        before: &dyn EntityLookup,
    ) -> Result<Option<(EntityId, bool)>> {
        let mut worst: Option<((EntityId, bool), f64)> = None;
        for (curve, at_end) in [(first, true), (second, false)] {
            let Some((_, e)) = solved.iter().find(|(id, _)| *id == curve) else {
                continue;
            };
            let (a, b) = e.domain().unwrap_or((0.0, 1.0));
            let u = if at_end { b } else { a };
            let (_, t) = point_tangent(e, curve, u)?;
            let floor = join_speed_floor(before, curve, u)?;
            let ratio = t[0].hypot(t[1]) / floor.max(f64::MIN_POSITIVE);
            if ratio <= 1.0 && worst.is_none_or(|(_, r)| ratio < r) {
                worst = Some(((curve, at_end), ratio));
            }
        }
        Ok(worst.map(|(side, _)| side))
    }

    /// The active row that answers a failed check at the solved unknowns `x` (the `solved`
    /// entities; `before`, the entities before the solve): a crossing gets the clearance on its
    /// side of the contact, a cusp the speed floor of the contact or of the collapsed side of a
    /// free-direction join. `None` for other errors and for contacts that are not with a circle
    /// or a line.
    pub(crate) fn active_row_for(
        &self,
        e: &Error,
        x: &[f64],
        solved: &[(EntityId, Entity)],
        before: &dyn EntityLookup,
    ) -> Result<Option<ActiveRow>> {
        Ok(match *e {
            Error::ContactCrossed {
                constraint,
                parameter,
                ..
            } => match self.built_contact(constraint) {
                Some(c) => Some(ActiveRow::Clearance {
                    owner: constraint,
                    after: parameter > self.contact_value(x, c.u)?,
                }),
                None => None,
            },
            Error::Cusp { constraint, .. } => match self.built_contact(constraint) {
                Some(_) => Some(ActiveRow::SpeedFloor { owner: constraint }),
                None => match self.built_join(constraint) {
                    Some(join) => {
                        Self::collapsed_side(join, solved, before)?.map(|(curve, at_end)| {
                            ActiveRow::JoinSpeedFloor {
                                owner: constraint,
                                curve,
                                at_end,
                            }
                        })
                    }
                    None => None,
                },
            },
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
    pub(crate) fn reversed_contacts(&self, lookup: &dyn EntityLookup) -> Result<Vec<ActiveRow>> {
        let x = self.problem.values();
        let mut out = Vec::new();
        let mut entities = None;
        for entry in &self.checks {
            // Only the contacts' own entries: looking up the contact of every check's owner
            // scanned all the checks for each, O(checks²) per solve (a W7 drag update on a
            // chain of 10⁴ G1 joints, with no contact at all, spent 10⁸ comparisons here).
            if entry.check.contact().is_none() {
                continue;
            }
            let Some(c) = self.built_contact(entry.owner) else {
                continue;
            };
            if out.contains(&ActiveRow::SpeedFloor { owner: entry.owner }) {
                continue;
            }
            let solved = entities.get_or_insert(self.entities_at(lookup, x)?);
            let find = |id| solved.iter().find(|(e, _)| *e == id).map(|(_, e)| e);
            let Some(curve) = find(c.spec.curve) else {
                continue;
            };
            let (p, t) = point_tangent(curve, c.spec.curve, self.contact_value(x, c.u)?)?;
            let reversed = match c.spec.target {
                ContactTarget::Circle {
                    circle, rotation, ..
                } => {
                    let Some((center, _, _)) = find(circle).and_then(round) else {
                        continue;
                    };
                    let turn = (p[0] - center.x) * t[1] - (p[1] - center.y) * t[0];
                    match rotation {
                        Rotation::CounterClockwise => turn < 0.0,
                        Rotation::Clockwise => turn > 0.0,
                    }
                }
                ContactTarget::Ellipse {
                    ellipse, rotation, ..
                } => {
                    let Some(el) = find(ellipse).and_then(|e| e.as_ellipse()) else {
                        continue;
                    };
                    // The ellipse's counter-clockwise tangent at the point nearest C(u) is
                    // rot₉₀ of the outward normal ∇F: the curve turns against the recorded
                    // rotation when its tangent points the other way.
                    let q = el.to_frame(&nalgebra::Point2::new(p[0], p[1]));
                    let (axis, across) = el.axes();
                    let (a, b) = (el.semi_axis_a(), el.semi_axis_b());
                    let normal = axis * (q.x / (a * a)) + across * (q.y / (b * b));
                    let turn = normal.x * t[1] - normal.y * t[0];
                    match rotation {
                        Rotation::CounterClockwise => turn < 0.0,
                        Rotation::Clockwise => turn > 0.0,
                    }
                }
                ContactTarget::Line { line, sense, .. } => {
                    let Some(crate::ground::entity::Entity::Line([a, b])) = find(line) else {
                        continue;
                    };
                    sense.sign() * (t[0] * (b.x - a.x) + t[1] * (b.y - a.y)) < 0.0
                }
            };
            if reversed {
                out.push(ActiveRow::SpeedFloor { owner: entry.owner });
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
    ///
    /// It takes one factorization of J·W⁻¹·Jᵀ (dense for small components, sparse otherwise)
    /// and is skipped when there are no active rows.
    pub(crate) fn active_multipliers(&self, z_start: &[f64], count: usize) -> Result<Vec<f64>> {
        if count == 0 {
            return Ok(Vec::new());
        }
        let options = camber_solve::Options::default().with_dense_max_unknowns(DENSE_MAX_UNKNOWNS);
        match camber_solve::multipliers(&self.problem, z_start, &options)? {
            Some(mut mu) if count <= mu.len() => {
                let m = mu.len();
                Ok(mu.split_off(m - count))
            }
            // Dependent rows: no multiplier to read, so no row is dropped.
            _ => Ok(vec![0.0; count]),
        }
    }

    /// Adds an active row, built against the problem's starting values (owned by the contact
    /// constraint), or for a join's speed floor against the curve in `lookup` (the entities
    /// before the solve). Returns false when it does not apply (no such contact, or a vanishing
    /// starting tangent for a speed floor).
    pub(crate) fn add_active_row(
        &mut self,
        lookup: &dyn EntityLookup,
        row: ActiveRow,
    ) -> Result<bool> {
        let owner = row.owner();
        if let ActiveRow::JoinSpeedFloor { curve, at_end, .. } = row {
            return self.add_join_speed_floor(lookup, owner, curve, at_end);
        }
        let Some(contact) = self.built_contact(owner) else {
            return Ok(false);
        };
        let curve = contact.spec.curve;
        let (target_slots, target, positive): (SmallVec<[Slot; 3]>, _, _) =
            match contact.spec.target {
                ContactTarget::Circle { circle, side, .. } => {
                    let arc = matches!(lookup.lookup(circle)?, Entity::Arc(_));
                    (
                        smallvec![
                            Slot::Point(circle, 0),
                            if arc {
                                Slot::Point(circle, 1)
                            } else {
                                Slot::Radius(circle)
                            },
                        ],
                        if arc { Target::Arc } else { Target::Circle },
                        side == CircleSide::Outside,
                    )
                }
                ContactTarget::Ellipse { ellipse, side, .. } => (
                    smallvec![
                        Slot::Point(ellipse, 0),
                        Slot::Point(ellipse, 1),
                        Slot::Radius(ellipse),
                    ],
                    Target::Ellipse,
                    side == CircleSide::Outside,
                ),
                ContactTarget::Line { line, side, .. } => (
                    smallvec![Slot::Point(line, 0), Slot::Point(line, 1)],
                    Target::Line,
                    side == LineSide::Left,
                ),
            };
        let (basis, mut slots) = curve_slots(lookup, curve)?;
        let width = side_width(basis.domain());
        let residual: Arc<dyn camber_solve::DynResidual> = match row {
            ActiveRow::Clearance { after, .. } => {
                let param = match contact.u {
                    ContactParam::Fixed(v) => Param::Fixed(v),
                    ContactParam::Block(b) => {
                        slots.push(Slot::Existing(b));
                        Param::Block
                    }
                };
                slots.extend(target_slots);
                Arc::new(Clearance::new(basis, param, target, positive, after, width))
            }
            ActiveRow::SpeedFloor { .. } => {
                let x = self.problem.values().to_vec();
                let at = self.contact_value(&x, contact.u)?;
                let entities = self.entities_at(lookup, &x)?;
                let Some((_, e)) = entities.iter().find(|(id, _)| *id == curve) else {
                    return Ok(false);
                };
                let (_, t) = point_tangent(e, curve, at)?;
                let speed = SPEED_FLOOR * t[0].hypot(t[1]);
                if !(speed.is_finite() && speed > 0.0) {
                    return Ok(false);
                }
                let (basis, param) = match contact.u {
                    ContactParam::Fixed(v) => {
                        let (fixed, points) = basis.at(v, 1);
                        slots = points.iter().map(|j| Slot::Point(curve, *j)).collect();
                        (fixed, Param::Fixed(v))
                    }
                    ContactParam::Block(b) => {
                        slots.push(Slot::Existing(b));
                        (basis, Param::Block)
                    }
                };
                Arc::new(TangentSpeed::new(basis, param, speed, width))
            }
            // Answered by `add_join_speed_floor` above.
            ActiveRow::JoinSpeedFloor { .. } => return Ok(false),
        };
        let piece = Piece::General {
            residual,
            slots,
            check: None,
        };
        self.add_piece(owner, &piece)?;
        Ok(true)
    }

    /// Adds |C′(u)| = κ·|C′₀(u)| at the joint end u of `curve` (C′₀ on the curve in `lookup`),
    /// owned by the join `owner`: the closed set that keeps the minimum-displacement solution
    /// of a free-direction join off the cusp it would otherwise run into (see
    /// [`crate::residuals::clearance`]). False for a vanishing starting tangent.
    fn add_join_speed_floor(
        &mut self,
        lookup: &dyn EntityLookup,
        owner: ConstraintId,
        curve: EntityId,
        at_end: bool,
    ) -> Result<bool> {
        let e = lookup.lookup(curve)?;
        let (a, b) = e.domain().unwrap_or((0.0, 1.0));
        let u = if at_end { b } else { a };
        let (_, t) = point_tangent(e, curve, u)?;
        let speed = SPEED_FLOOR * t[0].hypot(t[1]);
        if !(speed.is_finite() && speed > 0.0) {
            return Ok(false);
        }
        let (basis, _) = curve_slots(lookup, curve)?;
        let width = side_width(basis.domain());
        let (fixed, points) = basis.at(u, 1);
        let piece = Piece::General {
            residual: Arc::new(TangentSpeed::new(fixed, Param::Fixed(u), speed, width)),
            slots: points.iter().map(|j| Slot::Point(curve, *j)).collect(),
            check: None,
        };
        self.add_piece(owner, &piece)?;
        Ok(true)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::constraints::{Fixed, TangentToLine};
    use crate::ground::vocabulary::{Contact, Sense};
    use crate::{PointRef, Sketch};
    use camber_geom::BezierCurve2;
    use nalgebra::Point2;

    /// The cubic of `tests/clearance.rs` that leaves the line y = 0 at u = 0 and dips below
    /// it: P₃ and the line fixed, P₀…P₂ free.
    fn dipping() -> (Sketch, ConstraintId) {
        let mut s = Sketch::new();
        let c = s
            .add_bezier(
                BezierCurve2::try_new(vec![
                    Point2::new(0.0, 0.05),
                    Point2::new(0.3, 0.02),
                    Point2::new(0.6, -0.3),
                    Point2::new(1.0, 0.5),
                ])
                .unwrap(),
            )
            .unwrap();
        let line = s
            .add_line(Point2::new(0.0, 0.0), Point2::new(1.0, 0.0))
            .unwrap();
        s.add_constraint(Fixed::entity(line)).unwrap();
        s.add_constraint(Fixed::point(PointRef::Control(c, 3)))
            .unwrap();
        let id = s
            .add_constraint(TangentToLine {
                curve: c,
                line,
                u: Contact::At(0.0),
                side: LineSide::Left,
                sense: Sense::Agree,
            })
            .unwrap();
        (s, id)
    }

    /// Solves the component with one active row and returns that row's multiplier.
    fn multiplier(row: ActiveRow) -> f64 {
        let (s, _) = dipping();
        let comp = s.components().remove(0);
        let mut cp = s.build_component(&comp).unwrap();
        assert!(cp.add_active_row(&s, row).unwrap());
        let z0 = cp.problem().reduced_map().unwrap().z0().to_vec();
        cp.solve_once(s.options(), &camber_solve::Start::Cold)
            .unwrap();
        cp.active_multipliers(&z0, 1).unwrap()[0]
    }

    /// The clearance the crossing calls for binds (μ > 0: without it the curve would cross to
    /// get closer to the start); a speed floor the solution does not need, which only shortens
    /// the first leg from 0.9 to 0.225, does not (μ < 0: a longer leg is closer to the start),
    /// so the solve would drop it.
    #[test]
    fn multipliers_tell_binding_rows_from_slack_ones() {
        let (_, id) = dipping();
        let clearance = multiplier(ActiveRow::Clearance {
            owner: id,
            after: true,
        });
        assert!(clearance > 0.0, "clearance μ = {clearance}");
        let floor = multiplier(ActiveRow::SpeedFloor { owner: id });
        assert!(floor < 0.0, "floor μ = {floor}");
    }
}
