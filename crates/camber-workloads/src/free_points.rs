//! The analysis workload's many-component sketch: free points and nothing else.
//!
//! n points on a square grid of unit spacing, no constraint: n components of one point each,
//! every one with DOF 2. `camber check` and `camber render` of such a sketch once cost a fold
//! over the whole sketch per component (quadratic in n); this sketch keeps that case in the
//! bench's growth column.

use camber_sketch::{ComponentAnalysis, Result, Sketch};
use nalgebra::Point2;

/// `n` free points on a grid (row length ⌈√n⌉, unit spacing).
///
/// ```
/// let s = camber_workloads::free_points(7)?;
/// assert!(camber_workloads::free_points_valid(&s.analyze()?, 7));
/// # Ok::<(), camber_sketch::Error>(())
/// ```
///
/// # Errors
/// None in practice.
pub fn free_points(n: usize) -> Result<Sketch> {
    let mut s = Sketch::new();
    let row = (n as f64).sqrt().ceil().max(1.0) as usize;
    for k in 0..n {
        s.add_point(Point2::new((k % row) as f64, (k / row) as f64))?;
    }
    Ok(s)
}

/// Whether an analysis of [`free_points`]`(n)` is right: n components, each of DOF 2 with
/// nothing redundant, partly redundant or conflicting and its point listed as free.
pub fn free_points_valid(analyses: &[ComponentAnalysis], n: usize) -> bool {
    analyses.len() == n
        && analyses.iter().all(|a| {
            let d = &a.analysis;
            d.dof == 2
                && d.redundant.is_empty()
                && d.partly_redundant.is_empty()
                && d.conflicting.is_empty()
                && a.freedom.len() == 1
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sketch_of_free_points_is_one_component_per_point() {
        let s = free_points(10).unwrap();
        let analyses = s.analyze().unwrap();
        assert!(free_points_valid(&analyses, 10));
        // A wrong count is not valid.
        assert!(!free_points_valid(&analyses, 9));
    }
}
