//! Many sketches solved by one call ([`solve_many`]), one prepared problem kept per worker for
//! the sketches that share a structure.
//!
//! Variants of one design (other dimensions, other fixed geometry, other starting points)
//! build the same problem up to its values: the same blocks, bindings, rows and residual
//! objects. A worker keeps the problems of the last sketch it solved, each with the
//! signature of what it was built from; a component of the next sketch whose signature
//! matches is solved on the kept problem, its values refreshed in place
//! (`ComponentProblem::refresh_values`: the entities' points and scalars, the free
//! parameters' starts), so the evaluator, the patterns and the symbolic factorizations of its
//! plan serve again. Any other component is built as [`Sketch::solve_all`] builds it. A
//! problem whose pieces read the entities' values when it was compiled (a fixed combination, a
//! reference length), with relaxable constraints or with eliminated tangents is never refreshed.
//!
//! Each sketch is solved from its own values: the result is that of [`Sketch::solve_all`] on
//! it (up to the rounding of factorizations kept from another sketch's solve), a failed sketch
//! is left exactly as it was, and its error is the one `solve_all` gives.

use std::collections::HashMap;

use crate::component::ComponentProblem;
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::session::solve::SketchReport;
use crate::sketch::prepared::Signature;
use crate::sketch::Sketch;

/// Solves every sketch (every component, as [`Sketch::solve_all`]), each from its own values;
/// one result per sketch, in order. A sketch that fails is left exactly as it was and the
/// others go on.
///
/// A sketch whose options' cancel flag ([`camber_solve::Options::cancel`]) is raised when its
/// turn comes is not started: its result is [`camber_solve::Error::Cancelled`].
///
/// On rayon's current pool: one thread (for instance inside a pool of one, or with
/// `RAYON_NUM_THREADS=1`) solves the sketches one after another with no task overhead; more
/// threads split them into one contiguous run per thread. Each run keeps the prepared problems
/// of the sketch it solved last, and the next sketch's components of the same structure are
/// solved on them (see the module documentation).
///
/// ```
/// use camber_sketch::constraints::{Distance, Fixed};
/// use camber_sketch::{solve_many, PointRef, Sketch};
/// use nalgebra::Point2;
/// // One design, three lengths.
/// let variants: Vec<Sketch> = [1.0, 2.0, 3.0]
///     .iter()
///     .map(|d| {
///         let mut s = Sketch::new();
///         let a = s.add_point(Point2::new(0.0, 0.0))?;
///         let b = s.add_point(Point2::new(1.5, 0.0))?;
///         s.add_constraint(Fixed::point(PointRef::Point(a)))?;
///         s.add_constraint(Distance { a: PointRef::Point(a), b: PointRef::Point(b), distance: *d })?;
///         Ok(s)
///     })
///     .collect::<camber_sketch::Result<_>>()?;
/// let mut sketches = variants;
/// let results = solve_many(&mut sketches);
/// assert!(results.iter().all(|r| r.is_ok()));
/// let b = camber_sketch::EntityId(1);
/// assert!((sketches[2].point(PointRef::Point(b))?.x - 3.0).abs() < 1e-12);
/// # Ok::<(), camber_sketch::Error>(())
/// ```
pub fn solve_many(sketches: &mut [Sketch]) -> Vec<Result<SketchReport>> {
    let threads = rayon::current_num_threads();
    if threads <= 1 || sketches.len() < 2 {
        let mut worker = Worker::default();
        return sketches.iter_mut().map(|s| worker.solve(s)).collect();
    }
    use rayon::prelude::*;
    let run = sketches.len().div_ceil(threads);
    let runs: Vec<Vec<Result<SketchReport>>> = sketches
        .par_chunks_mut(run)
        .map(|chunk| {
            let mut worker = Worker::default();
            chunk.iter_mut().map(|s| worker.solve(s)).collect()
        })
        .collect();
    runs.into_iter().flatten().collect()
}

/// The problems one worker keeps from the last sketch it solved, each with what it was built
/// from, by the smallest entity id of its component.
#[derive(Debug, Default)]
pub(crate) struct Worker {
    kept: HashMap<EntityId, (Signature, ComponentProblem)>,
}

impl Worker {
    /// Solves every component of `sketch` (as [`Sketch::solve_all`]), each on a kept problem
    /// of the same structure when there is one; keeps the sketch's problems for the next.
    pub(crate) fn solve(&mut self, sketch: &mut Sketch) -> Result<SketchReport> {
        // A batch cancelled through the sketches' options starts none of the sketches left.
        if sketch
            .options()
            .cancel
            .as_ref()
            .is_some_and(camber_solve::CancelFlag::is_cancelled)
        {
            return Err(crate::ground::errors::Error::Solve(
                camber_solve::Error::Cancelled,
            ));
        }
        let comps = sketch.components();
        let parallel = crate::session::solve::solves_in_parallel(&comps);
        // What each problem solved now was built from, by its component's first entity.
        let mut signatures: HashMap<EntityId, Signature> = HashMap::new();
        let kept = &mut self.kept;
        let report = sketch.solve_components_with(comps, parallel, &mut |s, comp| {
            let first = *comp.entities.first()?;
            if let Some((sig, mut cp)) = kept.remove(&first) {
                if sig.matches(s, comp) && cp.refresh_values(s).unwrap_or(false) {
                    signatures.insert(first, sig);
                    return Some(cp);
                }
            }
            // Built by the solve from the sketch as it is now.
            if let Ok(sig) = Signature::of(s, comp) {
                signatures.insert(first, sig);
            }
            None
        })?;
        self.kept.clear();
        for cp in sketch.prepared.take_all() {
            let Some(first) = cp.component().entities.first().copied() else {
                continue;
            };
            if let Some(sig) = signatures.remove(&first) {
                if sig.component() == cp.component() {
                    self.kept.insert(first, (sig, cp));
                }
            }
        }
        Ok(report)
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use crate::constraints::{ArcLength, Distance, Fixed};
    use crate::PointRef;
    use nalgebra::Point2;

    /// A point at `d` from a fixed one, the fixed one at `x`.
    fn at_distance(x: f64, d: f64) -> Sketch {
        let mut s = Sketch::new();
        let a = s.add_point(Point2::new(x, 0.0)).unwrap();
        let b = s.add_point(Point2::new(x + 0.7, 0.4)).unwrap();
        s.add_constraint(Fixed::point(PointRef::Point(a))).unwrap();
        s.add_constraint(Distance {
            a: PointRef::Point(a),
            b: PointRef::Point(b),
            distance: d,
        })
        .unwrap();
        s
    }

    /// The stamps of the problem the worker keeps for the component of entity 0.
    fn kept_stamps(w: &Worker) -> Option<camber_solve::Stamps> {
        w.kept
            .get(&EntityId(0))
            .map(|(_, cp)| cp.problem().stamps())
    }

    #[test]
    fn a_variant_of_the_same_structure_is_solved_on_the_kept_problem() {
        let mut w = Worker::default();
        let mut first = at_distance(0.0, 1.0);
        w.solve(&mut first).unwrap();
        let stamps = kept_stamps(&w).unwrap();
        // Another fixed point, the same structure: the same problem (stamps are unique to a
        // problem's structure), refreshed and solved again.
        let mut second = at_distance(5.0, 1.0);
        w.solve(&mut second).unwrap();
        assert_eq!(kept_stamps(&w), Some(stamps));
        let b = second.point(PointRef::Point(EntityId(1))).unwrap();
        assert!(((b - Point2::new(5.0, 0.0)).norm() - 1.0).abs() < 1e-12);
        // Another distance: other constraint data, built again.
        let mut third = at_distance(5.0, 2.0);
        w.solve(&mut third).unwrap();
        assert_ne!(kept_stamps(&w), Some(stamps));
        // The batch leaves nothing prepared in the sketches it solved.
        assert_eq!(third.prepared.len(), 0);
    }

    #[test]
    fn a_sketch_cancelled_before_its_turn_is_not_started() {
        let flag = camber_solve::CancelFlag::new();
        let mut sketches = vec![at_distance(0.0, 1.0), at_distance(1.0, 2.0)];
        for s in &mut sketches {
            s.set_options(s.options().clone().with_cancel(Some(flag.clone())));
        }
        let before: Vec<String> = sketches
            .iter()
            .map(|s| crate::file::to_json(s).unwrap())
            .collect();
        flag.cancel();
        for r in solve_many(&mut sketches) {
            assert!(matches!(
                r,
                Err(crate::Error::Solve(camber_solve::Error::Cancelled))
            ));
        }
        for (s, b) in sketches.iter().zip(before) {
            assert_eq!(crate::file::to_json(s).unwrap(), b);
        }
    }

    #[test]
    fn problems_whose_pieces_read_the_points_are_not_refreshable() {
        let mut s = at_distance(0.0, 1.0);
        assert!(s.component_problem(EntityId(0)).unwrap().refreshable);
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
        s.add_constraint(ArcLength {
            curve: c,
            length: 3.0,
        })
        .unwrap();
        assert!(!s.component_problem(c).unwrap().refreshable);
        let mut fixed_mid = Sketch::new();
        let line = fixed_mid
            .add_bezier(
                camber_geom::BezierCurve2::try_new(vec![
                    Point2::new(0.0, 0.0),
                    Point2::new(1.0, 1.0),
                    Point2::new(2.0, 0.0),
                ])
                .unwrap(),
            )
            .unwrap();
        fixed_mid
            .add_constraint(Fixed::point(PointRef::Start(line)))
            .unwrap();
        assert!(fixed_mid.component_problem(line).unwrap().refreshable);
    }
}
