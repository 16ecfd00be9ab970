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
//!   of the curve whose control boxes come within e of Q can hold a closer point. On each such
//!   piece every local minimum of the distance is isolated exactly from the Bernstein form of
//!   g′(u) = (C(u) − Q)·C′(u) ([`distance_minima`](crate::queries::distance_minima)), refined by
//!   safeguarded Newton steps on g′, and the nearest of those minima and the piece's ends wins:
//!   no minimum is missed however wiggly the piece. Its distance is measured by the curve's own
//!   evaluation and replaces e when smaller. (Were the pieces not available, each span would be
//!   searched by [`SAMPLES_PER_PIECE`] samples and the sign changes of g′ between them.)

use nalgebra::{Point, SVector};

use super::power_form::PowerForm;
use crate::bspline::BSplineCurve;
use crate::curve::ParametricCurve;
use crate::errors::Result;
use crate::queries::box_tree::point_box_distance;
use crate::queries::distance_minima::{Candidate, DistanceMinima};
use crate::queries::RationalPiece;
use crate::scalar::{cst, from_usize, re, Scalar};

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

/// Samples per piece of the search for a closer point than the foot point: the window is a
/// piece the point lies within the fitting tolerance of, so eight steps bracket its minima.
const SAMPLES_PER_PIECE: usize = 8;

/// Newton or bisection steps per bracketed minimum at most (bisection alone halves the bracket
/// of an eighth of a piece to below 1e-16 of it in 50).
const MAX_STEPS: usize = 60;

/// The control boxes of a curve's Bézier pieces and of every aligned run of 2, 4, 8, …
/// pieces: level 0 holds the pieces, level l + 1 the union of pairs of level l. A query visits
/// only the runs whose box comes near the point, so it costs about the logarithm of the piece
/// count for a point near one place of the curve.
struct PieceTree<const D: usize> {
    /// Boxes by level.
    levels: Vec<Vec<(SVector<f64, D>, SVector<f64, D>)>>,
}

impl<const D: usize> PieceTree<D> {
    fn new(pieces: &[RationalPiece<D>]) -> Self {
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
        Self { levels }
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
            let (lo, hi) = &self.levels[level][i];
            if point_box_distance(q, (lo, hi)) > reach {
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
/// (the distance to some curve point, the one at `parameters[k]`): every Bézier piece whose
/// control box comes within the bound is searched (see the module header), and where a closer
/// point is found, the distance and the parameter are replaced by its. Returns the largest
/// distance.
pub(crate) fn distances_to_curve<T: Scalar, const D: usize>(
    curve: &BSplineCurve<T, D>,
    points: &[Point<T, D>],
    parameters: &mut [T],
    distances: &mut [f64],
) -> Result<f64> {
    let pieces = curve.bezier_enclosure()?.unwrap_or_default();
    let form = PowerForm::new(curve)?;
    // One Bézier piece per non-empty span, as the power form has; were it otherwise, every
    // span is searched.
    let tree = (pieces.len() == form.spans()).then(|| PieceTree::new(&pieces));
    let mut worst = 0.0_f64;
    let mut near = Vec::new();
    let mut minima = DistanceMinima::default();
    let mut candidates = Vec::new();
    for ((q, u), bound) in points
        .iter()
        .zip(parameters.iter_mut())
        .zip(distances.iter_mut())
    {
        let qf: SVector<f64, D> = SVector::from_fn(|c, _| re(q.coords[c]));
        match &tree {
            Some(tree) => tree.near(&qf, *bound, &mut near),
            None => {
                near.clear();
                near.extend(0..form.spans());
            }
        }
        for &j in &near {
            let exact = tree.is_some() && minima.find(&pieces[j], &qf, &mut candidates);
            let mut consider = |v: T| {
                let d = re((form.exact_point(j, v) - q.coords).norm());
                if d < *bound {
                    *bound = d;
                    *u = v;
                }
            };
            if exact {
                let (a, b) = form.span_bounds(j);
                consider(a);
                consider(b);
                let at_span = |t: f64| a + (b - a) * cst::<T>(t);
                let field = |v: T| squared_distance_field(&form, j, &q.coords, v);
                for candidate in &candidates {
                    match *candidate {
                        Candidate::Bracket(t0, t1) => {
                            consider(minimum_between(&field, at_span(t0), at_span(t1)).0);
                        }
                        Candidate::At(t) => consider(at_span(t)),
                    }
                }
            } else {
                consider(nearest_on_span(&form, j, &q.coords).0);
            }
        }
        worst = worst.max(*bound);
    }
    Ok(worst)
}

/// The parameter of the point of span `span` of `form` nearest to `q` the sampled search
/// finds (see the module header), with its squared distance by the power form.
fn nearest_on_span<T: Scalar, const D: usize>(
    form: &PowerForm<'_, T, D>,
    span: usize,
    q: &SVector<T, D>,
) -> (T, f64) {
    let (a, b) = form.span_bounds(span);
    let n = SAMPLES_PER_PIECE;
    let at = |u: T| squared_distance_field(form, span, q, u);
    let mut best = (a, f64::INFINITY);
    let mut previous: Option<(T, T)> = None;
    for i in 0..=n {
        let u = if i == n {
            b
        } else {
            a + (b - a) * from_usize::<T>(i) / from_usize::<T>(n)
        };
        let (g, slope, _) = at(u);
        if g < best.1 {
            best = (u, g);
        }
        if let Some((pu, ps)) = previous {
            if re(ps) < 0.0 && re(slope) > 0.0 {
                let (v, gv) = minimum_between(&at, pu, u);
                if gv < best.1 {
                    best = (v, gv);
                }
            }
        }
        previous = Some((u, slope));
    }
    best
}

/// g(u) = |C(u) − q|² on span `span` of `form`, with g′/2 and g″/2: (g, (C − q)·C′,
/// |C′|² + (C − q)·C″).
fn squared_distance_field<T: Scalar, const D: usize>(
    form: &PowerForm<'_, T, D>,
    span: usize,
    q: &SVector<T, D>,
    u: T,
) -> (f64, T, T) {
    let d = form.second_order(span, u);
    let w = d[0] - q;
    (
        re(w.norm_squared()),
        w.dot(&d[1]),
        d[1].norm_squared() + w.dot(&d[2]),
    )
}

/// The minimum of g between `lo` and `hi`, where g′ goes from negative to positive:
/// Newton steps on g′ (slope g″) while they stay inside the bracket and at least halve the
/// previous step, bisection otherwise. `at(u)` gives (g, g′, g″).
fn minimum_between<T: Scalar>(at: &impl Fn(T) -> (f64, T, T), lo: T, hi: T) -> (T, f64) {
    let half = cst::<T>(0.5);
    let (mut lo, mut hi) = (lo, hi);
    let mut x = (lo + hi) * half;
    let mut previous_step = re(hi - lo);
    let mut value = at(x);
    for _ in 0..MAX_STEPS {
        let (_, f, slope) = value;
        if re(f) == 0.0 {
            break;
        }
        if re(f) < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let newton = (re(slope) > 0.0).then(|| x - f / slope);
        let next = match newton {
            Some(nx) if nx > lo && nx < hi && re(nx - x).abs() <= 0.5 * previous_step => nx,
            _ => (lo + hi) * half,
        };
        let step = re(next - x).abs();
        if step == 0.0 {
            break;
        }
        x = next;
        previous_step = step;
        value = at(x);
        if step <= 1e-15 * re(hi - lo).max(re(x).abs()) {
            break;
        }
    }
    (x, value.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::knots::KnotVector;
    use crate::queries::closest_point;
    use nalgebra::Point2;
    use proptest::prelude::*;

    /// A clamped cubic with the given interior knots (sorted, distinct, in (0, 1)) whose
    /// control points zigzag: x = i, y from `ys`.
    fn wiggle(interior: &[f64], ys: &[f64]) -> BSplineCurve<f64, 2> {
        let mut knots = vec![0.0; 4];
        knots.extend_from_slice(interior);
        knots.extend([1.0; 4]);
        let count = knots.len() - 4;
        let points = (0..count)
            .map(|i| Point2::new(i as f64, ys[i % ys.len()]))
            .collect();
        BSplineCurve::try_new(3, KnotVector::try_new(knots).unwrap(), points).unwrap()
    }

    /// The smallest distance from `q` to `curve` among `count` + 1 equally spaced parameters.
    fn sampled_distance(curve: &BSplineCurve<f64, 2>, q: &Point2<f64>, count: usize) -> f64 {
        (0..=count)
            .map(|i| (curve.point(i as f64 / count as f64).unwrap() - q).norm())
            .fold(f64::INFINITY, f64::min)
    }

    proptest! {
        /// From the bound of an arbitrary curve point, the distance found is never above the
        /// bound, the toolkit's closest-point distance or the closest of 1,000 samples of the
        /// curve, and it is the distance from the point to the curve at the returned parameter,
        /// as the curve evaluates it (so never below the true distance).
        #[test]
        fn the_distance_to_the_curve_is_the_closest_point_distance(
            mut interior in proptest::collection::vec(0.01f64..0.99, 0..10),
            ys in proptest::collection::vec(-2.0f64..2.0, 2..12),
            queries in proptest::collection::vec((0.0f64..=1.0, -0.3f64..0.3, 0.0f64..=1.0), 1..12),
        ) {
            interior.sort_by(f64::total_cmp);
            interior.dedup_by(|a, b| (*a - *b).abs() < 1e-3);
            let curve = wiggle(&interior, &ys);
            let mut points = Vec::new();
            let mut parameters = Vec::new();
            let mut bounds = Vec::new();
            for &(u, offset, start) in &queries {
                let (c, d) = curve.point_and_derivative(u).unwrap();
                let normal = nalgebra::Vector2::new(-d.y, d.x) / d.norm().max(1e-12);
                let q = c + normal * offset;
                points.push(q);
                parameters.push(start);
                bounds.push((curve.point(start).unwrap() - q).norm());
            }
            let before = bounds.clone();
            let worst = distances_to_curve(&curve, &points, &mut parameters, &mut bounds).unwrap();
            for k in 0..points.len() {
                let toolkit = closest_point(&curve, &points[k]).unwrap().distance;
                let sampled = sampled_distance(&curve, &points[k], 1000);
                prop_assert!(bounds[k] <= before[k]);
                prop_assert!(bounds[k] <= toolkit + 1e-12 * (1.0 + toolkit), "{} vs {toolkit}", bounds[k]);
                prop_assert!(bounds[k] <= sampled + 1e-12 * (1.0 + sampled), "{} vs {sampled}", bounds[k]);
                let at = (curve.point(parameters[k]).unwrap() - points[k]).norm();
                prop_assert!((at - bounds[k]).abs() <= 1e-15 * (1.0 + at));
            }
            prop_assert!((worst - bounds.iter().copied().fold(0.0, f64::max)).abs() <= 0.0);
        }
    }

    /// A point whose nearest curve point lies between two other extrema of the distance within
    /// an eighth of one long span (a minimum, a maximum, then the deepest minimum): found
    /// anyway. Sampling the span at eight steps saw only rising distances around it.
    #[test]
    fn a_minimum_hidden_between_samples_is_found() {
        let curve = wiggle(
            &[
                0.01,
                0.027121738044469584,
                0.28526827169043995,
                0.303316016572566,
                0.5917319398779204,
                0.5942620620472083,
            ],
            &[
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                1.0725285608532373,
                -1.687239379087265,
                0.0,
            ],
        );
        let u = 0.3374011316497048;
        let (c, d) = curve.point_and_derivative(u).unwrap();
        let q = c - nalgebra::Vector2::new(-d.y, d.x) / d.norm() * 0.21895743841899049;
        let mut parameters = vec![0.0];
        let mut bounds = vec![(curve.point(0.0).unwrap() - q).norm()];
        distances_to_curve(&curve, &[q], &mut parameters, &mut bounds).unwrap();
        assert!(
            (bounds[0] - 0.21895743841899049).abs() < 1e-12,
            "{}",
            bounds[0]
        );
        assert!((parameters[0] - u).abs() < 1e-7, "{}", parameters[0]);
    }

    /// A point beside a hairpin: the foot point on the near leg bounds the distance, and the
    /// search finds the far leg's point only when it is closer.
    #[test]
    fn a_closer_point_on_another_piece_replaces_the_foot_point() {
        let curve = wiggle(&[0.25, 0.5, 0.75], &[0.0, 1.0]);
        // On the curve itself at u = 0.6: distance 0 however bad the start.
        let q = curve.point(0.6).unwrap();
        let mut parameters = vec![0.05];
        let mut bounds = vec![(curve.point(0.05).unwrap() - q).norm()];
        let worst = distances_to_curve(&curve, &[q], &mut parameters, &mut bounds).unwrap();
        assert!(worst < 1e-12, "{worst}");
        assert!((parameters[0] - 0.6).abs() < 1e-9, "{}", parameters[0]);
    }
}
