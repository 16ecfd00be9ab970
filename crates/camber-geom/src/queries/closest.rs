//! The point of a curve closest to a given point.

use nalgebra::{Point, SVector};

use super::distance_minima::{Candidate, DistanceMinima};
use super::{
    domain_length, evaluate, opposite, polish, refine, scan, ClosestPoint, Field, QueryOptions,
    Sample,
};
use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::scalar::{cst, re, Scalar};

/// h(u) = ½|C(u) − p|²/σ², h′ = (C − p)·C′/σ², h″ = (|C′|² + (C − p)·C″)/σ²; measure |C − p|.
/// σ is a power of two near the query point's size (1 for points within the unit box), so a
/// far point's squares do not overflow and σ changes nothing but the exponent.
struct SquaredDistance<T: Scalar, const D: usize> {
    target: Point<T, D>,
    /// 1/σ.
    inverse_scale: f64,
}

impl<T: Scalar, const D: usize> Field<T, D> for SquaredDistance<T, D> {
    fn eval(&self, d: &[SVector<T, D>; 3]) -> [T; 3] {
        let k = cst::<T>(self.inverse_scale);
        let w = (d[0] - self.target.coords) * k;
        let (d1, d2) = (d[1] * k, d[2] * k);
        [
            w.norm_squared() * cst::<T>(0.5),
            w.dot(&d1),
            d1.norm_squared() + w.dot(&d2),
        ]
    }

    fn measure(&self, d: &[SVector<T, D>; 3], _h: T) -> T {
        // |w| = m·|w/m| with m the largest component: no overflow for any finite w.
        let w = d[0] - self.target.coords;
        let m = w.iter().fold(0.0_f64, |m, c| m.max(re(*c).abs()));
        if m > 1e-300 && m.is_finite() {
            (w * cst::<T>(1.0 / m)).norm() * cst::<T>(m)
        } else {
            w.norm()
        }
    }
}

/// 1/σ for the query point `p`: σ = 2^⌈log₂ max(|p|∞, 1)⌉.
fn inverse_scale<T: Scalar, const D: usize>(p: &Point<T, D>) -> f64 {
    let size = p.coords.iter().fold(1.0_f64, |m, c| m.max(re(*c).abs()));
    // size ≤ f64::MAX, so the exponent is at most 1024 and 2^−1024 is a (subnormal) f64.
    2.0_f64.powi(-(size.log2().ceil() as i32))
}

/// The point of `curve` closest to `p`, with [`QueryOptions::default`].
///
/// See [`closest_point_with`].
pub fn closest_point<T, const D: usize, C>(curve: &C, p: &Point<T, D>) -> Result<ClosestPoint<T, D>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    closest_point_with(curve, p, &QueryOptions::default())
}

/// The point of `curve` closest to `p`: the parameter u* minimising |C(u) − p| over the whole
/// domain, ends and breakpoints included, with the point C(u*) and the distance.
///
/// Every piece is sampled, every sign change of f(u) = (C(u) − p)·C′(u) from − to + between
/// samples (a local minimum of the distance) is refined by safeguarded Newton on f, and the
/// best of those minima and of all samples wins. On ties the smallest parameter is returned.
/// Where the curve's Bézier pieces are exact (Bézier, B-spline, Hermite, segment, NURBS with
/// positive weights, circle and arc, and composites of those), every piece whose control box
/// comes closer than that answer is also searched exactly: the roots of f on it are isolated
/// from a Bernstein form of its sign (module `distance_minima`; for a rational piece the
/// numerator of f), so a minimum between two samples is not missed however wiggly the piece.
/// Fails with [`Error::NonFinite`] for a point with a NaN or infinite coordinate, where the
/// curve cannot be evaluated, and for bad options.
///
/// ```
/// use camber_geom::queries::{closest_point_with, QueryOptions};
/// # use camber_geom::{ParametricCurve, Result};
/// # use nalgebra::{Point2, SVector};
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
/// // `UnitCircle` is (cos u, sin u) on [0, 2π].
/// let near = closest_point_with(&UnitCircle, &Point2::new(0.0, 3.0), &QueryOptions::default())?;
/// assert!((near.parameter - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
/// assert!((near.distance - 2.0).abs() < 1e-12);
/// # Ok::<(), camber_geom::Error>(())
/// ```
pub fn closest_point_with<T, const D: usize, C>(
    curve: &C,
    p: &Point<T, D>,
    opts: &QueryOptions,
) -> Result<ClosestPoint<T, D>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    for (index, &c) in p.coords.iter().enumerate() {
        if !re(c).is_finite() {
            return Err(Error::NonFinite {
                what: "query point coordinate",
                index,
                value: re(c),
            });
        }
    }
    let field = SquaredDistance {
        target: *p,
        inverse_scale: inverse_scale(p),
    };
    let found = scan(curve, &field, opts)?;
    let mut best = found.samples.first().copied();
    for s in found.samples.iter().chain(&found.extrema) {
        if let Some(b) = best {
            let better = re(s.h[0]) < re(b.h[0]) || (re(s.h[0]) <= re(b.h[0]) && re(s.u) < re(b.u));
            if better {
                best = Some(*s);
            }
        }
    }
    // `scan` always returns at least the two domain ends.
    let best = best.ok_or(Error::ZeroCount { what: "samples" })?;
    let best = isolated_minimum(curve, &field, opts, best)?;
    // At an interior minimum h″ > 0; a converged Newton step there only adds dual parts.
    let best = if re(best.h[2]) > 0.0 {
        let polished = polish(curve, &field, best, 1)?;
        // Accept rounding-level changes (the step is converged), nothing more.
        if re(polished.h[0]) <= re(best.h[0]) * (1.0 + 1e-14) {
            polished
        } else {
            best
        }
    } else {
        best
    };
    // Only a distance beyond the largest f64 (a point near ±1.8e308 in every coordinate) is
    // not finite here: refused rather than answered as infinity.
    if !re(best.measure).is_finite() {
        return Err(Error::NonFinite {
            what: "distance from the query point to the curve",
            index: 0,
            value: re(best.measure),
        });
    }
    Ok(ClosestPoint {
        parameter: best.u,
        point: best.point,
        distance: best.measure,
    })
}

/// `best` improved by the exact search of the curve's exact Bézier pieces (see
/// [`closest_point_with`]): each piece within `best`'s distance, its minima isolated by
/// [`DistanceMinima`] and refined as the samples' are.
fn isolated_minimum<T, const D: usize, C>(
    curve: &C,
    field: &SquaredDistance<T, D>,
    opts: &QueryOptions,
    best: Sample<T, D>,
) -> Result<Sample<T, D>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let Some(pieces) = curve.bezier_enclosure()? else {
        return Ok(best);
    };
    let q: SVector<f64, D> = SVector::from_fn(|c, _| re(field.target.coords[c]));
    let tol_u = opts.parameter_tolerance.max(0.0) * domain_length(curve);
    let (lo, hi) = curve.domain();
    let (lo, hi) = (re(lo), re(hi));
    let mut best = best;
    let mut minima = DistanceMinima::default();
    let mut found = Vec::new();
    for piece in &pieces {
        // A sampled enclosure is not the curve itself: nothing exact to read from it.
        if piece.slack > 0.0 || piece.box_distance(&q) > re(best.measure) {
            continue;
        }
        if !minima.find(piece, &q, &mut found) {
            continue;
        }
        let at = |t: f64| cst::<T>((piece.start + (piece.end - piece.start) * t).clamp(lo, hi));
        for candidate in &found {
            let s = match *candidate {
                Candidate::Bracket(t0, t1) => {
                    let a = evaluate(curve, field, at(t0), 0)?;
                    let b = evaluate(curve, field, at(t1), 0)?;
                    if opposite(a.h[1], b.h[1]) {
                        refine(curve, field, &a, &b, 1, tol_u, opts.max_iterations)?
                    } else if re(a.h[0]) <= re(b.h[0]) {
                        a
                    } else {
                        b
                    }
                }
                Candidate::At(t) => evaluate(curve, field, at(t), 0)?,
            };
            if re(s.h[0]) < re(best.h[0]) {
                best = s;
            }
        }
    }
    Ok(best)
}
