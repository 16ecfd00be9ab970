//! The end conditions of a least-squares fit: a free end, an end on a data point, or a joint
//! with a given tangent direction (G1) and curvature vector (G2), solved as linear least
//! squares with the end control points constrained.
//!
//! For a clamped B-spline of degree p starting at P₀ with first interior knots t₁ = u_{p+1},
//! t₂ = u_{p+2} (t₁ = t₂ = 1 without interior knots), C′(0) = p(P₁ − P₀)/t₁ and the part of
//! C″(0) normal to the tangent is p(p − 1)/(t₁t₂) times the normal part of P₂ − P₀. With
//! P₁ = P₀ + βT (T the unit tangent, β > 0) the curvature vector at the start is therefore
//! k = (p − 1)t₁/(p t₂ β²) · (normal part of P₂ − P₀), so a given k holds exactly when
//! P₂ = P₀ + p t₂ β²/((p − 1)t₁) · k + γT for any γ: for a fixed β, G2 is a line for P₂.
//! The end of the curve is the start of the reversed one (tangent −T, the same curvature
//! vector, t₁ = 1 − u_n, t₂ = 1 − u_{n−1}).
//!
//! G1 is linear (P₁ on the tangent line). G2 is linear once β is known, so it is solved by a
//! fixed-point iteration on β: the G1 solution gives β, then [`G2_ROUNDS`] solves with P₂ on
//! the line of the last β, and a last solve with P₁ fixed at the final β, which makes the
//! curvature at the joint exactly k.

use nalgebra::{Point, SVector};

use super::least_squares::{fit_on_knots, EndRoles, OnSingular, Role};
use crate::bspline::BSplineCurve;
use crate::errors::Result;
use crate::knots::KnotVector;
use crate::scalar::{cst, from_usize, re, Scalar};

/// Fixed-point rounds on the tangent length β of a G2 joint.
const G2_ROUNDS: usize = 3;

/// How one end of a fitted curve is held.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum EndCondition<T: Scalar, const D: usize> {
    /// Not held.
    Free,
    /// On this point.
    Fixed(Point<T, D>),
    /// On this point, along this unit tangent (the direction of travel of the whole chain at
    /// the joint) and, when given, with this curvature vector.
    Joint {
        point: Point<T, D>,
        tangent: SVector<T, D>,
        curvature: Option<SVector<T, D>>,
    },
    /// On this point with this first derivative and, when given, this second derivative
    /// (with respect to the fit's parameter on [0, 1], in the direction of travel): the first
    /// two or three control points are then fixed (see [`clamped_roles`]).
    Clamped {
        point: Point<T, D>,
        first: SVector<T, D>,
        second: Option<SVector<T, D>>,
    },
}

/// The conditions at both ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Ends<T: Scalar, const D: usize> {
    pub start: EndCondition<T, D>,
    pub end: EndCondition<T, D>,
}

impl<T: Scalar, const D: usize> Ends<T, D> {
    /// Whether neither end is held to more than a point (free or fixed ends), so that an
    /// interpolation of the data keeps them.
    pub(crate) fn only_points(&self) -> bool {
        let plain =
            |c: &EndCondition<T, D>| matches!(c, EndCondition::Free | EndCondition::Fixed(_));
        plain(&self.start) && plain(&self.end)
    }
}

/// The distances (t₁, t₂) of the first two interior knots from the start of a clamped vector
/// of `degree` (1 where there is none), or from the end when `at_end`.
fn end_knots<T: Scalar>(knots: &KnotVector<T>, degree: usize, at_end: bool) -> (T, T) {
    // Knots t₀ … t_{n+p+1} of n + 1 control points: the last interior knot is t_n.
    let k = knots.as_slice();
    let n = k.len() - degree - 2;
    if at_end {
        (T::one() - k[n], T::one() - k[n - 1])
    } else {
        (k[degree + 1], k[degree + 2])
    }
}

/// The roles of the control points at one end, inwards: for a joint with curvature, with the
/// tangent length `beta` (None: P₂ free, the G1 solve).
fn end_roles<T: Scalar, const D: usize>(
    condition: &EndCondition<T, D>,
    knots: &KnotVector<T>,
    degree: usize,
    at_end: bool,
    beta: Option<(T, bool)>,
) -> Vec<Role<T, D>> {
    match *condition {
        EndCondition::Free => Vec::new(),
        EndCondition::Fixed(q) => vec![Role::Fixed(q)],
        EndCondition::Clamped {
            point,
            first,
            second,
        } => clamped_roles(point, first, second, knots, degree, at_end),
        EndCondition::Joint {
            point,
            tangent,
            curvature,
        } => {
            // Inwards from the end the curve travels against the chain's tangent.
            let inward = if at_end { -tangent } else { tangent };
            match (curvature, beta) {
                (Some(k), Some((b, final_round))) if degree >= 2 => {
                    let (t1, t2) = end_knots(knots, degree, at_end);
                    let p = from_usize::<T>(degree);
                    let scale = p * t2 * b * b / ((p - T::one()) * t1);
                    let second = Role::OnLine(point + k * scale, inward);
                    let first = if final_round {
                        Role::Fixed(point + inward * b)
                    } else {
                        Role::OnLine(point, inward)
                    };
                    vec![Role::Fixed(point), first, second]
                }
                _ => vec![Role::Fixed(point), Role::OnLine(point, inward)],
            }
        }
    }
}

/// The fixed control points of an end held to a point and its derivatives, inwards. At the
/// start C′(0) = p(P₁ − P₀)/t₁ and C″(0) = (p − 1)/t₁ · (p(P₂ − P₁)/t₂ − p(P₁ − P₀)/t₁), so
/// P₁ = P₀ + t₁C′/p and P₂ = P₁ + t₂/p · (t₁C″/(p − 1) + C′); the end is the start of the
/// reversed curve, whose first derivative is −C′ and second C″.
fn clamped_roles<T: Scalar, const D: usize>(
    point: Point<T, D>,
    first: SVector<T, D>,
    second: Option<SVector<T, D>>,
    knots: &KnotVector<T>,
    degree: usize,
    at_end: bool,
) -> Vec<Role<T, D>> {
    if degree == 0 {
        return vec![Role::Fixed(point)];
    }
    let (t1, t2) = end_knots(knots, degree, at_end);
    let p = from_usize::<T>(degree);
    let first = if at_end { -first } else { first };
    let p1 = point + first * (t1 / p);
    let mut roles = vec![Role::Fixed(point), Role::Fixed(p1)];
    if let Some(c2) = second.filter(|_| degree >= 2) {
        let p2 = p1 + (c2 * (t1 / (p - T::one())) + first) * (t2 / p);
        roles.push(Role::Fixed(p2));
    }
    roles
}

/// Whether a condition asks for curvature.
fn has_curvature<T: Scalar, const D: usize>(c: &EndCondition<T, D>) -> bool {
    matches!(
        c,
        EndCondition::Joint {
            curvature: Some(_),
            ..
        }
    )
}

/// The tangent length β of the curve at one end: (P₁ − P₀)·T inwards.
fn beta_of<T: Scalar, const D: usize>(
    curve: &BSplineCurve<T, D>,
    condition: &EndCondition<T, D>,
    at_end: bool,
) -> T {
    let cps = curve.control_points();
    let n = cps.len() - 1;
    match *condition {
        EndCondition::Joint { tangent, .. } => {
            let (p0, p1, inward) = if at_end {
                (cps[n], cps[n - 1], -tangent)
            } else {
                (cps[0], cps[1], tangent)
            };
            let b = (p1 - p0).dot(&inward);
            // A reversed tangent would be a cusp: keep a small positive length instead.
            if re(b) > 0.0 {
                b
            } else {
                cst::<T>(1e-6) * (cps[n] - cps[0]).norm().max(cst::<T>(1e-300))
            }
        }
        _ => T::zero(),
    }
}

/// Least squares on `knots` under the end conditions (see the module header); a singular
/// system is solved by [`OnSingular::MinimumNorm`].
pub(crate) fn solve<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    parameters: &[T],
    degree: usize,
    knots: &KnotVector<T>,
    ends: &Ends<T, D>,
) -> Result<BSplineCurve<T, D>> {
    solve_or(
        points,
        parameters,
        degree,
        knots,
        ends,
        OnSingular::MinimumNorm,
    )
}

/// [`solve`] with the choice of what a singular system does.
pub(crate) fn solve_or<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    parameters: &[T],
    degree: usize,
    knots: &KnotVector<T>,
    ends: &Ends<T, D>,
    on_singular: OnSingular,
) -> Result<BSplineCurve<T, D>> {
    let roles = |bs: Option<(T, bool)>, be: Option<(T, bool)>| EndRoles {
        start: end_roles(&ends.start, knots, degree, false, bs),
        end: end_roles(&ends.end, knots, degree, true, be),
    };
    let mut curve = fit_on_knots(
        points,
        parameters,
        degree,
        knots.clone(),
        &roles(None, None),
        on_singular,
    )?;
    let (g2_start, g2_end) = (has_curvature(&ends.start), has_curvature(&ends.end));
    if degree < 2 || !(g2_start || g2_end) {
        return Ok(curve);
    }
    let needed = 3 * usize::from(g2_start) + 3 * usize::from(g2_end);
    if knots.len() - degree - 1 < needed.max(degree + 1) {
        // Too few control points for both curvature conditions: G1 only.
        return Ok(curve);
    }
    for round in 0..=G2_ROUNDS {
        let final_round = round == G2_ROUNDS;
        let bs = g2_start.then(|| (beta_of(&curve, &ends.start, false), final_round));
        let be = g2_end.then(|| (beta_of(&curve, &ends.end, true), final_round));
        curve = fit_on_knots(
            points,
            parameters,
            degree,
            knots.clone(),
            &roles(bs, be),
            on_singular,
        )?;
    }
    Ok(curve)
}
