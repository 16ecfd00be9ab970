//! `Sketch::trim_closed`: a circle or an ellipse cut where it crosses other entities, the
//! piece around a point removed and the rest kept as an arc. Checked against hand-derived crossings (a unit
//! circle and the lines x = ½, y = ±½ meet at 60° and 30° steps), against the kernel's
//! closest point for a curve, for the constraints an arc carries on, and for refusals that
//! leave the sketch unchanged.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use std::f64::consts::PI;

use camber_geom::queries::closest_point;
use camber_geom::BezierCurve2;
use camber_sketch::constraints::semi_axis::Axis;
use camber_sketch::constraints::{
    Coincident, EqualRadius, Fixed, PointOnCircle, PointOnCurve, PointOnEllipse, PointOnLine,
    Radius, SemiAxis,
};
use camber_sketch::{Constraint, Entity, Error, PointRef, Sketch};
use nalgebra::{Point2, Vector2};
use proptest::prelude::*;

fn at_angle(degrees: f64) -> Point2<f64> {
    let t = degrees * PI / 180.0;
    Point2::new(t.cos(), t.sin())
}

/// The counter-clockwise sweep of an arc entity, in degrees.
fn sweep_degrees(e: &Entity) -> f64 {
    let Entity::Arc([c, s, f]) = e else {
        panic!("not an arc: {e:?}")
    };
    let (a0, a1) = ((s - c).y.atan2((s - c).x), (f - c).y.atan2((f - c).x));
    (a1 - a0).rem_euclid(2.0 * PI) * 180.0 / PI
}

/// The unit circle cut by x = ½ (crossings at ±60°): removing near (1, 0) keeps the 240° arc
/// from 60° to 300°, removing near (−1, 0) the 120° arc from −60° to 60°.
#[test]
fn a_circle_cut_by_one_line_keeps_the_side_away_from_the_point() {
    for (near, start, end, sweep) in [
        (Point2::new(1.0, 0.0), 60.0, -60.0, 240.0),
        (Point2::new(-1.0, 0.0), -60.0, 60.0, 120.0),
        // Far outside the circle, only the direction from the centre counts.
        (Point2::new(50.0, 1.0), 60.0, -60.0, 240.0),
    ] {
        let mut s = Sketch::new();
        let c = s.add_circle(Point2::origin(), 1.0).unwrap();
        let line = s
            .add_line(Point2::new(0.5, -2.0), Point2::new(0.5, 2.0))
            .unwrap();
        let trim = s.trim_closed(c, &[line], near).unwrap();
        assert_eq!(trim.entity, c);
        assert!((trim.start - at_angle(start)).norm() < 1e-12, "{trim:?}");
        assert!((trim.end - at_angle(end)).norm() < 1e-12, "{trim:?}");
        let arc = s.entity(c).unwrap().clone();
        assert!((sweep_degrees(&arc) - sweep).abs() < 1e-9);
        for (id, end) in trim
            .added
            .iter()
            .zip([PointRef::Start(c), PointRef::End(c)])
        {
            assert_eq!(
                s.constraint(*id).unwrap(),
                &Constraint::from(PointOnLine { point: end, line })
            );
        }
        s.solve().unwrap();
        assert!((s.point(PointRef::Start(c)).unwrap().x - 0.5).abs() < 1e-10);
        assert!((s.point(PointRef::End(c)).unwrap().x - 0.5).abs() < 1e-10);
    }
}

/// Two lines y = ±½ from x = 0 to 3 cross the unit circle at ±30° only: removing near (1, 0)
/// keeps the 300° arc from 30° (on the upper line) to −30° (on the lower), and the arc's ends
/// follow the lines when one is moved.
#[test]
fn a_circle_cut_by_two_lines_holds_each_end_on_its_own_line() {
    let mut s = Sketch::new();
    let c = s.add_circle(Point2::origin(), 1.0).unwrap();
    let upper = s
        .add_line(Point2::new(0.0, 0.5), Point2::new(3.0, 0.5))
        .unwrap();
    let lower = s
        .add_line(Point2::new(0.0, -0.5), Point2::new(3.0, -0.5))
        .unwrap();
    let trim = s
        .trim_closed(c, &[lower, upper], Point2::new(1.0, 0.0))
        .unwrap();
    assert!((trim.start - at_angle(30.0)).norm() < 1e-12);
    assert!((trim.end - at_angle(-30.0)).norm() < 1e-12);
    assert!((sweep_degrees(s.entity(c).unwrap()) - 300.0).abs() < 1e-9);
    let on = |id| match s.constraint(id).unwrap() {
        Constraint::PointOnLine(k) => (k.point, k.line),
        other => panic!("{other:?}"),
    };
    assert_eq!(on(trim.added[0]), (PointRef::Start(c), upper));
    assert_eq!(on(trim.added[1]), (PointRef::End(c), lower));
    // Fix the centre and the radius, move the upper line up: the start follows it.
    s.add_constraint(Fixed::point(PointRef::Control(c, 0)))
        .unwrap();
    s.add_constraint(Radius {
        circle: c,
        radius: 1.0,
    })
    .unwrap();
    s.set_entity(
        upper,
        Entity::Line([Point2::new(0.0, 0.8), Point2::new(3.0, 0.8)]),
    )
    .unwrap();
    for end in [PointRef::Start(upper), PointRef::End(upper)] {
        s.add_constraint(Fixed::point(end)).unwrap();
    }
    s.solve().unwrap();
    let start = s.point(PointRef::Start(c)).unwrap();
    assert!((start.y - 0.8).abs() < 1e-9 && (start.coords.norm() - 1.0).abs() < 1e-9);
    let end = s.point(PointRef::End(c)).unwrap();
    assert!((end - at_angle(-30.0)).norm() < 1e-9, "{end}");
}

/// A Bézier hump crossing the unit circle twice: the kept arc's ends lie on the curve (by the
/// kernel's closest point) before and after a solve.
#[test]
fn a_circle_cut_by_a_curve_ends_exactly_on_it() {
    let hump = BezierCurve2::try_new(vec![
        Point2::new(-2.0, 0.2),
        Point2::new(-0.5, 1.5),
        Point2::new(0.5, -0.8),
        Point2::new(2.0, 0.4),
    ])
    .unwrap();
    let mut s = Sketch::new();
    let c = s.add_circle(Point2::new(0.0, 0.1), 1.0).unwrap();
    let curve = s.add_bezier(hump).unwrap();
    let trim = s.trim_closed(c, &[curve], Point2::new(0.0, 2.0)).unwrap();
    for id in trim.added {
        assert!(matches!(
            s.constraint(id).unwrap(),
            Constraint::PointOnCurve(PointOnCurve { curve: k, .. }) if *k == curve
        ));
    }
    for solved in [false, true] {
        if solved {
            s.solve().unwrap();
        }
        for end in [PointRef::Start(c), PointRef::End(c)] {
            let p = s.point(end).unwrap();
            let now = s.entity(curve).unwrap().as_curve().unwrap();
            let off = closest_point(now, &p).unwrap().distance;
            assert!(off < 1e-10, "{end}: {off:e}");
        }
    }
    // The removed piece is the top one: the arc's midpoint is below the centre.
    let Entity::Arc([centre, a, b]) = s.entity(c).unwrap().clone() else {
        panic!()
    };
    let (a0, a1) = (
        (a - centre).y.atan2((a - centre).x),
        (b - centre).y.atan2((b - centre).x),
    );
    let mid = a0 + 0.5 * (a1 - a0).rem_euclid(2.0 * PI);
    assert!(mid.sin() < 0.0, "{mid}");
}

/// Radius, equal radius and a coincident at the centre mean the same of the arc: they stay,
/// under their ids, and hold after a solve.
#[test]
fn constraints_on_the_circle_carry_over_to_the_arc() {
    let mut s = Sketch::new();
    let c = s.add_circle(Point2::origin(), 1.0).unwrap();
    let other = s.add_circle(Point2::new(3.0, 0.0), 1.0).unwrap();
    let p = s.add_point(Point2::origin()).unwrap();
    let line = s
        .add_line(Point2::new(0.5, -2.0), Point2::new(0.5, 2.0))
        .unwrap();
    s.set_tag(c, Some("HUB")).unwrap();
    let kept = [
        s.add_constraint(Radius {
            circle: c,
            radius: 1.0,
        })
        .unwrap(),
        s.add_constraint(EqualRadius {
            first: c,
            second: other,
        })
        .unwrap(),
        s.add_constraint(Coincident {
            a: PointRef::Control(c, 0),
            b: PointRef::Point(p),
        })
        .unwrap(),
    ];
    let before: Vec<Constraint> = kept
        .iter()
        .map(|id| s.constraint(*id).unwrap().clone())
        .collect();
    s.trim_closed(c, &[line], Point2::new(1.0, 0.0)).unwrap();
    for (id, was) in kept.iter().zip(&before) {
        assert_eq!(s.constraint(*id).unwrap(), was);
    }
    assert_eq!(s.tag(c), Some("HUB"));
    // A new radius through the kept constraint: the arc and the other circle follow.
    s.remove_constraint(kept[0]).unwrap();
    s.add_constraint(Radius {
        circle: other,
        radius: 0.9,
    })
    .unwrap();
    s.solve().unwrap();
    let Entity::Arc([centre, a, b]) = s.entity(c).unwrap().clone() else {
        panic!()
    };
    assert!(((a - centre).norm() - 0.9).abs() < 1e-9);
    assert!(((b - centre).norm() - 0.9).abs() < 1e-9);
    // The ends stay on the line (which the solve may move too).
    let Entity::Line([l0, l1]) = s.entity(line).unwrap().clone() else {
        panic!()
    };
    let d = (l1 - l0).normalize();
    for q in [a, b] {
        let off = (q - l0).perp(&d);
        assert!(off.abs() < 1e-9, "{off:e}");
    }
}

/// Refusals name the circle and the cause, and change nothing.
#[test]
fn bad_circle_trims_are_refused_with_the_sketch_unchanged() {
    let mut s = Sketch::new();
    let c = s.add_circle(Point2::origin(), 1.0).unwrap();
    let through = s
        .add_line(Point2::new(0.5, -2.0), Point2::new(0.5, 2.0))
        .unwrap();
    let once = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(3.0, 0.0))
        .unwrap();
    let away = s
        .add_line(Point2::new(5.0, 0.0), Point2::new(6.0, 0.0))
        .unwrap();
    let file = camber_sketch::file::to_json(&s).unwrap();
    let near = Point2::new(1.0, 0.0);
    assert!(matches!(
        s.trim_closed(through, &[c], near),
        Err(Error::WrongEntityKind { entity, .. }) if entity == through
    ));
    assert_eq!(
        s.trim_closed(c, &[once], near),
        Err(Error::TooFewCrossings {
            entity: c,
            count: 1
        })
    );
    assert_eq!(
        s.trim_closed(c, &[away], near),
        Err(Error::TooFewCrossings {
            entity: c,
            count: 0
        })
    );
    assert_eq!(
        s.trim_closed(c, &[], near),
        Err(Error::TooFewCrossings {
            entity: c,
            count: 0
        })
    );
    assert_eq!(
        s.trim_closed(c, &[through, c], near),
        Err(Error::SameEntity { entity: c })
    );
    assert!(matches!(
        s.trim_closed(c, &[through], Point2::new(f64::NAN, 0.0)),
        Err(Error::NonFinite { .. })
    ));
    // A point held on the circle might fall in the removed piece: refused.
    let q = s.add_point(Point2::new(0.0, 1.0)).unwrap();
    let on = s
        .add_constraint(PointOnCircle {
            point: PointRef::Point(q),
            circle: c,
        })
        .unwrap();
    let file_with = camber_sketch::file::to_json(&s).unwrap();
    assert_eq!(
        s.trim_closed(c, &[through], near),
        Err(Error::EntityConstrained {
            entity: c,
            constraint: on,
            operation: "trim"
        })
    );
    assert_eq!(camber_sketch::file::to_json(&s).unwrap(), file_with);
    s.remove_constraint(on).unwrap();
    s.remove_entity(q).unwrap();
    assert_eq!(camber_sketch::file::to_json(&s).unwrap(), file);
}

/// A trimmed circle is an arc: a second circle trim of it is refused, and nothing changes.
#[test]
fn an_arc_is_not_trimmed_as_a_circle() {
    let mut s = Sketch::new();
    let c = s.add_circle(Point2::origin(), 1.0).unwrap();
    let line = s
        .add_line(Point2::new(0.5, -2.0), Point2::new(0.5, 2.0))
        .unwrap();
    s.trim_closed(c, &[line], Point2::new(1.0, 0.0)).unwrap();
    let file = camber_sketch::file::to_json(&s).unwrap();
    assert!(matches!(
        s.trim_closed(c, &[line], Point2::new(-1.0, 0.0)),
        Err(Error::WrongEntityKind {
            expected: "circle or ellipse",
            ..
        })
    ));
    assert_eq!(camber_sketch::file::to_json(&s).unwrap(), file);
}

/// A radius bound to a parameter keeps its binding through the trim, and
/// `set_parameter` then drives the arc's radius.
#[test]
fn a_parameter_bound_radius_drives_the_arc() {
    let mut s = Sketch::new();
    let c = s.add_circle(Point2::origin(), 1.0).unwrap();
    let line = s
        .add_line(Point2::new(0.5, -2.0), Point2::new(0.5, 2.0))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(c, 0)))
        .unwrap();
    for end in [PointRef::Start(line), PointRef::End(line)] {
        s.add_constraint(Fixed::point(end)).unwrap();
    }
    let text = camber_sketch::file::to_json(&s).unwrap().replacen(
        "\"constraints\"",
        "\"parameters\": {\"r0\": 1.0}, \"constraints\"",
        1,
    );
    let mut s = camber_sketch::file::from_json(&text).unwrap();
    s.add_constraint(Radius {
        circle: c,
        radius: 1.0,
    })
    .unwrap();
    let file = camber_sketch::file::to_json(&s).unwrap();
    // The constraint comes after the entities: bind its radius, the file's last one.
    let at = file.rfind("\"radius\":1.0}").unwrap();
    let bound = format!("{}\"radius\":\"r0\"}}{}", &file[..at], &file[at + 13..]);
    let mut s = camber_sketch::file::from_json(&bound).unwrap();
    s.trim_closed(c, &[line], Point2::new(1.0, 0.0)).unwrap();
    assert!(camber_sketch::file::to_json(&s)
        .unwrap()
        .contains("\"radius\":\"r0\""));
    s.set_parameter("r0", 0.8).unwrap();
    s.solve().unwrap();
    let Entity::Arc([centre, a, b]) = s.entity(c).unwrap().clone() else {
        panic!()
    };
    assert!(((a - centre).norm() - 0.8).abs() < 1e-9 && ((b - centre).norm() - 0.8).abs() < 1e-9);
    assert!((a.x - 0.5).abs() < 1e-9 && (b.x - 0.5).abs() < 1e-9);
}

/// The ellipse x²/4 + y² = 1 cut by x = 1 (2·cos t = 1: parametric angles ±60°, points
/// (1, ±√3/2)): removing near (2, 0) keeps the elliptic arc from 60° to −60° (a 240° sweep in
/// the parametric angle), ends on the line; its semi-axis constraint and a coincident at its
/// vertex carry over and drive it after the trim.
#[test]
fn an_ellipse_cut_by_a_line_keeps_the_far_elliptic_arc() {
    let mut s = Sketch::new();
    let shape = camber_geom::Ellipse::try_new(Point2::origin(), 2.0, 1.0, 0.0).unwrap();
    let e = s.add_entity(Entity::ellipse(&shape)).unwrap();
    let line = s
        .add_line(Point2::new(1.0, -2.0), Point2::new(1.0, 2.0))
        .unwrap();
    let vertex = s.add_point(Point2::new(2.0, 0.0)).unwrap();
    let semi = s
        .add_constraint(SemiAxis {
            ellipse: e,
            axis: Axis::B,
            length: 1.0,
        })
        .unwrap();
    let at_vertex = s
        .add_constraint(Coincident {
            a: PointRef::Control(e, 1),
            b: PointRef::Point(vertex),
        })
        .unwrap();
    let h = 0.75_f64.sqrt();
    let trim = s.trim_closed(e, &[line], Point2::new(2.0, 0.0)).unwrap();
    assert!(
        (trim.start - Point2::new(1.0, h)).norm() < 1e-12,
        "{trim:?}"
    );
    assert!((trim.end - Point2::new(1.0, -h)).norm() < 1e-12, "{trim:?}");
    let arc = s.entity(e).unwrap().as_elliptic_arc().unwrap();
    assert!(
        (arc.sweep() - 240.0_f64.to_radians()).abs() < 1e-9,
        "{}",
        arc.sweep()
    );
    assert!(s.constraint(semi).is_ok() && s.constraint(at_vertex).is_ok());
    for id in trim.added {
        assert!(matches!(
            s.constraint(id).unwrap(),
            Constraint::PointOnLine(PointOnLine { line: l, .. }) if *l == line
        ));
    }
    // Fix the line and the centre, ask for b = 0.5: the ends slide along x = 1 to
    // y = ±0.5·√3/2 (the angle stays ±60° since a and the line are unchanged).
    for end in [
        PointRef::Start(line),
        PointRef::End(line),
        PointRef::Control(e, 0),
        PointRef::Point(vertex),
    ] {
        s.add_constraint(Fixed::point(end)).unwrap();
    }
    s.remove_constraint(semi).unwrap();
    s.add_constraint(SemiAxis {
        ellipse: e,
        axis: Axis::B,
        length: 0.5,
    })
    .unwrap();
    s.solve().unwrap();
    let start = s.point(PointRef::Start(e)).unwrap();
    let end = s.point(PointRef::End(e)).unwrap();
    assert!((start - Point2::new(1.0, 0.5 * h)).norm() < 1e-9, "{start}");
    assert!((end - Point2::new(1.0, -0.5 * h)).norm() < 1e-9, "{end}");
}

/// A point held on the ellipse could fall in the removed piece: refused, nothing changed.
#[test]
fn a_point_on_the_ellipse_blocks_its_trim() {
    let mut s = Sketch::new();
    let shape = camber_geom::Ellipse::try_new(Point2::new(1.0, 1.0), 2.0, 1.0, 0.4).unwrap();
    let e = s.add_entity(Entity::ellipse(&shape)).unwrap();
    let line = s
        .add_line(Point2::new(1.0, -3.0), Point2::new(1.5, 4.0))
        .unwrap();
    let q = s.add_point(shape.point_at_angle(2.0)).unwrap();
    let on = s
        .add_constraint(PointOnEllipse {
            point: PointRef::Point(q),
            ellipse: e,
        })
        .unwrap();
    let file = camber_sketch::file::to_json(&s).unwrap();
    assert_eq!(
        s.trim_closed(e, &[line], Point2::new(3.0, 1.0)),
        Err(Error::EntityConstrained {
            entity: e,
            constraint: on,
            operation: "trim"
        })
    );
    assert_eq!(camber_sketch::file::to_json(&s).unwrap(), file);
    s.remove_constraint(on).unwrap();
    assert!(s.trim_closed(e, &[line], Point2::new(3.0, 1.0)).is_ok());
}

/// The crossings of the circle (c, r) with the segment a + t·(b − a), t ∈ [0, 1], as angles
/// about c, from the quadratic |a + t·d − c|² = r²; `None` when the line is within 1e-6 of
/// tangent (the count is then a matter of rounding).
fn segment_crossings(c: Point2<f64>, r: f64, a: Point2<f64>, b: Point2<f64>) -> Option<Vec<f64>> {
    let d = b - a;
    let f = a - c;
    let (qa, qb, qc) = (d.dot(&d), 2.0 * f.dot(&d), f.dot(&f) - r * r);
    let disc = qb * qb - 4.0 * qa * qc;
    if disc.abs() < 1e-6 * qb * qb.max(1.0) {
        return None;
    }
    if disc < 0.0 {
        return Some(Vec::new());
    }
    let mut out = Vec::new();
    for t in [
        (-qb - disc.sqrt()) / (2.0 * qa),
        (-qb + disc.sqrt()) / (2.0 * qa),
    ] {
        if (0.0..=1.0).contains(&t) {
            let p = a + d * t - c;
            out.push(p.y.atan2(p.x));
        }
    }
    Some(out)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Random circles and ellipses cut by up to three long lines: the kept arc starts and ends
    /// on crossings found by the quadratic formula (in the frame where the entity is the unit
    /// circle, where angles are parametric angles), every crossing lies on it, the point's
    /// direction does not; with fewer than two crossings the trim is refused and the sketch
    /// unchanged.
    #[test]
    fn a_trimmed_closed_entity_keeps_every_crossing_and_drops_the_point(
        cx in -2.0..2.0f64, cy in -2.0..2.0f64, r in 0.2..3.0f64,
        ellipse in prop::option::of((0.3..3.0f64, -3.0..3.0f64)),
        lines in prop::collection::vec((-3.0..3.0f64, -3.0..3.0f64, 0.0..PI), 1..4),
        pick in 0.0..(2.0 * PI),
    ) {
        let centre = Point2::new(cx, cy);
        let (b, rot) = ellipse.map_or((r, 0.0), |(k, rot)| (r * k, rot));
        let (cos, sin) = (rot.cos(), rot.sin());
        // The frame where the entity is the unit circle.
        let to_unit = |p: Point2<f64>| {
            let d = p - centre;
            Point2::new((cos * d.x + sin * d.y) / r, (-sin * d.x + cos * d.y) / b)
        };
        let from_unit = |t: f64| {
            let (x, y) = (r * t.cos(), b * t.sin());
            centre + Vector2::new(cos * x - sin * y, sin * x + cos * y)
        };
        let mut s = Sketch::new();
        let c = match ellipse {
            None => s.add_circle(centre, r).unwrap(),
            Some(_) => {
                let shape = camber_geom::Ellipse::try_new(centre, r, b, rot).unwrap();
                s.add_entity(Entity::ellipse(&shape)).unwrap()
            }
        };
        let mut at = Vec::new();
        let mut angles = Vec::new();
        for (px, py, th) in lines {
            let dir = Vector2::new(th.cos(), th.sin()) * 10.0;
            let (a, e) = (Point2::new(px, py) - dir, Point2::new(px, py) + dir);
            let Some(x) = segment_crossings(Point2::origin(), 1.0, to_unit(a), to_unit(e)) else {
                return Ok(());
            };
            angles.extend(x);
            at.push(s.add_line(a, e).unwrap());
        }
        let near = from_unit(pick) + (from_unit(pick) - centre);
        let file = camber_sketch::file::to_json(&s).unwrap();
        match s.trim_closed(c, &at, near) {
            Err(e) => {
                prop_assert!(angles.len() < 2, "{e} with {} crossings", angles.len());
                prop_assert_eq!(e, Error::TooFewCrossings { entity: c, count: angles.len() });
                prop_assert_eq!(camber_sketch::file::to_json(&s).unwrap(), file);
            }
            Ok(trim) => {
                prop_assert!(angles.len() >= 2);
                let (k, a, e) = match s.entity(c).unwrap().clone() {
                    Entity::Arc([k, a, e]) => (k, a, e),
                    Entity::EllipticArc { points: [k, _, a, e], .. } => (k, a, e),
                    other => panic!("not an arc: {other:?}"),
                };
                prop_assert!((k - centre).norm() < 1e-12);
                let (ua, ue) = (to_unit(a), to_unit(e));
                prop_assert!((ua.coords.norm() - 1.0).abs() < 1e-9 && (ue.coords.norm() - 1.0).abs() < 1e-9);
                prop_assert_eq!((a, e), (trim.start, trim.end));
                let start = ua.y.atan2(ua.x);
                let sweep = (ue.y.atan2(ue.x) - start).rem_euclid(2.0 * PI);
                let along = |t: f64| (t - start).rem_euclid(2.0 * PI);
                let eps = 1e-8;
                for t in &angles {
                    let u = along(*t);
                    prop_assert!(u <= sweep + eps || u >= 2.0 * PI - eps, "crossing {t} off the arc");
                }
                prop_assert!(along(pick) >= sweep - eps, "the point's direction is kept");
                prop_assert!(angles.iter().any(|t| (along(*t)).min(2.0 * PI - along(*t)) < eps));
            }
        }
    }
}

/// Crossings found twice (a cutter listed twice) count once, and many cutters are handled in
/// one sort: 500 lines through the centre cut the unit circle at 1,000 angles, the removed
/// piece is the one between the two crossings around the point.
#[test]
fn repeated_and_many_crossings_count_once_each() {
    let mut s = Sketch::new();
    let c = s.add_circle(Point2::origin(), 1.0).unwrap();
    let once = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(3.0, 0.0))
        .unwrap();
    assert_eq!(
        s.trim_closed(c, &[once, once], Point2::new(0.0, 1.0)),
        Err(Error::TooFewCrossings {
            entity: c,
            count: 1
        })
    );
    let n = 500;
    let lines: Vec<_> = (0..n)
        .map(|k| {
            let t = PI * (f64::from(k) + 0.5) / f64::from(n);
            let d = Vector2::new(t.cos(), t.sin()) * 2.0;
            s.add_line(Point2::origin() - d, Point2::origin() + d)
                .unwrap()
        })
        .collect();
    let mut at = lines.clone();
    at.extend(&lines);
    let trim = s.trim_closed(c, &at, Point2::new(1.0, 0.0)).unwrap();
    // The crossings nearest angle 0 lie half a step either side of it.
    let half = 0.5 * PI / f64::from(n);
    assert!(
        (trim.start - at_angle(half.to_degrees())).norm() < 1e-9,
        "{trim:?}"
    );
    assert!(
        (trim.end - at_angle(-half.to_degrees())).norm() < 1e-9,
        "{trim:?}"
    );
}
