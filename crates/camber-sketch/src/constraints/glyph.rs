//! How a constraint is marked in a picture: [`Glyph`]s in model coordinates, placed by each
//! kind ([`crate::Constraint::glyphs`]) on the geometry a lookup shows (the sketch, or a drag
//! session's current state).

use nalgebra::{Point2, Vector2};

use crate::ground::entity::{combine, Entity};
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;

/// A constraint's mark in the picture, in model coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Glyph {
    /// An arrow from the point along the direction (tangencies, joins, line relations).
    Arrow(Point2<f64>, Vector2<f64>),
    /// A triangle under the point (fixed).
    Fixed(Point2<f64>),
    /// A ring around the point (coincidences, points on curves and circles, distances).
    Ring(Point2<f64>),
    /// A short text beside the point ("H", "V", "=", "R", …).
    Mark(Point2<f64>, &'static str),
}

/// The location of a point reference (for `Start`/`End`, the curve point there).
///
/// # Errors
/// Unknown ids and indices, a reference of the wrong kind.
pub fn point(at: &dyn EntityLookup, r: PointRef) -> Result<Point2<f64>> {
    let e = at.lookup(r.entity())?;
    let v = combine(e.points(), &e.resolve(r)?);
    Ok(Point2::new(v[0], v[1]))
}

/// C(u) of a curve entity.
///
/// # Errors
/// Unknown id, not a curve, u outside the domain.
pub fn curve_point(at: &dyn EntityLookup, curve: EntityId, u: f64) -> Result<Point2<f64>> {
    let e = at.lookup(curve)?;
    let v = combine(e.points(), &e.coefficients(curve, u, 0)?);
    Ok(Point2::new(v[0], v[1]))
}

/// C′(u) of a curve entity.
///
/// # Errors
/// As [`curve_point`].
pub fn curve_tangent(at: &dyn EntityLookup, curve: EntityId, u: f64) -> Result<Vector2<f64>> {
    let e = at.lookup(curve)?;
    let v = combine(e.points(), &e.coefficients(curve, u, 1)?);
    Ok(Vector2::new(v[0], v[1]))
}

/// The end of a curve's domain (its start when `at_end` is false).
///
/// # Errors
/// Unknown id, not a curve.
pub fn domain_end(at: &dyn EntityLookup, curve: EntityId, at_end: bool) -> Result<f64> {
    let e = at.lookup(curve)?;
    let (a, b) = e.domain().ok_or(Error::WrongEntityKind {
        entity: curve,
        expected: "curve",
        found: e.kind_name(),
    })?;
    Ok(if at_end { b } else { a })
}

/// An arrow at C(u) along C′(u).
///
/// # Errors
/// As [`curve_point`].
pub fn tangent_arrow(at: &dyn EntityLookup, curve: EntityId, u: f64) -> Result<Glyph> {
    Ok(Glyph::Arrow(
        curve_point(at, curve, u)?,
        curve_tangent(at, curve, u)?,
    ))
}

/// The two ends of a line entity.
///
/// # Errors
/// Unknown id; [`Error::WrongEntityKind`] for anything but a line.
pub fn line_ends(at: &dyn EntityLookup, line: EntityId) -> Result<[Point2<f64>; 2]> {
    match at.lookup(line)? {
        Entity::Line(ends) => Ok(*ends),
        other => Err(Error::WrongEntityKind {
            entity: line,
            expected: "line",
            found: other.kind_name(),
        }),
    }
}

/// An arrow at the middle of a line entity along it.
///
/// # Errors
/// As [`line_ends`].
pub fn line_arrow(at: &dyn EntityLookup, line: EntityId) -> Result<Glyph> {
    let [a, b] = line_ends(at, line)?;
    Ok(Glyph::Arrow(
        Point2::from((a.coords + b.coords) / 2.0),
        b - a,
    ))
}

/// A text mark at the middle of a line entity.
///
/// # Errors
/// As [`line_ends`].
pub fn line_mark(at: &dyn EntityLookup, line: EntityId, text: &'static str) -> Result<Glyph> {
    let [a, b] = line_ends(at, line)?;
    Ok(Glyph::Mark(Point2::from((a.coords + b.coords) / 2.0), text))
}

/// A circle entity's (or an arc's) centre and radius.
///
/// # Errors
/// Unknown id; [`Error::WrongEntityKind`] for anything but a circle or an arc.
pub fn circle(at: &dyn EntityLookup, id: EntityId) -> Result<(Point2<f64>, f64)> {
    match at.lookup(id)? {
        Entity::Circle { center, radius } => Ok((*center, *radius)),
        Entity::Arc([c, s, _]) => Ok((*c, (s - c).norm())),
        other => Err(Error::WrongEntityKind {
            entity: id,
            expected: "circle or arc",
            found: other.kind_name(),
        }),
    }
}

/// The point halfway along a circular or an elliptic arc's sweep; `None` for any other entity
/// (or an arc whose blocks make no arc).
pub fn arc_midpoint(e: &Entity) -> Option<Point2<f64>> {
    match e {
        Entity::Arc(_) => e.as_arc().map(|a| a.point(0.5)),
        Entity::EllipticArc { .. } => e.as_elliptic_arc().map(|a| a.point_at(0.5)),
        _ => None,
    }
}
