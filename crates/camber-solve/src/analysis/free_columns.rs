//! The free unknowns of a component found block by block: the structure settles which unknowns
//! are determined, and the null-space projection runs only on the others.
//!
//! An unknown (a column of J) is *free* when some null vector of J is non-zero there, and
//! *determined* when every null vector is zero there. The whole-matrix method draws random
//! vectors v and projects them onto the null space of J; the free columns are where a
//! projection is not negligible. This module gets the same projections without factoring J.
//!
//! Take the blocks of J's Dulmage–Mendelsohn form ([`crate::analysis::structure`]) in block
//! upper-triangular order: the rows of a block read its own columns and those of later blocks
//! only; an over-determined block's rows read its own columns only. Going **last to first**, call
//! a block *determined* when
//!
//! - it is square (well-determined), its diagonal block J[R_k, C_k] (its rows on its own
//!   columns) has full rank, and every column outside C_k that its rows read lies in a
//!   determined block (a later one, so already decided); or
//! - it is over-determined and J[R_k, C_k] has full column rank.
//!
//! An under-determined block is never determined: it has more columns than rows. Let D be the
//! columns of the determined blocks, U (the *candidates*) the others, and R_U the rows of the
//! blocks that are not determined.
//!
//! **Claim 1: every null vector x of J is zero on D.** By induction from the last block to the
//! first. For a determined block k, the rows R_k of J·x = 0 read: C_k, and columns of later
//! determined blocks, where x is zero by induction (an over-determined block reads nothing
//! else). So J[R_k, C_k]·x_{C_k} = 0, and full column rank (a square block of full rank has it)
//! gives x_{C_k} = 0.
//!
//! **Claim 2: null(J) = {x : x_D = 0 and J[R_U, U]·x_U = 0}.** The rows of a determined block
//! read only columns of D (its own and, by the definition, determined ones). "⊆": by Claim 1
//! x_D = 0, and the rows R_U of J·x = 0 are then J[R_U, U]·x_U = 0. "⊇": with x_D = 0 the rows of
//! determined blocks vanish and the rows R_U give J[R_U, U]·x_U = 0.
//!
//! So the orthogonal projection of v onto null(J) is zero on D and, on U, the projection of v_U
//! onto null(J[R_U, U]). Joining the blocks of U whose rows read each other's columns splits
//! J[R_U, U] into *pieces* that share no row and no column; its null space is the orthogonal
//! sum of theirs, and each piece projects its part of v alone, with the dense kernel (Gram–
//! Schmidt) when it has at most [`crate::analysis::DENSE_ANALYSIS_MAX_ENTRIES`] entries, the
//! sparse one (Givens row selection, sparse Cholesky of J_A·J_Aᵀ) above. The vectors v are the
//! whole-matrix method's draws restricted to U, so the projections, and the free columns, are
//! the same up to rounding. A sketch whose blocks are all determined (fully constrained) has no
//! candidates and no projection at all.
//!
//! Each piece picks its independent rows again: J's independent rows restricted to U need not be
//! independent there (two rows that differ only on determined columns; a row dependent in J only
//! through a determined block's rows), and a dependent row adds no condition to the null space.
//! Rank decisions use the kernel and the threshold of the whole component's row verdicts, so a
//! result could differ from the whole-matrix projection only for a singular value at the
//! threshold.

use crate::analysis::blocks::{restrict, run, Kernel};
use crate::analysis::structure::{Decomposition, Part};
use crate::analysis::{
    dense_null_projection, free_columns_of, kernel_for, random_draws, sparse_null_projection,
};
use crate::linalg::sparse::SparseMatrix;
use crate::model::errors::Result;

/// The free columns and what the projection ran on.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub(crate) struct FreeColumns {
    /// The free columns, increasing.
    pub columns: Vec<usize>,
    /// Columns the projection ran on (the candidates); the others are determined.
    pub candidates: usize,
    /// Columns of the largest piece projected.
    pub largest_piece: usize,
}

/// The rank tests of the determination pass: the component's kernel and threshold.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RankTest {
    /// The kernel of the component's row verdicts.
    pub kernel: Kernel,
    /// The rank threshold (rank tolerance × scale).
    pub threshold: f64,
    /// The kernel's scale.
    pub scale: f64,
}

/// Union–find root with path halving.
pub(crate) fn root(parent: &mut [usize], mut a: usize) -> usize {
    while parent[a] != a {
        parent[a] = parent[parent[a]];
        a = parent[a];
    }
    a
}

/// The free columns of J (see the module documentation). `full_rank[b]`, when known, says
/// whether block b's rows have full column rank on its own columns (the row pass found it);
/// the unknown ones are tested here when the answer matters.
///
/// # Errors
/// Factorization errors of the projections.
pub(crate) fn by_blocks(
    j: &SparseMatrix,
    structure: &Decomposition,
    full_rank: &[Option<bool>],
    test: &RankTest,
) -> Result<FreeColumns> {
    let n = j.ncols();
    let blocks = &structure.blocks;
    let mut local = vec![usize::MAX; n];

    // Determined blocks, last to first.
    let mut determined = vec![false; blocks.len()];
    for id in (0..blocks.len()).rev() {
        let b = &blocks[id];
        let reads_only_determined = || {
            b.rows.iter().all(|r| {
                j.row(*r).0.iter().all(|c| {
                    let k = structure.column_block[*c];
                    k == id || determined[k]
                })
            })
        };
        determined[id] = match b.part {
            Part::UnderDetermined => false,
            Part::WellDetermined if !reads_only_determined() => false,
            Part::WellDetermined | Part::OverDetermined => match full_rank[id] {
                Some(known) => known,
                None => {
                    let own = restrict(j, &b.rows, &b.columns, &mut local)?;
                    let zeros = vec![0.0; b.rows.len()];
                    let verdict = run(
                        test.kernel,
                        &own,
                        &zeros,
                        test.threshold,
                        test.scale,
                        f64::INFINITY,
                    );
                    verdict.independent.len() == b.columns.len()
                }
            },
        };
    }

    // The candidate blocks joined into pieces by the columns their rows read.
    let mut parent: Vec<usize> = (0..blocks.len()).collect();
    for (id, b) in blocks.iter().enumerate() {
        if determined[id] {
            continue;
        }
        for r in &b.rows {
            for c in j.row(*r).0 {
                let k = structure.column_block[*c];
                if !determined[k] {
                    let (x, y) = (root(&mut parent, id), root(&mut parent, k));
                    parent[x] = y;
                }
            }
        }
    }
    let mut piece_of_root = vec![usize::MAX; blocks.len()];
    let mut pieces: Vec<(Vec<usize>, Vec<usize>)> = Vec::new();
    for (id, b) in blocks.iter().enumerate() {
        if determined[id] {
            continue;
        }
        let r = root(&mut parent, id);
        if piece_of_root[r] == usize::MAX {
            piece_of_root[r] = pieces.len();
            pieces.push((Vec::new(), Vec::new()));
        }
        let (rows, columns) = &mut pieces[piece_of_root[r]];
        rows.extend(&b.rows);
        columns.extend(&b.columns);
    }
    if pieces.is_empty() {
        return Ok(FreeColumns::default());
    }

    // The whole-matrix draws, projected piece by piece (zero on the determined columns).
    let draws = [random_draws(1, n), random_draws(2, n)];
    let mut vectors = vec![vec![0.0; n]; draws.len()];
    let mut out = FreeColumns::default();
    for (rows, columns) in &mut pieces {
        rows.sort_unstable();
        columns.sort_unstable();
        out.candidates += columns.len();
        out.largest_piece = out.largest_piece.max(columns.len());
        let mut parts: Vec<Vec<f64>> = draws
            .iter()
            .map(|d| columns.iter().map(|c| d[*c]).collect())
            .collect();
        if !rows.is_empty() {
            let s = restrict(j, rows, columns, &mut local)?;
            match kernel_for(rows.len().saturating_mul(columns.len())) {
                Kernel::Dense => dense_null_projection(&s.to_dense(), test.threshold, &mut parts),
                Kernel::Sparse => {
                    sparse_null_projection(&s, test.threshold, test.scale, &mut parts)?;
                }
            }
        }
        for (v, part) in vectors.iter_mut().zip(&parts) {
            for (c, x) in columns.iter().zip(part) {
                v[*c] = *x;
            }
        }
    }
    out.columns = free_columns_of(&vectors, n);
    Ok(out)
}

/// The tests' reference, independent of any projection: column c is free when the null space
/// of J found by the SVD (singular values at most 10⁻¹⁰·σ_max, and the directions beyond the
/// rows) has a basis row of norm above 10⁻⁶ there.
#[cfg(test)]
pub(crate) fn svd_free_columns(j: &nalgebra::DMatrix<f64>) -> Vec<usize> {
    let (m, n) = j.shape();
    // Padded with zero rows to at least n × n, so that Vᵀ is n × n.
    let mut a = nalgebra::DMatrix::<f64>::zeros(m.max(n), n);
    a.rows_mut(0, m).copy_from(j);
    let svd = a.svd(false, true);
    let Some(vt) = svd.v_t else { unreachable!() };
    let top = svd.singular_values.iter().copied().fold(0.0, f64::max);
    let null: Vec<usize> = (0..n)
        .filter(|k| svd.singular_values[*k] <= 1e-10 * top)
        .collect();
    (0..n)
        .filter(|c| null.iter().map(|k| vt[(*k, *c)].powi(2)).sum::<f64>() > 1e-12)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::blocks::{analyze_blocks, BlockAnalysis};
    use crate::analysis::{analyze_rows, analyze_rows_sparse};
    use proptest::prelude::*;

    fn matrix(m: usize, n: usize, entries: &[(usize, usize, f64)]) -> SparseMatrix {
        SparseMatrix::try_from_triplets(m, n, entries).unwrap_or_else(|_| unreachable!())
    }

    fn blocks(j: &SparseMatrix, kernel: Kernel) -> BlockAnalysis {
        let g = vec![0.0; j.nrows()];
        analyze_blocks(j, &g, 1e-10, 1e-9, kernel, true).unwrap_or_else(|_| unreachable!())
    }

    /// The free columns of `j` by blocks (both kernels), by the whole-matrix projections and by
    /// the SVD: all the same, and returned.
    fn agreed(j: &SparseMatrix) -> Vec<usize> {
        let dense = j.to_dense();
        let g = vec![0.0; j.nrows()];
        let whole = analyze_rows(&dense, &g, 1e-10, 1e-9).unwrap_or_else(|_| unreachable!());
        let sparse = analyze_rows_sparse(j, &g, 1e-10, 1e-9).unwrap_or_else(|_| unreachable!());
        let reference = svd_free_columns(&dense);
        assert_eq!(whole.free_columns, reference);
        assert_eq!(sparse.free_columns, reference);
        for kernel in [Kernel::Dense, Kernel::Sparse] {
            assert_eq!(blocks(j, kernel).rows.free_columns, reference, "{kernel:?}");
        }
        reference
    }

    #[test]
    fn a_determined_block_feeding_an_under_determined_part_is_not_projected() {
        // u₀ + u₁ + d₀ = 0 (under-determined), d₀ − d₁ = 0, d₁ = 0 (two square blocks of full
        // rank): d₀, d₁ determined, and only u₀, u₁ are projected.
        let j = matrix(
            3,
            4,
            &[
                (0, 0, 1.0),
                (0, 1, 1.0),
                (0, 2, 1.0),
                (1, 2, 1.0),
                (1, 3, -1.0),
                (2, 3, 1.0),
            ],
        );
        assert_eq!(agreed(&j), vec![0, 1]);
        let a = blocks(&j, Kernel::Sparse);
        assert_eq!((a.free.candidates, a.free.largest_piece), (2, 2));
    }

    #[test]
    fn a_singular_block_frees_the_block_that_reads_it() {
        // x₀ + x₁ = 0 (a block of its own, reading x₁); x₁ + x₂ = 0 and 2x₁ + 2x₂ = 0 (a square
        // block singular in value); x₃ = 0. The null vector (−1, 1, −1, 0): x₀..x₂ free.
        let j = matrix(
            4,
            4,
            &[
                (0, 0, 1.0),
                (0, 1, 1.0),
                (1, 1, 1.0),
                (1, 2, 1.0),
                (2, 1, 2.0),
                (2, 2, 2.0),
                (3, 3, 1.0),
            ],
        );
        assert_eq!(agreed(&j), vec![0, 1, 2]);
        assert_eq!(blocks(&j, Kernel::Dense).free.candidates, 3);
    }

    #[test]
    fn a_candidate_the_projection_finds_determined() {
        // x₀ + x₁ + x₂ = 0 reads the singular block {x₁ + x₂ = 0, 2x₁ + 2x₂ = 0}, so x₀ is a
        // candidate; but x₀ = −(x₁ + x₂) = 0 in every null vector.
        let j = matrix(
            3,
            3,
            &[
                (0, 0, 1.0),
                (0, 1, 1.0),
                (0, 2, 1.0),
                (1, 1, 1.0),
                (1, 2, 1.0),
                (2, 1, 2.0),
                (2, 2, 2.0),
            ],
        );
        assert_eq!(agreed(&j), vec![1, 2]);
        assert_eq!(blocks(&j, Kernel::Sparse).free.candidates, 3);
    }

    #[test]
    fn over_determined_blocks_by_their_column_rank() {
        // x₀ = 0, x₀ + x₁ = 0, x₁ = 0: three rows of full column rank on two unknowns.
        let full = matrix(3, 2, &[(0, 0, 1.0), (1, 0, 1.0), (1, 1, 1.0), (2, 1, 1.0)]);
        assert!(agreed(&full).is_empty());
        assert_eq!(blocks(&full, Kernel::Dense).free.candidates, 0);
        // x₀ + x₁, 2x₀ + 2x₁, −x₀ − x₁: rank one on two unknowns, both free.
        let deficient = matrix(
            3,
            2,
            &[
                (0, 0, 1.0),
                (0, 1, 1.0),
                (1, 0, 2.0),
                (1, 1, 2.0),
                (2, 0, -1.0),
                (2, 1, -1.0),
            ],
        );
        assert_eq!(agreed(&deficient), vec![0, 1]);
    }

    #[test]
    fn a_row_dependent_only_through_a_determined_block_is_left_out() {
        // Rows 0–1 on the singular block {x₀, x₁} (row 0 also reads x₂); rows 2–3 on {x₂, x₃}
        // (full rank, determined); x₄ alone. Row 3 is dependent in J (row 2 − row 0 + ½ row 1)
        // and rows 0, 1 are independent there, but on the candidates x₀, x₁ row 1 repeats
        // row 0: the piece picks its own independent rows. Free: x₀, x₁ (x₀ = −x₁).
        let j = matrix(
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
        );
        assert_eq!(agreed(&j), vec![0, 1]);
        assert_eq!(blocks(&j, Kernel::Sparse).free.candidates, 2);
    }

    #[test]
    fn a_fully_constrained_chain_projects_nothing() {
        // x₀ = 0, x_{i+1} − x_i = 0 for 100,000 unknowns: every block is determined.
        let n = 100_000;
        let mut t = vec![(0, 0, 1.0)];
        for i in 1..n {
            t.push((i, i - 1, -1.0));
            t.push((i, i, 1.0));
        }
        let a = blocks(&matrix(n, n, &t), Kernel::Sparse);
        assert!(a.rows.free_columns.is_empty());
        assert_eq!(a.free, FreeColumns::default());
    }

    #[test]
    fn a_large_piece_is_projected_sparsely() {
        // x_{i+1} − x_i + d = 0 for 300 unknowns x (an under-determined chain, 299 × 300 on
        // them: above the dense limit, so the sparse kernel projects it), d = 0 determined by a
        // square block the chain reads; a second copy of the chain's first row (dependent).
        let n = 300;
        let d = n;
        let mut t = Vec::new();
        for i in 0..n - 1 {
            t.extend([(i, i, -1.0), (i, i + 1, 1.0), (i, d, 1.0)]);
        }
        t.extend([(n - 1, d, 1.0), (n, 0, -1.0), (n, 1, 1.0)]);
        let j = matrix(n + 1, n + 1, &t);
        assert!((n - 1) * n > crate::analysis::DENSE_ANALYSIS_MAX_ENTRIES);
        let free = agreed(&j);
        assert_eq!(free, (0..n).collect::<Vec<_>>());
        let a = blocks(&j, Kernel::Sparse);
        assert_eq!((a.free.candidates, a.free.largest_piece), (n, n));
    }

    /// A block upper-triangular system planted block by block, then shuffled: under-determined
    /// blocks first (more columns than rows), square blocks of full rank or singular in value
    /// (a row's own part a combination of two others'), over-determined blocks last (full
    /// column rank or rank one). Rows read later blocks' columns at random (over-determined
    /// rows excepted), so determined blocks feed under-determined parts and singular blocks
    /// free the blocks that read them.
    fn planted_system() -> impl Strategy<Value = SparseMatrix> {
        (1usize..6, any::<u64>()).prop_map(|(count, seed)| {
            let mut state = seed | 1;
            let mut next = move |k: u64| {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                state % k
            };
            // (kind, rows, columns): 0 under, 1 square, 2 singular square, 3 over, 4 over of
            // rank one.
            let mut shapes: Vec<(u64, usize, usize)> = (0..count)
                .map(|_| {
                    let kind = next(5);
                    let r = 1 + next(3) as usize;
                    match kind {
                        0 => (kind, r, r + 1 + next(2) as usize),
                        1 => (kind, r, r),
                        2 => (kind, r + 1, r + 1),
                        _ => (kind, r + 1, r),
                    }
                })
                .collect();
            shapes.sort_by_key(|s| match s.0 {
                0 => 0,
                1 | 2 => 1,
                _ => 2,
            });
            let n: usize = shapes.iter().map(|s| s.2).sum();
            let mut rows: Vec<Vec<f64>> = Vec::new();
            let mut first = 0;
            for &(kind, r, c) in &shapes {
                let own = first..first + c;
                let block_start = rows.len();
                for k in 0..r {
                    let mut row = vec![0.0; n];
                    for x in &mut row[own.clone()] {
                        *x = next(7) as f64 - 3.0;
                    }
                    if kind == 2 && k == r - 1 {
                        let (a, b) = (next(3) as f64 - 1.0, 1.0 + next(2) as f64);
                        for col in own.clone() {
                            row[col] = if r > 2 {
                                a * rows[block_start][col] + b * rows[block_start + 1][col]
                            } else {
                                b * rows[block_start][col]
                            };
                        }
                    }
                    if kind == 4 && k > 0 {
                        let a = next(5) as f64 - 2.0;
                        for col in own.clone() {
                            row[col] = a * rows[block_start][col];
                        }
                    }
                    if kind < 3 {
                        for x in &mut row[first + c..] {
                            if next(5) == 0 {
                                *x = next(5) as f64 - 2.0;
                            }
                        }
                    }
                    rows.push(row);
                }
                first += c;
            }
            // Shuffled rows and columns.
            let m = rows.len();
            let mut row_order: Vec<usize> = (0..m).collect();
            let mut col_order: Vec<usize> = (0..n).collect();
            for k in (1..m).rev() {
                row_order.swap(k, next(k as u64 + 1) as usize);
            }
            for k in (1..n).rev() {
                col_order.swap(k, next(k as u64 + 1) as usize);
            }
            let t: Vec<(usize, usize, f64)> = rows
                .iter()
                .enumerate()
                .flat_map(|(i, row)| {
                    let (ro, co) = (&row_order, &col_order);
                    row.iter().enumerate().map(move |(c, v)| (ro[i], co[c], *v))
                })
                .collect();
            matrix(m, n, &t)
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(512))]
        /// The free columns by blocks (dense and sparse kernels) are the whole-matrix
        /// projection's and the SVD's.
        #[test]
        fn block_wise_free_columns_agree_with_the_svd(j in planted_system()) {
            let dense = j.to_dense();
            let g = vec![0.0; j.nrows()];
            let reference = svd_free_columns(&dense);
            let whole = analyze_rows(&dense, &g, 1e-10, 1e-9).unwrap_or_else(|_| unreachable!());
            prop_assert_eq!(&whole.free_columns, &reference);
            for kernel in [Kernel::Dense, Kernel::Sparse] {
                let a = blocks(&j, kernel);
                prop_assert_eq!(&a.rows.free_columns, &reference);
                prop_assert!(a.free.candidates >= reference.len());
                prop_assert_eq!(a.rows.rank, whole.rank);
            }
        }
    }
}
