//! Drag sessions: the interactive loop, on the dragged component's kept plan.
//!
//! A session builds the dragged point's component once, with the policy's plan beside it
//! ([`camber_solve::Plan`]), and pins the point to the cursor in one of two ways:
//!
//! - a point free in both directions that is one block of its own (a point entity, a control
//!   point, a line end, a circle centre) is **fixed** in the problem, and each update sets the
//!   fixed block to the target;
//! - otherwise (a curve end that combines several control points, a point that can only slide
//!   along one direction, a component with priorities) it is **pinned by rows**
//!   a·(Σ cⱼ·Pⱼ − T) = 0 along its directions of freedom a, against a fixed target block T;
//!   each update sets T.
//!
//! Either way an update changes values only, so it re-solves on the kept plan: for an affine
//! component J does not change, and the plan's linear path answers from its kept factorization
//! (for a small component a dense gain: one evaluation of g, one small product, one
//! validation); for a nonlinear one the plan runs Newton minimum norm from the previous step's
//! solution pulling toward it (so each step moves the rest of the sketch as little as it can),
//! with the full selection as fallback, then the orientation and contact checks of a solve and
//! the active set of honest contact (`component::solve`). An update that fails leaves the
//! session at its previous state, and the next update starts from that state (the last
//! accepted solution, never the refused one); the sketch itself is unchanged until
//! [`DragSession::finish`].
//!
//! How the point can move ([`Freedom`]) comes from the constraints linearized at the session's
//! start ([`camber_solve::mobility`]); for a point that slides on a nonlinear component the
//! direction is taken again after every update (it turns as the point slides on a circle).

use std::collections::BTreeMap;

use camber_solve::{BlockId, Options, Residual, ResidualId, Scalar, Start, UnknownId};
use nalgebra::{Point2, Vector2};
use smallvec::SmallVec;

use crate::component::{Component, ComponentProblem, DRAG_CONSTRAINT};
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{ConstraintId, EntityId, PointRef};
use crate::ground::lookup::EntityLookup;
use crate::sketch::Sketch;

/// The entity shapes a session started from, as an [`EntityLookup`] (knots, weights and kinds
/// do not change during a drag).
#[derive(Debug)]
struct Shapes(BTreeMap<EntityId, Entity>);

impl EntityLookup for Shapes {
    fn lookup(&self, id: EntityId) -> Result<&Entity> {
        self.0.get(&id).ok_or(Error::UnknownEntity { entity: id })
    }
}

impl Shapes {
    fn of(sketch: &Sketch, comp: &Component) -> Result<Self> {
        let mut shapes = BTreeMap::new();
        for id in &comp.entities {
            shapes.insert(*id, sketch.lookup(*id)?.clone());
        }
        Ok(Self(shapes))
    }
}

/// How a dragged point can move under its constraints, at the state a session is in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Freedom {
    /// In every direction: it goes to the target.
    Free,
    /// Along one direction only (unit): it goes to the target's projection on that line (a
    /// point on a ray, a curve, a circle, where it is now).
    Along(Vector2<f64>),
    /// Not at all: the constraints determine it; updates change nothing.
    Determined,
}

impl Freedom {
    /// The freedom of a point whose achievable moves δP span the range of the symmetric 2 × 2
    /// matrix `g` ([`camber_solve::mobility`]), relative to the unconstrained mobility `scale`.
    fn of(g: [[f64; 2]; 2], scale: f64) -> Self {
        let (a, b, c) = (g[0][0], g[0][1], g[1][1]);
        let mean = 0.5 * (a + c);
        let radius = (0.25 * (a - c) * (a - c) + b * b).sqrt();
        let (l1, l2) = (mean + radius, mean - radius);
        let small = 1e-9 * scale.max(f64::MIN_POSITIVE);
        // The eigenvector of the larger eigenvalue.
        let u = if b.abs() > 1e-300 {
            let v = Vector2::new(l1 - c, b);
            v / v.norm()
        } else if a >= c {
            Vector2::x()
        } else {
            Vector2::y()
        };
        if l2 > small {
            Freedom::Free
        } else if l1 > small {
            Freedom::Along(u)
        } else {
            Freedom::Determined
        }
    }

    /// The unit directions the pin rows hold the point along: both axes, the one direction,
    /// or none.
    fn axes(self) -> SmallVec<[[f64; 2]; 2]> {
        match self {
            Freedom::Free => SmallVec::from_slice(&[[1.0, 0.0], [0.0, 1.0]]),
            Freedom::Along(u) => SmallVec::from_slice(&[[u.x, u.y]]),
            Freedom::Determined => SmallVec::new(),
        }
    }
}

/// a·(Σ cⱼ·Pⱼ − T) = 0 for each direction a: the pin of a dragged point (a combination of the
/// point blocks it reads, all but the last) to the fixed target block T (the last), along the
/// directions the point may move in. Affine.
#[derive(Debug, Clone, PartialEq)]
struct PinTo {
    coeffs: SmallVec<[f64; 4]>,
    axes: SmallVec<[[f64; 2]; 2]>,
}

impl Residual for PinTo {
    fn name(&self) -> &str {
        "drag"
    }
    fn dim(&self) -> usize {
        self.axes.len()
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2; self.coeffs.len() + 1])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        use camber_solve::scalar::cst;
        let target = x[self.coeffs.len()];
        let (mut vx, mut vy) = (T::zero(), T::zero());
        for (c, p) in self.coeffs.iter().zip(x) {
            vx += cst::<T>(*c) * p[0];
            vy += cst::<T>(*c) * p[1];
        }
        let (dx, dy) = (vx - target[0], vy - target[1]);
        for (o, a) in out.iter_mut().zip(&self.axes) {
            *o = cst::<T>(a[0]) * dx + cst::<T>(a[1]) * dy;
        }
    }
    fn is_affine(&self) -> bool {
        true
    }
}

/// How the session holds the point to the cursor (see the module documentation).
#[derive(Debug, Clone)]
enum Pin {
    /// The point's own block, fixed and set to the target.
    Block(BlockId),
    /// Pin rows against the fixed target block.
    Rows {
        /// The target block T.
        target: BlockId,
        /// The pin's residual block.
        residual: ResidualId,
        /// Its combination coefficients.
        coeffs: SmallVec<[f64; 4]>,
    },
    /// A determined point: nothing to pin, updates change nothing.
    Held,
}

/// How far a drag target may lie from the centre of the sketch ([`Sketch::centre`]), in
/// multiples of the sketch's scale ([`Sketch::scale`], the diagonal of its box, at least 1),
/// both taken when the drag starts: a thousand sketches away is surely a slip of the hand or a
/// hostile request, and would wreck the sketch's numbers. [`DragSession::update`] refuses
/// farther targets with [`Error::DragTargetTooFar`], whatever the surface (editor, Python).
pub const MAX_DRAG_REACH: f64 = 1000.0;

/// What an update changed: the entities it moved and every constraint's residual at the new
/// state.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DragUpdate {
    /// The entities of the dragged component whose points (or radius) the update moved, by
    /// increasing id.
    pub moved: Vec<EntityId>,
    /// Each constraint of the component with its residual (max |g| over its rows) at the new
    /// state, by increasing id; the pin rows of the dragged point left out.
    pub residuals: Vec<(ConstraintId, f64)>,
}

/// An interactive drag of one point; see the module documentation.
///
/// ```
/// use camber_sketch::constraints::Fixed;
/// use camber_sketch::{PointRef, Sketch};
/// use camber_geom::BezierCurve2;
/// use nalgebra::Point2;
/// let mut s = Sketch::new();
/// let c = s.add_bezier(BezierCurve2::try_new(vec![
///     Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(2.0, 1.0), Point2::new(3.0, 0.0),
/// ])?)?;
/// s.add_constraint(Fixed::point(PointRef::End(c)))?;
/// let mut drag = s.drag(PointRef::Control(c, 1))?;
/// let moved = drag.update(Point2::new(1.2, 1.5))?.moved.clone();
/// assert_eq!(moved, vec![c]);
/// assert!((drag.point(PointRef::Control(c, 1))?.y - 1.5).abs() < 1e-12);
/// assert!((s.point(PointRef::Control(c, 1))?.y - 1.0).abs() < 1e-15); // not yet committed
/// drag.finish(&mut s)?;
/// assert!((s.point(PointRef::Control(c, 1))?.y - 1.5).abs() < 1e-12);
/// # Ok::<(), camber_sketch::Error>(())
/// ```
#[derive(Debug)]
pub struct DragSession {
    point: PointRef,
    revision: u64,
    /// The component's problem and plan; its values are the session's current state.
    cp: ComponentProblem,
    /// The component's entities at the start (their shapes resolve point references).
    shapes: Shapes,
    options: Options,
    moved: bool,
    pin: Pin,
    /// What the point can do at the current state.
    freedom: Freedom,
    /// The unknowns of the point's x and y, with the combination's coefficients.
    unknowns: [Vec<(UnknownId, f64)>; 2],
    /// Whether the component has constraints with priorities: the cursor is then a wish below
    /// every tier (pin rows of the lowest priority), so no constraint gives way to it.
    wish: bool,
    /// The reduced unknowns at the session's start (a warm start's point before any update).
    z_start: Vec<f64>,
    /// The reduced unknowns of the last accepted update (empty before the first): where the
    /// next update's warm start begins. Not the plan's last solution, which a refused update
    /// (solved, then failing a check of the solved state) leaves at the refused state.
    accepted: Vec<f64>,
    /// The unknowns before an update (scratch: which entities it moved).
    before: Vec<f64>,
    /// What the last update changed (its storage reused by the next).
    last: DragUpdate,
    /// The sketch's centre when the drag began, and the farthest a target may lie from it.
    centre: Point2<f64>,
    reach: f64,
}

/// The mobility of the point with the unknown rows `unknowns` (see [`Freedom::of`]); a large
/// component whose rows turn out dependent has no cheap answer and counts as free.
fn freedom_of(
    cp: &ComponentProblem,
    unknowns: &[Vec<(UnknownId, f64)>; 2],
    options: &Options,
) -> Result<(Freedom, Vec<ConstraintId>)> {
    // The dragged point's own pin rows are not among the constraints it moves under.
    let pin = [DRAG_CONSTRAINT];
    match camber_solve::mobility(&cp.problem, &[&unknowns[0], &unknowns[1]], &pin, options)? {
        Some(m) => Ok((
            Freedom::of([[m.gram[0], m.gram[1]], [m.gram[2], m.gram[3]]], m.scale),
            m.conflicting,
        )),
        None => Ok((Freedom::Free, Vec::new())),
    }
}

/// # Dragging
impl Sketch {
    /// Where a drag target of `point` is measured from and how far it may lie from there
    /// ([`MAX_DRAG_REACH`]): the sketch's centre for a position; the origin for the tangent
    /// block of a Hermite or composite curve, whose value is ±3·(handle − node), so that a handle
    /// within reach gives a tangent within 3·(reach + scale).
    fn drag_limits(&self, point: PointRef) -> (Point2<f64>, f64) {
        let (scale, centre) = (self.scale(), self.centre());
        let reach = MAX_DRAG_REACH * scale;
        let tangent = match point {
            PointRef::Control(e, j) => self.lookup(e).is_ok_and(|e| e.is_tangent_block(j)),
            _ => false,
        };
        if tangent {
            (Point2::origin(), 3.0 * (reach + scale))
        } else {
            (centre, reach)
        }
    }

    /// Starts dragging a point (a point entity, a control point, a line end, a circle centre,
    /// or a curve end).
    ///
    /// # Errors
    /// Id errors; [`Error::Conflicting`] when the constraints of an affine component contradict
    /// each other. A point the constraints determine (a fixed one, say) gives a session whose
    /// [`DragSession::freedom`] is [`Freedom::Determined`] and whose updates change nothing.
    pub fn drag(&self, point: PointRef) -> Result<DragSession> {
        let e = self.lookup(point.entity())?;
        let terms = e.resolve(point)?;
        let comp = self.component_of(point.entity())?;
        let mut cp = self.build_component(&comp)?;
        let options = self.solve_options();
        let mut unknowns: [Vec<(UnknownId, f64)>; 2] = [Vec::new(), Vec::new()];
        let mut blocks: SmallVec<[BlockId; 4]> = SmallVec::new();
        let mut coeffs: SmallVec<[f64; 4]> = SmallVec::new();
        for (j, c) in &terms {
            // A point merged into a coincident one moves with that one's unknowns.
            let block = cp.merged_into(cp.point_block(point.entity(), *j)?);
            for (k, row) in unknowns.iter_mut().enumerate() {
                row.push((cp.problem.unknown(block, k)?, *c));
            }
            match blocks.iter().position(|b| *b == block) {
                Some(at) => coeffs[at] += c,
                None => {
                    blocks.push(block);
                    coeffs.push(*c);
                }
            }
        }
        let (freedom, conflicting) = freedom_of(&cp, &unknowns, &options)?;
        if cp.nonlinear.is_none() && !conflicting.is_empty() {
            return Err(Error::Conflicting {
                constraints: conflicting,
            });
        }
        let wish = cp.problem.has_priorities();
        let own_block = match (blocks.as_slice(), coeffs.as_slice()) {
            ([b], [c]) if (c - 1.0).abs() <= 0.0 => Some(*b),
            _ => None,
        };
        let free_block = own_block.filter(|b| {
            (0..2).all(|k| {
                cp.problem
                    .unknown(*b, k)
                    .and_then(|u| cp.problem.binding(u).cloned())
                    .is_ok_and(|binding| binding == camber_solve::Binding::Free)
            })
        });
        let pin = match (freedom, free_block) {
            (Freedom::Determined, _) => Pin::Held,
            (Freedom::Free, Some(b)) if !wish => {
                cp.problem.fix_block(b)?;
                Pin::Block(b)
            }
            _ => {
                let at = crate::ground::entity::combine(e.points(), &terms);
                let target = cp.problem.add_block(&at)?;
                cp.problem.fix_block(target)?;
                let mut read: SmallVec<[BlockId; 5]> = SmallVec::from_slice(&blocks);
                read.push(target);
                let residual = cp.problem.add_residual(
                    PinTo {
                        coeffs: coeffs.clone(),
                        axes: freedom.axes(),
                    },
                    &read,
                    DRAG_CONSTRAINT,
                )?;
                if wish {
                    cp.problem
                        .set_priority(DRAG_CONSTRAINT, camber_solve::Priority::MAX);
                }
                Pin::Rows {
                    target,
                    residual,
                    coeffs,
                }
            }
        };
        let z_start = cp.problem.reduced_map()?.z0().to_vec();
        let (centre, reach) = self.drag_limits(point);
        Ok(DragSession {
            point,
            revision: self.revision(),
            shapes: Shapes::of(self, &comp)?,
            cp,
            options,
            moved: false,
            pin,
            freedom,
            unknowns,
            wish,
            z_start,
            accepted: Vec::new(),
            before: Vec::new(),
            last: DragUpdate::default(),
            centre,
            reach,
        })
    }
}

impl DragSession {
    /// Moves the dragged point to `target` (or, when it can only slide, to the target's
    /// projection on its direction of freedom) and every other free unknown by the weighted
    /// minimum norm from the current state, keeping every constraint. Returns the entities
    /// that moved and the residuals at the new state (kept in the session until the next
    /// update: a drag allocates nothing per update on the way).
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a bad target; [`Error::DragTargetTooFar`] for one farther than
    /// [`MAX_DRAG_REACH`] sketch scales from the sketch's centre; [`Error::NotSatisfied`],
    /// [`Error::OrientationFlipped`], [`Error::ContactCrossed`], … when the result would break
    /// a constraint (the session keeps its previous state).
    pub fn update(&mut self, target: Point2<f64>) -> Result<&DragUpdate> {
        crate::ground::entity::check_point("target", 0, &target)?;
        if (target - self.centre).norm() > self.reach {
            return Err(Error::DragTargetTooFar {
                x: target.x,
                y: target.y,
                reach: self.reach,
            });
        }
        let block = match &self.pin {
            Pin::Held => {
                self.last.moved.clear();
                self.last.residuals = self.residuals()?;
                return Ok(&self.last);
            }
            Pin::Block(b) => *b,
            Pin::Rows { target, .. } => *target,
        };
        let previous = [
            self.cp.problem.block_values(block)?[0],
            self.cp.problem.block_values(block)?[1],
        ];
        self.before.clear();
        self.before.extend_from_slice(self.cp.problem.values());
        self.cp
            .problem
            .set_block_values(block, &[target.x, target.y])?;
        // An affine component's step does not depend on where it starts.
        let start = if self.cp.nonlinear.is_none() {
            Start::Cold
        } else {
            let from = if self.accepted.is_empty() {
                self.z_start.clone()
            } else {
                self.accepted.clone()
            };
            Start::Warm {
                toward: from.clone(),
                from,
            }
        };
        match crate::component::solve::solve(&mut self.cp, &self.shapes, &self.options, start) {
            Ok(report) => {
                self.moved = true;
                if self.cp.nonlinear.is_some() {
                    self.accepted.clear();
                    self.accepted
                        .extend_from_slice(self.cp.plan.last_solution());
                }
                self.cp
                    .moved_entities_into(&self.before, &mut self.last.moved);
                // The report has one entry per constraint: sorted by id, the pin left out.
                let residuals = &mut self.last.residuals;
                residuals.clear();
                residuals.extend(
                    report
                        .residuals
                        .iter()
                        .filter(|r| r.constraint != DRAG_CONSTRAINT)
                        .map(|r| (r.constraint, r.max_abs)),
                );
                residuals.sort_unstable_by_key(|(c, _)| *c);
                residuals.dedup_by(|later, first| {
                    let same = later.0 == first.0;
                    if same {
                        first.1 = first.1.max(later.1);
                    }
                    same
                });
                self.cp.plan.recycle(report);
                if let (
                    Pin::Rows {
                        residual, coeffs, ..
                    },
                    Freedom::Along(_),
                    true,
                ) = (&self.pin, self.freedom, self.cp.nonlinear.is_some())
                {
                    // The direction of freedom turns as the point slides (on a circle, say).
                    let (residual, coeffs) = (*residual, coeffs.clone());
                    self.refresh_direction(residual, coeffs)?;
                }
                Ok(&self.last)
            }
            Err(e) => {
                // The solve left the problem at its start: move the target back too.
                self.cp.problem.set_block_values(block, &previous)?;
                Err(e)
            }
        }
    }

    /// Watches `cancel` in the solves of the following updates: once it is raised, an update
    /// stops at its next evaluation with [`camber_solve::Error::Cancelled`], the session keeping
    /// its state (an affine component's update, one kept linear step, does not look). None
    /// stops watching.
    pub fn set_cancel(&mut self, cancel: Option<camber_solve::CancelFlag>) {
        self.options.cancel = cancel;
    }

    /// What the last update changed (empty before the first): the value
    /// [`DragSession::update`] returned.
    pub fn last_update(&self) -> &DragUpdate {
        &self.last
    }

    /// Takes the point's direction of freedom again at the current state and turns its pin row
    /// along it (a change of the pin's coefficients only).
    fn refresh_direction(
        &mut self,
        residual: ResidualId,
        coeffs: SmallVec<[f64; 4]>,
    ) -> Result<()> {
        let (freedom, _) = freedom_of(&self.cp, &self.unknowns, &self.options)?;
        if let Freedom::Along(_) = freedom {
            self.freedom = freedom;
            self.cp.problem.replace_residual(
                residual,
                std::sync::Arc::new(PinTo {
                    coeffs,
                    axes: freedom.axes(),
                }),
            )?;
        }
        Ok(())
    }

    /// The dragged point.
    pub fn dragged(&self) -> PointRef {
        self.point
    }

    /// How the dragged point can move: freely, along one direction (it follows the target's
    /// projection there), or not at all (updates are calm no-ops).
    pub fn freedom(&self) -> Freedom {
        self.freedom
    }

    /// Whether the cursor is a wish below every priority tier of the component's constraints
    /// (pin rows of the lowest priority): no constraint gives way to it.
    pub fn is_wish(&self) -> bool {
        self.wish
    }

    /// Every entity of the dragged component as it is now (points and radii).
    ///
    /// # Errors
    /// None in practice (the session's own entities).
    pub fn entities(&self) -> Result<Vec<(EntityId, Entity)>> {
        self.cp.entities_at(&self.shapes, self.cp.problem.values())
    }

    /// One entity of the dragged component as it is now.
    ///
    /// # Errors
    /// [`Error::UnknownEntity`] for an entity outside the component.
    pub fn entity(&self, id: EntityId) -> Result<Entity> {
        self.cp
            .entity_at(&self.shapes, id, self.cp.problem.values())
    }

    /// The free parameters of the component's constraints as they are now: (constraint, k,
    /// value) for the k-th free parameter of each (contact parameters, custom parameters).
    ///
    /// # Errors
    /// None in practice.
    pub fn free_parameters(&self) -> Result<Vec<(ConstraintId, usize, f64)>> {
        self.cp.free_at(self.cp.problem.values())
    }

    /// How far each constraint of the dragged component is from satisfied at the session's
    /// current state: (constraint, max |g| over its rows), by increasing constraint id. The
    /// dragged point's own pin rows are left out. After [`DragSession::finish`] the committed
    /// sketch has the same residuals.
    ///
    /// # Errors
    /// A residual that cannot be evaluated (not for a state an update accepted).
    ///
    /// ```
    /// use camber_sketch::constraints::{Fixed, PointAtParameter};
    /// use camber_sketch::{PointRef, Sketch, Target};
    /// use camber_geom::BezierCurve2;
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let c = s.add_bezier(BezierCurve2::try_new(vec![
    ///     Point2::new(0.0, 0.0), Point2::new(1.0, 2.0), Point2::new(2.0, 0.0),
    /// ])?)?;
    /// s.add_constraint(Fixed::point(PointRef::Start(c)))?; // a binding, no residual row
    /// let mid = s.add_constraint(PointAtParameter { curve: c, u: 0.5, target: Target::At(Point2::new(1.0, 1.0)) })?;
    /// let mut drag = s.drag(PointRef::Control(c, 2))?;
    /// let update = drag.update(Point2::new(2.0, 1.0))?.clone();
    /// let residuals = drag.residuals()?;
    /// assert_eq!(residuals, update.residuals);
    /// assert_eq!(residuals.len(), 1);
    /// assert_eq!(residuals[0].0, mid);
    /// assert!(residuals[0].1 < 1e-12);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn residuals(&self) -> Result<Vec<(ConstraintId, f64)>> {
        let problem = &self.cp.problem;
        let mut g = vec![0.0; problem.num_rows()];
        problem.evaluate_at(problem.values(), &mut g)?;
        let owners = problem.row_owners();
        let mut worst: BTreeMap<ConstraintId, f64> = BTreeMap::new();
        for (owner, v) in owners.iter().zip(&g) {
            if *owner == DRAG_CONSTRAINT {
                continue;
            }
            let slot = worst.entry(*owner).or_insert(0.0);
            *slot = slot.max(v.abs());
        }
        Ok(worst.into_iter().collect())
    }

    /// The current location of a point of the dragged component.
    ///
    /// # Errors
    /// [`Error::UnknownEntity`] for an entity outside the component, [`Error::UnknownPoint`].
    pub fn point(&self, r: PointRef) -> Result<Point2<f64>> {
        let x = self.cp.problem.values();
        let e = r.entity();
        let mut s = [0.0; 2];
        let terms = self.shapes.lookup(e)?.resolve(r)?;
        for (j, k) in terms {
            let i = self.cp.point_unknown(e, j)?;
            s[0] += k * x[i];
            s[1] += k * x[i + 1];
        }
        Ok(Point2::new(s[0], s[1]))
    }

    /// Commits the current state to the sketch (nothing happens if no update succeeded).
    ///
    /// # Errors
    /// [`Error::StaleSession`] when the sketch was edited since the drag began; the sketch is
    /// unchanged then.
    pub fn finish(self, sketch: &mut Sketch) -> Result<()> {
        if sketch.revision() != self.revision {
            return Err(Error::StaleSession {
                expected: self.revision,
                found: sketch.revision(),
            });
        }
        if !self.moved {
            return Ok(());
        }
        let x = self.cp.problem.values();
        let updates = self.cp.entities_at(sketch, x)?;
        let free = self.cp.free_at(x)?;
        let ids: Vec<EntityId> = updates.iter().map(|(id, _)| *id).collect();
        for id in &ids {
            sketch.prepared.forget_entity(*id);
        }
        sketch.commit(updates, &ids);
        // Free parameters moved with the drag: the constraints keep the solved ones.
        sketch.store_free(&free);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::constraints::{Fixed, StartTangent};
    use crate::ground::vocabulary::{Sense, TangentForm};
    use camber_geom::BezierCurve2;

    /// W1's cubic (P₃ fixed, start tangent along D) in the given form, dragged by P₁.
    fn w1(form: TangentForm) -> (Sketch, EntityId, Vector2<f64>) {
        let d = Vector2::new(30f64.to_radians().cos(), 30f64.to_radians().sin());
        let mut s = Sketch::new();
        let c = s
            .add_bezier(
                BezierCurve2::try_new(vec![
                    Point2::origin(),
                    Point2::from(1.2 * d),
                    Point2::new(2.2, 0.9),
                    Point2::new(3.0, 0.0),
                ])
                .unwrap(),
            )
            .unwrap();
        s.add_constraint(Fixed::point(PointRef::Control(c, 3)))
            .unwrap();
        s.add_constraint(StartTangent {
            curve: c,
            direction: d,
            sense: Sense::Agree,
            form,
        })
        .unwrap();
        (s, c, d)
    }

    /// Each update of a drag on W1 in row form lands where a one-off solve from the same state
    /// lands (the dragged point fixed at the target, the rest moved by the minimum norm): the
    /// kept factorization and its dense gain give the step a fresh plan gives, update after
    /// update.
    #[test]
    fn row_form_updates_match_a_fresh_solve_from_the_same_state() {
        let (s, c, d) = w1(TangentForm::Row);
        let mut drag = s.drag(PointRef::Control(c, 1)).unwrap();
        assert_eq!(drag.freedom(), Freedom::Free);
        let p1 = drag.point(PointRef::Control(c, 1)).unwrap();
        for k in 1..=60 {
            let th = std::f64::consts::TAU * f64::from(k) / 60.0;
            let target = p1 + 0.3 * Vector2::new(th.cos() - 1.0, th.sin());
            // The independent reference: the session's state as a sketch, the point set to the
            // target and fixed, solved once.
            let mut reference = s.clone();
            for (id, e) in drag.entities().unwrap() {
                reference.set_entity(id, e).unwrap();
            }
            reference
                .set_point(PointRef::Control(c, 1), target)
                .unwrap();
            reference
                .add_constraint(Fixed::point(PointRef::Control(c, 1)))
                .unwrap();
            reference.solve().unwrap();
            let update = drag.update(target).unwrap().clone();
            assert_eq!(update.moved, vec![c]);
            for j in 0..4 {
                let (a, b) = (
                    drag.point(PointRef::Control(c, j)).unwrap(),
                    reference.point(PointRef::Control(c, j)).unwrap(),
                );
                assert!((a - b).norm() < 1e-12, "update {k} point {j}: {a} {b}");
            }
            let t = drag.point(PointRef::Control(c, 1)).unwrap()
                - drag.point(PointRef::Control(c, 0)).unwrap();
            assert!((t.x * d.y - t.y * d.x).abs() < 1e-12 && t.dot(&d) > 0.0);
            assert!(update.residuals.iter().all(|(_, r)| *r < 1e-12));
            assert_eq!(update.residuals, drag.residuals().unwrap());
        }
    }

    /// In elimination form P₁ = P₀ + t·D, so pinning P₁ to the target q leaves P₀ = q − t·D and
    /// the least move of the unknowns (P₀, t) minimises |q − t·D − P₀|² + (t − t₀)²: by hand,
    /// t = (D·(q − P₀) + t₀)/2 for a unit D. Every update lands there, from where the last left.
    #[test]
    fn elimination_form_updates_move_by_the_hand_derived_minimum_norm() {
        let (s, c, d) = w1(TangentForm::Elimination);
        let mut drag = s.drag(PointRef::Control(c, 1)).unwrap();
        let p1 = drag.point(PointRef::Control(c, 1)).unwrap();
        for k in 1..=60 {
            let th = std::f64::consts::TAU * f64::from(k) / 60.0;
            let q = p1 + 0.3 * Vector2::new(th.cos() - 1.0, th.sin());
            let p0 = drag.point(PointRef::Control(c, 0)).unwrap();
            let t0 = (drag.point(PointRef::Control(c, 1)).unwrap() - p0).dot(&d);
            let t = (d.dot(&(q - p0)) + t0) / 2.0;
            let expected = q - t * d;
            let update = drag.update(q).unwrap().clone();
            assert_eq!(update.moved, vec![c]);
            let (a, b) = (
                drag.point(PointRef::Control(c, 0)).unwrap(),
                drag.point(PointRef::Control(c, 1)).unwrap(),
            );
            assert!((a - expected).norm() < 1e-12, "update {k}: {a} {expected}");
            assert!((b - q).norm() < 1e-12, "update {k}: {b} {q}");
            assert!(update.residuals.iter().all(|(_, r)| *r < 1e-12));
        }
    }
}
