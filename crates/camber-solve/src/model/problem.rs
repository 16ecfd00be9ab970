//! The problem: parameter blocks of unknowns, their bindings (free, fixed or substituted),
//! bounds, weights, auxiliary unknowns, and the residual blocks that read them.
//!
//! The unknowns x form one flat vector, blocks laid end to end. The solve does not run over x
//! but over reduced unknowns z through an affine map x = A·z + c (see [`crate::linalg::reduced`]):
//! - a **free** unknown owns one z (A row = unit vector, c = 0);
//! - a **fixed** unknown keeps its value (A row = 0, c = value);
//! - a **substituted** unknown is x_i = Σ a_k·z_k + c_i over the own z of free unknowns and over
//!   auxiliary unknowns declared with [`Problem::add_aux`]. Merged unknowns
//!   ([`Problem::merge`]) and the tangency elimination x_P1 = x_P0 + t·T
//!   ([`Problem::eliminate`]) are special cases.

use std::sync::Arc;

use smallvec::SmallVec;

use crate::model::budget::Budget;
use crate::model::errors::{Error, Result};
use crate::model::ids::{AuxId, BlockId, ConstraintId, ResidualId, UnknownId, Var};
use crate::model::residual::{DynResidual, Residual};

/// How one unknown x_i is tied to the reduced unknowns z.
#[derive(Debug, Clone, PartialEq)]
pub enum Binding {
    /// x_i owns a reduced unknown of its own (the default).
    Free,
    /// x_i keeps its current value.
    Fixed,
    /// x_i = Σ coefficient·z(var) + constant.
    Affine {
        /// The terms (reduced variable, coefficient): one sparse row of A.
        terms: Vec<(Var, f64)>,
        /// The constant c_i.
        constant: f64,
    },
}

/// A residual block: the residual, the blocks it reads, and the constraint that owns it.
///
/// What every evaluation asks of the residual and its blocks is kept here, taken once when the
/// block is added: its row count and whether it is affine (each a call through the trait
/// object otherwise), and where its blocks lie in x (a block's range never changes once
/// issued).
#[derive(Debug)]
pub(crate) struct ResidualBlock {
    /// Shared, so that a residual a caller already holds behind an `Arc` (the sketch's
    /// compiled constraints) is added without a copy or a second indirection.
    pub(crate) residual: Arc<dyn DynResidual>,
    /// The blocks it reads (inline up to four: most residuals read one to four points).
    pub(crate) blocks: SmallVec<[BlockId; 4]>,
    /// Where the (first unknown, length) of every block in `blocks` start in
    /// [`Problem::spans`] ([`Problem::spans_of`]): kept there end to end rather than here, so
    /// that a residual block stays small.
    pub(crate) spans_at: usize,
    /// `residual.dim()`.
    pub(crate) dim: usize,
    /// `residual.is_affine()`.
    pub(crate) affine: bool,
    pub(crate) owner: ConstraintId,
    /// Its priority tier (0, required, unless [`Problem::set_priority`] said otherwise).
    pub(crate) priority: crate::model::priority::Priority,
}

/// Parameter blocks, their bindings and the residual blocks over them.
///
/// ```
/// use camber_solve::{ConstraintId, Options, Problem, Residual, Scalar, solve_linear};
///
/// /// x + y − 2 = 0 for a block (x, y).
/// #[derive(Debug)]
/// struct SumIsTwo;
/// impl Residual for SumIsTwo {
///     fn name(&self) -> &str { "sum is two" }
///     fn dim(&self) -> usize { 1 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
///         out[0] = x[0][0] + x[0][1] - camber_solve::scalar::cst(2.0);
///     }
///     fn is_affine(&self) -> bool { true }
/// }
///
/// let mut p = Problem::new();
/// let b = p.add_block(&[0.0, 0.0])?;
/// p.add_residual(SumIsTwo, &[b], ConstraintId(1))?;
/// let report = solve_linear(&mut p, &Options::default())?;
/// // The minimum-norm move splits the correction evenly.
/// assert!((p.values()[0] - 1.0).abs() < 1e-12 && (p.values()[1] - 1.0).abs() < 1e-12);
/// assert_eq!(report.dof, 1);
/// # Ok::<(), camber_solve::Error>(())
/// ```
#[derive(Debug, Default)]
pub struct Problem {
    pub(crate) values: Vec<f64>,
    /// (start, len) of every block in `values`.
    pub(crate) blocks: Vec<(usize, usize)>,
    pub(crate) bindings: Vec<Binding>,
    pub(crate) bounds: Vec<(f64, f64)>,
    pub(crate) weights: Vec<f64>,
    pub(crate) aux_values: Vec<f64>,
    pub(crate) aux_weights: Vec<f64>,
    pub(crate) aux_bounds: Vec<(f64, f64)>,
    pub(crate) residuals: Vec<ResidualBlock>,
    /// (first unknown, length) of the blocks every residual block reads, end to end in the
    /// order of `residuals` (see [`ResidualBlock::spans_at`]).
    pub(crate) spans: Vec<(usize, usize)>,
    /// The evaluations a solve may still spend ([`Problem::start_budget`]).
    pub(crate) budget: Budget,
    /// Changed by every change of structure: blocks, bindings, bounds, weights, residual
    /// blocks, priorities (see [`Problem::stamps`]).
    shape_stamp: u64,
    /// Changed by every residual object replaced in place ([`Problem::replace_residual`]).
    residual_stamp: u64,
}

/// A new stamp, distinct from every stamp handed out before in this process.
fn next_stamp() -> u64 {
    static NEXT: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(1);
    NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed)
}

/// What changed in a problem, as two stamps ([`Problem::stamps`]): a plan kept between solves
/// compares them with those it was made at.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Stamps {
    /// Changed by every change of structure (blocks, bindings, bounds, weights, residual
    /// blocks added or taken back, priorities); values alone never change it.
    pub shape: u64,
    /// Changed by every residual object replaced in place (same rows and blocks, other
    /// coefficients or constants).
    pub residuals: u64,
}

/// # Construction
impl Problem {
    /// An empty problem.
    pub fn new() -> Self {
        Self::default()
    }

    /// Reserves room for `blocks` more parameter blocks holding `unknowns` more unknowns in
    /// all, and `residuals` more residual blocks, so that building a problem of known size
    /// grows its lists once.
    ///
    /// ```
    /// use camber_solve::Problem;
    /// let mut p = Problem::new();
    /// p.reserve(2, 4, 1);
    /// p.add_block(&[0.0, 1.0])?;
    /// p.add_block(&[2.0, 3.0])?;
    /// assert_eq!(p.values(), &[0.0, 1.0, 2.0, 3.0]);
    /// # Ok::<(), camber_solve::Error>(())
    /// ```
    pub fn reserve(&mut self, blocks: usize, unknowns: usize, residuals: usize) {
        self.touch();
        self.blocks.reserve(blocks);
        self.values.reserve(unknowns);
        self.bindings.reserve(unknowns);
        self.bounds.reserve(unknowns);
        self.weights.reserve(unknowns);
        self.residuals.reserve(residuals);
        self.spans.reserve(2 * residuals);
    }

    /// Adds a parameter block with the given starting values (all free, unbounded, weight 1).
    ///
    /// # Errors
    /// [`Error::Dimension`] for an empty block, [`Error::NonFinite`] for a NaN or infinite value.
    pub fn add_block(&mut self, values: &[f64]) -> Result<BlockId> {
        if values.is_empty() {
            return Err(Error::Dimension {
                what: "block values",
                expected: 1,
                found: 0,
            });
        }
        check_finite("block value", values)?;
        let start = self.values.len();
        self.touch();
        self.values.extend_from_slice(values);
        self.blocks.push((start, values.len()));
        for _ in values {
            self.bindings.push(Binding::Free);
            self.bounds.push((f64::NEG_INFINITY, f64::INFINITY));
            self.weights.push(1.0);
        }
        Ok(BlockId(self.blocks.len() - 1))
    }

    /// Declares an auxiliary reduced unknown with a starting value (weight 1, unbounded), to be
    /// used in substitutions ([`Problem::substitute`]).
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a NaN or infinite value.
    pub fn add_aux(&mut self, value: f64) -> Result<AuxId> {
        check_finite("auxiliary value", &[value])?;
        self.touch();
        self.aux_values.push(value);
        self.aux_weights.push(1.0);
        self.aux_bounds.push((f64::NEG_INFINITY, f64::INFINITY));
        Ok(AuxId(self.aux_values.len() - 1))
    }

    /// Adds a residual block reading `blocks` (in that order), owned by the caller's constraint
    /// `owner`. The blocks must have the count and lengths the residual declares, if it does
    /// ([`Residual::block_sizes`]), which is what lets its `eval` index them freely.
    ///
    /// # Errors
    /// [`Error::UnknownBlock`] for a block this problem did not issue; [`Error::BlockShape`]
    /// for blocks of another count or length than declared. Nothing is added then.
    pub fn add_residual<R: Residual>(
        &mut self,
        residual: R,
        blocks: &[BlockId],
        owner: ConstraintId,
    ) -> Result<ResidualId> {
        self.add_shared_residual(Arc::new(residual), blocks, owner)
    }

    /// [`Problem::add_residual`] for an already boxed residual.
    ///
    /// # Errors
    /// [`Error::UnknownBlock`] for a block this problem did not issue;
    /// [`Error::BlockShape`] when the blocks differ in count or length from the residual's
    /// [`DynResidual::block_sizes`].
    pub fn add_dyn_residual(
        &mut self,
        residual: Box<dyn DynResidual>,
        blocks: &[BlockId],
        owner: ConstraintId,
    ) -> Result<ResidualId> {
        self.add_shared_residual(Arc::from(residual), blocks, owner)
    }

    /// [`Problem::add_residual`] for a shared residual: the problem keeps a reference to it,
    /// so one residual can serve several problems (the solves of one sketch component, say)
    /// without being copied.
    ///
    /// ```
    /// use std::sync::Arc;
    /// use camber_solve::{scalar::cst, ConstraintId, DynResidual, Problem, Residual, Scalar};
    ///
    /// /// x = 1.
    /// #[derive(Debug)]
    /// struct IsOne;
    /// impl Residual for IsOne {
    ///     fn name(&self) -> &str { "is one" }
    ///     fn dim(&self) -> usize { 1 }
    ///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) { out[0] = x[0][0] - cst(1.0); }
    ///     fn is_affine(&self) -> bool { true }
    /// }
    ///
    /// let shared: Arc<dyn DynResidual> = Arc::new(IsOne);
    /// let (mut p, mut q) = (Problem::new(), Problem::new());
    /// let (b, c) = (p.add_block(&[0.0])?, q.add_block(&[2.0])?);
    /// p.add_shared_residual(shared.clone(), &[b], ConstraintId(1))?;
    /// q.add_shared_residual(shared, &[c], ConstraintId(1))?;
    /// assert_eq!((p.num_rows(), q.num_rows()), (1, 1));
    /// # Ok::<(), camber_solve::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Problem::add_dyn_residual`].
    pub fn add_shared_residual(
        &mut self,
        residual: Arc<dyn DynResidual>,
        blocks: &[BlockId],
        owner: ConstraintId,
    ) -> Result<ResidualId> {
        let mut spans: SmallVec<[(usize, usize); 8]> = SmallVec::with_capacity(blocks.len());
        for b in blocks {
            spans.push(self.block_range(*b)?);
        }
        let found: SmallVec<[usize; 8]> = spans.iter().map(|(_, len)| *len).collect();
        if !residual.accepts_block_sizes(&found) {
            return Err(Error::BlockShape {
                residual: residual.name().to_owned(),
                owner,
                expected: residual.block_sizes().unwrap_or_default(),
                found: found.to_vec(),
            });
        }
        let (dim, affine) = (residual.dim(), residual.is_affine());
        self.touch();
        let spans_at = self.spans.len();
        self.spans.extend_from_slice(&spans);
        self.residuals.push(ResidualBlock {
            residual,
            blocks: SmallVec::from_slice(blocks),
            spans_at,
            dim,
            affine,
            owner,
            priority: 0,
        });
        Ok(ResidualId(self.residuals.len() - 1))
    }
}

/// # Priorities
impl Problem {
    /// Gives every residual block owned by `owner` the priority tier `priority`: 0 (the
    /// default) is required; 1, 2, … may be relaxed, the higher tiers first, when the whole set
    /// cannot be met (met tier by tier, see [`crate::solve()`]). Returns how many residual blocks it changed.
    ///
    /// ```
    /// use camber_solve::{solve, ConstraintId, Options, Problem, Residual, Scalar, Status};
    /// use camber_solve::scalar::cst;
    /// /// x = a.
    /// #[derive(Debug)]
    /// struct XIs(f64);
    /// impl Residual for XIs {
    ///     fn name(&self) -> &str { "x is" }
    ///     fn dim(&self) -> usize { 1 }
    ///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) { out[0] = x[0][0] - cst(self.0); }
    ///     fn is_affine(&self) -> bool { true }
    /// }
    /// let mut p = Problem::new();
    /// let b = p.add_block(&[0.0])?;
    /// p.add_residual(XIs(1.0), &[b], ConstraintId(1))?;
    /// p.add_residual(XIs(2.0), &[b], ConstraintId(2))?;
    /// assert_eq!(p.set_priority(ConstraintId(2), 1), 1);
    /// let report = solve(&mut p, &Options::default())?;
    /// // x = 1 is required; x = 2 is relaxed, and the report says so.
    /// assert_eq!(report.status, Status::Relaxed);
    /// assert_eq!(report.conflicting, vec![ConstraintId(2)]);
    /// assert!((p.values()[0] - 1.0).abs() < 1e-12);
    /// # Ok::<(), camber_solve::Error>(())
    /// ```
    pub fn set_priority(
        &mut self,
        owner: ConstraintId,
        priority: crate::model::priority::Priority,
    ) -> usize {
        let mut changed = 0;
        for rb in self.residuals.iter_mut().filter(|rb| rb.owner == owner) {
            if rb.priority != priority {
                rb.priority = priority;
                changed += 1;
            }
        }
        if changed > 0 {
            self.touch();
        }
        changed
    }

    /// The priority tier of `owner`'s residual blocks (0 when it owns none).
    pub fn priority(&self, owner: ConstraintId) -> crate::model::priority::Priority {
        self.residuals
            .iter()
            .find(|rb| rb.owner == owner)
            .map_or(0, |rb| rb.priority)
    }

    /// Whether any residual block may be relaxed (has a priority above 0).
    pub fn has_priorities(&self) -> bool {
        self.residuals.iter().any(|rb| rb.priority > 0)
    }
}

/// The values of a problem's unknowns and auxiliary unknowns at one moment, to go back to
/// ([`Problem::state`], [`Problem::restore`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ProblemState {
    values: Vec<f64>,
    aux_values: Vec<f64>,
}

/// # The evaluation budget
///
/// A failing solve tries every path in turn (Newton, SLSQP, Levenberg–Marquardt, a moved
/// start); a caller that runs the whole cascade several times (from other starts, in
/// active-set rounds) shares one budget between the runs by starting it around them. Each
/// evaluation of the residuals, their Jacobian or a Hessian costs one unit; once the budget
/// is spent, the paths stop and the solve reports [`Error::NotSolved`].
///
/// ```
/// use camber_solve::{scalar::cst, ConstraintId, Options, Problem, Residual, Scalar};
///
/// /// |p|² = 1: the point lies on the unit circle.
/// #[derive(Debug)]
/// struct OnUnitCircle;
/// impl Residual for OnUnitCircle {
///     fn name(&self) -> &str { "on unit circle" }
///     fn dim(&self) -> usize { 1 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
///         out[0] = x[0][0] * x[0][0] + x[0][1] * x[0][1] - cst(1.0);
///     }
/// }
///
/// let mut p = Problem::new();
/// let b = p.add_block(&[3.0, 0.5])?;
/// p.add_residual(OnUnitCircle, &[b], ConstraintId(1))?;
/// p.start_budget(Some(2));
/// let options = Options::default();
/// assert!(camber_solve::solve(&mut p, &options).is_err(), "two evaluations are not enough");
/// assert_eq!(p.values(), &[3.0, 0.5], "a failed solve leaves the problem as it was");
/// p.end_budget();
/// camber_solve::solve(&mut p, &options)?;
/// assert!(p.evaluations_spent() > 2);
/// # Ok::<(), camber_solve::Error>(())
/// ```
impl Problem {
    /// Starts a budget of `limit` evaluations (`None`: counted, never refused), shared by every
    /// solve of this problem until [`Problem::end_budget`]. While it runs, a solve does not
    /// start its own ([`crate::NonlinearOptions::max_evaluations`]).
    pub fn start_budget(&mut self, limit: Option<usize>) {
        self.budget.start(limit);
    }

    /// Ends the running budget.
    pub fn end_budget(&mut self) {
        self.budget.end();
    }

    /// Watches `cancel` in every evaluation charged from now on: once it is raised, the solve
    /// stops at its next evaluation with [`crate::Error::Cancelled`] ([`crate::Options::cancel`];
    /// a solve that starts its own budget sets it from its options).
    pub fn set_cancel(&mut self, cancel: Option<crate::model::options::CancelFlag>) {
        self.budget.set_cancel(cancel);
    }

    /// Evaluations spent since the budget last started.
    pub fn evaluations_spent(&self) -> usize {
        self.budget.spent()
    }

    /// Whether a budget runs and every evaluation it allowed is spent.
    pub fn budget_spent(&self) -> bool {
        self.budget.exhausted()
    }
}

/// # Editing rows and states
impl Problem {
    /// Removes every residual block after the first `count` (rows added last, such as the
    /// active rows of an inequality, can be taken back without rebuilding the problem).
    /// Nothing happens when there are `count` or fewer.
    pub fn truncate_residuals(&mut self, count: usize) {
        if let Some(first) = self.residuals.get(count) {
            self.spans.truncate(first.spans_at);
            self.shape_stamp = next_stamp();
        }
        self.residuals.truncate(count);
    }

    /// The current values of the unknowns and auxiliary unknowns.
    pub fn state(&self) -> ProblemState {
        ProblemState {
            values: self.values.clone(),
            aux_values: self.aux_values.clone(),
        }
    }

    /// Writes the current values into `state`, reusing its storage (a state taken at every
    /// step of a drag allocates nothing).
    pub fn save_state(&self, state: &mut ProblemState) {
        state.values.clear();
        state.values.extend_from_slice(&self.values);
        state.aux_values.clear();
        state.aux_values.extend_from_slice(&self.aux_values);
    }

    /// Goes back to a state taken from this problem (blocks and auxiliaries added since keep
    /// their values).
    ///
    /// ```
    /// use camber_solve::Problem;
    /// let mut p = Problem::new();
    /// let b = p.add_block(&[1.0, 2.0])?;
    /// let saved = p.state();
    /// p.set_block_values(b, &[5.0, 6.0])?;
    /// p.restore(&saved);
    /// assert_eq!(p.values(), &[1.0, 2.0]);
    /// # Ok::<(), camber_solve::Error>(())
    /// ```
    pub fn restore(&mut self, state: &ProblemState) {
        let n = state.values.len().min(self.values.len());
        self.values[..n].copy_from_slice(&state.values[..n]);
        let m = state.aux_values.len().min(self.aux_values.len());
        self.aux_values[..m].copy_from_slice(&state.aux_values[..m]);
    }
}

/// # Bindings, bounds and weights
impl Problem {
    /// Fixes x_i at its current value.
    ///
    /// # Errors
    /// [`Error::UnknownUnknown`] for an unknown this problem did not issue.
    pub fn fix(&mut self, unknown: UnknownId) -> Result<()> {
        *self.binding_mut(unknown)? = Binding::Fixed;
        Ok(())
    }

    /// Fixes every unknown of a block.
    ///
    /// # Errors
    /// [`Error::UnknownBlock`] for a block this problem did not issue.
    pub fn fix_block(&mut self, block: BlockId) -> Result<()> {
        let (start, len) = self.block_range(block)?;
        self.touch();
        for b in &mut self.bindings[start..start + len] {
            *b = Binding::Fixed;
        }
        Ok(())
    }

    /// Makes x_i free again (own reduced unknown), undoing a fix or a substitution.
    ///
    /// # Errors
    /// [`Error::UnknownUnknown`] for an unknown this problem did not issue.
    pub fn free(&mut self, unknown: UnknownId) -> Result<()> {
        *self.binding_mut(unknown)? = Binding::Free;
        Ok(())
    }

    /// Substitutes x_i = Σ coefficient·z(var) + constant, where each var is the own reduced
    /// unknown of a free unknown, the value of a fixed unknown, or an auxiliary unknown.
    /// Substitutions do not chain; that is checked when the reduced map is built.
    ///
    /// # Errors
    /// Unknown ids ([`Error::UnknownUnknown`], [`Error::UnknownAux`]) and non-finite numbers
    /// ([`Error::NonFinite`]).
    pub fn substitute(
        &mut self,
        unknown: UnknownId,
        terms: &[(Var, f64)],
        constant: f64,
    ) -> Result<()> {
        for (k, (var, a)) in terms.iter().enumerate() {
            self.check_var(*var)?;
            check_finite_at("substitution coefficient", k, *a)?;
        }
        check_finite("substitution constant", &[constant])?;
        *self.binding_mut(unknown)? = Binding::Affine {
            terms: terms.to_vec(),
            constant,
        };
        Ok(())
    }

    /// Merges `target` into `source`: x_target = x_source, both moved by the one reduced unknown
    /// of `source` (which must not be substituted itself).
    ///
    /// # Errors
    /// As [`Problem::substitute`].
    pub fn merge(&mut self, target: UnknownId, source: UnknownId) -> Result<()> {
        self.substitute(target, &[(Var::Unknown(source), 1.0)], 0.0)
    }

    /// Merges every unknown of `members` into `representative` (x_m = x_r), the way coincident
    /// points become one: when the representative is free it starts at the weighted mean
    /// Σ w_i·x_i / Σ w_i of the group (its reduced unknown then carries the weight Σ w_i, see
    /// [`Problem::reduced_map`]), so the least weighted move of the merged unknown is the least
    /// move of every member: Σ w_i·(z − x_i)² = (Σ w_i)·(z − x̄)² + const. A fixed
    /// representative keeps its value, and the members take it.
    ///
    /// ```
    /// use camber_solve::{Problem, UnknownId};
    /// let mut p = Problem::new();
    /// let a = p.add_block(&[0.0])?;
    /// let b = p.add_block(&[3.0])?;
    /// let (ua, ub) = (p.unknown(a, 0)?, p.unknown(b, 0)?);
    /// p.merge_group(ua, &[ub])?;
    /// let map = p.reduced_map()?;
    /// assert_eq!(map.len(), 1);
    /// assert!((map.z0()[0] - 1.5).abs() < 1e-15 && (map.weights()[0] - 2.0).abs() < 1e-15);
    /// # Ok::<(), camber_solve::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Problem::substitute`].
    pub fn merge_group(&mut self, representative: UnknownId, members: &[UnknownId]) -> Result<()> {
        // Every id is checked before anything changes; the bindings are then written directly
        // (what `merge` would write, without checking the one representative per member).
        let representative_free = matches!(self.binding(representative)?, Binding::Free);
        for m in members {
            self.binding(*m)?;
        }
        self.touch();
        if representative_free {
            let (mut sum, mut total) = (0.0, 0.0);
            for u in std::iter::once(&representative).chain(members) {
                let w = self.weights[u.0];
                sum += w * self.values[u.0];
                total += w;
            }
            if total > 0.0 {
                self.values[representative.0] = sum / total;
            }
        }
        for m in members {
            self.bindings[m.0] = Binding::Affine {
                terms: vec![(Var::Unknown(representative), 1.0)],
                constant: 0.0,
            };
        }
        Ok(())
    }

    /// The tangency elimination x_target,k = x_base,k + t·direction_k for every k, with t a
    /// new auxiliary unknown starting at `t0` (returned). The targets stop being unknowns of
    /// their own; the bases must not be substituted themselves (free or fixed).
    ///
    /// # Errors
    /// [`Error::Dimension`] when the three slices differ in length, plus those of
    /// [`Problem::substitute`].
    pub fn eliminate(
        &mut self,
        targets: &[UnknownId],
        bases: &[UnknownId],
        direction: &[f64],
        t0: f64,
    ) -> Result<AuxId> {
        crate::model::errors::check_len("elimination bases", targets.len(), bases.len())?;
        crate::model::errors::check_len("elimination direction", targets.len(), direction.len())?;
        for u in targets.iter().chain(bases) {
            self.binding(*u)?;
        }
        check_finite("elimination direction", direction)?;
        let t = self.add_aux(t0)?;
        for ((target, base), d) in targets.iter().zip(bases).zip(direction) {
            self.substitute(
                *target,
                &[(Var::Unknown(*base), 1.0), (Var::Aux(t), *d)],
                0.0,
            )?;
        }
        Ok(t)
    }

    /// Bounds lower ≤ value ≤ upper on an unknown x_i or an auxiliary unknown. The linear
    /// solver does not steer by bounds; it refuses a result that violates one
    /// ([`Error::OutOfBounds`]). Infinite bounds are allowed.
    ///
    /// # Errors
    /// Unknown ids; [`Error::NonFinite`] for a NaN bound; [`Error::InvalidBounds`] when
    /// lower > upper.
    pub fn set_bounds(&mut self, var: Var, lower: f64, upper: f64) -> Result<()> {
        if lower.is_nan() || upper.is_nan() {
            return Err(Error::NonFinite {
                what: "bound",
                index: 0,
                value: f64::NAN,
            });
        }
        let slot = match var {
            Var::Unknown(u) => {
                self.binding(u)?;
                &mut self.bounds[u.0]
            }
            Var::Aux(a) => {
                self.check_var(var)?;
                &mut self.aux_bounds[a.0]
            }
        };
        self.shape_stamp = next_stamp();
        if lower > upper {
            let unknown = match var {
                Var::Unknown(u) => u.0,
                Var::Aux(a) => a.0,
            };
            return Err(Error::InvalidBounds {
                unknown,
                lower,
                upper,
            });
        }
        *slot = (lower, upper);
        Ok(())
    }

    /// The weight w > 0 of a reduced unknown in the metric ‖Δz‖²_W = Σ w_k Δz_k²: a larger weight
    /// makes that unknown costlier to move. It applies to free unknowns and auxiliary unknowns.
    ///
    /// # Errors
    /// Unknown ids; [`Error::NonPositiveWeight`] for w ≤ 0 or non-finite.
    pub fn set_weight(&mut self, var: Var, weight: f64) -> Result<()> {
        self.check_var(var)?;
        let index = match var {
            Var::Unknown(u) => u.0,
            Var::Aux(a) => a.0,
        };
        if !(weight.is_finite() && weight > 0.0) {
            return Err(Error::NonPositiveWeight {
                index,
                value: weight,
            });
        }
        self.touch();
        match var {
            Var::Unknown(u) => self.weights[u.0] = weight,
            Var::Aux(a) => self.aux_weights[a.0] = weight,
        }
        Ok(())
    }
}

/// # Changes of structure and of residuals
impl Problem {
    /// Marks a change of structure.
    fn touch(&mut self) {
        self.shape_stamp = next_stamp();
    }

    /// The stamps of the problem's structure and residual objects: equal stamps mean nothing
    /// but values changed in between (see [`Stamps`]).
    ///
    /// ```
    /// use camber_solve::Problem;
    /// let mut p = Problem::new();
    /// let b = p.add_block(&[1.0, 2.0])?;
    /// let before = p.stamps();
    /// p.set_block_values(b, &[3.0, 4.0])?;
    /// assert_eq!(p.stamps(), before); // values only
    /// p.fix_block(b)?;
    /// assert_ne!(p.stamps().shape, before.shape);
    /// # Ok::<(), camber_solve::Error>(())
    /// ```
    pub fn stamps(&self) -> Stamps {
        Stamps {
            shape: self.shape_stamp,
            residuals: self.residual_stamp,
        }
    }

    /// Replaces the residual object of a residual block by another of the same rows, blocks and
    /// affinity (a dimension's new value, a pin's new target): a change of values, which a
    /// plan kept between solves takes without being made again.
    ///
    /// ```
    /// use std::sync::Arc;
    /// use camber_solve::{scalar::cst, ConstraintId, Problem, Residual, Scalar};
    /// /// x = v.
    /// #[derive(Debug)]
    /// struct Is(f64);
    /// impl Residual for Is {
    ///     fn name(&self) -> &str { "is" }
    ///     fn dim(&self) -> usize { 1 }
    ///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) { out[0] = x[0][0] - cst(self.0); }
    ///     fn is_affine(&self) -> bool { true }
    /// }
    /// let mut p = Problem::new();
    /// let b = p.add_block(&[0.0])?;
    /// let r = p.add_residual(Is(1.0), &[b], ConstraintId(1))?;
    /// let shape = p.stamps().shape;
    /// p.replace_residual(r, Arc::new(Is(2.0)))?;
    /// assert_eq!(p.stamps().shape, shape);
    /// let mut g = [0.0];
    /// p.evaluate_at(&[0.0], &mut g)?;
    /// assert!((g[0] + 2.0).abs() < 1e-15);
    /// # Ok::<(), camber_solve::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::UnknownUnknown`] for a residual block this problem did not issue;
    /// [`Error::BlockShape`] when the new residual differs in rows, blocks or affinity.
    pub fn replace_residual(
        &mut self,
        residual: ResidualId,
        with: Arc<dyn DynResidual>,
    ) -> Result<()> {
        let count = self.residuals.len();
        let rb = self
            .residuals
            .get(residual.0)
            .ok_or(Error::UnknownUnknown {
                index: residual.0,
                len: count,
            })?;
        let found: SmallVec<[usize; 8]> = self.spans_of(rb).iter().map(|(_, l)| *l).collect();
        if with.dim() != rb.dim
            || with.is_affine() != rb.affine
            || !with.accepts_block_sizes(&found)
        {
            return Err(Error::BlockShape {
                residual: with.name().to_owned(),
                owner: rb.owner,
                expected: with.block_sizes().unwrap_or_default(),
                found: found.to_vec(),
            });
        }
        self.residuals[residual.0].residual = with;
        self.residual_stamp = next_stamp();
        Ok(())
    }
}

/// # Access
impl Problem {
    /// All unknowns x, blocks laid end to end.
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// Number of unknowns x (fixed and substituted ones included).
    pub fn num_unknowns(&self) -> usize {
        self.values.len()
    }

    /// Number of parameter blocks.
    pub fn num_blocks(&self) -> usize {
        self.blocks.len()
    }

    /// Number of auxiliary unknowns.
    pub fn num_aux(&self) -> usize {
        self.aux_values.len()
    }

    /// Number of residual blocks.
    pub fn num_residuals(&self) -> usize {
        self.residuals.len()
    }

    /// Number of residual rows (Σ dim over residual blocks).
    pub fn num_rows(&self) -> usize {
        self.residuals.iter().map(|r| r.dim).sum()
    }

    /// The values of a block.
    ///
    /// # Errors
    /// [`Error::UnknownBlock`].
    pub fn block_values(&self, block: BlockId) -> Result<&[f64]> {
        let (start, len) = self.block_range(block)?;
        Ok(&self.values[start..start + len])
    }

    /// Overwrites the values of a block (fixed unknowns included).
    ///
    /// # Errors
    /// [`Error::UnknownBlock`], [`Error::Dimension`], [`Error::NonFinite`].
    pub fn set_block_values(&mut self, block: BlockId, values: &[f64]) -> Result<()> {
        let (start, len) = self.block_range(block)?;
        crate::model::errors::check_len("block values", len, values.len())?;
        check_finite("block value", values)?;
        self.values[start..start + len].copy_from_slice(values);
        Ok(())
    }

    /// The unknown at `offset` inside `block`.
    ///
    /// # Errors
    /// [`Error::UnknownBlock`], or [`Error::UnknownUnknown`] for an offset past the block.
    pub fn unknown(&self, block: BlockId, offset: usize) -> Result<UnknownId> {
        let (start, len) = self.block_range(block)?;
        if offset >= len {
            return Err(Error::UnknownUnknown { index: offset, len });
        }
        Ok(UnknownId(start + offset))
    }

    /// How an unknown is bound.
    ///
    /// # Errors
    /// [`Error::UnknownUnknown`].
    pub fn binding(&self, unknown: UnknownId) -> Result<&Binding> {
        let len = self.bindings.len();
        self.bindings.get(unknown.0).ok_or(Error::UnknownUnknown {
            index: unknown.0,
            len,
        })
    }

    /// The current value of an auxiliary unknown.
    ///
    /// # Errors
    /// [`Error::UnknownAux`].
    pub fn aux_value(&self, aux: AuxId) -> Result<f64> {
        let len = self.aux_values.len();
        self.aux_values
            .get(aux.0)
            .copied()
            .ok_or(Error::UnknownAux { aux: aux.0, len })
    }

    /// The constraint owning a residual block, and the residual's name.
    ///
    /// # Errors
    /// [`Error::UnknownUnknown`] for a residual id past the end.
    pub fn residual_owner(&self, residual: ResidualId) -> Result<(ConstraintId, &str)> {
        let len = self.residuals.len();
        self.residuals
            .get(residual.0)
            .map(|r| (r.owner, r.residual.name()))
            .ok_or(Error::UnknownUnknown {
                index: residual.0,
                len,
            })
    }

    /// The residual blocks `owner` owns, in the order they were added (those a dimension's new
    /// value replaces, [`Problem::replace_residual`]).
    pub fn residuals_of(&self, owner: ConstraintId) -> Vec<ResidualId> {
        self.residuals
            .iter()
            .enumerate()
            .filter(|(_, rb)| rb.owner == owner)
            .map(|(i, _)| ResidualId(i))
            .collect()
    }

    /// The constraint owning each residual row, in row order.
    pub fn row_owners(&self) -> Vec<ConstraintId> {
        let mut out = Vec::with_capacity(self.num_rows());
        for rb in &self.residuals {
            out.extend(std::iter::repeat_n(rb.owner, rb.dim));
        }
        out
    }

    /// Evaluates every residual at the unknowns `x` (a full vector, as [`Problem::values`]),
    /// writing the stacked rows into `g` ([`Problem::num_rows`] entries).
    ///
    /// # Errors
    /// [`Error::Dimension`] for wrong lengths, [`Error::NonFiniteResidual`] for a NaN result.
    pub fn evaluate_at(&self, x: &[f64], g: &mut [f64]) -> Result<()> {
        crate::model::errors::check_len("unknowns", self.values.len(), x.len())?;
        crate::model::errors::check_len("residual rows", self.num_rows(), g.len())?;
        let mut row = 0;
        let mut slices = SmallVec::new();
        for rb in &self.residuals {
            gather_into(x, self.spans_of(rb), &mut slices);
            let out = &mut g[row..row + rb.dim];
            rb.residual.values(&slices, out)?;
            check_residual(rb, out)?;
            row += rb.dim;
        }
        Ok(())
    }

    /// Slices of `x` for the given blocks (ids already validated by `add_residual`).
    pub(crate) fn gather<'a>(&self, x: &'a [f64], blocks: &[BlockId]) -> SmallVec<[&'a [f64]; 8]> {
        // A plain loop: the iterator `collect` of SmallVec costs several times more for the
        // one to four blocks of most residuals, at every evaluation.
        let mut out = SmallVec::new();
        for b in blocks {
            let (start, len) = self.blocks.get(b.0).copied().unwrap_or((0, 0));
            out.push(x.get(start..start + len).unwrap_or(&[]));
        }
        out
    }

    /// (first unknown, length) of every block a residual block reads, in order.
    #[inline]
    pub(crate) fn spans_of(&self, rb: &ResidualBlock) -> &[(usize, usize)] {
        self.spans
            .get(rb.spans_at..rb.spans_at + rb.blocks.len())
            .unwrap_or(&[])
    }

    /// The first unknown and the length of a block. The error is built only on a miss: this
    /// runs for every block of every residual at every evaluation.
    pub(crate) fn block_range(&self, block: BlockId) -> Result<(usize, usize)> {
        match self.blocks.get(block.0) {
            Some(range) => Ok(*range),
            None => Err(Error::UnknownBlock {
                block: block.0,
                blocks: self.blocks.len(),
            }),
        }
    }

    fn binding_mut(&mut self, unknown: UnknownId) -> Result<&mut Binding> {
        self.shape_stamp = next_stamp();
        let len = self.bindings.len();
        self.bindings
            .get_mut(unknown.0)
            .ok_or(Error::UnknownUnknown {
                index: unknown.0,
                len,
            })
    }

    fn check_var(&self, var: Var) -> Result<()> {
        match var {
            Var::Unknown(u) => self.binding(u).map(|_| ()),
            Var::Aux(a) => self.aux_value(a).map(|_| ()),
        }
    }
}

/// Slices of `x` for the spans (first unknown, length) of a residual's blocks
/// ([`Problem::spans_of`]), written over `out`: one list serves every residual of an
/// evaluation (a list returned per residual was a copy of its inline storage each time).
#[inline]
pub(crate) fn gather_into<'a>(
    x: &'a [f64],
    spans: &[(usize, usize)],
    out: &mut SmallVec<[&'a [f64]; 8]>,
) {
    out.clear();
    // A plain loop: the iterator `extend` of SmallVec costs more for the one to four blocks
    // of most residuals.
    for (start, len) in spans {
        out.push(x.get(*start..*start + *len).unwrap_or(&[]));
    }
}

/// Rejects a NaN or infinite residual value, naming the owner.
pub(crate) fn check_residual(rb: &ResidualBlock, out: &[f64]) -> Result<()> {
    match out.iter().position(|v| !v.is_finite()) {
        None => Ok(()),
        Some(row) => Err(Error::NonFiniteResidual {
            constraint: rb.owner,
            name: rb.residual.name().to_owned(),
            row,
            value: out[row],
        }),
    }
}

fn check_finite(what: &'static str, values: &[f64]) -> Result<()> {
    for (index, v) in values.iter().enumerate() {
        check_finite_at(what, index, *v)?;
    }
    Ok(())
}

fn check_finite_at(what: &'static str, index: usize, value: f64) -> Result<()> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(Error::NonFinite { what, index, value })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_are_checked() {
        let mut p = Problem::new();
        let b = p.add_block(&[1.0, 2.0]).unwrap();
        assert_eq!(
            p.unknown(b, 2),
            Err(Error::UnknownUnknown { index: 2, len: 2 })
        );
        assert_eq!(
            p.fix_block(BlockId(3)),
            Err(Error::UnknownBlock {
                block: 3,
                blocks: 1
            })
        );
        assert_eq!(
            p.fix(UnknownId(5)),
            Err(Error::UnknownUnknown { index: 5, len: 2 })
        );
        assert_eq!(
            p.aux_value(AuxId(0)),
            Err(Error::UnknownAux { aux: 0, len: 0 })
        );
        let u = p.unknown(b, 1).unwrap();
        assert_eq!(
            p.set_bounds(Var::Unknown(u), 2.0, 1.0),
            Err(Error::InvalidBounds {
                unknown: 1,
                lower: 2.0,
                upper: 1.0
            })
        );
        assert_eq!(
            p.set_weight(Var::Unknown(u), 0.0),
            Err(Error::NonPositiveWeight {
                index: 1,
                value: 0.0
            })
        );
        assert!(matches!(
            p.substitute(u, &[(Var::Aux(AuxId(0)), 1.0)], 0.0),
            Err(Error::UnknownAux { aux: 0, .. })
        ));
        assert_eq!(
            p.eliminate(&[u], &[], &[1.0], 0.0),
            Err(Error::Dimension {
                what: "elimination bases",
                expected: 1,
                found: 0
            })
        );
        assert_eq!(p.num_aux(), 0, "a failed elimination declares nothing");
        assert!(matches!(
            p.set_block_values(b, &[1.0, f64::NAN]),
            Err(Error::NonFinite { index: 1, .. })
        ));
        assert_eq!(p.values(), &[1.0, 2.0]);
    }

    #[test]
    fn bindings_are_recorded() {
        let mut p = Problem::new();
        let b0 = p.add_block(&[0.0, 0.0]).unwrap();
        let b1 = p.add_block(&[1.0, 1.0]).unwrap();
        let (x0, y0) = (p.unknown(b0, 0).unwrap(), p.unknown(b0, 1).unwrap());
        let (x1, y1) = (p.unknown(b1, 0).unwrap(), p.unknown(b1, 1).unwrap());
        let t = p.eliminate(&[x1, y1], &[x0, y0], &[1.0, 0.0], 0.5).unwrap();
        assert_eq!(
            p.binding(x1).unwrap(),
            &Binding::Affine {
                terms: vec![(Var::Unknown(x0), 1.0), (Var::Aux(t), 1.0)],
                constant: 0.0
            }
        );
        p.fix(y0).unwrap();
        assert_eq!(p.binding(y0).unwrap(), &Binding::Fixed);
        p.free(y0).unwrap();
        assert_eq!(p.binding(y0).unwrap(), &Binding::Free);
        assert!((p.aux_value(t).unwrap() - 0.5).abs() < 1e-15);
    }

    /// g = x₀ + 2·x₁ − c over one block (x₀) and another (x₁), declaring two blocks of one.
    #[derive(Debug)]
    struct Sum(f64);
    impl Residual for Sum {
        fn name(&self) -> &str {
            "sum"
        }
        fn dim(&self) -> usize {
            1
        }
        fn block_sizes(&self) -> Option<Vec<usize>> {
            Some(vec![1, 1])
        }
        fn eval<T: crate::Scalar>(&self, x: &[&[T]], out: &mut [T]) {
            out[0] = x[0][0] + x[1][0] * crate::model::scalar::cst(2.0)
                - crate::model::scalar::cst(self.0);
        }
        fn is_affine(&self) -> bool {
            true
        }
    }

    /// The rows a problem's residuals give at `x`, one residual at a time by hand.
    fn by_hand(p: &Problem, x: &[f64]) -> Vec<f64> {
        let mut out = Vec::new();
        for rb in &p.residuals {
            let slices: Vec<&[f64]> = rb
                .blocks
                .iter()
                .map(|b| {
                    let (start, len) = p.blocks[b.0];
                    &x[start..start + len]
                })
                .collect();
            let mut g = vec![0.0; rb.residual.dim()];
            rb.residual.values(&slices, &mut g).unwrap();
            out.extend(g);
        }
        out
    }

    #[test]
    fn spans_follow_added_and_truncated_residuals() {
        let mut p = Problem::new();
        let a = p.add_block(&[1.0]).unwrap();
        let b = p.add_block(&[2.0, 3.0]).unwrap();
        let c = p.add_block(&[4.0]).unwrap();
        p.add_residual(Sum(0.5), &[a, c], ConstraintId(1)).unwrap();
        p.add_residual(Sum(1.5), &[c, a], ConstraintId(2)).unwrap();
        // A refused residual leaves no spans behind.
        assert!(matches!(
            p.add_residual(Sum(0.0), &[a, b], ConstraintId(3)),
            Err(Error::BlockShape { ref expected, ref found, .. })
                if expected == &vec![1, 1] && found == &vec![1, 2]
        ));
        p.truncate_residuals(1);
        p.add_residual(Sum(-1.0), &[c, c], ConstraintId(4)).unwrap();
        assert_eq!(p.spans, vec![(0, 1), (3, 1), (3, 1), (3, 1)]);
        let x = [0.25, 7.0, 8.0, -1.5];
        let mut g = vec![0.0; p.num_rows()];
        p.evaluate_at(&x, &mut g).unwrap();
        assert_eq!(g, by_hand(&p, &x));
        assert_eq!(g, vec![0.25 - 3.0 - 0.5, -1.5 - 3.0 + 1.0]);
    }

    #[test]
    fn merging_a_group_checks_every_id_before_changing_anything() {
        let mut p = Problem::new();
        let b = p.add_block(&[1.0, 3.0]).unwrap();
        let (u0, u1) = (p.unknown(b, 0).unwrap(), p.unknown(b, 1).unwrap());
        assert_eq!(
            p.merge_group(u0, &[u1, UnknownId(9)]),
            Err(Error::UnknownUnknown { index: 9, len: 2 })
        );
        assert_eq!(p.binding(u1).unwrap(), &Binding::Free);
        assert_eq!(p.values(), &[1.0, 3.0]);
        p.merge_group(u0, &[u1]).unwrap();
        assert_eq!(
            p.binding(u1).unwrap(),
            &Binding::Affine {
                terms: vec![(Var::Unknown(u0), 1.0)],
                constant: 0.0
            }
        );
        assert!((p.values()[0] - 2.0).abs() < 1e-15);
    }
}
