//! Weighted least squares over a problem's reduced unknowns, by sparse normal equations.
//!
//! Every residual block k of a [`Problem`] gets a weight w_k > 0, and the solve minimises
//!
//! F(z) = Σ_k w_k ‖r_k(x(z))‖²
//!
//! over the reduced unknowns z (x = A·z + c, see [`crate::linalg::reduced`]). With the stacked residual
//! g, its Jacobian J = ∂g/∂z and the diagonal row weight W (w_k repeated over the rows of block
//! k), the Gauss–Newton step Δ solves the normal equations
//!
//! (JᵀWJ + ε·D)·Δ = −JᵀW·g,
//!
//! where D is the diagonal of the reduced unknowns' metric weights ([`Problem::set_weight`]) and
//! ε ≥ 0 an optional damping ([`LsqOptions::damping`], 0 by default). The matrix is symmetric
//! positive semi-definite and sparse; it is formed column by column (lower triangle only) and
//! factorized by faer's sparse Cholesky with a fill-reducing ordering. When every residual is
//! affine, F is quadratic and one step is the exact minimiser; otherwise steps repeat, halved
//! while they do not decrease F, until the step is small.

use faer::linalg::solvers::Solve;
use faer::sparse::{SparseColMat, SymbolicSparseColMat};
use faer::{MatMut, Side};

use crate::linalg::sparse::SparseMatrix;
use crate::model::errors::check_len;
use crate::model::errors::{Error, Result};
use crate::model::problem::Problem;

/// Iteration limits and tolerances of [`solve_least_squares`].
///
/// ```
/// let o = camber_solve::LsqOptions::default().with_max_iterations(5).with_damping(1e-9);
/// assert_eq!(o.max_iterations, 5);
/// ```
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct LsqOptions {
    /// Most Gauss–Newton steps (nonlinear residuals); affine problems take exactly one.
    pub max_iterations: usize,
    /// Converged when max |Δz| ≤ step_tolerance · (1 + max |z|).
    pub step_tolerance: f64,
    /// ε ≥ 0 added as ε·w_i to the diagonal (Levenberg-style damping); 0 solves exactly.
    pub damping: f64,
}

impl Default for LsqOptions {
    fn default() -> Self {
        Self {
            max_iterations: 50,
            step_tolerance: 1e-12,
            damping: 0.0,
        }
    }
}

impl LsqOptions {
    /// Sets [`LsqOptions::max_iterations`].
    pub fn with_max_iterations(mut self, max_iterations: usize) -> Self {
        self.max_iterations = max_iterations;
        self
    }

    /// Sets [`LsqOptions::step_tolerance`].
    pub fn with_step_tolerance(mut self, step_tolerance: f64) -> Self {
        self.step_tolerance = step_tolerance;
        self
    }

    /// Sets [`LsqOptions::damping`].
    pub fn with_damping(mut self, damping: f64) -> Self {
        self.damping = damping;
        self
    }
}

/// What a least-squares solve did. Not converging within the iteration limit is reported here,
/// not as an error.
#[derive(Debug, Clone, PartialEq)]
pub struct LsqReport {
    /// F = Σ w_k ‖r_k‖² at the start.
    pub initial_cost: f64,
    /// F at the result.
    pub final_cost: f64,
    /// Gauss–Newton steps taken.
    pub iterations: usize,
    /// Whether the step tolerance was met (always true for an affine problem).
    pub converged: bool,
    /// Whether every residual is affine (one exact step).
    pub affine: bool,
    /// Reduced unknowns (size of the normal equations).
    pub unknowns: usize,
    /// Residual rows.
    pub rows: usize,
    /// Stored entries of the lower triangle of JᵀWJ.
    pub normal_nonzeros: usize,
}

/// Minimises Σ_k w_k ‖r_k‖² over the reduced unknowns and writes the result into `problem`.
///
/// `residual_weights` holds one w_k > 0 per residual block, in the order they were added; an
/// empty slice means every weight is 1. On error the problem keeps its starting values.
///
/// ```
/// use camber_solve::{solve_least_squares, ConstraintId, LsqOptions, Problem, Residual, Scalar};
/// use camber_solve::scalar::cst;
///
/// /// x − c: pulls the single unknown towards c.
/// #[derive(Debug)]
/// struct Towards(f64);
/// impl Residual for Towards {
///     fn name(&self) -> &str { "towards" }
///     fn dim(&self) -> usize { 1 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) { out[0] = x[0][0] - cst(self.0); }
///     fn is_affine(&self) -> bool { true }
/// }
///
/// let mut p = Problem::new();
/// let b = p.add_block(&[0.0])?;
/// p.add_residual(Towards(1.0), &[b], ConstraintId(0))?;
/// p.add_residual(Towards(4.0), &[b], ConstraintId(1))?;
/// // Weights 2 and 1: the weighted mean (2·1 + 1·4)/3 = 2.
/// let report = solve_least_squares(&mut p, &[2.0, 1.0], &LsqOptions::default())?;
/// assert!((p.values()[0] - 2.0).abs() < 1e-12);
/// assert!((report.final_cost - 6.0).abs() < 1e-12); // 2·1² + 1·2²
/// # Ok::<(), camber_solve::Error>(())
/// ```
///
/// # Errors
/// [`Error::Dimension`] when `residual_weights` is neither empty nor one per residual block;
/// [`Error::NonPositiveWeight`] (index = residual block) for a weight ≤ 0 or non-finite;
/// [`Error::RankDeficient`] (rows = unknowns) when JᵀWJ + ε·D is singular (an unknown no
/// residual determines); and the errors of [`Problem::linearize`].
pub fn solve_least_squares(
    problem: &mut Problem,
    residual_weights: &[f64],
    options: &LsqOptions,
) -> Result<LsqReport> {
    let row_weights = row_weights(problem, residual_weights)?;
    let start_map = problem.reduced_map()?;
    let start_z = start_map.z0().to_vec();
    let outcome = iterate(problem, &row_weights, options);
    if outcome.is_err() {
        // Restores the starting values (they were valid, so this cannot fail in practice).
        problem.apply_reduced(&start_map, &start_z)?;
    }
    outcome
}

fn iterate(problem: &mut Problem, row_weights: &[f64], options: &LsqOptions) -> Result<LsqReport> {
    let mut report = LsqReport {
        initial_cost: 0.0,
        final_cost: 0.0,
        iterations: 0,
        converged: false,
        affine: true,
        unknowns: 0,
        rows: row_weights.len(),
        normal_nonzeros: 0,
    };
    let mut g_trial = vec![0.0; row_weights.len()];
    let mut x_trial = vec![0.0; problem.num_unknowns()];
    for iteration in 0..options.max_iterations.max(1) {
        let lin = problem.linearize()?;
        let cost = weighted_cost(&lin.g, row_weights);
        if iteration == 0 {
            report.initial_cost = cost;
            report.affine = lin.affine;
            report.unknowns = lin.map.len();
        }
        report.final_cost = cost;
        if lin.map.is_empty() {
            report.converged = true;
            break;
        }
        let (normal, mut step) = normal_equations(
            &lin.jacobian,
            row_weights,
            &lin.g,
            lin.map.weights(),
            options.damping,
        )?;
        report.normal_nonzeros = normal.compute_nnz();
        let n = step.len();
        let llt = normal
            .sp_cholesky(Side::Lower)
            .map_err(|_| Error::RankDeficient { rows: n })?;
        llt.solve_in_place(MatMut::from_column_major_slice_mut(
            step.as_mut_slice(),
            n,
            1,
        ));
        if let Some((index, value)) = step.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(Error::NonFinite {
                what: "least-squares step",
                index,
                value: *value,
            });
        }
        report.iterations = iteration + 1;
        let z0 = lin.map.z0();
        if lin.affine {
            let z: Vec<f64> = z0.iter().zip(&step).map(|(a, d)| a + d).collect();
            problem.apply_reduced(&lin.map, &z)?;
            problem.evaluate_at(problem.values(), &mut g_trial)?;
            report.final_cost = weighted_cost(&g_trial, row_weights);
            report.converged = true;
            break;
        }
        // Backtracking: halve the step while it does not decrease F.
        let mut t = 1.0;
        let mut z = z0.to_vec();
        for _ in 0..30 {
            for ((zk, a), d) in z.iter_mut().zip(z0).zip(&step) {
                *zk = a + t * d;
            }
            lin.map.expand(&z, &mut x_trial)?;
            problem.evaluate_at(&x_trial, &mut g_trial)?;
            let trial = weighted_cost(&g_trial, row_weights);
            if trial <= cost {
                report.final_cost = trial;
                break;
            }
            t *= 0.5;
        }
        if report.final_cost > cost {
            // No decrease along the step: a (local) minimum to rounding.
            report.final_cost = cost;
            report.converged = true;
            break;
        }
        problem.apply_reduced(&lin.map, &z)?;
        let size = z0.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let moved = step.iter().fold(0.0_f64, |m, v| m.max((t * v).abs()));
        if moved <= options.step_tolerance * (1.0 + size) {
            report.converged = true;
            break;
        }
    }
    Ok(report)
}

/// One weight per row, from one per residual block (empty = all 1), after checking them.
fn row_weights(problem: &Problem, residual_weights: &[f64]) -> Result<Vec<f64>> {
    if !residual_weights.is_empty() {
        check_len(
            "residual weights",
            problem.num_residuals(),
            residual_weights.len(),
        )?;
    }
    let mut rows = Vec::with_capacity(problem.num_rows());
    for (index, rb) in problem.residuals.iter().enumerate() {
        let w = residual_weights.get(index).copied().unwrap_or(1.0);
        if !(w.is_finite() && w > 0.0) {
            return Err(Error::NonPositiveWeight { index, value: w });
        }
        rows.extend(std::iter::repeat_n(w, rb.residual.dim()));
    }
    Ok(rows)
}

fn weighted_cost(g: &[f64], row_weights: &[f64]) -> f64 {
    g.iter().zip(row_weights).map(|(r, w)| w * r * r).sum()
}

/// The lower triangle of N = JᵀWJ + ε·diag(d) in compressed columns, and b = −JᵀW·g.
///
/// Column j of N is Σ_{i : J_ij ≠ 0} w_i·J_ij·J_i,: (rows i of J that touch column j), gathered
/// with a dense accumulator; only entries r ≥ j are kept. The diagonal is always stored.
fn normal_equations(
    j: &SparseMatrix,
    row_weights: &[f64],
    g: &[f64],
    metric: &[f64],
    damping: f64,
) -> Result<(SparseColMat<usize, f64>, Vec<f64>)> {
    let n = j.ncols();
    check_len("row weights", j.nrows(), row_weights.len())?;
    check_len("residual values", j.nrows(), g.len())?;
    if !(damping.is_finite() && damping >= 0.0) {
        return Err(Error::NonFinite {
            what: "damping",
            index: 0,
            value: damping,
        });
    }
    // The columns of J as (row, value) lists, and b = −JᵀWg.
    let mut col_ptr = vec![0_usize; n + 1];
    for i in 0..j.nrows() {
        for c in j.row(i).0 {
            col_ptr[c + 1] += 1;
        }
    }
    for c in 0..n {
        col_ptr[c + 1] += col_ptr[c];
    }
    let mut next = col_ptr.clone();
    let mut entries = vec![(0_usize, 0.0_f64); col_ptr[n]];
    let mut rhs = vec![0.0; n];
    for i in 0..j.nrows() {
        let (cols, vals) = j.row(i);
        for (c, v) in cols.iter().zip(vals) {
            entries[next[*c]] = (i, *v);
            next[*c] += 1;
            rhs[*c] -= v * row_weights[i] * g[i];
        }
    }
    let mut acc = vec![0.0; n];
    let mut seen = vec![usize::MAX; n];
    let mut touched: Vec<usize> = Vec::new();
    let mut out_ptr = Vec::with_capacity(n + 1);
    let mut out_rows = Vec::new();
    let mut out_vals = Vec::new();
    out_ptr.push(0);
    for col in 0..n {
        touched.clear();
        seen[col] = col;
        touched.push(col);
        acc[col] = damping * metric.get(col).copied().unwrap_or(1.0);
        for &(i, v) in &entries[col_ptr[col]..col_ptr[col + 1]] {
            let scale = row_weights[i] * v;
            let (cols, vals) = j.row(i);
            for (r, a) in cols.iter().zip(vals) {
                if *r < col {
                    continue;
                }
                if seen[*r] != col {
                    seen[*r] = col;
                    acc[*r] = 0.0;
                    touched.push(*r);
                }
                acc[*r] += scale * a;
            }
        }
        touched.sort_unstable();
        for r in &touched {
            out_rows.push(*r);
            out_vals.push(acc[*r]);
        }
        out_ptr.push(out_rows.len());
    }
    let symbolic = SymbolicSparseColMat::new_checked(n, n, out_ptr, None, out_rows);
    Ok((SparseColMat::new(symbolic, out_vals), rhs))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ids::ConstraintId;
    use crate::model::residual::Residual;
    use crate::model::scalar::{cst, Scalar};
    use approx::assert_relative_eq;
    use nalgebra::{DMatrix, DVector};

    /// Row a·x − b over one block.
    #[derive(Debug)]
    struct Row {
        a: Vec<f64>,
        b: f64,
    }

    impl Residual for Row {
        fn name(&self) -> &str {
            "row"
        }
        fn dim(&self) -> usize {
            1
        }
        fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
            let mut s = cst::<T>(-self.b);
            for (a, xi) in self.a.iter().zip(x[0]) {
                s += cst::<T>(*a) * *xi;
            }
            out[0] = s;
        }
        fn is_affine(&self) -> bool {
            true
        }
    }

    fn line_fit(points: &[(f64, f64)], weights: &[f64]) -> (Problem, LsqReport) {
        let mut p = Problem::new();
        let b = p.add_block(&[0.0, 0.0]).unwrap();
        for (k, (x, y)) in points.iter().enumerate() {
            p.add_residual(
                Row {
                    a: vec![1.0, *x],
                    b: *y,
                },
                &[b],
                ConstraintId(k as u64),
            )
            .unwrap();
        }
        let r = solve_least_squares(&mut p, weights, &LsqOptions::default()).unwrap();
        (p, r)
    }

    #[test]
    fn line_fit_by_hand() {
        // y = c + m·x through (0, 1), (1, 3), (2, 2): [3 3; 3 5](c, m) = (6, 7) → c = 3/2, m = 1/2.
        let (p, r) = line_fit(&[(0.0, 1.0), (1.0, 3.0), (2.0, 2.0)], &[]);
        assert_relative_eq!(p.values()[0], 1.5, epsilon = 1e-13);
        assert_relative_eq!(p.values()[1], 0.5, epsilon = 1e-13);
        // Residuals 0.5, −1, 0.5: F = 1.5.
        assert_relative_eq!(r.final_cost, 1.5, epsilon = 1e-13);
        assert_relative_eq!(r.initial_cost, 14.0, epsilon = 1e-13);
        assert!(r.affine && r.converged && r.iterations == 1);
        assert_eq!((r.unknowns, r.rows, r.normal_nonzeros), (2, 3, 3));
    }

    #[test]
    fn weights_behave() {
        let pts = [(0.0, 1.0), (1.0, 3.0), (2.0, 2.0), (3.0, 5.0)];
        // Scaling every weight leaves the minimiser.
        let (a, _) = line_fit(&pts, &[1.0, 2.0, 3.0, 4.0]);
        let (b, _) = line_fit(&pts, &[10.0, 20.0, 30.0, 40.0]);
        assert_relative_eq!(a.values()[0], b.values()[0], epsilon = 1e-12);
        assert_relative_eq!(a.values()[1], b.values()[1], epsilon = 1e-12);
        // Weight 2 on a point equals listing it twice.
        let (c, _) = line_fit(&pts, &[1.0, 2.0, 1.0, 1.0]);
        let twice = [pts[0], pts[1], pts[1], pts[2], pts[3]];
        let (d, _) = line_fit(&twice, &[]);
        assert_relative_eq!(c.values()[0], d.values()[0], epsilon = 1e-12);
        assert_relative_eq!(c.values()[1], d.values()[1], epsilon = 1e-12);
        // A dominant weight makes the line pass through that point (to 1e-6).
        let (e, _) = line_fit(&pts, &[1.0, 1.0, 1e9, 1.0]);
        let at2 = e.values()[0] + 2.0 * e.values()[1];
        assert_relative_eq!(at2, 2.0, epsilon = 1e-6);
    }

    #[test]
    fn agrees_with_dense_qr() {
        // 9 rows, 4 unknowns, deterministic pseudo-random entries.
        let (m, n) = (9, 4);
        let entry = |i: usize, k: usize| ((i * 7 + k * 13) % 11) as f64 / 5.0 - 1.0;
        let a = DMatrix::from_fn(m, n, entry);
        let b = DVector::from_fn(m, |i, _| (i as f64 * 0.7).sin());
        let w: Vec<f64> = (0..m).map(|i| 0.5 + i as f64 / 4.0).collect();
        let mut p = Problem::new();
        let blk = p.add_block(&[0.3; 4]).unwrap();
        for i in 0..m {
            let row = Row {
                a: a.row(i).iter().copied().collect(),
                b: b[i],
            };
            p.add_residual(row, &[blk], ConstraintId(i as u64)).unwrap();
        }
        solve_least_squares(&mut p, &w, &LsqOptions::default()).unwrap();
        // Dense: QR of √W·A, x = R⁻¹Qᵀ√W·b.
        let sw = DMatrix::from_diagonal(&DVector::from_iterator(m, w.iter().map(|v| v.sqrt())));
        let qr = (&sw * &a).qr();
        let rhs = qr.q().transpose() * (&sw * &b);
        let x = qr.r().solve_upper_triangular(&rhs).unwrap();
        for k in 0..n {
            assert_relative_eq!(p.values()[k], x[k], epsilon = 1e-11);
        }
    }

    /// Rosenbrock as residuals: (10(y − x²), 1 − x); minimum (1, 1) with F = 0.
    #[derive(Debug)]
    struct Rosenbrock;

    impl Residual for Rosenbrock {
        fn name(&self) -> &str {
            "rosenbrock"
        }
        fn dim(&self) -> usize {
            2
        }
        fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
            out[0] = cst::<T>(10.0) * (x[0][1] - x[0][0] * x[0][0]);
            out[1] = T::one() - x[0][0];
        }
    }

    #[test]
    fn gauss_newton_on_nonlinear_residuals() {
        let mut p = Problem::new();
        let b = p.add_block(&[-1.2, 1.0]).unwrap();
        p.add_residual(Rosenbrock, &[b], ConstraintId(0)).unwrap();
        let r = solve_least_squares(&mut p, &[], &LsqOptions::default()).unwrap();
        assert!(!r.affine && r.converged, "{r:?}");
        assert_relative_eq!(p.values()[0], 1.0, epsilon = 1e-9);
        assert_relative_eq!(p.values()[1], 1.0, epsilon = 1e-9);
        assert!(r.final_cost < 1e-20);
    }

    #[test]
    fn bad_weights_and_singular_systems_are_errors() {
        let mut p = Problem::new();
        let b = p.add_block(&[0.0, 0.0]).unwrap();
        p.add_residual(
            Row {
                a: vec![1.0, 1.0],
                b: 1.0,
            },
            &[b],
            ConstraintId(0),
        )
        .unwrap();
        let o = LsqOptions::default();
        assert_eq!(
            solve_least_squares(&mut p, &[1.0, 1.0], &o),
            Err(Error::Dimension {
                what: "residual weights",
                expected: 1,
                found: 2
            })
        );
        assert_eq!(
            solve_least_squares(&mut p, &[-1.0], &o),
            Err(Error::NonPositiveWeight {
                index: 0,
                value: -1.0
            })
        );
        // One row, two unknowns: JᵀJ is singular; damping makes it the minimum-norm-like step.
        assert_eq!(
            solve_least_squares(&mut p, &[], &o),
            Err(Error::RankDeficient { rows: 2 })
        );
        assert_eq!(p.values(), &[0.0, 0.0]);
        let r = solve_least_squares(&mut p, &[], &o.with_damping(1e-12)).unwrap();
        assert_relative_eq!(p.values()[0], 0.5, epsilon = 1e-9);
        assert_relative_eq!(p.values()[1], 0.5, epsilon = 1e-9);
        assert!(r.final_cost < 1e-20);
    }
}
