//! A small compressed-sparse-row matrix, the public form of assembled Jacobians.
//!
//! It is built from (row, column, value) triplets; duplicates are summed and explicit zeros kept
//! out. Factorizations convert it to the backend they need (nalgebra dense or faer sparse), so no
//! backend type appears in the public API.

use nalgebra::DMatrix;

use crate::model::errors::{check_len, Error, Result};

/// A sparse matrix in compressed-sparse-row form: the entries of row i are
/// `col_idx[row_ptr[i]..row_ptr[i+1]]` (strictly increasing) with `values` alongside.
///
/// ```
/// use camber_solve::SparseMatrix;
/// let a = SparseMatrix::try_from_triplets(2, 3, &[(0, 2, 1.0), (1, 0, 2.0), (0, 2, 0.5)])?;
/// assert_eq!(a.nnz(), 2);
/// assert!((a.get(0, 2) - 1.5).abs() < 1e-15);
/// let mut y = [0.0; 2];
/// a.mul_vec(&[1.0, 1.0, 2.0], &mut y)?;
/// assert!((y[0] - 3.0).abs() < 1e-15 && (y[1] - 2.0).abs() < 1e-15);
/// # Ok::<(), camber_solve::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct SparseMatrix {
    nrows: usize,
    ncols: usize,
    row_ptr: Vec<usize>,
    col_idx: Vec<usize>,
    values: Vec<f64>,
}

/// # Construction
impl SparseMatrix {
    /// Builds an `nrows × ncols` matrix from triplets (row, column, value); duplicate positions
    /// are summed and entries that sum to exactly zero are dropped.
    ///
    /// # Errors
    /// [`Error::UnknownUnknown`] for an index out of range, [`Error::NonFinite`] for a NaN or
    /// infinite value.
    pub fn try_from_triplets(
        nrows: usize,
        ncols: usize,
        triplets: &[(usize, usize, f64)],
    ) -> Result<Self> {
        let mut counts = vec![0_usize; nrows + 1];
        for (k, &(r, c, v)) in triplets.iter().enumerate() {
            if r >= nrows {
                return Err(Error::UnknownUnknown {
                    index: r,
                    len: nrows,
                });
            }
            if c >= ncols {
                return Err(Error::UnknownUnknown {
                    index: c,
                    len: ncols,
                });
            }
            if !v.is_finite() {
                return Err(Error::NonFinite {
                    what: "matrix entry",
                    index: k,
                    value: v,
                });
            }
            counts[r + 1] += 1;
        }
        for i in 0..nrows {
            counts[i + 1] += counts[i];
        }
        // Bucket by row, then sort and merge each row.
        let mut next = counts.clone();
        let mut cols = vec![0_usize; triplets.len()];
        let mut vals = vec![0.0; triplets.len()];
        for &(r, c, v) in triplets {
            let slot = next[r];
            cols[slot] = c;
            vals[slot] = v;
            next[r] += 1;
        }
        let mut row_ptr = Vec::with_capacity(nrows + 1);
        let mut col_idx = Vec::with_capacity(triplets.len());
        let mut values = Vec::with_capacity(triplets.len());
        row_ptr.push(0);
        let mut pairs: Vec<(usize, f64)> = Vec::new();
        for i in 0..nrows {
            pairs.clear();
            pairs.extend(
                cols[counts[i]..counts[i + 1]]
                    .iter()
                    .copied()
                    .zip(vals[counts[i]..counts[i + 1]].iter().copied()),
            );
            pairs.sort_unstable_by_key(|p| p.0);
            let mut k = 0;
            while k < pairs.len() {
                let c = pairs[k].0;
                let mut sum = 0.0;
                while k < pairs.len() && pairs[k].0 == c {
                    sum += pairs[k].1;
                    k += 1;
                }
                if sum != 0.0 {
                    col_idx.push(c);
                    values.push(sum);
                }
            }
            row_ptr.push(col_idx.len());
        }
        Ok(Self {
            nrows,
            ncols,
            row_ptr,
            col_idx,
            values,
        })
    }

    /// A matrix from its compressed rows, checked: `row_ptr` has `nrows + 1` non-decreasing
    /// offsets from 0 to the number of entries, and each row's columns are strictly
    /// increasing and below `ncols`.
    ///
    /// # Errors
    /// [`Error::Dimension`] for inconsistent lengths or offsets, [`Error::UnknownUnknown`]
    /// for a column out of range or out of order.
    pub(crate) fn from_csr(
        nrows: usize,
        ncols: usize,
        row_ptr: Vec<usize>,
        col_idx: Vec<usize>,
        values: Vec<f64>,
    ) -> Result<Self> {
        check_len("row offsets", nrows + 1, row_ptr.len())?;
        check_len("column indices", values.len(), col_idx.len())?;
        check_len(
            "entries",
            col_idx.len(),
            row_ptr.last().copied().unwrap_or(0),
        )?;
        check_len("first row offset", 0, row_ptr.first().copied().unwrap_or(0))?;
        for w in row_ptr.windows(2) {
            let Some(cols) = col_idx.get(w[0]..w[1]) else {
                return Err(Error::Dimension {
                    what: "row offsets",
                    expected: w[0],
                    found: w[1],
                });
            };
            let mut prev = None;
            for &c in cols {
                if c >= ncols || prev.is_some_and(|p| c <= p) {
                    return Err(Error::UnknownUnknown {
                        index: c,
                        len: ncols,
                    });
                }
                prev = Some(c);
            }
        }
        Ok(Self {
            nrows,
            ncols,
            row_ptr,
            col_idx,
            values,
        })
    }

    /// The 0 × 0 matrix.
    pub(crate) fn empty() -> Self {
        Self {
            nrows: 0,
            ncols: 0,
            row_ptr: vec![0],
            col_idx: Vec::new(),
            values: Vec::new(),
        }
    }

    /// Takes the storage of the compressed-row arrays, emptied, to build another matrix in;
    /// `self` is left 0 × 0 without even its one row offset, so it must be replaced before
    /// it is used again.
    pub(crate) fn take_storage(&mut self) -> (Vec<usize>, Vec<usize>, Vec<f64>) {
        self.nrows = 0;
        self.ncols = 0;
        let mut row_ptr = std::mem::take(&mut self.row_ptr);
        let mut col_idx = std::mem::take(&mut self.col_idx);
        let mut values = std::mem::take(&mut self.values);
        row_ptr.clear();
        col_idx.clear();
        values.clear();
        (row_ptr, col_idx, values)
    }

    /// The sparse form of a dense matrix (exact zeros dropped).
    pub fn from_dense(m: &DMatrix<f64>) -> Self {
        let mut row_ptr = vec![0];
        let mut col_idx = Vec::new();
        let mut values = Vec::new();
        for i in 0..m.nrows() {
            for (j, v) in m.row(i).iter().enumerate() {
                if *v != 0.0 {
                    col_idx.push(j);
                    values.push(*v);
                }
            }
            row_ptr.push(col_idx.len());
        }
        Self {
            nrows: m.nrows(),
            ncols: m.ncols(),
            row_ptr,
            col_idx,
            values,
        }
    }
}

impl SparseMatrix {
    /// Number of rows.
    pub fn nrows(&self) -> usize {
        self.nrows
    }

    /// Number of columns.
    pub fn ncols(&self) -> usize {
        self.ncols
    }

    /// Number of stored (nonzero) entries.
    pub fn nnz(&self) -> usize {
        self.values.len()
    }

    /// The column indices and values of row `i` (empty slices for a row out of range).
    pub fn row(&self, i: usize) -> (&[usize], &[f64]) {
        match (self.row_ptr.get(i), self.row_ptr.get(i + 1)) {
            (Some(&a), Some(&b)) => (&self.col_idx[a..b], &self.values[a..b]),
            _ => (&[], &[]),
        }
    }

    /// The compressed-row arrays: row pointers, column indices and values.
    pub(crate) fn raw(&self) -> (&[usize], &[usize], &[f64]) {
        (&self.row_ptr, &self.col_idx, &self.values)
    }

    /// Entry (i, j), zero when not stored or out of range.
    pub fn get(&self, i: usize, j: usize) -> f64 {
        let (cols, vals) = self.row(i);
        cols.binary_search(&j).map_or(0.0, |k| vals[k])
    }

    /// y = A·x.
    ///
    /// # Errors
    /// [`Error::Dimension`] when `x` or `y` has the wrong length.
    pub fn mul_vec(&self, x: &[f64], y: &mut [f64]) -> Result<()> {
        check_len("vector x", self.ncols, x.len())?;
        check_len("vector y", self.nrows, y.len())?;
        for (i, yi) in y.iter_mut().enumerate() {
            let (cols, vals) = self.row(i);
            *yi = cols.iter().zip(vals).map(|(c, v)| v * x[*c]).sum();
        }
        Ok(())
    }

    /// The dense copy (for small matrices, analysis and tests).
    pub fn to_dense(&self) -> DMatrix<f64> {
        let mut m = DMatrix::zeros(self.nrows, self.ncols);
        for i in 0..self.nrows {
            let (cols, vals) = self.row(i);
            for (c, v) in cols.iter().zip(vals) {
                m[(i, *c)] = *v;
            }
        }
        m
    }

    /// Every value multiplied by `factor` (same pattern).
    pub(crate) fn scaled(&self, factor: f64) -> Self {
        let mut out = self.clone();
        for v in &mut out.values {
            *v *= factor;
        }
        out
    }

    /// The rows listed in `rows`, in that order, as a new matrix (same columns).
    pub fn select_rows(&self, rows: &[usize]) -> Self {
        let mut row_ptr = vec![0];
        let mut col_idx = Vec::new();
        let mut values = Vec::new();
        for &i in rows {
            let (cols, vals) = self.row(i);
            col_idx.extend_from_slice(cols);
            values.extend_from_slice(vals);
            row_ptr.push(col_idx.len());
        }
        Self {
            nrows: rows.len(),
            ncols: self.ncols,
            row_ptr,
            col_idx,
            values,
        }
    }
}

/// Builds compressed-row matrices from triplet lists that repeat their (row, column) sequence:
/// the Jacobian and Hessian of every Newton iteration list their entries in the same order.
/// The first list fixes the pattern (duplicates summed, explicit zeros kept, so a derivative
/// that happens to vanish does not change it) and the slot of every triplet; a list with the
/// same positions then only sums values into those slots. Another sequence rebuilds.
#[derive(Debug, Clone, Default)]
pub(crate) struct Assembler {
    keys: Vec<(usize, usize)>,
    slots: Vec<usize>,
    matrix: Option<SparseMatrix>,
}

impl Assembler {
    /// The `nrows × ncols` matrix of `triplets`, with every value multiplied by `keep(column)`
    /// (0 or 1: columns left out keep their place in the pattern).
    ///
    /// # Errors
    /// [`Error::UnknownUnknown`] for an index out of range, [`Error::NonFinite`] for a NaN or
    /// infinite value.
    pub(crate) fn assemble(
        &mut self,
        nrows: usize,
        ncols: usize,
        triplets: &[(usize, usize, f64)],
        keep: impl Fn(usize) -> bool,
    ) -> Result<&SparseMatrix> {
        let same = self
            .matrix
            .as_ref()
            .is_some_and(|m| m.nrows == nrows && m.ncols == ncols)
            && self.keys.len() == triplets.len()
            && self
                .keys
                .iter()
                .zip(triplets)
                .all(|(k, t)| k.0 == t.0 && k.1 == t.1);
        if !same {
            self.rebuild(nrows, ncols, triplets)?;
        }
        let Some(m) = self.matrix.as_mut() else {
            return Err(Error::Dimension {
                what: "assembled matrix",
                expected: nrows,
                found: 0,
            });
        };
        m.values.fill(0.0);
        for (k, ((_, c, v), slot)) in triplets.iter().zip(&self.slots).enumerate() {
            if !v.is_finite() {
                return Err(Error::NonFinite {
                    what: "matrix entry",
                    index: k,
                    value: *v,
                });
            }
            if keep(*c) {
                m.values[*slot] += v;
            }
        }
        Ok(m)
    }

    fn rebuild(
        &mut self,
        nrows: usize,
        ncols: usize,
        triplets: &[(usize, usize, f64)],
    ) -> Result<()> {
        self.keys.clear();
        for &(r, c, _) in triplets {
            if r >= nrows {
                return Err(Error::UnknownUnknown {
                    index: r,
                    len: nrows,
                });
            }
            if c >= ncols {
                return Err(Error::UnknownUnknown {
                    index: c,
                    len: ncols,
                });
            }
            self.keys.push((r, c));
        }
        let (row_ptr, col_idx) = compress(nrows, &self.keys);
        self.slots.clear();
        for &(r, c) in &self.keys {
            let cols = &col_idx[row_ptr[r]..row_ptr[r + 1]];
            self.slots
                .push(row_ptr[r] + cols.binary_search(&c).unwrap_or(0));
        }
        let values = vec![0.0; col_idx.len()];
        self.matrix = Some(SparseMatrix {
            nrows,
            ncols,
            row_ptr,
            col_idx,
            values,
        });
        Ok(())
    }
}

/// The compressed-row pattern (row pointers, strictly increasing column indices per row) of
/// the distinct positions among `positions` (row, column), every row below `nrows`. Positions
/// are bucketed by row first (a counting sort) and only each row's short list is sorted, so
/// the cost is about the number of positions, not that times its logarithm as for one sort of
/// them all (the Jacobian and Hessian patterns of a large component hold 10⁵ and more).
pub(crate) fn compress(nrows: usize, positions: &[(usize, usize)]) -> (Vec<usize>, Vec<usize>) {
    let mut row_ptr = vec![0_usize; nrows + 1];
    for &(r, _) in positions {
        row_ptr[r + 1] += 1;
    }
    for i in 0..nrows {
        row_ptr[i + 1] += row_ptr[i];
    }
    let mut next = row_ptr.clone();
    let mut bucketed = vec![0_usize; positions.len()];
    for &(r, c) in positions {
        bucketed[next[r]] = c;
        next[r] += 1;
    }
    // Sort and deduplicate each row in place, moving it down over the duplicates removed
    // before it.
    let mut col_idx = bucketed;
    let mut write = 0;
    let mut start = 0;
    for i in 0..nrows {
        let end = row_ptr[i + 1];
        col_idx[start..end].sort_unstable();
        let row_start = write;
        for k in start..end {
            let c = col_idx[k];
            if write == row_start || col_idx[write - 1] != c {
                col_idx[write] = c;
                write += 1;
            }
        }
        start = end;
        row_ptr[i + 1] = write;
    }
    col_idx.truncate(write);
    (row_ptr, col_idx)
}

/// The entries of a compressed-row matrix column by column: `(col_ptr, by_col)` with the
/// entries of column c at `by_col[col_ptr[c]..col_ptr[c + 1]]`, each as (row, index of its
/// value in the compressed rows), rows increasing. One counting pass, no sort.
pub(crate) fn entries_by_column(
    ncols: usize,
    row_ptr: &[usize],
    col_idx: &[usize],
) -> (Vec<usize>, Vec<(usize, usize)>) {
    let mut col_ptr = vec![0_usize; ncols + 1];
    for &c in col_idx {
        col_ptr[c + 1] += 1;
    }
    for c in 0..ncols {
        col_ptr[c + 1] += col_ptr[c];
    }
    let mut next = col_ptr[..ncols].to_vec();
    let mut by_col = vec![(0_usize, 0_usize); col_idx.len()];
    for (i, w) in row_ptr.windows(2).enumerate() {
        for (a, &c) in col_idx.iter().enumerate().take(w[1]).skip(w[0]) {
            by_col[next[c]] = (i, a);
            next[c] += 1;
        }
    }
    (col_ptr, by_col)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Compressed rows as given equal the triplet construction; malformed ones are refused.
    #[test]
    fn compressed_rows_are_checked() {
        let a = SparseMatrix::from_csr(2, 3, vec![0, 2, 3], vec![0, 2, 1], vec![1.0, 2.0, 3.0])
            .unwrap();
        let b = SparseMatrix::try_from_triplets(2, 3, &[(1, 1, 3.0), (0, 2, 2.0), (0, 0, 1.0)])
            .unwrap();
        assert_eq!(a, b);
        let bad = |row_ptr: Vec<usize>, col_idx: Vec<usize>| {
            let values = vec![1.0; col_idx.len()];
            SparseMatrix::from_csr(2, 3, row_ptr, col_idx, values).is_err()
        };
        assert!(bad(vec![0, 2], vec![0, 1])); // too few offsets
        assert!(bad(vec![1, 2, 3], vec![0, 1, 2])); // not starting at 0
        assert!(bad(vec![0, 2, 1], vec![0, 1])); // decreasing
        assert!(bad(vec![0, 2, 2], vec![1, 0])); // columns out of order
        assert!(bad(vec![0, 1, 2], vec![0, 3])); // column out of range
        assert!(bad(vec![0, 1, 3], vec![0, 1])); // offsets past the entries
    }

    #[test]
    fn triplets_sum_and_sort() {
        let a = SparseMatrix::try_from_triplets(
            3,
            3,
            &[
                (2, 1, 1.0),
                (0, 2, 2.0),
                (0, 0, 3.0),
                (2, 1, -1.0),
                (1, 1, 4.0),
                (0, 2, 1.0),
            ],
        )
        .unwrap();
        assert_eq!(a.nnz(), 3); // (2,1) cancels
        assert_eq!(a.row(0), (&[0, 2][..], &[3.0, 3.0][..]));
        let d = a.to_dense();
        assert_relative_eq!(d[(1, 1)], 4.0);
        assert_eq!(SparseMatrix::from_dense(&d), a);
        assert_eq!(
            a.select_rows(&[1]).to_dense()[(0, 1)].to_bits(),
            4.0_f64.to_bits()
        );
    }

    #[test]
    fn bad_triplets_are_errors() {
        assert_eq!(
            SparseMatrix::try_from_triplets(2, 2, &[(2, 0, 1.0)]),
            Err(Error::UnknownUnknown { index: 2, len: 2 })
        );
        assert!(matches!(
            SparseMatrix::try_from_triplets(2, 2, &[(0, 0, f64::INFINITY)]),
            Err(Error::NonFinite { index: 0, .. })
        ));
        let a = SparseMatrix::try_from_triplets(2, 2, &[]).unwrap();
        assert_eq!(
            a.mul_vec(&[0.0], &mut [0.0; 2]),
            Err(Error::Dimension {
                what: "vector x",
                expected: 2,
                found: 1
            })
        );
    }

    #[test]
    fn compress_matches_one_sort_of_all_positions() {
        // A deterministic scramble with duplicates, empty rows and rows of one entry.
        let nrows = 37;
        let positions: Vec<(usize, usize)> = (0..600_usize)
            .map(|k| ((k * 7919) % 31 + (k % 3) * 2, (k * 104_729) % 23))
            .collect();
        let (row_ptr, col_idx) = compress(nrows, &positions);
        let mut want = positions.clone();
        want.sort_unstable();
        want.dedup();
        let mut got = Vec::new();
        for r in 0..nrows {
            for &c in &col_idx[row_ptr[r]..row_ptr[r + 1]] {
                got.push((r, c));
            }
        }
        assert_eq!(got, want);
        assert_eq!(row_ptr.len(), nrows + 1);
        assert_eq!(compress(3, &[]), (vec![0; 4], Vec::new()));
    }

    #[test]
    fn the_assembler_keeps_its_pattern_and_sums_like_triplets() {
        let mut asm = Assembler::default();
        let t1 = [(0, 2, 1.0), (1, 0, 2.0), (0, 2, 0.5), (1, 1, 0.0)];
        let a = asm.assemble(2, 3, &t1, |_| true).unwrap().clone();
        assert_eq!(a.nnz(), 3); // the explicit zero at (1, 1) keeps its place
        assert_relative_eq!(a.get(0, 2), 1.5);
        let want = SparseMatrix::try_from_triplets(2, 3, &t1).unwrap();
        assert_eq!(a.to_dense(), want.to_dense());
        // Same positions, new values, column 0 left out.
        let t2 = [(0, 2, 2.0), (1, 0, 3.0), (0, 2, 1.0), (1, 1, 4.0)];
        let b = asm.assemble(2, 3, &t2, |c| c != 0).unwrap();
        assert_relative_eq!(b.get(0, 2), 3.0);
        assert_relative_eq!(b.get(1, 0), 0.0);
        assert_relative_eq!(b.get(1, 1), 4.0);
        // Another sequence rebuilds; bad entries are errors.
        assert!(asm.assemble(2, 3, &[(2, 0, 1.0)], |_| true).is_err());
        assert!(asm.assemble(2, 3, &[(0, 0, f64::NAN)], |_| true).is_err());
    }
}
