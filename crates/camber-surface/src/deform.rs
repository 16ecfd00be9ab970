//! Minimal deformation of a face F0 towards G1 continuity with neighbour faces F1 … Fk that
//! share its edges (after D. V. Berzin, "Surface deformation with geometric constraints").
//!
//! The unknowns are F0's control points P (knots, weights and the net size stay as they are)
//! and two scalars λ_s, μ_s per continuity sample w_s on a shared edge. The objective is
//!
//! E(P, λ, μ) = α·D + β·H + γ·G,
//!
//! - D = (1/n_D) Σ_s |S(P, w_s) − S(P⁰, w_s)|² / L² over samples on the shared edges (and on
//!   the free edges with [`DeformOptions::keep_free_edges`]): the curve error, how far the
//!   boundary moves;
//! - H = (1/n_P) Σ_k |P_k − P_k⁰|² / L² (the control-point error);
//! - G = (1/n_G) Σ_s |S_u(P, w_s) − λ_s a_s|²/|a_s|² + |S_v(P, w_s) − μ_s b_s|²/|b_s|² (the
//!   quasi-G1 error), where a_s, b_s are S_u(P⁰, w_s), S_v(P⁰, w_s) projected onto the
//!   neighbour's tangent plane at the sample: a_s = t − (t·n)n for the neighbour's unit normal n.
//!
//! L is the diagonal of F0's control box. G = 0 puts both tangents of F0 in the neighbour's
//! tangent plane, so the normals agree (G1); λ_s, μ_s let the tangents change length. Every term
//! is quadratic in (P, λ, μ), so ∇E = 0 is one sparse symmetric positive-definite linear system,
//! the normal equations that [`camber_solve::solve_least_squares`] forms and factorizes.
//!
//! When the result misses the angle or position tolerance, knots are inserted in the initial
//! surface at the middle of the knot spans holding the worst samples (along the edge), and the
//! deformation restarts from the refined initial surface, for a bounded number of rounds.

use camber_geom::queries::closest_point;
use camber_solve::{solve_least_squares, BlockId, ConstraintId, LsqOptions, Problem};
use nalgebra::{Point3, Vector3};

use crate::errors::{Error, Result};
use crate::report::{plane_angle_deg, DeformationReport, EdgeReport};
use crate::residuals::{Anchor, PointSample, TangentSample};
use crate::surface::{Direction, NurbsSurface};

/// One of the four boundary edges of a surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Edge {
    /// u = u_min (runs along v).
    UMin,
    /// u = u_max (runs along v).
    UMax,
    /// v = v_min (runs along u).
    VMin,
    /// v = v_max (runs along u).
    VMax,
}

impl Edge {
    /// All four edges.
    pub const ALL: [Edge; 4] = [Edge::UMin, Edge::UMax, Edge::VMin, Edge::VMax];

    /// The direction the edge runs along (its free parameter).
    pub fn along(self) -> Direction {
        match self {
            Edge::UMin | Edge::UMax => Direction::V,
            Edge::VMin | Edge::VMax => Direction::U,
        }
    }

    /// (u, v) of the edge point with parameter t along it.
    pub fn uv(self, s: &NurbsSurface<f64>, t: f64) -> (f64, f64) {
        let ((u0, u1), (v0, v1)) = (s.domain_u(), s.domain_v());
        match self {
            Edge::UMin => (u0, t),
            Edge::UMax => (u1, t),
            Edge::VMin => (t, v0),
            Edge::VMax => (t, v1),
        }
    }

    /// The domain of the parameter along the edge.
    pub fn range(self, s: &NurbsSurface<f64>) -> (f64, f64) {
        match self.along() {
            Direction::U => s.domain_u(),
            Direction::V => s.domain_v(),
        }
    }

    /// `n` ≥ 2 parameters evenly spaced along the edge, ends included.
    fn samples(self, s: &NurbsSurface<f64>, n: usize) -> Vec<f64> {
        let (a, b) = self.range(s);
        let last = n.saturating_sub(1).max(1) as f64;
        (0..n).map(|k| a + (b - a) * k as f64 / last).collect()
    }
}

/// A neighbour face: its surface, the edge of F0 it shares and its own edge on that boundary.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Neighbour {
    /// The neighbour's surface (not changed by the deformation).
    pub surface: NurbsSurface<f64>,
    /// The edge of F0 shared with it.
    pub face_edge: Edge,
    /// The neighbour's own edge lying on that shared boundary.
    pub neighbour_edge: Edge,
}

/// Weights, sampling and tolerances of [`deform_to_g1`].
///
/// ```
/// let o = camber_surface::DeformOptions::default().with_samples_per_edge(40).with_weights(10.0, 1e-3, 1.0);
/// assert_eq!(o.samples_per_edge, 40);
/// ```
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct DeformOptions {
    /// α > 0: weight of the curve error D.
    pub alpha: f64,
    /// β > 0: weight of the control-point error H (keeps the system positive definite).
    pub beta: f64,
    /// γ > 0: weight of the quasi-G1 error G.
    pub gamma: f64,
    /// Samples per boundary edge (≥ 2), ends included; the continuity samples are those on
    /// shared edges.
    pub samples_per_edge: usize,
    /// The largest angle allowed after deformation, in degrees.
    pub angle_tolerance_deg: f64,
    /// The largest boundary movement allowed, relative to the size L.
    pub position_tolerance: f64,
    /// Most refinement rounds (knot insertion and a new solve).
    pub max_refinements: usize,
    /// Knots inserted per round at most.
    pub knots_per_round: usize,
    /// Largest gap between F0's edge and a neighbour's edge, relative to L.
    pub adjacency_tolerance: f64,
    /// Whether the edges not shared with a neighbour also count in the curve error D (they
    /// are then held in place too; where two of F0's edges meet at a corner this can conflict
    /// with G1 at that corner). Shared edges always count.
    pub keep_free_edges: bool,
}

impl Default for DeformOptions {
    fn default() -> Self {
        Self {
            alpha: 100.0,
            beta: 1e-4,
            gamma: 1.0,
            samples_per_edge: 50,
            angle_tolerance_deg: 0.05,
            position_tolerance: 1e-4,
            max_refinements: 3,
            knots_per_round: 4,
            adjacency_tolerance: 1e-6,
            keep_free_edges: false,
        }
    }
}

impl DeformOptions {
    /// Sets α, β, γ.
    pub fn with_weights(mut self, alpha: f64, beta: f64, gamma: f64) -> Self {
        (self.alpha, self.beta, self.gamma) = (alpha, beta, gamma);
        self
    }

    /// Sets [`DeformOptions::samples_per_edge`].
    pub fn with_samples_per_edge(mut self, n: usize) -> Self {
        self.samples_per_edge = n;
        self
    }

    /// Sets [`DeformOptions::max_refinements`].
    pub fn with_max_refinements(mut self, rounds: usize) -> Self {
        self.max_refinements = rounds;
        self
    }

    /// Sets [`DeformOptions::keep_free_edges`].
    pub fn with_keep_free_edges(mut self, keep: bool) -> Self {
        self.keep_free_edges = keep;
        self
    }

    /// Sets the angle (degrees) and relative position tolerances.
    pub fn with_tolerances(mut self, angle_deg: f64, position: f64) -> Self {
        (self.angle_tolerance_deg, self.position_tolerance) = (angle_deg, position);
        self
    }

    fn check(&self) -> Result<()> {
        let positive = [
            ("alpha", self.alpha),
            ("beta", self.beta),
            ("gamma", self.gamma),
            ("angle_tolerance_deg", self.angle_tolerance_deg),
            ("position_tolerance", self.position_tolerance),
            ("adjacency_tolerance", self.adjacency_tolerance),
        ];
        for (what, value) in positive {
            if !(value.is_finite() && value > 0.0) {
                return Err(Error::InvalidOption { what, value });
            }
        }
        if self.samples_per_edge < 2 {
            return Err(Error::InvalidOption {
                what: "samples_per_edge",
                value: self.samples_per_edge as f64,
            });
        }
        Ok(())
    }
}

/// A boundary sample of term D: its (u, v) and initial point.
#[derive(Debug, Clone)]
struct BoundarySample {
    uv: (f64, f64),
    along: f64,
    edge: Edge,
    point: Point3<f64>,
}

/// A continuity sample of term G: (u, v) on F0, a_s, b_s and the neighbour's unit normal.
#[derive(Debug, Clone)]
struct ContinuitySample {
    uv: (f64, f64),
    along: f64,
    edge: Edge,
    neighbour: usize,
    a: Vector3<f64>,
    b: Vector3<f64>,
    normal: Vector3<f64>,
}

/// Deforms `face` as little as possible (objective in the module documentation) towards G1
/// continuity with every neighbour, refining the knots when a tolerance is missed.
///
/// ```
/// use camber_surface::{deform_to_g1, examples::crease_pair, DeformOptions};
/// let (face, neighbour) = crease_pair(10.0)?;
/// let (deformed, report) = deform_to_g1(&face, &[neighbour], &DeformOptions::default())?;
/// assert!(report.max_angle_before_deg() > 9.0);
/// assert!(report.max_angle_after_deg() < 0.1);
/// assert!(report.max_boundary_deviation < 1e-3 * report.size);
/// assert_eq!(deformed.degrees(), (3, 3));
/// # Ok::<(), camber_surface::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidOption`] for bad options, [`Error::NotAdjacent`] when a neighbour's edge does
/// not run along the face's edge, [`Error::DegenerateNormal`] where the neighbour has no normal,
/// and solver errors ([`Error::Solve`]).
pub fn deform_to_g1(
    face: &NurbsSurface<f64>,
    neighbours: &[Neighbour],
    options: &DeformOptions,
) -> Result<(NurbsSurface<f64>, DeformationReport)> {
    options.check()?;
    let size = face.size().max(f64::MIN_POSITIVE);
    let mut edges: Vec<Edge> = neighbours.iter().map(|n| n.face_edge).collect();
    if options.keep_free_edges {
        edges.extend(Edge::ALL);
    }
    let boundary = boundary_samples(face, &edges, options.samples_per_edge)?;
    let continuity = continuity_samples(face, neighbours, options, size)?;
    let mut initial = face.clone();
    let mut rounds = 0;
    let mut inserted = 0;
    loop {
        let (deformed, solve) = solve_once(&initial, &boundary, &continuity, options, size)?;
        let angles: Vec<f64> = continuity
            .iter()
            .map(|s| {
                let n = deformed.normal(s.uv.0, s.uv.1)?;
                Ok(plane_angle_deg(&n, &s.normal))
            })
            .collect::<Result<_>>()?;
        let deviations: Vec<f64> = boundary
            .iter()
            .map(|s| Ok((deformed.point(s.uv.0, s.uv.1)? - s.point).norm()))
            .collect::<Result<_>>()?;
        let max_dev = deviations.iter().copied().fold(0.0, f64::max);
        let max_angle = angles.iter().copied().fold(0.0, f64::max);
        let met = max_angle <= options.angle_tolerance_deg
            && max_dev <= options.position_tolerance * size;
        if met || rounds >= options.max_refinements {
            let report = build_report(
                face,
                neighbours,
                &continuity,
                &angles,
                (&initial, &deformed),
                (max_dev, size, rounds, inserted, met),
                solve,
            )?;
            return Ok((deformed, report));
        }
        let worst = worst_parameters(&continuity, &angles, &boundary, &deviations, options, size);
        let refined = refine_at(&initial, &worst, options.knots_per_round)?;
        inserted += refined.1;
        if refined.1 == 0 {
            // Nowhere left to insert: report what we have on the next pass.
            rounds = options.max_refinements;
            continue;
        }
        initial = refined.0;
        rounds += 1;
    }
}

fn boundary_samples(
    face: &NurbsSurface<f64>,
    edges: &[Edge],
    n: usize,
) -> Result<Vec<BoundarySample>> {
    let mut out = Vec::with_capacity(4 * n);
    for (k, &edge) in edges.iter().enumerate() {
        if edges[..k].contains(&edge) {
            continue;
        }
        for t in edge.samples(face, n) {
            let uv = edge.uv(face, t);
            out.push(BoundarySample {
                uv,
                along: t,
                edge,
                point: face.point(uv.0, uv.1)?,
            });
        }
    }
    Ok(out)
}

fn continuity_samples(
    face: &NurbsSurface<f64>,
    neighbours: &[Neighbour],
    options: &DeformOptions,
    size: f64,
) -> Result<Vec<ContinuitySample>> {
    let mut out = Vec::new();
    for (k, nb) in neighbours.iter().enumerate() {
        let edge_curve = nb.surface.isocurve(
            match nb.neighbour_edge.along() {
                Direction::U => Direction::V,
                Direction::V => Direction::U,
            },
            match nb.neighbour_edge {
                Edge::UMin => nb.surface.domain_u().0,
                Edge::UMax => nb.surface.domain_u().1,
                Edge::VMin => nb.surface.domain_v().0,
                Edge::VMax => nb.surface.domain_v().1,
            },
        )?;
        let mut gap = 0.0_f64;
        let face_range = nb.face_edge.range(face);
        for t in nb.face_edge.samples(face, options.samples_per_edge) {
            let uv = nb.face_edge.uv(face, t);
            let d = face.derivatives(uv.0, uv.1)?;
            let (parameter, distance) = match_on_edge(nb, &edge_curve, face_range, t, &d.point)?;
            gap = gap.max(distance);
            let (nu, nv) = nb.neighbour_edge.uv(&nb.surface, parameter);
            let n = nb.surface.normal(nu, nv)?;
            out.push(ContinuitySample {
                uv,
                along: t,
                edge: nb.face_edge,
                neighbour: k,
                a: d.su - n * n.dot(&d.su),
                b: d.sv - n * n.dot(&d.sv),
                normal: n,
            });
        }
        let tolerance = options.adjacency_tolerance * size;
        if gap > tolerance {
            return Err(Error::NotAdjacent {
                neighbour: k,
                gap,
                tolerance,
            });
        }
    }
    Ok(out)
}

/// The neighbour's edge parameter of the face's edge point `p` (at `t` in `face_range`) and its
/// distance. Shared edges are usually parameterized alike (or reversed), so the affine maps of
/// `face_range` onto the neighbour's edge range are tried first; when neither lands within
/// rounding of `p`, the closest point on the neighbour's edge curve is searched.
fn match_on_edge(
    nb: &Neighbour,
    edge_curve: &camber_geom::NurbsCurve3<f64>,
    (a, b): (f64, f64),
    t: f64,
    p: &Point3<f64>,
) -> Result<(f64, f64)> {
    let (c, d) = nb.neighbour_edge.range(&nb.surface);
    let s = (t - a) / (b - a);
    let scale = 1.0 + p.coords.norm();
    for guess in [c + s * (d - c), d - s * (d - c)] {
        let guess = guess.clamp(c, d);
        let (nu, nv) = nb.neighbour_edge.uv(&nb.surface, guess);
        let dist = (nb.surface.point(nu, nv)? - p).norm();
        if dist <= 1e-12 * scale {
            return Ok((guess, dist));
        }
    }
    let hit = closest_point(edge_curve, p)?;
    Ok((hit.parameter, hit.distance))
}

/// One least-squares solve on the (possibly refined) initial surface.
fn solve_once(
    initial: &NurbsSurface<f64>,
    boundary: &[BoundarySample],
    continuity: &[ContinuitySample],
    options: &DeformOptions,
    size: f64,
) -> Result<(NurbsSurface<f64>, camber_solve::LsqReport)> {
    let inv_scale = 1.0 / size;
    let mut problem = Problem::new();
    let mut weights = Vec::new();
    let points = initial.control_points();
    let blocks: Vec<BlockId> = points
        .iter()
        .map(|p| problem.add_block(&[p.x, p.y, p.z]))
        .collect::<std::result::Result<_, _>>()?;
    let owner = ConstraintId(0);
    let w_h = options.beta / points.len().max(1) as f64;
    for (p, b) in points.iter().zip(&blocks) {
        let start = [p.x, p.y, p.z];
        problem.add_residual(Anchor { start, inv_scale }, &[*b], owner)?;
        weights.push(w_h);
    }
    let w_d = options.alpha / boundary.len().max(1) as f64;
    for s in boundary {
        let basis = initial.basis(s.uv.0, s.uv.1)?;
        let read: Vec<BlockId> = basis.indices.iter().map(|i| blocks[*i]).collect();
        let target = [s.point.x, s.point.y, s.point.z];
        let residual = PointSample {
            coeffs: basis.value,
            target,
            inv_scale,
        };
        problem.add_residual(residual, &read, ConstraintId(1))?;
        weights.push(w_d);
    }
    let w_g = options.gamma / continuity.len().max(1) as f64;
    for s in continuity {
        let basis = initial.basis(s.uv.0, s.uv.1)?;
        let mut read: Vec<BlockId> = basis.indices.iter().map(|i| blocks[*i]).collect();
        read.push(problem.add_block(&[1.0, 1.0])?);
        let inv = |v: &Vector3<f64>| 1.0 / v.norm().max(f64::MIN_POSITIVE);
        let residual = TangentSample {
            du: basis.du,
            dv: basis.dv,
            a: [s.a.x, s.a.y, s.a.z],
            b: [s.b.x, s.b.y, s.b.z],
            inv_norms: [inv(&s.a), inv(&s.b)],
        };
        problem.add_residual(residual, &read, ConstraintId(2 + s.neighbour as u64))?;
        weights.push(w_g);
    }
    let report = solve_least_squares(&mut problem, &weights, &LsqOptions::default())?;
    let moved: Vec<Point3<f64>> = problem
        .values()
        .chunks_exact(3)
        .take(points.len())
        .map(|c| Point3::new(c[0], c[1], c[2]))
        .collect();
    Ok((initial.try_with_control_points(moved)?, report))
}

/// Parameters (direction, value) along the edge of the samples that miss a tolerance, worst
/// first.
fn worst_parameters(
    continuity: &[ContinuitySample],
    angles: &[f64],
    boundary: &[BoundarySample],
    deviations: &[f64],
    options: &DeformOptions,
    size: f64,
) -> Vec<(Direction, f64)> {
    let mut bad: Vec<(f64, Direction, f64)> = Vec::new();
    for (s, a) in continuity.iter().zip(angles) {
        if *a > options.angle_tolerance_deg {
            let dir = s.edge.along();
            bad.push((a / options.angle_tolerance_deg, dir, s.along));
        }
    }
    for (s, d) in boundary.iter().zip(deviations) {
        let limit = options.position_tolerance * size;
        if *d > limit {
            bad.push((d / limit, s.edge.along(), s.along));
        }
    }
    bad.sort_by(|x, y| y.0.total_cmp(&x.0));
    bad.into_iter().map(|(_, d, t)| (d, t)).collect()
}

/// Inserts up to `limit` knots, each at the middle of the span (in its direction) holding one of
/// the given parameters, skipping spans already split this round. Returns the surface and the
/// number inserted.
fn refine_at(
    s: &NurbsSurface<f64>,
    worst: &[(Direction, f64)],
    limit: usize,
) -> Result<(NurbsSurface<f64>, usize)> {
    let mut new_u: Vec<f64> = Vec::new();
    let mut new_v: Vec<f64> = Vec::new();
    let (p, q) = s.degrees();
    for (dir, t) in worst {
        if new_u.len() + new_v.len() >= limit {
            break;
        }
        let (knots, degree, list) = match dir {
            Direction::U => (s.knots_u(), p, &mut new_u),
            Direction::V => (s.knots_v(), q, &mut new_v),
        };
        let span = knots.find_span(degree, *t);
        let k = knots.as_slice();
        let (Some(a), Some(b)) = (k.get(span), k.get(span + 1)) else {
            continue;
        };
        let mid = 0.5 * (a + b);
        if b > a && !list.iter().any(|m| (m - mid).abs() <= f64::EPSILON) {
            list.push(mid);
        }
    }
    let count = new_u.len() + new_v.len();
    new_u.sort_by(f64::total_cmp);
    new_v.sort_by(f64::total_cmp);
    let mut out = s.clone();
    if !new_u.is_empty() {
        out = out.refine(Direction::U, &new_u)?;
    }
    if !new_v.is_empty() {
        out = out.refine(Direction::V, &new_v)?;
    }
    Ok((out, count))
}

fn build_report(
    face: &NurbsSurface<f64>,
    neighbours: &[Neighbour],
    continuity: &[ContinuitySample],
    angles_after: &[f64],
    (initial, deformed): (&NurbsSurface<f64>, &NurbsSurface<f64>),
    (max_dev, size, rounds, inserted, met): (f64, f64, usize, usize, bool),
    solve: camber_solve::LsqReport,
) -> Result<DeformationReport> {
    let mut edges: Vec<EdgeReport> = neighbours
        .iter()
        .enumerate()
        .map(|(k, nb)| EdgeReport {
            neighbour: k,
            edge: nb.face_edge,
            parameters: Vec::new(),
            angles_before_deg: Vec::new(),
            angles_after_deg: Vec::new(),
        })
        .collect();
    for (s, after) in continuity.iter().zip(angles_after) {
        let n0 = face.normal(s.uv.0, s.uv.1)?;
        if let Some(e) = edges.get_mut(s.neighbour) {
            e.parameters.push(s.along);
            e.angles_before_deg.push(plane_angle_deg(&n0, &s.normal));
            e.angles_after_deg.push(*after);
        }
    }
    let max_cp = initial
        .control_points()
        .iter()
        .zip(deformed.control_points())
        .map(|(a, b)| (a - b).norm())
        .fold(0.0, f64::max);
    Ok(DeformationReport {
        edges,
        max_boundary_deviation: max_dev,
        size,
        max_control_point_movement: max_cp,
        refinement_rounds: rounds,
        knots_inserted: inserted,
        met_tolerances: met,
        solve,
    })
}
