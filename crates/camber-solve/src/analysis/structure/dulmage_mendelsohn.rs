//! The Dulmage–Mendelsohn decomposition of a sparsity pattern: over-, well- and
//! under-determined parts, and the square part split into irreducible blocks.
//!
//! Given a maximum matching (see [`super::matching`]):
//! - the **under-determined** part is everything reachable from an unmatched column by
//!   alternating paths (a column leads to every row that reads it, a row to its matched
//!   column). Its columns are read by no other rows, and it has more columns than rows: these
//!   unknowns are not fixed by the equations whatever their values.
//! - the **over-determined** part is everything reachable from an unmatched row the same way (a
//!   row leads to every column it reads, a column to its matched row). Its rows read no other
//!   columns, and it has more rows than columns: where its rows are independent in value they
//!   contradict each other or repeat each other.
//! - the rest is the **well-determined** part, square and perfectly matched. Ordering it by the
//!   strongly connected components of the graph "row r reads the column matched to row r′"
//!   (Tarjan, iterative) gives its irreducible diagonal blocks: each block's rows read only its
//!   own columns and those of later blocks.
//!
//! The parts do not depend on which maximum matching was found. Listing the blocks as
//! [under-determined components, well-determined blocks in order, over-determined components]
//! puts the matrix in block upper-triangular form: every entry of a row lies in its own block's
//! columns or in a later block's.

use super::matching::{maximum_matching, Matching};
use crate::linalg::sparse::SparseMatrix;

/// The three parts of the coarse decomposition.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
pub enum Part {
    /// More unknowns than rows: free whatever the values.
    UnderDetermined,
    /// Square and structurally nonsingular.
    WellDetermined,
    /// More rows than unknowns: dependent or contradictory rows live here.
    OverDetermined,
}

/// One diagonal block: a connected component of the under- or over-determined part, or an
/// irreducible block of the well-determined part.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Block {
    /// The part it belongs to.
    pub part: Part,
    /// Its rows, increasing.
    pub rows: Vec<usize>,
    /// Its columns, increasing.
    pub columns: Vec<usize>,
}

/// The decomposition of a pattern.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Decomposition {
    /// The maximum matching it was built from.
    pub matching: Matching,
    /// The diagonal blocks in block upper-triangular order (see the module documentation).
    pub blocks: Vec<Block>,
    /// The block of each row.
    pub row_block: Vec<usize>,
    /// The block of each column.
    pub column_block: Vec<usize>,
}

/// Column-wise adjacency (the transpose pattern): `rows[ptr[c]..ptr[c + 1]]` read column c.
fn transpose(pattern: &SparseMatrix) -> (Vec<usize>, Vec<usize>) {
    let (row_ptr, cols, _) = pattern.raw();
    let mut ptr = vec![0_usize; pattern.ncols() + 1];
    for c in cols {
        ptr[c + 1] += 1;
    }
    for c in 0..pattern.ncols() {
        ptr[c + 1] += ptr[c];
    }
    let mut next = ptr.clone();
    let mut rows = vec![0_usize; cols.len()];
    for r in 0..pattern.nrows() {
        for c in &cols[row_ptr[r]..row_ptr[r + 1]] {
            rows[next[*c]] = r;
            next[*c] += 1;
        }
    }
    (ptr, rows)
}

impl Decomposition {
    /// The decomposition of the stored entries of `pattern` (explicit zeros count).
    ///
    /// ```
    /// use camber_solve::{structure::{Decomposition, Part}, SparseMatrix};
    /// // x₀ = a, x₀ = b (over-determined); x₁ + x₂ = c (under-determined); x₃ = d (square).
    /// let j = SparseMatrix::try_from_triplets(4, 4, &[
    ///     (0, 0, 1.0), (1, 0, 1.0), (2, 1, 1.0), (2, 2, 1.0), (3, 3, 1.0)])?;
    /// let d = Decomposition::of(&j);
    /// assert_eq!(d.matching.size(), 3);
    /// assert_eq!(d.rows_in(Part::OverDetermined), vec![0, 1]);
    /// assert_eq!(d.columns_in(Part::UnderDetermined), vec![1, 2]);
    /// assert_eq!(d.rows_in(Part::WellDetermined), vec![3]);
    /// # Ok::<(), camber_solve::Error>(())
    /// ```
    pub fn of(pattern: &SparseMatrix) -> Self {
        let matching = maximum_matching(pattern);
        let (m, n) = (pattern.nrows(), pattern.ncols());
        let (row_ptr, cols, _) = pattern.raw();
        let (col_ptr, col_rows) = transpose(pattern);
        let reads = |r: usize| &cols[row_ptr[r]..row_ptr[r + 1]];
        let read_by = |c: usize| &col_rows[col_ptr[c]..col_ptr[c + 1]];

        let mut row_part = vec![Part::WellDetermined; m];
        let mut column_part = vec![Part::WellDetermined; n];
        // Under-determined: alternating paths from the unmatched columns.
        let mut queue: Vec<usize> = (0..n)
            .filter(|c| matching.column_to_row[*c].is_none())
            .collect();
        for c in &queue {
            column_part[*c] = Part::UnderDetermined;
        }
        while let Some(c) = queue.pop() {
            for &r in read_by(c) {
                if row_part[r] == Part::UnderDetermined {
                    continue;
                }
                row_part[r] = Part::UnderDetermined;
                // A maximum matching matches every row reached from an unmatched column.
                if let Some(c2) = matching.row_to_column[r] {
                    if column_part[c2] != Part::UnderDetermined {
                        column_part[c2] = Part::UnderDetermined;
                        queue.push(c2);
                    }
                }
            }
        }
        // Over-determined: alternating paths from the unmatched rows.
        let mut queue: Vec<usize> = (0..m)
            .filter(|r| matching.row_to_column[*r].is_none())
            .collect();
        for r in &queue {
            row_part[*r] = Part::OverDetermined;
        }
        while let Some(r) = queue.pop() {
            for &c in reads(r) {
                if column_part[c] == Part::OverDetermined {
                    continue;
                }
                column_part[c] = Part::OverDetermined;
                if let Some(r2) = matching.column_to_row[c] {
                    if row_part[r2] != Part::OverDetermined {
                        row_part[r2] = Part::OverDetermined;
                        queue.push(r2);
                    }
                }
            }
        }

        let unassigned = usize::MAX;
        let mut row_block = vec![unassigned; m];
        let mut column_block = vec![unassigned; n];
        let mut blocks = Vec::new();
        // Connected components of the under-determined part (seeded by columns: each of its
        // rows is matched to one of its columns).
        let components = |part: Part,
                          blocks: &mut Vec<Block>,
                          row_block: &mut Vec<usize>,
                          column_block: &mut Vec<usize>| {
            let seeds: Vec<(bool, usize)> = match part {
                Part::UnderDetermined => (0..n)
                    .filter(|c| column_part[*c] == part)
                    .map(|c| (false, c))
                    .collect(),
                _ => (0..m)
                    .filter(|r| row_part[*r] == part)
                    .map(|r| (true, r))
                    .collect(),
            };
            for (is_row, seed) in seeds {
                let taken = if is_row {
                    row_block[seed]
                } else {
                    column_block[seed]
                };
                if taken != unassigned {
                    continue;
                }
                let id = blocks.len();
                let mut block = Block {
                    part,
                    rows: Vec::new(),
                    columns: Vec::new(),
                };
                let mut stack = vec![(is_row, seed)];
                if is_row {
                    row_block[seed] = id;
                } else {
                    column_block[seed] = id;
                }
                while let Some((is_row, k)) = stack.pop() {
                    if is_row {
                        block.rows.push(k);
                        for &c in reads(k) {
                            if column_part[c] == part && column_block[c] == unassigned {
                                column_block[c] = id;
                                stack.push((false, c));
                            }
                        }
                    } else {
                        block.columns.push(k);
                        for &r in read_by(k) {
                            if row_part[r] == part && row_block[r] == unassigned {
                                row_block[r] = id;
                                stack.push((true, r));
                            }
                        }
                    }
                }
                block.rows.sort_unstable();
                block.columns.sort_unstable();
                blocks.push(block);
            }
        };
        components(
            Part::UnderDetermined,
            &mut blocks,
            &mut row_block,
            &mut column_block,
        );
        // The square part: strongly connected components, first to last.
        let sccs = well_determined_blocks(&matching, &row_part, &column_part, reads);
        for rows in sccs.into_iter().rev() {
            let id = blocks.len();
            let mut columns: Vec<usize> = rows
                .iter()
                .filter_map(|r| matching.row_to_column[*r])
                .collect();
            let mut rows = rows;
            rows.sort_unstable();
            columns.sort_unstable();
            for r in &rows {
                row_block[*r] = id;
            }
            for c in &columns {
                column_block[*c] = id;
            }
            blocks.push(Block {
                part: Part::WellDetermined,
                rows,
                columns,
            });
        }
        components(
            Part::OverDetermined,
            &mut blocks,
            &mut row_block,
            &mut column_block,
        );
        Self {
            matching,
            blocks,
            row_block,
            column_block,
        }
    }

    /// The rows of one part, increasing.
    pub fn rows_in(&self, part: Part) -> Vec<usize> {
        (0..self.row_block.len())
            .filter(|r| self.blocks[self.row_block[*r]].part == part)
            .collect()
    }

    /// The columns of one part, increasing.
    pub fn columns_in(&self, part: Part) -> Vec<usize> {
        (0..self.column_block.len())
            .filter(|c| self.blocks[self.column_block[*c]].part == part)
            .collect()
    }
}

/// The strongly connected components of the well-determined rows under "r reads the column
/// matched to r′" (r → r′), by Tarjan's algorithm without recursion, in the order Tarjan closes
/// them: a component comes after every component it reaches.
fn well_determined_blocks<'a>(
    matching: &Matching,
    row_part: &[Part],
    column_part: &[Part],
    reads: impl Fn(usize) -> &'a [usize],
) -> Vec<Vec<usize>> {
    let m = row_part.len();
    let unvisited = usize::MAX;
    let mut index = vec![unvisited; m];
    let mut low = vec![0_usize; m];
    let mut on_stack = vec![false; m];
    let mut stack: Vec<usize> = Vec::new();
    // (row, position of its next column to look at).
    let mut calls: Vec<(usize, usize)> = Vec::new();
    let mut counter = 0;
    let mut out = Vec::new();
    let successor = |c: usize| -> Option<usize> {
        if column_part[c] == Part::WellDetermined {
            matching.column_to_row[c]
        } else {
            None
        }
    };
    for root in 0..m {
        if row_part[root] != Part::WellDetermined || index[root] != unvisited {
            continue;
        }
        index[root] = counter;
        low[root] = counter;
        counter += 1;
        stack.push(root);
        on_stack[root] = true;
        calls.push((root, 0));
        while let Some(&mut (v, ref mut pos)) = calls.last_mut() {
            let edges = reads(v);
            let mut descend = None;
            while *pos < edges.len() {
                let c = edges[*pos];
                *pos += 1;
                let Some(w) = successor(c) else { continue };
                if index[w] == unvisited {
                    descend = Some(w);
                    break;
                }
                if on_stack[w] {
                    low[v] = low[v].min(index[w]);
                }
            }
            if let Some(w) = descend {
                index[w] = counter;
                low[w] = counter;
                counter += 1;
                stack.push(w);
                on_stack[w] = true;
                calls.push((w, 0));
                continue;
            }
            calls.pop();
            if low[v] == index[v] {
                let mut component = Vec::new();
                while let Some(w) = stack.pop() {
                    on_stack[w] = false;
                    component.push(w);
                    if w == v {
                        break;
                    }
                }
                out.push(component);
            }
            if let Some(&(parent, _)) = calls.last() {
                low[parent] = low[parent].min(low[v]);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn matrix(m: usize, n: usize, entries: &[(usize, usize)]) -> SparseMatrix {
        let t: Vec<(usize, usize, f64)> = entries.iter().map(|&(r, c)| (r, c, 1.0)).collect();
        SparseMatrix::try_from_triplets(m, n, &t).unwrap_or_else(|_| unreachable!())
    }

    /// Random patterns of up to 9 × 9 with a varying density.
    fn pattern() -> impl Strategy<Value = SparseMatrix> {
        (0usize..10, 0usize..10, any::<u64>(), 1u64..5).prop_map(|(m, n, seed, density)| {
            let mut state = seed | 1;
            let mut entries = Vec::new();
            for r in 0..m {
                for c in 0..n {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    if state % 9 < density {
                        entries.push((r, c));
                    }
                }
            }
            matrix(m, n, &entries)
        })
    }

    #[test]
    fn a_hand_made_pattern_splits_as_drawn() {
        // Rows 0–1 over-determine x₀ (x₀ = a, x₀ = b); rows 2–3 form a 2 × 2 cycle on x₁, x₂
        // and read x₀; row 4 reads x₃ and x₂ (a 1 × 1 block before the cycle); row 5 reads
        // x₄, x₅ and x₃ (under-determined).
        let j = matrix(
            6,
            6,
            &[
                (0, 0),
                (1, 0),
                (2, 1),
                (2, 2),
                (2, 0),
                (3, 1),
                (3, 2),
                (4, 3),
                (4, 2),
                (5, 4),
                (5, 5),
                (5, 3),
            ],
        );
        let d = Decomposition::of(&j);
        assert_eq!(d.matching.size(), 5);
        assert_eq!(d.rows_in(Part::UnderDetermined), vec![5]);
        assert_eq!(d.columns_in(Part::UnderDetermined), vec![4, 5]);
        assert_eq!(d.rows_in(Part::WellDetermined), vec![2, 3, 4]);
        assert_eq!(d.columns_in(Part::WellDetermined), vec![1, 2, 3]);
        assert_eq!(d.rows_in(Part::OverDetermined), vec![0, 1]);
        assert_eq!(d.columns_in(Part::OverDetermined), vec![0]);
        let shapes: Vec<(Part, Vec<usize>, Vec<usize>)> = d
            .blocks
            .iter()
            .map(|b| (b.part, b.rows.clone(), b.columns.clone()))
            .collect();
        assert_eq!(
            shapes,
            vec![
                (Part::UnderDetermined, vec![5], vec![4, 5]),
                (Part::WellDetermined, vec![4], vec![3]),
                (Part::WellDetermined, vec![2, 3], vec![1, 2]),
                (Part::OverDetermined, vec![0, 1], vec![0]),
            ]
        );
    }

    #[test]
    fn a_long_chain_is_a_long_run_of_one_by_one_blocks() {
        // x₀ fixed, then x_{i+1} − x_i: 200,000 blocks, no recursion.
        let n = 200_000;
        let mut entries = vec![(0, 0)];
        for i in 1..n {
            entries.push((i, i - 1));
            entries.push((i, i));
        }
        let d = Decomposition::of(&matrix(n, n, &entries));
        assert_eq!(d.blocks.len(), n);
        assert!(d.blocks.iter().all(|b| b.part == Part::WellDetermined));
        // Row i reads x_{i−1}: its block comes before that of x_{i−1}.
        assert_eq!(d.blocks[0].rows, vec![n - 1]);
    }

    proptest! {
        /// Every row and column lies in exactly one block; the parts have their shapes; the
        /// form is block upper-triangular.
        #[test]
        fn the_blocks_partition_and_triangularize(j in pattern()) {
            let d = Decomposition::of(&j);
            let mut rows_seen = vec![0; j.nrows()];
            let mut columns_seen = vec![0; j.ncols()];
            for (id, b) in d.blocks.iter().enumerate() {
                for r in &b.rows {
                    rows_seen[*r] += 1;
                    prop_assert_eq!(d.row_block[*r], id);
                }
                for c in &b.columns {
                    columns_seen[*c] += 1;
                    prop_assert_eq!(d.column_block[*c], id);
                }
                match b.part {
                    Part::UnderDetermined => prop_assert!(b.columns.len() > b.rows.len()),
                    Part::OverDetermined => prop_assert!(b.rows.len() > b.columns.len()),
                    Part::WellDetermined => {
                        prop_assert_eq!(b.rows.len(), b.columns.len());
                        for r in &b.rows {
                            let c = d.matching.row_to_column[*r];
                            prop_assert!(c.is_some_and(|c| b.columns.contains(&c)));
                        }
                    }
                }
            }
            prop_assert!(rows_seen.iter().all(|k| *k == 1));
            prop_assert!(columns_seen.iter().all(|k| *k == 1));
            for r in 0..j.nrows() {
                for c in j.row(r).0 {
                    prop_assert!(d.column_block[*c] >= d.row_block[r], "entry ({}, {}) below the diagonal blocks", r, c);
                }
            }
            // The parts are in order: under-determined, well-determined, over-determined.
            let rank = |p: Part| p as usize;
            prop_assert!(d.blocks.windows(2).all(|w| rank(w[0].part) <= rank(w[1].part)));
        }

        /// The square part's blocks are the strongly connected components petgraph finds.
        #[test]
        fn the_square_blocks_are_the_strong_components(j in pattern()) {
            let d = Decomposition::of(&j);
            let well = d.rows_in(Part::WellDetermined);
            let mut g = petgraph::graph::DiGraph::<usize, ()>::new();
            let nodes: Vec<_> = well.iter().map(|r| g.add_node(*r)).collect();
            for (a, r) in well.iter().enumerate() {
                for c in j.row(*r).0 {
                    if let Some(b) = well.iter().position(|r2| d.matching.row_to_column[*r2] == Some(*c)) {
                        g.add_edge(nodes[a], nodes[b], ());
                    }
                }
            }
            let mut expected: Vec<Vec<usize>> = petgraph::algo::tarjan_scc(&g)
                .into_iter()
                .map(|scc| {
                    let mut rows: Vec<usize> = scc.iter().map(|v| g[*v]).collect();
                    rows.sort_unstable();
                    rows
                })
                .collect();
            expected.sort();
            let mut found: Vec<Vec<usize>> = d
                .blocks
                .iter()
                .filter(|b| b.part == Part::WellDetermined)
                .map(|b| b.rows.clone())
                .collect();
            found.sort();
            prop_assert_eq!(found, expected);
        }

        /// The parts do not depend on the matching: listing the rows in reverse order (which
        /// changes the greedy start and the searches) gives the same parts.
        #[test]
        fn the_parts_do_not_depend_on_the_matching(j in pattern()) {
            let m = j.nrows();
            let reversed: Vec<usize> = (0..m).rev().collect();
            let d = Decomposition::of(&j);
            let e = Decomposition::of(&j.select_rows(&reversed));
            for r in 0..m {
                prop_assert_eq!(d.blocks[d.row_block[r]].part, e.blocks[e.row_block[m - 1 - r]].part);
            }
            for c in 0..j.ncols() {
                prop_assert_eq!(d.blocks[d.column_block[c]].part, e.blocks[e.column_block[c]].part);
            }
            prop_assert_eq!(d.blocks.len(), e.blocks.len());
        }
    }
}
