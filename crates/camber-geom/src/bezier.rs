//! Bézier curves of any degree in D dimensions.
//!
//! A Bézier curve of degree n is C(t) = Σ_{i=0..n} B_{i,n}(t) P_i on t ∈ [0, 1], with n + 1
//! control points P_i and the Bernstein polynomials B_{i,n} of [`crate::bernstein`]. It passes
//! through P_0 and P_n, is tangent there to the first and last legs of the control polygon, and
//! lies in the convex hull of its control points.
//!
//! This module evaluates the curve two ways (the Bernstein form and de Casteljau's algorithm,
//! both public so that they can be compared), its derivatives of any order through forward
//! differences (the hodograph), and provides subdivision, extraction of a piece, degree
//! elevation and reversal. All of it is generic over [`Scalar`], so differentiating a point with
//! respect to t or to the control points needs only dual numbers. Evaluation keeps its scratch on
//! the stack up to degree [`INLINE_DEGREE`].

use nalgebra::{Point, SVector};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use smallvec::{smallvec, SmallVec};

use crate::basis::INLINE_DEGREE;
use crate::bernstein::bernstein_all;
use crate::curve::{check_interval, check_parameter, check_points, ParametricCurve};
use crate::errors::{Error, Result};
use crate::knots::min_span_width;
use crate::scalar::{from_usize, re, Scalar};
use crate::serde_support::{points_from_raw, points_to_raw, RawPoint};

/// Stack capacity of the evaluation scratch: one entry per control point up to
/// [`INLINE_DEGREE`].
const INLINE: usize = INLINE_DEGREE + 1;
/// Scratch for n + 1 scalars (Bernstein values).
type Values<T> = SmallVec<[T; INLINE]>;
/// Scratch for n + 1 vectors (de Casteljau columns, forward differences).
type Vectors<T, const D: usize> = SmallVec<[SVector<T, D>; INLINE]>;

/// A Bézier curve C(t) = Σ B_{i,n}(t) P_i on t ∈ [0, 1], with n + 1 control points P_i.
///
/// ```
/// use camber_geom::{BezierCurve2, ParametricCurve};
/// use nalgebra::Point2;
/// let c = BezierCurve2::<f64>::try_new(vec![
///     Point2::new(0.0, 0.0),
///     Point2::new(1.0, 2.0),
///     Point2::new(3.0, 2.0),
///     Point2::new(4.0, 0.0),
/// ])?;
/// // C(1/2) = (P0 + 3 P1 + 3 P2 + P3) / 8.
/// let p = c.point(0.5)?;
/// assert!((p.x - 2.0).abs() < 1e-15 && (p.y - 1.5).abs() < 1e-15);
/// # Ok::<(), camber_geom::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BezierCurve<T: Scalar, const D: usize> {
    control_points: Vec<Point<T, D>>,
}

/// A planar Bézier curve.
pub type BezierCurve2<T> = BezierCurve<T, 2>;
/// A spatial Bézier curve.
pub type BezierCurve3<T> = BezierCurve<T, 3>;

/// # Construction
impl<T: Scalar, const D: usize> BezierCurve<T, D> {
    /// A Bézier curve of degree `control_points.len() − 1`: at least one control point, a
    /// degree of at most [`MAX_DEGREE`](crate::knots::MAX_DEGREE) (as for B-splines), all
    /// coordinates finite.
    ///
    /// Fails with [`Error::TooFewControlPoints`] for an empty list,
    /// [`Error::DegreeTooHigh`] for more than `MAX_DEGREE` + 1 points and
    /// [`Error::NonFinite`] (naming the point) for a NaN or infinite coordinate.
    ///
    /// ```
    /// use camber_geom::{BezierCurve2, Error};
    /// use nalgebra::Point2;
    /// assert_eq!(BezierCurve2::try_new(vec![Point2::new(1.0, 2.0)])?.degree(), 0);
    /// assert!(matches!(
    ///     BezierCurve2::<f64>::try_new(vec![]),
    ///     Err(Error::TooFewControlPoints { needed: 1, found: 0, .. })
    /// ));
    /// assert!(matches!(
    ///     BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(f64::NAN, 0.0)]),
    ///     Err(Error::NonFinite { index: 1, .. })
    /// ));
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn try_new(control_points: Vec<Point<T, D>>) -> Result<Self> {
        if control_points.is_empty() {
            return Err(Error::TooFewControlPoints {
                degree: 0,
                needed: 1,
                found: 0,
            });
        }
        crate::knots::check_degree(control_points.len() - 1)?;
        check_points(&control_points)?;
        Ok(Self { control_points })
    }

    /// The control points P_0 … P_n.
    pub fn control_points(&self) -> &[Point<T, D>] {
        &self.control_points
    }

    /// The degree n (number of control points − 1).
    pub fn degree(&self) -> usize {
        self.control_points.len() - 1
    }
}

/// # Evaluation
impl<T: Scalar, const D: usize> BezierCurve<T, D> {
    /// The point C(t) = Σ B_{i,n}(t) P_i, from the Bernstein values computed by their triangular
    /// recurrence. t must lie in [0, 1].
    ///
    /// Fails with [`Error::ParameterOutsideDomain`] or [`Error::NonFinite`] for a bad t.
    ///
    /// ```
    /// use camber_geom::BezierCurve2;
    /// use nalgebra::Point2;
    /// let c = BezierCurve2::<f64>::try_new(vec![
    ///     Point2::new(0.0, 0.0),
    ///     Point2::new(1.0, 2.0),
    ///     Point2::new(2.0, 0.0),
    /// ])?;
    /// // (1/4) P0 + (1/2) P1 + (1/4) P2.
    /// let p = c.point_bernstein(0.5)?;
    /// assert!((p.x - 1.0).abs() < 1e-15 && (p.y - 1.0).abs() < 1e-15);
    /// assert!(c.point_bernstein(1.5).is_err());
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn point_bernstein(&self, t: T) -> Result<Point<T, D>> {
        check_parameter(t, self.domain())?;
        let mut basis: Values<T> = smallvec![T::zero(); self.control_points.len()];
        bernstein_all(t, &mut basis);
        let coords = self.control_points.iter().map(|p| &p.coords);
        Ok(Point::from(weighted_sum(coords, &basis)))
    }

    /// The point C(t) by de Casteljau's algorithm: n rounds of linear interpolation
    /// P_i ← (1 − t) P_i + t P_{i+1} of the control polygon. t must lie in [0, 1].
    ///
    /// Fails with [`Error::ParameterOutsideDomain`] or [`Error::NonFinite`] for a bad t.
    ///
    /// ```
    /// use camber_geom::BezierCurve2;
    /// use nalgebra::Point2;
    /// let c = BezierCurve2::<f64>::try_new(vec![
    ///     Point2::new(0.0, 0.0),
    ///     Point2::new(1.0, 2.0),
    ///     Point2::new(2.0, 0.0),
    /// ])?;
    /// let (a, b) = (c.point_de_casteljau(0.3)?, c.point_bernstein(0.3)?);
    /// assert!((a - b).norm() < 1e-15);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn point_de_casteljau(&self, t: T) -> Result<Point<T, D>> {
        check_parameter(t, self.domain())?;
        let mut column: Vectors<T, D> = self.control_points.iter().map(|p| p.coords).collect();
        let one_minus_t = T::one() - t;
        for round in 1..column.len() {
            for i in 0..column.len() - round {
                column[i] = column[i] * one_minus_t + column[i + 1] * t;
            }
        }
        // The curve has at least one control point (checked by `try_new`).
        Ok(Point::from(
            column.first().copied().unwrap_or_else(SVector::zeros),
        ))
    }
}

/// # Derived curves
impl<T: Scalar, const D: usize> BezierCurve<T, D> {
    /// The hodograph C′ as a Bézier curve of degree n − 1, with control points
    /// n (P_{i+1} − P_i). For degree 0 (a constant curve) it is the single point at the origin.
    ///
    /// ```
    /// use camber_geom::BezierCurve2;
    /// use nalgebra::Point2;
    /// let c = BezierCurve2::<f64>::try_new(vec![
    ///     Point2::new(0.0, 0.0),
    ///     Point2::new(1.0, 2.0),
    ///     Point2::new(3.0, 2.0),
    /// ])?;
    /// let h = c.hodograph();
    /// assert_eq!(h.control_points(), &[Point2::new(2.0, 4.0), Point2::new(4.0, 0.0)]);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn hodograph(&self) -> Self {
        let n = self.degree();
        if n == 0 {
            return Self {
                control_points: vec![Point::origin()],
            };
        }
        let scale = from_usize::<T>(n);
        let control_points = self
            .control_points
            .windows(2)
            .map(|leg| Point::from((leg[1] - leg[0]) * scale))
            .collect();
        Self { control_points }
    }

    /// Splits the curve at t by de Casteljau's algorithm into the pieces over [0, t] and
    /// [t, 1], each reparameterized to [0, 1]: left(s) = C(t s), right(s) = C(t + (1 − t) s).
    /// Both have the degree of the curve.
    ///
    /// t must lie strictly inside (0, 1): t = 0 or t = 1 fails with [`Error::InvalidInterval`]
    /// (one piece would be empty), t outside [0, 1] with [`Error::ParameterOutsideDomain`], NaN
    /// with [`Error::NonFinite`], and a t nearer an end than
    /// [`min_span_width`]`(0, 1)` (≈ 1.4e-14) with
    /// [`Error::DegenerateSpan`]: that piece's control points would collapse onto one another
    /// in f64 (the rule B-spline splits follow).
    ///
    /// ```
    /// use camber_geom::BezierCurve2;
    /// use nalgebra::Point2;
    /// let c = BezierCurve2::<f64>::try_new(vec![
    ///     Point2::new(0.0, 0.0),
    ///     Point2::new(1.0, 2.0),
    ///     Point2::new(2.0, 0.0),
    /// ])?;
    /// let (left, right) = c.subdivide(0.5)?;
    /// assert_eq!(left.control_points()[2], Point2::new(1.0, 1.0));
    /// assert_eq!(right.control_points()[0], Point2::new(1.0, 1.0));
    /// assert!(c.subdivide(1.0).is_err());
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn subdivide(&self, t: T) -> Result<(Self, Self)> {
        check_parameter(t, self.domain())?;
        check_interval(T::zero(), t)?;
        check_interval(t, T::one())?;
        check_piece_width(t, re(t), 1.0 - re(t))?;
        Ok(self.split(t))
    }

    /// The piece of the curve over [t0, t1] reparameterized to [0, 1]:
    /// piece(s) = C(t0 + (t1 − t0) s), of the same degree.
    ///
    /// Both ends must lie in [0, 1] ([`Error::ParameterOutsideDomain`], [`Error::NonFinite`])
    /// with t0 < t1 ([`Error::InvalidInterval`]) at least
    /// [`min_span_width`]`(0, 1)` apart
    /// ([`Error::DegenerateSpan`]).
    ///
    /// ```
    /// use camber_geom::BezierCurve2;
    /// use nalgebra::Point2;
    /// let c = BezierCurve2::<f64>::try_new(vec![Point2::new(0.0, 0.0), Point2::new(4.0, 8.0)])?;
    /// let piece = c.segment(0.25, 0.75)?;
    /// assert_eq!(piece.control_points(), &[Point2::new(1.0, 2.0), Point2::new(3.0, 6.0)]);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn segment(&self, t0: T, t1: T) -> Result<Self> {
        check_parameter(t0, self.domain())?;
        check_parameter(t1, self.domain())?;
        check_interval(t0, t1)?;
        check_piece_width(t1, re(t1) - re(t0), f64::INFINITY)?;
        // head(s) = C(t1 s); its piece from s = t0 / t1 to 1 is C over [t0, t1]. t1 > t0 ≥ 0.
        let (head, _) = self.split(t1);
        let (_, piece) = head.split(t0 / t1);
        Ok(piece)
    }

    /// The same curve written with degree n + `times`: each step replaces the n + 1 control
    /// points by the n + 2 points Q_0 = P_0, Q_i = (i/(n+1)) P_{i−1} + (1 − i/(n+1)) P_i,
    /// Q_{n+1} = P_n. The curve itself is unchanged; `times` = 0 returns a copy.
    ///
    /// ```
    /// use camber_geom::BezierCurve2;
    /// use nalgebra::Point2;
    /// let line = BezierCurve2::<f64>::try_new(vec![Point2::new(0.0, 0.0), Point2::new(2.0, 4.0)])?;
    /// let q = line.elevate_degree(1);
    /// assert_eq!(q.degree(), 2);
    /// assert_eq!(q.control_points()[1], Point2::new(1.0, 2.0));
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    ///
    /// It takes O((n + times)·times) time and trusts `times`; for a count from user input use
    /// [`try_elevate_degree`](Self::try_elevate_degree), which bounds it.
    pub fn elevate_degree(&self, times: usize) -> Self {
        let mut points = Vec::with_capacity(self.control_points.len() + times);
        points.extend_from_slice(&self.control_points);
        for _ in 0..times {
            // `points` holds P_0 … P_n (never empty); rewrite it in place into Q_0 … Q_{n+1},
            // from the top down so that P_{i−1} and P_i are still unchanged when Q_i is formed.
            let count = points.len();
            let Some(&last) = points.last() else {
                break;
            };
            points.push(last);
            let denominator = from_usize::<T>(count);
            for i in (1..count).rev() {
                let a = from_usize::<T>(i) / denominator;
                let b = from_usize::<T>(count - i) / denominator;
                points[i] = Point::from(points[i - 1].coords * a + points[i].coords * b);
            }
        }
        Self {
            control_points: points,
        }
    }

    /// [`elevate_degree`](Self::elevate_degree) for an untrusted count: fails with
    /// [`Error::DegreeTooHigh`] when n + `times` exceeds
    /// [`MAX_DEGREE`](crate::knots::MAX_DEGREE) (`times` = 0 always succeeds).
    ///
    /// ```
    /// use camber_geom::{BezierCurve2, Error};
    /// use nalgebra::Point2;
    /// let line = BezierCurve2::<f64>::try_new(vec![Point2::new(0.0, 0.0), Point2::new(2.0, 4.0)])?;
    /// assert_eq!(line.try_elevate_degree(2)?.degree(), 3);
    /// assert!(matches!(line.try_elevate_degree(usize::MAX), Err(Error::DegreeTooHigh { .. })));
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn try_elevate_degree(&self, times: usize) -> Result<Self> {
        if times > 0 {
            crate::knots::check_degree(self.degree().saturating_add(times))?;
        }
        Ok(self.elevate_degree(times))
    }

    /// The same curve traversed backwards: reversed(s) = C(1 − s) (control points in reverse
    /// order).
    ///
    /// ```
    /// use camber_geom::BezierCurve2;
    /// use nalgebra::Point2;
    /// let c = BezierCurve2::<f64>::try_new(vec![Point2::new(0.0, 0.0), Point2::new(1.0, 0.0)])?;
    /// assert_eq!(c.reversed().control_points()[0], Point2::new(1.0, 0.0));
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn reversed(&self) -> Self {
        let mut control_points = self.control_points.clone();
        control_points.reverse();
        Self { control_points }
    }

    /// The length Σ |P_{i+1} − P_i| of the control polygon, in the units of the coordinates.
    /// It bounds the arc length of the curve from above; zero for degree 0.
    ///
    /// ```
    /// use camber_geom::BezierCurve2;
    /// use nalgebra::Point2;
    /// let c = BezierCurve2::<f64>::try_new(vec![
    ///     Point2::new(0.0, 0.0),
    ///     Point2::new(3.0, 4.0),
    ///     Point2::new(3.0, 0.0),
    /// ])?;
    /// assert!((c.control_polygon_length() - 9.0).abs() < 1e-15);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn control_polygon_length(&self) -> T {
        self.control_points
            .windows(2)
            .fold(T::zero(), |sum, leg| sum + (leg[1] - leg[0]).norm())
    }

    /// de Casteljau split at any t (no checks): the pieces over [0, t] and [t, 1]. With the
    /// columns b_i^r (round r, i = 0 … n − r) the left control points are b_0^0 … b_0^n and the
    /// right ones b_0^n, b_1^{n−1}, …, b_n^0.
    fn split(&self, t: T) -> (Self, Self) {
        let count = self.control_points.len();
        let mut column: Vectors<T, D> = self.control_points.iter().map(|p| p.coords).collect();
        let mut left = Vec::with_capacity(count);
        let mut right = Vec::with_capacity(count);
        left.extend(self.control_points.first().copied());
        right.extend(self.control_points.last().copied());
        let one_minus_t = T::one() - t;
        for round in 1..count {
            let top = count - round;
            for i in 0..top {
                column[i] = column[i] * one_minus_t + column[i + 1] * t;
            }
            left.push(Point::from(column[0]));
            right.push(Point::from(column[top - 1]));
        }
        right.reverse();
        (
            Self {
                control_points: left,
            },
            Self {
                control_points: right,
            },
        )
    }
}

/// Σ wᵢ vᵢ over the shorter of the two sequences.
fn weighted_sum<'a, T: Scalar, const D: usize>(
    vectors: impl Iterator<Item = &'a SVector<T, D>>,
    weights: &[T],
) -> SVector<T, D> {
    vectors
        .zip(weights)
        .fold(SVector::zeros(), |sum, (v, &w)| sum + v * w)
}

impl<T: Scalar, const D: usize> ParametricCurve<T, D> for BezierCurve<T, D> {
    /// The curve itself, one piece on [0, 1].
    fn bezier_enclosure(&self) -> Result<Option<Vec<crate::queries::RationalPiece<D>>>> {
        Ok(Some(crate::queries::pieces::bezier_form(self)))
    }

    /// Always [0, 1].
    fn domain(&self) -> (T, T) {
        (T::zero(), T::one())
    }

    /// C(t) and its derivatives from the forward differences Δᵏ P_i of the control points:
    /// C⁽ᵏ⁾(t) = n!/(n − k)! Σ_{i=0..n−k} Δᵏ P_i B_{i,n−k}(t), zero for k > n. Allocation-free up
    /// to degree [`INLINE_DEGREE`].
    ///
    /// ```
    /// use camber_geom::{BezierCurve2, ParametricCurve};
    /// use nalgebra::Point2;
    /// let c = BezierCurve2::<f64>::try_new(vec![
    ///     Point2::new(0.0, 0.0),
    ///     Point2::new(1.0, 2.0),
    ///     Point2::new(2.0, 0.0),
    /// ])?;
    /// let [_, d1, d2] = c.second_order(0.5)?;
    /// // C′ = 2 Σ ΔP_i B_{i,1} = (2, 0) at t = 1/2; C″ = 2 Δ²P_0 = (0, −8).
    /// assert!((d1.x - 2.0).abs() < 1e-15 && d1.y.abs() < 1e-15);
    /// assert!(d2.x.abs() < 1e-15 && (d2.y + 8.0).abs() < 1e-15);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    fn derivatives_into(&self, u: T, out: &mut [SVector<T, D>]) -> Result<()> {
        check_parameter(u, self.domain())?;
        let n = self.degree();
        // differences[i] = Δᵏ P_i for i = 0 … n − k after round k.
        let mut differences: Vectors<T, D> = self.control_points.iter().map(|p| p.coords).collect();
        let mut basis: Values<T> = smallvec![T::zero(); n + 1];
        // n! / (n − k)!
        let mut factor = T::one();
        for (k, slot) in out.iter_mut().enumerate() {
            if k > n {
                *slot = SVector::zeros();
                continue;
            }
            let m = n - k;
            let values = &mut basis[..=m];
            bernstein_all(u, values);
            *slot = weighted_sum(differences.iter(), values) * factor;
            for i in 0..m {
                differences[i] = differences[i + 1] - differences[i];
            }
            factor *= from_usize::<T>(m);
        }
        Ok(())
    }
}

/// The JSON form: `{"control_points": [[x, y], ...]}`.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBezier {
    control_points: Vec<RawPoint>,
}

impl<const D: usize> Serialize for BezierCurve<f64, D> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        RawBezier {
            control_points: points_to_raw(&self.control_points),
        }
        .serialize(serializer)
    }
}

impl<'de, const D: usize> Deserialize<'de> for BezierCurve<f64, D> {
    /// Reads `{"control_points": [[x, y], ...]}` and validates it as [`BezierCurve::try_new`]
    /// does; a point with the wrong number of coordinates is an [`Error::Dimension`].
    fn deserialize<De: Deserializer<'de>>(
        deserializer: De,
    ) -> std::result::Result<Self, De::Error> {
        let raw = RawBezier::deserialize(deserializer)?;
        let points = points_from_raw(&raw.control_points).map_err(serde::de::Error::custom)?;
        Self::try_new(points).map_err(serde::de::Error::custom)
    }
}

/// Fails with [`Error::DegenerateSpan`] (naming `t`) when the narrower of two pieces of [0, 1]
/// cut at `t`, `left` and `right` wide, is narrower than [`min_span_width`]`(0, 1)`.
fn check_piece_width<T: Scalar>(t: T, left: f64, right: f64) -> Result<()> {
    let (width, min) = (left.min(right), min_span_width(0.0, 1.0));
    if width < min {
        return Err(Error::DegenerateSpan {
            value: re(t),
            width,
            min,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use nalgebra::{Point2, Vector2};

    /// The cubic of the crate example: P = (0,0), (1,2), (3,2), (4,0).
    fn cubic() -> BezierCurve2<f64> {
        BezierCurve2::try_new(vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 2.0),
            Point2::new(3.0, 2.0),
            Point2::new(4.0, 0.0),
        ])
        .unwrap()
    }

    #[test]
    fn cubic_at_one_half_by_hand() {
        // C(1/2) = (P0 + 3P1 + 3P2 + P3)/8 = (16, 12)/8 = (2, 1.5).
        // ΔP = (1,2), (2,0), (1,−2); C′(1/2) = 3 (ΔP0 + 2ΔP1 + ΔP2)/4 = 3 (6, 0)/4 = (4.5, 0).
        // Δ²P = (1,−2), (−1,−2); C″(1/2) = 6 (Δ²P0 + Δ²P1)/2 = 6 (0, −2) = (0, −12).
        // Δ³P = (−2, 0); C‴ = 6 Δ³P0 = (−12, 0); C⁗ = 0.
        let c = cubic();
        let d = c.derivatives(0.5, 4).unwrap();
        let expected = [
            Vector2::new(2.0, 1.5),
            Vector2::new(4.5, 0.0),
            Vector2::new(0.0, -12.0),
            Vector2::new(-12.0, 0.0),
            Vector2::new(0.0, 0.0),
        ];
        for (a, e) in d.iter().zip(expected) {
            assert_relative_eq!(*a, e, epsilon = 1e-14);
        }
        for p in [
            c.point_bernstein(0.5).unwrap(),
            c.point_de_casteljau(0.5).unwrap(),
        ] {
            assert_relative_eq!(p, Point2::new(2.0, 1.5), epsilon = 1e-15);
        }
    }

    #[test]
    fn cubic_at_one_quarter_by_hand() {
        // B_{·,3}(1/4) = (27, 27, 9, 1)/64: C = (27·1 + 9·3 + 4, 27·2 + 9·2)/64 = (58, 72)/64.
        let c = cubic();
        let expected = Point2::new(58.0 / 64.0, 72.0 / 64.0);
        assert_relative_eq!(c.point(0.25).unwrap(), expected, epsilon = 1e-15);
        assert_relative_eq!(c.point_bernstein(0.25).unwrap(), expected, epsilon = 1e-15);
        assert_relative_eq!(
            c.point_de_casteljau(0.25).unwrap(),
            expected,
            epsilon = 1e-15
        );
    }

    #[test]
    fn subdivision_of_the_cubic_by_hand() {
        // Left: P0, (P0+P1)/2, (P0+2P1+P2)/4, C(1/2); right: C(1/2), (P1+2P2+P3)/4, (P2+P3)/2, P3.
        let (left, right) = cubic().subdivide(0.5).unwrap();
        let l = [(0.0, 0.0), (0.5, 1.0), (1.25, 1.5), (2.0, 1.5)];
        let r = [(2.0, 1.5), (2.75, 1.5), (3.5, 1.0), (4.0, 0.0)];
        for (p, (x, y)) in left.control_points().iter().zip(l) {
            assert_relative_eq!(*p, Point2::new(x, y), epsilon = 1e-15);
        }
        for (p, (x, y)) in right.control_points().iter().zip(r) {
            assert_relative_eq!(*p, Point2::new(x, y), epsilon = 1e-15);
        }
    }

    #[test]
    fn elevation_of_a_quadratic_by_hand() {
        // Q1 = P0/3 + 2P1/3, Q2 = 2P1/3 + P2/3.
        let c = BezierCurve2::try_new(vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 2.0),
            Point2::new(2.0, 0.0),
        ])
        .unwrap();
        let q = c.elevate_degree(1);
        let expected = [
            (0.0, 0.0),
            (2.0 / 3.0, 4.0 / 3.0),
            (4.0 / 3.0, 4.0 / 3.0),
            (2.0, 0.0),
        ];
        assert_eq!(q.degree(), 3);
        for (p, (x, y)) in q.control_points().iter().zip(expected) {
            assert_relative_eq!(*p, Point2::new(x, y), epsilon = 1e-15);
        }
        assert_eq!(c.elevate_degree(0), c);
    }

    #[test]
    fn degree_zero_is_a_constant() {
        let c = BezierCurve2::try_new(vec![Point2::new(3.0, -1.0)]).unwrap();
        let d = c.derivatives(0.7, 2).unwrap();
        assert_relative_eq!(d[0], Vector2::new(3.0, -1.0));
        assert_relative_eq!(d[1], Vector2::zeros());
        assert_relative_eq!(d[2], Vector2::zeros());
        assert_eq!(c.hodograph().control_points(), &[Point2::origin()]);
        assert_relative_eq!(c.control_polygon_length(), 0.0);
        let (l, r) = c.subdivide(0.3).unwrap();
        assert_eq!((l.clone(), r), (c.clone(), c.clone()));
        assert_eq!(c.segment(0.2, 0.4).unwrap(), c);
    }

    #[test]
    fn bad_parameters_are_errors() {
        let c = cubic();
        let outside = |value| Error::ParameterOutsideDomain {
            value,
            min: 0.0,
            max: 1.0,
        };
        assert_eq!(c.point(1.5), Err(outside(1.5)));
        assert_eq!(c.point_bernstein(-0.25), Err(outside(-0.25)));
        assert_eq!(c.point_de_casteljau(2.0), Err(outside(2.0)));
        assert_eq!(c.derivatives(-1.0, 2), Err(outside(-1.0)));
        assert!(matches!(
            c.point(f64::NAN),
            Err(Error::NonFinite {
                what: "parameter",
                ..
            })
        ));
        assert_eq!(c.subdivide(1.5), Err(outside(1.5)));
        let empty = |start, end| Error::InvalidInterval { start, end };
        assert_eq!(c.subdivide(0.0), Err(empty(0.0, 0.0)));
        assert_eq!(c.subdivide(1.0), Err(empty(1.0, 1.0)));
        // A piece narrower than f64 resolves on [0, 1] is refused, at either end.
        for t in [5e-324, 1e-15, 1.0 - f64::EPSILON] {
            assert!(
                matches!(c.subdivide(t), Err(Error::DegenerateSpan { value, .. }) if value.to_bits() == t.to_bits())
            );
        }
        assert!(c.subdivide(1e-13).is_ok());
        assert!(matches!(
            c.segment(0.5, 0.5 + 1e-16),
            Err(Error::DegenerateSpan { .. })
        ));
        assert_eq!(c.segment(0.5, 0.5), Err(empty(0.5, 0.5)));
        assert_eq!(c.segment(0.6, 0.4), Err(empty(0.6, 0.4)));
        assert_eq!(c.segment(0.5, 1.25), Err(outside(1.25)));
        // The ends themselves are inside the domain.
        assert_relative_eq!(c.point(1.0).unwrap(), Point2::new(4.0, 0.0));
        assert_eq!(c.segment(0.0, 1.0).unwrap(), c);
    }
}
