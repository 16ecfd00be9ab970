//! Custom constraints: a user's affine residual solves with the built-ins; a non-affine one
//! sends its component to the nonlinear solver, in solves and drags.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_abs_diff_eq;
use camber_sketch::{Constraint, Custom, Error, PointRef, Sketch};
use camber_solve::SolverKind;
use camber_solve::{Residual, Scalar};
use nalgebra::Point2;

/// |q − p|² − 1 = 0: not affine.
#[derive(Debug)]
struct UnitDistance;

impl Residual for UnitDistance {
    fn name(&self) -> &str {
        "unit distance"
    }
    fn dim(&self) -> usize {
        1
    }

    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (dx, dy) = (x[1][0] - x[0][0], x[1][1] - x[0][1]);
        out[0] = dx * dx + dy * dy - T::one();
    }
}

#[test]
fn a_nonlinear_custom_constraint_goes_to_the_nonlinear_solver() {
    let mut s = Sketch::new();
    let p = s.add_point(Point2::new(0.0, 0.0)).unwrap();
    let q = s.add_point(Point2::new(2.0, 0.0)).unwrap();
    let other = s.add_point(Point2::new(9.0, 9.0)).unwrap();
    s.add_constraint(Constraint::Custom(Custom::new(
        UnitDistance,
        vec![PointRef::Point(p), PointRef::Point(q)],
    )))
    .unwrap();
    let report = s.solve().unwrap();
    assert_eq!(report.components[0].report.solver, SolverKind::Newton);
    // Minimum norm: both points move ½ toward each other.
    let (a, b) = (
        s.point(PointRef::Point(p)).unwrap(),
        s.point(PointRef::Point(q)).unwrap(),
    );
    assert_abs_diff_eq!(a.x, 0.5, epsilon = 1e-9);
    assert_abs_diff_eq!(b.x, 1.5, epsilon = 1e-9);
    // A drag of p keeps q at unit distance.
    let mut d = s.drag(PointRef::Point(p)).unwrap();
    d.update(Point2::new(0.5, 0.2)).unwrap();
    let (a, b) = (
        d.point(PointRef::Point(p)).unwrap(),
        d.point(PointRef::Point(q)).unwrap(),
    );
    assert_abs_diff_eq!((b - a).norm(), 1.0, epsilon = 1e-9);
    assert_abs_diff_eq!(a.y, 0.2, epsilon = 1e-12);
    d.finish(&mut s).unwrap();
    // Other components are unaffected: a drag there works.
    let mut d = s.drag(PointRef::Point(other)).unwrap();
    d.update(Point2::new(8.0, 9.0)).unwrap();
    // A custom point must be a single block.
    let c = s
        .add_line(Point2::new(0.0, 0.0), Point2::new(1.0, 0.0))
        .unwrap();
    assert!(matches!(
        s.add_constraint(Constraint::Custom(Custom::new(
            UnitDistance,
            vec![PointRef::Point(p), PointRef::Control(c, 5)],
        ))),
        Err(Error::UnknownPoint { index: 5, .. })
    ));
}

mod typed_args {
    //! Custom constraints over any unknown (issue 12): curves read with their live knots,
    //! radii, other constraints' free parameters and parameters of their own; argument shapes
    //! checked when the constraint is added.

    use camber_geom::{BSplineCurve2, KnotVector};
    use camber_sketch::constraints::{Fixed, TangentToCircle};
    use camber_sketch::{
        Arg, ArgKind, Args, CircleSide, Contact, Custom, CustomResidual, Entity, Error, PointRef,
        Rotation, Sketch,
    };
    use camber_solve::{Residual, Scalar};
    use nalgebra::Point2;

    /// The curve passes through the point at the constraint's own parameter s: C(s) − P = 0.
    #[derive(Debug)]
    struct Through;

    impl CustomResidual for Through {
        fn name(&self) -> &str {
            "through"
        }
        fn dim(&self) -> usize {
            2
        }
        fn arg_kinds(&self) -> Vec<ArgKind> {
            vec![ArgKind::Curve, ArgKind::Point, ArgKind::Scalar]
        }
        fn eval<T: Scalar>(&self, a: &Args<'_, T>, out: &mut [T]) {
            let (c, p) = (a.curve(0).point(a.scalar(2)), a.point(1));
            out[0] = c[0] - p[0];
            out[1] = c[1] - p[1];
        }
    }

    fn param(s: &Sketch, id: camber_sketch::ConstraintId) -> f64 {
        match s.constraint(id).unwrap().as_custom().unwrap().args()[2] {
            Arg::Param(u) => u,
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn a_custom_constraint_on_a_curve_survives_knot_refinement() {
        let mut s = Sketch::new();
        let pts = vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 2.0),
            Point2::new(3.0, 2.0),
            Point2::new(4.0, 0.0),
        ];
        let curve =
            BSplineCurve2::try_new(3, KnotVector::clamped_uniform(3, 4).unwrap(), pts).unwrap();
        let c = s.add_bspline(curve.clone()).unwrap();
        let q = s.add_point(Point2::new(2.0, 2.0)).unwrap();
        s.add_constraint(Fixed::point(PointRef::Point(q))).unwrap();
        let id = s
            .add_constraint(Custom::with_args(
                Through,
                vec![
                    Arg::Curve(c),
                    Arg::Point(PointRef::Point(q)),
                    Arg::Param(0.4),
                ],
            ))
            .unwrap();
        s.solve().unwrap();
        let on =
            |s: &Sketch| (s.curve_point(c, param(s, id)).unwrap() - Point2::new(2.0, 2.0)).norm();
        assert!(on(&s) < 1e-10);
        // Refine: the same curve with two more knots (and so two more control points), then
        // move the point so the constraint must act on the refined curve.
        let Entity::BSpline(now) = s.entity(c).unwrap().clone() else {
            unreachable!()
        };
        let refined = now
            .insert_knot(0.3, 1)
            .unwrap()
            .insert_knot(0.7, 1)
            .unwrap();
        s.set_entity(c, Entity::BSpline(refined)).unwrap();
        assert_eq!(s.entity(c).unwrap().points().len(), 6);
        s.remove_constraint(camber_sketch::ConstraintId(2)).unwrap();
        s.set_point(PointRef::Point(q), Point2::new(2.2, 1.6))
            .unwrap();
        s.add_constraint(Fixed::point(PointRef::Point(q))).unwrap();
        s.solve().unwrap();
        let target = Point2::new(2.2, 1.6);
        assert!((s.curve_point(c, param(&s, id)).unwrap() - target).norm() < 1e-10);
    }

    /// |q − p|² − 1 over two declared point blocks.
    #[derive(Debug)]
    struct Unit;

    impl Residual for Unit {
        fn name(&self) -> &str {
            "unit"
        }
        fn dim(&self) -> usize {
            1
        }
        fn block_sizes(&self) -> Option<Vec<usize>> {
            Some(vec![2, 2])
        }
        fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
            let (dx, dy) = (x[1][0] - x[0][0], x[1][1] - x[0][1]);
            out[0] = dx * dx + dy * dy - T::one();
        }
    }

    #[test]
    fn a_wrong_block_count_is_a_typed_error_not_a_panic() {
        let mut s = Sketch::new();
        let p = s.add_point(Point2::new(0.0, 0.0)).unwrap();
        let e = s
            .add_constraint(Custom::new(Unit, vec![PointRef::Point(p)]))
            .unwrap_err();
        assert_eq!(
            e,
            Error::CustomArgs {
                name: "unit".into(),
                expected: vec![ArgKind::Point, ArgKind::Point],
                found: vec![ArgKind::Point],
            }
        );
        assert_eq!(s.constraints().count(), 0);
        // A typed residual given a point where it reads a curve.
        let e = s
            .add_constraint(Custom::with_args(
                Through,
                vec![
                    Arg::Point(PointRef::Point(p)),
                    Arg::Point(PointRef::Point(p)),
                    Arg::Param(0.0),
                ],
            ))
            .unwrap_err();
        assert!(matches!(e, Error::CustomArgs { .. }), "{e}");
    }

    /// The contact parameter read from another constraint equals the own parameter... fixed
    /// at ½: u − ½ = 0, and the circle's radius is read too: r − R = 0.
    #[derive(Debug)]
    struct ContactAtHalfAndRadius(f64);

    impl CustomResidual for ContactAtHalfAndRadius {
        fn name(&self) -> &str {
            "contact at half"
        }
        fn dim(&self) -> usize {
            2
        }
        fn arg_kinds(&self) -> Vec<ArgKind> {
            vec![ArgKind::Scalar, ArgKind::Scalar]
        }
        fn eval<T: Scalar>(&self, a: &Args<'_, T>, out: &mut [T]) {
            out[0] = a.scalar(0) - camber_solve::scalar::cst(0.5);
            out[1] = a.scalar(1) - camber_solve::scalar::cst(self.0);
        }
        fn is_affine(&self) -> bool {
            true
        }
    }

    #[test]
    fn a_custom_constraint_reads_a_contact_parameter_and_a_radius() {
        let mut s = Sketch::new();
        let arc = s
            .add_bezier(
                camber_geom::BezierCurve2::try_new(vec![
                    Point2::new(-2.0, 1.3),
                    Point2::new(-0.7, 1.5),
                    Point2::new(0.7, 1.5),
                    Point2::new(2.0, 1.3),
                ])
                .unwrap(),
            )
            .unwrap();
        let circle = s.add_circle(Point2::new(0.3, 0.0), 1.0).unwrap();
        s.add_constraint(Fixed::point(PointRef::Control(circle, 0)))
            .unwrap();
        let touch = s
            .add_constraint(TangentToCircle {
                curve: arc,
                circle,
                u: Contact::Free(0.6),
                side: CircleSide::Outside,
                rotation: Rotation::Clockwise,
            })
            .unwrap();
        s.add_constraint(Custom::with_args(
            ContactAtHalfAndRadius(1.1),
            vec![Arg::free_of(touch, 0), Arg::Radius(circle)],
        ))
        .unwrap();
        s.solve().unwrap();
        let TangentToCircle { u, .. } = match s.constraint(touch).unwrap() {
            camber_sketch::Constraint::TangentToCircle(t) => *t,
            _ => unreachable!(),
        };
        assert!((u.value() - 0.5).abs() < 1e-10);
        let Entity::Circle { center, radius } = *s.entity(circle).unwrap() else {
            unreachable!()
        };
        assert!((radius - 1.1).abs() < 1e-10);
        assert!(((s.curve_point(arc, 0.5).unwrap() - center).norm() - 1.1).abs() < 1e-9);
        // The contact cannot go while the custom constraint reads its parameter.
        assert!(matches!(
            s.remove_constraint(touch),
            Err(Error::ConstraintInUse { .. })
        ));
    }
}

/// A residual of no arguments: the constant `value`, whatever the sketch.
#[derive(Debug)]
struct Constant {
    value: f64,
}

impl Residual for Constant {
    fn name(&self) -> &str {
        "constant"
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(Vec::new())
    }
    fn eval<T: Scalar>(&self, _: &[&[T]], out: &mut [T]) {
        out[0] = camber_solve::scalar::cst(self.value);
    }
}

#[test]
fn a_custom_constraint_of_no_arguments_that_cannot_hold_is_a_conflict() {
    // 1 = 0 reads nothing: no move can satisfy it. It used to belong to no component, so the
    // solve skipped it and the report said every residual was already within tolerance.
    let mut s = Sketch::new();
    let p = s.add_point(Point2::new(1.0, 2.0)).unwrap();
    let id = s
        .add_constraint(Constraint::Custom(Custom::new(
            Constant { value: 1.0 },
            vec![],
        )))
        .unwrap();
    let before = s.clone();
    match s.solve() {
        Err(Error::Conflicting { constraints }) => assert_eq!(constraints, vec![id]),
        other => panic!("expected a conflict naming constraint {id:?}, got {other:?}"),
    }
    assert_eq!(s.point(PointRef::Point(p)).unwrap(), Point2::new(1.0, 2.0));
    assert_eq!(s.constraints().count(), before.constraints().count());
    let analyses = s.analyze().unwrap();
    assert!(
        analyses.iter().any(|a| a.analysis.conflicting == vec![id]),
        "{analyses:?}"
    );
    // One that holds (0 = 0) is satisfied, and said so.
    let mut s = Sketch::new();
    let id = s
        .add_constraint(Constraint::Custom(Custom::new(
            Constant { value: 0.0 },
            vec![],
        )))
        .unwrap();
    let report = s.solve().unwrap();
    assert!(report
        .components
        .iter()
        .any(|c| c.component.constraints == vec![id]));
}

/// s − 1 = 0 over one scalar argument s.
#[derive(Debug)]
struct ParameterIsOne;

impl Residual for ParameterIsOne {
    fn name(&self) -> &str {
        "parameter is one"
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![1])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = x[0][0] - T::one();
    }
    fn is_affine(&self) -> bool {
        true
    }
}

/// A residual declaring a row count nobody can hold (a typing slip, `dim=10**9` from Python):
/// its values are never asked for.
#[derive(Debug)]
struct Huge(usize);

impl Residual for Huge {
    fn name(&self) -> &str {
        "huge"
    }
    fn dim(&self) -> usize {
        self.0
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        for o in out.iter_mut() {
            *o = x[0][0];
        }
    }
}

#[test]
fn a_custom_constraint_over_its_own_parameter_only_is_solved() {
    // It reads no entity, so it used to be in no component and its parameter never moved.
    use camber_sketch::constraints::custom::Arg;
    let mut s = Sketch::new();
    let id = s
        .add_constraint(Constraint::Custom(Custom::plain(
            ParameterIsOne,
            vec![Arg::Param(0.25)],
        )))
        .unwrap();
    s.solve().unwrap();
    let Some(Arg::Param(v)) = s.constraint(id).unwrap().as_custom().map(|c| c.args()[0]) else {
        panic!("no parameter")
    };
    assert_abs_diff_eq!(v, 1.0, epsilon = 1e-12);
}

#[test]
fn a_custom_residual_with_too_many_rows_is_refused_before_anything_is_allocated() {
    let mut s = Sketch::new();
    let p = s.add_point(Point2::new(0.0, 0.0)).unwrap();
    let before = camber_sketch::file::to_json(&s).unwrap();
    for rows in [
        1_000_000_000,
        usize::MAX,
        camber_sketch::constraints::custom::MAX_CUSTOM_ROWS + 1,
    ] {
        let err = s
            .add_constraint(Constraint::Custom(Custom::new(
                Huge(rows),
                vec![PointRef::Point(p)],
            )))
            .and_then(|_| s.solve().map(|_| ()))
            .unwrap_err();
        assert!(
            matches!(err, Error::CustomTooLarge { rows: r, unknowns: 2, .. } if r == rows),
            "{err}"
        );
        assert!(err.to_string().contains("\"huge\""), "{err}");
    }
    assert_eq!(camber_sketch::file::to_json(&s).unwrap(), before);
}
