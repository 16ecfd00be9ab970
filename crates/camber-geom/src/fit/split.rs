//! Fits split at features: every piece of the data between two split points gets its own
//! curve, fitted to the tolerance with adaptive knots, and neighbouring curves share the data
//! point of their joint, its tangent direction (G1) and, with [`JointContinuity::G2`], its
//! curvature vector.
//!
//! The tangent T and curvature vector k at a joint are estimated from the data: the cubic
//! interpolant (centripetal parameters) of up to seven data points around the joint is
//! evaluated at the joint's point, T = C′/|C′| and k from C′ and C″. Each piece then holds
//! its end control points (P₁ on the tangent line, and for G2 P₂ on the line that gives the
//! curvature vector, see docs/geometry.md), so both sides meet at the data
//! point with the same tangent direction (and curvature vector) by construction.

use nalgebra::{Point, SVector};

use super::ends::{EndCondition, Ends};
use super::tolerance::Problem;
use super::{
    check_data, check_tolerance, data_parameters, interpolate_at, Fit, FitOptions, ParameterMethod,
};
use crate::budget::Budget;
use crate::composite::CompositeCurve;
use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::queries::curvature_vector_from_derivatives;
use crate::scalar::{re, Scalar};

/// Where a fit is split.
#[derive(Debug, Clone, PartialEq)]
pub enum SplitAt {
    /// At the leading edge of an airfoil: the data point of smallest first coordinate (x).
    LeadingEdge,
    /// At the data points whose parameters (by the fit's parameter method, in (0, 1)) are
    /// nearest these values.
    Parameters(Vec<f64>),
    /// At these data points (indices, strictly inside the data).
    Indices(Vec<usize>),
}

/// How the pieces of a split fit meet.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum JointContinuity {
    /// Same point and tangent direction.
    #[default]
    G1,
    /// Same point, tangent direction and curvature vector.
    G2,
}

/// A fit in pieces split at features.
#[derive(Debug, Clone, PartialEq)]
pub struct SplitFit<T: Scalar, const D: usize> {
    /// The fit of every piece, in order; piece i covers data points `joints[i − 1]` … `joints[i]`
    /// (the first starts at 0, the last ends at the last point).
    pub pieces: Vec<Fit<T, D>>,
    /// The data index of every joint.
    pub joints: Vec<usize>,
    /// The largest distance from a data point to its piece (length units).
    pub max_error: f64,
}

impl<T: Scalar + 'static, const D: usize> SplitFit<T, D> {
    /// The pieces as one composite curve on [0, number of pieces].
    pub fn to_composite(&self) -> Result<CompositeCurve<T, D>> {
        CompositeCurve::try_new(
            self.pieces
                .iter()
                .map(|f| Box::new(f.curve.clone()) as Box<dyn ParametricCurve<T, D>>)
                .collect(),
        )
    }
}

/// The data indices of the joints, sorted, strictly inside, without repeats.
fn joint_indices<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    split: &SplitAt,
    method: ParameterMethod,
) -> Result<Vec<usize>> {
    let m = points.len() - 1;
    let mut out = match split {
        SplitAt::LeadingEdge => {
            let mut best = 0;
            for (k, q) in points.iter().enumerate() {
                if re(q.coords[0]) < re(points[best].coords[0]) {
                    best = k;
                }
            }
            vec![best]
        }
        SplitAt::Indices(list) => list.clone(),
        SplitAt::Parameters(list) => {
            let params = data_parameters(points, method)?;
            let mut out = Vec::with_capacity(list.len());
            for (index, &u) in list.iter().enumerate() {
                if !u.is_finite() {
                    return Err(Error::NonFinite {
                        what: "split parameter",
                        index,
                        value: u,
                    });
                }
                if u <= 0.0 || u >= 1.0 {
                    return Err(Error::ParameterOutsideDomain {
                        value: u,
                        min: 0.0,
                        max: 1.0,
                    });
                }
                let k = params.partition_point(|&v| re(v) < u).min(m);
                let nearer = if k > 0 && u - re(params[k - 1]) < re(params[k]) - u {
                    k - 1
                } else {
                    k
                };
                out.push(nearer);
            }
            out
        }
    };
    out.sort_unstable();
    out.dedup();
    for &k in &out {
        if k == 0 || k >= m {
            return Err(Error::SplitPointAtEnd { index: k, last: m });
        }
    }
    Ok(out)
}

/// The unit tangent and curvature vector of the data at point `k` (see the module header).
fn joint_frame<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    k: usize,
) -> Result<(SVector<T, D>, SVector<T, D>)> {
    let lo = k.saturating_sub(3);
    let hi = (k + 3).min(points.len() - 1);
    let local = &points[lo..=hi];
    let params = data_parameters(local, ParameterMethod::Centripetal)?;
    let degree = 3.min(local.len() - 1);
    let fit = interpolate_at(local, &params, degree, None)?;
    let d = fit.curve.second_order(params[k - lo])?;
    let speed = d[1].norm();
    if re(speed) <= 0.0 {
        return Err(Error::SingularSystem {
            what: "joint tangent",
        });
    }
    let curvature = curvature_vector_from_derivatives(&d[1], &d[2]).unwrap_or_else(SVector::zeros);
    Ok((d[1] / speed, curvature))
}

/// Fits `points` in pieces split at `split`, each within `tolerance` (length units, > 0) with
/// adaptive knots and as few control points as [`fit_to_tolerance_with`](super::fit_to_tolerance_with)
/// finds, neighbouring pieces sharing the joint's data point, tangent direction and (G2)
/// curvature vector. The first and last pieces start and end on the first and last data
/// points when `options.fixed_ends`.
///
/// ```
/// use camber_geom::fit::split::{fit_split, JointContinuity, SplitAt};
/// use camber_geom::budget::Budget;
/// use camber_geom::fit::FitOptions;
/// use camber_geom::composite::ContinuityTolerances;
/// use camber_geom::Continuity;
/// use nalgebra::Point2;
/// // An ellipse arc around its left end, split there.
/// let pts: Vec<_> = (0..=120).map(|i| {
///     let t = std::f64::consts::FRAC_PI_2 + f64::from(i) / 120.0 * std::f64::consts::PI;
///     Point2::new(t.cos(), 0.2 * t.sin())
/// }).collect();
/// let fit = fit_split(&pts, 1e-5, &FitOptions::default(), &SplitAt::LeadingEdge,
///     JointContinuity::G2, &Budget::default())?;
/// assert_eq!(fit.joints, vec![60]);
/// assert!(fit.max_error <= 1e-5);
/// let joint = fit.to_composite()?.joints()?[0];
/// let tol = ContinuityTolerances { curvature: 1e-6, ..Default::default() };
/// assert!(joint.continuity(&tol) >= Continuity::G2);
/// # Ok::<(), camber_geom::Error>(())
/// ```
///
/// Each piece runs under `budget` as [`fit_to_tolerance_with`](super::fit_to_tolerance_with)
/// does.
///
/// Errors: those of [`fit_to_tolerance_with`](super::fit_to_tolerance_with) for every piece,
/// [`Error::SplitPointAtEnd`] for a split at the first or last point, and
/// [`Error::ParameterOutsideDomain`] / [`Error::NonFinite`] for a split parameter outside (0, 1).
pub fn fit_split<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    tolerance: f64,
    options: &FitOptions,
    split: &SplitAt,
    joint: JointContinuity,
    budget: &Budget,
) -> Result<SplitFit<T, D>> {
    check_tolerance(tolerance)?;
    check_data(points, options.degree)?;
    data_parameters(points, options.method)?;
    let joints = joint_indices(points, split, options.method)?;
    let mut frames = Vec::with_capacity(joints.len());
    for &k in &joints {
        let (tangent, curvature) = joint_frame(points, k)?;
        frames.push(EndCondition::Joint {
            point: points[k],
            tangent,
            curvature: (joint == JointContinuity::G2).then_some(curvature),
        });
    }
    let whole = options.ends(points);
    let mut bounds = vec![0];
    bounds.extend(&joints);
    bounds.push(points.len() - 1);
    let mut pieces = Vec::with_capacity(bounds.len() - 1);
    let mut max_error = 0.0_f64;
    for (i, w) in bounds.windows(2).enumerate() {
        let data = &points[w[0]..=w[1]];
        check_data(data, options.degree)?;
        let ends = Ends {
            start: if i == 0 { whole.start } else { frames[i - 1] },
            end: if i + 1 == bounds.len() - 1 {
                whole.end
            } else {
                frames[i]
            },
        };
        let parameters = data_parameters(data, options.method)?;
        let problem = Problem::new(
            data,
            &parameters,
            options.degree,
            ends,
            options.measure(),
            budget,
        );
        let fit = problem.finish(problem.fit_to_tolerance(tolerance)?)?;
        max_error = max_error.max(fit.max_error);
        pieces.push(fit);
    }
    Ok(SplitFit {
        pieces,
        joints,
        max_error,
    })
}
