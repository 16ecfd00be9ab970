//! The cases a new user met where the analysis or the solve said something untrue,
//! or a drag refused what could move. Each is checked against the right answer.

#![allow(clippy::unwrap_used)] // fixture helpers unwrap like the tests do

use camber_geom::BezierCurve2;
use camber_sketch::constraints::{Fixed, TangentToCircle, TangentToLine};
use camber_sketch::{
    CircleSide, Constraint, Contact, Entity, EntityId, LineSide, PointRef, Rotation, Sense, Sketch,
};
use nalgebra::Point2;

/// Case 4: a cubic with fixed ends, touching a fixed circle from outside (counter-clockwise)
/// and a fixed line on its left, both at free parameters guessed at ½ (an impossible start:
/// one parameter for two contacts).
fn case_4(u_circle: f64, u_line: f64) -> (Sketch, EntityId, [camber_sketch::ConstraintId; 2]) {
    let mut s = Sketch::new();
    let c = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(-3.0, 0.0),
                Point2::new(-1.0, 1.0),
                Point2::new(1.0, 0.6),
                Point2::new(3.0, 0.0),
            ])
            .unwrap(),
        )
        .unwrap();
    let circle = s.add_circle(Point2::new(0.3, 2.2), 1.0).unwrap();
    let line = s
        .add_line(Point2::new(-3.0, -0.8), Point2::new(3.0, -0.5))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(c))).unwrap();
    s.add_constraint(Fixed::point(PointRef::End(c))).unwrap();
    s.add_constraint(Fixed::entity(circle)).unwrap();
    s.add_constraint(Fixed::entity(line)).unwrap();
    let a = s
        .add_constraint(TangentToCircle {
            curve: c,
            circle,
            u: Contact::Free(u_circle),
            side: CircleSide::Outside,
            rotation: Rotation::CounterClockwise,
        })
        .unwrap();
    let b = s
        .add_constraint(TangentToLine {
            curve: c,
            line,
            u: Contact::Free(u_line),
            side: LineSide::Left,
            sense: Sense::Agree,
        })
        .unwrap();
    (s, c, [a, b])
}

/// The solved contact parameters of case 4's two contacts.
fn contacts(s: &Sketch, ids: [camber_sketch::ConstraintId; 2]) -> [f64; 2] {
    ids.map(|id| match s.constraint(id).unwrap() {
        Constraint::TangentToCircle(t) => t.u.value(),
        Constraint::TangentToLine(t) => t.u.value(),
        other => panic!("{other:?}"),
    })
}

#[test]
fn solves_from_a_start_the_user_could_not_guess() {
    let (mut given, c, ids) = case_4(0.5, 0.5);
    let report = given.solve().unwrap();
    assert!(
        report.components[0]
            .report
            .reason
            .to_string()
            .contains("contact start"),
        "{}",
        report.components[0].report.reason
    );
    // The good guesses solve directly (to a slightly different member of the 2-DOF family: the
    // minimum-norm metric counts the contact parameters' moves too).
    let (mut reference, _, _) = case_4(0.3, 0.8);
    reference.solve().unwrap();
    let [u, v] = contacts(&given, ids);
    assert!(u < v, "the circle is touched before the line: {u} {v}");
    // The contacts hold where they are recorded.
    let Entity::Bezier(curve) = given.entity(c).unwrap() else {
        unreachable!()
    };
    let p = camber_geom::ParametricCurve::point(curve, u).unwrap();
    assert!(((p - Point2::new(0.3, 2.2)).norm() - 1.0).abs() < 1e-9);
    // On the line y = −0.8 + 0.05·(x + 3), tangent to it, from above.
    let (q, t) = camber_geom::ParametricCurve::point_and_derivative(curve, v).unwrap();
    assert!((q.y - (-0.8 + 0.05 * (q.x + 3.0))).abs() < 1e-9);
    assert!((t.y - 0.05 * t.x).abs() < 1e-9 * t.norm() && t.x > 0.0);
    // Honest: the curve stays on or above the line and outside the circle everywhere.
    for i in 0..=2000 {
        let r = camber_geom::ParametricCurve::point(curve, f64::from(i) / 2000.0).unwrap();
        assert!(r.y >= -0.8 + 0.05 * (r.x + 3.0) - 1e-7);
        assert!((r - Point2::new(0.3, 2.2)).norm() >= 1.0 - 1e-7);
    }
}

/// Case 6a: with P₀ fixed and the start tangent along D, P₁ can still slide along the ray
/// P₀ + t·D; dragged off the ray, it goes to the target's projection onto it.
#[test]
fn a_partly_determined_point_slides_along_its_freedom() {
    use camber_sketch::constraints::StartTangent;
    use camber_sketch::drag::Freedom;
    use camber_sketch::TangentForm;
    for form in [TangentForm::Row, TangentForm::Elimination] {
        let mut s = Sketch::new();
        let c = s
            .add_bezier(
                BezierCurve2::try_new(vec![
                    Point2::new(0.0, 0.0),
                    Point2::new(1.0, 1.0),
                    Point2::new(2.0, 1.0),
                    Point2::new(3.0, 0.0),
                ])
                .unwrap(),
            )
            .unwrap();
        s.add_constraint(Fixed::point(PointRef::Control(c, 0)))
            .unwrap();
        let d = nalgebra::Vector2::new(1.0, 1.0) / 2f64.sqrt();
        s.add_constraint(StartTangent {
            curve: c,
            direction: d,
            sense: Sense::Agree,
            form,
        })
        .unwrap();
        s.solve().unwrap();
        let mut drag = s.drag(PointRef::Control(c, 1)).unwrap();
        match drag.freedom() {
            Freedom::Along(u) => assert!((u.x * d.y - u.y * d.x).abs() < 1e-9, "{u}"),
            other => panic!("{form:?}: {other:?}"),
        }
        let target = Point2::new(2.0, 0.5);
        drag.update(target).unwrap();
        // The projection of (2, 0.5) onto the ray y = x: (1.25, 1.25).
        let p1 = drag.point(PointRef::Control(c, 1)).unwrap();
        assert!(
            (p1 - Point2::new(1.25, 1.25)).norm() < 1e-9,
            "{form:?}: {p1}"
        );
        assert_eq!(
            drag.point(PointRef::Control(c, 0)).unwrap(),
            Point2::origin()
        );
    }
}

/// Case 6b: a fully constrained square (0 DOF) is dragged: a calm no-op that says so, not
/// "conflicting constraints".
#[test]
fn dragging_a_determined_point_is_a_calm_no_op() {
    use camber_sketch::constraints::{Coincident, Distance, Horizontal, Vertical};
    use camber_sketch::drag::Freedom;
    let mut s = Sketch::new();
    let corners = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
    let lines: Vec<EntityId> = (0..4)
        .map(|k| {
            let (a, b) = (corners[k], corners[(k + 1) % 4]);
            s.add_line(Point2::new(a.0, a.1), Point2::new(b.0, b.1))
                .unwrap()
        })
        .collect();
    for k in 0..4 {
        s.add_constraint(Coincident {
            a: PointRef::End(lines[k]),
            b: PointRef::Start(lines[(k + 1) % 4]),
        })
        .unwrap();
    }
    s.add_constraint(Horizontal::line(lines[0])).unwrap();
    s.add_constraint(Horizontal::line(lines[2])).unwrap();
    s.add_constraint(Vertical::line(lines[1])).unwrap();
    s.add_constraint(Vertical::line(lines[3])).unwrap();
    for l in [lines[0], lines[3]] {
        s.add_constraint(Distance {
            a: PointRef::Start(l),
            b: PointRef::End(l),
            distance: 1.0,
        })
        .unwrap();
    }
    s.add_constraint(Fixed::point(PointRef::Start(lines[0])))
        .unwrap();
    s.solve().unwrap();
    let corner = PointRef::Start(lines[2]);
    let at = s.point(corner).unwrap();
    let mut drag = s.drag(corner).unwrap();
    assert_eq!(drag.freedom(), Freedom::Determined);
    drag.update(at + nalgebra::Vector2::new(0.5, 0.5)).unwrap();
    assert_eq!(drag.point(corner).unwrap(), at);
    drag.finish(&mut s).unwrap();
    assert_eq!(s.point(corner).unwrap(), at);
}

/// Case 6c: a drag session reports every unknown: circle radii and free contact parameters,
/// not only points.
#[test]
fn a_drag_reports_radii_and_contact_parameters() {
    let (s, c, ids) = case_4(0.3, 0.8);
    let mut s = s;
    s.solve().unwrap();
    let mut drag = s.drag(PointRef::Control(c, 1)).unwrap();
    let p = s.point(PointRef::Control(c, 1)).unwrap();
    drag.update(p + nalgebra::Vector2::new(0.02, 0.0)).unwrap();
    let entities = drag.entities().unwrap();
    assert!(entities
        .iter()
        .any(|(_, e)| matches!(e, Entity::Circle { radius, .. } if (*radius - 1.0).abs() < 1e-12)));
    let free = drag.free_parameters().unwrap();
    for id in ids {
        assert!(
            free.iter()
                .any(|(c, k, u)| *c == id && *k == 0 && u.is_finite()),
            "{free:?}"
        );
    }
}

/// Case 6d: a nonlinear drag keeps the touch-never-cross active set: on the diffuser, moving
/// the control points next to the thickness contact down toward the circle never leaves a
/// crossing curve, and every accepted step is valid.
#[test]
fn nonlinear_drags_keep_contacts_honest() {
    let (mut s, w) = camber_workloads::w2_bspline7().unwrap();
    s.solve().unwrap();
    for k in [2, 3, 4] {
        let r = PointRef::Control(w.curve, k);
        let p = s.point(r).unwrap();
        let mut drag = s.drag(r).unwrap();
        let mut accepted = 0;
        for step in 1..=10 {
            let target = p + nalgebra::Vector2::new(0.0, -0.004 * f64::from(step));
            if drag.update(target).is_ok() {
                accepted += 1;
                let mut t = s.clone();
                for (id, e) in drag.entities().unwrap() {
                    t.set_entity(id, e).unwrap();
                }
                assert!(
                    camber_workloads::w2_valid(&t, &w),
                    "control point {k} step {step}"
                );
            }
        }
        assert!(accepted > 0, "control point {k}: every step refused");
    }
}

/// Case 2: a coincidence between two fixed points (0, 0) and (1, 0). Its y row is consistent
/// and its x row is not: the constraint is conflicting, and only conflicting (deleting it would
/// change what the sketch asks for).
#[test]
fn a_constraint_is_never_both_redundant_and_conflicting() {
    let mut s = Sketch::new();
    let a = s.add_point(Point2::new(0.0, 0.0)).unwrap();
    let b = s.add_point(Point2::new(1.0, 0.0)).unwrap();
    s.add_constraint(Fixed::entity(a)).unwrap();
    s.add_constraint(Fixed::entity(b)).unwrap();
    let coincidence = s
        .add_constraint(camber_sketch::constraints::Coincident {
            a: PointRef::Point(a),
            b: PointRef::Point(b),
        })
        .unwrap();
    let analyses = s.analyze().unwrap();
    let conflicting: Vec<_> = analyses
        .iter()
        .flat_map(|c| c.analysis.conflicting.clone())
        .collect();
    let redundant: Vec<_> = analyses
        .iter()
        .flat_map(|c| c.analysis.redundant.clone())
        .collect();
    assert!(conflicting.contains(&coincidence), "{analyses:?}");
    assert!(
        conflicting.iter().all(|c| !redundant.contains(c)),
        "redundant {redundant:?}, conflicting {conflicting:?}"
    );
}

/// A chain of `n` points, the first fixed, each at distance 1 from the next (nonlinear rows):
/// 2n unknowns, 2 fixed, n − 1 rows, so n − 1 degrees of freedom and nothing dependent.
pub fn point_chain(n: usize) -> Sketch {
    let mut s = Sketch::new();
    let points: Vec<EntityId> = (0..n)
        .map(|i| {
            let t = i as f64;
            s.add_point(Point2::new(t, 0.1 * (t * 0.7).sin())).unwrap()
        })
        .collect();
    s.add_constraint(Fixed::entity(points[0])).unwrap();
    for pair in points.windows(2) {
        let d = (s.point(PointRef::Point(pair[1])).unwrap()
            - s.point(PointRef::Point(pair[0])).unwrap())
        .norm();
        s.add_constraint(camber_sketch::constraints::Distance {
            a: PointRef::Point(pair[0]),
            b: PointRef::Point(pair[1]),
            distance: d,
        })
        .unwrap();
    }
    s
}

/// Case 5: the analysis of a large component is sparse: a 100,000-point chain is analysed
/// (it aborted out of memory building a dense 10⁵ × 2·10⁵ matrix), with the right DOF.
#[test]
fn a_huge_chain_is_analysed_without_a_dense_matrix() {
    let n = 100_000;
    let s = point_chain(n);
    let analyses = s.analyze().unwrap();
    assert_eq!(analyses.len(), 1);
    let a = &analyses[0].analysis;
    assert_eq!((a.free_unknowns, a.rank, a.dof), (2 * n - 2, n - 1, n - 1));
    assert!(a.redundant.is_empty() && a.conflicting.is_empty());
}

fn cubic(s: &mut Sketch, points: [(f64, f64); 4]) -> EntityId {
    s.add_bezier(
        BezierCurve2::try_new(points.iter().map(|(x, y)| Point2::new(*x, *y)).collect()).unwrap(),
    )
    .unwrap()
}

/// Case 3: a constraint whose rows are only partly implied by the others is not redundant:
/// deleting it would change the sketch. A tangency at two curve ends that a coincidence already
/// joins repeats the coincidence in its position rows, but its direction row is its own.
#[test]
fn a_partly_redundant_constraint_is_not_called_redundant() {
    use camber_sketch::constraints::{Coincident, CurveCurveTangent};
    let mut s = Sketch::new();
    let a = cubic(&mut s, [(0.0, 0.0), (1.0, 1.0), (2.0, 1.0), (3.0, 0.0)]);
    let b = cubic(&mut s, [(3.0, 0.0), (4.0, 0.5), (5.0, 1.0), (6.0, 0.0)]);
    s.add_constraint(Fixed::entity(a)).unwrap();
    s.add_constraint(Coincident {
        a: PointRef::End(a),
        b: PointRef::Start(b),
    })
    .unwrap();
    let tangent = s
        .add_constraint(CurveCurveTangent {
            first: a,
            u: Contact::At(1.0),
            second: b,
            v: Contact::At(0.0),
            sense: Sense::Agree,
        })
        .unwrap();
    let analysis = &s.analyze().unwrap()[0].analysis;
    assert!(!analysis.redundant.contains(&tangent), "{analysis:?}");
    assert_eq!(analysis.partly_redundant, vec![tangent]);
    // B's free points (3 of them after the join: 6 unknowns) lose one to the direction row.
    assert_eq!(analysis.dof, 5);
    // Started with a kink, it solves to a tangent join: the direction row was needed.
    s.solve().unwrap();
    let end_a =
        s.point(PointRef::Control(a, 3)).unwrap() - s.point(PointRef::Control(a, 2)).unwrap();
    let start_b =
        s.point(PointRef::Control(b, 1)).unwrap() - s.point(PointRef::Control(b, 0)).unwrap();
    let cross = end_a.x * start_b.y - end_a.y * start_b.x;
    assert!(cross.abs() < 1e-9 * end_a.norm() * start_b.norm() && end_a.dot(&start_b) > 0.0);
}

/// Case 3 with a line: a curve end coincident with a line's end and tangent to the line there.
/// The tangency's on-the-line row repeats the coincidence; its direction row does not.
#[test]
fn tangent_to_a_line_at_a_joined_end_is_needed() {
    use camber_sketch::constraints::Coincident;
    let mut s = Sketch::new();
    let c = cubic(&mut s, [(0.0, 0.0), (1.0, 1.0), (2.0, 1.0), (3.0, 0.5)]);
    let line = s
        .add_line(Point2::new(3.0, 0.5), Point2::new(5.0, 0.5))
        .unwrap();
    s.add_constraint(Fixed::entity(line)).unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(c))).unwrap();
    let join = s
        .add_constraint(Coincident {
            a: PointRef::End(c),
            b: PointRef::Start(line),
        })
        .unwrap();
    let tangent = s
        .add_constraint(TangentToLine {
            curve: c,
            line,
            u: Contact::At(1.0),
            side: LineSide::Left,
            sense: Sense::Agree,
        })
        .unwrap();
    let analysis = &s.analyze().unwrap()[0].analysis;
    assert!(!analysis.redundant.contains(&tangent), "{analysis:?}");
    assert!(!analysis.redundant.contains(&join), "{analysis:?}");
    assert_eq!(analysis.partly_redundant, vec![tangent], "{analysis:?}");
}

/// Case 1 (the FreeCAD 5931 pattern): a fixed line y = `line_y`, a circle of fixed centre
/// (0, 0) and free radius starting at 1, a point at (0, 1) on both, and radius = `radius`.
fn case_1(line_y: f64, radius: f64) -> (Sketch, camber_sketch::ConstraintId) {
    use camber_sketch::constraints::{PointOnCircle, PointOnLine, Radius};
    let mut s = Sketch::new();
    let line = s
        .add_line(Point2::new(-3.0, line_y), Point2::new(3.0, line_y))
        .unwrap();
    s.add_constraint(Fixed::entity(line)).unwrap();
    let circle = s.add_circle(Point2::new(0.0, 0.0), 1.0).unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(circle, 0)))
        .unwrap();
    let p = s.add_point(Point2::new(0.0, 1.0)).unwrap();
    s.add_constraint(PointOnLine {
        point: PointRef::Point(p),
        line,
    })
    .unwrap();
    s.add_constraint(PointOnCircle {
        point: PointRef::Point(p),
        circle,
    })
    .unwrap();
    let r = s.add_constraint(Radius { circle, radius }).unwrap();
    (s, r)
}

/// Case 1: a tangency by design is not redundancy. The point, the line and the circle touch at
/// (0, 1), where the Jacobian is singular; nearby it is not, so DOF is 0 and nothing is
/// redundant; the radius is named as dependent only here.
#[test]
fn a_tangency_by_design_is_not_redundant() {
    let (s, radius) = case_1(1.0, 1.0);
    let a = &s.analyze().unwrap()[0];
    assert_eq!(a.analysis.dof, 0, "{:?}", a.analysis);
    assert!(a.analysis.redundant.is_empty(), "{:?}", a.analysis);
    assert_eq!(a.analysis.accidental, vec![radius]);
    // With the line at y = 0.6 the circle crosses it: the same answer (the start (0, 1) is
    // still a singular point of the rows, which the analysis says rather than "redundant").
    let (s, _) = case_1(0.6, 1.0);
    let a = &s.analyze().unwrap()[0];
    assert_eq!(a.analysis.dof, 0);
    assert!(a.analysis.redundant.is_empty() && a.analysis.conflicting.is_empty());
}

/// Case 1 with radius 1.1 from the same start: not "conflicting", and the solve succeeds.
#[test]
fn a_singular_start_is_not_a_conflict() {
    let (mut s, radius) = case_1(1.0, 1.1);
    let a = &s.analyze().unwrap()[0];
    assert!(a.analysis.conflicting.is_empty(), "{:?}", a.analysis);
    assert_eq!(a.analysis.accidental, vec![radius]);
    assert_eq!(a.analysis.dof, 0);
    // The start sits on the symmetry x = 0, which least squares never leaves; the solve moves
    // off it and finds the crossing: radius 1.1, the point at (±√0.21, 1).
    let report = s.solve().unwrap();
    assert!(report.components[0]
        .report
        .reason
        .contains("moved off the singular"));
    let p = s.point(PointRef::Point(EntityId(4))).unwrap();
    assert!(
        (p.x.abs() - 0.21_f64.sqrt()).abs() < 1e-9 && (p.y - 1.0).abs() < 1e-9,
        "{p:?}"
    );
    let _ = radius;
}

/// The other side: a constraint implied by the others keeps its dependence along the
/// manifold and stays redundant. P, C and D lie on line L (free ends); line M joins C and D;
/// "P on M" is then implied.
#[test]
fn an_implied_constraint_stays_redundant_along_the_manifold() {
    use camber_sketch::constraints::{Coincident, PointOnLine};
    let mut s = Sketch::new();
    let l = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(4.0, 1.0))
        .unwrap();
    let m = s
        .add_line(Point2::new(1.0, 0.25), Point2::new(3.0, 0.75))
        .unwrap();
    let p = s.add_point(Point2::new(2.0, 0.5)).unwrap();
    for point in [PointRef::Start(m), PointRef::End(m), PointRef::Point(p)] {
        s.add_constraint(PointOnLine { point, line: l }).unwrap();
    }
    let implied = s
        .add_constraint(PointOnLine {
            point: PointRef::Point(p),
            line: m,
        })
        .unwrap();
    let a = &s.analyze().unwrap()[0];
    assert_eq!(a.analysis.redundant, vec![implied], "{:?}", a.analysis);
    assert!(a.analysis.accidental.is_empty());
    // 4 (L) + 4 (M) + 2 (P) unknowns, 3 independent rows.
    assert_eq!(a.analysis.dof, 7);
    let _ = Coincident {
        a: PointRef::Point(p),
        b: PointRef::Point(p),
    };
}

/// Case 3 at scale: a chain of 1,000 cubics, each join a coincidence and a tangency at the same
/// ends. Every tangency is partly redundant and none is redundant. Each candidate is tested on
/// its own coupled piece, so this takes a fraction of a second in a debug build (testing each
/// on the whole component took 42 s in release at 3,000 joins).
#[test]
fn many_partly_redundant_joins() {
    use camber_sketch::constraints::{Coincident, CurveCurveTangent};
    let n = 1000;
    let mut s = Sketch::new();
    let curves: Vec<EntityId> = (0..n)
        .map(|k| {
            let x = 3.0 * k as f64;
            cubic(
                &mut s,
                [(x, 0.0), (x + 1.0, 1.0), (x + 2.0, 0.5), (x + 3.0, 0.0)],
            )
        })
        .collect();
    s.add_constraint(Fixed::entity(curves[0])).unwrap();
    let mut tangents = Vec::new();
    for w in curves.windows(2) {
        s.add_constraint(Coincident {
            a: PointRef::End(w[0]),
            b: PointRef::Start(w[1]),
        })
        .unwrap();
        tangents.push(
            s.add_constraint(CurveCurveTangent {
                first: w[0],
                u: Contact::At(1.0),
                second: w[1],
                v: Contact::At(0.0),
                sense: Sense::Agree,
            })
            .unwrap(),
        );
    }
    let analysis = &s.analyze().unwrap()[0].analysis;
    assert!(analysis.redundant.is_empty(), "{:?}", analysis.redundant);
    assert!(
        analysis.conflicting.is_empty(),
        "{:?}",
        analysis.conflicting
    );
    let mut partly = analysis.partly_redundant.clone();
    partly.sort_unstable();
    assert_eq!(partly, tangents);
    assert_eq!(analysis.rank, n - 1);
}
