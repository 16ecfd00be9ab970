//! Non-rational B-spline curves C(u) = Σ N_{i,p}(u) P_i of any degree in D dimensions.
//!
//! A [`BSplineCurve`] owns its degree p, a [`KnotVector`] of n + p + 2 knots and n + 1 control
//! points; its domain is [u_p, u_{n+1}], any interval, clamped or not. Evaluation finds the knot
//! span and combines the p + 1 non-zero basis functions (The NURBS Book A3.2) without
//! allocating. Knot insertion, refinement, splitting, degree elevation, reversal and
//! reparameterization delegate to the flat [`ControlNet`] algorithms and never change the curve.

use nalgebra::{Point, SVector};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use smallvec::{smallvec, SmallVec};

use crate::basis::INLINE_DEGREE;
use crate::bezier::BezierCurve;
use crate::curve::{check_parameter, check_points, ParametricCurve};
use crate::errors::{Error, Result};
use crate::knot_ops::ControlNet;
use crate::knots::KnotVector;
use crate::scalar::{from_usize, re, Scalar};
use crate::serde_support::{points_from_raw, points_to_raw, RawPoint};

/// Scratch for up to (INLINE_DEGREE + 1)² basis values on the stack.
type Scratch<T> = SmallVec<[T; (INLINE_DEGREE + 1) * (INLINE_DEGREE + 1)]>;

/// A B-spline curve C(u) = Σᵢ N_{i,p}(u) P_i on its domain [u_p, u_{n+1}], with degree p,
/// knots u₀ ≤ … ≤ u_{n+p+1} and control points P₀ … P_n (n + 1 ≥ p + 1). Coordinates are in
/// the caller's length unit; derivatives are per unit of u.
///
/// ```
/// use camber_geom::{BSplineCurve2, KnotVector, ParametricCurve};
/// use nalgebra::Point2;
/// // A clamped quadratic with an interior knot at 1 on the domain [0, 2].
/// let knots = KnotVector::try_new(vec![0.0_f64, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])?;
/// let points = vec![
///     Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(3.0, 1.0), Point2::new(4.0, 0.0),
/// ];
/// let curve = BSplineCurve2::try_new(2, knots, points)?;
/// // At the interior knot the curve is the midpoint of P1 and P2.
/// let p = curve.point(1.0)?;
/// assert!((p.x - 2.0).abs() < 1e-15 && (p.y - 1.0).abs() < 1e-15);
/// assert!(curve.point(2.5).is_err());
/// # Ok::<(), camber_geom::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineCurve<T: Scalar, const D: usize> {
    degree: usize,
    knots: KnotVector<T>,
    control_points: Vec<Point<T, D>>,
}

/// A planar B-spline curve.
pub type BSplineCurve2<T> = BSplineCurve<T, 2>;
/// A spatial B-spline curve.
pub type BSplineCurve3<T> = BSplineCurve<T, 3>;

/// # Construction
impl<T: Scalar, const D: usize> BSplineCurve<T, D> {
    /// A B-spline of `degree` with `knots` and `control_points`: at least degree + 1 points,
    /// knot count = points + degree + 1, knots finite and non-decreasing, a domain of positive
    /// length, finite coordinates.
    ///
    /// ```
    /// use camber_geom::{BSplineCurve2, Error, KnotVector};
    /// use nalgebra::Point2;
    /// let knots = KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0])?;
    /// let points = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 0.0), Point2::new(2.0, 0.0)];
    /// assert!(matches!(
    ///     BSplineCurve2::try_new(1, knots, points),
    ///     Err(Error::KnotCount { expected: 5, found: 4, .. })
    /// ));
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn try_new(
        degree: usize,
        knots: KnotVector<T>,
        control_points: Vec<Point<T, D>>,
    ) -> Result<Self> {
        // Re-check the knot values too: a KnotVector may have been built unchecked.
        knots.validate()?;
        knots.check_for(degree, control_points.len())?;
        check_points(&control_points)?;
        Ok(Self {
            degree,
            knots,
            control_points,
        })
    }

    /// The Bézier curve as a B-spline: same control points, degree n, clamped knots on
    /// [0, 1] (n + 1 zeros and n + 1 ones), so both curves agree for every u ∈ [0, 1].
    ///
    /// ```
    /// use camber_geom::{BezierCurve2, BSplineCurve2, ParametricCurve};
    /// use nalgebra::Point2;
    /// let bezier = BezierCurve2::try_new(vec![Point2::new(0.0_f64, 0.0), Point2::new(2.0, 4.0)])?;
    /// let spline = BSplineCurve2::from_bezier(&bezier);
    /// assert_eq!(spline.knots().as_slice(), &[0.0, 0.0, 1.0, 1.0]);
    /// assert!((spline.point(0.25)?.y - 1.0).abs() < 1e-15);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn from_bezier(bezier: &BezierCurve<T, D>) -> Self {
        let degree = bezier.degree();
        let mut knots = vec![T::zero(); degree + 1];
        knots.extend(std::iter::repeat_n(T::one(), degree + 1));
        Self {
            degree,
            knots: KnotVector::new_unchecked(knots),
            control_points: bezier.control_points().to_vec(),
        }
    }

    /// The same degree and knots with new control points (as many as before, all finite).
    ///
    /// ```
    /// use camber_geom::{BSplineCurve2, KnotVector};
    /// use nalgebra::Point2;
    /// let knots = KnotVector::clamped_uniform(1, 2)?;
    /// let line = BSplineCurve2::try_new(1, knots, vec![Point2::origin(), Point2::new(1.0, 0.0)])?;
    /// let moved = line.with_control_points(vec![Point2::origin(), Point2::new(0.0, 1.0)])?;
    /// assert!(line.with_control_points(vec![Point2::origin()]).is_err());
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn with_control_points(&self, control_points: Vec<Point<T, D>>) -> Result<Self> {
        Self::try_new(self.degree, self.knots.clone(), control_points)
    }

    /// The curve of a control net with `dim` = D (validated like [`try_new`](Self::try_new)).
    /// Fails with [`Error::Dimension`] when the net's dimension is not D.
    pub fn try_from_control_net(net: ControlNet<T>) -> Result<Self> {
        if net.dim != D {
            return Err(Error::Dimension {
                index: 0,
                expected: D,
                found: net.dim,
            });
        }
        net.check()?;
        let points = net
            .coords
            .chunks_exact(D)
            .map(|c| Point::from(SVector::<T, D>::from_column_slice(c)))
            .collect();
        Self::try_new(net.degree, net.knots, points)
    }
}

impl<T: Scalar, const D: usize> BSplineCurve<T, D> {
    /// The degree p.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The knot vector (control points + degree + 1 knots).
    pub fn knots(&self) -> &KnotVector<T> {
        &self.knots
    }

    /// The control points P₀ … P_n.
    pub fn control_points(&self) -> &[Point<T, D>] {
        &self.control_points
    }

    /// The flat control net (`dim` = D) that the knot algorithms work on.
    pub fn to_control_net(&self) -> ControlNet<T> {
        ControlNet {
            degree: self.degree,
            knots: self.knots.clone(),
            dim: D,
            coords: self
                .control_points
                .iter()
                .flat_map(|p| p.coords.iter().copied())
                .collect(),
        }
    }

    /// Rebuilds a curve from a net produced by a knot algorithm on this curve's net.
    fn from_net(net: ControlNet<T>) -> Self {
        let control_points = net
            .coords
            .chunks_exact(D)
            .map(|c| Point::from(SVector::<T, D>::from_column_slice(c)))
            .collect();
        Self {
            degree: net.degree,
            knots: net.knots,
            control_points,
        }
    }

    /// The Bézier pieces of the curve, one per non-empty knot span of the domain, as
    /// (start, end, piece): on [start, end] the curve equals the piece at
    /// t = (u − start) / (end − start). A piece whose control points would not be finite
    /// (only possible when coordinates are near the floating-point limit) is left out.
    ///
    /// ```
    /// use camber_geom::{BSplineCurve2, KnotVector};
    /// use nalgebra::Point2;
    /// let knots = KnotVector::try_new(vec![0.0_f64, 0.0, 1.0, 3.0, 3.0])?;
    /// let points = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(2.0, 0.0)];
    /// let segments = BSplineCurve2::try_new(1, knots, points)?.to_bezier_segments();
    /// assert_eq!(segments.len(), 2);
    /// assert!((segments[1].0 - 1.0).abs() < 1e-15 && (segments[1].1 - 3.0).abs() < 1e-15);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn to_bezier_segments(&self) -> Vec<(T, T, BezierCurve<T, D>)> {
        self.to_control_net()
            .decompose()
            .into_iter()
            .filter_map(|piece| {
                let points = piece
                    .coords
                    .chunks_exact(D)
                    .map(|c| Point::from(SVector::<T, D>::from_column_slice(c)))
                    .collect();
                let bezier = BezierCurve::try_new(points).ok()?;
                Some((piece.start, piece.end, bezier))
            })
            .collect()
    }

    /// Inserts the knot u `times` times (A5.1); the curve is unchanged. Errors as
    /// [`ControlNet::insert_knot`]: u outside the domain, multiplicity + times > degree.
    ///
    /// ```
    /// use camber_geom::{BSplineCurve2, KnotVector, ParametricCurve};
    /// use nalgebra::Point2;
    /// let knots = KnotVector::clamped_uniform(2, 3)?;
    /// let pts = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 2.0), Point2::new(2.0, 0.0)];
    /// let curve = BSplineCurve2::try_new(2, knots, pts)?;
    /// let finer = curve.insert_knot(0.3, 2)?;
    /// assert_eq!(finer.control_points().len(), 5);
    /// assert!((finer.point(0.7)? - curve.point(0.7)?).norm() < 1e-14);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn insert_knot(&self, u: T, times: usize) -> Result<Self> {
        Ok(Self::from_net(self.to_control_net().insert_knot(u, times)?))
    }

    /// Inserts all of the non-decreasing `new_knots` (inside the domain) at once (A5.4);
    /// the curve is unchanged. Errors as [`ControlNet::refine`].
    pub fn refine(&self, new_knots: &[T]) -> Result<Self> {
        Ok(Self::from_net(self.to_control_net().refine(new_knots)?))
    }

    /// Splits at u strictly inside the domain [a, b] into a curve on [a, u] and one on [u, b],
    /// both clamped, which together trace this curve. Fails with
    /// [`Error::ParameterOutsideDomain`] otherwise.
    ///
    /// ```
    /// use camber_geom::{BSplineCurve2, KnotVector, ParametricCurve};
    /// use nalgebra::Point2;
    /// let knots = KnotVector::<f64>::clamped_uniform(2, 4)?;
    /// let pts = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 2.0), Point2::new(2.0, 2.0),
    ///     Point2::new(3.0, 0.0)];
    /// let curve = BSplineCurve2::try_new(2, knots, pts)?;
    /// let (left, right) = curve.split(0.4)?;
    /// assert!((left.domain().1 - 0.4).abs() < 1e-15 && (right.domain().0 - 0.4).abs() < 1e-15);
    /// assert!((right.point(0.8)? - curve.point(0.8)?).norm() < 1e-14);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn split(&self, u: T) -> Result<(Self, Self)> {
        let (left, right) = self.to_control_net().split(u)?;
        Ok((Self::from_net(left), Self::from_net(right)))
    }

    /// Raises the degree by `times` without changing the curve; every distinct knot's
    /// multiplicity grows by `times` (the result is clamped).
    pub fn elevate_degree(&self, times: usize) -> Result<Self> {
        Ok(Self::from_net(self.to_control_net().elevate_degree(times)?))
    }

    /// The same curve traversed backwards on the same domain [a, b]: the result at u equals
    /// this curve at a + b − u.
    pub fn reversed(&self) -> Self {
        let knots = self.to_control_net().reversed().knots;
        let mut control_points = self.control_points.clone();
        control_points.reverse();
        Self {
            degree: self.degree,
            knots,
            control_points,
        }
    }

    /// [`BSplineCurve::reversed`], refused with [`Error::ReparamNotRepresentable`] (the domain)
    /// when the reflected knots cannot stay distinct in f64
    /// ([`KnotVector::reverses_faithfully`]).
    pub fn try_reversed(&self) -> Result<Self> {
        if !self.knots.reverses_faithfully() {
            let (a, b) = self.domain();
            return Err(Error::ReparamNotRepresentable {
                start: re(a),
                end: re(b),
            });
        }
        Ok(self.reversed())
    }

    /// The same curve on the domain [a, b] (a < b): the result at a + (b − a)·s equals this
    /// curve at u₀ + (u₁ − u₀)·s, so the k-th derivative scales by ((u₁ − u₀) / (b − a))ᵏ.
    pub fn reparameterized(&self, a: T, b: T) -> Result<Self> {
        let knots = self.to_control_net().reparameterized(a, b)?.knots;
        Ok(Self {
            degree: self.degree,
            knots,
            control_points: self.control_points.clone(),
        })
    }

    /// The same curve with clamped ends (end knots of multiplicity p + 1 at the domain ends),
    /// so that the first and last control points are the curve's end points.
    pub fn clamped(&self) -> Self {
        Self::from_net(self.to_control_net().clamped())
    }

    /// C(u) and C′(u) (into `out[0]` and, if present, `out[1]`) for degree p ≤
    /// [`INLINE_DEGREE`]: the Cox–de Boor triangle (A2.2) up to degree p − 1, then its last
    /// step fused with the combination. With tᵣ = N_{i,p−1}(u) / (u_{i+p} − u_i),
    /// i = span − p + 1 + r, the active control points P₀ … P_p (local indices) give
    /// C = Σᵣ tᵣ ((u_{i+p} − u) P_r + (u − u_i) P_{r+1}) and C′ = p Σᵣ tᵣ (P_{r+1} − P_r).
    fn point_and_tangent(&self, span: usize, u: T, out: &mut [SVector<T, D>]) {
        let p = self.degree;
        let active = &self.control_points[span - p..=span];
        if p == 0 {
            out[0] = active[0].coords;
            if let Some(d) = out.get_mut(1) {
                *d = SVector::zeros();
            }
            return;
        }
        let knots = self.knots.as_slice();
        let mut left = [T::zero(); INLINE_DEGREE + 1];
        let mut right = [T::zero(); INLINE_DEGREE + 1];
        let mut n = [T::zero(); INLINE_DEGREE + 1];
        n[0] = T::one();
        for j in 1..=p {
            left[j] = u - knots[span + 1 - j];
            right[j] = knots[span + j] - u;
        }
        for j in 1..p {
            let mut saved = T::zero();
            for r in 0..j {
                let temp = n[r] / (right[r + 1] + left[j - r]);
                n[r] = saved + right[r + 1] * temp;
                saved = left[j - r] * temp;
            }
            n[j] = saved;
        }
        let mut position = SVector::<T, D>::zeros();
        let mut tangent = SVector::<T, D>::zeros();
        for r in 0..p {
            let (hi, lo) = (right[r + 1], left[p - r]);
            let t = n[r] / (hi + lo);
            let (a, b) = (&active[r].coords, &active[r + 1].coords);
            position += a * (hi * t) + b * (lo * t);
            tangent += (b - a) * t;
        }
        out[0] = position;
        if let Some(d) = out.get_mut(1) {
            *d = tangent * from_usize::<T>(p);
        }
    }

    /// C(u) and its first `out.len() − 1` derivatives for degree p ≤ [`INLINE_DEGREE`], with
    /// stack scratch only (The NURBS Book A3.4): the whole Cox–de Boor triangle N_{·,j}(u),
    /// j = 0 … p, at the span, and the derivative control points of the p + 1 active ones,
    /// P⁽ᵏ⁾_i = (p − k + 1) (P⁽ᵏ⁻¹⁾_{i+1} − P⁽ᵏ⁻¹⁾_i) / (u_{i+p+1} − u_{i+k}), so that
    /// C⁽ᵏ⁾(u) = Σ_i N_{i+k,p−k}(u) P⁽ᵏ⁾_i. Orders above p are zero.
    fn derivatives_inline(&self, span: usize, u: T, out: &mut [SVector<T, D>]) {
        const W: usize = INLINE_DEGREE + 1;
        let p = self.degree;
        let knots = self.knots.as_slice();
        let active = &self.control_points[span - p..=span];
        let mut left = [T::zero(); W];
        let mut right = [T::zero(); W];
        // tri[j * W + r] = N_{span−j+r, j}(u).
        let mut tri = [T::zero(); W * W];
        tri[0] = T::one();
        for j in 1..=p {
            left[j] = u - knots[span + 1 - j];
            right[j] = knots[span + j] - u;
            let mut saved = T::zero();
            for r in 0..j {
                let temp = tri[(j - 1) * W + r] / (right[r + 1] + left[j - r]);
                tri[j * W + r] = saved + right[r + 1] * temp;
                saved = left[j - r] * temp;
            }
            tri[j * W + j] = saved;
        }
        let mut pk = [SVector::<T, D>::zeros(); W];
        for (q, point) in pk.iter_mut().zip(active) {
            *q = point.coords;
        }
        for (k, o) in out.iter_mut().enumerate() {
            if k > p {
                *o = SVector::zeros();
                continue;
            }
            if k > 0 {
                let factor = from_usize::<T>(p - k + 1);
                let first = span - p;
                for i in 0..=p - k {
                    let den = knots[first + i + p + 1] - knots[first + i + k];
                    pk[i] = (pk[i + 1] - pk[i]) * (factor / den);
                }
            }
            let row = &tri[(p - k) * W..(p - k) * W + p - k + 1];
            let mut sum = SVector::<T, D>::zeros();
            for (q, &n) in pk.iter().zip(row) {
                sum += q * n;
            }
            *o = sum;
        }
    }

    /// C(u) on knot span `span` (as [`KnotVector::find_span`] gives it for u, which the caller
    /// has found; u in the domain): the evaluation of [`point`](ParametricCurve::point)
    /// without its domain check and span search, for callers that walk the spans in order.
    pub(crate) fn point_in_span(&self, span: usize, u: T) -> SVector<T, D> {
        let mut out = [SVector::<T, D>::zeros(); 1];
        if self.degree > INLINE_DEGREE {
            self.derivatives_general(span, u, &mut out);
        } else {
            self.point_and_tangent(span, u, &mut out);
        }
        out[0]
    }

    /// C(u) and its first `out.len() − 1` derivatives from the basis-function derivatives
    /// (A2.3) combined with the active control points (A3.2); for degrees above
    /// [`INLINE_DEGREE`], where the scratch may live on the heap.
    fn derivatives_general(&self, span: usize, u: T, out: &mut [SVector<T, D>]) {
        let p = self.degree;
        let top = out.len().saturating_sub(1).min(p);
        let width = p + 1;
        let mut table: Scratch<T> = smallvec![T::zero(); (top + 1) * width];
        self.knots
            .basis_function_derivatives(span, u, p, top, &mut table);
        let active = &self.control_points[span - p..=span];
        for (k, o) in out.iter_mut().enumerate() {
            *o = SVector::zeros();
            if k <= top {
                for (j, point) in active.iter().enumerate() {
                    *o += point.coords * table[k * width + j];
                }
            }
        }
    }
}

impl<T: Scalar, const D: usize> ParametricCurve<T, D> for BSplineCurve<T, D> {
    /// Its Bézier segments, one per non-empty knot span.
    fn bezier_enclosure(&self) -> Result<Option<Vec<crate::queries::RationalPiece<D>>>> {
        Ok(Some(crate::queries::pieces::bspline_form(self)))
    }

    fn domain(&self) -> (T, T) {
        self.knots.domain(self.degree)
    }

    /// C(u) and its derivatives by span search and the basis-function derivatives (A2.3,
    /// A3.2); derivatives above the degree are zero. At an interior knot the piece to the
    /// right is used.
    fn derivatives_into(&self, u: T, out: &mut [SVector<T, D>]) -> Result<()> {
        check_parameter(u, self.domain())?;
        let p = self.degree;
        let span = self.knots.find_span(p, u);
        if p > INLINE_DEGREE {
            self.derivatives_general(span, u, out);
        } else if out.len() <= 2 {
            if !out.is_empty() {
                self.point_and_tangent(span, u, out);
            }
        } else {
            self.derivatives_inline(span, u, out);
        }
        Ok(())
    }

    fn breakpoints(&self) -> Vec<T> {
        self.knots.breakpoints(self.degree)
    }
}

/// The JSON form: `{"degree": 3, "knots": [...], "control_points": [[x, y], ...]}`.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBSpline {
    degree: usize,
    knots: Vec<f64>,
    control_points: Vec<RawPoint>,
}

impl<const D: usize> Serialize for BSplineCurve<f64, D> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        RawBSpline {
            degree: self.degree,
            knots: self.knots.as_slice().to_vec(),
            control_points: points_to_raw(&self.control_points),
        }
        .serialize(serializer)
    }
}

impl<'de, const D: usize> Deserialize<'de> for BSplineCurve<f64, D> {
    /// Validates like [`BSplineCurve::try_new`], and refuses unknown fields and degree 0 (a
    /// file describes a continuous curve); the error message names the offending value.
    fn deserialize<De: Deserializer<'de>>(
        deserializer: De,
    ) -> std::result::Result<Self, De::Error> {
        let raw = RawBSpline::deserialize(deserializer)?;
        if raw.degree == 0 {
            return Err(serde::de::Error::custom(Error::DegreeZero));
        }
        let points = points_from_raw(&raw.control_points).map_err(serde::de::Error::custom)?;
        let knots = KnotVector::try_new(raw.knots).map_err(serde::de::Error::custom)?;
        Self::try_new(raw.degree, knots, points).map_err(serde::de::Error::custom)
    }
}
