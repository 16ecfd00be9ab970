//! Residuals and Jacobians over the reduced unknowns z at any point, not only at the start.
//!
//! The nonlinear solvers evaluate g(x(z)) and J_z = J_x·A many times at moving z. An
//! [`Evaluator`] holds the reduced map x = A·z + c, the bounds that apply directly to each
//! reduced unknown, and reusable scratch (the expanded x, the per-block dense Jacobian, the
//! triplet list), so repeated evaluations allocate little.

use crate::errors::Result;
use crate::ids::{ConstraintId, Var};
use crate::problem::{check_residual, Problem};
use crate::reduced::ReducedMap;
use crate::report::{per_constraint, ConstraintResidual};
use crate::sparse::{check_len, Assembler, SparseMatrix};

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
        let (mut lower, mut upper) = (Vec::with_capacity(map.len()), Vec::with_capacity(map.len()));
        for var in map.vars() {
            let (lo, hi) = match var {
                Var::Unknown(u) => problem.bounds.get(u.0).copied(),
                Var::Aux(a) => problem.aux_bounds.get(a.0).copied(),
            }
            .unwrap_or((f64::NEG_INFINITY, f64::INFINITY));
            lower.push(lo);
            upper.push(hi);
        }
        let mut row_owner = Vec::with_capacity(problem.num_rows());
        let mut block_moves =
            Vec::with_capacity(problem.residuals.iter().map(|rb| rb.blocks.len()).sum());
        for rb in &problem.residuals {
            row_owner.extend(std::iter::repeat_n(rb.owner, rb.residual.dim()));
            for b in &rb.blocks {
                let (start, len) = problem.block_range(*b)?;
                block_moves.push((start..start + len).any(|u| !map.row(u).0.is_empty()));
            }
        }
        Ok(Self {
            x: vec![0.0; problem.num_unknowns()],
            map,
            lower,
            upper,
            row_owner,
            block_moves,
            jac: Vec::new(),
            triplets: Vec::new(),
            hess: Vec::new(),
            hess_triplets: Vec::new(),
            jac_asm: Assembler::default(),
            hess_asm: Assembler::default(),
            affine_triplets: Vec::new(),
            affine_at: vec![None; problem.residuals.len()],
        })
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
        for (r, rb) in problem.residuals.iter().enumerate() {
            let dim = rb.residual.dim();
            let slices = problem.gather(&self.x, &rb.blocks);
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
            for b in &rb.blocks {
                let (start, len) = problem.block_range(*b)?;
                for u in start..start + len {
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
            if rb.residual.is_affine() {
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
        for rb in &problem.residuals {
            let dim = rb.residual.dim();
            let weights = &lambda[row0..row0 + dim];
            row0 += dim;
            let moves = &self.block_moves[flags..flags + rb.blocks.len()];
            flags += rb.blocks.len();
            if rb.residual.is_affine()
                || weights.iter().all(|w| *w == 0.0)
                || !moves.iter().any(|a| *a)
            {
                continue;
            }
            let slices = problem.gather(&self.x, &rb.blocks);
            let ncols: usize = slices.iter().map(|s| s.len()).sum();
            self.hess.clear();
            self.hess.resize(ncols * ncols, 0.0);
            if !rb
                .residual
                .weighted_hessian(&slices, weights, moves, &mut self.hess)?
            {
                continue;
            }
            // Local column → unknown index.
            let mut unknowns: smallvec::SmallVec<[usize; 32]> = smallvec::SmallVec::new();
            for b in &rb.blocks {
                let (start, len) = problem.block_range(*b)?;
                unknowns.extend(start..start + len);
            }
            for (p, up) in unknowns.iter().enumerate() {
                let (tp, _) = self.map.row(*up);
                if tp.is_empty() {
                    continue;
                }
                for (q, uq) in unknowns.iter().enumerate() {
                    let h = self.hess[p * ncols + q];
                    let (tq, _) = self.map.row(*uq);
                    for (c1, a1) in tp {
                        for (c2, a2) in tq {
                            self.hess_triplets.push((*c1, *c2, h * a1 * a2));
                        }
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
