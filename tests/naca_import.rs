//! The `naca_import` example, run in-process (its code is compiled into this test with
//! `#[path]`): the fitted sides are within the tolerance of every data point, measured again
//! by closest-point distances; after the nose droop the leading edge sits where it was dragged,
//! the trailing-edge ends have not moved and the two sides still meet with one tangent; and the
//! move is the least one: the rest of each side stays close to the section.

#![allow(clippy::unwrap_used)]

#[allow(dead_code)] // its `main` is not called here
#[path = "../examples/naca_import.rs"]
mod naca_import;

use camber::geom::queries::closest_point;
use camber::geom::ParametricCurve;
use camber::sketch::{Entity, PointRef};
use naca_import::{join_angle, run, DROOP, TOLERANCE};

#[test]
fn an_imported_section_keeps_its_joins_when_its_nose_is_drooped() {
    let i = run().unwrap();
    assert!(i.fit_error <= TOLERANCE, "{}", i.fit_error);

    let le = i.sketch.point(PointRef::End(i.upper)).unwrap();
    assert!((le.x - i.leading_edge.x).abs() < 1e-9, "{le}");
    assert!((le.y - (i.leading_edge.y - DROOP)).abs() < 1e-9, "{le}");
    assert_eq!(i.sketch.point(PointRef::Start(i.lower)).unwrap(), le);
    // Trailing-edge ends: the first and last data points, unmoved.
    let te_upper = i.sketch.point(PointRef::Start(i.upper)).unwrap();
    let te_lower = i.sketch.point(PointRef::End(i.lower)).unwrap();
    assert!((te_upper - i.points[0]).norm() < 1e-12, "{te_upper}");
    assert!(
        (te_lower - i.points[i.points.len() - 1]).norm() < 1e-12,
        "{te_lower}"
    );
    assert!(join_angle(&i.sketch, i.upper, i.lower).unwrap().abs() < 1e-9);

    // Far from the nose the sides hardly move: every data point aft of 30 % chord is within
    // the tolerance plus a small share of the droop of the drooped section.
    let sides = [i.upper, i.lower].map(|id| match i.sketch.entity(id).unwrap() {
        Entity::BSpline(c) => c.clone(),
        other => panic!("not a B-spline: {other:?}"),
    });
    for p in i.points.iter().filter(|p| p.x > 0.3) {
        let d = sides
            .iter()
            .map(|c| closest_point(c, p).unwrap().distance)
            .fold(f64::INFINITY, f64::min);
        assert!(d < TOLERANCE + 0.2 * DROOP, "{p}: {d}");
    }
    // Both sides are still curves on their own domains with finite points.
    for c in &sides {
        let (a, b) = c.domain();
        assert!(c
            .point(0.5 * (a + b))
            .unwrap()
            .coords
            .iter()
            .all(|x| x.is_finite()));
    }
}
