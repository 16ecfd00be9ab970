//! DXF → sketch: each DXF entity turned into sketch entities, or listed as skipped with why.

use std::f64::consts::TAU;
use std::panic::{catch_unwind, AssertUnwindSafe};

use camber_geom::{
    BSplineCurve2, BezierCurve2, CircularArc, Ellipse, EllipticArc, KnotVector, NurbsCurve2,
};
use camber_sketch::{Entity, EntityId, PointRef, Sketch};
use dxf::entities::EntityType;
use nalgebra::{Point2, Vector2};

use super::plane::{common_z, Facing};
use super::{Error, ReadOptions};
use crate::joins::{add_coincidences, join_close, Clusters};
use crate::{Imported, Skipped};

/// Parses the bytes with the `dxf` crate. The reader is third-party code fed untrusted input:
/// a panic inside it is reported as a malformed file rather than taking the caller down.
fn parse(bytes: &[u8]) -> Result<dxf::Drawing, Error> {
    let result = catch_unwind(AssertUnwindSafe(|| dxf::Drawing::load(&mut &bytes[..])));
    match result {
        Ok(Ok(drawing)) => Ok(drawing),
        Ok(Err(e)) => Err(Error::Malformed {
            message: e.to_string(),
        }),
        Err(_) => Err(Error::Malformed {
            message: "the DXF reader gave up on this input".into(),
        }),
    }
}

/// A sketch entity made from a DXF entity, with the ends a polyline joins through: `from` is
/// the end at the segment's first vertex, `to` the end at its second (an arc drawn clockwise
/// in the file runs counter-clockwise in the sketch, so its start is the segment's `to`).
struct Piece {
    entity: Entity,
    reversed: bool,
}

impl Piece {
    fn plain(entity: Entity) -> Self {
        Self {
            entity,
            reversed: false,
        }
    }
}

/// What one DXF entity gives: its pieces, whether consecutive pieces are joined (polylines),
/// and the parts of it left out (a zero-length polyline segment).
#[derive(Default)]
struct Converted {
    pieces: Vec<Piece>,
    chained: bool,
    closed: bool,
    notes: Vec<String>,
}

impl Converted {
    fn one(entity: Entity) -> Self {
        Self {
            pieces: vec![Piece::plain(entity)],
            ..Self::default()
        }
    }
}

pub(super) fn read(bytes: &[u8], options: &ReadOptions) -> Result<Imported, Error> {
    let drawing = parse(bytes)?;
    let count = drawing.entities().count();
    if count > options.max_entities {
        return Err(Error::TooManyEntities {
            count,
            limit: options.max_entities,
        });
    }
    let mut sketch = Sketch::new();
    let mut skipped = Vec::new();
    // Every end point a join may use, with its position; pairs joined by construction.
    let mut ends: Vec<(PointRef, Point2<f64>)> = Vec::new();
    let mut chained: Vec<(usize, usize)> = Vec::new();
    let mut made = 0usize;
    for (index, e) in drawing.entities().enumerate() {
        let location = format!(
            "{} {index} (handle {})",
            type_name(&e.specific),
            e.common.handle.as_string()
        );
        let converted = match convert(&e.specific) {
            Ok(c) => c,
            Err(reason) => {
                skipped.push(Skipped { location, reason });
                continue;
            }
        };
        made += converted.pieces.len();
        if made > options.max_entities {
            return Err(Error::TooManyEntities {
                count: made,
                limit: options.max_entities,
            });
        }
        for note in converted.notes {
            skipped.push(Skipped {
                location: location.clone(),
                reason: note,
            });
        }
        let mut previous_to: Option<usize> = None;
        let mut first_from: Option<usize> = None;
        for (k, piece) in converted.pieces.into_iter().enumerate() {
            let id = match sketch.add_entity(piece.entity) {
                Ok(id) => id,
                Err(err) => {
                    let part = if converted.chained {
                        format!("segment {k}: ")
                    } else {
                        String::new()
                    };
                    skipped.push(Skipped {
                        location: location.clone(),
                        reason: format!("{part}{err}"),
                    });
                    previous_to = None;
                    continue;
                }
            };
            let layer = &e.common.layer;
            if layer != "0" {
                if let Err(err) = sketch.set_tag(id, Some(layer)) {
                    skipped.push(Skipped {
                        location: location.clone(),
                        reason: format!("its layer is not kept as a tag: {err}"),
                    });
                }
            }
            let before = ends.len();
            push_ends(&sketch, id, &mut ends);
            if converted.chained && ends.len() == before + 2 {
                let (from, to) = if piece.reversed {
                    (before + 1, before)
                } else {
                    (before, before + 1)
                };
                if let Some(p) = previous_to {
                    chained.push((p, from));
                }
                first_from.get_or_insert(from);
                previous_to = Some(to);
            }
        }
        if converted.closed {
            if let (Some(last), Some(first)) = (previous_to, first_from) {
                chained.push((last, first));
            }
        }
    }
    let mut clusters = Clusters::new(ends.len());
    for (a, b) in chained {
        clusters.union(a, b);
    }
    let positions: Vec<Point2<f64>> = ends.iter().map(|(_, p)| *p).collect();
    join_close(&positions, options.join_tolerance, &mut clusters);
    let refs: Vec<PointRef> = ends.iter().map(|(r, _)| *r).collect();
    add_coincidences(&mut sketch, &refs, &mut clusters)?;
    Ok(Imported { sketch, skipped })
}

/// The end points of an entity that joins may use: a point entity itself, the ends of lines,
/// arcs and open curves; whole circles and ellipses have none.
fn push_ends(sketch: &Sketch, id: EntityId, ends: &mut Vec<(PointRef, Point2<f64>)>) {
    let refs: &[PointRef] = match sketch.entity(id) {
        Ok(Entity::Point(_)) => &[PointRef::Point(id)],
        Ok(Entity::Circle { .. } | Entity::Ellipse { .. }) | Err(_) => &[],
        Ok(_) => &[PointRef::Start(id), PointRef::End(id)],
    };
    for r in refs {
        if let Ok(p) = sketch.point(*r) {
            ends.push((*r, p));
        }
    }
}

/// The DXF type of an entity for messages (`LINE`, `TEXT`, …), read off its variant's name.
fn type_name(specific: &EntityType) -> String {
    let known = match specific {
        EntityType::Line(_) => "LINE",
        EntityType::ModelPoint(_) => "POINT",
        EntityType::Circle(_) => "CIRCLE",
        EntityType::Arc(_) => "ARC",
        EntityType::Ellipse(_) => "ELLIPSE",
        EntityType::Spline(_) => "SPLINE",
        EntityType::LwPolyline(_) => "LWPOLYLINE",
        EntityType::Polyline(_) => "POLYLINE",
        EntityType::Insert(_) => "INSERT",
        EntityType::Text(_) => "TEXT",
        EntityType::MText(_) => "MTEXT",
        _ => "",
    };
    if !known.is_empty() {
        return known.to_owned();
    }
    // `Variant(…)`: the variant's name, upper case.
    let debug = format!("{specific:?}");
    debug
        .split(|c: char| !c.is_alphanumeric())
        .next()
        .unwrap_or("entity")
        .to_uppercase()
}

/// One DXF entity as sketch pieces, or why it is left out.
fn convert(specific: &EntityType) -> Result<Converted, String> {
    match specific {
        EntityType::ModelPoint(p) => {
            let at = &p.location;
            Ok(Converted::one(Entity::Point(Point2::new(at.x, at.y))))
        }
        EntityType::Line(l) => {
            common_z([l.p1.z, l.p2.z])
                .ok_or_else(|| "its ends differ in z: not in a plane parallel to XY".to_owned())?;
            Ok(Converted::one(Entity::Line([
                Point2::new(l.p1.x, l.p1.y),
                Point2::new(l.p2.x, l.p2.y),
            ])))
        }
        EntityType::Circle(c) => {
            let facing = facing(&c.normal)?;
            Ok(Converted::one(Entity::Circle {
                center: Point2::new(facing.x(c.center.x), c.center.y),
                radius: c.radius,
            }))
        }
        EntityType::Arc(a) => {
            let facing = facing(&a.normal)?;
            let center = Point2::new(facing.x(a.center.x), a.center.y);
            let (s, e) = (a.start_angle.to_radians(), a.end_angle.to_radians());
            // Counter-clockwise from s to e in object coordinates; mirrored, clockwise, which
            // is counter-clockwise from the image of e to the image of s.
            let (s, e) = match facing {
                Facing::Up => (s, e),
                Facing::Down => (facing.angle(e), facing.angle(s)),
            };
            let arc = CircularArc::try_new(center, a.radius, s, e).map_err(|e| e.to_string())?;
            Ok(Converted::one(Entity::arc(&arc)))
        }
        EntityType::Ellipse(el) => ellipse(el),
        EntityType::Spline(s) => spline(s),
        EntityType::LwPolyline(p) => {
            let facing = facing(&p.extrusion_direction)?;
            let vertices: Vec<(f64, f64, f64)> =
                p.vertices.iter().map(|v| (v.x, v.y, v.bulge)).collect();
            polyline(&vertices, facing, p.is_closed())
        }
        EntityType::Polyline(p) => {
            if p.is_3d_polyline() || p.is_3d_polygon_mesh() || p.is_polyface_mesh() {
                return Err("3D polylines and meshes are not planar sketch geometry".into());
            }
            let facing = facing(&p.normal)?;
            let kept: Vec<_> = p
                .vertices()
                .filter(|v| !v.is_spline_frame_control_point())
                .collect();
            common_z(kept.iter().map(|v| v.location.z)).ok_or_else(|| {
                "its vertices differ in z: not in a plane parallel to XY".to_owned()
            })?;
            let vertices: Vec<(f64, f64, f64)> = kept
                .iter()
                .map(|v| (v.location.x, v.location.y, v.bulge))
                .collect();
            polyline(&vertices, facing, p.is_closed())
        }
        EntityType::Insert(_) => {
            Err("block references are not expanded; explode the block in the CAD system".into())
        }
        _ => Err("not geometry a sketch holds".into()),
    }
}

/// The facing of an extrusion direction, or why the entity is out of the sketch plane.
fn facing(n: &dxf::Vector) -> Result<Facing, String> {
    Facing::of(n).ok_or_else(|| {
        format!(
            "its extrusion direction ({}, {}, {}) is not ±Z: not in a plane parallel to XY",
            n.x, n.y, n.z
        )
    })
}

/// An ELLIPSE: P(t) = C + cos t·M + sin t·k·(N × M) for t from the start to the end parameter.
/// With N = +Z that is camber's parametric form with a = |M|, b = k·|M| and the rotation of M;
/// with N = −Z the minor axis flips, so camber's angle is −t and the arc runs from −t₁ to −t₀.
fn ellipse(el: &dxf::entities::Ellipse) -> Result<Converted, String> {
    let facing = facing(&el.normal)?;
    if el.major_axis.z != 0.0 {
        return Err(format!(
            "its major axis leaves the XY plane (z = {})",
            el.major_axis.z
        ));
    }
    let m = Vector2::new(el.major_axis.x, el.major_axis.y);
    let a = m.norm();
    let b = el.minor_axis_ratio * a;
    let rotation = m.y.atan2(m.x);
    let center = Point2::new(el.center.x, el.center.y);
    let (t0, t1) = (el.start_parameter, el.end_parameter);
    if !(t0.is_finite() && t1.is_finite()) {
        return Err(format!("its parameters {t0} and {t1} are not finite"));
    }
    let whole = Ellipse::try_new(center, a, b, rotation).map_err(|e| e.to_string())?;
    let sweep = (t1 - t0).rem_euclid(TAU);
    if sweep < 1e-12 || TAU - sweep < 1e-12 {
        return Ok(Converted::one(Entity::ellipse(&whole)));
    }
    let (s, e) = match facing {
        Facing::Up => (t0, t1),
        Facing::Down => (-t1, -t0),
    };
    let arc = EllipticArc::try_new(center, a, b, rotation, s, e).map_err(|e| e.to_string())?;
    Ok(Converted::one(Entity::elliptic_arc(&arc)))
}

/// A SPLINE by its control points, knots and (when rational) weights: a NURBS curve when
/// rational or weighted, a Bézier curve when it is one clamped span on [0, 1], else a
/// B-spline.
fn spline(s: &dxf::entities::Spline) -> Result<Converted, String> {
    if s.control_points.is_empty() {
        return Err(format!(
            "it is given by {} fit points only; a sketch takes a SPLINE's control points",
            s.fit_points.len()
        ));
    }
    common_z(s.control_points.iter().map(|p| p.z)).ok_or_else(|| {
        "its control points differ in z: not in a plane parallel to XY".to_owned()
    })?;
    let degree = usize::try_from(s.degree_of_curve)
        .ok()
        .filter(|&d| d >= 1)
        .ok_or_else(|| format!("its degree {} is not a positive integer", s.degree_of_curve))?;
    let points: Vec<Point2<f64>> = s
        .control_points
        .iter()
        .map(|p| Point2::new(p.x, p.y))
        .collect();
    let weights = &s.weight_values;
    if !weights.is_empty() && weights.len() != points.len() {
        return Err(format!(
            "it has {} weights for {} control points",
            weights.len(),
            points.len()
        ));
    }
    let knots = KnotVector::try_new(s.knot_values.clone()).map_err(|e| e.to_string())?;
    #[allow(clippy::float_cmp)] // a weight of exactly 1 is the unweighted case
    let weighted = s.is_rational() || weights.iter().any(|&w| w != 1.0);
    let entity = if weighted {
        let w = if weights.is_empty() {
            vec![1.0; points.len()]
        } else {
            weights.clone()
        };
        Entity::Nurbs(NurbsCurve2::try_new(degree, knots, points, w).map_err(|e| e.to_string())?)
    } else if is_bezier_span(&s.knot_values, degree, points.len()) {
        Entity::Bezier(BezierCurve2::try_new(points).map_err(|e| e.to_string())?)
    } else {
        Entity::BSpline(BSplineCurve2::try_new(degree, knots, points).map_err(|e| e.to_string())?)
    };
    Ok(Converted::one(entity))
}

/// Whether knots and counts describe one Bézier span on [0, 1]: p + 1 control points and the
/// knots 0 (p + 1 times) then 1 (p + 1 times).
#[allow(clippy::float_cmp)] // the exact knots 0 and 1 are what a Bézier span is written with
fn is_bezier_span(knots: &[f64], degree: usize, count: usize) -> bool {
    count == degree + 1
        && knots.len() == 2 * count
        && knots[..count].iter().all(|&k| k == 0.0)
        && knots[count..].iter().all(|&k| k == 1.0)
}

/// A polyline's segments from its vertices (x, y, bulge) in object coordinates: a line for a
/// zero bulge, else the arc of included angle 4·atan(bulge), counter-clockwise for a positive
/// bulge. With chord c from P to Q, its midpoint M and the unit normal n to the left of P→Q,
/// the centre is M + n·c·(1 − b²)/(4b) for either sign of b (derived from the half-angle
/// tangent tan(θ/2) = 2b/(1 − b²)).
fn polyline(
    vertices: &[(f64, f64, f64)],
    facing: Facing,
    closed: bool,
) -> Result<Converted, String> {
    if vertices.len() < 2 {
        return Err(format!(
            "it has {} vertices, fewer than two",
            vertices.len()
        ));
    }
    let world = |(x, y, b): (f64, f64, f64)| {
        let bulge = match facing {
            Facing::Up => b,
            Facing::Down => -b,
        };
        (Point2::new(facing.x(x), y), bulge)
    };
    let n = vertices.len();
    let segments = if closed { n } else { n - 1 };
    let mut out = Converted {
        chained: true,
        closed,
        ..Converted::default()
    };
    for k in 0..segments {
        let (p, bulge) = world(vertices[k]);
        let (q, _) = world(vertices[(k + 1) % n]);
        if p == q {
            out.notes
                .push(format!("segment {k} has zero length and is left out"));
            continue;
        }
        if !bulge.is_finite() {
            out.notes
                .push(format!("segment {k} has the bulge {bulge} and is left out"));
            continue;
        }
        if bulge == 0.0 {
            out.pieces.push(Piece::plain(Entity::Line([p, q])));
            continue;
        }
        let chord = q - p;
        let left = Vector2::new(-chord.y, chord.x);
        let center = nalgebra::center(&p, &q) + left * ((1.0 - bulge * bulge) / (4.0 * bulge));
        let (start, end, reversed) = if bulge > 0.0 {
            (p, q, false)
        } else {
            (q, p, true)
        };
        out.pieces.push(Piece {
            entity: Entity::Arc([center, start, end]),
            reversed,
        });
    }
    Ok(out)
}
