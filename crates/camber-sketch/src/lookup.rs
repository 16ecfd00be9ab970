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
}
