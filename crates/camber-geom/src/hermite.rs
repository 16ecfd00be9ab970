//! Cubic Hermite (parametric cubic, "PC") curves.
//!
//! A cubic Hermite curve on u ∈ [0, 1] is fixed by its two end points and its two end tangent
//! vectors, the *geometric form* B = [p0, p1, t0, t1] (rows are points or vectors of D
//! coordinates). With the monomial row U = [u³, u², u, 1] and the Hermite basis matrix
//!
//! ```text
//!         ⎡  2  −2   1   1 ⎤
//!     M = ⎢ −3   3  −2  −1 ⎥
//!         ⎢  0   0   1   0 ⎥
//!         ⎣  1   0   0   0 ⎦
//! ```
//!
//! the curve is p(u) = U·M·B = F(u)·B, where F = U·M = [F1, F2, F3, F4] are the blending
//! functions ([`blending_functions`]). The *algebraic form* A = M·B = [a3, a2, a1, a0] holds the
//! polynomial coefficients, p(u) = a3·u³ + a2·u² + a1·u + a0. Derivatives follow by
//! differentiating U (or F): p′ = U′·M·B, p″ = U″·M·B, p‴ = 6·a3, and zero above.
//!
//! Tangent vectors are *not* unit vectors: they carry length units per unit of u, and their
//! magnitudes shape the curve. Reparameterizing a piece [ui, uj] to [0, 1] therefore scales
//! them by (uj − ui) ([`HermiteCurve::truncated`], [`HermiteCurve::subdivided`]).
//!
//! A cubic Hermite curve is a cubic Bézier curve in another basis:
//! P0 = p0, P1 = p0 + t0/3, P2 = p1 − t1/3, P3 = p1 ([`HermiteCurve::to_bezier`]).

use nalgebra::{Matrix4, Point, SVector};
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::bezier::BezierCurve;
use crate::curve::{check_parameter, check_points, ParametricCurve};
use crate::errors::{Error, Result};
use crate::scalar::{cst, from_usize, re, Scalar};
use crate::serde_support::{point_from_raw, point_to_raw, vector_from_raw, vector_to_raw};

/// The Hermite basis matrix M (row-major), mapping the geometric form B = [p0, p1, t0, t1] to the
/// algebraic form A = M·B = [a3, a2, a1, a0]. Column j of row i is the coefficient of u^(3−i)
/// in the blending function F_{j+1}.
pub const HERMITE_BASIS: [[f64; 4]; 4] = [
    [2.0, -2.0, 1.0, 1.0],
    [-3.0, 3.0, -2.0, -1.0],
    [0.0, 0.0, 1.0, 0.0],
    [1.0, 0.0, 0.0, 0.0],
];

/// The Hermite basis matrix M ([`HERMITE_BASIS`]) as an nalgebra matrix in the scalar type `T`.
///
/// ```
/// use camber_geom::hermite::hermite_basis_matrix;
/// use nalgebra::{Matrix4, RowVector4};
/// let m: Matrix4<f64> = hermite_basis_matrix();
/// // U·M at u = 1/2 gives the blending functions F(1/2) = (1/2, 1/2, 1/8, −1/8).
/// let u = 0.5_f64;
/// let f = RowVector4::new(u * u * u, u * u, u, 1.0) * m;
/// assert!((f[0] - 0.5).abs() < 1e-15 && (f[3] + 0.125).abs() < 1e-15);
/// ```
pub fn hermite_basis_matrix<T: Scalar>() -> Matrix4<T> {
    // `from_fn` visits i, j < 4 only, so the indexing cannot fail.
    Matrix4::from_fn(|i, j| cst(HERMITE_BASIS[i][j]))
}

/// The Hermite blending functions F(u) = U·M = [F1, F2, F3, F4] (dimensionless):
///
/// F1 = 2u³ − 3u² + 1, F2 = −2u³ + 3u², F3 = u³ − 2u² + u, F4 = u³ − u²,
///
/// the weights of p0, p1, t0 and t1 in p(u). They are polynomials defined for every u; the
/// curve uses them on [0, 1], where F1 + F2 = 1.
///
/// ```
/// use camber_geom::hermite::blending_functions;
/// let f = blending_functions(0.25_f64);
/// assert!((f[0] + f[1] - 1.0).abs() < 1e-15);
/// assert!((f[2] - 9.0 / 64.0).abs() < 1e-15);
/// ```
pub fn blending_functions<T: Scalar>(u: T) -> [T; 4] {
    let one = T::one();
    let two = cst::<T>(2.0);
    let three = cst::<T>(3.0);
    let u2 = u * u;
    let um1 = u - one;
    [
        u2 * (two * u - three) + one,
        u2 * (three - two * u),
        u * um1 * um1,
        u2 * um1,
    ]
}

/// First derivatives of the blending functions with respect to u (units 1/u):
///
/// F1′ = 6u² − 6u, F2′ = −6u² + 6u, F3′ = 3u² − 4u + 1, F4′ = 3u² − 2u.
///
/// ```
/// use camber_geom::hermite::blending_first_derivatives;
/// let d = blending_first_derivatives(0.0_f64);
/// assert!(d[0].abs() < 1e-15 && (d[2] - 1.0).abs() < 1e-15 && d[3].abs() < 1e-15);
/// ```
pub fn blending_first_derivatives<T: Scalar>(u: T) -> [T; 4] {
    let one = T::one();
    let two = cst::<T>(2.0);
    let three = cst::<T>(3.0);
    let six = cst::<T>(6.0);
    let a = six * u * (u - one);
    [a, -a, (three * u - one) * (u - one), u * (three * u - two)]
}

/// Second derivatives of the blending functions with respect to u (units 1/u²):
///
/// F1″ = 12u − 6, F2″ = −12u + 6, F3″ = 6u − 4, F4″ = 6u − 2.
///
/// ```
/// use camber_geom::hermite::blending_second_derivatives;
/// let d = blending_second_derivatives(1.0_f64);
/// assert!((d[0] - 6.0).abs() < 1e-15 && (d[3] - 4.0).abs() < 1e-15);
/// ```
pub fn blending_second_derivatives<T: Scalar>(u: T) -> [T; 4] {
    let six = cst::<T>(6.0);
    let twelve = cst::<T>(12.0);
    let a = twelve * u - six;
    [a, -a, six * u - cst::<T>(4.0), six * u - cst::<T>(2.0)]
}

/// Third derivatives of the blending functions (constants, units 1/u³): [12, −12, 6, 6]. All
/// higher derivatives are zero.
pub fn blending_third_derivatives<T: Scalar>() -> [T; 4] {
    [cst(12.0), cst(-12.0), cst(6.0), cst(6.0)]
}

/// The combination Σ wₖ·bₖ of four vectors.
fn combine<T: Scalar, const D: usize>(w: [T; 4], b: &[SVector<T, D>; 4]) -> SVector<T, D> {
    w.iter()
        .zip(b.iter())
        .fold(SVector::<T, D>::zeros(), |acc, (&wk, bk)| acc + bk * wk)
}

/// Checks that every coordinate of every vector is finite; the error names the vector index.
fn check_vectors<T: Scalar, const D: usize>(
    vectors: &[SVector<T, D>],
    what: &'static str,
) -> Result<()> {
    for (index, v) in vectors.iter().enumerate() {
        if let Some(&c) = v.iter().find(|c| !re(**c).is_finite()) {
            return Err(Error::NonFinite {
                what,
                index,
                value: re(c),
            });
        }
    }
    Ok(())
}

/// The most pieces [`HermiteCurve::subdivided`] makes (a million pieces are 64 MB of planar
/// curves; a count from outside above it is refused before allocating).
pub const MAX_SUBDIVISIONS: usize = 1 << 20;

/// A cubic Hermite curve p(u) = U·M·B on u ∈ [0, 1], with geometric form B = [p0, p1, t0, t1]:
/// p(0) = p0, p(1) = p1, p′(0) = t0, p′(1) = t1 (tangents in length units per unit of u).
///
/// ```
/// use camber_geom::{HermiteCurve2, ParametricCurve};
/// use nalgebra::{Point2, Vector2};
/// let c = HermiteCurve2::<f64>::try_new(
///     Point2::new(0.0, 0.0),
///     Point2::new(1.0, 0.0),
///     Vector2::new(0.0, 3.0),
///     Vector2::new(0.0, -3.0),
/// )?;
/// let (p, d) = c.point_and_derivative(0.5)?;
/// // p(1/2) = (p0 + p1)/2 + (t0 − t1)/8; p′(1/2) = 1.5 (p1 − p0) − (t0 + t1)/4.
/// assert!((p.x - 0.5).abs() < 1e-15 && (p.y - 0.75).abs() < 1e-15);
/// assert!((d.x - 1.5).abs() < 1e-15 && d.y.abs() < 1e-15);
/// # Ok::<(), camber_geom::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct HermiteCurve<T: Scalar, const D: usize> {
    p0: Point<T, D>,
    p1: Point<T, D>,
    t0: SVector<T, D>,
    t1: SVector<T, D>,
}

/// A planar cubic Hermite curve.
pub type HermiteCurve2<T> = HermiteCurve<T, 2>;
/// A spatial cubic Hermite curve.
pub type HermiteCurve3<T> = HermiteCurve<T, 3>;

/// # Construction
impl<T: Scalar, const D: usize> HermiteCurve<T, D> {
    /// The curve from p(0) = `p0` to p(1) = `p1` with end tangent vectors p′(0) = `t0` and
    /// p′(1) = `t1`. Every coordinate must be finite: [`Error::NonFinite`] names the point
    /// (0 for p0, 1 for p1) or the tangent (0 for t0, 1 for t1). Zero tangents are allowed.
    ///
    /// ```
    /// use camber_geom::{Error, HermiteCurve2};
    /// use nalgebra::{Point2, Vector2};
    /// let (a, b) = (Point2::new(0.0, 0.0), Point2::new(1.0, 1.0));
    /// assert!(HermiteCurve2::try_new(a, b, Vector2::x(), Vector2::y()).is_ok());
    /// let bad = HermiteCurve2::try_new(a, b, Vector2::x(), Vector2::new(f64::NAN, 0.0));
    /// assert!(matches!(bad, Err(Error::NonFinite { index: 1, .. })));
    /// ```
    pub fn try_new(
        p0: Point<T, D>,
        p1: Point<T, D>,
        t0: SVector<T, D>,
        t1: SVector<T, D>,
    ) -> Result<Self> {
        check_points(&[p0, p1])?;
        check_vectors(&[t0, t1], "coordinate of end tangent")?;
        Ok(Self { p0, p1, t0, t1 })
    }

    /// The curve with algebraic form A = [a3, a2, a1, a0], p(u) = a3·u³ + a2·u² + a1·u + a0.
    /// Inverting A = M·B gives p0 = a0, p1 = a3 + a2 + a1 + a0, t0 = a1,
    /// t1 = 3·a3 + 2·a2 + a1. [`Error::NonFinite`] names the coefficient index in `a`.
    ///
    /// ```
    /// use camber_geom::HermiteCurve2;
    /// use nalgebra::Vector2;
    /// // p(u) = (u, u³)
    /// let a = [Vector2::new(0.0, 1.0), Vector2::zeros(), Vector2::new(1.0, 0.0), Vector2::zeros()];
    /// let c = HermiteCurve2::<f64>::from_algebraic(a)?;
    /// assert!((c.p1().y - 1.0).abs() < 1e-15 && (c.t1().y - 3.0).abs() < 1e-15);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn from_algebraic(a: [SVector<T, D>; 4]) -> Result<Self> {
        check_vectors(&a, "coordinate of algebraic coefficient")?;
        let [a3, a2, a1, a0] = a;
        let two = cst::<T>(2.0);
        let three = cst::<T>(3.0);
        Self::try_new(
            Point::from(a0),
            Point::from(a3 + a2 + a1 + a0),
            a1,
            a3 * three + a2 * two + a1,
        )
    }

    /// The Hermite form of a cubic Bézier curve with control points P0 … P3:
    /// p0 = P0, p1 = P3, t0 = 3(P1 − P0), t1 = 3(P3 − P2). Any other degree is
    /// [`Error::DegreeMismatch`].
    ///
    /// ```
    /// use camber_geom::{BezierCurve, HermiteCurve};
    /// use nalgebra::Point2;
    /// let b = BezierCurve::try_new(vec![
    ///     Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(2.0, 1.0), Point2::new(3.0, 0.0),
    /// ])?;
    /// let h = HermiteCurve::<f64, 2>::from_bezier(&b)?;
    /// assert!((h.t0().x - 3.0).abs() < 1e-15 && (h.t1().y + 3.0).abs() < 1e-15);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn from_bezier(bezier: &BezierCurve<T, D>) -> Result<Self> {
        let mismatch = Error::DegreeMismatch {
            expected: 3,
            found: bezier.degree(),
        };
        let [c0, c1, c2, c3]: [Point<T, D>; 4] =
            bezier.control_points().try_into().map_err(|_| mismatch)?;
        let three = cst::<T>(3.0);
        Self::try_new(c0, c3, (c1 - c0) * three, (c3 - c2) * three)
    }
}

/// # Accessors and forms
impl<T: Scalar, const D: usize> HermiteCurve<T, D> {
    /// The start point p0 = p(0).
    pub fn p0(&self) -> Point<T, D> {
        self.p0
    }

    /// The end point p1 = p(1).
    pub fn p1(&self) -> Point<T, D> {
        self.p1
    }

    /// The start tangent vector t0 = p′(0) (length units per unit of u).
    pub fn t0(&self) -> SVector<T, D> {
        self.t0
    }

    /// The end tangent vector t1 = p′(1) (length units per unit of u).
    pub fn t1(&self) -> SVector<T, D> {
        self.t1
    }

    /// The geometric form B = [p0, p1, t0, t1], the points as position vectors.
    pub fn geometric(&self) -> [SVector<T, D>; 4] {
        [self.p0.coords, self.p1.coords, self.t0, self.t1]
    }

    /// The algebraic form A = M·B = [a3, a2, a1, a0], the coefficients of
    /// p(u) = a3·u³ + a2·u² + a1·u + a0.
    ///
    /// ```
    /// use camber_geom::HermiteCurve2;
    /// use nalgebra::{Point2, Vector2};
    /// let c = HermiteCurve2::<f64>::try_new(Point2::origin(), Point2::new(1.0, 0.0), Vector2::x(), Vector2::x())?;
    /// let [a3, a2, a1, a0] = c.algebraic();
    /// // A straight line traversed at unit speed: p(u) = (u, 0).
    /// assert!(a3.norm() < 1e-15 && a2.norm() < 1e-15 && (a1.x - 1.0).abs() < 1e-15 && a0.norm() < 1e-15);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn algebraic(&self) -> [SVector<T, D>; 4] {
        let b = self.geometric();
        HERMITE_BASIS.map(|row| combine(row.map(cst::<T>), &b))
    }

    /// The same curve as a cubic Bézier curve: P0 = p0, P1 = p0 + t0/3, P2 = p1 − t1/3,
    /// P3 = p1. Fails only if the control points overflow to non-finite values.
    ///
    /// ```
    /// use camber_geom::{HermiteCurve2, ParametricCurve};
    /// use nalgebra::{Point2, Vector2};
    /// let h = HermiteCurve2::try_new(Point2::origin(), Point2::new(3.0, 0.0), Vector2::new(3.0, 3.0), Vector2::new(3.0, -3.0))?;
    /// let b = h.to_bezier()?;
    /// assert_eq!(b.degree(), 3);
    /// assert!((b.control_points()[1] - Point2::new(1.0, 1.0)).norm() < 1e-15);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn to_bezier(&self) -> Result<BezierCurve<T, D>> {
        let third = T::one() / cst::<T>(3.0);
        BezierCurve::try_new(vec![
            self.p0,
            self.p0 + self.t0 * third,
            self.p1 - self.t1 * third,
            self.p1,
        ])
    }
}

/// # Reparameterization, truncation and subdivision
impl<T: Scalar, const D: usize> HermiteCurve<T, D> {
    /// The same curve traversed backwards, q(v) = p(1 − v): q0 = p1, q1 = p0, q0′ = −t1,
    /// q1′ = −t0.
    ///
    /// ```
    /// use camber_geom::{HermiteCurve2, ParametricCurve};
    /// use nalgebra::{Point2, Vector2};
    /// let c = HermiteCurve2::try_new(Point2::origin(), Point2::new(2.0, 1.0), Vector2::x(), Vector2::y())?;
    /// let r = c.reversed();
    /// assert!((r.point(0.3)? - c.point(0.7)?).norm() < 1e-14);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn reversed(&self) -> Self {
        Self {
            p0: self.p1,
            p1: self.p0,
            t0: -self.t1,
            t1: -self.t0,
        }
    }

    /// The piece of the curve over [ui, uj] reparameterized to [0, 1], q(v) = p(ui + (uj − ui)v):
    /// q0 = p(ui), q1 = p(uj), q0′ = (uj − ui)·p′(ui), q1′ = (uj − ui)·p′(uj).
    ///
    /// Both parameters must be finite and in [0, 1] ([`Error::ParameterOutsideDomain`]) with
    /// ui < uj ([`Error::InvalidInterval`]).
    ///
    /// ```
    /// use camber_geom::{HermiteCurve2, ParametricCurve};
    /// use nalgebra::{Point2, Vector2};
    /// let c = HermiteCurve2::try_new(Point2::origin(), Point2::new(2.0, 1.0), Vector2::x(), Vector2::y())?;
    /// let piece = c.truncated(0.2, 0.7)?;
    /// assert!((piece.point(0.5)? - c.point(0.45)?).norm() < 1e-14);
    /// assert!(c.truncated(0.7, 0.2).is_err());
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn truncated(&self, ui: T, uj: T) -> Result<Self> {
        check_parameter(ui, self.domain())?;
        check_parameter(uj, self.domain())?;
        if ui >= uj {
            return Err(Error::InvalidInterval {
                start: re(ui),
                end: re(uj),
            });
        }
        let (qi, di) = self.point_and_tangent(ui);
        let (qj, dj) = self.point_and_tangent(uj);
        let h = uj - ui;
        Self::try_new(qi, qj, di * h, dj * h)
    }

    /// The curve cut into `n` pieces of equal parameter length 1/n, each reparameterized to
    /// [0, 1]: piece i (1-based) has B_i = [p((i−1)/n), p(i/n), p′((i−1)/n)/n, p′(i/n)/n].
    /// `n` = 0 is [`Error::ZeroCount`], `n` above [`MAX_SUBDIVISIONS`] [`Error::TooLarge`]
    /// (checked before anything is allocated).
    ///
    /// ```
    /// use camber_geom::{HermiteCurve2, ParametricCurve};
    /// use nalgebra::{Point2, Vector2};
    /// let c = HermiteCurve2::try_new(Point2::origin(), Point2::new(2.0, 1.0), Vector2::x(), Vector2::y())?;
    /// let pieces = c.subdivided(4)?;
    /// assert_eq!(pieces.len(), 4);
    /// assert!((pieces[2].point(0.5)? - c.point(0.625)?).norm() < 1e-14);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn subdivided(&self, n: usize) -> Result<Vec<Self>> {
        if n == 0 {
            return Err(Error::ZeroCount { what: "segments" });
        }
        if n > MAX_SUBDIVISIONS {
            return Err(Error::TooLarge {
                what: "segments",
                value: n,
                max: MAX_SUBDIVISIONS,
            });
        }
        let nt = from_usize::<T>(n);
        let h = T::one() / nt;
        let params = (0..=n).map(|i| from_usize::<T>(i) / nt);
        self.pieces_between(params, |_, _| h)
    }

    /// The curve cut at the interior parameters `joints` = [u1, …, u_{n−1}] into n pieces, each
    /// reparameterized to [0, 1]. With u0 = 0 and u_n = 1, piece i (1-based) has
    /// B_i = [p(u_{i−1}), p(u_i), (u_i − u_{i−1})·p′(u_{i−1}), (u_i − u_{i−1})·p′(u_i)].
    ///
    /// Each joint must be finite and in [0, 1] ([`Error::ParameterOutsideDomain`]), and
    /// 0 < u1 < … < u_{n−1} < 1 ([`Error::InvalidInterval`] names the first empty piece). No
    /// joints gives the curve itself as the only piece.
    ///
    /// ```
    /// use camber_geom::{HermiteCurve2, ParametricCurve};
    /// use nalgebra::{Point2, Vector2};
    /// let c = HermiteCurve2::try_new(Point2::origin(), Point2::new(2.0, 1.0), Vector2::x(), Vector2::y())?;
    /// let pieces = c.subdivided_at(&[0.25, 0.5])?;
    /// assert_eq!(pieces.len(), 3);
    /// assert!((pieces[2].point(0.5)? - c.point(0.75)?).norm() < 1e-14);
    /// assert!(c.subdivided_at(&[0.5, 0.5]).is_err());
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn subdivided_at(&self, joints: &[T]) -> Result<Vec<Self>> {
        let mut previous = T::zero();
        for &u in joints {
            check_parameter(u, self.domain())?;
            if u <= previous {
                return Err(Error::InvalidInterval {
                    start: re(previous),
                    end: re(u),
                });
            }
            previous = u;
        }
        if previous >= T::one() {
            return Err(Error::InvalidInterval {
                start: re(previous),
                end: 1.0,
            });
        }
        let params = std::iter::once(T::zero())
            .chain(joints.iter().copied())
            .chain(std::iter::once(T::one()));
        self.pieces_between(params, |a, b| b - a)
    }

    /// The pieces between consecutive parameters of the increasing sequence `params` (checked by
    /// the caller); the piece over [a, b] scales its tangents by `length(a, b)`.
    fn pieces_between(
        &self,
        params: impl Iterator<Item = T>,
        length: impl Fn(T, T) -> T,
    ) -> Result<Vec<Self>> {
        let mut pieces = Vec::new();
        let mut start: Option<(T, Point<T, D>, SVector<T, D>)> = None;
        for u in params {
            let (q, d) = self.point_and_tangent(u);
            if let Some((a, q0, d0)) = start {
                let h = length(a, u);
                pieces.push(Self::try_new(q0, q, d0 * h, d * h)?);
            }
            start = Some((u, q, d));
        }
        Ok(pieces)
    }

    /// p(u) and p′(u) without the domain check (callers have checked u).
    fn point_and_tangent(&self, u: T) -> (Point<T, D>, SVector<T, D>) {
        let b = self.geometric();
        (
            Point::from(combine(blending_functions(u), &b)),
            combine(blending_first_derivatives(u), &b),
        )
    }
}

impl<T: Scalar, const D: usize> ParametricCurve<T, D> for HermiteCurve<T, D> {
    /// Its cubic Bézier form on [0, 1].
    fn bezier_enclosure(&self) -> Result<Option<Vec<crate::queries::RationalPiece<D>>>> {
        Ok(crate::queries::pieces::hermite_form(self))
    }

    /// Always [0, 1].
    fn domain(&self) -> (T, T) {
        (T::zero(), T::one())
    }

    /// p⁽ᵏ⁾(u) = F⁽ᵏ⁾(u)·B for k ≤ 3 (F⁽ᵏ⁾ = U⁽ᵏ⁾·M, see the blending function helpers) and zero
    /// for k > 3; u must lie in [0, 1].
    fn derivatives_into(&self, u: T, out: &mut [SVector<T, D>]) -> Result<()> {
        check_parameter(u, self.domain())?;
        let b = self.geometric();
        for (k, slot) in out.iter_mut().enumerate() {
            *slot = match k {
                0 => combine(blending_functions(u), &b),
                1 => combine(blending_first_derivatives(u), &b),
                2 => combine(blending_second_derivatives(u), &b),
                3 => combine(blending_third_derivatives(), &b),
                _ => SVector::<T, D>::zeros(),
            };
        }
        Ok(())
    }
}

/// The JSON form: `{"p0": [..], "p1": [..], "t0": [..], "t1": [..]}`, D coordinates each.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawHermite {
    p0: Vec<f64>,
    p1: Vec<f64>,
    t0: Vec<f64>,
    t1: Vec<f64>,
}

/// Serializes as `{"p0": [x, y, …], "p1": […], "t0": […], "t1": […]}`.
impl<const D: usize> Serialize for HermiteCurve<f64, D> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        RawHermite {
            p0: point_to_raw(&self.p0),
            p1: point_to_raw(&self.p1),
            t0: vector_to_raw(&self.t0),
            t1: vector_to_raw(&self.t1),
        }
        .serialize(serializer)
    }
}

/// Deserializes from the form written by `Serialize` and validates it with
/// [`HermiteCurve::try_new`]. A wrong coordinate count is [`Error::Dimension`] with index 0, 1,
/// 2, 3 for p0, p1, t0, t1.
impl<'de, const D: usize> Deserialize<'de> for HermiteCurve<f64, D> {
    fn deserialize<De: Deserializer<'de>>(
        deserializer: De,
    ) -> std::result::Result<Self, De::Error> {
        let raw = RawHermite::deserialize(deserializer)?;
        let build = || -> Result<Self> {
            Self::try_new(
                point_from_raw(&raw.p0, 0)?,
                point_from_raw(&raw.p1, 1)?,
                vector_from_raw(&raw.t0, 2)?,
                vector_from_raw(&raw.t1, 3)?,
            )
        };
        build().map_err(serde::de::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use nalgebra::{Point2, RowVector4, Vector2};

    fn sample() -> HermiteCurve2<f64> {
        HermiteCurve2::try_new(
            Point2::new(1.0, -1.0),
            Point2::new(4.0, 2.0),
            Vector2::new(2.0, 5.0),
            Vector2::new(-1.0, 3.0),
        )
        .unwrap()
    }

    #[test]
    fn matrix_rows_are_blending_coefficients() {
        let m: Matrix4<f64> = hermite_basis_matrix();
        for &u in &[0.0, 0.3, 0.8, 1.0] {
            let f = RowVector4::new(u * u * u, u * u, u, 1.0) * m;
            let g = blending_functions(u);
            for j in 0..4 {
                assert_relative_eq!(f[j], g[j], epsilon = 1e-15);
            }
            // U′·M gives the first derivatives.
            let df = RowVector4::new(3.0 * u * u, 2.0 * u, 1.0, 0.0) * m;
            let dg = blending_first_derivatives(u);
            for j in 0..4 {
                assert_relative_eq!(df[j], dg[j], epsilon = 1e-14);
            }
        }
    }

    #[test]
    fn algebraic_round_trip() {
        let c = sample();
        let back = HermiteCurve2::from_algebraic(c.algebraic()).unwrap();
        assert_relative_eq!(back.p1(), c.p1(), epsilon = 1e-14);
        assert_relative_eq!(back.t1(), c.t1(), epsilon = 1e-14);
        assert_relative_eq!(back.t0(), c.t0(), epsilon = 1e-14);
    }

    #[test]
    fn domain_and_high_derivatives() {
        let c = sample();
        assert!(matches!(
            c.point(1.5),
            Err(Error::ParameterOutsideDomain { .. })
        ));
        assert!(matches!(c.point(f64::NAN), Err(Error::NonFinite { .. })));
        let d = c.derivatives(0.4, 5).unwrap();
        assert_relative_eq!(d[3], c.algebraic()[0] * 6.0, epsilon = 1e-13);
        assert_relative_eq!(d[4].norm() + d[5].norm(), 0.0);
    }

    #[test]
    fn bad_input_is_typed() {
        let c = sample();
        assert_eq!(
            c.truncated(0.5, 0.5),
            Err(Error::InvalidInterval {
                start: 0.5,
                end: 0.5
            })
        );
        assert!(matches!(
            c.truncated(-0.1, 0.5),
            Err(Error::ParameterOutsideDomain { .. })
        ));
        assert_eq!(c.subdivided(0), Err(Error::ZeroCount { what: "segments" }));
        assert_eq!(
            c.subdivided_at(&[0.5, 0.3]),
            Err(Error::InvalidInterval {
                start: 0.5,
                end: 0.3
            })
        );
        assert_eq!(
            c.subdivided_at(&[0.0]),
            Err(Error::InvalidInterval {
                start: 0.0,
                end: 0.0
            })
        );
        assert_eq!(
            c.subdivided_at(&[0.5, 1.0]),
            Err(Error::InvalidInterval {
                start: 1.0,
                end: 1.0
            })
        );
        assert_eq!(c.subdivided_at(&[]).unwrap(), vec![c.clone()]);
        let a = [
            Vector2::zeros(),
            Vector2::new(0.0, f64::INFINITY),
            Vector2::zeros(),
            Vector2::zeros(),
        ];
        assert!(matches!(
            HermiteCurve2::from_algebraic(a),
            Err(Error::NonFinite { index: 1, .. })
        ));
    }

    #[test]
    fn serde_round_trip_and_validation() {
        let c = sample();
        let json = serde_json::to_string(&c).unwrap();
        assert_eq!(
            json,
            r#"{"p0":[1.0,-1.0],"p1":[4.0,2.0],"t0":[2.0,5.0],"t1":[-1.0,3.0]}"#
        );
        let back: HermiteCurve2<f64> = serde_json::from_str(&json).unwrap();
        assert_eq!(back, c);
        let short = r#"{"p0":[1.0,-1.0],"p1":[4.0,2.0],"t0":[2.0],"t1":[-1.0,3.0]}"#;
        let err = serde_json::from_str::<HermiteCurve2<f64>>(short).unwrap_err();
        assert!(
            err.to_string().contains("point 2 has 1 coordinates"),
            "{err}"
        );
    }
}
