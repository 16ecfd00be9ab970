//! Typed ids: parameter blocks, single unknowns, auxiliary reduced unknowns, residual blocks and
//! the caller's constraint ids.
//!
//! Ids other than [`ConstraintId`] are handed out by [`crate::Problem`] and are only meaningful
//! for the problem that issued them.

/// A parameter block of a [`crate::Problem`]: a contiguous run of unknowns (for example the x and
/// y of one control point).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct BlockId(pub(crate) usize);

impl BlockId {
    /// Position of the block in the order blocks were added (0-based).
    pub fn index(self) -> usize {
        self.0
    }
}

/// One unknown x_i of a [`crate::Problem`], by its position in the flat vector of unknowns.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct UnknownId(pub(crate) usize);

impl UnknownId {
    /// Position of the unknown in the flat vector x (blocks laid end to end, 0-based).
    pub fn index(self) -> usize {
        self.0
    }
}

/// An auxiliary reduced unknown: a z that is not the own variable of any x (for example the
/// scalar t of the tangency elimination x_P1 = x_P0 + t·T).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct AuxId(pub(crate) usize);

impl AuxId {
    /// Position of the auxiliary unknown in the order it was declared (0-based).
    pub fn index(self) -> usize {
        self.0
    }
}

/// A residual block of a [`crate::Problem`], in the order residuals were added.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ResidualId(pub(crate) usize);

impl ResidualId {
    /// Position of the residual block in the order it was added (0-based).
    pub fn index(self) -> usize {
        self.0
    }
}

/// The caller's id of the constraint a residual block belongs to. camber-solve never interprets
/// it; reports and errors name constraints by it.
///
/// ```
/// use camber_solve::ConstraintId;
/// let id = ConstraintId(7);
/// assert_eq!(id.0, 7);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
#[serde(transparent)]
pub struct ConstraintId(pub u64);

impl std::fmt::Display for ConstraintId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "constraint {}", self.0)
    }
}

/// A reduced unknown z referred to by an affine substitution: either the own variable of a free
/// unknown x_i (z = x_i at the start of a solve) or an auxiliary unknown.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Var {
    /// The own reduced variable of a free (neither fixed nor substituted) unknown.
    Unknown(UnknownId),
    /// An auxiliary unknown declared with [`crate::Problem::add_aux`].
    Aux(AuxId),
}
