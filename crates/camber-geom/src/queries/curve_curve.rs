//! Intersections and minimum distance between two curves of any kinds (Bézier, B-spline,
//! NURBS, Hermite, segment, circle, in any pairing), each result with both parameters.
//!
//! **Search.** Both curves are cut into rational Bézier pieces ([`BezierPieces`]), and each
//! set of pieces gets a bounding-box hierarchy (`box_tree`): descending both together finds the
//! pairs of pieces whose boxes (grown by the tolerance) come together without looking at the
//! others, so the search grows like n log n rather than n_a·n_b. Within such a pair, the piece
//! with the larger box is halved by de Casteljau's algorithm and the halves are paired again,
//! until both boxes are below a leaf size (10⁻³ of the curves' extent). Each surviving leaf
//! pair seeds a Newton iteration.
//!
//! **Refinement.** From the seed (s, t), Newton's method minimises f = ½|A(s) − B(t)|² with the
//! exact Hessian: with F = A − B, f_s = F·A′, f_t = −F·B′,
//! f_ss = |A′|² + F·A″, f_tt = |B′|² − F·B″, f_st = −A′·B′, parameters kept in their domains
//! and a Levenberg–Marquardt shift when the Hessian is not positive definite. At a transversal
//! crossing this is Newton on F = 0 (quadratic convergence); at a tangential contact F·A″ and
//! F·B″ vanish with F and the iteration still converges to the contact (linearly). A result is
//! an intersection when |F| ≤ the tolerance; results closer than 10⁻⁶ of the extent merge.
//! A contact is *tangential* when the sine of the angle between A′ and B′ is below 10⁻⁶. Near
//! a touch the gap grows only quadratically, |F| ≈ ½Δκ·δ², so the minimisation locates a touch
//! to about √(2·tolerance/Δκ) along the curves (Δκ the difference of the curvatures); in the
//! plane a second Newton iteration on "parallel tangents and foot point" then pins it down to
//! rounding whenever the curvatures differ.
//!
//! **Distance.** Branch and bound over pairs of tree nodes, then of pieces: the distance
//! between two boxes bounds the pieces' distance from below, piece end points (on the curves)
//! from above; pairs that cannot beat the best value are dropped, leaves are refined by the same
//! Newton iteration, and both curves' end points are projected onto the other curve.
//!
//! **Work.** Both searches run under the [`Budget`] of their options (operations "curve
//! intersection" and "curve distance"): one unit per node or piece pair looked at and per
//! Newton step.

use std::cmp::Ordering;
use std::collections::{BinaryHeap, HashMap};

use nalgebra::{Point, SVector};

use super::box_tree::{box_distance, near_pairs, BoxTree};
use super::closest_point;
use super::pieces::{segment_segment_distance, BezierPieces, RationalPiece};
use crate::budget::{default_limit, Budget, Meter};
use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};

/// Settings of the curve–curve searches.
///
/// ```
/// use camber_geom::queries::CurveCurveOptions;
/// let opts = CurveCurveOptions::default().with_tolerance(1e-8);
/// assert!((opts.tolerance - 1e-8).abs() < 1e-20);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CurveCurveOptions {
    /// Two points closer than this (length units) coincide: it accepts intersections and grows
    /// the boxes (default 1e-9).
    pub tolerance: f64,
    /// The most leaf pairs a search may refine before it gives up with
    /// [`Error::TooManyCandidates`] (intersections) or returns its best so far (distance)
    /// (default 20 000).
    pub max_candidates: usize,
    /// The work budget and stop flag of the search (default: the scale-aware default limit,
    /// no flag).
    pub budget: Budget,
}

impl Default for CurveCurveOptions {
    fn default() -> Self {
        Self {
            tolerance: 1e-9,
            max_candidates: 20_000,
            budget: Budget::default(),
        }
    }
}

impl CurveCurveOptions {
    /// Sets [`tolerance`](Self::tolerance).
    pub fn with_tolerance(mut self, tolerance: f64) -> Self {
        self.tolerance = tolerance;
        self
    }

    /// Sets [`max_candidates`](Self::max_candidates).
    pub fn with_max_candidates(mut self, max: usize) -> Self {
        self.max_candidates = max;
        self
    }

    /// Sets [`budget`](Self::budget).
    pub fn with_budget(mut self, budget: Budget) -> Self {
        self.budget = budget;
        self
    }

    pub(super) fn check(&self) -> Result<()> {
        if !self.tolerance.is_finite() {
            return Err(Error::NonFinite {
                what: "intersection tolerance",
                index: 0,
                value: self.tolerance,
            });
        }
        if self.tolerance <= 0.0 {
            return Err(Error::NonPositiveTolerance {
                value: self.tolerance,
            });
        }
        if self.max_candidates == 0 {
            return Err(Error::ZeroCount {
                what: "candidate limit",
            });
        }
        Ok(())
    }
}

/// A point where two curves meet, or their closest pair of points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurvePairPoint<const D: usize> {
    /// The parameter on the first curve.
    pub parameter_a: f64,
    /// The parameter on the second curve.
    pub parameter_b: f64,
    /// The point on the first curve.
    pub point_a: Point<f64, D>,
    /// The point on the second curve.
    pub point_b: Point<f64, D>,
    /// |point_a − point_b|.
    pub distance: f64,
    /// Whether the curves are tangent there (sine of the angle between the tangents < 1e-6).
    pub tangential: bool,
}

/// The extent (diagonal of the common box) of a set of pieces.
pub(super) fn extent<const D: usize>(pieces: &[RationalPiece<D>]) -> f64 {
    let mut lo = SVector::<f64, D>::repeat(f64::INFINITY);
    let mut hi = SVector::<f64, D>::repeat(f64::NEG_INFINITY);
    for p in pieces {
        let (a, b) = p.bounding_box();
        lo = lo.inf(&a);
        hi = hi.sup(&b);
    }
    (hi - lo).norm()
}

/// A lower bound on the distance between two pieces: the larger of their boxes' distance and
/// their chords' distance less both flatnesses. Near a closest pair the second is the sharper
/// (its error shrinks with the square of the pieces' length), so few leaf pairs survive it.
fn lower_bound<const D: usize>(x: &RationalPiece<D>, y: &RationalPiece<D>) -> f64 {
    let (bx, by) = (x.bounding_box(), y.bounding_box());
    let by_box = box_distance((&bx.0, &bx.1), (&by.0, &by.1));
    let (xa, xb, fx) = x.chord_and_flatness();
    let (ya, yb, fy) = y.chord_and_flatness();
    let by_chord = segment_segment_distance((&xa, &xb), (&ya, &yb)) - fx - fy;
    by_box.max(by_chord)
}

/// Whether a leaf pair of planar pieces (both boxes within `leaf`) holds at most one
/// crossing, so that one seed finds everything in it: when the lines of their tangents lie in
/// disjoint angle intervals (between two meeting points each curve has a tangent parallel to
/// the chord joining them, so two crossings need a common tangent direction), or when both
/// pieces are below 1/8 of a leaf (crossings closer than that are left to the one seed).
/// Otherwise the pair is halved again.
fn at_most_one_crossing<const D: usize>(
    x: &RationalPiece<D>,
    y: &RationalPiece<D>,
    leaf: f64,
) -> bool {
    let fine = leaf / 8.0;
    if diagonal(&x.bounding_box()) <= fine && diagonal(&y.bounding_box()) <= fine {
        return true;
    }
    let (Some((cx, wx)), Some((cy, wy))) = (x.tangent_lines(), y.tangent_lines()) else {
        return false;
    };
    let mut apart = (cy - cx).rem_euclid(std::f64::consts::PI);
    if apart > std::f64::consts::FRAC_PI_2 {
        apart = std::f64::consts::PI - apart;
    }
    apart > wx + wy + 1e-9
}

fn diagonal<const D: usize>((lo, hi): &(SVector<f64, D>, SVector<f64, D>)) -> f64 {
    (hi - lo).norm()
}

/// The sine of the angle between two tangents (0 when either vanishes).
fn sine_between<const D: usize>(da: &SVector<f64, D>, db: &SVector<f64, D>) -> f64 {
    let (na, nb) = (da.norm(), db.norm());
    if na > 0.0 && nb > 0.0 {
        let cos = da.dot(db) / (na * nb);
        (1.0 - cos * cos).max(0.0).sqrt()
    } else {
        0.0
    }
}

/// Evaluates both curves and the pair's data at (s, t).
fn pair_point<const D: usize, A, B>(a: &A, b: &B, s: f64, t: f64) -> Result<CurvePairPoint<D>>
where
    A: ParametricCurve<f64, D> + ?Sized,
    B: ParametricCurve<f64, D> + ?Sized,
{
    let (pa, da) = a.point_and_derivative(s)?;
    let (pb, db) = b.point_and_derivative(t)?;
    let tangential = sine_between(&da, &db) < 1e-6;
    Ok(CurvePairPoint {
        parameter_a: s,
        parameter_b: t,
        point_a: pa,
        point_b: pb,
        distance: (pa - pb).norm(),
        tangential,
    })
}

/// How much one Newton step of [`refine`] may grow the squared gap |A − B|² before it is
/// refused.
///
/// Not 1: near a touch the Hessian is indefinite off the valley floor and Newton's path to the
/// contact is not monotone; refusing every growth would leave only the slower fallback. A
/// blow-up (a gap of 10⁻⁵ thrown to 1) is what is refused.
const GROWTH: f64 = 4.0;

/// Minimises f = ½|A(s) − B(t)|² from (s, t), inside both domains.
///
/// Each iteration first tries Newton's step with the exact Hessian where that is positive
/// definite: quadratic at crossings and at the closest pair of curves apart. Where it is not,
/// or the step grows the squared gap more than [`GROWTH`]-fold, a Levenberg–Marquardt step on
/// the Gauss–Newton matrix JᵀJ + μI (J = [A′, −B′]) is taken instead, with μ grown tenfold
/// until the gap decreases. The exact Hessian misleads in two places: between two crossings
/// close together it is indefinite, and shifted it aims at the far one; where the curves run
/// along each other it is singular along "both parameters move together" (determinant
/// −(F·A″)² when B = A), so a step can throw both parameters far along the curves.
/// Jᵀ F is the gradient, so a large enough μ always decreases f unless (s, t) is stationary.
/// Stops when the gap is rounding, the parameters no longer move, or no step decreases f.
pub(super) fn refine<const D: usize, A, B>(
    a: &A,
    b: &B,
    (mut s, mut t): (f64, f64),
    meter: &mut Meter<'_>,
) -> Result<(f64, f64)>
where
    A: ParametricCurve<f64, D> + ?Sized,
    B: ParametricCurve<f64, D> + ?Sized,
{
    let ((a0, a1), (b0, b1)) = (a.domain(), b.domain());
    for _ in 0..200 {
        meter.charge(2)?;
        let [pa, da, dda] = a.second_order(s)?;
        let [pb, db, ddb] = b.second_order(t)?;
        let f = pa - pb;
        let value = f.norm_squared();
        // Gaps below this are rounding of the points' coordinates: no step can be judged.
        let floor = (4.0 * f64::EPSILON * pa.amax().max(pb.amax())).powi(2);
        if value <= floor {
            break;
        }
        let (gs, gt) = (f.dot(&da), -f.dot(&db));
        let (gss, gtt, hst) = (da.norm_squared(), db.norm_squared(), -da.dot(&db));
        let scale = (gss + gtt).max(1e-300);
        // The step for the 2×2 system [[hss, hst], [hst, htt]]·δ = −g, clamped into both
        // domains, with the squared gap it leads to (None when not positive definite).
        let try_step = |hss: f64, htt: f64, meter: &mut Meter<'_>| -> Result<_> {
            let det = hss * htt - hst * hst;
            if !(hss > 0.0 && htt > 0.0 && det > 1e-14 * scale * scale && det.is_finite()) {
                return Ok(None);
            }
            let ds = -(htt * gs - hst * gt) / det;
            let dt = -(hss * gt - hst * gs) / det;
            let (ns, nt) = ((s + ds).clamp(a0, a1), (t + dt).clamp(b0, b1));
            meter.charge(1)?;
            let gap = (a.point(ns)? - b.point(nt)?).norm_squared();
            Ok(Some((ns, nt, gap)))
        };
        let (hss, htt) = (gss + f.dot(&dda), gtt - f.dot(&ddb));
        // Newton only where the exact Hessian is positive definite as it stands.
        let mut step = try_step(hss, htt, meter)?
            .filter(|found| found.2 <= GROWTH * value || found.2 <= floor);
        let mut mu = 1e-12 * scale;
        while step.is_none() && mu <= 1e10 * scale {
            if let Some(found) = try_step(gss + mu, gtt + mu, meter)? {
                if found.2 < value || found.2 <= floor {
                    step = Some(found);
                }
            }
            mu *= 10.0;
        }
        let Some((ns, nt, _)) = step else { break };
        let moved = (ns - s).abs() / (a1 - a0) + (nt - t).abs() / (b1 - b0);
        s = ns;
        t = nt;
        if moved < 1e-16 {
            break;
        }
    }
    Ok((s, t))
}

/// Newton on ½|C(u) − p|² from `u`, inside [lo, hi] (within the curve's domain): the foot of
/// `p` near `u`.
pub(super) fn foot<const D: usize, C>(
    curve: &C,
    p: &Point<f64, D>,
    mut u: f64,
    (lo, hi): (f64, f64),
    meter: &mut Meter<'_>,
) -> Result<f64>
where
    C: ParametricCurve<f64, D> + ?Sized,
{
    for _ in 0..50 {
        meter.charge(1)?;
        let [c, d, dd] = curve.second_order(u)?;
        let w = c - p.coords;
        let g = w.dot(&d);
        let h = d.norm_squared() + w.dot(&dd);
        // Away from the foot the Hessian may be negative: fall back to a Gauss–Newton step.
        let h = if h > 0.0 { h } else { d.norm_squared() };
        if h <= 0.0 || !h.is_finite() {
            break;
        }
        let next = (u - g / h).clamp(lo, hi);
        let moved = (next - u).abs() / (hi - lo);
        u = next;
        if moved < 1e-16 {
            break;
        }
    }
    Ok(u)
}

/// In the plane, a tangential contact solves G = (A′ × B′, (A − B)·B′) = 0 — parallel tangents
/// and B's foot point — whose Jacobian [[A″ × B′, A′ × B″], [A′·B′, (A − B)·B″ − |B′|²]] is
/// regular when the curvatures differ (its determinant is −λ²|B′|⁵(κ_B − κ_A) at the contact,
/// λ = |A′|/|B′|). Newton on G from a converged (s, t) locates the touch to rounding instead of
/// to √tolerance. Returns `None` when it does not converge inside both domains.
fn refine_touch<const D: usize, A, B>(
    a: &A,
    b: &B,
    (mut s, mut t): (f64, f64),
    meter: &mut Meter<'_>,
) -> Result<Option<(f64, f64)>>
where
    A: ParametricCurve<f64, D> + ?Sized,
    B: ParametricCurve<f64, D> + ?Sized,
{
    if D != 2 {
        return Ok(None);
    }
    let ((a0, a1), (b0, b1)) = (a.domain(), b.domain());
    let cross = |x: &SVector<f64, D>, y: &SVector<f64, D>| x[0] * y[1] - x[1] * y[0];
    for _ in 0..30 {
        meter.charge(2)?;
        let [pa, da, dda] = a.second_order(s)?;
        let [pb, db, ddb] = b.second_order(t)?;
        let f = pa - pb;
        let g = [cross(&da, &db), f.dot(&db)];
        let j = [
            [cross(&dda, &db), cross(&da, &ddb)],
            [da.dot(&db), f.dot(&ddb) - db.norm_squared()],
        ];
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if det == 0.0 || !det.is_finite() {
            return Ok(None);
        }
        let ds = -(j[1][1] * g[0] - j[0][1] * g[1]) / det;
        let dt = -(j[0][0] * g[1] - j[1][0] * g[0]) / det;
        let (ns, nt) = (s + ds, t + dt);
        if ns < a0 || ns > a1 || nt < b0 || nt > b1 || !ns.is_finite() || !nt.is_finite() {
            return Ok(None);
        }
        let moved = (ns - s).abs() / (a1 - a0) + (nt - t).abs() / (b1 - b0);
        s = ns;
        t = nt;
        if moved < 1e-15 {
            return Ok(Some((s, t)));
        }
    }
    Ok(Some((s, t)))
}

/// Every point where `a` and `b` meet (within the tolerance), in order of the first curve's
/// parameter, each with both parameters and whether the contact is tangential.
///
/// ```
/// use camber_geom::queries::{intersect_curves, CurveCurveOptions};
/// use camber_geom::{BezierCurve2, Circle};
/// use nalgebra::Point2;
/// // The parabola y = x² − 1 (x from −2 to 2) meets the unit circle where x⁴ − x² = 0: it
/// // crosses at (±1, 0) and touches at (0, −1) (a double root).
/// let parabola = BezierCurve2::try_new(vec![Point2::new(-2.0, 3.0), Point2::new(0.0, -5.0),
///     Point2::new(2.0, 3.0)])?;
/// let circle = Circle::try_new(Point2::origin(), 1.0)?;
/// let hits = intersect_curves(&parabola, &circle, &CurveCurveOptions::default())?;
/// assert_eq!(hits.len(), 3);
/// assert!((hits[1].point_a - Point2::new(0.0, -1.0)).norm() < 1e-9);
/// assert!(hits[1].tangential);
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// Errors: bad options ([`Error::NonPositiveTolerance`], [`Error::NonFinite`],
/// [`Error::ZeroCount`]), [`Error::CurvesOverlap`] when the curves coincide along a stretch
/// (their meeting points are not isolated:
/// [`intersect_curves_with_overlaps`](super::intersect_curves_with_overlaps) reports the
/// stretches as intervals), [`Error::TooManyCandidates`] when the search needs more leaf pairs
/// than allowed, [`Error::BudgetExhausted`] / [`Error::Cancelled`] ("curve intersection").
pub fn intersect_curves<const D: usize, A, B>(
    a: &A,
    b: &B,
    opts: &CurveCurveOptions,
) -> Result<Vec<CurvePairPoint<D>>>
where
    A: ParametricCurve<f64, D> + ?Sized,
    B: ParametricCurve<f64, D> + ?Sized,
{
    let found = super::intersect_curves_with_overlaps(a, b, opts)?;
    if let Some(o) = found.overlaps.first() {
        return Err(Error::CurvesOverlap {
            a_start: o.a.0,
            a_end: o.a.1,
            b_start: o.b.0,
            b_end: o.b.1,
        });
    }
    Ok(found.points)
}

/// Both curves' pieces and box trees, the common extent, and the meter of one search.
pub(super) struct Prepared<const D: usize> {
    pub a: Vec<RationalPiece<D>>,
    pub b: Vec<RationalPiece<D>>,
    pub tree_a: BoxTree<D>,
    pub tree_b: BoxTree<D>,
    pub size: f64,
}

impl<const D: usize> Prepared<D> {
    pub fn new<A, B>(a: &A, b: &B, opts: &CurveCurveOptions) -> Result<Self>
    where
        A: ParametricCurve<f64, D> + ?Sized,
        B: ParametricCurve<f64, D> + ?Sized,
    {
        opts.check()?;
        let (pa, pb) = (a.bezier_pieces()?, b.bezier_pieces()?);
        let size = extent(&pa).max(extent(&pb)).max(opts.tolerance);
        Ok(Self {
            tree_a: BoxTree::new(&pa),
            tree_b: BoxTree::new(&pb),
            a: pa,
            b: pb,
            size,
        })
    }

    /// The default work limit of a search over these pieces.
    pub fn default_limit(&self) -> u64 {
        default_limit(self.a.len() + self.b.len())
    }
}

/// What the point search does on meeting a tangential contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum OnTangent {
    /// Keep it and go on.
    Keep,
    /// Stop and return `None`: the caller looks for overlaps first (inside a coincident
    /// stretch every contact is tangential, and refining them all would be wasted).
    Stop,
}

/// The points [`intersect_curves`] finds, without the stretches of `a` in `excluded` (sorted,
/// disjoint parameter intervals of `a` already known to overlap `b`): piece pairs whose `a`
/// piece lies inside one are dropped, and so are contacts found inside one. `None` when
/// `on_tangent` is [`OnTangent::Stop`] and a tangential contact was found.
pub(super) fn intersect_excluding<const D: usize, A, B>(
    a: &A,
    b: &B,
    opts: &CurveCurveOptions,
    prepared: &Prepared<D>,
    (excluded, on_tangent): (&[(f64, f64)], OnTangent),
    meter: &mut Meter<'_>,
) -> Result<Option<Vec<CurvePairPoint<D>>>>
where
    A: ParametricCurve<f64, D> + ?Sized,
    B: ParametricCurve<f64, D> + ?Sized,
{
    let inside = |lo: f64, hi: f64| {
        let k = excluded.partition_point(|(_, y)| *y < hi);
        excluded.get(k).is_some_and(|(x, y)| lo >= *x && hi <= *y)
    };
    let size = prepared.size;
    let leaf = 1e-3 * size;
    let grow = opts.tolerance;
    let mut seeds = Vec::new();
    let mut tangent_seen = false;
    near_pairs(
        &prepared.tree_a,
        &prepared.tree_b,
        grow,
        meter,
        |i, j, meter| {
            if tangent_seen {
                return Ok(());
            }
            let mut stack = vec![(prepared.a[i].clone(), prepared.b[j].clone())];
            while let Some((x, y)) = stack.pop() {
                meter.charge(1)?;
                if inside(x.start, x.end) || lower_bound(&x, &y) > grow {
                    continue;
                }
                let (bx, by) = (x.bounding_box(), y.bounding_box());
                let (dx, dy) = (diagonal(&bx), diagonal(&by));
                let seed = (0.5 * (x.start + x.end), 0.5 * (y.start + y.end));
                let is_leaf = dx <= leaf && dy <= leaf;
                let single = is_leaf && (D != 2 || at_most_one_crossing(&x, &y, leaf));
                if is_leaf && !single && on_tangent == OnTangent::Stop {
                    // A leaf pair about to be halved again because its tangents may be
                    // parallel: if it holds a tangential contact the search ends here anyway,
                    // so look now (along a coincident stretch, halving every leaf pair again
                    // would multiply the work before the first one is refined).
                    let (s, t) = refine(a, b, seed, meter)?;
                    let hit = pair_point(a, b, s, t)?;
                    if hit.distance <= opts.tolerance && hit.tangential {
                        tangent_seen = true;
                        return Ok(());
                    }
                }
                if single {
                    seeds.push(seed);
                    if seeds.len() > opts.max_candidates {
                        return Err(Error::TooManyCandidates {
                            what: "leaf pairs",
                            limit: opts.max_candidates,
                        });
                    }
                    continue;
                }
                if dx >= dy {
                    let (l, r) = x.halves();
                    stack.push((l, y.clone()));
                    stack.push((r, y));
                } else {
                    let (l, r) = y.halves();
                    stack.push((x.clone(), l));
                    stack.push((x, r));
                }
            }
            Ok(())
        },
    )?;
    if tangent_seen {
        return Ok(None);
    }
    let mut found = Hits::new(1e-6 * size);
    let rounding = 64.0 * f64::EPSILON * size;
    for seed in seeds {
        let (s, t) = refine(a, b, seed, meter)?;
        let mut hit = pair_point(a, b, s, t)?;
        if hit.distance > opts.tolerance || inside(hit.parameter_a, hit.parameter_a) {
            continue;
        }
        // The minimisation leaves a touch imprecise, so its tangents may still differ by the
        // curvature times √tolerance: try the sharp touch iteration on anything near-parallel.
        let near_parallel = sine_between(&a.derivative(s)?, &b.derivative(t)?) < 1e-3;
        if near_parallel {
            if let Some((s2, t2)) = refine_touch(a, b, (s, t), meter)? {
                let touch = pair_point(a, b, s2, t2)?;
                // Keep the sharper location only if it is still a contact. At a touch both
                // gaps are rounding (the minimisation's error e leaves a gap of κe²/2), so the
                // sharp one may be the larger by a few ulps of the curves' size.
                if touch.distance <= opts.tolerance
                    && touch.distance <= (hit.distance * 10.0).max(rounding)
                {
                    hit = touch;
                }
            }
        }
        if hit.tangential && on_tangent == OnTangent::Stop {
            return Ok(None);
        }
        found.add(hit, |candidate, kept| {
            // The closer of two seeds' answers, and between gaps equal to rounding the one
            // with the more parallel tangents (a touch located sharply).
            let sine = |p: &CurvePairPoint<D>| -> Result<f64> {
                Ok(sine_between(
                    &a.derivative(p.parameter_a)?,
                    &b.derivative(p.parameter_b)?,
                ))
            };
            Ok(if (candidate.distance - kept.distance).abs() <= rounding {
                sine(candidate)? < sine(kept)?
            } else {
                candidate.distance < kept.distance
            })
        })?;
    }
    let mut found = found.into_points();
    found.sort_by(|x, y| x.parameter_a.total_cmp(&y.parameter_a));
    Ok(Some(found))
}

/// Contacts kept distinct: a new one within `merge` of a kept one (on the first curve) is the
/// same contact, and replaces it when better — unless both are transversal crossings more than
/// `merge`/1000 apart (each located to rounding, so they are two crossings). A grid of cells `merge` wide finds the kept ones
/// nearby, so merging k contacts costs O(k).
struct Hits<const D: usize> {
    merge: f64,
    points: Vec<CurvePairPoint<D>>,
    grid: HashMap<[i64; D], Vec<usize>>,
}

impl<const D: usize> Hits<D> {
    fn new(merge: f64) -> Self {
        Self {
            merge: merge.max(f64::MIN_POSITIVE),
            points: Vec::new(),
            grid: HashMap::new(),
        }
    }

    fn cell(&self, p: &Point<f64, D>) -> [i64; D] {
        // Saturating casts: a coordinate far beyond the grid lands in its outermost cell.
        #[allow(clippy::cast_possible_truncation)]
        std::array::from_fn(|i| (p[i] / self.merge).floor() as i64)
    }

    /// Adds `hit`, or lets it replace a kept contact within `merge` when `better(hit, kept)`.
    fn add(
        &mut self,
        hit: CurvePairPoint<D>,
        better: impl Fn(&CurvePairPoint<D>, &CurvePairPoint<D>) -> Result<bool>,
    ) -> Result<()> {
        let home = self.cell(&hit.point_a);
        let mut near = None;
        'cells: for k in 0..3usize.pow(D as u32) {
            let mut key = home;
            let mut code = k;
            for c in key.iter_mut() {
                *c = c.saturating_add(code as i64 % 3 - 1);
                code /= 3;
            }
            if let Some(list) = self.grid.get(&key) {
                for &i in list {
                    let kept = &self.points[i];
                    let apart = (kept.point_a - hit.point_a).norm();
                    // Transversal crossings are located to rounding: two of them further
                    // apart than that are two crossings, however close.
                    let distinct = !kept.tangential && !hit.tangential && apart > 1e-3 * self.merge;
                    if apart <= self.merge && !distinct {
                        near = Some(i);
                        break 'cells;
                    }
                }
            }
        }
        match near {
            Some(i) => {
                if better(&hit, &self.points[i])? {
                    self.points[i] = hit;
                }
            }
            None => {
                self.grid.entry(home).or_default().push(self.points.len());
                self.points.push(hit);
            }
        }
        Ok(())
    }

    fn into_points(self) -> Vec<CurvePairPoint<D>> {
        self.points
    }
}

/// A pair in the distance search, ordered by its lower bound (smallest first): two tree nodes,
/// or two pieces being subdivided.
struct Candidate<const D: usize> {
    lower: f64,
    pair: Pair<D>,
}

enum Pair<const D: usize> {
    Nodes(usize, usize),
    Pieces(RationalPiece<D>, RationalPiece<D>),
}

impl<const D: usize> PartialEq for Candidate<D> {
    fn eq(&self, other: &Self) -> bool {
        self.lower.total_cmp(&other.lower) == Ordering::Equal
    }
}
impl<const D: usize> Eq for Candidate<D> {}
impl<const D: usize> PartialOrd for Candidate<D> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl<const D: usize> Ord for Candidate<D> {
    fn cmp(&self, other: &Self) -> Ordering {
        // BinaryHeap is a max-heap: reverse so the smallest lower bound comes first.
        other.lower.total_cmp(&self.lower)
    }
}

/// The closest pair of points of `a` and `b` (distance 0 where they meet), with both
/// parameters. When the search hits `max_candidates` leaf pairs it returns the best pair found
/// so far (an upper bound on the distance).
///
/// ```
/// use camber_geom::queries::{curve_distance, CurveCurveOptions};
/// use camber_geom::{Circle, Segment};
/// use nalgebra::Point2;
/// // The segment y = 3 from x = −1 to 1 is 2 away from the unit circle, at (0, 3) and (0, 1).
/// let s = Segment::try_new(Point2::new(-1.0, 3.0), Point2::new(1.0, 3.0))?;
/// let c = Circle::try_new(Point2::origin(), 1.0)?;
/// let near = curve_distance(&s, &c, &CurveCurveOptions::default())?;
/// assert!((near.distance - 2.0).abs() < 1e-9);
/// assert!((near.point_b - Point2::new(0.0, 1.0)).norm() < 1e-6);
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// Errors: bad options, [`Error::BudgetExhausted`] / [`Error::Cancelled`] ("curve distance"),
/// and the curves' evaluation errors.
pub fn curve_distance<const D: usize, A, B>(
    a: &A,
    b: &B,
    opts: &CurveCurveOptions,
) -> Result<CurvePairPoint<D>>
where
    A: ParametricCurve<f64, D> + ?Sized,
    B: ParametricCurve<f64, D> + ?Sized,
{
    let prepared = Prepared::new(a, b, opts)?;
    let mut meter = opts
        .budget
        .meter("curve distance", prepared.default_limit());
    let (pa, pb) = (&prepared.a, &prepared.b);
    let (ta, tb) = (&prepared.tree_a, &prepared.tree_b);
    let leaf = 1e-3 * prepared.size;
    let ((a0, a1), (b0, b1)) = (a.domain(), b.domain());
    let mut best = pair_point(a, b, a0, b0)?;
    let consider = |cand: CurvePairPoint<D>, best: &mut CurvePairPoint<D>| {
        if cand.distance < best.distance {
            *best = cand;
        }
    };
    // Curve ends projected onto the other curve.
    for s in [a0, a1] {
        meter.charge(16 * u64::try_from(pb.len()).unwrap_or(u64::MAX))?;
        let p = a.point(s)?;
        let c = closest_point(b, &p)?;
        consider(pair_point(a, b, s, c.parameter)?, &mut best);
    }
    for t in [b0, b1] {
        meter.charge(16 * u64::try_from(pa.len()).unwrap_or(u64::MAX))?;
        let p = b.point(t)?;
        let c = closest_point(a, &p)?;
        consider(pair_point(a, b, c.parameter, t)?, &mut best);
    }
    let mut heap = BinaryHeap::new();
    if !ta.is_empty() && !tb.is_empty() {
        heap.push(Candidate {
            lower: 0.0,
            pair: Pair::Nodes(0, 0),
        });
    }
    let mut leaves = 0;
    while let Some(Candidate { lower, pair }) = heap.pop() {
        if lower >= best.distance - opts.tolerance {
            break;
        }
        meter.charge(1)?;
        let (x, y) = match pair {
            Pair::Nodes(i, j) => {
                let (nx, ny) = (ta.node(i), tb.node(j));
                let children: Vec<(usize, usize)> = match (nx.children, ny.children) {
                    (None, None) => {
                        let (x, y) = (pa[nx.first].clone(), pb[ny.first].clone());
                        let lower = lower_bound(&x, &y);
                        if lower < best.distance - opts.tolerance {
                            heap.push(Candidate {
                                lower,
                                pair: Pair::Pieces(x, y),
                            });
                        }
                        continue;
                    }
                    (Some((l, r)), None) => vec![(l, j), (r, j)],
                    (None, Some((l, r))) => vec![(i, l), (i, r)],
                    (Some((xl, xr)), Some((yl, yr))) => {
                        if nx.diagonal() >= ny.diagonal() {
                            vec![(xl, j), (xr, j)]
                        } else {
                            vec![(i, yl), (i, yr)]
                        }
                    }
                };
                for (ci, cj) in children {
                    let (cx, cy) = (ta.node(ci), tb.node(cj));
                    let lower = box_distance((&cx.lo, &cx.hi), (&cy.lo, &cy.hi));
                    if lower < best.distance - opts.tolerance {
                        heap.push(Candidate {
                            lower,
                            pair: Pair::Nodes(ci, cj),
                        });
                    }
                }
                continue;
            }
            Pair::Pieces(x, y) => (x, y),
        };
        // Piece ends are curve points: an upper bound.
        let (xa, xb) = (x.start, x.end);
        let (ya, yb) = (y.start, y.end);
        for (s, t) in [(xa, ya), (xa, yb), (xb, ya), (xb, yb)] {
            consider(pair_point(a, b, s, t)?, &mut best);
        }
        let (bx, by) = (x.bounding_box(), y.bounding_box());
        let (dx, dy) = (diagonal(&bx), diagonal(&by));
        if dx <= leaf && dy <= leaf {
            leaves += 1;
            let (s, t) = refine(a, b, (0.5 * (xa + xb), 0.5 * (ya + yb)), &mut meter)?;
            consider(pair_point(a, b, s, t)?, &mut best);
            // A closest pair at a piece end (a corner of a composite, a domain end) is not a
            // stationary point of the distance, so the joint Newton iteration may stop short
            // of it: hold each piece end fixed and find its foot on the other curve.
            let (ym, xm) = (0.5 * (ya + yb), 0.5 * (xa + xb));
            for s in [xa, xb] {
                let t = foot(b, &a.point(s)?, ym, (b0, b1), &mut meter)?;
                consider(pair_point(a, b, s, t)?, &mut best);
            }
            for t in [ya, yb] {
                let s = foot(a, &b.point(t)?, xm, (a0, a1), &mut meter)?;
                consider(pair_point(a, b, s, t)?, &mut best);
            }
            if leaves >= opts.max_candidates {
                break;
            }
            continue;
        }
        let children = if dx >= dy {
            let (l, r) = x.halves();
            [(l, y.clone()), (r, y)]
        } else {
            let (l, r) = y.halves();
            [(x.clone(), l), (x, r)]
        };
        for (cx, cy) in children {
            let lower = lower_bound(&cx, &cy);
            if lower < best.distance - opts.tolerance {
                heap.push(Candidate {
                    lower,
                    pair: Pair::Pieces(cx, cy),
                });
            }
        }
    }
    Ok(best)
}
