//! The diffuser airfoil: a clamped cubic B-spline with seven control points held tangent to a
//! leading-edge circle, a thickness circle (at a free contact parameter) and a trailing-edge
//! circle, solved from a rough start and then dragged. Prints which solver ran and why, the
//! contact parameter, and the clearance to each circle; exits non-zero when the curve crosses
//! a circle or leaves the thickness circle.
//!
//! Run with `cargo run --example diffuser_airfoil`.

use camber::geom::queries::closest_point;
use camber::geom::{BSplineCurve2, KnotVector};
use camber::sketch::constraints::{Fixed, TangentToCircle};
use camber::sketch::{CircleSide, Constraint, Contact, Entity, PointRef, Rotation, Sketch};
use nalgebra::Point2;

/// Centre and radius of the leading-edge, thickness and trailing-edge circles.
const CIRCLES: [([f64; 2], f64); 3] = [
    ([0.03, 0.0], 0.03),
    ([0.38, 0.04], 0.07),
    ([0.985, 0.01], 0.015),
];

fn on_circle(k: usize, degrees: f64) -> Point2<f64> {
    let ((c, r), a) = (CIRCLES[k], degrees.to_radians());
    Point2::new(c[0] + r * a.cos(), c[1] + r * a.sin())
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let start = vec![
        on_circle(0, 110.0),
        Point2::new(0.07, 0.06),
        Point2::new(0.18, 0.115),
        Point2::new(0.38, 0.125),
        Point2::new(0.62, 0.10),
        Point2::new(0.86, 0.045),
        on_circle(2, 70.0),
    ];
    let knots = KnotVector::try_new(vec![
        0.0, 0.0, 0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0, 1.0, 1.0,
    ])?;
    let mut sketch = Sketch::new();
    let curve = sketch.add_bspline(BSplineCurve2::try_new(3, knots, start)?)?;
    let mut circles = Vec::new();
    let mut thickness_contact = None;
    for (k, u) in [Contact::At(0.0), Contact::Free(0.45), Contact::At(1.0)]
        .into_iter()
        .enumerate()
    {
        let (c, r) = CIRCLES[k];
        let circle = sketch.add_circle(Point2::new(c[0], c[1]), r)?;
        sketch.add_constraint(Fixed::entity(circle))?;
        let id = sketch.add_constraint(TangentToCircle {
            curve,
            circle,
            u,
            side: CircleSide::Outside,
            rotation: Rotation::Clockwise,
        })?;
        if k == 1 {
            thickness_contact = Some(id);
        }
        circles.push(circle);
    }

    let report = sketch.solve()?;
    for c in &report.components {
        println!(
            "solved with {:?} in {} iterations: {}",
            c.report.solver, c.report.iterations, c.report.reason
        );
    }
    if let Some(id) = thickness_contact {
        if let Constraint::TangentToCircle(TangentToCircle { u, .. }) = sketch.constraint(id)? {
            println!("thickness contact at u = {:.6}", u.value());
        }
    }
    print_clearances(&sketch, curve)?;

    // Drag the middle control point upward in 50 small steps, then commit.
    let dragged = PointRef::Control(curve, 3);
    let p = sketch.point(dragged)?;
    let mut drag = sketch.drag(dragged)?;
    for k in 1..=50 {
        drag.update(Point2::new(p.x, p.y + 0.0004 * f64::from(k)))?;
    }
    drag.finish(&mut sketch)?;
    println!("after dragging P3 up by 0.02:");
    print_clearances(&sketch, curve)?;
    Ok(())
}

/// The least distance from each circle centre to the curve, minus the radius.
fn print_clearances(
    sketch: &Sketch,
    curve: camber::sketch::EntityId,
) -> Result<(), Box<dyn std::error::Error>> {
    let Entity::BSpline(c) = sketch.entity(curve)? else {
        return Err("the airfoil side is not a B-spline".into());
    };
    for ((centre, r), name) in CIRCLES.iter().zip(["LE", "TH", "TE"]) {
        let nearest = closest_point(c, &Point2::new(centre[0], centre[1]))?;
        let clearance = nearest.distance - r;
        println!(
            "  {name}: clearance {clearance:+.2e} at ({:.4}, {:.4})",
            nearest.point.x, nearest.point.y
        );
        // The curve touches TH and never comes inside any circle.
        if clearance < -1e-6 || (name == "TH" && clearance > 1e-6) {
            return Err(format!("the curve misses or crosses the {name} circle").into());
        }
    }
    Ok(())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("diffuser_airfoil: {e}");
        std::process::exit(1);
    }
}
