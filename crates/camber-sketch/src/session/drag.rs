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
//! On a small component (J_z and the gain below with at most 4,096 entries each) steps 2 and 3
//! are dense products worked out when the session starts: Δz = K·g with K's columns the
//! refined steps for unit right-hand sides (the step is linear in g), and the rows
//! g(z) = g(z₀) + J_z·(z − z₀) from the session's start z₀ (exact for affine rows, with the
//! rounding of one product and no drift across updates). An update those products would refuse
//! is redone by the factorization before it is refused.
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

use camber_solve::analyze;
use camber_solve::{MinNormFactorization, ReducedMap};
use nalgebra::{Point2, Vector2};
use smallvec::SmallVec;

use crate::component::policy::{self, Start};
use crate::component::{Component, ComponentProblem, DRAG_CONSTRAINT};
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{EntityId, PointRef};
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

/// How far a drag target may lie from the centre of the sketch ([`Sketch::centre`]), in
/// multiples of the sketch's scale ([`Sketch::scale`], the diagonal of its box, at least 1),
/// both taken when the drag starts: a thousand sketches away is surely a slip of the hand or a
/// hostile request, and would wreck the sketch's numbers. [`DragSession::update`] refuses
/// farther targets with [`Error::DragTargetTooFar`], whatever the surface (editor, Python).
pub const MAX_DRAG_REACH: f64 = 1000.0;

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
    /// The sketch's centre when the drag began, and the farthest a target may lie from it.
    centre: Point2<f64>,
    reach: f64,
}

/// The state of a drag on an affine component (see the module documentation).
#[derive(Debug)]
pub struct AffineDrag {
    common: Common,
    map: ReducedMap,
    /// The factorization of the kept constraint rows and the pin rows (absent when the point
    /// cannot move at all).
    factorization: Option<MinNormFactorization>,
    /// Constraint rows of J kept (independent), and the two pin rows' positions in g.
    rows: Vec<usize>,
    row_owner: Vec<camber_solve::ConstraintId>,
    pin: [usize; 2],
    /// The directions the point can move in (unit, orthonormal; none, one or both axes): each
    /// is one pin row m·(P − target) = 0.
    mix: SmallVec<[[f64; 2]; 2]>,
    /// The freedom those directions give.
    freedom: Freedom,
    anchor: [f64; 2],
    tolerance: f64,
    /// The update as one small affine map, for components small enough (see [`AffineGain`]).
    gain: Option<AffineGain>,
    // Current state (pin rows of g relative to the anchor) and scratch.
    z: Vec<f64>,
    g: Vec<f64>,
    z_new: Vec<f64>,
    x_new: Vec<f64>,
    g_new: Vec<f64>,
    g_sel: Vec<f64>,
    dz: Vec<f64>,
}

/// The most entries of the dense matrices of an [`AffineGain`] (each of K and J_z).
const GAIN_MAX_ENTRIES: usize = 4096;

/// An affine update written out as dense products, for a small component.
///
/// The step is linear in the selected right-hand side: Δz = K·g_sel, where column j of K is the
/// refined minimum-norm step for the unit right-hand side eⱼ (so every step stays in the range
/// of W⁻¹Jᵀ, the minimum-norm one). The residuals are affine in z, so
/// g(z) = g(z₀) + J_z·(z − z₀) with z₀ the state the session started from: no residual is
/// evaluated through the problem and nothing drifts from one update to the next (the rounding
/// is that of one product, as when the rows are evaluated). x = A·z + c comes from the map's
/// terms flattened into one list. An update that this path would refuse is redone by the
/// factorization (refined solve, rows evaluated) before it is refused.
#[derive(Debug)]
struct AffineGain {
    /// K, n × k, row-major (row i gives Δzᵢ).
    k: Vec<f64>,
    /// k, the number of selected rows (K's columns).
    selected: usize,
    /// J_z, m × n, row-major.
    jacobian: Vec<f64>,
    /// z₀ and g(z₀).
    z0: Vec<f64>,
    g0: Vec<f64>,
    /// x = A·z + c: for unknown i, `x_terms[x_ptr[i]..x_ptr[i + 1]]` as (column, coefficient)
    /// and `x_const[i]`.
    x_ptr: Vec<usize>,
    x_terms: Vec<(usize, f64)>,
    x_const: Vec<f64>,
}

impl AffineGain {
    /// The gain of `factorization` (k selected rows) over the linearization `lin`; `None` when
    /// no row is selected or the component is too large for dense matrices.
    fn of(
        factorization: &mut MinNormFactorization,
        lin: &camber_solve::Linearization,
    ) -> Result<Option<Self>> {
        let (m, n, k) = (lin.g.len(), lin.map.len(), factorization.rows());
        if k == 0
            || n.saturating_mul(k) > GAIN_MAX_ENTRIES
            || m.saturating_mul(n) > GAIN_MAX_ENTRIES
        {
            return Ok(None);
        }
        // Column j: the refined step for g_sel = e_j (J·col = −e_j); the step is linear in g_sel.
        let mut gain = vec![0.0; n * k];
        let (mut unit, mut col) = (vec![0.0; k], vec![0.0; n]);
        for j in 0..k {
            unit[j] = 1.0;
            factorization.solve_refined(&unit, &mut col, REFINEMENT_STEPS, 0.0)?;
            unit[j] = 0.0;
            for (i, v) in col.iter().enumerate() {
                gain[i * k + j] = *v;
            }
        }
        let mut jacobian = vec![0.0; m * n];
        for (i, row) in jacobian.chunks_exact_mut(n).enumerate() {
            let (cols, vals) = lin.jacobian.row(i);
            for (c, v) in cols.iter().zip(vals) {
                row[*c] = *v;
            }
        }
        let nx = lin.x.len();
        let (mut x_ptr, mut x_terms, mut x_const) = (vec![0], Vec::new(), Vec::with_capacity(nx));
        for i in 0..nx {
            let (terms, c) = lin.map.row(i);
            x_terms.extend_from_slice(terms);
            x_ptr.push(x_terms.len());
            x_const.push(c);
        }
        Ok(Some(Self {
            k: gain,
            selected: k,
            jacobian,
            z0: lin.map.z0().to_vec(),
            g0: lin.g.clone(),
            x_ptr,
            x_terms,
            x_const,
        }))
    }

    /// Δz = K·g_sel, z_new = z + Δz, x_new = A·z_new + c and g_new = g(z₀) + J_z·(z_new − z₀).
    ///
    /// Each entry is one sum in a fixed order (z_new[i] = z[i] + Σⱼ K[i, j]·g_sel[j], j rising),
    /// over rows stored contiguously, so the few dozen products of a small drag run without
    /// scratch vectors or bounds checks.
    fn step(
        &self,
        g_sel: &[f64],
        z: &[f64],
        z_new: &mut [f64],
        x_new: &mut [f64],
        g_new: &mut [f64],
    ) {
        for ((zn, z), row) in z_new
            .iter_mut()
            .zip(z)
            .zip(self.k.chunks_exact(self.selected))
        {
            let mut acc = *z;
            for (kv, s) in row.iter().zip(g_sel) {
                acc += kv * s;
            }
            *zn = acc;
        }
        for ((x, c), ends) in x_new
            .iter_mut()
            .zip(&self.x_const)
            .zip(self.x_ptr.windows(2))
        {
            let terms = &self.x_terms[ends[0]..ends[1]];
            *x = c + terms.iter().map(|(k, a)| a * z_new[*k]).sum::<f64>();
        }
        let n = z_new.len();
        for ((gn, g0), row) in g_new
            .iter_mut()
            .zip(&self.g0)
            .zip(self.jacobian.chunks_exact(n))
        {
            *gn = g0
                + row
                    .iter()
                    .zip(&*z_new)
                    .zip(&self.z0)
                    .map(|((a, zn), z0)| a * (zn - z0))
                    .sum::<f64>();
        }
    }
}

/// The state of a drag on a nonlinear component: the component's solve policy runs from the
/// previous step's solution, pulling toward it. A point free in both directions is fixed in the
/// problem and moved to the target; a point that can only slide (on a curve, a circle, a ray)
/// is pinned by one row along its current direction of freedom instead, so it follows the
/// target's projection.
#[derive(Debug)]
pub struct NonlinearDrag {
    common: Common,
    block: camber_solve::BlockId,
    /// The reduced unknowns of the current state.
    z: Vec<f64>,
    options: camber_solve::Options,
    /// What the point can do at the current state.
    freedom: Freedom,
    /// The residual rows of the problem without the pin row.
    base_rows: usize,
    /// The constraint owning each of those rows.
    row_owner: Vec<camber_solve::ConstraintId>,
    /// Whether the component has constraints with priorities: the cursor is then a wish
    /// below every tier (pin rows of the lowest priority, never a fixed block), so no
    /// constraint gives way to it.
    wish: bool,
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
    /// matrix `g` (see [`point_mobility`]), relative to the unconstrained mobility `scale`.
    fn of(g: [[f64; 2]; 2], scale: f64) -> (Self, SmallVec<[[f64; 2]; 2]>) {
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
            (Freedom::Free, smallvec::smallvec![[1.0, 0.0], [0.0, 1.0]])
        } else if l1 > small {
            (Freedom::Along(u), smallvec::smallvec![[u.x, u.y]])
        } else {
            (Freedom::Determined, SmallVec::new())
        }
    }
}

/// The mobility of the point whose coordinates have the Jacobian rows `e` (2 × n) under the
/// independent constraint rows factorized in `f`: G = E·P_W·W⁻¹·Eᵀ, P_W the W-orthogonal
/// projector onto the null space of the constraints. Its range is the set of moves δP the
/// constraints allow (to first order); also returns the unconstrained scale E·W⁻¹·Eᵀ's trace.
fn point_mobility(
    e: [&[f64]; 2],
    f: Option<&mut MinNormFactorization>,
    weights: &[f64],
) -> Result<([[f64; 2]; 2], f64)> {
    let n = weights.len();
    let mut g = [[0.0; 2]; 2];
    let scale: f64 = e
        .iter()
        .map(|row| row.iter().zip(weights).map(|(v, w)| v * v / w).sum::<f64>())
        .sum();
    match f {
        Some(f) => {
            let (mut out, mut y) = (vec![0.0; n], vec![0.0; f.rows()]);
            for k in 0..2 {
                f.project(e[k], &mut out, &mut y)?;
                for (i, row) in e.iter().enumerate() {
                    g[i][k] = row.iter().zip(&out).map(|(a, b)| a * b).sum();
                }
            }
        }
        None => {
            for i in 0..2 {
                for k in 0..2 {
                    g[i][k] = e[i]
                        .iter()
                        .zip(e[k])
                        .zip(weights)
                        .map(|((a, b), w)| a * b / w)
                        .sum();
                }
            }
        }
    }
    Ok((g, scale))
}

/// Row `i` of a sparse matrix as a dense vector of `n` entries.
fn dense_row(j: &camber_solve::SparseMatrix, i: usize, n: usize) -> Vec<f64> {
    let mut out = vec![0.0; n];
    let (cols, vals) = j.row(i);
    for (c, v) in cols.iter().zip(vals) {
        out[*c] = *v;
    }
    out
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
        let options = &self.solve_options();
        let lin = cp.problem().linearize()?;
        let (m, n) = (lin.g.len(), lin.map.len());
        let pin = [m - 2, m - 1];
        let weights = lin.map.weights().to_vec();
        // As in a solve: small components are analysed up front (dependent constraint rows
        // dropped; the pin rows come last, so they never hide a constraint row); large ones go
        // straight to the sparse factorization of every row and are analysed only when it meets
        // dependent rows.
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
            Ok(a.rows
                .independent
                .into_iter()
                .filter(|r| *r < m - 2)
                .collect())
        };
        let factorize = |j: &camber_solve::SparseMatrix| {
            MinNormFactorization::try_auto(j, &weights, options.dense_max_unknowns)
        };
        let (rows, constraints) = if m.saturating_mul(n) <= options.dense_analysis_max_entries {
            let rows = analysed_rows(options.dense_analysis_max_entries)?;
            let f = if rows.is_empty() {
                None
            } else {
                Some(factorize(&lin.jacobian.select_rows(&rows))?)
            };
            (rows, f)
        } else {
            let all: Vec<usize> = (0..m - 2).collect();
            match factorize(&lin.jacobian.select_rows(&all)) {
                Ok(f) => (all, Some(f)),
                Err(camber_solve::Error::RankDeficient { .. }) => {
                    let rows = analysed_rows(usize::MAX)?;
                    let f = factorize(&lin.jacobian.select_rows(&rows))?;
                    (rows, Some(f))
                }
                Err(e) => return Err(e.into()),
            }
        };
        // Where the point can go: the constraints' null space seen through the pin rows.
        let (ex, ey) = (
            dense_row(&lin.jacobian, pin[0], n),
            dense_row(&lin.jacobian, pin[1], n),
        );
        let mut constraints = constraints;
        let (g, scale) = point_mobility([&ex, &ey], constraints.as_mut(), &weights)?;
        let (freedom, mix) = Freedom::of(g, scale);
        let mut triplets = Vec::new();
        for (k, r) in rows.iter().enumerate() {
            let (cols, vals) = lin.jacobian.row(*r);
            triplets.extend(cols.iter().zip(vals).map(|(c, v)| (k, *c, *v)));
        }
        for (k, u) in mix.iter().enumerate() {
            for (c, (a, b)) in ex.iter().zip(&ey).enumerate() {
                let v = u[0] * a + u[1] * b;
                if v != 0.0 {
                    triplets.push((rows.len() + k, c, v));
                }
            }
        }
        let mut factorization = if mix.is_empty() {
            None
        } else {
            let j = camber_solve::SparseMatrix::try_from_triplets(
                rows.len() + mix.len(),
                n,
                &triplets,
            )?;
            Some(factorize(&j)?)
        };
        let anchor = {
            let p = self.point(point)?;
            [p.x, p.y]
        };
        let gain = match factorization.as_mut() {
            Some(f) => AffineGain::of(f, &lin)?,
            None => None,
        };
        let nx = lin.x.len();
        let selected = rows.len() + mix.len();
        let (centre, reach) = self.drag_limits(point);
        Ok(DragSession::Affine(AffineDrag {
            common: Common {
                point,
                revision: self.revision(),
                cp,
                shapes: Shapes::of(self, &comp)?,
                moved: false,
                x: lin.x,
                centre,
                reach,
            },
            z: lin.map.z0().to_vec(),
            g: lin.g,
            row_owner: lin.row_owner,
            map: lin.map,
            factorization,
            pin,
            mix,
            freedom,
            anchor,
            tolerance: options.tolerance,
            gain,
            z_new: vec![0.0; n],
            x_new: vec![0.0; nx],
            g_new: vec![0.0; m],
            g_sel: vec![0.0; selected],
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
        let block = cp.merged_into(block);
        for k in 0..2 {
            let u = cp.problem.unknown(block, k)?;
            if !matches!(cp.problem.binding(u)?, camber_solve::Binding::Free) {
                return Err(Error::NotDraggable { point });
            }
        }
        let freedom = nonlinear_freedom(&cp, block, &self.solve_options())?;
        let base_rows = cp.problem.num_residuals();
        let row_owner = cp.problem.linearize()?.row_owner;
        let wish = cp.problem.has_priorities();
        if freedom == Freedom::Free && !wish {
            cp.problem.fix_block(block)?;
        }
        let z = cp.problem.reduced_map()?.z0().to_vec();
        let x = cp.problem.values().to_vec();
        let (centre, reach) = self.drag_limits(point);
        Ok(DragSession::Nonlinear(NonlinearDrag {
            common: Common {
                point,
                revision: self.revision(),
                cp,
                shapes: Shapes::of(self, comp)?,
                moved: false,
                x,
                centre,
                reach,
            },
            block,
            z,
            options: self.solve_options(),
            freedom,
            base_rows,
            row_owner,
            wish,
        }))
    }
}

/// The freedom of a free point block of a nonlinear component at its current state: the
/// mobility of its two unknowns under the linearized constraints (independent rows).
fn nonlinear_freedom(
    cp: &ComponentProblem,
    block: camber_solve::BlockId,
    options: &camber_solve::Options,
) -> Result<Freedom> {
    let lin = cp.problem.linearize()?;
    let (m, n) = (lin.g.len(), lin.map.len());
    let mut e = [vec![0.0; n], vec![0.0; n]];
    for (k, row) in e.iter_mut().enumerate() {
        let u = cp.problem.unknown(block, k)?;
        match lin
            .map
            .vars()
            .iter()
            .position(|v| *v == camber_solve::Var::Unknown(u))
        {
            Some(i) => row[i] = 1.0,
            None => return Ok(Freedom::Determined),
        }
    }
    let rows: Vec<usize> = if m.saturating_mul(n) <= options.dense_analysis_max_entries {
        analyze(&lin, options.rank_tolerance, options.tolerance)?
            .rows
            .independent
    } else {
        (0..m).collect()
    };
    let weights = lin.map.weights();
    let mut f = if rows.is_empty() {
        None
    } else {
        match MinNormFactorization::try_auto(
            &lin.jacobian.select_rows(&rows),
            weights,
            options.dense_max_unknowns,
        ) {
            Ok(f) => Some(f),
            // Dependent rows in a large component: no cheap answer; let the point try to move.
            Err(camber_solve::Error::RankDeficient { .. }) => return Ok(Freedom::Free),
            Err(e) => return Err(e.into()),
        }
    };
    let (g, scale) = point_mobility([&e[0], &e[1]], f.as_mut(), weights)?;
    Ok(Freedom::of(g, scale).0)
}

/// u·(P − target) = 0 over the dragged point's block: the pin of a point that can only slide,
/// along its direction of freedom u (affine, one row).
#[derive(Debug, Clone, PartialEq)]
struct PinAlong {
    u: [f64; 2],
    target: [f64; 2],
}

impl camber_solve::Residual for PinAlong {
    fn name(&self) -> &str {
        "drag"
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2])
    }
    fn eval<T: camber_solve::Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        use camber_solve::scalar::cst;
        out[0] = cst::<T>(self.u[0]) * (x[0][0] - cst(self.target[0]))
            + cst::<T>(self.u[1]) * (x[0][1] - cst(self.target[1]));
    }
    fn is_affine(&self) -> bool {
        true
    }
}

impl AffineDrag {
    /// One affine update (see the module documentation): the pin rows along the point's
    /// directions of freedom move by the target's shift; a determined point does not move.
    fn update(&mut self, target: Point2<f64>) -> Result<()> {
        if self.factorization.is_none() {
            return Ok(());
        }
        let shift = [target.x - self.anchor[0], target.y - self.anchor[1]];
        let k0 = self.rows.len();
        for (k, r) in self.rows.iter().enumerate() {
            self.g_sel[k] = self.g[*r];
        }
        let pin_now = [
            self.g[self.pin[0]] - shift[0],
            self.g[self.pin[1]] - shift[1],
        ];
        for (k, u) in self.mix.iter().enumerate() {
            self.g_sel[k0 + k] = u[0] * pin_now[0] + u[1] * pin_now[1];
        }
        if let Some(gain) = self.gain.as_ref() {
            gain.step(
                &self.g_sel,
                &self.z,
                &mut self.z_new,
                &mut self.x_new,
                &mut self.g_new,
            );
            if self.worst(shift).1 <= self.tolerance {
                return self.accept();
            }
            // Refused by the dense products: the factorization decides.
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
        self.common
            .cp
            .problem
            .evaluate_at(&self.x_new, &mut self.g_new)?;
        let worst = self.worst(shift);
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
        self.accept()
    }

    /// The largest |row| of `g_new` (NaN as infinite) with its row: every constraint row, and
    /// the pin along each direction of freedom relative to the target's `shift`.
    fn worst(&self, shift: [f64; 2]) -> (usize, f64) {
        let mut worst = (0usize, 0.0_f64);
        for (i, v) in self.g_new.iter().enumerate() {
            if i == self.pin[0] || i == self.pin[1] {
                continue;
            }
            if v.is_nan() || v.abs() > worst.1 {
                worst = (i, if v.is_nan() { f64::INFINITY } else { v.abs() });
            }
        }
        let pin_new = [
            self.g_new[self.pin[0]] - shift[0],
            self.g_new[self.pin[1]] - shift[1],
        ];
        for u in &self.mix {
            let v = u[0] * pin_new[0] + u[1] * pin_new[1];
            if v.is_nan() || v.abs() > worst.1 {
                worst = (
                    self.pin[0],
                    if v.is_nan() { f64::INFINITY } else { v.abs() },
                );
            }
        }
        worst
    }

    /// Keeps the new state (z_new, x_new, g_new) when no tangent flipped or collapsed.
    fn accept(&mut self) -> Result<()> {
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
        let u = match self.freedom {
            Freedom::Determined => return Ok(()),
            Freedom::Free => None,
            Freedom::Along(u) => Some(u),
        };
        let options = self.options.clone();
        let cp = &mut self.common.cp;
        let before = cp.problem.block_values(self.block)?.to_vec();
        // The pin: rows along the directions the point may move (both axes for a free point
        // whose cursor is a wish), or the free block set to the target.
        let axes: SmallVec<[[f64; 2]; 2]> = match u {
            Some(u) => SmallVec::from_slice(&[[u.x, u.y]]),
            None if self.wish => SmallVec::from_slice(&[[1.0, 0.0], [0.0, 1.0]]),
            None => SmallVec::new(),
        };
        let pinned_by_rows = !axes.is_empty();
        if pinned_by_rows {
            cp.problem.truncate_residuals(self.base_rows);
            for axis in axes {
                cp.problem.add_residual(
                    PinAlong {
                        u: axis,
                        target: [target.x, target.y],
                    },
                    &[self.block],
                    DRAG_CONSTRAINT,
                )?;
            }
            if self.wish {
                cp.problem
                    .set_priority(DRAG_CONSTRAINT, camber_solve::Priority::MAX);
            }
        } else {
            cp.problem
                .set_block_values(self.block, &[target.x, target.y])?;
        }
        let start = Start::Warm {
            from: self.z.clone(),
            toward: self.z.clone(),
        };
        match policy::solve(cp, &self.common.shapes, &options, start) {
            Ok(_) => {
                self.z = cp.problem.reduced_map()?.z0().to_vec();
                self.common.x.clear();
                self.common.x.extend_from_slice(cp.problem.values());
                self.common.moved = true;
                if pinned_by_rows {
                    // The direction of freedom turns as the point slides (on a circle, say).
                    cp.problem.truncate_residuals(self.base_rows);
                    self.freedom = nonlinear_freedom(cp, self.block, &options)?;
                }
                Ok(())
            }
            Err(e) => {
                // The policy left the problem at its start: move the dragged block back too.
                if pinned_by_rows {
                    cp.problem.truncate_residuals(self.base_rows);
                } else {
                    cp.problem.set_block_values(self.block, &before)?;
                }
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
    /// [`Error::NonFinite`] for a bad target; [`Error::DragTargetTooFar`] for one farther than
    /// [`MAX_DRAG_REACH`] sketch scales from the sketch's centre; [`Error::NotSatisfied`] or
    /// [`Error::OrientationFlipped`] when the result would break a constraint (the session keeps
    /// its previous state).
    pub fn update(&mut self, target: Point2<f64>) -> Result<()> {
        crate::ground::entity::check_point("target", 0, &target)?;
        let c = self.common();
        if (target - c.centre).norm() > c.reach {
            return Err(Error::DragTargetTooFar {
                x: target.x,
                y: target.y,
                reach: c.reach,
            });
        }
        match self {
            DragSession::Affine(d) => d.update(target),
            DragSession::Nonlinear(d) => d.update(target),
        }
    }

    /// Watches `cancel` in the solves of the following updates (a nonlinear component's update
    /// stops at its next evaluation once it is raised, with the solver's
    /// [`camber_solve::Error::Cancelled`]; an affine update is one linear step and does not
    /// look). None stops watching.
    pub fn set_cancel(&mut self, cancel: Option<camber_solve::CancelFlag>) {
        if let DragSession::Nonlinear(d) = self {
            d.options.cancel = cancel;
        }
    }

    /// The dragged point.
    pub fn dragged(&self) -> PointRef {
        self.common().point
    }

    /// How the dragged point can move: freely, along one direction (it follows the target's
    /// projection there), or not at all (updates are calm no-ops).
    pub fn freedom(&self) -> Freedom {
        match self {
            DragSession::Affine(d) => d.freedom,
            DragSession::Nonlinear(d) => d.freedom,
        }
    }

    /// Every entity of the dragged component as it is now (points and radii).
    ///
    /// # Errors
    /// None in practice (the session's own entities).
    pub fn entities(&self) -> Result<Vec<(EntityId, Entity)>> {
        let c = self.common();
        c.cp.entities_at(&c.shapes, &c.x)
    }

    /// The free parameters of the component's constraints as they are now: (constraint, k,
    /// value) for the k-th free parameter of each (contact parameters, custom parameters).
    ///
    /// # Errors
    /// None in practice.
    pub fn free_parameters(&self) -> Result<Vec<(camber_solve::ConstraintId, usize, f64)>> {
        let c = self.common();
        c.cp.free_at(&c.x)
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
    /// drag.update(Point2::new(2.0, 1.0))?;
    /// let residuals = drag.residuals()?;
    /// assert_eq!(residuals.len(), 1);
    /// assert_eq!(residuals[0].0, mid);
    /// assert!(residuals[0].1 < 1e-12);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn residuals(&self) -> Result<Vec<(crate::ground::ids::ConstraintId, f64)>> {
        let c = self.common();
        let owners = match self {
            DragSession::Affine(d) => &d.row_owner,
            DragSession::Nonlinear(d) => &d.row_owner,
        };
        let problem = c.cp.problem();
        let mut g = vec![0.0; problem.num_rows()];
        problem.evaluate_at(&c.x, &mut g)?;
        let mut worst: BTreeMap<crate::ground::ids::ConstraintId, f64> = BTreeMap::new();
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::constraints::{Fixed, StartTangent};
    use crate::ground::vocabulary::{Sense, TangentForm};
    use camber_geom::BezierCurve2;

    /// W1's cubic (P₃ fixed, start tangent along D) in the given form, dragged by P₁.
    fn w1_session(form: TangentForm) -> (Sketch, EntityId, DragSession) {
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
        let session = s.drag(PointRef::Control(c, 1)).unwrap();
        (s, c, session)
    }

    /// The dense products give, update after update, the state the factorization gives (refined
    /// solve, rows evaluated through the problem), in both tangent forms.
    #[test]
    fn the_dense_update_follows_the_factorization() {
        for form in [TangentForm::Row, TangentForm::Elimination] {
            let (_, c, mut fast) = w1_session(form);
            let (_, _, mut slow) = w1_session(form);
            let DragSession::Affine(d) = &mut slow else {
                panic!("W1 is affine");
            };
            assert!(
                d.gain.take().is_some(),
                "a small component has the dense path"
            );
            let DragSession::Affine(d) = &fast else {
                panic!("W1 is affine");
            };
            assert!(d.gain.is_some());
            let p1 = fast.point(PointRef::Control(c, 1)).unwrap();
            for k in 1..=100 {
                let th = std::f64::consts::TAU * f64::from(k) / 100.0;
                let target = p1 + 0.3 * Vector2::new(th.cos() - 1.0, th.sin());
                fast.update(target).unwrap();
                slow.update(target).unwrap();
                for j in 0..4 {
                    let (a, b) = (
                        fast.point(PointRef::Control(c, j)).unwrap(),
                        slow.point(PointRef::Control(c, j)).unwrap(),
                    );
                    assert!(
                        (a - b).norm() < 1e-12,
                        "{form:?} update {k} point {j}: {a} {b}"
                    );
                }
                assert!((fast.point(PointRef::Control(c, 1)).unwrap() - target).norm() < 1e-12);
            }
            // The residuals the session reports come from the problem itself.
            assert!(fast.residuals().unwrap().iter().all(|(_, r)| *r < 1e-12));
        }
    }
}
