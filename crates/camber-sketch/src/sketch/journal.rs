//! Edits of several steps that either complete or leave the sketch exactly as it was.
//!
//! A fillet, a split or a trim removes constraints, replaces entities, adds an entity and adds
//! constraints, and any step may be refused (a constraint that no longer fits, an id taken).
//! [`Sketch::transaction`] runs such an edit with a [`Journal`] that records each step as it is
//! made; when a step fails, the recorded steps are undone newest first, each in the state
//! right after it was made, so every inverse is valid by construction: an added constraint is
//! removed before the entity it reads, a removed constraint comes back (under its id, with its
//! priority and its parameter bindings) after the entity it read is restored. The next automatic id is put back last, so
//! the ids a failed edit handed out are handed out again.

use crate::constraints::Constraint;
use crate::ground::entity::Entity;
use crate::ground::errors::Result;
use crate::ground::ids::{ConstraintId, EntityId};
use crate::sketch::parameters::Binding;
use crate::sketch::Sketch;
use camber_solve::Priority;

/// Point weights of one entity that differ from 1: (point index, weight).
type PointWeights = Vec<(usize, f64)>;

/// One step of an edit, with what its inverse needs.
#[derive(Debug)]
enum Step {
    /// A constraint removed.
    Removed(ConstraintId, Removed),
    /// An entity replaced: its value before, with its point weights.
    Replaced(EntityId, Entity, PointWeights),
    /// An entity added.
    AddedEntity(EntityId),
    /// An entity removed (its constraints were removed first): its value, point weights and
    /// tag.
    RemovedEntity(EntityId, Entity, PointWeights, Option<String>),
    /// A constraint added.
    AddedConstraint(ConstraintId),
}

/// A constraint as it was before [`Journal::remove_constraint`] removed it.
#[derive(Debug, Clone)]
pub(super) struct Removed {
    /// The constraint.
    pub(super) constraint: Constraint,
    /// Its priority, when it had one.
    pub(super) priority: Option<Priority>,
    /// The parameter expressions its values were bound to.
    pub(super) bindings: Vec<Binding>,
}

/// The steps an edit has made so far (see the module header).
#[derive(Debug)]
pub(super) struct Journal {
    /// The sketch's next automatic id before the edit.
    next_id: u64,
    /// The steps, oldest first.
    steps: Vec<Step>,
}

impl Journal {
    /// Removes constraint `id`, returning it as it was.
    pub(super) fn remove_constraint(
        &mut self,
        sketch: &mut Sketch,
        id: ConstraintId,
    ) -> Result<Removed> {
        let priority = sketch.priorities.get(&id).copied();
        let bindings = sketch.parameters.bindings(id).to_vec();
        let constraint = sketch.remove_constraint(id)?;
        let removed = Removed {
            constraint,
            priority,
            bindings,
        };
        self.steps.push(Step::Removed(id, removed.clone()));
        Ok(removed)
    }

    /// Replaces entity `id` by `entity` (same kind; point weights as they were).
    pub(super) fn replace_entity(
        &mut self,
        sketch: &mut Sketch,
        id: EntityId,
        entity: Entity,
    ) -> Result<()> {
        let before = sketch.entity(id)?.clone();
        let weights = sketch.weights_of(id);
        sketch.set_entity(id, entity)?;
        self.steps.push(Step::Replaced(id, before, weights));
        Ok(())
    }

    /// Removes entity `id`, which no constraint reads any more, returning it.
    pub(super) fn remove_entity(&mut self, sketch: &mut Sketch, id: EntityId) -> Result<Entity> {
        let weights = sketch.weights_of(id);
        let tag = sketch.tag(id).map(str::to_owned);
        let entity = sketch.remove_entity(id)?;
        self.steps
            .push(Step::RemovedEntity(id, entity.clone(), weights, tag));
        Ok(entity)
    }

    /// Adds `entity` under `id` (free: an entity this edit removed).
    pub(super) fn add_entity_with_id(
        &mut self,
        sketch: &mut Sketch,
        id: EntityId,
        entity: Entity,
    ) -> Result<()> {
        sketch.add_entity_with_id(id, entity)?;
        self.steps.push(Step::AddedEntity(id));
        Ok(())
    }

    /// Adds the removed constraint `was` again under its own id `id` (the entities it reads
    /// having changed), with its priority and its parameter bindings.
    pub(super) fn restore_constraint(
        &mut self,
        sketch: &mut Sketch,
        id: ConstraintId,
        was: &Removed,
    ) -> Result<()> {
        sketch.add_constraint_with_id(id, was.constraint.clone())?;
        self.steps.push(Step::AddedConstraint(id));
        if let Some(p) = was.priority {
            sketch.set_priority(id, p)?;
        }
        sketch.set_bindings(id, was.bindings.clone());
        Ok(())
    }

    /// Adds `entity`.
    pub(super) fn add_entity(&mut self, sketch: &mut Sketch, entity: Entity) -> Result<EntityId> {
        let id = sketch.add_entity(entity)?;
        self.steps.push(Step::AddedEntity(id));
        Ok(id)
    }

    /// Adds `constraint`.
    pub(super) fn add_constraint(
        &mut self,
        sketch: &mut Sketch,
        constraint: impl Into<Constraint>,
    ) -> Result<ConstraintId> {
        let id = sketch.add_constraint(constraint)?;
        self.steps.push(Step::AddedConstraint(id));
        Ok(id)
    }

    /// Adds `constraint` in place of `was` (the same constraint on other entities), carrying
    /// its priority and its parameter bindings (the values sit at the same paths).
    pub(super) fn add_carried(
        &mut self,
        sketch: &mut Sketch,
        constraint: Constraint,
        was: &Removed,
    ) -> Result<ConstraintId> {
        let id = self.add_constraint(sketch, constraint)?;
        if let Some(p) = was.priority {
            sketch.set_priority(id, p)?;
        }
        sketch.set_bindings(id, was.bindings.clone());
        Ok(id)
    }

    /// The constraints added so far, oldest first.
    pub(super) fn added_constraints(&self) -> Vec<ConstraintId> {
        self.steps
            .iter()
            .filter_map(|s| match s {
                Step::AddedConstraint(id) => Some(*id),
                _ => None,
            })
            .collect()
    }
}

impl Sketch {
    /// Runs `edit` with a fresh journal; returns its value and the journal of what it did, or,
    /// when it fails, undoes every recorded step (module header) and returns its error with the
    /// sketch as it was.
    ///
    /// `edit` must make every change through the journal: a change made past it is not undone.
    pub(super) fn transaction<T>(
        &mut self,
        edit: impl FnOnce(&mut Sketch, &mut Journal) -> Result<T>,
    ) -> Result<(T, Journal)> {
        let mut journal = Journal {
            next_id: self.next_id,
            steps: Vec::new(),
        };
        match edit(self, &mut journal) {
            Ok(value) => Ok((value, journal)),
            Err(e) => {
                self.undo(journal);
                Err(e)
            }
        }
    }

    /// Undoes the steps of `journal`, newest first, and puts the next automatic id back.
    fn undo(&mut self, journal: Journal) {
        for step in journal.steps.into_iter().rev() {
            match step {
                Step::AddedConstraint(id) => {
                    let removed = self.remove_constraint(id);
                    debug_assert!(removed.is_ok(), "a constraint the edit added: {removed:?}");
                }
                Step::AddedEntity(id) => {
                    // Every constraint added after it, all that could read it, is gone.
                    let removed = self.remove_entity(id);
                    debug_assert!(removed.is_ok(), "an entity the edit added: {removed:?}");
                }
                Step::RemovedEntity(id, entity, weights, tag) => {
                    let restored = self.add_entity_with_id(id, entity);
                    debug_assert!(restored.is_ok(), "an entity the edit removed: {restored:?}");
                    for (index, w) in weights {
                        self.weights.insert((id, index), w);
                    }
                    if let Some(tag) = tag {
                        let tagged = self.set_tag(id, Some(&tag));
                        debug_assert!(tagged.is_ok(), "its tag: {tagged:?}");
                    }
                }
                Step::Replaced(id, entity, weights) => {
                    // It was valid with the constraints that read it then, the same again.
                    let restored = self.set_entity(id, entity);
                    debug_assert!(restored.is_ok(), "an entity as it was: {restored:?}");
                    for (index, w) in weights {
                        self.weights.insert((id, index), w);
                    }
                }
                Step::Removed(id, was) => {
                    let restored = self.add_constraint_with_id(id, was.constraint);
                    debug_assert!(restored.is_ok(), "a constraint as it was: {restored:?}");
                    if let Some(p) = was.priority {
                        self.priorities.insert(id, p);
                    }
                    self.set_bindings(id, was.bindings);
                }
            }
        }
        self.next_id = journal.next_id;
    }

    /// The point weights of entity `id` that differ from 1, by point index.
    pub(super) fn weights_of(&self, id: EntityId) -> PointWeights {
        self.weights
            .range((id, 0)..=(id, usize::MAX))
            .map(|((_, index), w)| (*index, *w))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use crate::constraints::{Distance, Fixed};
    use crate::file::to_json;
    use crate::ground::errors::Error;
    use crate::ground::ids::PointRef;
    use nalgebra::Point2;

    /// Every kind of step made and then a failure: the sketch's file (entities, constraints,
    /// priorities, parameter bindings) and its next id are as before.
    #[test]
    fn a_failed_edit_leaves_the_sketch_as_it_was() {
        let mut s = Sketch::new();
        let a = s
            .add_line(Point2::new(0.0, 0.0), Point2::new(4.0, 0.0))
            .unwrap();
        let p = s.add_point(Point2::new(4.0, 2.0)).unwrap();
        s.define_parameter("gap", 2.0).unwrap();
        let gap = s
            .add_constraint(Distance {
                a: PointRef::End(a),
                b: PointRef::Point(p),
                distance: 2.0,
            })
            .unwrap();
        s.bind_dimension(gap, "distance", "gap").unwrap();
        s.set_priority(gap, 3).unwrap();
        let before = to_json(&s).unwrap();
        let next_id = s.next_id;
        let refused = s.transaction(|sk, j| {
            j.remove_constraint(sk, gap)?;
            j.replace_entity(
                sk,
                a,
                Entity::Line([Point2::new(0.0, 0.0), Point2::new(3.0, 1.0)]),
            )?;
            let q = j.add_entity(sk, Entity::Point(Point2::new(1.0, 1.0)))?;
            j.add_constraint(sk, Fixed::point(PointRef::Point(q)))?;
            // The last step fails: an unknown entity.
            j.add_constraint(sk, Fixed::point(PointRef::Point(EntityId(999))))
        });
        assert!(matches!(refused, Err(Error::UnknownEntity { .. })));
        assert_eq!(to_json(&s).unwrap(), before);
        assert_eq!(s.next_id, next_id);
        assert_eq!(s.parameters.bindings(gap).len(), 1);
    }
}
