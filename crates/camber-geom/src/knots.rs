//! Knot vectors: validated construction, the standard constructors, the parametric domain, span
//! search and multiplicities.
//!
//! A B-spline of degree p with n + 1 control points has m + 1 = n + p + 2 knots
//! U = {u₀ ≤ u₁ ≤ … ≤ u_m}. Its valid parametric domain is [u_p, u_{n+1}]; the knot vector is
//! *clamped* when the first and last p + 1 knots are equal, but nothing here requires it, and
//! the domain need not be [0, 1]. The basis functions themselves live in [`crate::basis`].

use crate::curve::check_interval;
use crate::errors::{Error, Result};
use crate::scalar::{cst, from_usize, re, Scalar};

/// The largest degree a B-spline, NURBS curve or surface may have (given or reached by degree
/// elevation). Far above any design degree (CAD works below 30); it exists so that a file
/// saying `"degree": 1000000` is refused with [`Error::DegreeTooHigh`] instead of asking for
/// (p + 1)² scratch values per evaluation.
pub const MAX_DEGREE: usize = 256;

/// A non-decreasing sequence of finite knots.
///
/// ```
/// use camber_geom::KnotVector;
/// let knots = KnotVector::clamped_uniform(3, 5).unwrap();
/// assert_eq!(knots.len(), 9);
/// assert_eq!(knots.find_span(3, 0.75), 4);
/// assert_eq!(knots.multiplicity(0.0), 4);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct KnotVector<T> {
    knots: Vec<T>,
}

/// # Construction
impl<T: Scalar> KnotVector<T> {
    /// Validates and wraps `knots`: every knot finite, the sequence non-decreasing, not empty.
    ///
    /// ```
    /// use camber_geom::{Error, KnotVector};
    /// assert!(KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0]).is_ok());
    /// assert!(matches!(KnotVector::try_new(vec![0.0, f64::NAN]), Err(Error::NonFinite { index: 1, .. })));
    /// ```
    pub fn try_new(knots: Vec<T>) -> Result<Self> {
        if knots.is_empty() {
            return Err(Error::TooFewKnots {
                degree: 0,
                needed: 2,
                found: 0,
            });
        }
        let vector = Self { knots };
        vector.validate()?;
        Ok(vector)
    }

    /// Wraps `knots` without checking that they are finite and non-decreasing. Every algorithm
    /// assumes both; violating them gives meaningless results (never undefined behaviour).
    pub fn new_unchecked(knots: Vec<T>) -> Self {
        Self { knots }
    }

    /// Checks what [`try_new`](Self::try_new) checks: every knot finite and the sequence
    /// non-decreasing. Useful for a vector built with [`new_unchecked`](Self::new_unchecked).
    pub fn validate(&self) -> Result<()> {
        let knots = &self.knots;
        for (index, &k) in knots.iter().enumerate() {
            if !re(k).is_finite() {
                return Err(Error::NonFinite {
                    what: "knot",
                    index,
                    value: re(k),
                });
            }
            if index > 0 && k < knots[index - 1] {
                return Err(Error::DecreasingKnots {
                    index,
                    value: re(k),
                    previous: re(knots[index - 1]),
                });
            }
        }
        if let (Some(&first), Some(&last)) = (knots.first(), knots.last()) {
            if !(re(last) - re(first)).is_finite() {
                return Err(Error::KnotRangeTooWide {
                    first: re(first),
                    last: re(last),
                });
            }
        }
        Ok(())
    }

    /// The knots of a Bézier curve of `degree` p on [0, 1]: p + 1 zeros then p + 1 ones, so that
    /// the B-spline basis on them is the Bernstein basis and a Bézier curve (or a line, p = 1)
    /// evaluates through the same basis code as a B-spline.
    ///
    /// ```
    /// use camber_geom::KnotVector;
    /// assert_eq!(KnotVector::<f64>::bezier(2).as_slice(), &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
    /// ```
    pub fn bezier(degree: usize) -> Self {
        let mut knots = vec![T::zero(); degree + 1];
        knots.extend(std::iter::repeat_n(T::one(), degree + 1));
        Self { knots }
    }

    /// The clamped uniform knot vector on [0, 1] for `control_points` control points of
    /// `degree`: p + 1 zeros, n − p equally spaced interior knots, p + 1 ones.
    pub fn clamped_uniform(degree: usize, control_points: usize) -> Result<Self> {
        Self::clamped_uniform_on(degree, control_points, T::zero(), T::one())
    }

    /// The clamped uniform knot vector on [a, b] (see [`clamped_uniform`](Self::clamped_uniform)).
    pub fn clamped_uniform_on(degree: usize, control_points: usize, a: T, b: T) -> Result<Self> {
        check_interval(a, b)?;
        check_enough_points(degree, control_points)?;
        let segments = control_points - degree;
        let mut knots = Vec::with_capacity(control_points + degree + 1);
        knots.extend(std::iter::repeat_n(a, degree + 1));
        for i in 1..segments {
            let t = from_usize::<T>(i) / from_usize::<T>(segments);
            knots.push(a + (b - a) * t);
        }
        knots.extend(std::iter::repeat_n(b, degree + 1));
        Ok(Self { knots })
    }

    /// The clamped knot vector for curve parameters ū₀ ≤ … ≤ ū_n (one per control point or data
    /// point) by averaging: u_{j+p} = (ū_j + … + ū_{j+p−1}) / p for j = 1 … n − p, with the end
    /// knots repeated p + 1 times. Averaging keeps the interpolation system well conditioned
    /// (every knot span holds at least one parameter).
    ///
    /// ```
    /// use camber_geom::KnotVector;
    /// let k = KnotVector::from_parameters(2, &[0.0_f64, 0.25, 0.5, 1.0]).unwrap();
    /// assert!((k.as_slice()[3] - 0.375).abs() < 1e-15);
    /// ```
    pub fn from_parameters(degree: usize, parameters: &[T]) -> Result<Self> {
        let count = parameters.len();
        check_enough_points(degree, count)?;
        let params = Self::try_new(parameters.to_vec())?;
        let (first, last) = (params.knots[0], params.knots[count - 1]);
        check_interval(first, last)?;
        let mut knots = Vec::with_capacity(count + degree + 1);
        knots.extend(std::iter::repeat_n(first, degree + 1));
        if degree > 0 {
            let inv_p = T::one() / from_usize::<T>(degree);
            for j in 1..count - degree {
                let sum = parameters[j..j + degree]
                    .iter()
                    .fold(T::zero(), |acc, &u| acc + u);
                knots.push(sum * inv_p);
            }
        } else {
            // Degree 0: one span per parameter, breaks half-way between parameters.
            for j in 1..count {
                knots.push((parameters[j - 1] + parameters[j]) * cst::<T>(0.5));
            }
        }
        knots.extend(std::iter::repeat_n(last, degree + 1));
        Ok(Self { knots })
    }
}

impl<T: Scalar> KnotVector<T> {
    /// The knots as a slice.
    pub fn as_slice(&self) -> &[T] {
        &self.knots
    }

    /// Consumes the vector and returns its knots.
    pub fn into_vec(self) -> Vec<T> {
        self.knots
    }

    /// Number of knots (m + 1).
    pub fn len(&self) -> usize {
        self.knots.len()
    }

    /// Whether there are no knots (never true for a validated vector).
    pub fn is_empty(&self) -> bool {
        self.knots.is_empty()
    }

    /// Checks that this knot vector fits `control_points` control points of `degree`:
    /// a degree of at most [`MAX_DEGREE`], at least degree + 1 control points, knot count = control points + degree + 1, and a
    /// domain of positive length.
    pub fn check_for(&self, degree: usize, control_points: usize) -> Result<()> {
        check_enough_points(degree, control_points)?;
        // degree < control_points, so degree + 1 cannot overflow; the sum can only for counts
        // no vector could hold, and then it cannot equal the knot count either.
        let expected = control_points.saturating_add(degree + 1);
        if self.knots.len() != expected {
            return Err(Error::KnotCount {
                expected,
                found: self.knots.len(),
                degree,
                control_points,
            });
        }
        let (a, b) = self.domain(degree);
        if a >= b {
            return Err(Error::EmptyDomain {
                min: re(a),
                max: re(b),
            });
        }
        self.check_multiplicities(degree)
    }

    /// Fails with [`Error::KnotMultiplicityTooHigh`] when a knot value occurs more than
    /// `degree` + 1 times.
    fn check_multiplicities(&self, degree: usize) -> Result<()> {
        let max = degree.saturating_add(1);
        let mut run = 0;
        for (i, &k) in self.knots.iter().enumerate() {
            run = if i > 0 && k <= self.knots[i - 1] {
                run + 1
            } else {
                1
            };
            if run > max {
                let value = re(k);
                return Err(Error::KnotMultiplicityTooHigh {
                    value,
                    multiplicity: self.multiplicity(k),
                    max,
                });
            }
        }
        Ok(())
    }

    /// The valid parametric domain [u_p, u_{m−p}] for `degree` p.
    ///
    /// Meaningful once [`check_for`](Self::check_for) has passed (at least 2p + 2 knots); on a
    /// shorter vector it returns the whole knot range [u₀, u_m] rather than panicking.
    pub fn domain(&self, degree: usize) -> (T, T) {
        let m = self.knots.len().saturating_sub(1);
        if self.knots.is_empty() {
            return (T::zero(), T::zero());
        }
        if degree.saturating_mul(2) > m {
            return (self.knots[0], self.knots[m]);
        }
        (self.knots[degree], self.knots[m - degree])
    }

    /// The knot span index i with u_i ≤ u < u_{i+1}, restricted to p ≤ i ≤ n (n + 1 control
    /// points), so that the p + 1 basis functions N_{i−p,p} … N_{i,p} are the ones non-zero at
    /// u (The NURBS Book A2.1). At the end of the domain, u = u_{n+1}, it returns the last
    /// non-empty span. Values outside the domain are clamped to its first or last span; callers
    /// check the domain first. Comparisons use real parts only.
    ///
    /// On a vector too short for `degree` (fewer than p + 2 knots) it returns `degree`; callers
    /// validate with [`check_for`](Self::check_for) first.
    pub fn find_span(&self, degree: usize, u: T) -> usize {
        let Some(n) = self.knots.len().checked_sub(degree.saturating_add(2)) else {
            return degree;
        };
        if n < degree {
            return degree;
        }
        // Last index whose knot is <= u, over the knots that can start a span.
        let count = self.knots[..=n + 1].partition_point(|&k| k <= u);
        let mut span = count.saturating_sub(1).clamp(degree, n);
        // At u = u_{n+1} (or beyond) step back over empty spans at the end.
        while span > degree && self.knots[span] >= self.knots[span + 1] {
            span -= 1;
        }
        span
    }

    /// [`find_span`](Self::find_span) by a walk from the span `hint` instead of a binary
    /// search: the same span, in a few steps when u lies near the hint (parameters visited in
    /// increasing order).
    pub(crate) fn find_span_from(&self, degree: usize, u: T, hint: usize) -> usize {
        let Some(n) = self.knots.len().checked_sub(degree.saturating_add(2)) else {
            return degree;
        };
        if n < degree {
            return degree;
        }
        let mut span = hint.clamp(degree, n);
        while span < n && self.knots[span + 1] <= u {
            span += 1;
        }
        while span > degree && self.knots[span] > u {
            span -= 1;
        }
        while span > degree && self.knots[span] >= self.knots[span + 1] {
            span -= 1;
        }
        span
    }

    /// How many knots equal `u` exactly.
    pub fn multiplicity(&self, u: T) -> usize {
        let lo = self.knots.partition_point(|&k| k < u);
        let hi = self.knots.partition_point(|&k| k <= u);
        hi - lo
    }

    /// The distinct knot values inside the domain of `degree`, in increasing order, both domain
    /// ends included: the breakpoints between polynomial pieces.
    pub fn breakpoints(&self, degree: usize) -> Vec<T> {
        let (a, b) = self.domain(degree);
        let mut out: Vec<T> = Vec::new();
        for &k in &self.knots {
            if k >= a && k <= b && out.last().is_none_or(|&l| k > l) {
                out.push(k);
            }
        }
        out
    }

    /// The knot vector of the reversed curve: u ↦ a + b − u over the full knot range
    /// [u₀, u_m], which maps the domain [u_p, u_{m−p}] of a clamped vector onto itself.
    pub fn reversed(&self) -> Self {
        let (Some(&first), Some(&last)) = (self.knots.first(), self.knots.last()) else {
            return self.clone();
        };
        Self {
            knots: self.knots.iter().rev().map(|&k| first + last - k).collect(),
        }
    }

    /// Whether [`KnotVector::reversed`] keeps every pair of distinct knots distinct. In f64 it
    /// need not: a knot within rounding of one end (3·10⁻¹⁹ in [0, 1]) lands exactly on the
    /// other end, where it would repeat that end's knot once too often.
    ///
    /// ```
    /// use camber_geom::KnotVector;
    /// let fine = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.3, 1.0, 1.0, 1.0])?;
    /// assert!(fine.reverses_faithfully());
    /// let tight = KnotVector::try_new(vec![0.0, 0.0, 0.0, 3e-19, 0.3, 1.0, 1.0, 1.0])?;
    /// assert!(!tight.reverses_faithfully());
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn reverses_faithfully(&self) -> bool {
        let reversed = self.reversed();
        self.knots
            .windows(2)
            .rev()
            .zip(reversed.knots.windows(2))
            .all(|(o, n)| (o[0] < o[1]) == (n[0] < n[1]))
    }

    /// The knot vector mapped affinely so that the domain of `degree` becomes [a, b].
    pub fn reparameterized(&self, degree: usize, a: T, b: T) -> Result<Self> {
        check_interval(a, b)?;
        let (u0, u1) = self.domain(degree);
        let scale = (b - a) / (u1 - u0);
        let knots: Vec<T> = self.knots.iter().map(|&k| a + (k - u0) * scale).collect();
        check_faithful_map(&self.knots, &knots, a, b)?;
        Ok(Self { knots })
    }
}

/// Fails with [`Error::ReparamNotRepresentable`] unless `new` (the knots `old` mapped onto
/// [a, b]) keeps every knot finite, the span a normal f64 (neither overflowing nor
/// subnormal, where parameters lose their digits), the order, and distinct knots distinct:
/// otherwise the curve they carry would change shape.
pub(crate) fn check_faithful_map<T: Scalar>(old: &[T], new: &[T], a: T, b: T) -> Result<()> {
    let finite = new.iter().all(|&k| re(k).is_finite())
        && new
            .first()
            .zip(new.last())
            .is_none_or(|(&f, &l)| (re(l) - re(f)).is_normal());
    let same_order = old
        .windows(2)
        .zip(new.windows(2))
        .all(|(o, n)| (o[0] < o[1]) == (n[0] < n[1]) && n[0] <= n[1]);
    if finite && same_order {
        Ok(())
    } else {
        Err(Error::ReparamNotRepresentable {
            start: re(a),
            end: re(b),
        })
    }
}

/// The narrowest knot span a split or knot insertion may create on the domain [a, b]:
/// [`MIN_SPAN_ULPS`] ulps of the largest of |a|, |b| and b − a. A narrower span holds too few
/// distinct f64 parameters for the basis functions, which divide by knot differences, to be
/// evaluated across it (a span of 5·10⁻³²⁴ makes every point on it NaN).
///
/// ```
/// use camber_geom::knots::min_span_width;
/// assert!((min_span_width(0.0, 1.0) - 64.0 * f64::EPSILON).abs() < 1e-30);
/// assert!(min_span_width(1e6, 1e6 + 1.0) > 1e-8);
/// ```
pub fn min_span_width(a: f64, b: f64) -> f64 {
    MIN_SPAN_ULPS * f64::EPSILON * a.abs().max(b.abs()).max(b - a)
}

/// See [`min_span_width`].
pub const MIN_SPAN_ULPS: f64 = 64.0;

/// Fails with [`Error::DegenerateSpan`] when inserting the new knot values `new` (sorted)
/// into `knots` on the domain [a, b] would make a span narrower than [`min_span_width`]: a new
/// value must be an existing knot or lie at least that far from every other knot value, old
/// or new.
pub(crate) fn check_new_spans<T: Scalar>(knots: &[T], (a, b): (T, T), new: &[T]) -> Result<()> {
    let min = min_span_width(re(a), re(b));
    let mut previous: Option<f64> = None;
    for (i, &u) in new.iter().enumerate() {
        let v = re(u);
        if previous.is_some_and(|p| p >= v) {
            continue;
        }
        previous = Some(v);
        let at = knots.partition_point(|&k| k < u);
        if knots.get(at).is_some_and(|&k| k <= u) {
            continue; // an existing knot: no new span
        }
        let below = at.checked_sub(1).map(|i| re(knots[i]));
        let above = knots.get(at).map(|&k| re(k));
        let next_new = new[i + 1..].iter().map(|&x| re(x)).find(|&x| x > v);
        let neighbours = [below, above, next_new];
        for w in neighbours.into_iter().flatten() {
            let width = (v - w).abs();
            if width < min {
                return Err(Error::DegenerateSpan {
                    value: v,
                    width,
                    min,
                });
            }
        }
    }
    Ok(())
}

/// Fails with [`Error::DegreeTooHigh`] when `degree` exceeds [`MAX_DEGREE`].
pub(crate) fn check_degree(degree: usize) -> Result<()> {
    if degree > MAX_DEGREE {
        return Err(Error::DegreeTooHigh {
            degree,
            max: MAX_DEGREE,
        });
    }
    Ok(())
}

/// Fails with [`Error::DegreeTooHigh`] above [`MAX_DEGREE`] and with
/// [`Error::TooFewControlPoints`] unless `control_points` ≥ `degree` + 1, without
/// overflowing for any degree (a file may say `"degree": 18446744073709551615`).
fn check_enough_points(degree: usize, control_points: usize) -> Result<()> {
    check_degree(degree)?;
    if control_points <= degree {
        return Err(Error::TooFewControlPoints {
            degree,
            needed: degree.saturating_add(1),
            found: control_points,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn a_span_walk_from_any_hint_finds_the_searched_span() {
        // Repeated interior knots (4, 4) and clamped ends: every hint, parameters on and
        // between knots, both domain ends.
        let k = KnotVector::try_new(vec![0., 0., 0., 1., 2., 3., 4., 4., 5., 5., 5.]).unwrap();
        for step in 0..=50 {
            let u = f64::from(step) / 10.0;
            for hint in 0..12 {
                assert_eq!(
                    k.find_span_from(2, u, hint),
                    k.find_span(2, u),
                    "u {u}, hint {hint}"
                );
            }
        }
    }

    #[test]
    fn span_search_matches_a_linear_scan() {
        // The NURBS Book example 2.3: U = {0,0,0,1,2,3,4,4,5,5,5}, p = 2.
        let k = KnotVector::try_new(vec![0., 0., 0., 1., 2., 3., 4., 4., 5., 5., 5.]).unwrap();
        assert_eq!(k.find_span(2, 2.5), 4);
        assert_eq!(k.find_span(2, 0.0), 2);
        assert_eq!(k.find_span(2, 4.0), 7);
        assert_eq!(k.find_span(2, 5.0), 7);
        assert_eq!(k.find_span(2, 1.0), 3);
        assert_eq!(k.multiplicity(4.0), 2);
        assert_eq!(k.multiplicity(5.0), 3);
        assert_eq!(k.multiplicity(2.5), 0);
        assert_eq!(k.breakpoints(2), vec![0., 1., 2., 3., 4., 5.]);
    }

    #[test]
    fn unclamped_domain_and_spans() {
        let k = KnotVector::try_new(vec![0., 1., 2., 3., 4., 5., 6., 7.]).unwrap();
        // p = 3, n + 1 = 4 control points: domain [u3, u4] = [3, 4].
        k.check_for(3, 4).unwrap();
        assert_eq!(k.domain(3), (3.0, 4.0));
        assert_eq!(k.find_span(3, 3.0), 3);
        assert_eq!(k.find_span(3, 4.0), 3);
    }

    #[test]
    fn validation_errors_name_the_knot() {
        assert_eq!(
            KnotVector::try_new(vec![0.0, 1.0, 0.5]),
            Err(Error::DecreasingKnots {
                index: 2,
                value: 0.5,
                previous: 1.0
            })
        );
        let k = KnotVector::try_new(vec![0., 0., 1., 1.]).unwrap();
        assert_eq!(
            k.check_for(1, 3),
            Err(Error::KnotCount {
                expected: 5,
                found: 4,
                degree: 1,
                control_points: 3
            })
        );
        let flat = KnotVector::try_new(vec![1., 1., 1., 1.]).unwrap();
        assert!(matches!(
            flat.check_for(1, 2),
            Err(Error::EmptyDomain { .. })
        ));
    }

    #[test]
    fn short_vectors_do_not_panic() {
        let k = KnotVector::try_new(vec![0.0, 1.0]).unwrap();
        assert_eq!(k.find_span(3, 0.5), 3);
        assert_eq!(k.domain(3), (0.0, 1.0));
        assert!(matches!(
            k.check_for(3, 1),
            Err(Error::TooFewControlPoints { .. })
        ));
    }

    #[test]
    fn averaging_and_uniform_constructors() {
        let k = KnotVector::from_parameters(3, &[0.0, 0.1, 0.3, 0.6, 1.0]).unwrap();
        // One interior knot: (0.1 + 0.3 + 0.6) / 3.
        assert_relative_eq!(k.as_slice()[4], 1.0 / 3.0, epsilon = 1e-15);
        assert_eq!(k.len(), 9);
        let u = KnotVector::<f64>::clamped_uniform_on(2, 5, -1.0, 2.0).unwrap();
        let expected = [-1., -1., -1., 0., 1., 2., 2., 2.];
        for (a, b) in u.as_slice().iter().zip(expected) {
            assert_relative_eq!(*a, b, epsilon = 1e-15);
        }
        let r = u.reversed();
        for (a, b) in r.as_slice().iter().zip(expected) {
            assert_relative_eq!(*a, b, epsilon = 1e-15);
        }
        let m = u.reparameterized(2, 0.0, 1.0).unwrap();
        assert_relative_eq!(m.as_slice()[3], 1.0 / 3.0, epsilon = 1e-15);
    }
}
