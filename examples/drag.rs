//! A scripted drag: the W1 cubic, whose start tangent must keep the direction D, has its second
//! control point P₁ dragged around a small circle in 200 mouse events. Each update is timed and
//! printed; after each one the example checks the constraints itself (tangent parallel to D
//! and pointing along it, P₃ unmoved, P₁ at the target) and that P₀ moved by the least
//! possible amount (its distance to the new tangent line), and exits non-zero when any check
//! fails.
//!
//! Run with `cargo run --release --example drag`.

use std::time::Instant;

use camber::geom::BezierCurve2;
use camber::sketch::constraints::{Fixed, StartTangent};
use camber::sketch::{PointRef, Sense, Sketch, TangentForm};
use nalgebra::{Point2, Vector2};

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    // P₀ = (0, 0), P₁ = 1.2·D, P₂ = (2.2, 0.9), P₃ = (3, 0), D at 30°.
    let d = Vector2::new(30f64.to_radians().cos(), 30f64.to_radians().sin());
    let mut sketch = Sketch::new();
    let c = sketch.add_bezier(BezierCurve2::try_new(vec![
        Point2::origin(),
        Point2::from(1.2 * d),
        Point2::new(2.2, 0.9),
        Point2::new(3.0, 0.0),
    ])?)?;
    sketch.add_constraint(Fixed::point(PointRef::Control(c, 3)))?;
    sketch.add_constraint(StartTangent {
        curve: c,
        direction: d,
        sense: Sense::Agree,
        form: TangentForm::Row,
    })?;

    let cp = |k| PointRef::Control(c, k);
    let p1 = sketch.point(cp(1))?;
    let p3 = sketch.point(cp(3))?;
    // The session factorizes once; every update is then a pair of triangular solves.
    let mut drag = sketch.drag(cp(1))?;
    let mut times = Vec::with_capacity(200);
    for k in 1..=200 {
        let th = std::f64::consts::TAU * f64::from(k) / 200.0;
        let target = p1 + 0.2 * Vector2::new(th.cos() - 1.0, th.sin());
        let p0_before = drag.point(cp(0))?;
        let p2_before = drag.point(cp(2))?;

        let t0 = Instant::now();
        drag.update(target)?;
        let micros = t0.elapsed().as_secs_f64() * 1e6;
        times.push(micros);
        println!(
            "update {k:3}: P1 → ({:+.4}, {:+.4}) in {micros:6.2} µs",
            target.x, target.y
        );

        let [q0, q1, q2, q3] = [0, 1, 2, 3].map(|i| drag.point(cp(i)));
        let (q0, q1, q2, q3) = (q0?, q1?, q2?, q3?);
        let leg = q1 - q0;
        if (cross(leg, d) / leg.norm()).abs() >= 1e-7 || leg.dot(&d) <= 0.0 {
            return Err(format!("update {k}: the start tangent left D").into());
        }
        if (q3 - p3).norm() > 1e-12 || (q1 - target).norm() > 1e-9 {
            return Err(format!("update {k}: P3 moved or P1 missed the target").into());
        }
        // The least move of the free points: P₂ is unconstrained and stays; P₀ goes to the
        // nearest point of the line through the target along D.
        let least = cross(target - p0_before, d).abs();
        let moved = ((q0 - p0_before).norm_squared() + (q2 - p2_before).norm_squared()).sqrt();
        if (moved - least).abs() > 1e-9 * (1.0 + least) {
            return Err(
                format!("update {k}: moved {moved:.3e}, least possible {least:.3e}").into(),
            );
        }
    }
    drag.finish(&mut sketch)?;

    times.sort_by(f64::total_cmp);
    println!(
        "200 updates: median {:.2} µs, slowest {:.2} µs; every update kept the tangent and moved by the minimum norm",
        times[99], times[199]
    );
    Ok(())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("drag: {e}");
        std::process::exit(1);
    }
}
