//! `camber intersect`: where two curve files meet, and how close they come, as JSON.

use std::path::PathBuf;

use anyhow::{Context, Result};
use camber_geom::queries::{
    curve_distance, intersect_curves_with_overlaps, BezierPieces, CurveCurveOptions, CurvePairPoint,
};
use clap::Args;
use serde::Serialize;

use crate::curve_file::{self, Curve};

/// Arguments of `camber intersect`.
#[derive(Debug, Args)]
pub struct IntersectArgs {
    /// The first curve file.
    pub a: PathBuf,
    /// The second curve file.
    pub b: PathBuf,
    /// Points closer than this (length units) coincide.
    #[arg(
        long,
        default_value_t = 1e-9,
        allow_negative_numbers = true,
        value_name = "TOL"
    )]
    pub tolerance: f64,
}

/// One meeting point or the closest pair, as printed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairJson {
    /// Parameter on the first curve.
    pub u_a: f64,
    /// Parameter on the second curve.
    pub u_b: f64,
    /// The point on the first curve.
    pub point_a: [f64; 2],
    /// The point on the second curve.
    pub point_b: [f64; 2],
    /// Their distance.
    pub distance: f64,
    /// Whether the curves are tangent there.
    pub tangential: bool,
}

impl From<CurvePairPoint<2>> for PairJson {
    fn from(p: CurvePairPoint<2>) -> Self {
        Self {
            u_a: p.parameter_a,
            u_b: p.parameter_b,
            point_a: [p.point_a.x, p.point_a.y],
            point_b: [p.point_b.x, p.point_b.y],
            distance: p.distance,
            tangential: p.tangential,
        }
    }
}

/// A stretch along which the curves coincide, as printed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OverlapJson {
    /// The interval on the first curve, increasing.
    pub u_a: (f64, f64),
    /// The matching parameters on the second curve (decreasing when it runs the other way).
    pub u_b: (f64, f64),
}

/// The printed report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct IntersectReport {
    /// Every isolated meeting point, in order along the first curve.
    pub intersections: Vec<PairJson>,
    /// Every stretch where the curves coincide, in order along the first curve.
    pub overlaps: Vec<OverlapJson>,
    /// The closest pair of points (distance 0 where they meet).
    pub closest: PairJson,
}

/// The curve as something that can be cut into Bézier pieces.
fn pieces(curve: &Curve) -> &dyn BezierPieces<2> {
    match curve {
        Curve::Bezier(c) => c,
        Curve::BSpline(c) => c,
        Curve::Nurbs(c) => c,
        Curve::Hermite(c) => c,
    }
}

/// The intersections and the closest pair of two curves.
pub fn report(a: &Curve, b: &Curve, tolerance: f64) -> Result<IntersectReport> {
    let opts = CurveCurveOptions::default().with_tolerance(tolerance);
    let hits = intersect_curves_with_overlaps(pieces(a), pieces(b), &opts)?;
    let closest = curve_distance(pieces(a), pieces(b), &opts)?;
    Ok(IntersectReport {
        intersections: hits.points.into_iter().map(PairJson::from).collect(),
        overlaps: hits
            .overlaps
            .into_iter()
            .map(|o| OverlapJson { u_a: o.a, u_b: o.b })
            .collect(),
        closest: closest.into(),
    })
}

/// Prints `{"intersections": [...], "overlaps": [...], "closest": {...}}`: for each meeting
/// point u_a, u_b, both points, the distance and whether the contact is tangential; for each
/// stretch where the curves coincide its intervals u_a and u_b.
pub fn run(args: &IntersectArgs) -> Result<()> {
    let a = curve_file::load(&args.a)?;
    let b = curve_file::load(&args.b)?;
    let r = report(&a, &b, args.tolerance)
        .with_context(|| format!("{} × {}", args.a.display(), args.b.display()))?;
    crate::print_stdout(&serde_json::to_string_pretty(&r)?)
}
