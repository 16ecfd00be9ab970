//! Composite curves — ordered chains of curves under one global parameter — and the
//! continuity report of their joints.
//!
//! A [`CompositeCurve`] of n pieces has the global domain [0, n]: piece i runs over [i, i + 1],
//! mapped affinely onto the piece's own domain [a_i, b_i] by u = a_i + (s − i)(b_i − a_i), so
//! the k-th derivative with respect to s is the piece's k-th derivative times (b_i − a_i)^k.
//! The chain is not required to be continuous; [`CompositeCurve::joints`] measures how well
//! neighbouring pieces fit, and [`JointReport::continuity`] classifies each joint.

use std::fmt;

use nalgebra::SVector;

use crate::curve::{check_interval, check_parameter, ParametricCurve};
use crate::errors::{Error, Result};
use crate::queries::{
    curvature_from_derivatives, curvature_vector_from_derivatives, sampled_pieces, RationalPiece,
};
use crate::scalar::{cst, from_usize, re, Scalar};

/// An ordered chain of curves C_0, …, C_{n−1} evaluated as one curve on s ∈ [0, n].
///
/// ```
/// use camber_geom::{CompositeCurve, ParametricCurve};
/// # use camber_geom::Result;
/// # use nalgebra::{Point2, SVector};
/// # struct Seg(Point2<f64>, Point2<f64>);
/// # impl ParametricCurve<f64, 2> for Seg {
/// #     fn domain(&self) -> (f64, f64) { (0.0, 2.0) }
/// #     fn derivatives_into(&self, u: f64, out: &mut [SVector<f64, 2>]) -> Result<()> {
/// #         let d = (self.1 - self.0) / 2.0;
/// #         let all = [self.0.coords + d * u, d];
/// #         for (k, o) in out.iter_mut().enumerate() {
/// #             *o = all.get(k).copied().unwrap_or_else(SVector::zeros);
/// #         }
/// #         Ok(())
/// #     }
/// # }
/// // `Seg(a, b)` is the segment from a to b on its own domain [0, 2].
/// let (a, b, c) = (Point2::new(0.0, 0.0), Point2::new(1.0, 0.0), Point2::new(1.0, 1.0));
/// let chain = CompositeCurve::try_new(vec![Box::new(Seg(a, b)), Box::new(Seg(b, c))])?;
/// assert_eq!(chain.domain(), (0.0, 2.0));
/// let p = chain.point(1.5)?;
/// assert!((p.x - 1.0).abs() < 1e-15 && (p.y - 0.5).abs() < 1e-15);
/// let joint = &chain.joints()?[0];
/// assert!(joint.position_gap.abs() < 1e-15);
/// assert!((joint.tangent_angle - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// The pieces are boxed trait objects by default; any one curve type `P` may hold them instead
/// (an enum of the kinds a caller uses), which keeps the chain `Clone`, `Send` and `Sync`
/// whenever `P` is.
#[derive(Clone)]
pub struct CompositeCurve<T: Scalar, const D: usize, P = Box<dyn ParametricCurve<T, D>>> {
    pieces: Vec<P>,
    _scalar: std::marker::PhantomData<fn() -> T>,
}

/// A planar composite curve.
pub type CompositeCurve2<T> = CompositeCurve<T, 2>;
/// A spatial composite curve.
pub type CompositeCurve3<T> = CompositeCurve<T, 3>;

impl<T: Scalar, const D: usize, P> fmt::Debug for CompositeCurve<T, D, P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("CompositeCurve")
            .field("pieces", &self.pieces.len())
            .finish()
    }
}

/// # Construction
impl<T: Scalar, const D: usize> CompositeCurve<T, D> {
    /// The chain of boxed `pieces` in order. Fails with [`Error::ZeroCount`] for an empty chain
    /// and with [`Error::InvalidInterval`] / [`Error::NonFinite`] if a piece reports a domain
    /// that is not a finite interval a < b.
    ///
    /// ```
    /// use camber_geom::{CompositeCurve, Error};
    /// let err = CompositeCurve::<f64, 2>::try_new(Vec::new()).unwrap_err();
    /// assert_eq!(err, Error::ZeroCount { what: "pieces of a composite curve" });
    /// ```
    pub fn try_new(pieces: Vec<Box<dyn ParametricCurve<T, D>>>) -> Result<Self> {
        Self::try_from_pieces(pieces)
    }
}

impl<T: Scalar, const D: usize, P: ParametricCurve<T, D>> CompositeCurve<T, D, P> {
    /// The chain of `pieces` of one curve type `P` in order, with the checks of
    /// [`try_new`](CompositeCurve::try_new).
    ///
    /// ```
    /// use camber_geom::{BezierCurve2, CompositeCurve, ParametricCurve};
    /// use nalgebra::Point2;
    /// let seg = |a: [f64; 2], b: [f64; 2]| {
    ///     BezierCurve2::try_new(vec![Point2::from(a), Point2::from(b)])
    /// };
    /// let chain = CompositeCurve::try_from_pieces(vec![
    ///     seg([0.0, 0.0], [1.0, 0.0])?,
    ///     seg([1.0, 0.0], [1.0, 1.0])?,
    /// ])?;
    /// assert_eq!(chain.point(1.5)?, Point2::new(1.0, 0.5));
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn try_from_pieces(pieces: Vec<P>) -> Result<Self> {
        if pieces.is_empty() {
            return Err(Error::ZeroCount {
                what: "pieces of a composite curve",
            });
        }
        for piece in &pieces {
            let (a, b) = piece.domain();
            check_interval(a, b)?;
        }
        Ok(Self {
            pieces,
            _scalar: std::marker::PhantomData,
        })
    }
}

impl<T: Scalar, const D: usize, P: ParametricCurve<T, D>> CompositeCurve<T, D, P> {
    /// The pieces in order.
    pub fn pieces(&self) -> &[P] {
        &self.pieces
    }

    /// The pieces in order, taken out of the chain.
    pub fn into_pieces(self) -> Vec<P> {
        self.pieces
    }

    /// Number of pieces n (at least 1); the global domain is [0, n].
    pub fn len(&self) -> usize {
        self.pieces.len()
    }

    /// Always false: a composite curve has at least one piece.
    pub fn is_empty(&self) -> bool {
        self.pieces.is_empty()
    }

    /// The piece holding global parameter `s` and the piece's own parameter there: (i, u)
    /// with u = a_i + (s − i)(b_i − a_i), exact at both ends of the piece. At a joint the
    /// right-hand piece, at s = n the last one.
    ///
    /// Fails with [`Error::ParameterOutsideDomain`] or [`Error::NonFinite`] for s outside
    /// [0, n].
    pub fn piece_at(&self, s: T) -> Result<(usize, T)> {
        check_parameter(s, self.domain())?;
        let (i, u, _) = self.locate(s).ok_or(Error::ZeroCount {
            what: "pieces of a composite curve",
        })?;
        Ok((i, u))
    }

    /// The piece index, local parameter u and scale b_i − a_i of global parameter `s`, which
    /// must be in [0, n].
    fn locate(&self, s: T) -> Option<(usize, T, T)> {
        let last = self.pieces.len().checked_sub(1)?;
        let floor = re(s).floor();
        // s is checked to lie in [0, n], so the floor is a small non-negative integer.
        let i = if floor > 0.0 {
            (floor as usize).min(last)
        } else {
            0
        };
        let piece = self.pieces.get(i)?;
        let (a, b) = piece.domain();
        let len = b - a;
        let t = s - from_usize::<T>(i);
        // Exact at both ends of the piece: a at t = 0, b at t = 1.
        let u = if t <= cst::<T>(0.5) {
            a + len * t
        } else {
            b - len * (T::one() - t)
        };
        Some((i, u, len))
    }

    /// The continuity report of every joint, in order (n − 1 reports for n pieces).
    ///
    /// Each is computed from the end of piece i and the start of piece i + 1, in the pieces'
    /// own parameters (not the global one). Fails if a piece cannot be evaluated at an end of
    /// its domain.
    pub fn joints(&self) -> Result<Vec<JointReport<T>>> {
        let mut out = Vec::with_capacity(self.pieces.len().saturating_sub(1));
        for (index, pair) in self.pieces.windows(2).enumerate() {
            let left = pair[0].second_order(pair[0].domain().1)?;
            let right = pair[1].second_order(pair[1].domain().0)?;
            out.push(JointReport::from_derivatives(index, &left, &right));
        }
        Ok(out)
    }
}

impl<T: Scalar, const D: usize, P: ParametricCurve<T, D>> ParametricCurve<T, D>
    for CompositeCurve<T, D, P>
{
    /// Each piece's own pieces (exact where the piece has a Bézier form, sampled with
    /// [`sampled_pieces`] where not), moved onto the piece's global interval [i, i + 1].
    fn bezier_enclosure(&self) -> Result<Option<Vec<RationalPiece<D>>>> {
        let mut out = Vec::new();
        for (i, piece) in self.pieces.iter().enumerate() {
            let local = match piece.bezier_enclosure()? {
                Some(local) => local,
                None => sampled_pieces(piece)?,
            };
            let (a, b) = piece.domain();
            let (a, b) = (re(a), re(b));
            let offset = i as f64;
            // Exact at the joints: a maps to i and b to i + 1.
            let global = |u: f64| {
                if u <= a {
                    offset
                } else if u >= b {
                    offset + 1.0
                } else {
                    offset + (u - a) / (b - a)
                }
            };
            out.extend(local.into_iter().map(|p| {
                let (s, e) = (global(p.start), global(p.end));
                p.reparameterized(s, e)
            }));
        }
        Ok(Some(out))
    }

    /// The global domain [0, n].
    fn domain(&self) -> (T, T) {
        (T::zero(), from_usize(self.pieces.len()))
    }

    fn derivatives_into(&self, s: T, out: &mut [SVector<T, D>]) -> Result<()> {
        check_parameter(s, self.domain())?;
        let (i, u, len) = self.locate(s).ok_or(Error::ZeroCount {
            what: "pieces of a composite curve",
        })?;
        self.pieces[i].derivatives_into(u, out)?;
        let mut scale = T::one();
        for d in out.iter_mut().skip(1) {
            scale *= len;
            *d *= scale;
        }
        Ok(())
    }

    /// Every joint 1, …, n − 1, both ends, and each piece's own breakpoints mapped to the
    /// global parameter.
    fn breakpoints(&self) -> Vec<T> {
        let mut out: Vec<T> = vec![T::zero()];
        for (i, piece) in self.pieces.iter().enumerate() {
            let (a, b) = piece.domain();
            let start = from_usize::<T>(i);
            for u in piece.breakpoints() {
                let s = start + (u - a) / (b - a);
                if out.last().is_some_and(|&l| s > l) && s < start + T::one() {
                    out.push(s);
                }
            }
            out.push(start + T::one());
        }
        out
    }
}

/// How smoothly two neighbouring pieces meet, in the pieces' own parameters: piece i is
/// evaluated at the end of its domain (left), piece i + 1 at the start of its domain (right).
///
/// All quantities are non-negative; lengths in length units, derivatives per unit of the
/// pieces' parameters, curvatures in 1/length, the angle in radians.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointReport<T: Scalar> {
    /// The joint between piece `index` and piece `index + 1`.
    pub index: usize,
    /// |C_{i+1}(start) − C_i(end)| (C0 when zero).
    pub position_gap: T,
    /// The angle in [0, π] between C_i′(end) and C_{i+1}′(start) (G1 when zero); π when either
    /// derivative is zero (no tangent direction).
    pub tangent_angle: T,
    /// |C_{i+1}′(start) − C_i′(end)| (C1 when zero, together with C0).
    pub first_derivative_mismatch: T,
    /// |κ_{i+1}(start) − κ_i(end)| of the unsigned curvatures
    /// κ = √(|C′|²|C″|² − (C′·C″)²)/|C′|³; infinite when a first derivative is zero.
    pub curvature_difference: T,
    /// |k_{i+1}(start) − k_i(end)| of the curvature vectors (length κ, towards the centre of
    /// curvature). Unlike `curvature_difference` it also sees curvature that keeps its size
    /// but flips side (an inflection at the joint); this is what G2 is judged on. Infinite
    /// when a first derivative is zero.
    pub curvature_vector_difference: T,
    /// |C_{i+1}″(start) − C_i″(end)| (C2 when zero, together with C1).
    pub second_derivative_mismatch: T,
}

impl<T: Scalar> JointReport<T> {
    /// The report from [C, C′, C″] at the end of the left piece and the start of the right one.
    pub fn from_derivatives<const D: usize>(
        index: usize,
        left: &[SVector<T, D>; 3],
        right: &[SVector<T, D>; 3],
    ) -> Self {
        let infinity = cst::<T>(f64::INFINITY);
        let (a, b) = (&left[1], &right[1]);
        let tangent_angle = if re(a.norm_squared()) > 0.0 && re(b.norm_squared()) > 0.0 {
            // atan2(|a × b|, a·b), accurate at small and large angles alike.
            let mut cross2 = T::zero();
            for i in 0..D {
                for j in i + 1..D {
                    let c = a[i] * b[j] - a[j] * b[i];
                    cross2 += c * c;
                }
            }
            cross2.sqrt().atan2(a.dot(b))
        } else {
            T::pi()
        };
        let curvature_difference = match (
            curvature_from_derivatives(&left[1], &left[2]),
            curvature_from_derivatives(&right[1], &right[2]),
        ) {
            (Some(kl), Some(kr)) => (kr - kl).abs(),
            _ => infinity,
        };
        let curvature_vector_difference = match (
            curvature_vector_from_derivatives(&left[1], &left[2]),
            curvature_vector_from_derivatives(&right[1], &right[2]),
        ) {
            (Some(kl), Some(kr)) => (kr - kl).norm(),
            _ => infinity,
        };
        Self {
            index,
            position_gap: (right[0] - left[0]).norm(),
            tangent_angle,
            first_derivative_mismatch: (right[1] - left[1]).norm(),
            curvature_difference,
            curvature_vector_difference,
            second_derivative_mismatch: (right[2] - left[2]).norm(),
        }
    }

    /// The highest continuity class whose conditions hold within `tol` (see [`Continuity`]).
    ///
    /// ```
    /// use camber_geom::composite::{Continuity, ContinuityTolerances, JointReport};
    /// use nalgebra::Vector2;
    /// // Same point and tangent direction, different speed, no curvature: G1 and G2, not C1.
    /// let left = [Vector2::new(1.0, 0.0), Vector2::new(1.0, 0.0), Vector2::zeros()];
    /// let right = [Vector2::new(1.0, 0.0), Vector2::new(3.0, 0.0), Vector2::zeros()];
    /// let joint = JointReport::from_derivatives(0, &left, &right);
    /// assert_eq!(joint.continuity(&ContinuityTolerances::default()), Continuity::G2);
    /// ```
    pub fn continuity(&self, tol: &ContinuityTolerances) -> Continuity {
        let c0 = re(self.position_gap) <= tol.position;
        let g1 = c0 && re(self.tangent_angle) <= tol.angle;
        let c1 = g1 && re(self.first_derivative_mismatch) <= tol.derivative;
        let g2 = g1 && re(self.curvature_vector_difference) <= tol.curvature;
        let c2 = c1 && g2 && re(self.second_derivative_mismatch) <= tol.derivative;
        if c2 {
            Continuity::C2
        } else if g2 {
            Continuity::G2
        } else if c1 {
            Continuity::C1
        } else if g1 {
            Continuity::G1
        } else if c0 {
            Continuity::C0
        } else {
            Continuity::None
        }
    }
}

/// Continuity classes of a joint, ordered from rough to smooth:
/// `None < C0 < G1 < C1 < G2 < C2`.
///
/// - `C0`: the pieces meet (position gap within tolerance);
/// - `G1`: C0 and the tangent directions agree (angle within tolerance);
/// - `C1`: G1 and the first derivatives agree as vectors;
/// - `G2`: G1 and the curvature vectors agree (same curvature, same side);
/// - `C2`: C1, G2 and the second derivatives agree.
///
/// C2 implies every other class. G2 and C1 are independent (a joint can have equal curvature
/// but different parameter speeds, or equal speeds but different curvature); the order ranks
/// G2 above C1 because it is the geometrically smoother joint, so a joint that is both C1 and
/// G2 but not C2 is reported as `G2`, and `>=` on classes means "at least as smooth" in that
/// ranking, not "implies".
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Continuity {
    /// The pieces do not meet.
    None,
    /// Positional continuity.
    C0,
    /// Tangent-direction continuity.
    G1,
    /// First-derivative continuity.
    C1,
    /// Curvature continuity (curvature vectors agree).
    G2,
    /// Second-derivative continuity.
    C2,
}

/// Absolute tolerances for [`JointReport::continuity`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContinuityTolerances {
    /// Largest position gap (length units) for C0 (default 1e-9).
    pub position: f64,
    /// Largest tangent angle (radians) for G1 (default 1e-9).
    pub angle: f64,
    /// Largest first- and second-derivative mismatch for C1 and C2 (default 1e-9).
    pub derivative: f64,
    /// Largest curvature-vector difference (1/length) for G2 (default 1e-9).
    pub curvature: f64,
}

impl Default for ContinuityTolerances {
    fn default() -> Self {
        Self {
            position: 1e-9,
            angle: 1e-9,
            derivative: 1e-9,
            curvature: 1e-9,
        }
    }
}
