//! Circular arcs in sketches: their 5 DOF, their ends read by the classic point kinds, the arc
//! kinds (point on arc, radius, equal radius, concentric, tangency to a line at an end) solved
//! against closed forms, and every arc residual's autodiff Jacobian against central
//! differences.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use std::f64::consts::{FRAC_PI_2, PI};

use approx::assert_relative_eq;
use camber_geom::CircularArc;
use camber_sketch::constraints::arc_tangent_to_line::{ArcEnd, ArcLineTangency};
use camber_sketch::constraints::equal_radius::RoundRadiiEqual;
use camber_sketch::constraints::point_on_arc::OnArc;
use camber_sketch::constraints::radius::ArcRadiusValue;
use camber_sketch::constraints::{
    ArcTangentToLine, Coincident, Concentric, Distance, EqualRadius, Fixed, PointOnArc,
    PointOnLine, Radius,
};
use camber_sketch::residuals::arc::ArcEnds;
use camber_sketch::{Entity, EntityId, Error, PointRef, Sense, Sketch};
use camber_solve::testing::check_jacobian;
use nalgebra::{Point2, Vector2};
use proptest::prelude::*;

fn arc(s: &mut Sketch, c: (f64, f64), r: f64, a0: f64, a1: f64) -> EntityId {
    s.add_arc(&CircularArc::try_new(Point2::new(c.0, c.1), r, a0, a1).unwrap())
        .unwrap()
}

fn dof(s: &Sketch) -> usize {
    s.analyze().unwrap().iter().map(|a| a.analysis.dof).sum()
}

/// The solved arc of an entity.
fn solved(s: &Sketch, a: EntityId) -> CircularArc<f64> {
    s.entity(a).unwrap().as_arc().unwrap()
}

/// |E − C| − |S − C| of a solved arc (its own row).
fn end_gap(s: &Sketch, a: EntityId) -> f64 {
    let Entity::Arc([c, p, e]) = s.entity(a).unwrap() else {
        panic!("not an arc")
    };
    (e - c).norm() - (p - c).norm()
}

#[test]
fn a_free_arc_has_five_dof_and_fixing_its_centre_and_radius_leaves_two() {
    let mut s = Sketch::new();
    let a = arc(&mut s, (0.0, 0.0), 2.0, 0.3, 2.0);
    assert_eq!(dof(&s), 5);
    s.add_constraint(Fixed::point(PointRef::Control(a, 0)))
        .unwrap();
    assert_eq!(dof(&s), 3);
    s.add_constraint(Radius {
        circle: a,
        radius: 2.0,
    })
    .unwrap();
    // Start and end angle.
    assert_eq!(dof(&s), 2);
    let report = s.analyze().unwrap();
    let free = &report[0].freedom;
    assert_eq!(free.len(), 1);
    assert_eq!(free[0].points, vec![1, 2]);
}

#[test]
fn a_fixed_arc_is_fully_determined_and_a_line_joins_its_end() {
    let mut s = Sketch::new();
    let a = arc(&mut s, (1.0, 1.0), 1.5, 0.0, FRAC_PI_2);
    let l = s
        .add_line(Point2::new(3.0, 3.0), Point2::new(5.0, 4.0))
        .unwrap();
    s.add_constraint(Fixed::entity(a)).unwrap();
    s.add_constraint(Coincident {
        a: PointRef::End(a),
        b: PointRef::Start(l),
    })
    .unwrap();
    s.solve().unwrap();
    assert_relative_eq!(
        s.point(PointRef::Start(l)).unwrap(),
        Point2::new(1.0, 2.5),
        epsilon = 1e-12
    );
    // The line's far end is all that is free.
    assert_eq!(dof(&s), 2);
}

/// The classic kinds read arc ends: a distance between the two ends of an arc of fixed centre
/// and radius is a chord, 2r·sin(φ/2).
#[test]
fn a_chord_between_the_arc_ends_sets_the_sweep() {
    let mut s = Sketch::new();
    let a = arc(&mut s, (0.0, 0.0), 2.0, 0.1, 1.0);
    s.add_constraint(Fixed::point(PointRef::Control(a, 0)))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(a))).unwrap();
    s.add_constraint(Distance {
        a: PointRef::Start(a),
        b: PointRef::End(a),
        distance: 2.0,
    })
    .unwrap();
    s.solve().unwrap();
    let arc = solved(&s, a);
    // 2·2·sin(φ/2) = 2: φ = π/3.
    assert_relative_eq!(arc.sweep(), PI / 3.0, epsilon = 1e-9);
    assert_relative_eq!(arc.radius(), 2.0, epsilon = 1e-12);
    assert!(end_gap(&s, a).abs() < 1e-10);
}

/// An arc of radius R tangent at its start to a fixed line, its start on that line: the centre
/// ends R from the line and the start is the foot of the perpendicular from the centre.
#[test]
fn the_tangent_point_of_an_arc_and_a_line_is_the_foot_of_the_centre() {
    let mut s = Sketch::new();
    let (p, q) = (Point2::new(-1.0, 0.5), Point2::new(4.0, 2.0));
    let l = s.add_line(p, q).unwrap();
    s.add_constraint(Fixed::entity(l)).unwrap();
    let a = arc(&mut s, (1.0, 2.0), 1.0, -1.2, 0.9);
    s.add_constraint(Radius {
        circle: a,
        radius: 1.25,
    })
    .unwrap();
    s.add_constraint(PointOnLine {
        point: PointRef::Start(a),
        line: l,
    })
    .unwrap();
    s.add_constraint(ArcTangentToLine {
        arc: a,
        end: ArcEnd::Start,
        line: l,
        sense: Sense::Agree,
    })
    .unwrap();
    let report = s.solve().unwrap();
    assert!(report
        .components
        .iter()
        .flat_map(|c| &c.report.residuals)
        .all(|r| r.max_abs < 1e-10));
    let arc = solved(&s, a);
    let d = (q - p).normalize();
    let c = arc.center();
    let distance = (d.x * (c.y - p.y) - d.y * (c.x - p.x)).abs();
    assert_relative_eq!(distance, 1.25, epsilon = 1e-10);
    let foot = p + d * (c - p).dot(&d);
    assert_relative_eq!(arc.start_point(), foot, epsilon = 1e-10);
    // The sense is kept: the counter-clockwise travel at the start runs along q − p.
    let r = arc.start_point() - c;
    assert!(Vector2::new(-r.y, r.x).dot(&(q - p)) > 0.0);
    assert!(end_gap(&s, a).abs() < 1e-10);
}

/// A fillet drawn by hand: a vertical line coming down the y axis, an arc of radius R, a
/// horizontal line leaving along the x axis, joined G1 at both arc ends. The closed form: the
/// centre is (R, R) from the corner, the ends are its feet on both lines; nothing is left free.
fn hand_fillet(sense_at_end: Sense) -> (Sketch, EntityId) {
    let mut s = Sketch::new();
    let v = s
        .add_line(Point2::new(0.0, 3.0), Point2::new(0.0, 0.3))
        .unwrap();
    let h = s
        .add_line(Point2::new(0.2, 0.0), Point2::new(3.0, 0.0))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(v))).unwrap();
    s.add_constraint(Fixed::point(PointRef::End(h))).unwrap();
    s.add_constraint(camber_sketch::constraints::Vertical::line(v))
        .unwrap();
    s.add_constraint(camber_sketch::constraints::Horizontal::line(h))
        .unwrap();
    // Counter-clockwise from the vertical line's foot (angle π) to the horizontal one's (−π/2).
    let a = arc(&mut s, (0.6, 0.6), 0.5, PI - 0.1, -FRAC_PI_2 + 0.2);
    s.add_constraint(Radius {
        circle: a,
        radius: 0.5,
    })
    .unwrap();
    s.add_constraint(Coincident {
        a: PointRef::End(v),
        b: PointRef::Start(a),
    })
    .unwrap();
    s.add_constraint(Coincident {
        a: PointRef::End(a),
        b: PointRef::Start(h),
    })
    .unwrap();
    // The arc's travel runs down the vertical line at its start and along +x at its end.
    for (line, end, sense) in [
        (v, ArcEnd::Start, Sense::Agree),
        (h, ArcEnd::End, sense_at_end),
    ] {
        s.add_constraint(ArcTangentToLine {
            arc: a,
            end,
            line,
            sense,
        })
        .unwrap();
    }
    (s, a)
}

#[test]
fn a_hand_drawn_fillet_meets_the_closed_form() {
    let (mut s, a) = hand_fillet(Sense::Agree);
    assert_eq!(dof(&s), 0);
    s.solve().unwrap();
    let arc = solved(&s, a);
    assert_relative_eq!(*arc.center(), Point2::new(0.5, 0.5), epsilon = 1e-10);
    assert_relative_eq!(arc.start_point(), Point2::new(0.0, 0.5), epsilon = 1e-10);
    assert_relative_eq!(arc.end_point(), Point2::new(0.5, 0.0), epsilon = 1e-10);
    assert_relative_eq!(arc.sweep(), FRAC_PI_2, epsilon = 1e-9);
    assert!(end_gap(&s, a).abs() < 1e-10);
}

/// The same fillet asking the arc to run against the horizontal line at its end: the only
/// nearby solution runs along it, so the solve fails naming the tangency and changes nothing.
#[test]
fn a_tangency_whose_sense_cannot_be_kept_fails_and_changes_nothing() {
    let (mut s, a) = hand_fillet(Sense::Oppose);
    let before = s.entity(a).unwrap().clone();
    let err = s.solve().unwrap_err();
    assert!(matches!(err, Error::OrientationFlipped { .. }), "{err}");
    assert_eq!(s.entity(a).unwrap(), &before);
}

#[test]
fn point_on_arc_lands_on_the_arc_and_refuses_a_point_pushed_past_its_end() {
    let mut s = Sketch::new();
    let a = arc(&mut s, (0.0, 0.0), 2.0, 0.0, FRAC_PI_2);
    s.add_constraint(Fixed::entity(a)).unwrap();
    let p = s.add_point(Point2::new(1.8, 1.9)).unwrap();
    s.add_constraint(PointOnArc {
        point: PointRef::Point(p),
        arc: a,
    })
    .unwrap();
    s.solve().unwrap();
    let q = s.point(PointRef::Point(p)).unwrap();
    assert_relative_eq!(q.coords.norm(), 2.0, epsilon = 1e-10);
    // The minimum-norm move is radial: the direction is kept.
    assert_relative_eq!(q.y.atan2(q.x), 1.9f64.atan2(1.8), epsilon = 1e-9);

    // Pinning the point below the x axis puts it on the circle outside the arc.
    let mut t = Sketch::new();
    let a = arc(&mut t, (0.0, 0.0), 2.0, 0.0, FRAC_PI_2);
    t.add_constraint(Fixed::entity(a)).unwrap();
    let p = t.add_point(Point2::new(1.0, -1.0)).unwrap();
    t.add_constraint(PointOnArc {
        point: PointRef::Point(p),
        arc: a,
    })
    .unwrap();
    let before = t.clone();
    let err = t.solve().unwrap_err();
    assert!(matches!(err, Error::PointOffArc { .. }), "{err}");
    assert_eq!(
        t.point(PointRef::Point(p)).unwrap(),
        before.point(PointRef::Point(p)).unwrap()
    );
}

#[test]
fn equal_radius_and_concentric_tie_arcs_and_circles() {
    let mut s = Sketch::new();
    let a = arc(&mut s, (0.0, 0.0), 1.0, 0.0, 2.0);
    let b = arc(&mut s, (0.4, -0.2), 1.7, 1.0, 4.0);
    let k = s.add_circle(Point2::new(-0.3, 0.1), 2.5).unwrap();
    s.add_constraint(Fixed::entity(a)).unwrap();
    s.add_constraint(Concentric {
        first: a,
        second: b,
    })
    .unwrap();
    s.add_constraint(Concentric {
        first: k,
        second: b,
    })
    .unwrap();
    s.add_constraint(EqualRadius {
        first: b,
        second: k,
    })
    .unwrap();
    s.add_constraint(Radius {
        circle: k,
        radius: 3.0,
    })
    .unwrap();
    s.solve().unwrap();
    let b_arc = solved(&s, b);
    assert_relative_eq!(b_arc.radius(), 3.0, epsilon = 1e-10);
    assert_relative_eq!(*b_arc.center(), Point2::origin(), epsilon = 1e-10);
    let Entity::Circle { center, radius } = s.entity(k).unwrap() else {
        panic!()
    };
    assert_relative_eq!(*center, Point2::origin(), epsilon = 1e-10);
    assert_relative_eq!(*radius, 3.0, epsilon = 1e-10);
    assert!(end_gap(&s, b).abs() < 1e-10);

    // Arc to arc.
    let mut t = Sketch::new();
    let a = arc(&mut t, (0.0, 0.0), 1.0, 0.0, 2.0);
    let b = arc(&mut t, (3.0, 0.0), 2.0, 0.5, 1.5);
    t.add_constraint(Fixed::entity(a)).unwrap();
    t.add_constraint(EqualRadius {
        first: a,
        second: b,
    })
    .unwrap();
    t.solve().unwrap();
    assert_relative_eq!(solved(&t, b).radius(), 1.0, epsilon = 1e-10);
    assert!(end_gap(&t, b).abs() < 1e-10);
}

#[test]
fn arc_kinds_refuse_entities_of_the_wrong_kind() {
    let mut s = Sketch::new();
    let k = s.add_circle(Point2::origin(), 1.0).unwrap();
    let l = s.add_line(Point2::origin(), Point2::new(1.0, 0.0)).unwrap();
    let p = s.add_point(Point2::new(1.0, 1.0)).unwrap();
    assert!(matches!(
        s.add_constraint(PointOnArc {
            point: PointRef::Point(p),
            arc: k
        }),
        Err(Error::WrongEntityKind {
            expected: "arc",
            ..
        })
    ));
    assert!(matches!(
        s.add_constraint(Radius {
            circle: l,
            radius: 1.0
        }),
        Err(Error::WrongEntityKind {
            expected: "circle or arc",
            ..
        })
    ));
    let a = arc(&mut s, (0.0, 0.0), 1.0, 0.0, 1.0);
    assert!(matches!(
        s.add_constraint(Radius {
            circle: a,
            radius: -1.0
        }),
        Err(Error::NotPositive { .. })
    ));
    assert!(matches!(
        s.add_constraint(ArcTangentToLine {
            arc: a,
            end: ArcEnd::End,
            line: k,
            sense: Sense::Agree
        }),
        Err(Error::WrongEntityKind {
            expected: "line",
            ..
        })
    ));
}

#[test]
fn degenerate_arcs_are_refused_naming_the_entity_and_value() {
    let mut s = Sketch::new();
    let c = Point2::new(1.0, 1.0);
    assert_eq!(
        s.add_entity(Entity::Arc([c, c, Point2::new(2.0, 1.0)])),
        Err(Error::InvalidArc {
            entity: EntityId(0),
            reason: camber_geom::Error::NonPositiveRadius { value: 0.0 }
        })
    );
    assert!(matches!(
        s.add_entity(Entity::Arc([c, Point2::new(f64::NAN, 0.0), c])),
        Err(Error::NonFinite { .. })
    ));
    assert_eq!(s.entities().count(), 0);
}

/// Dragging an arc's start with the centre fixed: the radius follows the cursor and the end
/// stays on the new circle (the arc's own row), at its old angle (minimum norm).
#[test]
fn dragging_an_arc_start_carries_its_end_to_the_new_circle() {
    let mut s = Sketch::new();
    let a = arc(&mut s, (0.0, 0.0), 1.0, 0.0, FRAC_PI_2);
    s.add_constraint(Fixed::point(PointRef::Control(a, 0)))
        .unwrap();
    let mut drag = s.drag(PointRef::Start(a)).unwrap();
    drag.update(Point2::new(1.5, 0.0)).unwrap();
    drag.finish(&mut s).unwrap();
    let arc = solved(&s, a);
    assert_relative_eq!(arc.radius(), 1.5, epsilon = 1e-9);
    assert!(end_gap(&s, a).abs() < 1e-9);
    assert_relative_eq!(arc.end_angle(), FRAC_PI_2, epsilon = 1e-6);
}

fn check<R: camber_solve::Residual>(r: &R, blocks: &[Vec<f64>]) -> f64 {
    let refs: Vec<&[f64]> = blocks.iter().map(|b| &b[..]).collect();
    check_jacobian(r, &refs, 1e-6, 1.0).unwrap().error
}

fn xy() -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-5.0..5.0f64, 2)
}

/// Blocks at least 0.1 apart from `from` (every arc residual divides by a radius or length).
fn away(from: &[f64], p: &[f64]) -> bool {
    (p[0] - from[0]).hypot(p[1] - from[1]) > 0.1
}

proptest! {
    #[test]
    fn arc_residual_jacobians_match_central_differences(
        c in xy(), s in xy(), e in xy(), p in xy(), a in xy(), b in xy(),
        r1 in 0.2..4.0f64, big in 0.2..4.0f64,
    ) {
        prop_assume!(away(&c, &s) && away(&c, &e) && away(&c, &p) && away(&a, &b));
        prop_assert!(check(&ArcEnds, &[c.clone(), s.clone(), e.clone()]) < 1e-6);
        prop_assert!(check(&ArcRadiusValue(big), &[c.clone(), s.clone()]) < 1e-6);
        prop_assert!(check(&OnArc, &[p.clone(), c.clone(), s.clone()]) < 1e-6);
        prop_assert!(check(&ArcLineTangency, &[c.clone(), s.clone(), a.clone(), b.clone()]) < 1e-6);
        let both = RoundRadiiEqual { first_arc: true, second_arc: true };
        prop_assert!(check(&both, &[c.clone(), s.clone(), p.clone(), c.clone()]) < 1e-6);
        let first = RoundRadiiEqual { first_arc: true, second_arc: false };
        prop_assert!(check(&first, &[c.clone(), s.clone(), vec![r1]]) < 1e-6);
        let second = RoundRadiiEqual { first_arc: false, second_arc: true };
        prop_assert!(check(&second, &[vec![r1], c.clone(), e.clone()]) < 1e-6);
    }
}

/// An arc of sweep 0.3 whose end is pinned 0.3 rad before its start: the rows hold with the
/// sweep 2π − 0.3, the complement of the arc, so the solve refuses and changes nothing; pinned
/// 0.6 rad after its start instead, it solves.
#[test]
fn a_solve_that_would_turn_an_arc_inside_out_is_refused() {
    let pinned = |angle: f64| {
        let mut s = Sketch::new();
        let a = arc(&mut s, (0.0, 0.0), 1.0, 0.0, 0.3);
        s.add_constraint(Fixed::point(PointRef::Control(a, 0)))
            .unwrap();
        s.add_constraint(Fixed::point(PointRef::Start(a))).unwrap();
        let p = s.add_point(Point2::new(angle.cos(), angle.sin())).unwrap();
        s.add_constraint(Fixed::entity(p)).unwrap();
        s.add_constraint(Coincident {
            a: PointRef::End(a),
            b: PointRef::Point(p),
        })
        .unwrap();
        (s, a)
    };
    let (mut s, a) = pinned(-0.3);
    let before = s.entity(a).unwrap().clone();
    let err = s.solve().unwrap_err();
    assert!(
        matches!(err, Error::ArcTurnedInsideOut { entity, .. } if entity == a),
        "{err}"
    );
    assert_eq!(s.entity(a).unwrap(), &before);
    let (mut s, a) = pinned(0.6);
    s.solve().unwrap();
    assert_relative_eq!(solved(&s, a).sweep(), 0.6, epsilon = 1e-10);
}

/// Each W5r rectangle (4 lines, 4 fillet arcs, W5's dimensions on the trimmed lines) counts 36
/// unknowns' worth of freedom against 36 rows: the analysis must find every rectangle fully
/// determined with no row redundant or conflicting, so a fillet adds no hidden freedom and
/// hides no dependent row.
#[test]
fn filleted_rectangles_are_fully_constrained_with_nothing_redundant() {
    let (mut s, _) = camber_workloads::w5r(3).unwrap();
    s.solve().unwrap();
    let analyses = s.analyze().unwrap();
    assert_eq!(analyses.len(), 3);
    for a in &analyses {
        assert_eq!(a.analysis.dof, 0, "{:?}", a.analysis);
        assert!(a.analysis.redundant.is_empty(), "{:?}", a.analysis);
        assert!(a.analysis.partly_redundant.is_empty(), "{:?}", a.analysis);
        assert!(a.analysis.conflicting.is_empty(), "{:?}", a.analysis);
        assert!(a.freedom.is_empty(), "{:?}", a.freedom);
    }
}
