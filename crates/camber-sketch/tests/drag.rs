//! Drag sessions on W1 (both tangency forms): validity after every one of the 200 targets, the
//! minimum-norm move checked against a hand-derived formula, commit, stale sessions, failed
//! updates that keep the previous state.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_abs_diff_eq;
use camber_sketch::constraints::{Fixed, TangentToCircle};
use camber_sketch::drag::Freedom;
use camber_sketch::{Constraint, Error, PointRef, Sense, TangentForm};
use camber_workloads::{w1, w1_targets};
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

/// Issue 13: dragging a fixed or fully determined point is a calm no-op that says so.
#[test]
fn fixed_points_do_not_move_and_the_session_says_why() {
    let (mut s, c, _) = w1(TangentForm::Row).unwrap();
    let p3 = PointRef::Control(c, 3);
    let at = s.point(p3).unwrap();
    let mut d = s.drag(p3).unwrap();
    assert_eq!(d.freedom(), Freedom::Determined);
    d.update(at + Vector2::new(1.0, 1.0)).unwrap();
    assert_eq!(d.point(p3).unwrap(), at);
    s.add_constraint(Fixed::entity(c)).unwrap();
    assert_eq!(
        s.drag(PointRef::Control(c, 1)).unwrap().freedom(),
        Freedom::Determined
    );
    let _ = Sense::Agree;
}

/// The editor's report: a drag on a 1,000-segment affine chain began with a dense SVD of the
/// whole component (minutes). Like a solve, a large component now goes straight to the sparse
/// factorization; the drag must start, follow the mouse and keep every joint.
#[test]
fn a_large_affine_component_drags_on_the_sparse_path() {
    let (mut s, segs) = camber_workloads::w3a_chain(1000).unwrap();
    s.solve().unwrap();
    let dragged = PointRef::Control(segs[500], 1);
    let start = s.point(dragged).unwrap();
    let mut drag = s.drag(dragged).unwrap();
    for k in 1..=5 {
        let target = start + Vector2::new(0.0, 0.01 * f64::from(k));
        drag.update(target).unwrap();
        assert_abs_diff_eq!(drag.point(dragged).unwrap(), target, epsilon = 1e-10);
    }
    drag.finish(&mut s).unwrap();
    // Every joint still closed with its tangent along the fixed direction.
    for pair in segs.windows(2) {
        let (a2, a3) = (
            s.point(PointRef::Control(pair[0], 2)).unwrap(),
            s.point(PointRef::Control(pair[0], 3)).unwrap(),
        );
        let (b0, b1) = (
            s.point(PointRef::Control(pair[1], 0)).unwrap(),
            s.point(PointRef::Control(pair[1], 1)).unwrap(),
        );
        assert_abs_diff_eq!(a3, b0, epsilon = 1e-9);
        let (ta, tb) = (a3 - a2, b1 - b0);
        assert!(cross(ta, tb).abs() <= 1e-9 * ta.norm() * tb.norm());
    }
}

/// A drag on a nonlinear component moves free contact parameters; committing it must store the
/// solved ones in their constraints, as a solve does.
#[test]
fn finish_stores_the_solved_free_contact_parameters() {
    use camber_sketch::Contact;
    use camber_workloads::{w2_bspline7, W2_CIRCLES};
    let (mut s, w) = w2_bspline7().unwrap();
    s.solve().unwrap();
    let th = s
        .constraints()
        .find_map(|(id, c)| match c {
            Constraint::TangentToCircle(TangentToCircle {
                circle,
                u: Contact::Free(_),
                ..
            }) if *circle == w.circles[1] => Some(id),
            _ => None,
        })
        .unwrap();
    let u_of = |s: &camber_sketch::Sketch| match s.constraint(th).unwrap() {
        Constraint::TangentToCircle(TangentToCircle { u, .. }) => u.value(),
        _ => unreachable!("the TH contact"),
    };
    let before = u_of(&s);
    let dragged = PointRef::Control(w.curve, 3);
    let p = s.point(dragged).unwrap();
    let mut drag = s.drag(dragged).unwrap();
    for k in 1..=5 {
        drag.update(p + Vector2::new(0.004 * f64::from(k), 0.002 * f64::from(k)))
            .unwrap();
    }
    drag.finish(&mut s).unwrap();
    let after = u_of(&s);
    assert!((after - before).abs() > 1e-6, "the contact did not move");
    // The stored parameter is the contact: on the TH circle, tangent there.
    let camber_sketch::Entity::BSpline(curve) = s.entity(w.curve).unwrap() else {
        unreachable!("a B-spline")
    };
    use camber_geom::ParametricCurve;
    let (q, t) = curve.point_and_derivative(after).unwrap();
    let (c, r) = W2_CIRCLES[1];
    let v = q - Point2::new(c[0], c[1]);
    assert_abs_diff_eq!(v.norm(), r, epsilon = 1e-9);
    assert!(v.dot(&t).abs() <= 1e-8 * t.norm());
}

#[test]
fn absurd_drag_targets_are_refused_by_the_session_itself_on_both_kinds_of_component() {
    // W1 in the row form (affine) and a distance (nonlinear): a target a thousand sketch
    // sizes away is refused with a typed error, the session keeping its state; a near one is
    // taken.
    let (w1_sketch, c, _) = w1(TangentForm::Row).unwrap();
    let two_points = camber_sketch::file::from_json(
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0, 0]},
            {"id": 1, "kind": "point", "at": [2, 0]}],
            "constraints": [{"id": 2, "kind": "distance", "a": {"point": 0}, "b": {"point": 1},
            "distance": 2.0}]}"#,
    )
    .unwrap();
    let cases = [
        (w1_sketch, PointRef::Control(c, 1)),
        (two_points, PointRef::Point(camber_sketch::EntityId(1))),
    ];
    for (s, p1) in cases {
        let form = p1;
        let (centre, scale) = (s.centre(), s.scale());
        let mut drag = s.drag(p1).unwrap();
        let at = drag.point(p1).unwrap();
        let reach = camber_sketch::drag::MAX_DRAG_REACH * scale;
        for far in [
            Point2::new(1e15, 0.0),
            Point2::new(0.0, -1e10),
            Point2::new(1e308, 1e308),
            centre + Vector2::new(1.01 * reach, 0.0),
        ] {
            let err = drag.update(far).unwrap_err();
            assert!(
                matches!(err, Error::DragTargetTooFar { x, .. } if x.to_bits() == far.x.to_bits()),
                "{form:?} {far}: {err}"
            );
            let text = err.to_string();
            assert!(
                text.contains("too far from the sketch") && text.len() < 200,
                "{text}"
            );
            assert_eq!(
                drag.point(p1).unwrap(),
                at,
                "a refused target moved the point"
            );
        }
        assert!(matches!(
            drag.update(Point2::new(f64::NAN, 0.0)),
            Err(Error::NonFinite { .. })
        ));
        drag.update(at + Vector2::new(0.05, 0.02)).unwrap();
    }
}
