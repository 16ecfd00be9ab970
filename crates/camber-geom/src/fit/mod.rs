//! Curves through and near data points: global interpolation, least-squares approximation
//! with a given number of control points, and fitting to a tolerance with adaptive knots and
//! as few control points as the search finds. The results are clamped B-splines on [0, 1].
//!
//! - **Parameters.** Each data point Q_k gets a parameter ū_k ∈ [0, 1]: equally spaced
//!   ([`ParameterMethod::Uniform`]), proportional to the cumulative chord length
//!   ([`ParameterMethod::ChordLength`]) or to the cumulative square roots of the chord
//!   lengths ([`ParameterMethod::Centripetal`], which keeps sharp turns from overshooting).
//! - **Interpolation** solves Σ_i N_{i,p}(ū_k) P_i = Q_k for all k (plus, with end
//!   derivatives, C′(0) = D₀ and C′(1) = D₁ as two more rows and two more unknowns), knots by
//!   averaging the parameters so that every span holds one (the system is then banded and
//!   non-singular by the Schoenberg–Whitney theorem). Banded elimination solves it.
//! - **Least squares** with n + 1 < m + 1 control points minimises Σ |C(ū_k) − Q_k|² through
//!   the banded normal equations, optionally with the end control points fixed on the end data
//!   points. Its knots are averaged from the parameters ([`KnotPlacement::Averaged`]: every
//!   span holds data) or placed adaptively ([`KnotPlacement::Adaptive`]: spread by the errors
//!   of trial fits so that all spans err alike, with the parameters corrected to foot points).
//! - **Fitting to a tolerance** refines the knots where the fit errs, then searches the
//!   number of knots downwards with adaptively placed knots (see [`fit_to_tolerance_with`]);
//!   it ends in interpolation only if the tolerance needs as many control points as points.
//! - **Errors are distances.** The `max_error` of an approximation is the largest distance
//!   from a data point to the curve (found by the toolkit's closest-point search), not a
//!   residual at an assigned parameter.
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

mod ends;
mod interpolation;
mod knot_placement;
mod least_squares;
mod parametric;
mod power_form;
mod projection;
pub mod split;
mod tolerance;

use nalgebra::Point;

use ends::{EndCondition, Ends};
pub(crate) use ends::{EndCondition as FitEnd, Ends as FitEnds};
pub use interpolation::interpolate;
pub(crate) use interpolation::interpolate_at;
use least_squares::clamped_knots;
pub(crate) use parametric::fit_at_parameters;
pub use split::{fit_split, JointContinuity, SplitAt, SplitFit};
use tolerance::{ErrorMeasure, Problem};

use crate::bspline::BSplineCurve;
use crate::budget::Budget;
use crate::curve::check_points;
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

/// How the interior knots of a least-squares fit are placed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum KnotPlacement {
    /// Interpolated between the data parameters at equal steps of the data count, so every
    /// span holds data: one least-squares solve.
    Averaged,
    /// Spread by the error density of trial fits (every span expected to err alike), with the
    /// parameters corrected to foot points: a few solves, a smaller error for the same count.
    #[default]
    Adaptive,
}

/// Checks a fitting tolerance: finite and positive.
fn check_tolerance(tolerance: f64) -> Result<()> {
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
    Ok(())
}

/// The least-squares B-spline of `degree` with `control_points` control points
/// (degree + 1 ≤ control_points ≤ number of data points) minimising Σ |C(ū_k) − Q_k|² over the
/// data, with parameters by `method` and knots averaged from them; with `fixed_ends` the first
/// and last control points are the first and last data points, so the curve starts and ends on
/// them. `max_error` is the largest distance from a data point to the curve.
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
    approximate_with(
        points,
        control_points,
        &FitOptions {
            degree,
            method,
            knots: KnotPlacement::Averaged,
            fixed_ends,
        },
    )
}

/// Settings of [`approximate_with`] and [`fit_to_tolerance_with`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FitOptions {
    /// The degree p (default 3).
    pub degree: usize,
    /// How the data get their first parameters (default [`ParameterMethod::Centripetal`]).
    pub method: ParameterMethod,
    /// How the knots are placed (default [`KnotPlacement::Adaptive`]; fitting to a tolerance
    /// with averaged knots searches the count with averaged knots and parametric errors).
    pub knots: KnotPlacement,
    /// Whether the curve starts and ends on the first and last data points (default true).
    pub fixed_ends: bool,
}

impl Default for FitOptions {
    fn default() -> Self {
        Self {
            degree: 3,
            method: ParameterMethod::Centripetal,
            knots: KnotPlacement::Adaptive,
            fixed_ends: true,
        }
    }
}

impl FitOptions {
    /// Sets [`degree`](Self::degree).
    pub fn with_degree(mut self, degree: usize) -> Self {
        self.degree = degree;
        self
    }

    /// Sets [`method`](Self::method).
    pub fn with_method(mut self, method: ParameterMethod) -> Self {
        self.method = method;
        self
    }

    /// Sets [`knots`](Self::knots).
    pub fn with_knots(mut self, knots: KnotPlacement) -> Self {
        self.knots = knots;
        self
    }

    /// Sets [`fixed_ends`](Self::fixed_ends).
    pub fn with_fixed_ends(mut self, fixed_ends: bool) -> Self {
        self.fixed_ends = fixed_ends;
        self
    }

    /// The end conditions of the least-squares problems for `points`.
    fn ends<T: Scalar, const D: usize>(&self, points: &[Point<T, D>]) -> Ends<T, D> {
        match (self.fixed_ends, points.first(), points.last()) {
            (true, Some(&a), Some(&b)) => Ends {
                start: EndCondition::Fixed(a),
                end: EndCondition::Fixed(b),
            },
            _ => Ends {
                start: EndCondition::Free,
                end: EndCondition::Free,
            },
        }
    }

    /// The error measure of the knot placement.
    fn measure(&self) -> ErrorMeasure {
        match self.knots {
            KnotPlacement::Adaptive => ErrorMeasure::Projected,
            KnotPlacement::Averaged => ErrorMeasure::Parametric,
        }
    }
}

/// The least-squares B-spline with `control_points` control points under `options`: with
/// [`KnotPlacement::Averaged`] as [`approximate`]; with [`KnotPlacement::Adaptive`] the knots
/// are spread by the error density of trial fits (from averaged knots, re-spread while the
/// largest error drops) and the data parameters are corrected to foot points, so the same
/// number of control points follows the data more closely.
///
/// ```
/// use camber_geom::fit::{approximate_with, FitOptions, KnotPlacement};
/// use nalgebra::Point2;
/// // A sharp bend: adaptive knots gather at it.
/// let pts: Vec<_> = (0..=200).map(|i| {
///     let x = f64::from(i) / 100.0 - 1.0;
///     Point2::new(x, (x * x + 1e-3).sqrt())
/// }).collect();
/// let averaged = approximate_with(&pts, 12, &FitOptions::default().with_knots(KnotPlacement::Averaged))?;
/// let adaptive = approximate_with(&pts, 12, &FitOptions::default())?;
/// assert!(adaptive.max_error < 0.5 * averaged.max_error);
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// Errors: as [`approximate`].
pub fn approximate_with<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    control_points: usize,
    options: &FitOptions,
) -> Result<Fit<T, D>> {
    let degree = options.degree;
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
    let parameters = data_parameters(points, options.method)?;
    let ends = options.ends(points);
    let knots = spread_knots(&parameters, degree, control_points);
    let curve = ends::solve(points, &parameters, degree, &knots, &ends)?;
    let fit = match options.knots {
        KnotPlacement::Averaged => {
            // The distances move copies of the parameters: the fit keeps those it was made at.
            let mut errors = Vec::with_capacity(points.len());
            let mut feet = parameters.clone();
            projection::parametric_distances(&curve, points, &parameters, &mut errors)?;
            let max_error = projection::distances_to_curve(&curve, points, &mut feet, &mut errors)?;
            Fit {
                curve,
                parameters,
                max_error,
            }
        }
        KnotPlacement::Adaptive => {
            let budget = Budget::default();
            let problem = Problem::new(
                points,
                &parameters,
                degree,
                ends,
                options.measure(),
                &budget,
            );
            problem.finish(problem.best_with_count(problem.averaged_knots(control_points))?)?
        }
    };
    Ok(fit)
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
    let mut interior = Vec::new();
    if n > p {
        let d = (m + 1) as f64 / (n - p + 1) as f64;
        for j in 1..=n - p {
            let jd = j as f64 * d;
            let i = (jd.floor() as usize).clamp(1, m);
            let alpha = cst::<T>(jd - i as f64);
            interior.push((T::one() - alpha) * parameters[i - 1] + alpha * parameters[i]);
        }
    }
    clamped_knots(p, &interior)
}

/// A B-spline of `degree` within `tolerance` (length units, > 0) of every data point, with
/// adaptive knots and as few control points as the search finds; see
/// [`fit_to_tolerance_with`] (this is it with the default options of that degree and
/// parameter method).
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
/// Errors: [`Error::NonPositiveTolerance`], [`Error::NonFinite`] for the tolerance, and those
/// of [`approximate`].
pub fn fit_to_tolerance<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    degree: usize,
    tolerance: f64,
    method: ParameterMethod,
) -> Result<Fit<T, D>> {
    fit_to_tolerance_with(
        points,
        tolerance,
        &FitOptions::default()
            .with_degree(degree)
            .with_method(method),
        &Budget::default(),
    )
}

/// A B-spline within `tolerance` (length units, > 0) of every data point — the largest
/// distance from a data point to the curve, `max_error`, is never above it — with as few
/// control points as the search finds: knots refined where the fit errs, then
/// the count searched downwards with knots spread by the error density, parameters corrected
/// to foot points. It interpolates only when the tolerance needs as many control points as
/// there are points.
///
/// ```
/// use camber_geom::budget::Budget;
/// use camber_geom::fit::{fit_to_tolerance_with, FitOptions};
/// use nalgebra::Point2;
/// // A quarter ellipse, 200 points: a handful of control points hold it to 1e-5.
/// let pts: Vec<_> = (0..200).map(|i| {
///     let t = f64::from(i) / 199.0 * std::f64::consts::FRAC_PI_2;
///     Point2::new(2.0 * t.cos(), t.sin())
/// }).collect();
/// let fit = fit_to_tolerance_with(&pts, 1e-5, &FitOptions::default(), &Budget::default())?;
/// assert!(fit.max_error <= 1e-5);
/// assert!(fit.curve.control_points().len() < 15);
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// The work runs under `budget`: every trial fit costs a few units per data point, and the
/// default limit ([`default_limit`](crate::budget::default_limit) of the point count) allows
/// hundreds of trials.
///
/// Errors: [`Error::NonPositiveTolerance`], [`Error::NonFinite`] for the tolerance,
/// [`Error::BudgetExhausted`] / [`Error::Cancelled`] (operation "fitting"), and those of
/// [`approximate`].
pub fn fit_to_tolerance_with<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    tolerance: f64,
    options: &FitOptions,
    budget: &Budget,
) -> Result<Fit<T, D>> {
    check_tolerance(tolerance)?;
    check_data(points, options.degree)?;
    let parameters = data_parameters(points, options.method)?;
    let problem = Problem::new(
        points,
        &parameters,
        options.degree,
        options.ends(points),
        options.measure(),
        budget,
    );
    problem.finish(problem.fit_to_tolerance(tolerance)?)
}
