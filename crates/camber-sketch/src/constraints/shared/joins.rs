//! The joints between curve ends, shared by the join kinds (C1/C2, G1/G2 with a free
//! direction) and the end tangencies: the parametric join of two ends, the bases of a joint and
//! the coincidence of its ends, the tangents-parallel residual and its same-sense check, and the
//! tangency of a curve end.

use crate::constraints::check::{point_tangent, speed_floor, SolvedState};
use crate::constraints::compiler::check_direction;
use crate::constraints::compiler::distinct;
use crate::constraints::glyph::{self, Glyph};
use crate::constraints::piece::Piece;
use crate::constraints::piece::{ETerms, Slot};
use crate::constraints::shared::angles::{angle_between, angle_of};
use crate::constraints::Compiler;
use crate::ground::curve_eval::CurveBasis;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::{Sense, TangentForm};
use crate::residuals::clearance::SPEED_FLOOR;
use crate::residuals::curve::{
    composed_hessian, composed_jacobian, cross, dot, Blocks, ComposedCurve, Param,
};
use camber_solve::derive::composed::{InnerMap, Outer};
use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use nalgebra::Vector2;

/// Writes C₁⁽ᵏ⁾(b₁) − C₂⁽ᵏ⁾(a₂) = 0 for k = 0 … `order` (two affine rows each).
pub(crate) fn parametric_join(
    cx: &mut Compiler<'_>,
    name: &'static str,
    (first, second): (EntityId, EntityId),
    order: usize,
) -> Result<()> {
    distinct(first, second)?;
    let (_, b) = cx.domain(first)?;
    let (a, _) = cx.domain(second)?;
    let mut joint = ETerms::new();
    cx.point_terms(PointRef::End(first), 1.0, &mut joint)?;
    cx.point_terms(PointRef::Start(second), -1.0, &mut joint)?;
    cx.combination(name, joint, [0.0; 2]);
    for k in 1..=order {
        let mut terms = cx.curve_derivative_terms(first, b, k)?;
        for (e, j, c) in cx.curve_derivative_terms(second, a, k)? {
            terms.push((e, j, -c));
        }
        cx.combination(name, terms, [0.0; 2]);
    }
    Ok(())
}

/// The glyph of a parametric join: its name beside the joint.
pub(crate) fn join_mark(
    at: &dyn EntityLookup,
    first: EntityId,
    text: &'static str,
) -> Result<Vec<Glyph>> {
    let b = glyph::domain_end(at, first, true)?;
    Ok(vec![
        glyph::tangent_arrow(at, first, b)?,
        Glyph::Mark(glyph::curve_point(at, first, b)?, text),
    ])
}

/// atan2(cross(C₁′(u₁), C₂′(u₂)), C₁′·C₂′) = 0: the tangents of two curves at fixed parameters
/// point the same way (blocks: the first curve's control points, then the second's).
#[derive(Debug, Clone, PartialEq)]
pub struct TangentsParallel {
    first: (CurveBasis, f64),
    second: (CurveBasis, f64),
}

impl TangentsParallel {
    /// Parallel tangents of `first` at u₁ and `second` at u₂.
    pub fn new(first: (CurveBasis, f64), second: (CurveBasis, f64)) -> Self {
        Self { first, second }
    }
}

impl Residual for TangentsParallel {
    fn name(&self) -> &str {
        "G1 join (free direction)"
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2; self.first.0.count() + self.second.0.count()])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let n1 = self.first.0.count();
        let t1 = self.first.0.tangent(x, cst(self.first.1));
        let t2 = self.second.0.tangent(&x[n1..], cst(self.second.1));
        self.outer(&[t1[0], t1[1], t2[0], t2[1]], out);
    }
    fn structured_jacobian(
        &self,
        x: &[&[f64]],
        active: &[bool],
        values: &mut [f64],
        jac: &mut [f64],
    ) -> bool {
        composed_jacobian(self, x, active, values, jac)
    }
    fn structured_hessian(
        &self,
        x: &[&[f64]],
        weights: &[f64],
        active: &[bool],
        out: &mut [f64],
    ) -> bool {
        composed_hessian(self, x, weights, active, out)
    }
}

/// f(t₁, t₂) = θ = atan2(cross(t₁, t₂), t₁·t₂), the angle from t₁ to t₂ (inputs t₁ₓ, t₁ᵧ, t₂ₓ,
/// t₂ᵧ), with its derivatives by hand. With y = (a, b), c = cross(a, b), d = a·b and
/// r² = c² + d² = |a|²|b|²: ∇θ = u/r² with u = d∇c − c∇d, and
/// ∇²θ = (d∇²c − c∇²d)/r² − (u vᵀ + v uᵀ)/r⁴ with v = c∇c + d∇d, where ∇c = (b_y, −b_x, −a_y, a_x),
/// ∇d = (b_x, b_y, a_x, a_y), ∇²c pairs a_x with b_y (+1) and a_y with b_x (−1), and ∇²d pairs
/// a_x with b_x and a_y with b_y (+1). (The mixed terms ∇c∇dᵀ − ∇d∇cᵀ of ∇u are antisymmetric
/// and cancel in the symmetric Hessian.)
impl Outer for TangentsParallel {
    fn outer<T: Scalar>(&self, y: &[T], out: &mut [T]) {
        out[0] = angle_between([y[0], y[1]], [y[2], y[3]], 1.0);
    }

    fn first_derivatives(&self, y: &[f64], values: &mut [f64], jacobian: &mut [f64]) -> bool {
        let Some(p) = AngleParts::at(y) else {
            return false;
        };
        values[0] = p.theta;
        for (k, d) in jacobian.iter_mut().enumerate().take(4) {
            *d = p.u[k] / p.r2;
        }
        true
    }

    fn weighted_second_derivatives(
        &self,
        y: &[f64],
        weights: &[f64],
        gradient: &mut [f64],
        hessian: &mut [f64],
    ) -> bool {
        let Some(p) = AngleParts::at(y) else {
            return false;
        };
        let w = weights[0];
        let r4 = p.r2 * p.r2;
        for k in 0..4 {
            gradient[k] = w * p.u[k] / p.r2;
            for l in 0..4 {
                let d2c = match (k, l) {
                    (0, 3) | (3, 0) => 1.0,
                    (1, 2) | (2, 1) => -1.0,
                    _ => 0.0,
                };
                let d2d = match (k, l) {
                    (0, 2) | (2, 0) | (1, 3) | (3, 1) => 1.0,
                    _ => 0.0,
                };
                hessian[k * 4 + l] =
                    w * ((p.d * d2c - p.c * d2d) / p.r2 - (p.u[k] * p.v[l] + p.v[k] * p.u[l]) / r4);
            }
        }
        true
    }
}

impl ComposedCurve for TangentsParallel {
    /// The two tangents as the inputs of [`Outer::outer`], with their derivatives.
    fn inner(&self, blocks: &Blocks<'_>, map: &mut InnerMap) -> Option<()> {
        let (b1, u1) = &self.first;
        let (b2, u2) = &self.second;
        let next = blocks.curve(b1, Param::Fixed(*u1), 0, 1..=1, map)?;
        blocks.curve(b2, Param::Fixed(*u2), next, 1..=1, map)?;
        Some(())
    }
}

/// Compiles the coincidence of a free-direction join's ends.
pub(crate) fn joint_coincidence(
    cx: &mut Compiler<'_>,
    label: &'static str,
    first: EntityId,
    second: EntityId,
) -> Result<()> {
    distinct(first, second)?;
    let mut terms = ETerms::new();
    cx.point_terms(PointRef::End(first), 1.0, &mut terms)?;
    cx.point_terms(PointRef::Start(second), -1.0, &mut terms)?;
    cx.combination(label, terms, [0.0; 2]);
    Ok(())
}

/// The bases of both curves at the joint up to the derivative `order`, restricted to the
/// control points they read (the end spans'), with those points' slots.
pub(crate) fn joint_bases(
    cx: &Compiler<'_>,
    first: EntityId,
    second: EntityId,
    order: usize,
) -> Result<JointBases> {
    let (full1, _) = cx.curve_basis(first)?;
    let (full2, _) = cx.curve_basis(second)?;
    let (u1, u2) = (full1.domain().1, full2.domain().0);
    let ((b1, r1), (b2, r2)) = (full1.at(u1, order), full2.at(u2, order));
    let slots = r1
        .iter()
        .map(|j| Slot::Point(first, *j))
        .chain(r2.iter().map(|j| Slot::Point(second, *j)))
        .collect();
    Ok(JointBases {
        first: (b1, u1),
        second: (b2, u2),
        slots,
    })
}

/// How far below its floor κ·|C′₀| a join's tangent speed may end before the check asks for the
/// floor row (a relative slack for the rounding of a solve that stands on the floor).
const JOIN_FLOOR_SLACK: f64 = 1e-6;

/// The speed below which the tangent of `curve` at its joint end `u` counts as collapsing:
/// [`SPEED_FLOOR`]·|C′₀(u)| (less [`JOIN_FLOOR_SLACK`]), C′₀ on the curve before the solve (in
/// a drag, before the session), and never below the cusp floor of [`SolvedState::floor`].
pub(crate) fn join_speed_floor(before: &dyn EntityLookup, curve: EntityId, u: f64) -> Result<f64> {
    let e = before.lookup(curve)?;
    let (_, t) = point_tangent(e, curve, u)?;
    let floor = (1.0 - JOIN_FLOOR_SLACK) * SPEED_FLOOR * t[0].hypot(t[1]);
    Ok(floor.max(speed_floor(e)))
}

/// The check of a free join: neither tangent at the joint has shrunk below its floor
/// ([`join_speed_floor`]), and they point the same way.
///
/// Moving a joint while keeping the tangents parallel is cheapest by shortening the leg it
/// moves onto: the minimum-displacement solution runs into a cusp, where the tangent has no
/// direction left and the angle row reads as met. A tangent below the floor fails with
/// [`Error::Cusp`], which the solve answers with the floor row on that side (the active set of
/// `component::solve`): the tangent then turns at the floor's length.
pub(crate) fn verify_same_sense(
    state: &SolvedState<'_>,
    first: EntityId,
    second: EntityId,
) -> Result<()> {
    let (e1, e2) = (state.entity(first)?, state.entity(second)?);
    let (b1, a2) = (
        e1.domain().unwrap_or((0.0, 1.0)).1,
        e2.domain().unwrap_or((0.0, 1.0)).0,
    );
    let (_, t1) = point_tangent(e1, first, b1)?;
    let (_, t2) = point_tangent(e2, second, a2)?;
    state.not_cusp(
        t1[0].hypot(t1[1]),
        join_speed_floor(state.before, first, b1)?,
    )?;
    state.not_cusp(
        t2[0].hypot(t2[1]),
        join_speed_floor(state.before, second, a2)?,
    )?;
    state.sense(t1[0] * t2[0] + t1[1] * t2[1])
}

/// Compiles an end tangency at the start (`at_end` false) or the end of the curve.
pub(crate) fn end_tangency(
    cx: &mut Compiler<'_>,
    label: &'static str,
    (curve, direction, sense, form): (EntityId, &Vector2<f64>, Sense, TangentForm),
    at_end: bool,
) -> Result<()> {
    let d = check_direction("tangent", direction)?;
    let (a, b) = cx.domain(curve)?;
    let u = if at_end { b } else { a };
    let orient = [sense.sign() * d[0], sense.sign() * d[1]];
    let row = Piece::Cross {
        name: label,
        terms: cx.curve_terms(curve, u, 1)?,
        direction: d,
        orient: Some(orient),
    };
    match form {
        TangentForm::Row => cx.push(row),
        TangentForm::Elimination => {
            let e = cx.entity(curve)?;
            if let crate::ground::entity::Entity::Hermite(chain)
            | crate::ground::entity::Entity::Composite(chain) = e
            {
                // The end tangent is itself a block of unknowns: T = t·s·d directly, t ≥ 0.
                let target = if at_end {
                    chain.blocks().len() - 1
                } else {
                    chain.node_count()
                };
                cx.push(Piece::Eliminate {
                    curve,
                    target,
                    base: None,
                    direction: orient,
                    fallback: Box::new(row),
                });
                return Ok(());
            }
            if !e.is_clamped(at_end) {
                return Err(Error::NotClampedEnd {
                    entity: curve,
                    end: if at_end { "end" } else { "start" },
                });
            }
            let n = e.points().len();
            // Start: P₁ = P₀ + t·s·T. End: Pₙ₋₁ = Pₙ − t·s·T.
            let (target, base, direction) = if at_end {
                (n - 2, n - 1, [-orient[0], -orient[1]])
            } else {
                (1, 0, orient)
            };
            cx.push(Piece::Eliminate {
                curve,
                target,
                base: Some(base),
                direction,
                fallback: Box::new(row),
            });
        }
    }
    Ok(())
}

/// The shared pieces of the hand-written derivatives of [`TangentsParallel`]'s f.
pub(crate) struct AngleParts {
    theta: f64,
    c: f64,
    d: f64,
    r2: f64,
    /// d∇c − c∇d.
    u: [f64; 4],
    /// c∇c + d∇d.
    v: [f64; 4],
}

impl AngleParts {
    /// `None` for a zero tangent (θ is not defined there; the dual path says what it says).
    fn at(y: &[f64]) -> Option<Self> {
        let (a, b) = ([*y.first()?, *y.get(1)?], [*y.get(2)?, *y.get(3)?]);
        let (c, d) = (cross(a, b), dot(a, b));
        let r2 = c * c + d * d;
        if r2 <= 0.0 || !r2.is_finite() {
            return None;
        }
        let dc = [b[1], -b[0], -a[1], a[0]];
        let dd = [b[0], b[1], a[0], a[1]];
        Some(Self {
            theta: angle_of(c, d),
            c,
            d,
            r2,
            u: std::array::from_fn(|k| d * dc[k] - c * dd[k]),
            v: std::array::from_fn(|k| c * dc[k] + d * dd[k]),
        })
    }
}

/// The bases of both curves at the joint, restricted to the control points their derivatives
/// up to `order` read, with those points' slots (the first curve's, then the second's).
pub(crate) struct JointBases {
    pub(crate) first: (CurveBasis, f64),
    pub(crate) second: (CurveBasis, f64),
    pub(crate) slots: Vec<Slot>,
}
