//! Knot removal within a tolerance (The NURBS Book A5.8), exact when the curve allows, with a
//! guaranteed bound on how far the curve moved.
//!
//! Removing an interior knot u once is the inverse of inserting it: the p − s + 1 control
//! points around u (s its multiplicity) are recomputed from both sides by inverting the
//! insertion's affine steps, P_i = (Q_i − (1 − α_i) P_{i−1}) / α_i from the left and
//! P_j = (Q_j − α_j P_{j+1}) / (1 − α_j) from the right. Where the two sweeps meet they must
//! agree: their distance measures what the removal would change, and the knot is removed only
//! when it is within the tolerance. A knot that was inserted into the curve is removed exactly.
//!
//! **The bound.** Both curves are written on the union of their knot vectors (knot insertion,
//! exact); there they share the basis functions, so C − C′ = Σ N_i (P_i − P′_i) and, since the
//! N_i are non-negative and sum to one, |C(u) − C′(u)| ≤ max_i |P_i − P′_i| for every u. That
//! maximum is the reported bound for B-splines; a removal whose bound exceeds the tolerance is
//! undone. For NURBS curves the test runs on the homogeneous net with the tolerance scaled by
//! w_min / (1 + max |P|), and the reported deviation is measured on 32 samples per span.
//!
//! ```
//! use camber_geom::{BSplineCurve2, KnotVector, ParametricCurve};
//! use nalgebra::Point2;
//! let knots = KnotVector::clamped_uniform(3, 4)?;
//! let pts = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 2.0), Point2::new(3.0, 2.0),
//!     Point2::new(4.0, 0.0)];
//! let curve = BSplineCurve2::try_new(3, knots, pts)?;
//! let busy = curve.insert_knot(0.4, 2)?;
//! let removal = busy.remove_knot(0.4, 2, 1e-12)?;
//! assert_eq!(removal.removed, 2);
//! assert!(removal.error_bound < 1e-12);
//! assert_eq!(removal.curve.control_points().len(), 4);
//! # Ok::<(), camber_geom::Error>(())
//! ```

use crate::bspline::BSplineCurve;
use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::knot_ops::ControlNet;
use crate::knots::KnotVector;
use crate::nurbs::NurbsCurve;
use crate::scalar::{cst, re, Scalar};

/// The movement, relative to the largest coordinate, that still counts as exact: the inverse
/// insertion steps divide by knot ratios and amplify rounding when knots lie close together.
pub(crate) const EXACT_SLACK: f64 = 1e-10;

/// The result of a knot removal: the new curve, how many knots went, and how far the curve
/// moved at most.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotRemoval<C> {
    /// The curve with the knots removed (clamped).
    pub curve: C,
    /// How many knots were removed (0 when none could be within the tolerance).
    pub removed: usize,
    /// An upper bound on max_u |C(u) − C′(u)| (B-splines; for NURBS, the deviation measured on
    /// 32 samples per span), in length units.
    pub error_bound: f64,
}

/// Euclidean distance between two flat points.
fn distance<T: Scalar>(a: &[T], b: &[T]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(&x, &y)| re(x - y) * re(x - y))
        .sum::<f64>()
        .sqrt()
}

/// A5.8: removes the interior knot `u` up to `times` times from the clamped net, while the
/// two sweeps agree within `tolerance`; returns the net and how many were removed.
pub(crate) fn remove_knot_net<T: Scalar>(
    net: &ControlNet<T>,
    u: T,
    times: usize,
    tolerance: f64,
) -> Result<(ControlNet<T>, usize)> {
    net.check()?;
    let net = net.clamped();
    let (p, dim) = (net.degree, net.dim);
    let (a, b) = net.domain();
    let s = net.knots.multiplicity(u);
    if s == 0 || u <= a || u >= b {
        return Err(Error::KnotNotFound { value: re(u) });
    }
    let knots = net.knots.as_slice().to_vec();
    let n = net.point_count() - 1;
    let m = n + p + 1;
    // r: the last index of u in the knot vector.
    let r = knots.partition_point(|&k| k <= u) - 1;
    let num = times.min(s);
    let ord = p + 1;
    let mut pw = net.coords.clone();
    let point = |v: &[T], i: usize| v[i * dim..(i + 1) * dim].to_vec();
    let (mut first, mut last) = (r as isize - p as isize, r as isize - s as isize);
    let mut temp = vec![T::zero(); (2 * p + 3) * dim];
    let mut removed = 0usize;
    for t in 0..num {
        let ti = t as isize;
        let off = first - 1;
        if off < 0 {
            break;
        }
        let put = |temp: &mut Vec<T>, at: isize, v: &[T]| {
            let at = at as usize;
            temp[at * dim..(at + 1) * dim].copy_from_slice(v);
        };
        put(&mut temp, 0, &point(&pw, off as usize));
        put(&mut temp, last + 1 - off, &point(&pw, (last + 1) as usize));
        let (mut i, mut j) = (first, last);
        let (mut ii, mut jj) = (1isize, last - off);
        while j - i > ti {
            let (iu, ju) = (i as usize, j as usize);
            let alfi = (u - knots[iu]) / (knots[iu + ord + t] - knots[iu]);
            let alfj = (u - knots[ju - t]) / (knots[ju + ord] - knots[ju - t]);
            for c in 0..dim {
                let prev = temp[(ii as usize - 1) * dim + c];
                temp[ii as usize * dim + c] = (pw[iu * dim + c] - (T::one() - alfi) * prev) / alfi;
                let next = temp[(jj as usize + 1) * dim + c];
                temp[jj as usize * dim + c] = (pw[ju * dim + c] - alfj * next) / (T::one() - alfj);
            }
            i += 1;
            ii += 1;
            j -= 1;
            jj -= 1;
        }
        let gap = if j - i < ti {
            let x = &temp[(ii as usize - 1) * dim..ii as usize * dim];
            let y = &temp[(jj as usize + 1) * dim..(jj as usize + 2) * dim];
            distance(x, y)
        } else {
            let iu = i as usize;
            let alfi = (u - knots[iu]) / (knots[iu + ord + t] - knots[iu]);
            let blend: Vec<T> = (0..dim)
                .map(|c| {
                    alfi * temp[(ii + ti + 1) as usize * dim + c]
                        + (T::one() - alfi) * temp[(ii as usize - 1) * dim + c]
                })
                .collect();
            distance(&point(&pw, iu), &blend)
        };
        // A NaN gap (degenerate knots) counts as too far.
        if gap.is_nan() || gap > tolerance {
            break;
        }
        let (mut i, mut j) = (first, last);
        while j - i > ti {
            let (iu, ju) = (i as usize, j as usize);
            let from_i = ((i - off) as usize) * dim;
            let from_j = ((j - off) as usize) * dim;
            pw[iu * dim..(iu + 1) * dim].copy_from_slice(&temp[from_i..from_i + dim]);
            pw[ju * dim..(ju + 1) * dim].copy_from_slice(&temp[from_j..from_j + dim]);
            i += 1;
            j -= 1;
        }
        first -= 1;
        last += 1;
        removed += 1;
    }
    if removed == 0 {
        return Ok((net, 0));
    }
    let t = removed;
    let mut new_knots = knots.clone();
    new_knots[r + 1 - t..=m - t].copy_from_slice(&knots[r + 1..=m]);
    new_knots.truncate(m + 1 - t);
    let fout = (2 * r - s - p) / 2;
    let (mut i, mut j) = (fout, fout);
    for k in 1..t {
        if k % 2 == 1 {
            i += 1;
        } else {
            j -= 1;
        }
    }
    for k in i + 1..=n {
        let from = pw[k * dim..(k + 1) * dim].to_vec();
        pw[j * dim..(j + 1) * dim].copy_from_slice(&from);
        j += 1;
    }
    pw.truncate((n + 1 - t) * dim);
    let out = ControlNet::try_new(p, KnotVector::new_unchecked(new_knots), dim, pw)?;
    Ok((out, removed))
}

/// max_i |P_i − P′_i| after writing both nets (same degree, dimension and domain) on the union
/// of their knot vectors: a bound on the distance between the two curves at every parameter.
/// Infinite when the nets cannot be compared.
pub(crate) fn deviation_bound<T: Scalar>(a: &ControlNet<T>, b: &ControlNet<T>) -> f64 {
    let (a, b) = (a.clamped(), b.clamped());
    if a.degree != b.degree || a.dim != b.dim || a.domain() != b.domain() {
        return f64::INFINITY;
    }
    let missing = |from: &ControlNet<T>, other: &ControlNet<T>| -> Vec<T> {
        let (lo, hi) = from.domain();
        let mut out = Vec::new();
        let mut last: Option<T> = None;
        for &k in other.knots.as_slice() {
            if k <= lo || k >= hi || last.is_some_and(|l| l >= k) {
                continue;
            }
            last = Some(k);
            let need = other.knots.multiplicity(k);
            let have = from.knots.multiplicity(k);
            out.extend(std::iter::repeat_n(k, need.saturating_sub(have)));
        }
        out
    };
    let (add_a, add_b) = (missing(&a, &b), missing(&b, &a));
    let (Ok(ra), Ok(rb)) = (a.refine(&add_a), b.refine(&add_b)) else {
        return f64::INFINITY;
    };
    if ra.coords.len() != rb.coords.len() {
        return f64::INFINITY;
    }
    ra.coords
        .chunks_exact(ra.dim)
        .zip(rb.coords.chunks_exact(rb.dim))
        .map(|(x, y)| distance(x, y))
        .fold(0.0, f64::max)
}

/// Checks that a tolerance is finite and not negative (zero asks for exact removal only).
fn check_tolerance(tolerance: f64) -> Result<()> {
    if !tolerance.is_finite() {
        return Err(Error::NonFinite {
            what: "knot removal tolerance",
            index: 0,
            value: tolerance,
        });
    }
    if tolerance < 0.0 {
        return Err(Error::NonPositiveTolerance { value: tolerance });
    }
    Ok(())
}

/// The largest |C(u) − C′(u)| over 32 samples per span of `a`.
pub(crate) fn sampled_deviation<T, const D: usize, A, B>(a: &A, b: &B) -> Result<f64>
where
    T: Scalar,
    A: ParametricCurve<T, D> + ?Sized,
    B: ParametricCurve<T, D> + ?Sized,
{
    let mut worst = 0.0_f64;
    for w in a.breakpoints().windows(2) {
        for k in 0..=32 {
            let u = w[0] + (w[1] - w[0]) * cst::<T>(f64::from(k) / 32.0);
            worst = worst.max(re((a.point(u)? - b.point(u)?).norm()));
        }
    }
    Ok(worst)
}

/// # Knot removal
impl<T: Scalar, const D: usize> BSplineCurve<T, D> {
    /// Removes the interior knot `u` up to `times` times, as long as the curve moves by at most
    /// `tolerance` (length units, ≥ 0; 0 removes only what is exactly removable, up to
    /// rounding, i.e. 1e-10 of the largest coordinate). The result's `error_bound` bounds the movement everywhere.
    ///
    /// Errors: [`Error::KnotNotFound`] when u is not an interior knot, [`Error::NonFinite`] or
    /// [`Error::NonPositiveTolerance`] for a bad tolerance.
    pub fn remove_knot(&self, u: T, times: usize, tolerance: f64) -> Result<KnotRemoval<Self>> {
        check_tolerance(tolerance)?;
        let net = self.to_control_net();
        // Rounding of the exact case: scale-relative slack.
        let slack = tolerance.max(EXACT_SLACK * (1.0 + scale(&net)));
        let mut budget = times;
        loop {
            let (out, removed) = remove_knot_net(&net, u, budget, slack)?;
            let bound = if removed == 0 {
                0.0
            } else {
                deviation_bound(&net, &out)
            };
            if bound <= slack || removed == 0 {
                return Ok(KnotRemoval {
                    curve: Self::try_from_control_net(out)?,
                    removed,
                    error_bound: bound,
                });
            }
            budget = removed - 1;
        }
    }

    /// Removes every interior knot as often as the tolerance allows, one knot value after the
    /// other; the total movement stays within `tolerance` (the bound is re-measured against the
    /// original curve after every removal).
    ///
    /// ```
    /// use camber_geom::{BSplineCurve2, KnotVector};
    /// use nalgebra::Point2;
    /// let knots = KnotVector::clamped_uniform(2, 3)?;
    /// let c = BSplineCurve2::try_new(2, knots, vec![Point2::new(0.0, 0.0),
    ///     Point2::new(1.0, 1.0), Point2::new(2.0, 0.0)])?;
    /// let busy = c.refine(&[0.2, 0.5, 0.5, 0.7])?;
    /// let clean = busy.remove_knots(1e-12)?;
    /// assert_eq!(clean.removed, 4);
    /// assert_eq!(clean.curve.control_points().len(), 3);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    ///
    /// Errors: as [`remove_knot`](Self::remove_knot) for the tolerance.
    pub fn remove_knots(&self, tolerance: f64) -> Result<KnotRemoval<Self>> {
        check_tolerance(tolerance)?;
        let original = self.clamped().to_control_net();
        let slack = tolerance.max(EXACT_SLACK * (1.0 + scale(&original)));
        let mut current = original.clone();
        let mut removed = 0;
        let mut bound = 0.0;
        let (a, b) = original.domain();
        let values: Vec<T> = original
            .knots
            .breakpoints(original.degree)
            .into_iter()
            .filter(|&k| k > a && k < b)
            .collect();
        for u in values {
            let mut times = current.knots.multiplicity(u);
            while times > 0 {
                let (out, count) = remove_knot_net(&current, u, times, slack)?;
                if count == 0 {
                    break;
                }
                let total = deviation_bound(&original, &out);
                if total <= slack {
                    current = out;
                    removed += count;
                    bound = total;
                    break;
                }
                times = count - 1;
            }
        }
        Ok(KnotRemoval {
            curve: Self::try_from_control_net(current)?,
            removed,
            error_bound: bound,
        })
    }
}

/// The largest coordinate magnitude of a net (for rounding slack).
fn scale<T: Scalar>(net: &ControlNet<T>) -> f64 {
    net.coords.iter().map(|&c| re(c).abs()).fold(0.0, f64::max)
}

/// # Knot removal
impl<T: Scalar, const D: usize> NurbsCurve<T, D> {
    /// Removes the interior knot `u` up to `times` times within `tolerance` (length units),
    /// testing the homogeneous net with the tolerance scaled by w_min / (1 + max |P|); the
    /// `error_bound` is the deviation measured on 32 samples per span.
    ///
    /// Errors: as [`BSplineCurve::remove_knot`], and [`Error::NonPositiveWeight`] if the new
    /// weights are not positive (then nothing is removed).
    pub fn remove_knot(&self, u: T, times: usize, tolerance: f64) -> Result<KnotRemoval<Self>> {
        check_tolerance(tolerance)?;
        let net = self.to_homogeneous();
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
        let scaled = tolerance * w_min / (1.0 + p_max);
        let slack = scaled.max(EXACT_SLACK * (1.0 + scale(&net)));
        let mut budget = times;
        loop {
            let (out, removed) = remove_knot_net(&net, u, budget, slack)?;
            if removed == 0 {
                return Ok(KnotRemoval {
                    curve: self.clamped(),
                    removed,
                    error_bound: 0.0,
                });
            }
            let curve = Self::try_from_homogeneous(out)?;
            let measured = sampled_deviation(self, &curve)?;
            if measured <= tolerance.max(1e-12 * (1.0 + p_max)) {
                return Ok(KnotRemoval {
                    curve,
                    removed,
                    error_bound: measured,
                });
            }
            budget = removed - 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_linear_knot_goes_when_the_points_are_collinear() {
        // Degree 1 through (0,0), (1,1), (2,2) with a knot at 1/2: the middle point lies on
        // the chord, so the knot goes exactly; with (1, 1.5) it moves the curve by 0.5 at most.
        let knots = KnotVector::try_new(vec![0.0, 0.0, 0.5, 1.0, 1.0]).unwrap();
        let straight =
            ControlNet::try_new(1, knots.clone(), 2, vec![0., 0., 1., 1., 2., 2.]).unwrap();
        let (out, removed) = remove_knot_net(&straight, 0.5, 1, 1e-12).unwrap();
        assert_eq!(removed, 1);
        assert_eq!(out.coords, vec![0., 0., 2., 2.]);
        let bent = ControlNet::try_new(1, knots, 2, vec![0., 0., 1., 1.5, 2., 2.]).unwrap();
        let (_, none) = remove_knot_net(&bent, 0.5, 1, 0.4).unwrap();
        assert_eq!(none, 0);
        let (moved, one) = remove_knot_net(&bent, 0.5, 1, 0.6).unwrap();
        assert_eq!(one, 1);
        assert!((deviation_bound(&bent, &moved) - 0.5).abs() < 1e-15);
    }
}
