//! The toolkit fuzz target: one or two curves and a set of numbers, run through every
//! operation of the curve toolkit under a small work budget.
//!
//! The input is a stream of JSON values: a curve file's object (curve A), optionally a second
//! one (curve B), then optionally an object of numbers, each optional:
//! `{"tolerance": 1e-9, "distance": 0.1, "order": 3, "at": [0.5], "lengths": [1.0],
//! "point": [0, 0]}`, where `null` stands for NaN (JSON has none).
//!
//! The promises checked are listed on [`toolkit`].

use std::path::PathBuf;

use camber_geom::arc_length::{arc_length_map_with, arc_length_with, parameters_at_lengths};
use camber_geom::budget::Budget;
use camber_geom::curve::MAX_DERIVATIVE_ORDER;
use camber_geom::fit::{fit_to_tolerance_with, FitOptions, ParameterMethod};
use camber_geom::offset::offset_with;
use camber_geom::queries::{
    closest_point, curve_distance, intersect_curves_with_overlaps, BezierPieces, CurveCurveOptions,
};
use camber_geom::Error;
use nalgebra::Point2;
use serde::Deserialize;
use serde_json::Value;

use crate::commands::eval;
use crate::commands::op::{Op, Output};
use crate::curve_file::Curve;

/// The work each toolkit operation may spend on one input: thirty thousand curve
/// evaluations, so that even under AddressSanitizer an input costs seconds at most.
pub const TOOLKIT_WORK: u64 = 30_000;

/// The most parameters or lengths read from one input.
const MAX_VALUES: usize = 8;

/// The numbers of a toolkit input (`null` = NaN).
#[derive(Debug, Default, Deserialize)]
#[serde(default)]
struct Numbers {
    tolerance: Option<Option<f64>>,
    distance: Option<Option<f64>>,
    order: Option<u64>,
    at: Vec<Option<f64>>,
    lengths: Vec<Option<f64>>,
    point: Option<[Option<f64>; 2]>,
}

fn nan(v: Option<f64>) -> f64 {
    v.unwrap_or(f64::NAN)
}

fn pieces(c: &Curve) -> &dyn BezierPieces<2> {
    match c {
        Curve::Bezier(c) => c,
        Curve::BSpline(c) => c,
        Curve::Nurbs(c) => c,
        Curve::Hermite(c) => c,
    }
}

/// A toolkit input's bytes: a stream of JSON values, a curve file's object (curve A),
/// optionally a second one (curve B), then optionally an object of numbers, each optional:
/// `{"tolerance": 1e-9, "distance": 0.1, "order": 3, "at": [0.5], "lengths": [1.0],
/// "point": [0, 0]}`, where `null` stands for NaN (JSON has none).
///
/// The promises checked (a broken one panics):
/// - every operation returns (the budget bounds it) with an error or a finite answer;
/// - a derivative order above the cap is an error, never an allocation;
/// - the arc length is at least the chord between the ends; a map's error is within the
///   tolerance it reports; a parameter at a length lies in the domain;
/// - a knot removal's bound is within its tolerance; an offset's and a fit's error are finite;
/// - intersections lie within the tolerance on both curves, overlap intervals inside both
///   domains; a distance is finite and not negative;
/// - `camber op split` either refuses a parameter or writes pieces that `camber eval`
///   evaluates at their ends and middle (op and eval agree), and that load again.
///
/// # Panics
/// When an operation breaks a promise on this input (the fuzzer's finding).
pub fn toolkit(data: &[u8]) {
    let Some(text) = super::text(data) else {
        return;
    };
    let values: Vec<Value> = serde_json::Deserializer::from_str(text)
        .into_iter::<Value>()
        .take(3)
        .map_while(Result::ok)
        .collect();
    let curve = |v: &Value| Curve::from_json(&v.to_string()).ok();
    let Some(a) = values.first().and_then(curve) else {
        return;
    };
    let b = values.get(1).and_then(curve);
    let numbers: Numbers = values
        .iter()
        .skip(1)
        .find(|v| v.get("type").is_none())
        .and_then(|v| serde_json::from_value(v.clone()).ok())
        .unwrap_or_default();
    let tolerance = numbers.tolerance.map_or(1e-9, nan);
    let budget = Budget::default().with_max_work(TOOLKIT_WORK);
    let (lo, hi) = a.as_parametric().domain();
    let mut at: Vec<f64> = numbers
        .at
        .iter()
        .take(MAX_VALUES)
        .map(|v| nan(*v))
        .collect();
    at.extend([lo, 0.5 * (lo + hi), hi]);
    derivatives(&a, &at, numbers.order.unwrap_or(2));
    lengths(&a, tolerance, &numbers, &budget);
    if let Some([x, y]) = numbers.point {
        let p = Point2::new(nan(x), nan(y));
        if let Ok(found) = closest_point(a.as_parametric(), &p) {
            assert!(found.distance.is_finite(), "closest point at NaN distance");
        }
    }
    reshape(&a, tolerance, numbers.distance.map_or(0.1, nan), &budget);
    splits(&a, &at);
    if let Some(b) = &b {
        meet(&a, b, tolerance, &budget);
    }
}

/// Derivatives to `order` at every parameter: an order above the cap is refused.
fn derivatives(a: &Curve, at: &[f64], order: u64) {
    let order = usize::try_from(order).unwrap_or(usize::MAX);
    for &u in at {
        match a.as_parametric().derivatives(u, order) {
            Ok(d) => assert_eq!(d.len(), order + 1),
            Err(Error::TooLarge { .. }) => assert!(order > MAX_DERIVATIVE_ORDER),
            Err(_) => {}
        }
    }
}

/// Arc length, the map, parameters at lengths.
fn lengths(a: &Curve, tolerance: f64, numbers: &Numbers, budget: &Budget) {
    let c = a.as_parametric();
    let (lo, hi) = c.domain();
    if let Ok(l) = arc_length_with(c, tolerance, budget) {
        assert!(l.length.is_finite(), "arc length {l:?}");
        if let (Ok(p), Ok(q)) = (c.point(lo), c.point(hi)) {
            let chord = (q - p).norm();
            assert!(
                l.length >= chord * (1.0 - 1e-9) - l.tolerance.max(l.error_estimate),
                "arc length {} below the chord {chord}",
                l.length
            );
        }
    }
    if let Ok(map) = arc_length_map_with(c, tolerance, budget) {
        assert!(
            map.max_error() <= map.tolerance(),
            "map error {} above its tolerance {}",
            map.max_error(),
            map.tolerance()
        );
        for s in [0.0, 0.5 * map.length(), map.length(), f64::NAN] {
            if let Ok(u) = map.parameter(s) {
                assert!(u >= lo && u <= hi, "map parameter {u} outside [{lo}, {hi}]");
            }
        }
    }
    let s: Vec<f64> = numbers
        .lengths
        .iter()
        .take(MAX_VALUES)
        .map(|v| nan(*v))
        .collect();
    if let Ok(us) = parameters_at_lengths(c, &s, tolerance, budget) {
        for u in us {
            assert!(
                u >= lo && u <= hi,
                "parameter at length {u} outside [{lo}, {hi}]"
            );
        }
    }
}

/// Knot removal, offset and fitting.
fn reshape(a: &Curve, tolerance: f64, distance: f64, budget: &Budget) {
    if let Curve::BSpline(c) = a {
        if let Ok(r) = c.remove_knots_with(tolerance, budget) {
            // Exact removal (tolerance 0) allows rounding: 1e-10 of the largest coordinate.
            let scale = c
                .control_points()
                .iter()
                .map(|p| p.coords.amax())
                .fold(0.0, f64::max);
            assert!(
                r.error_bound <= tolerance.max(1e-10 * (1.0 + scale)),
                "knot removal moved the curve {} > {tolerance}",
                r.error_bound
            );
            let _ = Curve::BSpline(r.curve).to_json();
        }
    }
    if let Ok(o) = offset_with(a.as_parametric(), distance, tolerance, budget) {
        assert!(!o.max_error.is_nan(), "offset error is NaN");
    }
    let c = a.as_parametric();
    let (lo, hi) = c.domain();
    let points: Option<Vec<Point2<f64>>> = (0..=24)
        .map(|k| c.point(lo + (hi - lo) * f64::from(k) / 24.0).ok())
        .collect();
    if let Some(points) = points {
        if let Ok(f) = fit_to_tolerance_with(
            &points,
            tolerance,
            &FitOptions::default().with_method(ParameterMethod::ChordLength),
            budget,
        ) {
            // Below rounding the fit ends in interpolation, exact to rounding of the data.
            let scale = points.iter().map(|p| p.coords.amax()).fold(0.0, f64::max);
            assert!(
                f.max_error <= tolerance.max(1e-9 * (1.0 + scale)),
                "fit error {} > {tolerance}",
                f.max_error
            );
        }
    }
}

/// `camber op split` at every parameter: refused, or pieces that `camber eval` evaluates.
fn splits(a: &Curve, at: &[f64]) {
    for &u in at {
        let op = Op::Split {
            at: u,
            out: Output {
                output: PathBuf::from("unused.json"),
            },
            second: PathBuf::from("unused2.json"),
        };
        let Ok(pieces) = op.apply(a) else { continue };
        for piece in &pieces {
            let c = piece.as_parametric();
            // The original evaluates near u (else eval refuses the pieces for its own reasons).
            if eval::evaluate(a.as_parametric(), &[u], 1).is_err() {
                continue;
            }
            let (p0, p1) = c.domain();
            if let Err(e) = eval::evaluate(c, &[p0, 0.5 * (p0 + p1), p1], 0) {
                panic!("split at {u} wrote a piece eval refuses: {e:#}");
            }
            let json = piece.to_json().unwrap_or_default();
            assert!(
                Curve::from_json(&json).is_ok(),
                "split at {u} wrote a file that does not load"
            );
        }
    }
}

/// Intersections (with overlaps) and distance of two curves.
fn meet(a: &Curve, b: &Curve, tolerance: f64, budget: &Budget) {
    let opts = CurveCurveOptions::default()
        .with_tolerance(tolerance)
        .with_budget(budget.clone());
    let (pa, pb) = (pieces(a), pieces(b));
    if let Ok(found) = intersect_curves_with_overlaps(pa, pb, &opts) {
        let ((a0, a1), (b0, b1)) = (pa.domain(), pb.domain());
        for p in &found.points {
            assert!(p.distance <= tolerance, "intersection {} apart", p.distance);
            assert!(p.parameter_a >= a0 && p.parameter_a <= a1);
            assert!(p.parameter_b >= b0 && p.parameter_b <= b1);
        }
        for o in &found.overlaps {
            assert!(
                o.a.0 >= a0 && o.a.1 <= a1 && o.a.0 <= o.a.1,
                "overlap {o:?}"
            );
            for t in [o.b.0, o.b.1] {
                assert!(t >= b0 && t <= b1, "overlap {o:?}");
            }
        }
    }
    if let Ok(d) = curve_distance(pa, pb, &opts) {
        assert!(
            d.distance >= 0.0 && d.distance.is_finite(),
            "distance {d:?}"
        );
    }
}
