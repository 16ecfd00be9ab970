//! Curve–curve intersection with overlaps: where two curves coincide along a stretch, the
//! stretch is reported as a pair of parameter intervals instead of (too many) points.
//!
//! **Points first.** The point search of [`super::intersect_curves`] runs first, and stops at
//! its first tangential contact. Inside a stretch where the curves coincide every contact is
//! tangential, so when none is (and the search did not run out of candidates) there is no
//! overlap longer than a leaf and the points are the answer; otherwise the overlaps are looked
//! for before any more contacts are refined.
//!
//! **Finding overlaps.** Otherwise curve `a` is sampled (33 parameters per Bézier piece, ends
//! included); a sample is *on* `b` when its distance to `b` is within the tolerance — measured
//! only against the pieces of `b` whose boxes come that close (found in `b`'s box tree), each
//! halved while a half's box comes that close and the half is not flat, with Newton's method on
//! the foot point started in every flat half (so a piece that passes the point twice, a narrow
//! U turn, cannot lead Newton to the wrong arm).
//! Runs of at least two consecutive on-samples, whose midpoints are on `b` too, are overlap
//! candidates; each end of a run is then located by bisection between its last on-sample and
//! the next off-sample (60 halvings, down to rounding). The interval on `b` is given by the
//! feet of the two ends (it runs backwards when the curves are traced in opposite directions).
//! An overlap shorter than the sample spacing is not seen as one: its contacts are searched as
//! points like any other.
//!
//! **Points again.** With overlaps found, the point search runs again with the overlap
//! stretches of `a` taken out (piece pairs inside them are dropped, contacts inside them too),
//! so a coincident stretch is neither a list of points along it nor a drain on the candidate
//! budget; crossings elsewhere are reported as usual.

use nalgebra::Point;

use super::box_tree::point_box_distance;
use super::curve_curve::{
    foot, intersect_excluding, CurveCurveOptions, CurvePairPoint, OnTangent, Prepared,
};
use super::pieces::RationalPiece;
use crate::budget::Meter;
use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};

/// Samples per Bézier piece of `a` when looking for overlaps (the pieces' ends included).
const SAMPLES_PER_PIECE: usize = 32;

/// Halvings that locate an overlap's end.
const BISECTIONS: usize = 60;

/// A piece of `b` is flat enough to start one foot-point Newton iteration in when its control
/// points lie within this fraction of its chord's length from the chord (see `foot_on`).
const FLAT: f64 = 0.1;

/// Halvings of a piece of `b` at most while looking for a foot point.
const FOOT_DEPTH: usize = 16;

/// Halvings at most of a flat half in which Newton missed a foot that its box allows (each
/// halving shrinks the box about fourfold across the chord, so few are ever taken).
const MISS_DEPTH: usize = 48;

/// A stretch along which two curves coincide: `a` on [a.0, a.1] (a.0 < a.1) traces the same
/// points as `b` from b.0 to b.1 (b.0 > b.1 when `b` runs the other way).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Overlap {
    /// The interval on the first curve, increasing.
    pub a: (f64, f64),
    /// The matching parameters on the second curve, at a.0 and at a.1.
    pub b: (f64, f64),
}

/// Intersections of two curves: isolated contacts, and coincident stretches.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveIntersections<const D: usize> {
    /// Contacts outside the overlaps, in increasing parameter on `a`.
    pub points: Vec<CurvePairPoint<D>>,
    /// Coincident stretches, in increasing parameter on `a`.
    pub overlaps: Vec<Overlap>,
}

/// The intersections of `a` and `b` with overlaps reported as intervals (see the module
/// documentation).
///
/// ```
/// use camber_geom::queries::{intersect_curves_with_overlaps, CurveCurveOptions};
/// use camber_geom::Segment;
/// use nalgebra::Point2;
/// // Two collinear segments sharing x ∈ [1, 2].
/// let a = Segment::try_new(Point2::new(0.0, 0.0), Point2::new(2.0, 0.0))?;
/// let b = Segment::try_new(Point2::new(1.0, 0.0), Point2::new(3.0, 0.0))?;
/// let hits = intersect_curves_with_overlaps(&a, &b, &CurveCurveOptions::default())?;
/// assert!(hits.points.is_empty());
/// let o = hits.overlaps[0];
/// assert!((o.a.0 - 0.5).abs() < 1e-9 && (o.a.1 - 1.0).abs() < 1e-9);
/// assert!(o.b.0.abs() < 1e-9 && (o.b.1 - 0.5).abs() < 1e-9);
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// Errors: bad options, [`Error::TooManyCandidates`] (when even outside the overlaps the
/// search needs more leaf pairs than allowed), [`Error::BudgetExhausted`] /
/// [`Error::Cancelled`] ("curve intersection"), and the curves' evaluation errors.
pub fn intersect_curves_with_overlaps<const D: usize, A, B>(
    a: &A,
    b: &B,
    opts: &CurveCurveOptions,
) -> Result<CurveIntersections<D>>
where
    A: ParametricCurve<f64, D> + ?Sized,
    B: ParametricCurve<f64, D> + ?Sized,
{
    let prepared = Prepared::new(a, b, opts)?;
    let mut meter = opts
        .budget
        .meter("curve intersection", prepared.default_limit());
    let first = intersect_excluding(a, b, opts, &prepared, (&[], OnTangent::Stop), &mut meter);
    match first {
        Ok(Some(points)) => {
            return Ok(CurveIntersections {
                points,
                overlaps: Vec::new(),
            })
        }
        Ok(None) | Err(Error::TooManyCandidates { .. }) => {}
        Err(e) => return Err(e),
    }
    let overlaps = find_overlaps(a, b, opts, &prepared, &mut meter)?;
    let excluded: Vec<(f64, f64)> = overlaps.iter().map(|o| o.a).collect();
    let points = intersect_excluding(
        a,
        b,
        opts,
        &prepared,
        (&excluded, OnTangent::Keep),
        &mut meter,
    )?
    .unwrap_or_default();
    Ok(CurveIntersections { points, overlaps })
}

/// The foot of `p` on `b` (parameter and distance) among the pieces of `b` whose boxes come
/// within `near` of it, if one is that close.
///
/// A piece may pass near `p` more than once (a narrow loop or U turn), and a start on the wrong
/// arm lets Newton settle on that arm's local minimum. So each piece is halved (de Casteljau)
/// while a half's box still comes within `near` of `p` and the half is not yet flat (its
/// control points further from its chord than [`FLAT`] of the chord's length): every piece
/// containing the foot is kept, and on a flat half the distance usually has a single minimum.
/// Newton on the foot point starts in every such half, at its chord's point nearest `p`; when
/// it misses (a sharp turn inside a flat half) and the half's box still comes within `near`,
/// the half is halved again ([`MISS_DEPTH`]).
fn foot_on<const D: usize, B>(
    b: &B,
    pieces: &[RationalPiece<D>],
    prepared: &Prepared<D>,
    p: &Point<f64, D>,
    near: f64,
    meter: &mut Meter<'_>,
) -> Result<Option<(f64, f64)>>
where
    B: ParametricCurve<f64, D> + ?Sized,
{
    let mut best: Option<(f64, f64)> = None;
    let mut consider = |found: (f64, f64)| {
        if best.is_none_or(|(_, bd)| found.1 < bd) {
            best = Some(found);
        }
    };
    for j in prepared.tree_b.pieces_near(&p.coords, near, meter)? {
        let piece = &pieces[j];
        let (lo, hi) = (piece.start, piece.end);
        // At a piece's right end the curve reports the next piece's derivative: keep Newton
        // a hair inside (the end itself is looked at as a start).
        let inner = (lo, hi - (hi - lo) * 1e-12);
        let mut stack = vec![(piece.clone(), 0usize)];
        while let Some((half, depth)) = stack.pop() {
            meter.charge(1)?;
            let (blo, bhi) = half.bounding_box();
            if point_box_distance(&p.coords, (&blo, &bhi)) > near {
                continue;
            }
            let (c0, c1, flat) = half.chord_and_flatness();
            let chord = c1 - c0;
            if depth < FOOT_DEPTH && flat > FLAT * chord.norm() && (bhi - blo).norm() > near {
                let (l, r) = half.halves();
                stack.push((r, depth + 1));
                stack.push((l, depth + 1));
                continue;
            }
            let along = if chord.norm_squared() > 0.0 {
                ((p.coords - c0).dot(&chord) / chord.norm_squared()).clamp(0.0, 1.0)
            } else {
                0.5
            };
            // Clamped: the start may round outside the piece.
            let start = (half.start + (half.end - half.start) * along).clamp(lo, hi);
            meter.charge(1)?;
            consider((start, (b.point(start)? - p).norm()));
            let t = foot(b, p, start.min(inner.1), inner, meter)?;
            let gap = (b.point(t)? - p).norm();
            consider((t, gap));
            // Flat is not always enough: where the curve turns sharply inside the half (its
            // speed low there), the chord's nearest point can lie on the far side of a local
            // minimum of the distance, and Newton settles there. A miss whose half still
            // comes within `near` is looked at again in both halves.
            if gap > near && depth < MISS_DEPTH && (bhi - blo).norm() > near {
                let (l, r) = half.halves();
                stack.push((r, depth + 1));
                stack.push((l, depth + 1));
            }
        }
    }
    Ok(best.filter(|(_, d)| *d <= near))
}

/// The overlap stretches of `a` along `b` (see the module documentation).
fn find_overlaps<const D: usize, A, B>(
    a: &A,
    b: &B,
    opts: &CurveCurveOptions,
    prepared: &Prepared<D>,
    meter: &mut Meter<'_>,
) -> Result<Vec<Overlap>>
where
    A: ParametricCurve<f64, D> + ?Sized,
    B: ParametricCurve<f64, D> + ?Sized,
{
    // On `b`: within the tolerance, or within what rounding leaves of the foot point.
    let near = opts.tolerance.max(1e-12 * prepared.size);
    let mut on = |s: f64, meter: &mut Meter<'_>| -> Result<Option<f64>> {
        meter.charge(1)?;
        let p: Point<f64, D> = a.point(s)?;
        Ok(foot_on(b, &prepared.b, prepared, &p, near, meter)?.map(|(t, _)| t))
    };
    let mut params: Vec<f64> = Vec::new();
    for piece in &prepared.a {
        for k in 0..=SAMPLES_PER_PIECE {
            let s = (piece.start + (piece.end - piece.start) * k as f64 / SAMPLES_PER_PIECE as f64)
                .min(piece.end);
            if params.last().is_none_or(|l| s > *l) {
                params.push(s);
            }
        }
    }
    let flags = params
        .iter()
        .map(|s| Ok(on(*s, meter)?.is_some()))
        .collect::<Result<Vec<bool>>>()?;
    let mut overlaps = Vec::new();
    let mut k = 0;
    while k < params.len() {
        if !flags[k] {
            k += 1;
            continue;
        }
        // The run k..=m of on-samples whose midpoints are on `b` too.
        let mut m = k;
        while m + 1 < params.len()
            && flags[m + 1]
            && on(0.5 * (params[m] + params[m + 1]), meter)?.is_some()
        {
            m += 1;
        }
        if m > k {
            let start = match k.checked_sub(1) {
                Some(j) => boundary(&mut on, params[k], params[j], meter)?,
                None => params[k],
            };
            let end = match params.get(m + 1) {
                Some(next) => boundary(&mut on, params[m], *next, meter)?,
                None => params[m],
            };
            let (Some(t0), Some(t1)) = (on(start, meter)?, on(end, meter)?) else {
                k = m + 1;
                continue;
            };
            overlaps.push(Overlap {
                a: (start, end),
                b: (t0, t1),
            });
        }
        k = m + 1;
    }
    Ok(overlaps)
}

/// The parameter between `inside` (on the other curve) and `outside` (off it) where the curve
/// leaves the other one, by bisection.
fn boundary(
    on: &mut impl FnMut(f64, &mut Meter<'_>) -> Result<Option<f64>>,
    inside: f64,
    outside: f64,
    meter: &mut Meter<'_>,
) -> Result<f64> {
    let (mut lo, mut hi) = (inside, outside);
    for _ in 0..BISECTIONS {
        let mid = 0.5 * (lo + hi);
        if on(mid, meter)?.is_some() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(lo)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::queries::intersect_curves;
    use crate::{BSplineCurve2, BezierCurve2, KnotVector, Segment};
    use approx::assert_relative_eq;
    use nalgebra::Point2;

    /// A cubic and its own piece over [0.3, 0.8] (de Casteljau): the overlap is exactly those
    /// intervals, where the plain point search returns a list of points along the stretch.
    #[test]
    fn a_curve_and_its_own_piece_overlap_on_the_piece() {
        let a = BezierCurve2::try_new(vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 2.0),
            Point2::new(3.0, -1.0),
            Point2::new(4.0, 1.0),
        ])
        .unwrap();
        let b = a.segment(0.3, 0.8).unwrap();
        let opts = CurveCurveOptions::default();
        let hits = intersect_curves_with_overlaps(&a, &b, &opts).unwrap();
        assert_eq!(hits.overlaps.len(), 1, "{hits:?}");
        let o = hits.overlaps[0];
        assert_relative_eq!(o.a.0, 0.3, epsilon = 1e-7);
        assert_relative_eq!(o.a.1, 0.8, epsilon = 1e-7);
        assert_relative_eq!(o.b.0, 0.0, epsilon = 1e-7);
        assert_relative_eq!(o.b.1, 1.0, epsilon = 1e-7);
        assert!(hits.points.is_empty(), "{:?}", hits.points);
        // The plain point search names the stretch instead of listing points along it.
        match intersect_curves(&a, &b, &opts) {
            Err(crate::Error::CurvesOverlap { a_start, a_end, .. }) => {
                assert_relative_eq!(a_start, 0.3, epsilon = 1e-7);
                assert_relative_eq!(a_end, 0.8, epsilon = 1e-7);
            }
            other => panic!("{other:?}"),
        }
    }

    /// `c` and its own piece over [u, v] (split twice, so the piece keeps c's parameters):
    /// exactly one overlap, [u, v] on both, and no points.
    fn overlaps_its_own_piece(c: &BSplineCurve2<f64>, u: f64, v: f64) {
        let (_, right) = c.split(u).unwrap();
        let (middle, _) = right.split(v).unwrap();
        let hits =
            intersect_curves_with_overlaps(c, &middle, &CurveCurveOptions::default()).unwrap();
        assert_eq!(hits.overlaps.len(), 1, "{hits:?}");
        let o = hits.overlaps[0];
        assert_relative_eq!(o.a.0, u, epsilon = 1e-7);
        assert_relative_eq!(o.a.1, v, epsilon = 1e-7);
        assert_relative_eq!(o.b.0, u, epsilon = 1e-7);
        assert_relative_eq!(o.b.1, v, epsilon = 1e-7);
        assert!(hits.points.is_empty(), "{:?}", hits.points);
    }

    /// A quadratic B-spline whose second span turns back in a narrow U (its arms a few
    /// hundredths apart), and its own piece over
    /// [0.2443…, 0.7676…]: one overlap, exactly that interval. Starting the foot point from
    /// the nearest of a few samples of `b`'s span let Newton settle on the other arm, which
    /// split the overlap in two with a list of tangential points between.
    #[test]
    fn a_piece_turning_back_narrowly_overlaps_in_one_stretch() {
        let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]).unwrap();
        let c = BSplineCurve2::try_new(
            2,
            knots,
            vec![
                Point2::new(0.0, 0.0),
                Point2::new(2.1772363746533623, 1.7471605410613125),
                Point2::new(1.4730934887179692, -1.763849929763408),
                Point2::new(2.530490599147476, 2.9335213148467405),
            ],
        )
        .unwrap();
        let (u, v) = (0.24431780265216982, 0.7676228814249136);
        overlaps_its_own_piece(&c, u, v);
    }

    /// A parabola arc and its own piece over [0.4258…, 0.5624…] (found by the property test):
    /// every leaf pair's Newton step, started with the parameters a little apart on the
    /// common stretch, was thrown along the nearly singular "both move together" direction
    /// to the piece's end, 1.25 away, so the search saw neither a point nor the overlap.
    #[test]
    fn a_short_piece_of_a_parabola_overlaps_it() {
        let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]).unwrap();
        let c = BSplineCurve2::try_new(
            2,
            knots,
            vec![
                Point2::new(0.4308948247908517, -0.2659049453992564),
                Point2::new(1.682013506907342, -1.8113044766584354),
                Point2::new(3.098810533100835, 0.4663204183668482),
            ],
        )
        .unwrap();
        let (u, v) = (0.4258355702169542, 0.5624853926851763);
        overlaps_its_own_piece(&c, u, v);
    }

    /// A parabola arc that turns sharply near u = 0.2 (its speed small there), and its own
    /// piece from 0.1644 to 0.55, whose de Casteljau polygon is flat by the chord test: from
    /// the chord's nearest point Newton settled on a local minimum of the distance 0.022 away
    /// for samples just past the turn, and the overlap began at 0.2448 after a list of points.
    #[test]
    fn a_piece_through_a_sharp_turn_overlaps_from_its_start() {
        let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]).unwrap();
        let c = BSplineCurve2::try_new(
            2,
            knots,
            vec![
                Point2::new(0.6602463816250876, 0.4528750142463607),
                Point2::new(0.5022982730309712, 1.361672158946099),
                Point2::new(0.894095107386031, -2.8071435439760606),
            ],
        )
        .unwrap();
        let (u, v) = (0.16438917594516006, 0.55);
        overlaps_its_own_piece(&c, u, v);
    }

    /// A polyline that runs along the segment for x ∈ [1, 2], leaves it, and crosses it again at
    /// x = 3.25 (hand-derived): one overlap, one crossing. Reversed, the `b` interval runs
    /// backwards.
    #[test]
    fn an_overlap_and_a_crossing_are_told_apart() {
        let line = Segment::try_new(Point2::new(0.0, 0.0), Point2::new(4.0, 0.0)).unwrap();
        let knots = KnotVector::try_new(vec![0.0, 0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0, 1.0]).unwrap();
        let pts = vec![
            Point2::new(1.0, 0.0),
            Point2::new(2.0, 0.0),
            Point2::new(3.0, 1.0),
            Point2::new(3.5, -1.0),
        ];
        let poly = BSplineCurve2::try_new(1, knots.clone(), pts.clone()).unwrap();
        let opts = CurveCurveOptions::default();
        let hits = intersect_curves_with_overlaps(&line, &poly, &opts).unwrap();
        assert_eq!(hits.overlaps.len(), 1, "{hits:?}");
        let o = hits.overlaps[0];
        assert_relative_eq!(o.a.0, 0.25, epsilon = 1e-9);
        assert_relative_eq!(o.a.1, 0.5, epsilon = 1e-9);
        assert_relative_eq!(o.b.0, 0.0, epsilon = 1e-9);
        assert_relative_eq!(o.b.1, 1.0 / 3.0, epsilon = 1e-9);
        assert_eq!(hits.points.len(), 1, "{:?}", hits.points);
        assert_relative_eq!(hits.points[0].parameter_a, 3.25 / 4.0, epsilon = 1e-9);
        // The polyline traced backwards: the same stretch, b's interval reversed.
        let back: Vec<_> = pts.into_iter().rev().collect();
        let rev = BSplineCurve2::try_new(1, knots, back).unwrap();
        let hits = intersect_curves_with_overlaps(&line, &rev, &opts).unwrap();
        let o = hits.overlaps[0];
        assert_relative_eq!(o.b.0, 1.0, epsilon = 1e-9);
        assert_relative_eq!(o.b.1, 2.0 / 3.0, epsilon = 1e-9);
    }

    /// Without an overlap the answer is the plain point search's.
    #[test]
    fn without_overlaps_the_points_are_the_plain_search() {
        let a = BezierCurve2::try_new(vec![
            Point2::new(-2.0, 3.0),
            Point2::new(0.0, -5.0),
            Point2::new(2.0, 3.0),
        ])
        .unwrap();
        let b = Segment::try_new(Point2::new(-3.0, 0.5), Point2::new(3.0, -0.5)).unwrap();
        let opts = CurveCurveOptions::default();
        let hits = intersect_curves_with_overlaps(&a, &b, &opts).unwrap();
        assert!(hits.overlaps.is_empty());
        assert_eq!(hits.points, intersect_curves(&a, &b, &opts).unwrap());
        assert_eq!(hits.points.len(), 2);
    }
}
