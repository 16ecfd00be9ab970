//! Distances from data points to a fitted curve: parameter correction by foot points while
//! fitting, and the distance to the whole curve for the reported error.
//!
//! - **Foot points.** For data point Q with parameter u, Newton's method on
//!   f(u) = (C(u) − Q)·C′(u), with f′ = |C′|² + (C − Q)·C″ (|C′|² alone where that is not
//!   positive), moves u to the foot of the perpendicular from Q, kept between the neighbours'
//!   parameters so the order of the data is kept. A step is taken only if it brings the curve
//!   point closer, so |C(u) − Q| only decreases and is always the distance to a point of the
//!   curve: an upper bound of the distance from Q to the curve.
//! - **Distance to the curve.** The reported error is the distance from every data point to
//!   the whole curve. The foot-point distance e bounds it from above, so only the Bézier pieces
//!   of the curve whose control boxes come within e of Q can hold a closer point; on each run of
//!   such neighbouring pieces the toolkit's closest-point search
//!   ([`closest_point_with`](crate::queries::closest_point_with)) finds the nearest point, and
//!   the smallest distance wins.

use nalgebra::{Point, SVector};

use super::power_form::PowerForm;
use crate::bspline::BSplineCurve;
use crate::curve::{check_parameter, ParametricCurve};
use crate::errors::Result;
use crate::queries::{closest_point_with, QueryOptions, RationalPiece};
use crate::scalar::{cst, re, Scalar};

/// Moves every interior parameter (the first and last stay) towards the foot point of its
/// data point on `curve`, `steps` Newton steps at most, each kept between the
/// neighbouring parameters and taken only when it brings the curve closer. Writes
/// |C(ū_k) − Q_k| into `distances` (all points, the ends included) and returns their largest.
///
/// The Newton steps evaluate the curve's [`PowerForm`]; the distance written is that of the
/// curve's own evaluation at the final parameter, so it is the distance to a point of the
/// curve as [`point`](crate::ParametricCurve::point) gives it.
pub(crate) fn correct_parameters<T: Scalar, const D: usize>(
    curve: &BSplineCurve<T, D>,
    points: &[Point<T, D>],
    parameters: &mut [T],
    distances: &mut Vec<f64>,
    steps: usize,
) -> Result<f64> {
    distances.clear();
    let form = PowerForm::new(curve)?;
    let m = points.len() - 1;
    let mut worst = 0.0_f64;
    let mut span = 0;
    for k in 0..=m {
        let q = points[k].coords;
        let mut u = parameters[k];
        span = form.locate(u, span);
        if k > 0 && k < m {
            let (lo, hi) = (parameters[k - 1], parameters[k + 1]);
            let mut d = form.second_order(span, u);
            let mut dist = re((d[0] - q).norm_squared());
            for _ in 0..steps {
                let w = d[0] - q;
                let f = w.dot(&d[1]);
                let speed2 = d[1].norm_squared();
                let curvature_term = speed2 + w.dot(&d[2]);
                let slope = if re(curvature_term) > 0.0 {
                    curvature_term
                } else {
                    speed2
                };
                if re(slope) <= 0.0 || re(f) == 0.0 {
                    break;
                }
                let next = (u - f / slope).max(lo).min(hi);
                if !re(next).is_finite() {
                    break;
                }
                let next_span = form.locate(next, span);
                let e = form.second_order(next_span, next);
                let next_dist = re((e[0] - q).norm_squared());
                if next_dist >= dist {
                    break;
                }
                let converged = re(next - u).abs() <= 1e-15;
                u = next;
                span = next_span;
                d = e;
                dist = next_dist;
                if converged {
                    break;
                }
            }
            parameters[k] = u;
        }
        let dist = re((form.exact_point(span, u) - q).norm());
        distances.push(dist);
        worst = worst.max(dist);
    }
    Ok(worst)
}

/// |C(ū_k) − Q_k| for every data point into `distances`; returns the largest.
pub(crate) fn parametric_distances<T: Scalar, const D: usize>(
    curve: &BSplineCurve<T, D>,
    points: &[Point<T, D>],
    parameters: &[T],
    distances: &mut Vec<f64>,
) -> Result<f64> {
    distances.clear();
    let mut worst = 0.0_f64;
    for (q, &u) in points.iter().zip(parameters) {
        let d = re((curve.point(u)? - q).norm());
        distances.push(d);
        worst = worst.max(d);
    }
    Ok(worst)
}

/// A curve seen only on a run of its consecutive polynomial pieces: the toolkit's queries then
/// search that part. `breaks` are the run's breakpoints, both ends included (strictly
/// increasing), so that asking for them costs the run's length, not the whole curve's.
struct Window<'a, C> {
    curve: &'a C,
    breaks: &'a [f64],
}

impl<T: Scalar, const D: usize, C: ParametricCurve<T, D>> ParametricCurve<T, D> for Window<'_, C> {
    fn domain(&self) -> (T, T) {
        let (a, b) = (self.breaks[0], self.breaks[self.breaks.len() - 1]);
        (cst::<T>(a), cst::<T>(b))
    }

    fn derivatives_into(&self, u: T, out: &mut [SVector<T, D>]) -> Result<()> {
        check_parameter(u, self.domain())?;
        self.curve.derivatives_into(u, out)
    }

    fn breakpoints(&self) -> Vec<T> {
        self.breaks.iter().map(|&u| cst::<T>(u)).collect()
    }
}

/// The closest-point search settings on a window of a fitted curve: the window is a few
/// polynomial pieces and the point lies within the fitting tolerance of one of them, so eight
/// samples per piece bracket its foot point.
fn window_options() -> QueryOptions {
    QueryOptions::default().with_samples_per_piece(8)
}

/// The distance from `q` to the box [lo, hi] (zero inside).
fn box_distance<const D: usize>(
    (lo, hi): &(SVector<f64, D>, SVector<f64, D>),
    q: &SVector<f64, D>,
) -> f64 {
    let mut sum = 0.0;
    for c in 0..D {
        let e = (lo[c] - q[c]).max(q[c] - hi[c]).max(0.0);
        sum += e * e;
    }
    sum.sqrt()
}

/// The control boxes of a curve's Bézier pieces and of every aligned run of 2, 4, 8, …
/// pieces: level 0 holds the pieces, level l + 1 the union of pairs of level l. A query visits
/// only the runs whose box comes near the point, so it costs about the logarithm of the piece
/// count for a point near one place of the curve.
struct PieceTree<const D: usize> {
    /// The parameter interval of every piece.
    spans: Vec<(f64, f64)>,
    /// Boxes by level.
    levels: Vec<Vec<(SVector<f64, D>, SVector<f64, D>)>>,
}

impl<const D: usize> PieceTree<D> {
    fn new(pieces: &[RationalPiece<D>]) -> Self {
        let spans = pieces.iter().map(|p| (p.start, p.end)).collect();
        let mut levels = vec![pieces
            .iter()
            .map(RationalPiece::bounding_box)
            .collect::<Vec<_>>()];
        while levels.last().is_some_and(|l| l.len() > 1) {
            let below = levels.last().map(Vec::as_slice).unwrap_or_default();
            let above = below
                .chunks(2)
                .map(|pair| {
                    let (mut lo, mut hi) = pair[0];
                    for b in &pair[1..] {
                        lo = lo.inf(&b.0);
                        hi = hi.sup(&b.1);
                    }
                    (lo, hi)
                })
                .collect();
            levels.push(above);
        }
        Self { spans, levels }
    }

    /// The indices of the pieces whose box is within `reach` of `q`, in order.
    fn near(&self, q: &SVector<f64, D>, reach: f64, out: &mut Vec<usize>) {
        out.clear();
        let Some(top) = self.levels.len().checked_sub(1) else {
            return;
        };
        let mut stack: Vec<(usize, usize)> = (0..self.levels[top].len())
            .rev()
            .map(|i| (top, i))
            .collect();
        while let Some((level, i)) = stack.pop() {
            if box_distance(&self.levels[level][i], q) > reach {
                continue;
            }
            if level == 0 {
                out.push(i);
            } else {
                let width = self.levels[level - 1].len();
                for child in [2 * i + 1, 2 * i] {
                    if child < width {
                        stack.push((level - 1, child));
                    }
                }
            }
        }
    }
}

/// The distance from every data point to the whole curve, given upper bounds `distances[k]`
/// (the distance to some curve point, the one at `parameters[k]`): the closest-point search runs
/// on every run of neighbouring Bézier pieces whose control box comes within the bound, and
/// where it finds a closer point, the distance and the parameter are replaced by its. Returns
/// the largest distance.
pub(crate) fn distances_to_curve<T: Scalar, const D: usize>(
    curve: &BSplineCurve<T, D>,
    points: &[Point<T, D>],
    parameters: &mut [T],
    distances: &mut [f64],
) -> Result<f64> {
    let pieces = curve.bezier_enclosure()?.unwrap_or_default();
    let tree = PieceTree::new(&pieces);
    let opts = window_options();
    let mut worst = 0.0_f64;
    let mut near = Vec::new();
    let mut breaks: Vec<f64> = Vec::new();
    for ((q, u), bound) in points
        .iter()
        .zip(parameters.iter_mut())
        .zip(distances.iter_mut())
    {
        let qf: SVector<f64, D> = SVector::from_fn(|c, _| re(q.coords[c]));
        tree.near(&qf, *bound, &mut near);
        let mut i = 0;
        while i < near.len() {
            // A run of consecutive pieces.
            let mut j = i;
            while j + 1 < near.len() && near[j + 1] == near[j] + 1 {
                j += 1;
            }
            breaks.clear();
            breaks.push(tree.spans[near[i]].0);
            breaks.extend(tree.spans[near[i]..=near[j]].iter().map(|s| s.1));
            let window = Window {
                curve,
                breaks: &breaks,
            };
            let found = closest_point_with(&window, q, &opts)?;
            if re(found.distance) < *bound {
                *bound = re(found.distance);
                *u = found.parameter;
            }
            i = j + 1;
        }
        worst = worst.max(*bound);
    }
    Ok(worst)
}
