//! Joining the chunks' curves into one cubic B-spline on the whole parameter range.
//!
//! Chunk c covers s ∈ [s_c, s_{c+1}] of the result and was fitted on σ = (s − s_c)/(s_{c+1} −
//! s_c); its knots map back linearly. At a joint both neighbours end on the same point J (the
//! exact offset there), so laid end to end they make a curve with a triple knot at s_j (C0),
//! control points …, L, J, R, … with L the left curve's last-but-one and R the right one's
//! second. Where the chunks were held to the same first derivative at the joint, the curve is
//! C1 there, i.e. J = L + α(R − L) with α = (s_j − s_prev)/(s_next − s_prev) (s_prev and s_next
//! the neighbouring distinct knots), and one copy of the knot is removed exactly by dropping J.
//! That is checked, not assumed: J stays (with the triple knot) where it is off that point by
//! more than rounding.

use nalgebra::Point2;

use crate::bspline::BSplineCurve;
use crate::errors::Result;
use crate::knots::KnotVector;
use crate::scalar::{re, Scalar};

/// Relative size of the rounding allowed when checking that a joint is C1.
const ROUNDING: f64 = 1e-9;

/// One chunk's curve (cubic, clamped, on σ ∈ [0, 1]) and where it lies in the result.
pub(super) struct Placed<T: Scalar> {
    pub curve: BSplineCurve<T, 2>,
    /// The result's parameters at the chunk's start and end.
    pub start: T,
    pub end: T,
    /// Whether the chunk was held to the same first derivative as the next one at its end.
    pub smooth_end: bool,
}

/// The chunks' curves as one cubic B-spline on [0, 1] (see the module header).
pub(super) fn join<T: Scalar>(chunks: &[Placed<T>]) -> Result<BSplineCurve<T, 2>> {
    let count: usize = chunks.iter().map(|c| c.curve.control_points().len()).sum();
    let mut points: Vec<Point2<T>> = Vec::with_capacity(count);
    let mut knots: Vec<T> = Vec::with_capacity(count + 4);
    knots.extend(std::iter::repeat_n(T::zero(), 4));
    for (c, chunk) in chunks.iter().enumerate() {
        let span = chunk.end - chunk.start;
        let own = chunk.curve.knots().as_slice();
        let interior = &own[4..own.len() - 4];
        let cps = chunk.curve.control_points();
        // Points of this chunk not yet written: the first is the previous chunk's last.
        let first = usize::from(c > 0);
        points.extend_from_slice(&cps[first..]);
        knots.extend(interior.iter().map(|&k| chunk.start + span * k));
        let Some(next) = chunks.get(c + 1) else {
            break;
        };
        knots.extend(std::iter::repeat_n(chunk.end, 3));
        if chunk.smooth_end && removable(chunk, next, &knots) {
            // Drop J (the last point written) and one copy of the knot; the next chunk's
            // first point (J again) is skipped as usual, so R follows L.
            points.pop();
            knots.pop();
        }
    }
    knots.extend(std::iter::repeat_n(T::one(), 4));
    BSplineCurve::try_new(3, KnotVector::try_new(knots)?, points)
}

/// Whether the joint at the end of `left` is C1 up to rounding (`knots` holds the result's
/// knots up to and including the joint's three copies).
fn removable<T: Scalar>(left: &Placed<T>, right: &Placed<T>, knots: &[T]) -> bool {
    let (lc, rc) = (left.curve.control_points(), right.curve.control_points());
    if lc.len() < 2 || rc.len() < 2 {
        return false;
    }
    let (l, j, r) = (lc[lc.len() - 2], lc[lc.len() - 1], rc[1]);
    let s = left.end;
    let before = knots
        .iter()
        .rev()
        .copied()
        .find(|&k| k < s)
        .unwrap_or(T::zero());
    let own = right.curve.knots().as_slice();
    let after = own[4..]
        .iter()
        .map(|&k| right.start + (right.end - right.start) * k)
        .find(|&k| k > s)
        .unwrap_or(T::one());
    let alpha = (s - before) / (after - before);
    let on_segment = l + (r - l) * alpha;
    let scale = 1.0 + re(l.coords.norm()).max(re(r.coords.norm()));
    re((on_segment - j).norm()) <= ROUNDING * scale
}
