//! Drag sessions: the interactive loop.
//!
//! **Affine components.** The component's problem is built once with the
//! dragged point pinned by two extra rows, P − anchor = 0 (anchor = where the point was);
//! the rows are analysed once, and the weighted minimum-norm factorization of the independent
//! rows is cached. Moving the target to q changes only the right-hand side of the pin rows,
//! by −(q − anchor), because every residual is affine and J does not change. So an update is:
//!
//! 1. g ← g(z) with the pin rows shifted by −(q − anchor);
//! 2. Δz = −W⁻¹Jᵀ(JW⁻¹Jᵀ)⁻¹g (two triangular solves, one product with Jᵀ, refined);
//! 3. z ← z + Δz, x = A·z + c, residuals re-evaluated, orientations checked;
//! 4. the new state is kept only if every row is within tolerance and no tangent flipped.
//!
//! Each update starts from the current state of the session (the result of the previous
//! update), so the displacement per mouse event is the minimum-norm one. Nothing allocates in
//! an update on the dense backend (components of up to `dense_max_unknowns` reduced unknowns)
//! as long as no residual reads more than 8 blocks. The sketch itself is unchanged until
//! [`DragSession::finish`].
//!
//! **Nonlinear components.** J changes with the unknowns, so the problem is built once and only
//! its values change. The dragged point (a single free block) is fixed in the problem and set
//! to the target at each update; the component's solve policy (`component::policy`)
//! then runs warm: Newton minimum norm starts from the previous step's solution and pulls
//! toward it, so each step moves the rest of the sketch as little as it can, with the full
//! selection as fallback, the orientation and contact checks of a solve, and the active set of
//! honest contact (a step that would cross a target gets its clearance row instead of being
//! refused). If that fails too, the session keeps its previous state.

use std::collections::BTreeMap;

use camber_solve::analysis::analyze;
use camber_solve::{MinNormFactorization, ReducedMap};
use nalgebra::Point2;

use crate::component::policy::{self, Start};
use crate::component::{Component, ComponentProblem, DRAG_CONSTRAINT};
use crate::entity::Entity;
use crate::errors::{Error, Result};
use crate::ids::{EntityId, PointRef};
use crate::lookup::EntityLookup;
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

/// Refinement rounds after each minimum-norm step.
const REFINEMENT_STEPS: usize = 2;

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
/// drag.update(Point2::new(1.2, 1.5))?;
/// assert!((drag.point(PointRef::Control(c, 1))?.y - 1.5).abs() < 1e-12);
/// assert!((s.point(PointRef::Control(c, 1))?.y - 1.0).abs() < 1e-15); // not yet committed
/// drag.finish(&mut s)?;
/// assert!((s.point(PointRef::Control(c, 1))?.y - 1.5).abs() < 1e-12);
/// # Ok::<(), camber_sketch::Error>(())
/// ```
#[derive(Debug)]
#[allow(clippy::large_enum_variant)] // one session per drag, made once and never moved in a loop
pub enum DragSession {
    /// A drag on an affine component: the cached minimum-norm factorization.
    Affine(AffineDrag),
    /// A drag on a nonlinear component: the component's solve policy, warm started.
    Nonlinear(NonlinearDrag),
}

/// What every drag session holds.
#[derive(Debug)]
struct Common {
    point: PointRef,
    revision: u64,
    cp: ComponentProblem,
    /// The component's entities at the start (their shapes resolve point references).
    shapes: Shapes,
    moved: bool,
    /// The current unknowns (all of them, fixed ones included).
    x: Vec<f64>,
}

/// The state of a drag on an affine component (see the module documentation).
#[derive(Debug)]
pub struct AffineDrag {
    common: Common,
    map: ReducedMap,
    factorization: MinNormFactorization,
    /// Rows of J kept (independent), and the two pin rows' positions in g.
    rows: Vec<usize>,
    row_owner: Vec<camber_solve::ConstraintId>,
    pin: [usize; 2],
    anchor: [f64; 2],
    tolerance: f64,
    // Current state (pin rows of g relative to the anchor) and scratch.
    z: Vec<f64>,
    g: Vec<f64>,
    z_new: Vec<f64>,
    x_new: Vec<f64>,
    g_new: Vec<f64>,
    g_sel: Vec<f64>,
    dz: Vec<f64>,
}

/// The state of a drag on a nonlinear component: the dragged block is fixed in the problem and
/// moved to the target at each update; the component's solve policy runs from the previous
/// step's solution, pulling toward it.
#[derive(Debug)]
pub struct NonlinearDrag {
    common: Common,
    block: camber_solve::BlockId,
    /// The reduced unknowns of the current state.
    z: Vec<f64>,
    options: camber_solve::Options,
}

/// # Dragging
impl Sketch {
    /// Starts dragging a point (a point entity, a control point, a line end, a circle centre,
    /// or a curve end).
    ///
    /// # Errors
    /// Id errors; [`Error::Conflicting`] when the component's constraints contradict each other;
    /// [`Error::NotDraggable`] when the point is fixed or determined by the constraints (on a
    /// nonlinear component: when it is not a single free point block).
    pub fn drag(&self, point: PointRef) -> Result<DragSession> {
        let e = self.lookup(point.entity())?;
        e.resolve(point)?;
        let comp = self.component_of(point.entity())?;
        let plain = self.build_component(&comp, None)?;
        if plain.nonlinear.is_some() {
            return self.drag_nonlinear(point, &comp, plain);
        }
        let cp = self.build_component(&comp, Some(point))?;
        let options = self.options();
        let lin = cp.problem().linearize()?;
        let (m, n) = (lin.g.len(), lin.map.len());
        let pin = [m - 2, m - 1];
        // As in a solve: small components are analysed up front (dependent rows dropped, the
        // pin must stay independent); large ones go straight to the sparse factorization of
        // every row and are analysed only when it meets dependent rows.
        let analysed_rows = |max_entries: usize| -> Result<Vec<usize>> {
            if m.saturating_mul(n) > max_entries {
                return Err(Error::Solve(camber_solve::Error::RankDeficient { rows: m }));
            }
            let a = analyze(&lin, options.rank_tolerance, options.tolerance)?;
            if !a.conflicting.is_empty() {
                return Err(Error::Conflicting {
                    constraints: a.conflicting,
                });
            }
            let rows = a.rows.independent;
            if !(rows.contains(&pin[0]) && rows.contains(&pin[1])) {
                return Err(Error::NotDraggable { point });
            }
            Ok(rows)
        };
        let factorize = |rows: &[usize]| {
            let j = lin.jacobian.select_rows(rows);
            MinNormFactorization::try_auto(&j, lin.map.weights(), options.dense_max_unknowns)
        };
        let (rows, factorization) = if m.saturating_mul(n) <= options.dense_analysis_max_entries {
            let rows = analysed_rows(options.dense_analysis_max_entries)?;
            let f = factorize(&rows)?;
            (rows, f)
        } else {
            let all: Vec<usize> = (0..m).collect();
            match factorize(&all) {
                Ok(f) => (all, f),
                Err(camber_solve::Error::RankDeficient { .. }) => {
                    let rows = analysed_rows(crate::solve::NAMING_ANALYSIS_MAX_ENTRIES)?;
                    let f = factorize(&rows)?;
                    (rows, f)
                }
                Err(e) => return Err(e.into()),
            }
        };
        let anchor = {
            let p = self.point(point)?;
            [p.x, p.y]
        };
        let n = lin.map.len();
        let nx = lin.x.len();
        Ok(DragSession::Affine(AffineDrag {
            common: Common {
                point,
                revision: self.revision(),
                cp,
                shapes: Shapes::of(self, &comp)?,
                moved: false,
                x: lin.x,
            },
            z: lin.map.z0().to_vec(),
            g: lin.g,
            row_owner: lin.row_owner,
            map: lin.map,
            factorization,
            pin,
            anchor,
            tolerance: options.tolerance,
            z_new: vec![0.0; n],
            x_new: vec![0.0; nx],
            g_new: vec![0.0; m],
            g_sel: vec![0.0; rows.len()],
            dz: vec![0.0; n],
            rows,
        }))
    }

    /// A drag session on a nonlinear component (see [`NonlinearDrag`]).
    fn drag_nonlinear(
        &self,
        point: PointRef,
        comp: &Component,
        mut cp: ComponentProblem,
    ) -> Result<DragSession> {
        let e = self.lookup(point.entity())?;
        let (entity, index) = match e.resolve(point)?.as_slice() {
            [(j, c)] if (c - 1.0).abs() <= 0.0 => (point.entity(), *j),
            _ => return Err(Error::NotDraggable { point }),
        };
        let block = cp.point_block(entity, index)?;
        // A point merged into a coincident one moves with that one's unknowns.
        let block = cp.merged.get(&block).copied().unwrap_or(block);
        for k in 0..2 {
            let u = cp.problem.unknown(block, k)?;
            if !matches!(cp.problem.binding(u)?, camber_solve::Binding::Free) {
                return Err(Error::NotDraggable { point });
            }
        }
        cp.problem.fix_block(block)?;
        let z = cp.problem.reduced_map()?.z0().to_vec();
        let x = cp.problem.values().to_vec();
        Ok(DragSession::Nonlinear(NonlinearDrag {
            common: Common {
                point,
                revision: self.revision(),
                cp,
                shapes: Shapes::of(self, comp)?,
                moved: false,
                x,
            },
            block,
            z,
            options: self.options().clone(),
        }))
    }
}

impl AffineDrag {
    /// One affine update (see the module documentation).
    fn update(&mut self, target: Point2<f64>) -> Result<()> {
        let shift = [target.x - self.anchor[0], target.y - self.anchor[1]];
        for (k, r) in self.rows.iter().enumerate() {
            let mut v = self.g[*r];
            if *r == self.pin[0] {
                v -= shift[0];
            } else if *r == self.pin[1] {
                v -= shift[1];
            }
            self.g_sel[k] = v;
        }
        self.factorization.solve_refined(
            &self.g_sel,
            &mut self.dz,
            REFINEMENT_STEPS,
            0.01 * self.tolerance,
        )?;
        for ((zn, z), d) in self.z_new.iter_mut().zip(&self.z).zip(&self.dz) {
            *zn = z + d;
        }
        self.map.expand(&self.z_new, &mut self.x_new)?;
        self.common
            .cp
            .problem
            .evaluate_at(&self.x_new, &mut self.g_new)?;
        let mut worst = (0usize, 0.0_f64);
        for (i, v) in self.g_new.iter().enumerate() {
            let v = if i == self.pin[0] {
                v - shift[0]
            } else if i == self.pin[1] {
                v - shift[1]
            } else {
                *v
            };
            if v.is_nan() || v.abs() > worst.1 {
                worst = (i, if v.is_nan() { f64::INFINITY } else { v.abs() });
            }
        }
        if worst.1 > self.tolerance {
            let owner = self
                .row_owner
                .get(worst.0)
                .copied()
                .unwrap_or(DRAG_CONSTRAINT);
            return Err(Error::NotSatisfied {
                failed: vec![(owner, worst.1)],
            });
        }
        self.common.cp.check_orientations(&self.x_new)?;
        std::mem::swap(&mut self.z, &mut self.z_new);
        std::mem::swap(&mut self.common.x, &mut self.x_new);
        std::mem::swap(&mut self.g, &mut self.g_new);
        self.common.moved = true;
        Ok(())
    }
}

impl NonlinearDrag {
    /// One nonlinear update: the solve policy, warm started from the previous step; the state
    /// is kept only when every constraint, orientation and contact check holds.
    fn update(&mut self, target: Point2<f64>) -> Result<()> {
        let cp = &mut self.common.cp;
        let before = cp.problem.block_values(self.block)?.to_vec();
        cp.problem
            .set_block_values(self.block, &[target.x, target.y])?;
        let start = Start::Warm {
            from: self.z.clone(),
            toward: self.z.clone(),
        };
        match policy::solve(cp, &self.common.shapes, &self.options, start) {
            Ok(_) => {
                self.z = cp.problem.reduced_map()?.z0().to_vec();
                self.common.x.clear();
                self.common.x.extend_from_slice(cp.problem.values());
                self.common.moved = true;
                Ok(())
            }
            Err(e) => {
                // The policy left the problem at its start: move the dragged block back too.
                cp.problem.set_block_values(self.block, &before)?;
                Err(e)
            }
        }
    }
}

impl DragSession {
    fn common(&self) -> &Common {
        match self {
            DragSession::Affine(d) => &d.common,
            DragSession::Nonlinear(d) => &d.common,
        }
    }

    /// Moves the dragged point to `target` and every other free unknown by the weighted
    /// minimum norm from the current state, keeping every constraint.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a bad target; [`Error::NotSatisfied`] or
    /// [`Error::OrientationFlipped`] when the result would break a constraint (the session keeps
    /// its previous state).
    pub fn update(&mut self, target: Point2<f64>) -> Result<()> {
        crate::entity::check_point("target", 0, &target)?;
        match self {
            DragSession::Affine(d) => d.update(target),
            DragSession::Nonlinear(d) => d.update(target),
        }
    }

    /// The dragged point.
    pub fn dragged(&self) -> PointRef {
        self.common().point
    }

    /// The current location of a point of the dragged component.
    ///
    /// # Errors
    /// [`Error::UnknownEntity`] for an entity outside the component, [`Error::UnknownPoint`].
    pub fn point(&self, r: PointRef) -> Result<Point2<f64>> {
        let c = self.common();
        let e = r.entity();
        let mut s = [0.0; 2];
        let terms = c.shapes.lookup(e)?.resolve(r)?;
        for (j, k) in terms {
            let i = c.cp.point_unknown(e, j)?;
            s[0] += k * c.x[i];
            s[1] += k * c.x[i + 1];
        }
        Ok(Point2::new(s[0], s[1]))
    }

    /// Commits the current state to the sketch (nothing happens if no update succeeded).
    ///
    /// # Errors
    /// [`Error::StaleSession`] when the sketch was edited since the drag began; the sketch is
    /// unchanged then.
    pub fn finish(self, sketch: &mut Sketch) -> Result<()> {
        let c = self.common();
        if sketch.revision() != c.revision {
            return Err(Error::StaleSession {
                expected: c.revision,
                found: sketch.revision(),
            });
        }
        if !c.moved {
            return Ok(());
        }
        let updates = c.cp.entities_at(sketch, &c.x)?;
        let free = c.cp.free_at(&c.x)?;
        let ids: Vec<EntityId> = updates.iter().map(|(id, _)| *id).collect();
        sketch.commit(updates, &ids);
        // Free parameters moved with the drag: the constraints keep the solved ones.
        sketch.store_free(&free);
        Ok(())
    }
}
