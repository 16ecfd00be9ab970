//! A bounding-box hierarchy over a curve's Bézier pieces, so that the curve–curve searches look
//! only at pieces whose boxes come near each other instead of at every pair.
//!
//! The pieces are in parameter order, so the tree is built over index ranges: a node holds the
//! pieces [first, last) and the union of their boxes, its children the two halves of the range
//! (a balanced tree of depth ⌈log₂ n⌉, built in O(n)). Two trees are traversed together: a pair
//! of nodes whose boxes are farther apart than the search needs is dropped with everything
//! below it, and the larger of two overlapping nodes is split. For two curves that meet in k
//! places this visits O((n_a + n_b + k) log n) node pairs in practice, instead of n_a·n_b.

use nalgebra::SVector;

use super::pieces::RationalPiece;
use crate::budget::Meter;
use crate::errors::Result;

/// One node: the pieces [first, last) and their common box; children `Some((left, right))`
/// for an inner node.
#[derive(Debug, Clone)]
pub(crate) struct Node<const D: usize> {
    pub lo: SVector<f64, D>,
    pub hi: SVector<f64, D>,
    pub first: usize,
    pub last: usize,
    pub children: Option<(usize, usize)>,
}

impl<const D: usize> Node<D> {
    /// The length of the box's diagonal.
    pub fn diagonal(&self) -> f64 {
        (self.hi - self.lo).norm()
    }
}

/// The hierarchy over a slice of pieces; node 0 is the root.
#[derive(Debug, Clone)]
pub(crate) struct BoxTree<const D: usize> {
    nodes: Vec<Node<D>>,
}

impl<const D: usize> BoxTree<D> {
    /// The tree over `pieces` (at least one).
    pub fn new(pieces: &[RationalPiece<D>]) -> Self {
        let mut nodes = Vec::with_capacity(2 * pieces.len());
        if !pieces.is_empty() {
            nodes.push(Node {
                lo: SVector::zeros(),
                hi: SVector::zeros(),
                first: 0,
                last: pieces.len(),
                children: None,
            });
            build(&mut nodes, 0, pieces);
        }
        Self { nodes }
    }

    /// Node `i`.
    pub fn node(&self, i: usize) -> &Node<D> {
        &self.nodes[i]
    }

    /// Whether the tree has no pieces.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// Every piece whose box, grown by `grow`, contains `p` (indices into the pieces), one unit
    /// per node visited charged to `meter`.
    pub fn pieces_near(
        &self,
        p: &SVector<f64, D>,
        grow: f64,
        meter: &mut Meter<'_>,
    ) -> Result<Vec<usize>> {
        let mut out = Vec::new();
        if self.is_empty() {
            return Ok(out);
        }
        let mut stack = vec![0usize];
        while let Some(i) = stack.pop() {
            meter.charge(1)?;
            let n = &self.nodes[i];
            if point_box_distance(p, (&n.lo, &n.hi)) > grow {
                continue;
            }
            match n.children {
                Some((l, r)) => {
                    stack.push(r);
                    stack.push(l);
                }
                None => out.push(n.first),
            }
        }
        Ok(out)
    }
}

/// Fills node `i` (its range set) and its subtree; returns nothing, the box is written.
fn build<const D: usize>(nodes: &mut Vec<Node<D>>, root: usize, pieces: &[RationalPiece<D>]) {
    // Iterative post-order: children first, then the parent's box from theirs.
    let mut stack = vec![(root, false)];
    while let Some((i, children_done)) = stack.pop() {
        let (first, last) = (nodes[i].first, nodes[i].last);
        if last - first == 1 {
            let (lo, hi) = pieces[first].bounding_box();
            nodes[i].lo = lo;
            nodes[i].hi = hi;
            continue;
        }
        if children_done {
            if let Some((l, r)) = nodes[i].children {
                nodes[i].lo = nodes[l].lo.inf(&nodes[r].lo);
                nodes[i].hi = nodes[l].hi.sup(&nodes[r].hi);
            }
            continue;
        }
        let mid = first + (last - first) / 2;
        let l = nodes.len();
        for (f, e) in [(first, mid), (mid, last)] {
            nodes.push(Node {
                lo: SVector::zeros(),
                hi: SVector::zeros(),
                first: f,
                last: e,
                children: None,
            });
        }
        nodes[i].children = Some((l, l + 1));
        stack.push((i, true));
        stack.push((l + 1, false));
        stack.push((l, false));
    }
}

/// The distance between two boxes (0 when they overlap).
pub(crate) fn box_distance<const D: usize>(
    (alo, ahi): (&SVector<f64, D>, &SVector<f64, D>),
    (blo, bhi): (&SVector<f64, D>, &SVector<f64, D>),
) -> f64 {
    let mut d2 = 0.0;
    for i in 0..D {
        let gap = (blo[i] - ahi[i]).max(alo[i] - bhi[i]).max(0.0);
        d2 += gap * gap;
    }
    d2.sqrt()
}

/// The distance from a point to a box (0 inside).
pub(crate) fn point_box_distance<const D: usize>(
    p: &SVector<f64, D>,
    (lo, hi): (&SVector<f64, D>, &SVector<f64, D>),
) -> f64 {
    box_distance((p, p), (lo, hi))
}

/// Calls `visit(i, j)` for every pair of pieces (i of `a`, j of `b`) whose boxes are at most
/// `grow` apart, found by the joint descent of both trees; one unit per node pair charged to
/// `meter`.
pub(crate) fn near_pairs<const D: usize>(
    a: &BoxTree<D>,
    b: &BoxTree<D>,
    grow: f64,
    meter: &mut Meter<'_>,
    mut visit: impl FnMut(usize, usize, &mut Meter<'_>) -> Result<()>,
) -> Result<()> {
    if a.is_empty() || b.is_empty() {
        return Ok(());
    }
    let mut stack = vec![(0usize, 0usize)];
    while let Some((i, j)) = stack.pop() {
        meter.charge(1)?;
        let (x, y) = (a.node(i), b.node(j));
        if box_distance((&x.lo, &x.hi), (&y.lo, &y.hi)) > grow {
            continue;
        }
        match (x.children, y.children) {
            (None, None) => visit(x.first, y.first, meter)?,
            (Some((l, r)), None) => {
                stack.push((r, j));
                stack.push((l, j));
            }
            (None, Some((l, r))) => {
                stack.push((i, r));
                stack.push((i, l));
            }
            (Some((xl, xr)), Some((yl, yr))) => {
                if x.diagonal() >= y.diagonal() {
                    stack.push((xr, j));
                    stack.push((xl, j));
                } else {
                    stack.push((i, yr));
                    stack.push((i, yl));
                }
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::budget::Budget;
    use nalgebra::Point2;

    fn piece(x: f64) -> RationalPiece<2> {
        RationalPiece::new(
            x,
            x + 1.0,
            &[Point2::new(x, 0.0), Point2::new(x + 1.0, 0.0)],
            &[1.0, 1.0],
        )
    }

    #[test]
    fn pairs_match_a_brute_force_scan() {
        // Pieces along y = 0 at x = k, against pieces at x = 2.5 k: boxes touch where the
        // intervals [k, k + 1] and [2.5 j, 2.5 j + 1] meet.
        let a: Vec<_> = (0..40).map(|k| piece(f64::from(k))).collect();
        let b: Vec<_> = (0..16).map(|k| piece(2.5 * f64::from(k))).collect();
        let (ta, tb) = (BoxTree::new(&a), BoxTree::new(&b));
        let budget = Budget::default();
        let mut meter = budget.meter("test", u64::MAX);
        let mut found = Vec::new();
        near_pairs(&ta, &tb, 0.0, &mut meter, |i, j, _| {
            found.push((i, j));
            Ok(())
        })
        .unwrap();
        found.sort_unstable();
        let mut brute = Vec::new();
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                let (bx, by) = (x.bounding_box(), y.bounding_box());
                if box_distance((&bx.0, &bx.1), (&by.0, &by.1)) <= 0.0 {
                    brute.push((i, j));
                }
            }
        }
        assert_eq!(found, brute);
        let near = ta
            .pieces_near(&SVector::from([10.5, 0.2]), 0.25, &mut meter)
            .unwrap();
        assert_eq!(near, vec![10]);
    }
}
