//! One path segment to one camber entity, in the sketch's frame: lines to [`Entity::Line`],
//! quadratic and cubic Béziers to [`Entity::Bezier`] of degree 2 and 3 with their control
//! points mapped (an affine map of a Bézier curve is the Bézier curve of the mapped control
//! points), arcs to [`Entity::Arc`] when the mapped ellipse is a circle and to
//! [`Entity::EllipticArc`] otherwise, their ends being the mapped ends of the command exactly
//! (so joins coincide bit for bit) and their centre and axes from [`super::ellipse_map`].

use camber_geom::arc::MIN_SWEEP;
use camber_geom::BezierCurve2;
use camber_sketch::Entity;
use nalgebra::Point2;

use super::affine::Affine;
use super::arc::{centre_form, ArcShape};
use super::commands::Shape;
use super::ellipse_map::map_arc;

/// A segment made into an entity.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Built {
    /// The entity.
    pub(crate) entity: Entity,
    /// Whether it runs from the path's end of the segment to its start (an arc whose
    /// counter-clockwise travel is against the path's).
    pub(crate) reversed: bool,
    /// Something worth saying about how it was made (an arc too flat for the kernel made a
    /// line).
    pub(crate) note: Option<String>,
}

/// What became of a segment.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Outcome {
    /// An entity.
    Built(Built),
    /// Nothing, for the reason given.
    Skipped(String),
}

/// The entity of `shape` under `map` (see the module documentation); segments whose points
/// all lie within `length_tolerance` of their start are skipped.
pub(crate) fn build(shape: &Shape, map: &Affine, length_tolerance: f64) -> Outcome {
    let points: Vec<Point2<f64>> = match shape {
        Shape::Line(p) => p.iter().map(|q| map.apply(*q)).collect(),
        Shape::Quadratic(p) => p.iter().map(|q| map.apply(*q)).collect(),
        Shape::Cubic(p) => p.iter().map(|q| map.apply(*q)).collect(),
        Shape::Arc(a) => return arc(a, map, length_tolerance),
    };
    if let Some(reason) = no_length(&points, length_tolerance) {
        return Outcome::Skipped(reason);
    }
    let entity = match points.as_slice() {
        [a, b] => Entity::Line([*a, *b]),
        _ => match BezierCurve2::try_new(points) {
            Ok(c) => Entity::Bezier(c),
            Err(e) => return Outcome::Skipped(format!("the curve cannot be made: {e}")),
        },
    };
    Outcome::Built(Built {
        entity,
        reversed: false,
        note: None,
    })
}

fn no_length(points: &[Point2<f64>], tolerance: f64) -> Option<String> {
    let first = points.first()?;
    points
        .iter()
        .all(|p| (p - first).norm() <= tolerance)
        .then(|| format!("it has no length: every point lies within {tolerance:e} of its start"))
}

fn line(from: Point2<f64>, to: Point2<f64>, tolerance: f64, note: Option<String>) -> Outcome {
    match no_length(&[from, to], tolerance) {
        Some(reason) => Outcome::Skipped(reason),
        None => Outcome::Built(Built {
            entity: Entity::Line([from, to]),
            reversed: false,
            note,
        }),
    }
}

fn arc(a: &super::arc::EndpointArc, map: &Affine, tolerance: f64) -> Outcome {
    let (from, to) = (map.apply(a.from), map.apply(a.to));
    let centre = match centre_form(a) {
        ArcShape::Nothing => {
            return Outcome::Skipped(
                "its ends are the same point, which draws nothing (SVG omits such an arc)".into(),
            )
        }
        ArcShape::Line => return line(from, to, tolerance, None),
        ArcShape::OutOfRange => {
            return Outcome::Skipped(format!(
                "its radii ({}, {}) put its centre out of f64's range",
                a.rx, a.ry
            ))
        }
        ArcShape::Arc(c) => c,
    };
    let sweep = centre.sweep.abs();
    if sweep < MIN_SWEEP {
        return line(
            from,
            to,
            tolerance,
            Some(format!(
                "an arc of sweep {sweep:e} rad, below the kernel's least sweep {MIN_SWEEP:e}, made the line between its ends"
            )),
        );
    }
    if sweep > std::f64::consts::TAU - MIN_SWEEP {
        return Outcome::Skipped(format!(
            "its sweep {sweep} rad is within {MIN_SWEEP:e} of a full turn, which the kernel's arcs cannot hold"
        ));
    }
    let Some((e, reversed)) = map_arc(map, &centre) else {
        return Outcome::Skipped("its transformed ellipse is degenerate (a singular map)".into());
    };
    let (start, end) = if reversed { (to, from) } else { (from, to) };
    let entity = if e.is_circle() {
        Entity::Arc([e.centre, start, end])
    } else {
        Entity::EllipticArc {
            points: [e.centre, e.centre + e.a_axis * e.a, start, end],
            semi_axis_b: e.b,
        }
    };
    Outcome::Built(Built {
        entity,
        reversed,
        note: None,
    })
}
