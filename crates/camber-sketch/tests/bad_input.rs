//! Bad input gives typed errors and leaves the sketch exactly as it was: unknown ids, zero
//! directions, parameters outside the domain, non-finite numbers, bad indices, the elimination
//! form on an unclamped end.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber_geom::{BSplineCurve2, BezierCurve2, KnotVector};
use camber_sketch::constraints::{
    Coincident, DirectionalTangentAt, Fixed, PointAtParameter, StartTangent, TangentToLineAt,
    TangentVectorAt,
};
use camber_sketch::{
    Constraint, ConstraintId, Entity, EntityId, Error, FixTarget, PointRef, Sense, Sketch,
    TangentForm, Target,
};
use nalgebra::{Point2, Vector2};

fn sketch() -> (Sketch, EntityId) {
    let mut s = Sketch::new();
    let c = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 0.0),
                Point2::new(1.0, 1.0),
                Point2::new(2.0, 0.0),
            ])
            .unwrap(),
        )
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Start(c))).unwrap();
    (s, c)
}

type Snapshot = (
    u64,
    Vec<(EntityId, Entity)>,
    Vec<(ConstraintId, Constraint)>,
);

fn snapshot(s: &Sketch) -> Snapshot {
    (
        s.revision(),
        s.entities().map(|(i, e)| (i, e.clone())).collect(),
        s.constraints().map(|(i, c)| (i, c.clone())).collect(),
    )
}

/// Applies `edit`, expects `expected`, and checks that nothing changed.
fn refused(s: &mut Sketch, c: Constraint, expected: Error) {
    let before = snapshot(s);
    assert_eq!(s.add_constraint(c).unwrap_err(), expected);
    assert_eq!(snapshot(s), before);
}

#[test]
fn unknown_ids() {
    let (mut s, c) = sketch();
    let ghost = EntityId(99);
    refused(
        &mut s,
        Constraint::Coincident(Coincident {
            a: PointRef::Start(c),
            b: PointRef::Point(ghost),
        }),
        Error::UnknownEntity { entity: ghost },
    );
    refused(
        &mut s,
        Constraint::Fixed(Fixed {
            target: FixTarget::Point(PointRef::Control(c, 3)),
        }),
        Error::UnknownPoint {
            entity: c,
            index: 3,
            count: 3,
        },
    );
    let before = snapshot(&s);
    assert_eq!(
        s.remove_constraint(ConstraintId(77)).unwrap_err(),
        Error::UnknownConstraint {
            constraint: ConstraintId(77)
        }
    );
    assert!(matches!(
        s.drag(PointRef::Point(ghost)),
        Err(Error::UnknownEntity { .. })
    ));
    assert!(matches!(
        s.remove_entity(c),
        Err(Error::EntityInUse { entity, .. }) if entity == c
    ));
    assert_eq!(snapshot(&s), before);
}

#[test]
fn zero_tangent_direction() {
    let (mut s, c) = sketch();
    refused(
        &mut s,
        Constraint::StartTangent(StartTangent {
            curve: c,
            direction: Vector2::zeros(),
            sense: Sense::Agree,
            form: TangentForm::Elimination,
        }),
        Error::ZeroDirection {
            what: "tangent",
            x: 0.0,
            y: 0.0,
        },
    );
    refused(
        &mut s,
        Constraint::TangentToLineAt(TangentToLineAt {
            curve: c,
            u: 0.5,
            point: Point2::origin(),
            direction: Vector2::zeros(),
            sense: Sense::Agree,
        }),
        Error::ZeroDirection {
            what: "line",
            x: 0.0,
            y: 0.0,
        },
    );
}

#[test]
fn parameter_outside_the_domain() {
    let (mut s, c) = sketch();
    refused(
        &mut s,
        Constraint::DirectionalTangentAt(DirectionalTangentAt {
            curve: c,
            u: 1.25,
            direction: Vector2::new(1.0, 0.0),
            sense: Sense::Agree,
        }),
        Error::ParameterOutsideDomain {
            entity: c,
            value: 1.25,
            min: 0.0,
            max: 1.0,
        },
    );
    let p = s.add_point(Point2::origin()).unwrap();
    refused(
        &mut s,
        Constraint::PointAtParameter(PointAtParameter {
            curve: p,
            u: 0.5,
            target: Target::At(Point2::origin()),
        }),
        Error::WrongEntityKind {
            entity: p,
            expected: "curve",
            found: "point",
        },
    );
}

#[test]
fn non_finite_numbers() {
    let (mut s, c) = sketch();
    refused(
        &mut s,
        Constraint::PointAtParameter(PointAtParameter {
            curve: c,
            u: 0.5,
            target: Target::At(Point2::new(1.0, f64::INFINITY)),
        }),
        Error::NonFinite {
            what: "target",
            index: 1,
            value: f64::INFINITY,
        },
    );
    let before = snapshot(&s);
    assert!(matches!(
        s.add_constraint(TangentVectorAt {
            curve: c,
            u: f64::NAN,
            vector: Vector2::new(1.0, 0.0)
        }),
        Err(Error::NonFinite {
            what: "parameter",
            ..
        })
    ));
    assert!(matches!(
        s.set_point(PointRef::Control(c, 1), Point2::new(f64::NAN, 0.0)),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        s.add_point(Point2::new(0.0, f64::NEG_INFINITY)),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        s.add_circle(Point2::origin(), -1.0),
        Err(Error::Geometry(_))
    ));
    assert_eq!(snapshot(&s), before);
}

#[test]
fn elimination_needs_a_clamped_end() {
    let mut s = Sketch::new();
    let knots = KnotVector::try_new(vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0]).unwrap();
    let pts = vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 1.0),
        Point2::new(2.0, 0.0),
        Point2::new(3.0, 1.0),
    ];
    let c = s
        .add_bspline(BSplineCurve2::try_new(2, knots, pts).unwrap())
        .unwrap();
    let tangent = |form| {
        Constraint::StartTangent(StartTangent {
            curve: c,
            direction: Vector2::new(1.0, 0.0),
            sense: Sense::Agree,
            form,
        })
    };
    refused(
        &mut s,
        tangent(TangentForm::Elimination),
        Error::NotClampedEnd {
            entity: c,
            end: "start",
        },
    );
    // The row form works on any curve.
    s.add_constraint(tangent(TangentForm::Row)).unwrap();
    s.solve().unwrap();
    let d = s.entity(c).unwrap().coefficients(c, 2.0, 1).unwrap();
    let pts = s.entity(c).unwrap().points().to_vec();
    let dy: f64 = d.iter().map(|(j, w)| w * pts[*j].y).sum();
    assert!(dy.abs() < 1e-12);
}

#[test]
fn messages_print_extreme_numbers_in_short_form() {
    // `{}` of 1e308 is 309 digits; the messages quote numbers in their shortest form.
    let (mut s, c) = sketch();
    let err = s
        .add_constraint(PointAtParameter {
            curve: c,
            u: 1e308,
            target: Target::At(Point2::new(0.0, 0.0)),
        })
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("parameter 1e308 is outside the domain [0, 1]"),
        "{err}"
    );
    let err = Error::ContactCrossed {
        constraint: ConstraintId(3),
        parameter: 0.25,
        depth: 2.5e-300,
    }
    .to_string();
    assert!(err.ends_with("at u = 0.25 by 2.5e-300"), "{err}");
    let err = Error::Solve(camber_solve::Error::OutOfBounds {
        unknown: 4,
        value: -1e300,
        lower: 0.0,
        upper: 1e20,
    })
    .to_string();
    assert!(
        err.ends_with("would move to -1e300, outside [0, 1e20]"),
        "{err}"
    );
}
