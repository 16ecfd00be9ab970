//! Maximum matching of rows to unknowns on a sparsity pattern (Hopcroft–Karp).
//!
//! A matching pairs rows with columns through nonzero entries, each row and each column at most
//! once. Its size is the *structural rank* of the pattern: the largest rank any matrix with
//! these nonzeros can have. Hopcroft–Karp grows a greedy matching in phases: a breadth-first
//! search from the unmatched rows layers the graph by alternating paths (any edge from a row, the
//! matched edge back from a column), then depth-first searches along the layers flip a maximal
//! set of disjoint shortest augmenting paths. No augmenting path left means the matching is
//! maximum (Berge). Both searches are iterative, so a chain of a million rows does not recurse.

use crate::linalg::sparse::SparseMatrix;

/// A matching of rows to columns.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Matching {
    /// The column matched to each row.
    pub row_to_column: Vec<Option<usize>>,
    /// The row matched to each column.
    pub column_to_row: Vec<Option<usize>>,
}

impl Matching {
    /// Number of matched pairs: the structural rank.
    pub fn size(&self) -> usize {
        self.row_to_column.iter().flatten().count()
    }
}

/// A maximum matching of the rows of `pattern` to its columns through its stored entries (an
/// explicit zero counts as an entry).
///
/// ```
/// use camber_solve::{structure::maximum_matching, SparseMatrix};
/// // Row 0 reads x₀ and x₁, row 1 only x₀: the greedy pair (0, x₀) must give way.
/// let j = SparseMatrix::try_from_triplets(2, 2, &[(0, 0, 1.0), (0, 1, 1.0), (1, 0, 1.0)])?;
/// let m = maximum_matching(&j);
/// assert_eq!(m.size(), 2);
/// assert_eq!(m.row_to_column, vec![Some(1), Some(0)]);
/// # Ok::<(), camber_solve::Error>(())
/// ```
pub fn maximum_matching(pattern: &SparseMatrix) -> Matching {
    let (row_ptr, cols, _) = pattern.raw();
    let (m, n) = (pattern.nrows(), pattern.ncols());
    let adjacent = |r: usize| &cols[row_ptr[r]..row_ptr[r + 1]];
    let mut row_to_column: Vec<Option<usize>> = vec![None; m];
    let mut column_to_row: Vec<Option<usize>> = vec![None; n];
    // A greedy start: most rows of a sketch match at once.
    for (r, slot) in row_to_column.iter_mut().enumerate() {
        if let Some(&c) = adjacent(r).iter().find(|c| column_to_row[**c].is_none()) {
            *slot = Some(c);
            column_to_row[c] = Some(r);
        }
    }
    let unreached = usize::MAX;
    let mut layer = vec![unreached; m];
    let mut queue = Vec::with_capacity(m);
    let mut next_edge = vec![0_usize; m];
    let mut stack: Vec<usize> = Vec::new();
    let mut via: Vec<usize> = Vec::new();
    loop {
        // Layers of alternating paths from the unmatched rows.
        queue.clear();
        for r in 0..m {
            if row_to_column[r].is_none() {
                layer[r] = 0;
                queue.push(r);
            } else {
                layer[r] = unreached;
            }
        }
        let mut found = false;
        let mut head = 0;
        while head < queue.len() {
            let r = queue[head];
            head += 1;
            for &c in adjacent(r) {
                match column_to_row[c] {
                    None => found = true,
                    Some(r2) if layer[r2] == unreached => {
                        layer[r2] = layer[r] + 1;
                        queue.push(r2);
                    }
                    Some(_) => {}
                }
            }
        }
        if !found {
            break;
        }
        // Disjoint augmenting paths along the layers.
        for (r, e) in next_edge.iter_mut().enumerate() {
            *e = row_ptr[r];
        }
        for start in 0..m {
            if row_to_column[start].is_some() {
                continue;
            }
            // `via[k]` is the column from stack[k] to stack[k + 1] (matched to stack[k + 1]).
            stack.clear();
            via.clear();
            stack.push(start);
            while let Some(&r) = stack.last() {
                if next_edge[r] == row_ptr[r + 1] {
                    // A dead end for this phase.
                    layer[r] = unreached;
                    stack.pop();
                    via.pop();
                    continue;
                }
                let c = cols[next_edge[r]];
                next_edge[r] += 1;
                match column_to_row[c] {
                    None => {
                        // Flip the path: the last row takes c, each other row the column
                        // toward the next one.
                        for (row, col) in stack.iter().zip(via.iter().chain([&c])) {
                            row_to_column[*row] = Some(*col);
                            column_to_row[*col] = Some(*row);
                        }
                        // The path is used: its rows leave this phase.
                        for row in &stack {
                            layer[*row] = unreached;
                        }
                        break;
                    }
                    Some(r2) if layer[r2] != unreached && layer[r2] == layer[r] + 1 => {
                        stack.push(r2);
                        via.push(c);
                    }
                    Some(_) => {}
                }
            }
        }
    }
    Matching {
        row_to_column,
        column_to_row,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The largest matching by dynamic programming over the sets of used columns.
    fn brute_force_size(j: &SparseMatrix) -> usize {
        let n = j.ncols();
        let mut best = vec![0_usize; 1 << n];
        for r in (0..j.nrows()).rev() {
            let mut next = best.clone();
            for (mask, slot) in next.iter_mut().enumerate() {
                for &c in j.row(r).0 {
                    if mask & (1 << c) == 0 {
                        *slot = (*slot).max(1 + best[mask | (1 << c)]);
                    }
                }
            }
            best = next;
        }
        best[0]
    }

    fn pattern() -> impl Strategy<Value = SparseMatrix> {
        (0usize..8, 0usize..8, any::<u64>(), 1u64..4).prop_map(|(m, n, seed, density)| {
            let mut state = seed | 1;
            let mut t = Vec::new();
            for r in 0..m {
                for c in 0..n {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    if state % 6 < density {
                        t.push((r, c, 1.0));
                    }
                }
            }
            SparseMatrix::try_from_triplets(m, n, &t).unwrap_or_else(|_| unreachable!())
        })
    }

    proptest! {
        /// The matching pairs entries, each row and column at most once, and no matching is
        /// larger.
        #[test]
        fn the_matching_is_valid_and_maximum(j in pattern()) {
            let m = maximum_matching(&j);
            for (r, c) in m.row_to_column.iter().enumerate() {
                if let Some(c) = c {
                    prop_assert!(j.row(r).0.contains(c));
                    prop_assert_eq!(m.column_to_row[*c], Some(r));
                }
            }
            prop_assert_eq!(m.column_to_row.iter().flatten().count(), m.size());
            prop_assert_eq!(m.size(), brute_force_size(&j));
        }
    }

    #[test]
    fn a_long_chain_needs_one_long_augmenting_path() {
        // Row i reads x_i and x_{i+1}; row n−1 reads only x_0... greedy matches row i to x_i, and
        // a last row reading x_0 alone forces every pair to shift by one: a path of n rows.
        let n = 100_000;
        let mut t: Vec<(usize, usize, f64)> = (0..n - 1)
            .flat_map(|i| [(i, i, 1.0), (i, i + 1, 1.0)])
            .collect();
        t.push((n - 1, 0, 1.0));
        let j = SparseMatrix::try_from_triplets(n, n, &t).unwrap_or_else(|_| unreachable!());
        let m = maximum_matching(&j);
        assert_eq!(m.size(), n);
        assert_eq!(m.row_to_column[n - 1], Some(0));
        assert_eq!(m.row_to_column[0], Some(1));
    }

    #[test]
    fn empty_rows_and_columns_stay_unmatched() {
        let j = SparseMatrix::try_from_triplets(3, 3, &[(1, 2, 1.0)])
            .unwrap_or_else(|_| unreachable!());
        let m = maximum_matching(&j);
        assert_eq!(m.row_to_column, vec![None, Some(2), None]);
        assert_eq!(m.column_to_row, vec![None, None, Some(1)]);
    }
}
