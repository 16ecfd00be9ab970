//! The residuals the built-in constraints compile to: constant-coefficient combinations of
//! point blocks (each block a point (x, y)), all affine.
//!
//! With blocks P₁, …, P_k read and coefficients c₁, …, c_k (curve basis values or their
//! derivatives at a fixed parameter, ±1 for plain points), v = Σ cⱼ·Pⱼ is a curve point, a
//! tangent, or a difference of points, and:
//! - [`PointCombination`]: v − target = 0 (two rows);
//! - [`DirectionCross`]: cross(v, d) = v_x·d_y − v_y·d_x = 0 (one row);
//! - [`LineTangency`]: cross(v₀ − L₀, d) = 0 and cross(v₁, d) = 0, v₀ and v₁ being two
//!   combinations over the same blocks (two rows);
//! - [`RadiusValue`]: r − R = 0 on a circle's radius block (one row).
//!
//! Their Jacobians are constant: ∂/∂Pⱼ of v is cⱼ·I₂.

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};

/// v = Σ cⱼ·Pⱼ over the blocks read (each of length 2).
#[inline]
fn combination<T: Scalar>(coeffs: &[f64], x: &[&[T]]) -> [T; 2] {
    let mut v = [T::zero(), T::zero()];
    for (c, p) in coeffs.iter().zip(x) {
        let c = cst::<T>(*c);
        v[0] += c * p[0];
        v[1] += c * p[1];
    }
    v
}

/// Σ cⱼ·Pⱼ − target = 0: a point of a curve at a parameter, a tangent vector, a difference of
/// two points (coincidence), or a pinned point (dragging). Two rows.
///
/// ```
/// use camber_sketch::residuals::PointCombination;
/// use camber_solve::Residual;
/// // The midpoint of two blocks at (1, 1).
/// let r = PointCombination::new("midpoint", vec![0.5, 0.5], [1.0, 1.0]);
/// let mut g = [0.0_f64; 2];
/// r.eval(&[&[0.0, 0.0][..], &[2.0, 4.0][..]], &mut g);
/// assert!(g[0].abs() < 1e-15 && (g[1] - 1.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct PointCombination {
    name: &'static str,
    coeffs: Vec<f64>,
    target: [f64; 2],
}

impl PointCombination {
    /// The residual Σ `coeffs`ⱼ·Pⱼ − `target`, named `name` in reports.
    pub fn new(name: &'static str, coeffs: Vec<f64>, target: [f64; 2]) -> Self {
        Self {
            name,
            coeffs,
            target,
        }
    }

    /// The coefficients, one per block read.
    pub fn coeffs(&self) -> &[f64] {
        &self.coeffs
    }
}

impl Residual for PointCombination {
    fn name(&self) -> &str {
        self.name
    }
    fn dim(&self) -> usize {
        2
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2; self.coeffs.len()])
    }
    /// One point (two unknowns) per coefficient, checked without building the list.
    fn accepts_block_sizes(&self, sizes: &[usize]) -> bool {
        sizes.len() == self.coeffs.len() && sizes.iter().all(|n| *n == 2)
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let v = combination(&self.coeffs, x);
        out[0] = v[0] - cst::<T>(self.target[0]);
        out[1] = v[1] - cst::<T>(self.target[1]);
    }
    fn is_affine(&self) -> bool {
        true
    }
    /// ∂/∂Pⱼ = cⱼ·I (two columns per block), constant: no dual numbers needed.
    fn structured_jacobian(
        &self,
        x: &[&[f64]],
        _active: &[bool],
        values: &mut [f64],
        jac: &mut [f64],
    ) -> bool {
        let ncols = 2 * self.coeffs.len();
        if x.len() != self.coeffs.len() || jac.len() != 2 * ncols || values.len() != 2 {
            return false;
        }
        self.eval(x, values);
        jac.fill(0.0);
        for (j, c) in self.coeffs.iter().enumerate() {
            jac[2 * j] = *c;
            jac[ncols + 2 * j + 1] = *c;
        }
        true
    }
}

/// cross(Σ cⱼ·Pⱼ, d) = 0: the combination (a tangent C′(u)) is parallel to the fixed direction
/// d. One row. Which way it points is checked separately (see [`crate::Sense`]).
///
/// ```
/// use camber_sketch::residuals::DirectionCross;
/// use camber_solve::Residual;
/// // P₁ − P₀ parallel to (1, 1).
/// let r = DirectionCross::new("start tangent", vec![-1.0, 1.0], [1.0, 1.0]);
/// let mut g = [0.0_f64];
/// r.eval(&[&[0.0, 0.0][..], &[2.0, 2.0][..]], &mut g);
/// assert!(g[0].abs() < 1e-15);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct DirectionCross {
    name: &'static str,
    coeffs: Vec<f64>,
    direction: [f64; 2],
}

impl DirectionCross {
    /// The residual cross(Σ `coeffs`ⱼ·Pⱼ, `direction`), named `name` in reports.
    pub fn new(name: &'static str, coeffs: Vec<f64>, direction: [f64; 2]) -> Self {
        Self {
            name,
            coeffs,
            direction,
        }
    }
}

impl Residual for DirectionCross {
    fn name(&self) -> &str {
        self.name
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2; self.coeffs.len()])
    }
    /// One point (two unknowns) per coefficient, checked without building the list.
    fn accepts_block_sizes(&self, sizes: &[usize]) -> bool {
        sizes.len() == self.coeffs.len() && sizes.iter().all(|n| *n == 2)
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let v = combination(&self.coeffs, x);
        out[0] = v[0] * cst::<T>(self.direction[1]) - v[1] * cst::<T>(self.direction[0]);
    }
    fn is_affine(&self) -> bool {
        true
    }
    /// ∂/∂Pⱼ = cⱼ·(d_y, −d_x), constant: no dual numbers needed.
    fn structured_jacobian(
        &self,
        x: &[&[f64]],
        _active: &[bool],
        values: &mut [f64],
        jac: &mut [f64],
    ) -> bool {
        if x.len() != self.coeffs.len() || jac.len() != 2 * self.coeffs.len() || values.len() != 1 {
            return false;
        }
        self.eval(x, values);
        for (j, c) in self.coeffs.iter().enumerate() {
            jac[2 * j] = c * self.direction[1];
            jac[2 * j + 1] = -(c * self.direction[0]);
        }
        true
    }
}

/// A curve point on a fixed line and the tangent parallel to it: with v₀ = Σ aⱼ·Pⱼ (the point)
/// and v₁ = Σ bⱼ·Pⱼ (the tangent) over the same blocks, the rows are cross(v₀ − L₀, d) and
/// cross(v₁, d).
///
/// ```
/// use camber_sketch::residuals::LineTangency;
/// use camber_solve::Residual;
/// // The segment P₀P₁ at u = ½ on the x axis and along it.
/// let r = LineTangency::new(vec![0.5, 0.5], vec![-1.0, 1.0], [0.0, 0.0], [1.0, 0.0]);
/// let mut g = [0.0_f64; 2];
/// r.eval(&[&[0.0, 1.0][..], &[2.0, -1.0][..]], &mut g);
/// assert!(g[0].abs() < 1e-15 && (g[1] - 2.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct LineTangency {
    point: Vec<f64>,
    tangent: Vec<f64>,
    origin: [f64; 2],
    direction: [f64; 2],
}

impl LineTangency {
    /// The two rows for point coefficients `point`, tangent coefficients `tangent` (one each
    /// per block read), and the line through `origin` along `direction`.
    pub fn new(point: Vec<f64>, tangent: Vec<f64>, origin: [f64; 2], direction: [f64; 2]) -> Self {
        Self {
            point,
            tangent,
            origin,
            direction,
        }
    }
}

impl Residual for LineTangency {
    fn name(&self) -> &str {
        "tangent to line at"
    }
    fn dim(&self) -> usize {
        2
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2; self.point.len()])
    }
    /// One point (two unknowns) per coefficient, checked without building the list.
    fn accepts_block_sizes(&self, sizes: &[usize]) -> bool {
        sizes.len() == self.point.len() && sizes.iter().all(|n| *n == 2)
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let p = combination(&self.point, x);
        let t = combination(&self.tangent, x);
        let (dx, dy) = (cst::<T>(self.direction[0]), cst::<T>(self.direction[1]));
        let (qx, qy) = (
            p[0] - cst::<T>(self.origin[0]),
            p[1] - cst::<T>(self.origin[1]),
        );
        out[0] = qx * dy - qy * dx;
        out[1] = t[0] * dy - t[1] * dx;
    }
    fn is_affine(&self) -> bool {
        true
    }
}

/// r − R = 0: the radius block holds R (affine): the `radius` kind, and a fixed circle's
/// radius held by a row.
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
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![1])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = x[0][0] - cst::<T>(self.radius);
    }
    fn is_affine(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use camber_solve::DynResidual;

    /// The structured Jacobian is the one automatic differentiation gives
    /// ([`DynResidual::jacobian`] does not take the shortcut): values to the bit, every entry
    /// written; and [`camber_solve::derive::autodiff::jacobian_active`] returns it.
    #[test]
    fn jacobians_by_hand_are_those_of_autodiff() {
        let blocks = [[0.3, -1.7], [2.0, 0.125], [-4.5, 3.3]];
        let x: Vec<&[f64]> = blocks.iter().map(|b| &b[..]).collect();
        let coeffs = vec![3.0, -6.000_000_1, 1.0 / 3.0];
        let check = |r: &dyn DynResidual, by_hand: &dyn Fn(&mut [f64], &mut [f64]) -> bool| {
            let dim = r.dim();
            let (mut g, mut jac) = (vec![0.0; dim], vec![0.0; dim * 6]);
            r.jacobian(&x, &mut g, &mut jac).unwrap();
            let (mut g2, mut jac2) = (vec![0.0; dim], vec![7.0; dim * 6]);
            assert!(by_hand(&mut g2, &mut jac2));
            assert_eq!(
                g.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                g2.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
            );
            // Equal as numbers (autodiff writes −0 where a negative coefficient meets a
            // zero seed).
            assert_eq!(jac, jac2);
            let (mut g3, mut jac3) = (vec![0.0; dim], vec![7.0; dim * 6]);
            r.jacobian_active(&x, &[true; 3], &mut g3, &mut jac3)
                .unwrap();
            assert_eq!(jac3, jac);
            assert!(jac.iter().any(|v| *v != 0.0));
        };
        let p = PointCombination::new("c", coeffs.clone(), [0.5, -2.0]);
        check(&p, &|g, j| {
            Residual::structured_jacobian(&p, &x, &[true; 3], g, j)
        });
        let d = DirectionCross::new("t", coeffs, [0.6, -0.8]);
        check(&d, &|g, j| {
            Residual::structured_jacobian(&d, &x, &[true; 3], g, j)
        });
        // Blocks that do not match the coefficients: left to automatic differentiation.
        let (mut g, mut j) = ([0.0; 2], [0.0; 8]);
        assert!(!Residual::structured_jacobian(
            &p,
            &x[..2],
            &[true; 2],
            &mut g,
            &mut j
        ));
    }

    /// The shape test without the list gives the answer of the declared list, for every
    /// residual here and shapes of the right and wrong count and lengths.
    #[test]
    fn block_shapes_are_checked_as_declared() {
        let residuals: [Box<dyn DynResidual>; 3] = [
            Box::new(PointCombination::new("p", vec![1.0, -1.0], [0.0, 0.0])),
            Box::new(DirectionCross::new("d", vec![1.0, 0.5, -1.5], [1.0, 0.0])),
            Box::new(LineTangency::new(
                vec![0.5, 0.5],
                vec![-1.0, 1.0],
                [0.0, 0.0],
                [1.0, 0.0],
            )),
        ];
        let shapes: [&[usize]; 7] = [
            &[],
            &[2],
            &[2, 2],
            &[2, 2, 2],
            &[2, 1],
            &[1, 2, 2],
            &[2, 2, 3],
        ];
        for r in &residuals {
            let declared = r.block_sizes().unwrap();
            for shape in shapes {
                assert_eq!(
                    r.accepts_block_sizes(shape),
                    declared.as_slice() == shape,
                    "{} with {shape:?}",
                    r.name()
                );
            }
        }
    }
}
