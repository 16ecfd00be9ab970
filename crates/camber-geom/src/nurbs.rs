//! NURBS (non-uniform rational B-spline) curves.
//!
//! A NURBS curve of degree p with control points P₀ … P_n, positive weights w₀ … w_n and a knot
//! vector U is
//!
//! ```text
//! C(u) = Σ N_{i,p}(u) w_i P_i / Σ N_{i,p}(u) w_i,    u ∈ [u_p, u_{n+1}].
//! ```
//!
//! It is the perspective image of the non-rational B-spline with homogeneous control points
//! Pʷ_i = (w_i P_i, w_i) in D + 1 dimensions. Evaluation and derivatives work on that
//! homogeneous curve and divide at the end (The NURBS Book A4.2); every knot operation (insertion,
//! refinement, splitting, Bézier decomposition, degree elevation, reversal, reparameterization)
//! runs the non-rational algorithm of [`crate::knot_ops`] on the homogeneous net and projects
//! back, so the curve never changes shape.

use nalgebra::{Point, SVector, Vector2};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use smallvec::{smallvec, SmallVec};

use crate::basis::INLINE_DEGREE;
use crate::curve::{check_interval, check_parameter, check_points, ParametricCurve};
use crate::errors::{Error, Result};
use crate::knot_ops::ControlNet;
use crate::knots::KnotVector;
use crate::scalar::{cst, from_usize, re, Scalar};
use crate::serde_support::{points_from_raw, points_to_raw, RawPoint};

/// Inline capacity of the basis-derivative table: (k + 1)(p + 1) values for k, p ≤
/// [`INLINE_DEGREE`]. Larger tables still work but allocate.
const DERS_INLINE: usize = (INLINE_DEGREE + 1) * (INLINE_DEGREE + 1);

/// A rational B-spline curve C: [u_p, u_{n+1}] → R^D.
///
/// Invariants (checked by [`try_new`](Self::try_new)): at least p + 1 control points, n + p + 2
/// knots with a domain of positive length, finite coordinates, one finite positive weight per
/// control point.
///
/// ```
/// use camber_geom::{KnotVector, NurbsCurve2, ParametricCurve};
/// use nalgebra::Point2;
///
/// // A quarter of the unit circle as a rational quadratic.
/// let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0])?;
/// let points = vec![Point2::new(1.0, 0.0), Point2::new(1.0, 1.0), Point2::new(0.0, 1.0)];
/// let weights = vec![1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0];
/// let arc = NurbsCurve2::try_new(2, knots, points, weights)?;
/// let p = arc.point(0.3)?;
/// assert!((p.coords.norm() - 1.0).abs() < 1e-14);
/// # Ok::<(), camber_geom::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsCurve<T: Scalar, const D: usize> {
    degree: usize,
    knots: KnotVector<T>,
    control_points: Vec<Point<T, D>>,
    weights: Vec<T>,
}

/// A planar NURBS curve.
pub type NurbsCurve2<T> = NurbsCurve<T, 2>;
/// A spatial NURBS curve.
pub type NurbsCurve3<T> = NurbsCurve<T, 3>;

/// # Construction
impl<T: Scalar, const D: usize> NurbsCurve<T, D> {
    /// A NURBS curve of `degree` p from its knots, control points and weights.
    ///
    /// Errors: [`Error::TooFewControlPoints`], [`Error::KnotCount`] and [`Error::EmptyDomain`]
    /// from the knot vector check; [`Error::NonFinite`] for a coordinate (naming the point) or a
    /// weight (naming the weight); [`Error::WeightCount`] when there is not exactly one weight per
    /// control point; [`Error::NonPositiveWeight`] for a weight ≤ 0.
    ///
    /// ```
    /// use camber_geom::{Error, KnotVector, NurbsCurve2};
    /// use nalgebra::Point2;
    /// let knots = KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0]).unwrap();
    /// let points = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 0.0)];
    /// assert!(NurbsCurve2::try_new(1, knots.clone(), points.clone(), vec![1.0, 2.0]).is_ok());
    /// assert_eq!(
    ///     NurbsCurve2::try_new(1, knots.clone(), points.clone(), vec![1.0, -2.0]),
    ///     Err(Error::NonPositiveWeight { index: 1, value: -2.0 })
    /// );
    /// assert_eq!(
    ///     NurbsCurve2::try_new(1, knots, points, vec![1.0]),
    ///     Err(Error::WeightCount { expected: 2, found: 1 })
    /// );
    /// ```
    pub fn try_new(
        degree: usize,
        knots: KnotVector<T>,
        control_points: Vec<Point<T, D>>,
        weights: Vec<T>,
    ) -> Result<Self> {
        // Re-check the knot values too: a KnotVector may have been built unchecked.
        knots.validate()?;
        knots.check_for(degree, control_points.len())?;
        check_points(&control_points)?;
        if weights.len() != control_points.len() {
            return Err(Error::WeightCount {
                expected: control_points.len(),
                found: weights.len(),
            });
        }
        for (index, &w) in weights.iter().enumerate() {
            let value = re(w);
            if !value.is_finite() {
                return Err(Error::NonFinite {
                    what: "weight",
                    index,
                    value,
                });
            }
            if w <= T::zero() {
                return Err(Error::NonPositiveWeight { index, value });
            }
        }
        let (lo, hi) = weights
            .iter()
            .fold((f64::INFINITY, 0.0_f64), |(lo, hi), &w| {
                (lo.min(re(w)), hi.max(re(w)))
            });
        if hi > lo * MAX_WEIGHT_RATIO {
            return Err(Error::WeightRatio {
                smallest: lo,
                largest: hi,
                max: MAX_WEIGHT_RATIO,
            });
        }
        Ok(Self {
            degree,
            knots,
            control_points,
            weights,
        })
    }

    /// The non-rational B-spline Σ N_{i,p}(u) P_i written as a NURBS curve: every weight 1.
    /// Same checks as [`try_new`](Self::try_new).
    ///
    /// ```
    /// use camber_geom::{KnotVector, NurbsCurve2, ParametricCurve};
    /// use nalgebra::Point2;
    /// let knots = KnotVector::<f64>::clamped_uniform(1, 2)?;
    /// let line = NurbsCurve2::try_with_unit_weights(1, knots, vec![Point2::origin(), Point2::new(2.0, 0.0)])?;
    /// assert!((line.point(0.25)?.x - 0.5).abs() < 1e-15);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn try_with_unit_weights(
        degree: usize,
        knots: KnotVector<T>,
        control_points: Vec<Point<T, D>>,
    ) -> Result<Self> {
        let weights = vec![T::one(); control_points.len()];
        Self::try_new(degree, knots, control_points, weights)
    }

    /// The curve whose homogeneous control net is `net`: `net.dim` must be D + 1 and each point
    /// holds (w·x, w·y, …, w). The control points are the projections (w·P) / w. Fails with
    /// [`Error::Dimension`] for a wrong `dim` or a coordinate count that is not a multiple of it,
    /// and otherwise as [`try_new`](Self::try_new) (in particular for a weight ≤ 0).
    pub fn try_from_homogeneous(net: ControlNet<T>) -> Result<Self> {
        let dim = D + 1;
        if net.dim != dim || !net.coords.len().is_multiple_of(dim) {
            return Err(Error::Dimension {
                index: 0,
                expected: dim,
                found: net.dim,
            });
        }
        let count = net.coords.len() / dim;
        let mut points = Vec::with_capacity(count);
        let mut weights = Vec::with_capacity(count);
        for (index, chunk) in net.coords.chunks_exact(dim).enumerate() {
            let w = chunk[D];
            if !re(w).is_finite() {
                return Err(Error::NonFinite {
                    what: "weight",
                    index,
                    value: re(w),
                });
            }
            if w <= T::zero() {
                return Err(Error::NonPositiveWeight {
                    index,
                    value: re(w),
                });
            }
            points.push(Point::from(
                SVector::<T, D>::from_column_slice(&chunk[..D]) / w,
            ));
            weights.push(w);
        }
        Self::try_new(net.degree, net.knots, points, weights)
    }
}

impl<T: Scalar, const D: usize> NurbsCurve<T, D> {
    /// The degree p.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The knot vector (n + p + 2 knots).
    pub fn knots(&self) -> &KnotVector<T> {
        &self.knots
    }

    /// The control points P₀ … P_n (Euclidean, not multiplied by their weights).
    pub fn control_points(&self) -> &[Point<T, D>] {
        &self.control_points
    }

    /// The weights w₀ … w_n, all positive.
    pub fn weights(&self) -> &[T] {
        &self.weights
    }

    /// Whether every weight equals the first one, in which case the curve is the non-rational
    /// B-spline of the same control points and knots.
    pub fn is_polynomial(&self) -> bool {
        let first = self.weights[0];
        self.weights.iter().all(|&w| w == first)
    }

    /// The homogeneous control net: degree, knots, `dim` = D + 1 and, per control point,
    /// (w_i·P_i, w_i).
    pub fn to_homogeneous(&self) -> ControlNet<T> {
        let dim = D + 1;
        let mut coords = Vec::with_capacity(self.control_points.len() * dim);
        for (p, &w) in self.control_points.iter().zip(&self.weights) {
            coords.extend(p.coords.iter().map(|&c| c * w));
            coords.push(w);
        }
        ControlNet {
            degree: self.degree,
            knots: self.knots.clone(),
            dim,
            coords,
        }
    }

    /// Inserts the knot `u` `times` times (The NURBS Book A5.1 on the homogeneous net). The
    /// curve is unchanged; it gains `times` control points. Errors: `u` outside the domain or not
    /// finite; [`Error::KnotMultiplicity`] when the multiplicity of `u` would exceed the degree.
    pub fn insert_knot(&self, u: T, times: usize) -> Result<Self> {
        check_parameter(u, self.domain())?;
        Self::try_from_homogeneous(self.to_homogeneous().insert_knot(u, times)?)
    }

    /// Inserts every knot of `new_knots` (non-decreasing, inside the domain) at once (A5.4).
    /// The curve is unchanged.
    pub fn refine(&self, new_knots: &[T]) -> Result<Self> {
        let domain = self.domain();
        for &u in new_knots {
            check_parameter(u, domain)?;
        }
        Self::try_from_homogeneous(self.to_homogeneous().refine(new_knots)?)
    }

    /// Splits the curve at `u`, strictly inside the domain [a, b], into the pieces on [a, u] and
    /// [u, b] (each keeps its part of the parameter, clamped at u). Fails with
    /// [`Error::ParameterOutsideDomain`] for u outside (a, b).
    ///
    /// ```
    /// use camber_geom::{KnotVector, NurbsCurve2, ParametricCurve};
    /// use nalgebra::Point2;
    /// # let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0])?;
    /// # let points = vec![Point2::new(1.0, 0.0), Point2::new(1.0, 1.0), Point2::new(0.0, 1.0)];
    /// # let arc = NurbsCurve2::try_new(2, knots, points, vec![1.0, 0.5_f64.sqrt(), 1.0])?;
    /// let (left, right) = arc.split(0.4)?;
    /// assert_eq!(left.domain(), (0.0, 0.4));
    /// assert!((right.point(0.7)? - arc.point(0.7)?).norm() < 1e-14);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn split(&self, u: T) -> Result<(Self, Self)> {
        let (left, right) = self.to_homogeneous().split(u)?;
        Ok((
            Self::try_from_homogeneous(left)?,
            Self::try_from_homogeneous(right)?,
        ))
    }

    /// The rational Bézier pieces of the curve (A5.6 on the homogeneous net): one
    /// `(start, end, piece)` per non-empty knot span of the domain, in order, where `piece` is a
    /// single-span NURBS curve of the same degree on [start, end] that agrees with `self` there.
    ///
    /// ```
    /// use camber_geom::{NurbsCurve2, ParametricCurve};
    /// use nalgebra::Point2;
    /// let circle = NurbsCurve2::try_circular_arc(Point2::origin(), 1.0, 0.0, std::f64::consts::TAU)?;
    /// let pieces = circle.to_bezier_segments();
    /// assert_eq!(pieces.len(), 4);
    /// let (start, end, quarter) = &pieces[1];
    /// assert!((start - 0.25).abs() < 1e-15 && (end - 0.5).abs() < 1e-15);
    /// assert!((quarter.point(0.3)? - circle.point(0.3)?).norm() < 1e-14);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn to_bezier_segments(&self) -> Vec<(T, T, Self)> {
        let p = self.degree;
        self.to_homogeneous()
            .decompose()
            .into_iter()
            .map(|piece| {
                let mut knots = Vec::with_capacity(2 * p + 2);
                knots.extend(std::iter::repeat_n(piece.start, p + 1));
                knots.extend(std::iter::repeat_n(piece.end, p + 1));
                let curve = Self::from_homogeneous_unchecked(
                    p,
                    KnotVector::new_unchecked(knots),
                    &piece.coords,
                );
                (piece.start, piece.end, curve)
            })
            .collect()
    }

    /// Raises the degree by `times` without changing the curve (degree elevation on the
    /// homogeneous net); each distinct knot's multiplicity grows by `times`.
    pub fn elevate_degree(&self, times: usize) -> Result<Self> {
        Self::try_from_homogeneous(self.to_homogeneous().elevate_degree(times)?)
    }

    /// The same curve with clamped ends: end knots of multiplicity p + 1 at the domain ends
    /// (the identity for a curve that is clamped already).
    pub fn clamped(&self) -> Self {
        let net = self.to_homogeneous().clamped();
        Self::from_homogeneous_unchecked(net.degree, net.knots, &net.coords)
    }

    /// The same point set traversed backwards over the same domain: C_r(u) = C(a + b − u).
    pub fn reversed(&self) -> Self {
        let net = self.to_homogeneous().reversed();
        Self::from_homogeneous_unchecked(net.degree, net.knots, &net.coords)
    }

    /// [`NurbsCurve::reversed`], refused with [`Error::ReparamNotRepresentable`] (the domain)
    /// when the reflected knots cannot stay distinct in f64
    /// ([`KnotVector::reverses_faithfully`]).
    pub fn try_reversed(&self) -> Result<Self> {
        if !self.knots().reverses_faithfully() {
            let (a, b) = self.domain();
            return Err(Error::ReparamNotRepresentable {
                start: re(a),
                end: re(b),
            });
        }
        Ok(self.reversed())
    }

    /// The same curve with its domain mapped affinely onto [a, b]: C_r(u) = C(φ(u)) with φ the
    /// increasing affine map from [a, b] onto the old domain. Fails with
    /// [`Error::InvalidInterval`] unless a < b (both finite).
    pub fn reparameterized(&self, a: T, b: T) -> Result<Self> {
        check_interval(a, b)?;
        Self::try_from_homogeneous(self.to_homogeneous().reparameterized(a, b)?)
    }

    /// Projects a homogeneous net that the algorithms of [`crate::knot_ops`] produced from a
    /// valid curve. Their new weights are convex combinations of positive weights, hence
    /// positive, so the checks of [`try_new`](Self::try_new) cannot fail and are skipped.
    fn from_homogeneous_unchecked(degree: usize, knots: KnotVector<T>, coords: &[T]) -> Self {
        let dim = D + 1;
        let (control_points, weights) = coords
            .chunks_exact(dim)
            .map(|chunk| {
                let w = chunk[D];
                let p = SVector::<T, D>::from_column_slice(&chunk[..D]) / w;
                (Point::from(p), w)
            })
            .unzip();
        Self {
            degree,
            knots,
            control_points,
            weights,
        }
    }
}

/// # Construction (planar)
impl<T: Scalar> NurbsCurve<T, 2> {
    /// The circular arc of `radius` around `center` from angle `start` to angle `end` (radians,
    /// counterclockwise, 0 < end − start ≤ 2π) as a rational quadratic (The NURBS Book A7.1):
    /// the sweep is cut into 1 to 4 equal arcs of at most 90°, each a rational Bézier piece with
    /// middle weight cos(Δθ/2) and middle point at distance r / cos(Δθ/2) from the center. The
    /// domain is [0, 1] and the joints are double knots at i / arcs; the curve is C¹ in u there
    /// (equal arcs have equal speeds) but not arc-length parameterized inside a piece.
    ///
    /// Errors: [`Error::NonFinite`] for the center, [`Error::NonPositiveRadius`] (also for a
    /// non-finite radius), [`Error::InvalidInterval`] when the sweep is not in (0, 2π] or an
    /// angle is not finite.
    ///
    /// ```
    /// use camber_geom::{NurbsCurve2, ParametricCurve};
    /// use nalgebra::Point2;
    /// let circle = NurbsCurve2::try_circular_arc(Point2::new(1.0, 2.0), 3.0, 0.0, std::f64::consts::TAU)?;
    /// assert_eq!(circle.control_points().len(), 9);
    /// let p = circle.point(0.3)?;
    /// assert!(((p - Point2::new(1.0, 2.0)).norm() - 3.0).abs() < 1e-14);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn try_circular_arc(center: Point<T, 2>, radius: T, start: T, end: T) -> Result<Self> {
        check_points(std::slice::from_ref(&center))?;
        let r = re(radius);
        if !r.is_finite() || r <= 0.0 {
            return Err(Error::NonPositiveRadius { value: re(radius) });
        }
        check_interval(start, end)?;
        let sweep = end - start;
        // A little slack so that a full turn computed in floating point is accepted.
        if re(sweep) > std::f64::consts::TAU * (1.0 + 1e-12) {
            return Err(Error::InvalidInterval {
                start: re(start),
                end: re(end),
            });
        }
        let quarter = std::f64::consts::FRAC_PI_2 * (1.0 + 1e-12);
        let quarters = re(sweep) / quarter;
        let arcs: usize = if quarters <= 1.0 {
            1
        } else if quarters <= 2.0 {
            2
        } else if quarters <= 3.0 {
            3
        } else {
            4
        };
        let step = sweep / from_usize::<T>(arcs);
        let half = step * cst::<T>(0.5);
        let middle_weight = half.cos();
        let on_circle = |angle: T| center + Vector2::new(angle.cos(), angle.sin()) * radius;
        let mut points = Vec::with_capacity(2 * arcs + 1);
        let mut weights = Vec::with_capacity(2 * arcs + 1);
        points.push(on_circle(start));
        weights.push(T::one());
        let mut knots = vec![T::zero(); 3];
        for i in 1..=arcs {
            let angle = start + step * from_usize::<T>(i);
            let mid = angle - half;
            points.push(center + Vector2::new(mid.cos(), mid.sin()) * (radius / middle_weight));
            weights.push(middle_weight);
            points.push(on_circle(angle));
            weights.push(T::one());
            let knot = if i == arcs {
                T::one()
            } else {
                from_usize::<T>(i) / from_usize::<T>(arcs)
            };
            knots.extend([knot, knot]);
        }
        knots.push(T::one());
        Self::try_new(2, KnotVector::try_new(knots)?, points, weights)
    }
}

impl<T: Scalar, const D: usize> ParametricCurve<T, D> for NurbsCurve<T, D> {
    /// Its rational Bézier segments, one per non-empty knot span.
    fn bezier_enclosure(&self) -> Result<Option<Vec<crate::queries::RationalPiece<D>>>> {
        Ok(Some(crate::queries::pieces::nurbs_form(self)))
    }

    fn domain(&self) -> (T, T) {
        self.knots.domain(self.degree)
    }

    /// C(u) and its derivatives through homogeneous coordinates (The NURBS Book A4.2): with
    /// A(u) = Σ N_{i,p} w_i P_i and w(u) = Σ N_{i,p} w_i,
    /// C⁽ᵏ⁾ = (A⁽ᵏ⁾ − Σ_{i=1..k} binom(k, i) w⁽ⁱ⁾ C⁽ᵏ⁻ⁱ⁾) / w. Allocation-free for degrees and
    /// orders up to [`INLINE_DEGREE`].
    fn derivatives_into(&self, u: T, out: &mut [SVector<T, D>]) -> Result<()> {
        check_parameter(u, self.domain())?;
        let Some(order) = out.len().checked_sub(1) else {
            return Ok(());
        };
        let p = self.degree;
        let width = p + 1;
        // Derivatives above the degree of A and w vanish.
        let top = order.min(p);
        let span = self.knots.find_span(p, u);
        let first = span - p;
        let mut ders: SmallVec<[T; DERS_INLINE]> = smallvec![T::zero(); (top + 1) * width];
        self.knots
            .basis_function_derivatives(span, u, p, top, &mut ders);
        let points = &self.control_points[first..=span];
        let weights = &self.weights[first..=span];
        // The curve does not change when every weight is scaled alike; dividing by the span's
        // largest keeps Σ Nᵢwᵢ and its derivatives inside f64 for weights near its top
        // (weights of 1e308 evaluate like weights of 1).
        let w_top = weights
            .iter()
            .copied()
            .fold(T::zero(), |m, w| if w > m { w } else { m });
        let w_scale = if w_top > T::zero() {
            T::one() / w_top
        } else {
            T::one()
        };
        let mut wders: SmallVec<[T; INLINE_DEGREE + 1]> = smallvec![T::zero(); top + 1];
        for (k, slot) in out.iter_mut().enumerate() {
            let mut a = SVector::<T, D>::zeros();
            if k <= top {
                let row = &ders[k * width..(k + 1) * width];
                let mut w = T::zero();
                for ((&n, point), &weight) in row.iter().zip(points).zip(weights) {
                    let nw = n * (weight * w_scale);
                    a += point.coords * nw;
                    w += nw;
                }
                wders[k] = w;
            }
            *slot = a;
        }
        // Quotient rule, lowest order first so that out[k − i] already holds C⁽ᵏ⁻ⁱ⁾.
        let inv_w = T::one() / wders[0];
        for k in 0..=order {
            let mut value = out[k];
            let mut binom = T::one();
            for i in 1..=k.min(top) {
                binom = binom * from_usize::<T>(k + 1 - i) / from_usize::<T>(i);
                value -= out[k - i] * (binom * wders[i]);
            }
            out[k] = value * inv_w;
        }
        Ok(())
    }

    fn breakpoints(&self) -> Vec<T> {
        self.knots.breakpoints(self.degree)
    }
}

/// The largest ratio between a NURBS curve's largest and smallest weight: about 1/ε of
/// f64. Beyond it a small weight's term vanishes entirely next to a large one in the sums
/// Σ Nᵢwᵢ, so the curve evaluated would not be the curve described.
pub const MAX_WEIGHT_RATIO: f64 = 1e15;

/// The JSON form: `{"degree", "knots", "control_points": [[x, y], …], "weights": […]}`.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawNurbs {
    degree: usize,
    knots: Vec<f64>,
    control_points: Vec<RawPoint>,
    weights: Vec<f64>,
}

impl<const D: usize> Serialize for NurbsCurve<f64, D> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        RawNurbs {
            degree: self.degree,
            knots: self.knots.as_slice().to_vec(),
            control_points: points_to_raw(&self.control_points),
            weights: self.weights.clone(),
        }
        .serialize(serializer)
    }
}

impl<'de, const D: usize> Deserialize<'de> for NurbsCurve<f64, D> {
    /// Reads the JSON form and validates it with [`NurbsCurve::try_new`]; unknown fields and
    /// degree 0 (a file describes a continuous curve) are refused.
    fn deserialize<De: Deserializer<'de>>(
        deserializer: De,
    ) -> std::result::Result<Self, De::Error> {
        let raw = RawNurbs::deserialize(deserializer)?;
        let build = || -> Result<Self> {
            if raw.degree == 0 {
                return Err(Error::DegreeZero);
            }
            let knots = KnotVector::try_new(raw.knots)?;
            let points = points_from_raw(&raw.control_points)?;
            Self::try_new(raw.degree, knots, points, raw.weights)
        };
        build().map_err(serde::de::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use nalgebra::{Point2, Vector2};
    use std::f64::consts::FRAC_1_SQRT_2;

    fn quarter_circle() -> NurbsCurve2<f64> {
        let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]).unwrap();
        let points = vec![
            Point2::new(1.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(0.0, 1.0),
        ];
        NurbsCurve2::try_new(2, knots, points, vec![1.0, FRAC_1_SQRT_2, 1.0]).unwrap()
    }

    #[test]
    fn quarter_circle_end_derivatives_by_hand() {
        // C′(0) = p (w₁ / w₀) (P₁ − P₀) / (u_{p+1} − u₁) = 2 · (√2/2) · (0, 1) = (0, √2).
        let c = quarter_circle();
        let [p0, d0, _] = c.second_order(0.0).unwrap();
        assert_relative_eq!(p0, Vector2::new(1.0, 0.0), epsilon = 1e-15);
        assert_relative_eq!(d0, Vector2::new(0.0, 2.0_f64.sqrt()), epsilon = 1e-14);
        let d1 = c.derivative(1.0).unwrap();
        assert_relative_eq!(d1, Vector2::new(-(2.0_f64.sqrt()), 0.0), epsilon = 1e-14);
        // The midpoint is (√2/2, √2/2) by symmetry.
        let mid = c.point(0.5).unwrap();
        assert_relative_eq!(
            mid,
            Point2::new(FRAC_1_SQRT_2, FRAC_1_SQRT_2),
            epsilon = 1e-15
        );
    }

    #[test]
    fn homogeneous_round_trip() {
        let c = quarter_circle();
        let net = c.to_homogeneous();
        assert_eq!(net.dim, 3);
        assert_relative_eq!(net.coords[3], FRAC_1_SQRT_2, epsilon = 1e-16);
        assert_relative_eq!(net.coords[5], FRAC_1_SQRT_2, epsilon = 1e-16);
        let back = NurbsCurve2::try_from_homogeneous(net).unwrap();
        for (a, b) in back.control_points().iter().zip(c.control_points()) {
            assert_relative_eq!(a, b, epsilon = 1e-15);
        }
        let mut bad = c.to_homogeneous();
        bad.dim = 2;
        assert!(matches!(
            NurbsCurve2::try_from_homogeneous(bad),
            Err(Error::Dimension { expected: 3, .. })
        ));
        let mut negative = c.to_homogeneous();
        negative.coords[5] = -1.0;
        assert_eq!(
            NurbsCurve2::try_from_homogeneous(negative),
            Err(Error::NonPositiveWeight {
                index: 1,
                value: -1.0
            })
        );
    }

    #[test]
    fn empty_output_and_bad_parameters() {
        let c = quarter_circle();
        c.derivatives_into(0.5, &mut []).unwrap();
        assert!(matches!(
            c.point(1.5),
            Err(Error::ParameterOutsideDomain { .. })
        ));
        assert!(matches!(
            c.point(f64::NAN),
            Err(Error::NonFinite {
                what: "parameter",
                ..
            })
        ));
        assert!(!c.is_polynomial());
    }
}
