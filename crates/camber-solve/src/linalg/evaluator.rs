//! Residuals and Jacobians over the reduced unknowns z at any point, not only at the start.
//!
//! The nonlinear solvers evaluate g(x(z)) and J_z = J_x·A many times at moving z. An
//! [`Evaluator`] holds the reduced map x = A·z + c, the bounds that apply directly to each
//! reduced unknown, and reusable scratch (the expanded x, the per-block dense Jacobian, the
//! triplet list), so repeated evaluations allocate little.

use crate::linalg::reduced::ReducedMap;
use crate::linalg::sparse::{Assembler, SparseMatrix};
use crate::model::errors::check_len;
use crate::model::errors::Result;
use crate::model::ids::{ConstraintId, Var};
use crate::model::problem::{check_residual, gather_into, Problem};
use crate::model::report::{per_constraint, ConstraintResidual};

/// Evaluation of a problem's residuals over z, with scratch kept between calls.
#[derive(Debug, Clone)]
pub(crate) struct Evaluator {
    /// The map x = A·z + c the evaluations run over.
    pub(crate) map: ReducedMap,
    /// Lower bound of every reduced unknown (from the free unknown or auxiliary it stands for).
    pub(crate) lower: Vec<f64>,
    /// Upper bound of every reduced unknown.
    pub(crate) upper: Vec<f64>,
    /// The owner of every residual row.
    pub(crate) row_owner: Vec<ConstraintId>,
    /// For every residual in turn, one flag per block it reads: whether one of the block's
    /// unknowns moves with z (a block of fixed unknowns needs no derivatives).
    block_moves: Vec<bool>,
    x: Vec<f64>,
    jac: Vec<f64>,
    triplets: Vec<(usize, usize, f64)>,
    /// Scratch of [`Evaluator::hessian`]: one residual's dense Hessian and the reduced
    /// triplets.
    hess: Vec<f64>,
    hess_triplets: Vec<(usize, usize, f64)>,
    /// The compressed forms of J and H, rebuilt only when their patterns change.
    jac_asm: Assembler,
    hess_asm: Assembler,
    /// The triplets of the affine residuals (constant, J_x and A both being: taken at the
    /// first linearization, then only the values are evaluated), end to end, and where each
    /// residual's run starts and ends (`None` until taken, and for residuals that are not
    /// affine).
    affine_triplets: Vec<(usize, usize, f64)>,
    affine_at: Vec<Option<(usize, usize)>>,
}

impl Evaluator {
    /// Builds the map of `problem` and the bounds of its reduced unknowns.
    pub(crate) fn new(problem: &Problem) -> Result<Self> {
        let map = problem.reduced_map()?;
        let Spare {
            mut lower,
            mut upper,
            mut row_owner,
            mut block_moves,
            mut x,
            mut jac,
            mut triplets,
            mut affine_triplets,
            mut affine_at,
        } = Spare::take();
        lower.clear();
        upper.clear();
        lower.reserve(map.len());
        upper.reserve(map.len());
        for var in map.vars() {
            let (lo, hi) = match var {
                Var::Unknown(u) => problem.bounds.get(u.0).copied(),
                Var::Aux(a) => problem.aux_bounds.get(a.0).copied(),
            }
            .unwrap_or((f64::NEG_INFINITY, f64::INFINITY));
            lower.push(lo);
            upper.push(hi);
        }
        row_owner.clear();
        row_owner.reserve(problem.num_rows());
        block_moves.clear();
        block_moves.reserve(problem.residuals.iter().map(|rb| rb.blocks.len()).sum());
        // The sizes the scratch of a linearization reaches, so that the first one does not
        // grow it step by step: the largest dense block Jacobian, and one triplet per row,
        // unknown read and reduced column it moves with (all of them, affine ones once more
        // for their cache).
        let (mut jac_len, mut triplets_len, mut affine_len) = (0, 0, 0);
        for rb in &problem.residuals {
            row_owner.extend(std::iter::repeat_n(rb.owner, rb.dim));
            let (mut cols, mut terms) = (0, 0);
            for (start, len) in problem.spans_of(rb) {
                block_moves.push((*start..start + len).any(|u| !map.row(u).0.is_empty()));
                cols += len;
                terms += (*start..start + len)
                    .map(|u| map.row(u).0.len())
                    .sum::<usize>();
            }
            jac_len = jac_len.max(rb.dim * cols);
            triplets_len += rb.dim * terms;
            if rb.affine {
                affine_len += rb.dim * terms;
            }
        }
        x.clear();
        x.resize(problem.num_unknowns(), 0.0);
        jac.clear();
        jac.reserve(jac_len);
        triplets.clear();
        triplets.reserve(triplets_len);
        affine_triplets.clear();
        affine_triplets.reserve(affine_len);
        affine_at.clear();
        affine_at.resize(problem.residuals.len(), None);
        Ok(Self {
            x,
            map,
            lower,
            upper,
            row_owner,
            block_moves,
            jac,
            triplets,
            hess: Vec::new(),
            hess_triplets: Vec::new(),
            jac_asm: Assembler::default(),
            hess_asm: Assembler::default(),
            affine_triplets,
            affine_at,
        })
    }

    /// Takes the problem's values (and the constants of the map x = A·z + c, which hold the
    /// fixed values) again, keeping everything its structure determines: the row owners, which
    /// blocks move, the patterns of J and H and the triplets of the affine residuals. For a
    /// problem whose structure has not changed since the evaluator was built
    /// ([`crate::Problem::stamps`]).
    ///
    /// # Errors
    /// Those of [`Problem::reduced_map`].
    pub(crate) fn refresh(&mut self, problem: &Problem) -> Result<()> {
        problem.reduced_map_into(&mut self.map)?;
        self.lower.clear();
        self.upper.clear();
        for var in self.map.vars() {
            let (lo, hi) = match var {
                Var::Unknown(u) => problem.bounds.get(u.0).copied(),
                Var::Aux(a) => problem.aux_bounds.get(a.0).copied(),
            }
            .unwrap_or((f64::NEG_INFINITY, f64::INFINITY));
            self.lower.push(lo);
            self.upper.push(hi);
        }
        self.x.resize(problem.num_unknowns(), 0.0);
        Ok(())
    }

    /// Forgets the kept triplets of the affine residuals (their objects were replaced: other
    /// coefficients, perhaps).
    pub(crate) fn forget_residuals(&mut self) {
        self.affine_triplets.clear();
        self.affine_at.fill(None);
    }

    /// Number of reduced unknowns n.
    pub(crate) fn cols(&self) -> usize {
        self.map.len()
    }

    /// Number of residual rows m.
    pub(crate) fn rows(&self) -> usize {
        self.row_owner.len()
    }

    /// Moves `z` into the bounds of the reduced unknowns (component-wise projection).
    pub(crate) fn clamp(&self, z: &mut [f64]) {
        for ((zk, lo), hi) in z.iter_mut().zip(&self.lower).zip(&self.upper) {
            *zk = zk.max(*lo).min(*hi);
        }
    }

    /// g(x(z)) into `g` (m entries).
    pub(crate) fn residuals(&mut self, problem: &Problem, z: &[f64], g: &mut [f64]) -> Result<()> {
        problem.budget.charge()?;
        self.map.expand(z, &mut self.x)?;
        problem.evaluate_at(&self.x, g)
    }

    /// [`Evaluator::residuals`] without charging the evaluation budget: for the account a
    /// solve gives of where it stopped, which a spent budget must not prevent.
    pub(crate) fn residuals_for_report(
        &mut self,
        problem: &Problem,
        z: &[f64],
        g: &mut [f64],
    ) -> Result<()> {
        self.map.expand(z, &mut self.x)?;
        problem.evaluate_at(&self.x, g)
    }

    /// g(x(z)) into `g` and the nonzero entries of J_z = J_x·A as triplets (row, column,
    /// value), kept inside the evaluator ([`Evaluator::triplets`]).
    pub(crate) fn linearize(&mut self, problem: &Problem, z: &[f64], g: &mut [f64]) -> Result<()> {
        problem.budget.charge()?;
        self.linearize_for_report(problem, z, g)
    }

    /// [`Evaluator::linearize`] without charging the evaluation budget: for the account a
    /// solve gives of where it stopped, which a spent budget must not prevent.
    pub(crate) fn linearize_for_report(
        &mut self,
        problem: &Problem,
        z: &[f64],
        g: &mut [f64],
    ) -> Result<()> {
        check_len("residual rows", self.rows(), g.len())?;
        self.map.expand(z, &mut self.x)?;
        self.triplets.clear();
        let mut row0 = 0;
        let mut flags = 0;
        let mut slices = smallvec::SmallVec::new();
        for (r, rb) in problem.residuals.iter().enumerate() {
            let dim = rb.dim;
            gather_into(&self.x, problem.spans_of(rb), &mut slices);
            let out = &mut g[row0..row0 + dim];
            let moves = &self.block_moves[flags..flags + rb.blocks.len()];
            flags += rb.blocks.len();
            if let Some(cached) = self
                .affine_at
                .get(r)
                .copied()
                .flatten()
                .and_then(|(a, b)| self.affine_triplets.get(a..b))
            {
                // Affine: the triplets are those taken before, only the values change.
                rb.residual.values(&slices, out)?;
                check_residual(rb, out)?;
                self.triplets.extend_from_slice(cached);
                row0 += dim;
                continue;
            }
            let ncols: usize = slices.iter().map(|s| s.len()).sum();
            self.jac.clear();
            self.jac.resize(dim * ncols, 0.0);
            rb.residual
                .jacobian_active(&slices, moves, out, &mut self.jac)?;
            check_residual(rb, out)?;
            let first = self.triplets.len();
            let mut local = 0;
            for (start, len) in problem.spans_of(rb) {
                for u in *start..start + len {
                    let (terms, _) = self.map.row(u);
                    // Zero derivatives are kept: the pattern stays that of the residual's reads.
                    for row in 0..dim {
                        let d = self.jac[row * ncols + local];
                        for (col, a) in terms {
                            self.triplets.push((row0 + row, *col, d * a));
                        }
                    }
                    local += 1;
                }
            }
            if rb.affine {
                if let Some(at) = self.affine_at.get_mut(r) {
                    let start = self.affine_triplets.len();
                    self.affine_triplets
                        .extend_from_slice(&self.triplets[first..]);
                    *at = Some((start, self.affine_triplets.len()));
                }
            }
            row0 += dim;
        }
        Ok(())
    }

    /// H_z = Aᵀ·(Σᵢ λᵢ·∇²gᵢ(x(z)))·A, the Hessian of λᵀg over the reduced unknowns (the map
    /// is affine, so it adds no curvature of its own), as a sparse symmetric matrix. `lambda`
    /// has one multiplier per residual row; affine residuals and rows with λᵢ = 0 cost nothing.
    /// Returns `None` when no residual contributes (H = 0).
    ///
    /// # Errors
    /// Dimension errors for wrong lengths.
    pub(crate) fn hessian(
        &mut self,
        problem: &Problem,
        z: &[f64],
        lambda: &[f64],
    ) -> Result<Option<SparseMatrix>> {
        check_len("multipliers", self.rows(), lambda.len())?;
        problem.budget.charge()?;
        self.map.expand(z, &mut self.x)?;
        self.hess_triplets.clear();
        let mut row0 = 0;
        let mut flags = 0;
        let mut slices = smallvec::SmallVec::new();
        for rb in &problem.residuals {
            let dim = rb.dim;
            let weights = &lambda[row0..row0 + dim];
            row0 += dim;
            let moves = &self.block_moves[flags..flags + rb.blocks.len()];
            flags += rb.blocks.len();
            if rb.affine || weights.iter().all(|w| *w == 0.0) || !moves.iter().any(|a| *a) {
                continue;
            }
            gather_into(&self.x, problem.spans_of(rb), &mut slices);
            let ncols: usize = slices.iter().map(|s| s.len()).sum();
            self.hess.clear();
            self.hess.resize(ncols * ncols, 0.0);
            if !rb
                .residual
                .weighted_hessian(&slices, weights, moves, &mut self.hess)?
            {
                continue;
            }
            // Local column → the reduced columns of its unknown (x = A·z + c), looked up once.
            let mut terms: smallvec::SmallVec<[&[(usize, f64)]; 32]> = smallvec::SmallVec::new();
            for (start, len) in problem.spans_of(rb) {
                terms.extend((*start..start + len).map(|u| self.map.row(u).0));
            }
            let triplets = &mut self.hess_triplets;
            for (tp, h_row) in terms.iter().zip(self.hess.chunks_exact(ncols)) {
                if tp.is_empty() {
                    continue;
                }
                for (tq, h) in terms.iter().zip(h_row) {
                    for (c1, a1) in *tp {
                        let ha = h * a1;
                        triplets.extend(tq.iter().map(|(c2, a2)| (*c1, *c2, ha * a2)));
                    }
                }
            }
        }
        if self.hess_triplets.is_empty() {
            return Ok(None);
        }
        let n = self.cols();
        self.hess_asm
            .assemble(n, n, &self.hess_triplets, |_| true)
            .cloned()
            .map(Some)
    }

    /// x(z) of the last evaluation (all unknowns of the problem).
    pub(crate) fn expanded(&self) -> &[f64] {
        &self.x
    }

    /// J_z of the last [`Evaluator::linearize`] as a dense m × n matrix.
    pub(crate) fn dense_jacobian(&self) -> nalgebra::DMatrix<f64> {
        let mut j = nalgebra::DMatrix::zeros(self.rows(), self.cols());
        for &(r, c, v) in &self.triplets {
            if let Some(e) = j.get_mut((r, c)) {
                *e += v;
            }
        }
        j
    }

    /// The triplets of the last [`Evaluator::linearize`].
    pub(crate) fn triplets(&self) -> &[(usize, usize, f64)] {
        &self.triplets
    }

    /// J_z of the last [`Evaluator::linearize`] as a sparse matrix, with the columns whose
    /// `drop_column` entry is true zeroed (they keep their place in the pattern).
    pub(crate) fn jacobian(&mut self, drop_column: &[bool]) -> Result<SparseMatrix> {
        let (rows, cols) = (self.rows(), self.cols());
        self.jac_asm
            .assemble(rows, cols, &self.triplets, |c| {
                !drop_column.get(c).copied().unwrap_or(false)
            })
            .cloned()
    }

    /// Residual per constraint for the rows `g`.
    pub(crate) fn per_constraint(&self, g: &[f64]) -> Vec<ConstraintResidual> {
        per_constraint(&self.row_owner, g)
    }
}

impl Drop for Evaluator {
    /// Hands the buffers to the next evaluator built on this thread.
    fn drop(&mut self) {
        use std::mem::take;
        Spare {
            lower: take(&mut self.lower),
            upper: take(&mut self.upper),
            row_owner: take(&mut self.row_owner),
            block_moves: take(&mut self.block_moves),
            x: take(&mut self.x),
            jac: take(&mut self.jac),
            triplets: take(&mut self.triplets),
            affine_triplets: take(&mut self.affine_triplets),
            affine_at: take(&mut self.affine_at),
        }
        .keep();
    }
}

/// The buffers of a dropped [`Evaluator`], kept per thread for the next one: a sketch solves
/// its components one after the other, each with an evaluator of its own, and these lists were
/// allocated and freed once per component (for a rectangle, as often as it has rows).
#[derive(Debug, Default)]
struct Spare {
    lower: Vec<f64>,
    upper: Vec<f64>,
    row_owner: Vec<ConstraintId>,
    block_moves: Vec<bool>,
    x: Vec<f64>,
    jac: Vec<f64>,
    triplets: Vec<(usize, usize, f64)>,
    affine_triplets: Vec<(usize, usize, f64)>,
    affine_at: Vec<Option<(usize, usize)>>,
}

/// Spare buffers of more entries than this in all are freed instead of kept, so that a thread
/// which once solved a large problem does not hold its memory.
const SPARE_MAX_ENTRIES: usize = 1 << 16;

thread_local! {
    static SPARE: std::cell::RefCell<Option<Spare>> = const { std::cell::RefCell::new(None) };
}

impl Spare {
    /// The buffers kept on this thread, or empty ones.
    fn take() -> Self {
        SPARE
            .try_with(|slot| slot.try_borrow_mut().ok().and_then(|mut s| s.take()))
            .ok()
            .flatten()
            .unwrap_or_default()
    }

    /// Keeps the buffers for the next [`Spare::take`] on this thread (unless they are large,
    /// or the thread is ending).
    fn keep(self) {
        let entries = self.lower.capacity()
            + self.upper.capacity()
            + self.row_owner.capacity()
            + self.block_moves.capacity()
            + self.x.capacity()
            + self.jac.capacity()
            + self.triplets.capacity()
            + self.affine_triplets.capacity()
            + self.affine_at.capacity();
        if entries > SPARE_MAX_ENTRIES {
            return;
        }
        // An unavailable slot (the thread is ending) drops the buffers.
        let _ = SPARE.try_with(|slot| {
            if let Ok(mut s) = slot.try_borrow_mut() {
                *s = Some(self);
            }
        });
    }
}

/// max |v|, 0 for an empty slice (NaN propagates as NaN is never below the running maximum
/// and is returned as infinity).
pub(crate) fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0_f64, |m, x| {
        if x.is_nan() {
            f64::INFINITY
        } else {
            m.max(x.abs())
        }
    })
}

/// Euclidean norm.
pub(crate) fn norm2(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ids::UnknownId;
    use crate::model::scalar::cst;
    use crate::{Residual, Scalar};

    /// |p|² − r² over one point block (nonlinear).
    #[derive(Debug)]
    struct OnCircle(f64);
    impl Residual for OnCircle {
        fn name(&self) -> &str {
            "on circle"
        }
        fn dim(&self) -> usize {
            1
        }
        fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
            out[0] = x[0][0] * x[0][0] + x[0][1] * x[0][1] - cst(self.0 * self.0);
        }
    }

    /// p − q − d over two point blocks (affine, two rows).
    #[derive(Debug)]
    struct Offset([f64; 2]);
    impl Residual for Offset {
        fn name(&self) -> &str {
            "offset"
        }
        fn dim(&self) -> usize {
            2
        }
        fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
            out[0] = x[0][0] - x[1][0] - cst(self.0[0]);
            out[1] = x[0][1] - x[1][1] - cst(self.0[1]);
        }
        fn is_affine(&self) -> bool {
            true
        }
    }

    fn large() -> Problem {
        let mut p = Problem::new();
        let mut blocks = Vec::new();
        for k in 0..6 {
            let v = f64::from(k);
            blocks.push(p.add_block(&[v, 1.0 - v]).unwrap());
        }
        for (k, pair) in blocks.windows(2).enumerate() {
            p.add_residual(Offset([1.0, -1.0]), pair, ConstraintId(k as u64))
                .unwrap();
            p.add_residual(OnCircle(2.0), &pair[..1], ConstraintId(10 + k as u64))
                .unwrap();
        }
        p
    }

    fn small() -> Problem {
        let mut p = Problem::new();
        let a = p.add_block(&[0.5, 0.25]).unwrap();
        let b = p.add_block(&[1.5, -0.5]).unwrap();
        let c = p.add_block(&[3.0, 2.0]).unwrap();
        p.fix_block(c).unwrap();
        p.merge(p.unknown(b, 1).unwrap(), p.unknown(a, 1).unwrap())
            .unwrap();
        p.set_bounds(Var::Unknown(UnknownId(0)), -1.0, 1.0).unwrap();
        p.add_residual(OnCircle(1.0), &[a], ConstraintId(1))
            .unwrap();
        p.add_residual(Offset([0.5, 0.0]), &[b, c], ConstraintId(2))
            .unwrap();
        p.add_residual(OnCircle(2.0), &[b], ConstraintId(3))
            .unwrap();
        p
    }

    /// What an evaluator gives at `z`: the rows and triplets of two linearizations (the
    /// second reuses the affine triplets), the values, and its bounds and owners.
    type Taken = (
        Vec<f64>,
        Vec<(usize, usize, f64)>,
        Vec<(usize, usize, f64)>,
        Vec<f64>,
        Vec<f64>,
        Vec<ConstraintId>,
    );

    fn take(ev: &mut Evaluator, p: &Problem, z: &[f64]) -> Taken {
        let mut g = vec![0.0; ev.rows()];
        ev.linearize_for_report(p, z, &mut g).unwrap();
        let first = ev.triplets().to_vec();
        ev.linearize_for_report(p, z, &mut g).unwrap();
        let second = ev.triplets().to_vec();
        (
            g,
            first,
            second,
            ev.lower.clone(),
            ev.upper.clone(),
            ev.row_owner.clone(),
        )
    }

    /// An evaluator built on the buffers a larger one left behind answers as a fresh one.
    #[test]
    fn an_evaluator_on_spare_buffers_matches_a_fresh_one() {
        let (big, p) = (large(), small());
        let mut e1 = Evaluator::new(&big).unwrap();
        let z1 = e1.map.z0().to_vec();
        let mut g1 = vec![0.0; e1.rows()];
        e1.linearize(&big, &z1, &mut g1).unwrap();
        drop(e1);
        let mut reused = Evaluator::new(&p).unwrap();
        // Built while `reused` holds the spare buffers: fresh ones.
        let mut fresh = Evaluator::new(&p).unwrap();
        assert_eq!((reused.rows(), reused.cols()), (fresh.rows(), fresh.cols()));
        assert_eq!((reused.rows(), reused.cols()), (4, 3));
        let z = [0.75, -0.3, 1.25];
        let (a, b) = (take(&mut reused, &p, &z), take(&mut fresh, &p, &z));
        assert_eq!(a, b);
        // J_z by hand: rows (circle a; offset x, y; circle b), columns (x_a, y_a = y_b, x_b).
        let (xa, ya, xb) = (z[0], z[1], z[2]);
        let mut dense = nalgebra::DMatrix::<f64>::zeros(4, 3);
        for (r, c, v) in &a.1 {
            dense[(*r, *c)] += v;
        }
        #[rustfmt::skip]
        let expected = nalgebra::DMatrix::from_row_slice(4, 3, &[
            2.0 * xa, 2.0 * ya, 0.0,
            0.0, 0.0, 1.0,
            0.0, 1.0, 0.0,
            0.0, 2.0 * ya, 2.0 * xb,
        ]);
        assert!((dense - expected).abs().max() < 1e-15);
        // The bound on x_a is the first column's.
        assert_eq!((a.3[0], a.4[0]), (-1.0, 1.0));
    }
}
