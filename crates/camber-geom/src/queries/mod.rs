//! Curve queries: curvature, closest point, intersections with lines and circles, minimum
//! distance.
//!
//! Everything here is written once against [`ParametricCurve`] and works for every curve type
//! and every scalar (with dual numbers the answers carry derivatives: every iterative search
//! ends with one Newton step, so the parameter it returns has the implicit-function derivative).
//!
//! # How the searches work
//! The curve is sampled at [`QueryOptions::samples_per_piece`] parameters on every piece
//! between consecutive [`breakpoints`](ParametricCurve::breakpoints) (at an interior breakpoint
//! the piece on the left is sampled just before it, the piece on the right at it, so a corner
//! is seen from both sides). Along the curve a smooth scalar field h(u) with its derivatives
//! h′, h″ is watched — the squared distance to a point, the signed distance to a line, the power
//! |C − c|² − r² with respect to a circle:
//! - a sign change of h′ between two samples of one piece brackets an extremum, refined by a
//!   safeguarded Newton iteration on h′ (Newton steps that leave the bracket or stall are
//!   replaced by bisection);
//! - a sign change of h brackets a root, refined the same way on h;
//! - an extremum (or a sample) where h comes within [`QueryOptions::touch_tolerance`] of zero
//!   is a tangential touch.
//!
//! Features smaller than the sample spacing (two extrema between neighbouring samples) can be
//! missed; raise `samples_per_piece` for wiggly pieces. The closest point does not rely on the
//! samples alone where the curve's pieces are polynomials: their minima are isolated exactly
//! (`distance_minima`).
//!
//! ```
//! use camber_geom::queries::{closest_point, intersect_line};
//! use camber_geom::{Line, ParametricCurve, Result};
//! use nalgebra::{Point2, SVector, Vector2};
//!
//! /// The parabola (u, u²) on [−2, 2].
//! struct Parabola;
//! impl ParametricCurve<f64, 2> for Parabola {
//!     fn domain(&self) -> (f64, f64) { (-2.0, 2.0) }
//!     fn derivatives_into(&self, u: f64, out: &mut [SVector<f64, 2>]) -> Result<()> {
//!         camber_geom::curve::check_parameter(u, self.domain())?;
//!         let all = [SVector::from([u, u * u]), SVector::from([1.0, 2.0 * u]), SVector::from([0.0, 2.0])];
//!         for (k, o) in out.iter_mut().enumerate() {
//!             *o = all.get(k).copied().unwrap_or_else(SVector::zeros);
//!         }
//!         Ok(())
//!     }
//! }
//!
//! let near = closest_point(&Parabola, &Point2::new(0.0, 1.0))?;
//! assert!((near.distance - 0.75_f64.sqrt()).abs() < 1e-12);
//! let line = Line::try_new(Point2::new(0.0, 1.0), Vector2::new(1.0, 0.0))?;
//! let hits = intersect_line(&Parabola, &line)?;
//! assert_eq!(hits.len(), 2);
//! assert!((hits[0].parameter + 1.0).abs() < 1e-12 && (hits[1].parameter - 1.0).abs() < 1e-12);
//! # Ok::<(), camber_geom::Error>(())
//! ```

pub(crate) mod box_tree;
mod closest;
mod curvature;
mod curve_curve;
mod distance;
pub(crate) mod distance_minima;
mod intersect;
mod overlap;
pub(crate) mod pieces;

pub use closest::{closest_point, closest_point_with};
pub use curvature::{
    curvature, curvature_from_derivatives, curvature_vector, curvature_vector_from_derivatives,
    signed_curvature, signed_curvature_from_derivatives,
};
pub use curve_curve::{curve_distance, intersect_curves, CurveCurveOptions, CurvePairPoint};
pub use distance::{
    distance_to_circle, distance_to_circle_with, distance_to_line, distance_to_line_with,
    signed_distance_to_circle, signed_distance_to_circle_with,
};
pub use intersect::{intersect_circle, intersect_circle_with, intersect_line, intersect_line_with};
pub use overlap::{intersect_curves_with_overlaps, CurveIntersections, Overlap};
pub use pieces::{sampled_pieces, BezierPieces, RationalPiece};

use nalgebra::{Point, Point2, SVector};

use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::scalar::{cst, from_usize, re, Scalar};

/// Settings shared by the sampling-and-refinement queries.
///
/// ```
/// use camber_geom::queries::QueryOptions;
/// let opts = QueryOptions::default().with_samples_per_piece(64);
/// assert_eq!(opts.samples_per_piece, 64);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QueryOptions {
    /// Samples per piece between consecutive breakpoints (at least 1; default 16).
    pub samples_per_piece: usize,
    /// Refinement stops when a step (or the bracket) is below this fraction of the domain
    /// length (default 1e-14).
    pub parameter_tolerance: f64,
    /// A point within this distance (length units) of the line or circle counts as on it: it
    /// decides tangential touches, accepts refined roots and merges near-coincident
    /// intersections (default 1e-9).
    pub touch_tolerance: f64,
    /// Iteration cap of every refinement (default 100).
    pub max_iterations: usize,
}

impl Default for QueryOptions {
    fn default() -> Self {
        Self {
            samples_per_piece: 16,
            parameter_tolerance: 1e-14,
            touch_tolerance: 1e-9,
            max_iterations: 100,
        }
    }
}

impl QueryOptions {
    /// Sets [`samples_per_piece`](Self::samples_per_piece).
    pub fn with_samples_per_piece(mut self, samples: usize) -> Self {
        self.samples_per_piece = samples;
        self
    }

    /// Sets [`parameter_tolerance`](Self::parameter_tolerance).
    pub fn with_parameter_tolerance(mut self, tolerance: f64) -> Self {
        self.parameter_tolerance = tolerance;
        self
    }

    /// Sets [`touch_tolerance`](Self::touch_tolerance).
    pub fn with_touch_tolerance(mut self, tolerance: f64) -> Self {
        self.touch_tolerance = tolerance;
        self
    }

    /// Sets [`max_iterations`](Self::max_iterations).
    pub fn with_max_iterations(mut self, iterations: usize) -> Self {
        self.max_iterations = iterations;
        self
    }

    /// Fails with [`Error::ZeroCount`] for zero samples and [`Error::NonFinite`] for a
    /// non-finite tolerance.
    fn check(&self) -> Result<()> {
        if self.samples_per_piece == 0 {
            return Err(Error::ZeroCount {
                what: "samples per piece",
            });
        }
        for (index, value) in [self.parameter_tolerance, self.touch_tolerance]
            .into_iter()
            .enumerate()
        {
            if !value.is_finite() {
                return Err(Error::NonFinite {
                    what: "query tolerance",
                    index,
                    value,
                });
            }
        }
        Ok(())
    }
}

/// A point of a curve found by a query: its parameter, the point, and its distance to the
/// query object (length units; signed where the function says so).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClosestPoint<T: Scalar, const D: usize> {
    /// The curve parameter u.
    pub parameter: T,
    /// The curve point C(u).
    pub point: Point<T, D>,
    /// The distance at C(u).
    pub distance: T,
}

/// An intersection of a planar curve with a line or circle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Intersection<T: Scalar> {
    /// The curve parameter u.
    pub parameter: T,
    /// The intersection point C(u).
    pub point: Point2<T>,
}

/// The field h(u), h′(u), h″(u) computed from C, C′, C″ at one parameter.
pub(crate) trait Field<T: Scalar, const D: usize> {
    /// h and its first two derivatives.
    fn eval(&self, d: &[SVector<T, D>; 3]) -> [T; 3];
    /// A non-negative distance (length units) that is zero exactly where h is.
    fn measure(&self, d: &[SVector<T, D>; 3], h: T) -> T;
}

/// One evaluation of a field along the curve.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Sample<T: Scalar, const D: usize> {
    /// The curve parameter.
    pub u: T,
    /// Index of the piece (between breakpoints) the sample belongs to.
    pub piece: usize,
    /// C(u).
    pub point: Point<T, D>,
    /// h, h′, h″ at u.
    pub h: [T; 3],
    /// The distance measure at u.
    pub measure: T,
}

/// The samples, refined extrema and refined roots of a field along a curve.
pub(crate) struct Scan<T: Scalar, const D: usize> {
    pub samples: Vec<Sample<T, D>>,
    pub extrema: Vec<Sample<T, D>>,
    pub roots: Vec<Sample<T, D>>,
}

/// Evaluates the field at `u`.
fn evaluate<T, const D: usize, C, F>(
    curve: &C,
    field: &F,
    u: T,
    piece: usize,
) -> Result<Sample<T, D>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
    F: Field<T, D>,
{
    let d = curve.second_order(u)?;
    let h = field.eval(&d);
    Ok(Sample {
        u,
        piece,
        point: Point::from(d[0]),
        h,
        measure: field.measure(&d, h[0]),
    })
}

/// The curve's breakpoints cleaned up: strictly increasing, inside the domain, both ends
/// included (whatever the implementation returned).
fn clean_breakpoints<T, const D: usize, C>(curve: &C) -> Vec<T>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let (a, b) = curve.domain();
    let mut out = vec![a];
    for u in curve.breakpoints() {
        if out.last().is_some_and(|&l| u > l) && u < b {
            out.push(u);
        }
    }
    out.push(b);
    out
}

/// The domain length as f64 (for tolerances).
fn domain_length<T, const D: usize, C>(curve: &C) -> f64
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
{
    let (a, b) = curve.domain();
    re(b - a)
}

/// Sign of the real part: −1, 0 or 1.
fn sign<T: Scalar>(x: T) -> i8 {
    let v = re(x);
    if v > 0.0 {
        1
    } else if v < 0.0 {
        -1
    } else {
        0
    }
}

/// Whether two values have strictly opposite signs.
fn opposite<T: Scalar>(x: T, y: T) -> bool {
    sign(x) * sign(y) < 0
}

/// Samples the field, then refines every bracketed extremum (within a piece) and root.
/// Roots whose measure exceeds the touch tolerance (a sign change across a gap) are dropped.
pub(crate) fn scan<T, const D: usize, C, F>(
    curve: &C,
    field: &F,
    opts: &QueryOptions,
) -> Result<Scan<T, D>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
    F: Field<T, D>,
{
    opts.check()?;
    let breaks = clean_breakpoints(curve);
    let n = opts.samples_per_piece;
    let pieces = breaks.len() - 1;
    let count = n
        .checked_add(1)
        .and_then(|per| per.checked_mul(pieces))
        .and_then(|c| c.checked_add(1))
        .unwrap_or(usize::MAX);
    if count > MAX_SAMPLES {
        return Err(Error::TooLarge {
            what: "query samples (pieces × (samples per piece + 1))",
            value: count,
            max: MAX_SAMPLES,
        });
    }
    let mut samples = Vec::new();
    samples
        .try_reserve_exact(count)
        .map_err(|_| Error::TooLarge {
            what: "query samples (memory)",
            value: count,
            max: MAX_SAMPLES,
        })?;
    for (k, pair) in breaks.windows(2).enumerate() {
        let (lo, hi) = (pair[0], pair[1]);
        let len = hi - lo;
        for j in 0..n {
            let u = lo + len * from_usize::<T>(j) / from_usize::<T>(n);
            samples.push(evaluate(curve, field, u, k)?);
        }
        // The end of an inner piece is sampled just before the breakpoint, so that its
        // derivatives are this piece's (the trait gives the right-hand piece's at a joint).
        let end = if k + 1 == pieces {
            hi
        } else {
            hi - len * cst::<T>(LEFT_LIMIT_OFFSET)
        };
        samples.push(evaluate(curve, field, end, k)?);
    }

    let tol_u = opts.parameter_tolerance.max(0.0) * domain_length(curve);
    let touch = opts.touch_tolerance.max(0.0);
    let mut extrema = Vec::new();
    let mut roots = Vec::new();
    for pair in samples.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let mut cuts = [Some(a), None, Some(b)];
        if a.piece == b.piece && opposite(a.h[1], b.h[1]) {
            let e = refine(curve, field, &a, &b, 1, tol_u, opts.max_iterations)?;
            extrema.push(e);
            cuts[1] = Some(e);
        }
        let cuts: Vec<Sample<T, D>> = cuts.into_iter().flatten().collect();
        for c in cuts.windows(2) {
            if opposite(c[0].h[0], c[1].h[0]) {
                let r = refine(curve, field, &c[0], &c[1], 0, tol_u, opts.max_iterations)?;
                if re(r.measure) <= touch {
                    roots.push(r);
                }
            }
        }
    }
    Ok(Scan {
        samples,
        extrema,
        roots,
    })
}

/// The most samples one query takes (pieces × (samples per piece + 1)): about 2 GB of
/// samples in f64, far above what the default 16 per piece needs for a curve of a million
/// pieces; a larger count (an absurd `samples_per_piece`) is refused before allocating.
pub const MAX_SAMPLES: usize = 1 << 25;

/// How far before an interior breakpoint the piece on its left is sampled, as a fraction of
/// the piece's length.
const LEFT_LIMIT_OFFSET: f64 = 1e-10;

/// Safeguarded Newton on h[k] (k = 0: a root of h, k = 1: an extremum of h) between samples
/// `a` and `b`, where h[k] has opposite signs. Newton steps that leave the bracket or do not
/// halve the previous step are replaced by bisection; the result ends with one Newton step
/// when it stays in the bracket, so that dual parts carry the implicit derivative.
fn refine<T, const D: usize, C, F>(
    curve: &C,
    field: &F,
    a: &Sample<T, D>,
    b: &Sample<T, D>,
    k: usize,
    tol_u: f64,
    max_iterations: usize,
) -> Result<Sample<T, D>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
    F: Field<T, D>,
{
    let half = cst::<T>(0.5);
    let (mut neg, mut pos) = if re(a.h[k]) < 0.0 {
        (a.u, b.u)
    } else {
        (b.u, a.u)
    };
    let ordered = |x: T, y: T| if x < y { (x, y) } else { (y, x) };
    let mut x = (a.u + b.u) * half;
    let mut s = evaluate(curve, field, x, a.piece)?;
    let mut previous_step = re(b.u - a.u).abs();
    for _ in 0..max_iterations {
        let (f, slope) = (s.h[k], s.h[k + 1]);
        if sign(f) == 0 {
            break;
        }
        if sign(f) < 0 {
            neg = x;
        } else {
            pos = x;
        }
        let (lo, hi) = ordered(neg, pos);
        let newton = (sign(slope) != 0).then(|| x - f / slope);
        let next = match newton {
            Some(nx) if nx > lo && nx < hi && re(nx - x).abs() <= 0.5 * previous_step => nx,
            _ => (lo + hi) * half,
        };
        let step = re(next - x).abs();
        x = next;
        s = evaluate(curve, field, x, a.piece)?;
        previous_step = step;
        if step <= tol_u || re(hi - lo) <= tol_u {
            break;
        }
    }
    let (f, slope) = (s.h[k], s.h[k + 1]);
    let (lo, hi) = ordered(a.u, b.u);
    if sign(slope) != 0 {
        let polished = x - f / slope;
        if polished >= lo && polished <= hi {
            s = evaluate(curve, field, polished, a.piece)?;
        }
    }
    Ok(s)
}

/// One Newton step on h[k] from sample `s` (k = 0: towards a root of h, k = 1: towards an
/// extremum), taken only when it stays in the domain and is no longer than
/// [`POLISH_STEP`] times the domain length, i.e. when `s` has already converged. In real
/// arithmetic it changes (next to) nothing; with dual numbers it gives the parameter the
/// implicit-function derivative −∂h[k]/∂θ / h[k+1], even when `s` is a sample that happened to
/// hit the solution exactly.
pub(crate) fn polish<T, const D: usize, C, F>(
    curve: &C,
    field: &F,
    s: Sample<T, D>,
    k: usize,
) -> Result<Sample<T, D>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
    F: Field<T, D>,
{
    let slope = s.h[k + 1];
    if sign(slope) == 0 {
        return Ok(s);
    }
    let next = s.u - s.h[k] / slope;
    let (a, b) = curve.domain();
    if next < a || next > b || re(next - s.u).abs() > POLISH_STEP * domain_length(curve) {
        return Ok(s);
    }
    evaluate(curve, field, next, s.piece)
}

/// Largest final Newton step [`polish`] takes, as a fraction of the domain length.
const POLISH_STEP: f64 = 1e-8;

/// Sorts events by parameter and merges neighbours that are the same intersection: closer
/// than the parameter tolerance, or joined by a curve point (their midpoint) within the touch
/// tolerance. Each cluster keeps its member of smallest measure.
pub(crate) fn merge_events<T, const D: usize, C, F>(
    curve: &C,
    field: &F,
    mut events: Vec<Sample<T, D>>,
    opts: &QueryOptions,
) -> Result<Vec<Sample<T, D>>>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
    F: Field<T, D>,
{
    events.sort_by(|x, y| re(x.u).total_cmp(&re(y.u)));
    let tol_u = opts.parameter_tolerance.max(0.0) * domain_length(curve);
    let touch = opts.touch_tolerance.max(0.0);
    let mut out: Vec<Sample<T, D>> = Vec::with_capacity(events.len());
    let mut last_u: Option<T> = None;
    for e in events {
        let same = match last_u {
            Some(prev) => {
                re(e.u - prev) <= tol_u || {
                    let mid = evaluate(curve, field, (e.u + prev) * cst::<T>(0.5), e.piece)?;
                    re(mid.measure) <= touch
                }
            }
            None => false,
        };
        last_u = Some(e.u);
        match out.last_mut() {
            Some(keep) if same => {
                if re(e.measure) < re(keep.measure) {
                    *keep = e;
                }
            }
            _ => out.push(e),
        }
    }
    Ok(out)
}

/// Every sample, extremum and root of a scan where the measure is within the touch tolerance,
/// merged into distinct intersections.
pub(crate) fn events<T, const D: usize, C, F>(
    curve: &C,
    field: &F,
    opts: &QueryOptions,
) -> Result<(Scan<T, D>, Vec<Sample<T, D>>)>
where
    T: Scalar,
    C: ParametricCurve<T, D> + ?Sized,
    F: Field<T, D>,
{
    let scan = scan(curve, field, opts)?;
    let touch = opts.touch_tolerance.max(0.0);
    let candidates: Vec<Sample<T, D>> = scan
        .samples
        .iter()
        .chain(&scan.extrema)
        .chain(&scan.roots)
        .filter(|s| re(s.measure) <= touch)
        .copied()
        .collect();
    let merged = merge_events(curve, field, candidates, opts)?
        .into_iter()
        .map(|e| polish(curve, field, e, 0))
        .collect::<Result<Vec<_>>>()?;
    Ok((scan, merged))
}
