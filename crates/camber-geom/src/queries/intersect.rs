//! Intersections of a planar curve with a line or a circle.

use nalgebra::{Point2, SVector, Vector2};

use super::{events, Field, Intersection, QueryOptions, Sample};
use crate::curve::ParametricCurve;
use crate::errors::Result;
use crate::primitives::{Circle, Line};
use crate::scalar::{cst, Scalar};

/// h(u) = (C(u) − P)·n, the signed distance to a line (n its unit left normal); measure |h|.
pub(super) struct LineField<T: Scalar> {
    point: Point2<T>,
    normal: Vector2<T>,
}

impl<T: Scalar> LineField<T> {
    pub(super) fn new(line: &Line<T>) -> Self {
        Self {
            point: *line.point(),
            normal: line.normal(),
        }
    }
}

impl<T: Scalar> Field<T, 2> for LineField<T> {
    fn eval(&self, d: &[SVector<T, 2>; 3]) -> [T; 3] {
        [
            (d[0] - self.point.coords).dot(&self.normal),
            d[1].dot(&self.normal),
            d[2].dot(&self.normal),
        ]
    }

    fn measure(&self, _d: &[SVector<T, 2>; 3], h: T) -> T {
        h.abs()
    }
}

/// h(u) = |C(u) − c|² − r², the power of C(u) with respect to a circle;
/// h′ = 2(C − c)·C′, h″ = 2(|C′|² + (C − c)·C″); measure ||C − c| − r|.
pub(super) struct CircleField<T: Scalar> {
    center: Point2<T>,
    radius: T,
}

impl<T: Scalar> CircleField<T> {
    pub(super) fn new(circle: &Circle<T>) -> Self {
        Self {
            center: *circle.center(),
            radius: circle.radius(),
        }
    }
}

impl<T: Scalar> Field<T, 2> for CircleField<T> {
    fn eval(&self, d: &[SVector<T, 2>; 3]) -> [T; 3] {
        let w = d[0] - self.center.coords;
        let two = cst::<T>(2.0);
        [
            w.norm_squared() - self.radius * self.radius,
            w.dot(&d[1]) * two,
            (d[1].norm_squared() + w.dot(&d[2])) * two,
        ]
    }

    fn measure(&self, d: &[SVector<T, 2>; 3], _h: T) -> T {
        ((d[0] - self.center.coords).norm() - self.radius).abs()
    }
}

/// Converts merged events to intersections.
fn to_intersections<T: Scalar>(events: Vec<Sample<T, 2>>) -> Vec<Intersection<T>> {
    events
        .into_iter()
        .map(|e| Intersection {
            parameter: e.u,
            point: e.point,
        })
        .collect()
}

/// Every intersection of `curve` with `line`, with [`QueryOptions::default`].
///
/// See [`intersect_line_with`].
pub fn intersect_line<T, C>(curve: &C, line: &Line<T>) -> Result<Vec<Intersection<T>>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    intersect_line_with(curve, line, &QueryOptions::default())
}

/// Every intersection of `curve` with `line`, sorted by parameter and deduplicated.
///
/// The roots of the signed distance g(u) = (C(u) − P)·n are bracketed by sign changes between
/// samples and refined by safeguarded Newton/bisection to the parameter tolerance; tangential
/// touches are the extrema of g (and the samples, domain ends included) where |g| is within
/// the touch tolerance. Intersections joined by curve points within the touch tolerance (a
/// touch found as two nearby crossings, a piece lying along the line) are reported once.
/// Fails where the curve cannot be evaluated, and for bad options.
///
/// ```
/// use camber_geom::queries::{intersect_line_with, QueryOptions};
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
/// // `UnitCircle` is (cos u, sin u) on [0, 2π]; the line y = 1 touches it at u = π/2.
/// let line = Line::try_new(Point2::new(0.0, 1.0), Vector2::new(1.0, 0.0))?;
/// let hits = intersect_line_with(&UnitCircle, &line, &QueryOptions::default())?;
/// assert_eq!(hits.len(), 1);
/// assert!((hits[0].parameter - std::f64::consts::FRAC_PI_2).abs() < 1e-9);
/// # Ok::<(), camber_geom::Error>(())
/// ```
pub fn intersect_line_with<T, C>(
    curve: &C,
    line: &Line<T>,
    opts: &QueryOptions,
) -> Result<Vec<Intersection<T>>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    let (_, merged) = events(curve, &LineField::new(line), opts)?;
    Ok(to_intersections(merged))
}

/// Every intersection of `curve` with `circle`, with [`QueryOptions::default`].
///
/// See [`intersect_circle_with`].
pub fn intersect_circle<T, C>(curve: &C, circle: &Circle<T>) -> Result<Vec<Intersection<T>>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    intersect_circle_with(curve, circle, &QueryOptions::default())
}

/// Every intersection of `curve` with `circle`, sorted by parameter and deduplicated.
///
/// Works as [`intersect_line_with`] on g(u) = |C(u) − c|² − r² (smooth, so Newton converges
/// quadratically); the touch tolerance applies to the distance ||C − c| − r|.
///
/// ```
/// use camber_geom::queries::{intersect_circle_with, QueryOptions};
/// use camber_geom::Circle;
/// # use camber_geom::{ParametricCurve, Result};
/// # use nalgebra::{Point2, SVector};
/// # struct Diagonal;
/// # impl ParametricCurve<f64, 2> for Diagonal {
/// #     fn domain(&self) -> (f64, f64) { (-2.0, 2.0) }
/// #     fn derivatives_into(&self, u: f64, out: &mut [SVector<f64, 2>]) -> Result<()> {
/// #         let all = [SVector::from([u, u]), SVector::from([1.0, 1.0])];
/// #         for (k, o) in out.iter_mut().enumerate() {
/// #             *o = all.get(k).copied().unwrap_or_else(SVector::zeros);
/// #         }
/// #         Ok(())
/// #     }
/// # }
/// // `Diagonal` is the segment (u, u), u ∈ [−2, 2]; it crosses the unit circle at u = ±1/√2.
/// let circle = Circle::try_new(Point2::new(0.0, 0.0), 1.0)?;
/// let hits = intersect_circle_with(&Diagonal, &circle, &QueryOptions::default())?;
/// assert_eq!(hits.len(), 2);
/// assert!((hits[1].parameter - 0.5_f64.sqrt()).abs() < 1e-14);
/// # Ok::<(), camber_geom::Error>(())
/// ```
pub fn intersect_circle_with<T, C>(
    curve: &C,
    circle: &Circle<T>,
    opts: &QueryOptions,
) -> Result<Vec<Intersection<T>>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    let (_, merged) = events(curve, &CircleField::new(circle), opts)?;
    Ok(to_intersections(merged))
}
