//! Fitting at fixed parameters from given knots, splitting the spans that err: the fit the
//! offsets use, whose curve must keep the parameterization (and the knot multiplicities) it
//! is given.

use nalgebra::Point;

use super::ends::{solve, Ends};
use super::interpolation::interpolate_at;
use super::projection::parametric_distances;
use super::{check_data, Fit};
use crate::budget::Meter;
use crate::errors::Result;
use crate::knots::KnotVector;
use crate::scalar::{cst, re, Scalar};

/// A B-spline of `degree` held at its ends by `ends` whose parametric error |C(ū_k) − Q_k| is within
/// `tolerance` at the given `parameters` (increasing from 0 to 1), starting from the interior
/// knots `initial` (sorted, inside (0, 1), each repeated at most `degree` times, every span
/// holding data) and halving, between their middle data parameters, every span between
/// distinct knots whose data err; the initial multiplicities stay. It interpolates when the
/// knots would be as many as the data carry.
///
/// Each pass is one least-squares solve and one evaluation per data point, and finds the data
/// of every span by binary search in the parameters, so a pass costs O(m log m); the passes,
/// which split every offending span at once, number about log m. Charges one unit per data
/// point to `meter` twice per pass.
///
/// Ends held to more than their points
/// ([`EndCondition::Clamped`](super::ends::EndCondition::Clamped)) are never given up for an
/// interpolation: where the splitting stops (no span left to split, or as many control
/// points as data) the last least-squares curve is returned with its measured error, which may
/// then exceed `tolerance`.
pub(crate) fn fit_at_parameters<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    parameters: &[T],
    degree: usize,
    tolerance: f64,
    initial: &[T],
    ends: &Ends<T, D>,
    meter: &mut Meter<'_>,
) -> Result<Fit<T, D>> {
    check_data(points, degree)?;
    let parameters = parameters.to_vec();
    let p = degree;
    let held = !ends.only_points();
    let mut last: Option<Fit<T, D>> = None;
    let units = u64::try_from(points.len()).unwrap_or(u64::MAX);
    let mut interior: Vec<T> = initial.to_vec();
    let mut errors = Vec::with_capacity(points.len());
    loop {
        let mut knots = Vec::with_capacity(interior.len() + 2 * p + 2);
        knots.extend(std::iter::repeat_n(T::zero(), p + 1));
        knots.extend_from_slice(&interior);
        knots.extend(std::iter::repeat_n(T::one(), p + 1));
        let count = interior.len() + p + 1;
        meter.charge(units)?;
        if count >= points.len() {
            if let Some(fit) = last.filter(|_| held) {
                return Ok(fit);
            }
            return interpolate_at(points, &parameters, p, None);
        }
        let curve = solve(
            points,
            &parameters,
            p,
            &KnotVector::new_unchecked(knots),
            ends,
        )?;
        meter.charge(units)?;
        let max_error = parametric_distances(&curve, points, &parameters, &mut errors)?;
        if max_error <= tolerance {
            return Ok(Fit {
                curve,
                parameters,
                max_error,
            });
        }
        // Spans (between consecutive distinct breaks) whose data are too far.
        let mut breaks = vec![T::zero()];
        for &k in &interior {
            if breaks.last().is_some_and(|&l| k > l) {
                breaks.push(k);
            }
        }
        breaks.push(T::one());
        let mut added = Vec::new();
        for w in breaks.windows(2) {
            // The data with w0 ≤ ū ≤ w1, and those strictly inside.
            let lo = parameters.partition_point(|&u| u < w[0]);
            let hi = parameters.partition_point(|&u| u <= w[1]);
            if !errors[lo..hi].iter().any(|&e| e > tolerance) {
                continue;
            }
            let inner_lo = parameters.partition_point(|&u| u <= w[0]);
            let inner_hi = parameters.partition_point(|&u| u < w[1]);
            let strictly = &parameters[inner_lo..inner_hi.max(inner_lo)];
            if strictly.len() >= 2 {
                let i = strictly.len() / 2;
                added.push((strictly[i - 1] + strictly[i]) * cst::<T>(0.5));
            }
        }
        if held {
            last = Some(Fit {
                curve,
                parameters: parameters.clone(),
                max_error,
            });
        }
        if added.is_empty() {
            if let Some(fit) = last {
                return Ok(fit);
            }
            return interpolate_at(points, &parameters, p, None);
        }
        interior.extend(added);
        interior.sort_by(|a, b| re(*a).total_cmp(&re(*b)));
    }
}
