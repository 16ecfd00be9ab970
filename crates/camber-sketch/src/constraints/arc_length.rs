//! `arc_length`: a curve's length equals L > 0:
//!
//! ∫ₐᵇ |C′(u)| du − L = 0 (one row in length units),
//!
//! the integral taken by composite Gauss–Legendre quadrature: every non-empty knot span split
//! into S equal pieces, 8 nodes on each. On a polynomial piece the speed |C′| is smooth
//! (analytic wherever C′ ≠ 0), so the rule converges fast; S is chosen when the component is
//! built, doubling from 2 until two successive rules agree to [`RULE_TOLERANCE`] relative on
//! the curve as it is (at most [`MAX_SUBINTERVALS`]). The rule then stays fixed for the solve,
//! so the residual is smooth in the control points and its Jacobian exact.
//!
//! On a circular arc the length is r·φ in closed form (radius times sweep, read from the
//! arc's blocks); on an elliptic arc it is the same kind of rule over the parametric angle
//! ([`ArcLengthOfArc`], formulas in its documentation). File form:
//! `{"kind": "arc_length", "curve": 0, "length": 3.2}` (`curve` may name an arc).

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::positive;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::ground::curve_eval::CurveBasis;
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::residuals::curve::dot;

pub use super::shared::sweeps::ArcLengthOfArc;
use super::shared::sweeps::SweptArc;

/// Two successive rules agreeing to this relative difference end the choice of S.
pub const RULE_TOLERANCE: f64 = 1e-14;

/// The most sub-intervals per knot span.
pub const MAX_SUBINTERVALS: usize = 256;

/// Nodes on [−1, 1] and weights of the 8-point Gauss–Legendre rule (exact for degree 15).
const GAUSS_8: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_2, 0.101_228_536_290_376_26),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (0.960_289_856_497_536_2, 0.101_228_536_290_376_26),
];

/// The curve is `length` long (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArcLength {
    /// The curve (a line, Bézier, B-spline, NURBS, Hermite or composite curve, a circular or
    /// an elliptic arc).
    pub curve: EntityId,
    /// The length L > 0.
    pub length: f64,
}

/// ∫|C′| − L by the fixed composite rule of the module documentation (blocks: the curve's
/// control points).
///
/// The nodes being fixed, and the weights of a NURBS being data, C′ at each node is a fixed
/// combination Σⱼ bⱼ·Pⱼ of the control points of the node's span ([`CurveBasis::at`]): the
/// coefficients are computed once, in f64, and an evaluation (in dual numbers for the Jacobian
/// and Hessian) is one short sum and one square root per node, never the basis again.
#[derive(Debug, Clone, PartialEq)]
pub struct LengthOf {
    /// (parameter, weight) of every node.
    nodes: Vec<(f64, f64)>,
    /// C′ at node k is Σ b·P_j over (j, b) in `terms[ends[k]..ends[k + 1]]`.
    terms: Vec<(usize, f64)>,
    ends: Vec<usize>,
    /// The number of control point blocks the residual reads.
    blocks: usize,
    length: f64,
}

impl LengthOf {
    /// The residual for a curve with `basis` and `breakpoints` (its distinct knots over the
    /// domain, increasing, ends included), for the length L, with the rule chosen on the
    /// control points `points` (see the module documentation).
    pub fn new(basis: CurveBasis, breakpoints: &[f64], points: &[&[f64]], length: f64) -> Self {
        let mut r = Self::with_rule(&basis, composite_rule(breakpoints, 2), length);
        let mut previous = r.integral(points);
        let mut pieces = 4;
        while pieces <= MAX_SUBINTERVALS {
            let next = Self::with_rule(&basis, composite_rule(breakpoints, pieces), length);
            let value = next.integral(points);
            r = next;
            let settled = (value - previous).abs() <= RULE_TOLERANCE * value.abs();
            previous = value;
            if settled {
                break;
            }
            pieces *= 2;
        }
        r
    }

    /// The residual on the given nodes: the coefficients of C′ at each.
    fn with_rule(basis: &CurveBasis, nodes: Vec<(f64, f64)>, length: f64) -> Self {
        let mut terms = Vec::with_capacity(nodes.len() * 4);
        let mut ends = Vec::with_capacity(nodes.len() + 1);
        ends.push(0);
        for (u, _) in &nodes {
            let (fixed, points) = basis.at(*u, 1);
            // Without coefficients (no valid knot vector, a curve the sketch refuses long
            // before) the node's speed reads as zero rather than panicking.
            if let Some(c) = fixed.fixed_coefficients() {
                terms.extend(points.iter().zip(c).map(|(j, c)| (*j, c[1])));
            }
            ends.push(terms.len());
        }
        Self {
            nodes,
            terms,
            ends,
            blocks: basis.count(),
            length,
        }
    }

    /// The number of quadrature nodes chosen.
    pub fn nodes(&self) -> usize {
        self.nodes.len()
    }

    /// C′ at node k, from the control points `x` (one block of two per control point).
    fn speed_vector<T: Scalar>(&self, x: &[&[T]], k: usize) -> [T; 2] {
        let mut c1 = [T::zero(), T::zero()];
        for (j, b) in &self.terms[self.ends[k]..self.ends[k + 1]] {
            let b = cst::<T>(*b);
            c1[0] += b * x[*j][0];
            c1[1] += b * x[*j][1];
        }
        c1
    }

    /// The quadrature of ∫|C′| at the control points `points` (f64), for reports and tests.
    pub fn integral(&self, points: &[&[f64]]) -> f64 {
        self.nodes
            .iter()
            .enumerate()
            .map(|(k, (_, w))| {
                let c1 = self.speed_vector(points, k);
                w * c1[0].hypot(c1[1])
            })
            .sum()
    }
}

impl Residual for LengthOf {
    fn name(&self) -> &str {
        ArcLength::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2; self.blocks])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let mut sum = T::zero();
        for (k, (_, w)) in self.nodes.iter().enumerate() {
            let c1 = self.speed_vector(x, k);
            sum += cst::<T>(*w) * dot(c1, c1).sqrt();
        }
        out[0] = sum - cst::<T>(self.length);
    }
}

/// The nodes (parameter, weight) of the composite 8-point Gauss–Legendre rule with `pieces`
/// sub-intervals per span between successive `breakpoints`.
pub(crate) fn composite_rule(breakpoints: &[f64], pieces: usize) -> Vec<(f64, f64)> {
    let mut nodes = Vec::with_capacity(breakpoints.len() * pieces * GAUSS_8.len());
    for w in breakpoints.windows(2) {
        let h = (w[1] - w[0]) / pieces as f64;
        for s in 0..pieces {
            let (a, b) = (w[0] + h * s as f64, w[0] + h * (s + 1) as f64);
            for (x, wt) in GAUSS_8 {
                nodes.push((0.5 * (a + b) + 0.5 * (b - a) * x, 0.5 * (b - a) * wt));
            }
        }
    }
    nodes
}

/// The distinct knots of a curve over its domain (its breakpoints), increasing.
pub(crate) fn breakpoints(e: &crate::ground::entity::Entity) -> Vec<f64> {
    let (a, b) = e.domain().unwrap_or((0.0, 1.0));
    let mut out = vec![a];
    let chain_knots;
    let knots: &[f64] = match e {
        crate::ground::entity::Entity::BSpline(c) => c.knots().as_slice(),
        crate::ground::entity::Entity::Nurbs(c) => c.knots().as_slice(),
        crate::ground::entity::Entity::Composite(c) => {
            chain_knots = c.knots();
            chain_knots.as_slice()
        }
        _ => &[],
    };
    for k in knots {
        if *k > a && *k < b && out.last().is_some_and(|l| k > l) {
            out.push(*k);
        }
    }
    out.push(b);
    out
}

impl ConstraintKind for ArcLength {
    const TAG: &'static str = "arc_length";
    const LABEL: &'static str = "arc length";

    fn value(&self) -> Option<f64> {
        Some(self.length)
    }

    fn value_field(&self) -> Option<&'static str> {
        Some("length")
    }

    fn set_value(&mut self, value: f64) -> bool {
        self.length = value;
        true
    }

    fn entities(&self, out: &mut Entities) {
        out.add(self.curve);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let length = positive("length", self.length)?;
        if let Some(arc) = SweptArc::from_entity(cx.entity(self.curve)?) {
            let slots = arc.slots(self.curve);
            let row = match arc {
                SweptArc::Circular => ArcLengthOfArc::circular(length),
                SweptArc::Elliptic => {
                    let e = cx.entity_values(self.curve)?;
                    let (p, b) = (e.points(), e.scalars());
                    let blocks: [&[f64]; 5] = [
                        p[0].coords.as_slice(),
                        p[1].coords.as_slice(),
                        &b[..1],
                        p[2].coords.as_slice(),
                        p[3].coords.as_slice(),
                    ];
                    ArcLengthOfArc::elliptic(&blocks, length)
                }
            };
            cx.residual(row, slots, None);
            return Ok(());
        }
        let (basis, slots) = cx.curve_basis(self.curve)?;
        let e = cx.entity_values(self.curve)?;
        let points: Vec<[f64; 2]> = e.points().iter().map(|p| [p.x, p.y]).collect();
        let refs: Vec<&[f64]> = points.iter().map(|p| &p[..]).collect();
        let rule = LengthOf::new(basis, &breakpoints(e), &refs, length);
        cx.residual(rule, slots, None);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        if let Some(mid) = glyph::arc_midpoint(at.lookup(self.curve)?) {
            return Ok(vec![Glyph::Mark(mid, "L")]);
        }
        let (a, b) = (
            glyph::domain_end(at, self.curve, false)?,
            glyph::domain_end(at, self.curve, true)?,
        );
        let mid = glyph::curve_point(at, self.curve, 0.5 * (a + b))?;
        Ok(vec![Glyph::Mark(mid, "L")])
    }
}
