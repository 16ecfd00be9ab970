//! `camber eval --arc-length`: the length of a curve file, with its error estimate, and the
//! length from the start to given parameters.

use anyhow::{Context, Result};
use camber_geom::arc_length::{arc_length, arc_length_between};
use camber_geom::ParametricCurve;
use serde::Serialize;

/// The length from the start of the domain to one parameter.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LengthTo {
    /// The parameter.
    pub u: f64,
    /// The arc length from the start of the domain to u.
    pub length: f64,
}

/// What `camber eval --arc-length` prints.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ArcLengthReport {
    /// The whole curve's length.
    pub length: f64,
    /// The quadrature's error estimate.
    pub error_estimate: f64,
    /// The tolerance honoured: the one asked for, or, when that is below what f64 resolves on
    /// this curve (64 ulps of its length), that floor.
    pub tolerance: f64,
    /// The length to each parameter asked for.
    pub at: Vec<LengthTo>,
}

/// Measures the curve, and the length to each of `us`, to `tolerance`.
///
/// ```
/// use camber_cli::commands::arc_length::measure;
/// use camber_cli::curve_file::Curve;
/// let line = Curve::from_json(r#"{"type": "bezier", "control_points": [[0, 0], [3, 4]]}"#)?;
/// let r = measure(line.as_parametric(), &[0.5], 1e-12)?;
/// assert!((r.length - 5.0).abs() < 1e-12 && (r.at[0].length - 2.5).abs() < 1e-12);
/// # Ok::<(), anyhow::Error>(())
/// ```
pub fn measure(
    curve: &dyn ParametricCurve<f64, 2>,
    us: &[f64],
    tolerance: f64,
) -> Result<ArcLengthReport> {
    let whole = arc_length(curve, tolerance)?;
    let (a, _) = curve.domain();
    let at = us
        .iter()
        .map(|&u| {
            let l = arc_length_between(curve, a, u, tolerance)
                .with_context(|| format!("cannot measure to u = {u}"))?;
            Ok(LengthTo {
                u,
                length: l.length,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(ArcLengthReport {
        length: whole.length,
        error_estimate: whole.error_estimate,
        tolerance: whole.tolerance,
        at,
    })
}
