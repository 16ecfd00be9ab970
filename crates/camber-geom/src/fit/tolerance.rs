//! Fitting to a tolerance with adaptive knots and a search for the fewest control points.
//!
//! 1. **Trial fit on given knots.** Least squares on the knots with the data's parameters,
//!    then [`CORRECTIONS`] rounds of parameter correction (every parameter moved to the foot
//!    point of its data point on the last curve, then least squares again), then the foot
//!    points on the final curve: the error of a trial is the largest distance from a data point
//!    to its foot point (with [`ErrorMeasure::Parametric`] the plain |C(ū_k) − Q_k| instead,
//!    parameters unchanged).
//! 2. **Refinement.** From one polynomial span, every span erring above the tolerance τ is cut
//!    into ⌈(E_j/τ)^{1/(p+1)}⌉ pieces, until a trial is within τ: a feasible knot count. Each
//!    step adds at least an eighth of the knots (spread by the error density when the cuts add
//!    fewer), so a refinement that stalls on noise reaches the count of interpolation in
//!    O(log m) trials.
//! 3. **Search.** Every count is tried with knots equidistributing the error density of the
//!    best fit so far (see [`knot_placement`](super::knot_placement)), re-spread [`RESPREADS`]
//!    times by its own errors. The density also predicts the count the tolerance needs (a span
//!    erring E_j becomes (E_j/τ)^{1/(p+1)} spans); the search goes down to the predicted count
//!    while that succeeds, then bisects between the largest count that failed and the
//!    smallest that succeeded.
//!
//! Interpolation is the answer only when the knots would be as many as the data carry.

use std::cell::RefCell;

use nalgebra::Point;

use super::ends::{solve, solve_or, Ends};
use super::interpolation::interpolate_at;
use super::knot_placement::{index_of, max_interior, parameter_at, refine, separate, Density};
use super::least_squares::{clamped_knots, OnSingular};
use super::projection::{correct_parameters, distances_to_curve, parametric_distances};
use super::Fit;
use crate::bspline::BSplineCurve;
use crate::budget::{default_limit, Budget, Meter};
use crate::errors::{Error, Result};
use crate::scalar::{cst, re, Scalar};

/// Rounds of parameter correction per trial (each one least-squares solve and one foot-point
/// pass). One round, then the final foot points of three Newton steps, gives the counts of two
/// rounds on the NACA benchmark sections (medians within one control point either way) for
/// about 30% less work.
pub(crate) const CORRECTIONS: usize = 1;

/// The least span error an error density counts, as a fraction of the tolerance. A fit within
/// the tolerance that holds few data points per span nearly interpolates them: its spans err
/// far below the tolerance however long they are, and a density from those errors predicts
/// that a few knots will do (from 52 interior knots at 7e-7 it predicted 8 for 1e-5 on a
/// 71-point section; 30 fail) and spreads the knots of a trial away from where they are
/// needed. Counting every span as erring at least 3% of the tolerance bounds a prediction at
/// about 0.03^{1/(p+1)} (0.42 for cubics) of the spans it starts from, and keeps knots in the
/// sparse stretches; 1%, 3%, 5%, 10% and 30% gave medians of 34.5, 34, 34, 34 and 37 control
/// points at 1e-5 on the benchmark sections (two correction rounds; 35.5 without a floor).
pub(crate) const TOLERANCE_FLOOR: f64 = 0.03;

/// How far a trial's control points may stray from the data, in data diameters beyond the
/// data's box, before the trial counts as failed. A least-squares spline on knots the data
/// supports keeps its control polygon near the data; a span the corrected parameters leave
/// (nearly) empty makes the system near-singular, and its solution passes through the data by
/// wild excursions (control points at 10⁷ for data of size 10): within the tolerance by the
/// numbers, but not a curve anyone asked for, and one no closest-point search can measure.
const STRAY: f64 = 8.0;

/// How often the knots of one count are re-spread by the errors of their own fit during the
/// search.
const RESPREADS: usize = 1;

/// A refinement step adds at least 1/GROWTH of the knots it starts from (see [`grown`]).
const GROWTH: usize = 8;

/// How often the search goes down to the count predicted by the error density.
const PREDICTIONS: usize = 4;

/// How often [`Problem::best_with_count`] re-spreads the knots at most.
const ADAPTIVE_ROUNDS: usize = 6;

/// How the error of a trial is measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum ErrorMeasure {
    /// Distance to the foot point, parameters corrected (the distance to the curve).
    Projected,
    /// |C(ū_k) − Q_k| at the given parameters, which stay.
    Parametric,
}

/// One fit on given knots.
#[derive(Debug, Clone)]
pub(crate) struct Trial<T: Scalar, const D: usize> {
    /// The interior knots in data-index coordinates (see
    /// [`knot_placement`](super::knot_placement)).
    pub interior: Vec<f64>,
    /// The curve.
    pub curve: BSplineCurve<T, D>,
    /// The data parameters (foot points with [`ErrorMeasure::Projected`]).
    pub parameters: Vec<T>,
    /// The error of every data point.
    pub errors: Vec<f64>,
    /// The largest of them.
    pub max_error: f64,
}

impl<T: Scalar, const D: usize> Trial<T, D> {
    /// The number of interior knots.
    pub fn knot_count(&self) -> usize {
        self.interior.len()
    }
}

/// The problem of one fit: data, start parameters, degree, end roles, error measure, and the
/// meter its trials charge.
pub(crate) struct Problem<'a, T: Scalar, const D: usize> {
    points: &'a [Point<T, D>],
    parameters: &'a [T],
    /// The start parameters as f64.
    start: Vec<f64>,
    degree: usize,
    ends: Ends<T, D>,
    measure: ErrorMeasure,
    /// Charged per trial: one unit per data point and least-squares solve or foot-point pass.
    meter: RefCell<Meter<'a>>,
}

impl<'a, T: Scalar, const D: usize> Problem<'a, T, D> {
    /// The problem of fitting `points` from `parameters` (increasing from 0 to 1), its work
    /// under `budget` (operation "fitting", the default limit of the point count).
    pub fn new(
        points: &'a [Point<T, D>],
        parameters: &'a [T],
        degree: usize,
        ends: Ends<T, D>,
        measure: ErrorMeasure,
        budget: &'a Budget,
    ) -> Self {
        Self {
            points,
            parameters,
            start: parameters.iter().map(|&u| re(u)).collect(),
            degree,
            ends,
            measure,
            meter: RefCell::new(budget.meter("fitting", default_limit(points.len()))),
        }
    }

    /// Charges the work of a trial: one unit per data point and pass over the data.
    fn charge(&self, passes: usize) -> Result<()> {
        let units = u64::try_from(self.points.len().saturating_mul(passes)).unwrap_or(u64::MAX);
        self.meter.borrow_mut().charge(units)
    }

    /// The averaged interior knots of `control_points` control points in data-index
    /// coordinates, spread as interpolation's averaged knots are: with h = m/n (n + 1 control
    /// points, h ≥ 1), knot j (1 ≤ j ≤ n − p) at s = (j + (p − 1)/2)·h, the average of p
    /// consecutive points of a grid of n + 1 over the data. Consecutive knots are h apart and
    /// the first and last (p + 1)/2·h from the ends, so every span holds data strictly inside
    /// and the end spans more than one: the least squares stays regular up to n = m − 1. (The
    /// rule s = j·(m + 1)/(n − p + 1) − 1 put the first knot a few thousandths of an index
    /// from the start near interpolation: 1,000 noisy points on 999 control points gave a
    /// singular system.)
    pub fn averaged_knots(&self, control_points: usize) -> Vec<f64> {
        let (p, m) = (self.degree, self.points.len() - 1);
        let n = control_points.saturating_sub(1);
        if n <= p {
            return Vec::new();
        }
        let h = m as f64 / n as f64;
        let offset = (p as f64 - 1.0) / 2.0;
        (1..=n - p)
            .map(|j| ((j as f64 + offset) * h).clamp(0.0, m as f64))
            .collect()
    }

    /// The data-index coordinates of interior knots given as parameters.
    pub fn knots_to_indices(&self, knots: &[f64]) -> Vec<f64> {
        knots.iter().map(|&u| index_of(&self.start, u)).collect()
    }

    /// A trial fit on the `interior` knots (data-index coordinates), from the start parameters.
    pub fn trial(&self, interior: Vec<f64>) -> Result<Trial<T, D>> {
        self.charge(match self.measure {
            ErrorMeasure::Parametric => 2,
            ErrorMeasure::Projected => 2 * CORRECTIONS + 2,
        })?;
        let mut knots_t: Vec<T> = Vec::with_capacity(interior.len());
        for &s in &interior {
            let u = cst::<T>(parameter_at(&self.start, s));
            // Strictly increasing inside (0, 1): a repeated or end value is dropped.
            if re(u) > 0.0 && re(u) < 1.0 && knots_t.last().is_none_or(|&l| u > l) {
                knots_t.push(u);
            }
        }
        let knots = clamped_knots(self.degree, &knots_t);
        let mut parameters = self.parameters.to_vec();
        let mut errors = Vec::with_capacity(self.points.len());
        let mut curve = solve(self.points, &parameters, self.degree, &knots, &self.ends)?;
        let max_error = match self.measure {
            ErrorMeasure::Parametric => {
                parametric_distances(&curve, self.points, &parameters, &mut errors)?
            }
            ErrorMeasure::Projected => {
                for _ in 0..CORRECTIONS {
                    correct_parameters(&curve, self.points, &mut parameters, &mut errors, 1)?;
                    // Corrected parameters can leave a span without data (the foot points of
                    // noisy data near interpolation land on a neighbouring wiggle): the least
                    // squares is then singular, or near it and its curve strays. The trial
                    // keeps the curve it had (no dense minimum-norm solve, O(m³) work its
                    // charge does not count); the final foot points are taken on that one.
                    let next = solve_or(
                        self.points,
                        &parameters,
                        self.degree,
                        &knots,
                        &self.ends,
                        OnSingular::Fail,
                    );
                    match next {
                        Ok(next) if !strays(&next, self.points) => curve = next,
                        Ok(_) | Err(Error::SingularSystem { .. }) => break,
                        Err(e) => return Err(e),
                    }
                }
                correct_parameters(&curve, self.points, &mut parameters, &mut errors, 3)?
            }
        };
        let max_error = if strays(&curve, self.points) {
            f64::INFINITY
        } else {
            max_error
        };
        Ok(Trial {
            interior,
            curve,
            parameters,
            errors,
            max_error,
        })
    }

    /// The best trial with `count` interior knots spread by the error density of `guide`, every
    /// span counted as erring `floor` at least (length units; [`TOLERANCE_FLOOR`]·τ while
    /// fitting to the tolerance τ, 0 for the best fit of a given count).
    fn spread(&self, count: usize, guide: &Trial<T, D>, floor: f64) -> Result<Trial<T, D>> {
        let n = self.points.len();
        let density = Density::from_errors(&guide.interior, &guide.errors, self.degree, floor);
        let knots = separate(&density.equidistribute(count), n, self.degree);
        let mut best = self.trial(knots)?;
        for _ in 0..RESPREADS {
            let density = Density::from_errors(&best.interior, &best.errors, self.degree, floor);
            let knots = separate(&density.equidistribute(count), n, self.degree);
            let next = self.trial(knots)?;
            if next.max_error < best.max_error {
                best = next;
            } else {
                break;
            }
        }
        Ok(best)
    }

    /// The best trial with the count of `interior` knots: from those knots, re-spread by the
    /// errors of the last fit while the largest error drops ([`ADAPTIVE_ROUNDS`] at most).
    pub fn best_with_count(&self, interior: Vec<f64>) -> Result<Trial<T, D>> {
        let count = interior.len();
        let mut best = self.trial(interior)?;
        for _ in 0..ADAPTIVE_ROUNDS {
            let next = self.spread(count, &best, 0.0)?;
            if next.max_error < best.max_error {
                best = next;
            } else {
                break;
            }
        }
        Ok(best)
    }

    /// The fit of a trial: with [`ErrorMeasure::Projected`] its errors become distances to the
    /// whole curve ([`distances_to_curve`]); with [`ErrorMeasure::Parametric`] they stay.
    pub fn finish(&self, trial: Trial<T, D>) -> Result<Fit<T, D>> {
        let Trial {
            curve,
            mut parameters,
            mut errors,
            max_error,
            ..
        } = trial;
        let max_error = match self.measure {
            ErrorMeasure::Projected => {
                distances_to_curve(&curve, self.points, &mut parameters, &mut errors)?
            }
            ErrorMeasure::Parametric => max_error,
        };
        Ok(Fit {
            curve,
            parameters,
            max_error,
        })
    }

    /// The interpolant (when the tolerance needs every data point as a control point); at a
    /// joint of a split fit, where the interpolant cannot hold the joint's tangent, `last`
    /// (the trial with the most knots the data carry) if it is within the tolerance.
    fn interpolation(&self, last: Trial<T, D>, tolerance: f64) -> Result<Trial<T, D>> {
        if !self.ends.only_points() {
            return if last.max_error <= tolerance {
                Ok(last)
            } else {
                Err(Error::ToleranceNotMet {
                    tolerance,
                    reached: last.max_error,
                })
            };
        }
        let fit = interpolate_at(self.points, self.parameters, self.degree, None)?;
        if fit.max_error > tolerance {
            return Err(Error::ToleranceNotMet {
                tolerance,
                reached: fit.max_error,
            });
        }
        let errors = vec![0.0; self.points.len()];
        let knots: Vec<f64> = fit.curve.knots().as_slice()
            [self.degree + 1..fit.curve.knots().len() - self.degree - 1]
            .iter()
            .map(|&u| re(u))
            .collect();
        let interior = self.knots_to_indices(&knots);
        Ok(Trial {
            interior,
            curve: fit.curve,
            parameters: fit.parameters,
            max_error: fit.max_error,
            errors,
        })
    }

    /// The fit within `tolerance` with the fewest interior knots the search finds.
    pub fn fit_to_tolerance(&self, tolerance: f64) -> Result<Trial<T, D>> {
        let p = self.degree;
        let limit = max_interior(self.points.len(), p);
        let floor = TOLERANCE_FLOOR * tolerance;
        // Refinement up to a feasible count.
        let mut interior: Vec<f64> = Vec::new();
        let feasible = loop {
            let t = self.trial(interior)?;
            if t.max_error <= tolerance {
                break t;
            }
            let refined = refine(&t.interior, &t.errors, p, tolerance);
            let mut next = separate(&refined, self.points.len(), p);
            let least = grown(t.knot_count(), limit);
            if next.len() < least {
                // The refinement stalls: a few spans err above the tolerance, their new
                // knots are pushed aside by the one-index spacing and the error stays (noise
                // above the tolerance near interpolation). The count grows by at least an
                // eighth instead, knots spread by the error density, so the refinement
                // reaches the largest count in O(log m) trials, not one per knot or two.
                let density = Density::from_errors(&t.interior, &t.errors, p, floor);
                next = separate(&density.equidistribute(least), self.points.len(), p);
            }
            if t.knot_count() >= limit || next.len() <= t.knot_count() {
                // The data carry no more knots: before interpolating, the best fit with one
                // control point fewer than points (as `approximate_with` finds it).
                let fewer = self.best_with_count(self.averaged_knots(self.points.len() - 1))?;
                if fewer.max_error <= tolerance {
                    break fewer;
                }
                return self.interpolation(t, tolerance);
            }
            interior = next;
        };
        let mut best = feasible;
        if best.knot_count() >= limit && self.points.len() > p + 1 {
            // The refinement needed as many control points as data points. The upper end of
            // the search, one control point fewer (as `approximate_with` finds it), decides:
            // when even it misses the tolerance, the tolerance is below what least squares
            // reaches on these data (noise far above it), every smaller count misses too, and
            // the fit through the data is the answer without a search down to one span.
            let fewer = self.best_with_count(self.averaged_knots(self.points.len() - 1))?;
            if fewer.max_error > tolerance {
                return Ok(best);
            }
            best = fewer;
        }
        // Downwards: the count the error density of the best fit predicts, while that
        // succeeds; then bisection between the largest failed count and the best.
        let mut failed: Option<usize> = None;
        for _ in 0..PREDICTIONS {
            let density = Density::from_errors(&best.interior, &best.errors, p, floor);
            let guess = density.predicted_count(tolerance, p);
            if guess >= best.knot_count() || failed.is_some_and(|f| guess <= f) {
                break;
            }
            let t = self.spread(guess, &best, floor)?;
            if t.max_error <= tolerance {
                best = t;
            } else {
                failed = Some(guess);
                break;
            }
        }
        let mut lo = failed.map_or(0, |f| f + 1);
        while lo < best.knot_count() {
            let mid = lo + (best.knot_count() - lo) / 2;
            let t = self.spread(mid, &best, floor)?;
            if t.max_error <= tolerance && t.knot_count() < best.knot_count() {
                best = t;
            } else {
                lo = mid + 1;
            }
        }
        if best.knot_count() >= limit && self.points.len() > p + 1 {
            // As many control points as data: one fewer as `approximate_with` finds it.
            let fewer = self.best_with_count(self.averaged_knots(self.points.len() - 1))?;
            if fewer.max_error <= tolerance {
                best = fewer;
            }
        }
        Ok(best)
    }
}

/// The fewest interior knots a refinement step from `count` goes to: an eighth more (at least
/// one), at most `limit`.
fn grown(count: usize, limit: usize) -> usize {
    (count + (count / GROWTH).max(1)).min(limit)
}

/// Whether a control point of `curve` lies farther than [`STRAY`] data diameters outside the
/// box of `points`.
fn strays<T: Scalar, const D: usize>(curve: &BSplineCurve<T, D>, points: &[Point<T, D>]) -> bool {
    let (mut lo, mut hi) = ([f64::INFINITY; D], [f64::NEG_INFINITY; D]);
    for q in points {
        for c in 0..D {
            lo[c] = lo[c].min(re(q.coords[c]));
            hi[c] = hi[c].max(re(q.coords[c]));
        }
    }
    let diameter = (0..D).map(|c| hi[c] - lo[c]).fold(0.0, f64::max);
    let reach = STRAY * diameter;
    curve.control_points().iter().any(|p| {
        (0..D).any(|c| {
            let x = re(p.coords[c]);
            !(x >= lo[c] - reach && x <= hi[c] + reach)
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::{data_parameters, FitOptions, ParameterMethod};
    use nalgebra::Point2;

    /// n points on y = sin 40t with uniform noise of ±`noise` (a fixed linear congruential
    /// sequence), t from 0 to 1.
    fn noisy(n: usize, noise: f64) -> Vec<Point2<f64>> {
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        (0..n)
            .map(|i| {
                state = state
                    .wrapping_mul(6_364_136_223_846_793_005)
                    .wrapping_add(1_442_695_040_888_963_407);
                let r = (state >> 11) as f64 / (1u64 << 53) as f64;
                let t = i as f64 / (n - 1) as f64;
                Point2::new(t, (40.0 * t).sin() + noise * (2.0 * r - 1.0))
            })
            .collect()
    }

    /// 2,000 points with noise of ±1e-3 and a tolerance of 1e-9: only the fit through the
    /// data meets it. The refinement reaches it in a few trials, and one control point fewer
    /// misses the tolerance, so the search stops there (it used to bisect down the whole range
    /// of counts, about 30 trials, each failing). A trial costs 6 units per data point: the
    /// fit must finish within 16 trials' work.
    #[test]
    fn a_tolerance_far_below_the_noise_interpolates_after_few_trials() {
        let n = 2000;
        let points = noisy(n, 1e-3);
        let options = FitOptions::default()
            .with_degree(3)
            .with_method(ParameterMethod::Centripetal);
        let per_trial = (2 * CORRECTIONS + 2) * n;
        let budget = Budget::default().with_max_work((16 * per_trial) as u64);
        let fit = crate::fit::fit_to_tolerance_with(&points, 1e-9, &options, &budget).unwrap();
        assert!(fit.max_error <= 1e-9, "{}", fit.max_error);
        assert_eq!(fit.curve.control_points().len(), n);
        // The parameters of the data: the problem the trials solve, for their count.
        let parameters = data_parameters(&points, options.method).unwrap();
        let budget = Budget::default();
        let problem = Problem::new(
            &points,
            &parameters,
            3,
            options.ends(&points),
            options.measure(),
            &budget,
        );
        let trial = problem.fit_to_tolerance(1e-9).unwrap();
        let trials = problem.meter.borrow().used() as usize / per_trial;
        assert!(trials <= 12, "{trials} trials");
        assert!(trial.max_error <= 1e-9);
    }

    /// 400 points with noise of ±0.05 and a tolerance of 1e-2, between the noise and
    /// interpolation: the refinement used to stall near interpolation, adding a knot or two
    /// per trial (126 trials with chord-length parameters, 215 centripetal; at 20,000 points
    /// it spent the whole budget, 500 trials). Growing by an eighth per trial it finishes in
    /// 32 and 44: the fit must finish within 80 trials' work, both parameter methods.
    #[test]
    fn tolerances_between_noise_and_interpolation_finish_within_a_bounded_search() {
        let n = 400;
        let tolerance = 1e-2;
        let points = noisy(n, 0.05);
        let per_trial = (2 * CORRECTIONS + 2) * n;
        for method in [ParameterMethod::ChordLength, ParameterMethod::Centripetal] {
            let options = FitOptions::default().with_degree(3).with_method(method);
            let budget = Budget::default().with_max_work((80 * per_trial) as u64);
            let fit = crate::fit::fit_to_tolerance_with(&points, tolerance, &options, &budget)
                .unwrap_or_else(|e| panic!("{method:?}: {e}"));
            assert!(fit.max_error <= tolerance, "{method:?}: {}", fit.max_error);
            assert!(fit.curve.control_points().len() < n, "{method:?}");
        }
    }

    /// Averaged knots for 1 to 20 control points fewer than data (1,000 and 2,100 noisy
    /// points, both parameter methods) make a regular least-squares system: the solve that
    /// refuses a singular one at once succeeds for every count. The knots used to put the
    /// first span at a few thousandths of a data index: singular at 999 control points for
    /// 1,000 points, and at 2,099 for 2,100 (chord length), where no dense fallback is taken
    /// and the whole fit failed with "least-squares system is singular".
    #[test]
    fn averaged_knots_near_interpolation_keep_the_least_squares_regular() {
        for n in [1000, 2100] {
            let points = noisy(n, 0.05);
            for method in [ParameterMethod::ChordLength, ParameterMethod::Centripetal] {
                let options = FitOptions::default().with_degree(3).with_method(method);
                let parameters = data_parameters(&points, method).unwrap();
                let budget = Budget::default();
                let problem = Problem::new(
                    &points,
                    &parameters,
                    3,
                    options.ends(&points),
                    options.measure(),
                    &budget,
                );
                for c in n - 20..n {
                    let interior: Vec<f64> = problem
                        .averaged_knots(c)
                        .iter()
                        .map(|&s| parameter_at(&problem.start, s))
                        .collect();
                    assert_eq!(interior.len(), c - 4);
                    assert!(interior.windows(2).all(|w| w[0] < w[1]));
                    let knots = clamped_knots(3, &interior);
                    let fit = solve_or(
                        &points,
                        &parameters,
                        3,
                        &knots,
                        &problem.ends,
                        OnSingular::Fail,
                    );
                    assert!(fit.is_ok(), "{n} points, {c} control points, {method:?}");
                }
            }
        }
    }
}
