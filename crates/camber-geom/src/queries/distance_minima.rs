//! Where the distance from a point to one Bézier piece, polynomial or rational, has its local
//! minima, found without sampling.
//!
//! For a piece C(t) = Σ B_{i,n}(t) P_i, t ∈ [0, 1], and a point Q, the derivative of the
//! squared distance is, up to the positive factor 2n,
//!
//! g′(t) ∝ (C(t) − Q)·Ĉ(t),  Ĉ(t) = Σ B_{j,n−1}(t) (P_{j+1} − P_j),
//!
//! a polynomial of degree 2n − 1 whose Bernstein coefficients are exact sums of products:
//!
//! c_k = Σ_{i+j=k} C(n, i)·C(n − 1, j) / C(2n − 1, k) · (P_i − Q)·(P_{j+1} − P_j).
//!
//! The Bernstein form diminishes variation: the number of roots in (0, 1) is at most the
//! number of sign changes among the coefficients and has the same parity. So no sign change
//! means no root and exactly one means exactly one. Halving an interval (de Casteljau) never
//! adds sign changes, so halving every interval with two or more isolates every root; those
//! where g′ goes from − to + are the minima. Each halving level halves at most (2n − 1)/2
//! intervals, and the halving stops at [`MAX_DEPTH`], so a piece costs O(n³·MAX_DEPTH) at
//! worst and a few coefficient sign checks in the common case.
//!
//! A rational piece C = X/w with homogeneous control points (X_i, w_i) = (w_i·P_i, w_i) and
//! every weight positive has (C − Q)·C′ = (X − Q·w)·(X′·w − X·w′)/w³, and w³ > 0, so g′ has
//! the sign of the polynomial N = A·B of degree 3n − 1, the product of
//!
//! A = X − Q·w (degree n, coefficients A_i = X_i − Q·w_i) and
//! B = (X′·w − X·w′)/n (degree 2n − 1, B_k = Σ_{j+i=k} C(n − 1, j)·C(n, i)/C(2n − 1, k)·
//! (ΔX_j·w_i − X_i·Δw_j), ΔX_j = X_{j+1} − X_j, Δw_j = w_{j+1} − w_j),
//!
//! N_m = Σ_{i+k=m} C(n, i)·C(2n − 1, k)/C(3n − 1, m)·A_i·B_k: the same isolation applies to N
//! (the product rule of Bernstein forms, C(a, i)·C(b, k)/C(a + b, i + k)).

use nalgebra::SVector;

use crate::bernstein::binomial;
use crate::queries::RationalPiece;

/// Deepest halving of the piece's parameter interval: 2⁻⁵² is below the spacing of f64 near 1.
const MAX_DEPTH: u32 = 52;

/// What the isolation found in the piece's own parameter t ∈ [0, 1].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Candidate {
    /// g′ goes from − to + exactly once inside (lo, hi): one local minimum there.
    Bracket(f64, f64),
    /// A parameter where g′ may vanish (a halving point where it is exactly zero, or an
    /// interval too narrow to halve further): to be evaluated as it is.
    At(f64),
}

/// Reusable buffers for [`DistanceMinima::find`], so that a search over many points allocates
/// only once.
#[derive(Debug, Default)]
pub(crate) struct DistanceMinima {
    /// The coefficients of the intervals still to look at, `width` values each.
    stack: Vec<f64>,
    /// (t0, t1, depth) of each interval on `stack`.
    intervals: Vec<(f64, f64, u32)>,
    /// De Casteljau working row and the two halves it gives.
    row: Vec<f64>,
    left: Vec<f64>,
    right: Vec<f64>,
}

impl DistanceMinima {
    /// Every local minimum of |C(t) − q| over the open interval (0, 1) of `piece`, as brackets
    /// or single parameters in increasing t, into `out`. Returns `false` (and leaves `out`
    /// empty) for a rational piece with a weight that is not positive and where the
    /// coefficients overflow (coordinates near the largest f64).
    pub(crate) fn find<const D: usize>(
        &mut self,
        piece: &RationalPiece<D>,
        q: &SVector<f64, D>,
        out: &mut Vec<Candidate>,
    ) -> bool {
        out.clear();
        let stride = D + 1;
        let count = piece.homogeneous.len() / stride;
        let weight = |i: usize| piece.homogeneous[i * stride + D];
        if count == 0 || (0..count).any(|i| !(weight(i) > 0.0 && weight(i).is_finite())) {
            return false;
        }
        let n = count - 1;
        if n == 0 {
            // A constant piece: the distance is the same everywhere.
            return true;
        }
        let point = |i: usize| -> SVector<f64, D> {
            SVector::from_fn(|c, _| piece.homogeneous[i * stride + c])
        };
        self.stack.clear();
        // A polynomial piece has every weight exactly 1 (a B-spline's pieces are built so).
        let width = if (0..count).all(|i| (weight(i) - 1.0).abs() <= 0.0) {
            let width = 2 * n;
            self.stack.resize(width, 0.0);
            for i in 0..=n {
                let a = point(i) - q;
                let weight_i: f64 = binomial(n, i);
                for j in 0..n {
                    let b = point(j + 1) - point(j);
                    let k = i + j;
                    let w = weight_i * binomial::<f64>(n - 1, j) / binomial::<f64>(width - 1, k);
                    self.stack[k] += w * a.dot(&b);
                }
            }
            width
        } else {
            self.rational_coefficients(n, &point, &weight, q)
        };
        if self.stack.iter().any(|c| !c.is_finite()) {
            // Coordinates so large that the products overflow: no signs to read.
            return false;
        }
        self.intervals.clear();
        self.intervals.push((0.0, 1.0, 0));
        while let Some((t0, t1, depth)) = self.intervals.pop() {
            let start = self.stack.len() - width;
            let coefficients = &self.stack[start..];
            let (changes, first, last) = sign_changes(coefficients);
            match changes {
                0 => {}
                1 => {
                    if first < 0.0 && last > 0.0 {
                        out.push(Candidate::Bracket(t0, t1));
                    }
                }
                _ if depth >= MAX_DEPTH || t1 - t0 <= f64::EPSILON * t1.max(1.0) => {
                    out.push(Candidate::At(0.5 * (t0 + t1)));
                }
                _ => {
                    let tm = 0.5 * (t0 + t1);
                    // Halve: the left half's coefficients are the first entries of each de
                    // Casteljau row, the right half's the last ones (reversed order of rows).
                    let (row, left, right) = (&mut self.row, &mut self.left, &mut self.right);
                    row.clear();
                    row.extend_from_slice(coefficients);
                    left.clear();
                    left.resize(width, 0.0);
                    right.clear();
                    right.resize(width, 0.0);
                    left[0] = row[0];
                    right[width - 1] = row[width - 1];
                    for r in 1..width {
                        for s in 0..width - r {
                            row[s] = 0.5 * (row[s] + row[s + 1]);
                        }
                        left[r] = row[0];
                        right[width - 1 - r] = row[width - 1 - r];
                    }
                    let middle = left[width - 1];
                    self.stack.truncate(start);
                    // Right first so the left half is looked at first: increasing t.
                    self.stack.extend_from_slice(&self.right);
                    self.intervals.push((tm, t1, depth + 1));
                    if middle == 0.0 {
                        // A root exactly at the halving point, seen by neither half.
                        self.intervals.push((tm, tm, u32::MAX));
                        self.stack.extend(std::iter::repeat_n(0.0, width));
                    }
                    self.stack.extend_from_slice(&self.left);
                    self.intervals.push((t0, tm, depth + 1));
                    continue;
                }
            }
            self.stack.truncate(start);
            if depth == u32::MAX {
                out.push(Candidate::At(t0));
            }
        }
        true
    }
}

impl DistanceMinima {
    /// The Bernstein coefficients of N = A·B (module documentation) of a rational piece of
    /// degree n ≥ 1, onto the empty `stack`; returns their number, 3n.
    fn rational_coefficients<const D: usize>(
        &mut self,
        n: usize,
        point: &impl Fn(usize) -> SVector<f64, D>,
        weight: &impl Fn(usize) -> f64,
        q: &SVector<f64, D>,
    ) -> usize {
        // B: degree 2n − 1, 2n coefficients, built in `row` (D values each).
        let b_count = 2 * n;
        self.row.clear();
        self.row.resize(b_count * D, 0.0);
        for j in 0..n {
            let dx = point(j + 1) - point(j);
            let dw = weight(j + 1) - weight(j);
            let wj: f64 = binomial(n - 1, j);
            for i in 0..=n {
                let k = i + j;
                let w = wj * binomial::<f64>(n, i) / binomial::<f64>(b_count - 1, k);
                let term = dx * weight(i) - point(i) * dw;
                for c in 0..D {
                    self.row[k * D + c] += w * term[c];
                }
            }
        }
        // N = A·B: degree 3n − 1, 3n coefficients.
        let width = 3 * n;
        self.stack.resize(width, 0.0);
        for i in 0..=n {
            let a = point(i) - q * weight(i);
            let wi: f64 = binomial(n, i);
            for k in 0..b_count {
                let m = i + k;
                let w = wi * binomial::<f64>(b_count - 1, k) / binomial::<f64>(width - 1, m);
                let b = &self.row[k * D..(k + 1) * D];
                let dot: f64 = (0..D).map(|c| a[c] * b[c]).sum();
                self.stack[m] += w * dot;
            }
        }
        width
    }
}

/// The sign changes among the non-zero entries of `c`, with the first and last non-zero
/// entries (0 when all are zero).
fn sign_changes(c: &[f64]) -> (usize, f64, f64) {
    let mut changes = 0;
    let mut first = 0.0;
    let mut previous = 0.0_f64;
    for &x in c {
        if x == 0.0 {
            continue;
        }
        if previous == 0.0 {
            first = x;
        } else if (x > 0.0) != (previous > 0.0) {
            changes += 1;
        }
        previous = x;
    }
    (changes, first, previous)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::BezierCurve;
    use crate::curve::ParametricCurve;
    use crate::queries::pieces::bezier_form;
    use nalgebra::{Point2, Vector2};
    use proptest::prelude::*;

    /// (C(t) − q)·C′(t) by the curve's own evaluation.
    fn slope(curve: &BezierCurve<f64, 2>, q: &Vector2<f64>, t: f64) -> f64 {
        let (c, d) = curve.point_and_derivative(t).unwrap();
        (c.coords - q).dot(&d)
    }

    fn piece(points: &[(f64, f64)]) -> (BezierCurve<f64, 2>, RationalPiece<2>) {
        let points: Vec<_> = points.iter().map(|&(x, y)| Point2::new(x, y)).collect();
        let curve = BezierCurve::try_new(points).unwrap();
        let mut pieces = bezier_form(&curve);
        (curve, pieces.remove(0))
    }

    /// A straight segment from (0, 0) to (1, 0) and a point above x = 0.3: one minimum,
    /// bracketing t = 0.3 (the foot of the perpendicular).
    #[test]
    fn the_foot_on_a_segment_is_bracketed() {
        let (_, p) = piece(&[(0.0, 0.0), (0.5, 0.0), (1.0, 0.0)]);
        let mut found = Vec::new();
        assert!(DistanceMinima::default().find(&p, &Vector2::new(0.3, 0.7), &mut found));
        match found[..] {
            [Candidate::Bracket(lo, hi)] => assert!(lo < 0.3 && 0.3 < hi, "{lo} {hi}"),
            ref other => panic!("{other:?}"),
        }
    }

    /// A point at the centre of a symmetric arch: the distance has a maximum at the apex
    /// (t = 1/2, exactly a halving point) only when the point is inside the arch's osculating
    /// circle; far below it the apex is the single minimum, found at the halving point.
    #[test]
    fn a_minimum_exactly_at_the_halving_point_is_kept() {
        let (_, p) = piece(&[(-1.0, 0.0), (0.0, 2.0), (1.0, 0.0)]);
        let mut found = Vec::new();
        assert!(DistanceMinima::default().find(&p, &Vector2::new(0.0, 5.0), &mut found));
        let holds_half = found.iter().any(|c| match *c {
            Candidate::Bracket(lo, hi) => lo < 0.5 && 0.5 < hi,
            Candidate::At(t) => (t - 0.5).abs() <= 0.0,
        });
        assert!(holds_half, "{found:?}");
    }

    /// A quarter of the unit circle as a rational quadratic: every point of it is a minimum of
    /// the distance from the centre (g′ ≡ 0, all coefficients zero: no bracket, nothing
    /// claimed), and from (2, 2) the one minimum is at 45°, which the piece reaches at t = ½.
    #[test]
    fn the_minimum_on_a_circular_arc_is_bracketed() {
        let p = RationalPiece::new(
            0.0,
            1.0,
            &[
                Point2::new(1.0, 0.0),
                Point2::new(1.0, 1.0),
                Point2::new(0.0, 1.0),
            ],
            &[1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0],
        );
        let mut found = Vec::new();
        assert!(DistanceMinima::default().find(&p, &Vector2::new(2.0, 2.0), &mut found));
        let holds_half = found.iter().any(|c| match *c {
            Candidate::Bracket(lo, hi) => lo < 0.5 && 0.5 < hi,
            Candidate::At(t) => (t - 0.5).abs() < 1e-12,
        });
        assert!(holds_half && found.len() == 1, "{found:?}");
        assert!(DistanceMinima::default().find(&p, &Vector2::zeros(), &mut found));
        assert!(found.is_empty(), "{found:?}");
    }

    /// A piece with a weight that is not positive is refused.
    #[test]
    fn a_piece_with_a_non_positive_weight_is_refused() {
        let p = RationalPiece::new(
            0.0,
            1.0,
            &[
                Point2::new(1.0, 0.0),
                Point2::new(1.0, 1.0),
                Point2::new(0.0, 1.0),
            ],
            &[1.0, -0.5, 1.0],
        );
        let mut found = vec![Candidate::At(0.0)];
        assert!(!DistanceMinima::default().find(&p, &Vector2::zeros(), &mut found));
        assert!(found.is_empty());
    }

    /// Against g′ (`slope`) evaluated at 2,000 points: g′ goes from − to + across every
    /// reported bracket, and every clear − to + sign change (not rounding near a double root)
    /// lies in a reported bracket or next to a reported parameter.
    fn every_minimum_found(
        slope: impl Fn(f64) -> f64,
        found: &[Candidate],
    ) -> Result<(), proptest::test_runner::TestCaseError> {
        for c in found {
            if let Candidate::Bracket(lo, hi) = *c {
                prop_assert!(lo < hi);
                prop_assert!(slope(lo) <= 1e-12 && slope(hi) >= -1e-12, "{lo} {hi}");
            }
        }
        let n = 2000;
        let mut previous = slope(0.0);
        for i in 1..=n {
            let (a, b) = ((i - 1) as f64 / n as f64, i as f64 / n as f64);
            let s = slope(b);
            if previous < -1e-9 && s > 1e-9 {
                let covered = found.iter().any(|c| match *c {
                    Candidate::Bracket(lo, hi) => lo <= b && a <= hi,
                    Candidate::At(t) => (a - 1e-9..=b + 1e-9).contains(&t),
                });
                prop_assert!(covered, "sign change in [{a}, {b}] not found: {found:?}");
            }
            previous = s;
        }
        Ok(())
    }

    proptest! {
        /// Against the curve's own evaluation of g′ at 2,000 points: every − to + sign change
        /// seen there lies in one reported bracket (or next to a reported parameter), and g′
        /// goes from − to + across every bracket.
        #[test]
        fn every_sampled_minimum_is_bracketed(
            coords in proptest::collection::vec((-2.0f64..2.0, -2.0f64..2.0), 2..9),
            qx in -2.0f64..2.0,
            qy in -2.0f64..2.0,
        ) {
            let (curve, p) = piece(&coords);
            let q = Vector2::new(qx, qy);
            let mut found = Vec::new();
            prop_assert!(DistanceMinima::default().find(&p, &q, &mut found));
            every_minimum_found(|t| slope(&curve, &q, t), &found)?;
        }

        /// The same for rational pieces with weights in [0.2, 3]: the sign of g′ from a direct
        /// evaluation of the homogeneous curve, (X − q·w)·(X′·w − X·w′) at 2,000 points
        /// (w³ > 0 dropped), against the isolation of the product's Bernstein coefficients.
        #[test]
        fn every_sampled_minimum_of_a_rational_piece_is_bracketed(
            coords in proptest::collection::vec((-2.0f64..2.0, -2.0f64..2.0, 0.2f64..3.0), 2..8),
            qx in -2.0f64..2.0,
            qy in -2.0f64..2.0,
        ) {
            let points: Vec<_> = coords.iter().map(|&(x, y, _)| Point2::new(x, y)).collect();
            let weights: Vec<_> = coords.iter().map(|&(_, _, w)| w).collect();
            let p = RationalPiece::new(0.0, 1.0, &points, &weights);
            let n = points.len() - 1;
            let q = Vector2::new(qx, qy);
            // X(t), w(t) and their derivatives by the Bernstein sums.
            let slope = |t: f64| -> f64 {
                let (mut x, mut dx, mut w, mut dw) = (Vector2::zeros(), Vector2::zeros(), 0.0, 0.0);
                for (i, (pt, wi)) in points.iter().zip(&weights).enumerate() {
                    let b = binomial::<f64>(n, i) * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32);
                    let db = binomial::<f64>(n, i)
                        * (if i > 0 { i as f64 * t.powi(i as i32 - 1) * (1.0 - t).powi((n - i) as i32) } else { 0.0 }
                            - if i < n { (n - i) as f64 * t.powi(i as i32) * (1.0 - t).powi((n - i - 1) as i32) } else { 0.0 });
                    x += pt.coords * (wi * b);
                    dx += pt.coords * (wi * db);
                    w += wi * b;
                    dw += wi * db;
                }
                (x - q * w).dot(&(dx * w - x * dw))
            };
            let mut found = Vec::new();
            prop_assert!(DistanceMinima::default().find(&p, &q, &mut found));
            every_minimum_found(slope, &found)?;
        }
    }
}
