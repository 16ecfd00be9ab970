//! Sketch → DXF: every sketch entity as the DXF entity of the same geometry, on the layer
//! named by its tag.

use std::collections::BTreeSet;
use std::f64::consts::{FRAC_PI_2, TAU};

use camber_sketch::ellipse_blocks::{ellipse_of_blocks, elliptic_arc_of_blocks};
use camber_sketch::entity::arc_of_blocks;
use camber_sketch::{Entity, EntityId, Sketch};
use dxf::entities::{self as de, EntityType};
use dxf::enums::AcadVersion;
use nalgebra::{Point2, Vector2};

use super::{Error, Form, MAX_SPLINE_ITEMS};

/// The characters a DXF layer name may not hold.
const LAYER_FORBIDDEN: &[char] = &['<', '>', '/', '\\', '"', ':', ';', '?', '*', '|', '=', '`'];

pub(super) fn write(sketch: &Sketch, form: Form) -> Result<Vec<u8>, Error> {
    let mut drawing = dxf::Drawing::new();
    drawing.header.version = AcadVersion::R2000;
    let mut layers = BTreeSet::new();
    for (id, entity) in sketch.entities() {
        let specific = specific(id, entity)?;
        let mut e = de::Entity::new(specific);
        if let Some(tag) = sketch.tag(id) {
            check_layer(id, tag)?;
            e.common.layer = tag.to_owned();
            layers.insert(tag.to_owned());
        }
        drawing.add_entity(e);
    }
    for name in layers {
        drawing.add_layer(dxf::tables::Layer {
            name,
            ..Default::default()
        });
    }
    let mut out = Vec::new();
    let saved = match form {
        Form::Text => drawing.save(&mut out),
        Form::Binary => drawing.save_binary(&mut out),
    };
    saved.map_err(|e| Error::Write {
        message: e.to_string(),
    })?;
    Ok(out)
}

/// Refuses a tag that a DXF reader would not take as a layer name.
fn check_layer(entity: EntityId, tag: &str) -> Result<(), Error> {
    let reason = if tag.contains(LAYER_FORBIDDEN) {
        Some("a layer name holds none of < > / \\ \" : ; ? * | = `")
    } else if tag.trim() != tag {
        Some("a layer name neither starts nor ends with a space")
    } else {
        None
    };
    match reason {
        Some(reason) => Err(Error::LayerName {
            entity,
            tag: tag.to_owned(),
            reason,
        }),
        None => Ok(()),
    }
}

fn point(p: &Point2<f64>) -> dxf::Point {
    dxf::Point::new(p.x, p.y, 0.0)
}

/// The DXF entity of one sketch entity.
fn specific(id: EntityId, entity: &Entity) -> Result<EntityType, Error> {
    // Entities in a sketch are valid by construction; a failure here is the sketch's own
    // inconsistency, reported rather than hidden.
    let invalid = |e: camber_geom::Error| Error::Sketch(camber_sketch::Error::Geometry(e));
    Ok(match entity {
        Entity::Point(p) => EntityType::ModelPoint(de::ModelPoint::new(point(p))),
        Entity::Line([a, b]) => EntityType::Line(de::Line::new(point(a), point(b))),
        Entity::Circle { center, radius } => {
            EntityType::Circle(de::Circle::new(point(center), *radius))
        }
        Entity::Arc(blocks) => {
            let arc = arc_of_blocks(blocks).map_err(invalid)?;
            let start = arc.start_angle().to_degrees();
            let end = (arc.start_angle() + arc.sweep()).to_degrees();
            EntityType::Arc(de::Arc::new(point(arc.center()), arc.radius(), start, end))
        }
        Entity::Ellipse {
            points,
            semi_axis_b,
        } => {
            let e = ellipse_of_blocks(points, *semi_axis_b).map_err(invalid)?;
            ellipse(
                e.center(),
                e.semi_axis_a(),
                e.semi_axis_b(),
                e.rotation(),
                0.0,
                TAU,
            )
        }
        Entity::EllipticArc {
            points,
            semi_axis_b,
        } => {
            let arc = elliptic_arc_of_blocks(points, *semi_axis_b).map_err(invalid)?;
            let e = arc.ellipse();
            ellipse(
                e.center(),
                e.semi_axis_a(),
                e.semi_axis_b(),
                e.rotation(),
                arc.start_angle(),
                arc.start_angle() + arc.sweep(),
            )
        }
        Entity::Bezier(c) => {
            let n = c.control_points().len();
            let mut knots = vec![0.0; n];
            knots.resize(2 * n, 1.0);
            spline(id, n - 1, knots, c.control_points(), None)?
        }
        Entity::BSpline(c) => spline(
            id,
            c.degree(),
            c.knots().as_slice().to_vec(),
            c.control_points(),
            None,
        )?,
        Entity::Nurbs(c) => spline(
            id,
            c.degree(),
            c.knots().as_slice().to_vec(),
            c.control_points(),
            Some(c.weights()),
        )?,
        Entity::Hermite(chain) | Entity::Composite(chain) => spline(
            id,
            3,
            chain.knots().as_slice().to_vec(),
            &chain.bezier_points(),
            None,
        )?,
    })
}

/// An ELLIPSE of centre C, semi-axes a, b, rotation θ and parametric angles t₀ < t₁
/// (counter-clockwise, radians). DXF wants the major axis and a ratio ≤ 1: when b > a the
/// major axis is the b-axis, M = b·(−sin θ, cos θ) with ratio a/b, and the parameters shift by
/// −π/2 (C + b·cos t·v − a·sin t·u is the point of angle t + π/2).
fn ellipse(c: &Point2<f64>, a: f64, b: f64, rotation: f64, t0: f64, t1: f64) -> EntityType {
    let u = Vector2::new(rotation.cos(), rotation.sin());
    let v = Vector2::new(-u.y, u.x);
    let (major, ratio, shift) = if b <= a {
        (u * a, b / a, 0.0)
    } else {
        (v * b, a / b, -FRAC_PI_2)
    };
    EntityType::Ellipse(de::Ellipse {
        center: point(c),
        major_axis: dxf::Vector::new(major.x, major.y, 0.0),
        minor_axis_ratio: ratio,
        start_parameter: t0 + shift,
        end_parameter: t1 + shift,
        ..Default::default()
    })
}

/// A planar SPLINE of the given degree, knots, control points and (for a NURBS) weights.
fn spline(
    id: EntityId,
    degree: usize,
    knots: Vec<f64>,
    control_points: &[Point2<f64>],
    weights: Option<&[f64]>,
) -> Result<EntityType, Error> {
    for (what, count) in [
        ("control points", control_points.len()),
        ("knots", knots.len()),
    ] {
        if count > MAX_SPLINE_ITEMS {
            return Err(Error::SplineTooLarge {
                entity: id,
                what,
                count,
            });
        }
    }
    let mut s = de::Spline {
        // Degrees beyond i32 cannot reach here: the knot count bounds the degree.
        degree_of_curve: i32::try_from(degree).unwrap_or(i32::MAX),
        knot_values: knots,
        control_points: control_points.iter().map(point).collect(),
        ..Default::default()
    };
    s.set_is_planar(true);
    if let Some(w) = weights {
        s.set_is_rational(true);
        s.weight_values = w.to_vec();
    }
    Ok(EntityType::Spline(s))
}
