//! Rank and degree-of-freedom analysis of a linearized problem.
//!
//! Dense form ([`analyze_rows`], small problems): the numerical rank r of J (m × n) is the
//! number of singular values above `rank_tolerance`·σ_max (SVD). DOF = n − r, n being the
//! reduced (free) unknowns.
//!
//! Which rows are dependent is decided greedily in row order by Gram–Schmidt on the rows of J
//! (a QR factorization of Jᵀ that rejects instead of pivoting), orthogonalizing twice for
//! stability: row i is independent when its distance from the span of the rows already accepted
//! exceeds `rank_tolerance`·σ_max. The right-hand side g is carried through the same
//! combinations, so for a dependent row i ≈ Σ λ_k·(accepted row k) the leftover
//! h_i = g_i − Σ λ_k·g_k is available at no extra cost: |h_i| ≤ `residual_tolerance` means the
//! row is **redundant** (consistent: J·Δz = −g stays solvable without it and then satisfies it);
//! otherwise it is **conflicting** (no Δz satisfies all rows).
//!
//! Sparse form ([`analyze_rows_sparse`], any size, never a dense matrix): the same greedy
//! decision in row order by a row-by-row Givens QR of [J | −g] (each incoming row is rotated
//! against the triangular rows already accepted, which keeps the elimination orthogonal and so
//! as stable as Gram–Schmidt). A row whose remainder has norm at most `rank_tolerance`·s is
//! dependent, s being the largest row norm of J (σ_max ≥ s ≥ σ_max/√m); its rotated right-hand
//! side is the least-squares residual it adds, zero (within `residual_tolerance`) for a
//! redundant row. The rank is the number of independent rows. Work and storage follow the
//! fill of the triangular factor: linear in the length of chains and ladders.
//!
//! Block by block ([`analyze`]): the same verdicts, with the numeric tests run only inside the
//! diagonal blocks of J's Dulmage–Mendelsohn form and inside the pieces of rows they couple (see
//! [`crate::analysis::structure`] and the `block_analysis` module); [`DofAnalysis::structure`] reports
//! the decomposition. The free columns come from the blocks too: full-rank blocks determine
//! their unknowns, and the null-space projection runs only on the others, piece by piece (the
//! `free_columns` module).

use std::collections::HashSet;

use nalgebra::{DMatrix, DVector};

use crate::analysis::blocks::{analyze_blocks, BlockAnalysis, Kernel};
use crate::analysis::structure::Part;
use crate::linalg::min_norm::MinNormFactorization;
use crate::linalg::reduced::Linearization;
use crate::linalg::sparse::SparseMatrix;
use crate::model::errors::check_len;
use crate::model::errors::Result;
use crate::model::ids::ConstraintId;

/// A row found to depend on the rows before it.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DependentRow {
    /// The row of J.
    pub row: usize,
    /// How far the row's right-hand side is from those of the rows it depends on: zero
    /// (within tolerance) for a redundant row. Dense form: |g_i − Σ λ_k·g_k| with row i ≈
    /// Σ λ_k·(row k); sparse form: the least-squares residual the row adds.
    pub mismatch: f64,
    /// Whether the row is consistent (redundant) rather than conflicting.
    pub consistent: bool,
}

impl DependentRow {
    /// Row `row` left with right-hand side `h` after the rows it depends on: consistent when
    /// |h| is within `residual_tolerance`.
    fn with_mismatch(row: usize, h: f64, residual_tolerance: f64) -> Self {
        Self {
            row,
            mismatch: h.abs(),
            consistent: h.abs() <= residual_tolerance,
        }
    }
}

/// The outcome of [`analyze_rows`].
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct RowAnalysis {
    /// Numerical rank of J (by SVD in the dense form, the independent rows in the sparse one).
    pub rank: usize,
    /// The scale of the rank tolerance: σ_max of J in the dense form, its largest row norm in
    /// the sparse one.
    pub scale: f64,
    /// Rows kept, in order (independent of each other).
    pub independent: Vec<usize>,
    /// Rows dependent on earlier rows, in order.
    pub dependent: Vec<DependentRow>,
    /// The columns (reduced unknowns) that can still move with every independent row held, to
    /// first order: those with a non-zero entry in some null vector of J. The others are
    /// determined by the constraints. In increasing order.
    pub free_columns: Vec<usize>,
}

/// Two random vectors of the null space of J are drawn (from draws of magnitude 1 to 2); a
/// column is free when either has an entry above this fraction of its largest one (a
/// determined column is exactly zero in every null vector, up to rounding), and a vector whose
/// largest entry is below it is rounding left of a trivial null space.
pub(crate) const FREE_COLUMN_TOLERANCE: f64 = 1e-8;

/// Uniform draws in ±[1, 2) from a fixed 64-bit LCG: the random combination of null vectors
/// [`free_columns_of`] needs, reproducible from run to run.
fn draws(seed: u64, n: usize) -> Vec<f64> {
    let mut state = seed;
    (0..n)
        .map(|_| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let u = (state >> 11) as f64 / (1u64 << 53) as f64;
            let sign = if state & 1 == 0 { 1.0 } else { -1.0 };
            sign * (1.0 + u)
        })
        .collect()
}

/// [`draws`] for the other modules of the crate.
pub(crate) fn random_draws(seed: u64, n: usize) -> Vec<f64> {
    draws(seed, n)
}

/// The columns where one of the null vectors `vectors` is not negligible (see
/// [`FREE_COLUMN_TOLERANCE`]).
pub(crate) fn free_columns_of(vectors: &[Vec<f64>], n: usize) -> Vec<usize> {
    let mut free = vec![false; n];
    for v in vectors {
        let top = v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        for (f, x) in free.iter_mut().zip(v) {
            *f |= top > FREE_COLUMN_TOLERANCE && x.abs() > FREE_COLUMN_TOLERANCE * top;
        }
    }
    (0..n).filter(|j| free[*j]).collect()
}

/// Rank of `j` and its dependent rows, classified against the right-hand side `g`
/// (see the module documentation for the tolerances).
///
/// ```
/// use camber_solve::analyze_rows;
/// use nalgebra::dmatrix;
/// // Rows: x = 1, x = 1 again (redundant), x = 2 (conflicting); residuals g = x₀ − b at x₀ = 0.
/// let j = dmatrix![1.0, 0.0; 1.0, 0.0; 1.0, 0.0];
/// let a = analyze_rows(&j, &[-1.0, -1.0, -2.0], 1e-10, 1e-10)?;
/// assert_eq!(a.rank, 1);
/// assert_eq!(a.independent, vec![0]);
/// assert!(a.dependent[0].consistent && !a.dependent[1].consistent);
/// # Ok::<(), camber_solve::Error>(())
/// ```
///
/// # Errors
/// [`crate::Error::Dimension`] when `g` does not have one entry per row.
pub fn analyze_rows(
    j: &DMatrix<f64>,
    g: &[f64],
    rank_tolerance: f64,
    residual_tolerance: f64,
) -> Result<RowAnalysis> {
    let (m, n) = j.shape();
    check_len("residual rows", m, g.len())?;
    let sigma_max = if m == 0 || n == 0 {
        0.0
    } else {
        j.clone()
            .singular_values()
            .iter()
            .copied()
            .fold(0.0, f64::max)
    };
    let dense = dense_rows(j, g, rank_tolerance * sigma_max, residual_tolerance);
    let free_columns = dense_free_columns(j, &dense.independent);
    Ok(RowAnalysis {
        rank: dense.rank,
        scale: sigma_max,
        independent: dense.independent,
        dependent: dense.dependent,
        free_columns,
    })
}

/// The verdicts of one run of a rank kernel over some rows.
#[derive(Clone)]
pub(crate) struct KernelRows {
    /// The numerical rank (SVD count for the dense kernel, independent rows for the sparse).
    pub rank: usize,
    /// Rows kept, in order.
    pub independent: Vec<usize>,
    /// Rows dependent on earlier rows, in order.
    pub dependent: Vec<DependentRow>,
}

/// The dense kernel: rank by the singular values above `threshold`, dependent rows by
/// Gram–Schmidt in row order against the same threshold (see the module documentation).
pub(crate) fn dense_rows(
    j: &DMatrix<f64>,
    g: &[f64],
    threshold: f64,
    residual_tolerance: f64,
) -> KernelRows {
    let (m, n) = j.shape();
    let rank = if m == 0 || n == 0 {
        0
    } else {
        j.clone()
            .singular_values()
            .iter()
            .filter(|s| **s > threshold && **s > 0.0)
            .count()
    };
    let mut basis = GramSchmidt::default();
    let mut independent = Vec::new();
    let mut dependent = Vec::new();
    for (i, gi) in g.iter().enumerate() {
        match basis.insert(j.row(i).transpose(), *gi, threshold) {
            None => independent.push(i),
            Some(h) => dependent.push(DependentRow::with_mismatch(i, h, residual_tolerance)),
        }
    }
    KernelRows {
        rank,
        independent,
        dependent,
    }
}

/// An orthonormal basis q_k of accepted rows, with h_k carrying the right-hand side through
/// the same combinations.
#[derive(Default)]
struct GramSchmidt {
    basis: Vec<(DVector<f64>, f64)>,
}

impl GramSchmidt {
    /// Orthogonalizes v (twice, for stability) against the basis: `None` when what is left
    /// exceeds `threshold` (it joins the basis), else the leftover right-hand side.
    fn insert(&mut self, mut v: DVector<f64>, h: f64, threshold: f64) -> Option<f64> {
        let mut h = h;
        for _ in 0..2 {
            for (q, hq) in &self.basis {
                let c = q.dot(&v);
                v.axpy(-c, q, 1.0);
                h -= c * hq;
            }
        }
        let norm = v.norm();
        if norm > threshold && norm > 0.0 {
            self.basis.push((v / norm, h / norm));
            None
        } else {
            Some(h)
        }
    }
}

/// The free columns of the dense J given its independent rows: random vectors with their
/// components along those rows removed (Gram–Schmidt, twice).
fn dense_free_columns(j: &DMatrix<f64>, independent: &[usize]) -> Vec<usize> {
    let n = j.ncols();
    let mut basis = GramSchmidt::default();
    for i in independent {
        basis.insert(j.row(*i).transpose(), 0.0, 0.0);
    }
    let vectors: Vec<Vec<f64>> = [1_u64, 2]
        .iter()
        .map(|seed| {
            let mut v = DVector::from_vec(draws(*seed, n));
            for _ in 0..2 {
                for (q, _) in &basis.basis {
                    let c = q.dot(&v);
                    v.axpy(-c, q, 1.0);
                }
            }
            v.as_slice().to_vec()
        })
        .collect();
    free_columns_of(&vectors, n)
}

/// Projects each of `vectors` (one entry per column of `j`) onto the null space of the rows
/// of the dense `j` that Gram–Schmidt accepts in row order against `threshold` (the dense
/// kernel's test): a row within `threshold` of the span of the rows before it is a combination
/// of them and adds no condition.
pub(crate) fn dense_null_projection(j: &DMatrix<f64>, threshold: f64, vectors: &mut [Vec<f64>]) {
    let mut basis = GramSchmidt::default();
    for i in 0..j.nrows() {
        basis.insert(j.row(i).transpose(), 0.0, threshold);
    }
    for v in vectors {
        let mut x = DVector::from_column_slice(v);
        for _ in 0..2 {
            for (q, _) in &basis.basis {
                let c = q.dot(&x);
                x.axpy(-c, q, 1.0);
            }
        }
        v.copy_from_slice(x.as_slice());
    }
}

/// [`dense_null_projection`] without a dense matrix: the rows the sparse kernel accepts in row
/// order against `threshold` ([`sparse_rows`], `scale` its rounding scale), then each vector
/// projected on their null space by their minimum-norm factorization (sparse Cholesky of
/// J_A·J_Aᵀ).
///
/// # Errors
/// Factorization errors.
pub(crate) fn sparse_null_projection(
    j: &SparseMatrix,
    threshold: f64,
    scale: f64,
    vectors: &mut [Vec<f64>],
) -> Result<()> {
    let zeros = vec![0.0; j.nrows()];
    let independent = sparse_rows(j, &zeros, threshold, scale, f64::INFINITY).independent;
    if independent.is_empty() {
        return Ok(());
    }
    let n = j.ncols();
    let kept = j.select_rows(&independent);
    let mut projection = MinNormFactorization::try_sparse(&kept, &vec![1.0; n])?;
    let mut multipliers = vec![0.0; independent.len()];
    let mut out = vec![0.0; n];
    for v in vectors {
        projection.project(v, &mut out, &mut multipliers)?;
        v.copy_from_slice(&out);
    }
    Ok(())
}

/// Above this many entries of J (rows × unknowns), [`analyze`] runs the sparse analysis.
pub const DENSE_ANALYSIS_MAX_ENTRIES: usize = 1 << 16;

/// [`analyze_rows`] without a dense matrix: dependent rows in row order by a row-by-row Givens
/// QR (see the module documentation for the tolerances).
///
/// ```
/// use camber_solve::{analyze_rows_sparse, SparseMatrix};
/// // x₀ = 1, x₀ = 1 again (redundant), x₀ + x₁ = 2, x₀ = 2 (conflicting); g = J·0 − b.
/// let j = SparseMatrix::try_from_triplets(4, 2, &[(0, 0, 1.0), (1, 0, 1.0), (2, 0, 1.0), (2, 1, 1.0), (3, 0, 1.0)])?;
/// let a = analyze_rows_sparse(&j, &[-1.0, -1.0, -2.0, -2.0], 1e-10, 1e-10)?;
/// assert_eq!((a.rank, a.independent.clone()), (2, vec![0, 2]));
/// assert!(a.dependent[0].consistent && a.dependent[0].row == 1);
/// assert!(!a.dependent[1].consistent && a.dependent[1].row == 3);
/// # Ok::<(), camber_solve::Error>(())
/// ```
///
/// # Errors
/// [`crate::Error::Dimension`] when `g` does not have one entry per row.
pub fn analyze_rows_sparse(
    j: &SparseMatrix,
    g: &[f64],
    rank_tolerance: f64,
    residual_tolerance: f64,
) -> Result<RowAnalysis> {
    check_len("residual rows", j.nrows(), g.len())?;
    let scale = largest_row_norm(j);
    let sparse = sparse_rows(j, g, rank_tolerance * scale, scale, residual_tolerance);
    let free_columns = sparse_free_columns(j, &sparse.independent)?;
    Ok(RowAnalysis {
        rank: sparse.rank,
        scale,
        independent: sparse.independent,
        dependent: sparse.dependent,
        free_columns,
    })
}

/// The largest row norm of J: the scale of the sparse kernel's tolerances.
pub(crate) fn largest_row_norm(j: &SparseMatrix) -> f64 {
    (0..j.nrows())
        .map(|i| j.row(i).1.iter().map(|v| v * v).sum::<f64>().sqrt())
        .fold(0.0, f64::max)
}

/// The sparse kernel: dependent rows in row order by the row-by-row Givens QR against
/// `threshold`; entries below ε·`scale` are dropped as rounding.
pub(crate) fn sparse_rows(
    j: &SparseMatrix,
    g: &[f64],
    threshold: f64,
    scale: f64,
    residual_tolerance: f64,
) -> KernelRows {
    // Entries this small are rounding left by a rotation: dropped, so they neither become
    // pivots nor grow the fill.
    let negligible = f64::EPSILON * scale;
    let mut factor = GivensRows::new(j.ncols());
    let mut independent = Vec::new();
    let mut dependent = Vec::new();
    for (i, gi) in g.iter().enumerate() {
        let (cols, vals) = j.row(i);
        let row = cols.iter().copied().zip(vals.iter().copied());
        match factor.insert(row, *gi, threshold, negligible) {
            None => independent.push(i),
            Some(h) => dependent.push(DependentRow::with_mismatch(i, h, residual_tolerance)),
        }
    }
    KernelRows {
        rank: independent.len(),
        independent,
        dependent,
    }
}

/// The free columns of J given its independent rows: random vectors projected onto the null
/// space of those rows by their minimum-norm factorization (sparse Cholesky of J·Jᵀ), which,
/// unlike back substitution in R, does not amplify along chains.
///
/// # Errors
/// Factorization errors.
fn sparse_free_columns(j: &SparseMatrix, independent: &[usize]) -> Result<Vec<usize>> {
    let n = j.ncols();
    let vectors: Vec<Vec<f64>> = if independent.is_empty() {
        [1_u64, 2].iter().map(|seed| draws(*seed, n)).collect()
    } else {
        let kept = j.select_rows(independent);
        let mut projection = MinNormFactorization::try_sparse(&kept, &vec![1.0; n])?;
        let mut multipliers = vec![0.0; independent.len()];
        [1_u64, 2]
            .iter()
            .map(|seed| {
                let mut v = vec![0.0; n];
                projection.project(&draws(*seed, n), &mut v, &mut multipliers)?;
                Ok(v)
            })
            .collect::<Result<_>>()?
    };
    Ok(free_columns_of(&vectors, n))
}

/// The upper-triangular factor R of the rows accepted so far, one sparse row per pivot
/// column, each with its rotated right-hand side.
struct GivensRows {
    /// `rows[k]`: the row whose first entry is in column k, as (column, value) pairs in
    /// increasing column order, and its right-hand side.
    rows: Vec<Option<Row>>,
    /// The rows of R an incoming row has rotated so far, as they were before: a row found
    /// dependent leaves R as it found it, so R stays the factor of the accepted rows alone.
    undo: Vec<(usize, Row)>,
    /// Scratch for the incoming row and a rotation's output.
    incoming: Vec<(usize, f64)>,
    spare: Vec<(usize, f64)>,
}

/// A row of R: its entries and its right-hand side.
type Row = (Vec<(usize, f64)>, f64);

impl GivensRows {
    fn new(columns: usize) -> Self {
        Self {
            rows: vec![None; columns],
            undo: Vec::new(),
            incoming: Vec::new(),
            spare: Vec::new(),
        }
    }

    /// Rotates the row w (with right-hand side h) against R until its first entry has no
    /// pivot row: it joins R there (`None`, independent) when its norm exceeds `threshold`;
    /// else it is dependent, R is restored, and its remaining right-hand side is returned.
    fn insert(
        &mut self,
        row: impl Iterator<Item = (usize, f64)>,
        h: f64,
        threshold: f64,
        negligible: f64,
    ) -> Option<f64> {
        let mut w = std::mem::take(&mut self.incoming);
        w.clear();
        w.extend(row.filter(|(_, v)| v.abs() > negligible));
        let mut h = h;
        self.undo.clear();
        loop {
            let Some(&(k, wk)) = w.first() else {
                return self.dependent(w, h);
            };
            let Some((r, hr)) = self.rows[k].take() else {
                if wk.abs() <= threshold {
                    // A leading entry within the rank tolerance is zero at that tolerance (the
                    // rounding a chain of rotations leaves where an exact combination cancels):
                    // as a pivot it would make every later rotation against it amplify
                    // rounding, and accept a dependent row. The row goes on to its next entry.
                    w.remove(0);
                    continue;
                }
                let norm = w.iter().map(|(_, v)| v * v).sum::<f64>().sqrt();
                if norm > threshold && norm > 0.0 {
                    self.rows[k] = Some((w, h));
                    return None;
                }
                return self.dependent(w, h);
            };
            // [c s; −s c] with c = r_kk/ρ, s = w_k/ρ zeroes w_k.
            let rho = r[0].1.hypot(wk);
            let (c, s) = (r[0].1 / rho, wk / rho);
            let mut new_r = Vec::with_capacity(r.len() + w.len());
            let mut rest = std::mem::take(&mut self.spare);
            rest.clear();
            let (mut a, mut b) = (0, 0);
            while a < r.len() || b < w.len() {
                let ca = r.get(a).map_or(usize::MAX, |e| e.0);
                let cb = w.get(b).map_or(usize::MAX, |e| e.0);
                let col = ca.min(cb);
                let ra = if ca == col { r[a].1 } else { 0.0 };
                let wb = if cb == col { w[b].1 } else { 0.0 };
                a += usize::from(ca == col);
                b += usize::from(cb == col);
                if col == k {
                    new_r.push((k, rho));
                    continue;
                }
                let (x, y) = (c * ra + s * wb, c * wb - s * ra);
                if x.abs() > negligible {
                    new_r.push((col, x));
                }
                if y.abs() > negligible {
                    rest.push((col, y));
                }
            }
            let new_hr = c * hr + s * h;
            h = c * h - s * hr;
            self.undo.push((k, (r, hr)));
            self.rows[k] = Some((new_r, new_hr));
            self.spare = std::mem::replace(&mut w, rest);
        }
    }

    /// A dependent row: undoes its rotations of R and returns its remaining right-hand side.
    fn dependent(&mut self, w: Vec<(usize, f64)>, h: f64) -> Option<f64> {
        for (k, row) in self.undo.drain(..).rev() {
            self.rows[k] = Some(row);
        }
        self.incoming = w;
        Some(h)
    }
}

/// The DOF analysis of a problem, by constraint.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DofAnalysis {
    /// Reduced (free) unknowns n.
    pub free_unknowns: usize,
    /// Numerical rank r of J.
    pub rank: usize,
    /// n − r.
    pub dof: usize,
    /// Constraints that can be deleted without changing the solution set to first order: they
    /// own a consistent dependent row, no inconsistent one, and J without their rows keeps its
    /// rank (each once, in row order).
    pub redundant: Vec<ConstraintId>,
    /// Constraints with consistent dependent rows that are still needed: deleting them would
    /// lower the rank (a tangency whose position rows repeat a coincidence but whose direction
    /// row does not). Their dependent rows are left out of solves like those of redundant ones.
    pub partly_redundant: Vec<ConstraintId>,
    /// Constraints owning an inconsistent dependent row (each once, in row order); never also
    /// listed as redundant.
    pub conflicting: Vec<ConstraintId>,
    /// Constraints whose rows are dependent only at this configuration (a tangency by design, a
    /// singular start): nearby on the constraint manifold they are independent, so they are
    /// neither redundant nor conflicting, and `rank` and `dof` are the nearby (generic) ones.
    /// Filled by [`crate::Problem::analyze`] for nonlinear problems; empty from [`analyze`].
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub accidental: Vec<ConstraintId>,
    /// For each redundant, partly redundant or conflicting constraint (in that order, as
    /// listed), the other constraints its dependent rows are combinations of: row_i ≈
    /// Σ λ_k·row_k over the independent rows k, the constraints owning a k with λ_k ≠ 0.
    /// Left empty above `DEPENDENCY_NAMING_MAX_ROWS` (1,000) dependent rows.
    pub depends_on: Vec<Dependency>,
    /// The row-level result.
    pub rows: RowAnalysis,
    /// What the sparsity pattern of J says before any value is looked at.
    pub structure: StructureSummary,
}

/// The structural facts of a DOF analysis: the Dulmage–Mendelsohn decomposition of J's pattern
/// (see [`crate::analysis::structure`]) and where the numeric rank tests ran.
#[derive(Debug, Clone, Default, PartialEq, Eq, serde::Serialize)]
pub struct StructureSummary {
    /// The size of a maximum matching of rows to unknowns: the largest rank any values could
    /// give J with this pattern (the numerical rank is at most this).
    pub structural_rank: usize,
    /// The rows of the over-determined part (more rows than the unknowns they read), in
    /// increasing order: every dependent row that is dependent by structure alone is here.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub over_determined_rows: Vec<usize>,
    /// The constraints owning those rows (each once, in row order).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub over_determined_constraints: Vec<ConstraintId>,
    /// The reduced unknowns of the under-determined part (more unknowns than the rows that read
    /// them), in increasing order: free whatever the values.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub under_determined_unknowns: Vec<usize>,
    /// Rows (and unknowns) of the well-determined, square part.
    pub well_determined_rows: usize,
    /// Irreducible blocks of the square part.
    pub square_blocks: usize,
    /// Rows of the largest of them.
    pub largest_square_block: usize,
    /// Rows whose rank test ran in a coupled piece (see [`analyze`]); the others were settled
    /// by the full rank of their diagonal blocks.
    pub coupled_rows: usize,
    /// Rows of the largest coupled piece.
    pub largest_coupled_piece: usize,
    /// Unknowns the free-unknown projection ran on: those that full-rank blocks do not
    /// determine (see [`analyze`]). Zero for a fully constrained sketch: no projection ran.
    pub projected_unknowns: usize,
    /// Unknowns of the largest piece projected.
    pub largest_projected_piece: usize,
}

impl StructureSummary {
    fn of(blocks: &BlockAnalysis, row_owner: &[ConstraintId]) -> Self {
        let d = &blocks.structure;
        let over_determined_rows = d.rows_in(Part::OverDetermined);
        let mut over_determined_constraints: Vec<ConstraintId> = Vec::new();
        let mut seen = std::collections::HashSet::new();
        for r in &over_determined_rows {
            if let Some(owner) = row_owner.get(*r) {
                if seen.insert(*owner) {
                    over_determined_constraints.push(*owner);
                }
            }
        }
        let square = d.blocks.iter().filter(|b| b.part == Part::WellDetermined);
        Self {
            structural_rank: d.matching.size(),
            over_determined_rows,
            over_determined_constraints,
            under_determined_unknowns: d.columns_in(Part::UnderDetermined),
            well_determined_rows: square.clone().map(|b| b.rows.len()).sum(),
            square_blocks: square.clone().count(),
            largest_square_block: square.map(|b| b.rows.len()).max().unwrap_or(0),
            coupled_rows: blocks.pieces.iter().map(|p| p.rows.len()).sum(),
            largest_coupled_piece: blocks
                .pieces
                .iter()
                .map(|p| p.rows.len())
                .max()
                .unwrap_or(0),
            projected_unknowns: blocks.free.candidates,
            largest_projected_piece: blocks.free.largest_piece,
        }
    }
}

/// Which constraints a constraint's dependent rows are combinations of.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct Dependency {
    /// The constraint with dependent rows.
    pub constraint: ConstraintId,
    /// The other constraints owning the independent rows its dependent rows combine.
    pub on: Vec<ConstraintId>,
}

/// At most this many dependent rows get their [`Dependency`] named (one projection each on
/// the factorization of the independent rows).
pub const DEPENDENCY_NAMING_MAX_ROWS: usize = 1000;

/// The constraints each named constraint's dependent rows depend on: for a dependent row i,
/// the multipliers y of the projection of row_iᵀ onto the span of the independent rows (the
/// minimum-norm factorization's y = (J_A·J_Aᵀ)⁻¹·J_A·row_iᵀ, so row_i ≈ yᵀ·J_A); the owners of
/// the rows with |y_k| above 10⁻⁸·max |y|. A dependent row is a combination of the independent
/// rows of its coupled piece alone (see [`analyze`]), so each piece is factored on its own.
fn dependencies(
    lin: &Linearization,
    blocks: &BlockAnalysis,
    named: &[ConstraintId],
) -> Result<Vec<Dependency>> {
    let rows = &blocks.rows;
    if named.is_empty()
        || rows.dependent.len() > DEPENDENCY_NAMING_MAX_ROWS
        || rows.independent.is_empty()
    {
        return Ok(Vec::new());
    }
    let mut out: Vec<Dependency> = named
        .iter()
        .map(|c| Dependency {
            constraint: *c,
            on: Vec::new(),
        })
        .collect();
    let m = lin.jacobian.nrows();
    let mut is_independent = vec![false; m];
    for i in &rows.independent {
        is_independent[*i] = true;
    }
    let mut is_dependent = vec![false; m];
    for d in &rows.dependent {
        is_dependent[d.row] = true;
    }
    let mut local = vec![usize::MAX; lin.jacobian.ncols()];
    for piece in &blocks.pieces {
        let named_here: Vec<usize> = piece
            .rows
            .iter()
            .copied()
            .filter(|r| {
                is_dependent[*r]
                    && lin
                        .row_owner
                        .get(*r)
                        .is_some_and(|o| out.iter().any(|e| e.constraint == *o))
            })
            .collect();
        let kept: Vec<usize> = piece
            .rows
            .iter()
            .copied()
            .filter(|r| is_independent[*r])
            .collect();
        if named_here.is_empty() || kept.is_empty() {
            continue;
        }
        let n = piece.columns.len();
        for (k, c) in piece.columns.iter().enumerate() {
            local[*c] = k;
        }
        let restricted = |r: usize| -> Vec<(usize, usize, f64)> {
            let (cols, vals) = lin.jacobian.row(r);
            cols.iter()
                .zip(vals)
                .filter(|(c, _)| local[**c] != usize::MAX)
                .map(|(c, v)| (0, local[*c], *v))
                .collect()
        };
        let triplets: Vec<(usize, usize, f64)> = kept
            .iter()
            .enumerate()
            .flat_map(|(k, r)| restricted(*r).into_iter().map(move |(_, c, v)| (k, c, v)))
            .collect();
        let independent = SparseMatrix::try_from_triplets(kept.len(), n, &triplets)?;
        let mut f = MinNormFactorization::try_auto(&independent, &vec![1.0; n], 2000)?;
        let (mut v, mut projected) = (vec![0.0; n], vec![0.0; n]);
        let mut y = vec![0.0; kept.len()];
        for r in named_here {
            let Some(owner) = lin.row_owner.get(r) else {
                continue;
            };
            let Some(entry) = out.iter_mut().find(|e| e.constraint == *owner) else {
                continue;
            };
            v.fill(0.0);
            for (_, c, x) in restricted(r) {
                v[c] = x;
            }
            f.project(&v, &mut projected, &mut y)?;
            let top = y.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
            for (k, yk) in y.iter().enumerate() {
                if yk.abs() > 1e-8 * top {
                    if let Some(o) = lin.row_owner.get(kept[k]) {
                        if o != owner && !entry.on.contains(o) {
                            entry.on.push(*o);
                        }
                    }
                }
            }
        }
        for c in &piece.columns {
            local[*c] = usize::MAX;
        }
    }
    for e in &mut out {
        e.on.sort_unstable();
    }
    Ok(out)
}

/// The kernel for a matrix of `entries` rows × unknowns: dense up to
/// [`DENSE_ANALYSIS_MAX_ENTRIES`], sparse above.
pub(crate) fn kernel_for(entries: usize) -> Kernel {
    if entries <= DENSE_ANALYSIS_MAX_ENTRIES {
        Kernel::Dense
    } else {
        Kernel::Sparse
    }
}

/// [`analyze_rows`] (up to [`DENSE_ANALYSIS_MAX_ENTRIES`] entries of J) or
/// [`analyze_rows_sparse`] run block by block on the Dulmage–Mendelsohn form of J: the same
/// verdicts, with numeric work only inside diagonal blocks and coupled pieces (see the
/// `block_analysis` module). The decomposition is reported in [`DofAnalysis::structure`].
///
/// # Errors
/// As [`analyze_rows`]; factorization errors of the free-column projection.
pub(crate) fn analyze_rows_by_blocks(
    j: &SparseMatrix,
    g: &[f64],
    rank_tolerance: f64,
    residual_tolerance: f64,
    free_columns: bool,
) -> Result<BlockAnalysis> {
    let kernel = kernel_for(j.nrows().saturating_mul(j.ncols()));
    analyze_blocks(
        j,
        g,
        rank_tolerance,
        residual_tolerance,
        kernel,
        free_columns,
    )
}

/// Runs [`analyze_rows`] (up to [`DENSE_ANALYSIS_MAX_ENTRIES`] entries of J) or
/// [`analyze_rows_sparse`] on a linearization, block by block on the Dulmage–Mendelsohn form
/// of J's pattern, and names the constraints.
///
/// The blocks are tested first to last: a block whose rows, restricted to its own columns,
/// have full rank, and whose columns no earlier coupled block reads, holds only independent
/// rows. The over-determined part, rank-deficient blocks and every block they read form the
/// coupled pieces, each analysed alone; a dependent row is a combination of rows of its own
/// piece.
///
/// The free unknowns ([`RowAnalysis::free_columns`]) come from the blocks too, tested last to
/// first: a square block of full rank whose rows read only determined unknowns outside it, and
/// an over-determined block of full column rank, determine their unknowns. Random vectors are
/// projected on the null space of the rows of the other blocks, restricted to the other
/// unknowns, piece by piece; a fully constrained sketch projects nothing.
///
/// # Errors
/// As [`analyze_rows`].
pub fn analyze(
    lin: &Linearization,
    rank_tolerance: f64,
    residual_tolerance: f64,
) -> Result<DofAnalysis> {
    let blocks = analyze_rows_by_blocks(
        &lin.jacobian,
        &lin.g,
        rank_tolerance,
        residual_tolerance,
        true,
    )?;
    let rows = &blocks.rows;
    // Each list in the order of its first dependent row, without repeats (sets, so that a
    // sketch with many dependent rows is not quadratic).
    let (mut redundant, mut conflicting) = (Vec::new(), Vec::new());
    let (mut in_redundant, mut in_conflicting) = (HashSet::new(), HashSet::new());
    for d in &rows.dependent {
        let (list, set) = if d.consistent {
            (&mut redundant, &mut in_redundant)
        } else {
            (&mut conflicting, &mut in_conflicting)
        };
        if let Some(owner) = lin.row_owner.get(d.row) {
            if set.insert(*owner) {
                list.push(*owner);
            }
        }
    }
    // A constraint with one inconsistent row is conflicting, even where its other rows are
    // merely redundant: never both.
    redundant.retain(|c| !in_conflicting.contains(c));
    let partly_redundant = needed(
        (&lin.jacobian, &lin.g, &lin.row_owner),
        &blocks,
        &redundant,
        residual_tolerance,
    )?;
    let needed_set: HashSet<ConstraintId> = partly_redundant.iter().copied().collect();
    redundant.retain(|c| !needed_set.contains(c));
    let named: Vec<ConstraintId> = redundant
        .iter()
        .chain(&partly_redundant)
        .chain(&conflicting)
        .copied()
        .collect();
    let depends_on = dependencies(lin, &blocks, &named)?;
    let free_unknowns = lin.map.len();
    Ok(DofAnalysis {
        free_unknowns,
        rank: rows.rank,
        dof: free_unknowns.saturating_sub(rows.rank),
        redundant,
        partly_redundant,
        conflicting,
        accidental: Vec::new(),
        depends_on,
        structure: StructureSummary::of(&blocks, &lin.row_owner),
        rows: blocks.rows,
    })
}

/// The constraints of `candidates` (each with a consistent dependent row) that cannot be
/// deleted: J without their rows has a lower rank. A candidate all of whose rows were found
/// dependent is deletable at once (each depends on accepted rows of other constraints). One
/// with an accepted row in a clear block cannot be deleted (a clear row is independent of all
/// the others). Any other is tested on the coupled pieces its accepted rows lie in: the rank of
/// J without its rows drops exactly when that of one of those pieces does
/// ([`BlockAnalysis::piece_rank_drops_without`]), so no test runs on the whole component.
fn needed(
    (j, g, row_owner): (&SparseMatrix, &[f64], &[ConstraintId]),
    blocks: &BlockAnalysis,
    candidates: &[ConstraintId],
    residual_tolerance: f64,
) -> Result<Vec<ConstraintId>> {
    if candidates.is_empty() {
        return Ok(Vec::new());
    }
    let m = g.len();
    let wanted: HashSet<ConstraintId> = candidates.iter().copied().collect();
    let mut rows_of: std::collections::HashMap<ConstraintId, Vec<usize>> =
        std::collections::HashMap::new();
    for (r, owner) in row_owner.iter().enumerate() {
        if wanted.contains(owner) {
            rows_of.entry(*owner).or_default().push(r);
        }
    }
    let mut independent = vec![false; m];
    for r in &blocks.rows.independent {
        independent[*r] = true;
    }
    let piece_of_row = blocks.piece_of_rows(m);
    let mut out = Vec::new();
    for c in candidates {
        let own = rows_of.get(c).map_or(&[][..], Vec::as_slice);
        let mut touched: Vec<usize> = own
            .iter()
            .filter(|r| independent[**r])
            .map(|r| piece_of_row[*r])
            .collect();
        if touched.is_empty() {
            continue;
        }
        if touched.contains(&usize::MAX) {
            out.push(*c);
            continue;
        }
        touched.sort_unstable();
        touched.dedup();
        for piece in touched {
            if blocks.piece_rank_drops_without(j, g, piece, own, residual_tolerance)? {
                out.push(*c);
                break;
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::dmatrix;
    use proptest::prelude::*;

    /// Sparse rows (two adjacent columns at a random place, small integers), copies of an
    /// earlier row and sums of two, with g = J·z except where one row is shifted: several
    /// pieces and clear blocks.
    fn sparse_dependent_system() -> impl Strategy<Value = (SparseMatrix, Vec<f64>)> {
        (3usize..12, 3usize..16, any::<u64>()).prop_map(|(n, m, seed)| {
            let mut state = seed | 1;
            let mut next = move |k: u64| {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                state % k
            };
            let mut j = DMatrix::<f64>::zeros(m, n);
            for i in 0..m {
                match next(4) {
                    0 if i > 0 => {
                        let k = next(i as u64) as usize;
                        let row = j.row(k).into_owned();
                        j.row_mut(i).copy_from(&row);
                    }
                    1 if i > 1 => {
                        let (a, b) = (next(i as u64) as usize, next(i as u64) as usize);
                        let row = j.row(a) + j.row(b);
                        j.row_mut(i).copy_from(&row);
                    }
                    _ => {
                        let c = next(n as u64 - 1) as usize;
                        j[(i, c)] = next(5) as f64 - 2.0;
                        j[(i, c + 1)] = next(5) as f64 - 2.0;
                    }
                }
            }
            let z: Vec<f64> = (0..n).map(|_| next(9) as f64 * 0.25 - 1.0).collect();
            let mut g: Vec<f64> = (0..m)
                .map(|i| (0..n).map(|c| j[(i, c)] * z[c]).sum())
                .collect();
            let broken = next(m as u64 + 3) as usize;
            if broken < m {
                g[broken] += 0.5;
            }
            (SparseMatrix::from_dense(&j), g)
        })
    }

    /// Rows that are random small-integer rows or integer combinations of earlier ones, with a
    /// right-hand side consistent with a point z (g = J·z), except where `break_row` shifts it.
    fn dependent_system() -> impl Strategy<Value = (DMatrix<f64>, Vec<f64>)> {
        (2usize..7, 3usize..9, any::<u64>()).prop_map(|(n, m, seed)| {
            let mut state = seed | 1;
            let mut next = move |k: i64| {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                (state % (2 * k as u64 + 1)) as i64 - k
            };
            let mut j = DMatrix::<f64>::zeros(m, n);
            for i in 0..m {
                if i > 0 && next(1) == 0 {
                    for k in 0..i {
                        let a = next(2) as f64;
                        for c in 0..n {
                            j[(i, c)] += a * j[(k, c)];
                        }
                    }
                } else {
                    for c in 0..n {
                        j[(i, c)] = next(3) as f64;
                    }
                }
            }
            let z: Vec<f64> = (0..n).map(|_| next(4) as f64 * 0.25).collect();
            let mut g: Vec<f64> = (0..m)
                .map(|i| (0..n).map(|c| j[(i, c)] * z[c]).sum())
                .collect();
            let broken = (next(100) + 100) as usize % (m + 2);
            if broken < m {
                g[broken] += 0.5;
            }
            (j, g)
        })
    }

    proptest! {
        /// The sparse analysis agrees with the dense one (SVD rank, Gram–Schmidt rows):
        /// same rank, same independent rows, same redundant/conflicting verdicts.
        #[test]
        fn sparse_agrees_with_dense((j, g) in dependent_system()) {
            let dense = analyze_rows(&j, &g, 1e-10, 1e-9).unwrap();
            let sparse = analyze_rows_sparse(&SparseMatrix::from_dense(&j), &g, 1e-10, 1e-9).unwrap();
            prop_assert_eq!(sparse.rank, dense.rank);
            prop_assert_eq!(&sparse.independent, &dense.independent);
            let verdicts = |a: &RowAnalysis| a.dependent.iter().map(|d| (d.row, d.consistent)).collect::<Vec<_>>();
            prop_assert_eq!(verdicts(&sparse), verdicts(&dense));
            prop_assert_eq!(&sparse.free_columns, &dense.free_columns);
        }

        /// The constraints found needed piece by piece are those whose deletion lowers the
        /// rank of the whole J (the whole-matrix test, run for every candidate), on sparse
        /// systems of several pieces and clear blocks with rows grouped into constraints.
        #[test]
        fn needed_by_pieces_agrees_with_the_whole_matrix(
            (j, g) in sparse_dependent_system(), grouping in any::<u64>(),
        ) {
            let m = j.nrows();
            let mut state = grouping | 1;
            let mut owner = 0u64;
            let row_owner: Vec<ConstraintId> = (0..m)
                .map(|_| {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    if state % 3 == 0 {
                        owner += 1;
                    }
                    ConstraintId(owner)
                })
                .collect();
            let blocks = analyze_rows_by_blocks(&j, &g, 1e-10, 1e-9, false).unwrap();
            let mut candidates: Vec<ConstraintId> = Vec::new();
            for d in blocks.rows.dependent.iter().filter(|d| d.consistent) {
                if !candidates.contains(&row_owner[d.row]) {
                    candidates.push(row_owner[d.row]);
                }
            }
            let by_pieces = needed((&j, &g, &row_owner), &blocks, &candidates, 1e-9).unwrap();
            let whole: Vec<ConstraintId> = candidates
                .iter()
                .copied()
                .filter(|c| {
                    let others: Vec<usize> = (0..m).filter(|i| row_owner[*i] != *c).collect();
                    let gj: Vec<f64> = others.iter().map(|i| g[*i]).collect();
                    let rank = analyze_rows_by_blocks(&j.select_rows(&others), &gj, 1e-10, 1e-9, false)
                        .unwrap()
                        .rows
                        .rank;
                    rank < blocks.rows.rank
                })
                .collect();
            prop_assert_eq!(by_pieces, whole);
        }
    }

    #[test]
    fn free_columns_are_those_the_rows_leave_movable() {
        // x₀ = 1 determines x₀; x₁ + x₂ = 3 leaves x₁ and x₂ free (one DOF between them);
        // x₃ − x₄ = 0 with x₄ = 2 determines both; x₅ appears nowhere.
        let j = dmatrix![
            1.0, 0.0, 0.0, 0.0, 0.0, 0.0;
            0.0, 1.0, 1.0, 0.0, 0.0, 0.0;
            0.0, 0.0, 0.0, 1.0, -1.0, 0.0;
            0.0, 0.0, 0.0, 0.0, 1.0, 0.0
        ];
        let g = [0.0; 4];
        let dense = analyze_rows(&j, &g, 1e-10, 1e-10).unwrap();
        assert_eq!(dense.free_columns, vec![1, 2, 5]);
        let sparse = analyze_rows_sparse(&SparseMatrix::from_dense(&j), &g, 1e-10, 1e-10).unwrap();
        assert_eq!(sparse.free_columns, vec![1, 2, 5]);
    }

    #[test]
    fn a_long_chain_is_analysed_sparsely() {
        // x_{i+1} − x_i = 1 for 200,000 unknowns, then a closing row x_last − x_0 = n − 1
        // (redundant) and x_0 = 5 twice with different values (the second conflicting).
        let n = 200_000;
        let mut t = Vec::new();
        let mut g = Vec::new();
        for i in 0..n - 1 {
            t.push((i, i, -1.0));
            t.push((i, i + 1, 1.0));
            g.push(-1.0);
        }
        t.push((n - 1, 0, -1.0));
        t.push((n - 1, n - 1, 1.0));
        g.push(-((n - 1) as f64));
        t.push((n, 0, 1.0));
        g.push(-5.0);
        t.push((n + 1, 0, 1.0));
        g.push(-6.0);
        let j = SparseMatrix::try_from_triplets(n + 2, n, &t).unwrap();
        let a = analyze_rows_sparse(&j, &g, 1e-10, 1e-9).unwrap();
        assert_eq!(a.rank, n);
        let verdicts: Vec<(usize, bool)> =
            a.dependent.iter().map(|d| (d.row, d.consistent)).collect();
        assert_eq!(verdicts, vec![(n - 1, true), (n + 1, false)]);
        // x₀ = 5 and the differences determine every unknown.
        assert!(a.free_columns.is_empty());
    }

    #[test]
    fn independent_rows_are_all_kept() {
        let j = dmatrix![1.0, 2.0, 0.0; 0.0, 1.0, 1.0];
        let a = analyze_rows(&j, &[0.3, -0.2], 1e-12, 1e-12).unwrap();
        assert_eq!(
            (a.rank, a.independent.clone(), a.dependent.len()),
            (2, vec![0, 1], 0)
        );
    }

    #[test]
    fn a_combination_of_earlier_rows_is_dependent() {
        // Row 2 = row 0 + 2·row 1; consistent when g2 = g0 + 2·g1.
        let j = dmatrix![1.0, 0.0, 1.0; 0.0, 1.0, -1.0; 1.0, 2.0, -1.0];
        let ok = analyze_rows(&j, &[1.0, 2.0, 5.0], 1e-12, 1e-12).unwrap();
        assert_eq!(ok.rank, 2);
        assert_eq!(ok.dependent.len(), 1);
        assert!(ok.dependent[0].consistent && ok.dependent[0].row == 2);
        let bad = analyze_rows(&j, &[1.0, 2.0, 5.5], 1e-12, 1e-12).unwrap();
        assert!(!bad.dependent[0].consistent);
        assert!((bad.dependent[0].mismatch - 0.5).abs() < 1e-12);
    }

    #[test]
    fn zero_rows_and_empty_matrices() {
        let j = dmatrix![0.0, 0.0; 1.0, 0.0];
        let a = analyze_rows(&j, &[0.0, 1.0], 1e-12, 1e-12).unwrap();
        assert_eq!(a.independent, vec![1]);
        assert!(a.dependent[0].consistent);
        let e = analyze_rows(&DMatrix::zeros(0, 3), &[], 1e-12, 1e-12).unwrap();
        assert_eq!(e.rank, 0);
    }
}
