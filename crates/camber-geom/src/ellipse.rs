//! Ellipses and elliptic arcs: points and derivatives of every order, the exact rational
//! (NURBS) form, arc length, closest points.
//!
//! An ellipse has a centre c, semi-axes a, b > 0 (a along its own x′ axis, b along y′, either
//! may be the longer) and a rotation θ of the x′ axis from +x. With the unit axes
//! u = (cos θ, sin θ) and v = (−sin θ, cos θ),
//!
//! E(φ) = c + a·cos φ·u + b·sin φ·v,  E⁽ᵏ⁾(φ) = a·cos(φ + kπ/2)·u + b·sin(φ + kπ/2)·v (k ≥ 1).
//!
//! φ is the *parametric* angle (the eccentric anomaly), not the polar angle of E(φ) − c, except
//! when a = b. In the ellipse's frame, x′ = (p − c)·u and y′ = (p − c)·v, its points satisfy the
//! implicit equation (x′/a)² + (y′/b)² = 1 ([`Ellipse::implicit_value`]).
//!
//! **Elliptic arcs** run like [`CircularArc`](crate::CircularArc)s: from a start parametric
//! angle φ₀ counter-clockwise (in the ellipse's frame, and so in the plane, since
//! (x′, y′) ↦ c + x′·u + y′·v is a rotation and a shift) through a sweep Δ ∈ (0, 2π), the end
//! angle minus the start reduced modulo 2π:
//!
//! A(t) = E(φ₀ + t·Δ), t ∈ [0, 1],  A⁽ᵏ⁾(t) = Δᵏ·E⁽ᵏ⁾(φ₀ + t·Δ).
//!
//! Angles are radians; a sweep that reduces to zero, or a whole turn (use [`Ellipse`]), is
//! refused ([`Error::DegenerateSweep`]); angles above [`MAX_ANGLE`] in magnitude are refused
//! ([`Error::AngleTooLarge`]).
//!
//! **Rational form.** The map (x, y) ↦ c + a·x·u + b·y·v is affine, and a rational curve's
//! affine image is the rational curve of the mapped control points with the same weights and
//! knots. So the exact NURBS form of an elliptic arc is the image of the unit circle's arc from
//! φ₀ through Δ in ⌈Δ/90°⌉ rational quadratic pieces (weights 1, cos(Δₖ/2), 1). The joints of
//! the pieces sit at the same parameters in both forms (t = k/n ↔ φ₀ + k·Δ/n); inside a piece of
//! half angle α the NURBS point at local parameter s is E(φₘ + β) with
//! tan(β/2) = (2s − 1)·tan(α/2), as for the circle.
//!
//! **Arc length** is ∫|A′(t)| dt, an incomplete elliptic integral of the second kind with no
//! elementary closed form; it is measured by the toolkit's adaptive Gauss–Legendre quadrature
//! under a work budget ([`arc_length`](crate::arc_length)). The tests check it against the
//! arithmetic–geometric-mean series of the complete integral, the Gauss–Kummer series, a
//! second quadrature rule and the NURBS form's length.
//!
//! **Curve queries.** Both types implement [`ParametricCurve`] (the ellipse on [0, 2π] like
//! [`Circle`](crate::Circle), the arc on [0, 1]) with their rational pieces as their exact
//! [`bezier_enclosure`](ParametricCurve::bezier_enclosure), so closest points, intersections
//! with lines, circles and curves, curve distances, offsets and arc lengths take them as they
//! are; [`EllipticArc::to_nurbs`] gives the NURBS curve for everything else (export, editing).
//!
//! ```
//! use camber_geom::{EllipticArc, ParametricCurve};
//! use nalgebra::{Point2, Vector2};
//! use std::f64::consts::FRAC_PI_2;
//! // The upper-right quarter of the ellipse x²/4 + y² = 1.
//! let arc = EllipticArc::try_new(Point2::new(0.0, 0.0), 2.0, 1.0, 0.0, 0.0, FRAC_PI_2)?;
//! assert!((arc.start_point() - Point2::new(2.0, 0.0)).norm() < 1e-15);
//! assert!((arc.end_point() - Point2::new(0.0, 1.0)).norm() < 1e-15);
//! // Its tangent at the start points straight up (+b·v, scaled by the sweep).
//! assert!((arc.derivative_at(0.0, 1) - Vector2::new(0.0, FRAC_PI_2)).norm() < 1e-15);
//! // Every point of the NURBS form satisfies (x/a)² + (y/b)² = 1.
//! let nurbs = arc.to_nurbs()?;
//! let p = nurbs.point(0.3)?;
//! assert!(arc.ellipse().implicit_value(&p).abs() < 1e-14);
//! # Ok::<(), camber_geom::Error>(())
//! ```

use std::f64::consts::TAU;

use nalgebra::{Point2, SVector, Vector2};

use crate::arc::{unit_rational_arc, MAX_ANGLE, MIN_SWEEP};
use crate::arc_length::{arc_length_with, ArcLength};
use crate::budget::Budget;
use crate::curve::{check_parameter, check_points, ParametricCurve};
use crate::errors::{Error, Result};
use crate::knots::KnotVector;
use crate::nurbs::NurbsCurve2;
use crate::queries::{closest_point, ClosestPoint, RationalPiece};
use crate::scalar::{cst, from_usize, re, Scalar};

/// A whole ellipse (see the module documentation), generic over the scalar.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipse<T: Scalar> {
    center: Point2<T>,
    a: T,
    b: T,
    rotation: T,
}

/// An arc of an ellipse (see the module documentation), generic over the scalar.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipticArc<T: Scalar> {
    ellipse: Ellipse<T>,
    start_angle: T,
    sweep: T,
}

/// Fails unless `angle` is finite and at most [`MAX_ANGLE`] in magnitude.
fn check_angle<T: Scalar>(what: &'static str, angle: T) -> Result<()> {
    let value = re(angle);
    if !value.is_finite() {
        return Err(Error::NonFinite {
            what,
            index: 0,
            value,
        });
    }
    if value.abs() > MAX_ANGLE {
        return Err(Error::AngleTooLarge {
            what,
            value,
            max: MAX_ANGLE,
        });
    }
    Ok(())
}

/// (cos(φ + kπ/2), sin(φ + kπ/2)) from cos φ and sin φ, exactly (no rounding of kπ/2).
fn quarter_turned<T: Scalar>(cos: T, sin: T, k: usize) -> (T, T) {
    match k % 4 {
        0 => (cos, sin),
        1 => (-sin, cos),
        2 => (-cos, -sin),
        _ => (sin, -cos),
    }
}

/// # Construction
impl<T: Scalar> Ellipse<T> {
    /// The ellipse of centre `center`, semi-axis `a` along the direction at angle `rotation`
    /// (radians from +x) and semi-axis `b` perpendicular to it.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a non-finite coordinate, semi-axis or rotation;
    /// [`Error::NonPositiveSemiAxis`] for a ≤ 0 or b ≤ 0 (naming the axis and the value);
    /// [`Error::AngleTooLarge`] for a rotation above [`MAX_ANGLE`] in magnitude.
    ///
    /// ```
    /// use camber_geom::{Ellipse, Error};
    /// use nalgebra::Point2;
    /// let e = Ellipse::try_new(Point2::new(1.0, 2.0), 3.0_f64, 1.0, 0.5)?;
    /// assert!((e.semi_axis_a() - 3.0).abs() < 1e-15);
    /// assert_eq!(
    ///     Ellipse::try_new(Point2::new(0.0, 0.0), 0.0, 1.0, 0.0),
    ///     Err(Error::NonPositiveSemiAxis { axis: "a", value: 0.0 })
    /// );
    /// # Ok::<(), Error>(())
    /// ```
    pub fn try_new(center: Point2<T>, a: T, b: T, rotation: T) -> Result<Self> {
        check_points(std::slice::from_ref(&center))?;
        for (axis, what, value) in [
            ("a", "ellipse semi-axis a", a),
            ("b", "ellipse semi-axis b", b),
        ] {
            let value = re(value);
            if !value.is_finite() {
                return Err(Error::NonFinite {
                    what,
                    index: 0,
                    value,
                });
            }
            if value <= 0.0 {
                return Err(Error::NonPositiveSemiAxis { axis, value });
            }
        }
        check_angle("ellipse rotation", rotation)?;
        Ok(Self {
            center,
            a,
            b,
            rotation,
        })
    }
}

impl<T: Scalar> Ellipse<T> {
    /// The centre c.
    pub fn center(&self) -> &Point2<T> {
        &self.center
    }

    /// The semi-axis a (> 0), along u.
    pub fn semi_axis_a(&self) -> T {
        self.a
    }

    /// The semi-axis b (> 0), along v.
    pub fn semi_axis_b(&self) -> T {
        self.b
    }

    /// The rotation θ of the a-axis from +x (radians, counter-clockwise).
    pub fn rotation(&self) -> T {
        self.rotation
    }

    /// The unit axes u = (cos θ, sin θ) and v = (−sin θ, cos θ).
    pub fn axes(&self) -> (Vector2<T>, Vector2<T>) {
        let (s, c) = (self.rotation.sin(), self.rotation.cos());
        (Vector2::new(c, s), Vector2::new(-s, c))
    }

    /// The point c + x·u + y·v of the ellipse's frame coordinates (x, y).
    fn frame_point(&self, x: T, y: T) -> Point2<T> {
        let (u, v) = self.axes();
        self.center + u * x + v * y
    }

    /// E(φ) = c + a·cos φ·u + b·sin φ·v at the parametric angle φ.
    pub fn point_at_angle(&self, angle: T) -> Point2<T> {
        self.frame_point(self.a * angle.cos(), self.b * angle.sin())
    }

    /// The derivative E⁽ᵏ⁾(φ) = a·cos(φ + kπ/2)·u + b·sin(φ + kπ/2)·v with respect to the
    /// parametric angle, k = `order` ≥ 1; for `order` 0, the point E(φ) as a vector from the
    /// origin.
    pub fn derivative_at_angle(&self, angle: T, order: usize) -> Vector2<T> {
        if order == 0 {
            return self.point_at_angle(angle).coords;
        }
        let (c, s) = quarter_turned(angle.cos(), angle.sin(), order);
        let (u, v) = self.axes();
        u * (self.a * c) + v * (self.b * s)
    }

    /// The frame coordinates (x′, y′) = ((p − c)·u, (p − c)·v) of a point.
    pub fn to_frame(&self, p: &Point2<T>) -> Vector2<T> {
        let (u, v) = self.axes();
        let d = p - self.center;
        Vector2::new(d.dot(&u), d.dot(&v))
    }

    /// (x′/a)² + (y′/b)² − 1: zero on the ellipse, negative inside, positive outside.
    pub fn implicit_value(&self, p: &Point2<T>) -> T {
        let q = self.to_frame(p);
        let (x, y) = (q.x / self.a, q.y / self.b);
        x * x + y * y - T::one()
    }

    /// The parametric angle of the frame direction of `p` scaled to the unit circle,
    /// atan2(y′/b, x′/a) ∈ (−π, π]: for a point on the ellipse, the φ with E(φ) = p.
    pub fn angle_of(&self, p: &Point2<T>) -> T {
        let q = self.to_frame(p);
        (q.y / self.b).atan2(q.x / self.a)
    }

    /// The exact rational form: a closed degree-2 NURBS curve on [0, 1] of four quarter
    /// pieces starting at E(0), the affine image of the unit circle's (9 control points,
    /// weights 1, √½, 1, …). Its parameter u lands on the ellipse's angle at the joints:
    /// E(2π·k/4) at u = k/4.
    ///
    /// # Errors
    /// None for a valid ellipse (the NURBS kernel's checks pass).
    pub fn to_nurbs(&self) -> Result<NurbsCurve2<T>> {
        self.rational_form(T::zero(), T::two_pi())
    }

    /// The affine image of the unit circle's rational arc from `start` through `sweep`.
    fn rational_form(&self, start: T, sweep: T) -> Result<NurbsCurve2<T>> {
        let (points, weights, knots) = unit_rational_arc(start, sweep);
        let points = points
            .into_iter()
            .map(|p| self.frame_point(self.a * p.x, self.b * p.y))
            .collect();
        NurbsCurve2::try_new(2, KnotVector::try_new(knots)?, points, weights)
    }

    /// The circumference, to an absolute `tolerance` (length units), under the default budget.
    ///
    /// # Errors
    /// As [`arc_length`](crate::arc_length::arc_length): a bad tolerance, an exhausted budget.
    ///
    /// ```
    /// use camber_geom::Ellipse;
    /// use nalgebra::Point2;
    /// let circle = Ellipse::try_new(Point2::new(0.0, 0.0), 2.0, 2.0, 0.3)?;
    /// let length = circle.circumference(1e-12)?.length;
    /// assert!((length - 4.0 * std::f64::consts::PI).abs() < 1e-12);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn circumference(&self, tolerance: f64) -> Result<ArcLength<T>> {
        arc_length_with(self, tolerance, &Budget::default())
    }

    /// The point of the ellipse nearest to `p` (its parametric angle in [0, 2π], the point,
    /// the distance), by the toolkit's closest-point search.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a non-finite query point.
    pub fn closest_point(&self, p: &Point2<T>) -> Result<ClosestPoint<T, 2>> {
        closest_point(self, p)
    }

    /// Whether `p` lies on the ellipse within `tolerance` (length units).
    ///
    /// # Errors
    /// As [`closest_point`](Self::closest_point).
    pub fn contains_point(&self, p: &Point2<T>, tolerance: f64) -> Result<bool> {
        Ok(re(self.closest_point(p)?.distance) <= tolerance)
    }
}

impl<T: Scalar> ParametricCurve<T, 2> for Ellipse<T> {
    /// [0, 2π]: the parametric angle.
    fn domain(&self) -> (T, T) {
        (T::zero(), T::two_pi())
    }

    fn derivatives_into(&self, u: T, out: &mut [SVector<T, 2>]) -> Result<()> {
        check_parameter(u, self.domain())?;
        for (k, slot) in out.iter_mut().enumerate() {
            *slot = self.derivative_at_angle(u, k);
        }
        Ok(())
    }

    /// The quarter angles, where the rational pieces join.
    fn breakpoints(&self) -> Vec<T> {
        (0..=4)
            .map(|k| T::frac_pi_2() * from_usize::<T>(k))
            .collect()
    }

    /// The four rational quadratic quarters, on [kπ/2, (k + 1)π/2].
    fn bezier_enclosure(&self) -> Result<Option<Vec<RationalPiece<2>>>> {
        let pieces = crate::queries::pieces::nurbs_form(&self.to_nurbs()?);
        Ok(Some(
            pieces
                .into_iter()
                .map(|p| {
                    let (s, e) = (p.start * TAU, p.end * TAU);
                    p.reparameterized(s, e)
                })
                .collect(),
        ))
    }
}

/// # Construction
impl<T: Scalar> EllipticArc<T> {
    /// The arc of the ellipse (`center`, `a`, `b`, `rotation`, as [`Ellipse::try_new`]) from the
    /// parametric angle `start_angle` counter-clockwise to `end_angle` (radians; the sweep is
    /// their difference reduced modulo 2π).
    ///
    /// # Errors
    /// Those of [`Ellipse::try_new`]; [`Error::NonFinite`] or [`Error::AngleTooLarge`] for a bad
    /// angle; [`Error::DegenerateSweep`] when the reduced sweep is within [`MIN_SWEEP`] of 0 or
    /// 2π.
    ///
    /// ```
    /// use camber_geom::{EllipticArc, Error};
    /// use nalgebra::Point2;
    /// let c = Point2::new(0.0, 0.0);
    /// // From 350° to 10°: a 20° sweep of the parametric angle.
    /// let arc = EllipticArc::try_new(c, 2.0, 1.0, 0.0, 350f64.to_radians(), 10f64.to_radians())?;
    /// assert!((arc.sweep() - 20f64.to_radians()).abs() < 1e-15);
    /// assert_eq!(
    ///     EllipticArc::try_new(c, 2.0, 1.0, 0.0, 0.5, 0.5),
    ///     Err(Error::DegenerateSweep { start: 0.5, end: 0.5 })
    /// );
    /// # Ok::<(), Error>(())
    /// ```
    pub fn try_new(
        center: Point2<T>,
        a: T,
        b: T,
        rotation: T,
        start_angle: T,
        end_angle: T,
    ) -> Result<Self> {
        Ellipse::try_new(center, a, b, rotation)?.arc(start_angle, end_angle)
    }
}

impl<T: Scalar> Ellipse<T> {
    /// The arc of this ellipse from `start_angle` to `end_angle` (see
    /// [`EllipticArc::try_new`]).
    ///
    /// # Errors
    /// As [`EllipticArc::try_new`] for the angles.
    pub fn arc(&self, start_angle: T, end_angle: T) -> Result<EllipticArc<T>> {
        check_angle("elliptic arc start angle", start_angle)?;
        check_angle("elliptic arc end angle", end_angle)?;
        let turns = ((re(end_angle) - re(start_angle)) / TAU).floor();
        let sweep = end_angle - start_angle - cst::<T>(turns * TAU);
        if !(MIN_SWEEP..=TAU - MIN_SWEEP).contains(&re(sweep)) {
            return Err(Error::DegenerateSweep {
                start: re(start_angle),
                end: re(end_angle),
            });
        }
        Ok(EllipticArc {
            ellipse: *self,
            start_angle,
            sweep,
        })
    }
}

impl<T: Scalar> EllipticArc<T> {
    /// The whole ellipse the arc lies on.
    pub fn ellipse(&self) -> &Ellipse<T> {
        &self.ellipse
    }

    /// The start parametric angle φ₀, as given.
    pub fn start_angle(&self) -> T {
        self.start_angle
    }

    /// The end parametric angle φ₀ + Δ (the given end angle up to a multiple of 2π).
    pub fn end_angle(&self) -> T {
        self.start_angle + self.sweep
    }

    /// The sweep Δ ∈ (0, 2π) of the parametric angle, counter-clockwise.
    pub fn sweep(&self) -> T {
        self.sweep
    }

    /// The parametric angle φ(t) = φ₀ + t·Δ at parameter t.
    pub fn angle_at(&self, t: T) -> T {
        self.start_angle + t * self.sweep
    }

    /// A(t) = E(φ₀ + t·Δ) (values of t outside [0, 1] continue around the ellipse).
    pub fn point_at(&self, t: T) -> Point2<T> {
        self.ellipse.point_at_angle(self.angle_at(t))
    }

    /// A⁽ᵏ⁾(t) = Δᵏ·E⁽ᵏ⁾(φ₀ + t·Δ), k = `order` (for 0, the point as a vector).
    pub fn derivative_at(&self, t: T, order: usize) -> Vector2<T> {
        let mut scale = T::one();
        for _ in 0..order {
            scale *= self.sweep;
        }
        self.ellipse.derivative_at_angle(self.angle_at(t), order) * scale
    }

    /// The start point A(0).
    pub fn start_point(&self) -> Point2<T> {
        self.ellipse.point_at_angle(self.start_angle)
    }

    /// The end point A(1).
    pub fn end_point(&self) -> Point2<T> {
        self.ellipse.point_at_angle(self.end_angle())
    }

    /// Whether the parametric angle φ lies on the arc, within `tolerance` radians (real parts).
    pub fn contains_angle(&self, angle: T, tolerance: f64) -> bool {
        let d = (re(angle) - re(self.start_angle)).rem_euclid(TAU);
        let s = re(self.sweep);
        d <= s + tolerance || d >= TAU - tolerance
    }

    /// The exact rational form on [0, 1]: n = ⌈Δ/90°⌉ rational quadratic pieces joined at
    /// double knots k/n, the affine image of the unit circle's arc (see the module
    /// documentation); its joints land on A(k/n).
    ///
    /// # Errors
    /// None for a valid arc (the NURBS kernel's checks pass).
    pub fn to_nurbs(&self) -> Result<NurbsCurve2<T>> {
        self.ellipse.rational_form(self.start_angle, self.sweep)
    }

    /// The arc length ∫₀¹ |A′(t)| dt to an absolute `tolerance` (length units), under
    /// `budget`.
    ///
    /// # Errors
    /// As [`arc_length_with`]: a bad tolerance, [`Error::BudgetExhausted`],
    /// [`Error::Cancelled`].
    ///
    /// ```
    /// use camber_geom::{budget::Budget, EllipticArc};
    /// use nalgebra::Point2;
    /// // Half of a circle of radius 3 drawn as an ellipse: 3π.
    /// let arc = EllipticArc::try_new(Point2::new(0.0, 0.0), 3.0, 3.0, 1.0, 0.0, std::f64::consts::PI)?;
    /// let length = arc.length_with(1e-12, &Budget::default())?.length;
    /// assert!((length - 3.0 * std::f64::consts::PI).abs() < 1e-12);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn length_with(&self, tolerance: f64, budget: &Budget) -> Result<ArcLength<T>> {
        arc_length_with(self, tolerance, budget)
    }

    /// The point of the arc nearest to `p` (its parameter t ∈ [0, 1], the point, the
    /// distance): an interior foot or an end.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a non-finite query point.
    pub fn closest_point(&self, p: &Point2<T>) -> Result<ClosestPoint<T, 2>> {
        closest_point(self, p)
    }

    /// Whether `p` lies on the arc within `tolerance` (length units).
    ///
    /// # Errors
    /// As [`closest_point`](Self::closest_point).
    pub fn contains_point(&self, p: &Point2<T>, tolerance: f64) -> Result<bool> {
        Ok(re(self.closest_point(p)?.distance) <= tolerance)
    }

    /// How many rational pieces the NURBS form has: ⌈Δ/90°⌉, 1 to 4.
    fn piece_count(&self) -> usize {
        ((re(self.sweep) / std::f64::consts::FRAC_PI_2).ceil() as usize).clamp(1, 4)
    }
}

impl<T: Scalar> ParametricCurve<T, 2> for EllipticArc<T> {
    /// [0, 1], from the start to the end.
    fn domain(&self) -> (T, T) {
        (T::zero(), T::one())
    }

    fn derivatives_into(&self, u: T, out: &mut [SVector<T, 2>]) -> Result<()> {
        check_parameter(u, self.domain())?;
        let angle = self.angle_at(u);
        let mut scale = T::one();
        for (k, slot) in out.iter_mut().enumerate() {
            *slot = self.ellipse.derivative_at_angle(angle, k) * scale;
            scale *= self.sweep;
        }
        Ok(())
    }

    /// The joints k/n of the rational pieces.
    fn breakpoints(&self) -> Vec<T> {
        let n = self.piece_count();
        (0..=n)
            .map(|k| {
                if k == n {
                    T::one()
                } else {
                    cst::<T>(k as f64 / n as f64)
                }
            })
            .collect()
    }

    /// The rational quadratic pieces of [`to_nurbs`](EllipticArc::to_nurbs), on [k/n, (k+1)/n].
    fn bezier_enclosure(&self) -> Result<Option<Vec<RationalPiece<2>>>> {
        Ok(Some(crate::queries::pieces::nurbs_form(&self.to_nurbs()?)))
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use approx::assert_relative_eq;
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_6, PI};

    fn tilted() -> Ellipse<f64> {
        Ellipse::try_new(Point2::new(1.0, -2.0), 3.0, 1.0, FRAC_PI_6).unwrap()
    }

    #[test]
    fn points_and_tangents_at_the_quarter_angles_are_the_axis_ends() {
        let e = tilted();
        let (s, c) = (0.5, 3f64.sqrt() / 2.0);
        let (u, v) = (Vector2::new(c, s), Vector2::new(-s, c));
        let centre = Point2::new(1.0, -2.0);
        assert_relative_eq!(e.point_at_angle(0.0), centre + u * 3.0, epsilon = 1e-15);
        assert_relative_eq!(e.point_at_angle(FRAC_PI_2), centre + v, epsilon = 1e-15);
        assert_relative_eq!(e.point_at_angle(PI), centre - u * 3.0, epsilon = 1e-15);
        // E′(0) = b·v (straight along the b-axis), E′(π/2) = −a·u, E″(0) = −a·u.
        assert_relative_eq!(e.derivative_at_angle(0.0, 1), v, epsilon = 1e-15);
        assert_relative_eq!(
            e.derivative_at_angle(FRAC_PI_2, 1),
            -u * 3.0,
            epsilon = 1e-15
        );
        assert_relative_eq!(e.derivative_at_angle(0.0, 2), -u * 3.0, epsilon = 1e-15);
        // The fourth derivative comes back to the position relative to the centre.
        assert_relative_eq!(
            e.derivative_at_angle(0.7, 4),
            e.point_at_angle(0.7) - centre,
            epsilon = 1e-15
        );
        // An arc's derivatives carry the sweep: A′(0) = Δ·b·v.
        let arc = e.arc(0.0, FRAC_PI_2).unwrap();
        assert_relative_eq!(arc.derivative_at(0.0, 1), v * FRAC_PI_2, epsilon = 1e-15);
        assert_relative_eq!(arc.end_point(), centre + v, epsilon = 1e-15);
    }

    #[test]
    fn frame_coordinates_satisfy_the_implicit_equation_and_give_back_the_angle() {
        let e = tilted();
        for k in 0..16 {
            let phi = -PI + 0.1 + f64::from(k) * TAU / 16.0;
            let p = e.point_at_angle(phi);
            assert!(e.implicit_value(&p).abs() < 1e-15);
            assert_relative_eq!(e.angle_of(&p), phi, epsilon = 1e-14);
            let q = e.to_frame(&p);
            assert_relative_eq!(q, Vector2::new(3.0 * phi.cos(), phi.sin()), epsilon = 1e-14);
        }
        // Inside negative, outside positive: the centre gives −1, 2a along u gives 3.
        assert_relative_eq!(e.implicit_value(e.center()), -1.0);
        let far = e.center() + e.axes().0 * 6.0;
        assert_relative_eq!(e.implicit_value(&far), 3.0, epsilon = 1e-14);
    }

    /// Every derivative order against central differences of the order below it (the closed
    /// forms are written by hand, so a second method checks them).
    #[test]
    fn derivatives_of_every_order_match_central_differences() {
        let arc = tilted().arc(-0.4, 2.9).unwrap();
        let h = 1e-6;
        for t in [0.0, 0.2, 0.5, 0.9, 1.0] {
            for k in 1..=6 {
                let fd =
                    (arc.derivative_at(t + h, k - 1) - arc.derivative_at(t - h, k - 1)) / (2.0 * h);
                let exact = arc.derivative_at(t, k);
                assert!(
                    (exact - fd).norm() <= 1e-7 * (1.0 + exact.norm()),
                    "order {k} at {t}: {exact} vs {fd}"
                );
            }
            // The trait's evaluation is the same.
            let all = arc.derivatives(t, 3).unwrap();
            for (k, d) in all.iter().enumerate() {
                assert_relative_eq!(*d, arc.derivative_at(t, k), epsilon = 1e-15);
            }
        }
    }

    #[test]
    fn arc_angles_are_reduced_to_a_counter_clockwise_sweep() {
        let e = tilted();
        for (a0, a1, sweep) in [
            (350f64.to_radians(), 10f64.to_radians(), 20f64.to_radians()),
            (10f64.to_radians(), 350f64.to_radians(), 340f64.to_radians()),
            (0.0, -FRAC_PI_2, 3.0 * FRAC_PI_2),
            (0.0, 5.0 * PI, PI),
        ] {
            let arc = e.arc(a0, a1).unwrap();
            assert_relative_eq!(arc.sweep(), sweep, epsilon = 1e-12);
            assert_relative_eq!(arc.start_angle(), a0);
            assert_relative_eq!(arc.end_point(), e.point_at_angle(a1), epsilon = 1e-12);
            assert!(arc.contains_angle(a0 + sweep / 2.0, 0.0));
            assert!(!arc.contains_angle(a0 + sweep + 0.5 * (TAU - sweep), 1e-9));
        }
    }

    #[test]
    fn bad_ellipses_and_arcs_are_refused_naming_the_value() {
        let c = Point2::new(0.0, 0.0);
        assert_eq!(
            Ellipse::try_new(c, 0.0, 1.0, 0.0),
            Err(Error::NonPositiveSemiAxis {
                axis: "a",
                value: 0.0
            })
        );
        assert_eq!(
            Ellipse::try_new(c, 1.0, -2.0, 0.0),
            Err(Error::NonPositiveSemiAxis {
                axis: "b",
                value: -2.0
            })
        );
        assert!(matches!(
            Ellipse::try_new(c, f64::NAN, 1.0, 0.0),
            Err(Error::NonFinite {
                what: "ellipse semi-axis a",
                ..
            })
        ));
        assert_eq!(
            Ellipse::try_new(c, 1.0, f64::INFINITY, 0.0),
            Err(Error::NonFinite {
                what: "ellipse semi-axis b",
                index: 0,
                value: f64::INFINITY
            })
        );
        assert!(matches!(
            Ellipse::try_new(c, 1.0, 1.0, f64::NAN),
            Err(Error::NonFinite {
                what: "ellipse rotation",
                ..
            })
        ));
        assert_eq!(
            Ellipse::try_new(c, 1.0, 1.0, 1e5),
            Err(Error::AngleTooLarge {
                what: "ellipse rotation",
                value: 1e5,
                max: MAX_ANGLE
            })
        );
        assert!(matches!(
            Ellipse::try_new(Point2::new(0.0, f64::NEG_INFINITY), 1.0, 1.0, 0.0),
            Err(Error::NonFinite { .. })
        ));
        assert_eq!(
            EllipticArc::try_new(c, 2.0, 1.0, 0.0, 1.0, 1.0 + TAU),
            Err(Error::DegenerateSweep {
                start: 1.0,
                end: 1.0 + TAU
            })
        );
        assert!(matches!(
            EllipticArc::try_new(c, 2.0, 1.0, 0.0, f64::NAN, 1.0),
            Err(Error::NonFinite {
                what: "elliptic arc start angle",
                ..
            })
        ));
        assert_eq!(
            EllipticArc::try_new(c, 2.0, 1.0, 0.0, 0.0, -1e6),
            Err(Error::AngleTooLarge {
                what: "elliptic arc end angle",
                value: -1e6,
                max: MAX_ANGLE
            })
        );
        // Outside the domain, the curve trait refuses the parameter.
        let arc = EllipticArc::try_new(c, 2.0, 1.0, 0.0, 0.0, 1.0).unwrap();
        assert!(matches!(
            arc.point(1.5),
            Err(Error::ParameterOutsideDomain { .. })
        ));
    }

    #[test]
    fn the_rational_form_of_a_full_ellipse_is_four_quarters_through_the_axis_ends() {
        let e = tilted();
        let n = e.to_nurbs().unwrap();
        assert_eq!(n.control_points().len(), 9);
        let w = std::f64::consts::FRAC_1_SQRT_2;
        for (a, b) in n
            .weights()
            .iter()
            .zip([1.0, w, 1.0, w, 1.0, w, 1.0, w, 1.0])
        {
            assert_relative_eq!(*a, b, epsilon = 1e-15);
        }
        // Joints at the axis ends; the first corner is c + a·u + b·v.
        for k in 0..=4 {
            let u = f64::from(k) / 4.0;
            let angle = FRAC_PI_2 * f64::from(k);
            assert_relative_eq!(
                n.point(u).unwrap(),
                e.point_at_angle(angle),
                epsilon = 1e-14
            );
        }
        let (u, v) = e.axes();
        assert_relative_eq!(
            n.control_points()[1],
            e.center() + u * 3.0 + v,
            epsilon = 1e-14
        );
    }
}
