//! Knot removal within a tolerance (The NURBS Book A5.8), exact when the curve allows, with a
//! guaranteed bound on how far the curve moved.
//!
//! Removing an interior knot u once is the inverse of inserting it: the p − s + 1 control
//! points around u (s its multiplicity) are recomputed from both sides by inverting the
//! insertion's affine steps, P_i = (Q_i − (1 − α_i) P_{i−1}) / α_i from the left and
//! P_j = (Q_j − α_j P_{j+1}) / (1 − α_j) from the right. Where the two sweeps meet they must
//! agree: their distance measures what the removal would change, and the knot is removed only
//! when it is within the tolerance. A knot that was inserted into the curve is removed exactly.
//!
//! **The bound.** Both curves are written on the union of their knot vectors (knot insertion,
//! exact); there they share the basis functions, so C − C′ = Σ N_i (P_i − P′_i) and, since the
//! N_i are non-negative and sum to one, |C(u) − C′(u)| ≤ max_i |P_i − P′_i| for every u. That
//! maximum is the reported bound for B-splines; a removal whose bound exceeds the tolerance is
//! undone. For NURBS curves the test runs on the homogeneous net with the tolerance scaled by
//! w_min / (1 + max |P|), and the reported deviation is measured on 32 samples per span.
//!
//! ```
//! use camber_geom::{BSplineCurve2, KnotVector, ParametricCurve};
//! use nalgebra::Point2;
//! let knots = KnotVector::clamped_uniform(3, 4)?;
//! let pts = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 2.0), Point2::new(3.0, 2.0),
//!     Point2::new(4.0, 0.0)];
//! let curve = BSplineCurve2::try_new(3, knots, pts)?;
//! let busy = curve.insert_knot(0.4, 2)?;
//! let removal = busy.remove_knot(0.4, 2, 1e-12)?;
//! assert_eq!(removal.removed, 2);
//! assert!(removal.error_bound < 1e-12);
//! assert_eq!(removal.curve.control_points().len(), 4);
//! # Ok::<(), camber_geom::Error>(())
//! ```

use crate::bspline::BSplineCurve;
use crate::budget::{default_limit, Budget};
use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::knot_ops::ControlNet;
use crate::knots::KnotVector;
use crate::nurbs::NurbsCurve;
use crate::scalar::{cst, re, Scalar};

/// The movement, relative to the largest coordinate, that still counts as exact: the inverse
/// insertion steps divide by knot ratios and amplify rounding when knots lie close together.
pub(crate) const EXACT_SLACK: f64 = 1e-10;

/// The result of a knot removal: the new curve, how many knots went, and how far the curve
/// moved at most.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotRemoval<C> {
    /// The curve with the knots removed (clamped).
    pub curve: C,
    /// How many knots were removed (0 when none could be within the tolerance).
    pub removed: usize,
    /// An upper bound on max_u |C(u) − C′(u)| (B-splines; for NURBS, the deviation measured on
    /// 32 samples per span), in length units.
    pub error_bound: f64,
}

/// Euclidean distance between two flat points.
fn distance<T: Scalar>(a: &[T], b: &[T]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(&x, &y)| re(x - y) * re(x - y))
        .sum::<f64>()
        .sqrt()
}

/// A5.8: removes the interior knot `u` up to `times` times from the clamped net, while the
/// two sweeps agree within `tolerance`; returns the net and how many were removed.
pub(crate) fn remove_knot_net<T: Scalar>(
    net: &ControlNet<T>,
    u: T,
    times: usize,
    tolerance: f64,
) -> Result<(ControlNet<T>, usize)> {
    net.check()?;
    let net = net.clamped();
    let (p, dim) = (net.degree, net.dim);
    let (a, b) = net.domain();
    let s = net.knots.multiplicity(u);
    if s == 0 || u <= a || u >= b {
        return Err(Error::KnotNotFound { value: re(u) });
    }
    let knots = net.knots.as_slice();
    // r: the last index of u in the knot vector.
    let r = knots.partition_point(|&k| k <= u) - 1;
    let window = Window {
        knots,
        points: &net.coords,
        dim,
        degree: p,
    };
    let (new_knots, pw, removed) = window.remove(u, r, s, times.min(s), tolerance);
    if removed == 0 {
        return Ok((net, 0));
    }
    let out = ControlNet::try_new(p, KnotVector::new_unchecked(new_knots), dim, pw)?;
    Ok((out, removed))
}

/// A run of a net's knots and control points: point i (`dim` coordinates from `points`)
/// has its support on knots[i] … knots[i + p + 1], so a window of points [w₀, w₁] of a net
/// comes with the knots [w₀, w₁ + p + 1]. Knot removal near a knot reads and changes only the
/// points around it, so it can run on a window holding them (A5.8 is local).
struct Window<'a, T> {
    knots: &'a [T],
    points: &'a [T],
    dim: usize,
    degree: usize,
}

impl<T: Scalar> Window<'_, T> {
    /// A5.8 on the window: removes u (the knot at index `r`, its last copy, of multiplicity
    /// `s`) up to `num` times while the two sweeps agree within `tolerance`. Returns the
    /// window's new knots and points and how many were removed (the result's point i keeps
    /// the window's first knot as its origin).
    fn remove(
        &self,
        u: T,
        r: usize,
        s: usize,
        num: usize,
        tolerance: f64,
    ) -> (Vec<T>, Vec<T>, usize) {
        let (p, dim, knots) = (self.degree, self.dim, self.knots);
        let n = self.points.len() / dim - 1;
        let m = knots.len() - 1;
        let ord = p + 1;
        let mut pw = self.points.to_vec();
        let point = |v: &[T], i: usize| v[i * dim..(i + 1) * dim].to_vec();
        let (mut first, mut last) = (r as isize - p as isize, r as isize - s as isize);
        let mut temp = vec![T::zero(); (2 * p + 3) * dim];
        let mut removed = 0usize;
        for t in 0..num {
            let ti = t as isize;
            let off = first - 1;
            if off < 0 || last + 1 > n as isize {
                break;
            }
            let put = |temp: &mut Vec<T>, at: isize, v: &[T]| {
                let at = at as usize;
                temp[at * dim..(at + 1) * dim].copy_from_slice(v);
            };
            put(&mut temp, 0, &point(&pw, off as usize));
            put(&mut temp, last + 1 - off, &point(&pw, (last + 1) as usize));
            let (mut i, mut j) = (first, last);
            let (mut ii, mut jj) = (1isize, last - off);
            while j - i > ti {
                let (iu, ju) = (i as usize, j as usize);
                let alfi = (u - knots[iu]) / (knots[iu + ord + t] - knots[iu]);
                let alfj = (u - knots[ju - t]) / (knots[ju + ord] - knots[ju - t]);
                for c in 0..dim {
                    let prev = temp[(ii as usize - 1) * dim + c];
                    temp[ii as usize * dim + c] =
                        (pw[iu * dim + c] - (T::one() - alfi) * prev) / alfi;
                    let next = temp[(jj as usize + 1) * dim + c];
                    temp[jj as usize * dim + c] =
                        (pw[ju * dim + c] - alfj * next) / (T::one() - alfj);
                }
                i += 1;
                ii += 1;
                j -= 1;
                jj -= 1;
            }
            let gap = if j - i < ti {
                let x = &temp[(ii as usize - 1) * dim..ii as usize * dim];
                let y = &temp[(jj as usize + 1) * dim..(jj as usize + 2) * dim];
                distance(x, y)
            } else {
                let iu = i as usize;
                let alfi = (u - knots[iu]) / (knots[iu + ord + t] - knots[iu]);
                let blend: Vec<T> = (0..dim)
                    .map(|c| {
                        alfi * temp[(ii + ti + 1) as usize * dim + c]
                            + (T::one() - alfi) * temp[(ii as usize - 1) * dim + c]
                    })
                    .collect();
                distance(&point(&pw, iu), &blend)
            };
            // A NaN gap (degenerate knots) counts as too far.
            if gap.is_nan() || gap > tolerance {
                break;
            }
            let (mut i, mut j) = (first, last);
            while j - i > ti {
                let (iu, ju) = (i as usize, j as usize);
                let from_i = ((i - off) as usize) * dim;
                let from_j = ((j - off) as usize) * dim;
                pw[iu * dim..(iu + 1) * dim].copy_from_slice(&temp[from_i..from_i + dim]);
                pw[ju * dim..(ju + 1) * dim].copy_from_slice(&temp[from_j..from_j + dim]);
                i += 1;
                j -= 1;
            }
            first -= 1;
            last += 1;
            removed += 1;
        }
        if removed == 0 {
            return (knots.to_vec(), pw, 0);
        }
        let t = removed;
        let mut new_knots = knots.to_vec();
        new_knots[r + 1 - t..=m - t].copy_from_slice(&knots[r + 1..=m]);
        new_knots.truncate(m + 1 - t);
        let fout = (2 * r - s - p) / 2;
        let (mut i, mut j) = (fout, fout);
        for k in 1..t {
            if k % 2 == 1 {
                i += 1;
            } else {
                j -= 1;
            }
        }
        for k in i + 1..=n {
            let from = pw[k * dim..(k + 1) * dim].to_vec();
            pw[j * dim..(j + 1) * dim].copy_from_slice(&from);
            j += 1;
        }
        pw.truncate((n + 1 - t) * dim);
        (new_knots, pw, removed)
    }
}

/// max_i |P_i − P′_i| after writing both nets (same degree, dimension and domain) on the union
/// of their knot vectors: a bound on the distance between the two curves at every parameter.
/// Infinite when the nets cannot be compared.
pub(crate) fn deviation_bound<T: Scalar>(a: &ControlNet<T>, b: &ControlNet<T>) -> f64 {
    let (a, b) = (a.clamped(), b.clamped());
    if a.degree != b.degree || a.dim != b.dim || a.domain() != b.domain() {
        return f64::INFINITY;
    }
    let missing = |from: &ControlNet<T>, other: &ControlNet<T>| -> Vec<T> {
        let (lo, hi) = from.domain();
        let mut out = Vec::new();
        let mut last: Option<T> = None;
        for &k in other.knots.as_slice() {
            if k <= lo || k >= hi || last.is_some_and(|l| l >= k) {
                continue;
            }
            last = Some(k);
            let need = other.knots.multiplicity(k);
            let have = from.knots.multiplicity(k);
            out.extend(std::iter::repeat_n(k, need.saturating_sub(have)));
        }
        out
    };
    let (add_a, add_b) = (missing(&a, &b), missing(&b, &a));
    let (Ok(ra), Ok(rb)) = (a.refine(&add_a), b.refine(&add_b)) else {
        return f64::INFINITY;
    };
    if ra.coords.len() != rb.coords.len() {
        return f64::INFINITY;
    }
    ra.coords
        .chunks_exact(ra.dim)
        .zip(rb.coords.chunks_exact(rb.dim))
        .map(|(x, y)| distance(x, y))
        .fold(0.0, f64::max)
}

/// Checks that a tolerance is finite and not negative (zero asks for exact removal only).
fn check_tolerance(tolerance: f64) -> Result<()> {
    if !tolerance.is_finite() {
        return Err(Error::NonFinite {
            what: "knot removal tolerance",
            index: 0,
            value: tolerance,
        });
    }
    if tolerance < 0.0 {
        return Err(Error::NonPositiveTolerance { value: tolerance });
    }
    Ok(())
}

/// The largest |C(u) − C′(u)| over 32 samples per span of `a`.
pub(crate) fn sampled_deviation<T, const D: usize, A, B>(a: &A, b: &B) -> Result<f64>
where
    T: Scalar,
    A: ParametricCurve<T, D> + ?Sized,
    B: ParametricCurve<T, D> + ?Sized,
{
    let mut worst = 0.0_f64;
    for w in a.breakpoints().windows(2) {
        for k in 0..=32 {
            let u = w[0] + (w[1] - w[0]) * cst::<T>(f64::from(k) / 32.0);
            worst = worst.max(re((a.point(u)? - b.point(u)?).norm()));
        }
    }
    Ok(worst)
}

/// # Knot removal
impl<T: Scalar, const D: usize> BSplineCurve<T, D> {
    /// Removes the interior knot `u` up to `times` times, as long as the curve moves by at most
    /// `tolerance` (length units, ≥ 0; 0 removes only what is exactly removable, up to
    /// rounding, i.e. 1e-10 of the largest coordinate). The result's `error_bound` bounds the movement everywhere.
    ///
    /// Errors: [`Error::KnotNotFound`] when u is not an interior knot, [`Error::NonFinite`] or
    /// [`Error::NonPositiveTolerance`] for a bad tolerance.
    pub fn remove_knot(&self, u: T, times: usize, tolerance: f64) -> Result<KnotRemoval<Self>> {
        check_tolerance(tolerance)?;
        let net = self.to_control_net();
        // Rounding of the exact case: scale-relative slack.
        let slack = tolerance.max(EXACT_SLACK * (1.0 + scale(&net)));
        let mut budget = times;
        loop {
            let (out, removed) = remove_knot_net(&net, u, budget, slack)?;
            let bound = if removed == 0 {
                0.0
            } else {
                deviation_bound(&net, &out)
            };
            if bound <= slack || removed == 0 {
                return Ok(KnotRemoval {
                    curve: Self::try_from_control_net(out)?,
                    removed,
                    error_bound: bound,
                });
            }
            budget = removed - 1;
        }
    }

    /// Removes every interior knot as often as the tolerance allows, one knot value after the
    /// other, under the default budget; the total movement stays within `tolerance` (see
    /// [`remove_knots_with`](Self::remove_knots_with) for how it is bounded).
    ///
    /// ```
    /// use camber_geom::{BSplineCurve2, KnotVector};
    /// use nalgebra::Point2;
    /// let knots = KnotVector::clamped_uniform(2, 3)?;
    /// let c = BSplineCurve2::try_new(2, knots, vec![Point2::new(0.0, 0.0),
    ///     Point2::new(1.0, 1.0), Point2::new(2.0, 0.0)])?;
    /// let busy = c.refine(&[0.2, 0.5, 0.5, 0.7])?;
    /// let clean = busy.remove_knots(1e-12)?;
    /// assert_eq!(clean.removed, 4);
    /// assert_eq!(clean.curve.control_points().len(), 3);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    ///
    /// Errors: as [`remove_knot`](Self::remove_knot) for the tolerance.
    pub fn remove_knots(&self, tolerance: f64) -> Result<KnotRemoval<Self>> {
        self.remove_knots_with(tolerance, &Budget::default())
    }

    /// [`remove_knots`](Self::remove_knots) under `budget` (one unit per knot value and per
    /// removal attempt): fails with [`Error::BudgetExhausted`] or [`Error::Cancelled`],
    /// operation "knot removal".
    ///
    /// **How the movement is bounded.** Each removal changes only the control points around
    /// the knot (A5.8 is local), so it runs on a window of the net: the window's points are
    /// recomputed, and the change is measured by inserting the knot back into the new window
    /// (exact) and comparing points, max |ΔP| = δ, which bounds |C_before − C_after| on the
    /// window's support. Every span of the original curve keeps the sum of the δ of the
    /// removals whose support covered it (a segment tree with range addition and range
    /// maximum); by the triangle inequality that sum bounds |C_original − C| on the span, and a
    /// removal is taken only while the sums on its support stay within the tolerance. The
    /// reported `error_bound` is the largest sum. Work and memory grow linearly with the number
    /// of knots (times log for the tree).
    pub fn remove_knots_with(&self, tolerance: f64, budget: &Budget) -> Result<KnotRemoval<Self>> {
        check_tolerance(tolerance)?;
        let original = self.clamped().to_control_net();
        let slack = tolerance.max(EXACT_SLACK * (1.0 + scale(&original)));
        let (p, dim) = (original.degree, original.dim);
        let breaks = original.knots.breakpoints(p);
        let mut meter = budget.meter("knot removal", default_limit(breaks.len()));
        let mut tree = MaxAddTree::new(breaks.len().saturating_sub(1));
        let mut knots = Split::new(original.knots.as_slice().to_vec(), 1);
        let mut points = Split::new(original.coords.clone(), dim);
        let mut removed = 0;
        let interior = breaks.len().saturating_sub(1);
        for &u in breaks.get(1..interior).unwrap_or(&[]) {
            meter.charge(1)?;
            // u's last copy r and multiplicity s in the current knots.
            let above = knots.partition_point(|k| k <= u);
            let below = knots.partition_point(|k| k < u);
            let s = above - below;
            if s == 0 {
                continue;
            }
            let r = above - 1;
            let n = points.len() - 1;
            // The window of points A5.8 reads for up to s removals, one more on each side.
            let w0 = (r + 1).saturating_sub(p + s + 2);
            let w1 = (r + 1).min(n);
            let local_knots = knots.tail_from(w0, w1 + p + 2);
            let local_points = points.tail_from(w0, w1 + 1);
            let window = Window {
                knots: &local_knots,
                points: &local_points,
                dim,
                degree: p,
            };
            // The original spans the window's points act on.
            let (lo, hi) = (local_knots[0], local_knots[local_knots.len() - 1]);
            let spans = breaks.partition_point(|&b| b < lo)..breaks.partition_point(|&b| b < hi);
            let already = tree.max(spans.clone());
            let mut times = s;
            while times > 0 {
                meter.charge(1)?;
                let (new_knots, new_points, count) =
                    window.remove(u, r - w0, s, times, slack - already);
                if count == 0 {
                    break;
                }
                let moved = window_change(&window, &new_knots, &new_points, u, s - count);
                if already + moved <= slack {
                    tree.add(spans, moved);
                    knots.replace(w0, w1 + p + 2, &new_knots);
                    points.replace(w0, w1 + 1, &new_points);
                    removed += count;
                    break;
                }
                times = count - 1;
            }
        }
        let net = ControlNet::try_new(
            p,
            KnotVector::new_unchecked(knots.finish()),
            dim,
            points.finish(),
        )?;
        Ok(KnotRemoval {
            curve: Self::try_from_control_net(net)?,
            removed,
            error_bound: tree.max(0..breaks.len().saturating_sub(1)),
        })
    }
}

/// max |ΔP| between a window before a removal and after it with the knot u inserted back
/// (from multiplicity `s_after`): exact insertion writes the new curve on the old knots, so
/// this bounds how far the curve moved on the window's support.
fn window_change<T: Scalar>(
    before: &Window<'_, T>,
    new_knots: &[T],
    new_points: &[T],
    u: T,
    s_after: usize,
) -> f64 {
    let removed = before.knots.len() - new_knots.len();
    let net = ControlNet {
        degree: before.degree,
        knots: KnotVector::new_unchecked(new_knots.to_vec()),
        dim: before.dim,
        coords: new_points.to_vec(),
    };
    let back = net.insert_unchecked(u, removed, s_after);
    if back.coords.len() != before.points.len() {
        return f64::INFINITY;
    }
    back.coords
        .chunks_exact(before.dim)
        .zip(before.points.chunks_exact(before.dim))
        .map(|(x, y)| distance(x, y))
        .fold(
            0.0,
            |m, d| if d.is_nan() { f64::INFINITY } else { m.max(d) },
        )
}

/// A sequence being rewritten from left to right: the finished part (`left`) followed by the
/// untouched rest of the original (`right[next..]`), in items of `stride` values. Rewriting
/// near the boundary moves items across it once, so a left-to-right pass of local rewrites
/// costs time linear in the length instead of a shift of the whole tail per rewrite.
struct Split<T> {
    left: Vec<T>,
    right: Vec<T>,
    next: usize,
    stride: usize,
}

impl<T: Copy + PartialOrd> Split<T> {
    fn new(values: Vec<T>, stride: usize) -> Self {
        Self {
            left: Vec::with_capacity(values.len()),
            right: values,
            next: 0,
            stride,
        }
    }

    /// The number of items.
    fn len(&self) -> usize {
        (self.left.len() + self.right.len() - self.next) / self.stride
    }

    /// Moves items across the boundary until the left part holds `count` of them (or all).
    fn advance_to(&mut self, count: usize) {
        let want = (count * self.stride).min(self.left.len() + self.right.len() - self.next);
        if self.left.len() < want {
            let take = want - self.left.len();
            self.left
                .extend_from_slice(&self.right[self.next..self.next + take]);
            self.next += take;
        }
    }

    /// Items `from .. to` (clipped to the length), after moving them into the left part.
    fn tail_from(&mut self, from: usize, to: usize) -> Vec<T> {
        self.advance_to(to);
        let end = self.left.len().min(to * self.stride);
        self.left[from * self.stride..end].to_vec()
    }

    /// Replaces items `from .. to` (already in the left part, as [`tail_from`](Self::tail_from)
    /// left them; `to` clipped to the length) by `values`.
    fn replace(&mut self, from: usize, to: usize, values: &[T]) {
        let end = self.left.len().min(to * self.stride);
        self.left
            .splice(from * self.stride..end, values.iter().copied());
    }

    /// The index of the first item (stride 1) for which `pred` is false, the sequence being
    /// partitioned by it (sorted knots).
    fn partition_point(&self, pred: impl Fn(T) -> bool) -> usize {
        let in_left = self.left.partition_point(|&k| pred(k));
        if in_left < self.left.len() {
            in_left
        } else {
            in_left + self.right[self.next..].partition_point(|&k| pred(k))
        }
    }

    /// The whole rewritten sequence.
    fn finish(mut self) -> Vec<T> {
        self.left.extend_from_slice(&self.right[self.next..]);
        self.left
    }
}

/// Range addition and range maximum over non-negative values (a lazy segment tree).
struct MaxAddTree {
    size: usize,
    max: Vec<f64>,
    pending: Vec<f64>,
}

impl MaxAddTree {
    fn new(size: usize) -> Self {
        let cap = 4 * size.max(1);
        Self {
            size,
            max: vec![0.0; cap],
            pending: vec![0.0; cap],
        }
    }

    /// Adds `value` to every entry of `range`.
    fn add(&mut self, range: std::ops::Range<usize>, value: f64) {
        if range.start < range.end && self.size > 0 {
            self.add_at(1, 0, self.size, &range, value);
        }
    }

    fn add_at(
        &mut self,
        node: usize,
        lo: usize,
        hi: usize,
        range: &std::ops::Range<usize>,
        v: f64,
    ) {
        if range.end <= lo || hi <= range.start {
            return;
        }
        if range.start <= lo && hi <= range.end {
            self.max[node] += v;
            self.pending[node] += v;
            return;
        }
        let mid = (lo + hi) / 2;
        self.add_at(2 * node, lo, mid, range, v);
        self.add_at(2 * node + 1, mid, hi, range, v);
        self.max[node] = self.pending[node] + self.max[2 * node].max(self.max[2 * node + 1]);
    }

    /// The largest entry of `range` (0 for an empty range).
    fn max(&self, range: std::ops::Range<usize>) -> f64 {
        if range.start < range.end && self.size > 0 {
            self.max_at(1, 0, self.size, &range)
        } else {
            0.0
        }
    }

    fn max_at(&self, node: usize, lo: usize, hi: usize, range: &std::ops::Range<usize>) -> f64 {
        if range.end <= lo || hi <= range.start {
            return 0.0;
        }
        if range.start <= lo && hi <= range.end {
            return self.max[node];
        }
        let mid = (lo + hi) / 2;
        self.pending[node]
            + self
                .max_at(2 * node, lo, mid, range)
                .max(self.max_at(2 * node + 1, mid, hi, range))
    }
}

/// The largest coordinate magnitude of a net (for rounding slack).
fn scale<T: Scalar>(net: &ControlNet<T>) -> f64 {
    net.coords.iter().map(|&c| re(c).abs()).fold(0.0, f64::max)
}

/// # Knot removal
impl<T: Scalar, const D: usize> NurbsCurve<T, D> {
    /// Removes the interior knot `u` up to `times` times within `tolerance` (length units),
    /// testing the homogeneous net with the tolerance scaled by w_min / (1 + max |P|); the
    /// `error_bound` is the deviation measured on 32 samples per span.
    ///
    /// Errors: as [`BSplineCurve::remove_knot`], and [`Error::NonPositiveWeight`] if the new
    /// weights are not positive (then nothing is removed).
    pub fn remove_knot(&self, u: T, times: usize, tolerance: f64) -> Result<KnotRemoval<Self>> {
        check_tolerance(tolerance)?;
        let net = self.to_homogeneous();
        let w_min = self
            .weights()
            .iter()
            .map(|&w| re(w))
            .fold(f64::INFINITY, f64::min);
        let p_max = self
            .control_points()
            .iter()
            .map(|p| re(p.coords.norm()))
            .fold(0.0, f64::max);
        let scaled = tolerance * w_min / (1.0 + p_max);
        let slack = scaled.max(EXACT_SLACK * (1.0 + scale(&net)));
        let mut budget = times;
        loop {
            let (out, removed) = remove_knot_net(&net, u, budget, slack)?;
            if removed == 0 {
                return Ok(KnotRemoval {
                    curve: self.clamped(),
                    removed,
                    error_bound: 0.0,
                });
            }
            let curve = Self::try_from_homogeneous(out)?;
            let measured = sampled_deviation(self, &curve)?;
            if measured <= tolerance.max(1e-12 * (1.0 + p_max)) {
                return Ok(KnotRemoval {
                    curve,
                    removed,
                    error_bound: measured,
                });
            }
            budget = removed - 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_linear_knot_goes_when_the_points_are_collinear() {
        // Degree 1 through (0,0), (1,1), (2,2) with a knot at 1/2: the middle point lies on
        // the chord, so the knot goes exactly; with (1, 1.5) it moves the curve by 0.5 at most.
        let knots = KnotVector::try_new(vec![0.0, 0.0, 0.5, 1.0, 1.0]).unwrap();
        let straight =
            ControlNet::try_new(1, knots.clone(), 2, vec![0., 0., 1., 1., 2., 2.]).unwrap();
        let (out, removed) = remove_knot_net(&straight, 0.5, 1, 1e-12).unwrap();
        assert_eq!(removed, 1);
        assert_eq!(out.coords, vec![0., 0., 2., 2.]);
        let bent = ControlNet::try_new(1, knots, 2, vec![0., 0., 1., 1.5, 2., 2.]).unwrap();
        let (_, none) = remove_knot_net(&bent, 0.5, 1, 0.4).unwrap();
        assert_eq!(none, 0);
        let (moved, one) = remove_knot_net(&bent, 0.5, 1, 0.6).unwrap();
        assert_eq!(one, 1);
        assert!((deviation_bound(&bent, &moved) - 0.5).abs() < 1e-15);
    }
}
