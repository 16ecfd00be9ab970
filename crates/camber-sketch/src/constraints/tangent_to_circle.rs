//! `tangent_to_circle`: a curve touches a circle entity (c, r) or a circular arc (centre c,
//! start S, r = |S − c|), whose centre and radius may be unknowns, at a fixed or free contact
//! parameter u, running around it in a given direction:
//!
//! C(u) − c − σ·r·n(u) = 0 (two rows),  n = (−t_y, t_x), t = C′(u)/|C′(u)|,
//!
//! with σ = +1 for clockwise travel (the centre to the right of C′) and −1 for
//! counter-clockwise. It holds exactly when |C(u) − c| = r, (C(u) − c)·C′(u) = 0 and the travel
//! direction is the recorded one, so Newton cannot converge to the reversed branch. After every
//! solve the contact must be honest: no cusp, the rotation kept, and the curve on its recorded
//! side of the circle near the contact (a crossing calls for a clearance row); for an arc the
//! contact's direction from the centre must also lie within the arc's sweep (to the solve's
//! tolerance over the radius), else the solve fails with [`Error::ContactOffArc`] and the
//! sketch is left as it was: the arc's circle would touch the curve, the arc would not. File form:
//! `{"kind": "tangent_to_circle", "curve": 0, "circle": 4, "u": {"free": 0.5}, "side":
//! "outside", "rotation": "clockwise"}`.

use std::sync::Arc;

use camber_solve::derive::composed::{InnerMap, Outer};
use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use super::glyph::{self, Glyph};
use super::shared::arc_span::outside_sweep;
use super::shared::radii::Round;
use super::shared::round_contacts::round;
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{point_tangent, ContactSpec, ContactTarget, SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::curve_eval::CurveBasis;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::residuals::curve::{
    composed_hessian, composed_jacobian, curve_at, curve_block_sizes, curve_support, dot, Blocks,
    ComposedCurve, Param,
};
use crate::ground::vocabulary::{CircleSide, Contact, Rotation};

/// The curve touches the circle entity or circular arc at u: |C(u) − c|² = r² and
/// (C(u) − c)·C′(u) = 0, lying on `side` near the contact and running around it in
/// `rotation` (two rows; on an arc, the contact checked within its sweep after the solve).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TangentToCircle {
    /// The curve.
    pub curve: EntityId,
    /// The circle entity or circular arc (centre and radius may be unknowns).
    pub circle: EntityId,
    /// The contact parameter.
    pub u: Contact,
    /// Outside or inside the circle near the contact.
    pub side: CircleSide,
    /// The direction of travel around the circle.
    pub rotation: Rotation,
}

/// C(u) − c − σ·r·n(u) = 0 (see the module documentation). Blocks: curve, u, centre, then the
/// radius (a circle) or the start S with r = |S − c| (an arc; see [`CircleContact::on_arc`]).
///
/// ```
/// use camber_sketch::constraints::tangent_to_circle::CircleContact;
/// use camber_sketch::residuals::Param;
/// use camber_sketch::{curve_eval::CurveBasis, Entity};
/// use camber_solve::Residual;
/// use nalgebra::Point2;
/// // The segment y = 1 run left to right passes clockwise over the unit circle at u = ½.
/// let line = Entity::Line([Point2::new(-1.0, 1.0), Point2::new(1.0, 1.0)]);
/// let r = CircleContact::new(CurveBasis::of(&line).ok_or("curve")?, Param::Fixed(0.5), true);
/// let mut g = [1.0; 2];
/// r.eval::<f64>(&[&[-1.0, 1.0][..], &[1.0, 1.0][..], &[0.0, 0.0][..], &[1.0][..]], &mut g);
/// assert!(g[0].abs() < 1e-15 && g[1].abs() < 1e-15);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CircleContact {
    basis: CurveBasis,
    u: Param,
    sigma: f64,
    arc: bool,
}

impl CircleContact {
    /// The two rows of oriented tangency to a circle given by a centre block and a radius
    /// block; `clockwise` selects σ.
    pub fn new(basis: CurveBasis, u: Param, clockwise: bool) -> Self {
        Self {
            basis,
            u,
            sigma: if clockwise { 1.0 } else { -1.0 },
            arc: false,
        }
    }

    /// The same rows against a circular arc's circle: the blocks after the curve (and u) are
    /// the arc's centre c and start S, and r = |S − c|.
    ///
    /// ```
    /// use camber_sketch::constraints::tangent_to_circle::CircleContact;
    /// use camber_sketch::residuals::Param;
    /// use camber_sketch::{curve_eval::CurveBasis, Entity};
    /// use camber_solve::Residual;
    /// use nalgebra::Point2;
    /// // The segment y = 1 touches the arc about (0, 0) starting at (1, 0) at u = ½.
    /// let line = Entity::Line([Point2::new(-1.0, 1.0), Point2::new(1.0, 1.0)]);
    /// let r = CircleContact::new(CurveBasis::of(&line).ok_or("curve")?, Param::Fixed(0.5), true)
    ///     .on_arc();
    /// let mut g = [1.0; 2];
    /// r.eval::<f64>(&[&[-1.0, 1.0][..], &[1.0, 1.0][..], &[0.0, 0.0][..], &[1.0, 0.0][..]], &mut g);
    /// assert!(g[0].abs() < 1e-15 && g[1].abs() < 1e-15);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn on_arc(self) -> Self {
        Self { arc: true, ..self }
    }
}

impl Residual for CircleContact {
    fn name(&self) -> &str {
        TangentToCircle::LABEL
    }
    fn dim(&self) -> usize {
        2
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        let mut sizes = curve_block_sizes(&self.basis, self.u);
        sizes.extend([2, if self.arc { 2 } else { 1 }]);
        Some(sizes)
    }
    fn depends_on(&self, x: &[&[f64]], blocks: &mut [bool]) {
        curve_support(&self.basis, self.u, x, blocks);
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (c, c1, k) = curve_at(&self.basis, self.u, x);
        let (centre, last) = (x[k], x[k + 1]);
        // The radius r, or the arc's start S.
        let far = if self.arc { last[1] } else { T::zero() };
        let y = [c[0], c[1], c1[0], c1[1], centre[0], centre[1], last[0], far];
        self.outer(&y[..if self.arc { 8 } else { 7 }], out);
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

/// f(C, C′, c, r) = C − c − σ·r·n (inputs Cₓ, C_y, C′ₓ, C′_y, cₓ, c_y, then r, or Sₓ, S_y
/// of an arc with r = |S − c|).
impl Outer for CircleContact {
    fn outer<T: Scalar>(&self, y: &[T], out: &mut [T]) {
        let (c, c1, centre) = ([y[0], y[1]], [y[2], y[3]], [y[4], y[5]]);
        let r = if self.arc {
            let v = [y[6] - y[4], y[7] - y[5]];
            dot(v, v).sqrt()
        } else {
            y[6]
        };
        let speed = dot(c1, c1).sqrt();
        let s = cst::<T>(self.sigma) * r / speed;
        out[0] = c[0] - centre[0] + s * c1[1];
        out[1] = c[1] - centre[1] - s * c1[0];
    }
}

impl ComposedCurve for CircleContact {
    /// C(u), C′(u), the centre and the radius (or an arc's start) as the inputs of
    /// [`Outer::outer`], with their
    /// derivatives (in u too when it is free).
    fn inner(&self, blocks: &Blocks<'_>, map: &mut InnerMap) -> Option<()> {
        let k = blocks.curve(&self.basis, self.u, 0, 0..=1, map)?;
        blocks.block(k, map)?;
        blocks.block(k + 1, map)?;
        Some(())
    }
}

impl ConstraintKind for TangentToCircle {
    const TAG: &'static str = "tangent_to_circle";
    const LABEL: &'static str = "tangent to circle";

    fn entities(&self, out: &mut Entities) {
        out.add(self.curve);
        out.add(self.circle);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let round = Round::of(cx, self.circle)?;
        let (basis, mut slots, param) = cx.curve_contact(self.curve, self.u)?;
        // [c, r] for a circle, [c, S] for an arc.
        slots.push(Slot::Point(self.circle, 0));
        slots.push(if round.is_arc() {
            Slot::Point(self.circle, 1)
        } else {
            Slot::Radius(self.circle)
        });
        let clockwise = self.rotation == Rotation::Clockwise;
        let rows = CircleContact::new(basis, param, clockwise);
        let rows = if round.is_arc() { rows.on_arc() } else { rows };
        cx.residual(rows, slots, Some(Arc::new(*self)));
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        Ok(vec![glyph::tangent_arrow(at, self.curve, self.u.value())?])
    }

    fn set_free_parameter(&mut self, k: usize, value: f64) {
        if k == 0 {
            self.u.set_free(value);
        }
    }

    fn contact(&self) -> Option<ContactSpec> {
        Some(ContactSpec {
            curve: self.curve,
            u: self.u,
            target: ContactTarget::Circle {
                circle: self.circle,
                side: self.side,
                rotation: self.rotation,
            },
        })
    }
}

impl SolvedCheck for TangentToCircle {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let u = state.parameter(self.u, &mut 0);
        let curve = state.entity(self.curve)?;
        let Some((center, radius, arc)) = round(state.entity(self.circle)?) else {
            return Err(Error::UnknownEntity {
                entity: self.circle,
            });
        };
        let (p, t) = point_tangent(curve, self.curve, u)?;
        if let Some(arc) = arc {
            let direction = Vector2::new(p[0] - center.x, p[1] - center.y);
            if let Some(outside) = outside_sweep(&arc, direction, state.penetration) {
                return Err(Error::ContactOffArc {
                    constraint: state.owner,
                    arc: self.circle,
                    outside,
                });
            }
        }
        state.not_cusp(t[0].hypot(t[1]), state.floor(self.curve)?)?;
        let turn = (p[0] - center.x) * t[1] - (p[1] - center.y) * t[0];
        state.sense(match self.rotation {
            Rotation::CounterClockwise => turn,
            Rotation::Clockwise => -turn,
        })?;
        let sign = match self.side {
            CircleSide::Outside => 1.0,
            CircleSide::Inside => -1.0,
        };
        state.no_crossing(self.curve, u, |q| {
            sign * ((q[0] - center.x).hypot(q[1] - center.y) - radius)
        })
    }

    fn contact(&self) -> Option<ContactSpec> {
        ConstraintKind::contact(self)
    }
}
