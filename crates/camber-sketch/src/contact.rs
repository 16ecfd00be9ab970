//! The nonlinear residuals: contact with a free parameter, circles and lines as unknowns,
//! distances, angles and the G1 joint with a free direction.
//!
//! A residual over a curve reads the curve's n control-point blocks first, then, when the
//! contact parameter is free ([`Param::Block`]), a block of one holding u, then the blocks of
//! the other entity. Rows are scaled to length units (or to the sine of an angle) so that one
//! tolerance fits them all:
//! - [`OnCurve`]: C(u) − Q (two rows);
//! - [`LineContact`]: cross(C(u) − A, d)/|d| and cross(C′(u), d)/|d| with d = B − A;
//! - [`CircleContact`]: C(u) − c − σ·r·n(u), n the unit normal (−C′_y, C′_x)/|C′|, σ = ±1 by
//!   the direction of travel around the circle;
//! - [`OnCircle`]: (|P − c|² − r²)/(2r);
//! - [`PointDistance`]: (|a − b|² − D²)/(2D);
//! - [`LineAngle`]: (cross(d₁, d₂)·cos θ − (d₁·d₂)·sin θ)/(|d₁||d₂|) = sin(φ − θ), φ the angle
//!   from d₁ to d₂ (zero at θ and θ + π; the sense is checked after the solve);
//! - [`TangentsParallel`]: cross(C₁′(b₁), C₂′(a₂))/(|C₁′||C₂′|);
//! - [`CurvatureMatch`]: κ₁(u₁) − κ₂(u₂), κ = cross(C′, C″)/|C′|³;
//! - [`CurveCurveContact`]: C₁(u) − C₂(v) and cross(C₁′(u), C₂′(v))/(|C₁′||C₂′|);
//! - [`RadiusValue`]: r − R (affine);
//!
//! Each is zero exactly on the constraint and differentiable wherever its denominators are
//! non-zero (positive radius and distance, non-degenerate directions and tangents).

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};

use crate::curve_eval::CurveBasis;

/// Where a curve residual takes its parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Param {
    /// A fixed parameter value.
    Fixed(f64),
    /// The block after the control points holds u (an unknown).
    Block,
}

/// C(u) and C′(u) from the first blocks, and the index of the next block.
pub(crate) fn curve_at<T: Scalar>(
    basis: &CurveBasis,
    u: Param,
    x: &[&[T]],
) -> ([T; 2], [T; 2], usize) {
    let n = basis.count();
    let (uu, next) = match u {
        Param::Fixed(v) => (cst::<T>(v), n),
        Param::Block => (x.get(n).map_or(T::zero(), |b| b[0]), n + 1),
    };
    let (c, c1) = basis.eval(x, uu);
    (c, c1, next)
}

/// Clears the flags of the curve's control-point blocks (the first `basis.count()`) outside
/// the knot span of a free parameter u (read from the block after them); returns the index of
/// the block after the curve's (and u's).
pub(crate) fn curve_support(
    basis: &CurveBasis,
    u: Param,
    x: &[&[f64]],
    blocks: &mut [bool],
) -> usize {
    let n = basis.count();
    match u {
        Param::Fixed(_) => n,
        Param::Block => {
            if let Some(uu) = x.get(n).and_then(|b| b.first()) {
                let keep = basis.support(*uu);
                for (j, flag) in blocks.iter_mut().enumerate().take(n) {
                    if !keep.contains(&j) {
                        *flag = false;
                    }
                }
            }
            n + 1
        }
    }
}

fn cross<T: Scalar>(a: [T; 2], b: [T; 2]) -> T {
    a[0] * b[1] - a[1] * b[0]
}

pub(crate) fn dot<T: Scalar>(a: [T; 2], b: [T; 2]) -> T {
    a[0] * b[0] + a[1] * b[1]
}

fn sub<T: Scalar>(a: &[T], b: &[T]) -> [T; 2] {
    [a[0] - b[0], a[1] - b[1]]
}

/// C(u) = Q: the point block Q (after the curve's blocks and u) lies on the curve.
///
/// ```
/// use camber_sketch::contact::{OnCurve, Param};
/// use camber_sketch::{curve_eval::CurveBasis, Entity};
/// use camber_solve::Residual;
/// use nalgebra::Point2;
/// let line = Entity::Line([Point2::new(0.0, 0.0), Point2::new(2.0, 0.0)]);
/// let r = OnCurve::new(CurveBasis::of(&line).ok_or("curve")?, Param::Block);
/// let mut g = [0.0; 2];
/// r.eval::<f64>(&[&[0.0, 0.0][..], &[2.0, 0.0][..], &[0.5][..], &[1.0, 0.0][..]], &mut g);
/// assert!(g[0].abs() < 1e-15 && g[1].abs() < 1e-15);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct OnCurve {
    basis: CurveBasis,
    u: Param,
}

impl OnCurve {
    /// The residual C(u) − Q.
    pub fn new(basis: CurveBasis, u: Param) -> Self {
        Self { basis, u }
    }
}

impl Residual for OnCurve {
    fn name(&self) -> &str {
        "point on curve"
    }
    fn dim(&self) -> usize {
        2
    }
    fn depends_on(&self, x: &[&[f64]], blocks: &mut [bool]) {
        curve_support(&self.basis, self.u, x, blocks);
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (c, _, k) = curve_at(&self.basis, self.u, x);
        let q = x[k];
        out[0] = c[0] - q[0];
        out[1] = c[1] - q[1];
    }
}

/// The curve touches the line through A and B at u: cross(C − A, d)/|d| = 0 and
/// cross(C′, d)/|d| = 0 with d = B − A (blocks: curve, u, A, B).
#[derive(Debug, Clone, PartialEq)]
pub struct LineContact {
    basis: CurveBasis,
    u: Param,
}

impl LineContact {
    /// The two rows of tangency to a line given by two point blocks.
    pub fn new(basis: CurveBasis, u: Param) -> Self {
        Self { basis, u }
    }
}

impl Residual for LineContact {
    fn name(&self) -> &str {
        "tangent to line"
    }
    fn dim(&self) -> usize {
        2
    }
    fn depends_on(&self, x: &[&[f64]], blocks: &mut [bool]) {
        curve_support(&self.basis, self.u, x, blocks);
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (c, c1, k) = curve_at(&self.basis, self.u, x);
        let (a, b) = (x[k], x[k + 1]);
        let d = sub(b, a);
        let len = dot(d, d).sqrt();
        out[0] = cross(sub(&c, a), d) / len;
        out[1] = cross(c1, d) / len;
    }
}

/// The curve touches the circle (c, r) at u, running around it in a given direction:
///
/// C(u) − c − σ·r·n(u) = 0 (two rows),  n = (−t_y, t_x), t = C′(u)/|C′(u)|,
///
/// with σ = +1 for clockwise travel (the centre to the right of C′) and σ = −1 for
/// counter-clockwise. It holds exactly when |C(u) − c| = r, (C(u) − c)·C′(u) = 0 and
/// sign cross(C(u) − c, C′(u)) = −σ: the usual two tangency conditions with the travel
/// direction built in, so Newton cannot converge to the reversed branch (a curve meeting the
/// circle with its tangent flipped). Blocks: curve, u, centre, radius.
///
/// ```
/// use camber_sketch::contact::{CircleContact, Param};
/// use camber_sketch::{curve_eval::CurveBasis, Entity};
/// use camber_solve::Residual;
/// use nalgebra::Point2;
/// // The segment y = 1 run left to right passes clockwise over the unit circle at u = ½.
/// let line = Entity::Line([Point2::new(-1.0, 1.0), Point2::new(1.0, 1.0)]);
/// let r = CircleContact::new(CurveBasis::of(&line).ok_or("curve")?, Param::Fixed(0.5), true);
/// let mut g = [1.0; 2];
/// r.eval::<f64>(&[&[-1.0, 1.0][..], &[1.0, 1.0][..], &[0.0, 0.0][..], &[1.0][..]], &mut g);
/// assert!(g[0].abs() < 1e-15 && g[1].abs() < 1e-15);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CircleContact {
    basis: CurveBasis,
    u: Param,
    sigma: f64,
}

impl CircleContact {
    /// The two rows of oriented tangency to a circle given by a centre block and a radius
    /// block; `clockwise` selects σ.
    pub fn new(basis: CurveBasis, u: Param, clockwise: bool) -> Self {
        Self {
            basis,
            u,
            sigma: if clockwise { 1.0 } else { -1.0 },
        }
    }
}

impl Residual for CircleContact {
    fn name(&self) -> &str {
        "tangent to circle"
    }
    fn dim(&self) -> usize {
        2
    }
    fn depends_on(&self, x: &[&[f64]], blocks: &mut [bool]) {
        curve_support(&self.basis, self.u, x, blocks);
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (c, c1, k) = curve_at(&self.basis, self.u, x);
        let (centre, r) = (x[k], x[k + 1][0]);
        let speed = dot(c1, c1).sqrt();
        let s = cst::<T>(self.sigma) * r / speed;
        out[0] = c[0] - centre[0] + s * c1[1];
        out[1] = c[1] - centre[1] - s * c1[0];
    }
}

/// (|P − c|² − r²)/(2r) = 0: the point lies on the circle (blocks: P, centre, radius).
#[derive(Debug, Clone, PartialEq)]
pub struct OnCircle;

impl Residual for OnCircle {
    fn name(&self) -> &str {
        "point on circle"
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let v = sub(x[0], x[1]);
        let r = x[2][0];
        out[0] = (dot(v, v) - r * r) / (cst::<T>(2.0) * r);
    }
}

/// (|a − b|² − D²)/(2D) = 0: two points D apart (blocks: a, b; D > 0).
#[derive(Debug, Clone, PartialEq)]
pub struct PointDistance {
    distance: f64,
}

impl PointDistance {
    /// The distance residual for D = `distance` (> 0, checked by the constraint).
    pub fn new(distance: f64) -> Self {
        Self { distance }
    }
}

impl Residual for PointDistance {
    fn name(&self) -> &str {
        "distance"
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let v = sub(x[0], x[1]);
        let d = cst::<T>(self.distance);
        out[0] = (dot(v, v) - d * d) / (cst::<T>(2.0) * d);
    }
}

/// sin(φ − θ) = 0 for the angle φ from d₁ = B₁ − A₁ to d₂ = B₂ − A₂ (blocks A₁, B₁, A₂, B₂).
#[derive(Debug, Clone, PartialEq)]
pub struct LineAngle {
    name: &'static str,
    cos: f64,
    sin: f64,
}

impl LineAngle {
    /// The residual for the angle θ (radians), named `name` in reports.
    pub fn new(name: &'static str, angle: f64) -> Self {
        Self {
            name,
            cos: angle.cos(),
            sin: angle.sin(),
        }
    }
}

impl Residual for LineAngle {
    fn name(&self) -> &str {
        self.name
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (d1, d2) = (sub(x[1], x[0]), sub(x[3], x[2]));
        let scale = (dot(d1, d1) * dot(d2, d2)).sqrt();
        out[0] = (cross(d1, d2) * cst::<T>(self.cos) - dot(d1, d2) * cst::<T>(self.sin)) / scale;
    }
}

/// cross(C₁′(u₁), C₂′(u₂))/(|C₁′||C₂′|) = 0: the tangents of two curves at fixed parameters
/// are parallel (blocks: the first curve's control points, then the second's).
#[derive(Debug, Clone, PartialEq)]
pub struct TangentsParallel {
    first: (CurveBasis, f64),
    second: (CurveBasis, f64),
}

impl TangentsParallel {
    /// Parallel tangents of `first` at u₁ and `second` at u₂.
    pub fn new(first: (CurveBasis, f64), second: (CurveBasis, f64)) -> Self {
        Self { first, second }
    }
}

impl Residual for TangentsParallel {
    fn name(&self) -> &str {
        "G1 join (free direction)"
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let n1 = self.first.0.count();
        let t1 = self.first.0.tangent(x, cst(self.first.1));
        let t2 = self.second.0.tangent(&x[n1..], cst(self.second.1));
        out[0] = cross(t1, t2) / (dot(t1, t1) * dot(t2, t2)).sqrt();
    }
}

/// r − R = 0: the radius block holds R (affine).
#[derive(Debug, Clone, PartialEq)]
pub struct RadiusValue {
    radius: f64,
}

impl RadiusValue {
    /// The residual r − `radius`.
    pub fn new(radius: f64) -> Self {
        Self { radius }
    }
}

impl Residual for RadiusValue {
    fn name(&self) -> &str {
        "radius"
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = x[0][0] - cst::<T>(self.radius);
    }
    fn is_affine(&self) -> bool {
        true
    }
}

/// Two curves touch at free (or fixed) parameters: C₁(u) − C₂(v) = 0 (two rows) and
/// cross(C₁′(u), C₂′(v))/(|C₁′||C₂′|) = 0 (one row). Blocks: the first curve's control points,
/// u if free, the second curve's control points, v if free.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveCurveContact {
    first: (CurveBasis, Param),
    second: (CurveBasis, Param),
}

impl CurveCurveContact {
    /// Contact of `first` at its parameter with `second` at its parameter.
    pub fn new(first: (CurveBasis, Param), second: (CurveBasis, Param)) -> Self {
        Self { first, second }
    }
}

impl Residual for CurveCurveContact {
    fn name(&self) -> &str {
        "curve-curve tangent"
    }
    fn dim(&self) -> usize {
        3
    }
    fn depends_on(&self, x: &[&[f64]], blocks: &mut [bool]) {
        let k = curve_support(&self.first.0, self.first.1, x, blocks);
        if let (Some(rest), Some(flags)) = (x.get(k..), blocks.get_mut(k..)) {
            curve_support(&self.second.0, self.second.1, rest, flags);
        }
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (c1, t1, k) = curve_at(&self.first.0, self.first.1, x);
        let (c2, t2, _) = curve_at(&self.second.0, self.second.1, &x[k..]);
        out[0] = c1[0] - c2[0];
        out[1] = c1[1] - c2[1];
        out[2] = cross(t1, t2) / (dot(t1, t1) * dot(t2, t2)).sqrt();
    }
}

/// κ₁(u₁) − κ₂(u₂) = 0 with κ = cross(C′, C″)/|C′|³, the signed curvature: two curves have the
/// same curvature at fixed parameters (blocks: the first curve's control points, then the
/// second's). With a G1 joint it makes the joint G2.
#[derive(Debug, Clone, PartialEq)]
pub struct CurvatureMatch {
    first: (CurveBasis, f64),
    second: (CurveBasis, f64),
}

impl CurvatureMatch {
    /// Equal curvature of `first` at u₁ and `second` at u₂.
    pub fn new(first: (CurveBasis, f64), second: (CurveBasis, f64)) -> Self {
        Self { first, second }
    }
}

fn curvature<T: Scalar>(c: [[T; 2]; 3]) -> T {
    let speed2 = dot(c[1], c[1]);
    cross(c[1], c[2]) / (speed2 * speed2.sqrt())
}

impl Residual for CurvatureMatch {
    fn name(&self) -> &str {
        "G2 join"
    }
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let n1 = self.first.0.count();
        let k1 = curvature(self.first.0.eval2(x, cst(self.first.1)));
        let k2 = curvature(self.second.0.eval2(&x[n1..], cst(self.second.1)));
        out[0] = k1 - k2;
    }
}
