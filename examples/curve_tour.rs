//! A tour of camber's geometry kernel on a blade-like suction side: evaluation, knot insertion,
//! splitting and the joint report, degree elevation, closest points, intersections and JSON.
//!
//! Run with `cargo run --release --example curve_tour`.

use camber::geom::queries::{closest_point, intersect_circle, signed_distance_to_circle};
use camber::geom::{
    BSplineCurve2, Circle, CompositeCurve2, HermiteCurve2, KnotVector, Line, NurbsCurve2,
    ParametricCurve,
};
use nalgebra::{Point2, Vector2};

/// The suction side of a thin blade section: a clamped cubic B-spline with 8 control points,
/// chord along x from the leading edge (0, 0) to the trailing edge (1, 0).
fn suction_side() -> camber::geom::Result<BSplineCurve2<f64>> {
    let control_points = vec![
        Point2::new(0.0, 0.0),
        Point2::new(0.0, 0.035),
        Point2::new(0.08, 0.085),
        Point2::new(0.25, 0.11),
        Point2::new(0.45, 0.105),
        Point2::new(0.68, 0.075),
        Point2::new(0.88, 0.03),
        Point2::new(1.0, 0.0),
    ];
    let knots = KnotVector::clamped_uniform(3, control_points.len())?;
    BSplineCurve2::try_new(3, knots, control_points)
}

/// Largest distance between two curves sampled at the same parameters.
fn max_deviation(
    a: &dyn ParametricCurve<f64, 2>,
    b: &dyn ParametricCurve<f64, 2>,
) -> camber::geom::Result<f64> {
    let mut worst: f64 = 0.0;
    for i in 0..=200 {
        let u = f64::from(i) / 200.0;
        worst = worst.max((a.point(u)? - b.point(u)?).norm());
    }
    Ok(worst)
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let curve = suction_side()?;
    println!(
        "suction side: degree {}, {} control points, knots {:?}",
        curve.degree(),
        curve.control_points().len(),
        curve.knots().as_slice()
    );
    for u in [0.0, 0.25, 0.5, 0.75, 1.0] {
        let (p, d) = curve.point_and_derivative(u)?;
        println!(
            "  C({u:.2}) = ({:.5}, {:.5})   C'({u:.2}) = ({:.4}, {:.4})",
            p.x, p.y, d.x, d.y
        );
    }

    // Representation changes leave the curve where it was.
    let refined = curve.insert_knot(0.3, 2)?;
    let elevated = curve.elevate_degree(1)?;
    println!(
        "knot 0.3 inserted twice: {} control points, deviation {:.1e}",
        refined.control_points().len(),
        max_deviation(&curve, &refined)?
    );
    println!(
        "degree elevated to {}: {} control points, deviation {:.1e}",
        elevated.degree(),
        elevated.control_points().len(),
        max_deviation(&curve, &elevated)?
    );

    // Split at the thickest point and check the joint of the two halves.
    let (front, back) = curve.split(0.4)?;
    let chain = CompositeCurve2::try_new(vec![Box::new(front), Box::new(back)])?;
    let joint = &chain.joints()?[0];
    println!(
        "split at 0.4: gap {:.1e}, tangent angle {:.1e} rad, |dC''| {:.1e} -> {:?}",
        joint.position_gap,
        joint.tangent_angle,
        joint.second_derivative_mismatch,
        joint.continuity(&Default::default())
    );

    // Leading-edge circle: how close does the curve come to its centre?
    let leading_edge = Circle::try_new(Point2::new(0.03, 0.0), 0.03)?;
    let nearest = closest_point(&curve, leading_edge.center())?;
    let clearance = signed_distance_to_circle(&curve, &leading_edge)?;
    println!(
        "leading-edge circle: nearest curve point at u = {:.4}, distance to centre {:.5}, \
              min |C - c| - r = {:.5} at u = {:.4}",
        nearest.parameter, nearest.distance, clearance.distance, clearance.parameter
    );
    // The curve starts on the circle with a vertical tangent: it touches it there only.
    let meets: Vec<String> = intersect_circle(&curve, &leading_edge)?
        .iter()
        .map(|hit| format!("{:.4}", hit.parameter))
        .collect();
    println!(
        "  the curve meets that circle at u = [{}]",
        meets.join(", ")
    );

    // A vertical line through mid-chord meets the suction side once.
    let mid_chord = Line::try_new(Point2::new(0.5, 0.0), Vector2::new(0.0, 1.0))?;
    for hit in camber::geom::queries::intersect_line(&curve, &mid_chord)? {
        println!(
            "mid-chord line: u = {:.6}, thickness there {:.5}",
            hit.parameter, hit.point.y
        );
    }

    // A NURBS quarter circle is exact; a cubic Hermite piece converts to Bezier form.
    let arc = NurbsCurve2::try_circular_arc(
        Point2::new(0.0, 0.0),
        1.0,
        0.0,
        std::f64::consts::FRAC_PI_2,
    )?;
    println!(
        "NURBS quarter circle: |C(0.37)| = {:.15}",
        arc.point(0.37)?.coords.norm()
    );
    let hermite = HermiteCurve2::try_new(
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 0.0),
        Vector2::new(1.0, 1.0),
        Vector2::new(1.0, -1.0),
    )?;
    let thirds = hermite.subdivided(3)?;
    let bezier: Vec<String> = thirds[1]
        .to_bezier()?
        .control_points()
        .iter()
        .map(|p| format!("({:.4}, {:.4})", p.x, p.y))
        .collect();
    println!(
        "Hermite cubic in three pieces; the middle one as a Bezier curve: {}",
        bezier.join(" ")
    );

    // Curves save as JSON and load back through the same validation as try_new.
    let json = serde_json::to_string(&curve)?;
    let back: BSplineCurve2<f64> = serde_json::from_str(&json)?;
    println!(
        "JSON ({} bytes) round trip equal: {}",
        json.len(),
        back == curve
    );
    Ok(())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}
