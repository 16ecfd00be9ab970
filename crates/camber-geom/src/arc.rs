//! Circular arcs and their exact rational (NURBS) form.
//!
//! An arc has a centre c, a radius r > 0, a start angle a₀ and a sweep φ ∈ (0, 2π), and runs
//! counter-clockwise from its start to its end:
//!
//! A(t) = c + r·(cos θ, sin θ),  θ(t) = a₀ + t·φ,  t ∈ [0, 1],
//!
//! A′(t) = r·φ·(−sin θ, cos θ),  A″(t) = −r·φ²·(cos θ, sin θ).
//!
//! **Angles** are radians, counter-clockwise from +x. The start angle is kept as given; the end
//! angle a₁ is given too, and the sweep is a₁ − a₀ reduced modulo 2π into [0, 2π), so an arc
//! from 350° to 10° sweeps 20° (its end angle reads back as a₀ + φ). A sweep that reduces to
//! zero — start and end at one place, or a whole turn, which is a circle — is refused
//! ([`Error::DegenerateSweep`]), as are angles of magnitude above [`MAX_ANGLE`], where f64 no
//! longer resolves 10⁻¹² rad ([`Error::AngleTooLarge`]).
//!
//! **Rational form.** A circular arc of sweep Δ ≤ 90° is exactly the rational quadratic Bézier
//! curve with control points A(θ₀), c + r/cos(Δ/2)·(cos θₘ, sin θₘ) (θₘ the middle angle, the
//! corner where the end tangents meet) and A(θ₁), weights 1, cos(Δ/2), 1. [`CircularArc::to_nurbs`]
//! splits the arc into n = ⌈φ/90°⌉ equal pieces and joins them as one degree-2 NURBS curve on
//! [0, 1] with double interior knots k/n. Its parameter is not the angle: on a piece of half
//! angle α, the point at local parameter s lies at angle θₘ + β with
//! tan(β/2) = (2s − 1)·tan(α/2); the tests check that closed form.
//!
//! ```
//! use camber_geom::{CircularArc, ParametricCurve};
//! use nalgebra::Point2;
//! use std::f64::consts::FRAC_PI_2;
//! // A quarter circle of radius 2 about (1, 0), from +x to +y.
//! let arc = CircularArc::try_new(Point2::new(1.0, 0.0), 2.0, 0.0, FRAC_PI_2)?;
//! let mid = arc.point(0.5);
//! assert!((mid - Point2::new(1.0 + 2f64.sqrt(), 2f64.sqrt())).norm() < 1e-15);
//! let nurbs = arc.to_nurbs()?;
//! let p = nurbs.point(0.3)?;
//! assert!(((p - arc.center()).norm() - 2.0).abs() < 1e-14);
//! # Ok::<(), camber_geom::Error>(())
//! ```

use std::f64::consts::{FRAC_PI_2, TAU};

use nalgebra::{Point2, Vector2};

use crate::curve::check_points;
use crate::errors::{Error, Result};
use crate::knots::KnotVector;
use crate::nurbs::NurbsCurve2;
use crate::scalar::{cst, re, Scalar};

/// The largest magnitude of an arc angle, 1024 turns (about 6434 rad): the spacing of f64
/// there is 9·10⁻¹³ rad.
pub const MAX_ANGLE: f64 = 1024.0 * TAU;

/// The smallest sweep (and the least distance of the sweep below 2π) an arc may have, in
/// radians: the ends of an arc at angles up to [`MAX_ANGLE`] are placed to about 10⁻¹² of its
/// radius, so a sweep this large survives saving the ends and reading the angles back.
pub const MIN_SWEEP: f64 = 1e-9;

/// A circular arc (see the module documentation), generic over the scalar.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircularArc<T: Scalar> {
    center: Point2<T>,
    radius: T,
    start_angle: T,
    sweep: T,
}

/// # Construction
impl<T: Scalar> CircularArc<T> {
    /// The arc of centre `center` and radius `radius` from `start_angle` counter-clockwise to
    /// `end_angle` (radians; the sweep is their difference reduced modulo 2π).
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a non-finite coordinate, radius or angle;
    /// [`Error::NonPositiveRadius`] for r ≤ 0; [`Error::AngleTooLarge`] for an angle above
    /// [`MAX_ANGLE`] in magnitude; [`Error::DegenerateSweep`] when the reduced sweep is zero
    /// (within [`MIN_SWEEP`] of 0 or 2π).
    ///
    /// ```
    /// use camber_geom::{CircularArc, Error};
    /// use nalgebra::Point2;
    /// // From 350° to 10°: a 20° arc through +x.
    /// let arc = CircularArc::try_new(Point2::new(0.0, 0.0), 1.0, 350f64.to_radians(), 10f64.to_radians())?;
    /// assert!((arc.sweep() - 20f64.to_radians()).abs() < 1e-15);
    /// assert_eq!(
    ///     CircularArc::try_new(Point2::new(0.0, 0.0), -1.0, 0.0, 1.0),
    ///     Err(Error::NonPositiveRadius { value: -1.0 })
    /// );
    /// # Ok::<(), Error>(())
    /// ```
    pub fn try_new(center: Point2<T>, radius: T, start_angle: T, end_angle: T) -> Result<Self> {
        check_points(std::slice::from_ref(&center))?;
        let r = re(radius);
        if !r.is_finite() {
            return Err(Error::NonFinite {
                what: "arc radius",
                index: 0,
                value: r,
            });
        }
        if r <= 0.0 {
            return Err(Error::NonPositiveRadius { value: r });
        }
        for (what, a) in [
            ("arc start angle", start_angle),
            ("arc end angle", end_angle),
        ] {
            let value = re(a);
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
        }
        let turns = ((re(end_angle) - re(start_angle)) / TAU).floor();
        let sweep = end_angle - start_angle - cst::<T>(turns * TAU);
        let s = re(sweep);
        if !(MIN_SWEEP..=TAU - MIN_SWEEP).contains(&s) {
            return Err(Error::DegenerateSweep {
                start: re(start_angle),
                end: re(end_angle),
            });
        }
        Ok(Self {
            center,
            radius,
            start_angle,
            sweep,
        })
    }
}

impl<T: Scalar> CircularArc<T> {
    /// The centre c.
    pub fn center(&self) -> &Point2<T> {
        &self.center
    }

    /// The radius r (> 0).
    pub fn radius(&self) -> T {
        self.radius
    }

    /// The start angle a₀, as given.
    pub fn start_angle(&self) -> T {
        self.start_angle
    }

    /// The end angle a₀ + φ (the given end angle up to a multiple of 2π).
    pub fn end_angle(&self) -> T {
        self.start_angle + self.sweep
    }

    /// The sweep φ ∈ (0, 2π), counter-clockwise.
    pub fn sweep(&self) -> T {
        self.sweep
    }

    /// The angle θ(t) = a₀ + t·φ at parameter t.
    pub fn angle_at(&self, t: T) -> T {
        self.start_angle + t * self.sweep
    }

    /// The point c + r·(cos θ, sin θ) of the arc's circle at angle θ.
    pub fn point_at_angle(&self, angle: T) -> Point2<T> {
        self.center + Vector2::new(angle.cos(), angle.sin()) * self.radius
    }

    /// A(t), t ∈ [0, 1] (values outside continue around the circle).
    pub fn point(&self, t: T) -> Point2<T> {
        self.point_at_angle(self.angle_at(t))
    }

    /// A′(t) = r·φ·(−sin θ, cos θ).
    pub fn derivative(&self, t: T) -> Vector2<T> {
        let a = self.angle_at(t);
        Vector2::new(-a.sin(), a.cos()) * (self.radius * self.sweep)
    }

    /// A″(t) = −r·φ²·(cos θ, sin θ).
    pub fn second_derivative(&self, t: T) -> Vector2<T> {
        let a = self.angle_at(t);
        Vector2::new(a.cos(), a.sin()) * (-self.radius * self.sweep * self.sweep)
    }

    /// The start point A(0).
    pub fn start_point(&self) -> Point2<T> {
        self.point_at_angle(self.start_angle)
    }

    /// The end point A(1).
    pub fn end_point(&self) -> Point2<T> {
        self.point_at_angle(self.end_angle())
    }

    /// The length r·φ.
    pub fn length(&self) -> T {
        self.radius * self.sweep
    }

    /// Whether the direction of angle θ from the centre lies on the arc, within `tolerance`
    /// radians of it (real parts).
    pub fn contains_angle(&self, angle: T, tolerance: f64) -> bool {
        let d = (re(angle) - re(self.start_angle)).rem_euclid(TAU);
        let s = re(self.sweep);
        d <= s + tolerance || d >= TAU - tolerance
    }

    /// The exact rational form: a degree-2 NURBS curve on [0, 1] made of n = ⌈φ/90°⌉ pieces
    /// of equal sweep Δ = φ/n, each with control points A(θₖ), the tangents' corner
    /// c + r/cos(Δ/2)·(cos θₘ, sin θₘ) and A(θₖ₊₁), weights 1, cos(Δ/2), 1, joined at double
    /// knots k/n (2n + 1 control points).
    ///
    /// # Errors
    /// None for a valid arc (the kernel's checks of the NURBS curve pass).
    pub fn to_nurbs(&self) -> Result<NurbsCurve2<T>> {
        let (points, weights, knots) = unit_rational_arc(self.start_angle, self.sweep);
        let points = points
            .into_iter()
            .map(|p| self.center + p.coords * self.radius)
            .collect();
        NurbsCurve2::try_new(2, KnotVector::try_new(knots)?, points, weights)
    }
}

/// The rational quadratic form of the unit circle's arc from angle `start` counter-clockwise
/// through `sweep` ∈ (0, 2π]: n = ⌈sweep/90°⌉ pieces of equal sweep Δ, control points
/// (cos θₖ, sin θₖ), the corner (cos θₘ, sin θₘ)/cos(Δ/2) and (cos θₖ₊₁, sin θₖ₊₁), weights
/// 1, cos(Δ/2), 1, and the clamped knot vector with double interior knots k/n. Any affine
/// image of these control points with the same weights and knots is the affine image of the
/// arc (rational curves are affinely invariant), which is how circular and elliptic arcs get
/// their exact NURBS forms.
pub(crate) fn unit_rational_arc<T: Scalar>(start: T, sweep: T) -> (Vec<Point2<T>>, Vec<T>, Vec<T>) {
    let pieces = ((re(sweep) / FRAC_PI_2).ceil() as usize).clamp(1, 4);
    let n = cst::<T>(pieces as f64);
    let delta = sweep / n;
    let half = delta / cst::<T>(2.0);
    let w = half.cos();
    let unit = |a: T| Point2::new(a.cos(), a.sin());
    let mut points = Vec::with_capacity(2 * pieces + 1);
    let mut weights = Vec::with_capacity(2 * pieces + 1);
    let mut knots = vec![T::zero(); 3];
    points.push(unit(start));
    weights.push(T::one());
    for k in 0..pieces {
        let a0 = start + delta * cst::<T>(k as f64);
        points.push(Point2::from(unit(a0 + half).coords / w));
        weights.push(w);
        points.push(unit(a0 + delta));
        weights.push(T::one());
        let knot = if k + 1 == pieces {
            T::one()
        } else {
            cst::<T>((k + 1) as f64 / pieces as f64)
        };
        knots.push(knot);
        knots.push(knot);
    }
    knots.push(T::one());
    (points, weights, knots)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use crate::curve::ParametricCurve;
    use approx::assert_relative_eq;
    use proptest::prelude::*;
    use std::f64::consts::PI;

    /// The angle of the NURBS point at global parameter u in closed form: piece k = ⌊u·n⌋,
    /// local s = u·n − k, angle θₖ + α + 2·atan((2s − 1)·tan(α/2)), α = Δ/2.
    fn nurbs_angle(arc: &CircularArc<f64>, u: f64) -> f64 {
        let n = ((arc.sweep() / FRAC_PI_2).ceil() as usize).clamp(1, 4);
        let k = ((u * n as f64).floor() as usize).min(n - 1);
        let s = u * n as f64 - k as f64;
        let delta = arc.sweep() / n as f64;
        let alpha = delta / 2.0;
        arc.start_angle()
            + delta * k as f64
            + alpha
            + 2.0 * ((2.0 * s - 1.0) * (alpha / 2.0).tan()).atan()
    }

    #[test]
    fn a_quarter_arc_has_its_ends_middle_and_derivatives_in_closed_form() {
        let arc = CircularArc::try_new(Point2::new(1.0, -2.0), 3.0, 0.0, FRAC_PI_2).unwrap();
        assert_relative_eq!(arc.start_point(), Point2::new(4.0, -2.0), epsilon = 1e-15);
        assert_relative_eq!(arc.end_point(), Point2::new(1.0, 1.0), epsilon = 1e-15);
        // A′(0) = r·φ·(0, 1), A″(0) = −r·φ²·(1, 0).
        assert_relative_eq!(
            arc.derivative(0.0),
            Vector2::new(0.0, 3.0 * FRAC_PI_2),
            epsilon = 1e-14
        );
        assert_relative_eq!(
            arc.second_derivative(0.0),
            Vector2::new(-3.0 * FRAC_PI_2 * FRAC_PI_2, 0.0),
            epsilon = 1e-14
        );
        assert_relative_eq!(arc.length(), 3.0 * FRAC_PI_2, epsilon = 1e-15);
    }

    #[test]
    fn angles_are_reduced_to_a_counter_clockwise_sweep() {
        let c = Point2::new(0.0, 0.0);
        // 350° → 10° sweeps 20°; 10° → 350° sweeps 340°; 0 → −π/2 sweeps 3π/2; 0 → 5π sweeps π.
        for (a0, a1, sweep) in [
            (350f64.to_radians(), 10f64.to_radians(), 20f64.to_radians()),
            (10f64.to_radians(), 350f64.to_radians(), 340f64.to_radians()),
            (0.0, -FRAC_PI_2, 3.0 * FRAC_PI_2),
            (0.0, 5.0 * PI, PI),
        ] {
            let arc = CircularArc::try_new(c, 1.0, a0, a1).unwrap();
            assert_relative_eq!(arc.sweep(), sweep, epsilon = 1e-12);
            assert_relative_eq!(arc.start_angle(), a0);
            assert_relative_eq!(arc.end_point(), arc.point_at_angle(a1), epsilon = 1e-12);
        }
    }

    #[test]
    fn degenerate_and_non_finite_arcs_are_refused_with_their_values() {
        let c = Point2::new(0.0, 0.0);
        assert_eq!(
            CircularArc::try_new(c, 0.0, 0.0, 1.0),
            Err(Error::NonPositiveRadius { value: 0.0 })
        );
        assert_eq!(
            CircularArc::try_new(c, 1.0, 1.0, 1.0 + TAU),
            Err(Error::DegenerateSweep {
                start: 1.0,
                end: 1.0 + TAU
            })
        );
        assert!(matches!(
            CircularArc::try_new(c, f64::NAN, 0.0, 1.0),
            Err(Error::NonFinite {
                what: "arc radius",
                ..
            })
        ));
        assert!(matches!(
            CircularArc::try_new(c, 1.0, f64::INFINITY, 1.0),
            Err(Error::NonFinite {
                what: "arc start angle",
                ..
            })
        ));
        assert!(matches!(
            CircularArc::try_new(Point2::new(f64::NAN, 0.0), 1.0, 0.0, 1.0),
            Err(Error::NonFinite { .. })
        ));
        assert_eq!(
            CircularArc::try_new(c, 1.0, -1e5, 1.0),
            Err(Error::AngleTooLarge {
                what: "arc start angle",
                value: -1e5,
                max: MAX_ANGLE
            })
        );
    }

    #[test]
    fn the_rational_form_of_a_semicircle_has_two_pieces_and_the_textbook_weights() {
        let arc = CircularArc::try_new(Point2::new(0.0, 0.0), 1.0, 0.0, PI).unwrap();
        let n = arc.to_nurbs().unwrap();
        assert_eq!(n.control_points().len(), 5);
        let w = std::f64::consts::FRAC_1_SQRT_2;
        for (a, b) in n.weights().iter().zip([1.0, w, 1.0, w, 1.0]) {
            assert_relative_eq!(*a, b, epsilon = 1e-15);
        }
        // The corner of the first quarter is (1, 1).
        assert_relative_eq!(
            n.control_points()[1],
            Point2::new(1.0, 1.0),
            epsilon = 1e-15
        );
        assert_relative_eq!(
            n.knots().as_slice(),
            &[0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0][..]
        );
    }

    /// The arc's derivative against central differences of its own evaluation (the closed
    /// forms are written by hand, so they are checked by a second method).
    #[test]
    fn the_derivatives_match_central_differences() {
        let arc = CircularArc::try_new(Point2::new(0.3, 0.1), 1.7, -0.4, 2.9).unwrap();
        let h = 1e-5;
        for t in [0.0, 0.2, 0.5, 0.9, 1.0] {
            let d = (arc.point(t + h) - arc.point(t - h)) / (2.0 * h);
            let dd = (arc.derivative(t + h) - arc.derivative(t - h)) / (2.0 * h);
            assert_relative_eq!(arc.derivative(t), d, epsilon = 1e-8);
            assert_relative_eq!(arc.second_derivative(t), dd, epsilon = 1e-8);
        }
    }

    proptest! {
        /// At every parameter, the NURBS point lies on the arc's circle, at the angle the
        /// closed form of the rational parameterisation gives, and is the arc's own point
        /// there; the ends and the end tangent directions agree.
        #[test]
        fn the_rational_form_is_the_arc(
            cx in -50.0..50.0f64, cy in -50.0..50.0f64, r in 1e-3..1e3f64,
            a0 in -20.0..20.0f64, sweep in 1e-3..(TAU - 1e-3), u in 0.0..1.0f64,
        ) {
            let arc = CircularArc::try_new(Point2::new(cx, cy), r, a0, a0 + sweep).unwrap();
            let n = arc.to_nurbs().unwrap();
            let scale = r.max(cx.abs()).max(cy.abs());
            let (p, d) = n.point_and_derivative(u).unwrap();
            prop_assert!(((p - arc.center()).norm() - r).abs() <= 1e-13 * scale);
            let q = arc.point_at_angle(nurbs_angle(&arc, u));
            prop_assert!((p - q).norm() <= 1e-12 * scale, "{p} vs {q}");
            // The NURBS tangent is along the arc's counter-clockwise tangent at that point.
            let radial = p - arc.center();
            prop_assert!(radial.dot(&d).abs() <= 1e-9 * d.norm() * r);
            prop_assert!(radial.x * d.y - radial.y * d.x > 0.0);
            prop_assert!((n.point(0.0).unwrap() - arc.start_point()).norm() <= 1e-13 * scale);
            prop_assert!((n.point(1.0).unwrap() - arc.end_point()).norm() <= 1e-12 * scale);
        }
    }

    /// Many parameters on arcs of every piece count: the NURBS point equals the arc's point
    /// at the closed-form angle.
    #[test]
    fn the_rational_form_matches_the_arc_at_many_parameters() {
        for sweep in [
            0.3,
            FRAC_PI_2,
            2.0,
            PI,
            4.0,
            3.0 * FRAC_PI_2 + 0.01,
            TAU - 1e-6,
        ] {
            let arc = CircularArc::try_new(Point2::new(2.0, -1.0), 0.75, 1.2, 1.2 + sweep).unwrap();
            let n = arc.to_nurbs().unwrap();
            for k in 0..=400 {
                let u = f64::from(k) / 400.0;
                let p = n.point(u).unwrap();
                assert_relative_eq!(p, arc.point_at_angle(nurbs_angle(&arc, u)), epsilon = 1e-13);
            }
        }
    }
}
