//! The rank analysis run block by block on the Dulmage–Mendelsohn form of J.
//!
//! Order the blocks of [`crate::analysis::structure::Decomposition`] first to last, so that the rows of a
//! block read only its own columns and those of later blocks. Call a block *clear* when its
//! diagonal block (its rows restricted to its own columns) has full row rank numerically, and
//! when every block whose rows read its columns is clear too (blocks are tested in order, so
//! this is known by the time a block is reached). Then:
//!
//! - every row of a clear block is independent of all the other rows of J: in a combination of
//!   rows that vanishes, restrict to the columns of the clear blocks. Only rows of clear blocks
//!   read them (a block reading a clear block's columns is clear), and there they form a block
//!   triangular matrix with full-row-rank diagonal blocks, so their coefficients are zero;
//! - the other rows (*coupled*: the over-determined part, every block whose diagonal block is
//!   rank deficient, and every block such a block's rows read) read only coupled columns. So a
//!   coupled row depends on earlier rows exactly when it depends on earlier coupled rows, with
//!   the same combination, hence the same consistency verdict and mismatch.
//!
//! The coupled rows split further into connected pieces that share no column, each analysed
//! alone with the kernel of [`crate::analysis`] (dense Gram–Schmidt and SVD for a small
//! component, the sparse row-by-row Givens QR for a large one) against the tolerances of the
//! whole component. A well-posed sketch has no coupled rows at all; a redundant dimension makes
//! a small over-determined piece. So no factorization of the component's size runs for the row
//! verdicts: only diagonal blocks and coupled pieces are factored.
//!
//! The scale of the dense kernel, σ_max(J), comes from power iteration on JᵀJ (sparse products).
//! The estimate ‖J·x‖ of the unit iterate x is never above σ_max; it falls short only while the
//! iteration has not yet separated σ_max from a close σ₂, and then by less than their relative
//! gap. So a rank verdict could differ from the whole-matrix SVD only for a singular value
//! within that fraction of the threshold.

use std::borrow::Cow;

use nalgebra::DVector;

use crate::analysis::free_columns::{self as free, FreeColumns, RankTest};
use crate::analysis::structure::{Decomposition, Part};
use crate::analysis::{
    dense_rows, largest_row_norm, random_draws, sparse_rows, DependentRow, KernelRows, RowAnalysis,
};
use crate::linalg::sparse::SparseMatrix;
use crate::model::errors::check_len;
use crate::model::errors::Result;

/// Which rank kernel runs inside the blocks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kernel {
    /// Gram–Schmidt and SVD on dense copies of each block, σ_max(J) as scale.
    Dense,
    /// Row-by-row Givens QR, the largest row norm of J as scale.
    Sparse,
}

/// A connected set of coupled rows and the columns they read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Piece {
    /// Its rows, increasing.
    pub rows: Vec<usize>,
    /// Its columns, increasing.
    pub columns: Vec<usize>,
    /// The rank of its rows (the number found independent).
    pub rank: usize,
}

/// The block-wise analysis: the row verdicts, the decomposition they were found on and the
/// coupled pieces.
#[derive(Debug, Clone)]
pub(crate) struct BlockAnalysis {
    /// The row-level result, as [`crate::analysis::analyze_rows`] gives it.
    pub rows: RowAnalysis,
    /// The structure of J.
    pub structure: Decomposition,
    /// The coupled pieces, each analysed alone.
    pub pieces: Vec<Piece>,
    /// What the free-column projection ran on (all zero when it was not asked for, or when
    /// every unknown is determined by structure and full-rank blocks).
    pub free: FreeColumns,
    /// The kernel, threshold and scale every rank test of the component ran with.
    pub test: RankTest,
}

impl BlockAnalysis {
    /// The piece of each of J's `m` rows; `usize::MAX` for a row of a clear block.
    pub(crate) fn piece_of_rows(&self, m: usize) -> Vec<usize> {
        let mut out = vec![usize::MAX; m];
        for (k, p) in self.pieces.iter().enumerate() {
            for r in &p.rows {
                out[*r] = k;
            }
        }
        out
    }

    /// Whether piece `piece` loses rank when the rows `removed` (increasing; rows of other
    /// pieces are ignored) are deleted from it, tested with the component's kernel and
    /// threshold. Pieces share no column and rows of clear blocks are independent of every
    /// other row, so the rank of J without a set of rows drops exactly when that of some piece
    /// does or when a clear row is among them.
    ///
    /// # Errors
    /// Building the restricted matrix.
    pub(crate) fn piece_rank_drops_without(
        &self,
        j: &SparseMatrix,
        g: &[f64],
        piece: usize,
        removed: &[usize],
        residual_tolerance: f64,
    ) -> Result<bool> {
        let p = &self.pieces[piece];
        let kept: Vec<usize> = p
            .rows
            .iter()
            .copied()
            .filter(|r| removed.binary_search(r).is_err())
            .collect();
        let mut local = vec![usize::MAX; j.ncols()];
        let sub = restrict(j, &kept, &p.columns, &mut local)?;
        let gp: Vec<f64> = kept.iter().map(|r| g[*r]).collect();
        let t = self.test;
        let verdict = run(
            t.kernel,
            &sub,
            &gp,
            t.threshold,
            t.scale,
            residual_tolerance,
        );
        Ok(verdict.rank < p.rank)
    }
}

/// Power iterations for σ_max at most.
const POWER_STEPS: usize = 500;

/// σ_max(J) by power iteration on JᵀJ from a fixed random start: ‖J·x‖ for the unit iterate x
/// (never above σ_max), stopped when it settles to 10⁻¹⁴.
pub(crate) fn largest_singular_value(j: &SparseMatrix) -> f64 {
    let (m, n) = (j.nrows(), j.ncols());
    if m == 0 || n == 0 || j.nnz() == 0 {
        return 0.0;
    }
    let mut x = DVector::from_vec(random_draws(3, n));
    x /= x.norm();
    let mut y = vec![0.0; m];
    let mut estimate = 0.0_f64;
    for _ in 0..POWER_STEPS {
        // y = J·x, z = Jᵀ·y.
        for (i, yi) in y.iter_mut().enumerate() {
            let (cols, vals) = j.row(i);
            *yi = cols.iter().zip(vals).map(|(c, v)| v * x[*c]).sum();
        }
        let now = y.iter().map(|v| v * v).sum::<f64>().sqrt();
        let settled = (now - estimate).abs() <= 1e-14 * now;
        estimate = estimate.max(now);
        let mut z: DVector<f64> = DVector::zeros(n);
        for (i, yi) in y.iter().enumerate() {
            let (cols, vals) = j.row(i);
            for (c, v) in cols.iter().zip(vals) {
                z[*c] += v * yi;
            }
        }
        let norm = z.norm();
        if settled || norm == 0.0 {
            break;
        }
        x = z / norm;
    }
    estimate
}

/// The rows `rows` of J restricted to the columns `columns` (renumbered in that order), with
/// `local` a scratch map of J's columns, all `usize::MAX` on entry and on exit. J itself when
/// they are all its rows and columns (a component that is one block).
pub(crate) fn restrict<'a>(
    j: &'a SparseMatrix,
    rows: &[usize],
    columns: &[usize],
    local: &mut [usize],
) -> Result<Cow<'a, SparseMatrix>> {
    if rows.len() == j.nrows() && columns.len() == j.ncols() {
        return Ok(Cow::Borrowed(j));
    }
    for (k, c) in columns.iter().enumerate() {
        local[*c] = k;
    }
    let mut triplets = Vec::new();
    for (k, r) in rows.iter().enumerate() {
        let (cols, vals) = j.row(*r);
        for (c, v) in cols.iter().zip(vals) {
            if local[*c] != usize::MAX {
                triplets.push((k, local[*c], *v));
            }
        }
    }
    for c in columns {
        local[*c] = usize::MAX;
    }
    SparseMatrix::try_from_triplets(rows.len(), columns.len(), &triplets).map(Cow::Owned)
}

/// Runs `kernel` on a restricted matrix with the whole component's threshold.
pub(crate) fn run(
    kernel: Kernel,
    j: &SparseMatrix,
    g: &[f64],
    threshold: f64,
    scale: f64,
    residual_tolerance: f64,
) -> KernelRows {
    match kernel {
        Kernel::Dense => dense_rows(&j.to_dense(), g, threshold, residual_tolerance),
        Kernel::Sparse => sparse_rows(j, g, threshold, scale, residual_tolerance),
    }
}

/// The row verdicts of J against g found block by block (see the module documentation), with
/// the free columns when `free_columns` is set (else left empty).
///
/// # Errors
/// [`crate::Error::Dimension`] when `g` does not have one entry per row; factorization errors
/// of the free-column projection.
pub(crate) fn analyze_blocks(
    j: &SparseMatrix,
    g: &[f64],
    rank_tolerance: f64,
    residual_tolerance: f64,
    kernel: Kernel,
    free_columns: bool,
) -> Result<BlockAnalysis> {
    let (m, n) = (j.nrows(), j.ncols());
    check_len("residual rows", m, g.len())?;
    let scale = match kernel {
        Kernel::Dense => largest_singular_value(j),
        Kernel::Sparse => largest_row_norm(j),
    };
    let threshold = rank_tolerance * scale;
    let structure = Decomposition::of(j);
    let blocks = &structure.blocks;
    let mut local = vec![usize::MAX; n];

    // Clear or coupled, first to last.
    let mut coupled = vec![false; blocks.len()];
    // Whether a block's rows have full column rank on its own columns, where a test showed it.
    let mut full_rank: Vec<Option<bool>> = vec![None; blocks.len()];
    // The verdicts of a failed diagonal test: those of its piece when the block is one alone.
    let mut failed: Vec<Option<KernelRows>> = vec![None; blocks.len()];
    for (id, b) in blocks.iter().enumerate() {
        if b.part == Part::OverDetermined {
            coupled[id] = true;
        }
        if !coupled[id] && !b.rows.is_empty() {
            let diagonal = restrict(j, &b.rows, &b.columns, &mut local)?;
            let gb: Vec<f64> = b.rows.iter().map(|r| g[*r]).collect();
            let verdict = run(kernel, &diagonal, &gb, threshold, scale, residual_tolerance);
            coupled[id] = !verdict.dependent.is_empty();
            full_rank[id] = Some(verdict.independent.len() == b.columns.len());
            if coupled[id] {
                failed[id] = Some(verdict);
            }
        }
        if coupled[id] {
            for r in &b.rows {
                for c in j.row(*r).0 {
                    coupled[structure.column_block[*c]] = true;
                }
            }
        }
    }

    // Coupled blocks joined into pieces by the columns their rows read (union–find).
    let mut parent: Vec<usize> = (0..blocks.len()).collect();
    for (id, b) in blocks.iter().enumerate() {
        if !coupled[id] {
            continue;
        }
        for r in &b.rows {
            for c in j.row(*r).0 {
                let (x, y) = (
                    free::root(&mut parent, id),
                    free::root(&mut parent, structure.column_block[*c]),
                );
                parent[x] = y;
            }
        }
    }
    let mut piece_of_root = vec![usize::MAX; blocks.len()];
    let mut pieces: Vec<Piece> = Vec::new();
    // The blocks of each piece: how many, and the first.
    let mut members: Vec<(usize, usize)> = Vec::new();
    for (id, b) in blocks.iter().enumerate() {
        if !coupled[id] {
            continue;
        }
        let r = free::root(&mut parent, id);
        if piece_of_root[r] == usize::MAX {
            piece_of_root[r] = pieces.len();
            pieces.push(Piece {
                rows: Vec::new(),
                columns: Vec::new(),
                rank: 0,
            });
            members.push((0, id));
        }
        let k = piece_of_root[r];
        members[k].0 += 1;
        let p = &mut pieces[k];
        p.rows.extend(&b.rows);
        p.columns.extend(&b.columns);
    }

    let mut rank = 0;
    let mut independent: Vec<usize> = Vec::new();
    for (id, b) in blocks.iter().enumerate() {
        if !coupled[id] {
            rank += b.rows.len();
            independent.extend(&b.rows);
        }
    }
    let mut dependent: Vec<DependentRow> = Vec::new();
    for (p, (count, first)) in pieces.iter_mut().zip(&members) {
        p.rows.sort_unstable();
        p.columns.sort_unstable();
        // A piece of one block whose diagonal test failed: the same matrix, already analysed
        // (its rows read only its own columns, else the piece would hold more blocks).
        let verdict = match failed[*first].take() {
            Some(verdict) if *count == 1 => verdict,
            _ => {
                let sub = restrict(j, &p.rows, &p.columns, &mut local)?;
                let gp: Vec<f64> = p.rows.iter().map(|r| g[*r]).collect();
                let verdict = run(kernel, &sub, &gp, threshold, scale, residual_tolerance);
                if *count == 1 {
                    // One block alone (an over-determined one): its own rank test.
                    full_rank[*first] = Some(verdict.independent.len() == p.columns.len());
                }
                verdict
            }
        };
        rank += verdict.rank;
        p.rank = verdict.rank;
        independent.extend(verdict.independent.iter().map(|k| p.rows[*k]));
        dependent.extend(verdict.dependent.into_iter().map(|d| DependentRow {
            row: p.rows[d.row],
            ..d
        }));
    }
    independent.sort_unstable();
    dependent.sort_unstable_by_key(|d| d.row);

    let test = RankTest {
        kernel,
        threshold,
        scale,
    };
    let free = if free_columns {
        free::by_blocks(j, &structure, &full_rank, &test)?
    } else {
        FreeColumns::default()
    };
    Ok(BlockAnalysis {
        rows: RowAnalysis {
            rank,
            scale,
            independent,
            dependent,
            free_columns: free.columns.clone(),
        },
        structure,
        pieces,
        free,
        test,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::free_columns::svd_free_columns;
    use crate::analysis::{analyze_rows, analyze_rows_sparse};
    use proptest::prelude::*;

    /// Sparse rows (one to three small integers), integer combinations of one or two earlier
    /// rows, copies and empty rows, with g = J·z for a point z except where one row is shifted
    /// (inconsistent).
    fn sparse_system() -> impl Strategy<Value = (SparseMatrix, Vec<f64>)> {
        (1usize..14, 1usize..12, any::<u64>()).prop_map(|(m, n, seed)| {
            let mut state = seed | 1;
            let mut next = move |k: u64| {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                state % k
            };
            let mut rows: Vec<Vec<f64>> = Vec::new();
            for i in 0..m {
                let mut row = vec![0.0; n];
                match next(12) {
                    0..=6 => {
                        for _ in 0..=next(3) {
                            let c = next(n as u64) as usize;
                            row[c] = next(7) as f64 - 3.0;
                        }
                    }
                    7..=9 if i > 0 => {
                        for _ in 0..=next(2) {
                            let k = next(i as u64) as usize;
                            let a = [-2.0, -1.0, 1.0, 2.0][next(4) as usize];
                            for (x, y) in row.iter_mut().zip(&rows[k]) {
                                *x += a * y;
                            }
                        }
                    }
                    10 if i > 0 => row.clone_from(&rows[next(i as u64) as usize]),
                    _ => {}
                }
                rows.push(row);
            }
            let z: Vec<f64> = (0..n).map(|_| (next(9) as f64 - 4.0) * 0.25).collect();
            let mut g: Vec<f64> = rows
                .iter()
                .map(|r| r.iter().zip(&z).map(|(a, b)| a * b).sum())
                .collect();
            let broken = next(m as u64 + 2) as usize;
            if broken < m {
                g[broken] += 0.5;
            }
            let t: Vec<(usize, usize, f64)> = rows
                .iter()
                .enumerate()
                .flat_map(|(i, r)| r.iter().enumerate().map(move |(c, v)| (i, c, *v)))
                .collect();
            let j = SparseMatrix::try_from_triplets(m, n, &t).unwrap_or_else(|_| unreachable!());
            (j, g)
        })
    }

    fn verdicts(a: &RowAnalysis) -> Vec<(usize, bool)> {
        a.dependent.iter().map(|d| (d.row, d.consistent)).collect()
    }

    /// Same rank, independent rows and verdicts, and free columns.
    fn assert_same_verdicts(
        a: &RowAnalysis,
        b: &RowAnalysis,
    ) -> std::result::Result<(), TestCaseError> {
        prop_assert_eq!(a.rank, b.rank);
        prop_assert_eq!(&a.independent, &b.independent);
        prop_assert_eq!(verdicts(a), verdicts(b));
        prop_assert_eq!(&a.free_columns, &b.free_columns);
        Ok(())
    }

    fn same_mismatches(a: &RowAnalysis, b: &RowAnalysis) -> bool {
        a.dependent
            .iter()
            .zip(&b.dependent)
            .all(|(x, y)| (x.mismatch - y.mismatch).abs() <= 1e-9 * (1.0 + y.mismatch))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(512))]
        /// Block by block, the dense kernel gives what it gives on the whole matrix (its SVD
        /// rank, Gram–Schmidt rows and mismatches, free columns), and so does the sparse
        /// kernel, block by block and on the whole matrix (see
        /// `the_whole_givens_no_longer_misses_a_conflict`); the free columns are the SVD's.
        #[test]
        fn block_wise_agrees_with_whole((j, g) in sparse_system()) {
            let dense = analyze_rows(&j.to_dense(), &g, 1e-10, 1e-9).unwrap_or_else(|_| unreachable!());
            // The free columns (by blocks and whole) are also those of the SVD's null space.
            prop_assert_eq!(&dense.free_columns, &svd_free_columns(&j.to_dense()));
            let blocks = analyze_blocks(&j, &g, 1e-10, 1e-9, Kernel::Dense, true).unwrap_or_else(|_| unreachable!());
            assert_same_verdicts(&blocks.rows, &dense)?;
            prop_assert!(same_mismatches(&blocks.rows, &dense));
            // The power iteration's σ_max is never above the SVD's and close below it.
            prop_assert!(blocks.rows.scale <= dense.scale * (1.0 + 1e-12));
            prop_assert!(blocks.rows.scale >= 0.99 * dense.scale);

            let sparse = analyze_blocks(&j, &g, 1e-10, 1e-9, Kernel::Sparse, true).unwrap_or_else(|_| unreachable!());
            assert_same_verdicts(&sparse.rows, &dense)?;
            let whole = analyze_rows_sparse(&j, &g, 1e-10, 1e-9).unwrap_or_else(|_| unreachable!());
            assert_same_verdicts(&whole, &dense)?;
            prop_assert!(same_mismatches(&sparse.rows, &whole));
            prop_assert!((sparse.rows.scale - whole.scale).abs() <= 0.0);
        }
    }

    #[test]
    fn the_whole_givens_no_longer_misses_a_conflict() {
        // Found by the property test. Rows 8–10 on x₄, x₅, x₁₀ are dependent (row 10 =
        // −⅔·row 9 + ⅚·row 8) and inconsistent; rotated against the whole matrix, row 10 kept
        // a leading entry of rounding size and was accepted with it as its pivot (rank 7, the
        // conflict missed). A leading entry within the rank tolerance is now passed over.
        let rows: [&[(usize, f64)]; 11] = [
            &[],
            &[],
            &[],
            &[(3, 1.0)],
            &[(3, 1.0)],
            &[(1, -1.0), (9, -3.0)],
            &[(4, -1.0), (6, -3.0)],
            &[(2, 3.0), (9, -3.0), (10, 1.0)],
            &[(10, -2.0)],
            &[(4, -3.0), (5, -3.0), (10, 2.0)],
            &[(4, 2.0), (5, 2.0), (10, -3.0)],
        ];
        let t: Vec<(usize, usize, f64)> = rows
            .iter()
            .enumerate()
            .flat_map(|(i, r)| r.iter().map(move |(c, v)| (i, *c, *v)))
            .collect();
        let j = SparseMatrix::try_from_triplets(11, 11, &t).unwrap_or_else(|_| unreachable!());
        let g = [0., 0., 0., 0., 0., 1.5, 1.75, 2.75, 2.0, -4.25, 5.0];
        let dense = analyze_rows(&j.to_dense(), &g, 1e-10, 1e-9).unwrap_or_else(|_| unreachable!());
        let want = vec![(0, true), (1, true), (2, true), (4, true), (10, false)];
        assert_eq!((dense.rank, verdicts(&dense)), (6, want.clone()));
        for kernel in [Kernel::Dense, Kernel::Sparse] {
            let a = analyze_blocks(&j, &g, 1e-10, 1e-9, kernel, true)
                .unwrap_or_else(|_| unreachable!());
            assert_eq!((a.rows.rank, verdicts(&a.rows)), (6, want.clone()));
        }
        let whole = analyze_rows_sparse(&j, &g, 1e-10, 1e-9).unwrap_or_else(|_| unreachable!());
        assert_eq!((whole.rank, verdicts(&whole)), (6, want));
    }

    #[test]
    fn a_deficient_square_block_couples_what_it_reads() {
        // Rows 0–1: x₀ + x₁ + x₂ = 3 and 2x₀ + 2x₁ = 4 on a structurally square block {x₀, x₁}
        // (with x₂ read by row 0); rows 2–3: x₂ + x₃ = 2, x₃ = 1 (square, nonsingular);
        // row 4: x₄ = 7 alone. The {x₀, x₁} block is singular in value, so its rows and the
        // block of x₂, x₃ are analysed together; x₄ is clear.
        let j = SparseMatrix::try_from_triplets(
            5,
            5,
            &[
                (0, 0, 1.0),
                (0, 1, 1.0),
                (0, 2, 1.0),
                (1, 0, 2.0),
                (1, 1, 2.0),
                (2, 2, 1.0),
                (2, 3, 1.0),
                (3, 3, 1.0),
                (4, 4, 1.0),
            ],
        )
        .unwrap_or_else(|_| unreachable!());
        // At z = 0 with x = (1, 1, 1, 1, 7): consistent, g = −b.
        let g = [-3.0, -4.0, -2.0, -1.0, -7.0];
        let a = analyze_blocks(&j, &g, 1e-10, 1e-9, Kernel::Sparse, true)
            .unwrap_or_else(|_| unreachable!());
        assert_eq!(a.structure.matching.size(), 5);
        assert_eq!(a.pieces.len(), 1);
        assert_eq!(a.pieces[0].rows, vec![0, 1, 2, 3]);
        // Row 3 = row 2 − row 0 + ½·row 1 (and −1 = −2 + 3 − 2): though its own block is
        // nonsingular, row 3 is a consistent dependent row, which only the coupling shows.
        assert_eq!(a.rows.rank, 4);
        assert_eq!(verdicts(&a.rows), vec![(3, true)]);
        let whole = analyze_rows_sparse(&j, &g, 1e-10, 1e-9).unwrap_or_else(|_| unreachable!());
        assert_eq!(a.rows.rank, whole.rank);
        assert_eq!(a.rows.free_columns, whole.free_columns);
    }

    #[test]
    fn a_chain_with_a_repeated_row_couples_only_the_repeat() {
        // x₀ = 0, x_{i+1} − x_i = 1 for 50,000 unknowns, and x₀ = 0 again at the end: the
        // chain is square and clear; only the two rows on x₀ form a coupled piece.
        let n = 50_000;
        let mut t = vec![(0, 0, 1.0)];
        let mut g = vec![0.0];
        for i in 1..n {
            t.push((i, i - 1, -1.0));
            t.push((i, i, 1.0));
            g.push(-1.0);
        }
        t.push((n, 0, 1.0));
        g.push(0.0);
        let j = SparseMatrix::try_from_triplets(n + 1, n, &t).unwrap_or_else(|_| unreachable!());
        let a = analyze_blocks(&j, &g, 1e-10, 1e-9, Kernel::Sparse, false)
            .unwrap_or_else(|_| unreachable!());
        assert_eq!(a.rows.rank, n);
        assert_eq!(
            a.pieces,
            vec![Piece {
                rows: vec![0, n],
                columns: vec![0],
                rank: 1,
            }]
        );
        assert_eq!(verdicts(&a.rows), vec![(n, true)]);
    }

    #[test]
    fn the_largest_singular_value_matches_the_svd() {
        let j = SparseMatrix::try_from_triplets(
            3,
            3,
            &[
                (0, 0, 3.0),
                (0, 1, 1.0),
                (1, 1, 2.0),
                (2, 0, -1.0),
                (2, 2, 0.5),
            ],
        )
        .unwrap_or_else(|_| unreachable!());
        let svd = j.to_dense().singular_values().max();
        assert!((largest_singular_value(&j) - svd).abs() <= 1e-9 * svd);
        let zero = SparseMatrix::try_from_triplets(2, 2, &[]).unwrap_or_else(|_| unreachable!());
        assert!(largest_singular_value(&zero).abs() < f64::MIN_POSITIVE);
    }
}
