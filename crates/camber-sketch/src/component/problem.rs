//! Building the [`Problem`] of one connected component from its constraints' pieces: a block
//! per entity point (and circle radius), bindings for fixed points and eliminated tangents,
//! merged coincident points, residual blocks for every other piece, and the checks of the
//! solved state.
//!
//! Order matters because bindings do not chain: eliminations are bound first (a target that is
//! fixed, already eliminated, or the base of another elimination falls back to the row form),
//! then fixed points (a fixed point that is an elimination target is held by rows instead),
//! then coincident points are merged (module `merge`), then every other row; a residual
//! reading another constraint's free parameter comes after the constraint that owns it.

use std::collections::HashMap;

use rustc_hash::FxHashMap;
use std::sync::Arc;

use camber_solve::{BlockId, ConstraintId, Problem, Var};
use nalgebra::Point2;
use smallvec::SmallVec;

use super::Component;
use crate::constraints::check::SolvedCheck;
use crate::constraints::piece::{ETerms, Piece, Slot};
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::residuals::{DirectionCross, LineTangency, PointCombination};

pub use crate::ground::ids::DRAG_CONSTRAINT;

/// Blocks of one entity.
/// What of an entity can still move with its component's constraints held (to first order).
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct EntityFreedom {
    /// The entity.
    pub entity: EntityId,
    /// Indices of its points (control points, line ends, a circle's centre) that can move.
    pub points: Vec<usize>,
    /// Indices of its scalars (a circle's radius) that can change.
    pub scalars: Vec<usize>,
}

/// A free parameter of a constraint (a contact parameter, say) that can still change with the
/// component's constraints held (to first order): the contact can slide.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub struct ParameterFreedom {
    /// The constraint owning the parameter.
    pub constraint: ConstraintId,
    /// Which of its free parameters (0 for the first).
    pub parameter: usize,
}

/// Where an entity's blocks are in [`ComponentProblem`]'s list of entity blocks: its points'
/// from `start`, then its scalars'.
#[derive(Debug, Clone, Copy)]
struct EntityBlocks {
    start: usize,
    points: usize,
    scalars: usize,
}

/// The orientation check of a tangency: (Σ c·(x_i, x_{i+1})) · direction > 0, i being the flat
/// index of a point block's x.
#[derive(Debug, Clone)]
pub(crate) struct Orientation {
    pub(crate) constraint: ConstraintId,
    pub(crate) terms: Vec<(usize, f64)>,
    pub(crate) direction: [f64; 2],
}

impl Orientation {
    /// The oriented tangent v = Σ c·(x_i, x_{i+1}) at the unknowns `x`, and the upper bound
    /// Σ|c|·(|x_i| + |x_{i+1}|) of the size of the terms it sums (a missing unknown reads NaN).
    fn tangent(&self, x: &[f64]) -> ([f64; 2], f64) {
        let (mut vx, mut vy, mut bound) = (0.0_f64, 0.0_f64, 0.0_f64);
        for (i, c) in &self.terms {
            let px = x.get(*i).copied().unwrap_or(f64::NAN);
            let py = x.get(*i + 1).copied().unwrap_or(f64::NAN);
            vx += c * px;
            vy += c * py;
            bound += c.abs() * (px.abs() + py.abs());
        }
        ([vx, vy], bound)
    }

    /// The signed dot product v·direction of a tangent v.
    fn dot_of(&self, v: [f64; 2]) -> f64 {
        v[0] * self.direction[0] + v[1] * self.direction[1]
    }

    /// |v|, the length of the oriented tangent v at `x` (with the `bound` of its terms, both
    /// from [`Self::tangent`]), when it has vanished: when it is no more than
    /// [`COLLAPSED_TANGENT`] times the size Σ|c|·|p| of the terms it sums (rounding left over
    /// from points that coincide, whose sign means nothing); `None` otherwise.
    ///
    /// This runs on every drag update, so it decides from the bound when it can: the size is
    /// at most Σ|c|·(|px| + |py|), so a tangent above the threshold of that bound (with a
    /// margin of 1e-9 for the sums' rounding) is not collapsed. That comparison is made on
    /// squares, |v|² > limit², when limit² is a normal number (its margin of 2e-9 is then far
    /// above the rounding of either square, and an overflowed |v|² means |v| > limit); only
    /// a tangent near the threshold pays for |v| and the exact Σ|c|·|p|.
    fn collapsed_given(&self, x: &[f64], v: [f64; 2], bound: f64) -> Option<f64> {
        let limit = COLLAPSED_TANGENT * bound * (1.0 + 1e-9);
        let limit2 = limit * limit;
        if limit2 >= f64::MIN_POSITIVE && v[0] * v[0] + v[1] * v[1] > limit2 {
            return None;
        }
        let speed = v[0].hypot(v[1]);
        if speed > limit {
            return None;
        }
        let size: f64 = self
            .terms
            .iter()
            .map(|(i, c)| {
                let px = x.get(*i).copied().unwrap_or(f64::NAN);
                let py = x.get(*i + 1).copied().unwrap_or(f64::NAN);
                c.abs() * px.hypot(py)
            })
            .sum();
        (speed <= COLLAPSED_TANGENT * size).then_some(speed)
    }
}

/// The relative size below which an oriented tangent counts as vanished (issue 11: a linear
/// solve that collapsed a G1 joint left a tangent of 2e-15 whose sign passed the check, and the
/// next solve of the written-back sketch failed on it).
const COLLAPSED_TANGENT: f64 = 1e-9;

/// A check of the solved state with its owner and the blocks of the owner's free parameters.
#[derive(Debug, Clone)]
pub(crate) struct CheckEntry {
    pub(crate) owner: ConstraintId,
    pub(crate) check: Arc<dyn SolvedCheck>,
    pub(crate) free: SmallVec<[BlockId; 2]>,
}

/// The problem of one component, with the map from entity points to its blocks.
///
/// Built by [`crate::Sketch::component_problem`]; exposed so that callers can inspect the
/// problem (DOF analysis, Jacobian) without solving.
#[derive(Debug)]
pub struct ComponentProblem {
    pub(crate) problem: Problem,
    pub(crate) component: Component,
    /// Every entity with where its blocks are in `blocks`, by increasing id.
    layout: Vec<(EntityId, EntityBlocks)>,
    /// The blocks of all entities, end to end: the first blocks of the problem, block k at
    /// position k.
    blocks: Vec<BlockId>,
    pub(crate) orientations: Vec<Orientation>,
    /// The first constraint whose residual is not affine, with the residual's name.
    pub(crate) nonlinear: Option<(ConstraintId, String)>,
    /// Free parameters (contact parameters, a custom constraint's own unknowns): the owning
    /// constraint and the block of one holding the value, in order per owner.
    pub(crate) free: Vec<(ConstraintId, BlockId)>,
    /// The checks of the solved state, with their owners.
    pub(crate) checks: Vec<CheckEntry>,
    /// Point blocks bound to a coincident one (block, the block whose unknowns it shares), by
    /// increasing block.
    pub(crate) merged: Vec<(BlockId, BlockId)>,
    /// Constraints whose coincidence joined points already merged (redundant).
    pub(crate) merged_redundant: Vec<ConstraintId>,
    /// The policy's plan for this problem: what it keeps between solves (evaluator, Newton's
    /// factorization patterns, the linear path's factorization), so that a change of values
    /// re-solves without being prepared again.
    pub(crate) plan: camber_solve::Plan,
    /// Storage for the state a solve starts from (it goes back there on failure).
    pub(crate) saved: camber_solve::ProblemState,
    /// The starting value of every free parameter, in the order of `free`.
    free_starts: Vec<f64>,
    /// Whether nothing of the problem but its values depends on where the entities were when
    /// it was built (no piece read them, no relaxable rows, no eliminations): another sketch
    /// of the same structure may then be solved on it once its values are refreshed
    /// ([`ComponentProblem::refresh_values`]).
    pub(crate) refreshable: bool,
}

impl ComponentProblem {
    /// The camber-solve problem.
    pub fn problem(&self) -> &Problem {
        &self.problem
    }

    /// The component it was built from.
    pub fn component(&self) -> &Component {
        &self.component
    }

    /// The point blocks and the scalar blocks of an entity, `None` for one outside the
    /// component.
    fn entity_blocks(&self, entity: EntityId) -> Option<(&[BlockId], &[BlockId])> {
        let k = self
            .layout
            .binary_search_by_key(&entity, |(id, _)| *id)
            .ok()?;
        let (_, b) = self.layout.get(k)?;
        let points = self.blocks.get(b.start..b.start + b.points)?;
        let scalars = self
            .blocks
            .get(b.start + b.points..b.start + b.points + b.scalars)?;
        Some((points, scalars))
    }

    /// The block that a point block shares its unknowns with: the representative of its
    /// coincident points when it was merged, else itself.
    pub(crate) fn merged_into(&self, block: BlockId) -> BlockId {
        match self.merged.binary_search_by_key(&block, |(b, _)| *b) {
            Ok(k) => self.merged.get(k).map_or(block, |(_, r)| *r),
            Err(_) => block,
        }
    }

    /// The block of point `index` of an entity.
    ///
    /// # Errors
    /// [`Error::UnknownEntity`] or [`Error::UnknownPoint`].
    pub fn point_block(&self, entity: EntityId, index: usize) -> Result<BlockId> {
        let (points, _) = self
            .entity_blocks(entity)
            .ok_or(Error::UnknownEntity { entity })?;
        points.get(index).copied().ok_or(Error::UnknownPoint {
            entity,
            index,
            count: points.len(),
        })
    }

    /// The block of an entity's `index`-th scalar (a circle's radius).
    fn scalar_block(&self, entity: EntityId, index: usize) -> Result<BlockId> {
        self.entity_blocks(entity)
            .and_then(|(_, scalars)| scalars.get(index).copied())
            .ok_or(Error::UnknownEntity { entity })
    }

    /// The flat index of the x unknown of an entity point.
    pub(crate) fn point_unknown(&self, entity: EntityId, index: usize) -> Result<usize> {
        let b = self.point_block(entity, index)?;
        Ok(self.problem.unknown(b, 0)?.index())
    }

    /// The block of the `k`-th free parameter of a constraint.
    pub(crate) fn free_block(&self, owner: ConstraintId, k: usize) -> Option<BlockId> {
        self.free
            .iter()
            .filter(|(c, _)| *c == owner)
            .nth(k)
            .map(|(_, b)| *b)
    }

    /// Maps terms to (block, coefficient), merging repeated blocks.
    fn blocks_of(&self, terms: &ETerms) -> Result<(SmallVec<[BlockId; 8]>, Vec<f64>)> {
        let mut blocks: SmallVec<[BlockId; 8]> = SmallVec::with_capacity(terms.len());
        let mut coeffs: Vec<f64> = Vec::with_capacity(terms.len());
        for (e, j, c) in terms {
            let b = self.point_block(*e, *j)?;
            match blocks.iter().position(|x| *x == b) {
                Some(k) => coeffs[k] += c,
                None => {
                    blocks.push(b);
                    coeffs.push(*c);
                }
            }
        }
        Ok((blocks, coeffs))
    }

    fn orientation(
        &self,
        constraint: ConstraintId,
        terms: &ETerms,
        direction: [f64; 2],
    ) -> Result<Orientation> {
        let mut flat = Vec::with_capacity(terms.len());
        for (e, j, c) in terms {
            flat.push((self.point_unknown(*e, *j)?, *c));
        }
        Ok(Orientation {
            constraint,
            terms: flat,
            direction,
        })
    }

    /// The block a slot denotes, creating the block of a new free parameter.
    fn slot_block(&mut self, owner: ConstraintId, slot: Slot) -> Result<(BlockId, bool)> {
        Ok(match slot {
            Slot::Point(e, j) => (self.point_block(e, j)?, false),
            Slot::Radius(e) => (self.scalar_block(e, 0)?, false),
            Slot::Free { start, lo, hi } => {
                let b = self.problem.add_block(&[start])?;
                let u = self.problem.unknown(b, 0)?;
                self.problem.set_bounds(Var::Unknown(u), lo, hi)?;
                self.free.push((owner, b));
                self.free_starts.push(start);
                (b, true)
            }
            Slot::FreeOf(other, k) => (
                self.free_block(other, k)
                    .ok_or(Error::UnknownFreeParameter {
                        constraint: owner,
                        of: other,
                        index: k,
                    })?,
                false,
            ),
            Slot::Existing(b) => (b, false),
        })
    }

    pub(crate) fn add_piece(&mut self, owner: ConstraintId, piece: &Piece) -> Result<()> {
        match piece {
            Piece::FixEntity(_) | Piece::FixPoint(..) | Piece::Eliminate { .. } => {}
            Piece::General {
                residual,
                slots,
                check,
            } => {
                if !residual.is_affine() && self.nonlinear.is_none() {
                    self.nonlinear = Some((owner, residual.name().to_owned()));
                }
                let mut blocks: SmallVec<[BlockId; 8]> = SmallVec::with_capacity(slots.len());
                let mut free = SmallVec::new();
                for slot in slots {
                    let (block, new) = self.slot_block(owner, *slot)?;
                    blocks.push(block);
                    if new {
                        free.push(block);
                    }
                }
                self.problem
                    .add_shared_residual(residual.clone(), &blocks, owner)?;
                if let Some(check) = check {
                    self.checks.push(CheckEntry {
                        owner,
                        check: check.clone(),
                        free,
                    });
                }
            }
            Piece::Combination {
                name,
                terms,
                target,
            } => {
                let (blocks, coeffs) = self.blocks_of(terms)?;
                self.problem.add_residual(
                    PointCombination::new(name, coeffs, *target),
                    &blocks,
                    owner,
                )?;
            }
            Piece::Cross {
                name,
                terms,
                direction,
                orient,
            } => {
                let (blocks, coeffs) = self.blocks_of(terms)?;
                self.problem.add_residual(
                    DirectionCross::new(name, coeffs, *direction),
                    &blocks,
                    owner,
                )?;
                if let Some(o) = orient {
                    let check = self.orientation(owner, terms, *o)?;
                    self.orientations.push(check);
                }
            }
            Piece::Line {
                point,
                tangent,
                origin,
                direction,
                orient,
            } => {
                let mut all = point.clone();
                for (e, j, _) in tangent {
                    all.push((*e, *j, 0.0));
                }
                let (blocks, _) = self.blocks_of(&all)?;
                let spread = |terms: &ETerms| -> Result<Vec<f64>> {
                    let mut v = vec![0.0; blocks.len()];
                    for (e, j, c) in terms {
                        let b = self.point_block(*e, *j)?;
                        if let Some(k) = blocks.iter().position(|x| *x == b) {
                            v[k] += c;
                        }
                    }
                    Ok(v)
                };
                let (pc, tc) = (spread(point)?, spread(tangent)?);
                self.problem.add_residual(
                    LineTangency::new(pc, tc, *origin, *direction),
                    &blocks,
                    owner,
                )?;
                let check = self.orientation(owner, tangent, *orient)?;
                self.orientations.push(check);
            }
        }
        Ok(())
    }
}

impl ComponentProblem {
    /// Replaces the residual objects of constraint `id` by those of its new pieces `pieces` (a
    /// dimension's new value), in place: the same rows over the same blocks, so the problem's
    /// structure and the plan's kept state stay. `Ok(false)` when the pieces do not map one to
    /// one onto the constraint's residual blocks, or carry a check or a binding of their own
    /// (the component is then compiled again); the problem may be part-edited then and must be
    /// dropped.
    ///
    /// # Errors
    /// Those of [`camber_solve::Problem::replace_residual`] (a residual of other rows or blocks).
    pub(crate) fn replace_pieces(&mut self, id: ConstraintId, pieces: &[Piece]) -> Result<bool> {
        let owned = self.problem.residuals_of(id);
        let mut new: Vec<Arc<dyn camber_solve::DynResidual>> = Vec::with_capacity(owned.len());
        for piece in pieces {
            match piece {
                Piece::General {
                    residual,
                    check: None,
                    slots,
                } if !slots.iter().any(|s| matches!(s, Slot::Free { .. })) => {
                    new.push(residual.clone());
                }
                Piece::Combination {
                    name,
                    terms,
                    target,
                } => {
                    let (_, coeffs) = self.blocks_of(terms)?;
                    new.push(Arc::new(PointCombination::new(name, coeffs, *target)));
                }
                Piece::Cross {
                    name,
                    terms,
                    direction,
                    orient: None,
                } => {
                    let (_, coeffs) = self.blocks_of(terms)?;
                    new.push(Arc::new(DirectionCross::new(name, coeffs, *direction)));
                }
                _ => return Ok(false),
            }
        }
        if new.len() != owned.len() {
            return Ok(false);
        }
        for (r, residual) in owned.into_iter().zip(new) {
            self.problem.replace_residual(r, residual)?;
        }
        Ok(true)
    }
}

/// Whether a piece reads another constraint's free parameter (it is added last).
fn reads_other_free(piece: &Piece) -> bool {
    matches!(piece, Piece::General { slots, .. } if slots.iter().any(|s| matches!(s, Slot::FreeOf(..))))
}

/// Builds the problem of `component` from its constraints' pieces. The coincidences of
/// `relaxable` constraints (a priority above 0) stay rows: a merge could not give way.
pub(crate) fn build(
    lookup: &dyn EntityLookup,
    component: &Component,
    compiled: &[(ConstraintId, crate::constraints::piece::Pieces)],
    relaxable: &[ConstraintId],
) -> Result<ComponentProblem> {
    let mut cp = ComponentProblem {
        problem: Problem::new(),
        component: component.clone(),
        layout: Vec::with_capacity(component.entities.len()),
        blocks: Vec::new(),
        orientations: Vec::new(),
        nonlinear: None,
        free: Vec::new(),
        checks: Vec::new(),
        merged: Vec::new(),
        merged_redundant: Vec::new(),
        plan: camber_solve::Plan::new(),
        saved: camber_solve::ProblemState::default(),
        free_starts: Vec::new(),
        refreshable: false,
    };
    let mut entities: SmallVec<[&Entity; 16]> = SmallVec::with_capacity(component.entities.len());
    let (mut blocks_needed, mut unknowns_needed) = (0, 0);
    for id in &component.entities {
        let e = lookup.lookup(*id)?;
        let (points, scalars) = (e.points().len(), e.scalars().len());
        blocks_needed += points + scalars;
        unknowns_needed += 2 * points + scalars;
        entities.push(e);
    }
    cp.problem
        .reserve(blocks_needed, unknowns_needed, compiled.len());
    cp.blocks.reserve(blocks_needed);
    for (id, e) in component.entities.iter().zip(entities) {
        let (start, points) = (cp.blocks.len(), e.points().len());
        for (j, p) in e.points().iter().enumerate() {
            let block = cp.problem.add_block(&[p.x, p.y])?;
            let weight = lookup.weight(*id, j);
            if (weight - 1.0).abs() > 0.0 {
                for k in 0..2 {
                    let unknown = cp.problem.unknown(block, k)?;
                    cp.problem.set_weight(Var::Unknown(unknown), weight)?;
                }
            }
            cp.blocks.push(block);
        }
        for s in e.scalars() {
            let block = cp.problem.add_block(&[s])?;
            cp.blocks.push(block);
        }
        let scalars = cp.blocks.len() - start - points;
        cp.layout.push((
            *id,
            EntityBlocks {
                start,
                points,
                scalars,
            },
        ));
    }
    // Components list their entities by id already; sorting keeps the lookups right if not.
    if !cp.layout.is_sorted_by_key(|(id, _)| *id) {
        cp.layout.sort_by_key(|(id, _)| *id);
    }
    // Flags per entity block (block k at index k, see `ComponentProblem::blocks`).
    let flag = |set: &mut [bool], b: BlockId| {
        if let Some(f) = set.get_mut(b.index()) {
            *f = true;
        }
    };
    let is = |set: &[bool], b: BlockId| set.get(b.index()).copied().unwrap_or(false);

    // Points held by `Fixed` (one block each).
    let mut fixed = vec![false; cp.blocks.len()];
    for (_, pieces) in compiled {
        for piece in pieces {
            match piece {
                Piece::FixPoint(e, j) => flag(&mut fixed, cp.point_block(*e, *j)?),
                Piece::FixEntity(e) => {
                    if let Some((points, _)) = cp.entity_blocks(*e) {
                        for b in points {
                            flag(&mut fixed, *b);
                        }
                    }
                }
                _ => {}
            }
        }
    }

    // Eliminations first.
    let (mut targets, mut bases) = (vec![false; cp.blocks.len()], vec![false; cp.blocks.len()]);
    let mut rows: Vec<(ConstraintId, Piece)> = Vec::new();
    for (id, pieces) in compiled {
        for piece in pieces {
            let Piece::Eliminate {
                curve,
                target,
                base,
                direction,
                fallback,
            } = piece
            else {
                continue;
            };
            let tb = cp.point_block(*curve, *target)?;
            let bb = match base {
                Some(base) => Some(cp.point_block(*curve, *base)?),
                None => None,
            };
            let usable = !is(&fixed, tb)
                && !is(&targets, tb)
                && !is(&bases, tb)
                && bb.is_none_or(|bb| !is(&targets, bb));
            if !usable {
                rows.push((*id, (**fallback).clone()));
                continue;
            }
            let p = &cp.problem;
            let (tx, ty) = (p.unknown(tb, 0)?, p.unknown(tb, 1)?);
            let pt = p.values()[tx.index()..=ty.index()].to_vec();
            let pb = match bb {
                Some(bb) => {
                    let (bx, by) = (p.unknown(bb, 0)?, p.unknown(bb, 1)?);
                    Some(([bx, by], p.values()[bx.index()..=by.index()].to_vec()))
                }
                None => None,
            };
            let d = direction;
            let (ex, ey) = match &pb {
                Some((_, v)) => (pt[0] - v[0], pt[1] - v[1]),
                None => (pt[0], pt[1]),
            };
            let dd = d[0] * d[0] + d[1] * d[1];
            let proj = (ex * d[0] + ey * d[1]) / dd;
            // Start on the ray: the projection when it is ahead, else the same distance.
            let t0 = if proj > 0.0 {
                proj
            } else {
                (ex * ex + ey * ey).sqrt() / dd.sqrt()
            };
            let t = match &pb {
                Some((b, _)) => cp.problem.eliminate(&[tx, ty], b, d, t0)?,
                None => {
                    // The target is a tangent vector: T = t·direction.
                    let t = cp.problem.add_aux(t0)?;
                    for (u, dk) in [(tx, d[0]), (ty, d[1])] {
                        cp.problem.substitute(u, &[(Var::Aux(t), dk)], 0.0)?;
                    }
                    t
                }
            };
            cp.problem.set_bounds(Var::Aux(t), 0.0, f64::INFINITY)?;
            flag(&mut targets, tb);
            let mut terms = ETerms::new();
            if let (Some(bb), Some(base)) = (bb, base) {
                flag(&mut bases, bb);
                terms.push((*curve, *base, -1.0));
            }
            terms.push((*curve, *target, 1.0));
            let check = cp.orientation(*id, &terms, *d)?;
            cp.orientations.push(check);
        }
    }

    // Fixed points: bindings, or rows for eliminated targets.
    for (id, pieces) in compiled {
        for piece in pieces {
            let list: Vec<(EntityId, usize)> = match piece {
                Piece::FixPoint(e, j) => vec![(*e, *j)],
                Piece::FixEntity(e) => {
                    let scalars: SmallVec<[BlockId; 2]> = cp
                        .entity_blocks(*e)
                        .map(|(_, s)| s.iter().copied().collect())
                        .unwrap_or_default();
                    for s in scalars {
                        cp.problem.fix_block(s)?;
                    }
                    let n = lookup.lookup(*e)?.points().len();
                    (0..n).map(|j| (*e, j)).collect()
                }
                _ => continue,
            };
            for (e, j) in list {
                let b = cp.point_block(e, j)?;
                if is(&targets, b) {
                    let p: Point2<f64> = lookup.lookup(e)?.points()[j];
                    let mut terms = ETerms::new();
                    terms.push((e, j, 1.0));
                    rows.push((
                        *id,
                        Piece::Combination {
                            name: "fixed",
                            terms,
                            target: [p.x, p.y],
                        },
                    ));
                } else {
                    cp.problem.fix_block(b)?;
                }
            }
        }
    }

    // Coincident points: one set of unknowns per class instead of two rows per pair.
    let lists: Vec<(ConstraintId, &[Piece])> = compiled
        .iter()
        .map(|(id, p)| {
            let pieces: &[Piece] = if relaxable.contains(id) { &[] } else { p };
            (*id, pieces)
        })
        .collect();
    // Fixed points and elimination bases stay the representatives of their classes.
    let anchored: Vec<bool> = fixed.iter().zip(&bases).map(|(f, b)| *f || *b).collect();
    let merges = super::merge::plan(
        &lists,
        &cp.blocks,
        |e, j| cp.point_block(e, j),
        &anchored,
        &targets,
    )?;
    // The members of each class by increasing representative, then block (`into` is by
    // increasing block).
    let mut by_representative: Vec<(BlockId, BlockId)> =
        merges.into.iter().map(|(b, r)| (*r, *b)).collect();
    by_representative.sort_unstable();
    let mut us: SmallVec<[camber_solve::UnknownId; 8]> = SmallVec::new();
    for group in by_representative.chunk_by(|a, b| a.0 == b.0) {
        let Some((r, _)) = group.first() else {
            continue;
        };
        for k in 0..2 {
            let rep = cp.problem.unknown(*r, k)?;
            us.clear();
            for (_, m) in group {
                us.push(cp.problem.unknown(*m, k)?);
            }
            cp.problem.merge_group(rep, &us)?;
        }
    }
    cp.merged = merges.into;
    cp.merged_redundant = merges.redundant;

    let mut later: Vec<(ConstraintId, &Piece)> = Vec::new();
    let mut replaced = merges.replaced.iter().peekable();
    for (ci, (id, pieces)) in compiled.iter().enumerate() {
        for (pi, piece) in pieces.iter().enumerate() {
            // `replaced` is in increasing order, as this walk.
            if replaced.next_if(|at| **at == (ci, pi)).is_some() {
                continue;
            }
            if reads_other_free(piece) {
                later.push((*id, piece));
            } else {
                cp.add_piece(*id, piece)?;
            }
        }
    }
    for (id, piece) in later {
        cp.add_piece(id, piece)?;
    }
    // Every arc's own row (its end on the circle of its centre and start), unless all three
    // of its blocks are fixed.
    for id in &component.entities {
        if let Entity::Arc(_) = lookup.lookup(*id)? {
            let mut free = false;
            for j in 0..3 {
                free |= !is(&fixed, cp.point_block(*id, j)?);
            }
            if free {
                let arc_row = super::arcs::arc_row(*id);
                cp.add_piece(crate::residuals::arc::ARC_ROW, &arc_row)?;
            }
        }
    }
    // Every elliptic arc's two rows (its ends on its ellipse), unless all its blocks are
    // fixed.
    for id in &component.entities {
        if let Entity::EllipticArc { .. } = lookup.lookup(*id)? {
            // A wholly fixed arc needs no rows (they would be constant, so redundant).
            let whole = compiled.iter().any(|(_, pieces)| {
                pieces
                    .iter()
                    .any(|p| matches!(p, Piece::FixEntity(e) if e == id))
            });
            let mut free = false;
            for j in 0..4 {
                free |= !is(&fixed, cp.point_block(*id, j)?);
            }
            free |= !is(&fixed, cp.scalar_block(*id, 0)?);
            if free && !whole {
                for row in super::ellipses::elliptic_arc_rows(*id) {
                    cp.add_piece(crate::residuals::ellipse::ELLIPSE_ROW, &row)?;
                }
            }
        }
    }
    for (id, piece) in &rows {
        cp.add_piece(*id, piece)?;
    }
    Ok(cp)
}

impl ComponentProblem {
    /// Sets the problem's values to what building it from `lookup` would give: every entity's
    /// points and scalars from `lookup`, every free parameter at its starting value. The
    /// structure, the residual objects and the plan stay, so a solve after this is a solve of
    /// a component built from `lookup`, on the kept plan — provided the component's entities
    /// in `lookup` have the shapes, and its constraints the data, the problem was built from,
    /// which the caller checks (`crate::session::batch`).
    ///
    /// `Ok(false)`, with nothing changed, when the problem is not [`Self::refreshable`] or an
    /// entity of `lookup` has other counts of points or scalars.
    ///
    /// # Errors
    /// An entity of the component missing from `lookup`; a non-finite value.
    pub(crate) fn refresh_values(&mut self, lookup: &dyn EntityLookup) -> Result<bool> {
        if !self.refreshable {
            return Ok(false);
        }
        for (id, b) in &self.layout {
            let e = lookup.lookup(*id)?;
            if e.points().len() != b.points || e.scalars().len() != b.scalars {
                return Ok(false);
            }
        }
        for (id, b) in &self.layout {
            let e = lookup.lookup(*id)?;
            let blocks = &self.blocks[b.start..b.start + b.points + b.scalars];
            for (block, p) in blocks.iter().zip(e.points()) {
                self.problem.set_block_values(*block, &[p.x, p.y])?;
            }
            for (block, v) in blocks[b.points..].iter().zip(e.scalars()) {
                self.problem.set_block_values(*block, &[v])?;
            }
        }
        for ((_, block), start) in self.free.iter().zip(&self.free_starts) {
            self.problem.set_block_values(*block, &[*start])?;
        }
        Ok(true)
    }

    /// The entities of the component with their points (and radii) read from the unknowns `x`.
    pub(crate) fn entities_at(
        &self,
        lookup: &dyn EntityLookup,
        x: &[f64],
    ) -> Result<Vec<(EntityId, Entity)>> {
        let mut out = Vec::with_capacity(self.component.entities.len());
        for id in &self.component.entities {
            if self.entity_blocks(*id).is_some() {
                out.push((*id, self.entity_at(lookup, *id, x)?));
            }
        }
        Ok(out)
    }

    /// One entity of the component with its points (and radius) read from the unknowns `x`.
    ///
    /// # Errors
    /// [`Error::UnknownEntity`] for an entity outside the component.
    pub(crate) fn entity_at(
        &self,
        lookup: &dyn EntityLookup,
        id: EntityId,
        x: &[f64],
    ) -> Result<Entity> {
        let e = lookup.lookup(id)?;
        let (points, scalar_blocks) = self
            .entity_blocks(id)
            .ok_or(Error::UnknownEntity { entity: id })?;
        let mut pts = Vec::with_capacity(points.len());
        for b in points {
            let i = self.problem.unknown(*b, 0)?.index();
            pts.push(Point2::new(x[i], x[i + 1]));
        }
        let mut scalars = Vec::with_capacity(scalar_blocks.len());
        for b in scalar_blocks {
            scalars.push(x[self.problem.unknown(*b, 0)?.index()]);
        }
        e.with_points(&pts, &scalars)
    }

    /// The entities whose unknowns differ between `before` and the problem's values, by
    /// increasing id.
    pub(crate) fn moved_entities_into(&self, before: &[f64], moved: &mut Vec<EntityId>) {
        moved.clear();
        for (id, b) in &self.layout {
            let blocks = &self.blocks[b.start..b.start + b.points + b.scalars];
            let differs = blocks.iter().any(|block| {
                self.problem.block_values(*block).is_ok_and(|values| {
                    let start = self
                        .problem
                        .unknown(*block, 0)
                        .map_or(usize::MAX, |u| u.index());
                    values.iter().enumerate().any(|(k, v)| {
                        before
                            .get(start + k)
                            .is_none_or(|w| w.to_bits() != v.to_bits())
                    })
                })
            });
            if differs {
                moved.push(*id);
            }
        }
    }

    /// Which points and scalars of each entity can still move with the constraints held (to
    /// first order), given the free columns of the DOF analysis (reduced unknowns, see
    /// [`camber_solve::RowAnalysis::free_columns`]): an unknown is free when its
    /// reduced form x = A·z + c reads a free column. Entities with nothing free are left out.
    ///
    /// # Errors
    /// Building the reduced map fails (it does not once the problem was analysed).
    pub(crate) fn freedom(&self, free_columns: &[usize]) -> Result<Vec<EntityFreedom>> {
        let map = self.problem.reduced_map()?;
        let mut free = vec![false; map.vars().len()];
        for c in free_columns {
            if let Some(f) = free.get_mut(*c) {
                *f = true;
            }
        }
        let moves = |b: BlockId, k: usize| -> Result<bool> {
            let u = self.problem.unknown(b, k)?.index();
            Ok(map
                .row(u)
                .0
                .iter()
                .any(|(c, a)| *a != 0.0 && free.get(*c).copied().unwrap_or(false)))
        };
        let mut out = Vec::new();
        for id in &self.component.entities {
            let Some((point_blocks, scalar_blocks)) = self.entity_blocks(*id) else {
                continue;
            };
            let mut points = Vec::new();
            for (i, b) in point_blocks.iter().enumerate() {
                if moves(*b, 0)? || moves(*b, 1)? {
                    points.push(i);
                }
            }
            let mut scalars = Vec::new();
            for (i, b) in scalar_blocks.iter().enumerate() {
                if moves(*b, 0)? {
                    scalars.push(i);
                }
            }
            if !points.is_empty() || !scalars.is_empty() {
                out.push(EntityFreedom {
                    entity: *id,
                    points,
                    scalars,
                });
            }
        }
        Ok(out)
    }

    /// Which constraints' free parameters can still change, given the free columns of the DOF
    /// analysis (as [`ComponentProblem::freedom`] for entities), in constraint order.
    ///
    /// # Errors
    /// Building the reduced map fails (it does not once the problem was analysed).
    pub(crate) fn parameter_freedom(
        &self,
        free_columns: &[usize],
    ) -> Result<Vec<ParameterFreedom>> {
        let map = self.problem.reduced_map()?;
        let mut out = Vec::new();
        let mut seen: FxHashMap<ConstraintId, usize> = FxHashMap::default();
        for (c, b) in &self.free {
            let count = seen.entry(*c).or_insert(0);
            let parameter = *count;
            *count += 1;
            let u = self.problem.unknown(*b, 0)?.index();
            // `free_columns` is increasing.
            if map
                .row(u)
                .0
                .iter()
                .any(|(col, a)| *a != 0.0 && free_columns.binary_search(col).is_ok())
            {
                out.push(ParameterFreedom {
                    constraint: *c,
                    parameter,
                });
            }
        }
        Ok(out)
    }

    /// The solved free parameters at `x`: (constraint, k, value) for the k-th free parameter
    /// of each constraint.
    pub(crate) fn free_at(&self, x: &[f64]) -> Result<Vec<(ConstraintId, usize, f64)>> {
        let mut out: Vec<(ConstraintId, usize, f64)> = Vec::with_capacity(self.free.len());
        let mut seen: FxHashMap<ConstraintId, usize> = FxHashMap::default();
        for (c, b) in &self.free {
            let k = seen.entry(*c).or_insert(0);
            out.push((*c, *k, x[self.problem.unknown(*b, 0)?.index()]));
            *k += 1;
        }
        Ok(out)
    }

    /// The value of a block of one at the unknowns `x`.
    pub(crate) fn block_value(&self, x: &[f64], b: BlockId) -> Result<f64> {
        Ok(x[self.problem.unknown(b, 0)?.index()])
    }

    /// Runs the checks of the solved state on the entities solved at `x`, allowing a
    /// penetration of `tolerance` (length units); `before` holds the entities before the solve.
    pub(crate) fn check_solved(
        &self,
        before: &dyn EntityLookup,
        solved: &[(EntityId, Entity)],
        x: &[f64],
        tolerance: f64,
    ) -> Result<()> {
        if self.checks.is_empty() {
            return Ok(());
        }
        let map: HashMap<EntityId, &Entity> = solved.iter().map(|(id, e)| (*id, e)).collect();
        let mut free: SmallVec<[f64; 2]> = SmallVec::new();
        for entry in &self.checks {
            free.clear();
            for b in &entry.free {
                free.push(self.block_value(x, *b)?);
            }
            entry
                .check
                .verify(&crate::constraints::check::SolvedState {
                    owner: entry.owner,
                    solved: &map,
                    before,
                    free: &free,
                    penetration: tolerance,
                })?;
        }
        Ok(())
    }

    /// The first orientation check that fails at `x`, as an error.
    pub(crate) fn check_orientations(&self, x: &[f64]) -> Result<()> {
        for o in &self.orientations {
            let (v, bound) = o.tangent(x);
            if let Some(speed) = o.collapsed_given(x, v, bound) {
                return Err(Error::Cusp {
                    constraint: o.constraint,
                    speed,
                });
            }
            let dot = o.dot_of(v);
            if dot.is_nan() || dot <= 0.0 {
                return Err(Error::OrientationFlipped {
                    constraint: o.constraint,
                    dot,
                });
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The direct definition: |v| when |v| ≤ COLLAPSED_TANGENT·Σ|c|·|p|.
    fn collapsed_directly(o: &Orientation, x: &[f64]) -> Option<f64> {
        let (mut vx, mut vy, mut size) = (0.0_f64, 0.0_f64, 0.0_f64);
        for (i, c) in &o.terms {
            let (px, py) = (x[*i], x[*i + 1]);
            vx += c * px;
            vy += c * py;
            size += c.abs() * px.hypot(py);
        }
        let speed = vx.hypot(vy);
        (speed <= COLLAPSED_TANGENT * size).then_some(speed)
    }

    proptest! {
        /// The bounded test gives the direct answer, on tangents far from, near and exactly at
        /// collapse (two points that coincide up to a relative `gap`), at magnitudes whose
        /// squares underflow or overflow.
        #[test]
        fn the_bounded_collapse_test_matches_the_direct_one(
            p in prop::array::uniform2(-1e3..1e3_f64),
            q in prop::array::uniform2(-1e3..1e3_f64),
            gap in prop::sample::select(vec![0.0, 1e-15, 1e-12, 1e-10, 1e-9, 1e-8, 1e-3]),
            scale in -5.0..5.0_f64,
            magnitude in prop::sample::select(vec![1e-165, 1e-150, 1e-100, 1.0, 1e100, 1e150, 1e160]),
        ) {
            let (p, q) = (p.map(|v| v * magnitude), q.map(|v| v * magnitude));
            let x = [p[0], p[1], p[0] * (1.0 + gap) + q[0] * gap, p[1] * (1.0 - gap) + q[1] * gap];
            let o = Orientation {
                constraint: ConstraintId(0),
                terms: vec![(2, scale), (0, -scale)],
                direction: [1.0, 0.0],
            };
            let (v, bound) = o.tangent(&x);
            prop_assert_eq!(o.collapsed_given(&x, v, bound), collapsed_directly(&o, &x));
        }
    }
}
