//! The sketch's extent kept up to date as entities change: the bounding box of every entity
//! point (circles with their radius) and the largest coordinate magnitude, which set the
//! sketch's scale, its centre and the rounding floor of the solve tolerance.
//!
//! Each entity contributes five numbers (its own box and magnitude); the sketch's values are
//! the least and greatest of them, kept in ordered multisets, so that adding, replacing or
//! writing back one entity costs O(log n) and reading the extent O(log n), where a scan over
//! every entity cost O(n) per solve (the most of a re-solve after one dimension edit).

use std::cmp::Ordering;
use std::collections::BTreeMap;

use crate::ground::entity::Entity;

/// An `f64` ordered by [`f64::total_cmp`], for use as a map key.
#[derive(Debug, Clone, Copy)]
struct Key(f64);

impl PartialEq for Key {
    fn eq(&self, other: &Self) -> bool {
        self.0.total_cmp(&other.0) == Ordering::Equal
    }
}

impl Eq for Key {}

impl PartialOrd for Key {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Key {
    fn cmp(&self, other: &Self) -> Ordering {
        self.0.total_cmp(&other.0)
    }
}

/// A multiset of numbers with its least and greatest element.
#[derive(Debug, Clone, Default)]
struct Multiset(BTreeMap<Key, usize>);

impl Multiset {
    fn insert(&mut self, v: f64) {
        *self.0.entry(Key(v)).or_insert(0) += 1;
    }

    fn remove(&mut self, v: f64) {
        if let Some(count) = self.0.get_mut(&Key(v)) {
            *count -= 1;
            if *count == 0 {
                self.0.remove(&Key(v));
            }
        }
    }

    fn least(&self) -> Option<f64> {
        self.0.keys().next().map(|k| k.0)
    }

    fn greatest(&self) -> Option<f64> {
        self.0.keys().next_back().map(|k| k.0)
    }
}

/// One entity's share of the extent: the box of its hull points widened by its radius (a
/// circle's), `[+∞, +∞] … [−∞, −∞]` when it has no finite point, and its largest finite
/// coordinate or radius magnitude (0 when none).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Share {
    lo: [f64; 2],
    hi: [f64; 2],
    magnitude: f64,
}

impl Share {
    fn of(e: &Entity) -> Self {
        let r = match e {
            Entity::Circle { radius, .. } => *radius,
            _ => 0.0,
        };
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in e.hull_points().iter() {
            lo = [lo[0].min(p.x - r), lo[1].min(p.y - r)];
            hi = [hi[0].max(p.x + r), hi[1].max(p.y + r)];
        }
        let magnitude = e
            .points()
            .iter()
            .map(|p| p.x.abs().max(p.y.abs()).max(r.abs()))
            .filter(|m| m.is_finite())
            .fold(0.0, f64::max);
        Self { lo, hi, magnitude }
    }
}

/// The extent of every entity of a sketch (see the module documentation).
#[derive(Debug, Clone, Default)]
pub(crate) struct Extent {
    lo: [Multiset; 2],
    hi: [Multiset; 2],
    magnitude: Multiset,
}

impl Extent {
    /// Counts an entity in.
    pub(crate) fn add(&mut self, e: &Entity) {
        self.add_share(Share::of(e));
    }

    /// Replaces an entity's old values by its new ones (the old ones must have been counted
    /// in).
    pub(crate) fn replace(&mut self, old: &Entity, new: &Entity) {
        let (old, new) = (Share::of(old), Share::of(new));
        if old != new {
            self.remove_share(old);
            self.add_share(new);
        }
    }

    fn add_share(&mut self, s: Share) {
        for k in 0..2 {
            self.lo[k].insert(s.lo[k]);
            self.hi[k].insert(s.hi[k]);
        }
        self.magnitude.insert(s.magnitude);
    }

    fn remove_share(&mut self, s: Share) {
        for k in 0..2 {
            self.lo[k].remove(s.lo[k]);
            self.hi[k].remove(s.hi[k]);
        }
        self.magnitude.remove(s.magnitude);
    }

    /// The bounding box `(lo, hi)` of every entity point (circles with their radius):
    /// `([+∞; 2], [−∞; 2])` for an empty sketch.
    pub(crate) fn bounds(&self) -> ([f64; 2], [f64; 2]) {
        let lo = [0, 1].map(|k| self.lo[k].least().unwrap_or(f64::INFINITY));
        let hi = [0, 1].map(|k| self.hi[k].greatest().unwrap_or(f64::NEG_INFINITY));
        (lo, hi)
    }

    /// The largest finite coordinate or radius magnitude of any entity (0 for none).
    pub(crate) fn magnitude(&self) -> f64 {
        self.magnitude.greatest().unwrap_or(0.0).max(0.0)
    }
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // exact: the extent picks stored values, it computes none
mod tests {
    use super::*;
    use nalgebra::Point2;

    fn line(a: (f64, f64), b: (f64, f64)) -> Entity {
        Entity::Line([Point2::new(a.0, a.1), Point2::new(b.0, b.1)])
    }

    #[test]
    fn the_extent_follows_entities_moved_in_and_out_of_its_corners() {
        let mut x = Extent::default();
        assert_eq!(x.bounds(), ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]));
        let a = line((0.0, 0.0), (1.0, 2.0));
        let b = line((-3.0, 1.0), (0.5, 0.5));
        x.add(&a);
        x.add(&b);
        assert_eq!(x.bounds(), ([-3.0, 0.0], [1.0, 2.0]));
        assert_eq!(x.magnitude(), 3.0);
        // The corner entity moves inwards: the box shrinks to the others.
        let b2 = line((0.25, 0.25), (0.5, 0.5));
        x.replace(&b, &b2);
        assert_eq!(x.bounds(), ([0.0, 0.0], [1.0, 2.0]));
        assert_eq!(x.magnitude(), 2.0);
        // Two entities with one value: moving one away keeps the other's.
        let far = line((10.0, 10.0), (11.0, 11.0));
        x.add(&a);
        x.replace(&a, &far);
        assert_eq!(x.bounds(), ([0.0, 0.0], [11.0, 11.0]));
        x.replace(&far, &b2);
        assert_eq!(x.bounds(), ([0.0, 0.0], [1.0, 2.0]));
        x.replace(&a, &b2);
        assert_eq!(x.bounds(), ([0.25, 0.25], [0.5, 0.5]));
    }

    #[test]
    fn non_finite_coordinates_do_not_count_in_the_magnitude() {
        let mut x = Extent::default();
        x.add(&line((f64::INFINITY, 0.0), (2.0, -5.0)));
        assert_eq!(x.magnitude(), 5.0);
    }
}
