//! Offset curves of planar curves, approximated by B-splines to a tolerance, with the error
//! measured.
//!
//! The offset of C at signed distance d is O(u) = C(u) + d·n(u), with n = (−C′_y, C′_x)/|C′|
//! the unit normal to the left of the direction of travel (d > 0 offsets to the left). Except
//! for lines and circles O is not a (rational) polynomial, so it is approximated by a cubic
//! B-spline F(s), s = (u − a)/(b − a).
//!
//! **Knots where O is less smooth.** O′ = C′·(1 − dκ) (κ the signed curvature), so O is as
//! smooth as C′ and κ: where C′ or κ jumps — at every knot of a quadratic B-spline, at a G1
//! joint that is not C1 — O′ jumps, and where only C‴ jumps (a simple knot of a cubic) O″ does.
//! A smooth cubic follows such a jump only with ever more control points (its error falls like
//! the spacing, or its square, instead of its fourth power: a quadratic B-spline's offset at
//! 10⁻⁶ used to end at 1.7·10⁻⁴ with 6,145 control points). So every breakpoint of C becomes a
//! knot of F whose multiplicity matches O there: 3 (C0) where O′ or the tangent direction of C
//! jumps, 2 (C1) where O″ jumps, 1 otherwise — the two sides compared just before and at the
//! breakpoint, a jump being a relative difference above 10⁻⁶. At a corner of C (a tangent jump)
//! the exact offset has a gap, which the fit bridges across its triple knot.
//!
//! **Chunks.** The pieces are fitted in chunks of about 32, each on its own parameter
//! σ ∈ [0, 1], so that work spent where the offset is hard stays there: one global fit redid
//! every piece whenever one missed, and its work grew faster than the curve. A chunk is cut
//! only at a breakpoint where O is continuous (never at a corner), and both chunks meeting
//! there are held to the exact offset at it and to as many of its derivatives as the knot
//! leaves continuous (O′ for multiplicity 2, O′ and O″ for 1, scaled to each chunk's σ; see
//! the module `jet` for O″). Laid end to end the chunks then join with a triple knot that is C1, and one
//! copy of it is removed exactly (module `join`): the result has the multiplicities above, except
//! that a cut at a multiplicity-1 breakpoint keeps two (C2 in fact, C1 in its knots).
//!
//! **Fitting a chunk.** O is sampled at parameters spread evenly over every piece, the samples
//! are fitted by least squares on those knots to half the tolerance (spans whose data are too
//! far are split further, see [`crate::fit`]), and the error max |F(s) − O(u)| is measured at
//! every sample and seven parameters between each pair. Until it is within the tolerance the
//! sampling of every piece whose measured error misses it is doubled (at most eight times),
//! the other pieces keep theirs; the error reported is the measured one either way, the
//! largest over the chunks.
//!
//! The offset is not trimmed: where |d| exceeds the radius of curvature it has cusps and loops,
//! and across a corner of C the fit bridges the gap; in both cases the measured error says how
//! well the fit follows O.
//!
//! ```
//! use camber_geom::offset::offset;
//! use camber_geom::{NurbsCurve2, ParametricCurve};
//! use nalgebra::Point2;
//! // A counter-clockwise unit circle offset by −0.25 (to the right, outwards).
//! let circle = NurbsCurve2::try_circular_arc(Point2::origin(), 1.0, 0.0, std::f64::consts::TAU)?;
//! let o = offset(&circle, -0.25, 1e-6)?;
//! assert!(o.max_error <= 1e-6);
//! assert!((o.curve.point(0.3)?.coords.norm() - 1.25).abs() < 1e-6);
//! # Ok::<(), camber_geom::Error>(())
//! ```

use nalgebra::{Point2, Vector2};

mod chunk;
mod jet;
mod join;

use chunk::{fit_chunk, Chunk};
use join::{join, Placed};

use crate::bspline::BSplineCurve;
use crate::budget::{default_limit, Budget};
use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::fit::{FitEnd, FitEnds};
use crate::scalar::{cst, re, Scalar};

/// An offset curve and how far it is from the exact offset.
#[derive(Debug, Clone, PartialEq)]
pub struct OffsetCurve<T: Scalar> {
    /// The approximating cubic B-spline, on [0, 1]: F(s) approximates O(a + (b − a)s).
    pub curve: BSplineCurve<T, 2>,
    /// The largest |F(s) − O(u)| measured (length units).
    pub max_error: f64,
}

/// Pieces per chunk: the fit is cut into independent chunks of about this many pieces.
const CHUNK_PIECES: usize = 32;
/// A relative difference above this between the two sides of a breakpoint is a jump.
const JUMP: f64 = 1e-6;
/// How far before a breakpoint its left side is read, as a fraction of the piece on its left.
const LEFT_LIMIT: f64 = 1e-9;

/// The exact offset point at u.
fn offset_point<T, C>(curve: &C, distance: T, u: T) -> Result<Point2<T>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    let (p, d) = curve.point_and_derivative(u)?;
    let speed = d.norm();
    if re(speed) <= 0.0 {
        return Err(Error::ZeroLength {
            what: "tangent of the curve to offset",
        });
    }
    Ok(p + Vector2::new(-d.y, d.x) * (distance / speed))
}

/// Whether two vectors differ by more than [`JUMP`] of the larger.
fn jumps(x: &Vector2<f64>, y: &Vector2<f64>) -> bool {
    (x - y).norm() > JUMP * x.norm().max(y.norm())
}

/// How the offset behaves at an interior breakpoint of the curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Breakpoint {
    /// The multiplicity of the fit's knot there: 3 where the tangent direction of C or
    /// O′ = C′·(1 − dκ) jumps, 2 where only O″ can (C‴ jumps), 1 otherwise.
    multiplicity: usize,
    /// Whether the tangent direction of C jumps (or vanishes) there: the exact offset has a
    /// gap, which only a fit across the breakpoint can bridge.
    corner: bool,
}

/// The breakpoint `u` (the piece on its left starting at `before`), its two sides compared
/// just before and at it.
fn breakpoint<T, C>(curve: &C, distance: f64, before: T, u: T) -> Result<Breakpoint>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    let left_u = u - (u - before) * cst::<T>(LEFT_LIMIT);
    let mut sides = [[Vector2::<f64>::zeros(); 4]; 2];
    for (side, at) in sides.iter_mut().zip([left_u, u]) {
        let mut d = [nalgebra::SVector::<T, 2>::zeros(); 4];
        curve.derivatives_into(at, &mut d)?;
        for (v, w) in side.iter_mut().zip(&d) {
            *v = Vector2::new(re(w.x), re(w.y));
        }
    }
    let ([_, l1, l2, l3], [_, r1, r2, r3]) = (sides[0], sides[1]);
    let (nl, nr) = (l1.norm(), r1.norm());
    let at = |multiplicity, corner| Breakpoint {
        multiplicity,
        corner,
    };
    if nl <= 0.0 || nr <= 0.0 || jumps(&(l1 / nl), &(r1 / nr)) {
        return Ok(at(3, true));
    }
    // O′ = C′·(1 − dκ), κ = (x′y″ − y′x″)/|C′|³.
    let o1 = |c1: &Vector2<f64>, c2: &Vector2<f64>| {
        let kappa = (c1.x * c2.y - c1.y * c2.x) / c1.norm().powi(3);
        c1 * (1.0 - distance * kappa)
    };
    if jumps(&o1(&l1, &l2), &o1(&r1, &r2)) {
        return Ok(at(3, false));
    }
    if jumps(&l2, &r2) || jumps(&l3, &r3) {
        return Ok(at(2, false));
    }
    Ok(at(1, false))
}

/// The offset of the planar `curve` at signed `distance` (length units; positive to the left
/// of the direction of travel), approximated by a cubic B-spline within `tolerance`
/// (length units, > 0) where the sampling allows, under the default budget.
///
/// Errors: [`Error::NonFinite`] for a non-finite distance or tolerance,
/// [`Error::NonPositiveTolerance`], [`Error::ZeroLength`] where the curve has no tangent, and
/// the fitting errors.
pub fn offset<T, C>(curve: &C, distance: T, tolerance: f64) -> Result<OffsetCurve<T>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    offset_with(curve, distance, tolerance, &Budget::default())
}

/// [`offset`] under `budget` (one unit per offset point evaluated and per data point of every
/// fitting pass): fails with [`Error::BudgetExhausted`] or [`Error::Cancelled`], operation
/// "offset".
pub fn offset_with<T, C>(
    curve: &C,
    distance: T,
    tolerance: f64,
    budget: &Budget,
) -> Result<OffsetCurve<T>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    if !re(distance).is_finite() {
        return Err(Error::NonFinite {
            what: "offset distance",
            index: 0,
            value: re(distance),
        });
    }
    if !tolerance.is_finite() {
        return Err(Error::NonFinite {
            what: "offset tolerance",
            index: 0,
            value: tolerance,
        });
    }
    if tolerance <= 0.0 {
        return Err(Error::NonPositiveTolerance { value: tolerance });
    }
    let (a, b) = curve.domain();
    let mut breaks: Vec<T> = vec![a];
    for u in curve.breakpoints() {
        if u > a && u < b && breaks.last().is_some_and(|&l| u > l) {
            breaks.push(u);
        }
    }
    breaks.push(b);
    let mut meter = budget.meter("offset", default_limit(breaks.len()));
    meter.charge(0)?;
    let mut inner = Vec::with_capacity(breaks.len() - 2);
    for k in 1..breaks.len() - 1 {
        meter.charge(8)?;
        inner.push(breakpoint(curve, re(distance), breaks[k - 1], breaks[k])?);
    }
    let multiplicities: Vec<usize> = inner.iter().map(|p| p.multiplicity).collect();
    let cuts = chunk_cuts(&inner);
    // The exact offset and as many of its derivatives as the knot's multiplicity leaves
    // continuous, at every cut: both chunks meeting there are held to the same values.
    let mut joints = Vec::with_capacity(cuts.len());
    for &k in &cuts {
        meter.charge(8)?;
        joints.push(jet::offset_jet(curve, distance, breaks[k])?);
    }
    let normalize = |u: T| (u - a) / (b - a);
    let mut placed = Vec::with_capacity(cuts.len() + 1);
    let mut worst = 0.0_f64;
    let bounds: Vec<usize> = std::iter::once(0)
        .chain(cuts.iter().copied())
        .chain(std::iter::once(breaks.len() - 1))
        .collect();
    for (c, w) in bounds.windows(2).enumerate() {
        let (first, last) = (w[0], w[1]);
        let length = breaks[last] - breaks[first];
        // Held at a cut to the joint's derivatives up to order 3 − multiplicity, in σ.
        let held = |joint: usize| {
            let (point, d1, d2) = joints[joint];
            match multiplicities[cuts[joint] - 1] {
                1 => FitEnd::Clamped {
                    point,
                    first: d1 * length,
                    second: Some(d2 * (length * length)),
                },
                2 => FitEnd::Clamped {
                    point,
                    first: d1 * length,
                    second: None,
                },
                _ => FitEnd::Fixed(point),
            }
        };
        let start = if c == 0 {
            FitEnd::Fixed(offset_point(curve, distance, a)?)
        } else {
            held(c - 1)
        };
        let end = if c == cuts.len() {
            FitEnd::Fixed(offset_point(curve, distance, b)?)
        } else {
            held(c)
        };
        let chunk = Chunk {
            breaks: &breaks[first..=last],
            multiplicities: &multiplicities[first..last - 1],
            ends: FitEnds { start, end },
        };
        let fit = fit_chunk(curve, distance, tolerance, &chunk, &mut meter)?;
        worst = worst.max(fit.max_error);
        placed.push(Placed {
            curve: fit.curve,
            start: normalize(breaks[first]),
            end: normalize(breaks[last]),
            smooth_end: c < cuts.len() && multiplicities[cuts[c] - 1] < 3,
        });
    }
    let curve = if placed.len() == 1 {
        placed.pop().map(|p| p.curve).ok_or(Error::ZeroCount {
            what: "offset chunks",
        })?
    } else {
        join(&placed)?
    };
    Ok(OffsetCurve {
        curve,
        max_error: worst,
    })
}

/// The breakpoints (indices into the curve's breakpoints, whose interior ones `inner` holds
/// from index 1) where the fit is cut into chunks of about [`CHUNK_PIECES`] pieces: never at a
/// corner (the fit bridges the offset's gap there), and never leaving a last chunk of fewer
/// than half as many pieces.
fn chunk_cuts(inner: &[Breakpoint]) -> Vec<usize> {
    let pieces = inner.len() + 1;
    let mut cuts = Vec::new();
    let mut since = 0;
    for (i, p) in inner.iter().enumerate() {
        let k = i + 1;
        since += 1;
        if since >= CHUNK_PIECES && !p.corner && pieces - k >= CHUNK_PIECES / 2 {
            cuts.push(k);
            since = 0;
        }
    }
    cuts
}
