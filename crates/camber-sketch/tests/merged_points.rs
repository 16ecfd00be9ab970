//! Coincident points merged into one set of unknowns: the minimum-norm answer is the one the
//! two-row form gives (both points meet at their midpoint), duplicated and cyclic coincidences
//! are named redundant, two fixed points that disagree still conflict, and a drag of a merged
//! point carries its partner along.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_abs_diff_eq;
use camber_geom::BezierCurve2;
use camber_sketch::constraints::{Coincident, Fixed};
use camber_sketch::{EntityId, Error, PointRef, Sketch};
use nalgebra::Point2;

fn cubic(s: &mut Sketch, x0: f64, y0: f64) -> EntityId {
    s.add_bezier(
        BezierCurve2::try_new(vec![
            Point2::new(x0, y0),
            Point2::new(x0 + 1.0, y0 + 1.0),
            Point2::new(x0 + 2.0, y0 + 1.0),
            Point2::new(x0 + 3.0, y0),
        ])
        .unwrap(),
    )
    .unwrap()
}

fn joined(s: &mut Sketch) -> (EntityId, EntityId) {
    let a = cubic(s, 0.0, 0.0);
    // b starts 0.4 right of and 0.2 above a's end.
    let b = cubic(s, 3.4, 0.2);
    s.add_constraint(Coincident {
        a: PointRef::End(a),
        b: PointRef::Start(b),
    })
    .unwrap();
    (a, b)
}

#[test]
fn two_apart_points_meet_at_their_midpoint_and_nothing_else_moves() {
    let mut s = Sketch::new();
    let (a, b) = joined(&mut s);
    let before: Vec<_> = (0..3)
        .map(|k| s.point(PointRef::Control(a, k)).unwrap())
        .collect();
    let after_b: Vec<_> = (1..4)
        .map(|k| s.point(PointRef::Control(b, k)).unwrap())
        .collect();
    s.solve().unwrap();
    // Least ‖Δ‖² with P_a + Δa = P_b + Δb: Δa = −Δb = (P_b − P_a)/2.
    let mid = Point2::new(3.2, 0.1);
    assert_abs_diff_eq!(s.point(PointRef::End(a)).unwrap(), mid, epsilon = 1e-12);
    assert_abs_diff_eq!(s.point(PointRef::Start(b)).unwrap(), mid, epsilon = 1e-12);
    for (k, p) in before.iter().enumerate() {
        assert_abs_diff_eq!(s.point(PointRef::Control(a, k)).unwrap(), *p, epsilon = 0.0);
    }
    for (k, p) in after_b.iter().enumerate() {
        assert_abs_diff_eq!(
            s.point(PointRef::Control(b, k + 1)).unwrap(),
            *p,
            epsilon = 0.0
        );
    }
}

#[test]
fn a_merged_pair_counts_once_in_the_dof() {
    let mut s = Sketch::new();
    joined(&mut s);
    let a = &s.analyze().unwrap()[0].analysis;
    // 16 coordinates, 2 of them bound to the other 2: 14, nothing redundant.
    assert_eq!(a.dof, 14);
    assert!(a.redundant.is_empty() && a.conflicting.is_empty());
}

#[test]
fn duplicated_and_cyclic_coincidences_are_named_redundant() {
    let mut s = Sketch::new();
    let (a, b) = joined(&mut s);
    let dup = s
        .add_constraint(Coincident {
            a: PointRef::Start(b),
            b: PointRef::End(a),
        })
        .unwrap();
    let p = s.add_point(Point2::new(3.0, 0.5)).unwrap();
    s.add_constraint(Coincident {
        a: PointRef::Point(p),
        b: PointRef::End(a),
    })
    .unwrap();
    let cycle = s
        .add_constraint(Coincident {
            a: PointRef::Start(b),
            b: PointRef::Point(p),
        })
        .unwrap();
    let analysis = &s.analyze().unwrap()[0].analysis;
    assert_eq!(analysis.redundant, vec![dup, cycle]);
    assert_eq!(analysis.dof, 14);
    let r = s.solve().unwrap();
    assert_eq!(r.components[0].report.redundant, vec![dup, cycle]);
    let joint = s.point(PointRef::End(a)).unwrap();
    assert_abs_diff_eq!(s.point(PointRef::Start(b)).unwrap(), joint, epsilon = 0.0);
    assert_abs_diff_eq!(s.point(PointRef::Point(p)).unwrap(), joint, epsilon = 0.0);
}

#[test]
fn two_fixed_points_that_disagree_still_conflict() {
    let mut s = Sketch::new();
    let a = cubic(&mut s, 0.0, 0.0);
    let b = cubic(&mut s, 3.4, 0.2);
    let joint = s
        .add_constraint(Coincident {
            a: PointRef::End(a),
            b: PointRef::Start(b),
        })
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::End(a))).unwrap();
    let second = s.add_constraint(Fixed::point(PointRef::Start(b))).unwrap();
    let err = s.solve().unwrap_err();
    let Error::Conflicting { constraints } = err else {
        panic!("expected a conflict, got {err:?}");
    };
    assert!(!constraints.is_empty());
    // The coincidence or the second fix is named: without either one the rest is satisfiable.
    assert!(constraints.iter().all(|c| *c == joint || *c == second));
}

#[test]
fn dragging_a_merged_point_carries_its_partner() {
    let mut s = Sketch::new();
    let (a, b) = joined(&mut s);
    s.solve().unwrap();
    let others: Vec<_> = [(a, 0), (a, 1), (a, 2), (b, 1), (b, 2), (b, 3)]
        .into_iter()
        .map(|(c, k)| s.point(PointRef::Control(c, k)).unwrap())
        .collect();
    let mut drag = s.drag(PointRef::End(a)).unwrap();
    for k in 0..20 {
        let target = Point2::new(3.2 + 0.05 * f64::from(k), 0.1 - 0.03 * f64::from(k));
        drag.update(target).unwrap();
        assert_abs_diff_eq!(
            drag.point(PointRef::End(a)).unwrap(),
            target,
            epsilon = 1e-12
        );
        assert_abs_diff_eq!(
            drag.point(PointRef::Start(b)).unwrap(),
            target,
            epsilon = 1e-12
        );
    }
    drag.finish(&mut s).unwrap();
    let moved: Vec<_> = [(a, 0), (a, 1), (a, 2), (b, 1), (b, 2), (b, 3)]
        .into_iter()
        .map(|(c, k)| s.point(PointRef::Control(c, k)).unwrap())
        .collect();
    assert_eq!(moved, others);
    assert_abs_diff_eq!(
        s.point(PointRef::Start(b)).unwrap(),
        Point2::new(4.15, -0.47),
        epsilon = 1e-12
    );
}
