//! Properties of the toolkit's bounded algorithms, each against a second method: the adaptive
//! arc length against fixed-grid Gauss–Legendre, the parameter at many lengths against the
//! reference, knot removal within its bound (dense sampling), splitting and insertion keeping
//! the curve, curve–curve intersections against the line scan of `intersect_line`, and the
//! overlap search against a curve and its own pieces.

// Test helpers outside #[test] functions unwrap too; a failed unwrap is a failed test.
#![allow(clippy::unwrap_used)]

mod reference;

use camber_geom::arc_length::{arc_length, parameters_at_lengths};
use camber_geom::budget::Budget;
use camber_geom::queries::{
    intersect_curves, intersect_curves_with_overlaps, intersect_line, CurveCurveOptions,
};
use camber_geom::{BSplineCurve2, KnotVector, Line, NurbsCurve2, ParametricCurve, Segment};
use nalgebra::{Point2, Vector2};
use proptest::prelude::*;
use reference::Reference;

fn spline() -> impl Strategy<Value = BSplineCurve2<f64>> {
    (1usize..=4, 0usize..12).prop_flat_map(|(p, extra)| {
        let n = p + 1 + extra;
        proptest::collection::vec((-3.0..3.0_f64, -3.0..3.0_f64), n).prop_map(move |pts| {
            let points = pts
                .into_iter()
                .enumerate()
                .map(|(i, (x, y))| Point2::new(i as f64 + 0.4 * x, y))
                .collect();
            BSplineCurve2::try_new(p, KnotVector::clamped_uniform(p, n).unwrap(), points).unwrap()
        })
    })
}

fn nurbs() -> impl Strategy<Value = NurbsCurve2<f64>> {
    proptest::collection::vec((-3.0..3.0_f64, 0.2..5.0_f64), 7).prop_map(|data| {
        let points = data
            .iter()
            .enumerate()
            .map(|(i, &(y, _))| Point2::new(i as f64, y))
            .collect();
        let weights = data.iter().map(|&(_, w)| w).collect();
        NurbsCurve2::try_new(
            3,
            KnotVector::clamped_uniform(3, 7).unwrap(),
            points,
            weights,
        )
        .unwrap()
    })
}

/// The largest |A(u) − B(u)| over 200 samples per span of `a`.
fn dense_gap(a: &BSplineCurve2<f64>, b: &BSplineCurve2<f64>) -> f64 {
    let mut worst = 0.0_f64;
    for w in a.breakpoints().windows(2) {
        for k in 0..=200 {
            // w₀ + (w₁ − w₀)·1 can round past w₁ (past the domain's end at the last span).
            let u = (w[0] + (w[1] - w[0]) * f64::from(k) / 200.0).min(w[1]);
            worst = worst.max((a.point(u).unwrap() - b.point(u).unwrap()).norm());
        }
    }
    worst
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn adaptive_arc_length_agrees_with_fixed_grid_gauss_legendre(c in spline()) {
        let l = arc_length(&c, 1e-11).unwrap();
        // Fine steps: where the speed nearly vanishes inside a span it has a sharp minimum,
        // which 200 steps of the fixed grid integrate to 1e-7 only, 1 000 to 1e-9.
        let reference = Reference::new(&c, &[], 1_000).total();
        prop_assert!((l.length - reference).abs() < 1e-8 * (1.0 + reference),
            "{} vs {reference}", l.length);
        prop_assert!(l.error_estimate <= l.tolerance);
    }

    #[test]
    fn rational_arc_length_agrees_with_fixed_grid_gauss_legendre(c in nurbs()) {
        let l = arc_length(&c, 1e-11).unwrap();
        let reference = Reference::new(&c, &[], 400).total();
        prop_assert!((l.length - reference).abs() < 1e-9 * (1.0 + reference),
            "{} vs {reference}", l.length);
    }

    #[test]
    fn parameters_at_many_lengths_invert_the_reference(c in spline()) {
        let total = arc_length(&c, 1e-12).unwrap().length;
        prop_assume!(total > 1e-3);
        let lengths: Vec<f64> = (0..=64).map(|k| total * f64::from(k) / 64.0).collect();
        let us = parameters_at_lengths(&c, &lengths, 1e-12, &Budget::default()).unwrap();
        let reference = Reference::new(&c, &[], 1_000);
        for (s, u) in lengths.iter().zip(&us) {
            let back = reference.length_to(&c, *u);
            // Where the speed vanishes u is found to the square root of the rounding, and the
            // length to that u is still right.
            prop_assert!((back - s).abs() < 1e-8 * (1.0 + total), "{back} vs {s}");
        }
        prop_assert!(us.windows(2).all(|w| w[0] <= w[1]), "{us:?}");
    }

    #[test]
    fn removing_knots_stays_within_the_reported_bound(
        c in spline(),
        cuts in proptest::collection::vec(0.05..0.95_f64, 0..6),
        tol_exp in -6i32..0,
    ) {
        let tol = 10f64.powi(tol_exp);
        let (a, b) = c.domain();
        let mut new: Vec<f64> = cuts.iter().map(|f| a + (b - a) * f).collect();
        new.sort_by(f64::total_cmp);
        let Ok(busy) = c.refine(&new) else {
            // Too close to an existing knot (a degenerate span): nothing to test.
            return Ok(());
        };
        let out = busy.remove_knots(tol).unwrap();
        prop_assert!(out.error_bound <= tol.max(1e-9), "{} > {tol}", out.error_bound);
        let gap = dense_gap(&busy, &out.curve);
        prop_assert!(gap <= out.error_bound + 1e-9, "{gap} > {}", out.error_bound);
        // Removal within rounding takes out at least the inserted knots (with a larger
        // tolerance the greedy pass may spend it on original knots first).
        let exact = busy.remove_knots(1e-12).unwrap();
        prop_assert!(exact.removed >= new.len(), "{} < {}", exact.removed, new.len());
        prop_assert!(dense_gap(&busy, &exact.curve) <= 1e-9);
    }

    #[test]
    fn splitting_and_insertion_keep_the_curve(c in spline(), f in 0.01..0.99_f64, g in 0.0..1.0_f64) {
        let (a, b) = c.domain();
        let u = a + (b - a) * f;
        let Ok((left, right)) = c.split(u) else {
            return Ok(());
        };
        let v = a + (b - a) * g;
        let piece = if v <= u { &left } else { &right };
        prop_assert!((piece.point(v).unwrap() - c.point(v).unwrap()).norm() < 1e-12);
        let finer = c.insert_knot(u, 1).unwrap();
        prop_assert!((finer.point(v).unwrap() - c.point(v).unwrap()).norm() < 1e-12);
    }

    #[test]
    fn curve_intersections_agree_with_the_line_scan(
        c in spline(),
        y in -2.0..2.0_f64,
        tilt in -0.3..0.3_f64,
    ) {
        // A segment across the whole curve, and the line through it.
        let (x0, x1) = (-10.0, 30.0);
        let p0 = Point2::new(x0, y + tilt * x0);
        let p1 = Point2::new(x1, y + tilt * x1);
        let segment = Segment::try_new(p0, p1).unwrap();
        let line = Line::try_new(p0, Vector2::new(x1 - x0, tilt * (x1 - x0))).unwrap();
        let scan = intersect_line(&c, &line).unwrap();
        match intersect_curves(&c, &segment, &CurveCurveOptions::default()) {
            Ok(hits) => {
                // Tangential touches are found by both, but located to different precision:
                // compare the transversal crossings.
                let crossing = |u: f64| {
                    let d = c.derivative(u).unwrap();
                    (d.x * tilt - d.y).abs() / d.norm() > 1e-3
                };
                let a: Vec<f64> = hits.iter().map(|h| h.parameter_a).filter(|&u| crossing(u)).collect();
                let b: Vec<f64> = scan.iter().map(|h| h.parameter).filter(|&u| crossing(u)).collect();
                prop_assert_eq!(a.len(), b.len(), "{:?} vs {:?}", a, b);
                for (u, v) in a.iter().zip(&b) {
                    prop_assert!((u - v).abs() < 1e-8, "{u} vs {v}");
                }
            }
            // A degree-1 piece lying on the line: both see it, one as a stretch.
            Err(camber_geom::Error::CurvesOverlap { .. }) => {}
            Err(e) => prop_assert!(false, "{e}"),
        }
    }

    #[test]
    fn a_curve_overlaps_its_own_pieces_exactly_there(c in spline(), f in 0.1..0.45_f64, g in 0.55..0.9_f64) {
        let (a, b) = c.domain();
        let (u, v) = (a + (b - a) * f, a + (b - a) * g);
        let (_, right) = c.split(u).unwrap();
        let (middle, _) = right.split(v).unwrap();
        let found = intersect_curves_with_overlaps(&c, &middle, &CurveCurveOptions::default()).unwrap();
        prop_assume!(arc_length(&middle, 1e-9).unwrap().length > 1e-3);
        prop_assert!(!found.overlaps.is_empty(), "{found:?}");
        let first = found.overlaps[0];
        let last = found.overlaps[found.overlaps.len() - 1];
        prop_assert!((first.a.0 - u).abs() < 1e-6 && (last.a.1 - v).abs() < 1e-6, "{found:?}");
    }
}
