//! Angles between tangents and of lines, shared by the angle kinds (`angle`, `parallel`,
//! `perpendicular`) and the free-direction joins: the signed angle atan2(cross, dot) written so
//! that dual numbers carry exact first and second derivatives, its folded form, and the
//! [`LineAngle`] residual of two lines.

use crate::constraints::check::SolvedCheck;
use crate::constraints::compiler::distinct;
use crate::constraints::piece::Slot;
use crate::constraints::Compiler;
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::residuals::curve::{cross, dot, sub};
use camber_solve::scalar::{cst, re};
use camber_solve::{Residual, Scalar};
use std::sync::Arc;

/// atan2(s, c): the angle of the vector (c, s), in (−π, π]; NaN for the zero vector (a
/// direction that vanished has no angle, and the solver must not read it as satisfied).
///
/// Written with atan of the smaller component over the larger, the quadrant chosen on the
/// values: atan(s/c) when |s| ≤ c, ±π/2 − atan(c/s) when |c| < |s|, atan(s/c) ± π when
/// |s| ≤ −c. Each branch divides by a component at least |(c, s)|/√2 in size, so the
/// derivatives a dual number carries, (c·ds − s·dc)/(s² + c²), stay finite everywhere but at
/// the zero vector (a plain atan2 of dual numbers divides by c and is NaN at c = 0, the right
/// angle this row exists for).
pub(crate) fn angle_of<T: Scalar>(s: T, c: T) -> T {
    let (sv, cv) = (re(s), re(c));
    if sv == 0.0 && cv == 0.0 {
        return cst::<T>(f64::NAN);
    }
    let half_turn = cst::<T>(std::f64::consts::PI);
    if sv.abs() <= cv {
        (s / c).atan()
    } else if cv.abs() < sv.abs() {
        let quarter = cst::<T>(std::f64::consts::FRAC_PI_2);
        let quarter = if sv > 0.0 { quarter } else { -quarter };
        quarter - (c / s).atan()
    } else if sv >= 0.0 {
        (s / c).atan() + half_turn
    } else {
        (s / c).atan() - half_turn
    }
}

/// The signed angle from t₁ to t₂, atan2(cross(t₁, t₂), t₁·t₂) ∈ (−π, π], of `sense` (±1) t₂:
/// zero when the two point the same way (`sense` = 1) or opposite ways (`sense` = −1).
pub(crate) fn angle_between<T: Scalar>(t1: [T; 2], t2: [T; 2], sense: f64) -> T {
    let sense = cst::<T>(sense);
    angle_of(sense * cross(t1, t2), sense * dot(t1, t2))
}

/// Compiles the angle row between two distinct lines, with an optional check of the solved
/// state.
pub(crate) fn line_angle(
    cx: &mut Compiler<'_>,
    name: &'static str,
    (first, second): (EntityId, EntityId),
    angle: f64,
    check: Option<Arc<dyn SolvedCheck>>,
) -> Result<()> {
    distinct(first, second)?;
    cx.line(first)?;
    cx.line(second)?;
    let slots = vec![
        Slot::Point(first, 0),
        Slot::Point(first, 1),
        Slot::Point(second, 0),
        Slot::Point(second, 1),
    ];
    // A sense check comes with the sensed row; without one either sense solves.
    let row = match check {
        Some(_) => LineAngle::new(name, angle),
        None => LineAngle::either_sense(name, angle),
    };
    cx.residual(row, slots, check);
    Ok(())
}

/// φ − θ = 0 for the angle φ from d₁ = B₁ − A₁ to d₂ = B₂ − A₂ (blocks A₁, B₁, A₂, B₂), the
/// difference in (−π, π], or folded into [−π/2, π/2] for either sense (see the module
/// documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct LineAngle {
    name: &'static str,
    cos: f64,
    sin: f64,
    either_sense: bool,
}

impl LineAngle {
    /// The residual for the angle θ (radians), named `name` in reports.
    ///
    /// ```
    /// use camber_sketch::constraints::angle::LineAngle;
    /// use camber_solve::Residual;
    /// // d₁ = (1, 0), d₂ at 170°: 170° − 30° = 140° for the sensed row; the row of either
    /// // sense at θ = 0 (parallel) is 170° − 180° = −10°.
    /// let (c, s) = (170f64.to_radians().cos(), 170f64.to_radians().sin());
    /// let x = [[0.0, 0.0], [1.0, 0.0], [0.0, 0.0], [c, s]];
    /// let blocks: Vec<&[f64]> = x.iter().map(|p| &p[..]).collect();
    /// let mut out = [0.0];
    /// LineAngle::new("angle", 30f64.to_radians()).eval(&blocks, &mut out);
    /// assert!((out[0] - 140f64.to_radians()).abs() < 1e-14);
    /// LineAngle::either_sense("parallel", 0.0).eval(&blocks, &mut out);
    /// assert!((out[0] + 10f64.to_radians()).abs() < 1e-14);
    /// ```
    pub fn new(name: &'static str, angle: f64) -> Self {
        Self {
            name,
            cos: angle.cos(),
            sin: angle.sin(),
            either_sense: false,
        }
    }

    /// The residual for the angle θ or θ + π (radians), named `name` in reports.
    pub fn either_sense(name: &'static str, angle: f64) -> Self {
        Self {
            either_sense: true,
            ..Self::new(name, angle)
        }
    }
}

impl Residual for LineAngle {
    fn name(&self) -> &str {
        self.name
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2; 4])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (d1, d2) = (sub(x[1], x[0]), sub(x[3], x[2]));
        let (crs, dt) = (cross(d1, d2), dot(d1, d2));
        let (cos, sin) = (cst::<T>(self.cos), cst::<T>(self.sin));
        let (s, c) = (crs * cos - dt * sin, dt * cos + crs * sin);
        out[0] = if self.either_sense {
            folded_angle_of(s, c)
        } else {
            angle_of(s, c)
        };
    }
}

/// The angle of (c, s) or of (−c, −s), whichever has c ≥ 0: the angle up to a half turn, in
/// [−π/2, π/2] (NaN for the zero vector). Its gradient is that of [`angle_of`] (the sign flip
/// is constant nearby).
pub(crate) fn folded_angle_of<T: Scalar>(s: T, c: T) -> T {
    if c < T::zero() {
        angle_of(-s, -c)
    } else {
        angle_of(s, c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_dual::{Dual2_64, Dual64};
    use proptest::prelude::*;

    /// Angles on the axes and the diagonals, where the branches meet.
    #[test]
    fn angle_of_on_the_axes_and_diagonals() {
        for k in -3..=4 {
            let a = f64::from(k) * std::f64::consts::FRAC_PI_4;
            let (s, c) = (a.sin(), a.cos());
            assert!((angle_of(s, c) - s.atan2(c)).abs() < 1e-15, "{k}");
            let (s, c) = (a.sin().round(), a.cos().round());
            assert_eq!(angle_of(s, c).to_bits(), s.atan2(c).to_bits(), "{k}");
        }
        assert!(angle_of(0.0_f64, 0.0).is_nan());
        assert!(folded_angle_of(0.0_f64, 0.0).is_nan());
    }

    proptest! {
        /// The value is f64's atan2 to a few ulps, the folded one differs from it by a whole
        /// number of half turns, and the first and second derivatives carried by dual numbers
        /// are those of the closed form θ′ = (c·s′ − s·c′)/(s² + c²), along (s, c) = (s₀ + t·a,
        /// c₀ + t·b): θ″ = −2(c·a − s·b)(s·a + c·b)/(s² + c²)².
        #[test]
        fn angle_of_is_atan2_with_exact_derivatives(
            s in -10.0..10.0_f64, c in -10.0..10.0_f64,
            a in -1.0..1.0_f64, b in -1.0..1.0_f64,
        ) {
            prop_assume!(s.hypot(c) > 1e-6);
            prop_assert!((angle_of(s, c) - s.atan2(c)).abs() <= 4.0 * f64::EPSILON * std::f64::consts::PI);
            let folded = folded_angle_of(s, c);
            prop_assert!(folded.abs() <= std::f64::consts::FRAC_PI_2 + 1e-15);
            let turns = (s.atan2(c) - folded) / std::f64::consts::PI;
            prop_assert!((turns - turns.round()).abs() < 1e-12);
            let r2 = s * s + c * c;
            let d1 = (c * a - s * b) / r2;
            let d2 = -2.0 * (c * a - s * b) * (s * a + c * b) / (r2 * r2);
            let first = angle_of(Dual64::new(s, a), Dual64::new(c, b));
            prop_assert!((first.eps - d1).abs() <= 1e-12 * (1.0 + d1.abs()));
            let t = Dual2_64::new(0.0, 1.0, 0.0);
            let sd = t * a + s;
            let cd = t * b + c;
            let second = angle_of(sd, cd);
            prop_assert!((second.v1 - d1).abs() <= 1e-12 * (1.0 + d1.abs()));
            prop_assert!((second.v2 - d2).abs() <= 1e-10 * (1.0 + d2.abs()));
        }
    }
}
