//! Knot insertion, refinement, splitting, Bézier decomposition, degree elevation, reversal and
//! reparameterization on B-spline control nets (The NURBS Book A5.1, A5.4, A5.6, A5.9).
//!
//! A [`ControlNet`] is the flat, dimension-agnostic form of a B-spline: degree p, knot vector
//! U = {u₀ … u_m} and n + 1 control points of `dim` coordinates each. Every operation here
//! changes the *representation* and never the curve C(u) = Σ N_{i,p}(u) P_i on its domain
//! [u_p, u_{n+1}]. Because they are linear in the control points, rational curves reuse them on
//! homogeneous coordinates (w·x, w·y, w).
//!
//! Unclamped knot vectors and any domain [a, b] are accepted; algorithms that need clamped ends
//! (A5.6, A5.9, splitting) clamp first with [`ControlNet::clamped`], which is exact.

use crate::curve::{check_interior_parameter, check_interval, check_parameter};
use crate::errors::{Error, Result};
use crate::knots::{check_new_spans, KnotVector};
use crate::scalar::{cst, re, Scalar};

/// A B-spline control net in flat form: `coords` holds `dim` coordinates per control point,
/// point after point.
///
/// The fields are public so that curve types can build and take apart nets without copies.
/// The operations expect the invariants that [`try_new`](Self::try_new) checks (see
/// [`check`](Self::check)): on a net that breaks them, fallible operations return the error and
/// infallible ones return the net unchanged (or no pieces).
///
/// ```
/// use camber_geom::knot_ops::ControlNet;
/// use camber_geom::KnotVector;
/// // A clamped quadratic on [0, 1] in one dimension: C(u) = 2u(1 − u) · 1 + u² · 2.
/// let net = ControlNet::try_new(2, KnotVector::try_new(vec![0., 0., 0., 1., 1., 1.])?, 1,
///     vec![0.0, 1.0, 2.0])?;
/// let refined = net.insert_knot(0.5, 1)?;
/// assert_eq!(refined.point_count(), 4);
/// let mut c = [0.0_f64];
/// refined.evaluate_into(0.25, &mut c)?;
/// assert!((c[0] - 0.5).abs() < 1e-15);
/// # Ok::<(), camber_geom::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ControlNet<T> {
    /// Degree p.
    pub degree: usize,
    /// The knots: control points + degree + 1 of them.
    pub knots: KnotVector<T>,
    /// Coordinates per control point (at least 1).
    pub dim: usize,
    /// `dim` coordinates per control point, point after point.
    pub coords: Vec<T>,
}

/// One Bézier piece of a decomposed net: its parameter interval [start, end] (in the net's
/// parameter) and its p + 1 Bézier control points, flat with `dim` coordinates each. On that
/// interval the net's curve is C(u) = Σ B_{i,p}(t) Q_i with t = (u − start) / (end − start).
#[derive(Debug, Clone, PartialEq)]
pub struct BezierPiece<T> {
    /// Start of the piece's interval.
    pub start: T,
    /// End of the piece's interval (> start).
    pub end: T,
    /// (p + 1) · dim coordinates.
    pub coords: Vec<T>,
}

/// # Construction
impl<T: Scalar> ControlNet<T> {
    /// Validates and builds a net (see [`check`](Self::check)).
    ///
    /// ```
    /// use camber_geom::knot_ops::ControlNet;
    /// use camber_geom::{Error, KnotVector};
    /// let knots = KnotVector::try_new(vec![0., 0., 1., 1.]).unwrap();
    /// // Three coordinates do not make whole 2D points.
    /// assert!(matches!(ControlNet::try_new(1, knots, 2, vec![0.0, 0.0, 1.0]),
    ///     Err(Error::Dimension { .. })));
    /// ```
    pub fn try_new(
        degree: usize,
        knots: KnotVector<T>,
        dim: usize,
        coords: Vec<T>,
    ) -> Result<Self> {
        let net = Self {
            degree,
            knots,
            dim,
            coords,
        };
        net.check()?;
        Ok(net)
    }

    /// Checks the invariants: `dim` ≥ 1, `coords` a whole number of points, knots finite and
    /// non-decreasing, knot count = points + degree + 1, a domain of positive length and finite
    /// coordinates.
    pub fn check(&self) -> Result<()> {
        if self.dim == 0 {
            return Err(Error::ZeroCount {
                what: "control net dimension",
            });
        }
        let rest = self.coords.len() % self.dim;
        if rest != 0 {
            return Err(Error::Dimension {
                index: self.coords.len() / self.dim,
                expected: self.dim,
                found: rest,
            });
        }
        self.knots.validate()?;
        self.knots
            .check_for(self.degree, self.coords.len() / self.dim)?;
        for (i, &c) in self.coords.iter().enumerate() {
            if !re(c).is_finite() {
                return Err(Error::NonFinite {
                    what: "control point coordinate of point",
                    index: i / self.dim,
                    value: re(c),
                });
            }
        }
        Ok(())
    }
}

impl<T: Scalar> ControlNet<T> {
    /// Number of control points, n + 1 (knots − degree − 1).
    pub fn point_count(&self) -> usize {
        self.knots
            .len()
            .saturating_sub(self.degree.saturating_add(1))
    }

    /// The `dim` coordinates of control point `i` (an empty slice when `i` is out of range).
    pub fn point(&self, i: usize) -> &[T] {
        self.coords
            .get(i * self.dim..(i + 1) * self.dim)
            .unwrap_or(&[])
    }

    /// The parametric domain [u_p, u_{n+1}]. Requires a valid net (at least 2p + 2 knots).
    pub fn domain(&self) -> (T, T) {
        self.knots.domain(self.degree)
    }

    /// Evaluates C(u) = Σ N_{i,p}(u) P_i into `out` (`dim` values). A plain reference
    /// evaluator for tests and one-off use; curve types have their own fast paths.
    pub fn evaluate_into(&self, u: T, out: &mut [T]) -> Result<()> {
        self.check()?;
        check_parameter(u, self.domain())?;
        if out.len() != self.dim {
            return Err(Error::Dimension {
                index: 0,
                expected: self.dim,
                found: out.len(),
            });
        }
        let p = self.degree;
        let span = self.knots.find_span(p, u);
        let mut basis = vec![T::zero(); p + 1];
        self.knots.basis_functions(span, u, p, &mut basis);
        out.fill(T::zero());
        for (j, &n) in basis.iter().enumerate() {
            for (o, &c) in out.iter_mut().zip(self.point(span - p + j)) {
                *o += n * c;
            }
        }
        Ok(())
    }

    /// The same curve with clamped ends: knots a and b (the domain ends) of multiplicity
    /// exactly p + 1 at both ends of the knot vector, so that the first and last control points
    /// are the curve's end points. Inserts a and b as needed (A5.1) and drops the control
    /// points and knots that do not act on the domain. The domain is unchanged.
    pub fn clamped(&self) -> Self {
        if self.check().is_err() {
            return self.clone();
        }
        let (a, b) = self.domain();
        self.raised_to_degree_multiplicity(a)
            .tail_from(a)
            .raised_to_degree_multiplicity(b)
            .head_to(b)
    }

    /// Inserts the knot u `times` times (A5.1). The curve is unchanged; the net gains `times`
    /// control points.
    ///
    /// Errors: [`Error::ParameterOutsideDomain`] (or [`Error::NonFinite`]) when u is not in
    /// the domain, [`Error::KnotMultiplicity`] when u's multiplicity plus `times` exceeds the
    /// degree, [`Error::DegenerateSpan`] when u is a new knot closer to another than
    /// [`min_span_width`](crate::knots::min_span_width), and the [`check`](Self::check) errors
    /// for an invalid net.
    pub fn insert_knot(&self, u: T, times: usize) -> Result<Self> {
        self.check()?;
        check_parameter(u, self.domain())?;
        let s = self.knots.multiplicity(u);
        if s.saturating_add(times) > self.degree {
            return Err(Error::KnotMultiplicity {
                value: re(u),
                multiplicity: s,
                times,
                degree: self.degree,
            });
        }
        if times == 0 {
            return Ok(self.clone());
        }
        check_new_spans(self.knots.as_slice(), self.domain(), &[u])?;
        Ok(self.insert_unchecked(u, times, s))
    }

    /// Inserts all of `new_knots` at once (knot refinement, A5.4). The curve is unchanged.
    ///
    /// Errors: a non-finite new knot ([`Error::NonFinite`], what = "new knot"), a decreasing
    /// sequence ([`Error::DecreasingKnots`], indices into `new_knots`), a knot outside the
    /// domain ([`Error::ParameterOutsideDomain`]), a resulting multiplicity above the degree
    /// ([`Error::KnotMultiplicity`]) and a new knot too close to another
    /// ([`Error::DegenerateSpan`]).
    pub fn refine(&self, new_knots: &[T]) -> Result<Self> {
        self.check()?;
        let domain = self.domain();
        for (index, &x) in new_knots.iter().enumerate() {
            if !re(x).is_finite() {
                return Err(Error::NonFinite {
                    what: "new knot",
                    index,
                    value: re(x),
                });
            }
            if index > 0 && x < new_knots[index - 1] {
                return Err(Error::DecreasingKnots {
                    index,
                    value: re(x),
                    previous: re(new_knots[index - 1]),
                });
            }
            check_parameter(x, domain)?;
        }
        let mut start = 0;
        while start < new_knots.len() {
            let v = new_knots[start];
            let times = new_knots[start..].iter().take_while(|&&x| x <= v).count();
            let multiplicity = self.knots.multiplicity(v);
            if multiplicity + times > self.degree {
                return Err(Error::KnotMultiplicity {
                    value: re(v),
                    multiplicity,
                    times,
                    degree: self.degree,
                });
            }
            start += times;
        }
        if new_knots.is_empty() {
            return Ok(self.clone());
        }
        check_new_spans(self.knots.as_slice(), domain, new_knots)?;
        Ok(self.refine_unchecked(new_knots))
    }

    /// Splits the curve at u, strictly inside the domain [a, b]: the left net has domain
    /// [a, u], the right one [u, b], both clamped at every end, and together they trace the
    /// original curve. The joint keeps the continuity the curve had at u.
    ///
    /// Errors: [`Error::ParameterOutsideDomain`] for u ≤ a or u ≥ b (or non-finite u), and
    /// [`Error::DegenerateSpan`] for a u closer to a knot than
    /// [`min_span_width`](crate::knots::min_span_width) (the pieces could not be evaluated).
    pub fn split(&self, u: T) -> Result<(Self, Self)> {
        self.check()?;
        let (a, b) = self.domain();
        check_interior_parameter(u, (a, b))?;
        check_new_spans(self.knots.as_slice(), (a, b), &[u])?;
        let net = self.clamped().raised_to_degree_multiplicity(u);
        Ok((net.head_to(u), net.tail_from(u)))
    }

    /// The Bézier pieces of the curve, one per non-empty knot span of the domain, in order
    /// (Bézier decomposition, A5.6, applied to the clamped net). Empty for an invalid net.
    pub fn decompose(&self) -> Vec<BezierPiece<T>> {
        if self.check().is_err() {
            return Vec::new();
        }
        let net = self.clamped();
        let (p, dim) = (net.degree, net.dim);
        let u = net.knots.as_slice();
        let m = u.len() - 1;
        let pw = &net.coords;
        let mut pieces = Vec::new();
        if p == 0 {
            for (i, pair) in u.windows(2).enumerate() {
                if pair[0] < pair[1] {
                    pieces.push(BezierPiece {
                        start: pair[0],
                        end: pair[1],
                        coords: net.point(i).to_vec(),
                    });
                }
            }
            return pieces;
        }
        let width = (p + 1) * dim;
        let mut current: Vec<T> = pw[..width].to_vec();
        let mut next = vec![T::zero(); width];
        let mut alphas = vec![T::zero(); p];
        let (mut a, mut b) = (p, p + 1);
        while b < m {
            let first = b;
            while b < m && u[b + 1] <= u[b] {
                b += 1;
            }
            let mult = b - first + 1;
            if mult < p {
                let numer = u[b] - u[a];
                for j in (mult + 1..=p).rev() {
                    alphas[j - mult - 1] = numer / (u[a + j] - u[a]);
                }
                let r = p - mult;
                for j in 1..=r {
                    let (save, s) = (r - j, mult + j);
                    for k in (s..=p).rev() {
                        blend_down(&mut current, dim, k, alphas[k - s]);
                    }
                    if b < m {
                        next[save * dim..(save + 1) * dim]
                            .copy_from_slice(&current[p * dim..width]);
                    }
                }
            }
            pieces.push(BezierPiece {
                start: u[a],
                end: u[b],
                coords: current.clone(),
            });
            if b < m {
                let keep = p.saturating_sub(mult);
                current[..keep * dim].copy_from_slice(&next[..keep * dim]);
                current[keep * dim..].copy_from_slice(&pw[(b - p + keep) * dim..(b + 1) * dim]);
                a = b;
                b += 1;
            }
        }
        pieces
    }

    /// Raises the degree by `times` without changing the curve (A5.9 on the clamped net): the
    /// result has degree p + times and every distinct knot's multiplicity grows by `times`.
    /// An interior knot of multiplicity above p (a break in the curve) is handled by elevating
    /// the pieces on either side and joining them with multiplicity p + times + 1.
    ///
    /// Fails with [`Error::DegreeTooHigh`] when p + times exceeds
    /// [`MAX_DEGREE`](crate::knots::MAX_DEGREE) (an untrusted count cannot overflow or exhaust
    /// memory).
    pub fn elevate_degree(&self, times: usize) -> Result<Self> {
        self.check()?;
        crate::knots::check_degree(self.degree.saturating_add(times))?;
        if times == 0 {
            return Ok(self.clone());
        }
        Ok(self.clamped().elevate_clamped(times))
    }

    /// The same curve traversed backwards over the same domain [a, b]: the result at
    /// a + b − u equals the original at u. Knots map by u ↦ a + (b − u) and the control points
    /// come in reverse order.
    pub fn reversed(&self) -> Self {
        if self.check().is_err() {
            return self.clone();
        }
        let (a, b) = self.domain();
        let knots = self.knots.as_slice().iter().rev().map(|&k| {
            if k <= a {
                if k < a {
                    (a + (b - k)).max(b)
                } else {
                    b
                }
            } else if k >= b {
                if k > b {
                    (a + (b - k)).min(a)
                } else {
                    a
                }
            } else {
                (a + (b - k)).max(a).min(b)
            }
        });
        let coords = self.coords.chunks_exact(self.dim).rev().flatten().copied();
        Self {
            degree: self.degree,
            knots: KnotVector::new_unchecked(knots.collect()),
            dim: self.dim,
            coords: coords.collect(),
        }
    }

    /// The same curve on the domain [a, b]: the result at a + (b − a)·s equals the original at
    /// u₀ + (u₁ − u₀)·s for s ∈ [0, 1], where [u₀, u₁] is the old domain, so derivatives scale
    /// by (u₁ − u₀) / (b − a) per order. The domain ends map exactly onto a and b.
    ///
    /// Errors: [`Error::InvalidInterval`] unless a < b, [`Error::NonFinite`],
    /// [`Error::ReparamNotRepresentable`] when the knots cannot be carried onto [a, b] in f64.
    pub fn reparameterized(&self, a: T, b: T) -> Result<Self> {
        self.check()?;
        check_interval(a, b)?;
        let (u0, u1) = self.domain();
        let scale = (b - a) / (u1 - u0);
        let knots = self.knots.as_slice().iter().map(|&k| {
            let mapped = a + (k - u0) * scale;
            if k <= u0 {
                if k < u0 {
                    mapped.min(a)
                } else {
                    a
                }
            } else if k >= u1 {
                if k > u1 {
                    mapped.max(b)
                } else {
                    b
                }
            } else {
                mapped.max(a).min(b)
            }
        });
        let knots: Vec<T> = knots.collect();
        crate::knots::check_faithful_map(self.knots.as_slice(), &knots, a, b)?;
        Ok(Self {
            degree: self.degree,
            knots: KnotVector::new_unchecked(knots),
            dim: self.dim,
            coords: self.coords.clone(),
        })
    }
}

/// Private building blocks; all assume a valid net.
impl<T: Scalar> ControlNet<T> {
    /// A5.1: inserts u (in the domain, current multiplicity s) r ≥ 1 times, s + r ≤ p.
    pub(crate) fn insert_unchecked(&self, u: T, r: usize, s: usize) -> Self {
        let (p, dim) = (self.degree, self.dim);
        let uk = self.knots.as_slice();
        // The span k with u_k ≤ u < u_{k+1}; k ≥ p because u ≥ u_p.
        let k = uk.partition_point(|&x| x <= u) - 1;
        let np = self.point_count();
        let pw = &self.coords;
        let mut q = vec![T::zero(); (np + r) * dim];
        q[..(k - p + 1) * dim].copy_from_slice(&pw[..(k - p + 1) * dim]);
        q[(k - s + r) * dim..].copy_from_slice(&pw[(k - s) * dim..]);
        let mut rw: Vec<T> = pw[(k - p) * dim..(k - s + 1) * dim].to_vec();
        for j in 1..=r {
            let l = k - p + j;
            for i in 0..=(p - j - s) {
                let alpha = (u - uk[l + i]) / (uk[i + k + 1] - uk[l + i]);
                for c in 0..dim {
                    rw[i * dim + c] =
                        alpha * rw[(i + 1) * dim + c] + (T::one() - alpha) * rw[i * dim + c];
                }
            }
            q[l * dim..(l + 1) * dim].copy_from_slice(&rw[..dim]);
            let last = k + r - j - s;
            let from = (p - j - s) * dim;
            q[last * dim..(last + 1) * dim].copy_from_slice(&rw[from..from + dim]);
        }
        let l = k - p + r;
        for i in l + 1..k - s {
            q[i * dim..(i + 1) * dim].copy_from_slice(&rw[(i - l) * dim..(i - l + 1) * dim]);
        }
        let mut knots = Vec::with_capacity(uk.len() + r);
        knots.extend_from_slice(&uk[..=k]);
        knots.extend(std::iter::repeat_n(u, r));
        knots.extend_from_slice(&uk[k + 1..]);
        Self {
            degree: p,
            knots: KnotVector::new_unchecked(knots),
            dim,
            coords: q,
        }
    }

    /// The net with u (in the domain) inserted until its multiplicity is at least p.
    fn raised_to_degree_multiplicity(&self, u: T) -> Self {
        let s = self.knots.multiplicity(u);
        if s < self.degree {
            self.insert_unchecked(u, self.degree - s, s)
        } else {
            self.clone()
        }
    }

    /// The part of the curve before u, which must have multiplicity ≥ p and lie after the
    /// domain start: the domain becomes [a, u], clamped at u.
    fn head_to(&self, u: T) -> Self {
        let (p, dim) = (self.degree, self.dim);
        let uk = self.knots.as_slice();
        let first = uk.partition_point(|&x| x < u);
        let mut knots = uk[..first + p].to_vec();
        knots.push(u);
        Self {
            degree: p,
            knots: KnotVector::new_unchecked(knots),
            dim,
            coords: self.coords[..first * dim].to_vec(),
        }
    }

    /// The part of the curve after u, which must have multiplicity ≥ p and lie before the
    /// domain end: the domain becomes [u, b], clamped at u.
    fn tail_from(&self, u: T) -> Self {
        let (p, dim) = (self.degree, self.dim);
        let uk = self.knots.as_slice();
        let last = uk.partition_point(|&x| x <= u) - 1;
        let mut knots = Vec::with_capacity(uk.len() + p + 1 - last);
        knots.push(u);
        knots.extend_from_slice(&uk[last + 1 - p..]);
        Self {
            degree: p,
            knots: KnotVector::new_unchecked(knots),
            dim,
            coords: self.coords[(last - p) * dim..].to_vec(),
        }
    }

    /// A5.4: inserts the non-decreasing knots `x` (inside the domain, multiplicities ≤ p).
    fn refine_unchecked(&self, x: &[T]) -> Self {
        let (p, dim) = (self.degree, self.dim);
        let uk = self.knots.as_slice();
        let pw = &self.coords;
        let m = uk.len() - 1;
        let n = m - p - 1;
        let r = x.len() - 1;
        let a = self.knots.find_span(p, x[0]);
        let b = self.knots.find_span(p, x[r]) + 1;
        let mut q = vec![T::zero(); (n + r + 2) * dim];
        let mut ubar = vec![T::zero(); m + r + 2];
        q[..(a - p + 1) * dim].copy_from_slice(&pw[..(a - p + 1) * dim]);
        q[(b + r) * dim..].copy_from_slice(&pw[(b - 1) * dim..]);
        ubar[..=a].copy_from_slice(&uk[..=a]);
        ubar[b + p + r + 1..].copy_from_slice(&uk[b + p..]);
        let mut i = b + p - 1;
        let mut k = b + p + r;
        for &xj in x.iter().rev() {
            while xj <= uk[i] && i > a {
                q[(k - p - 1) * dim..(k - p) * dim]
                    .copy_from_slice(&pw[(i - p - 1) * dim..(i - p) * dim]);
                ubar[k] = uk[i];
                k -= 1;
                i -= 1;
            }
            q.copy_within((k - p) * dim..(k - p + 1) * dim, (k - p - 1) * dim);
            for l in 1..=p {
                let ind = k - p + l;
                let alpha = ubar[k + l] - xj;
                if alpha <= T::zero() {
                    q.copy_within(ind * dim..(ind + 1) * dim, (ind - 1) * dim);
                } else {
                    let alpha = alpha / (ubar[k + l] - uk[i - p + l]);
                    for c in 0..dim {
                        q[(ind - 1) * dim + c] =
                            alpha * q[(ind - 1) * dim + c] + (T::one() - alpha) * q[ind * dim + c];
                    }
                }
            }
            ubar[k] = xj;
            k -= 1;
        }
        Self {
            degree: p,
            knots: KnotVector::new_unchecked(ubar),
            dim,
            coords: q,
        }
    }

    /// Degree elevation of a clamped net; splits at interior knots of multiplicity > p.
    fn elevate_clamped(&self, t: usize) -> Self {
        let p = self.degree;
        let (a, b) = self.domain();
        let uk = self.knots.as_slice();
        let break_at = uk
            .iter()
            .copied()
            .find(|&v| v > a && v < b && self.knots.multiplicity(v) > p);
        if let Some(v) = break_at {
            let ph = p + t;
            let left = self.head_to(v).elevate_clamped(t);
            let right = self.tail_from(v).elevate_clamped(t);
            let mut knots = left.knots.into_vec();
            knots.truncate(knots.len() - (ph + 1));
            knots.extend_from_slice(right.knots.as_slice());
            let mut coords = left.coords;
            coords.extend_from_slice(&right.coords);
            return Self {
                degree: ph,
                knots: KnotVector::new_unchecked(knots),
                dim: self.dim,
                coords,
            };
        }
        if p == 0 {
            // One constant span (interior knots of a degree-0 net are breaks).
            let mut knots = vec![a; t + 1];
            knots.extend(std::iter::repeat_n(b, t + 1));
            let coords = self.point(0).repeat(t + 1);
            return Self {
                degree: t,
                knots: KnotVector::new_unchecked(knots),
                dim: self.dim,
                coords,
            };
        }
        elevate_a5_9(self, t)
    }
}

/// In-place de Casteljau-style blend of flat point k with point k − 1:
/// P_k ← α P_k + (1 − α) P_{k−1}.
fn blend_down<T: Scalar>(buf: &mut [T], dim: usize, k: usize, alpha: T) {
    for c in 0..dim {
        buf[k * dim + c] = alpha * buf[k * dim + c] + (T::one() - alpha) * buf[(k - 1) * dim + c];
    }
}

/// The binomial coefficient C(n, k) as f64.
fn binomial(n: usize, k: usize) -> f64 {
    let k = k.min(n - k);
    let mut value = 1.0;
    for i in 0..k {
        #[allow(clippy::cast_precision_loss)] // small integers, exact in f64
        let (num, den) = ((n - i) as f64, (i + 1) as f64);
        value = value * num / den;
    }
    value.round()
}

/// A5.9: degree elevation by t of a clamped net of degree p ≥ 1 whose interior knots have
/// multiplicity ≤ p.
fn elevate_a5_9<T: Scalar>(net: &ControlNet<T>, t: usize) -> ControlNet<T> {
    let (p, dim) = (net.degree, net.dim);
    let uk = net.knots.as_slice();
    let pw = &net.coords;
    let m = uk.len() - 1;
    let ph = p + t;
    let ph2 = ph / 2;
    let distinct = 1 + uk.windows(2).filter(|w| w[0] < w[1]).count();
    let knot_count = m + 1 + distinct * t;
    let point_count = knot_count - ph - 1;
    // Bézier degree-elevation coefficients bez[i][j], (ph + 1) × (p + 1).
    let w = p + 1;
    let mut bez = vec![T::zero(); (ph + 1) * w];
    bez[0] = T::one();
    bez[ph * w + p] = T::one();
    for i in 1..=ph2 {
        let inv = 1.0 / binomial(ph, i);
        for j in i.saturating_sub(t)..=p.min(i) {
            bez[i * w + j] = cst(inv * binomial(p, j) * binomial(t, i - j));
        }
    }
    for i in ph2 + 1..ph {
        for j in i.saturating_sub(t)..=p.min(i) {
            bez[i * w + j] = bez[(ph - i) * w + p - j];
        }
    }
    let mut qw = vec![T::zero(); point_count * dim];
    let mut uh = vec![T::zero(); knot_count];
    let mut bpts: Vec<T> = pw[..w * dim].to_vec();
    let mut next = vec![T::zero(); w * dim];
    let mut ebpts = vec![T::zero(); (ph + 1) * dim];
    let mut alfs = vec![T::zero(); p];
    let (mut a, mut b) = (p, p + 1);
    let mut kind = ph + 1;
    let mut r: isize = -1;
    let mut cind = 1;
    let mut ua = uk[0];
    qw[..dim].copy_from_slice(&pw[..dim]);
    uh[..=ph].fill(ua);
    let one = T::one();
    while b < m {
        let first = b;
        while b < m && uk[b + 1] <= uk[b] {
            b += 1;
        }
        let mul = b - first + 1;
        let ub = uk[b];
        let oldr = r;
        r = p as isize - mul as isize;
        let lbz = if oldr > 0 { (oldr as usize + 2) / 2 } else { 1 };
        let rbz = if r > 0 {
            ph - (r as usize).div_ceil(2)
        } else {
            ph
        };
        if r > 0 {
            // Insert ub r times to isolate the Bézier segment [ua, ub].
            let numer = ub - ua;
            for k in (mul + 1..=p).rev() {
                alfs[k - mul - 1] = numer / (uk[a + k] - ua);
            }
            for j in 1..=r as usize {
                let (save, s) = (r as usize - j, mul + j);
                for k in (s..=p).rev() {
                    blend_down(&mut bpts, dim, k, alfs[k - s]);
                }
                next[save * dim..(save + 1) * dim].copy_from_slice(&bpts[p * dim..w * dim]);
            }
        }
        // Degree-elevate the Bézier segment.
        for i in lbz..=ph {
            for c in 0..dim {
                let mut sum = T::zero();
                for j in i.saturating_sub(t)..=p.min(i) {
                    sum += bez[i * w + j] * bpts[j * dim + c];
                }
                ebpts[i * dim + c] = sum;
            }
        }
        if oldr > 1 {
            // Remove the knot ua oldr − 1 times (it was inserted to isolate the segment).
            let (mut lo, mut hi) = (kind - 2, kind);
            let den = ub - ua;
            let bet = (ub - uh[kind - 1]) / den;
            for tr in 1..oldr as usize {
                let (mut i, mut j) = (lo, hi);
                let mut kj = j - kind + 1;
                while j - i > tr {
                    if i < cind {
                        let alf = (ub - uh[i]) / (ua - uh[i]);
                        for c in 0..dim {
                            qw[i * dim + c] =
                                alf * qw[i * dim + c] + (one - alf) * qw[(i - 1) * dim + c];
                        }
                    }
                    if j >= lbz {
                        let g = if (j - tr) as isize <= kind as isize - ph as isize + oldr {
                            (ub - uh[j - tr]) / den
                        } else {
                            bet
                        };
                        for c in 0..dim {
                            ebpts[kj * dim + c] =
                                g * ebpts[kj * dim + c] + (one - g) * ebpts[(kj + 1) * dim + c];
                        }
                    }
                    i += 1;
                    j -= 1;
                    kj = kj.saturating_sub(1);
                }
                lo -= 1;
                hi += 1;
            }
        }
        if a != p {
            let copies = (ph as isize - oldr) as usize;
            uh[kind..kind + copies].fill(ua);
            kind += copies;
        }
        for j in lbz..=rbz {
            qw[cind * dim..(cind + 1) * dim].copy_from_slice(&ebpts[j * dim..(j + 1) * dim]);
            cind += 1;
        }
        if b < m {
            let rr = r.max(0) as usize;
            bpts[..rr * dim].copy_from_slice(&next[..rr * dim]);
            bpts[rr * dim..].copy_from_slice(&pw[(b - p + rr) * dim..(b + 1) * dim]);
            a = b;
            b += 1;
            ua = ub;
        } else {
            uh[kind..=kind + ph].fill(ub);
        }
    }
    ControlNet {
        degree: ph,
        knots: KnotVector::new_unchecked(uh),
        dim,
        coords: qw,
    }
}
