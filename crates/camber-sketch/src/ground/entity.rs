//! Entities: points, lines, circles, Bézier, B-spline and NURBS curves, cubic Hermite curves and
//! composite curves (planar, f64), and the linear maps from their blocks to curve points and
//! tangents.
//!
//! Every point of an entity (a point, a line end, a circle centre, a control point) is one
//! parameter block of two unknowns (x, y) in a solve; a circle's radius is a block of one.
//! Knots and weights are data, never unknowns. With them fixed, a curve point and its
//! derivatives are linear in the control points:
//!
//! C⁽ᵏ⁾(u) = Σⱼ cⱼ⁽ᵏ⁾(u)·Pⱼ,
//!
//! with cⱼ = N⁽ᵏ⁾_{j,p}(u) for B-splines (Bézier curves and lines being B-splines on clamped
//! knots over [0, 1]) and, for NURBS with weights wⱼ, W = Σ wⱼNⱼ, W′ = Σ wⱼN′ⱼ:
//!
//! Rⱼ = wⱼNⱼ/W,  R′ⱼ = wⱼ(N′ⱼ·W − Nⱼ·W′)/W².
//!
//! Hermite and composite curves ([`HermiteChain`]) have nodes and tangent vectors as their
//! blocks; their Bézier control points are a fixed linear map of those blocks, so the same
//! holds with cⱼ summed through that map ([`crate::ground::hermite_chain`]).
//!
//! [`Entity::coefficients`] returns those cⱼ (only the p + 1 that can be non-zero), which makes
//! every constraint at a *given* parameter a constant-coefficient combination of control-point
//! blocks (an affine constraint); those with a free parameter, distances, angles and lengths are
//! nonlinear.

use camber_geom::{BSplineCurve2, BezierCurve2, CircularArc, Ellipse, EllipticArc, NurbsCurve2};
use nalgebra::Point2;
use smallvec::SmallVec;

use crate::ground::curve_eval::CurveBasis;
use crate::ground::ellipse_blocks::{
    box_corners, ellipse_blocks, ellipse_of_blocks, elliptic_arc_blocks, elliptic_arc_of_blocks,
};
use crate::ground::errors::{Error, Result};
use crate::ground::hermite_chain::HermiteChain;
use crate::ground::ids::{EntityId, PointRef};

/// A linear combination Σ cⱼ·Pⱼ over an entity's points: (point index, coefficient) pairs.
pub type Terms = SmallVec<[(usize, f64); 8]>;

/// A sketch entity. Points are stored as the kernel's types, so they can be evaluated directly.
///
/// ```
/// use camber_sketch::Entity;
/// use nalgebra::Point2;
/// let e = Entity::Line([Point2::new(0.0, 0.0), Point2::new(2.0, 0.0)]);
/// let t = e.coefficients(EntityId(0), 0.25, 0)?;
/// # use camber_sketch::EntityId;
/// // C(1/4) = ¾·P₀ + ¼·P₁.
/// assert!((t[0].1 - 0.75).abs() < 1e-15 && (t[1].1 - 0.25).abs() < 1e-15);
/// # Ok::<(), camber_sketch::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum Entity {
    /// A point.
    Point(Point2<f64>),
    /// A straight line through two points, parameterized C(u) = (1 − u)·P₀ + u·P₁ on [0, 1].
    Line([Point2<f64>; 2]),
    /// A circle: centre (a point block) and radius (a block of one).
    Circle {
        /// The centre.
        center: Point2<f64>,
        /// The radius, > 0.
        radius: f64,
    },
    /// A circular arc, stored by its blocks [centre, start, end]: it runs counter-clockwise
    /// from the start to the end about the centre, its radius is |start − centre| and its end
    /// lies on that circle (the arc's own row |end − centre| − |start − centre| = 0 holds it
    /// there in every solve, so the arc has 6 − 1 = 5 DOF). Its ends are point blocks, so every
    /// constraint that reads a point reads them: `Start(e)` / `Control(e, 1)` and `End(e)` /
    /// `Control(e, 2)`; `Control(e, 0)` is the centre. Make one with [`Entity::arc`].
    Arc([Point2<f64>; 3]),
    /// An ellipse, stored by its blocks [centre, a-axis vertex] and its semi-axis b (a scalar
    /// block): a = |V − C|, rotation atan2(V − C); 5 DOF, no row of its own
    /// ([`crate::ellipse_blocks`]). `Control(e, 0)` is the centre, `Control(e, 1)` the vertex
    /// (a point on the ellipse). Make one with [`Entity::ellipse`].
    Ellipse {
        /// [centre, a-axis vertex].
        points: [Point2<f64>; 2],
        /// The semi-axis b (> 0), perpendicular to the a-axis.
        semi_axis_b: f64,
    },
    /// An elliptic arc, stored by its blocks [centre, a-axis vertex, start, end] and its
    /// semi-axis b: it runs counter-clockwise from the start to the end, whose parametric
    /// angles are read from where they lie; two rows of its own hold both ends on the ellipse,
    /// so it has 9 − 2 = 7 DOF ([`crate::ellipse_blocks`]). Its ends are point blocks:
    /// `Start(e)` / `Control(e, 2)` and `End(e)` / `Control(e, 3)`. Make one with
    /// [`Entity::elliptic_arc`].
    EllipticArc {
        /// [centre, a-axis vertex, start, end].
        points: [Point2<f64>; 4],
        /// The semi-axis b (> 0), perpendicular to the a-axis.
        semi_axis_b: f64,
    },
    /// A Bézier curve on [0, 1].
    Bezier(BezierCurve2<f64>),
    /// A B-spline curve.
    BSpline(BSplineCurve2<f64>),
    /// A NURBS curve (weights held fixed).
    Nurbs(NurbsCurve2<f64>),
    /// A cubic Hermite curve on [0, 1]: a chain of one segment, blocks [p0, p1, t0, t1] (end
    /// points, then end tangent vectors).
    Hermite(HermiteChain),
    /// A composite curve: a chain of n cubic Hermite segments on [0, n] whose joins are shared
    /// nodes (C0) and, at smooth joins, shared tangents (C1); blocks are the nodes, then the
    /// tangents ([`crate::ground::hermite_chain`]).
    Composite(HermiteChain),
}

impl Entity {
    /// A curve entity (Bézier, B-spline, NURBS) through the geometry kernel's common face, for
    /// evaluation and queries in f64; `None` for points, lines and circles.
    ///
    /// ```
    /// use camber_geom::{BezierCurve2, ParametricCurve};
    /// use camber_sketch::Entity;
    /// use nalgebra::Point2;
    /// let arc = BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(2.0, 0.0)])?;
    /// let p = Entity::Bezier(arc).as_curve().map(|c| c.point(0.5)).transpose()?;
    /// assert_eq!(p, Some(Point2::new(1.0, 0.5)));
    /// assert!(Entity::Point(Point2::origin()).as_curve().is_none());
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn as_curve(&self) -> Option<&dyn camber_geom::ParametricCurve<f64, 2>> {
        match self {
            Entity::Bezier(c) => Some(c),
            Entity::BSpline(c) => Some(c),
            Entity::Nurbs(c) => Some(c),
            Entity::Hermite(c) | Entity::Composite(c) => Some(c),
            Entity::Point(_)
            | Entity::Line(_)
            | Entity::Circle { .. }
            | Entity::Arc(_)
            | Entity::Ellipse { .. }
            | Entity::EllipticArc { .. } => None,
        }
    }

    /// The arc entity of a circular arc: blocks [centre, start point, end point].
    ///
    /// ```
    /// use camber_geom::CircularArc;
    /// use camber_sketch::Entity;
    /// use nalgebra::Point2;
    /// let e = Entity::arc(&CircularArc::try_new(Point2::new(0.0, 0.0), 2.0, 0.0, std::f64::consts::FRAC_PI_2)?);
    /// assert!((e.points()[2] - Point2::new(0.0, 2.0)).norm() < 1e-15);
    /// let back = e.as_arc().unwrap();
    /// assert!((back.radius() - 2.0).abs() < 1e-15 && (back.sweep() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn arc(arc: &CircularArc<f64>) -> Entity {
        Entity::Arc([*arc.center(), arc.start_point(), arc.end_point()])
    }

    /// The ellipse entity of an ellipse: blocks [centre, a-axis vertex] and b.
    ///
    /// ```
    /// use camber_geom::Ellipse;
    /// use camber_sketch::Entity;
    /// use nalgebra::Point2;
    /// let e = Entity::ellipse(&Ellipse::try_new(Point2::new(1.0, 1.0), 2.0, 0.5, std::f64::consts::FRAC_PI_2)?);
    /// assert!((e.points()[1] - Point2::new(1.0, 3.0)).norm() < 1e-15);
    /// assert!((e.as_ellipse().unwrap().semi_axis_b() - 0.5).abs() < 1e-15);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn ellipse(e: &Ellipse<f64>) -> Entity {
        let (points, semi_axis_b) = ellipse_blocks(e);
        Entity::Ellipse {
            points,
            semi_axis_b,
        }
    }

    /// The elliptic arc entity of an elliptic arc: blocks [centre, a-axis vertex, start, end]
    /// and b.
    ///
    /// ```
    /// use camber_geom::EllipticArc;
    /// use camber_sketch::Entity;
    /// use nalgebra::Point2;
    /// let arc = EllipticArc::try_new(Point2::new(0.0, 0.0), 2.0, 1.0, 0.0, 0.0, std::f64::consts::FRAC_PI_2)?;
    /// let e = Entity::elliptic_arc(&arc);
    /// assert!((e.points()[3] - Point2::new(0.0, 1.0)).norm() < 1e-15);
    /// let back = e.as_elliptic_arc().unwrap();
    /// assert!((back.sweep() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    /// # Ok::<(), camber_geom::Error>(())
    /// ```
    pub fn elliptic_arc(arc: &EllipticArc<f64>) -> Entity {
        let (points, semi_axis_b) = elliptic_arc_blocks(arc);
        Entity::EllipticArc {
            points,
            semi_axis_b,
        }
    }

    /// The ellipse of an ellipse entity, or the whole ellipse of an elliptic arc, read from its
    /// blocks; `None` for other entities and for blocks that make no ellipse.
    pub fn as_ellipse(&self) -> Option<Ellipse<f64>> {
        match self {
            Entity::Ellipse {
                points,
                semi_axis_b,
            } => ellipse_of_blocks(points, *semi_axis_b).ok(),
            Entity::EllipticArc {
                points,
                semi_axis_b,
            } => ellipse_of_blocks(&[points[0], points[1]], *semi_axis_b).ok(),
            _ => None,
        }
    }

    /// The elliptic arc of an elliptic arc entity, read from its blocks; `None` for other
    /// entities and for blocks that make no arc.
    pub fn as_elliptic_arc(&self) -> Option<EllipticArc<f64>> {
        match self {
            Entity::EllipticArc {
                points,
                semi_axis_b,
            } => elliptic_arc_of_blocks(points, *semi_axis_b).ok(),
            _ => None,
        }
    }

    /// The circular arc of an arc entity, read from its blocks: radius |S − C|, start angle
    /// atan2(S − C) ∈ (−π, π], end angle atan2(E − C) (so the sweep lies in (0, 2π)); `None`
    /// for other entities and for blocks that make no arc (see [`arc_of_blocks`]).
    pub fn as_arc(&self) -> Option<CircularArc<f64>> {
        match self {
            Entity::Arc(blocks) => arc_of_blocks(blocks).ok(),
            _ => None,
        }
    }

    /// The sweep (radians, in (0, 2π)) of a circular or elliptic arc, read from its blocks:
    /// the angle of the end less that of the start, counter-clockwise (parametric angles for
    /// an elliptic arc); `None` for other entities and for blocks that make no arc.
    pub fn sweep(&self) -> Option<f64> {
        match self {
            Entity::Arc(_) => self.as_arc().map(|a| a.sweep()),
            Entity::EllipticArc { .. } => self.as_elliptic_arc().map(|a| a.sweep()),
            _ => None,
        }
    }

    /// C(s) and C′(s) of a curve entity in f64 through the geometry kernel, a line counting as
    /// the segment (1 − s)·P₀ + s·P₁; `None` for points and circles or s outside the domain.
    ///
    /// ```
    /// use camber_sketch::Entity;
    /// use nalgebra::{Point2, Vector2};
    /// let line = Entity::Line([Point2::new(0.0, 0.0), Point2::new(2.0, 4.0)]);
    /// assert_eq!(line.point_tangent(0.25), Some((Point2::new(0.5, 1.0), Vector2::new(2.0, 4.0))));
    /// ```
    pub fn point_tangent(&self, s: f64) -> Option<(Point2<f64>, nalgebra::Vector2<f64>)> {
        match self {
            Entity::Line([a, b]) => Some((a + (b - a) * s, b - a)),
            _ => self.as_curve()?.point_and_derivative(s).ok(),
        }
    }

    /// The kind as a word ("point", "line", "circle", "Bézier curve", …).
    pub fn kind_name(&self) -> &'static str {
        match self {
            Entity::Point(_) => "point",
            Entity::Line(_) => "line",
            Entity::Circle { .. } => "circle",
            Entity::Arc(_) => "arc",
            Entity::Ellipse { .. } => "ellipse",
            Entity::EllipticArc { .. } => "elliptic arc",
            Entity::Bezier(_) => "Bézier curve",
            Entity::BSpline(_) => "B-spline curve",
            Entity::Nurbs(_) => "NURBS curve",
            Entity::Hermite(_) => "Hermite curve",
            Entity::Composite(_) => "composite curve",
        }
    }

    /// The entity's points in block order: the point; the two line ends; the circle centre; the
    /// control points; for Hermite and composite curves the nodes, then the tangent vectors
    /// (whose coordinates are not positions: see [`Entity::hull_points`]).
    pub fn points(&self) -> &[Point2<f64>] {
        match self {
            Entity::Point(p) => std::slice::from_ref(p),
            Entity::Line(ends) => ends,
            Entity::Arc(blocks) => blocks,
            Entity::Ellipse { points, .. } => points,
            Entity::EllipticArc { points, .. } => points,
            Entity::Circle { center, .. } => std::slice::from_ref(center),
            Entity::Bezier(c) => c.control_points(),
            Entity::BSpline(c) => c.control_points(),
            Entity::Nurbs(c) => c.control_points(),
            Entity::Hermite(c) | Entity::Composite(c) => c.blocks(),
        }
    }

    /// Positions that bound the entity's drawing (with a circle's radius): its points, or for
    /// Hermite and composite curves the Bézier control points of their segments (nodes and the
    /// handles N ± t/3), whose hull holds the curve.
    ///
    /// ```
    /// use camber_sketch::{hermite_chain::HermiteChain, Entity};
    /// use nalgebra::{Point2, Vector2};
    /// let h = Entity::Hermite(HermiteChain::single(
    ///     Point2::new(0.0, 0.0), Point2::new(3.0, 0.0), Vector2::new(0.0, 3.0), Vector2::new(0.0, -3.0),
    /// )?);
    /// assert_eq!(h.hull_points()[1], Point2::new(0.0, 1.0));
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    pub fn hull_points(&self) -> std::borrow::Cow<'_, [Point2<f64>]> {
        match self {
            Entity::Hermite(c) | Entity::Composite(c) => c.bezier_points().into(),
            Entity::Ellipse { .. } | Entity::EllipticArc { .. } => match self.as_ellipse() {
                Some(e) => box_corners(&e).into(),
                None => self.points().into(),
            },
            other => other.points().into(),
        }
    }

    /// Where point block `index` is drawn and grabbed: the point itself, or for a tangent block
    /// of a Hermite or composite curve its handle N ± t/3 ([`HermiteChain::handle`]).
    pub fn handle(&self, index: usize) -> Option<Point2<f64>> {
        match self {
            Entity::Hermite(c) | Entity::Composite(c) => c.handle(index),
            other => other.points().get(index).copied(),
        }
    }

    /// The value of point block `index` that puts its handle at `q` (the inverse of
    /// [`Entity::handle`], the other blocks as they are).
    pub fn block_for_handle(&self, index: usize, q: Point2<f64>) -> Point2<f64> {
        match self {
            Entity::Hermite(c) | Entity::Composite(c) => c.block_for_handle(index, q),
            _ => q,
        }
    }

    /// Whether point block `index` is a tangent vector rather than a position (the tangent
    /// blocks of Hermite and composite curves).
    pub fn is_tangent_block(&self, index: usize) -> bool {
        match self {
            Entity::Hermite(c) | Entity::Composite(c) => c.is_tangent_block(index),
            _ => false,
        }
    }

    /// Scalar unknowns besides the points (the circle radius, an ellipse's semi-axis b), in block order after the points.
    pub fn scalars(&self) -> SmallVec<[f64; 1]> {
        match self {
            Entity::Circle { radius, .. } => smallvec::smallvec![*radius],
            Entity::Ellipse { semi_axis_b, .. } | Entity::EllipticArc { semi_axis_b, .. } => {
                smallvec::smallvec![*semi_axis_b]
            }
            _ => SmallVec::new(),
        }
    }

    /// The same entity with new points and scalars (as many as before), validated.
    ///
    /// # Errors
    /// [`Error::Geometry`] when the kernel refuses the points (non-finite coordinates),
    /// [`Error::NonFinite`] for a bad radius, [`Error::UnknownPoint`]-style count mismatches as
    /// [`Error::Geometry`].
    pub fn with_points(&self, points: &[Point2<f64>], scalars: &[f64]) -> Result<Entity> {
        for (i, p) in points.iter().enumerate() {
            check_point("point", i, p)?;
        }
        let expect = |n: usize| -> Result<()> {
            if points.len() == n {
                Ok(())
            } else {
                Err(Error::Geometry(camber_geom::Error::Dimension {
                    index: 0,
                    expected: n,
                    found: points.len(),
                }))
            }
        };
        Ok(match self {
            Entity::Point(_) => {
                expect(1)?;
                Entity::Point(points[0])
            }
            Entity::Line(_) => {
                expect(2)?;
                Entity::Line([points[0], points[1]])
            }
            Entity::Circle { radius, .. } => {
                expect(1)?;
                let r = scalars.first().copied().unwrap_or(*radius);
                if !(r.is_finite() && r > 0.0) {
                    return Err(Error::Geometry(camber_geom::Error::NonPositiveRadius {
                        value: r,
                    }));
                }
                Entity::Circle {
                    center: points[0],
                    radius: r,
                }
            }
            Entity::Arc(_) => {
                expect(3)?;
                let blocks = [points[0], points[1], points[2]];
                arc_of_blocks(&blocks)?;
                Entity::Arc(blocks)
            }
            Entity::Ellipse { semi_axis_b, .. } => {
                expect(2)?;
                let points = [points[0], points[1]];
                let semi_axis_b = scalars.first().copied().unwrap_or(*semi_axis_b);
                ellipse_of_blocks(&points, semi_axis_b)?;
                Entity::Ellipse {
                    points,
                    semi_axis_b,
                }
            }
            Entity::EllipticArc { semi_axis_b, .. } => {
                expect(4)?;
                let points = [points[0], points[1], points[2], points[3]];
                let semi_axis_b = scalars.first().copied().unwrap_or(*semi_axis_b);
                elliptic_arc_of_blocks(&points, semi_axis_b)?;
                Entity::EllipticArc {
                    points,
                    semi_axis_b,
                }
            }
            Entity::Bezier(c) => {
                expect(c.control_points().len())?;
                Entity::Bezier(BezierCurve2::try_new(points.to_vec())?)
            }
            Entity::BSpline(c) => Entity::BSpline(c.with_control_points(points.to_vec())?),
            Entity::Nurbs(c) => Entity::Nurbs(NurbsCurve2::try_new(
                c.degree(),
                c.knots().clone(),
                points.to_vec(),
                c.weights().to_vec(),
            )?),
            Entity::Hermite(c) => Entity::Hermite(c.with_blocks(points)?),
            Entity::Composite(c) => Entity::Composite(c.with_blocks(points)?),
        })
    }

    /// Whether the entity is a curve (line, Bézier, B-spline, NURBS, Hermite or composite): it
    /// has a parameter.
    pub fn is_curve(&self) -> bool {
        !matches!(
            self,
            Entity::Point(_)
                | Entity::Circle { .. }
                | Entity::Arc(_)
                | Entity::Ellipse { .. }
                | Entity::EllipticArc { .. }
        )
    }

    /// The parametric domain [a, b] of a curve (`None` for points and circles).
    pub fn domain(&self) -> Option<(f64, f64)> {
        match self {
            Entity::Line(_) | Entity::Bezier(_) => Some((0.0, 1.0)),
            Entity::BSpline(c) => Some(c.knots().domain(c.degree())),
            Entity::Nurbs(c) => Some(c.knots().domain(c.degree())),
            Entity::Hermite(c) | Entity::Composite(c) => Some((0.0, c.segment_count() as f64)),
            Entity::Point(_)
            | Entity::Circle { .. }
            | Entity::Arc(_)
            | Entity::Ellipse { .. }
            | Entity::EllipticArc { .. } => None,
        }
    }

    /// Whether the curve is clamped at its start (`at_end` false) or end (true): the first
    /// (last) p + 1 knots are equal, so C(a) = P₀ and C′(a) ∥ P₁ − P₀ (likewise at b). Hermite
    /// and composite curves are not: their end tangent is a block of its own, not a difference
    /// of neighbouring points.
    pub fn is_clamped(&self, at_end: bool) -> bool {
        let (degree, knots) = match self {
            Entity::Hermite(_) | Entity::Composite(_) => return false,
            Entity::Line(_) => return true,
            Entity::Bezier(c) => return c.degree() >= 1,
            Entity::BSpline(c) => (c.degree(), c.knots().as_slice()),
            Entity::Nurbs(c) => (c.degree(), c.knots().as_slice()),
            Entity::Point(_)
            | Entity::Circle { .. }
            | Entity::Arc(_)
            | Entity::Ellipse { .. }
            | Entity::EllipticArc { .. } => return false,
        };
        let run: &[f64] = if at_end {
            &knots[knots.len() - 1 - degree..]
        } else {
            &knots[..=degree]
        };
        degree >= 1 && run.windows(2).all(|w| (w[1] - w[0]).abs() <= 0.0)
    }

    /// The coefficients cⱼ of C⁽ᵏ⁾(u) = Σ cⱼ·Pⱼ for `order` k ∈ {0, 1} (see the module
    /// documentation), as (control point index, cⱼ) for the p + 1 basis functions that can be
    /// non-zero at u. `id` only names the entity in errors.
    ///
    /// # Errors
    /// [`Error::WrongEntityKind`] for a point or circle; [`Error::NonFinite`] and
    /// [`Error::ParameterOutsideDomain`] for a bad u.
    pub fn coefficients(&self, id: EntityId, u: f64, order: usize) -> Result<Terms> {
        if !self.is_curve() {
            return Err(Error::WrongEntityKind {
                entity: id,
                expected: "curve",
                found: self.kind_name(),
            });
        }
        if !u.is_finite() {
            return Err(Error::NonFinite {
                what: "parameter",
                index: 0,
                value: u,
            });
        }
        let (min, max) = self.domain().unwrap_or((0.0, 1.0));
        if u < min || u > max {
            return Err(Error::ParameterOutsideDomain {
                entity: id,
                value: u,
                min,
                max,
            });
        }
        let order = order.min(1);
        let basis = CurveBasis::of(self).ok_or(Error::WrongEntityKind {
            entity: id,
            expected: "curve",
            found: self.kind_name(),
        })?;
        let (at_u, points) = basis.at(u, order);
        let mut out: Terms = match at_u.fixed_coefficients() {
            Some(c) => points.iter().zip(c).map(|(j, c)| (*j, c[order])).collect(),
            None => Terms::new(),
        };
        out.retain(|(_, c)| c.abs() > 0.0);
        Ok(out)
    }

    /// The control point a B-spline or NURBS curve starts on (`start`) or ends on, when its
    /// knot vector is clamped at that end (the first or last p + 1 knots equal).
    fn clamped_end_point(&self, start: bool) -> Option<usize> {
        let (knots, degree, count) = match self {
            Entity::BSpline(c) => (c.knots().as_slice(), c.degree(), c.control_points().len()),
            Entity::Nurbs(c) => (c.knots().as_slice(), c.degree(), c.control_points().len()),
            _ => return None,
        };
        let m = degree + 1;
        if count == 0 || knots.len() < m {
            return None;
        }
        let (end, index) = if start {
            (&knots[..m], 0)
        } else {
            (&knots[knots.len() - m..], count - 1)
        };
        let clamped = end.windows(2).all(|w| (w[1] - w[0]).abs() <= 0.0);
        clamped.then_some(index)
    }

    /// The combination of this entity's points that a [`PointRef`] denotes.
    ///
    /// # Errors
    /// [`Error::UnknownPoint`] for an index past the points, [`Error::WrongEntityKind`] for
    /// `Point(_)` on a non-point or `Start`/`End` on a non-curve.
    pub fn resolve(&self, r: PointRef) -> Result<Terms> {
        let id = r.entity();
        match r {
            PointRef::Point(_) => match self {
                Entity::Point(_) => Ok(smallvec::smallvec![(0, 1.0)]),
                other => Err(Error::WrongEntityKind {
                    entity: id,
                    expected: "point",
                    found: other.kind_name(),
                }),
            },
            PointRef::Control(_, index) => {
                let count = self.points().len();
                if index < count {
                    Ok(smallvec::smallvec![(index, 1.0)])
                } else {
                    Err(Error::UnknownPoint {
                        entity: id,
                        index,
                        count,
                    })
                }
            }
            PointRef::Start(_) | PointRef::End(_) => {
                // An arc's ends are its blocks 1 and 2, an elliptic arc's 2 and 3.
                let first = match self {
                    Entity::Arc(_) => Some(1),
                    Entity::EllipticArc { .. } => Some(2),
                    _ => None,
                };
                if let Some(first) = first {
                    let index = if matches!(r, PointRef::Start(_)) {
                        first
                    } else {
                        first + 1
                    };
                    return Ok(smallvec::smallvec![(index, 1.0)]);
                }
                // A line or a Bézier curve starts at its first point and ends at its last: the
                // basis evaluation below gives exactly these weights, at a fraction of the cost.
                if let Entity::Line(_) | Entity::Bezier(_) = self {
                    let last = self.points().len().saturating_sub(1);
                    let index = if matches!(r, PointRef::Start(_)) {
                        0
                    } else {
                        last
                    };
                    return Ok(smallvec::smallvec![(index, 1.0)]);
                }
                // A spline clamped at an end (that end's knot of multiplicity p + 1) starts or
                // ends on its first or last control point, for any weights. The recurrence
                // gives that weight as right·(1/right), which need not round to 1 (0.999…9 for
                // a first span of 0.0387…); the joint of two such curves would then not be a
                // pure coincidence, so not one merged unknown, and the ends would differ in the
                // last bits after a solve.
                let start = matches!(r, PointRef::Start(_));
                if let Some(index) = self.clamped_end_point(start) {
                    return Ok(smallvec::smallvec![(index, 1.0)]);
                }
                let (a, b) = self.domain().ok_or(Error::WrongEntityKind {
                    entity: id,
                    expected: "curve",
                    found: self.kind_name(),
                })?;
                let u = if matches!(r, PointRef::Start(_)) {
                    a
                } else {
                    b
                };
                self.coefficients(id, u, 0)
            }
        }
    }

    /// Checks an entity on entry to a sketch as `id`: finite points, a positive radius, a
    /// line or curve whose points do not all coincide (its squared extent is a positive f64),
    /// a spline degree of at least 1.
    pub(crate) fn validate(&self, id: EntityId) -> Result<()> {
        for (i, p) in self.points().iter().enumerate() {
            check_point("point", i, p)?;
        }
        let degenerate = |reason| Error::DegenerateEntity {
            entity: id,
            kind: self.kind_name(),
            reason,
        };
        if let Entity::BSpline(c) = self {
            if c.degree() == 0 {
                return Err(degenerate("has degree 0 (a spline needs degree 1 or more)"));
            }
        }
        if let Entity::Nurbs(c) = self {
            if c.degree() == 0 {
                return Err(degenerate("has degree 0 (a spline needs degree 1 or more)"));
            }
        }
        if let Entity::Hermite(c) = self {
            if c.segment_count() != 1 {
                return Err(degenerate(
                    "has more than one segment (a chain of segments is a composite curve)",
                ));
            }
        }
        if let Entity::Arc(blocks) = self {
            arc_of_blocks(blocks).map_err(|reason| Error::InvalidArc { entity: id, reason })?;
        }
        let invalid_ellipse = |reason| Error::InvalidEllipse { entity: id, reason };
        match self {
            Entity::Ellipse {
                points,
                semi_axis_b,
            } => {
                ellipse_of_blocks(points, *semi_axis_b).map_err(invalid_ellipse)?;
            }
            Entity::EllipticArc {
                points,
                semi_axis_b,
            } => {
                elliptic_arc_of_blocks(points, *semi_axis_b).map_err(invalid_ellipse)?;
            }
            _ => {}
        }
        if !matches!(
            self,
            Entity::Point(_)
                | Entity::Circle { .. }
                | Entity::Arc(_)
                | Entity::Ellipse { .. }
                | Entity::EllipticArc { .. }
        ) {
            let points = self.hull_points();
            let spread = points
                .iter()
                .map(|p| (p - points[0]).norm_squared())
                .fold(0.0_f64, f64::max);
            if spread <= 0.0 || spread.is_nan() {
                return Err(degenerate(if matches!(self, Entity::Line(_)) {
                    "has zero length"
                } else {
                    "has all its control points at one place"
                }));
            }
        }
        if let Entity::Circle { radius, .. } = self {
            if !(radius.is_finite() && *radius > 0.0) {
                return Err(Error::Geometry(camber_geom::Error::NonPositiveRadius {
                    value: *radius,
                }));
            }
        }
        Ok(())
    }
}

/// The circular arc of an arc entity's blocks [C, S, E]: radius |S − C|, start angle
/// atan2(S − C), end angle atan2(E − C).
///
/// # Errors
/// The kernel's: [`camber_geom::Error::NonPositiveRadius`] when S = C (or E = C, as a radius
/// of 0), [`camber_geom::Error::DegenerateSweep`] when S and E lie in one direction from C.
pub fn arc_of_blocks(
    blocks: &[Point2<f64>; 3],
) -> std::result::Result<CircularArc<f64>, camber_geom::Error> {
    let [c, s, e] = blocks;
    let (vs, ve) = (s - c, e - c);
    let r = vs.norm();
    if ve.norm() <= 0.0 {
        return Err(camber_geom::Error::NonPositiveRadius { value: 0.0 });
    }
    CircularArc::try_new(*c, r, vs.y.atan2(vs.x), ve.y.atan2(ve.x))
}

/// Σ cⱼ·Pⱼ for terms over `points`.
pub(crate) fn combine(points: &[Point2<f64>], terms: &[(usize, f64)]) -> [f64; 2] {
    let mut s = [0.0; 2];
    for (j, c) in terms {
        if let Some(p) = points.get(*j) {
            s[0] += c * p.x;
            s[1] += c * p.y;
        }
    }
    s
}

/// Rejects a point with a non-finite coordinate.
pub(crate) fn check_point(what: &'static str, index: usize, p: &Point2<f64>) -> Result<()> {
    check_finite2(what, index, [p.x, p.y])
}

/// Rejects a pair with a non-finite entry (`index` is 2·index + coordinate in the error).
pub(crate) fn check_finite2(what: &'static str, index: usize, v: [f64; 2]) -> Result<()> {
    for (k, value) in v.into_iter().enumerate() {
        if !value.is_finite() {
            return Err(Error::NonFinite {
                what,
                index: 2 * index + k,
                value,
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use camber_geom::KnotVector;
    use camber_geom::ParametricCurve;

    #[test]
    fn nurbs_coefficients_reproduce_the_curve_and_its_tangent() {
        let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]).unwrap();
        let pts = vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 2.0),
            Point2::new(2.0, -1.0),
            Point2::new(3.0, 0.5),
        ];
        let c = NurbsCurve2::try_new(2, knots, pts.clone(), vec![1.0, 2.0, 0.5, 1.5]).unwrap();
        let e = Entity::Nurbs(c.clone());
        for u in [0.0, 0.2, 0.5, 0.77, 1.0] {
            let (p, d) = c.point_and_derivative(u).unwrap();
            let t0 = e.coefficients(EntityId(0), u, 0).unwrap();
            let t1 = e.coefficients(EntityId(0), u, 1).unwrap();
            let (a, b) = (combine(&pts, &t0), combine(&pts, &t1));
            assert_relative_eq!(a[0], p.x, epsilon = 1e-12);
            assert_relative_eq!(a[1], p.y, epsilon = 1e-12);
            assert_relative_eq!(b[0], d.x, epsilon = 1e-11);
            assert_relative_eq!(b[1], d.y, epsilon = 1e-11);
        }
        assert!(e.is_clamped(false) && e.is_clamped(true));
    }

    #[test]
    fn bad_parameters_and_kinds() {
        let e = Entity::Point(Point2::new(1.0, 1.0));
        assert!(matches!(
            e.coefficients(EntityId(2), 0.5, 0),
            Err(Error::WrongEntityKind { .. })
        ));
        let l = Entity::Line([Point2::origin(), Point2::new(1.0, 0.0)]);
        assert_eq!(
            l.coefficients(EntityId(3), 1.5, 0),
            Err(Error::ParameterOutsideDomain {
                entity: EntityId(3),
                value: 1.5,
                min: 0.0,
                max: 1.0
            })
        );
        assert!(matches!(
            l.resolve(PointRef::Control(EntityId(3), 2)),
            Err(Error::UnknownPoint {
                index: 2,
                count: 2,
                ..
            })
        ));
    }
}
