//! Coincident points as one set of unknowns.
//!
//! A coincidence between two point blocks, P_a − P_b = 0 (a [`Constraint::Coincident`] or the
//! joint of a G1/G2 join), is two affine rows when written as a residual. Binding P_b to P_a
//! instead ([`camber_solve::Problem::merge`]) removes the two rows and the two unknowns: the
//! problem shrinks, every factorization and every residual reading the joint gets cheaper, and
//! the minimum-norm metric is unchanged because the merged unknown carries both points' weights
//! (see [`camber_solve::ReducedMap`]).
//!
//! Points linked by coincidences form classes (union–find). A class is bound to one
//! representative; it can be merged only if it holds at most one block that must stay its own
//! unknown or constant (a fixed point, or the base of a tangent elimination, which another
//! point's binding refers to), and no elimination target (already bound). A coincidence that
//! would break that rule stays a pair of rows, so conflicts between two fixed points are still
//! found and named. A coincidence between points already in one class is redundant: its rows
//! would be identically zero, and the analysis names its constraint.
//!
//! [`Constraint::Coincident`]: crate::constraints::Coincident

use camber_solve::{BlockId, ConstraintId};

use crate::constraints::piece::Piece;
use crate::ground::errors::Result;

/// The merges of one component: which pieces became bindings and which were redundant.
#[derive(Debug, Default)]
pub(crate) struct Merges {
    /// Every merged block and the block it is bound to, by increasing block.
    pub(crate) into: Vec<(BlockId, BlockId)>,
    /// (constraint position, piece position) of the coincidences replaced by bindings, in
    /// increasing order.
    pub(crate) replaced: Vec<(usize, usize)>,
    /// Constraints with a coincidence between points already merged.
    pub(crate) redundant: Vec<ConstraintId>,
}

/// The two blocks of a pure coincidence P_a − P_b = 0 (coefficients +1 and −1, zero target),
/// or `None` for any other piece.
pub(crate) fn coincidence(
    piece: &Piece,
    block: impl Fn(crate::ground::ids::EntityId, usize) -> Result<BlockId>,
) -> Result<Option<(BlockId, BlockId)>> {
    let Piece::Combination { terms, target, .. } = piece else {
        return Ok(None);
    };
    if target.iter().any(|t| *t != 0.0) {
        return Ok(None);
    }
    let mut sums: smallvec::SmallVec<[(BlockId, f64); 4]> = smallvec::SmallVec::new();
    for (e, j, c) in terms {
        let b = block(*e, *j)?;
        match sums.iter_mut().find(|(x, _)| *x == b) {
            Some(slot) => slot.1 += c,
            None => sums.push((b, *c)),
        }
    }
    Ok(match sums.as_slice() {
        [(a, ca), (b, cb)] if (ca + cb).abs() <= 0.0 && (ca.abs() - 1.0).abs() <= 0.0 => {
            Some((*a, *b))
        }
        _ => None,
    })
}

/// Union–find over the blocks of a component (dense indices: block k is `parent[k]`'s child,
/// a root its own parent), each class rooted at its representative.
struct Classes<'a> {
    parent: Vec<usize>,
    /// Blocks that must be the representative of their class, by index.
    anchored: &'a [bool],
}

impl Classes<'_> {
    fn root(&mut self, b: usize) -> usize {
        let mut r = b;
        while self.parent[r] != r {
            r = self.parent[r];
        }
        // Path compression.
        let mut c = b;
        while c != r {
            let next = self.parent[c];
            self.parent[c] = r;
            c = next;
        }
        r
    }

    /// Joins the classes of a and b, or returns false when both are anchored.
    fn join(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.root(a), self.root(b));
        let (fa, fb) = (self.anchored[ra], self.anchored[rb]);
        if fa && fb {
            return false;
        }
        // The anchored root, else the lower id, represents the class.
        let (keep, bound) = if fa || (!fb && ra <= rb) {
            (ra, rb)
        } else {
            (rb, ra)
        };
        self.parent[bound] = keep;
        true
    }
}

/// Plans the merges of a component's coincidences. `blocks` holds every block a piece can
/// name, block k at position k (the entity blocks, which a component problem adds first);
/// `anchored` (fixed blocks and elimination bases) must stay representatives, elimination
/// `targets` are never merged (both flags by block index, as long as `blocks`).
///
/// # Errors
/// Those of `block`.
pub(crate) fn plan(
    pieces: &[(ConstraintId, &[Piece])],
    blocks: &[BlockId],
    block: impl Fn(crate::ground::ids::EntityId, usize) -> Result<BlockId> + Copy,
    anchored: &[bool],
    targets: &[bool],
) -> Result<Merges> {
    let n = blocks.len();
    let mut classes = Classes {
        parent: (0..n).collect(),
        anchored,
    };
    let mut merges = Merges::default();
    for (ci, (id, list)) in pieces.iter().enumerate() {
        for (pi, piece) in list.iter().enumerate() {
            let Some((a, b)) = coincidence(piece, block)? else {
                continue;
            };
            let (a, b) = (a.index(), b.index());
            // Blocks outside `blocks` (none, as the caller names entity blocks only) stay rows.
            if a >= n || b >= n || targets[a] || targets[b] {
                continue;
            }
            if classes.root(a) == classes.root(b) {
                merges.redundant.push(*id);
                merges.replaced.push((ci, pi));
            } else if classes.join(a, b) {
                merges.replaced.push((ci, pi));
            }
        }
    }
    for (b, block) in blocks.iter().enumerate() {
        let r = classes.root(b);
        if r != b {
            merges.into.push((*block, blocks[r]));
        }
    }
    merges.redundant.sort_unstable();
    merges.redundant.dedup();
    Ok(merges)
}
