//! The affine map x = A·z + c from reduced unknowns z to the problem's unknowns x, and the
//! linearization of the residuals over z.
//!
//! Columns of A (the reduced unknowns) are, in order: the own variable of every free unknown
//! (in unknown order), then every auxiliary unknown. At the start of a solve z₀ holds the current
//! values of those; x(z₀) = A·z₀ + c may differ from the stored x where a substitution is not yet
//! satisfied, which is how a substitution imposes itself. By the chain rule the Jacobian over z
//! is J_z = J_x·A, assembled sparse from each residual block's dense Jacobian.

use crate::linalg::sparse::SparseMatrix;
use crate::model::errors::check_len;
use crate::model::errors::{Error, Result};
use crate::model::ids::{ConstraintId, ResidualId, Var};
use crate::model::problem::{check_residual, Binding, Problem};

/// The map x = A·z + c with the starting point z₀ and the weights of the reduced unknowns.
#[derive(Debug, Clone, PartialEq)]
pub struct ReducedMap {
    vars: Vec<Var>,
    z0: Vec<f64>,
    weights: Vec<f64>,
    lower: Vec<f64>,
    upper: Vec<f64>,
    /// Row i of A is `terms[row_ptr[i]..row_ptr[i+1]]` as (column, coefficient).
    row_ptr: Vec<usize>,
    terms: Vec<(usize, f64)>,
    constant: Vec<f64>,
    /// The column of each free unknown (`usize::MAX` for the others): storage reused by
    /// [`Problem::reduced_map_into`], determined by `vars`.
    column: Vec<usize>,
}

impl ReducedMap {
    /// A map of nothing, storage for [`Problem::reduced_map_into`].
    pub(crate) fn empty() -> Self {
        Self {
            vars: Vec::new(),
            z0: Vec::new(),
            weights: Vec::new(),
            lower: Vec::new(),
            upper: Vec::new(),
            row_ptr: Vec::new(),
            terms: Vec::new(),
            constant: Vec::new(),
            column: Vec::new(),
        }
    }

    /// Number of reduced unknowns (columns of A).
    pub fn len(&self) -> usize {
        self.vars.len()
    }

    /// Whether there is no reduced unknown (everything fixed).
    pub fn is_empty(&self) -> bool {
        self.vars.is_empty()
    }

    /// What each reduced unknown is: the own variable of a free unknown, or an auxiliary.
    pub fn vars(&self) -> &[Var] {
        &self.vars
    }

    /// The starting point z₀ (current values of free and auxiliary unknowns).
    pub fn z0(&self) -> &[f64] {
        &self.z0
    }

    /// The positive weights w of the metric ‖Δz‖²_W.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// Row i of A as (column, coefficient) pairs, and c_i.
    pub fn row(&self, unknown: usize) -> (&[(usize, f64)], f64) {
        match (self.row_ptr.get(unknown), self.row_ptr.get(unknown + 1)) {
            (Some(&a), Some(&b)) => (&self.terms[a..b], self.constant[unknown]),
            _ => (&[], 0.0),
        }
    }

    /// x = A·z + c.
    ///
    /// # Errors
    /// [`Error::Dimension`] for wrong lengths.
    pub fn expand(&self, z: &[f64], x: &mut [f64]) -> Result<()> {
        check_len("reduced unknowns", self.len(), z.len())?;
        check_len("unknowns", self.constant.len(), x.len())?;
        for (i, xi) in x.iter_mut().enumerate() {
            *xi = self.value_at(i, z);
        }
        Ok(())
    }

    /// xᵢ = (A·z + c)ᵢ (`unknown` in range, lengths checked by the caller).
    #[inline]
    fn value_at(&self, unknown: usize, z: &[f64]) -> f64 {
        let terms = &self.terms[self.row_ptr[unknown]..self.row_ptr[unknown + 1]];
        self.constant[unknown] + terms.iter().map(|(k, a)| a * z[*k]).sum::<f64>()
    }
}

/// The residuals and their Jacobian over z at z₀, with the owner of every row.
#[derive(Debug, Clone)]
pub struct Linearization {
    /// The map x = A·z + c it was taken over.
    pub map: ReducedMap,
    /// x(z₀) = A·z₀ + c.
    pub x: Vec<f64>,
    /// g(x(z₀)), the stacked residual rows.
    pub g: Vec<f64>,
    /// J_z = ∂g/∂z at z₀ (rows × reduced unknowns).
    pub jacobian: SparseMatrix,
    /// The constraint owning each row.
    pub row_owner: Vec<ConstraintId>,
    /// The residual block of each row.
    pub row_residual: Vec<ResidualId>,
    /// Whether every residual block declares itself affine.
    pub affine: bool,
}

impl Linearization {
    /// A linearization of nothing, storage for [`Problem::linearize_into`].
    pub(crate) fn empty() -> Self {
        Self {
            map: ReducedMap::empty(),
            x: Vec::new(),
            g: Vec::new(),
            jacobian: SparseMatrix::empty(),
            row_owner: Vec::new(),
            row_residual: Vec::new(),
            affine: true,
        }
    }
}

/// # Reduction
impl Problem {
    /// Builds the map x = A·z + c from the current bindings and values.
    ///
    /// A substitution term on a fixed unknown folds into the constant (a·value). The weight of a
    /// reduced unknown is its own plus w·a² for every unknown bound to it alone (x = a·z, a
    /// merge): moving z moves them all, and each counts in ‖Δx‖²_W.
    ///
    /// # Errors
    /// [`Error::SubstitutionChain`] when a substitution refers to an unknown that is itself
    /// substituted.
    pub fn reduced_map(&self) -> Result<ReducedMap> {
        let mut map = ReducedMap::empty();
        self.reduced_map_into(&mut map)?;
        Ok(map)
    }

    /// [`Problem::reduced_map`] written into `map`, whose storage is reused (a solve of many
    /// small components allocates nothing here once the storage has grown).
    pub(crate) fn reduced_map_into(&self, map: &mut ReducedMap) -> Result<()> {
        let n = self.values.len();
        let ReducedMap {
            vars,
            z0,
            weights,
            lower,
            upper,
            row_ptr,
            terms,
            constant,
            column,
        } = map;
        // At most every unknown and every auxiliary is a column.
        let cols = n + self.aux_values.len();
        for v in [
            &mut *z0,
            &mut *weights,
            &mut *lower,
            &mut *upper,
            &mut *constant,
        ] {
            v.clear();
            v.reserve(cols);
        }
        vars.clear();
        vars.reserve(cols);
        row_ptr.clear();
        terms.clear();
        column.clear();
        column.resize(n, usize::MAX);
        for (i, b) in self.bindings.iter().enumerate() {
            if *b == Binding::Free {
                column[i] = vars.len();
                vars.push(Var::Unknown(crate::model::ids::UnknownId(i)));
                z0.push(self.values[i]);
                weights.push(self.weights[i]);
                lower.push(f64::NEG_INFINITY);
                upper.push(f64::INFINITY);
            }
        }
        let aux_start = vars.len();
        for (a, v) in self.aux_values.iter().enumerate() {
            vars.push(Var::Aux(crate::model::ids::AuxId(a)));
            z0.push(*v);
            weights.push(self.aux_weights[a]);
            lower.push(self.aux_bounds[a].0);
            upper.push(self.aux_bounds[a].1);
        }
        let column = |u: usize| column.get(u).copied().filter(|c| *c != usize::MAX);
        row_ptr.reserve(n + 1);
        // One term per free or merged unknown, more for the few other substitutions.
        terms.reserve(n);
        constant.reserve(n);
        row_ptr.push(0);
        let mut free = 0;
        for (i, b) in self.bindings.iter().enumerate() {
            match b {
                Binding::Free => {
                    terms.push((free, 1.0));
                    free += 1;
                    constant.push(0.0);
                }
                Binding::Fixed => constant.push(self.values[i]),
                Binding::Affine {
                    terms: t,
                    constant: c,
                } => {
                    let mut c = *c;
                    for (var, a) in t {
                        match var {
                            Var::Unknown(u) => match (self.bindings.get(u.0), column(u.0)) {
                                (Some(Binding::Free), Some(col)) => terms.push((col, *a)),
                                // A fixed unknown contributes its value to the constant.
                                (Some(Binding::Fixed), _) => c += a * self.values[u.0],
                                _ => {
                                    return Err(Error::SubstitutionChain {
                                        unknown: i,
                                        referenced: u.0,
                                    })
                                }
                            },
                            Var::Aux(k) => terms.push((aux_start + k.0, *a)),
                        }
                    }
                    constant.push(c);
                }
            }
            row_ptr.push(terms.len());
        }
        // An unknown bound to a single free one (a merge) moves with it: its weight adds to
        // that one's, the metric of x pulled back through the binding (w·a² for x = a·z).
        for (i, b) in self.bindings.iter().enumerate() {
            if let Binding::Affine { terms: t, .. } = b {
                if let [(Var::Unknown(u), a)] = t.as_slice() {
                    if let (Some(Binding::Free), Some(col)) = (self.bindings.get(u.0), column(u.0))
                    {
                        weights[col] += self.weights[i] * a * a;
                    }
                }
            }
        }
        Ok(())
    }

    /// The reduced unknowns z as they are now, in the order of [`ReducedMap::vars`] (the own
    /// variable of every free unknown, then every auxiliary), without building the map.
    pub(crate) fn reduced_values_into(&self, z: &mut Vec<f64>) {
        z.clear();
        z.extend(
            self.bindings
                .iter()
                .zip(&self.values)
                .filter(|(b, _)| **b == Binding::Free)
                .map(|(_, v)| *v),
        );
        z.extend_from_slice(&self.aux_values);
    }

    /// Evaluates the residuals and their Jacobian over z at z₀ (autodiff through every residual
    /// block, chain rule through A, sparse assembly).
    ///
    /// # Errors
    /// Those of [`Problem::reduced_map`], and [`Error::NonFiniteResidual`].
    pub fn linearize(&self) -> Result<Linearization> {
        let mut lin = Linearization::empty();
        self.linearize_into(&mut lin)?;
        Ok(lin)
    }

    /// [`Problem::linearize`] written into `lin`, whose storage is reused. On an error `lin`
    /// holds no meaningful linearization.
    pub(crate) fn linearize_into(&self, lin: &mut Linearization) -> Result<()> {
        self.reduced_map_into(&mut lin.map)?;
        let map = &lin.map;
        lin.x.clear();
        lin.x.resize(self.values.len(), 0.0);
        map.expand(&map.z0, &mut lin.x)?;
        let x = &lin.x;
        let m = self.num_rows();
        lin.g.clear();
        lin.g.resize(m, 0.0);
        lin.row_owner.clear();
        lin.row_owner.reserve(m);
        lin.row_residual.clear();
        lin.row_residual.reserve(m);
        // J_z in compressed rows, assembled row by row: a residual's rows are consecutive, so
        // no global sort of triplets is needed, only of each row's few entries.
        let mut rows = CsrRows::in_storage(&mut lin.jacobian, m);
        let mut jac: smallvec::SmallVec<[f64; 64]> = smallvec::SmallVec::new();
        let mut moves: smallvec::SmallVec<[bool; 16]> = smallvec::SmallVec::new();
        // The residual's local columns as unknowns (flat indices).
        // The residual's local columns as ranges of A's terms (x_u = Σ a·z over the range).
        let mut local: smallvec::SmallVec<[(usize, usize); 32]> = smallvec::SmallVec::new();
        let mut row0 = 0;
        let mut affine = true;
        for (r, rb) in self.residuals.iter().enumerate() {
            let dim = rb.residual.dim();
            affine &= rb.residual.is_affine();
            let slices = self.gather(x, &rb.blocks);
            moves.clear();
            local.clear();
            for b in &rb.blocks {
                let (start, len) = self.block_range(*b)?;
                let before = local.len();
                local.extend((start..start + len).map(|u| {
                    match (map.row_ptr.get(u), map.row_ptr.get(u + 1)) {
                        (Some(&a), Some(&e)) => (a, e),
                        _ => (0, 0),
                    }
                }));
                moves.push(local[before..].iter().any(|(a, e)| a < e));
            }
            let ncols = local.len();
            jac.clear();
            jac.resize(dim * ncols, 0.0);
            let out = &mut lin.g[row0..row0 + dim];
            rb.residual
                .jacobian_active(&slices, &moves, out, &mut jac)?;
            check_residual(rb, out)?;
            for jac_row in jac.chunks_exact(ncols.max(1)).take(dim) {
                // Local column → flat unknown index → reduced columns.
                for (&(a, e), d) in local.iter().zip(jac_row) {
                    if *d != 0.0 {
                        for (col, coef) in &map.terms[a..e] {
                            rows.push(*col, d * coef)?;
                        }
                    }
                }
                rows.finish_row();
            }
            if ncols == 0 {
                for _ in 0..dim {
                    rows.finish_row();
                }
            }
            lin.row_owner.extend(std::iter::repeat_n(rb.owner, dim));
            lin.row_residual
                .extend(std::iter::repeat_n(ResidualId(r), dim));
            row0 += dim;
        }
        lin.jacobian = rows.into_matrix(m, map.len())?;
        lin.affine = affine;
        Ok(())
    }

    /// Writes x = A·z + c and the auxiliary values from z. `map` must come from this problem
    /// with its bindings unchanged since.
    ///
    /// # Errors
    /// [`Error::Dimension`] for a z of the wrong length, [`Error::NonFinite`] for a NaN in z,
    /// [`Error::OutOfBounds`] when an unknown would leave its bounds (nothing is written then).
    pub fn apply_reduced(&mut self, map: &ReducedMap, z: &[f64]) -> Result<()> {
        check_len("reduced unknowns", map.len(), z.len())?;
        if let Some((index, value)) = z.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(Error::NonFinite {
                what: "reduced unknown",
                index,
                value: *value,
            });
        }
        check_len("unknowns", map.constant.len(), self.values.len())?;
        // x is formed row by row twice, to check and then to write, so that nothing is
        // written on an error and nothing is allocated.
        for (i, (lo, hi)) in self.bounds.iter().enumerate().take(self.values.len()) {
            // z is finite, so an unbounded unknown needs no check.
            if lo.is_infinite()
                && lo.is_sign_negative()
                && hi.is_infinite()
                && hi.is_sign_positive()
            {
                continue;
            }
            let xi = map.value_at(i, z);
            if xi < *lo || xi > *hi {
                return Err(Error::OutOfBounds {
                    unknown: i,
                    value: xi,
                    lower: *lo,
                    upper: *hi,
                });
            }
        }
        for (k, zk) in z.iter().enumerate() {
            if *zk < map.lower[k] || *zk > map.upper[k] {
                return Err(Error::OutOfBounds {
                    unknown: k,
                    value: *zk,
                    lower: map.lower[k],
                    upper: map.upper[k],
                });
            }
        }
        for (i, xi) in self.values.iter_mut().enumerate() {
            *xi = map.value_at(i, z);
        }
        for (var, zk) in map.vars.iter().zip(z) {
            if let Var::Aux(a) = var {
                if let Some(slot) = self.aux_values.get_mut(a.0) {
                    *slot = *zk;
                }
            }
        }
        Ok(())
    }
}

/// A compressed-row matrix built one row at a time: each row's entries are pushed in any
/// order, then sorted and merged (duplicates summed, sums of exactly zero dropped, as
/// [`SparseMatrix::try_from_triplets`] does).
struct CsrRows {
    row_ptr: Vec<usize>,
    col_idx: Vec<usize>,
    values: Vec<f64>,
    /// The current row's entries.
    pending: smallvec::SmallVec<[(usize, f64); 32]>,
    /// Entries pushed so far (the index named by a non-finite entry's error).
    pushed: usize,
}

impl CsrRows {
    /// Rows to be built in the storage of `matrix`, which must be replaced by
    /// [`CsrRows::into_matrix`]'s result (see [`SparseMatrix::take_storage`]).
    fn in_storage(matrix: &mut SparseMatrix, rows: usize) -> Self {
        let (mut row_ptr, mut col_idx, mut values) = matrix.take_storage();
        row_ptr.reserve(rows + 1);
        row_ptr.push(0);
        col_idx.reserve(4 * rows);
        values.reserve(4 * rows);
        Self {
            row_ptr,
            col_idx,
            values,
            pending: smallvec::SmallVec::new(),
            pushed: 0,
        }
    }

    /// Adds `value` at column `col` of the current row.
    fn push(&mut self, col: usize, value: f64) -> Result<()> {
        if !value.is_finite() {
            return Err(Error::NonFinite {
                what: "matrix entry",
                index: self.pushed,
                value,
            });
        }
        self.pending.push((col, value));
        self.pushed += 1;
        Ok(())
    }

    /// Ends the current row.
    fn finish_row(&mut self) {
        // Entries pushed in increasing columns (the usual order) need no sort and no merge.
        if self.pending.windows(2).all(|w| w[0].0 < w[1].0) {
            for &(col, value) in &self.pending {
                if value != 0.0 {
                    self.col_idx.push(col);
                    self.values.push(value);
                }
            }
            self.pending.clear();
            self.row_ptr.push(self.col_idx.len());
            return;
        }
        self.pending.sort_unstable_by_key(|e| e.0);
        let mut k = 0;
        while k < self.pending.len() {
            let col = self.pending[k].0;
            let mut sum = 0.0;
            while k < self.pending.len() && self.pending[k].0 == col {
                sum += self.pending[k].1;
                k += 1;
            }
            if sum != 0.0 {
                self.col_idx.push(col);
                self.values.push(sum);
            }
        }
        self.pending.clear();
        self.row_ptr.push(self.col_idx.len());
    }

    /// The matrix of the rows finished (`nrows` of them, columns below `ncols`).
    fn into_matrix(self, nrows: usize, ncols: usize) -> Result<SparseMatrix> {
        SparseMatrix::from_csr(nrows, ncols, self.row_ptr, self.col_idx, self.values)
    }
}
