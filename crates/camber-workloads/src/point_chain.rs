//! The analysis workload's second sketch: a chain of points held by distances.
//!
//! n points along a gentle wave, P_k = (k, 0.1·sin 0.7k), the first fixed, each at its current
//! distance from the next (n − 1 nonlinear rows over 2n − 2 free unknowns). Nothing is
//! dependent, so the DOF analysis must report DOF n − 1 with no redundant or conflicting
//! constraint: a large component (2·10⁵ unknowns at n = 10⁵) for the sparse analysis.

use camber_sketch::constraints::{Distance, Fixed};
use camber_sketch::{ComponentAnalysis, PointRef, Result, Sketch};
use nalgebra::Point2;

/// The chain of `n` points (n ≥ 2).
///
/// ```
/// let s = camber_workloads::point_chain(5)?;
/// assert!(camber_workloads::point_chain_valid(&s.analyze()?, 5));
/// # Ok::<(), camber_sketch::Error>(())
/// ```
///
/// # Errors
/// None in practice.
pub fn point_chain(n: usize) -> Result<Sketch> {
    let mut s = Sketch::new();
    let mut points = Vec::with_capacity(n);
    for k in 0..n {
        let t = k as f64;
        points.push(s.add_point(Point2::new(t, 0.1 * (0.7 * t).sin()))?);
    }
    if let Some(first) = points.first() {
        s.add_constraint(Fixed::entity(*first))?;
    }
    for pair in points.windows(2) {
        let (a, b) = (PointRef::Point(pair[0]), PointRef::Point(pair[1]));
        let distance = (s.point(b)? - s.point(a)?).norm();
        s.add_constraint(Distance { a, b, distance })?;
    }
    Ok(s)
}

/// Whether an analysis of [`point_chain`]`(n)` is right: one component, DOF n − 1, nothing
/// redundant, partly redundant or conflicting.
pub fn point_chain_valid(analyses: &[ComponentAnalysis], n: usize) -> bool {
    match analyses {
        [a] => {
            let d = &a.analysis;
            d.dof == n.saturating_sub(1)
                && d.redundant.is_empty()
                && d.partly_redundant.is_empty()
                && d.conflicting.is_empty()
        }
        _ => false,
    }
}
