//! The sketch: entities and constraints as nodes of a petgraph graph, connected components,
//! the dirty set, and editing.
//!
//! The graph is bipartite: an entity node per entity, a constraint node per constraint, and an
//! edge from a constraint to every entity it reads. Two entities share a component exactly when
//! a chain of constraints links them; each component is an independent problem. Edits mark the
//! entities they touch as dirty, and [`Sketch::solve`] solves only the components that contain a
//! dirty entity.

mod cut;
mod describe;
mod extent;
pub mod fillet;
mod fillet_curve;
mod journal;
pub mod parameters;
pub(crate) mod prepared;
pub mod split;
pub mod trim_closed;
pub mod warnings;

use std::collections::{BTreeMap, BTreeSet};

use camber_geom::{BSplineCurve2, BezierCurve2, NurbsCurve2};
use camber_solve::{ConstraintId, Options, Priority};
use nalgebra::Point2;
use petgraph::stable_graph::{NodeIndex, StableUnGraph};
use petgraph::visit::NodeIndexable;

use crate::component::problem::build;
use crate::component::{Component, ComponentProblem};
use crate::constraints::Constraint;
use crate::ground::entity::{combine, Entity};

/// How many rounding units ε·M above the exact residual [`Sketch::solve_options`] allows: 2⁸,
/// room for the few operations a residual row takes and for Newton's stop at a tenth of the
/// tolerance.
pub const ROUNDING_HEADROOM: f64 = 256.0;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;

/// A node of the sketch graph.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Node {
    Entity(EntityId),
    Constraint(ConstraintId),
}

/// A planar sketch of entities held by constraints.
///
/// ```
/// use camber_sketch::constraints::{Fixed, PointAtParameter};
/// use camber_sketch::{PointRef, Sketch, Target};
/// use camber_geom::BezierCurve2;
/// use nalgebra::Point2;
/// let mut s = Sketch::new();
/// let c = s.add_bezier(BezierCurve2::try_new(vec![
///     Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(2.0, 0.0),
/// ])?)?;
/// s.add_constraint(Fixed::point(PointRef::Start(c)))?;
/// s.add_constraint(PointAtParameter { curve: c, u: 0.5, target: Target::At(Point2::new(1.0, 1.0)) })?;
/// let report = s.solve()?;
/// assert_eq!(report.components.len(), 1);
/// // C(½) = ¼P₀ + ½P₁ + ¼P₂ reaches (1, 1); P₀ stays.
/// let mid = s.curve_point(c, 0.5)?;
/// assert!((mid.y - 1.0).abs() < 1e-12 && s.point(PointRef::Start(c))?.y.abs() < 1e-15);
/// # Ok::<(), camber_sketch::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct Sketch {
    graph: StableUnGraph<Node, ()>,
    entities: BTreeMap<EntityId, (Entity, NodeIndex)>,
    constraints: BTreeMap<ConstraintId, (Constraint, NodeIndex)>,
    next_id: u64,
    dirty: BTreeSet<EntityId>,
    /// The constraints that read no entity (a custom constraint of no arguments or of its own
    /// parameters only): each is a component of its own, which no dirty mark reaches, so every
    /// solve looks at them.
    standalone: BTreeSet<ConstraintId>,
    /// The bounding box and largest magnitude of every entity, kept as entities change.
    pub(crate) extent: extent::Extent,
    revision: u64,
    options: Options,
    /// Weights of points in the minimum-norm metric, by (entity, point index); absent = 1.
    weights: BTreeMap<(EntityId, usize), f64>,
    /// Priority tiers of constraints that may be relaxed; absent = 0 (required).
    priorities: BTreeMap<ConstraintId, Priority>,
    /// Free labels of entities ([`Sketch::set_tag`]); absent = no tag.
    tags: BTreeMap<EntityId, String>,
    /// The components compiled and solved by earlier solves, kept with their plans
    /// ([`prepared`]).
    pub(crate) prepared: prepared::Prepared,
    /// Named parameters and the dimensions bound to expressions of them.
    pub(crate) parameters: parameters::Parameters,
}

impl Default for Sketch {
    fn default() -> Self {
        Self::new()
    }
}

impl EntityLookup for Sketch {
    fn lookup(&self, id: EntityId) -> Result<&Entity> {
        self.entities
            .get(&id)
            .map(|(e, _)| e)
            .ok_or(Error::UnknownEntity { entity: id })
    }

    fn weight(&self, id: EntityId, index: usize) -> f64 {
        self.weights.get(&(id, index)).copied().unwrap_or(1.0)
    }

    fn parameter(&self, name: &str) -> Option<f64> {
        self.parameters.get(name).map(|p| p.value)
    }
}

/// # Construction
impl Sketch {
    /// An empty sketch with the default solver options ([`crate::component::solve::default_options`]).
    pub fn new() -> Self {
        Self::with_options(crate::component::solve::default_options())
    }

    /// An empty sketch solved with `options` (tolerances, dense/sparse thresholds).
    pub fn with_options(options: Options) -> Self {
        Self {
            graph: StableUnGraph::default(),
            entities: BTreeMap::new(),
            constraints: BTreeMap::new(),
            next_id: 0,
            dirty: BTreeSet::new(),
            standalone: BTreeSet::new(),
            extent: extent::Extent::default(),
            revision: 0,
            options,
            weights: BTreeMap::new(),
            priorities: BTreeMap::new(),
            tags: BTreeMap::new(),
            prepared: prepared::Prepared::default(),
            parameters: parameters::Parameters::default(),
        }
    }
}

/// # Entities
impl Sketch {
    /// Adds an entity (validated: finite points, positive radius).
    ///
    /// # Errors
    /// [`Error::NonFinite`] or [`Error::Geometry`]; nothing is added then.
    pub fn add_entity(&mut self, entity: Entity) -> Result<EntityId> {
        self.add_entity_with_id(EntityId(self.next_id), entity)
    }

    /// Adds an entity under a given id (as a sketch file names it), validated like
    /// [`Sketch::add_entity`]. Later automatic ids continue past the largest id used.
    ///
    /// ```
    /// use camber_sketch::{EntityId, Error, Sketch, Entity};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// s.add_entity_with_id(EntityId(7), Entity::Point(Point2::new(1.0, 2.0)))?;
    /// assert_eq!(s.add_point(Point2::origin())?, EntityId(8));
    /// let again = s.add_entity_with_id(EntityId(7), Entity::Point(Point2::origin()));
    /// assert_eq!(again, Err(Error::DuplicateId { id: 7 }));
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::DuplicateId`] when an entity or constraint already has that id; the
    /// validation errors of [`Sketch::add_entity`]. Nothing is added then.
    pub fn add_entity_with_id(&mut self, id: EntityId, entity: Entity) -> Result<EntityId> {
        self.check_free_id(id.0)?;
        entity.validate(id)?;
        self.next_id = self.next_id.max(id.0.saturating_add(1));
        let node = self.graph.add_node(Node::Entity(id));
        self.extent.add(&entity);
        self.entities.insert(id, (entity, node));
        self.dirty.insert(id);
        self.revision += 1;
        Ok(id)
    }

    /// Adds a point.
    ///
    /// # Errors
    /// As [`Sketch::add_entity`].
    pub fn add_point(&mut self, p: Point2<f64>) -> Result<EntityId> {
        self.add_entity(Entity::Point(p))
    }

    /// Adds a line through two points.
    ///
    /// # Errors
    /// As [`Sketch::add_entity`].
    pub fn add_line(&mut self, a: Point2<f64>, b: Point2<f64>) -> Result<EntityId> {
        self.add_entity(Entity::Line([a, b]))
    }

    /// Adds a circle.
    ///
    /// # Errors
    /// As [`Sketch::add_entity`].
    pub fn add_circle(&mut self, center: Point2<f64>, radius: f64) -> Result<EntityId> {
        self.add_entity(Entity::Circle { center, radius })
    }

    /// Adds a circular arc (blocks [centre, start, end], see [`Entity::Arc`]).
    ///
    /// # Errors
    /// As [`Sketch::add_entity`].
    pub fn add_arc(&mut self, arc: &camber_geom::CircularArc<f64>) -> Result<EntityId> {
        self.add_entity(Entity::arc(arc))
    }

    /// Adds an ellipse (blocks [centre, a-axis vertex] and b, see [`Entity::Ellipse`]).
    ///
    /// # Errors
    /// As [`Sketch::add_entity`].
    ///
    /// ```
    /// use camber_geom::Ellipse;
    /// use camber_sketch::Sketch;
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// s.add_ellipse(&Ellipse::try_new(Point2::new(0.0, 0.0), 2.0, 1.0, 0.3)?)?;
    /// // Centre, vertex and b: 5 DOF.
    /// assert_eq!(s.analyze()?[0].analysis.dof, 5);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn add_ellipse(&mut self, ellipse: &camber_geom::Ellipse<f64>) -> Result<EntityId> {
        self.add_entity(Entity::ellipse(ellipse))
    }

    /// Adds an elliptic arc (blocks [centre, a-axis vertex, start, end] and b, see
    /// [`Entity::EllipticArc`]).
    ///
    /// # Errors
    /// As [`Sketch::add_entity`].
    ///
    /// ```
    /// use camber_geom::EllipticArc;
    /// use camber_sketch::Sketch;
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// s.add_elliptic_arc(&EllipticArc::try_new(Point2::new(0.0, 0.0), 2.0, 1.0, 0.3, 0.0, 2.0)?)?;
    /// // 9 unknowns less its two rows (both ends on the ellipse): 7 DOF.
    /// assert_eq!(s.analyze()?[0].analysis.dof, 7);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn add_elliptic_arc(&mut self, arc: &camber_geom::EllipticArc<f64>) -> Result<EntityId> {
        self.add_entity(Entity::elliptic_arc(arc))
    }

    /// Adds a Bézier curve.
    ///
    /// # Errors
    /// As [`Sketch::add_entity`].
    pub fn add_bezier(&mut self, curve: BezierCurve2<f64>) -> Result<EntityId> {
        self.add_entity(Entity::Bezier(curve))
    }

    /// Adds a B-spline curve.
    ///
    /// # Errors
    /// As [`Sketch::add_entity`].
    pub fn add_bspline(&mut self, curve: BSplineCurve2<f64>) -> Result<EntityId> {
        self.add_entity(Entity::BSpline(curve))
    }

    /// Adds a NURBS curve (its weights stay fixed in every solve).
    ///
    /// # Errors
    /// As [`Sketch::add_entity`].
    pub fn add_nurbs(&mut self, curve: NurbsCurve2<f64>) -> Result<EntityId> {
        self.add_entity(Entity::Nurbs(curve))
    }

    /// The entity with that id.
    ///
    /// # Errors
    /// [`Error::UnknownEntity`].
    pub fn entity(&self, id: EntityId) -> Result<&Entity> {
        self.lookup(id)
    }

    /// Every entity, by id.
    pub fn entities(&self) -> impl Iterator<Item = (EntityId, &Entity)> {
        self.entities.iter().map(|(id, (e, _))| (*id, e))
    }

    /// The location of a point of the sketch (for `Start`/`End`, the curve point there).
    ///
    /// # Errors
    /// [`Error::UnknownEntity`], [`Error::UnknownPoint`], [`Error::WrongEntityKind`].
    pub fn point(&self, r: PointRef) -> Result<Point2<f64>> {
        let e = self.lookup(r.entity())?;
        let v = combine(e.points(), &e.resolve(r)?);
        Ok(Point2::new(v[0], v[1]))
    }

    /// The curve point C(u) of a curve entity.
    ///
    /// # Errors
    /// As [`Entity::coefficients`].
    pub fn curve_point(&self, curve: EntityId, u: f64) -> Result<Point2<f64>> {
        let e = self.lookup(curve)?;
        let v = combine(e.points(), &e.coefficients(curve, u, 0)?);
        Ok(Point2::new(v[0], v[1]))
    }

    /// Moves one point block (a point entity, a control point, a line end, a circle centre) to
    /// `to`, marking the entity dirty. The constraints are not solved here.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for `to`; [`Error::WrongEntityKind`] for `Start`/`End` references
    /// (they are combinations, move a control point instead); id errors. Nothing changes then.
    pub fn set_point(&mut self, r: PointRef, to: Point2<f64>) -> Result<()> {
        crate::ground::entity::check_point("point", 0, &to)?;
        let e = self.lookup(r.entity())?;
        let index = match (r, e) {
            (PointRef::Point(_), Entity::Point(_)) => 0,
            (PointRef::Control(_, i), _) => i,
            _ => {
                return Err(Error::WrongEntityKind {
                    entity: r.entity(),
                    expected: "point or control point",
                    found: e.kind_name(),
                })
            }
        };
        e.resolve(PointRef::Control(r.entity(), index))?;
        let mut pts = e.points().to_vec();
        pts[index] = to;
        let updated = e.with_points(&pts, &e.scalars())?;
        if let Some(slot) = self.entities.get_mut(&r.entity()) {
            self.extent.replace(&slot.0, &updated);
            slot.0 = updated;
        }
        self.touch(r.entity());
        self.revision += 1;
        Ok(())
    }

    /// Sets the weight w > 0 of a point or control point in the minimum-norm metric
    /// Σ wᵢ‖ΔPᵢ‖²: solves and drag sessions move a point of weight w as if moving it cost w times
    /// as much, so heavier points move less (w = 1 is the default; a very large w approaches
    /// fixing the point without constraining it). Marks the entity dirty.
    ///
    /// ```
    /// use camber_geom::BezierCurve2;
    /// use camber_sketch::constraints::PointAtParameter;
    /// use camber_sketch::{PointRef, Sketch, Target};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let line = BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(2.0, 0.0)])?;
    /// let c = s.add_bezier(line)?;
    /// s.set_weight(PointRef::Control(c, 0), 4.0)?;
    /// s.add_constraint(PointAtParameter {
    ///     curve: c,
    ///     u: 0.5,
    ///     target: Target::At(Point2::new(1.0, 1.0)),
    /// })?;
    /// s.solve()?;
    /// // ½ΔP₀ + ½ΔP₁ = (0, 1) with ΔPᵢ ∝ 1/wᵢ: ΔP₀ = (0, 0.4), ΔP₁ = (0, 1.6).
    /// assert!((s.point(PointRef::Control(c, 0))?.y - 0.4).abs() < 1e-12);
    /// assert!((s.point(PointRef::Control(c, 1))?.y - 1.6).abs() < 1e-12);
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::UnknownEntity`], [`Error::UnknownPoint`], [`Error::WrongEntityKind`] for a
    /// reference that is not a point or control point; [`Error::InvalidWeight`] for w ≤ 0 or
    /// non-finite w. Nothing changes then.
    pub fn set_weight(&mut self, r: PointRef, weight: f64) -> Result<()> {
        let e = self.lookup(r.entity())?;
        let index = match (r, e) {
            (PointRef::Point(_), Entity::Point(_)) => 0,
            (PointRef::Control(_, i), _) => i,
            _ => {
                return Err(Error::WrongEntityKind {
                    entity: r.entity(),
                    expected: "point or control point",
                    found: e.kind_name(),
                })
            }
        };
        e.resolve(PointRef::Control(r.entity(), index))?;
        if !(weight.is_finite() && weight > 0.0) {
            return Err(Error::InvalidWeight {
                entity: r.entity(),
                index,
                value: weight,
            });
        }
        self.weights.insert((r.entity(), index), weight);
        self.touch(r.entity());
        self.revision += 1;
        Ok(())
    }

    /// Removes an entity no constraint reads.
    ///
    /// # Errors
    /// [`Error::UnknownEntity`]; [`Error::EntityInUse`] naming a constraint that reads it.
    pub fn remove_entity(&mut self, id: EntityId) -> Result<Entity> {
        let (_, node) = self
            .entities
            .get(&id)
            .ok_or(Error::UnknownEntity { entity: id })?;
        if let Some(Node::Constraint(c)) = self
            .graph
            .neighbors(*node)
            .next()
            .and_then(|n| self.graph.node_weight(n).copied())
        {
            return Err(Error::EntityInUse {
                entity: id,
                constraint: c,
            });
        }
        let (e, node) = self
            .entities
            .remove(&id)
            .ok_or(Error::UnknownEntity { entity: id })?;
        self.graph.remove_node(node);
        self.prepared.forget_entity(id);
        self.dirty.remove(&id);
        self.weights.retain(|(entity, _), _| *entity != id);
        self.tags.remove(&id);
        self.revision += 1;
        Ok(e)
    }
}

/// The longest entity tag, in bytes.
pub const MAX_TAG_LEN: usize = 255;

/// # Tags
impl Sketch {
    /// Labels an entity with a tag, a free name such as the DXF layer it came from, or clears
    /// its tag with `None`. Tags are saved in sketch files and never affect a solve.
    ///
    /// ```
    /// use camber_sketch::{Entity, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let line = s.add_entity(Entity::Line([Point2::new(0.0, 0.0), Point2::new(1.0, 0.0)]))?;
    /// s.set_tag(line, Some("OUTLINE"))?;
    /// assert_eq!(s.tag(line), Some("OUTLINE"));
    /// assert!(s.set_tag(line, Some("two\nlines")).is_err());
    /// s.set_tag(line, None)?;
    /// assert_eq!(s.tag(line), None);
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::UnknownEntity`]; [`Error::InvalidTag`] for an empty tag, one longer than
    /// [`MAX_TAG_LEN`] bytes or one holding a control character. Nothing changes then.
    pub fn set_tag(&mut self, id: EntityId, tag: Option<&str>) -> Result<()> {
        if !self.entities.contains_key(&id) {
            return Err(Error::UnknownEntity { entity: id });
        }
        let Some(tag) = tag else {
            self.tags.remove(&id);
            return Ok(());
        };
        let reason = if tag.is_empty() {
            Some("a tag is not empty")
        } else if tag.len() > MAX_TAG_LEN {
            Some("a tag has at most 255 bytes")
        } else if tag.chars().any(char::is_control) {
            Some("a tag holds no control character")
        } else {
            None
        };
        if let Some(reason) = reason {
            return Err(Error::InvalidTag {
                entity: id,
                tag: tag.chars().take(64).collect(),
                reason,
            });
        }
        self.tags.insert(id, tag.to_owned());
        Ok(())
    }

    /// The tag of an entity ([`Sketch::set_tag`]), `None` when it has none or does not exist.
    pub fn tag(&self, id: EntityId) -> Option<&str> {
        self.tags.get(&id).map(String::as_str)
    }
}

/// # Replacing geometry
impl Sketch {
    /// Replaces an entity by another of the same kind (a curve after knot insertion or
    /// refinement, degree elevation, …), keeping its id. Every constraint that reads it must
    /// still be valid (a parameter still inside the domain, a control point index still
    /// there): they are checked against the new entity, and any failure leaves the sketch as
    /// it was. Point weights of the entity are dropped (the point indices may mean other
    /// points now). Marks the entity dirty.
    ///
    /// ```
    /// use camber_geom::{BSplineCurve2, KnotVector};
    /// use camber_sketch::{Entity, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let pts = (0..4).map(|i| Point2::new(f64::from(i), 0.0)).collect();
    /// let c = BSplineCurve2::try_new(3, KnotVector::clamped_uniform(3, 4)?, pts)?;
    /// let id = s.add_bspline(c.clone())?;
    /// let refined = c.insert_knot(0.5, 1)?;
    /// s.set_entity(id, Entity::BSpline(refined))?;
    /// assert_eq!(s.entity(id)?.points().len(), 5);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::UnknownEntity`]; [`Error::WrongEntityKind`] for another kind; the validation
    /// errors of the entity or of a constraint reading it. Nothing changes then.
    pub fn set_entity(&mut self, id: EntityId, entity: Entity) -> Result<()> {
        let old = self.lookup(id)?;
        if std::mem::discriminant(old) != std::mem::discriminant(&entity) {
            return Err(Error::WrongEntityKind {
                entity: id,
                expected: old.kind_name(),
                found: entity.kind_name(),
            });
        }
        entity.validate(id)?;
        let previous = match self.entities.get_mut(&id) {
            Some(slot) => {
                self.extent.replace(&slot.0, &entity);
                std::mem::replace(&mut slot.0, entity)
            }
            None => return Err(Error::UnknownEntity { entity: id }),
        };
        // The graph's neighbours of the entity: every constraint reading it, and those reading
        // a constraint that reads it (checked too: they depend on it as well).
        for cid in self.constraints_at(id) {
            let outcome = self.constraint(cid).and_then(|c| c.compile(self));
            if let Err(e) = outcome {
                if let Some(slot) = self.entities.get_mut(&id) {
                    self.extent.replace(&slot.0, &previous);
                    slot.0 = previous;
                }
                return Err(e);
            }
        }
        self.weights.retain(|(entity, _), _| *entity != id);
        self.touch(id);
        self.revision += 1;
        Ok(())
    }
}

impl Sketch {
    /// Fails with [`Error::DuplicateId`] when an entity or a constraint already uses `id`.
    fn check_free_id(&self, id: u64) -> Result<()> {
        if self.entities.contains_key(&EntityId(id))
            || self.constraints.contains_key(&ConstraintId(id))
        {
            Err(Error::DuplicateId { id })
        } else {
            Ok(())
        }
    }
}

/// # Constraints
impl Sketch {
    /// Adds a constraint after validating it against the current entities (ids, indices,
    /// parameters inside the domains, finite numbers, non-zero directions, clamped ends for the
    /// elimination form, a custom residual's declared arguments). Its entities become dirty;
    /// nothing is solved here. Any kind converts: `s.add_constraint(Horizontal::line(l))`.
    ///
    /// # Errors
    /// The validation errors; nothing is added then.
    pub fn add_constraint(&mut self, constraint: impl Into<Constraint>) -> Result<ConstraintId> {
        self.add_constraint_with_id(ConstraintId(self.next_id), constraint)
    }

    /// Adds a constraint under a given id (as a sketch file names it), validated like
    /// [`Sketch::add_constraint`]. Entities and constraints share one id space; later automatic
    /// ids continue past the largest id used.
    ///
    /// # Errors
    /// [`Error::DuplicateId`] when an entity or constraint already has that id;
    /// [`Error::UnknownConstraint`] for another constraint it reads that does not exist; the
    /// validation errors of [`Sketch::add_constraint`]. Nothing is added then.
    pub fn add_constraint_with_id(
        &mut self,
        id: ConstraintId,
        constraint: impl Into<Constraint>,
    ) -> Result<ConstraintId> {
        let constraint = constraint.into();
        self.check_free_id(id.0)?;
        constraint.compile(self)?;
        let mut entities = constraint.entities();
        for other in constraint.reads_constraints() {
            for e in self.constraint(other)?.entities() {
                if !entities.contains(&e) {
                    entities.push(e);
                }
            }
        }
        self.next_id = self.next_id.max(id.0.saturating_add(1));
        let node = self.graph.add_node(Node::Constraint(id));
        if entities.is_empty() {
            self.standalone.insert(id);
        }
        for e in entities {
            if let Some((_, en)) = self.entities.get(&e) {
                self.graph.add_edge(node, *en, ());
            }
            self.touch(e);
        }
        self.constraints.insert(id, (constraint, node));
        self.revision += 1;
        Ok(id)
    }

    /// The constraint with that id.
    ///
    /// # Errors
    /// [`Error::UnknownConstraint`].
    pub fn constraint(&self, id: ConstraintId) -> Result<&Constraint> {
        self.constraints
            .get(&id)
            .map(|(c, _)| c)
            .ok_or(Error::UnknownConstraint { constraint: id })
    }

    /// Every constraint, by id.
    pub fn constraints(&self) -> impl Iterator<Item = (ConstraintId, &Constraint)> {
        self.constraints.iter().map(|(id, (c, _))| (*id, c))
    }

    /// Removes a constraint; its entities become dirty.
    ///
    /// # Errors
    /// [`Error::UnknownConstraint`]; [`Error::ConstraintInUse`] naming a constraint that reads
    /// its free parameters.
    pub fn remove_constraint(&mut self, id: ConstraintId) -> Result<Constraint> {
        if !self.constraints.contains_key(&id) {
            return Err(Error::UnknownConstraint { constraint: id });
        }
        if let Some(by) = self.readers_of(id) {
            return Err(Error::ConstraintInUse { constraint: id, by });
        }
        let (c, node) = self
            .constraints
            .remove(&id)
            .ok_or(Error::UnknownConstraint { constraint: id })?;
        self.graph.remove_node(node);
        self.standalone.remove(&id);
        self.priorities.remove(&id);
        self.parameters.bindings.remove(&id);
        for e in c.entities() {
            self.touch(e);
        }
        self.revision += 1;
        Ok(c)
    }
}

/// # Dimensions
impl Sketch {
    /// Sets the value of a dimension (the distance of a [`crate::constraints::Distance`], the
    /// radius of a [`crate::constraints::Radius`], an angle, an arc length, …) and marks its
    /// component for the next solve. The component a solve prepared is kept: the next
    /// [`Sketch::solve`] replaces the constraint's residuals in place and re-solves that
    /// component alone on its kept plan (docs/sketch.md, "Dimension edits").
    ///
    /// ```
    /// use camber_sketch::constraints::{Distance, Fixed};
    /// use camber_sketch::{PointRef, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let a = s.add_point(Point2::new(0.0, 0.0))?;
    /// let b = s.add_point(Point2::new(1.0, 0.0))?;
    /// s.add_constraint(Fixed::point(PointRef::Point(a)))?;
    /// let d = s.add_constraint(Distance { a: PointRef::Point(a), b: PointRef::Point(b), distance: 1.0 })?;
    /// s.solve()?;
    /// s.set_value(d, 2.5)?;
    /// assert_eq!(s.constraint(d)?.value(), Some(2.5));
    /// s.solve()?;
    /// assert!((s.point(PointRef::Point(b))?.x - 2.5).abs() < 1e-12);
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::UnknownConstraint`]; [`Error::NoValue`] for a kind without a value;
    /// [`Error::ValueBound`] for a value that follows an expression of the parameters
    /// ([`Sketch::bind_dimension`]: change the parameters, or bind it again); the
    /// validation errors of the kind for the new value (a negative distance, a non-finite
    /// number, …). The sketch is unchanged then.
    pub fn set_value(&mut self, id: ConstraintId, value: f64) -> Result<()> {
        let (constraint, _) = self
            .constraints
            .get(&id)
            .ok_or(Error::UnknownConstraint { constraint: id })?;
        let mut edited = constraint.clone();
        if !edited.set_value(value) {
            return Err(Error::NoValue {
                constraint: id,
                kind: edited.kind_name(),
            });
        }
        // A dimension bound to an expression of the parameters follows them: a value set here
        // would be overwritten by the next parameter change, so it is refused.
        for binding in self.parameters.bindings(id) {
            let follows =
                parameters::apply(&edited, std::slice::from_ref(binding), &self.parameters)?;
            if follows.value() != Some(value) {
                return Err(Error::ValueBound {
                    constraint: id,
                    path: binding.path.clone(),
                    expression: binding.text.clone(),
                });
            }
        }
        edited.compile(self)?;
        self.replace_constraint_value(id, edited);
        Ok(())
    }

    /// Stores `c` as constraint `id` when only its values changed (a dimension, a parameter it
    /// reads): the same entities, so its prepared component is kept and its residuals are
    /// replaced in place before the next solve (compiled again when they cannot be).
    pub(crate) fn replace_constraint_value(&mut self, id: ConstraintId, c: Constraint) {
        let entities = c.entities();
        if let Some(slot) = self.constraints.get_mut(&id) {
            slot.0 = c;
        }
        self.prepared.edit(id);
        for e in entities {
            self.dirty.insert(e);
        }
        self.revision += 1;
    }
}

/// # Priorities
impl Sketch {
    /// Gives a constraint a priority tier: 0 (the default) is required; a constraint of tier
    /// 1, 2, … may be relaxed when the whole set cannot be met, the higher tiers first. The
    /// solve then meets the tiers in order, each as closely as the tiers before allow (least
    /// squares within their solutions), and its report names every relaxed constraint
    /// ([`crate::SketchReport::relaxed`]). A constraint with a priority is always solved as
    /// rows, never folded into the unknowns (a `fixed` point stays an unknown held by two
    /// rows, a coincidence is not merged), so that it can give way. Marks its entities dirty.
    ///
    /// ```
    /// use camber_sketch::constraints::{Distance, Fixed};
    /// use camber_sketch::{PointRef, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let a = s.add_point(Point2::new(0.0, 0.0))?;
    /// let b = s.add_point(Point2::new(1.0, 0.0))?;
    /// s.add_constraint(Fixed::point(PointRef::Point(a)))?;
    /// s.add_constraint(Fixed::point(PointRef::Point(b)))?;
    /// // 2 apart cannot be met with both points fixed: as priority 1 it gives way.
    /// let d = s.add_constraint(Distance { a: PointRef::Point(a), b: PointRef::Point(b), distance: 2.0 })?;
    /// s.set_priority(d, 1)?;
    /// let report = s.solve()?;
    /// assert_eq!(report.relaxed(), vec![d]);
    /// assert_eq!(s.point(PointRef::Point(b))?, Point2::new(1.0, 0.0));
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::UnknownConstraint`].
    pub fn set_priority(&mut self, id: ConstraintId, priority: Priority) -> Result<()> {
        let entities = self.constraint(id)?.entities();
        if priority == 0 {
            self.priorities.remove(&id);
        } else {
            self.priorities.insert(id, priority);
        }
        for e in entities {
            self.mark_dirty(e);
        }
        Ok(())
    }

    /// A constraint's priority tier (0, required, unless [`Sketch::set_priority`] said
    /// otherwise; 0 also for an unknown id).
    pub fn priority(&self, id: ConstraintId) -> Priority {
        self.priorities.get(&id).copied().unwrap_or(0)
    }
}

/// # Components
impl Sketch {
    /// The connected components of the graph, each with its entities and constraints sorted by
    /// id, ordered by their smallest entity id; then, in id order, one component for each
    /// constraint that reads no entity (a custom constraint of no arguments or of its own
    /// parameters only), so that it is solved and analysed like any other.
    pub fn components(&self) -> Vec<Component> {
        let (mut out, seen) = self.walk_from(self.entities.values().map(|(_, node)| *node));
        for (id, (_, node)) in &self.constraints {
            if !seen[node.index()] {
                out.push(Component {
                    entities: Vec::new(),
                    constraints: vec![*id],
                });
            }
        }
        out
    }

    /// The components holding a dirty entity, as [`Sketch::components`] gives them (entities
    /// and constraints sorted, ordered by smallest entity id), found by walking the graph from
    /// the dirty entities only: a re-solve after one edit costs the size of what it touches,
    /// not of the sketch. The constraints that read no entity follow, one component each, as
    /// in [`Sketch::components`]: no mark reaches them, and they are cheap to check again.
    pub(crate) fn dirty_components(&self) -> Vec<Component> {
        let starts = self
            .dirty
            .iter()
            .filter_map(|id| self.entities.get(id).map(|(_, node)| *node));
        let (mut out, _) = self.walk_from(starts);
        out.sort_unstable_by_key(|c| c.entities.first().copied());
        out.extend(self.standalone.iter().map(|id| Component {
            entities: Vec::new(),
            constraints: vec![*id],
        }));
        out
    }

    /// The components reached from the graph nodes `starts` (one per start not reached from an
    /// earlier one, in the order of the starts), each with its entities and constraints sorted
    /// by id; and which nodes the walk saw.
    fn walk_from(&self, starts: impl Iterator<Item = NodeIndex>) -> (Vec<Component>, Vec<bool>) {
        let mut seen = vec![false; self.graph.node_bound()];
        let mut out = Vec::new();
        let mut stack = Vec::new();
        for node in starts {
            if seen[node.index()] {
                continue;
            }
            let mut comp = Component {
                entities: Vec::new(),
                constraints: Vec::new(),
            };
            seen[node.index()] = true;
            stack.push(node);
            while let Some(n) = stack.pop() {
                match self.graph.node_weight(n) {
                    Some(Node::Entity(e)) => comp.entities.push(*e),
                    Some(Node::Constraint(c)) => comp.constraints.push(*c),
                    None => {}
                }
                for m in self.graph.neighbors(n) {
                    if !seen[m.index()] {
                        seen[m.index()] = true;
                        stack.push(m);
                    }
                }
            }
            comp.entities.sort_unstable();
            comp.constraints.sort_unstable();
            out.push(comp);
        }
        (out, seen)
    }

    /// The component containing an entity.
    ///
    /// # Errors
    /// [`Error::UnknownEntity`].
    pub fn component_of(&self, entity: EntityId) -> Result<Component> {
        self.lookup(entity)?;
        self.components()
            .into_iter()
            .find(|c| c.entities.binary_search(&entity).is_ok())
            .ok_or(Error::UnknownEntity { entity })
    }

    /// Entities changed since they were last solved.
    pub fn dirty(&self) -> impl Iterator<Item = EntityId> + '_ {
        self.dirty.iter().copied()
    }

    /// A counter that grows with every edit (used to detect stale drag sessions).
    pub fn revision(&self) -> u64 {
        self.revision
    }

    /// The solver options.
    pub fn options(&self) -> &Options {
        &self.options
    }

    /// The options solves, drags and analyses of this sketch use: [`Sketch::options`] with the
    /// residual tolerance raised, for sketches far from the origin, to what double rounding
    /// can reach at their coordinates: tol = max(tolerance, [`ROUNDING_HEADROOM`]·ε·M), M the
    /// largest |coordinate| (or radius) of any entity and ε the machine epsilon. Residuals are
    /// differences of coordinates, so they cannot be computed more exactly than ε·M: with the
    /// default 10⁻¹⁰ nothing changes below M ≈ 1,760, and a rectangle at x = 10⁷ solves to
    /// 5.7·10⁻⁷ instead of chasing 10⁻¹⁰ it can never reach. The solve report records the
    /// tolerance used ([`crate::SketchReport::tolerance`]).
    ///
    /// ```
    /// use camber_sketch::Sketch;
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// s.add_point(Point2::new(1.0, 2.0))?;
    /// assert_eq!(s.solve_options().tolerance, s.options().tolerance);
    /// s.add_point(Point2::new(1e7, 0.0))?;
    /// assert!(s.solve_options().tolerance > 5e-7);
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    pub fn solve_options(&self) -> Options {
        let magnitude = self.extent.magnitude();
        let floor = ROUNDING_HEADROOM * f64::EPSILON * magnitude;
        let mut options = self.options.clone();
        if floor > options.tolerance {
            options.tolerance = floor;
        }
        options
    }

    /// Replaces the solver options (tolerances, thresholds, the nonlinear settings such as a
    /// forced solver or the soft mode) for the following solves and drags. Marks nothing
    /// dirty.
    pub fn set_options(&mut self, options: Options) {
        self.prepared.forget_all();
        self.options = options;
    }

    /// Builds (without solving) the problem of the component containing `entity`.
    ///
    /// # Errors
    /// [`Error::UnknownEntity`]; errors of compiling the constraints.
    pub fn component_problem(&self, entity: EntityId) -> Result<ComponentProblem> {
        let comp = self.component_of(entity)?;
        self.build_component(&comp)
    }

    pub(crate) fn build_component(&self, comp: &Component) -> Result<ComponentProblem> {
        // The component's entities, found by binary search in a short list instead of the
        // sketch's map at every one of the many lookups below.
        let lookup = crate::ground::lookup::ComponentEntities::new(self, &comp.entities);
        let mut compiled = Vec::with_capacity(comp.constraints.len());
        let mut reads_values = false;
        for id in &comp.constraints {
            let (pieces, reads) = self.constraint(*id)?.compile_tracked(&lookup)?;
            reads_values |= reads;
            let pieces = if self.priority(*id) > 0 {
                crate::constraints::piece::as_rows(&lookup, pieces)?
            } else {
                pieces
            };
            compiled.push((*id, pieces));
        }
        let relaxable: Vec<ConstraintId> = comp
            .constraints
            .iter()
            .copied()
            .filter(|id| self.priority(*id) > 0)
            .collect();
        let mut cp = build(&lookup, comp, &compiled, &relaxable)?;
        // Rows of relaxable constraints hold their points' current values, and eliminations
        // start their auxiliary unknowns from them.
        cp.refreshable = !reads_values && relaxable.is_empty() && cp.problem.num_aux() == 0;
        for id in relaxable {
            cp.problem.set_priority(id, self.priority(id));
        }
        Ok(cp)
    }

    /// Marks an entity as changed, so that the next solve solves its component.
    pub(crate) fn mark_dirty(&mut self, id: EntityId) {
        self.touch(id);
        self.revision += 1;
    }

    /// Marks an entity as changed by something other than a constraint's value: its prepared
    /// component is dropped ([`prepared`]).
    /// The constraints joined to entity `id` in the graph: those reading it and those reading
    /// the free parameters of a constraint that reads it. Empty for an unknown entity.
    pub(crate) fn constraints_at(&self, id: EntityId) -> Vec<ConstraintId> {
        let Some((_, node)) = self.entities.get(&id) else {
            return Vec::new();
        };
        let mut out: Vec<ConstraintId> = self
            .graph
            .neighbors(*node)
            .filter_map(|n| match self.graph.node_weight(n) {
                Some(Node::Constraint(c)) => Some(*c),
                _ => None,
            })
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    }

    /// A constraint that reads the free parameters of constraint `id`, if any. A reader is
    /// joined in the graph to every entity of `id`, so only the constraints at the first of
    /// them are looked at (all constraints when `id` reads no entity).
    fn readers_of(&self, id: ConstraintId) -> Option<ConstraintId> {
        let reads = |c: &Constraint| c.reads_constraints().contains(&id);
        let first = self.constraints.get(&id)?.0.entities().first().copied();
        match first {
            Some(e) => self
                .constraints_at(e)
                .into_iter()
                .find(|by| *by != id && self.constraints.get(by).is_some_and(|(c, _)| reads(c))),
            None => self
                .constraints
                .iter()
                .find(|(_, (c, _))| reads(c))
                .map(|(by, _)| *by),
        }
    }

    fn touch(&mut self, id: EntityId) {
        self.prepared.forget_entity(id);
        self.dirty.insert(id);
    }

    /// Stores solved free parameters (contact parameters, a custom constraint's own) into
    /// their constraints: (constraint, k, value) for the k-th free parameter of each.
    pub(crate) fn store_free(&mut self, free: &[(ConstraintId, usize, f64)]) {
        for (id, k, u) in free {
            if let Some(slot) = self.constraints.get_mut(id) {
                slot.0.set_free_parameter(*k, *u);
            }
        }
    }

    /// Writes solved entities and clears their dirty marks.
    pub(crate) fn commit(&mut self, updates: Vec<(EntityId, Entity)>, clean: &[EntityId]) {
        for (id, e) in updates {
            if let Some(slot) = self.entities.get_mut(&id) {
                self.extent.replace(&slot.0, &e);
                slot.0 = e;
            }
        }
        for id in clean {
            self.dirty.remove(id);
        }
        self.revision += 1;
    }
}
