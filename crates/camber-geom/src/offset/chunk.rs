//! The fit of one chunk of the offset: a run of consecutive pieces of the curve, sampled per
//! piece, fitted on its own parameter σ ∈ [0, 1] under the end conditions that join it to its
//! neighbours, and resampled only where it misses.

use nalgebra::Point2;

use super::offset_point;
use crate::bspline::BSplineCurve;
use crate::budget::Meter;
use crate::curve::ParametricCurve;
use crate::errors::Result;
use crate::fit::{fit_at_parameters, FitEnds};
use crate::scalar::{cst, from_usize, re, Scalar};

/// Samples per piece to start with.
const START_SAMPLES: usize = 8;
/// Doublings of a piece's sampling before giving up on the tolerance.
const MAX_DOUBLINGS: usize = 8;
/// Measurement points per sample interval (the sample itself and the ones between).
const CHECKS_PER_INTERVAL: usize = 8;

/// What a chunk is: the curve's breakpoints `breaks` (first and last bound the chunk; at least
/// two), the fit's knot multiplicity at each interior one, and how its ends are held.
pub(super) struct Chunk<'a, T: Scalar> {
    pub breaks: &'a [T],
    pub multiplicities: &'a [usize],
    pub ends: FitEnds<T, 2>,
}

/// A chunk's fitted curve (on σ ∈ [0, 1]) and its largest measured error (length units).
pub(super) struct ChunkFit<T: Scalar> {
    pub curve: BSplineCurve<T, 2>,
    pub max_error: f64,
}

/// Fits the offset at `distance` of `curve` over `chunk` within `tolerance`: the samples are
/// fitted to half of it, and the error is measured at the samples and seven points between
/// each pair; every piece whose measurements miss gets twice its samples in the next round
/// (at most [`MAX_DOUBLINGS`] times), the others keep theirs. Returns the first fit within the
/// tolerance, or the best one measured.
pub(super) fn fit_chunk<T, C>(
    curve: &C,
    distance: T,
    tolerance: f64,
    chunk: &Chunk<'_, T>,
    meter: &mut Meter<'_>,
) -> Result<ChunkFit<T>>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    let breaks = chunk.breaks;
    let (a, b) = (breaks[0], breaks[breaks.len() - 1]);
    let local = |u: T| (u - a) / (b - a);
    let knots: Vec<T> = breaks[1..breaks.len() - 1]
        .iter()
        .zip(chunk.multiplicities)
        .flat_map(|(&u, &m)| std::iter::repeat_n(local(u), m))
        .collect();
    let pieces = breaks.len() - 1;
    let mut per_piece = vec![START_SAMPLES; pieces];
    let mut best: Option<ChunkFit<T>> = None;
    for _ in 0..=MAX_DOUBLINGS {
        // Charged before anything is allocated for the samples.
        let count = per_piece
            .iter()
            .fold(1usize, |total, &n| total.saturating_add(n));
        meter.charge(u64::try_from(count).unwrap_or(u64::MAX))?;
        let mut params = Vec::with_capacity(count);
        let mut piece_of = Vec::with_capacity(count);
        for (piece, w) in breaks.windows(2).enumerate() {
            let n = per_piece[piece];
            for j in 0..n {
                params.push(w[0] + (w[1] - w[0]) * from_usize::<T>(j) / from_usize::<T>(n));
                piece_of.push(piece);
            }
        }
        params.push(b);
        let points = params
            .iter()
            .map(|&u| offset_point(curve, distance, u))
            .collect::<Result<Vec<Point2<T>>>>()?;
        let mut fit_params: Vec<T> = params.iter().map(|&u| local(u)).collect();
        fit_params[0] = T::zero();
        if let Some(last) = fit_params.last_mut() {
            *last = T::one();
        }
        let fit = fit_at_parameters(
            &points,
            &fit_params,
            3,
            tolerance * 0.5,
            &knots,
            &chunk.ends,
            meter,
        )?;
        let mut worst = 0.0_f64;
        let mut missed = vec![false; pieces];
        for (i, w) in params.windows(2).enumerate() {
            meter.charge(2 * CHECKS_PER_INTERVAL as u64)?;
            for k in 0..CHECKS_PER_INTERVAL {
                let u = w[0] + (w[1] - w[0]) * cst::<T>(k as f64 / CHECKS_PER_INTERVAL as f64);
                let exact = if k == 0 {
                    points[i]
                } else {
                    offset_point(curve, distance, u)?
                };
                let approx = fit.curve.point(local(u).max(T::zero()).min(T::one()))?;
                let e = re((approx - exact).norm());
                worst = worst.max(e);
                if e > tolerance {
                    missed[piece_of[i]] = true;
                }
            }
        }
        // The last sample, the chunk's end.
        let end_error = re((fit.curve.point(T::one())? - points[points.len() - 1]).norm());
        worst = worst.max(end_error);
        if end_error > tolerance {
            missed[pieces - 1] = true;
        }
        let result = ChunkFit {
            curve: fit.curve,
            max_error: worst,
        };
        if worst <= tolerance {
            return Ok(result);
        }
        if best.as_ref().is_none_or(|b| worst < b.max_error) {
            best = Some(result);
        }
        for (n, &miss) in per_piece.iter_mut().zip(&missed) {
            if miss {
                *n *= 2;
            }
        }
    }
    // The loop runs at least once and keeps every measured fit that is not within tolerance.
    best.ok_or(crate::errors::Error::ZeroCount {
        what: "offset samples",
    })
}
