//! Custom constraints: a user's affine residual solves with the built-ins; a non-affine one
//! makes its component report that it needs the nonlinear solver, with the sketch unchanged.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber_sketch::{Constraint, Custom, Error, PointRef, Sketch};
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
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (dx, dy) = (x[1][0] - x[0][0], x[1][1] - x[0][1]);
        out[0] = dx * dx + dy * dy - T::one();
    }
}

#[test]
fn a_nonlinear_custom_constraint_needs_the_nonlinear_solver() {
    let mut s = Sketch::new();
    let p = s.add_point(Point2::new(0.0, 0.0)).unwrap();
    let q = s.add_point(Point2::new(2.0, 0.0)).unwrap();
    let other = s.add_point(Point2::new(9.0, 9.0)).unwrap();
    let id = s
        .add_constraint(Constraint::Custom(Custom::new(
            UnitDistance,
            vec![PointRef::Point(p), PointRef::Point(q)],
        )))
        .unwrap();
    let expected = Error::NeedsNonlinear {
        constraint: id,
        name: "unit distance".to_owned(),
    };
    let before: Vec<_> = s.entities().map(|(i, e)| (i, e.clone())).collect();
    assert_eq!(s.solve().unwrap_err(), expected);
    assert_eq!(s.drag(PointRef::Point(p)).unwrap_err(), expected);
    let after: Vec<_> = s.entities().map(|(i, e)| (i, e.clone())).collect();
    assert_eq!(before, after);
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
