//! Looking up entities by id: what compiling a constraint, building a component's problem and
//! drawing a glyph need of a sketch (or of a drag session's snapshot, or of a picture's view).

use crate::entity::Entity;
use crate::errors::Result;
use crate::ids::EntityId;

/// Read access to entities by id.
///
/// ```
/// use camber_sketch::{EntityLookup, Sketch};
/// use nalgebra::Point2;
/// let mut s = Sketch::new();
/// let p = s.add_point(Point2::new(1.0, 2.0))?;
/// assert_eq!(s.lookup(p)?.points()[0], Point2::new(1.0, 2.0));
/// # Ok::<(), camber_sketch::Error>(())
/// ```
pub trait EntityLookup {
    /// The entity with that id.
    ///
    /// # Errors
    /// [`crate::Error::UnknownEntity`].
    fn lookup(&self, id: EntityId) -> Result<&Entity>;

    /// The weight of the entity's point `index` in the minimum-norm metric (1 unless set).
    fn weight(&self, _id: EntityId, _index: usize) -> f64 {
        1.0
    }

    /// The value of the sketch's named parameter `name` (`None`: no such parameter), read by
    /// expressions.
    fn parameter(&self, _name: &str) -> Option<f64> {
        None
    }
}

/// The entities of one component, read once from a larger lookup (a sketch's map) into a short
/// list sorted by id and then found by binary search: compiling a component's constraints and
/// building its problem look entities up tens of times each. An id outside the list falls
/// through to the larger lookup, whose answer (or error) it gives; weights come from it too.
pub(crate) struct ComponentEntities<'a> {
    all: &'a dyn EntityLookup,
    entities: Vec<(EntityId, &'a Entity)>,
}

impl<'a> ComponentEntities<'a> {
    /// The entities `ids` of `all` (ids it does not hold are left to it).
    pub(crate) fn new(all: &'a dyn EntityLookup, ids: &[EntityId]) -> Self {
        let mut entities: Vec<(EntityId, &'a Entity)> = ids
            .iter()
            .filter_map(|id| all.lookup(*id).ok().map(|e| (*id, e)))
            .collect();
        if !entities.is_sorted_by_key(|(id, _)| *id) {
            entities.sort_unstable_by_key(|(id, _)| *id);
        }
        Self { all, entities }
    }
}

impl EntityLookup for ComponentEntities<'_> {
    fn lookup(&self, id: EntityId) -> Result<&Entity> {
        match self.entities.binary_search_by_key(&id, |(k, _)| *k) {
            Ok(k) => self
                .entities
                .get(k)
                .map(|(_, e)| *e)
                .map_or_else(|| self.all.lookup(id), Ok),
            Err(_) => self.all.lookup(id),
        }
    }

    fn weight(&self, id: EntityId, index: usize) -> f64 {
        self.all.weight(id, index)
    }

    fn parameter(&self, name: &str) -> Option<f64> {
        self.all.parameter(name)
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use crate::Sketch;
    use nalgebra::Point2;

    /// The component's entities are the sketch's own (the same values), in any order of ids
    /// given; other ids fall through to the sketch, unknown ones with its error.
    #[test]
    fn component_entities_answer_as_the_sketch() {
        let mut s = Sketch::new();
        let ids: Vec<EntityId> = (0..6)
            .map(|k| s.add_point(Point2::new(k as f64, 1.0)).unwrap())
            .collect();
        let within = ComponentEntities::new(&s, &[ids[4], ids[1], ids[2]]);
        for id in &ids {
            assert_eq!(within.lookup(*id).unwrap(), s.lookup(*id).unwrap());
            assert!(std::ptr::eq(
                within.lookup(*id).unwrap(),
                s.lookup(*id).unwrap()
            ));
        }
        let missing = EntityId(999);
        assert_eq!(
            within.lookup(missing).unwrap_err(),
            s.lookup(missing).unwrap_err()
        );
        assert_eq!(
            within.weight(ids[1], 0).to_bits(),
            s.weight(ids[1], 0).to_bits()
        );
    }
}
