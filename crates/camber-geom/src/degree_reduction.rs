//! Degree reduction of Bézier, B-spline and NURBS curves by one degree: exact when the curve
//! is of lower degree, with a guaranteed error bound otherwise.
//!
//! **Bézier.** Elevating Q₀ … Q_{n−1} gives P_i = (i/n) Q_{i−1} + (1 − i/n) Q_i. Inverted from the
//! left, Q_i = (P_i − (i/n) Q_{i−1}) / (1 − i/n) starting at Q₀ = P₀; from the right,
//! Q_{i−1} = (P_i − (1 − i/n) Q_i) / (i/n) starting at Q_{n−1} = P_n. Each sweep amplifies
//! errors as it goes, so the first half comes from the left and the second from the right; if
//! the curve is really of degree n − 1 both sweeps agree and the reduction is exact. The
//! reduced curve elevated back is a degree-n Bézier with points P̃_i, and
//! |C(t) − C̃(t)| ≤ max_i |P_i − P̃_i| (the difference is a Bézier curve with those control
//! points, inside their convex hull): that maximum is the reported bound.
//!
//! **B-spline.** Every Bézier piece is reduced, the pieces are joined with (p − 1)-fold knots,
//! and then each interior knot is removed as far as the original continuity and the remaining
//! tolerance allow. The bound compares the reduced curve elevated back with the original on
//! the union of their knot vectors (see [`crate::knot_removal`]).
//!
//! **NURBS.** The same on the homogeneous net; the reported error is measured on 32 samples
//! per span.
//!
//! ```
//! use camber_geom::BezierCurve2;
//! use nalgebra::Point2;
//! let quadratic = BezierCurve2::try_new(vec![Point2::new(0.0_f64, 0.0), Point2::new(1.0, 2.0),
//!     Point2::new(2.0, 0.0)])?;
//! let cubic = quadratic.elevate_degree(1);
//! let back = cubic.reduce_degree()?;
//! assert!(back.error_bound < 1e-14);
//! assert!((back.curve.control_points()[1] - Point2::new(1.0, 2.0)).norm() < 1e-14);
//! # Ok::<(), camber_geom::Error>(())
//! ```

use nalgebra::Point;

use crate::bezier::BezierCurve;
use crate::bspline::BSplineCurve;
use crate::errors::{Error, Result};
use crate::knot_ops::ControlNet;
use crate::knot_removal::{deviation_bound, remove_knot_net, sampled_deviation, EXACT_SLACK};
use crate::knots::KnotVector;
use crate::nurbs::NurbsCurve;
use crate::scalar::{from_usize, re, Scalar};

/// A curve of one degree less and the bound on how far it lies from the original.
#[derive(Debug, Clone, PartialEq)]
pub struct DegreeReduction<C> {
    /// The reduced curve.
    pub curve: C,
    /// max_u |C(u) − C̃(u)| is at most this (length units); 0 up to rounding when exact.
    pub error_bound: f64,
}

/// Reduces one Bézier piece given flat (`dim` per point, n + 1 points); returns the n points
/// and max_i |P_i − P̃_i| of the elevated result.
fn reduce_flat<T: Scalar>(coords: &[T], dim: usize) -> (Vec<T>, f64) {
    let count = coords.len() / dim;
    let n = count - 1;
    let nf = from_usize::<T>(n);
    let at = |v: &[T], i: usize| v[i * dim..(i + 1) * dim].to_vec();
    // Left sweep.
    let mut left = vec![T::zero(); n * dim];
    left[..dim].copy_from_slice(&coords[..dim]);
    for i in 1..n {
        let alpha = from_usize::<T>(i) / nf;
        for c in 0..dim {
            left[i * dim + c] =
                (coords[i * dim + c] - alpha * left[(i - 1) * dim + c]) / (T::one() - alpha);
        }
    }
    // Right sweep.
    let mut right = vec![T::zero(); n * dim];
    right[(n - 1) * dim..].copy_from_slice(&coords[n * dim..]);
    for i in (1..n).rev() {
        let alpha = from_usize::<T>(i) / nf;
        for c in 0..dim {
            right[(i - 1) * dim + c] =
                (coords[i * dim + c] - (T::one() - alpha) * right[i * dim + c]) / alpha;
        }
    }
    let half = (n - 1) / 2;
    let mut out = Vec::with_capacity(n * dim);
    for i in 0..n {
        out.extend(if i <= half {
            at(&left, i)
        } else {
            at(&right, i)
        });
    }
    // Elevate back and compare.
    let mut bound = 0.0_f64;
    for i in 0..=n {
        let alpha = from_usize::<T>(i) / nf;
        let mut d2 = 0.0;
        for c in 0..dim {
            let prev = if i > 0 {
                out[(i - 1) * dim + c]
            } else {
                T::zero()
            };
            let here = if i < n { out[i * dim + c] } else { T::zero() };
            let e = alpha * prev + (T::one() - alpha) * here;
            d2 += re(coords[i * dim + c] - e).powi(2);
        }
        bound = bound.max(d2.sqrt());
    }
    (out, bound)
}

/// Degree reduction of a net (clamped inside), with the knot removal budget `tolerance`;
/// returns the reduced net and the largest piece bound.
fn reduce_net<T: Scalar>(net: &ControlNet<T>, tolerance: f64) -> Result<(ControlNet<T>, f64)> {
    net.check()?;
    let p = net.degree;
    if p == 0 {
        return Err(Error::TooFewControlPoints {
            degree: 0,
            needed: 2,
            found: 1,
        });
    }
    let net = net.clamped();
    let dim = net.dim;
    let pieces = net.decompose();
    let q = p - 1;
    let mut coords: Vec<T> = Vec::new();
    let mut knots: Vec<T> = Vec::new();
    let mut worst = 0.0_f64;
    for (k, piece) in pieces.iter().enumerate() {
        let (reduced, bound) = reduce_flat(&piece.coords, dim);
        worst = worst.max(bound);
        if k == 0 {
            knots.extend(std::iter::repeat_n(piece.start, q + 1));
            coords.extend_from_slice(&reduced);
        } else {
            // The first point repeats the previous piece's last (both are the joint point).
            knots.extend(std::iter::repeat_n(piece.start, q));
            coords.extend_from_slice(&reduced[dim..]);
        }
        if k + 1 == pieces.len() {
            knots.extend(std::iter::repeat_n(piece.end, q + 1));
        }
    }
    let mut reduced = ControlNet::try_new(q, KnotVector::new_unchecked(knots), dim, coords)?;
    // Restore the original continuity where the tolerance allows: a knot of multiplicity s
    // at degree p (C^{p−s}) needs multiplicity s − 1 at degree p − 1.
    // Rounding of an exact reduction leaves gaps of order ε·scale: allow them.
    let scale = net.coords.iter().map(|&c| re(c).abs()).fold(0.0, f64::max);
    let budget = (tolerance - worst).max(EXACT_SLACK * (1.0 + scale));
    if q > 0 {
        for piece in pieces.iter().skip(1) {
            let u = piece.start;
            let target = net.knots.multiplicity(u).saturating_sub(1);
            let have = reduced.knots.multiplicity(u);
            if have > target {
                let (out, _) = remove_knot_net(&reduced, u, have - target, budget)?;
                reduced = out;
            }
        }
    }
    Ok((reduced, worst))
}

/// # Degree reduction
impl<T: Scalar, const D: usize> BezierCurve<T, D> {
    /// The Bézier curve of degree n − 1 closest in the sense above, with its error bound
    /// (0 up to rounding when this curve is an elevated one).
    ///
    /// Errors: [`Error::TooFewControlPoints`] for degree 0.
    pub fn reduce_degree(&self) -> Result<DegreeReduction<Self>> {
        if self.degree() == 0 {
            return Err(Error::TooFewControlPoints {
                degree: 0,
                needed: 2,
                found: 1,
            });
        }
        let coords: Vec<T> = self
            .control_points()
            .iter()
            .flat_map(|p| p.coords.iter().copied())
            .collect();
        let (reduced, error_bound) = reduce_flat(&coords, D);
        let points = reduced
            .chunks_exact(D)
            .map(|c| Point::from(nalgebra::SVector::<T, D>::from_column_slice(c)))
            .collect();
        Ok(DegreeReduction {
            curve: Self::try_new(points)?,
            error_bound,
        })
    }
}

/// # Degree reduction
impl<T: Scalar, const D: usize> BSplineCurve<T, D> {
    /// The B-spline of degree p − 1 on the same domain, its pieces reduced and its knots removed
    /// as far as the original continuity and `tolerance` (length units, ≥ 0) allow. The bound
    /// holds everywhere; it exceeds the tolerance only when the pieces themselves cannot be
    /// reduced within it.
    ///
    /// ```
    /// use camber_geom::{BSplineCurve2, KnotVector};
    /// use nalgebra::Point2;
    /// let knots = KnotVector::clamped_uniform(2, 4)?;
    /// let c = BSplineCurve2::try_new(2, knots, vec![Point2::new(0.0_f64, 0.0),
    ///     Point2::new(1.0, 2.0), Point2::new(2.0, 2.0), Point2::new(3.0, 0.0)])?;
    /// let back = c.elevate_degree(1)?.reduce_degree(1e-12)?;
    /// assert!(back.error_bound < 1e-12);
    /// assert_eq!(back.curve.degree(), 2);
    /// assert_eq!(back.curve.control_points().len(), 4);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    ///
    /// Errors: [`Error::TooFewControlPoints`] for degree 0, [`Error::NonFinite`] or
    /// [`Error::NonPositiveTolerance`] for a bad tolerance.
    pub fn reduce_degree(&self, tolerance: f64) -> Result<DegreeReduction<Self>> {
        check_tolerance(tolerance)?;
        let original = self.to_control_net();
        let (reduced, _) = reduce_net(&original, tolerance)?;
        let error_bound = match reduced.elevate_degree(1) {
            Ok(back) => deviation_bound(&original, &back),
            Err(_) => f64::INFINITY,
        };
        Ok(DegreeReduction {
            curve: Self::try_from_control_net(reduced)?,
            error_bound,
        })
    }
}

/// # Degree reduction
impl<T: Scalar, const D: usize> NurbsCurve<T, D> {
    /// The NURBS curve of degree p − 1, reduced on the homogeneous net (see
    /// [`BSplineCurve::reduce_degree`]); `error_bound` is the deviation measured on 32 samples
    /// per span.
    ///
    /// Errors: as [`BSplineCurve::reduce_degree`], and [`Error::NonPositiveWeight`] when the
    /// reduced weights are not positive.
    pub fn reduce_degree(&self, tolerance: f64) -> Result<DegreeReduction<Self>> {
        check_tolerance(tolerance)?;
        let w_min = self
            .weights()
            .iter()
            .map(|&w| re(w))
            .fold(f64::INFINITY, f64::min);
        let p_max = self
            .control_points()
            .iter()
            .map(|p| re(p.coords.norm()))
            .fold(0.0, f64::max);
        let (reduced, _) = reduce_net(&self.to_homogeneous(), tolerance * w_min / (1.0 + p_max))?;
        let curve = Self::try_from_homogeneous(reduced)?;
        let error_bound = sampled_deviation(self, &curve)?;
        Ok(DegreeReduction { curve, error_bound })
    }
}

/// Checks that a tolerance is finite and not negative.
fn check_tolerance(tolerance: f64) -> Result<()> {
    if !tolerance.is_finite() {
        return Err(Error::NonFinite {
            what: "degree reduction tolerance",
            index: 0,
            value: tolerance,
        });
    }
    if tolerance < 0.0 {
        return Err(Error::NonPositiveTolerance { value: tolerance });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cubic_that_is_not_quadratic_by_hand() {
        // y = 3t³ as a cubic: P = (0, 0, 0, 3). Left sweep: Q0 = 0, Q1 = (0 − 0)/(2/3) = 0;
        // right sweep: Q2 = 3. Q = (0, 0, 3) elevates to (0, 0, 1, 3), so the bound is
        // |0 − 1| = 1 at P2.
        let (q, bound) = reduce_flat(&[0.0_f64, 0.0, 0.0, 3.0], 1);
        assert_eq!(q.len(), 3);
        assert!(q[1].abs() < 1e-15 && (q[2] - 3.0).abs() < 1e-15);
        assert!((bound - 1.0).abs() < 1e-15);
    }
}
