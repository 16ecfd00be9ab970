//! Cubic Hermite curves and composite curves (chains of cubic Hermite segments) as sketch
//! entities: their unknowns, the linear map from those unknowns to Bézier control points, and
//! evaluation through the geometry kernel.
//!
//! # Unknowns
//!
//! A chain of n segments has n + 1 **nodes** N₀ … Nₙ (positions) and **tangent vectors**
//! (length per unit of parameter). Segment i runs from Nᵢ to Nᵢ₊₁ with out-tangent aᵢ at its
//! start and in-tangent bᵢ₊₁ at its end, on the global parameter u ∈ [i, i + 1] (local
//! s = u − i), so the chain's parameter domain is [0, n]. Each interior node has a **join**:
//!
//! - [`Join::Smooth`]: one tangent block shared by both segments, aᵢ = bᵢ — C1 by construction
//!   (equal position, equal first derivative in u);
//! - [`Join::Corner`]: two tangent blocks, bᵢ (in) then aᵢ (out) — C0 by construction; a G1
//!   or other condition on them is a constraint.
//!
//! Every node and every tangent is one block of two unknowns, stored in this order: the nodes
//! N₀ … Nₙ, then the tangents node by node (a₀; at each interior node its one shared tangent,
//! or bᵢ then aᵢ; bₙ). A single cubic Hermite curve ([`HermiteChain::single`]) is a chain of one
//! segment, blocks [p0, p1, t0, t1] — the geometric form of [`camber_geom::HermiteCurve2`].
//!
//! # Why these unknowns keep constraints linear
//!
//! Segment i is the cubic Bézier curve with control points
//!
//! Q₃ᵢ = Nᵢ, Q₃ᵢ₊₁ = Nᵢ + aᵢ/3, Q₃ᵢ₊₂ = Nᵢ₊₁ − bᵢ₊₁/3, Q₃ᵢ₊₃ = Nᵢ₊₁,
//!
//! so the whole chain is the cubic B-spline on the knots {0⁴, 1³, …, (n − 1)³, n⁴} with control
//! points Q = M·X, M a fixed sparse matrix ([`HermiteChain::bezier_map`]) and X the blocks. A
//! point or derivative at a fixed u is then Σᵣ Nᵣ(u)·Qᵣ = Σⱼ (Σᵣ Nᵣ(u)·Mᵣⱼ)·Xⱼ: constant
//! coefficients on the blocks, exactly like the control points of the other curve kinds, and
//! the solver's linear (minimum-norm) path applies unchanged. The minimum-norm step measures
//! tangents in their own units (length per unit u), not as handle positions.
//!
//! ```
//! use camber_sketch::hermite_chain::{HermiteChain, Join};
//! use camber_geom::ParametricCurve;
//! use nalgebra::{Point2, Vector2};
//! let chain = HermiteChain::try_new(
//!     vec![Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(2.0, 0.0)],
//!     vec![Vector2::new(1.0, 0.0), Vector2::new(1.0, 0.0), Vector2::new(1.0, 0.0)],
//!     vec![Join::Smooth],
//! )?;
//! assert_eq!(chain.segment_count(), 2);
//! assert_eq!(chain.point(1.0)?, Point2::new(1.0, 1.0));
//! assert_eq!(chain.derivative(1.0)?, Vector2::new(1.0, 0.0));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use camber_geom::curve::check_parameter;
use camber_geom::queries::RationalPiece;
use camber_geom::{BezierCurve2, HermiteCurve2, KnotVector, ParametricCurve};
use nalgebra::{Point2, SVector, Vector2};
use serde::{Deserialize, Serialize};
use smallvec::SmallVec;

use crate::ground::errors::{Error, Result};

/// How two neighbouring segments of a composite curve meet at their shared node.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Join {
    /// One shared tangent block: C1 by construction.
    Smooth,
    /// Separate in- and out-tangent blocks: C0 by construction.
    Corner,
}

/// One row of the map from blocks to Bézier control points: (block index, coefficient).
pub type MapRow = SmallVec<[(usize, f64); 2]>;

/// A chain of cubic Hermite segments with its joins (see the module documentation); a single
/// Hermite curve is a chain of one segment.
///
/// ```
/// use camber_sketch::hermite_chain::HermiteChain;
/// use nalgebra::{Point2, Vector2};
/// let h = HermiteChain::single(Point2::new(0.0, 0.0), Point2::new(3.0, 0.0), Vector2::new(0.0, 3.0), Vector2::new(0.0, -3.0))?;
/// // Blocks [p0, p1, t0, t1]; the equivalent Bézier handles sit at p0 + t0/3 and p1 − t1/3.
/// assert_eq!(h.blocks().len(), 4);
/// assert_eq!(h.bezier_points()[1], Point2::new(0.0, 1.0));
/// assert_eq!(h.bezier_points()[2], Point2::new(3.0, 1.0));
/// # Ok::<(), camber_sketch::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct HermiteChain {
    /// Nodes, then tangents (stored as the coordinates of a vector).
    blocks: Vec<Point2<f64>>,
    /// One join per interior node.
    joins: Vec<Join>,
}

/// # Construction
impl HermiteChain {
    /// The chain through `nodes` (at least two) with `tangents` in block order (a₀; one per
    /// smooth interior node, in then out at a corner; bₙ) and one join per interior node.
    ///
    /// # Errors
    /// [`Error::CountMismatch`] naming the field (`nodes`, `joins`, `tangents`) whose length is
    /// wrong; [`Error::NonFinite`] naming a node or tangent with a non-finite coordinate.
    ///
    /// ```
    /// use camber_sketch::hermite_chain::{HermiteChain, Join};
    /// use camber_sketch::Error;
    /// use nalgebra::{Point2, Vector2};
    /// let nodes = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 0.0), Point2::new(2.0, 1.0)];
    /// let bad = HermiteChain::try_new(nodes, vec![Vector2::x(); 3], vec![Join::Corner]);
    /// assert_eq!(bad, Err(Error::CountMismatch { field: "tangents", expected: 4, found: 3 }));
    /// ```
    pub fn try_new(
        nodes: Vec<Point2<f64>>,
        tangents: Vec<Vector2<f64>>,
        joins: Vec<Join>,
    ) -> Result<Self> {
        if nodes.len() < 2 {
            return Err(Error::CountMismatch {
                field: "nodes",
                expected: 2,
                found: nodes.len(),
            });
        }
        if joins.len() != nodes.len() - 2 {
            return Err(Error::CountMismatch {
                field: "joins",
                expected: nodes.len() - 2,
                found: joins.len(),
            });
        }
        let expected = tangent_count(&joins);
        if tangents.len() != expected {
            return Err(Error::CountMismatch {
                field: "tangents",
                expected,
                found: tangents.len(),
            });
        }
        for (i, p) in nodes.iter().enumerate() {
            crate::ground::entity::check_point("node", i, p)?;
        }
        for (i, t) in tangents.iter().enumerate() {
            crate::ground::entity::check_finite2("tangent", i, [t.x, t.y])?;
        }
        let mut blocks = nodes;
        blocks.extend(tangents.iter().map(|t| Point2::from(*t)));
        Ok(Self { blocks, joins })
    }

    /// One cubic Hermite segment from p(0) = `p0` to p(1) = `p1` with p′(0) = `t0`,
    /// p′(1) = `t1`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a non-finite coordinate.
    pub fn single(
        p0: Point2<f64>,
        p1: Point2<f64>,
        t0: Vector2<f64>,
        t1: Vector2<f64>,
    ) -> Result<Self> {
        Self::try_new(vec![p0, p1], vec![t0, t1], Vec::new())
    }

    /// The chain of one segment equal to a geometry-kernel Hermite curve.
    ///
    /// # Errors
    /// As [`HermiteChain::single`].
    pub fn from_curve(c: &HermiteCurve2<f64>) -> Result<Self> {
        Self::single(c.p0(), c.p1(), c.t0(), c.t1())
    }

    /// The same chain with new blocks (as many as before, in block order).
    ///
    /// # Errors
    /// [`Error::CountMismatch`] for another number of blocks, [`Error::NonFinite`].
    pub fn with_blocks(&self, blocks: &[Point2<f64>]) -> Result<Self> {
        if blocks.len() != self.blocks.len() {
            return Err(Error::CountMismatch {
                field: "blocks",
                expected: self.blocks.len(),
                found: blocks.len(),
            });
        }
        let n = self.node_count();
        Self::try_new(
            blocks[..n].to_vec(),
            blocks[n..].iter().map(|p| p.coords).collect(),
            self.joins.clone(),
        )
    }
}

/// The number of tangent blocks for these interior joins: a₀ and bₙ, one per smooth join, two
/// per corner.
fn tangent_count(joins: &[Join]) -> usize {
    2 + joins
        .iter()
        .map(|j| match j {
            Join::Smooth => 1,
            Join::Corner => 2,
        })
        .sum::<usize>()
}

impl HermiteChain {
    /// Every block: nodes, then tangents (a tangent's coordinates read as a point).
    pub fn blocks(&self) -> &[Point2<f64>] {
        &self.blocks
    }

    /// The number of segments n (the domain is [0, n]).
    pub fn segment_count(&self) -> usize {
        self.joins.len() + 1
    }

    /// The number of nodes, n + 1; they are the first blocks.
    pub fn node_count(&self) -> usize {
        self.joins.len() + 2
    }

    /// The nodes N₀ … Nₙ.
    pub fn nodes(&self) -> &[Point2<f64>] {
        &self.blocks[..self.node_count()]
    }

    /// The tangent vectors in block order.
    pub fn tangents(&self) -> Vec<Vector2<f64>> {
        self.blocks[self.node_count()..]
            .iter()
            .map(|p| p.coords)
            .collect()
    }

    /// The joins at the interior nodes N₁ … Nₙ₋₁.
    pub fn joins(&self) -> &[Join] {
        &self.joins
    }

    /// Whether block `j` is a tangent (not a node).
    pub fn is_tangent_block(&self, j: usize) -> bool {
        j >= self.node_count() && j < self.blocks.len()
    }

    /// The block indices of segment i's out-tangent aᵢ and in-tangent bᵢ₊₁.
    ///
    /// ```
    /// use camber_sketch::hermite_chain::{HermiteChain, Join};
    /// use nalgebra::{Point2, Vector2};
    /// let nodes = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 0.0), Point2::new(2.0, 1.0)];
    /// let c = HermiteChain::try_new(nodes, vec![Vector2::x(); 4], vec![Join::Corner])?;
    /// // Blocks: N₀ N₁ N₂ | a₀ b₁ a₁ b₂.
    /// assert_eq!(c.segment_tangents(0), (3, 4));
    /// assert_eq!(c.segment_tangents(1), (5, 6));
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    pub fn segment_tangents(&self, i: usize) -> (usize, usize) {
        let mut out = self.node_count();
        for join in &self.joins[..i.min(self.joins.len())] {
            out += match join {
                Join::Smooth => 1,
                Join::Corner => 2,
            };
        }
        // bᵢ₊₁ follows aᵢ: it is the next node's shared tangent, its in-tangent, or bₙ.
        (out, out + 1)
    }

    /// For tangent block j: the node it belongs to and +1 for an out-tangent (shared smooth
    /// tangents count as out), −1 for an in-tangent; `None` for a node or an index past the
    /// blocks.
    ///
    /// ```
    /// use camber_sketch::hermite_chain::{HermiteChain, Join};
    /// use nalgebra::{Point2, Vector2};
    /// let nodes = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 0.0), Point2::new(2.0, 1.0)];
    /// let c = HermiteChain::try_new(nodes, vec![Vector2::x(); 4], vec![Join::Corner])?;
    /// assert_eq!(c.tangent_anchor(4), Some((1, -1.0))); // b₁
    /// assert_eq!(c.tangent_anchor(5), Some((1, 1.0))); // a₁
    /// assert_eq!(c.tangent_anchor(2), None); // a node
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    pub fn tangent_anchor(&self, j: usize) -> Option<(usize, f64)> {
        if !self.is_tangent_block(j) {
            return None;
        }
        let mut next = self.node_count();
        let mut slots = vec![(0, 1.0)];
        for (k, join) in self.joins.iter().enumerate() {
            match join {
                Join::Smooth => slots.push((k + 1, 1.0)),
                Join::Corner => slots.extend([(k + 1, -1.0), (k + 1, 1.0)]),
            }
        }
        slots.push((self.node_count() - 1, -1.0));
        for slot in slots {
            if next == j {
                return Some(slot);
            }
            next += 1;
        }
        None
    }

    /// Where block j is drawn and dragged: a node at itself, a tangent t at its handle
    /// N + t/3 (out) or N − t/3 (in) — the Bézier control point it moves.
    pub fn handle(&self, j: usize) -> Option<Point2<f64>> {
        match self.tangent_anchor(j) {
            Some((node, sign)) => Some(self.blocks[node] + self.blocks[j].coords * (sign / 3.0)),
            None => self.blocks.get(j).copied(),
        }
    }

    /// The value of block j that puts its handle at `q` with the nodes as they are (the inverse
    /// of [`HermiteChain::handle`]): q itself for a node, ±3·(q − N) for a tangent.
    pub fn block_for_handle(&self, j: usize, q: Point2<f64>) -> Point2<f64> {
        match self.tangent_anchor(j) {
            Some((node, sign)) => Point2::from((q - self.blocks[node]) * (3.0 * sign)),
            None => q,
        }
    }

    /// Segment i as a geometry-kernel Hermite curve on its local parameter s ∈ [0, 1].
    ///
    /// # Errors
    /// [`Error::CountMismatch`] (field `segment`) for i ≥ n.
    pub fn segment(&self, i: usize) -> Result<HermiteCurve2<f64>> {
        if i >= self.segment_count() {
            return Err(Error::CountMismatch {
                field: "segment",
                expected: self.segment_count(),
                found: i,
            });
        }
        let (a, b) = self.segment_tangents(i);
        Ok(HermiteCurve2::try_new(
            self.blocks[i],
            self.blocks[i + 1],
            self.blocks[a].coords,
            self.blocks[b].coords,
        )?)
    }

    /// The map M from blocks to the 3n + 1 Bézier control points Q of the chain (see the module
    /// documentation): row r lists the blocks and coefficients of Qᵣ.
    pub fn bezier_map(&self) -> Vec<MapRow> {
        let third = 1.0 / 3.0;
        let mut rows = Vec::with_capacity(3 * self.segment_count() + 1);
        for i in 0..self.segment_count() {
            let (a, b) = self.segment_tangents(i);
            rows.push(smallvec::smallvec![(i, 1.0)]);
            rows.push(smallvec::smallvec![(i, 1.0), (a, third)]);
            rows.push(smallvec::smallvec![(i + 1, 1.0), (b, -third)]);
        }
        rows.push(smallvec::smallvec![(self.segment_count(), 1.0)]);
        rows
    }

    /// The Bézier control points Q = M·X of the whole chain (3n + 1 positions: nodes and the
    /// handles Nᵢ + aᵢ/3, Nᵢ₊₁ − bᵢ₊₁/3): the convex hulls of the segments, for drawing and
    /// bounding boxes.
    pub fn bezier_points(&self) -> Vec<Point2<f64>> {
        self.bezier_map()
            .iter()
            .map(|row| {
                let mut q = Vector2::zeros();
                for (j, c) in row {
                    q += self.blocks[*j].coords * *c;
                }
                Point2::from(q)
            })
            .collect()
    }

    /// The knots {0⁴, 1³, …, (n − 1)³, n⁴} of the chain as a cubic B-spline over
    /// [`HermiteChain::bezier_points`].
    pub fn knots(&self) -> KnotVector<f64> {
        let n = self.segment_count();
        let mut k = vec![0.0; 4];
        for i in 1..n {
            k.extend([i as f64; 3]);
        }
        k.extend([n as f64; 4]);
        // Non-decreasing, finite and long enough by construction; the fallback is never taken.
        KnotVector::try_new(k).unwrap_or_else(|_| KnotVector::bezier(3))
    }

    /// Segment i as a cubic Bézier curve (the conversion P₁ = p0 + t0/3, P₂ = p1 − t1/3).
    ///
    /// # Errors
    /// As [`HermiteChain::segment`].
    pub fn segment_bezier(&self, i: usize) -> Result<BezierCurve2<f64>> {
        Ok(self.segment(i)?.to_bezier()?)
    }

    /// The segment holding the global parameter u (clamped to [0, n]) and the local s ∈ [0, 1].
    fn locate(&self, u: f64) -> (usize, f64) {
        let n = self.segment_count();
        let u = u.clamp(0.0, n as f64);
        let i = (u.floor() as usize).min(n - 1);
        (i, u - i as f64)
    }
}

impl ParametricCurve<f64, 2> for HermiteChain {
    /// The chain's segments as cubic Bézier pieces on [i, i + 1], so that the kernel's
    /// curve–curve intersection and distance ([`camber_geom::queries::intersect_curves`],
    /// [`camber_geom::queries::curve_distance`]) cut the chain exactly and report parameters on
    /// its own domain [0, n].
    fn bezier_enclosure(&self) -> camber_geom::Result<Option<Vec<RationalPiece<2>>>> {
        let q = self.bezier_points();
        Ok(Some(
            (0..self.segment_count())
                .map(|i| {
                    RationalPiece::new(i as f64, (i + 1) as f64, &q[3 * i..=3 * i + 3], &[1.0; 4])
                })
                .collect(),
        ))
    }

    /// [0, n].
    fn domain(&self) -> (f64, f64) {
        (0.0, self.segment_count() as f64)
    }

    /// The joins' parameters 0, 1, …, n.
    fn breakpoints(&self) -> Vec<f64> {
        (0..=self.segment_count()).map(|i| i as f64).collect()
    }

    /// The derivatives of the segment holding u (the later one at a join), which are the
    /// derivatives in u since each segment has unit parameter length.
    fn derivatives_into(&self, u: f64, out: &mut [SVector<f64, 2>]) -> camber_geom::Result<()> {
        check_parameter(u, self.domain())?;
        let (i, s) = self.locate(u);
        let (a, b) = self.segment_tangents(i);
        HermiteCurve2::try_new(
            self.blocks[i],
            self.blocks[i + 1],
            self.blocks[a].coords,
            self.blocks[b].coords,
        )?
        .derivatives_into(s, out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn corner_chain() -> HermiteChain {
        HermiteChain::try_new(
            vec![
                Point2::new(0.0, 0.0),
                Point2::new(2.0, 1.0),
                Point2::new(3.0, -1.0),
                Point2::new(5.0, 0.0),
            ],
            vec![
                Vector2::new(1.0, 2.0),
                Vector2::new(2.0, 0.5),
                Vector2::new(-1.0, -2.0),
                Vector2::new(1.5, 1.0),
                Vector2::new(0.5, -3.0),
            ],
            vec![Join::Smooth, Join::Corner],
        )
        .unwrap()
    }

    #[test]
    fn joins_are_c0_and_smooth_joins_c1() {
        let c = corner_chain();
        for i in 1..c.segment_count() {
            let before = c.segment(i - 1).unwrap();
            let after = c.segment(i).unwrap();
            let (p, d) = before.point_and_derivative(1.0).unwrap();
            let (q, e) = after.point_and_derivative(0.0).unwrap();
            assert_relative_eq!(p, q, epsilon = 1e-14);
            if c.joins()[i - 1] == Join::Smooth {
                assert_relative_eq!(d, e, epsilon = 1e-14);
            } else {
                assert!((d - e).norm() > 0.1);
            }
        }
    }

    #[test]
    fn the_bezier_map_reproduces_each_segment() {
        let c = corner_chain();
        let q = c.bezier_points();
        assert_eq!(q.len(), 3 * c.segment_count() + 1);
        for i in 0..c.segment_count() {
            let bez = BezierCurve2::try_new(q[3 * i..=3 * i + 3].to_vec()).unwrap();
            let seg = c.segment(i).unwrap();
            for s in [0.0, 0.2, 0.5, 0.9, 1.0] {
                let (a, da) = bez.point_and_derivative(s).unwrap();
                let (b, db) = seg.point_and_derivative(s).unwrap();
                assert_relative_eq!(a, b, epsilon = 1e-13);
                assert_relative_eq!(da, db, epsilon = 1e-12);
                let (g, dg) = c.point_and_derivative(i as f64 + s).unwrap();
                if s < 1.0 || i + 1 == c.segment_count() {
                    assert_relative_eq!(g, b, epsilon = 1e-13);
                    assert_relative_eq!(dg, db, epsilon = 1e-12);
                }
            }
        }
    }

    #[test]
    fn handles_are_the_bezier_control_points_and_invert() {
        let c = corner_chain();
        let q = c.bezier_points();
        // Blocks: N₀ … N₃ | a₀, (b₁ = a₁ shared), b₂, a₂, b₃.
        let expect = [(4, q[1]), (5, q[4]), (6, q[5]), (7, q[7]), (8, q[8])];
        for (j, at) in expect {
            let h = c.handle(j).unwrap();
            assert_relative_eq!(h, at, epsilon = 1e-14);
            assert_relative_eq!(c.block_for_handle(j, h), c.blocks()[j], epsilon = 1e-14);
        }
        assert_eq!(c.handle(2), Some(c.nodes()[2]));
        assert_eq!(c.handle(9), None);
    }

    /// Intersections of the chain with a horizontal segment: the chain's parameters equal the
    /// per-segment intersections of the equivalent Bézier curves shifted by the segment index,
    /// and both points lie on the line.
    #[test]
    fn intersections_report_parameters_on_the_chain() {
        use camber_geom::queries::{curve_distance, intersect_curves, CurveCurveOptions};
        use camber_geom::Segment;
        let c = corner_chain();
        let line = Segment::try_new(Point2::new(-1.0, 0.25), Point2::new(6.0, 0.25)).unwrap();
        let opts = CurveCurveOptions::default();
        let hits = intersect_curves(&c, &line, &opts).unwrap();
        let mut expected = Vec::new();
        for i in 0..c.segment_count() {
            let bez = c.segment_bezier(i).unwrap();
            for h in intersect_curves(&bez, &line, &opts).unwrap() {
                expected.push(i as f64 + h.parameter_a);
            }
        }
        expected.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
        assert!(!hits.is_empty());
        assert_eq!(hits.len(), expected.len(), "{hits:?} vs {expected:?}");
        for (h, u) in hits.iter().zip(&expected) {
            assert_relative_eq!(h.parameter_a, *u, epsilon = 1e-9);
            assert_relative_eq!(c.point(h.parameter_a).unwrap().y, 0.25, epsilon = 1e-9);
        }
        // Distance to a line above the chain: the highest point, where C′ is horizontal.
        let high = Segment::try_new(Point2::new(-1.0, 5.0), Point2::new(6.0, 5.0)).unwrap();
        let d = curve_distance(&c, &high, &opts).unwrap();
        let top = (0..=60_000)
            .map(|k| c.point(3.0 * f64::from(k) / 60_000.0).unwrap().y)
            .fold(f64::NEG_INFINITY, f64::max);
        assert_relative_eq!(d.distance, 5.0 - top, epsilon = 1e-7);
    }

    /// The chain against its own middle segment as a Bézier curve: one overlap, u ∈ [1, 2] on
    /// the chain and [0, 1] on the segment.
    #[test]
    fn a_chain_overlaps_its_own_segment_on_its_interval() {
        use camber_geom::queries::{intersect_curves_with_overlaps, CurveCurveOptions};
        let c = corner_chain();
        let middle = c.segment_bezier(1).unwrap();
        let hits =
            intersect_curves_with_overlaps(&c, &middle, &CurveCurveOptions::default()).unwrap();
        assert_eq!(hits.overlaps.len(), 1, "{hits:?}");
        let o = hits.overlaps[0];
        assert_relative_eq!(o.a.0, 1.0, epsilon = 1e-7);
        assert_relative_eq!(o.a.1, 2.0, epsilon = 1e-7);
        assert_relative_eq!(o.b.0, 0.0, epsilon = 1e-7);
        assert_relative_eq!(o.b.1, 1.0, epsilon = 1e-7);
    }

    #[test]
    fn bad_counts_name_their_field() {
        let two = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 0.0)];
        assert_eq!(
            HermiteChain::try_new(two.clone(), vec![Vector2::x(); 2], vec![Join::Smooth]),
            Err(Error::CountMismatch {
                field: "joins",
                expected: 0,
                found: 1
            })
        );
        assert_eq!(
            HermiteChain::try_new(vec![two[0]], vec![], vec![]),
            Err(Error::CountMismatch {
                field: "nodes",
                expected: 2,
                found: 1
            })
        );
        assert_eq!(
            HermiteChain::try_new(
                two,
                vec![Vector2::x(), Vector2::new(0.0, f64::INFINITY)],
                vec![]
            ),
            Err(Error::NonFinite {
                what: "tangent",
                index: 3,
                value: f64::INFINITY
            })
        );
    }
}
