//! `Sketch::trim`: a line or a curve cut where it crosses another entity, one piece kept. The
//! kept cut end lies on the other entity (checked by the kernel's closest point, independently
//! of the constraint that holds it), the kept piece keeps its shape, the constraints of the
//! dropped end go with it, and bad inputs are refused with the sketch unchanged.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber_geom::queries::closest_point;
use camber_geom::BezierCurve2;
use camber_sketch::constraints::{Coincident, Fixed, Horizontal};
use camber_sketch::sketch::split::Keep;
use camber_sketch::{Constraint, Error, PointRef, Sketch};
use nalgebra::Point2;

fn hump() -> BezierCurve2<f64> {
    BezierCurve2::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 3.0),
        Point2::new(3.0, -1.0),
        Point2::new(4.0, 2.0),
    ])
    .unwrap()
}

/// The line y = 0.9 from x = −1 to 5 crosses the hump three times (near x = 0.49, 2.31,
/// 3.24); trimmed at the crossing nearest (1, 0.9), keeping its start, it ends exactly on the curve (closest-point residual
/// below 1e-10), before and after a solve, and its direction is unchanged.
#[test]
fn a_line_trimmed_at_a_bezier_crossing_ends_exactly_on_the_curve() {
    let mut s = Sketch::new();
    let line = s
        .add_line(Point2::new(-1.0, 0.9), Point2::new(5.0, 0.9))
        .unwrap();
    let curve = s.add_bezier(hump()).unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(line)))
        .unwrap();
    assert!(matches!(
        s.trim(line, curve, Keep::Start, None),
        Err(Error::AmbiguousIntersection { count: 3, .. })
    ));
    let trim = s
        .trim(line, curve, Keep::Start, Some(Point2::new(1.0, 0.9)))
        .unwrap();
    let end = s.point(PointRef::End(line)).unwrap();
    let off = closest_point(&hump(), &end).unwrap().distance;
    assert!(off < 1e-10, "{off:e}");
    assert!((end.y - 0.9).abs() < 1e-15 && (end.x - 0.4859).abs() < 1e-3);
    assert!(matches!(
        s.constraint(trim.added).unwrap(),
        Constraint::PointOnCurve(_)
    ));
    s.solve().unwrap();
    let end = s.point(PointRef::End(line)).unwrap();
    let now = s.entity(curve).unwrap().as_curve().unwrap();
    let off = closest_point(now, &end).unwrap().distance;
    assert!(off < 1e-10, "{off:e}");
}

/// The hump trimmed at the line x = 2, keeping its end: the kept piece lies on the original,
/// starts on the line, and the `fixed` at the dropped start is removed with it while the one
/// at the kept end stays.
#[test]
fn a_bezier_trimmed_at_a_line_keeps_the_shape_and_drops_the_constraints_of_the_dropped_end() {
    let mut s = Sketch::new();
    let curve = s.add_bezier(hump()).unwrap();
    let line = s
        .add_line(Point2::new(2.0, -3.0), Point2::new(2.0, 3.0))
        .unwrap();
    let at_start = s
        .add_constraint(Fixed::point(PointRef::Start(curve)))
        .unwrap();
    let at_end = s
        .add_constraint(Fixed::point(PointRef::End(curve)))
        .unwrap();
    let trim = s.trim(curve, line, Keep::End, None).unwrap();
    assert_eq!(trim.removed, vec![at_start]);
    assert!(s.constraint(at_start).is_err() && s.constraint(at_end).is_ok());
    let kept = s.entity(curve).unwrap().as_curve().unwrap();
    for k in 0..=40 {
        let p = kept.point(f64::from(k) / 40.0).unwrap();
        assert!(closest_point(&hump(), &p).unwrap().distance < 1e-12);
    }
    let start = s.point(PointRef::Start(curve)).unwrap();
    assert!((start.x - 2.0).abs() < 1e-12);
    assert!((s.point(PointRef::End(curve)).unwrap() - Point2::new(4.0, 2.0)).norm() < 1e-15);
    s.solve().unwrap();
    assert!((s.point(PointRef::Start(curve)).unwrap().x - 2.0).abs() < 1e-10);
}

/// Bad trims: typed errors naming the entities, nothing changed.
#[test]
fn bad_trims_are_refused_and_change_nothing() {
    let mut s = Sketch::new();
    let a = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(4.0, 0.0))
        .unwrap();
    let b = s
        .add_line(Point2::new(2.0, -1.0), Point2::new(2.0, 1.0))
        .unwrap();
    let c = s
        .add_line(Point2::new(4.0, 0.0), Point2::new(4.0, 3.0))
        .unwrap();
    s.add_constraint(Coincident {
        a: PointRef::End(a),
        b: PointRef::Start(c),
    })
    .unwrap();
    let h = s.add_constraint(Horizontal::line(a)).unwrap();
    let file = camber_sketch::file::to_json(&s).unwrap();
    assert_eq!(
        s.trim(a, b, Keep::Start, None).unwrap_err(),
        Error::EntityConstrained {
            entity: a,
            constraint: h,
            operation: "trim"
        }
    );
    assert_eq!(
        s.trim(c, b, Keep::Start, None).unwrap_err(),
        Error::NoIntersection {
            entity: c,
            other: b
        }
    );
    assert_eq!(camber_sketch::file::to_json(&s).unwrap(), file);
    // Without the horizontal the trim goes through and drops the corner at the removed end.
    s.remove_constraint(h).unwrap();
    let trim = s.trim(a, b, Keep::Start, None).unwrap();
    assert_eq!(trim.removed.len(), 1);
    assert!((s.point(PointRef::End(a)).unwrap() - Point2::new(2.0, 0.0)).norm() < 1e-15);
}

/// A line split at a circle, then trimmed at the circle's other crossing: the joint the split
/// put on the circle (`point_on_circle` at the piece's end) follows the trim, and both cut
/// ends stay on the circle through a solve.
#[test]
fn a_split_piece_trims_again_with_its_joint_kept() {
    let mut s = Sketch::new();
    let a = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(4.0, 0.0))
        .unwrap();
    let c = s.add_circle(Point2::new(2.0, 0.0), 1.0).unwrap();
    let split = s
        .split_at_intersection(a, c, Some(Point2::new(3.2, 0.1)))
        .unwrap();
    let trim = s.trim(a, c, Keep::End, None).unwrap();
    assert!(trim.removed.is_empty());
    assert!(s.constraint(split.added[1]).is_ok());
    assert!((s.point(PointRef::Start(a)).unwrap() - Point2::new(1.0, 0.0)).norm() < 1e-12);
    assert!((s.point(PointRef::End(a)).unwrap() - Point2::new(3.0, 0.0)).norm() < 1e-12);
    s.solve().unwrap();
    for end in [PointRef::Start(a), PointRef::End(a)] {
        let p = s.point(end).unwrap();
        assert!(((p - Point2::new(2.0, 0.0)).norm() - 1.0).abs() < 1e-10);
    }
}
