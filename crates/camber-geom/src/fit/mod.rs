//! Curves through and near data points: global interpolation, least-squares approximation
//! with a given number of control points, and fitting to a tolerance with automatic knot
//! placement. The results are clamped B-splines on [0, 1].
//!
//! - **Parameters.** Each data point Q_k gets a parameter ū_k ∈ [0, 1]: equally spaced
//!   ([`ParameterMethod::Uniform`]), proportional to the cumulative chord length
//!   ([`ParameterMethod::ChordLength`]) or to the cumulative square roots of the chord
//!   lengths ([`ParameterMethod::Centripetal`], which keeps sharp turns from overshooting).
//! - **Interpolation** solves Σ_i N_{i,p}(ū_k) P_i = Q_k for all k (plus, with end
//!   derivatives, C′(0) = D₀ and C′(1) = D₁ as two more rows and two more unknowns), knots by
//!   averaging the parameters so that every span holds one (the system is then banded and
//!   non-singular by the Schoenberg–Whitney theorem). Banded elimination solves it.
//! - **Least squares** with n + 1 < m + 1 control points places knots so that every span holds
//!   data (u_{p+j} interpolates between ū_{i−1} and ū_i with i = ⌊j·d⌋, d = (m + 1)/(n − p + 1)),
//!   and minimises Σ |C(ū_k) − Q_k|² through the normal equations, optionally with the end
//!   control points fixed on the end data points.
//! - **Fitting to a tolerance** starts from one polynomial span and, while some data point is
//!   farther than the tolerance from the curve point at its parameter, splits every offending
//!   span between its middle data parameters and fits again; it ends in interpolation if the
//!   spans run out of data.
//!
//! ```
//! use camber_geom::fit::{interpolate, ParameterMethod};
//! use camber_geom::ParametricCurve;
//! use nalgebra::Point2;
//! let points = [Point2::new(0.0_f64, 0.0), Point2::new(1.0, 1.0), Point2::new(3.0, 1.5),
//!     Point2::new(4.0, 0.0)];
//! let fit = interpolate(&points, 3, ParameterMethod::Centripetal, None)?;
//! for (q, &u) in points.iter().zip(&fit.parameters) {
//!     assert!((fit.curve.point(u)? - q).norm() < 1e-12);
//! }
//! # Ok::<(), camber_geom::Error>(())
//! ```

use nalgebra::{DMatrix, Point, SVector};

use crate::banded::BandedMatrix;
use crate::bspline::BSplineCurve;
use crate::curve::{check_points, ParametricCurve};
use crate::errors::{Error, Result};
use crate::knots::{check_degree, KnotVector};
use crate::scalar::{cst, from_usize, re, Scalar};

/// How data points are given curve parameters.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParameterMethod {
    /// ū_k = k / m.
    Uniform,
    /// ū_k proportional to the chord length from Q₀ to Q_k along the data polygon.
    ChordLength,
    /// ū_k proportional to Σ √|Q_j − Q_{j−1}| (the centripetal model).
    Centripetal,
}

/// A fitted curve with the parameters of its data points and its measured error.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit<T: Scalar, const D: usize> {
    /// The curve, a clamped B-spline on [0, 1].
    pub curve: BSplineCurve<T, D>,
    /// The parameter ū_k of every data point.
    pub parameters: Vec<T>,
    /// max_k |C(ū_k) − Q_k| (length units): bounds the distance from every data point to the
    /// curve from above.
    pub max_error: f64,
}

/// The parameters ū₀ = 0 < … < ū_m = 1 of the data points by `method`.
///
/// ```
/// use camber_geom::fit::{data_parameters, ParameterMethod};
/// use nalgebra::Point2;
/// let pts = [Point2::new(0.0_f64, 0.0), Point2::new(1.0, 0.0), Point2::new(5.0, 0.0)];
/// let chord = data_parameters(&pts, ParameterMethod::ChordLength)?;
/// assert!((chord[1] - 0.2).abs() < 1e-15);
/// let centripetal = data_parameters(&pts, ParameterMethod::Centripetal)?;
/// assert!((centripetal[1] - 1.0 / 3.0).abs() < 1e-15);
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// Errors: [`Error::TooFewDataPoints`] for fewer than two points, [`Error::NonFinite`], and
/// [`Error::CoincidentDataPoints`] when consecutive points coincide (chord-length and
/// centripetal only).
pub fn data_parameters<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    method: ParameterMethod,
) -> Result<Vec<T>> {
    check_points(points)?;
    if points.len() < 2 {
        return Err(Error::TooFewDataPoints {
            degree: 1,
            needed: 2,
            found: points.len(),
        });
    }
    let m = points.len() - 1;
    if method == ParameterMethod::Uniform {
        return Ok((0..=m)
            .map(|k| from_usize::<T>(k) / from_usize::<T>(m))
            .collect());
    }
    let mut cumulative = Vec::with_capacity(m + 1);
    cumulative.push(T::zero());
    let mut total = T::zero();
    for (k, pair) in points.windows(2).enumerate() {
        let d = (pair[1] - pair[0]).norm();
        if re(d) <= 0.0 {
            return Err(Error::CoincidentDataPoints { index: k + 1 });
        }
        total += match method {
            ParameterMethod::Centripetal => d.sqrt(),
            _ => d,
        };
        cumulative.push(total);
    }
    let mut out: Vec<T> = cumulative.into_iter().map(|c| c / total).collect();
    out[m] = T::one();
    Ok(out)
}

/// Checks the degree and the number of data points.
fn check_data<T: Scalar, const D: usize>(points: &[Point<T, D>], degree: usize) -> Result<()> {
    check_degree(degree)?;
    if points.len() < degree + 1 {
        return Err(Error::TooFewDataPoints {
            degree,
            needed: degree + 1,
            found: points.len(),
        });
    }
    Ok(())
}

/// The basis values of the p + 1 functions non-zero at u, with the index of the first.
fn basis_row<T: Scalar>(knots: &KnotVector<T>, degree: usize, u: T) -> (usize, Vec<T>) {
    let span = knots.find_span(degree, u);
    let mut values = vec![T::zero(); degree + 1];
    knots.basis_functions(span, u, degree, &mut values);
    (span - degree, values)
}

/// The first derivatives of the p + 1 functions non-zero at u, with the index of the first.
fn derivative_row<T: Scalar>(knots: &KnotVector<T>, degree: usize, u: T) -> (usize, Vec<T>) {
    let span = knots.find_span(degree, u);
    let mut values = vec![T::zero(); 2 * (degree + 1)];
    knots.basis_function_derivatives(span, u, degree, 1, &mut values);
    (span - degree, values.split_off(degree + 1))
}

/// Rows of control points as points, checking that they are finite.
fn to_points<T: Scalar, const D: usize>(
    solution: &DMatrix<T>,
    what: &'static str,
) -> Result<Vec<Point<T, D>>> {
    let mut points = Vec::with_capacity(solution.nrows());
    for r in 0..solution.nrows() {
        let row: SVector<T, D> = SVector::from_fn(|c, _| solution[(r, c)]);
        if row.iter().any(|&x| !re(x).is_finite()) {
            return Err(Error::SingularSystem { what });
        }
        points.push(Point::from(row));
    }
    Ok(points)
}

/// max_k |C(ū_k) − Q_k|.
fn max_error<T: Scalar, const D: usize>(
    curve: &BSplineCurve<T, D>,
    points: &[Point<T, D>],
    parameters: &[T],
) -> Result<f64> {
    let mut worst = 0.0_f64;
    for (q, &u) in points.iter().zip(parameters) {
        worst = worst.max(re((curve.point(u)? - q).norm()));
    }
    Ok(worst)
}

/// The clamped B-spline of `degree` through every point of `points` (at least degree + 1),
/// parameterized by `method`, and, when `end_derivatives` = Some((D₀, D₁)), with C′(0) = D₀ and
/// C′(1) = D₁ (length units per unit of the [0, 1] parameter: a unit tangent times the total
/// chord length is a natural size).
///
/// Errors: those of [`data_parameters`], [`Error::TooFewDataPoints`],
/// [`Error::DegreeTooHigh`], [`Error::NonFinite`] for a derivative, and
/// [`Error::SingularSystem`] (possible only with end derivatives of degree 1).
pub fn interpolate<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    degree: usize,
    method: ParameterMethod,
    end_derivatives: Option<(SVector<T, D>, SVector<T, D>)>,
) -> Result<Fit<T, D>> {
    check_data(points, degree)?;
    let parameters = data_parameters(points, method)?;
    interpolate_at(points, &parameters, degree, end_derivatives)
}

/// One row of an interpolation system: the first column and the values of the basis functions
/// (or their derivatives) non-zero at its parameter, and its right-hand side.
type CollocationRow<T, const D: usize> = ((usize, Vec<T>), SVector<T, D>);

/// [`interpolate`] with given parameters (strictly increasing from 0 to 1).
pub(crate) fn interpolate_at<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    parameters: &[T],
    degree: usize,
    end_derivatives: Option<(SVector<T, D>, SVector<T, D>)>,
) -> Result<Fit<T, D>> {
    let m = points.len() - 1;
    let p = degree;
    let (knots, size) = match &end_derivatives {
        None => (KnotVector::from_parameters(p, parameters)?, m + 1),
        Some((d0, d1)) => {
            for (index, v) in d0.iter().chain(d1.iter()).enumerate() {
                if !re(*v).is_finite() {
                    return Err(Error::NonFinite {
                        what: "end derivative coordinate",
                        index,
                        value: re(*v),
                    });
                }
            }
            // Each end parameter counted twice: one more knot span per end.
            let mut augmented = Vec::with_capacity(m + 3);
            augmented.push(parameters[0]);
            augmented.extend_from_slice(parameters);
            augmented.push(parameters[m]);
            (KnotVector::from_parameters(p, &augmented)?, m + 3)
        }
    };
    // The collocation rows (first column, values, right-hand side) in order, then the band
    // they span: about the degree on each side of the diagonal.
    let mut rows: Vec<CollocationRow<T, D>> = Vec::with_capacity(size);
    for (k, (q, &u)) in points.iter().zip(parameters).enumerate() {
        if let (Some((d0, _)), 1) = (&end_derivatives, k) {
            rows.push((derivative_row(&knots, p, parameters[0]), *d0));
        }
        if let (Some((_, d1)), true) = (&end_derivatives, k == m) {
            rows.push((derivative_row(&knots, p, parameters[m]), *d1));
        }
        rows.push((basis_row(&knots, p, u), q.coords));
    }
    let (mut kl, mut ku) = (0, 0);
    for (r, ((first, values), _)) in rows.iter().enumerate() {
        kl = kl.max(r.saturating_sub(*first));
        ku = ku.max((first + values.len()).saturating_sub(r + 1));
    }
    let mut a = BandedMatrix::<T>::zeros(size, kl, ku);
    let mut b = DMatrix::<T>::zeros(size, D);
    let singular = Error::SingularSystem {
        what: "interpolation",
    };
    for (r, ((first, values), rhs)) in rows.into_iter().enumerate() {
        for (j, v) in values.into_iter().enumerate() {
            a.set(r, first + j, v).ok_or(singular.clone())?;
        }
        for c in 0..D {
            b[(r, c)] = rhs[c];
        }
    }
    let solution = a.solve(b).ok_or(singular)?;
    let control = to_points(&solution, "interpolation")?;
    let curve = BSplineCurve::try_new(p, knots, control)?;
    let max_error = max_error(&curve, points, parameters)?;
    Ok(Fit {
        curve,
        parameters: parameters.to_vec(),
        max_error,
    })
}

/// The least-squares B-spline of `degree` with `control_points` control points
/// (degree + 1 ≤ control_points ≤ number of data points) minimising Σ |C(ū_k) − Q_k|² over the
/// data, with parameters by `method`; with `fixed_ends` the first and last control points are
/// the first and last data points, so the curve starts and ends on them.
///
/// ```
/// use camber_geom::fit::{approximate, ParameterMethod};
/// use nalgebra::Point2;
/// // Noisy samples of a straight line are approximated by a straight quadratic.
/// let pts: Vec<_> = (0..=10).map(|i| {
///     let x = f64::from(i);
///     Point2::new(x, 2.0 * x + if i % 2 == 0 { 0.01 } else { -0.01 })
/// }).collect();
/// let fit = approximate(&pts, 2, 4, ParameterMethod::ChordLength, true)?;
/// assert!(fit.max_error < 0.02);
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// Errors: those of [`data_parameters`], [`Error::TooFewDataPoints`] when there are fewer data
/// points than control points, [`Error::TooFewControlPoints`] for fewer than degree + 1 (or,
/// with fixed ends, fewer than 2) control points, [`Error::SingularSystem`].
pub fn approximate<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    degree: usize,
    control_points: usize,
    method: ParameterMethod,
    fixed_ends: bool,
) -> Result<Fit<T, D>> {
    check_data(points, degree)?;
    if control_points < degree + 1 {
        return Err(Error::TooFewControlPoints {
            degree,
            needed: degree + 1,
            found: control_points,
        });
    }
    if control_points > points.len() {
        return Err(Error::TooFewDataPoints {
            degree,
            needed: control_points,
            found: points.len(),
        });
    }
    let parameters = data_parameters(points, method)?;
    let knots = spread_knots(&parameters, degree, control_points);
    least_squares(points, &parameters, degree, knots, fixed_ends)
}

/// Knots for n + 1 control points over m + 1 parameters so that every span holds parameters
/// (clamped on [0, 1]).
fn spread_knots<T: Scalar>(
    parameters: &[T],
    degree: usize,
    control_points: usize,
) -> KnotVector<T> {
    let p = degree;
    let m = parameters.len() - 1;
    let n = control_points - 1;
    let mut knots = vec![T::zero(); p + 1];
    if n > p {
        let d = (m + 1) as f64 / (n - p + 1) as f64;
        for j in 1..=n - p {
            let jd = j as f64 * d;
            let i = (jd.floor() as usize).clamp(1, m);
            let alpha = cst::<T>(jd - i as f64);
            knots.push((T::one() - alpha) * parameters[i - 1] + alpha * parameters[i]);
        }
    }
    knots.extend(std::iter::repeat_n(T::one(), p + 1));
    KnotVector::new_unchecked(knots)
}

/// The largest least-squares system (unknown control points) solved by a dense SVD when its
/// normal equations are singular (a span without data): 2,000 unknowns is a 32 MB copy and a
/// few seconds; beyond that a singular system is reported instead.
const DENSE_FALLBACK_MAX: usize = 2_000;

/// Least squares on given knots through the normal equations (SVD when a span without data
/// makes them singular: the minimum-norm solution is taken).
fn least_squares<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    parameters: &[T],
    degree: usize,
    knots: KnotVector<T>,
    fixed_ends: bool,
) -> Result<Fit<T, D>> {
    let p = degree;
    let n = knots.len() - p - 2;
    let m = points.len() - 1;
    let (first, last) = (points[0].coords, points[m].coords);
    let unknowns: Vec<usize> = if fixed_ends && n >= 1 {
        (1..n).collect()
    } else {
        (0..=n).collect()
    };
    let rows: Vec<usize> = if fixed_ends && n >= 1 {
        (1..m).collect()
    } else {
        (0..=m).collect()
    };
    let mut control = vec![Point::<T, D>::origin(); n + 1];
    if fixed_ends && n >= 1 {
        control[0] = points[0];
        control[n] = points[m];
    }
    if !unknowns.is_empty() && !rows.is_empty() {
        let offset = unknowns[0];
        let size = unknowns.len();
        // Normal equations NᵀN x = Nᵀr, assembled row by row from the p + 1 non-zero basis
        // values (NᵀN is banded with half-width p).
        let mut normal = BandedMatrix::<T>::zeros(size, p, p);
        let mut rhs_all = DMatrix::<T>::zeros(size, D);
        for &k in &rows {
            let (start, values) = basis_row(&knots, p, parameters[k]);
            let mut rhs = points[k].coords;
            let mut active: Vec<(usize, T)> = Vec::with_capacity(p + 1);
            for (j, v) in values.into_iter().enumerate() {
                let i = start + j;
                if fixed_ends && i == 0 {
                    rhs -= first * v;
                } else if fixed_ends && i == n {
                    rhs -= last * v;
                } else {
                    active.push((i - offset, v));
                }
            }
            for &(i, vi) in &active {
                for &(j, vj) in &active {
                    // |i − j| ≤ p: both basis functions are non-zero at one parameter.
                    normal.add(i, j, vi * vj).ok_or(Error::SingularSystem {
                        what: "least-squares",
                    })?;
                }
                for c in 0..D {
                    rhs_all[(i, c)] += vi * rhs[c];
                }
            }
        }
        // Banded elimination first; a span without data makes NᵀN singular, and then the
        // SVD's minimum-norm solution is taken, on a dense copy, so only for systems of at
        // most DENSE_FALLBACK_MAX unknowns (larger ones report the singular system).
        let solution = match normal.clone().solve(rhs_all.clone()) {
            Some(x) if x.iter().all(|v| re(*v).is_finite()) => x,
            _ if size <= DENSE_FALLBACK_MAX => normal
                .to_dense()
                .svd(true, true)
                .solve(&rhs_all, cst::<T>(1e-13))
                .map_err(|_| Error::SingularSystem {
                    what: "least-squares",
                })?,
            _ => {
                return Err(Error::SingularSystem {
                    what: "least-squares",
                })
            }
        };
        let solved = to_points::<T, D>(&solution, "least-squares")?;
        for (&i, q) in unknowns.iter().zip(solved) {
            control[i] = q;
        }
    }
    let curve = BSplineCurve::try_new(p, knots, control)?;
    let max_error = max_error(&curve, points, parameters)?;
    Ok(Fit {
        curve,
        parameters: parameters.to_vec(),
        max_error,
    })
}

/// A B-spline of `degree` within `tolerance` (length units, > 0) of every data point (at its
/// parameter), with as few knots as the span splitting finds: it starts from one polynomial
/// span and splits, between their middle data parameters, the spans whose data are too far,
/// refitting by least squares with fixed ends each time; if a span runs out of data to split,
/// it interpolates. The result's `max_error` is measured, never above the tolerance.
///
/// ```
/// use camber_geom::fit::{fit_to_tolerance, ParameterMethod};
/// use nalgebra::Point2;
/// let pts: Vec<_> = (0..=40).map(|i| {
///     let t = f64::from(i) / 40.0 * std::f64::consts::PI;
///     Point2::new(t, t.sin())
/// }).collect();
/// let fit = fit_to_tolerance(&pts, 3, 1e-4, ParameterMethod::ChordLength)?;
/// assert!(fit.max_error <= 1e-4);
/// assert!(fit.curve.control_points().len() < pts.len());
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// Errors: [`Error::NonPositiveTolerance`], and those of [`approximate`].
pub fn fit_to_tolerance<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    degree: usize,
    tolerance: f64,
    method: ParameterMethod,
) -> Result<Fit<T, D>> {
    if !tolerance.is_finite() {
        return Err(Error::NonFinite {
            what: "fitting tolerance",
            index: 0,
            value: tolerance,
        });
    }
    if tolerance <= 0.0 {
        return Err(Error::NonPositiveTolerance { value: tolerance });
    }
    check_data(points, degree)?;
    let parameters = data_parameters(points, method)?;
    fit_to_tolerance_at(points, &parameters, degree, tolerance)
}

/// [`fit_to_tolerance`] with given parameters ū₀ = 0 < … < ū_m = 1 (checked as a knot-like
/// sequence: finite, increasing, from 0 to 1) and a tolerance already checked.
pub(crate) fn fit_to_tolerance_at<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    parameters: &[T],
    degree: usize,
    tolerance: f64,
) -> Result<Fit<T, D>> {
    check_data(points, degree)?;
    let parameters = parameters.to_vec();
    let p = degree;
    let mut interior: Vec<T> = Vec::new();
    loop {
        let mut knots = vec![T::zero(); p + 1];
        knots.extend_from_slice(&interior);
        knots.extend(std::iter::repeat_n(T::one(), p + 1));
        let count = interior.len() + p + 1;
        if count >= points.len() {
            return interpolate_at(points, &parameters, p, None);
        }
        let fit = least_squares(
            points,
            &parameters,
            p,
            KnotVector::new_unchecked(knots),
            true,
        )?;
        if fit.max_error <= tolerance {
            return Ok(fit);
        }
        // Spans (between consecutive breaks) whose data are too far.
        let mut breaks = vec![T::zero()];
        breaks.extend_from_slice(&interior);
        breaks.push(T::one());
        let mut added = Vec::new();
        for w in breaks.windows(2) {
            let inside: Vec<usize> = (0..points.len())
                .filter(|&k| parameters[k] >= w[0] && parameters[k] <= w[1])
                .collect();
            let bad = inside.iter().any(|&k| {
                fit.curve
                    .point(parameters[k])
                    .map(|c| re((c - points[k]).norm()) > tolerance)
                    .unwrap_or(true)
            });
            let strictly: Vec<T> = inside
                .iter()
                .map(|&k| parameters[k])
                .filter(|&u| u > w[0] && u < w[1])
                .collect();
            if bad && strictly.len() >= 2 {
                let i = strictly.len() / 2;
                added.push((strictly[i - 1] + strictly[i]) * cst::<T>(0.5));
            }
        }
        if added.is_empty() {
            return interpolate_at(points, &parameters, p, None);
        }
        interior.extend(added);
        interior.sort_by(|a, b| re(*a).total_cmp(&re(*b)));
    }
}
