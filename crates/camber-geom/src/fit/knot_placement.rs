//! Where the interior knots of an adaptive fit go: refinement where the error is above the
//! tolerance, and any number of knots spread so that every span is expected to err alike.
//!
//! Knots are placed in the data-index coordinate s (s = k at data point k, linear between the
//! points' parameters), so a placement means the same thing whatever parameters a fit moved its
//! data to; a knot goes to the curve parameter at s of the data's start parameters.
//!
//! - **Error density.** A polynomial span of length h approximating a smooth curve errs about
//!   E ≈ c·h^{p+1}, so a span of the last fit with error E_j and length h_j (in s) asks for a
//!   knot density (knots per unit of s) proportional to ρ_j = E_j^{1/(p+1)}/h_j: spans of
//!   equal ∫ρ err alike. Placing N knots at equal steps of ∫ρ (equidistribution) is the
//!   spread of N knots with the smallest expected largest error.
//! - **Refinement.** A span with error E_j above the tolerance τ needs about
//!   ⌈(E_j/τ)^{1/(p+1)}⌉ pieces; it is cut into that many at equal steps of s.
//! - **Data in every span.** Knots are kept apart by at least one data point: consecutive
//!   knots are at least 1 apart in s and the first and last at least (p + 1)/2 from the ends, as the averaged knots of
//!   interpolation are. Then every span holds data and the least-squares system stays regular
//!   in practice (its singular cases are still handled by the solver).

/// A piecewise constant density on [0, m] (data-index coordinate): `values[j]` on
/// [`breaks[j]`, `breaks[j + 1]`].
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Density {
    breaks: Vec<f64>,
    values: Vec<f64>,
}

/// The relative floor of the error in a span when the density is formed: spans that fit
/// (nearly) exactly still get some density, since merging them changes the error.
const ERROR_FLOOR: f64 = 1e-3;

impl Density {
    /// The error density of a fit with interior knots at `interior` (data-index coordinates)
    /// and per-point errors `errors` (see [`span_errors`]), every span counted as erring at
    /// least `least` (length units; 0 for no floor beyond [`ERROR_FLOOR`] of the largest).
    pub fn from_errors(interior: &[f64], errors: &[f64], degree: usize, least: f64) -> Self {
        let breaks = breaks_of(interior, errors.len());
        let worst = span_errors(&breaks, errors);
        let top = worst.iter().copied().fold(0.0, f64::max);
        let floor = if top > 0.0 { top * ERROR_FLOOR } else { 1.0 }.max(least);
        let exponent = 1.0 / (degree as f64 + 1.0);
        let values = worst
            .iter()
            .zip(breaks.windows(2))
            .map(|(&e, w)| {
                let h = (w[1] - w[0]).max(f64::MIN_POSITIVE);
                e.max(floor).powf(exponent) / h
            })
            .collect();
        Self { breaks, values }
    }

    /// The number of interior knots the density predicts for `tolerance`, for a density made
    /// from errors ([`Density::from_errors`]): a span of the fit with error E_j becomes
    /// (E_j/τ)^{1/(p+1)} spans of error τ, so the spans needed are about the sum of those.
    pub fn predicted_count(&self, tolerance: f64, degree: usize) -> usize {
        let scale = tolerance.powf(1.0 / (degree as f64 + 1.0));
        let spans: f64 = self
            .values
            .iter()
            .zip(self.breaks.windows(2))
            .map(|(v, w)| v * (w[1] - w[0]) / scale)
            .sum();
        (spans.ceil() as usize).saturating_sub(1)
    }

    /// `count` interior knots at equal steps of the cumulative density.
    pub fn equidistribute(&self, count: usize) -> Vec<f64> {
        let mut cumulative = Vec::with_capacity(self.values.len() + 1);
        cumulative.push(0.0);
        let mut total = 0.0;
        for (v, w) in self.values.iter().zip(self.breaks.windows(2)) {
            total += v * (w[1] - w[0]);
            cumulative.push(total);
        }
        let mut out = Vec::with_capacity(count);
        let mut j = 0;
        for i in 1..=count {
            let target = total * i as f64 / (count as f64 + 1.0);
            while j + 1 < self.values.len() && cumulative[j + 1] < target {
                j += 1;
            }
            let (a, b) = (self.breaks[j], self.breaks[j + 1]);
            let mass = cumulative[j + 1] - cumulative[j];
            let t = if mass > 0.0 {
                a + (b - a) * ((target - cumulative[j]) / mass).clamp(0.0, 1.0)
            } else {
                0.5 * (a + b)
            };
            out.push(t);
        }
        out
    }
}

/// 0, the interior knots, m (data-index coordinates, `points` = m + 1 data points).
fn breaks_of(interior: &[f64], points: usize) -> Vec<f64> {
    let mut breaks = Vec::with_capacity(interior.len() + 2);
    breaks.push(0.0);
    breaks.extend_from_slice(interior);
    breaks.push(points.saturating_sub(1) as f64);
    breaks
}

/// The largest error of the data in every span between consecutive `breaks` (data-index
/// coordinates; a point on a break belongs to both spans, a span without data gets 0).
fn span_errors(breaks: &[f64], errors: &[f64]) -> Vec<f64> {
    let spans = breaks.len() - 1;
    let mut worst = vec![0.0_f64; spans];
    let mut j = 0;
    for (k, &e) in errors.iter().enumerate() {
        let u = k as f64;
        while j + 1 < spans && u > breaks[j + 1] {
            j += 1;
        }
        worst[j] = worst[j].max(e);
        if j + 1 < spans && u >= breaks[j + 1] {
            worst[j + 1] = worst[j + 1].max(e);
        }
    }
    worst
}

/// The knots (data-index coordinates) after refinement: every span whose error is above
/// `tolerance` is cut into ⌈(E_j/τ)^{1/(p+1)}⌉ pieces (at least two) at equal steps.
pub(crate) fn refine(interior: &[f64], errors: &[f64], degree: usize, tolerance: f64) -> Vec<f64> {
    let breaks = breaks_of(interior, errors.len());
    let worst = span_errors(&breaks, errors);
    let exponent = 1.0 / (degree as f64 + 1.0);
    let mut out = Vec::with_capacity(2 * interior.len() + 2);
    for (j, w) in breaks.windows(2).enumerate() {
        if worst[j] > tolerance {
            let pieces = ((worst[j] / tolerance).powf(exponent).ceil() as usize).clamp(2, 64);
            for i in 1..pieces {
                out.push(w[0] + (w[1] - w[0]) * i as f64 / pieces as f64);
            }
        }
        if j + 2 < breaks.len() {
            out.push(w[1]);
        }
    }
    out
}

/// The data-index coordinate s of parameter u (s = k at ū_k, linear between).
pub(crate) fn index_of(parameters: &[f64], u: f64) -> f64 {
    let k = parameters.partition_point(|&v| v <= u);
    if k == 0 {
        return 0.0;
    }
    if k >= parameters.len() {
        return (parameters.len() - 1) as f64;
    }
    let (a, b) = (parameters[k - 1], parameters[k]);
    let f = if b > a { (u - a) / (b - a) } else { 0.0 };
    (k - 1) as f64 + f
}

/// The parameter at data-index coordinate s.
pub(crate) fn parameter_at(parameters: &[f64], s: f64) -> f64 {
    let m = parameters.len() - 1;
    let s = s.clamp(0.0, m as f64);
    let k = (s.floor() as usize).min(m.saturating_sub(1));
    let f = s - k as f64;
    parameters[k] + (parameters[(k + 1).min(m)] - parameters[k]) * f
}

/// The largest number of interior knots the data carry: m − p (interpolation).
pub(crate) fn max_interior(points: usize, degree: usize) -> usize {
    points.saturating_sub(degree + 1)
}

/// `interior` (sorted data-index coordinates of m + 1 = `points` data points) moved apart so
/// that consecutive knots are at least one data index apart and the first and last at least
/// (p + 1)/2 from the ends; knots beyond what the data carry (m − p) are dropped first (the
/// list is thinned evenly).
pub(crate) fn separate(interior: &[f64], points: usize, degree: usize) -> Vec<f64> {
    let m = points.saturating_sub(1) as f64;
    let limit = max_interior(points, degree);
    let mut s: Vec<f64> = interior.to_vec();
    if s.len() > limit {
        let total = s.len();
        s = (0..limit)
            .map(|i| s[((i as f64 + 0.5) * total as f64 / limit as f64) as usize])
            .collect();
    }
    if s.is_empty() {
        return s;
    }
    let margin = (degree as f64 + 1.0) / 2.0;
    let (lo, hi) = (margin, m - margin);
    let n = s.len();
    // Forward: at least 1 apart from the left limit; backward: from the right limit.
    let mut previous = lo - 1.0;
    for v in s.iter_mut() {
        *v = v.max(previous + 1.0);
        previous = *v;
    }
    let mut next = hi + 1.0;
    for v in s.iter_mut().rev() {
        *v = v.min(next - 1.0);
        next = *v;
    }
    // If the data are too few for the count the backward sweep pushes below `lo`: spread
    // evenly instead (the count is at most m − p, so the spacing is at least one).
    if s[0] < lo - 1e-9 {
        let step = if n > 1 {
            (hi - lo) / (n - 1) as f64
        } else {
            0.0
        };
        for (i, v) in s.iter_mut().enumerate() {
            *v = if n > 1 { lo + step * i as f64 } else { 0.5 * m };
        }
    }
    s.retain(|&v| v > 0.0 && v < m);
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_errors_keep_the_knots_of_equal_spans() {
        // Uniform density on [0, 4]: N knots at 4i/(N + 1).
        let d = Density::from_errors(&[2.0], &[1.0; 5], 3, 0.0);
        let k = d.equidistribute(3);
        for (i, &t) in k.iter().enumerate() {
            assert!((t - (i + 1) as f64).abs() < 1e-12, "{k:?}");
        }
    }

    #[test]
    fn a_span_with_larger_error_gets_more_knots() {
        // Error 16 on [0, 2.5], 1 on [2.5, 5], cubic: density 2 against 1 per unit, so two
        // thirds of the mass is left: of 5 knots at equal sixths, the fourth is at the break.
        let d = Density::from_errors(&[2.5], &[16.0, 16.0, 16.0, 1.0, 1.0, 1.0], 3, 0.0);
        let k = d.equidistribute(5);
        assert_eq!(k.iter().filter(|&&t| t < 2.5 - 1e-12).count(), 3, "{k:?}");
        assert!((k[3] - 2.5).abs() < 1e-12, "{k:?}");
        assert!(
            (k[0] - 0.625).abs() < 1e-12 && (k[4] - 3.75).abs() < 1e-12,
            "{k:?}"
        );
    }

    #[test]
    fn a_floor_keeps_knots_in_a_span_that_fits_far_below_it() {
        // Span [0, 2] fits to 1e-12, span [2, 4] errs 1. Without a floor beyond a thousandth
        // of the largest error the first span has density (1e-3)^{1/4}/2 against 1/2, and both
        // of 2 knots go into the second span. Counted as erring 1/16 (fourth root 1/2), its
        // mass is 1/2 of 3/2: the knots fall at equal thirds of the mass, s = 2 and s = 3.
        let errors = [0.0, 0.0, 1e-12, 1.0, 1.0];
        let bare = Density::from_errors(&[2.0], &errors, 3, 0.0).equidistribute(2);
        assert!(bare.iter().all(|&t| t > 2.0), "{bare:?}");
        let floored = Density::from_errors(&[2.0], &errors, 3, 1.0 / 16.0).equidistribute(2);
        assert!((floored[0] - 2.0).abs() < 1e-12, "{floored:?}");
        assert!((floored[1] - 3.0).abs() < 1e-12, "{floored:?}");
    }

    #[test]
    fn a_floor_bounds_how_far_a_prediction_goes_down() {
        // Ten spans fitting to 1e-12 at tolerance 1: no floor predicts no knot at all; a floor
        // of 1/16 of the tolerance counts each span as half a span of the tolerance's error,
        // 5 spans (4 interior knots) in all.
        let errors = [1e-12; 11];
        let interior: Vec<f64> = (1..10).map(f64::from).collect();
        let bare = Density::from_errors(&interior, &errors, 3, 0.0);
        assert!(bare.predicted_count(1.0, 3) <= 1);
        let floored = Density::from_errors(&interior, &errors, 3, 1.0 / 16.0);
        assert_eq!(floored.predicted_count(1.0, 3), 4);
    }

    #[test]
    fn separated_knots_hold_data_between_them() {
        let out = separate(&[4.1, 4.2, 4.3], 11, 3);
        assert_eq!(out.len(), 3);
        for w in out.windows(2) {
            assert!(w[1] - w[0] >= 1.0 - 1e-12, "{out:?}");
        }
        // More knots than the data carry are thinned to m − p.
        let many: Vec<f64> = (1..40).map(|i| f64::from(i) / 4.0).collect();
        assert_eq!(separate(&many, 11, 3).len(), 7);
    }

    #[test]
    fn index_and_parameter_coordinates_are_inverse() {
        let params = [0.0, 0.1, 0.5, 0.6, 1.0];
        for s in [0.0, 0.5, 1.25, 2.0, 3.9, 4.0] {
            assert!((index_of(&params, parameter_at(&params, s)) - s).abs() < 1e-12);
        }
    }
}
