//! Rational Bézier pieces of every curve kind, for searches that subdivide: each piece knows
//! its parameter interval on the curve, its homogeneous control points and the bounding box of
//! its projected control points, which contains the piece (all weights are positive, so each
//! point of the piece is a convex combination of the projected control points).
//!
//! Every curve kind gives its pieces through [`ParametricCurve::bezier_enclosure`]: Bézier,
//! B-spline, NURBS, Hermite, segment and circle exactly (slack 0), composite curves piece by
//! piece. A curve without such a form (a user's own [`ParametricCurve`], or a composite piece
//! of that kind) is enclosed by [`sampled_pieces`]: cubic Bézier pieces interpolating the curve,
//! each with a slack measured against the curve, so that every curve works in the curve–curve
//! queries.
//!
//! Segments and circles become curves here too: a segment is parameterized by t ∈ [0, 1]
//! from its start to its end, a circle by its angle θ ∈ [0, 2π] counter-clockwise from +x.

use nalgebra::{Point, Point2, SVector, Vector2};

use super::box_tree::point_box_distance;
use crate::bezier::BezierCurve;
use crate::bspline::BSplineCurve;
use crate::curve::{check_parameter, ParametricCurve};
use crate::errors::{Error, Result};
use crate::hermite::HermiteCurve;
use crate::nurbs::NurbsCurve;
use crate::primitives::{Circle, Segment};
use crate::scalar::{cst, re, Scalar};

/// One rational Bézier piece: C(s) for s ∈ [start, end] of the curve's parameter is the
/// projection of Σ B_{i,n}(t) (w_i P_i, w_i), with t mapping [start, end] onto [0, 1] (exactly
/// linearly for polynomial and NURBS pieces; monotonically for circle quarters), up to
/// [`slack`](Self::slack) (0 for exact forms).
#[derive(Debug, Clone, PartialEq)]
pub struct RationalPiece<const D: usize> {
    /// Start of the piece's parameter interval on its curve.
    pub start: f64,
    /// End of the piece's parameter interval.
    pub end: f64,
    /// Homogeneous control points, D + 1 values each: (w·P, w).
    pub homogeneous: Vec<f64>,
    /// How far (length units) the curve may lie from the piece over [start, end]: 0 when the
    /// piece is the curve's exact form, the measured margin of a sampled enclosure otherwise.
    /// [`bounding_box`](Self::bounding_box) is grown by it.
    pub slack: f64,
}

impl<const D: usize> RationalPiece<D> {
    /// A piece from Euclidean control points and their weights.
    pub fn new(start: f64, end: f64, points: &[Point<f64, D>], weights: &[f64]) -> Self {
        let mut homogeneous = Vec::with_capacity(points.len() * (D + 1));
        for (p, &w) in points.iter().zip(weights) {
            homogeneous.extend(p.coords.iter().map(|&c| c * w));
            homogeneous.push(w);
        }
        Self {
            start,
            end,
            homogeneous,
            slack: 0.0,
        }
    }

    /// The same piece with [`slack`](Self::slack) set.
    pub fn with_slack(mut self, slack: f64) -> Self {
        self.slack = slack;
        self
    }

    /// The same piece on the parameter interval [start, end] (an affine change of the curve's
    /// parameter, as a composite curve makes of its pieces' own parameters).
    pub fn reparameterized(mut self, start: f64, end: f64) -> Self {
        self.start = start;
        self.end = end;
        self
    }

    /// The projected control points.
    pub fn points(&self) -> impl Iterator<Item = SVector<f64, D>> + '_ {
        self.homogeneous
            .chunks_exact(D + 1)
            .map(|c| SVector::<f64, D>::from_fn(|i, _| c[i] / c[D]))
    }

    /// The bounding box (min, max) of the projected control points grown by the
    /// [`slack`](Self::slack); it contains the curve over [start, end].
    pub fn bounding_box(&self) -> (SVector<f64, D>, SVector<f64, D>) {
        let mut lo = SVector::<f64, D>::repeat(f64::INFINITY);
        let mut hi = SVector::<f64, D>::repeat(f64::NEG_INFINITY);
        for p in self.points() {
            lo = lo.inf(&p);
            hi = hi.sup(&p);
        }
        let grow = SVector::<f64, D>::repeat(self.slack);
        (lo - grow, hi + grow)
    }

    /// The distance from `q` to [`bounding_box`](Self::bounding_box) (zero inside).
    pub(crate) fn box_distance(&self, q: &SVector<f64, D>) -> f64 {
        let (lo, hi) = self.bounding_box();
        point_box_distance(q, (&lo, &hi))
    }

    /// In the plane, the directions the piece's tangent takes: the centre angle and the
    /// half-width of an interval holding them all, or `None` when they span a right angle or
    /// more, the piece is not exact (slack > 0), or D ≠ 2. (Read as lines, mod π, by callers
    /// that need only the tangent's line.)
    ///
    /// With positive weights C′(t) is a positive combination of the differences P_j − P_i
    /// (j > i) of the projected control points, hence of consecutive differences, so the
    /// interval of the consecutive differences' directions holds every tangent.
    pub(crate) fn tangent_lines(&self) -> Option<(f64, f64)> {
        if D != 2 || self.slack > 0.0 {
            return None;
        }
        let mut reference: Option<f64> = None;
        let (mut lo, mut hi) = (0.0_f64, 0.0_f64);
        let mut previous: Option<SVector<f64, D>> = None;
        for point in self.points() {
            let Some(before) = previous.replace(point) else {
                continue;
            };
            let d = point - before;
            if d[0] == 0.0 && d[1] == 0.0 {
                continue;
            }
            let angle = d[1].atan2(d[0]);
            let Some(r) = reference else {
                reference = Some(angle);
                continue;
            };
            // Relative to the first direction, as a vector: into (−π, π]. (Folding to
            // lines here would be wrong: a piece whose tangent turns back through a cusp-like
            // bend has differences pointing nearly opposite ways, on one line, while its
            // tangent sweeps every direction between.)
            let mut rel = (angle - r).rem_euclid(std::f64::consts::TAU);
            if rel > std::f64::consts::PI {
                rel -= std::f64::consts::TAU;
            }
            lo = lo.min(rel);
            hi = hi.max(rel);
        }
        let r = reference?;
        let half = 0.5 * (hi - lo);
        (half < std::f64::consts::FRAC_PI_4).then_some((r + 0.5 * (lo + hi), half))
    }

    /// The chord from the first to the last control point and how far the curve may lie from
    /// it over [start, end]: the largest distance of a control point from the chord segment,
    /// plus the [`slack`](Self::slack). The piece lies in the convex hull of its control points,
    /// so every point of it is within that distance of the chord. For a short piece the
    /// distance shrinks like the square of its length (where a box shrinks only linearly).
    pub fn chord_and_flatness(&self) -> (SVector<f64, D>, SVector<f64, D>, f64) {
        let (a, b) = self.end_points();
        let flat = self
            .points()
            .map(|p| point_segment_distance(&p, &a, &b))
            .fold(0.0, f64::max);
        (a, b, flat + self.slack)
    }

    /// The first and last control points, which lie on the curve.
    pub fn end_points(&self) -> (SVector<f64, D>, SVector<f64, D>) {
        let mut it = self.points();
        let first = it.next().unwrap_or_else(SVector::zeros);
        let last = it.last().unwrap_or(first);
        (first, last)
    }

    /// The two halves at t = 1/2 (de Casteljau on the homogeneous points).
    pub fn halves(&self) -> (Self, Self) {
        let dim = D + 1;
        let count = self.homogeneous.len() / dim;
        let mut column = self.homogeneous.clone();
        let mut left = Vec::with_capacity(column.len());
        let mut right = Vec::with_capacity(column.len());
        left.extend_from_slice(&column[..dim]);
        right.extend_from_slice(&column[(count - 1) * dim..]);
        for round in 1..count {
            let top = count - round;
            for i in 0..top {
                for c in 0..dim {
                    column[i * dim + c] = 0.5 * (column[i * dim + c] + column[(i + 1) * dim + c]);
                }
            }
            left.extend_from_slice(&column[..dim]);
            right.extend_from_slice(&column[(top - 1) * dim..top * dim]);
        }
        // `right` was gathered from the last point inwards.
        let mut ordered = Vec::with_capacity(right.len());
        for chunk in right.chunks_exact(dim).rev() {
            ordered.extend_from_slice(chunk);
        }
        let mid = 0.5 * (self.start + self.end);
        (
            Self {
                start: self.start,
                end: mid,
                homogeneous: left,
                slack: self.slack,
            },
            Self {
                start: mid,
                end: self.end,
                homogeneous: ordered,
                slack: self.slack,
            },
        )
    }
}

/// The distance from `p` to the segment from `a` to `b`.
pub(crate) fn point_segment_distance<const D: usize>(
    p: &SVector<f64, D>,
    a: &SVector<f64, D>,
    b: &SVector<f64, D>,
) -> f64 {
    let d = b - a;
    let len2 = d.norm_squared();
    let t = if len2 > 0.0 {
        ((p - a).dot(&d) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a + d * t - p).norm()
}

/// The distance between the segments p1q1 and p2q2 (their closest pair: the unconstrained
/// minimiser of |p1 + s·d1 − p2 − t·d2|² clamped to the unit square, one parameter at a time).
pub(crate) fn segment_segment_distance<const D: usize>(
    (p1, q1): (&SVector<f64, D>, &SVector<f64, D>),
    (p2, q2): (&SVector<f64, D>, &SVector<f64, D>),
) -> f64 {
    let (d1, d2, r) = (q1 - p1, q2 - p2, p1 - p2);
    let (a, e, f) = (d1.norm_squared(), d2.norm_squared(), d2.dot(&r));
    let tiny = f64::MIN_POSITIVE;
    let (s, t) = if a <= tiny && e <= tiny {
        (0.0, 0.0)
    } else if a <= tiny {
        (0.0, (f / e).clamp(0.0, 1.0))
    } else {
        let c = d1.dot(&r);
        if e <= tiny {
            ((-c / a).clamp(0.0, 1.0), 0.0)
        } else {
            let b = d1.dot(&d2);
            let denom = a * e - b * b;
            let s = if denom > 0.0 {
                ((b * f - c * e) / denom).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let t = (b * s + f) / e;
            if t < 0.0 {
                ((-c / a).clamp(0.0, 1.0), 0.0)
            } else if t > 1.0 {
                (((b - c) / a).clamp(0.0, 1.0), 1.0)
            } else {
                (s, t)
            }
        }
    };
    (p1 + d1 * s - p2 - d2 * t).norm()
}

/// Curves that can be cut into rational Bézier pieces: every [`ParametricCurve`] over `f64`,
/// exactly when it gives [`ParametricCurve::bezier_enclosure`], by [`sampled_pieces`] otherwise.
pub trait BezierPieces<const D: usize>: ParametricCurve<f64, D> {
    /// The pieces, in parameter order, covering the whole domain.
    ///
    /// Fails only when a curve without an exact form cannot be evaluated where it is sampled.
    fn bezier_pieces(&self) -> Result<Vec<RationalPiece<D>>>;
}

impl<C: ParametricCurve<f64, D> + ?Sized, const D: usize> BezierPieces<D> for C {
    fn bezier_pieces(&self) -> Result<Vec<RationalPiece<D>>> {
        match self.bezier_enclosure()? {
            Some(pieces) => Ok(pieces),
            None => sampled_pieces(self),
        }
    }
}

/// The real part of a point.
fn real_point<T: Scalar, const D: usize>(p: &Point<T, D>) -> Point<f64, D> {
    p.map(re)
}

/// A polynomial Bézier curve's real part as one piece on [0, 1].
pub(crate) fn bezier_form<T: Scalar, const D: usize>(
    curve: &BezierCurve<T, D>,
) -> Vec<RationalPiece<D>> {
    let points: Vec<_> = curve.control_points().iter().map(real_point).collect();
    let weights = vec![1.0; points.len()];
    vec![RationalPiece::new(0.0, 1.0, &points, &weights)]
}

/// A B-spline's real part as its Bézier segments on their knot spans.
pub(crate) fn bspline_form<T: Scalar, const D: usize>(
    curve: &BSplineCurve<T, D>,
) -> Vec<RationalPiece<D>> {
    curve
        .to_bezier_segments()
        .into_iter()
        .flat_map(|(a, b, piece)| {
            bezier_form(&piece)
                .into_iter()
                .map(move |p| p.reparameterized(re(a), re(b)))
        })
        .collect()
}

/// A NURBS curve's real part as its rational Bézier segments on their knot spans.
pub(crate) fn nurbs_form<T: Scalar, const D: usize>(
    curve: &NurbsCurve<T, D>,
) -> Vec<RationalPiece<D>> {
    curve
        .to_bezier_segments()
        .into_iter()
        .map(|(a, b, piece)| {
            let points: Vec<_> = piece.control_points().iter().map(real_point).collect();
            let weights: Vec<f64> = piece.weights().iter().map(|&w| re(w)).collect();
            RationalPiece::new(re(a), re(b), &points, &weights)
        })
        .collect()
}

/// A cubic Hermite curve's real part as its cubic Bézier form, if it has one.
pub(crate) fn hermite_form<T: Scalar, const D: usize>(
    curve: &HermiteCurve<T, D>,
) -> Option<Vec<RationalPiece<D>>> {
    curve.to_bezier().ok().map(|b| bezier_form(&b))
}

/// Samples per piece against which a sampled enclosure is measured (at t = k/8, k = 1…7).
const CHECK_SAMPLES: usize = 7;

/// Deepest halving of one breakpoint span in [`sampled_pieces`] (2²⁰ pieces at most).
const MAX_DEPTH: u32 = 20;

/// The real part of C(u).
fn real_position<T: Scalar, const D: usize, C>(curve: &C, u: f64) -> Result<SVector<f64, D>>
where
    C: ParametricCurve<T, D> + ?Sized,
{
    Ok(curve.point(cst(u))?.coords.map(re))
}

/// Cubic Bézier pieces that enclose any curve, from evaluation alone: on each span between
/// the curve's breakpoints, the cubic through C at t = 0, ⅓, ⅔, 1 of the span, halved until it
/// is within 10⁻⁶ of the curve's extent of C at t = k/8 (k = 1…7), with twice that measured
/// error as the piece's [`slack`](RationalPiece::slack).
///
/// The enclosure is as good as the samples: the interpolation error of a smooth curve is
/// O(h⁴) and varies slowly over a short piece, so 7 samples see its size. Around a kink the
/// curve does not report, the samples see an error of the order of the piece's length, so the
/// pieces there are halved until they are about as short as the accuracy asked (the tests
/// check such an enclosure densely); a jump is halved to 2⁻²⁰ of the span and its measured gap
/// kept as slack, which is as good as the samples that straddle it.
///
/// ```
/// use camber_geom::queries::{sampled_pieces, RationalPiece};
/// use camber_geom::{ParametricCurve, Result};
/// use nalgebra::{Point2, SVector, Vector2};
/// /// The unit circle by angle, known to the kernel only through evaluation.
/// struct Round;
/// impl ParametricCurve<f64, 2> for Round {
///     fn domain(&self) -> (f64, f64) { (0.0, std::f64::consts::TAU) }
///     fn derivatives_into(&self, u: f64, out: &mut [SVector<f64, 2>]) -> Result<()> {
///         for (k, o) in out.iter_mut().enumerate() {
///             let a = u + k as f64 * std::f64::consts::FRAC_PI_2;
///             *o = Vector2::new(a.cos(), a.sin());
///         }
///         Ok(())
///     }
/// }
/// let pieces = sampled_pieces(&Round)?;
/// // Every point of the circle lies in the box of the piece holding its angle.
/// for k in 0..100 {
///     let u = k as f64 * 0.0628;
///     let p = Round.point(u)?.coords;
///     let piece = pieces.iter().find(|q| q.start <= u && u <= q.end).unwrap();
///     let (lo, hi) = piece.bounding_box();
///     assert!(p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y);
/// }
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// Errors: the curve's own evaluation errors, and [`Error::NonFinite`] for a non-finite
/// domain or point.
pub fn sampled_pieces<T: Scalar, const D: usize, C>(curve: &C) -> Result<Vec<RationalPiece<D>>>
where
    C: ParametricCurve<T, D> + ?Sized,
{
    let (a, b) = curve.domain();
    let (a, b) = (re(a), re(b));
    crate::curve::check_interval(a, b)?;
    let mut spans: Vec<f64> = curve
        .breakpoints()
        .into_iter()
        .map(re)
        .filter(|u| u.is_finite() && *u > a && *u < b)
        .collect();
    spans.insert(0, a);
    spans.push(b);
    spans.dedup_by(|x, y| x <= y);
    // The extent, from a few points per span, sets the accuracy asked of the pieces.
    let mut lo = SVector::<f64, D>::repeat(f64::INFINITY);
    let mut hi = SVector::<f64, D>::repeat(f64::NEG_INFINITY);
    for w in spans.windows(2) {
        for k in 0..=8 {
            let p = real_position(curve, w[0] + (w[1] - w[0]) * k as f64 / 8.0)?;
            if let Some((i, &v)) = p.iter().enumerate().find(|(_, v)| !v.is_finite()) {
                return Err(Error::NonFinite {
                    what: "point of a sampled curve, coordinate",
                    index: i,
                    value: v,
                });
            }
            lo = lo.inf(&p);
            hi = hi.sup(&p);
        }
    }
    let target = 1e-6 * (hi - lo).norm().max(f64::MIN_POSITIVE);
    let mut out = Vec::new();
    for w in spans.windows(2) {
        let mut stack = vec![(w[0], w[1], 0_u32)];
        // Depth-first, right half pushed first, so the pieces come out in parameter order.
        while let Some((u0, u1, depth)) = stack.pop() {
            let (piece, error) = interpolating_cubic(curve, u0, u1)?;
            if error <= target || depth >= MAX_DEPTH {
                out.push(piece.with_slack(2.0 * error));
            } else {
                let mid = 0.5 * (u0 + u1);
                stack.push((mid, u1, depth + 1));
                stack.push((u0, mid, depth + 1));
            }
        }
    }
    Ok(out)
}

/// The cubic Bézier through C(u0), C at ⅓ and ⅔ of the way, and C(u1), and its largest
/// distance from the curve at the check samples.
fn interpolating_cubic<T: Scalar, const D: usize, C>(
    curve: &C,
    u0: f64,
    u1: f64,
) -> Result<(RationalPiece<D>, f64)>
where
    C: ParametricCurve<T, D> + ?Sized,
{
    let at = |t: f64| real_position(curve, if t >= 1.0 { u1 } else { u0 + (u1 - u0) * t });
    let (q0, q1, q2, q3) = (at(0.0)?, at(1.0 / 3.0)?, at(2.0 / 3.0)?, at(1.0)?);
    // B(⅓) = (8b0 + 12b1 + 6b2 + b3)/27 and B(⅔) = (b0 + 6b1 + 12b2 + 8b3)/27, solved for b1, b2.
    let r1 = q1 * 27.0 - q0 * 8.0 - q3;
    let r2 = q2 * 27.0 - q0 - q3 * 8.0;
    let b1 = (r1 * 2.0 - r2) / 18.0;
    let b2 = (r2 * 2.0 - r1) / 18.0;
    let control = [q0, b1, b2, q3];
    let mut error: f64 = 0.0;
    for k in 1..=CHECK_SAMPLES {
        let t = k as f64 / (CHECK_SAMPLES + 1) as f64;
        let s = 1.0 - t;
        let bez = control[0] * (s * s * s)
            + control[1] * (3.0 * s * s * t)
            + control[2] * (3.0 * s * t * t)
            + control[3] * (t * t * t);
        let gap = (at(t)? - bez).norm();
        if !gap.is_finite() {
            return Err(Error::NonFinite {
                what: "sampled curve point at parameter index",
                index: k,
                value: gap,
            });
        }
        error = error.max(gap);
    }
    let points = control.map(Point::from);
    Ok((RationalPiece::new(u0, u1, &points, &[1.0; 4]), error))
}

impl<T: Scalar> ParametricCurve<T, 2> for Segment<T> {
    /// [0, 1], from the start to the end.
    fn domain(&self) -> (T, T) {
        (T::zero(), T::one())
    }

    fn derivatives_into(&self, u: T, out: &mut [SVector<T, 2>]) -> Result<()> {
        check_parameter(u, (T::zero(), T::one()))?;
        for (k, slot) in out.iter_mut().enumerate() {
            *slot = match k {
                0 => self.point_at(u).coords,
                1 => self.direction(),
                _ => Vector2::zeros(),
            };
        }
        Ok(())
    }

    /// The segment itself, as one linear piece on [0, 1].
    fn bezier_enclosure(&self) -> Result<Option<Vec<RationalPiece<2>>>> {
        let ends = [real_point(self.start()), real_point(self.end())];
        Ok(Some(vec![RationalPiece::new(0.0, 1.0, &ends, &[1.0, 1.0])]))
    }
}

impl<T: Scalar> ParametricCurve<T, 2> for Circle<T> {
    /// [0, 2π]: the angle from +x, counter-clockwise.
    fn domain(&self) -> (T, T) {
        (T::zero(), T::two_pi())
    }

    /// The k-th derivative with respect to the angle is r·(cos(θ + kπ/2), sin(θ + kπ/2)).
    fn derivatives_into(&self, u: T, out: &mut [SVector<T, 2>]) -> Result<()> {
        check_parameter(u, (T::zero(), T::two_pi()))?;
        let (s, c) = (u.sin(), u.cos());
        for (k, slot) in out.iter_mut().enumerate() {
            let (x, y) = match k % 4 {
                0 => (c, s),
                1 => (-s, c),
                2 => (-c, -s),
                _ => (s, -c),
            };
            *slot = Vector2::new(x, y) * self.radius();
            if k == 0 {
                *slot += self.center().coords;
            }
        }
        Ok(())
    }

    /// The quarter angles, where the rational pieces join.
    fn breakpoints(&self) -> Vec<T> {
        (0..=4)
            .map(|k| T::frac_pi_2() * crate::scalar::from_usize::<T>(k))
            .collect()
    }

    /// Four rational quadratic quarters, (1, 1/√2, 1) weights, over the quarter angles.
    fn bezier_enclosure(&self) -> Result<Option<Vec<RationalPiece<2>>>> {
        let (c, r) = (real_point(self.center()), re(self.radius()));
        let w = std::f64::consts::FRAC_1_SQRT_2;
        let corner = |x: f64, y: f64| Point2::new(c.x + r * x, c.y + r * y);
        let quarter = std::f64::consts::FRAC_PI_2;
        let dirs = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0), (1.0, 0.0)];
        Ok(Some(
            (0..4)
                .map(|k| {
                    let (a, b) = (dirs[k], dirs[k + 1]);
                    let pts = [
                        corner(a.0, a.1),
                        corner(a.0 + b.0, a.1 + b.1),
                        corner(b.0, b.1),
                    ];
                    let start = quarter * k as f64;
                    RationalPiece::new(start, start + quarter, &pts, &[1.0, w, 1.0])
                })
                .collect(),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// By hand: the polygon (0, 0), (1, 1), (2, 1) turns from 45° to 0°, so the tangent's
    /// directions are [0, π/4] (centre π/8, half-width π/8); a quadratic that turns back
    /// (its differences nearly opposite, on almost one line) sweeps too wide for an interval;
    /// so does a piece with slack.
    #[test]
    fn tangent_directions_of_pieces_by_hand() {
        let pts = [
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(2.0, 1.0),
        ];
        let piece = RationalPiece::<2>::new(0.0, 1.0, &pts, &[1.0, 3.0, 1.0]);
        let (centre, half) = piece.tangent_lines().unwrap();
        let eighth = std::f64::consts::FRAC_PI_8;
        assert!((centre - eighth).abs() < 1e-15 && (half - eighth).abs() < 1e-15);
        let back = [
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 3.0),
            Point2::new(2.1, -3.0),
        ];
        assert!(RationalPiece::<2>::new(0.0, 1.0, &back, &[1.0; 3])
            .tangent_lines()
            .is_none());
        assert!(piece.with_slack(1e-9).tangent_lines().is_none());
    }

    #[test]
    fn halves_of_a_quadratic_by_hand() {
        let piece = RationalPiece::<2>::new(
            0.0,
            2.0,
            &[
                Point2::new(0.0, 0.0),
                Point2::new(1.0, 2.0),
                Point2::new(2.0, 0.0),
            ],
            &[1.0, 1.0, 1.0],
        );
        let (l, r) = piece.halves();
        let lp: Vec<_> = l.points().collect();
        let rp: Vec<_> = r.points().collect();
        assert_eq!(lp[1], Vector2::new(0.5, 1.0));
        assert_eq!(lp[2], Vector2::new(1.0, 1.0));
        assert_eq!(rp[0], Vector2::new(1.0, 1.0));
        assert_eq!(rp[2], Vector2::new(2.0, 0.0));
        assert!((l.end - 1.0).abs() < 1e-15 && (r.start - 1.0).abs() < 1e-15);
    }

    #[test]
    fn segment_distances_by_hand() {
        let v = |x: f64, y: f64| Vector2::new(x, y);
        // Crossing: 0. Parallel, 1 apart, overlapping: 1. Skew ends: (1, 0)–(2, 1) is √2.
        let d =
            segment_segment_distance((&v(0.0, 0.0), &v(2.0, 2.0)), (&v(0.0, 2.0), &v(2.0, 0.0)));
        assert!(d.abs() < 1e-15);
        let d =
            segment_segment_distance((&v(0.0, 0.0), &v(2.0, 0.0)), (&v(1.0, 1.0), &v(3.0, 1.0)));
        assert!((d - 1.0).abs() < 1e-15);
        let d =
            segment_segment_distance((&v(0.0, 0.0), &v(1.0, 0.0)), (&v(2.0, 1.0), &v(2.0, 3.0)));
        assert!((d - 2.0_f64.sqrt()).abs() < 1e-15);
        // A point (degenerate segment) against a segment.
        let d =
            segment_segment_distance((&v(0.5, 2.0), &v(0.5, 2.0)), (&v(0.0, 0.0), &v(1.0, 0.0)));
        assert!((d - 2.0).abs() < 1e-15);
        assert!(
            (point_segment_distance(&v(3.0, 4.0), &v(0.0, 0.0), &v(0.0, 1.0)) - 4.242640687119285)
                .abs()
                < 1e-12
        );
    }

    #[test]
    fn circle_quarters_lie_on_the_circle() {
        let circle = Circle::try_new(Point2::new(1.0, -1.0), 2.0).unwrap();
        for piece in circle.bezier_pieces().unwrap() {
            let (a, b) = piece.end_points();
            assert!(((a - Vector2::new(1.0, -1.0)).norm() - 2.0).abs() < 1e-15);
            assert!(((b - Vector2::new(1.0, -1.0)).norm() - 2.0).abs() < 1e-15);
            let (l, _) = piece.halves();
            let (_, mid) = l.end_points();
            assert!(((mid - Vector2::new(1.0, -1.0)).norm() - 2.0).abs() < 1e-14);
        }
    }
}
