//! SVG's elliptical arc command from its endpoint form to its centre form, as the SVG
//! specification's implementation notes give it (SVG 1.1 appendix F.6.5 and F.6.6).
//!
//! An arc `A rx ry φ fA fS x y` from the current point p₁ = (x₁, y₁) to p₂ = (x₂, y₂) lies on
//! the ellipse p(θ) = c + R(φ)·diag(rx, ry)·(cos θ, sin θ), θ from θ₁ to θ₁ + Δθ. With the
//! half chord in the ellipse's frame (x₁′, y₁′) = R(−φ)·(p₁ − p₂)/2 and its coordinates in the
//! unit circle's frame X = x₁′/rx, Y = y₁′/ry, Λ = X² + Y²:
//!
//! - radii of 0 make the arc the straight line p₁p₂ (F.6.6 step 1); negative radii count by
//!   their magnitude (step 2);
//! - when Λ > 1 the ellipse cannot reach both ends, so both radii are scaled by √Λ and the
//!   centre is the chord's midpoint (step 3);
//! - otherwise c′ = ±√((1 − Λ)/Λ)·(rx·Y, −ry·X), + when fA ≠ fS, and c = R(φ)·c′ + (p₁ + p₂)/2;
//! - θ₁ is the angle of u = (X − c′ₓ/rx, Y − c′ᵧ/ry) and Δθ the angle from u to
//!   v = (−X − c′ₓ/rx, −Y − c′ᵧ/ry), taken in (0, 2π) when fS = 1 and in (−2π, 0) when fS = 0.
//!
//! Working in the unit circle's frame (X, Y) rather than with rx²·ry² keeps large radii from
//! overflowing. Angles are radians; φ arrives in degrees, as SVG writes it.

use nalgebra::{Point2, Rotation2, Vector2};

/// The endpoint form of one arc command, in user coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct EndpointArc {
    /// The current point p₁.
    pub(crate) from: Point2<f64>,
    /// The end p₂.
    pub(crate) to: Point2<f64>,
    /// The radii as written (their magnitudes are used).
    pub(crate) rx: f64,
    /// See `rx`.
    pub(crate) ry: f64,
    /// The x-axis rotation φ, degrees.
    pub(crate) rotation_degrees: f64,
    /// fA: the arc of more than 180°.
    pub(crate) large_arc: bool,
    /// fS: the arc in the direction of increasing θ.
    pub(crate) sweep: bool,
}

/// The centre form of an arc: p(θ) = c + R(φ)·diag(rx, ry)·(cos θ, sin θ), θ ∈ θ₁ + [0, Δθ].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct CentreArc {
    /// The centre c.
    pub(crate) centre: Point2<f64>,
    /// The radius along the rotated x axis (scaled up if it was too small), > 0.
    pub(crate) rx: f64,
    /// The radius along the rotated y axis, > 0.
    pub(crate) ry: f64,
    /// φ, radians.
    pub(crate) rotation: f64,
    /// θ₁, radians.
    pub(crate) start_angle: f64,
    /// Δθ ∈ (−2π, 2π), radians: positive when fS = 1.
    pub(crate) sweep: f64,
}

#[cfg(test)]
impl CentreArc {
    /// p(θ).
    pub(crate) fn point_at_angle(&self, theta: f64) -> Point2<f64> {
        let local = Vector2::new(self.rx * theta.cos(), self.ry * theta.sin());
        self.centre + Rotation2::new(self.rotation) * local
    }
}

/// What an arc command draws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum ArcShape {
    /// Nothing: its ends are the same point (the specification omits the segment).
    Nothing,
    /// The straight line between its ends (a radius of 0).
    Line,
    /// An arc of an ellipse.
    Arc(CentreArc),
    /// Numbers out of f64's range on the way (radii near the smallest or largest magnitudes).
    OutOfRange,
}

/// The centre form of `arc` (see the module documentation).
pub(crate) fn centre_form(arc: &EndpointArc) -> ArcShape {
    if arc.from == arc.to {
        return ArcShape::Nothing;
    }
    let (rx, ry) = (arc.rx.abs(), arc.ry.abs());
    if rx == 0.0 || ry == 0.0 {
        return ArcShape::Line;
    }
    let phi = arc.rotation_degrees.to_radians();
    let rotation = Rotation2::new(phi);
    let half = rotation.inverse() * ((arc.from - arc.to) / 2.0);
    let (x, y) = (half.x / rx, half.y / ry);
    let lambda = x.hypot(y);
    let (rx, ry, cx, cy) = if lambda >= 1.0 {
        (rx * lambda, ry * lambda, 0.0, 0.0)
    } else {
        let mut coef = ((1.0 - lambda) * (1.0 + lambda)).sqrt() / lambda;
        if arc.large_arc == arc.sweep {
            coef = -coef;
        }
        (rx, ry, coef * rx * y, -coef * ry * x)
    };
    // In the unit circle's frame the centre sits at (cx/rx, cy/ry).
    let (ux, uy) = if lambda >= 1.0 {
        (x / lambda, y / lambda)
    } else {
        (x - cx / rx, y - cy / ry)
    };
    let (vx, vy) = if lambda >= 1.0 {
        (-ux, -uy)
    } else {
        (-x - cx / rx, -y - cy / ry)
    };
    let start_angle = uy.atan2(ux);
    let mut sweep = (ux * vy - uy * vx).atan2(ux * vx + uy * vy);
    if !arc.sweep && sweep > 0.0 {
        sweep -= std::f64::consts::TAU;
    } else if arc.sweep && sweep < 0.0 {
        sweep += std::f64::consts::TAU;
    }
    // atan2 of a half turn gives ±π by the sign of a zero; the flag picks the side.
    if arc.sweep && sweep <= 0.0 {
        sweep = std::f64::consts::PI;
    } else if !arc.sweep && sweep >= 0.0 {
        sweep = -std::f64::consts::PI;
    }
    let mid = Point2::from((arc.from.coords + arc.to.coords) / 2.0);
    let centre = mid + rotation * Vector2::new(cx, cy);
    let out = CentreArc {
        centre,
        rx,
        ry,
        rotation: phi,
        start_angle,
        sweep,
    };
    let finite = [centre.x, centre.y, rx, ry, phi, start_angle, sweep]
        .iter()
        .all(|v| v.is_finite());
    if finite && rx > 0.0 && ry > 0.0 {
        ArcShape::Arc(out)
    } else {
        ArcShape::OutOfRange
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, PI};

    fn arc(from: [f64; 2], to: [f64; 2], r: [f64; 2], phi: f64, fa: bool, fs: bool) -> ArcShape {
        centre_form(&EndpointArc {
            from: Point2::new(from[0], from[1]),
            to: Point2::new(to[0], to[1]),
            rx: r[0],
            ry: r[1],
            rotation_degrees: phi,
            large_arc: fa,
            sweep: fs,
        })
    }

    fn centre(shape: ArcShape) -> CentreArc {
        match shape {
            ArcShape::Arc(c) => c,
            other => panic!("expected an arc, got {other:?}"),
        }
    }

    #[test]
    fn a_semicircle_has_its_centre_at_the_chord_midpoint() {
        // M 0 0 A 1 1 0 0 1 2 0: from angle π through increasing θ, through (1, −1) (above
        // the chord on SVG's y-down page: clockwise there), to angle 2π.
        let c = centre(arc([0.0, 0.0], [2.0, 0.0], [1.0, 1.0], 0.0, false, true));
        assert!((c.centre - Point2::new(1.0, 0.0)).norm() < 1e-15);
        assert!((c.start_angle.abs() - PI).abs() < 1e-15);
        assert!((c.sweep - PI).abs() < 1e-15);
        assert!(
            (c.point_at_angle(c.start_angle + c.sweep / 2.0) - Point2::new(1.0, -1.0)).norm()
                < 1e-15
        );
        let d = centre(arc([0.0, 0.0], [2.0, 0.0], [1.0, 1.0], 0.0, false, false));
        assert!((d.sweep + PI).abs() < 1e-15);
        assert!(
            (d.point_at_angle(d.start_angle + d.sweep / 2.0) - Point2::new(1.0, 1.0)).norm()
                < 1e-15
        );
    }

    #[test]
    fn radii_too_small_are_scaled_up_to_reach_both_ends() {
        // The chord is 2 long; radius 0.5 becomes 1 and the arc a semicircle.
        let c = centre(arc([0.0, 0.0], [2.0, 0.0], [0.5, 0.5], 0.0, false, true));
        assert!((c.rx - 1.0).abs() < 1e-15 && (c.ry - 1.0).abs() < 1e-15);
        assert!((c.centre - Point2::new(1.0, 0.0)).norm() < 1e-15);
    }

    #[test]
    fn the_four_flag_choices_give_the_four_quarter_and_three_quarter_arcs() {
        // Ends (1, 0) and (0, 1), radius 1: centres (0, 0) and (1, 1).
        let (p, q) = ([1.0, 0.0], [0.0, 1.0]);
        for (fa, fs, centre_at, sweep) in [
            (false, true, [0.0, 0.0], FRAC_PI_2),
            (true, false, [0.0, 0.0], -3.0 * FRAC_PI_2),
            (false, false, [1.0, 1.0], -FRAC_PI_2),
            (true, true, [1.0, 1.0], 3.0 * FRAC_PI_2),
        ] {
            let c = centre(arc(p, q, [1.0, 1.0], 0.0, fa, fs));
            assert!(
                (c.centre - Point2::new(centre_at[0], centre_at[1])).norm() < 1e-14,
                "{fa} {fs}: {c:?}"
            );
            assert!((c.sweep - sweep).abs() < 1e-14, "{fa} {fs}: {c:?}");
            let end = c.point_at_angle(c.start_angle + c.sweep);
            assert!((end - Point2::new(q[0], q[1])).norm() < 1e-14);
            assert!((c.point_at_angle(c.start_angle) - Point2::new(p[0], p[1])).norm() < 1e-14);
        }
    }

    #[test]
    fn a_rotated_ellipse_passes_through_both_ends() {
        let c = centre(arc(
            [3.0, -1.0],
            [-2.0, 4.0],
            [10.0, 6.0],
            30.0,
            true,
            false,
        ));
        assert!((c.rx - 10.0).abs() < 1e-15 && (c.ry - 6.0).abs() < 1e-15);
        assert!((c.point_at_angle(c.start_angle) - Point2::new(3.0, -1.0)).norm() < 1e-12);
        assert!(
            (c.point_at_angle(c.start_angle + c.sweep) - Point2::new(-2.0, 4.0)).norm() < 1e-12
        );
        assert!(c.sweep < -PI, "a large arc against the sweep: {c:?}");
    }

    #[test]
    fn zero_radii_draw_a_line_and_equal_ends_draw_nothing() {
        assert_eq!(
            arc([0.0, 0.0], [1.0, 0.0], [0.0, 1.0], 0.0, false, true),
            ArcShape::Line
        );
        assert_eq!(
            arc([1.0, 1.0], [1.0, 1.0], [1.0, 1.0], 0.0, false, true),
            ArcShape::Nothing
        );
        assert_eq!(
            arc([0.0, 0.0], [1e300, 0.0], [1e-320, 1e-320], 0.0, false, true),
            ArcShape::OutOfRange
        );
    }
}
