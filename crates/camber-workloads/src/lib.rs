//! The standard workloads of `shared/benchmarks/WORKLOADS.md` (W1, W2 in both representations,
//! W3 and its affine variant W3a, W4, the rectangles W5 and the ladder W5b), the blade section
//! of the paper and the two-curve sketch,
//! built as sketches so that benchmarks, tests and tools share one definition, each with a
//! validity check that reads the geometry and never the solver's status.

use camber_geom::BezierCurve2;
use nalgebra::{Point2, Vector2};

use camber_sketch::constraints::{
    C2Join, Distance, Fixed, G1Join, G1JoinFree, StartTangent, TangentToCircle,
};
use camber_sketch::vocabulary::{CircleSide, Contact, Rotation, Sense, TangentForm};
use camber_sketch::Entity;
use camber_sketch::Result;
use camber_sketch::Sketch;
use camber_sketch::{EntityId, PointRef};

pub mod airfoils;
mod free_points;
mod point_chain;
mod rectangles;
mod rounded;
mod two_curves;
mod variants;
pub use free_points::{free_points, free_points_valid};
pub use point_chain::{point_chain, point_chain_valid};
pub use rectangles::{w5, w5_at, w5_valid, w5b, Rectangles};
pub use rounded::{rounded_plate, w5r, w5r_valid, RoundedRectangles, Tangency, W5R_RADIUS};
pub use two_curves::{two_curves, two_curves_valid, TwoCurves, TWO_CURVES_CIRCLES};
pub use variants::{w8_circles, w8_variants, Circles};

/// W1: the cubic P₀ = (0, 0), P₁ = 1.2·D, P₂ = (2.2, 0.9), P₃ = (3, 0) with D = (cos 30°,
/// sin 30°); P₃ fixed; start tangent parallel to D with the same sense (in `form`). Returns the
/// sketch, the curve and D.
///
/// ```
/// let (s, c, d) = camber_workloads::w1(camber_sketch::TangentForm::Row)?;
/// assert!((s.point(camber_sketch::PointRef::Control(c, 1))?.x - 1.2 * d.x).abs() < 1e-15);
/// # Ok::<(), camber_sketch::Error>(())
/// ```
///
/// # Errors
/// None in practice (the data are valid); the signature carries the sketch's errors.
pub fn w1(form: TangentForm) -> Result<(Sketch, EntityId, Vector2<f64>)> {
    let a = 30f64.to_radians();
    let d = Vector2::new(a.cos(), a.sin());
    let mut s = Sketch::new();
    let c = s.add_bezier(BezierCurve2::try_new(vec![
        Point2::origin(),
        Point2::from(1.2 * d),
        Point2::new(2.2, 0.9),
        Point2::new(3.0, 0.0),
    ])?)?;
    s.add_constraint(Fixed::point(PointRef::Control(c, 3)))?;
    s.add_constraint(StartTangent {
        curve: c,
        direction: d,
        sense: Sense::Agree,
        form,
    })?;
    Ok((s, c, d))
}

/// The W1 drag targets: P₁ + 0.2·(cos θₖ − 1, sin θₖ), θₖ = 2πk/200, k = 1..200.
pub fn w1_targets(p1: Point2<f64>) -> Vec<Point2<f64>> {
    (1..=200)
        .map(|k| {
            let th = std::f64::consts::TAU * k as f64 / 200.0;
            p1 + 0.2 * Vector2::new(th.cos() - 1.0, th.sin())
        })
        .collect()
}

/// The curves of a blade section around its leading edge.
#[derive(Debug, Clone, Copy)]
pub struct Blade {
    /// Pressure side, a quintic from the trailing edge to the leading edge (start fixed).
    pub pressure: EntityId,
    /// Leading edge, a quintic from the pressure-side end to the suction-side start.
    pub leading: EntityId,
    /// Suction side, a quintic from the leading edge to the trailing edge (end fixed).
    pub suction: EntityId,
}

/// The blade section: three quintic Béziers (18 control points) joined G1 at the leading edge
/// with the joint directions fixed (the pressure side's end tangent and the suction side's
/// start tangent), outer ends fixed: 8 affine rows, 32 free unknowns.
///
/// # Errors
/// None in practice.
pub fn blade() -> Result<(Sketch, Blade)> {
    let pts = |v: &[(f64, f64)]| v.iter().map(|(x, y)| Point2::new(*x, *y)).collect();
    let mut s = Sketch::new();
    let pressure = s.add_bezier(BezierCurve2::try_new(pts(&[
        (1.0, 0.0),
        (0.8, -0.04),
        (0.6, -0.06),
        (0.35, -0.06),
        (0.15, -0.045),
        (0.05, -0.03),
    ]))?)?;
    let leading = s.add_bezier(BezierCurve2::try_new(pts(&[
        (0.05, -0.03),
        (0.0, -0.0225),
        (-0.01, -0.01),
        (-0.01, 0.01),
        (0.0, 0.03),
        (0.05, 0.04),
    ]))?)?;
    let suction = s.add_bezier(BezierCurve2::try_new(pts(&[
        (0.05, 0.04),
        (0.15, 0.06),
        (0.35, 0.08),
        (0.6, 0.075),
        (0.8, 0.05),
        (1.0, 0.0),
    ]))?)?;
    s.add_constraint(Fixed::point(PointRef::Start(pressure)))?;
    s.add_constraint(Fixed::point(PointRef::End(suction)))?;
    s.add_constraint(G1Join {
        first: pressure,
        second: leading,
        direction: Vector2::new(-0.1, 0.015),
    })?;
    s.add_constraint(G1Join {
        first: leading,
        second: suction,
        direction: Vector2::new(0.05, 0.01),
    })?;
    Ok((
        s,
        Blade {
            pressure,
            leading,
            suction,
        },
    ))
}

/// The W3 joint Jₖ = (k, 0.5·sin(2πk/12)).
fn sine_joint(k: usize) -> Point2<f64> {
    let w = std::f64::consts::TAU / 12.0;
    Point2::new(k as f64, 0.5 * (w * k as f64).sin())
}

/// The W3 unit tangent Tₖ along (1, 0.5·(2π/12)·cos(2πk/12)).
fn sine_tangent(k: usize) -> Vector2<f64> {
    let w = std::f64::consts::TAU / 12.0;
    Vector2::new(1.0, 0.5 * w * (w * k as f64).cos()).normalize()
}

/// The W3 initial chain: `n` cubic segments with joints [`sine_joint`], inner control points
/// Jᵢ + hᵢTᵢ and Jᵢ₊₁ − hᵢTᵢ₊₁, hᵢ = |Jᵢ₊₁ − Jᵢ|/3. Returns the sketch and the segments.
fn sine_chain(n: usize) -> Result<(Sketch, Vec<EntityId>)> {
    let mut s = Sketch::new();
    let mut segs = Vec::with_capacity(n);
    for i in 0..n {
        let (a, b) = (sine_joint(i), sine_joint(i + 1));
        let h = (b - a).norm() / 3.0;
        segs.push(s.add_bezier(BezierCurve2::try_new(vec![
            a,
            a + h * sine_tangent(i),
            b - h * sine_tangent(i + 1),
            b,
        ])?)?);
    }
    Ok((s, segs))
}

/// Fixes the chain's first point, moves its last point by (−0.3, 0.4) and fixes it there.
fn pin_chain_ends(s: &mut Sketch, segs: &[EntityId]) -> Result<()> {
    if let (Some(first), Some(last)) = (segs.first(), segs.last()) {
        s.add_constraint(Fixed::point(PointRef::Control(*first, 0)))?;
        let end = PointRef::Control(*last, 3);
        let moved = s.point(end)? + Vector2::new(-0.3, 0.4);
        s.set_point(end, moved)?;
        s.add_constraint(Fixed::point(end))?;
    }
    Ok(())
}

/// W3: the sine chain of [`w3a_chain`] with the joint directions free: consecutive segments
/// joined by [`G1JoinFree`] (coincident, tangents parallel with the same sense),
/// each segment's chord |P₃ − P₀| held at its initial length by [`Distance`], the
/// first point fixed and the last moved by (−0.3, 0.4) and fixed there. Nonlinear: 3(n − 1) +
/// n rows over 8n unknowns less the pinned ends. Returns the sketch (dirty) and the segments.
///
/// ```
/// let (s, segs) = camber_workloads::w3_chain(3)?;
/// assert_eq!(segs.len(), 3);
/// assert!(!camber_workloads::w3_valid(&s, &segs, 1e-6)); // the end was moved
/// # Ok::<(), camber_sketch::Error>(())
/// ```
///
/// # Errors
/// None in practice.
pub fn w3_chain(n: usize) -> Result<(Sketch, Vec<EntityId>)> {
    let (mut s, segs) = sine_chain(n)?;
    for pair in segs.windows(2) {
        s.add_constraint(G1JoinFree {
            first: pair[0],
            second: pair[1],
        })?;
    }
    for &seg in &segs {
        let chord = (s.point(PointRef::End(seg))? - s.point(PointRef::Start(seg))?).norm();
        s.add_constraint(Distance {
            a: PointRef::Start(seg),
            b: PointRef::End(seg),
            distance: chord,
        })?;
    }
    pin_chain_ends(&mut s, &segs)?;
    Ok((s, segs))
}

/// The W3 validity check, independent of the solver: every joint coincident to `tol`, its
/// tangents parallel (|sin| ≤ tol) with the same sense, every chord at its initial length
/// (the W3 construction's |Jᵢ₊₁ − Jᵢ|) to `tol`, the first point at J₀ and the last at
/// J_N + (−0.3, 0.4).
pub fn w3_valid(s: &Sketch, segs: &[EntityId], tol: f64) -> bool {
    let joint = sine_joint;
    let cp = |seg: EntityId, i: usize| s.point(PointRef::Control(seg, i)).ok();
    let n = segs.len();
    let (Some(&first), Some(&last)) = (segs.first(), segs.last()) else {
        return true;
    };
    let ends_ok = cp(first, 0).is_some_and(|p| (p - joint(0)).norm() <= tol)
        && cp(last, 3).is_some_and(|p| (p - (joint(n) + Vector2::new(-0.3, 0.4))).norm() <= tol);
    let chords_ok = segs.iter().enumerate().all(|(i, &seg)| {
        let chord = (joint(i + 1) - joint(i)).norm();
        matches!((cp(seg, 0), cp(seg, 3)), (Some(a), Some(b)) if ((b - a).norm() - chord).abs() <= tol)
    });
    let joints_ok = segs.windows(2).all(|pair| {
        let (Some(a2), Some(a3), Some(b0), Some(b1)) = (
            cp(pair[0], 2),
            cp(pair[0], 3),
            cp(pair[1], 0),
            cp(pair[1], 1),
        ) else {
            return false;
        };
        let (ta, tb) = (a3 - a2, b1 - b0);
        let sin = (ta.x * tb.y - ta.y * tb.x) / (ta.norm() * tb.norm());
        (a3 - b0).norm() <= tol && sin.abs() <= tol && ta.dot(&tb) > 0.0
    });
    ends_ok && chords_ok && joints_ok
}

/// W3a (WORKLOADS.md, as redefined): `n` cubic segments along y = 0.5·sin(2πx/12), each with
/// its own four control points, consecutive segments joined C2 by affine rows ([`C2Join`]: at
/// each joint P3ᵢ = P0ᵢ₊₁, and equal first and second derivatives), the first point fixed and
/// the last point moved by (−0.3, 0.4) and fixed there. The start (the sine chain) is neither
/// C1 nor C2, so the one minimum-norm solve moves every segment: 8n unknowns, 6(n − 1) rows.
/// Returns the sketch (dirty, not solved) and the segments.
///
/// # Errors
/// None in practice.
pub fn w3a_chain(n: usize) -> Result<(Sketch, Vec<EntityId>)> {
    let (mut s, segs) = sine_chain(n)?;
    for i in 1..n {
        s.add_constraint(C2Join {
            first: segs[i - 1],
            second: segs[i],
        })?;
    }
    pin_chain_ends(&mut s, &segs)?;
    Ok((s, segs))
}

/// W4: `n` independent cubics, each with both ends fixed and a start tangent (row form) along
/// a direction that its first leg misses by a few degrees, so that every component needs a
/// solve. Returns the sketch (dirty) and the curves.
///
/// # Errors
/// None in practice.
pub fn w4(n: usize) -> Result<(Sketch, Vec<EntityId>)> {
    let mut s = Sketch::new();
    let mut curves = Vec::with_capacity(n);
    for i in 0..n {
        let x = 4.0 * i as f64;
        let c = s.add_bezier(BezierCurve2::try_new(vec![
            Point2::new(x, 0.0),
            Point2::new(x + 1.0, 1.0),
            Point2::new(x + 2.0, 1.0),
            Point2::new(x + 3.0, 0.0),
        ])?)?;
        s.add_constraint(Fixed::point(PointRef::Start(c)))?;
        s.add_constraint(Fixed::point(PointRef::End(c)))?;
        s.add_constraint(StartTangent {
            curve: c,
            direction: w4_direction(i),
            sense: Sense::Agree,
            form: TangentForm::Row,
        })?;
        curves.push(c);
    }
    Ok((s, curves))
}

/// The start direction of the W4 curve number `i`: (cos a, sin a) with a = 40° + (i mod 10)°.
fn w4_direction(i: usize) -> Vector2<f64> {
    let a = (40.0 + (i % 10) as f64).to_radians();
    Vector2::new(a.cos(), a.sin())
}

/// The W4 validity check, independent of the solver: curve number `i` still starts at (4i, 0)
/// and ends at (4i + 3, 0) (to `tol`), and its first leg P₁ − P₀ is parallel to
/// [`w4`]'s direction for it (|sin| ≤ `tol`) with the same sense.
///
/// ```
/// let (mut s, curves) = camber_workloads::w4(3)?;
/// assert!(!camber_workloads::w4_valid(&s, &curves, 1e-9));
/// s.solve()?;
/// assert!(camber_workloads::w4_valid(&s, &curves, 1e-9));
/// # Ok::<(), camber_sketch::Error>(())
/// ```
pub fn w4_valid(s: &Sketch, curves: &[EntityId], tol: f64) -> bool {
    curves.iter().enumerate().all(|(i, &c)| {
        let cp = |k: usize| s.point(PointRef::Control(c, k)).ok();
        let (Some(p0), Some(p1), Some(p3)) = (cp(0), cp(1), cp(3)) else {
            return false;
        };
        let x = 4.0 * i as f64;
        let leg = p1 - p0;
        let d = w4_direction(i);
        (p0 - Point2::new(x, 0.0)).norm() <= tol
            && (p3 - Point2::new(x + 3.0, 0.0)).norm() <= tol
            && cross(leg, d).abs() <= tol * leg.norm()
            && leg.dot(&d) > 0.0
    })
}

/// The z-component of the cross product of two plane vectors.
fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The W1 validity check for one drag update, independent of the solver: the start leg
/// P₁ − P₀ parallel to `d` (|sin| < 1e-7) with the same sense, P₃ where it was (`p3`, to
/// 1e-12) and P₁ at the drag target (to 1e-9). `points` are P₀…P₃ after the update.
pub fn w1_valid(
    points: &[Point2<f64>; 4],
    d: Vector2<f64>,
    target: Point2<f64>,
    p3: Point2<f64>,
) -> bool {
    let leg = points[1] - points[0];
    let sin = cross(leg, d) / (leg.norm() * d.norm());
    sin.abs() < 1e-7
        && leg.dot(&d) > 0.0
        && (points[3] - p3).norm() <= 1e-12
        && (points[1] - target).norm() <= 1e-9
}

/// The least displacement of W1's free points P₀ and P₂ that meets the constraints after P₁
/// is pinned at `target`, computed by hand: P₂ is not constrained and stays, and P₀ must lie on
/// the line through the target along `d`, so it moves by its distance to that line,
/// |cross(target − P₀, d)|/|d|. `before` are P₀…P₃ before the update.
pub fn w1_min_norm_displacement(
    before: &[Point2<f64>; 4],
    d: Vector2<f64>,
    target: Point2<f64>,
) -> f64 {
    cross(target - before[0], d).abs() / d.norm()
}

/// The W3a validity check, independent of the solver, with WORKLOADS.md's rows written out at
/// every joint between segments i and i + 1: P3ᵢ − P0ᵢ₊₁ (C0), (P3ᵢ − P2ᵢ) − (P1ᵢ₊₁ − P0ᵢ₊₁)
/// (C1) and (P1ᵢ − 2P2ᵢ + P3ᵢ) − (P0ᵢ₊₁ − 2P1ᵢ₊₁ + P2ᵢ₊₁) (C2), each within `tol`, and the pins:
/// the first point at J₀ and the last at J_N + (−0.3, 0.4) (to 1e-12).
///
/// ```
/// use camber_sketch::PointRef;
/// use camber_workloads as workloads;
/// let (mut s, segs) = workloads::w3a_chain(4)?;
/// // The sine chain is G1 but not C2: nothing holds until the solve.
/// assert!(!workloads::w3a_valid(&s, &segs, 1e-9));
/// s.solve()?;
/// assert!(workloads::w3a_valid(&s, &segs, 1e-9));
/// # Ok::<(), camber_sketch::Error>(())
/// ```
pub fn w3a_valid(s: &Sketch, segs: &[EntityId], tol: f64) -> bool {
    let cp = |seg: EntityId, i: usize| s.point(PointRef::Control(seg, i)).ok();
    let n = segs.len();
    let (Some(&first), Some(&last)) = (segs.first(), segs.last()) else {
        return true;
    };
    let pins_ok = cp(first, 0).is_some_and(|p| (p - sine_joint(0)).norm() <= 1e-12)
        && cp(last, 3)
            .is_some_and(|p| (p - (sine_joint(n) + Vector2::new(-0.3, 0.4))).norm() <= 1e-12);
    let joints_ok = segs.windows(2).all(|pair| {
        let (Some(a), Some(b)) = (
            (0..4).map(|k| cp(pair[0], k)).collect::<Option<Vec<_>>>(),
            (0..4).map(|k| cp(pair[1], k)).collect::<Option<Vec<_>>>(),
        ) else {
            return false;
        };
        let c0 = a[3] - b[0];
        let c1 = (a[3] - a[2]) - (b[1] - b[0]);
        let c2 = (a[1].coords - 2.0 * a[2].coords + a[3].coords)
            - (b[0].coords - 2.0 * b[1].coords + b[2].coords);
        c0.norm() <= tol && c1.norm() <= tol && c2.norm() <= tol
    });
    pins_ok && joints_ok
}

/// The three circles of W2 as (centre, radius): leading edge, thickness, trailing edge.
pub const W2_CIRCLES: [([f64; 2], f64); 3] = [
    ([0.03, 0.0], 0.03),
    ([0.38, 0.04], 0.07),
    ([0.985, 0.01], 0.015),
];

/// The point of circle (c, r) at `degrees`: c + r·(cos a, sin a).
pub fn on_circle(circle: ([f64; 2], f64), degrees: f64) -> Point2<f64> {
    let (c, r) = circle;
    let a = degrees.to_radians();
    Point2::new(c[0] + r * a.cos(), c[1] + r * a.sin())
}

/// The entities of a W2 sketch.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct W2 {
    /// The B-spline.
    pub curve: EntityId,
    /// The leading-edge, thickness and trailing-edge circles (fixed).
    pub circles: [EntityId; 3],
}

/// W2 `bspline7` at its rough start: a clamped cubic B-spline with 7 control points on the knots
/// [0,0,0,0, ¼, ½, ¾, 1,1,1,1], tangent to the LE circle at u = 0 and the TE circle at u = 1, and
/// to the TH circle at a free contact parameter (starting at the parameter of the rough start's
/// point nearest the TH centre); outside every circle, running clockwise around each (from the
/// leading edge over the top of TH to the trailing edge). The circles are fixed.
///
/// ```
/// let (mut s, w) = camber_workloads::w2_bspline7()?;
/// let report = s.solve()?;
/// assert_eq!(report.components.len(), 1);
/// # let _ = w;
/// # Ok::<(), camber_sketch::Error>(())
/// ```
///
/// # Errors
/// None in practice (the data are valid); the signature carries the sketch's errors.
pub fn w2_bspline7() -> Result<(Sketch, W2)> {
    let [le, th, te] = W2_CIRCLES;
    let points = vec![
        on_circle(le, 110.0),
        Point2::new(0.07, 0.06),
        Point2::new(0.18, 0.115),
        Point2::new(0.38, 0.125),
        Point2::new(0.62, 0.10),
        Point2::new(0.86, 0.045),
        on_circle(te, 70.0),
    ];
    let knots = camber_geom::KnotVector::try_new(vec![
        0.0, 0.0, 0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0, 1.0, 1.0,
    ])?;
    let curve = camber_geom::BSplineCurve2::try_new(3, knots, points)?;
    let u_th = nearest_parameter(&curve, th.0);
    let mut s = Sketch::new();
    let c = s.add_bspline(curve)?;
    let mut circles = [c; 3];
    for (slot, (centre, r)) in circles.iter_mut().zip(W2_CIRCLES) {
        *slot = s.add_circle(Point2::new(centre[0], centre[1]), r)?;
        s.add_constraint(Fixed::entity(*slot))?;
    }
    for (circle, u) in [
        (circles[0], Contact::At(0.0)),
        (circles[1], Contact::Free(u_th)),
        (circles[2], Contact::At(1.0)),
    ] {
        s.add_constraint(TangentToCircle {
            curve: c,
            circle,
            u,
            side: CircleSide::Outside,
            rotation: Rotation::Clockwise,
        })?;
    }
    Ok((s, W2 { curve: c, circles }))
}

/// The parameter of the curve point nearest `p`, by sampling (a starting guess).
fn nearest_parameter(curve: &camber_geom::BSplineCurve2<f64>, p: [f64; 2]) -> f64 {
    use camber_geom::ParametricCurve;
    let (a, b) = curve.domain();
    let mut best = (f64::INFINITY, a);
    for i in 0..=200 {
        let u = a + (b - a) * f64::from(i) / 200.0;
        if let Ok(q) = curve.point(u) {
            let d = (q.x - p[0]).hypot(q.y - p[1]);
            if d < best.0 {
                best = (d, u);
            }
        }
    }
    best.1
}

/// W2's perturbed starts: `trials` copies of the solved sketch `base` with every control point
/// of `w.curve` moved by uniform noise in [−δ, δ]² (a seeded splitmix64 generator).
///
/// # Errors
/// Errors of reading or moving the points (none for a W2 sketch).
pub fn w2_perturbed(
    base: &Sketch,
    w: &W2,
    delta: f64,
    trials: usize,
    seed: u64,
) -> Result<Vec<Sketch>> {
    let mut noise = uniform_noise(seed);
    let n = base.entity(w.curve)?.points().len();
    let mut out = Vec::with_capacity(trials);
    for _ in 0..trials {
        let mut s = base.clone();
        for j in 0..n {
            let p = s.point(PointRef::Control(w.curve, j))?;
            let q = Point2::new(p.x + delta * noise(), p.y + delta * noise());
            s.set_point(PointRef::Control(w.curve, j), q)?;
        }
        out.push(s);
    }
    Ok(out)
}

/// A seeded splitmix64 generator of uniform numbers in [−1, 1).
fn uniform_noise(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || {
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
}

/// W2's validity check at tolerance 1e-6: the curve's ends on the LE and TE circles with the
/// tangent perpendicular to the radius there; the least distance from each centre to the curve
/// equal to the radius for TH (contact on its upper half) and not below it for LE and TE.
pub fn w2_valid(s: &Sketch, w: &W2) -> bool {
    w2_valid_with(s, w, &W2_CIRCLES)
}

/// [`w2_valid`] against the circles `circles` (centre, radius) for LE, TH and TE: W8's
/// variants have other radii.
pub fn w2_valid_with(s: &Sketch, w: &W2, circles: &Circles) -> bool {
    use camber_geom::ParametricCurve;
    let tol = 1e-6;
    let Ok(Entity::BSpline(curve)) = s.entity(w.curve) else {
        return false;
    };
    let (a, b) = curve.domain();
    for (k, u) in [(0, a), (2, b)] {
        let (c, r) = circles[k];
        let Ok((p, t)) = curve.point_and_derivative(u) else {
            return false;
        };
        let v = p - Point2::new(c[0], c[1]);
        if (v.norm() - r).abs() > tol || (v.dot(&t) / (v.norm() * t.norm())).abs() > tol {
            return false;
        }
    }
    circles.iter().enumerate().all(|(k, (c, r))| {
        let Ok(cp) = camber_geom::queries::closest_point(curve, &Point2::new(c[0], c[1])) else {
            return false;
        };
        if k == 1 {
            (cp.distance - r).abs() <= tol && cp.point.y >= c[1]
        } else {
            cp.distance - r >= -tol
        }
    })
}

/// W2 `2cubic` at its rough start: two cubic Béziers Q₀…Q₃ and Q₃…Q₆ (each with its own copy
/// of Q₃), joined G1 at Q₃ with a free direction ([`G1JoinFree`]); Q₃ on the TH
/// circle and tangent there (the first curve at u = 1), Q₀ on LE and tangent, Q₆ on TE and
/// tangent; all outside and clockwise, the circles fixed. Returns the sketch, the two curves
/// and the circles.
///
/// ```
/// let (mut s, curves, _) = camber_workloads::w2_2cubic()?;
/// s.solve()?;
/// assert!(camber_workloads::w2_2cubic_valid(&s, curves));
/// # Ok::<(), camber_sketch::Error>(())
/// ```
///
/// # Errors
/// None in practice (the data are valid); the signature carries the sketch's errors.
pub fn w2_2cubic() -> Result<(Sketch, [EntityId; 2], [EntityId; 3])> {
    let [le, _, te] = W2_CIRCLES;
    let q = [
        on_circle(le, 110.0),
        Point2::new(0.09, 0.07),
        Point2::new(0.24, 0.11),
        Point2::new(0.38, 0.11),
        Point2::new(0.55, 0.11),
        Point2::new(0.85, 0.05),
        on_circle(te, 70.0),
    ];
    let mut s = Sketch::new();
    let first = s.add_bezier(BezierCurve2::try_new(q[..4].to_vec())?)?;
    let second = s.add_bezier(BezierCurve2::try_new(q[3..].to_vec())?)?;
    let mut circles = [first; 3];
    for (slot, (centre, r)) in circles.iter_mut().zip(W2_CIRCLES) {
        *slot = s.add_circle(Point2::new(centre[0], centre[1]), r)?;
        s.add_constraint(Fixed::entity(*slot))?;
    }
    s.add_constraint(G1JoinFree { first, second })?;
    for (curve, circle, u) in [
        (first, circles[0], 0.0),
        (first, circles[1], 1.0),
        (second, circles[2], 1.0),
    ] {
        s.add_constraint(TangentToCircle {
            curve,
            circle,
            u: Contact::At(u),
            side: CircleSide::Outside,
            rotation: Rotation::Clockwise,
        })?;
    }
    Ok((s, [first, second], circles))
}

/// W2's validity check for `2cubic` (tolerance 1e-6): Q₀ on LE and Q₆ on TE with the tangent
/// perpendicular to the radius; the least distance from each centre to the two curves equal to
/// the radius for TH (contact on the upper half) and not below it for LE and TE; and the joint
/// closed with parallel, same-sense tangents.
pub fn w2_2cubic_valid(s: &Sketch, curves: [EntityId; 2]) -> bool {
    use camber_geom::ParametricCurve;
    let tol = 1e-6;
    let (Ok(Entity::Bezier(c1)), Ok(Entity::Bezier(c2))) =
        (s.entity(curves[0]), s.entity(curves[1]))
    else {
        return false;
    };
    let (Ok((a, ta)), Ok((b, tb))) = (c1.point_and_derivative(1.0), c2.point_and_derivative(0.0))
    else {
        return false;
    };
    let cross = (ta.x * tb.y - ta.y * tb.x) / (ta.norm() * tb.norm());
    if (a - b).norm() > tol || cross.abs() > tol || ta.dot(&tb) <= 0.0 {
        return false;
    }
    for (c, k, u) in [(c1, 0, 0.0), (c2, 2, 1.0)] {
        let (centre, r) = W2_CIRCLES[k];
        let Ok((p, t)) = c.point_and_derivative(u) else {
            return false;
        };
        let v = p - Point2::new(centre[0], centre[1]);
        if (v.norm() - r).abs() > tol || (v.dot(&t) / (v.norm() * t.norm())).abs() > tol {
            return false;
        }
    }
    W2_CIRCLES.iter().enumerate().all(|(k, (c, r))| {
        let centre = Point2::new(c[0], c[1]);
        let (Ok(n1), Ok(n2)) = (
            camber_geom::queries::closest_point(c1, &centre),
            camber_geom::queries::closest_point(c2, &centre),
        ) else {
            return false;
        };
        let nearest = if n1.distance <= n2.distance { n1 } else { n2 };
        if k == 1 {
            (nearest.distance - r).abs() <= tol && nearest.point.y >= c[1]
        } else {
            nearest.distance - r >= -tol
        }
    })
}

/// W2 `2cubic`'s perturbed starts: `trials` copies of the solved sketch `base` with the seven
/// points Q₀…Q₆ moved by uniform noise in [−δ, δ]² (a seeded splitmix64 generator); Q₃, held
/// by both curves, moves as one point.
///
/// # Errors
/// Errors of reading or moving the points (none for a W2 `2cubic` sketch).
pub fn w2_2cubic_perturbed(
    base: &Sketch,
    curves: [EntityId; 2],
    delta: f64,
    trials: usize,
    seed: u64,
) -> Result<Vec<Sketch>> {
    let mut noise = uniform_noise(seed);
    // Q₀…Q₆ as the slots holding each: Q₃ is the end of the first curve and the start of the
    // second.
    let slots: [&[PointRef]; 7] = [
        &[PointRef::Control(curves[0], 0)],
        &[PointRef::Control(curves[0], 1)],
        &[PointRef::Control(curves[0], 2)],
        &[
            PointRef::Control(curves[0], 3),
            PointRef::Control(curves[1], 0),
        ],
        &[PointRef::Control(curves[1], 1)],
        &[PointRef::Control(curves[1], 2)],
        &[PointRef::Control(curves[1], 3)],
    ];
    let mut out = Vec::with_capacity(trials);
    for _ in 0..trials {
        let mut s = base.clone();
        for refs in slots {
            let shift = Vector2::new(delta * noise(), delta * noise());
            for &r in refs {
                let p = s.point(r)?;
                s.set_point(r, p + shift)?;
            }
        }
        out.push(s);
    }
    Ok(out)
}
