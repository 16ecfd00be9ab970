//! Building the [`Problem`] of one connected component: a block per entity point, bindings for
//! fixed points and eliminated tangents, residual blocks for every other piece, and the
//! orientation checks of the tangencies.
//!
//! Order matters because bindings do not chain: eliminations are bound first (a target that is
//! fixed, already eliminated, or the base of another elimination falls back to the row form),
//! then fixed points (a fixed point that is an elimination target is held by rows instead),
//! then coincident points are merged (module `merge`), then every other row.

use std::collections::{HashMap, HashSet};

use camber_solve::{BlockId, ConstraintId, Problem, Var};
use nalgebra::Point2;

use crate::compile::{compile, ETerms, EntityLookup, Piece};
use crate::entity::Entity;
use crate::errors::{Error, Result};
use crate::general::{Check, CheckParam, Slot};
use crate::ids::{EntityId, PointRef};
use crate::residuals::{DirectionCross, LineTangency, PointCombination};

/// The constraint id owning the rows that pin a dragged point.
pub const DRAG_CONSTRAINT: ConstraintId = ConstraintId(u64::MAX);

/// A connected component of the sketch graph: entities and the constraints between them,
/// each sorted by id.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Component {
    /// The entities.
    pub entities: Vec<EntityId>,
    /// The constraints.
    pub constraints: Vec<ConstraintId>,
}

/// A custom constraint's residual, shared between the sketch and every problem built from it.
#[derive(Debug)]
struct SharedResidual(std::sync::Arc<dyn camber_solve::DynResidual>);

impl camber_solve::DynResidual for SharedResidual {
    fn name(&self) -> &str {
        self.0.name()
    }
    fn dim(&self) -> usize {
        self.0.dim()
    }
    fn is_affine(&self) -> bool {
        self.0.is_affine()
    }
    fn values(&self, x: &[&[f64]], out: &mut [f64]) -> camber_solve::Result<()> {
        self.0.values(x, out)
    }
    fn jacobian(
        &self,
        x: &[&[f64]],
        values: &mut [f64],
        jac: &mut [f64],
    ) -> camber_solve::Result<()> {
        self.0.jacobian(x, values, jac)
    }
    fn jacobian_active(
        &self,
        x: &[&[f64]],
        active: &[bool],
        values: &mut [f64],
        jac: &mut [f64],
    ) -> camber_solve::Result<()> {
        self.0.jacobian_active(x, active, values, jac)
    }
    fn weighted_hessian(
        &self,
        x: &[&[f64]],
        weights: &[f64],
        active: &[bool],
        out: &mut [f64],
    ) -> camber_solve::Result<bool> {
        self.0.weighted_hessian(x, weights, active, out)
    }
    fn as_any(&self) -> &dyn std::any::Any {
        self.0.as_any()
    }
}

/// Blocks of one entity.
#[derive(Debug, Clone)]
struct EntityBlocks {
    points: Vec<BlockId>,
    scalars: Vec<BlockId>,
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
    /// The signed dot product at the unknowns `x`.
    pub(crate) fn dot(&self, x: &[f64]) -> f64 {
        let (mut vx, mut vy) = (0.0, 0.0);
        for (i, c) in &self.terms {
            vx += c * x.get(*i).copied().unwrap_or(f64::NAN);
            vy += c * x.get(*i + 1).copied().unwrap_or(f64::NAN);
        }
        vx * self.direction[0] + vy * self.direction[1]
    }
}

/// The problem of one component, with the map from entity points to its blocks.
///
/// Built by [`crate::Sketch::component_problem`]; exposed so that callers can inspect the
/// problem (DOF analysis, Jacobian) without solving.
#[derive(Debug)]
pub struct ComponentProblem {
    pub(crate) problem: Problem,
    pub(crate) component: Component,
    layout: HashMap<EntityId, EntityBlocks>,
    pub(crate) orientations: Vec<Orientation>,
    /// The first constraint whose residual is not affine, with the residual's name.
    pub(crate) nonlinear: Option<(ConstraintId, String)>,
    /// Free contact parameters: the owning constraint and the block of one holding u.
    pub(crate) contacts: Vec<(ConstraintId, BlockId)>,
    /// The honesty checks of contacts, joints and angles, with their owners.
    pub(crate) checks: Vec<(ConstraintId, Check)>,
    /// Point blocks bound to a coincident one (block → the block whose unknowns it shares).
    pub(crate) merged: HashMap<BlockId, BlockId>,
    /// Constraints whose coincidence joined points already merged (redundant).
    pub(crate) merged_redundant: Vec<ConstraintId>,
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

    /// The block of point `index` of an entity.
    ///
    /// # Errors
    /// [`Error::UnknownEntity`] or [`Error::UnknownPoint`].
    pub fn point_block(&self, entity: EntityId, index: usize) -> Result<BlockId> {
        let blocks = self
            .layout
            .get(&entity)
            .ok_or(Error::UnknownEntity { entity })?;
        blocks
            .points
            .get(index)
            .copied()
            .ok_or(Error::UnknownPoint {
                entity,
                index,
                count: blocks.points.len(),
            })
    }

    /// The flat index of the x unknown of an entity point.
    pub(crate) fn point_unknown(&self, entity: EntityId, index: usize) -> Result<usize> {
        let b = self.point_block(entity, index)?;
        Ok(self.problem.unknown(b, 0)?.index())
    }

    /// Maps terms to (block, coefficient), merging repeated blocks.
    fn blocks_of(&self, terms: &ETerms) -> Result<(Vec<BlockId>, Vec<f64>)> {
        let mut blocks: Vec<BlockId> = Vec::with_capacity(terms.len());
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

    pub(crate) fn add_piece(&mut self, owner: ConstraintId, piece: &Piece) -> Result<()> {
        match piece {
            Piece::FixEntity(_) | Piece::FixPoint(..) | Piece::Eliminate { .. } => {}
            Piece::General {
                name,
                residual,
                slots,
                check,
            } => {
                if !residual.is_affine() && self.nonlinear.is_none() {
                    self.nonlinear = Some((owner, (*name).to_owned()));
                }
                let mut blocks = Vec::with_capacity(slots.len());
                let mut contact_blocks = Vec::with_capacity(slots.len());
                for slot in slots {
                    let (block, contact) = match *slot {
                        Slot::Point(e, j) => (self.point_block(e, j)?, None),
                        Slot::Radius(e) => {
                            let b = self
                                .layout
                                .get(&e)
                                .and_then(|b| b.scalars.first().copied())
                                .ok_or(Error::UnknownEntity { entity: e })?;
                            (b, None)
                        }
                        Slot::Contact { u0, lo, hi } => {
                            let b = self.problem.add_block(&[u0])?;
                            let u = self.problem.unknown(b, 0)?;
                            self.problem.set_bounds(Var::Unknown(u), lo, hi)?;
                            self.contacts.push((owner, b));
                            (b, Some(b))
                        }
                        Slot::Existing(b) => (b, None),
                    };
                    blocks.push(block);
                    contact_blocks.push(contact);
                }
                self.problem.add_dyn_residual(
                    Box::new(SharedResidual(residual.clone())),
                    &blocks,
                    owner,
                )?;
                if let Some(c) = check {
                    self.checks.push((owner, c.resolved(&contact_blocks)));
                }
            }
            Piece::Custom { residual, points } => {
                if !residual.is_affine() && self.nonlinear.is_none() {
                    self.nonlinear = Some((owner, residual.name().to_owned()));
                }
                let mut blocks = Vec::with_capacity(points.len());
                for (e, j) in points {
                    blocks.push(self.point_block(*e, *j)?);
                }
                self.problem.add_dyn_residual(
                    Box::new(SharedResidual(residual.clone())),
                    &blocks,
                    owner,
                )?;
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

/// Builds the problem of `component`, with the rows pinning `pin` (if any) at its current
/// position last, owned by [`DRAG_CONSTRAINT`].
pub(crate) fn build<L: EntityLookup>(
    lookup: &L,
    component: &Component,
    constraints: &[(ConstraintId, &crate::Constraint)],
    pin: Option<PointRef>,
) -> Result<ComponentProblem> {
    let mut cp = ComponentProblem {
        problem: Problem::new(),
        component: component.clone(),
        layout: HashMap::with_capacity(component.entities.len()),
        orientations: Vec::new(),
        nonlinear: None,
        contacts: Vec::new(),
        checks: Vec::new(),
        merged: HashMap::new(),
        merged_redundant: Vec::new(),
    };
    for id in &component.entities {
        let e = lookup.lookup(*id)?;
        let mut blocks = EntityBlocks {
            points: Vec::with_capacity(e.points().len()),
            scalars: Vec::new(),
        };
        for (j, p) in e.points().iter().enumerate() {
            let block = cp.problem.add_block(&[p.x, p.y])?;
            let weight = lookup.weight(*id, j);
            if (weight - 1.0).abs() > 0.0 {
                for k in 0..2 {
                    let unknown = cp.problem.unknown(block, k)?;
                    cp.problem.set_weight(Var::Unknown(unknown), weight)?;
                }
            }
            blocks.points.push(block);
        }
        for s in e.scalars() {
            blocks.scalars.push(cp.problem.add_block(&[s])?);
        }
        cp.layout.insert(*id, blocks);
    }
    let mut compiled = Vec::with_capacity(constraints.len());
    for (id, c) in constraints {
        compiled.push((*id, compile(lookup, c)?));
    }

    // Points held by `Fixed` (one block each).
    let mut fixed: HashSet<BlockId> = HashSet::new();
    for (_, pieces) in &compiled {
        for piece in pieces {
            match piece {
                Piece::FixPoint(e, j) => {
                    fixed.insert(cp.point_block(*e, *j)?);
                }
                Piece::FixEntity(e) => {
                    if let Some(b) = cp.layout.get(e) {
                        fixed.extend(b.points.iter().copied());
                    }
                }
                _ => {}
            }
        }
    }

    // Eliminations first.
    let (mut targets, mut bases): (HashSet<BlockId>, HashSet<BlockId>) = Default::default();
    let mut rows: Vec<(ConstraintId, Piece)> = Vec::new();
    for (id, pieces) in &compiled {
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
            let (tb, bb) = (
                cp.point_block(*curve, *target)?,
                cp.point_block(*curve, *base)?,
            );
            let usable = !fixed.contains(&tb)
                && !targets.contains(&tb)
                && !bases.contains(&tb)
                && !targets.contains(&bb);
            if !usable {
                rows.push((*id, (**fallback).clone()));
                continue;
            }
            let p = &cp.problem;
            let (tx, ty) = (p.unknown(tb, 0)?, p.unknown(tb, 1)?);
            let (bx, by) = (p.unknown(bb, 0)?, p.unknown(bb, 1)?);
            let (pt, pb) = (p.values()[tx.index()..=ty.index()].to_vec(), {
                p.values()[bx.index()..=by.index()].to_vec()
            });
            let d = direction;
            let (ex, ey) = (pt[0] - pb[0], pt[1] - pb[1]);
            let dd = d[0] * d[0] + d[1] * d[1];
            let proj = (ex * d[0] + ey * d[1]) / dd;
            // Start on the ray: the projection when it is ahead, else the same distance.
            let t0 = if proj > 0.0 {
                proj
            } else {
                (ex * ex + ey * ey).sqrt() / dd.sqrt()
            };
            let t = cp.problem.eliminate(&[tx, ty], &[bx, by], d, t0)?;
            cp.problem.set_bounds(Var::Aux(t), 0.0, f64::INFINITY)?;
            targets.insert(tb);
            bases.insert(bb);
            let mut terms = ETerms::new();
            terms.push((*curve, *base, -1.0));
            terms.push((*curve, *target, 1.0));
            let check = cp.orientation(*id, &terms, *d)?;
            cp.orientations.push(check);
        }
    }

    // Fixed points: bindings, or rows for eliminated targets.
    for (id, pieces) in &compiled {
        for piece in pieces {
            let list: Vec<(EntityId, usize)> = match piece {
                Piece::FixPoint(e, j) => vec![(*e, *j)],
                Piece::FixEntity(e) => {
                    if let Some(b) = cp.layout.get(e) {
                        for s in b.scalars.clone() {
                            cp.problem.fix_block(s)?;
                        }
                    }
                    let n = lookup.lookup(*e)?.points().len();
                    (0..n).map(|j| (*e, j)).collect()
                }
                _ => continue,
            };
            for (e, j) in list {
                let b = cp.point_block(e, j)?;
                if targets.contains(&b) {
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
    let lists: Vec<(ConstraintId, &[Piece])> =
        compiled.iter().map(|(id, p)| (*id, p.as_slice())).collect();
    let merges = crate::merge::plan(
        &lists,
        |e, j| cp.point_block(e, j),
        &fixed,
        &targets,
        &bases,
    )?;
    let mut groups: HashMap<BlockId, Vec<BlockId>> = HashMap::new();
    for (b, r) in &merges.into {
        groups.entry(*r).or_default().push(*b);
    }
    let mut representatives: Vec<_> = groups.into_iter().collect();
    representatives.sort_unstable_by_key(|(r, _)| *r);
    for (r, members) in &representatives {
        for k in 0..2 {
            let rep = cp.problem.unknown(*r, k)?;
            let mut us = Vec::with_capacity(members.len());
            for m in members {
                us.push(cp.problem.unknown(*m, k)?);
            }
            cp.problem.merge_group(rep, &us)?;
        }
        for m in members {
            cp.merged.insert(*m, *r);
        }
    }
    cp.merged_redundant = merges.redundant;

    for (ci, (id, pieces)) in compiled.iter().enumerate() {
        for (pi, piece) in pieces.iter().enumerate() {
            if !merges.replaced.contains(&(ci, pi)) {
                cp.add_piece(*id, piece)?;
            }
        }
    }
    for (id, piece) in &rows {
        cp.add_piece(*id, piece)?;
    }
    if let Some(r) = pin {
        let t = lookup.lookup(r.entity())?.resolve(r)?;
        let mut terms = ETerms::new();
        for (j, c) in &t {
            terms.push((r.entity(), *j, *c));
        }
        let at = crate::entity::combine(lookup.lookup(r.entity())?.points(), &t);
        cp.add_piece(
            DRAG_CONSTRAINT,
            &Piece::Combination {
                name: "drag",
                terms,
                target: at,
            },
        )?;
    }
    Ok(cp)
}

impl ComponentProblem {
    /// The entities of the component with their points (and radii) read from the unknowns `x`.
    pub(crate) fn entities_at<L: EntityLookup>(
        &self,
        lookup: &L,
        x: &[f64],
    ) -> Result<Vec<(EntityId, Entity)>> {
        let mut out = Vec::with_capacity(self.component.entities.len());
        for id in &self.component.entities {
            let e = lookup.lookup(*id)?;
            let Some(blocks) = self.layout.get(id) else {
                continue;
            };
            let mut pts = Vec::with_capacity(blocks.points.len());
            for b in &blocks.points {
                let i = self.problem.unknown(*b, 0)?.index();
                pts.push(Point2::new(x[i], x[i + 1]));
            }
            let mut scalars = Vec::with_capacity(blocks.scalars.len());
            for b in &blocks.scalars {
                scalars.push(x[self.problem.unknown(*b, 0)?.index()]);
            }
            out.push((*id, e.with_points(&pts, &scalars)?));
        }
        Ok(out)
    }

    /// The solved free contact parameters at `x`, with their constraints.
    pub(crate) fn contacts_at(&self, x: &[f64]) -> Result<Vec<(ConstraintId, usize, f64)>> {
        let mut out: Vec<(ConstraintId, usize, f64)> = Vec::with_capacity(self.contacts.len());
        for (c, b) in &self.contacts {
            // The k-th free parameter of its constraint (clearance rows add none).
            let k = out.iter().filter(|(o, _, _)| o == c).count();
            out.push((*c, k, x[self.problem.unknown(*b, 0)?.index()]));
        }
        Ok(out)
    }

    /// A check's parameter at the unknowns `x` (NaN for an unresolved slot).
    pub(crate) fn check_param(&self, x: &[f64], p: CheckParam) -> Result<f64> {
        Ok(match p {
            CheckParam::Fixed(u) => u,
            CheckParam::Block(b) => x[self.problem.unknown(b, 0)?.index()],
            CheckParam::Slot(_) => f64::NAN,
        })
    }

    /// Runs the contact, joint and angle checks on the entities solved at `x`, allowing a
    /// penetration of `tolerance` (length units).
    pub(crate) fn check_contacts(
        &self,
        solved: &[(EntityId, Entity)],
        x: &[f64],
        tolerance: f64,
    ) -> Result<()> {
        if self.checks.is_empty() {
            return Ok(());
        }
        let map: HashMap<EntityId, &Entity> = solved.iter().map(|(id, e)| (*id, e)).collect();
        let param = |p: CheckParam| self.check_param(x, p);
        for (owner, check) in &self.checks {
            check.verify(*owner, &map, &param, tolerance)?;
        }
        Ok(())
    }

    /// The first orientation check that fails at `x`, as an error.
    pub(crate) fn check_orientations(&self, x: &[f64]) -> Result<()> {
        for o in &self.orientations {
            let dot = o.dot(x);
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
