//! Joins found by position: end points of different entities that lie within a tolerance of
//! each other become one cluster, held together by `Coincident` constraints.
//!
//! The points are bucketed on a grid of cell size equal to the tolerance, so each point is
//! compared only with the points of its own and the eight neighbouring cells: near-linear in
//! the number of points for any drawing whose points are not all piled into a few cells.
//! Clusters are the connected sets of the relation "closer than the tolerance" (a union-find
//! over the pairs found), so a chain of points each within the tolerance of the next is one
//! cluster even when its ends are farther apart.

use std::collections::HashMap;

use camber_sketch::constraints::Coincident;
use camber_sketch::{PointRef, Sketch};
use nalgebra::Point2;

/// A union-find over point indices, with path halving and union by size.
#[derive(Debug, Clone)]
pub(crate) struct Clusters {
    parent: Vec<usize>,
    size: Vec<usize>,
}

impl Clusters {
    /// `n` points, each a cluster of its own.
    pub(crate) fn new(n: usize) -> Self {
        Self {
            parent: (0..n).collect(),
            size: vec![1; n],
        }
    }

    /// The representative of the cluster holding `i`.
    pub(crate) fn find(&mut self, mut i: usize) -> usize {
        while self.parent[i] != i {
            self.parent[i] = self.parent[self.parent[i]];
            i = self.parent[i];
        }
        i
    }

    /// Puts `a` and `b` in one cluster.
    pub(crate) fn union(&mut self, a: usize, b: usize) {
        let (mut a, mut b) = (self.find(a), self.find(b));
        if a == b {
            return;
        }
        if self.size[a] < self.size[b] {
            std::mem::swap(&mut a, &mut b);
        }
        self.parent[b] = a;
        self.size[a] += self.size[b];
    }
}

/// Joins `points[i]` and `points[j]` for every pair closer than `tolerance` (Euclidean
/// distance ≤ tolerance); a tolerance of 0 joins only equal points, a negative or non-finite
/// one joins nothing.
pub(crate) fn join_close(points: &[Point2<f64>], tolerance: f64, clusters: &mut Clusters) {
    if !(tolerance >= 0.0 && tolerance.is_finite()) {
        return;
    }
    if tolerance == 0.0 {
        // Equal points share their bits (−0 and +0 aside, which the key folds together).
        let key = |p: &Point2<f64>| ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits());
        let mut first: HashMap<(u64, u64), usize> = HashMap::with_capacity(points.len());
        for (i, p) in points.iter().enumerate() {
            match first.get(&key(p)) {
                Some(&j) => clusters.union(i, j),
                None => {
                    first.insert(key(p), i);
                }
            }
        }
        return;
    }
    // Cells of side `tolerance`; coordinates far beyond i64's range (or a tolerance so small
    // that they overflow) saturate, which only puts far points in one edge cell, still
    // compared by their true distance.
    let cell = |p: &Point2<f64>| {
        (
            (p.x / tolerance).floor() as i64,
            (p.y / tolerance).floor() as i64,
        )
    };
    let mut grid: HashMap<(i64, i64), Vec<usize>> = HashMap::with_capacity(points.len());
    for (i, p) in points.iter().enumerate() {
        let (cx, cy) = cell(p);
        for dx in -1..=1_i64 {
            for dy in -1..=1_i64 {
                let Some(others) = grid.get(&(cx.saturating_add(dx), cy.saturating_add(dy))) else {
                    continue;
                };
                for &j in others {
                    if (points[j] - p).norm() <= tolerance {
                        clusters.union(i, j);
                    }
                }
            }
        }
        grid.entry((cx, cy)).or_default().push(i);
    }
}

/// Adds one `Coincident` constraint from the first point of every cluster of two or more to
/// each other point of it; returns how many were added.
///
/// # Errors
/// Those of [`Sketch::add_constraint`] (a reference to a point the sketch does not have).
pub(crate) fn add_coincidences(
    sketch: &mut Sketch,
    refs: &[PointRef],
    clusters: &mut Clusters,
) -> camber_sketch::Result<usize> {
    let mut first_of: HashMap<usize, usize> = HashMap::new();
    let mut added = 0;
    for i in 0..refs.len() {
        let root = clusters.find(i);
        match first_of.get(&root) {
            Some(&first) => {
                sketch.add_constraint(Coincident {
                    a: refs[first],
                    b: refs[i],
                })?;
                added += 1;
            }
            None => {
                first_of.insert(root, i);
            }
        }
    }
    Ok(added)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn clusters_of(points: &[Point2<f64>], tol: f64) -> Vec<usize> {
        let mut c = Clusters::new(points.len());
        join_close(points, tol, &mut c);
        (0..points.len()).map(|i| c.find(i)).collect()
    }

    #[test]
    fn points_within_the_tolerance_join_and_farther_ones_do_not() {
        let p = [
            Point2::new(0.0, 0.0),
            Point2::new(0.5e-9, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(1.0, 1.0 + 2e-9),
        ];
        let c = clusters_of(&p, 1e-9);
        assert_eq!(c[0], c[1]);
        assert_ne!(c[0], c[2]);
        assert_ne!(c[2], c[3]);
    }

    #[test]
    fn neighbouring_cells_are_searched() {
        // Either side of a cell boundary at x = 1e-3 (tolerance 1e-3).
        let p = [Point2::new(0.999e-3, 0.0), Point2::new(1.001e-3, 0.0)];
        let c = clusters_of(&p, 1e-3);
        assert_eq!(c[0], c[1]);
    }

    #[test]
    fn a_zero_tolerance_joins_equal_points_only() {
        let p = [
            Point2::new(-0.0, 2.0),
            Point2::new(0.0, 2.0),
            Point2::new(0.0, 2.0 + f64::EPSILON * 2.0),
        ];
        let c = clusters_of(&p, 0.0);
        assert_eq!(c[0], c[1]);
        assert_ne!(c[0], c[2]);
    }

    #[test]
    fn a_chain_of_close_points_is_one_cluster() {
        let p: Vec<_> = (0..10)
            .map(|i| Point2::new(f64::from(i) * 0.9, 0.0))
            .collect();
        let c = clusters_of(&p, 1.0);
        assert!(c.iter().all(|&r| r == c[0]));
    }

    #[test]
    fn the_grid_agrees_with_all_pairs() {
        // A deterministic scatter with many near pairs, against the quadratic definition.
        let p: Vec<_> = (0..300)
            .map(|i| {
                let t = f64::from(i);
                Point2::new((t * 0.618).fract() * 3.0, (t * 0.414).fract() * 3.0)
            })
            .collect();
        let tol = 0.05;
        let c = clusters_of(&p, tol);
        let mut naive = Clusters::new(p.len());
        for i in 0..p.len() {
            for j in 0..i {
                if (p[i] - p[j]).norm() <= tol {
                    naive.union(i, j);
                }
            }
        }
        for i in 0..p.len() {
            for j in 0..i {
                assert_eq!(
                    c[i] == c[j],
                    naive.find(i) == naive.find(j),
                    "points {i} and {j}"
                );
            }
        }
    }
}
