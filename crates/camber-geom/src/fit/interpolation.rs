//! Global interpolation: the clamped B-spline through every data point, optionally with end
//! derivatives.

use nalgebra::{DMatrix, Point, SVector};

use super::{check_data, data_parameters, Fit, ParameterMethod};
use crate::banded::BandedMatrix;
use crate::bspline::BSplineCurve;
use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::knots::KnotVector;
use crate::scalar::{re, Scalar};

/// The basis values of the p + 1 functions non-zero at u, with the index of the first.
fn basis_row<T: Scalar>(knots: &KnotVector<T>, degree: usize, u: T) -> (usize, Vec<T>) {
    let span = knots.find_span(degree, u);
    let mut values = vec![T::zero(); degree + 1];
    knots.basis_functions(span, u, degree, &mut values);
    (span - degree, values)
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

/// The first derivatives of the p + 1 functions non-zero at u, with the index of the first.
fn derivative_row<T: Scalar>(knots: &KnotVector<T>, degree: usize, u: T) -> (usize, Vec<T>) {
    let span = knots.find_span(degree, u);
    let mut values = vec![T::zero(); 2 * (degree + 1)];
    knots.basis_function_derivatives(span, u, degree, 1, &mut values);
    (span - degree, values.split_off(degree + 1))
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
