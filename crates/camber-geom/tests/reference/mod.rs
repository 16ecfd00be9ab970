//! An independent arc-length reference for the tests: composite 5-point Gauss–Legendre on a
//! fixed grid (every piece between breakpoints, and between any extra cuts, split into equal
//! steps), with the cumulative length at every grid node. It shares no code with the library's
//! adaptive 8-point quadrature: a different rule, a fixed grid, no error estimate.

// Test helpers unwrap: a failed evaluation is a failed test.
#![allow(clippy::unwrap_used, dead_code)]

use camber_geom::ParametricCurve;

/// Nodes and weights of the 5-point Gauss–Legendre rule on [−1, 1] (tabulated).
const GL5: [(f64, f64); 5] = [
    (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.0, 0.568_888_888_888_888_9),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];

/// The 5-point rule for ∫|C′| over [a, b] (open: never evaluates at a or b).
pub fn gl5<const D: usize>(curve: &dyn ParametricCurve<f64, D>, a: f64, b: f64) -> f64 {
    let (half, mid) = (0.5 * (b - a), 0.5 * (a + b));
    GL5.iter()
        .map(|&(x, w)| w * curve.derivative(mid + half * x).unwrap().norm())
        .sum::<f64>()
        * half
}

/// Cumulative arc length on a fixed grid.
pub struct Reference {
    nodes: Vec<f64>,
    cumulative: Vec<f64>,
}

impl Reference {
    /// The grid: the curve's breakpoints and `cuts` (inside the domain), each piece between
    /// them split into `steps` equal steps.
    pub fn new<const D: usize>(
        curve: &dyn ParametricCurve<f64, D>,
        cuts: &[f64],
        steps: usize,
    ) -> Self {
        let (a, b) = curve.domain();
        let mut breaks: Vec<f64> = curve.breakpoints();
        breaks.extend(cuts.iter().copied().filter(|&u| u > a && u < b));
        breaks.push(a);
        breaks.push(b);
        breaks.sort_by(f64::total_cmp);
        breaks.dedup();
        let mut nodes = vec![a];
        for w in breaks.windows(2) {
            for k in 1..=steps {
                nodes.push(w[0] + (w[1] - w[0]) * k as f64 / steps as f64);
            }
        }
        let mut cumulative = vec![0.0];
        let mut sum = 0.0;
        for w in nodes.windows(2) {
            sum += gl5(curve, w[0], w[1]);
            cumulative.push(sum);
        }
        Self { nodes, cumulative }
    }

    /// The total length.
    pub fn total(&self) -> f64 {
        *self.cumulative.last().unwrap()
    }

    /// The length from the domain start to `u`: the grid up to the node before u, then the
    /// rest of that step in eight sub-steps.
    pub fn length_to<const D: usize>(&self, curve: &dyn ParametricCurve<f64, D>, u: f64) -> f64 {
        let k = self.nodes.partition_point(|&x| x <= u).saturating_sub(1);
        let k = k.min(self.nodes.len() - 1);
        let start = self.nodes[k];
        let mut sum = self.cumulative[k];
        if u > start {
            for j in 0..8 {
                let lo = start + (u - start) * j as f64 / 8.0;
                let hi = start + (u - start) * (j + 1) as f64 / 8.0;
                sum += gl5(curve, lo, hi);
            }
        }
        sum
    }
}
