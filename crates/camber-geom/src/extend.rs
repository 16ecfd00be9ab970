//! Extension of Bézier, B-spline and NURBS curves beyond either end of their domain.
//!
//! Two kinds of extension, both of which leave the curve unchanged (same points at the same
//! parameters) on its original domain:
//!
//! - **Natural extrapolation** continues the end polynomial piece (for NURBS, the end piece of
//!   the homogeneous curve) to a new domain end. A control point of a B-spline is the *blossom*
//!   (polar form) of the piece it acts on, evaluated at its p knots
//!   P_i = f(u_{i+1}, …, u_{i+p}); moving the p + 1 end knots from b to b′ changes only the p
//!   control points whose knot tuples contain b, and each becomes the end piece's blossom at
//!   its new tuple. The blossom of a Bézier piece on [c, d] at (x₁, …, x_p) is de Casteljau's
//!   algorithm with a different parameter (x_k − c)/(d − c) at each level k.
//! - **Extension by a length**: with [`ExtensionContinuity::G1`] a straight piece of the given
//!   length is attached along the end tangent (multiplicity-p joint knot, parameter speed
//!   matched, so the joint is even C1); with [`ExtensionContinuity::G2`] the end piece is
//!   extrapolated naturally (C∞ at the joint, hence G2) over the parameter extent whose arc
//!   length equals the given length, found by safeguarded Newton on the arc length.
//!
//! Extrapolating a NURBS curve can drive a weight to zero or below; that is reported as
//! [`Error::NonPositiveWeight`] rather than returning a curve with a pole.
//!
//! ```
//! use camber_geom::extend::CurveEnd;
//! use camber_geom::{BSplineCurve2, KnotVector, ParametricCurve};
//! use nalgebra::Point2;
//! let knots = KnotVector::clamped_uniform(2, 4)?;
//! let pts = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(2.0, 1.0),
//!     Point2::new(3.0, 0.0)];
//! let curve = BSplineCurve2::try_new(2, knots, pts)?;
//! let longer = curve.extrapolated(CurveEnd::End, 1.5)?;
//! assert_eq!(longer.domain(), (0.0, 1.5));
//! assert!((longer.point(0.7)? - curve.point(0.7)?).norm() < 1e-14);
//! # Ok::<(), camber_geom::Error>(())
//! ```

use nalgebra::{Point, SVector};

use crate::arc_length::arc_length_between;
use crate::bezier::BezierCurve;
use crate::bspline::BSplineCurve;
use crate::curve::{check_interval, ParametricCurve};
use crate::errors::{Error, Result};
use crate::knot_ops::ControlNet;
use crate::knots::KnotVector;
use crate::nurbs::NurbsCurve;
use crate::scalar::{cst, from_usize, re, Scalar};

/// Which end of a curve an operation acts on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CurveEnd {
    /// The start of the domain.
    Start,
    /// The end of the domain.
    End,
}

/// The continuity of an extension by a length with the curve it extends.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExtensionContinuity {
    /// Tangent continuity: a straight piece along the end tangent.
    G1,
    /// Curvature continuity: the end piece continued naturally.
    G2,
}

/// The blossom of the Bézier piece with flat control points `coords` (`dim` per point, p + 1
/// points) on [c, d], at the p arguments `args`.
fn blossom<T: Scalar>(coords: &[T], dim: usize, (c, d): (T, T), args: &[T]) -> Vec<T> {
    let mut column = coords.to_vec();
    let count = coords.len() / dim;
    for (level, &x) in args.iter().enumerate() {
        let t = (x - c) / (d - c);
        let s = T::one() - t;
        for i in 0..count - 1 - level {
            for k in 0..dim {
                column[i * dim + k] = column[i * dim + k] * s + column[(i + 1) * dim + k] * t;
            }
        }
    }
    column.truncate(dim);
    column
}

/// Checks that `target` lies beyond `end` of the domain (a, b).
fn check_beyond<T: Scalar>(end: CurveEnd, target: T, (a, b): (T, T)) -> Result<()> {
    if !re(target).is_finite() {
        return Err(Error::NonFinite {
            what: "extension parameter",
            index: 0,
            value: re(target),
        });
    }
    let beyond = match end {
        CurveEnd::Start => target < a,
        CurveEnd::End => target > b,
    };
    if beyond {
        Ok(())
    } else {
        Err(Error::ExtensionInsideDomain {
            value: re(target),
            min: re(a),
            max: re(b),
        })
    }
}

/// The net extrapolated naturally so that its domain reaches `target` at `end`.
pub(crate) fn extrapolate_net<T: Scalar>(
    net: &ControlNet<T>,
    end: CurveEnd,
    target: T,
) -> Result<ControlNet<T>> {
    net.check()?;
    check_beyond(end, target, net.domain())?;
    let net = net.clamped();
    let (p, dim) = (net.degree, net.dim);
    let pieces = net.decompose();
    let piece = match end {
        CurveEnd::Start => pieces.first(),
        CurveEnd::End => pieces.last(),
    }
    .ok_or(Error::ZeroCount {
        what: "polynomial pieces",
    })?;
    let mut knots = net.knots.as_slice().to_vec();
    let m = knots.len() - 1;
    match end {
        CurveEnd::Start => knots[..=p].fill(target),
        CurveEnd::End => knots[m - p..].fill(target),
    }
    let n = net.point_count() - 1;
    let mut coords = net.coords.clone();
    let changed: Vec<usize> = match end {
        CurveEnd::Start => (0..p).collect(),
        CurveEnd::End => (n + 1 - p..=n).collect(),
    };
    for i in changed {
        let point = blossom(
            &piece.coords,
            dim,
            (piece.start, piece.end),
            &knots[i + 1..=i + p],
        );
        coords[i * dim..(i + 1) * dim].copy_from_slice(&point);
    }
    ControlNet::try_new(p, KnotVector::new_unchecked(knots), dim, coords)
}

/// The net with a straight piece of `length` attached at `end` along the unit tangent
/// `direction`, its parameter speed `speed` (= |C′| at that end) so that the joint is C1.
/// `weight` is the homogeneous weight of the attached points (1 for a polynomial net, whose
/// `dim` then equals the point dimension; the last coordinate of each point otherwise).
fn attach_line<T: Scalar>(
    net: &ControlNet<T>,
    end: CurveEnd,
    point: &[T],
    direction: &[T],
    speed: T,
    length: T,
    weight: Option<T>,
) -> Result<ControlNet<T>> {
    let net = net.clamped();
    let (p, dim) = (net.degree, net.dim);
    let (a, b) = net.domain();
    let h = length / speed;
    let step = length / from_usize::<T>(p);
    let new_point = |j: usize| -> Vec<T> {
        let sign = match end {
            CurveEnd::Start => -T::one(),
            CurveEnd::End => T::one(),
        };
        let offset = step * from_usize::<T>(j) * sign;
        let mut out: Vec<T> = point
            .iter()
            .zip(direction)
            .map(|(&x, &d)| x + d * offset)
            .collect();
        if let Some(w) = weight {
            for c in &mut out {
                *c *= w;
            }
            out.push(w);
        }
        out
    };
    let old = net.knots.as_slice();
    let m = old.len() - 1;
    let (knots, coords) = match end {
        CurveEnd::End => {
            let mut knots = old[..m].to_vec(); // b now has multiplicity p
            knots.extend(std::iter::repeat_n(b + h, p + 1));
            let mut coords = net.coords.clone();
            for j in 1..=p {
                coords.extend(new_point(j));
            }
            (knots, coords)
        }
        CurveEnd::Start => {
            let mut knots = vec![a - h; p + 1];
            knots.extend_from_slice(&old[1..]);
            let mut coords = Vec::with_capacity(net.coords.len() + p * dim);
            for j in (1..=p).rev() {
                coords.extend(new_point(j));
            }
            coords.extend_from_slice(&net.coords);
            (knots, coords)
        }
    };
    ControlNet::try_new(p, KnotVector::new_unchecked(knots), dim, coords)
}

/// The point, unit tangent (pointing away from the curve at `end`) and speed at an end.
fn end_frame<T, const D: usize, C>(curve: &C, end: CurveEnd) -> Result<(Vec<T>, Vec<T>, T)>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let (a, b) = curve.domain();
    let u = match end {
        CurveEnd::Start => a,
        CurveEnd::End => b,
    };
    let (point, derivative) = curve.point_and_derivative(u)?;
    let speed = derivative.norm();
    if re(speed) <= 0.0 {
        return Err(Error::ZeroLength {
            what: "tangent at the extended end",
        });
    }
    let unit = derivative / speed;
    Ok((
        point.coords.iter().copied().collect(),
        unit.iter().copied().collect(),
        speed,
    ))
}

/// Checks that a length is finite and positive.
fn check_length<T: Scalar>(length: T, (a, b): (T, T)) -> Result<()> {
    if !re(length).is_finite() {
        return Err(Error::NonFinite {
            what: "extension length",
            index: 0,
            value: re(length),
        });
    }
    if re(length) <= 0.0 {
        return Err(Error::ExtensionInsideDomain {
            value: re(length),
            min: re(a),
            max: re(b),
        });
    }
    Ok(())
}

/// Natural extrapolation by the parameter extent whose added arc length is `length`: Newton on
/// g(Δ) = L(Δ) − length with g′(Δ) = |C′| at the new end, bisection inside a bracket found by
/// doubling.
fn extrapolate_by_length<T, const D: usize, C, F>(
    curve: &C,
    end: CurveEnd,
    length: T,
    extrapolate: F,
) -> Result<C>
where
    T: Scalar,
    C: ParametricCurve<T, D>,
    F: Fn(T) -> Result<C>,
{
    let (a, b) = curve.domain();
    check_length(length, (a, b))?;
    let (_, _, speed) = end_frame(curve, end)?;
    let tolerance = re(length) * 1e-13;
    // Added length and speed at the new end for an extent Δ > 0.
    let measure = |delta: T| -> Result<(T, T, C)> {
        let target = match end {
            CurveEnd::Start => a - delta,
            CurveEnd::End => b + delta,
        };
        let extended = extrapolate(target)?;
        let (lo, hi) = match end {
            CurveEnd::Start => (target, a),
            CurveEnd::End => (b, target),
        };
        let added = arc_length_between(&extended, lo, hi, tolerance.max(1e-300))?.length;
        let v = extended.derivative(target)?.norm();
        Ok((added, v, extended))
    };
    let mut lo = T::zero();
    let mut hi = length / speed;
    // Grow the bracket until it holds the length (the extrapolated speed may fall).
    let mut grown = 0;
    loop {
        let (added, _, _) = measure(hi)?;
        if added >= length {
            break;
        }
        lo = hi;
        hi *= cst::<T>(2.0);
        grown += 1;
        if grown > 60 {
            return Err(Error::ZeroLength {
                what: "extrapolated end piece (it does not reach the length)",
            });
        }
    }
    let mut delta = (lo + hi) * cst::<T>(0.5);
    let mut best = measure(delta)?;
    for _ in 0..100 {
        let (added, v, _) = &best;
        let g = *added - length;
        if re(g).abs() <= tolerance {
            break;
        }
        if re(g) > 0.0 {
            hi = delta;
        } else {
            lo = delta;
        }
        let newton = delta - g / *v;
        delta = if re(*v) > 0.0 && newton > lo && newton < hi {
            newton
        } else {
            (lo + hi) * cst::<T>(0.5)
        };
        best = measure(delta)?;
        if re(hi - lo) <= 1e-15 * re(hi) {
            break;
        }
    }
    Ok(best.2)
}

/// # Extension
impl<T: Scalar, const D: usize> BezierCurve<T, D> {
    /// The curve's polynomial continued to the parameter `t` beyond `end` (t > 1 for the end,
    /// t < 0 for the start), as a Bézier curve on [0, 1] of the same degree: the result at s is
    /// this curve's polynomial at t₀ + (t₁ − t₀)s, where [t₀, t₁] is [0, t] or [t, 1]. Its
    /// control points are the blossom values Q_i = f(t₀, …, t₀, t₁, …, t₁) (i copies of t₁).
    ///
    /// ```
    /// use camber_geom::extend::CurveEnd;
    /// use camber_geom::BezierCurve2;
    /// use nalgebra::Point2;
    /// // y = 2t(1 − t): continued to t = 2 it ends at (4, −4).
    /// let c = BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(1.0, 1.0),
    ///     Point2::new(2.0, 0.0)])?;
    /// let e = c.extrapolated(CurveEnd::End, 2.0)?;
    /// assert_eq!(e.control_points(), &[Point2::new(0.0, 0.0), Point2::new(2.0, 2.0),
    ///     Point2::new(4.0, -4.0)]);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    ///
    /// Errors: [`Error::ExtensionInsideDomain`] when t is not beyond the end, [`Error::NonFinite`].
    pub fn extrapolated(&self, end: CurveEnd, t: T) -> Result<Self> {
        check_beyond(end, t, self.domain())?;
        let (t0, t1) = match end {
            CurveEnd::Start => (t, T::one()),
            CurveEnd::End => (T::zero(), t),
        };
        check_interval(t0, t1)?;
        let n = self.degree();
        let coords: Vec<T> = self
            .control_points()
            .iter()
            .flat_map(|p| p.coords.iter().copied())
            .collect();
        let mut args = vec![t0; n];
        let mut points = Vec::with_capacity(n + 1);
        for i in 0..=n {
            if i > 0 {
                args[n - i] = t1;
            }
            let q = blossom(&coords, D, (T::zero(), T::one()), &args);
            points.push(Point::from(SVector::<T, D>::from_column_slice(&q)));
        }
        Self::try_new(points)
    }

    /// The curve extended at `end` by an arc of the given `length` with the given continuity,
    /// as a B-spline whose domain [0, 1] part is this curve (see
    /// [`BSplineCurve::extended_by_length`]).
    pub fn extended_by_length(
        &self,
        end: CurveEnd,
        length: T,
        continuity: ExtensionContinuity,
    ) -> Result<BSplineCurve<T, D>> {
        BSplineCurve::from_bezier(self).extended_by_length(end, length, continuity)
    }
}

/// # Extension
impl<T: Scalar, const D: usize> BSplineCurve<T, D> {
    /// The curve with its end polynomial piece continued so that the domain reaches `target`
    /// (below the domain start for [`CurveEnd::Start`], above its end for [`CurveEnd::End`]).
    /// On the old domain the result equals this curve at every parameter; the result is
    /// clamped.
    ///
    /// Errors: [`Error::ExtensionInsideDomain`] when `target` is not beyond that end,
    /// [`Error::NonFinite`].
    pub fn extrapolated(&self, end: CurveEnd, target: T) -> Result<Self> {
        Self::try_from_control_net(extrapolate_net(&self.to_control_net(), end, target)?)
    }

    /// The curve extended at `end` by an arc of `length` (length units, > 0):
    /// [`ExtensionContinuity::G1`] attaches a straight piece along the end tangent,
    /// [`ExtensionContinuity::G2`] continues the end piece naturally until the added arc length
    /// is `length` (to 1e-13 relative). On the old domain the result equals this curve; the
    /// added piece's parameter runs beyond it.
    ///
    /// ```
    /// use camber_geom::arc_length::arc_length_between;
    /// use camber_geom::extend::{CurveEnd, ExtensionContinuity};
    /// use camber_geom::{BSplineCurve2, KnotVector, ParametricCurve};
    /// use nalgebra::Point2;
    /// let knots = KnotVector::clamped_uniform(2, 3)?;
    /// let pts = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(2.0, 0.0)];
    /// let c = BSplineCurve2::try_new(2, knots, pts)?;
    /// let e = c.extended_by_length(CurveEnd::End, 0.5, ExtensionContinuity::G1)?;
    /// // The tangent at (2, 0) points along (1, −1)/√2.
    /// let end = e.point(e.domain().1)?;
    /// let step = 0.5 / 2.0_f64.sqrt();
    /// assert!((end - Point2::new(2.0 + step, -step)).norm() < 1e-12);
    /// // The added piece is 0.5 long.
    /// let added = arc_length_between(&e, 1.0, e.domain().1, 1e-12)?;
    /// assert!((added.length - 0.5).abs() < 1e-12);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    ///
    /// Errors: [`Error::ExtensionInsideDomain`] for a length ≤ 0, [`Error::ZeroLength`] when the
    /// curve has no tangent at that end.
    pub fn extended_by_length(
        &self,
        end: CurveEnd,
        length: T,
        continuity: ExtensionContinuity,
    ) -> Result<Self> {
        check_length(length, self.domain())?;
        match continuity {
            ExtensionContinuity::G1 => {
                let (point, direction, speed) = end_frame(self, end)?;
                let net = attach_line(
                    &self.to_control_net(),
                    end,
                    &point,
                    &direction,
                    speed,
                    length,
                    None,
                )?;
                Self::try_from_control_net(net)
            }
            ExtensionContinuity::G2 => {
                extrapolate_by_length(self, end, length, |u| self.extrapolated(end, u))
            }
        }
    }
}

/// # Extension
impl<T: Scalar, const D: usize> NurbsCurve<T, D> {
    /// The curve with its end rational piece continued so that the domain reaches `target`
    /// (the homogeneous end piece is extrapolated). On the old domain the result equals this
    /// curve.
    ///
    /// ```
    /// use camber_geom::extend::CurveEnd;
    /// use camber_geom::{NurbsCurve2, ParametricCurve};
    /// use nalgebra::Point2;
    /// // A quarter circle continued stays on the circle.
    /// let arc = NurbsCurve2::try_circular_arc(Point2::origin(), 1.0, 0.0, std::f64::consts::FRAC_PI_2)?;
    /// let more = arc.extrapolated(CurveEnd::End, 1.3)?;
    /// assert!((more.point(1.3)?.coords.norm() - 1.0).abs() < 1e-12);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    ///
    /// Errors: [`Error::ExtensionInsideDomain`], [`Error::NonFinite`], and
    /// [`Error::NonPositiveWeight`] when the extrapolated weights stop being positive.
    pub fn extrapolated(&self, end: CurveEnd, target: T) -> Result<Self> {
        Self::try_from_homogeneous(extrapolate_net(&self.to_homogeneous(), end, target)?)
    }

    /// The curve extended at `end` by an arc of `length` with the given continuity (see
    /// [`BSplineCurve::extended_by_length`]); the straight piece of G1 has the end weight.
    pub fn extended_by_length(
        &self,
        end: CurveEnd,
        length: T,
        continuity: ExtensionContinuity,
    ) -> Result<Self> {
        check_length(length, self.domain())?;
        match continuity {
            ExtensionContinuity::G1 => {
                let (point, direction, speed) = end_frame(self, end)?;
                let clamped = self.clamped();
                let weight = match end {
                    CurveEnd::Start => clamped.weights().first(),
                    CurveEnd::End => clamped.weights().last(),
                }
                .copied()
                .unwrap_or_else(T::one);
                let net = attach_line(
                    &clamped.to_homogeneous(),
                    end,
                    &point,
                    &direction,
                    speed,
                    length,
                    Some(weight),
                )?;
                Self::try_from_homogeneous(net)
            }
            ExtensionContinuity::G2 => {
                extrapolate_by_length(self, end, length, |u| self.extrapolated(end, u))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Point2;

    #[test]
    fn blossom_on_the_diagonal_is_the_point() {
        // y = 2t(1 − t) as a quadratic: f(t, t) = C(t); f(0, 2) = 2 (hand-derived).
        let coords = [0.0_f64, 0.0, 1.0, 1.0, 2.0, 0.0];
        let on = blossom(&coords, 2, (0.0, 1.0), &[0.25, 0.25]);
        assert!((on[0] - 0.5).abs() < 1e-15 && (on[1] - 0.375).abs() < 1e-15);
        let off = blossom(&coords, 2, (0.0, 1.0), &[0.0, 2.0]);
        assert!((off[0] - 2.0).abs() < 1e-15 && (off[1] - 2.0).abs() < 1e-15);
    }

    #[test]
    fn a_line_extends_along_itself() {
        let c = BezierCurve::try_new(vec![Point2::new(0.0, 0.0), Point2::new(1.0, 0.0)]).unwrap();
        let e = c.extrapolated(CurveEnd::Start, -1.0).unwrap();
        assert_eq!(
            e.control_points(),
            &[Point2::new(-1.0, 0.0), Point2::new(1.0, 0.0)]
        );
    }
}
