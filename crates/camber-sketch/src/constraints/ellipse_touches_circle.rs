//! `ellipse_touches_circle`: an ellipse or an elliptic arc (centre C, a-axis vertex V,
//! semi-axis b) touches a circle or a circular arc (centre c, radius r: a radius block, or
//! |S − c| for an arc) somewhere in its interior, from outside (each outside the other) or
//! from inside (one inside the other), as recorded. There is no closed form for where, so the
//! constraint owns the contact's parametric angle θ on the ellipse as a free unknown (stored
//! back after every solve). With w = V − C, a = |w|, u = w/a, v = rot₉₀(u),
//!
//! P(θ) = C + a·cos θ·u + b·sin θ·v,  P′(θ) = −a·sin θ·u + b·cos θ·v,
//! N(θ) = rot₋₉₀(P′) = b·cos θ·u + a·sin θ·v (the outward normal),
//!
//! the two rows, in length units, are
//!
//! P(θ) + s·r·N(θ)/|N(θ)| − c = 0 (s = +1 from outside, −1 from inside):
//!
//! the circle's centre lies at distance r from P(θ) along the ellipse's normal, on the recorded
//! side. They hold exactly when |P(θ) − c| = r and (P(θ) − c) × P′(θ) = 0 with the centre on
//! that side, so Newton cannot settle on the other side's contact; smooth wherever a > 0 and
//! b > 0 (|N| ≥ min(a, b)). The rows hold at every foot of a normal from c at distance r (up
//! to four for a centre inside the evolute): the solve follows the one θ starts nearest. From
//! outside the two cannot cross elsewhere (both are convex and the common tangent separates
//! them). From inside, the circle lies inside the ellipse when r is below the ellipse's radius
//! of curvature ρ(θ) at the contact and around it when r is above; after every solve the
//! ellipse (its sweep, for an arc) must then stay on that side of the circle (of its drawn
//! sweep, for an arc) at 512 samples, else [`Error::ContactCrossed`] names the constraint, the
//! parametric angle of the deepest crossing and its depth (a circle touching the top of an
//! ellipse from inside while poking out through the bottom is not an internal tangency). After
//! every solve the contact must also lie on the arcs: on an elliptic arc θ within
//! its sweep (to the solve's tolerance over the smaller semi-axis), on a circular arc the
//! direction (P(θ) − c)/r within its sweep (to the tolerance over the radius), else the solve
//! fails with [`Error::ContactOffArc`] naming the constraint and the arc, and the sketch is
//! left as it was. File form: `{"kind": "ellipse_touches_circle", "ellipse": 1, "circle": 2,
//! "tangency": "external", "theta": 4.71}` (θ in radians, the start of the free unknown).

use std::f64::consts::TAU;
use std::sync::Arc;

use camber_geom::Ellipse;
use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use nalgebra::{Point2, Vector2};
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::Glyph;
use super::shared::arc_span::{outside_elliptic_sweep, outside_sweep};
use super::shared::ellipses::{contact_slots, ellipse_kind, ellipse_of};
use super::shared::radii::{radius_of, Round};
use super::shared::round_contacts::round;
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::Tangency;
use crate::residuals::curve::{dot, sub};

/// The ellipse or elliptic arc touches the circle or circular arc at the free parametric
/// angle `theta`, from outside or inside (two rows and one unknown; the contact checked on
/// the arcs after the solve).
///
/// ```
/// use camber_geom::Ellipse;
/// use camber_sketch::constraints::{EllipseTouchesCircle, Fixed, HorizontalDistance, Radius};
/// use camber_sketch::vocabulary::PointPair;
/// use camber_sketch::{Entity, PointRef, Sketch, Tangency};
/// use nalgebra::Point2;
/// let mut s = Sketch::new();
/// // An ellipse with semi-axes 2 (along x) and 1, held; a circle of radius 0.5 rests on top.
/// let e = s.add_ellipse(&Ellipse::try_new(Point2::new(0.0, 0.0), 2.0, 1.0, 0.0)?)?;
/// s.add_constraint(Fixed::entity(e))?;
/// let c = s.add_entity(Entity::Circle { center: Point2::new(0.0, 1.8), radius: 0.5 })?;
/// s.add_constraint(Radius { circle: c, radius: 0.5 })?;
/// // The centres on one vertical.
/// let centres = PointPair::Points(PointRef::Control(e, 0), PointRef::Control(c, 0));
/// s.add_constraint(HorizontalDistance { of: centres, distance: 0.0 })?;
/// s.add_constraint(EllipseTouchesCircle {
///     ellipse: e,
///     circle: c,
///     tangency: Tangency::External,
///     theta: 1.5,
/// })?;
/// s.solve()?;
/// let Entity::Circle { center, .. } = s.entity(c)? else { unreachable!() };
/// assert!((center.y - 1.5).abs() < 1e-10);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EllipseTouchesCircle {
    /// The ellipse or elliptic arc.
    pub ellipse: EntityId,
    /// The circle or circular arc.
    pub circle: EntityId,
    /// Each outside the other, or one inside the other.
    pub tangency: Tangency,
    /// The contact's parametric angle on the ellipse (radians): where the free unknown starts,
    /// and its solved value after a solve.
    pub theta: f64,
}

/// The rows of the module documentation over the blocks [C, V, b, θ, c, r] (a circle) or
/// [C, V, b, θ, c, S] (a circular arc).
///
/// ```
/// use camber_sketch::constraints::ellipse_touches_circle::EllipseCircleContact;
/// use camber_sketch::Tangency;
/// use camber_solve::Residual;
/// let mut g = [f64::NAN; 2];
/// // Semi-axes 2 (along x) and 1 about (0, 0); a circle of radius 0.5 about (2.5, 0) touches
/// // the vertex θ = 0 from outside, one of radius 3 about (−1, 0) from inside.
/// let x: [&[f64]; 6] = [&[0.0, 0.0], &[2.0, 0.0], &[1.0], &[0.0], &[2.5, 0.0], &[0.5]];
/// EllipseCircleContact::new(Tangency::External, false).eval(&x, &mut g);
/// assert!(g[0].abs() < 1e-15 && g[1].abs() < 1e-15);
/// let x: [&[f64]; 6] = [&[0.0, 0.0], &[2.0, 0.0], &[1.0], &[0.0], &[-1.0, 0.0], &[3.0]];
/// EllipseCircleContact::new(Tangency::Internal, false).eval(&x, &mut g);
/// assert!(g[0].abs() < 1e-15 && g[1].abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipseCircleContact {
    tangency: Tangency,
    other_arc: bool,
}

impl EllipseCircleContact {
    /// The rows for the `tangency` with a circle (`other_arc` false) or a circular arc.
    pub fn new(tangency: Tangency, other_arc: bool) -> Self {
        Self {
            tangency,
            other_arc,
        }
    }
}

/// s: +1 when the circle's centre lies outside the ellipse (from outside), −1 inside.
fn side_sign(tangency: Tangency) -> f64 {
    match tangency {
        Tangency::External => 1.0,
        Tangency::Internal => -1.0,
    }
}

impl Residual for EllipseCircleContact {
    fn name(&self) -> &str {
        EllipseTouchesCircle::LABEL
    }
    fn dim(&self) -> usize {
        2
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        // [c, r] or [c, S].
        Some(vec![2, 2, 1, 1, 2, if self.other_arc { 2 } else { 1 }])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (centre, w, b, theta) = (x[0], sub(x[1], x[0]), x[2][0], x[3][0]);
        let a = dot(w, w).sqrt();
        // a·v = rot₉₀(w), so b·v = (b/a)·rot₉₀(w) and b·u = (b/a)·w.
        let turned = [-w[1], w[0]];
        let k = b / a;
        let (sin, cos) = (theta.sin(), theta.cos());
        let p = [
            centre[0] + cos * w[0] + k * sin * turned[0],
            centre[1] + cos * w[1] + k * sin * turned[1],
        ];
        let n = [
            k * cos * w[0] + sin * turned[0],
            k * cos * w[1] + sin * turned[1],
        ];
        let r = if self.other_arc {
            radius_of(true, &x[4..]).0
        } else {
            x[5][0]
        };
        let reach = cst::<T>(side_sign(self.tangency)) * r / dot(n, n).sqrt();
        out[0] = p[0] + reach * n[0] - x[4][0];
        out[1] = p[1] + reach * n[1] - x[4][1];
    }
}

/// The contact point P(θ), the tangent P′(θ) and the unit direction from the circle's centre
/// to P(θ), −s·N/|N|.
fn contact(ellipse: &Ellipse<f64>, theta: f64, tangency: Tangency) -> (Point2<f64>, Vector2<f64>, Vector2<f64>) {
    let p = ellipse.point_at_angle(theta);
    let t = ellipse.derivative_at_angle(theta, 1);
    let n = Vector2::new(t.y, -t.x).normalize();
    (p, t, n * -side_sign(tangency))
}

impl ConstraintKind for EllipseTouchesCircle {
    const TAG: &'static str = "ellipse_touches_circle";
    const LABEL: &'static str = "ellipse touches circle";

    fn entities(&self, out: &mut Entities) {
        out.add(self.ellipse);
        out.add(self.circle);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let elliptic_arc = ellipse_kind(cx.entity(self.ellipse)?, self.ellipse)?;
        distinct(self.ellipse, self.circle)?;
        let other = Round::of(cx, self.circle)?;
        let mut slots = contact_slots(self.ellipse, self.theta)?.to_vec();
        slots.extend([
            Slot::Point(self.circle, 0),
            if other.is_arc() {
                Slot::Point(self.circle, 1)
            } else {
                Slot::Radius(self.circle)
            },
        ]);
        let internal = self.tangency == Tangency::Internal;
        let check: Option<Arc<dyn SolvedCheck>> = if elliptic_arc || other.is_arc() || internal {
            Some(Arc::new(*self))
        } else {
            None
        };
        cx.residual(
            EllipseCircleContact::new(self.tangency, other.is_arc()),
            slots,
            check,
        );
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let ellipse = ellipse_of(at.lookup(self.ellipse)?, self.ellipse)?;
        let (p, t, _) = contact(&ellipse, self.theta, self.tangency);
        Ok(vec![Glyph::Arrow(p, t), Glyph::Ring(p)])
    }

    fn set_free_parameter(&mut self, k: usize, value: f64) {
        if k == 0 && value.is_finite() {
            // The angle is periodic: keep the stored one in [0, 2π).
            self.theta = value.rem_euclid(std::f64::consts::TAU);
        }
    }
}

impl SolvedCheck for EllipseTouchesCircle {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let theta = state.free.first().copied().unwrap_or(f64::NAN);
        let e = state.entity(self.ellipse)?;
        let ellipse = ellipse_of(e, self.ellipse)?;
        let off = |arc: EntityId, outside: f64| Error::ContactOffArc {
            constraint: state.owner,
            arc,
            outside,
        };
        if let Some(arc) = e.as_elliptic_arc() {
            if let Some(outside) = outside_elliptic_sweep(&arc, theta, state.penetration) {
                return Err(off(self.ellipse, outside));
            }
        }
        let Some((centre, r, circle_arc)) = round(state.entity(self.circle)?) else {
            return Err(Error::UnknownEntity {
                entity: self.circle,
            });
        };
        if let Some(arc) = &circle_arc {
            let (_, _, w) = contact(&ellipse, theta, self.tangency);
            if let Some(outside) = outside_sweep(arc, w, state.penetration) {
                return Err(off(self.circle, outside));
            }
        }
        if self.tangency == Tangency::Internal {
            let sweep = e
                .as_elliptic_arc()
                .map_or((0.0, TAU), |a| (a.start_angle(), a.sweep()));
            let drawn = |q: Point2<f64>| {
                circle_arc
                    .as_ref()
                    .is_none_or(|a| outside_sweep(a, q - centre, state.penetration).is_none())
            };
            if let Some((angle, depth)) =
                internal_crossing(&ellipse, theta, centre, r, sweep, drawn, state.penetration)
            {
                return Err(Error::ContactCrossed {
                    constraint: state.owner,
                    parameter: angle,
                    depth,
                });
            }
        }
        Ok(())
    }
}

/// Samples of the ellipse checked for a crossing of an internal contact.
const CROSSING_SAMPLES: usize = 512;

/// For an internal contact at θ: which of the two lies inside follows from the circle's radius
/// against the ellipse's radius of curvature there, ρ(θ) = (a²sin²θ + b²cos²θ)^{3/2}/(ab)
/// (r < ρ: the circle inside; r > ρ: the ellipse inside the circle; equal: osculating, not
/// decided, nothing checked). The deepest of [`CROSSING_SAMPLES`] points of the ellipse's
/// `(start, sweep)` on the wrong side of the circle by more than `penetration` (only where
/// `drawn` says the circle's arc is there), as (parametric angle, depth).
fn internal_crossing(
    ellipse: &Ellipse<f64>,
    theta: f64,
    centre: Point2<f64>,
    r: f64,
    (start, sweep): (f64, f64),
    drawn: impl Fn(Point2<f64>) -> bool,
    penetration: f64,
) -> Option<(f64, f64)> {
    let (a, b) = (ellipse.semi_axis_a(), ellipse.semi_axis_b());
    let (sin, cos) = theta.sin_cos();
    let rho = (a * a * sin * sin + b * b * cos * cos).powf(1.5) / (a * b);
    // +1: every ellipse point outside the circle; −1: inside it.
    let side = if r < rho * (1.0 - 1e-9) {
        1.0
    } else if r > rho * (1.0 + 1e-9) {
        -1.0
    } else {
        return None;
    };
    let mut worst: Option<(f64, f64)> = None;
    for k in 0..=CROSSING_SAMPLES {
        let angle = start + sweep * k as f64 / CROSSING_SAMPLES as f64;
        let q = ellipse.point_at_angle(angle);
        let gap = side * ((q - centre).norm() - r);
        if gap < -penetration && drawn(q) && worst.is_none_or(|(_, w)| -gap > w) {
            worst = Some((angle, -gap));
        }
    }
    worst
}
