//! The active rows of honest contact: clearance beside a contact ("touch, never cross" on the
//! whole stretch of curve near it, not on one sample of it) and the floor on the contact's
//! tangent speed ("a tangency, never a cusp").
//!
//! # Clearance
//!
//! A curve C touching a target (a circle, an arc's circle, an ellipse or a line) at the contact
//! parameter u must stay on its
//! side of the target near u. Write G(s) for the signed gap of the curve point C(s), positive
//! on the intended side and in length units near the target:
//!
//! - circle (c, r): G = ς·(|C − c|² − r²)/(2r), ς = +1 outside, −1 inside, so that
//!   G′ = ς·(C − c)·C′/r and G″ = ς·(|C′|² + (C − c)·C″)/r; an arc's circle the same with
//!   r = |S − c| from its start S;
//! - ellipse (centre c, vertex V, semi-axis b; a = |V − c|, unit axes û = (V − c)/a and
//!   v̂ = rot₉₀(û)): with the symmetric form B(p, q) = k·((p·û)(q·û)/a² + (p·v̂)(q·v̂)/b²),
//!   k = ab/(a + b), G = ς·(B(C − c, C − c) − k) (the implicit equation scaled to length units
//!   near the ellipse, as the point-on-ellipse row), so G′ = 2ς·B(C − c, C′) and
//!   G″ = 2ς·(B(C′, C′) + B(C − c, C″)); a circle is the case a = b = r, B(p, q) = p·q/(2r);
//! - line through A and B, d = B − A: G = ς·cross(d, C − A)/|d|, ς = +1 on the left, so that
//!   G′ = ς·cross(d, C′)/|d| and G″ = ς·cross(d, C″)/|d|.
//!
//! The requirement is the semi-infinite inequality G(s) ≥ 0 for every s of the window beside
//! u. It cannot be imposed on G directly: the contact itself makes G(u) = G′(u) = 0, so
//! min G = 0 is always reached at s = u and an inequality on it would only repeat the contact
//! rows (dependent, with no information about the rest of the window). The double root is
//! divided out instead, with the Taylor remainder about the contact
//!
//! Q(s) = [G(s) − G(u) − G′(u)·(s − u)] / (s − u)²  (s ≠ u),   Q(u) = G″(u)/2,
//!
//! which is smooth in s, in the control points and in u (it is ∫₀¹ (1 − t)·G″(u + t(s − u)) dt)
//! and needs the contact rows to hold only at the solution: wherever G(u) = G′(u) = 0,
//! G(s) = (s − u)²·Q(s), so G ≥ 0 on the window exactly when Q ≥ 0 there. Q(u) ≥ 0 is the
//! second-order condition at the contact (the curve bends toward the target no more than the
//! target itself: curvature at most 1/r toward a circle's centre, none toward a line), and
//! Q(s) ≥ 0 away from u excludes a crossing further along.
//!
//! One [`Clearance`] row covers one whole side of the contact, the bracket B = [u, b] or
//! [a, u] of the domain [a, b], and its value is
//!
//! h(x) = w²·min_{s ∈ B} Q(s; x)
//!
//! with w the half-width of the window the crossing check samples (w² turns Q back into a
//! length, so that one tolerance fits every row). The bracket runs to the end of the curve, not
//! only to the edge of that window: a row cut at the window would be met by a curve touching
//! the target at the window's edge and crossing just past it. By Danskin's theorem
//! h is differentiable wherever the minimiser s* is unique, with ∇h = w²·∂Q/∂x (s*, x): s* is
//! located on the real parts (a sampled scan of B, then golden-section and Newton refinement)
//! and the residual is evaluated at s₁ = s* − Q′(s*)/Q″(s*) in the scalar type. At a converged
//! interior minimum the step is zero in value, but its derivatives are those of the implicit
//! function s*(x), so dual numbers see ∇h exactly and hyper-dual numbers see the second
//! derivatives ∇²h = Q_xx − Q_xs·Q_ss⁻¹·Q_sx as well. At an end of B (the contact itself
//! included) s* stays put.
//!
//! # Tangent speed floor
//!
//! An oriented contact asks C′(u) = λ·T with λ > 0, T the target's tangent direction of the
//! recorded sense: an open condition. When the start's tangent points against T (or into the
//! target), the displacement ½‖x − x₀‖² has no minimiser on that set: shortening C′(u) makes
//! turning it cheaper and cheaper, and the infimum is a cusp, λ = 0, which is not a tangency.
//! The closed set |C′(u)| ≥ f with f = [`SPEED_FLOOR`]·|C′₀(u)| (C′₀ at the start) restores a
//! minimiser; when the solve ends in a cusp, that minimiser lies on the floor, and the row
//! [`TangentSpeed`], w·(|C′(u)|² − f²)/(2f) = 0, is its active form.
//!
//! # The active-set loop
//!
//! Both are inequalities, and the solve treats them as an active set ([`crate::session::solve`]): the
//! component is first solved with the contact rows alone; if the result meets every
//! inequality it is also the solution of the problem with them (an inactive inequality does not
//! change a local minimum). If a contact crosses its target on one side, the nearest valid
//! curve lies on the boundary of {h ≥ 0} there, so the row h = 0 is added on that side (the
//! curve touches the target again at a free point s*, or osculates it at u); if a contact's
//! tangent collapsed, its speed floor is added; and the component is solved again from the
//! sketch's state. Unlike a push-back of one sample onto the target at a fixed parameter, the
//! second touching point slides freely, so the row neither conflicts with the contact a short
//! distance away nor leaves the curve crossing beside the pinned sample.
//!
//! A contact whose tangent already points against its recorded direction at the start
//! is headed for the cusp: when Newton alone fails
//! from such a start, its floor is added before any fallback runs (a least-squares rescue would
//! find some valid curve, but not the nearest one).
//!
//! An active row may turn out not to bind. At the solution z* of min ½‖z − z₀‖²_W subject to the
//! rows, W·(z* − z₀) = Jᵀμ; an inequality h ≥ 0 binds only with μ ≥ 0, and with μ < 0 letting h
//! grow would bring the curve closer to the start. Such a row is dropped and Newton resumes
//! from z* toward z₀. A result is written back only
//! after every check passes on the solved curve.

use camber_solve::scalar::{cst, re};
use camber_solve::{Residual, Scalar};
use smallvec::SmallVec;

use crate::ground::curve_eval::CurveBasis;
use crate::residuals::curve::{curve_at, curve_block_sizes, dot, Param};

/// The fraction κ of its starting speed below which the tangent at a contact may not shrink
/// once a solve has collapsed it into a cusp: the speed floor is f = κ·|C′₀(u)|.
pub const SPEED_FLOOR: f64 = 0.25;

/// Samples of Q on a bracket before the minimiser is refined.
const SAMPLES: usize = 32;

/// Parameter distance (relative to the domain length) within which Q is taken from the
/// curve's Taylor expansion at the contact instead of the quotient, which loses digits to
/// cancellation as s → u (see [`Clearance::taylor`]).
const NEAR_CONTACT: f64 = 1e-4;

/// What the clearance is measured against.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    /// A circle: the blocks after the curve (and u) are its centre and its radius.
    Circle,
    /// A circular arc's circle: the blocks after the curve (and u) are its centre C and its
    /// start S; the radius is |S − C|.
    Arc,
    /// An ellipse (or an elliptic arc's ellipse): the blocks after the curve (and u) are its
    /// centre C, its a-axis vertex V and its semi-axis b.
    Ellipse,
    /// A line: the blocks after the curve (and u) are two of its points A and B.
    Line,
}

/// The gap of a round target (circle, arc's circle or ellipse) as a quadratic form about its
/// centre: G(q) = B(q − c, q − c) − k with B(p, q) = k·((p·û)(q·û)/a² + (p·v̂)(q·v̂)/b²)
/// (module documentation; a circle has a = b = r, k = r/2).
struct Quadric<'a, T> {
    centre: &'a [T],
    /// û (unit; v̂ = rot₉₀(û)).
    axis: [T; 2],
    /// k/a² and k/b².
    weights: [T; 2],
    /// k.
    offset: T,
}

impl<T: Scalar> Quadric<'_, T> {
    /// B(p, q).
    fn form(&self, p: [T; 2], q: [T; 2]) -> T {
        let [ux, uy] = self.axis;
        let along = (p[0] * ux + p[1] * uy) * (q[0] * ux + q[1] * uy);
        let across = (p[1] * ux - p[0] * uy) * (q[1] * ux - q[0] * uy);
        self.weights[0] * along + self.weights[1] * across
    }

    /// q − c.
    fn relative(&self, q: &[T; 2]) -> [T; 2] {
        [q[0] - self.centre[0], q[1] - self.centre[1]]
    }
}

/// h = w²·min Q over one side of a contact (see the module documentation): zero when the curve
/// touches the target again somewhere beside the contact (or osculates it there), negative when
/// it crosses. Blocks: the curve's control points, u when free, then the target's blocks.
///
/// ```
/// use camber_sketch::residuals::clearance::{Clearance, Target};
/// use camber_sketch::residuals::Param;
/// use camber_sketch::{curve_eval::CurveBasis, Entity};
/// use camber_solve::Residual;
/// use nalgebra::Point2;
/// // The parabola-like cubic y = (x − 1)²/… touches the x axis at u = ½ from above and stays
/// // above: the clearance on its right is positive.
/// let pts = [[0.0, 1.0], [1.0 / 3.0, -1.0 / 3.0], [2.0 / 3.0, -1.0 / 3.0], [1.0, 1.0]];
/// let bez = Entity::Bezier(camber_geom::BezierCurve2::try_new(
///     pts.iter().map(|p| Point2::new(p[0], p[1])).collect(),
/// )?);
/// let basis = CurveBasis::of(&bez).ok_or("curve")?;
/// let h = Clearance::new(basis, Param::Fixed(0.5), Target::Line, true, true, 0.2);
/// let mut out = [0.0];
/// let blocks: Vec<&[f64]> = pts.iter().map(|p| &p[..]).chain([&[0.0, 0.0][..], &[1.0, 0.0][..]]).collect();
/// h.eval::<f64>(&blocks, &mut out);
/// assert!(out[0] > 0.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Clearance {
    basis: CurveBasis,
    u: Param,
    target: Target,
    /// ς = ±1: the sign that makes the gap positive on the intended side.
    side: f64,
    /// +1 for the bracket after the contact, −1 for the one before.
    direction: f64,
    /// The scale w (parameter units): h = w²·min Q.
    width: f64,
    /// The last search, reused while the real parts of the inputs stay the same.
    last: LocateCache,
}

/// The inputs (real parts of the control points, u and the target, flattened) and the result of
/// the last minimiser search. A Jacobian evaluates the row in one dual pass per group of
/// columns and a Hessian in one pass per pair of blocks, all at the same real point, and the
/// search (a scan, golden section and Newton: some 200 curve evaluations) is the dearest part
/// of each; the result depends only on the real parts, so it is computed once. Clones start
/// empty and two caches always compare equal: the cache is not part of the residual's value.
#[derive(Debug, Default)]
struct LocateCache(std::sync::Mutex<Option<(SmallVec<[f64; 32]>, Minimum)>>);

impl Clone for LocateCache {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl PartialEq for LocateCache {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl LocateCache {
    /// The cached result for `key`, or `search()`'s (then cached). When another thread holds
    /// the cache, searches without it.
    fn get_or(&self, key: SmallVec<[f64; 32]>, search: impl FnOnce() -> Minimum) -> Minimum {
        let Ok(mut slot) = self.0.try_lock() else {
            return search();
        };
        if let Some((k, m)) = slot.as_ref() {
            // Bitwise equality: a hit returns exactly what the search would.
            if k.len() == key.len() && k.iter().zip(&key).all(|(a, b)| a.to_bits() == b.to_bits()) {
                return *m;
            }
        }
        let m = search();
        *slot = Some((key, m));
        m
    }
}

impl Clearance {
    /// The clearance of the curve `basis` (the whole curve, not [`CurveBasis::at`]) beside its
    /// contact at `u` with a circle or line: on the positive side of the target (outside the
    /// circle, left of the line A → B) when `positive`, from u to the end of the domain when
    /// `after`, else from its start to u; `width` > 0 is the scale w of the row (and sets the
    /// scan's density: 32 samples per w).
    pub fn new(
        basis: CurveBasis,
        u: Param,
        target: Target,
        positive: bool,
        after: bool,
        width: f64,
    ) -> Self {
        Self {
            basis,
            u,
            target,
            side: if positive { 1.0 } else { -1.0 },
            direction: if after { 1.0 } else { -1.0 },
            width,
            last: LocateCache::default(),
        }
    }

    /// The quadratic form of a circle, arc or ellipse target (`None` for a line).
    fn quadric<'a, T: Scalar>(&self, target: &[&'a [T]]) -> Option<Quadric<'a, T>> {
        let centre = target[0];
        let span = |p: &[T]| [p[0] - centre[0], p[1] - centre[1]];
        let (one, half) = (T::one(), cst::<T>(0.5));
        match self.target {
            Target::Circle | Target::Arc => {
                let r = if self.target == Target::Arc {
                    let v = span(target[1]);
                    dot(v, v).sqrt()
                } else {
                    target[1][0]
                };
                let w = one / (r + r);
                Some(Quadric {
                    centre,
                    axis: [one, T::zero()],
                    weights: [w, w],
                    offset: r * half,
                })
            }
            Target::Ellipse => {
                let w = span(target[1]);
                let a = dot(w, w).sqrt();
                let b = target[2][0];
                let k = a * b / (a + b);
                Some(Quadric {
                    centre,
                    axis: [w[0] / a, w[1] / a],
                    weights: [k / (a * a), k / (b * b)],
                    offset: k,
                })
            }
            Target::Line => None,
        }
    }

    /// G, G′ and G″ at a point with C, C′ and C″ = `d` (see the module documentation).
    fn gap<T: Scalar>(&self, target: &[&[T]], d: &[[T; 2]; 3]) -> [T; 3] {
        let side = cst::<T>(self.side);
        let [c, c1, c2] = d;
        if let Some(form) = self.quadric(target) {
            let v = form.relative(c);
            let two = cst::<T>(2.0);
            let g = form.form(v, v) - form.offset;
            let g1 = two * form.form(v, *c1);
            let g2 = two * (form.form(*c1, *c1) + form.form(v, *c2));
            return [side * g, side * g1, side * g2];
        }
        // A line through A and B.
        let (a, b) = (target[0], target[1]);
        let dir = [b[0] - a[0], b[1] - a[1]];
        let len = (dir[0] * dir[0] + dir[1] * dir[1]).sqrt();
        let cross = |v: [T; 2]| (dir[0] * v[1] - dir[1] * v[0]) / len;
        let g = cross([c[0] - a[0], c[1] - a[1]]);
        [side * g, side * cross(*c1), side * cross(*c2)]
    }

    /// Q, Q′ and Q″ at s = u + Δ from the gap derivatives there and (G, G′) at u (Δ ≠ 0).
    fn quotient<T: Scalar>(at_s: [T; 3], at_u: [T; 3], delta: T) -> [T; 3] {
        let r0 = at_s[0] - at_u[0] - at_u[1] * delta;
        let r1 = at_s[1] - at_u[1];
        let r2 = at_s[2];
        let d2 = delta * delta;
        let q = r0 / d2;
        let q1 = (r1 - cst::<T>(2.0) * r0 / delta) / d2;
        let q2 = (r2 - cst::<T>(4.0) * r1 / delta + cst::<T>(6.0) * r0 / d2) / d2;
        [q, q1, q2]
    }

    /// Q, Q′ and Q″ at s = u + Δ for small Δ, from C and its first three derivatives at u
    /// (`d`) without cancellation. With the curve's expansion C(s) = C + C′Δ + C″Δ²/2 +
    /// C‴Δ³/6, the remainder K = (C(s) − C − C′Δ)/Δ² = C″/2 + C‴Δ/6 and the secant slope
    /// M = (C(s) − C)/Δ = C′ + C″Δ/2 + C‴Δ²/6 give
    ///
    /// - circle or ellipse: Q = ς·(2B(C − c, K) + B(M, M)) (for a circle (2(C − c)·K + |M|²)/(2r)),
    /// - line: Q = ς·cross(d, K)/|d|,
    ///
    /// exact for cubic pieces and accurate to O(Δ²) otherwise; Q(u) = G″(u)/2.
    fn taylor<T: Scalar>(&self, target: &[&[T]], d: &[[T; 2]; 4], delta: T) -> [T; 3] {
        let side = cst::<T>(self.side);
        let [c, c1, c2, c3] = d;
        let (half, third, sixth) = (cst::<T>(0.5), cst::<T>(1.0 / 3.0), cst::<T>(1.0 / 6.0));
        let k = [
            c2[0] * half + c3[0] * delta * sixth,
            c2[1] * half + c3[1] * delta * sixth,
        ];
        let k1 = [c3[0] * sixth, c3[1] * sixth];
        if let Some(form) = self.quadric(target) {
            let v = form.relative(c);
            let d2 = delta * delta;
            let m = [
                c1[0] + c2[0] * delta * half + c3[0] * d2 * sixth,
                c1[1] + c2[1] * delta * half + c3[1] * d2 * sixth,
            ];
            let m1 = [
                c2[0] * half + c3[0] * delta * third,
                c2[1] * half + c3[1] * delta * third,
            ];
            let m2 = [c3[0] * third, c3[1] * third];
            let two = cst::<T>(2.0);
            let q = two * form.form(v, k) + form.form(m, m);
            let q1 = two * (form.form(v, k1) + form.form(m, m1));
            let q2 = two * (form.form(m1, m1) + form.form(m, m2));
            return [side * q, side * q1, side * q2];
        }
        // A line through A and B.
        let (a, b) = (target[0], target[1]);
        let dir = [b[0] - a[0], b[1] - a[1]];
        let len = (dir[0] * dir[0] + dir[1] * dir[1]).sqrt();
        let cross = |v: [T; 2]| side * (dir[0] * v[1] - dir[1] * v[0]) / len;
        [cross(k), cross(k1), T::zero()]
    }

    /// Q, Q′ and Q″ at s, given C and its derivatives at the contact u (`at_u`): the quotient,
    /// or the Taylor form within [`NEAR_CONTACT`] of u.
    fn q_at<T: Scalar>(
        &self,
        points: &[&[T]],
        target: &[&[T]],
        u: T,
        at_u: &[[T; 2]; 4],
        s: T,
    ) -> [T; 3] {
        let delta = s - u;
        if re(delta).abs() <= self.near() {
            return self.taylor(target, at_u, delta);
        }
        let g_u = self.gap(target, &[at_u[0], at_u[1], at_u[2]]);
        Self::quotient(self.gap(target, &self.basis.eval2(points, s)), g_u, delta)
    }

    /// The distance from the contact within which Q comes from the Taylor form.
    fn near(&self) -> f64 {
        let (a, b) = self.basis.domain();
        NEAR_CONTACT * (b - a).max(f64::MIN_POSITIVE)
    }

    /// The bracket [lo, hi] for the contact at `u` (real parts), cut to the domain.
    fn bracket(&self, u: f64) -> (f64, f64) {
        let (a, b) = self.basis.domain();
        if self.direction > 0.0 {
            (u, b.max(u))
        } else {
            (a.min(u), u)
        }
    }

    /// Where Q is least over the bracket, from the real parts: a scan ([`SAMPLES`] points per w),
    /// then golden-section and Newton refinement around the best one.
    fn locate(&self, points: &[&[f64]], u: f64, target: &[&[f64]]) -> Minimum {
        let (lo, hi) = self.bracket(u);
        // The contact end of the bracket moves with u; the far end is the end of the domain.
        let end = |s: f64| -> Minimum {
            let at_contact = if self.direction > 0.0 {
                s <= lo
            } else {
                s >= hi
            };
            if at_contact {
                Minimum::Contact
            } else {
                Minimum::DomainEnd(s)
            }
        };
        if hi - lo <= 0.0 {
            return Minimum::Contact;
        }
        let at_u = self.basis.eval3(points, u);
        let q = |s: f64| self.q_at(points, target, u, &at_u, s);
        // Q alone for the scan and the golden section: the gap G(s) needs only C(s).
        let g_u = self.gap(target, &[at_u[0], at_u[1], at_u[2]]);
        let q_value = |s: f64| {
            let delta = s - u;
            if delta.abs() <= self.near() {
                return self.taylor(target, &at_u, delta)[0];
            }
            let c = self.basis.point(points, s);
            Self::quotient(self.gap(target, &[c, [0.0; 2], [0.0; 2]]), g_u, delta)[0]
        };
        // SAMPLES per width w, at least SAMPLES in all.
        let count = ((SAMPLES as f64 * (hi - lo) / self.width).ceil() as usize).max(SAMPLES);
        let step = (hi - lo) / count as f64;
        let mut best = (f64::INFINITY, lo);
        for i in 0..=count {
            let s = lo + step * i as f64;
            let v = q_value(s);
            if v < best.0 || best.0.is_nan() {
                best = (v, s);
            }
        }
        // Golden section on the neighbouring samples, then Newton on Q′ = 0 inside them.
        let (mut l, mut r) = ((best.1 - step).max(lo), (best.1 + step).min(hi));
        let phi = 0.5 * (5f64.sqrt() - 1.0);
        let (mut x1, mut x2) = (r - phi * (r - l), l + phi * (r - l));
        let (mut f1, mut f2) = (q_value(x1), q_value(x2));
        for _ in 0..24 {
            if f1 <= f2 {
                r = x2;
                x2 = x1;
                f2 = f1;
                x1 = r - phi * (r - l);
                f1 = q_value(x1);
            } else {
                l = x1;
                x1 = x2;
                f1 = f2;
                x2 = l + phi * (r - l);
                f2 = q_value(x2);
            }
        }
        let mut s = 0.5 * (l + r);
        let mut fs = q_value(s);
        for e in [lo, hi] {
            if q_value(e) <= fs {
                (s, fs) = (e, q_value(e));
            }
        }
        if s <= lo || s >= hi {
            return end(s);
        }
        for _ in 0..4 {
            let [_, q1, q2] = q(s);
            if q2.is_nan() || q2 <= 0.0 {
                return Minimum::Interior(s, false);
            }
            let next = s - q1 / q2;
            if next <= lo || next >= hi {
                // Q falls toward an end beyond the sampled neighbourhood: the end is least.
                let e = if next <= lo { lo } else { hi };
                if q_value(e) <= fs {
                    return end(e);
                }
                return Minimum::Interior(s, false);
            }
            let fn_ = q_value(next);
            if fn_ > fs {
                break;
            }
            (s, fs) = (next, fn_);
        }
        Minimum::Interior(s, true)
    }
}

/// Where Q is least over a bracket.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Minimum {
    /// Inside the bracket at s*; with `true` when Q″(s*) > 0 and Q′(s*) = 0 up to the
    /// search's accuracy (the scalar-type Newton step applies).
    Interior(f64, bool),
    /// At the contact itself: Q(u) = G″(u)/2, moving with u.
    Contact,
    /// At the end of the curve's domain: s* is held.
    DomainEnd(f64),
}

impl Residual for Clearance {
    fn name(&self) -> &str {
        "clearance"
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        let mut sizes = curve_block_sizes(&self.basis, self.u);
        sizes.extend_from_slice(match self.target {
            Target::Circle => &[2, 1][..],
            Target::Arc | Target::Line => &[2, 2],
            Target::Ellipse => &[2, 2, 1],
        });
        Some(sizes)
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let n = self.basis.count();
        let (u, k) = match self.u {
            Param::Fixed(v) => (cst::<T>(v), n),
            Param::Block => (x.get(n).map_or(T::zero(), |b| b[0]), n + 1),
        };
        let (points, target) = (&x[..n], &x[k..]);
        // Real parts for the search.
        let pr: SmallVec<[[f64; 2]; 16]> = points.iter().map(|p| [re(p[0]), re(p[1])]).collect();
        let tr: SmallVec<[[f64; 2]; 3]> = target
            .iter()
            .take(3)
            .map(|b| [re(b[0]), b.get(1).map_or(0.0, |v| re(*v))])
            .collect();
        let prefs: SmallVec<[&[f64]; 16]> = pr.iter().map(|p| &p[..]).collect();
        // A one-number block (a radius, a semi-axis) keeps its length: the forms read b[0].
        let trefs: SmallVec<[&[f64]; 3]> = tr.iter().map(|p| &p[..]).collect();
        let at_u = self.basis.eval3(points, u);
        let q = |s: T| self.q_at(points, target, u, &at_u, s);
        let key: SmallVec<[f64; 32]> = pr
            .iter()
            .flatten()
            .chain(tr.iter().flatten())
            .copied()
            .chain([re(u)])
            .collect();
        let least = match self.last.get_or(key, || self.locate(&prefs, re(u), &trefs)) {
            Minimum::Contact => q(u)[0],
            Minimum::DomainEnd(s) => q(cst::<T>(s))[0],
            Minimum::Interior(s, false) => q(cst::<T>(s))[0],
            Minimum::Interior(s, true) => {
                // One Newton step on Q′ = 0 in the scalar type: s₁ carries ∂s*/∂x.
                let q0 = q(cst::<T>(s));
                q(cst::<T>(s) - q0[1] / q0[2])[0]
            }
        };
        out[0] = cst::<T>(self.width * self.width) * least;
    }
}

/// w·(|C′(u)|² − f²)/(2f) = 0: the tangent speed at the contact parameter u equals f > 0
/// (blocks: the curve, then u when free); w (parameter units) turns the row into a length.
/// The active form of the speed floor |C′(u)| ≥ f of a contact whose solve collapsed its
/// tangent (see the module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct TangentSpeed {
    basis: CurveBasis,
    u: Param,
    speed: f64,
    width: f64,
}

impl TangentSpeed {
    /// |C′(u)| = `speed` (> 0), scaled by `width`.
    pub fn new(basis: CurveBasis, u: Param, speed: f64, width: f64) -> Self {
        Self {
            basis,
            u,
            speed,
            width,
        }
    }
}

impl Residual for TangentSpeed {
    fn name(&self) -> &str {
        "tangent speed floor"
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(curve_block_sizes(&self.basis, self.u))
    }
    fn depends_on(&self, x: &[&[f64]], blocks: &mut [bool]) {
        crate::residuals::curve::curve_support(&self.basis, self.u, x, blocks);
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (_, c1, _) = curve_at(&self.basis, self.u, x);
        let f = cst::<T>(self.speed);
        out[0] = cst::<T>(self.width) * (dot(c1, c1) - f * f) / (cst::<T>(2.0) * f);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Entity;
    use camber_solve::DynResidual;
    use nalgebra::Point2;

    fn bezier(pts: &[[f64; 2]]) -> CurveBasis {
        let e = Entity::Bezier(
            camber_geom::BezierCurve2::try_new(
                pts.iter().map(|p| Point2::new(p[0], p[1])).collect(),
            )
            .unwrap(),
        );
        CurveBasis::of(&e).unwrap()
    }

    /// A clamped cubic B-spline on [0,0,0,0, ¼, ½, ¾, 1,1,1,1] that leaves the unit circle
    /// tangentially at (0, 1), rises, then dips into the circle around s ≈ 0.4 and leaves it:
    /// Q has an interior minimum.
    const DIPPING: [[f64; 2]; 7] = [
        [0.0, 1.0],
        [0.3, 1.0],
        [0.6, 1.0],
        [0.9, 0.2],
        [1.2, 0.5],
        [1.5, 1.5],
        [1.8, 1.8],
    ];

    fn dipping() -> CurveBasis {
        let knots = camber_geom::KnotVector::try_new(vec![
            0.0, 0.0, 0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0, 1.0, 1.0,
        ])
        .unwrap();
        let pts = DIPPING.iter().map(|p| Point2::new(p[0], p[1])).collect();
        CurveBasis::of(&Entity::BSpline(
            camber_geom::BSplineCurve2::try_new(3, knots, pts).unwrap(),
        ))
        .unwrap()
    }

    fn blocks<'a>(pts: &'a [[f64; 2]], target: &[&'a [f64]]) -> Vec<&'a [f64]> {
        let mut b: Vec<&[f64]> = pts.iter().map(|p| &p[..]).collect();
        b.extend_from_slice(target);
        b
    }

    fn value(h: &Clearance, x: &[&[f64]]) -> f64 {
        let mut out = [0.0];
        h.eval::<f64>(x, &mut out);
        out[0]
    }

    /// min over (0, `end`] of G(s)/s² for the unit circle by a dense scan, G = (|C|² − 1)/2
    /// (the contact at s = 0 holds exactly, so the remainder is G itself).
    fn scan(basis: &CurveBasis, pts: &[[f64; 2]], end: f64) -> f64 {
        let refs: Vec<&[f64]> = pts.iter().map(|p| &p[..]).collect();
        (1..=20_000)
            .map(|i| {
                let s = end * f64::from(i) / 20_000.0;
                let (c, _) = basis.eval::<f64>(&refs, s);
                (c[0] * c[0] + c[1] * c[1] - 1.0) / 2.0 / (s * s)
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// The straight cubic along y = 0 touches the line y = 0 everywhere: Q ≡ 0.
    #[test]
    fn a_curve_on_its_line_has_zero_clearance() {
        let pts = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]];
        let h = Clearance::new(
            bezier(&pts),
            Param::Fixed(0.0),
            Target::Line,
            true,
            true,
            0.5,
        );
        let v = value(&h, &blocks(&pts, &[&[0.0, 0.0], &[1.0, 0.0]]));
        assert!(v.abs() < 1e-12, "{v}");
    }

    /// A cubic leaving the unit circle tangentially at (0, 1) and bending into it has its least
    /// Q at the contact, Q(0) = G″(0)/2 = (|C′|² + C·C″)/2 (by hand: C′ = (0.9, 0),
    /// C″ = (0, 6·bend)); bending away, a positive clearance. Both agree with a dense scan.
    #[test]
    fn bending_into_the_circle_at_the_contact_is_a_negative_curvature_margin() {
        for bend in [-0.8, 0.8] {
            let pts = [[0.0, 1.0], [0.3, 1.0], [0.6, 1.0 + bend], [1.0, 1.0 + bend]];
            let h = Clearance::new(
                bezier(&pts),
                Param::Fixed(0.0),
                Target::Circle,
                true,
                true,
                0.5,
            );
            let v = value(&h, &blocks(&pts, &[&[0.0, 0.0], &[1.0]]));
            let limit = 0.5 * (0.81 + 6.0 * bend);
            let least = scan(&bezier(&pts), &pts, 1.0).min(limit);
            assert!(
                (v - 0.25 * least).abs() < 1e-9,
                "bend {bend}: {v} vs {least}"
            );
            assert_eq!(v < 0.0, bend < 0.0);
            if bend < 0.0 {
                assert!((v - 0.25 * limit).abs() < 1e-12, "{v} vs {limit}");
            }
        }
    }

    /// A dip into the circle away from the contact: h is the interior minimum of Q, and on the
    /// other side of the contact (nothing there) the bracket is empty and h = w²·G″(0)/2.
    #[test]
    fn a_dip_further_along_is_an_interior_minimum() {
        let h = Clearance::new(
            dipping(),
            Param::Fixed(0.0),
            Target::Circle,
            true,
            true,
            1.0,
        );
        let x = blocks(&DIPPING, &[&[0.0, 0.0], &[1.0]]);
        let v = value(&h, &x);
        let least = scan(&dipping(), &DIPPING, 1.0);
        assert!(v < 0.0 && (v - least).abs() < 1e-9, "{v} vs {least}");
        let refs: Vec<&[f64]> = DIPPING.iter().map(|p| &p[..]).collect();
        let [c, c1, c2] = dipping().eval2::<f64>(&refs, 0.0);
        let limit = 0.5 * (c1[0] * c1[0] + c1[1] * c1[1] + c[0] * c2[0] + c[1] * c2[1]);
        let before = Clearance::new(
            dipping(),
            Param::Fixed(0.0),
            Target::Circle,
            true,
            false,
            1.0,
        );
        assert!((value(&before, &x) - limit).abs() < 1e-12);
    }

    /// At an interior minimum the scalar-type Newton step gives h its exact second derivatives
    /// ∇²h = Q_xx − Q_xs·Q_ss⁻¹·Q_sx (hyper-dual numbers), against central differences of the
    /// exact gradient (the circle's centre and radius move too).
    #[test]
    fn the_hessian_at_an_interior_minimum_includes_the_moving_minimiser() {
        let h = Clearance::new(
            dipping(),
            Param::Fixed(0.0),
            Target::Circle,
            true,
            true,
            1.0,
        );
        let mut flat: Vec<f64> = DIPPING.iter().flatten().copied().collect();
        flat.extend([0.0, 0.0, 1.0]);
        let lens = [2, 2, 2, 2, 2, 2, 2, 2, 1];
        let split = |v: &[f64]| -> Vec<Vec<f64>> {
            let mut out = Vec::new();
            let mut k = 0;
            for l in lens {
                out.push(v[k..k + l].to_vec());
                k += l;
            }
            out
        };
        let gradient = |v: &[f64]| -> Vec<f64> {
            let b = split(v);
            let refs: Vec<&[f64]> = b.iter().map(|x| &x[..]).collect();
            let (mut g, mut j) = ([0.0], vec![0.0; v.len()]);
            DynResidual::jacobian(&h, &refs, &mut g, &mut j).unwrap();
            j
        };
        let n = flat.len();
        let b = split(&flat);
        let refs: Vec<&[f64]> = b.iter().map(|x| &x[..]).collect();
        let mut hess = vec![0.0; n * n];
        let active = vec![true; lens.len()];
        assert!(h
            .weighted_hessian(&refs, &[1.0], &active, &mut hess)
            .unwrap());
        let step = 1e-5;
        let mut worst: f64 = 0.0;
        for k in 0..n {
            let (mut plus, mut minus) = (flat.clone(), flat.clone());
            plus[k] += step;
            minus[k] -= step;
            let (gp, gm) = (gradient(&plus), gradient(&minus));
            for i in 0..n {
                let central = (gp[i] - gm[i]) / (2.0 * step);
                worst = worst.max((hess[i * n + k] - central).abs() / (1.0 + central.abs()));
            }
        }
        assert!(worst < 1e-5, "worst Hessian entry off by {worst}");
    }

    /// The speed floor's row is w·(|C′|² − f²)/(2f): zero at speed f, about w·(|C′| − f) near.
    #[test]
    fn the_speed_floor_row_measures_the_tangent_speed() {
        let pts = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0], [3.0, 1.0]];
        let refs: Vec<&[f64]> = pts.iter().map(|p| &p[..]).collect();
        // C′(0) = 3·(P₁ − P₀) = (3, 0).
        let mut out = [1.0];
        TangentSpeed::new(bezier(&pts), Param::Fixed(0.0), 3.0, 0.2).eval::<f64>(&refs, &mut out);
        assert!(out[0].abs() < 1e-15);
        TangentSpeed::new(bezier(&pts), Param::Fixed(0.0), 2.0, 0.2).eval::<f64>(&refs, &mut out);
        assert!((out[0] - 0.2 * (9.0 - 4.0) / 4.0).abs() < 1e-15);
    }
}
