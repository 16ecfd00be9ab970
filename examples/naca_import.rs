//! A NACA 2412 section brought in from coordinates and constrained: its 161 points (cosine
//! spacing, from the four-digit formulas) are fitted within 1e-4 chord by one cubic B-spline
//! per side, split at the leading edge and joined G1; the two curves become a sketch with the
//! trailing-edge ends fixed and a free-direction G1 join at the leading edge, and the leading
//! edge is then dragged down by 1 % chord (a nose droop) in 20 steps. Prints the fit, the
//! droop and the join angle; exits non-zero when a constraint does not hold.
//!
//! Run with `cargo run --example naca_import`.

use camber::geom::fit::{fit_split, FitOptions, JointContinuity, SplitAt};
use camber::geom::{Budget, ParametricCurve};
use camber::sketch::constraints::{Fixed, G1JoinFree};
use camber::sketch::{Entity, EntityId, PointRef, Sketch};
use camber_workloads::airfoils::{naca, Spacing};
use nalgebra::Point2;

/// The fit tolerance (chord lengths).
pub const TOLERANCE: f64 = 1e-4;
/// How far the leading edge is moved down (chord lengths).
pub const DROOP: f64 = 0.01;

/// What the example did.
pub struct Imported {
    /// The section's data points (Selig order: upper surface from the trailing edge, then the
    /// lower one back).
    pub points: Vec<Point2<f64>>,
    /// The largest distance from a data point to its fitted side, as the fit measured it.
    pub fit_error: f64,
    /// The sketch after the droop.
    pub sketch: Sketch,
    /// The upper side: from the trailing edge to the leading edge.
    pub upper: EntityId,
    /// The lower side: from the leading edge back to the trailing edge.
    pub lower: EntityId,
    /// The leading edge before the droop.
    pub leading_edge: Point2<f64>,
}

/// Fits, builds the sketch and droops the nose.
pub fn run() -> Result<Imported, Box<dyn std::error::Error>> {
    let points = naca("2412", 161, Spacing::Cosine).ok_or("2412 is a four-digit NACA section")?;
    let fit = fit_split(
        &points,
        TOLERANCE,
        &FitOptions::default(),
        &SplitAt::LeadingEdge,
        JointContinuity::G1,
        &Budget::default(),
    )?;
    let [upper_fit, lower_fit] = fit.pieces.as_slice() else {
        return Err(format!("expected two sides, the fit has {}", fit.pieces.len()).into());
    };
    let mut sketch = Sketch::new();
    let upper = sketch.add_bspline(upper_fit.curve.clone())?;
    let lower = sketch.add_bspline(lower_fit.curve.clone())?;
    sketch.add_constraint(Fixed::point(PointRef::Start(upper)))?;
    sketch.add_constraint(Fixed::point(PointRef::End(lower)))?;
    sketch.add_constraint(G1JoinFree {
        first: upper,
        second: lower,
    })?;
    // The fit already meets every constraint: a solve moves nothing.
    sketch.solve()?;
    let leading_edge = sketch.point(PointRef::End(upper))?;
    let mut drag = sketch.drag(PointRef::End(upper))?;
    for k in 1..=20 {
        let down = DROOP * f64::from(k) / 20.0;
        drag.update(Point2::new(leading_edge.x, leading_edge.y - down))?;
    }
    drag.finish(&mut sketch)?;
    Ok(Imported {
        points,
        fit_error: fit.max_error,
        sketch,
        upper,
        lower,
        leading_edge,
    })
}

/// The angle (radians) between the upper side's end tangent and the lower side's start
/// tangent.
pub fn join_angle(sketch: &Sketch, upper: EntityId, lower: EntityId) -> Result<f64, String> {
    let (Ok(Entity::BSpline(a)), Ok(Entity::BSpline(b))) =
        (sketch.entity(upper), sketch.entity(lower))
    else {
        return Err("the sides are not B-splines".into());
    };
    let ta = a.derivative(a.domain().1).map_err(|e| e.to_string())?;
    let tb = b.derivative(b.domain().0).map_err(|e| e.to_string())?;
    Ok((ta.x * tb.y - ta.y * tb.x).atan2(ta.dot(&tb)))
}

#[allow(dead_code)] // the test that includes this file calls `run` instead
fn main() {
    let outcome = run().and_then(|i| {
        let now = i.sketch.point(PointRef::End(i.upper))?;
        let angle = join_angle(&i.sketch, i.upper, i.lower)?;
        println!(
            "NACA 2412: {} points fitted within {:.2e} chord by two cubic B-splines",
            i.points.len(),
            i.fit_error
        );
        println!(
            "leading edge ({:.5}, {:.5}) -> ({:.5}, {:.5}); G1 join angle {:.1e} rad",
            i.leading_edge.x, i.leading_edge.y, now.x, now.y, angle
        );
        if (now.y - (i.leading_edge.y - DROOP)).abs() > 1e-9 || angle.abs() > 1e-9 {
            return Err("the droop or the G1 join does not hold".into());
        }
        Ok(())
    });
    if let Err(e) = outcome {
        eprintln!("naca_import: {e}");
        std::process::exit(1);
    }
}
