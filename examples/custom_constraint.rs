//! A constraint of your own, written once and solved with no derivative code: the curvature of a
//! cubic Bézier at a parameter u must equal a prescribed value, while its end points stay put and
//! its end tangents keep their directions.
//!
//! Run with `cargo run --release --example custom_constraint`.

use camber::geom::queries::signed_curvature;
use camber::geom::scalar::cst;
use camber::geom::{BezierCurve2, ParametricCurve};
use camber::solve::{solve, ConstraintId, Options, Problem, Residual, Scalar};
use nalgebra::{Point2, Vector2};

/// κ(u) − κ*, with κ = cross(C′, C″)/|C′|³ the signed curvature (1/length, positive where the
/// curve turns left). It reads the four control points, one block (x, y) each.
#[derive(Debug)]
struct CurvatureAt {
    u: f64,
    curvature: f64,
}

impl Residual for CurvatureAt {
    fn name(&self) -> &str {
        "curvature at u"
    }

    fn dim(&self) -> usize {
        1
    }

    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2; 4])
    }

    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let points: Vec<Point2<T>> = x.iter().map(|p| Point2::new(p[0], p[1])).collect();
        // The same camber-geom code that evaluates f64 curves runs here on dual numbers. A
        // degenerate curve gives NaN, which the solver reports as a non-finite residual.
        out[0] = BezierCurve2::try_new(points)
            .and_then(|curve| curve.second_order(cst(self.u)))
            .map(|[_, d1, d2]| {
                let speed = d1.norm();
                (d1.x * d2.y - d1.y * d2.x) / (speed * speed * speed) - cst::<T>(self.curvature)
            })
            .unwrap_or_else(|_| cst(f64::NAN));
    }
}

/// The end tangents keep their directions: cross(P₁ − P₀, T₀) = 0 and cross(P₃ − P₂, T₁) = 0.
/// Affine in the control points, which the solver can exploit.
#[derive(Debug)]
struct EndTangentDirections {
    start: Vector2<f64>,
    end: Vector2<f64>,
}

impl Residual for EndTangentDirections {
    fn name(&self) -> &str {
        "end tangent directions"
    }

    fn dim(&self) -> usize {
        2
    }

    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2; 4])
    }

    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let cross = |a: &[T], b: &[T], d: &Vector2<f64>| {
            (b[0] - a[0]) * cst::<T>(d.y) - (b[1] - a[1]) * cst::<T>(d.x)
        };
        out[0] = cross(x[0], x[1], &self.start);
        out[1] = cross(x[2], x[3], &self.end);
    }

    fn is_affine(&self) -> bool {
        true
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let start = [[0.0, 0.0], [1.0, 1.0], [2.0, 1.0], [3.0, 0.0]];
    let before = BezierCurve2::try_new(start.iter().map(|p| Point2::new(p[0], p[1])).collect())?;
    // At u = ½: C′ = (3, 0), C″ = (0, −6), so κ = −18/27 = −2/3.
    println!(
        "curvature at u = 0.5 before: {:.6}",
        signed_curvature(&before, 0.5)?
    );

    let mut problem = Problem::new();
    let blocks = start
        .iter()
        .map(|p| problem.add_block(p))
        .collect::<Result<Vec<_>, _>>()?;
    problem.fix_block(blocks[0])?;
    problem.fix_block(blocks[3])?;
    let target = -1.2;
    problem.add_residual(
        EndTangentDirections {
            start: Vector2::new(1.0, 1.0),
            end: Vector2::new(1.0, -1.0),
        },
        &blocks,
        ConstraintId(1),
    )?;
    problem.add_residual(
        CurvatureAt {
            u: 0.5,
            curvature: target,
        },
        &blocks,
        ConstraintId(2),
    )?;

    let report = solve(&mut problem, &Options::default())?;
    println!(
        "solved by {:?} in {} iterations ({}); DOF left {}, moved {:.4}",
        report.solver, report.iterations, report.reason, report.dof, report.displacement_norm
    );

    let solved: Vec<Point2<f64>> = blocks
        .iter()
        .map(|&b| problem.block_values(b).map(|v| Point2::new(v[0], v[1])))
        .collect::<Result<_, _>>()?;
    let after = BezierCurve2::try_new(solved.clone())?;
    let achieved = signed_curvature(&after, 0.5)?;
    println!("curvature at u = 0.5 after:  {achieved:.12} (target {target})");
    for (i, p) in solved.iter().enumerate() {
        println!("  P{i} = ({:.6}, {:.6})", p.x, p.y);
    }
    if (achieved - target).abs() > 1e-9 {
        return Err("the solved curve misses the prescribed curvature".into());
    }
    Ok(())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}
