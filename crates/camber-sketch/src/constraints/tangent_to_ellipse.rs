//! `tangent_to_ellipse`: a free-form curve touches an ellipse or an elliptic arc (centre E,
//! a-axis vertex V, semi-axis b, all possibly unknowns) in the ellipse's interior, at a fixed
//! or free curve parameter u. Where on the ellipse has no closed form, so the constraint owns
//! the contact's parametric angle θ as a free unknown (stored back after every solve). With
//! w = V − E, a = |w| and rot₉₀(w) = (−w_y, w_x),
//!
//! P(θ) = E + cos θ·w + (b/a)·sin θ·rot₉₀(w),  P′(θ) = −sin θ·w + (b/a)·cos θ·rot₉₀(w)
//!
//! (P′ runs counter-clockwise), the three rows are
//!
//! C(u) − P(θ) = 0 (two rows, length units),
//! atan2(σ·(P′(θ) × C′(u)), σ·(P′(θ)·C′(u))) = 0 (one row, radians),
//!
//! with σ = +1 when the curve runs counter-clockwise around the ellipse at the contact and −1
//! clockwise: the curve passes through the ellipse point and runs along its tangent in the
//! recorded direction (the angle row is smooth near its zero and vanishes only for that
//! direction, so Newton cannot settle on the reversed branch). With u free the constraint takes
//! one degree of freedom (three rows, two unknowns), with u fixed two, as `tangent_to_circle`.
//! After every solve the contact must be honest: no cusp on the curve, the rotation kept, the
//! curve on its recorded side of the ellipse near the contact (within the solve's penetration,
//! else [`Error::ContactCrossed`]), and on an elliptic arc θ within the arc's sweep (to the
//! tolerance over the smaller semi-axis, else [`Error::ContactOffArc`]); a failed check leaves
//! the sketch as it was. As a contact with a circle or line, it takes part in the solve's
//! active set of honest contact: a crossing beside the contact adds a clearance row against
//! the ellipse ([`crate::residuals::clearance`]), a collapsed tangent its speed floor. File form: `{"kind": "tangent_to_ellipse", "curve": 0, "ellipse": 1,
//! "u": {"free": 0.5}, "theta": 1.57, "side": "outside", "rotation": "clockwise"}` (θ in
//! radians, the start of the free unknown).

use std::sync::Arc;

use camber_geom::{Ellipse, EllipticArc};
use nalgebra::Point2;
use camber_solve::derive::composed::{InnerMap, Outer};
use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::shared::angles::angle_between;
use super::shared::arc_span::outside_elliptic_sweep;
use super::shared::ellipses::{contact_slots, ellipse_gap, ellipse_kind, ellipse_of};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{
    point_tangent, ContactSpec, ContactTarget, SolvedCheck, SolvedState,
};
use crate::ground::curve_eval::CurveBasis;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::{CircleSide, Contact, Rotation};
use crate::residuals::curve::{
    composed_hessian, composed_jacobian, curve_at, curve_block_sizes, curve_support, dot,
    Blocks, ComposedCurve, Param,
};

/// The curve touches the ellipse or elliptic arc at the curve parameter `u` and the ellipse's
/// parametric angle `theta` (free), lying on `side` of it near the contact and running around
/// it in `rotation` (three rows; on an arc, θ checked within its sweep after the solve).
///
/// ```
/// use camber_geom::{BezierCurve2, Ellipse, ParametricCurve};
/// use camber_sketch::constraints::{Fixed, TangentToEllipse};
/// use camber_sketch::{CircleSide, Contact, Entity, PointRef, Rotation, Sketch};
/// use nalgebra::Point2;
/// let mut s = Sketch::new();
/// // An ellipse with semi-axes 2 (along x) and 1, held; a flat cubic above it, ends held at
/// // height 1.5, is pulled down onto its top (0, 1).
/// let e = s.add_ellipse(&Ellipse::try_new(Point2::new(0.0, 0.0), 2.0, 1.0, 0.0)?)?;
/// s.add_constraint(Fixed::entity(e))?;
/// let points = vec![
///     Point2::new(-3.0, 1.5),
///     Point2::new(-1.0, 1.5),
///     Point2::new(1.0, 1.5),
///     Point2::new(3.0, 1.5),
/// ];
/// let c = s.add_bezier(BezierCurve2::try_new(points)?)?;
/// for j in [0, 3] {
///     s.add_constraint(Fixed::point(PointRef::Control(c, j)))?;
/// }
/// s.add_constraint(TangentToEllipse {
///     curve: c,
///     ellipse: e,
///     u: Contact::Free(0.5),
///     theta: std::f64::consts::FRAC_PI_2,
///     side: CircleSide::Outside,
///     rotation: Rotation::Clockwise,
/// })?;
/// s.solve()?;
/// let Entity::Bezier(curve) = s.entity(c)? else { unreachable!() };
/// // Started at u = ½ and θ = π/2, the least move keeps the symmetry: the contact is the
/// // top vertex.
/// let p = curve.point(0.5)?;
/// assert!(p.x.abs() < 1e-9 && (p.y - 1.0).abs() < 1e-9);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TangentToEllipse {
    /// The curve (Bézier, B-spline, NURBS, Hermite, composite or line).
    pub curve: EntityId,
    /// The ellipse or elliptic arc (its centre, vertex and semi-axis may be unknowns).
    pub ellipse: EntityId,
    /// The contact parameter on the curve.
    pub u: Contact,
    /// The contact's parametric angle on the ellipse (radians): where the free unknown
    /// starts, and its solved value after a solve.
    pub theta: f64,
    /// Outside or inside the ellipse near the contact.
    pub side: CircleSide,
    /// The direction of travel around the ellipse.
    pub rotation: Rotation,
}

/// The rows of the module documentation. Blocks: the curve's, u when free, then the ellipse's
/// centre E, vertex V, semi-axis b and the angle θ.
///
/// ```
/// use camber_sketch::constraints::tangent_to_ellipse::EllipseContact;
/// use camber_sketch::residuals::Param;
/// use camber_sketch::{curve_eval::CurveBasis, Entity};
/// use camber_solve::Residual;
/// use nalgebra::Point2;
/// // The segment y = 1 run left to right passes clockwise over the top (0, 1) of the
/// // ellipse with semi-axes 2 and 1 at u = ½, θ = π/2.
/// let line = Entity::Line([Point2::new(-1.0, 1.0), Point2::new(1.0, 1.0)]);
/// let r = EllipseContact::new(CurveBasis::of(&line).ok_or("curve")?, Param::Fixed(0.5), true);
/// let theta = [std::f64::consts::FRAC_PI_2];
/// let x: [&[f64]; 6] = [&[-1.0, 1.0], &[1.0, 1.0], &[0.0, 0.0], &[2.0, 0.0], &[1.0], &theta];
/// let mut g = [1.0; 3];
/// r.eval::<f64>(&x, &mut g);
/// assert!(g.iter().all(|v| v.abs() < 1e-15));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct EllipseContact {
    basis: CurveBasis,
    u: Param,
    sigma: f64,
}

impl EllipseContact {
    /// The three rows of oriented tangency of the curve of `basis` at `u` to an ellipse;
    /// `clockwise` selects σ.
    pub fn new(basis: CurveBasis, u: Param, clockwise: bool) -> Self {
        Self {
            basis,
            u,
            sigma: if clockwise { -1.0 } else { 1.0 },
        }
    }
}

impl Residual for EllipseContact {
    fn name(&self) -> &str {
        TangentToEllipse::LABEL
    }
    fn dim(&self) -> usize {
        3
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        let mut sizes = curve_block_sizes(&self.basis, self.u);
        sizes.extend([2, 2, 1, 1]);
        Some(sizes)
    }
    fn depends_on(&self, x: &[&[f64]], blocks: &mut [bool]) {
        curve_support(&self.basis, self.u, x, blocks);
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (c, c1, k) = curve_at(&self.basis, self.u, x);
        let (e, v) = (x[k], x[k + 1]);
        let y = [
            c[0], c[1], c1[0], c1[1], e[0], e[1], v[0], v[1], x[k + 2][0], x[k + 3][0],
        ];
        self.outer(&y, out);
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

/// f(C, C′, E, V, b, θ) = (C − P(θ), angle from P′(θ) to σ·C′) (inputs Cₓ, C_y, C′ₓ, C′_y, Eₓ,
/// E_y, Vₓ, V_y, b, θ).
impl Outer for EllipseContact {
    fn outer<T: Scalar>(&self, y: &[T], out: &mut [T]) {
        let (c, c1) = ([y[0], y[1]], [y[2], y[3]]);
        let w = [y[6] - y[4], y[7] - y[5]];
        let (b, theta) = (y[8], y[9]);
        let k = b / dot(w, w).sqrt();
        let turned = [-w[1], w[0]];
        let (sin, cos) = (theta.sin(), theta.cos());
        let p = [
            y[4] + cos * w[0] + k * sin * turned[0],
            y[5] + cos * w[1] + k * sin * turned[1],
        ];
        let tangent = [
            k * cos * turned[0] - sin * w[0],
            k * cos * turned[1] - sin * w[1],
        ];
        out[0] = c[0] - p[0];
        out[1] = c[1] - p[1];
        out[2] = angle_between(tangent, c1, self.sigma);
    }
}

impl ComposedCurve for EllipseContact {
    /// C(u), C′(u), then the ellipse's centre, vertex, semi-axis and θ as the inputs of
    /// [`Outer::outer`], with their derivatives (in u too when it is free).
    fn inner(&self, blocks: &Blocks<'_>, map: &mut InnerMap) -> Option<()> {
        let k = blocks.curve(&self.basis, self.u, 0, 0..=1, map)?;
        for j in k..k + 4 {
            blocks.block(j, map)?;
        }
        Some(())
    }
}

impl ConstraintKind for TangentToEllipse {
    const TAG: &'static str = "tangent_to_ellipse";
    const LABEL: &'static str = "tangent to ellipse";

    fn entities(&self, out: &mut Entities) {
        out.add(self.curve);
        out.add(self.ellipse);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        ellipse_kind(cx.entity(self.ellipse)?, self.ellipse)?;
        distinct(self.curve, self.ellipse)?;
        let (basis, mut slots, param) = cx.curve_contact(self.curve, self.u)?;
        slots.extend(contact_slots(self.ellipse, self.theta)?);
        let clockwise = self.rotation == Rotation::Clockwise;
        cx.residual(
            EllipseContact::new(basis, param, clockwise),
            slots,
            Some(Arc::new(*self)),
        );
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let ellipse = ellipse_of(at.lookup(self.ellipse)?, self.ellipse)?;
        Ok(vec![
            glyph::tangent_arrow(at, self.curve, self.u.value())?,
            Glyph::Ring(ellipse.point_at_angle(self.theta)),
        ])
    }

    fn contact(&self) -> Option<ContactSpec> {
        Some(ContactSpec {
            curve: self.curve,
            u: self.u,
            target: ContactTarget::Ellipse {
                ellipse: self.ellipse,
                side: self.side,
                rotation: self.rotation,
            },
        })
    }

    fn set_free_parameter(&mut self, k: usize, value: f64) {
        // The free parameters in slot order: u when it is free, then θ.
        let theta_at = usize::from(matches!(self.u, Contact::Free(_)));
        if k + 1 == theta_at {
            self.u.set_free(value);
        } else if k == theta_at && value.is_finite() {
            // The angle is periodic: keep the stored one in [0, 2π).
            self.theta = value.rem_euclid(std::f64::consts::TAU);
        }
    }
}

impl SolvedCheck for TangentToEllipse {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let mut next = 0;
        let u = state.parameter(self.u, &mut next);
        let theta = state.free.get(next).copied().unwrap_or(f64::NAN);
        let e = state.entity(self.ellipse)?;
        let ellipse = ellipse_of(e, self.ellipse)?;
        let arc = e.as_elliptic_arc();
        if let Some(arc) = &arc {
            if let Some(outside) = outside_elliptic_sweep(arc, theta, state.penetration) {
                return Err(Error::ContactOffArc {
                    constraint: state.owner,
                    arc: self.ellipse,
                    outside,
                });
            }
        }
        let (_, t) = point_tangent(state.entity(self.curve)?, self.curve, u)?;
        state.not_cusp(t[0].hypot(t[1]), state.floor(self.curve)?)?;
        let travel = ellipse.derivative_at_angle(theta, 1);
        let along = travel.x * t[0] + travel.y * t[1];
        state.sense(match self.rotation {
            Rotation::CounterClockwise => along,
            Rotation::Clockwise => -along,
        })?;
        let sign = match self.side {
            CircleSide::Outside => 1.0,
            CircleSide::Inside => -1.0,
        };
        state.no_crossing(self.curve, u, |q| {
            signed_gap(&ellipse, arc.as_ref(), q, state.penetration).map_or(f64::INFINITY, |g| sign * g)
        })
    }

    fn contact(&self) -> Option<ContactSpec> {
        ConstraintKind::contact(self)
    }
}

/// The signed distance from `q` to the ellipse to first order ([`ellipse_gap`]), or `None`
/// where it does not count: on an elliptic arc, where the point's parametric direction lies
/// off the arc's sweep.
fn signed_gap(
    ellipse: &Ellipse<f64>,
    arc: Option<&EllipticArc<f64>>,
    q: [f64; 2],
    penetration: f64,
) -> Option<f64> {
    let q = Point2::new(q[0], q[1]);
    if arc.is_some_and(|a| outside_elliptic_sweep(a, ellipse.angle_of(&q), penetration).is_some()) {
        return None;
    }
    Some(ellipse_gap(ellipse, &q))
}
