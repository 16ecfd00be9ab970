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
//! **Nonlinear components.** J changes with the unknowns, so nothing is cached but the Newton
//! workspace. The dragged point (a single free block) is fixed in the problem and set to the
//! target at each update; Newton minimum norm starts from the previous step's solution and
//! pulls toward it ([`camber_solve::solve_newton_from`]), so each step moves the rest of the
//! sketch as little as it can; if Newton fails, the full selection ([`camber_solve::solve()`])
//! runs from the same state. The result must pass the orientation and contact checks of a
//! solve, otherwise the session keeps its previous state.

use std::collections::BTreeMap;

use camber_solve::analysis::analyze;
use camber_solve::{MinNormFactorization, ReducedMap};
use nalgebra::Point2;

use crate::build::ComponentProblem;
use crate::compile::EntityLookup;
use crate::entity::Entity;
use crate::errors::{Error, Result};
use crate::ids::{EntityId, PointRef};
use crate::sketch::Sketch;

/// The entity shapes a session started from, as an [`EntityLookup`] (knots, weights and kinds
/// do not change during a drag).
struct Shapes<'a>(&'a BTreeMap<EntityId, Entity>);

impl EntityLookup for Shapes<'_> {
    fn lookup(&self, id: EntityId) -> Result<&Entity> {
        self.0.get(&id).ok_or(Error::UnknownEntity { entity: id })
    }
}

/// Refinement rounds after each minimum-norm step.
const REFINEMENT_STEPS: usize = 2;

/// An interactive drag of one point; see the module documentation.
///
/// ```
/// use camber_sketch::{Constraint, FixTarget, PointRef, Sketch};
/// use camber_geom::BezierCurve2;
/// use nalgebra::Point2;
/// let mut s = Sketch::new();
/// let c = s.add_bezier(BezierCurve2::try_new(vec![
///     Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(2.0, 1.0), Point2::new(3.0, 0.0),
/// ])?)?;
/// s.add_constraint(Constraint::Fixed(FixTarget::Point(PointRef::End(c))))?;
/// let mut drag = s.drag(PointRef::Control(c, 1))?;
/// drag.update(Point2::new(1.2, 1.5))?;
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
    cp: ComponentProblem,
    map: ReducedMap,
    /// The cached factorization (affine components only).
    factorization: Option<MinNormFactorization>,
    /// Rows of J kept (independent), and the two pin rows' positions in g.
    rows: Vec<usize>,
    row_owner: Vec<camber_solve::ConstraintId>,
    pin: [usize; 2],
    /// The component's entities at the start (their shapes resolve point references).
    shapes: BTreeMap<EntityId, Entity>,
    anchor: [f64; 2],
    tolerance: f64,
    moved: bool,
    // Current state (pin rows of g relative to the anchor) and scratch.
    z: Vec<f64>,
    x: Vec<f64>,
    g: Vec<f64>,
    z_new: Vec<f64>,
    x_new: Vec<f64>,
    g_new: Vec<f64>,
    g_sel: Vec<f64>,
    dz: Vec<f64>,
    /// Present when the component is nonlinear: the warm-started Newton state.
    nonlinear: Option<NonlinearDrag>,
}

/// The state of a drag on a nonlinear component: the dragged block is fixed in the problem and
/// moved to the target at each update; Newton starts from the previous step's solution and
/// pulls toward it, and the full selection ([`camber_solve::solve()`]) runs when it fails.
#[derive(Debug)]
struct NonlinearDrag {
    block: camber_solve::BlockId,
    /// The reduced unknowns of the current state.
    z: Vec<f64>,
    workspace: camber_solve::NewtonWorkspace,
    options: camber_solve::Options,
    penetration: f64,
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
        if self.build_component(&comp, None)?.nonlinear.is_some() {
            return self.drag_nonlinear(point, &comp);
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
        let mut shapes = BTreeMap::new();
        for id in &comp.entities {
            shapes.insert(*id, self.lookup(*id)?.clone());
        }
        Ok(DragSession {
            point,
            revision: self.revision(),
            z: lin.map.z0().to_vec(),
            x: lin.x,
            g: lin.g,
            row_owner: lin.row_owner,
            shapes,
            map: lin.map,
            cp,
            factorization: Some(factorization),
            pin,
            anchor,
            tolerance: options.tolerance,
            moved: false,
            z_new: vec![0.0; n],
            x_new: vec![0.0; nx],
            g_new: vec![0.0; m],
            g_sel: vec![0.0; rows.len()],
            dz: vec![0.0; n],
            rows,
            nonlinear: None,
        })
    }

    /// A drag session on a nonlinear component (see [`NonlinearDrag`]).
    fn drag_nonlinear(
        &self,
        point: PointRef,
        comp: &crate::build::Component,
    ) -> Result<DragSession> {
        let (entity, index) = crate::general::single_block(self, point)?;
        let mut cp = self.build_component(comp, None)?;
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
        let map = cp.problem.reduced_map()?;
        let z = map.z0().to_vec();
        let x = cp.problem.values().to_vec();
        let mut shapes = BTreeMap::new();
        for id in &comp.entities {
            shapes.insert(*id, self.lookup(*id)?.clone());
        }
        let anchor = {
            let p = self.point(point)?;
            [p.x, p.y]
        };
        let options = self.options().clone();
        Ok(DragSession {
            point,
            revision: self.revision(),
            z: Vec::new(),
            x,
            g: Vec::new(),
            row_owner: Vec::new(),
            shapes,
            map,
            cp,
            factorization: None,
            pin: [0, 0],
            anchor,
            tolerance: options.tolerance,
            moved: false,
            z_new: Vec::new(),
            x_new: Vec::new(),
            g_new: Vec::new(),
            g_sel: Vec::new(),
            dz: Vec::new(),
            rows: Vec::new(),
            nonlinear: Some(NonlinearDrag {
                block,
                z,
                workspace: camber_solve::NewtonWorkspace::new(),
                penetration: crate::solve::penetration_tolerance(&options),
                options,
            }),
        })
    }
}

impl DragSession {
    /// Moves the dragged point to `target` and every other free unknown by the weighted
    /// minimum norm from the current state, keeping every constraint.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a bad target; [`Error::NotSatisfied`] or
    /// [`Error::OrientationFlipped`] when the result would break a constraint (the session keeps
    /// its previous state).
    pub fn update(&mut self, target: Point2<f64>) -> Result<()> {
        crate::entity::check_point("target", 0, &target)?;
        if self.nonlinear.is_some() {
            return self.update_nonlinear(target);
        }
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
        let Some(factorization) = self.factorization.as_mut() else {
            return Ok(());
        };
        factorization.solve_refined(
            &self.g_sel,
            &mut self.dz,
            REFINEMENT_STEPS,
            0.01 * self.tolerance,
        )?;
        for ((zn, z), d) in self.z_new.iter_mut().zip(&self.z).zip(&self.dz) {
            *zn = z + d;
        }
        self.map.expand(&self.z_new, &mut self.x_new)?;
        self.cp.problem.evaluate_at(&self.x_new, &mut self.g_new)?;
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
                .unwrap_or(crate::build::DRAG_CONSTRAINT);
            return Err(Error::NotSatisfied {
                failed: vec![(owner, worst.1)],
            });
        }
        self.cp.check_orientations(&self.x_new)?;
        std::mem::swap(&mut self.z, &mut self.z_new);
        std::mem::swap(&mut self.x, &mut self.x_new);
        std::mem::swap(&mut self.g, &mut self.g_new);
        self.moved = true;
        Ok(())
    }

    /// One nonlinear update: warm-started Newton, then the full selection; the state is kept
    /// only when every constraint, orientation and contact check holds.
    fn update_nonlinear(&mut self, target: Point2<f64>) -> Result<()> {
        let Some(nl) = self.nonlinear.as_mut() else {
            return Ok(());
        };
        let problem = &mut self.cp.problem;
        let before = problem.block_values(nl.block)?.to_vec();
        problem.set_block_values(nl.block, &[target.x, target.y])?;
        let z_prev = nl.z.clone();
        let solved = camber_solve::solve_newton_from(
            problem,
            &nl.options,
            &mut nl.workspace,
            &z_prev,
            &z_prev,
        )
        .or_else(|_| camber_solve::solve(problem, &nl.options));
        let checked = solved.map_err(Error::from).and_then(|_| {
            let x = self.cp.problem.values();
            self.cp.check_orientations(x)?;
            let entities = self.cp.entities_at(&Shapes(&self.shapes), x)?;
            self.cp.check_contacts(&entities, x, nl.penetration)
        });
        match checked {
            Ok(()) => {
                nl.z = self.cp.problem.reduced_map()?.z0().to_vec();
                self.x.clear();
                self.x.extend_from_slice(self.cp.problem.values());
                self.moved = true;
                Ok(())
            }
            Err(e) => {
                // Back to the previous state: the dragged block, then every reduced unknown.
                self.cp.problem.set_block_values(nl.block, &before)?;
                let map = self.cp.problem.reduced_map()?;
                self.cp.problem.apply_reduced(&map, &nl.z)?;
                Err(e)
            }
        }
    }

    /// The dragged point.
    pub fn dragged(&self) -> PointRef {
        self.point
    }

    /// The current location of a point of the dragged component.
    ///
    /// # Errors
    /// [`Error::UnknownEntity`] for an entity outside the component, [`Error::UnknownPoint`].
    pub fn point(&self, r: PointRef) -> Result<Point2<f64>> {
        let e = r.entity();
        let mut s = [0.0; 2];
        let terms = self.entity_terms(r)?;
        for (j, c) in terms {
            let i = self.cp.point_unknown(e, j)?;
            s[0] += c * self.x[i];
            s[1] += c * self.x[i + 1];
        }
        Ok(Point2::new(s[0], s[1]))
    }

    fn entity_terms(&self, r: PointRef) -> Result<crate::entity::Terms> {
        // The resolution only needs the entity's shape, which a drag does not change.
        self.shapes
            .get(&r.entity())
            .ok_or(Error::UnknownEntity { entity: r.entity() })
            .and_then(|e: &Entity| e.resolve(r))
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
        let updates = self.cp.entities_at(sketch, &self.x)?;
        let contacts = self.cp.contacts_at(&self.x)?;
        let ids: Vec<EntityId> = updates.iter().map(|(id, _)| *id).collect();
        sketch.commit(updates, &ids);
        // Free contact parameters moved with the drag: the constraints keep the solved ones.
        sketch.store_contacts(&contacts);
        Ok(())
    }
}
