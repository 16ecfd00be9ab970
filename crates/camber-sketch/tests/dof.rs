//! DOF analysis on known cases: free cubic (8), ends fixed (4), end tangent directions fixed
//! too (2, in both forms), a duplicated constraint (redundant, named), contradictory
//! constraints (conflicting, named, nothing moved).

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber_geom::BezierCurve2;
use camber_sketch::constraints::{
    DirectionalTangentAt, EndTangent, Fixed, PointAtParameter, StartTangent,
};
use camber_sketch::{Constraint, EntityId, Error, PointRef, Sense, Sketch, TangentForm, Target};
use nalgebra::{Point2, Vector2};

fn cubic(s: &mut Sketch) -> EntityId {
    s.add_bezier(
        BezierCurve2::try_new(vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(2.0, 1.0),
            Point2::new(3.0, 0.0),
        ])
        .unwrap(),
    )
    .unwrap()
}

fn dof(s: &Sketch) -> usize {
    let a = s.analyze().unwrap();
    assert_eq!(a.len(), 1);
    a[0].analysis.dof
}

fn fix_ends(s: &mut Sketch, c: EntityId) {
    s.add_constraint(Fixed::point(PointRef::Start(c))).unwrap();
    s.add_constraint(Fixed::point(PointRef::End(c))).unwrap();
}

fn tangents(s: &mut Sketch, c: EntityId, form: TangentForm) {
    s.add_constraint(StartTangent {
        curve: c,
        direction: Vector2::new(1.0, 1.0),
        sense: Sense::Agree,
        form,
    })
    .unwrap();
    s.add_constraint(EndTangent {
        curve: c,
        direction: Vector2::new(1.0, -1.0),
        sense: Sense::Agree,
        form,
    })
    .unwrap();
}

#[test]
fn free_cubic_has_eight() {
    let mut s = Sketch::new();
    cubic(&mut s);
    assert_eq!(dof(&s), 8);
}

#[test]
fn fixed_ends_leave_four() {
    let mut s = Sketch::new();
    let c = cubic(&mut s);
    fix_ends(&mut s, c);
    assert_eq!(dof(&s), 4);
}

#[test]
fn fixed_end_tangent_directions_leave_two_in_both_forms() {
    for form in [TangentForm::Row, TangentForm::Elimination] {
        let mut s = Sketch::new();
        let c = cubic(&mut s);
        fix_ends(&mut s, c);
        tangents(&mut s, c, form);
        assert_eq!(dof(&s), 2, "{form:?}");
        // Elimination: the two interior points are replaced by two scalars t.
        let a = &s.analyze().unwrap()[0].analysis;
        let expected_unknowns = if form == TangentForm::Row { 4 } else { 2 };
        assert_eq!(a.free_unknowns, expected_unknowns);
        s.solve().unwrap();
    }
}

#[test]
fn a_duplicated_constraint_is_redundant_and_named() {
    let mut s = Sketch::new();
    let c = cubic(&mut s);
    fix_ends(&mut s, c);
    let tangent = Constraint::DirectionalTangentAt(DirectionalTangentAt {
        curve: c,
        u: 0.5,
        direction: Vector2::new(1.0, 0.1),
        sense: Sense::Agree,
    });
    s.add_constraint(tangent.clone()).unwrap();
    let dup = s.add_constraint(tangent).unwrap();
    let a = &s.analyze().unwrap()[0].analysis;
    assert_eq!(a.redundant, vec![dup]);
    assert!(a.conflicting.is_empty());
    assert_eq!(a.dof, 3);
    // The solve drops the dependent row and says so.
    let r = s.solve().unwrap();
    assert_eq!(r.components[0].report.redundant, vec![dup]);
}

#[test]
fn contradictory_constraints_conflict_are_named_and_move_nothing() {
    let mut s = Sketch::new();
    let c = cubic(&mut s);
    let at = |y: f64| {
        Constraint::PointAtParameter(PointAtParameter {
            curve: c,
            u: 0.5,
            target: Target::At(Point2::new(1.5, y)),
        })
    };
    s.add_constraint(at(1.0)).unwrap();
    let bad = s.add_constraint(at(2.0)).unwrap();
    let a = &s.analyze().unwrap()[0].analysis;
    assert_eq!(a.conflicting, vec![bad]);
    let before: Vec<_> = s.entities().map(|(id, e)| (id, e.clone())).collect();
    assert_eq!(
        s.solve().unwrap_err(),
        Error::Conflicting {
            constraints: vec![bad]
        }
    );
    let after: Vec<_> = s.entities().map(|(id, e)| (id, e.clone())).collect();
    assert_eq!(before, after);
}
