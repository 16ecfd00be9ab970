//! What a sketch looks like, independent of the output: the geometry of every entity and the
//! glyphs of every constraint, in model coordinates.
//!
//! `camber render` draws a scene as SVG ([`crate::commands::render`]) and `camber edit` sends it
//! to the browser as JSON ([`crate::editor`]), so both show the same curve samples and put the
//! same glyph at the same place. A [`View`] reads a sketch, optionally with some entities
//! replaced: a drag session's current geometry is shown that way without touching the sketch.

use std::collections::BTreeMap;

use anyhow::Result;
pub use camber_sketch::Glyph;
use camber_sketch::{Constraint, EntityId, EntityLookup, PointRef, Sketch};
use camber_sketch::{Entity, Error as SketchError};
use nalgebra::{Point2, Vector2};

/// The file-format word for an entity's kind (`"bezier"`, `"circle"`, …).
pub fn kind_word(e: &Entity) -> &'static str {
    match e {
        Entity::Point(_) => "point",
        Entity::Line(_) => "line",
        Entity::Circle { .. } => "circle",
        Entity::Arc(_) => "arc",
        Entity::Ellipse { .. } => "ellipse",
        Entity::EllipticArc { .. } => "elliptic_arc",
        Entity::Bezier(_) => "bezier",
        Entity::BSpline(_) => "bspline",
        Entity::Nurbs(_) => "nurbs",
        Entity::Hermite(_) => "hermite",
        Entity::Composite(_) => "composite",
    }
}

/// A sketch as it is, or with some entities replaced by other geometry of the same shape.
///
/// ```
/// use std::collections::BTreeMap;
/// use camber_cli::scene::View;
/// use camber_sketch::{Entity, PointRef, Sketch};
/// use nalgebra::Point2;
/// let mut s = Sketch::new();
/// let p = s.add_point(Point2::new(1.0, 2.0))?;
/// let moved = BTreeMap::from([(p, Entity::Point(Point2::new(3.0, 4.0)))]);
/// assert_eq!(View::new(&s).point(PointRef::Point(p))?, Point2::new(1.0, 2.0));
/// assert_eq!(View::with_overrides(&s, &moved).point(PointRef::Point(p))?, Point2::new(3.0, 4.0));
/// # Ok::<(), anyhow::Error>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct View<'a> {
    sketch: &'a Sketch,
    overrides: Option<&'a BTreeMap<EntityId, Entity>>,
}

impl<'a> View<'a> {
    /// The sketch as it is.
    pub fn new(sketch: &'a Sketch) -> Self {
        Self {
            sketch,
            overrides: None,
        }
    }

    /// The sketch with the entities of `overrides` in place of its own.
    pub fn with_overrides(sketch: &'a Sketch, overrides: &'a BTreeMap<EntityId, Entity>) -> Self {
        Self {
            sketch,
            overrides: Some(overrides),
        }
    }

    /// The sketch underneath (constraints, ids).
    pub fn sketch(&self) -> &'a Sketch {
        self.sketch
    }

    /// An entity, replaced or not.
    ///
    /// # Errors
    /// An unknown id.
    pub fn entity(&self, id: EntityId) -> Result<&'a Entity, SketchError> {
        match self.overrides.and_then(|o| o.get(&id)) {
            Some(e) => Ok(e),
            None => self.sketch.entity(id),
        }
    }

    /// Every entity by id, replaced or not.
    pub fn entities(&self) -> impl Iterator<Item = (EntityId, &'a Entity)> + '_ {
        self.sketch
            .entities()
            .map(|(id, e)| (id, self.overrides.and_then(|o| o.get(&id)).unwrap_or(e)))
    }

    /// The location of a point reference (for `Start`/`End`, the curve point there).
    ///
    /// # Errors
    /// Unknown ids and indices, a reference of the wrong kind.
    pub fn point(&self, r: PointRef) -> Result<Point2<f64>, SketchError> {
        let e = self.entity(r.entity())?;
        Ok(combine(e.points(), &e.resolve(r)?))
    }

    /// C(u) of a curve entity.
    ///
    /// # Errors
    /// Unknown id, not a curve, u outside the domain.
    pub fn curve_point(&self, curve: EntityId, u: f64) -> Result<Point2<f64>, SketchError> {
        let e = self.entity(curve)?;
        Ok(combine(e.points(), &e.coefficients(curve, u, 0)?))
    }

    /// C′(u) of a curve entity.
    ///
    /// # Errors
    /// As [`View::curve_point`].
    pub fn curve_tangent(&self, curve: EntityId, u: f64) -> Result<Vector2<f64>, SketchError> {
        let e = self.entity(curve)?;
        Ok(combine(e.points(), &e.coefficients(curve, u, 1)?).coords)
    }
}

/// Σ cⱼ·Pⱼ over an entity's points.
fn combine(points: &[Point2<f64>], terms: &[(usize, f64)]) -> Point2<f64> {
    terms
        .iter()
        .filter_map(|(j, c)| points.get(*j).map(|p| p.coords * *c))
        .fold(Point2::origin(), |s, v| s + v)
}

/// A view resolves entities for the constraint kinds' glyphs, replaced ones included.
impl EntityLookup for View<'_> {
    fn lookup(&self, id: EntityId) -> Result<&Entity, SketchError> {
        self.entity(id)
    }
}

/// The glyphs of one constraint, at the geometry `view` shows: each kind places its own
/// ([`Constraint::glyphs`]). A contact at a free parameter is marked at the parameter the
/// constraint records (the last solved one).
///
/// ```
/// use camber_cli::scene::{glyphs, View};
/// use camber_sketch::constraints::Fixed;
/// use camber_sketch::{Constraint, Glyph, PointRef, Sketch};
/// use nalgebra::Point2;
/// let mut s = Sketch::new();
/// let p = s.add_point(Point2::new(1.0, 2.0))?;
/// let fix = Constraint::from(Fixed::point(PointRef::Point(p)));
/// assert_eq!(glyphs(&View::new(&s), &fix)?, vec![Glyph::Fixed(Point2::new(1.0, 2.0))]);
/// # Ok::<(), anyhow::Error>(())
/// ```
///
/// # Errors
/// A reference the view cannot resolve (not for a constraint the sketch accepted).
pub fn glyphs(view: &View, c: &Constraint) -> Result<Vec<Glyph>> {
    Ok(c.glyphs(view)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use camber_sketch::constraints::{Fixed, TangentToCircle};
    use camber_sketch::{CircleSide, Contact, FixTarget, Rotation};

    #[test]
    fn overrides_move_points_and_glyphs_but_not_the_sketch() {
        let mut s = Sketch::new();
        let c = s
            .add_bezier(
                camber_geom::BezierCurve2::try_new(vec![
                    Point2::new(0.0, 0.0),
                    Point2::new(1.0, 1.0),
                    Point2::new(2.0, 0.0),
                ])
                .unwrap(),
            )
            .unwrap();
        let fix = Constraint::Fixed(Fixed {
            target: FixTarget::Point(PointRef::End(c)),
        });
        let moved = s
            .entity(c)
            .unwrap()
            .with_points(
                &[
                    Point2::new(0.0, 0.0),
                    Point2::new(1.0, 1.0),
                    Point2::new(4.0, 0.0),
                ],
                &[],
            )
            .unwrap();
        let overrides = BTreeMap::from([(c, moved)]);
        let view = View::with_overrides(&s, &overrides);
        assert_eq!(
            glyphs(&view, &fix).unwrap(),
            vec![Glyph::Fixed(Point2::new(4.0, 0.0))]
        );
        assert_eq!(
            glyphs(&View::new(&s), &fix).unwrap(),
            vec![Glyph::Fixed(Point2::new(2.0, 0.0))]
        );
        // C′(1) of the quadratic = 2·(P₂ − P₁).
        let t = view.curve_tangent(c, 1.0).unwrap();
        assert!((t - Vector2::new(6.0, -2.0)).norm() < 1e-12);
        assert_eq!(view.entities().count(), 1);
    }

    #[test]
    fn contacts_are_marked_where_the_constraint_touches() {
        let mut s = Sketch::new();
        let c = s
            .add_bezier(
                camber_geom::BezierCurve2::try_new(vec![
                    Point2::new(-1.0, 1.0),
                    Point2::new(0.0, 1.0),
                    Point2::new(1.0, 1.0),
                ])
                .unwrap(),
            )
            .unwrap();
        let circle = s.add_circle(Point2::origin(), 1.0).unwrap();
        let touch = Constraint::TangentToCircle(TangentToCircle {
            curve: c,
            circle,
            u: Contact::Free(0.5),
            side: CircleSide::Outside,
            rotation: Rotation::Clockwise,
        });
        match glyphs(&View::new(&s), &touch).unwrap().as_slice() {
            [Glyph::Arrow(at, d)] => {
                assert!((at - Point2::new(0.0, 1.0)).norm() < 1e-12);
                assert!(d.y.abs() < 1e-12 && d.x > 0.0);
            }
            other => panic!("{other:?}"),
        }
    }
}
