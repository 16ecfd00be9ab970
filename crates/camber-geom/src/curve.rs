//! The [`ParametricCurve`] trait every curve type implements, and the input checks they share.
//!
//! A curve maps a parameter u in its domain [a, b] to a point C(u) in D dimensions. Queries
//! (closest point, intersections, curvature) and composite curves are written once against this
//! trait, for every curve type and every scalar.

use nalgebra::{Point, SVector};

use crate::errors::{Error, Result};
use crate::queries::RationalPiece;
use crate::scalar::{re, Scalar};

/// A parametric curve C: [a, b] → R^D, differentiable to any order inside its pieces.
///
/// Implementors provide [`domain`](Self::domain) and
/// [`derivatives_into`](Self::derivatives_into); everything else has a default.
///
/// ```
/// use camber_geom::{BezierCurve, ParametricCurve};
/// use nalgebra::Point2;
/// let c = BezierCurve::try_new(vec![Point2::new(0.0_f64, 0.0), Point2::new(2.0, 2.0)]).unwrap();
/// let (p, d) = c.point_and_derivative(0.5).unwrap();
/// assert!((p.x - 1.0).abs() < 1e-15 && (d.y - 2.0).abs() < 1e-15);
/// ```
pub trait ParametricCurve<T: Scalar, const D: usize> {
    /// The parametric domain [a, b], a < b.
    fn domain(&self) -> (T, T);

    /// Writes C(u), C′(u), …, C⁽ᵏ⁾(u) into `out`, where k = `out.len()` − 1 (`out[0]` is the
    /// position vector of the point). Derivatives are with respect to u. At a knot or joint the
    /// derivatives are those of the piece to the right, except at the end of the domain.
    ///
    /// Fails with [`Error::ParameterOutsideDomain`] or [`Error::NonFinite`] for a bad u.
    fn derivatives_into(&self, u: T, out: &mut [SVector<T, D>]) -> Result<()>;

    /// Parameters at which the curve may be less smooth than its pieces (its distinct knots, its
    /// joints), including both ends of the domain, in increasing order. Queries sample per piece.
    fn breakpoints(&self) -> Vec<T> {
        let (a, b) = self.domain();
        vec![a, b]
    }

    /// The curve's real part as rational Bézier pieces in parameter order covering the domain,
    /// each within its [`slack`](RationalPiece::slack) of the curve on its parameter interval;
    /// this is what the curve–curve queries subdivide. `Ok(None)` (the default) when the curve
    /// has no such form; the queries then enclose it by sampling
    /// ([`sampled_pieces`](crate::queries::sampled_pieces)). Bézier, B-spline, NURBS, Hermite,
    /// segment and circle give their exact form (slack 0), a composite curve its pieces' forms.
    fn bezier_enclosure(&self) -> Result<Option<Vec<RationalPiece<D>>>> {
        Ok(None)
    }

    /// The point C(u).
    fn point(&self, u: T) -> Result<Point<T, D>> {
        let mut out = [SVector::<T, D>::zeros(); 1];
        self.derivatives_into(u, &mut out)?;
        Ok(Point::from(out[0]))
    }

    /// The first derivative C′(u) (the tangent vector, in length units per unit of u).
    fn derivative(&self, u: T) -> Result<SVector<T, D>> {
        Ok(self.point_and_derivative(u)?.1)
    }

    /// C(u) and C′(u) in one evaluation.
    fn point_and_derivative(&self, u: T) -> Result<(Point<T, D>, SVector<T, D>)> {
        let mut out = [SVector::<T, D>::zeros(); 2];
        self.derivatives_into(u, &mut out)?;
        Ok((Point::from(out[0]), out[1]))
    }

    /// C(u), C′(u) and C″(u) in one evaluation.
    fn second_order(&self, u: T) -> Result<[SVector<T, D>; 3]> {
        let mut out = [SVector::<T, D>::zeros(); 3];
        self.derivatives_into(u, &mut out)?;
        Ok(out)
    }

    /// C(u) and its derivatives up to `order` (at most [`MAX_DERIVATIVE_ORDER`]), as vectors
    /// (index k holds the k-th derivative).
    ///
    /// Errors: [`Error::TooLarge`] for an order above [`MAX_DERIVATIVE_ORDER`] (checked before
    /// anything is allocated), and the evaluation's errors.
    fn derivatives(&self, u: T, order: usize) -> Result<Vec<SVector<T, D>>> {
        check_derivative_order(order)?;
        let mut out = vec![SVector::<T, D>::zeros(); order + 1];
        self.derivatives_into(u, &mut out)?;
        Ok(out)
    }
}

/// A boxed curve is the curve it holds (so chains of boxed trait objects are curves).
impl<T: Scalar, const D: usize, C: ParametricCurve<T, D> + ?Sized> ParametricCurve<T, D>
    for Box<C>
{
    fn domain(&self) -> (T, T) {
        (**self).domain()
    }

    fn derivatives_into(&self, u: T, out: &mut [SVector<T, D>]) -> Result<()> {
        (**self).derivatives_into(u, out)
    }

    fn breakpoints(&self) -> Vec<T> {
        (**self).breakpoints()
    }

    fn bezier_enclosure(&self) -> Result<Option<Vec<RationalPiece<D>>>> {
        (**self).bezier_enclosure()
    }

    fn point(&self, u: T) -> Result<Point<T, D>> {
        (**self).point(u)
    }

    fn derivative(&self, u: T) -> Result<SVector<T, D>> {
        (**self).derivative(u)
    }

    fn point_and_derivative(&self, u: T) -> Result<(Point<T, D>, SVector<T, D>)> {
        (**self).point_and_derivative(u)
    }

    fn second_order(&self, u: T) -> Result<[SVector<T, D>; 3]> {
        (**self).second_order(u)
    }

    fn derivatives(&self, u: T, order: usize) -> Result<Vec<SVector<T, D>>> {
        (**self).derivatives(u, order)
    }
}

/// The highest derivative order [`ParametricCurve::derivatives`] computes. Above a polynomial
/// curve's degree every derivative is zero, and a rational curve's high derivatives leave the
/// f64 range long before this order (they grow like k!).
pub const MAX_DERIVATIVE_ORDER: usize = 64;

/// Fails with [`Error::TooLarge`] when `order` exceeds [`MAX_DERIVATIVE_ORDER`]: check an
/// order from outside before allocating for it.
///
/// ```
/// use camber_geom::curve::{check_derivative_order, MAX_DERIVATIVE_ORDER};
/// assert!(check_derivative_order(MAX_DERIVATIVE_ORDER).is_ok());
/// assert!(check_derivative_order(1 << 40).is_err());
/// ```
pub fn check_derivative_order(order: usize) -> Result<()> {
    if order > MAX_DERIVATIVE_ORDER {
        return Err(Error::TooLarge {
            what: "derivative order",
            value: order,
            max: MAX_DERIVATIVE_ORDER,
        });
    }
    Ok(())
}

/// Checks that `u` is finite and inside `[min, max]` (closed), comparing real parts.
///
/// ```
/// use camber_geom::curve::check_parameter;
/// assert!(check_parameter(0.5, (0.0, 1.0)).is_ok());
/// assert!(check_parameter(1.5, (0.0, 1.0)).is_err());
/// ```
pub fn check_parameter<T: Scalar>(u: T, (min, max): (T, T)) -> Result<()> {
    let v = re(u);
    if !v.is_finite() {
        return Err(Error::NonFinite {
            what: "parameter",
            index: 0,
            value: v,
        });
    }
    if u < min || u > max {
        return Err(Error::ParameterOutsideDomain {
            value: v,
            min: re(min),
            max: re(max),
        });
    }
    Ok(())
}

/// Checks that `u` is finite and strictly inside `(min, max)`: where a curve can be split.
///
/// ```
/// use camber_geom::curve::check_interior_parameter;
/// assert!(check_interior_parameter(0.5, (0.0, 1.0)).is_ok());
/// assert!(check_interior_parameter(1.0, (0.0, 1.0)).is_err());
/// ```
pub fn check_interior_parameter<T: Scalar>(u: T, (min, max): (T, T)) -> Result<()> {
    check_parameter(u, (min, max))?;
    if u <= min || u >= max {
        return Err(Error::ParameterOutsideDomain {
            value: re(u),
            min: re(min),
            max: re(max),
        });
    }
    Ok(())
}

/// Checks that every coordinate of every point is finite; the error names the point index.
pub fn check_points<T: Scalar, const D: usize>(points: &[Point<T, D>]) -> Result<()> {
    for (index, p) in points.iter().enumerate() {
        for &c in p.coords.iter() {
            if !re(c).is_finite() {
                return Err(Error::NonFinite {
                    what: "control point coordinate of point",
                    index,
                    value: re(c),
                });
            }
        }
    }
    Ok(())
}

/// Checks that `start < end` and both are finite.
pub fn check_interval<T: Scalar>(start: T, end: T) -> Result<()> {
    for (i, v) in [start, end].into_iter().enumerate() {
        if !re(v).is_finite() {
            return Err(Error::NonFinite {
                what: "interval end",
                index: i,
                value: re(v),
            });
        }
    }
    if start >= end {
        return Err(Error::InvalidInterval {
            start: re(start),
            end: re(end),
        });
    }
    Ok(())
}
