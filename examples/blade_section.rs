//! A blade section held by the paper's tangency constraints: pressure side, leading edge,
//! suction side and trailing edge, four Béziers in a closed loop whose joints keep fixed
//! tangent directions (G1), with the trailing-edge corners fixed. The example loads the
//! bundled sketch file, prints the DOF analysis, drags the nose of the leading edge forward,
//! and checks every joint with an independent evaluation of the curves; it exits non-zero
//! when a joint opens, a tangent turns, or a fixed corner moves.
//!
//! Run with `cargo run --example blade_section`.

use camber::geom::ParametricCurve;
use camber::sketch::constraints::{Fixed, G1Join};
use camber::sketch::{file, Constraint, Entity, EntityId, FixTarget, PointRef, Sketch};
use nalgebra::{Point2, Vector2};

/// The bundled file (examples/sketches/blade_section.json).
const BLADE: &str = include_str!("sketches/blade_section.json");

/// Point and first derivative of a Bézier entity at u.
fn at(s: &Sketch, e: EntityId, u: f64) -> Result<(Point2<f64>, Vector2<f64>), String> {
    match s.entity(e).map_err(|e| e.to_string())? {
        Entity::Bezier(c) => c.point_and_derivative(u).map_err(|e| e.to_string()),
        _ => Err(format!("entity {e} is not a Bézier curve")),
    }
}

/// Checks every G1 joint: the end of `first` is the start of `second`, and both tangents
/// there are parallel to the joint direction and point along it. Returns the widest gap and
/// the largest |sin| between a tangent and its direction.
fn check_joints(s: &Sketch) -> Result<(f64, f64), String> {
    let (mut gap, mut sin) = (0.0_f64, 0.0_f64);
    for (id, c) in s.constraints() {
        let Constraint::G1Join(G1Join {
            first,
            second,
            direction,
        }) = c
        else {
            continue;
        };
        let (a, ta) = at(s, *first, 1.0)?;
        let (b, tb) = at(s, *second, 0.0)?;
        gap = gap.max((a - b).norm());
        for t in [ta, tb] {
            if t.dot(direction) <= 0.0 {
                return Err(format!(
                    "joint {id}: a tangent turned against its direction"
                ));
            }
            sin = sin
                .max((t.x * direction.y - t.y * direction.x).abs() / (t.norm() * direction.norm()));
        }
    }
    Ok((gap, sin))
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let mut sketch = file::from_json(BLADE)?;
    for a in sketch.analyze()? {
        println!(
            "{} curves, {} constraints: {} free unknowns, rank {}, DOF {}",
            a.component.entities.len(),
            a.component.constraints.len(),
            a.analysis.free_unknowns,
            a.analysis.rank,
            a.analysis.dof
        );
    }
    let fixed: Vec<(PointRef, Point2<f64>)> = sketch
        .constraints()
        .filter_map(|(_, c)| match c {
            Constraint::Fixed(Fixed {
                target: FixTarget::Point(p),
            }) => Some(*p),
            _ => None,
        })
        .map(|p| sketch.point(p).map(|at| (p, at)))
        .collect::<Result<_, _>>()?;

    // Drag the nose of the leading edge (entity 1, its middle control points) forward by
    // 0.004 in 20 steps; the joints on both sides follow.
    let nose = PointRef::Control(EntityId(1), 2);
    let start = sketch.point(nose)?;
    let mut drag = sketch.drag(nose)?;
    for k in 1..=20 {
        drag.update(start + Vector2::new(-0.0002 * f64::from(k), 0.0))?;
    }
    drag.finish(&mut sketch)?;
    println!(
        "nose moved from ({:.4}, {:.4}) to ({:.4}, {:.4})",
        start.x,
        start.y,
        sketch.point(nose)?.x,
        sketch.point(nose)?.y
    );

    let (gap, sin) = check_joints(&sketch)?;
    println!("joints: widest gap {gap:.1e}, largest tangent angle sin {sin:.1e}");
    if gap > 1e-9 || sin > 1e-9 {
        return Err("a G1 joint is not held".into());
    }
    for (p, was) in fixed {
        if (sketch.point(p)? - was).norm() > 1e-12 {
            return Err("a fixed trailing-edge corner moved".into());
        }
    }
    // The edited blade saves and loads back to the same file.
    let saved = file::to_json(&sketch)?;
    if file::to_json(&file::from_json(&saved)?)? != saved {
        return Err("the edited blade does not round-trip".into());
    }
    println!("checked: joints closed and tangent, corners fixed, file round-trips");
    Ok(())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("blade_section: {e}");
        std::process::exit(1);
    }
}
