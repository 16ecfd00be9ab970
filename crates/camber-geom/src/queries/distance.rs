//! Minimum distance between a planar curve and a line or a circle.

use super::intersect::{CircleField, LineField};
use super::{closest_point_with, events, ClosestPoint, Field, QueryOptions};
use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::primitives::{Circle, Line};
use crate::scalar::{re, Scalar};

/// The smallest measure over the curve: zero at the first intersection if there is one,
/// otherwise the best of all samples and refined extrema of the field.
fn minimum<T, C, F>(curve: &C, field: &F, opts: &QueryOptions) -> Result<ClosestPoint<T, 2>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
    F: Field<T, 2>,
{
    let (scan, merged) = events(curve, field, opts)?;
    if let Some(first) = merged.first() {
        return Ok(ClosestPoint {
            parameter: first.u,
            point: first.point,
            distance: T::zero(),
        });
    }
    let mut best = None;
    for s in scan.samples.iter().chain(&scan.extrema) {
        if best.is_none_or(|b: &super::Sample<T, 2>| re(s.measure) < re(b.measure)) {
            best = Some(s);
        }
    }
    // `scan` always returns at least the two domain ends.
    let best = best.ok_or(Error::ZeroCount { what: "samples" })?;
    Ok(ClosestPoint {
        parameter: best.u,
        point: best.point,
        distance: best.measure,
    })
}

/// The minimum distance from `curve` to `line`, with [`QueryOptions::default`].
///
/// See [`distance_to_line_with`].
pub fn distance_to_line<T, C>(curve: &C, line: &Line<T>) -> Result<ClosestPoint<T, 2>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    distance_to_line_with(curve, line, &QueryOptions::default())
}

/// The minimum over u of the distance |(C(u) − P)·n| from `curve` to `line`, with the
/// parameter and point where it occurs. Where the curve meets the line the distance is exactly
/// zero and the parameter is that of the first intersection (as found by
/// [`intersect_line_with`](super::intersect_line_with)). Otherwise the minimum is at a domain
/// end, a breakpoint or an extremum of the signed distance, all of which are searched.
///
/// ```
/// use camber_geom::queries::{distance_to_line_with, QueryOptions};
/// use camber_geom::Line;
/// # use camber_geom::{ParametricCurve, Result};
/// # use nalgebra::{Point2, SVector, Vector2};
/// # struct UnitCircle;
/// # impl ParametricCurve<f64, 2> for UnitCircle {
/// #     fn domain(&self) -> (f64, f64) { (0.0, std::f64::consts::TAU) }
/// #     fn derivatives_into(&self, u: f64, out: &mut [SVector<f64, 2>]) -> Result<()> {
/// #         for (k, o) in out.iter_mut().enumerate() {
/// #             let a = u + k as f64 * std::f64::consts::FRAC_PI_2;
/// #             *o = SVector::from([a.cos(), a.sin()]);
/// #         }
/// #         Ok(())
/// #     }
/// # }
/// // `UnitCircle` is (cos u, sin u); the line x = 3 is 2 away, nearest at u = 0.
/// let line = Line::try_new(Point2::new(3.0, 0.0), Vector2::new(0.0, 1.0))?;
/// let d = distance_to_line_with(&UnitCircle, &line, &QueryOptions::default())?;
/// assert!((d.distance - 2.0).abs() < 1e-12 && d.parameter.abs() < 1e-12);
/// # Ok::<(), camber_geom::Error>(())
/// ```
pub fn distance_to_line_with<T, C>(
    curve: &C,
    line: &Line<T>,
    opts: &QueryOptions,
) -> Result<ClosestPoint<T, 2>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    minimum(curve, &LineField::new(line), opts)
}

/// The minimum distance from `curve` to `circle`, with [`QueryOptions::default`].
///
/// See [`distance_to_circle_with`].
pub fn distance_to_circle<T, C>(curve: &C, circle: &Circle<T>) -> Result<ClosestPoint<T, 2>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    distance_to_circle_with(curve, circle, &QueryOptions::default())
}

/// The minimum over u of the distance ||C(u) − c| − r| from `curve` to the circle (the circle
/// as a curve, not the disk), with the parameter and point where it occurs; exactly zero at the
/// first intersection when they meet.
pub fn distance_to_circle_with<T, C>(
    curve: &C,
    circle: &Circle<T>,
    opts: &QueryOptions,
) -> Result<ClosestPoint<T, 2>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    minimum(curve, &CircleField::new(circle), opts)
}

/// The signed minimum distance from `curve` to `circle`, with [`QueryOptions::default`].
///
/// See [`signed_distance_to_circle_with`].
pub fn signed_distance_to_circle<T, C>(curve: &C, circle: &Circle<T>) -> Result<ClosestPoint<T, 2>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    signed_distance_to_circle_with(curve, circle, &QueryOptions::default())
}

/// min over u of (|C(u) − c| − r), with the parameter and point where it occurs: the point of
/// the curve closest to the centre, and its signed distance to the circle (the `distance`
/// field is signed here).
///
/// A positive value means the curve stays outside the closed disk; zero (within tolerance)
/// that it touches the circle from outside without entering; a negative value that it enters
/// the disk (and, unless it lies wholly inside, crosses the circle). Together with
/// [`distance_to_circle_with`] this tells a touch from outside (signed ≈ 0) from a crossing
/// (unsigned = 0, signed < 0).
///
/// ```
/// use camber_geom::queries::{signed_distance_to_circle_with, QueryOptions};
/// use camber_geom::Circle;
/// # use camber_geom::{ParametricCurve, Result};
/// # use nalgebra::{Point2, SVector};
/// # struct Horizontal;
/// # impl ParametricCurve<f64, 2> for Horizontal {
/// #     fn domain(&self) -> (f64, f64) { (-3.0, 3.0) }
/// #     fn derivatives_into(&self, u: f64, out: &mut [SVector<f64, 2>]) -> Result<()> {
/// #         let all = [SVector::from([u, 0.5]), SVector::from([1.0, 0.0])];
/// #         for (k, o) in out.iter_mut().enumerate() {
/// #             *o = all.get(k).copied().unwrap_or_else(SVector::zeros);
/// #         }
/// #         Ok(())
/// #     }
/// # }
/// // `Horizontal` is the segment y = 0.5, x ∈ [−3, 3]: it crosses the unit circle.
/// let circle = Circle::try_new(Point2::new(0.0, 0.0), 1.0)?;
/// let d = signed_distance_to_circle_with(&Horizontal, &circle, &QueryOptions::default())?;
/// assert!((d.distance + 0.5).abs() < 1e-12 && d.parameter.abs() < 1e-12);
/// # Ok::<(), camber_geom::Error>(())
/// ```
pub fn signed_distance_to_circle_with<T, C>(
    curve: &C,
    circle: &Circle<T>,
    opts: &QueryOptions,
) -> Result<ClosestPoint<T, 2>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    let nearest = closest_point_with(curve, circle.center(), opts)?;
    Ok(ClosestPoint {
        distance: nearest.distance - circle.radius(),
        ..nearest
    })
}
