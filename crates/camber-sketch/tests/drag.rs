//! Drag sessions on W1 (both tangency forms): validity after every one of the 200 targets, the
//! minimum-norm move checked against a hand-derived formula, commit, stale sessions, failed
//! updates that keep the previous state.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_abs_diff_eq;
use camber_sketch::workloads::{w1, w1_targets};
use camber_sketch::{Constraint, Error, FixTarget, PointRef, Sense, TangentForm};
use nalgebra::{Point2, Vector2};

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

#[test]
fn w1_row_form_is_valid_and_minimum_norm_at_every_target() {
    let (s, c, d) = w1(TangentForm::Row).unwrap();
    let p = |k| PointRef::Control(c, k);
    let p3 = s.point(p(3)).unwrap();
    let mut drag = s.drag(p(1)).unwrap();
    for target in w1_targets(s.point(p(1)).unwrap()) {
        let (p0_old, p2_old) = (drag.point(p(0)).unwrap(), drag.point(p(2)).unwrap());
        drag.update(target).unwrap();
        let (p0, p1) = (drag.point(p(0)).unwrap(), drag.point(p(1)).unwrap());
        let t = p1 - p0;
        assert!(cross(t, d).abs() / t.norm() < 1e-10);
        assert!(t.dot(&d) > 0.0);
        assert_abs_diff_eq!(p1, target, epsilon = 1e-12);
        assert_abs_diff_eq!(drag.point(p(3)).unwrap(), p3, epsilon = 0.0);
        // Only P0 has to move: the one row cross(P1 − P0, D) = 0 has gradient (−D_y, D_x) in
        // P0, so the least move is ΔP0 = −r·(−D_y, D_x)/|D|² with r the row at the old P0.
        let r = cross(target - p0_old, d);
        let expected = p0_old - r * Vector2::new(-d.y, d.x) / d.norm_squared();
        assert_abs_diff_eq!(p0, expected, epsilon = 1e-12);
        assert_abs_diff_eq!(drag.point(p(2)).unwrap(), p2_old, epsilon = 1e-12);
    }
}

#[test]
fn w1_elimination_form_is_valid_at_every_target() {
    let (s, c, d) = w1(TangentForm::Elimination).unwrap();
    let p = |k| PointRef::Control(c, k);
    let p3 = s.point(p(3)).unwrap();
    let mut drag = s.drag(p(1)).unwrap();
    for target in w1_targets(s.point(p(1)).unwrap()) {
        drag.update(target).unwrap();
        let (p0, p1) = (drag.point(p(0)).unwrap(), drag.point(p(1)).unwrap());
        let t = p1 - p0;
        assert!(cross(t, d).abs() / t.norm() < 1e-10);
        assert!(t.dot(&d) > 0.0);
        assert_abs_diff_eq!(p1, target, epsilon = 1e-12);
        assert_abs_diff_eq!(drag.point(p(3)).unwrap(), p3, epsilon = 0.0);
    }
}

#[test]
fn finish_commits_and_a_stale_session_is_refused() {
    let (mut s, c, _) = w1(TangentForm::Row).unwrap();
    let p1 = PointRef::Control(c, 1);
    let target = s.point(p1).unwrap() + Vector2::new(0.05, 0.02);
    let mut drag = s.drag(p1).unwrap();
    drag.update(target).unwrap();
    drag.finish(&mut s).unwrap();
    assert_abs_diff_eq!(s.point(p1).unwrap(), target, epsilon = 1e-12);

    let mut drag = s.drag(p1).unwrap();
    drag.update(target + Vector2::new(0.1, 0.0)).unwrap();
    s.set_point(PointRef::Control(c, 2), Point2::new(2.0, 1.0))
        .unwrap();
    let rev = s.revision();
    assert!(matches!(
        drag.finish(&mut s),
        Err(Error::StaleSession { found, .. }) if found == rev
    ));
    assert_abs_diff_eq!(s.point(p1).unwrap(), target, epsilon = 1e-12);
}

#[test]
fn a_flipping_update_is_refused_and_the_session_keeps_its_state() {
    let (s, c, d) = w1(TangentForm::Row).unwrap();
    let p1 = PointRef::Control(c, 1);
    let mut drag = s.drag(p1).unwrap();
    let good = s.point(p1).unwrap() + Vector2::new(0.0, 0.05);
    drag.update(good).unwrap();
    let p0 = drag.point(PointRef::Control(c, 0)).unwrap();
    // Behind P0 along D: the row still holds but the tangent would point against D.
    let err = drag.update(p0 - 0.5 * d).unwrap_err();
    assert!(matches!(err, Error::OrientationFlipped { .. }), "{err:?}");
    assert_abs_diff_eq!(drag.point(p1).unwrap(), good, epsilon = 1e-12);
    assert!(matches!(
        drag.update(Point2::new(f64::NAN, 0.0)),
        Err(Error::NonFinite { what: "target", .. })
    ));
    assert_abs_diff_eq!(drag.point(p1).unwrap(), good, epsilon = 1e-12);
}

#[test]
fn fixed_points_cannot_be_dragged() {
    let (mut s, c, _) = w1(TangentForm::Row).unwrap();
    assert_eq!(
        s.drag(PointRef::Control(c, 3)).unwrap_err(),
        Error::NotDraggable {
            point: PointRef::Control(c, 3)
        }
    );
    s.add_constraint(Constraint::Fixed(FixTarget::Entity(c)))
        .unwrap();
    assert!(matches!(
        s.drag(PointRef::Control(c, 1)),
        Err(Error::NotDraggable { .. })
    ));
    let _ = Sense::Agree;
}
