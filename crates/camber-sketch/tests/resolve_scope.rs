//! Only what changed is solved again: residuals that count their own evaluations show that an
//! edit (or a drag) in one component never evaluates another component's constraints, while
//! `solve_all` does; and the elimination form of an end tangency refuses a solve that would
//! need t ≤ 0 (a cusp) without touching the sketch.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

use approx::assert_abs_diff_eq;
use camber_geom::BezierCurve2;
use camber_sketch::constraints::{Fixed, PointAtParameter, StartTangent};
use camber_sketch::{Constraint, Custom, Error, PointRef, Sense, Sketch, TangentForm, Target};
use camber_solve::{Residual, Scalar};
use nalgebra::{Point2, Vector2};

/// q − p = offset (two affine rows), counting every evaluation (values and Jacobians alike).
#[derive(Debug)]
struct CountingOffset {
    calls: Arc<AtomicUsize>,
    offset: [f64; 2],
}

impl Residual for CountingOffset {
    fn name(&self) -> &str {
        "counting offset"
    }
    fn dim(&self) -> usize {
        2
    }

    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        self.calls.fetch_add(1, Ordering::Relaxed);
        for c in 0..2 {
            out[c] = x[1][c] - x[0][c] - camber_solve::scalar::cst::<T>(self.offset[c]);
        }
    }
    fn is_affine(&self) -> bool {
        true
    }
}

/// Two points joined by a counting offset; returns the counter and the two point refs.
fn pair(s: &mut Sketch, at: Point2<f64>) -> (Arc<AtomicUsize>, PointRef, PointRef) {
    let calls = Arc::new(AtomicUsize::new(0));
    let p = PointRef::Point(s.add_point(at).unwrap());
    let q = PointRef::Point(s.add_point(at + Vector2::new(3.0, 0.0)).unwrap());
    let r = CountingOffset {
        calls: Arc::clone(&calls),
        offset: [1.0, 0.5],
    };
    s.add_constraint(Constraint::Custom(Custom::new(r, vec![p, q])))
        .unwrap();
    (calls, p, q)
}

fn count(c: &Arc<AtomicUsize>) -> usize {
    c.load(Ordering::Relaxed)
}

#[test]
fn an_edit_never_evaluates_the_constraints_of_untouched_components() {
    let mut s = Sketch::new();
    let (ca, pa, qa) = pair(&mut s, Point2::new(0.0, 0.0));
    let (cb, pb, qb) = pair(&mut s, Point2::new(10.0, 10.0));
    assert_eq!(s.components().len(), 2);
    let first = s.solve().unwrap();
    assert_eq!(first.components.len(), 2);
    assert!(count(&ca) > 0 && count(&cb) > 0);
    let b_points = (s.point(pb).unwrap(), s.point(qb).unwrap());

    // Edit A and solve: A's residual runs again, B's not once.
    let (a0, b0) = (count(&ca), count(&cb));
    s.set_point(pa, Point2::new(-1.0, 2.0)).unwrap();
    let report = s.solve().unwrap();
    assert_eq!(report.components.len(), 1);
    assert!(count(&ca) > a0);
    assert_eq!(count(&cb), b0, "the untouched component was evaluated");
    assert_abs_diff_eq!(
        s.point(qa).unwrap() - s.point(pa).unwrap(),
        Vector2::new(1.0, 0.5),
        epsilon = 1e-12
    );
    assert_eq!((s.point(pb).unwrap(), s.point(qb).unwrap()), b_points);

    // Nothing dirty: nothing evaluated at all.
    let (a1, b1) = (count(&ca), count(&cb));
    assert!(s.solve().unwrap().components.is_empty());
    assert_eq!((count(&ca), count(&cb)), (a1, b1));

    // A drag session in A, updates and commit: B is still never evaluated.
    let mut drag = s.drag(qa).unwrap();
    for k in 1..=10 {
        drag.update(Point2::new(2.0 + 0.1 * f64::from(k), 1.0))
            .unwrap();
    }
    drag.finish(&mut s).unwrap();
    s.solve().unwrap();
    assert!(count(&ca) > a1);
    assert_eq!(count(&cb), b1, "a drag in A evaluated B");

    // The counter does see B when B is solved: solve_all re-solves every component.
    s.solve_all().unwrap();
    assert!(count(&cb) > b1);
}

#[test]
fn elimination_refuses_a_solve_that_needs_a_negative_t() {
    // P₁ = P₀ + t·(1, 0) with P₁ held at (1, 1); asking C(0) = P₀ to go to (5, 1), ahead of
    // P₁, would need t = −4: the tangent would point against the recorded sense (a cusp in the
    // making). The solve is refused with the tangency named and the sketch left as it was.
    let mut s = Sketch::new();
    let c = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 1.0),
                Point2::new(1.0, 1.0),
                Point2::new(2.0, 0.5),
                Point2::new(3.0, 0.0),
            ])
            .unwrap(),
        )
        .unwrap();
    let tangent = s
        .add_constraint(StartTangent {
            curve: c,
            direction: Vector2::new(1.0, 0.0),
            sense: Sense::Agree,
            form: TangentForm::Elimination,
        })
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(c, 1)))
        .unwrap();
    s.solve().unwrap();
    let before = s.entity(c).unwrap().clone();

    let ahead = s
        .add_constraint(PointAtParameter {
            curve: c,
            u: 0.0,
            target: Target::At(Point2::new(5.0, 1.0)),
        })
        .unwrap();
    let err = s.solve().unwrap_err();
    assert!(
        matches!(err, Error::OrientationFlipped { constraint, .. } if constraint == tangent),
        "{err:?}"
    );
    assert_eq!(s.entity(c).unwrap(), &before);

    // Behind P₁ instead (t = 2 > 0) the same system solves, the sense kept.
    s.remove_constraint(ahead).unwrap();
    s.add_constraint(PointAtParameter {
        curve: c,
        u: 0.0,
        target: Target::At(Point2::new(-1.0, 1.0)),
    })
    .unwrap();
    s.solve().unwrap();
    let p0 = s.point(PointRef::Control(c, 0)).unwrap();
    let p1 = s.point(PointRef::Control(c, 1)).unwrap();
    assert_abs_diff_eq!(p0, Point2::new(-1.0, 1.0), epsilon = 1e-12);
    assert_abs_diff_eq!(p1, Point2::new(1.0, 1.0), epsilon = 1e-12);
}
