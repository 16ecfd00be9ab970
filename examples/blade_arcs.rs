//! The blade section drawn as designers draw it: pressure and suction sides as Bézier curves,
//! an elliptic leading edge and a circular trailing edge, each arc joined G1 to both sides
//! (`coincident` at the ends, `elliptic_arc_tangent_to_curve` and `arc_tangent_to_curve` for
//! the tangents, senses kept), the trailing-edge circle's centre and radius fixed. The example
//! loads the bundled sketch, prints the DOF analysis, drags the leading edge's centre forward
//! and its vertex round, and checks every joint with an independent evaluation: the sides'
//! end tangents from their Bézier control points, the arcs' directions of travel from their
//! centres and axes. It exits non-zero when a joint opens, a tangent turns or flips, or the
//! trailing edge moves.
//!
//! Run with `cargo run --example blade_arcs`.

use camber::sketch::constraints::arc_tangent_to_line::ArcEnd;
use camber::sketch::{file, Constraint, Entity, EntityId, PointRef, Sense, Sketch};
use nalgebra::{Point2, Vector2};

/// The bundled file (examples/sketches/blade_arcs.json).
pub const BLADE: &str = include_str!("sketches/blade_arcs.json");

/// The leading-edge elliptic arc of the bundled file.
pub const LEADING_EDGE: EntityId = EntityId(1);
/// The trailing-edge circular arc of the bundled file.
pub const TRAILING_EDGE: EntityId = EntityId(3);

/// A Bézier side's end point and tangent C′ there, from its control points: C(0) = P₀,
/// C′(0) = n(P₁ − P₀), C(1) = Pₙ, C′(1) = n(Pₙ − Pₙ₋₁).
fn side_end(s: &Sketch, e: EntityId, end: ArcEnd) -> Result<(Point2<f64>, Vector2<f64>), String> {
    let Entity::Bezier(c) = s.entity(e).map_err(|e| e.to_string())? else {
        return Err(format!("entity {e} is not a Bézier curve"));
    };
    let p = c.control_points();
    let n = p.len() - 1;
    Ok(match end {
        ArcEnd::Start => (p[0], (p[1] - p[0]) * n as f64),
        ArcEnd::End => (p[n], (p[n] - p[n - 1]) * n as f64),
    })
}

/// An arc's end point and its counter-clockwise direction of travel there. A circular arc
/// [C, S, E] travels along rot₉₀(P − C); an elliptic arc [C, V, S, E] with minor semi-axis b,
/// in its frame u = (V − C)/a, v = rot₉₀(u), at the parametric angle φ of P, along
/// −a·sin φ·u + b·cos φ·v.
fn arc_end(s: &Sketch, e: EntityId, end: ArcEnd) -> Result<(Point2<f64>, Vector2<f64>), String> {
    let rot = |w: Vector2<f64>| Vector2::new(-w.y, w.x);
    match s.entity(e).map_err(|e| e.to_string())? {
        Entity::Arc(b) => {
            let p = b[end.block()];
            Ok((p, rot(p - b[0])))
        }
        Entity::EllipticArc {
            points,
            semi_axis_b,
        } => {
            let (c, vertex) = (points[0], points[1]);
            let p = points[if end == ArcEnd::Start { 2 } else { 3 }];
            let a = (vertex - c).norm();
            let u = (vertex - c) / a;
            let v = rot(u);
            let phi = ((p - c).dot(&v) / semi_axis_b).atan2((p - c).dot(&u) / a);
            Ok((p, u * (-a * phi.sin()) + v * (semi_axis_b * phi.cos())))
        }
        _ => Err(format!("entity {e} is not an arc")),
    }
}

/// Every arc–side joint of the sketch: the widest gap between the arc's end and the side's
/// end, and the largest |sin| of the angle between the arc's travel and the side's tangent.
/// Fails when a tangent turned against the constraint's sense.
pub fn check_joints(s: &Sketch) -> Result<(f64, f64, usize), String> {
    let (mut gap, mut sin, mut count) = (0.0_f64, 0.0_f64, 0);
    for (id, c) in s.constraints() {
        let (arc, end, curve, curve_end, sense) = match c {
            Constraint::ArcTangentToCurve(t) => (t.arc, t.end, t.curve, t.curve_end, t.sense),
            Constraint::EllipticArcTangentToCurve(t) => {
                (t.arc, t.end, t.curve, t.curve_end, t.sense)
            }
            _ => continue,
        };
        let (p, travel) = arc_end(s, arc, end)?;
        let (q, tangent) = side_end(s, curve, curve_end)?;
        gap = gap.max((p - q).norm());
        let sign = if sense == Sense::Agree { 1.0 } else { -1.0 };
        if sign * travel.dot(&tangent) <= 0.0 {
            return Err(format!(
                "joint {id}: the arc's travel turned against its sense"
            ));
        }
        sin = sin.max(
            (travel.x * tangent.y - travel.y * tangent.x).abs() / (travel.norm() * tangent.norm()),
        );
        count += 1;
    }
    Ok((gap, sin, count))
}

/// Loads the bundled blade, drags its leading edge and checks every joint after each drag.
pub fn run() -> Result<(), Box<dyn std::error::Error>> {
    let mut sketch = file::from_json(BLADE)?;
    for a in sketch.analyze()? {
        println!(
            "{} entities, {} constraints: {} free unknowns, rank {}, DOF {}",
            a.component.entities.len(),
            a.component.constraints.len(),
            a.analysis.free_unknowns,
            a.analysis.rank,
            a.analysis.dof
        );
    }
    let trailing = sketch.entity(TRAILING_EDGE)?.clone();
    let (_, _, joints) = check_joints(&sketch)?;
    if joints != 4 {
        return Err(format!("expected four arc joints, found {joints}").into());
    }

    // Drag the leading edge's centre forward by 0.01 in 20 steps, then its vertex (the end of
    // its a-axis) round by 0.01 upwards: the sides and both joints follow.
    for (point, step) in [
        (
            PointRef::Control(LEADING_EDGE, 0),
            Vector2::new(-0.0005, 0.0),
        ),
        (
            PointRef::Control(LEADING_EDGE, 1),
            Vector2::new(0.0, 0.0005),
        ),
    ] {
        let start = sketch.point(point)?;
        let mut drag = sketch.drag(point)?;
        let clock = std::time::Instant::now();
        for k in 1..=20 {
            drag.update(start + step * f64::from(k))?;
        }
        let per_update = clock.elapsed() / 20;
        drag.finish(&mut sketch)?;
        let end = sketch.point(point)?;
        println!(
            "{point} moved from ({:.4}, {:.4}) to ({:.4}, {:.4}), {per_update:?} per update",
            start.x, start.y, end.x, end.y
        );
        let (gap, sin, _) = check_joints(&sketch)?;
        println!("joints: widest gap {gap:.1e}, largest tangent angle sin {sin:.1e}");
        if gap > 1e-9 || sin > 1e-9 {
            return Err("an arc joint is not held".into());
        }
    }

    // The trailing edge's centre and radius are fixed; only its ends slide round it.
    let (Entity::Arc(before), Entity::Arc(after)) = (&trailing, sketch.entity(TRAILING_EDGE)?)
    else {
        return Err("the trailing edge is not an arc".into());
    };
    let radius = (after[1] - after[0]).norm();
    if (after[0] - before[0]).norm() > 1e-12 || (radius - 0.004).abs() > 1e-12 {
        return Err("the trailing edge's centre or radius moved".into());
    }
    // The edited blade saves and loads back to the same file.
    let saved = file::to_json(&sketch)?;
    if file::to_json(&file::from_json(&saved)?)? != saved {
        return Err("the edited blade does not round-trip".into());
    }
    println!("checked: arc joints closed and tangent with their senses, trailing edge fixed, file round-trips");
    Ok(())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("blade_arcs: {e}");
        std::process::exit(1);
    }
}
