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
