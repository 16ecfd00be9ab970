//! Two curves tangent to circles, to lines and to each other: an arch leaving along an inlet
//! line and arriving on a circle, and a valley leaving from another circle and arriving along
//! an outlet line, which must touch each other at parameters that are themselves unknowns.
//! These constraints are nonlinear, so the solve goes through Newton (or SLSQP); the example
//! prints which solver ran, the contact parameters, and then checks the solved geometry with
//! an independent evaluation, exiting non-zero when it is wrong.
//!
//! The same sketch is bundled as examples/sketches/two_curves.json.
//!
//! Run with `cargo run --example two_curves`.

use camber::geom::BezierCurve2;
use camber::sketch::constraints::{CurveCurveTangent, Fixed, TangentToCircle, TangentToLine};
use camber::sketch::{CircleSide, Constraint, Contact, LineSide, Rotation, Sense, Sketch};
use camber_workloads::{two_curves_valid, TwoCurves, TWO_CURVES_CIRCLES};
use nalgebra::Point2;

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let pts = |v: [(f64, f64); 4]| v.iter().map(|&(x, y)| Point2::new(x, y)).collect();
    let mut sketch = Sketch::new();
    let lower = sketch.add_bezier(BezierCurve2::try_new(pts([
        (0.0, 0.0),
        (1.5, 1.4),
        (2.5, 1.4),
        (4.0, 0.0),
    ]))?)?;
    let upper = sketch.add_bezier(BezierCurve2::try_new(pts([
        (0.0, 2.5),
        (1.5, 0.9),
        (2.5, 0.9),
        (4.0, 2.5),
    ]))?)?;
    // The walls: lines and circles that do not move.
    let inlet = sketch.add_line(Point2::new(-1.5, -1.4), Point2::new(0.0, 0.0))?;
    let outlet = sketch.add_line(Point2::new(4.0, 2.5), Point2::new(5.5, 4.1))?;
    let [(lc, lr), (rc, rr)] = TWO_CURVES_CIRCLES;
    let left = sketch.add_circle(Point2::new(lc[0], lc[1]), lr)?;
    let right = sketch.add_circle(Point2::new(rc[0], rc[1]), rr)?;
    for e in [inlet, outlet, left, right] {
        sketch.add_constraint(Fixed::entity(e))?;
    }

    // The arch leaves along the inlet (curving to its right) and arrives on the right circle.
    sketch.add_constraint(TangentToLine {
        curve: lower,
        line: inlet,
        u: Contact::At(0.0),
        side: LineSide::Right,
        sense: Sense::Agree,
    })?;
    sketch.add_constraint(TangentToCircle {
        curve: lower,
        circle: right,
        u: Contact::At(1.0),
        side: CircleSide::Outside,
        rotation: Rotation::Clockwise,
    })?;
    // The valley leaves from the left circle and arrives along the outlet.
    sketch.add_constraint(TangentToCircle {
        curve: upper,
        circle: left,
        u: Contact::At(0.0),
        side: CircleSide::Outside,
        rotation: Rotation::CounterClockwise,
    })?;
    sketch.add_constraint(TangentToLine {
        curve: upper,
        line: outlet,
        u: Contact::At(1.0),
        side: LineSide::Left,
        sense: Sense::Agree,
    })?;
    // They start 0.25 apart and must touch where they like: u and v are unknowns.
    let touch = sketch.add_constraint(CurveCurveTangent {
        first: lower,
        u: Contact::Free(0.5),
        second: upper,
        v: Contact::Free(0.5),
        sense: Sense::Agree,
    })?;

    for a in sketch.analyze()? {
        if !a.component.constraints.is_empty() {
            println!(
                "{} entities, {} constraints: DOF {}",
                a.component.entities.len(),
                a.component.constraints.len(),
                a.analysis.dof
            );
        }
    }
    let report = sketch.solve()?;
    for c in &report.components {
        println!(
            "solved with {:?} in {} iterations ({})",
            c.report.solver, c.report.iterations, c.report.reason
        );
    }
    if let Constraint::CurveCurveTangent(CurveCurveTangent { u, v, .. }) =
        sketch.constraint(touch)?
    {
        let p = sketch.curve_point(lower, u.value())?;
        println!(
            "the curves touch at u = {:.6}, v = {:.6}, point ({:.4}, {:.4})",
            u.value(),
            v.value(),
            p.x,
            p.y
        );
    }

    let ids = TwoCurves {
        lower,
        upper,
        inlet,
        outlet,
        left,
        right,
    };
    if !two_curves_valid(&sketch, &ids, 1e-6) {
        return Err("the solved curves miss a line, a circle or each other".into());
    }
    println!("checked: both lines, both circles and the touch hold to 1e-6");
    Ok(())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("two_curves: {e}");
        std::process::exit(1);
    }
}
