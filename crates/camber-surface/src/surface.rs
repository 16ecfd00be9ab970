//! Tensor-product NURBS surfaces in 3D, generic over the scalar type.
//!
//! A surface of degrees (p, q) over knot vectors U (in u) and V (in v) with an n_u × n_v net of
//! control points P_ij and weights w_ij > 0 is
//!
//! S(u, v) = A(u, v) / W(u, v),  A = Σ_i Σ_j N_{i,p}(u) N_{j,q}(v) w_ij P_ij,
//! W = Σ_i Σ_j N_{i,p}(u) N_{j,q}(v) w_ij,
//!
//! on the domain [u_p, u_{n_u}] × [v_q, v_{n_v}]. Derivatives follow from the quotient rule on
//! the homogeneous form (The NURBS Book, eq. 4.20): with A_kl = ∂ᵏ⁺ˡA/∂uᵏ∂vˡ and W_kl alike,
//!
//! S_u = (A_10 − W_10 S) / W,   S_v = (A_01 − W_01 S) / W,
//! S_uu = (A_20 − 2 W_10 S_u − W_20 S) / W,   S_vv = (A_02 − 2 W_01 S_v − W_02 S) / W,
//! S_uv = (A_11 − W_11 S − W_10 S_v − W_01 S_u) / W.
//!
//! Knot insertion reuses camber-geom's [`ControlNet`] on homogeneous coordinates: inserting in u
//! treats each row i of the net (all n_v points, 4 numbers each) as one control "point" of
//! dimension 4·n_v, so the curve algorithm (A5.1, A5.4) runs once for every column at a time.

use camber_geom::curve::check_parameter;
use camber_geom::knot_ops::ControlNet;
use camber_geom::scalar::re;
use camber_geom::{KnotVector, NurbsCurve3, Scalar};
use nalgebra::{Point3, Vector3};
use smallvec::{smallvec, SmallVec};

use crate::errors::{Error, Result};

/// Scratch length for (order + 1)(degree + 1) basis values held on the stack.
const BASIS_INLINE: usize = 24;

/// A tensor-product NURBS surface in 3D (see the module documentation for the formulas).
///
/// Control points are stored row by row: P_ij (i along u, j along v) at index i·n_v + j.
///
/// ```
/// use camber_geom::KnotVector;
/// use camber_surface::NurbsSurface;
/// use nalgebra::Point3;
/// // The bilinear patch z = u·v over the unit square.
/// let k = KnotVector::try_new(vec![0.0_f64, 0.0, 1.0, 1.0])?;
/// let pts = vec![Point3::new(0.0, 0.0, 0.0), Point3::new(0.0, 1.0, 0.0),
///                Point3::new(1.0, 0.0, 0.0), Point3::new(1.0, 1.0, 1.0)];
/// let s = NurbsSurface::try_with_unit_weights(1, k.clone(), 1, k, pts)?;
/// let d = s.derivatives(0.5, 0.25)?;
/// assert!((d.point.z - 0.125).abs() < 1e-15);
/// assert!((d.su.z - 0.25).abs() < 1e-15 && (d.suv.z - 1.0).abs() < 1e-15);
/// # Ok::<(), camber_surface::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsSurface<T: Scalar> {
    degree_u: usize,
    degree_v: usize,
    knots_u: KnotVector<T>,
    knots_v: KnotVector<T>,
    count_u: usize,
    count_v: usize,
    control_points: Vec<Point3<T>>,
    weights: Vec<T>,
}

/// The point and the partial derivatives up to second order at one (u, v).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceDerivatives<T: Scalar> {
    /// S(u, v).
    pub point: Point3<T>,
    /// ∂S/∂u.
    pub su: Vector3<T>,
    /// ∂S/∂v.
    pub sv: Vector3<T>,
    /// ∂²S/∂u².
    pub suu: Vector3<T>,
    /// ∂²S/∂u∂v.
    pub suv: Vector3<T>,
    /// ∂²S/∂v².
    pub svv: Vector3<T>,
}

impl<T: Scalar> SurfaceDerivatives<T> {
    /// The unit normal (S_u × S_v)/|S_u × S_v|, or `None` where the cross product vanishes.
    pub fn normal(&self) -> Option<Vector3<T>> {
        let n = self.su.cross(&self.sv);
        let len = n.norm();
        if re(len) > 0.0 {
            Some(n / len)
        } else {
            None
        }
    }
}

/// The rational basis at one (u, v), restricted to the (p + 1)(q + 1) control points that act
/// there: S = Σ_k value_k P_{index_k}, S_u = Σ_k du_k P_{index_k}, S_v = Σ_k dv_k P_{index_k}.
///
/// With R_k = N_k w_k / W, the derivatives are ∂R_k/∂u = (∂N_k/∂u · w_k − R_k W_u) / W (and
/// likewise in v). The weights are held fixed, so S, S_u and S_v are linear in the control
/// points: this is what makes the deformation's objective quadratic.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceBasis<T> {
    /// Flat control point indices i·n_v + j.
    pub indices: Vec<usize>,
    /// R_k(u, v).
    pub value: Vec<T>,
    /// ∂R_k/∂u.
    pub du: Vec<T>,
    /// ∂R_k/∂v.
    pub dv: Vec<T>,
}

/// # Construction
impl<T: Scalar> NurbsSurface<T> {
    /// A surface of degrees (p, q) = (`degree_u`, `degree_v`) from its knots, its control
    /// points (row by row, n_u·n_v of them with n_u = |U| − p − 1 and n_v = |V| − q − 1) and one
    /// weight per control point.
    ///
    /// # Errors
    /// The knot checks of camber-geom ([`camber_geom::Error::TooFewControlPoints`],
    /// [`camber_geom::Error::KnotCount`], [`camber_geom::Error::EmptyDomain`], …) wrapped in
    /// [`Error::Geom`]; [`Error::ControlPointCount`]; non-finite coordinates and weights, a
    /// wrong weight count and weights ≤ 0 as the camber-geom NURBS curve reports them.
    ///
    /// ```
    /// use camber_geom::KnotVector;
    /// use camber_surface::{Error, NurbsSurface};
    /// use nalgebra::Point3;
    /// let k = KnotVector::try_new(vec![0.0_f64, 0.0, 1.0, 1.0])?;
    /// let pts = vec![Point3::origin(); 4];
    /// let bad = NurbsSurface::try_new(1, k.clone(), 1, k, pts, vec![1.0, 1.0, 0.0, 1.0]);
    /// assert_eq!(bad, Err(Error::Geom(camber_geom::Error::NonPositiveWeight { index: 2, value: 0.0 })));
    /// # Ok::<(), camber_surface::Error>(())
    /// ```
    pub fn try_new(
        degree_u: usize,
        knots_u: KnotVector<T>,
        degree_v: usize,
        knots_v: KnotVector<T>,
        control_points: Vec<Point3<T>>,
        weights: Vec<T>,
    ) -> Result<Self> {
        knots_u.validate()?;
        knots_v.validate()?;
        // Saturating: a file may carry any degree, and an absurd one must be an error.
        let count_u = knots_u.len().saturating_sub(degree_u.saturating_add(1));
        let count_v = knots_v.len().saturating_sub(degree_v.saturating_add(1));
        knots_u.check_for(degree_u, count_u)?;
        knots_v.check_for(degree_v, count_v)?;
        if control_points.len() != count_u * count_v {
            return Err(Error::ControlPointCount {
                count_u,
                count_v,
                found: control_points.len(),
            });
        }
        camber_geom::curve::check_points(&control_points)?;
        if weights.len() != control_points.len() {
            return Err(camber_geom::Error::WeightCount {
                expected: control_points.len(),
                found: weights.len(),
            }
            .into());
        }
        for (index, &w) in weights.iter().enumerate() {
            let value = re(w);
            if !value.is_finite() {
                return Err(camber_geom::Error::NonFinite {
                    what: "weight",
                    index,
                    value,
                }
                .into());
            }
            if w <= T::zero() {
                return Err(camber_geom::Error::NonPositiveWeight { index, value }.into());
            }
        }
        Ok(Self {
            degree_u,
            degree_v,
            knots_u,
            knots_v,
            count_u,
            count_v,
            control_points,
            weights,
        })
    }

    /// The non-rational B-spline surface (every weight 1). Same checks as
    /// [`try_new`](Self::try_new).
    ///
    /// # Errors
    /// As [`try_new`](Self::try_new).
    pub fn try_with_unit_weights(
        degree_u: usize,
        knots_u: KnotVector<T>,
        degree_v: usize,
        knots_v: KnotVector<T>,
        control_points: Vec<Point3<T>>,
    ) -> Result<Self> {
        let weights = vec![T::one(); control_points.len()];
        Self::try_new(
            degree_u,
            knots_u,
            degree_v,
            knots_v,
            control_points,
            weights,
        )
    }

    /// The same knots and weights with new control points (same count).
    ///
    /// # Errors
    /// [`Error::ControlPointCount`] for a wrong count, non-finite coordinates.
    pub fn try_with_control_points(&self, control_points: Vec<Point3<T>>) -> Result<Self> {
        Self::try_new(
            self.degree_u,
            self.knots_u.clone(),
            self.degree_v,
            self.knots_v.clone(),
            control_points,
            self.weights.clone(),
        )
    }
}

/// # Access
impl<T: Scalar> NurbsSurface<T> {
    /// Degrees (p, q).
    pub fn degrees(&self) -> (usize, usize) {
        (self.degree_u, self.degree_v)
    }

    /// Knot vector in u.
    pub fn knots_u(&self) -> &KnotVector<T> {
        &self.knots_u
    }

    /// Knot vector in v.
    pub fn knots_v(&self) -> &KnotVector<T> {
        &self.knots_v
    }

    /// Net size (n_u, n_v).
    pub fn counts(&self) -> (usize, usize) {
        (self.count_u, self.count_v)
    }

    /// All control points, row by row (P_ij at i·n_v + j).
    pub fn control_points(&self) -> &[Point3<T>] {
        &self.control_points
    }

    /// All weights, in the order of the control points.
    pub fn weights(&self) -> &[T] {
        &self.weights
    }

    /// The domain in u, [u_p, u_{n_u}].
    pub fn domain_u(&self) -> (T, T) {
        self.knots_u.domain(self.degree_u)
    }

    /// The domain in v, [v_q, v_{n_v}].
    pub fn domain_v(&self) -> (T, T) {
        self.knots_v.domain(self.degree_v)
    }

    /// The length of the diagonal of the control points' bounding box: a size for relative
    /// tolerances (0 for an empty or single-point net).
    pub fn size(&self) -> f64 {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for p in &self.control_points {
            for k in 0..3 {
                lo[k] = lo[k].min(re(p[k]));
                hi[k] = hi[k].max(re(p[k]));
            }
        }
        (0..3).map(|k| (hi[k] - lo[k]).powi(2)).sum::<f64>().sqrt()
    }
}

/// # Evaluation
impl<T: Scalar> NurbsSurface<T> {
    /// S(u, v).
    ///
    /// # Errors
    /// [`camber_geom::Error::ParameterOutsideDomain`] / `NonFinite` (in [`Error::Geom`]) for a
    /// parameter outside its domain.
    pub fn point(&self, u: T, v: T) -> Result<Point3<T>> {
        Ok(self.derivatives(u, v)?.point)
    }

    /// The unit normal (S_u × S_v)/|S_u × S_v|.
    ///
    /// # Errors
    /// As [`point`](Self::point), and [`Error::DegenerateNormal`] where S_u × S_v = 0.
    pub fn normal(&self, u: T, v: T) -> Result<Vector3<T>> {
        self.derivatives(u, v)?
            .normal()
            .ok_or(Error::DegenerateNormal { u: re(u), v: re(v) })
    }

    /// The point and every partial derivative up to second order (module documentation),
    /// without heap allocation for degrees up to 7.
    ///
    /// # Errors
    /// As [`point`](Self::point).
    pub fn derivatives(&self, u: T, v: T) -> Result<SurfaceDerivatives<T>> {
        check_parameter(u, self.domain_u())?;
        check_parameter(v, self.domain_v())?;
        let (p, q) = (self.degree_u, self.degree_v);
        let (span_u, nu) = basis_ders(&self.knots_u, p, u);
        let (span_v, nv) = basis_ders(&self.knots_v, q, v);
        // a[k][l], w[k][l] for k + l ≤ 2 (entries with k + l > 2 stay unused).
        let mut a = [[Vector3::<T>::zeros(); 3]; 3];
        let mut w = [[T::zero(); 3]; 3];
        for ia in 0..=p {
            let i = span_u - p + ia;
            for jb in 0..=q {
                let j = span_v - q + jb;
                let idx = i * self.count_v + j;
                let (Some(pt), Some(&wt)) = (self.control_points.get(idx), self.weights.get(idx))
                else {
                    continue;
                };
                let wp = pt.coords * wt;
                for k in 0..3 {
                    for l in 0..3 - k {
                        let c = nu[k * (p + 1) + ia] * nv[l * (q + 1) + jb];
                        a[k][l] += wp * c;
                        w[k][l] += wt * c;
                    }
                }
            }
        }
        let inv = T::one() / w[0][0];
        let two = T::one() + T::one();
        let s = a[0][0] * inv;
        let su = (a[1][0] - s * w[1][0]) * inv;
        let sv = (a[0][1] - s * w[0][1]) * inv;
        let suu = (a[2][0] - su * (two * w[1][0]) - s * w[2][0]) * inv;
        let svv = (a[0][2] - sv * (two * w[0][1]) - s * w[0][2]) * inv;
        let suv = (a[1][1] - s * w[1][1] - sv * w[1][0] - su * w[0][1]) * inv;
        Ok(SurfaceDerivatives {
            point: Point3::from(s),
            su,
            sv,
            suu,
            suv,
            svv,
        })
    }

    /// The rational basis (R_k, ∂R_k/∂u, ∂R_k/∂v) of the control points acting at (u, v)
    /// (see [`SurfaceBasis`]).
    ///
    /// # Errors
    /// As [`point`](Self::point).
    pub fn basis(&self, u: T, v: T) -> Result<SurfaceBasis<T>> {
        check_parameter(u, self.domain_u())?;
        check_parameter(v, self.domain_v())?;
        let (p, q) = (self.degree_u, self.degree_v);
        let (span_u, nu) = basis_ders(&self.knots_u, p, u);
        let (span_v, nv) = basis_ders(&self.knots_v, q, v);
        let len = (p + 1) * (q + 1);
        let mut out = SurfaceBasis {
            indices: Vec::with_capacity(len),
            value: Vec::with_capacity(len),
            du: Vec::with_capacity(len),
            dv: Vec::with_capacity(len),
        };
        let (mut w, mut wu, mut wv) = (T::zero(), T::zero(), T::zero());
        for ia in 0..=p {
            for jb in 0..=q {
                let idx = (span_u - p + ia) * self.count_v + span_v - q + jb;
                let wt = self.weights.get(idx).copied().unwrap_or(T::zero());
                let n = nu[ia] * nv[jb] * wt;
                let n_u = nu[p + 1 + ia] * nv[jb] * wt;
                let n_v = nu[ia] * nv[q + 1 + jb] * wt;
                w += n;
                wu += n_u;
                wv += n_v;
                out.indices.push(idx);
                out.value.push(n);
                out.du.push(n_u);
                out.dv.push(n_v);
            }
        }
        let inv = T::one() / w;
        for k in 0..len {
            let r = out.value[k] * inv;
            out.du[k] = (out.du[k] - r * wu) * inv;
            out.dv[k] = (out.dv[k] - r * wv) * inv;
            out.value[k] = r;
        }
        Ok(out)
    }
}

/// Span and basis derivatives up to order 2, row k at [k(p + 1) .. (k + 1)(p + 1)].
fn basis_ders<T: Scalar>(
    knots: &KnotVector<T>,
    degree: usize,
    t: T,
) -> (usize, SmallVec<[T; BASIS_INLINE]>) {
    let span = knots.find_span(degree, t);
    let mut ders: SmallVec<[T; BASIS_INLINE]> = smallvec![T::zero(); 3 * (degree + 1)];
    knots.basis_function_derivatives(span, t, degree, 2, &mut ders);
    (span, ders)
}

/// Which parameter direction a knot operation or an isocurve refers to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Direction {
    /// The u direction (first index of P_ij).
    U,
    /// The v direction (second index of P_ij).
    V,
}

/// # Knot insertion and isocurves
impl<T: Scalar> NurbsSurface<T> {
    /// Inserts the knot t `times` times in `direction` (The NURBS Book A5.3 by rows: A5.1 on
    /// homogeneous coordinates). The surface is unchanged; the net gains `times` rows
    /// (direction U) or columns (direction V).
    ///
    /// ```
    /// use camber_geom::KnotVector;
    /// use camber_surface::{Direction, NurbsSurface};
    /// use nalgebra::Point3;
    /// let k = KnotVector::try_new(vec![0.0_f64, 0.0, 1.0, 1.0])?;
    /// let pts = vec![Point3::new(0.0, 0.0, 0.0), Point3::new(0.0, 1.0, 1.0),
    ///                Point3::new(1.0, 0.0, 0.0), Point3::new(1.0, 1.0, 0.0)];
    /// let s = NurbsSurface::try_with_unit_weights(1, k.clone(), 1, k, pts)?;
    /// let r = s.insert_knot(Direction::U, 0.5, 1)?;
    /// assert_eq!(r.counts(), (3, 2));
    /// assert!((r.point(0.3, 0.7)? - s.point(0.3, 0.7)?).norm() < 1e-15);
    /// # Ok::<(), camber_surface::Error>(())
    /// ```
    ///
    /// # Errors
    /// Those of [`ControlNet::insert_knot`] (parameter outside the domain, multiplicity above
    /// the degree), in [`Error::Geom`].
    pub fn insert_knot(&self, direction: Direction, t: T, times: usize) -> Result<Self> {
        let net = self.rows_as_net(direction)?.insert_knot(t, times)?;
        self.rebuilt_from_rows(direction, net)
    }

    /// Inserts all of `new_knots` (non-decreasing) in `direction` at once (knot refinement,
    /// A5.5). The surface is unchanged.
    ///
    /// # Errors
    /// Those of [`ControlNet::refine`], in [`Error::Geom`].
    pub fn refine(&self, direction: Direction, new_knots: &[T]) -> Result<Self> {
        let net = self.rows_as_net(direction)?.refine(new_knots)?;
        self.rebuilt_from_rows(direction, net)
    }

    /// The isoparametric curve at a fixed parameter t of `direction`: with direction U the curve
    /// v ↦ S(t, v), with direction V the curve u ↦ S(u, t), as a NURBS curve of the other
    /// degree. Its homogeneous control points are Σ_i N_{i,p}(t)·(w_ij P_ij, w_ij).
    ///
    /// ```
    /// use camber_geom::{KnotVector, ParametricCurve};
    /// use camber_surface::{Direction, NurbsSurface};
    /// use nalgebra::Point3;
    /// let k = KnotVector::try_new(vec![0.0_f64, 0.0, 1.0, 1.0])?;
    /// let pts = vec![Point3::new(0.0, 0.0, 0.0), Point3::new(0.0, 1.0, 0.0),
    ///                Point3::new(1.0, 0.0, 0.0), Point3::new(1.0, 1.0, 1.0)];
    /// let s = NurbsSurface::try_with_unit_weights(1, k.clone(), 1, k, pts)?;
    /// let c = s.isocurve(Direction::U, 0.5)?; // v ↦ S(0.5, v) = (0.5, v, v/2)
    /// assert!((c.point(1.0)?.z - 0.5).abs() < 1e-15);
    /// # Ok::<(), camber_surface::Error>(())
    /// ```
    ///
    /// # Errors
    /// A parameter outside the domain ([`Error::Geom`]).
    pub fn isocurve(&self, direction: Direction, t: T) -> Result<NurbsCurve3<T>> {
        let net = self.rows_as_net(direction)?;
        let mut coords = vec![T::zero(); net.dim];
        net.evaluate_into(t, &mut coords)?;
        let (degree, knots) = match direction {
            Direction::U => (self.degree_v, self.knots_v.clone()),
            Direction::V => (self.degree_u, self.knots_u.clone()),
        };
        let curve_net = ControlNet::try_new(degree, knots, 4, coords)?;
        Ok(NurbsCurve3::try_from_homogeneous(curve_net)?)
    }

    /// The net as a curve net along `direction`: point k is row k (direction U) or column k
    /// (direction V), each of the other count's homogeneous points (w·x, w·y, w·z, w).
    fn rows_as_net(&self, direction: Direction) -> Result<ControlNet<T>> {
        let (outer, inner) = match direction {
            Direction::U => (self.count_u, self.count_v),
            Direction::V => (self.count_v, self.count_u),
        };
        let mut coords = Vec::with_capacity(4 * outer * inner);
        for a in 0..outer {
            for b in 0..inner {
                let idx = match direction {
                    Direction::U => a * self.count_v + b,
                    Direction::V => b * self.count_v + a,
                };
                let (pt, w) = (self.control_points[idx], self.weights[idx]);
                coords.extend_from_slice(&[pt.x * w, pt.y * w, pt.z * w, w]);
            }
        }
        let (degree, knots) = match direction {
            Direction::U => (self.degree_u, self.knots_u.clone()),
            Direction::V => (self.degree_v, self.knots_v.clone()),
        };
        Ok(ControlNet::try_new(degree, knots, 4 * inner, coords)?)
    }

    /// Rebuilds a surface from a curve net made by [`rows_as_net`](Self::rows_as_net).
    fn rebuilt_from_rows(&self, direction: Direction, net: ControlNet<T>) -> Result<Self> {
        let inner = net.dim / 4;
        let outer = net.point_count();
        let mut points = vec![Point3::origin(); outer * inner];
        let mut weights = vec![T::one(); outer * inner];
        for a in 0..outer {
            for (b, h) in net.point(a).chunks_exact(4).enumerate() {
                let idx = match direction {
                    Direction::U => a * inner + b,
                    Direction::V => b * outer + a,
                };
                points[idx] = Point3::new(h[0] / h[3], h[1] / h[3], h[2] / h[3]);
                weights[idx] = h[3];
            }
        }
        let (ku, kv) = match direction {
            Direction::U => (net.knots, self.knots_v.clone()),
            Direction::V => (self.knots_u.clone(), net.knots),
        };
        Self::try_new(self.degree_u, ku, self.degree_v, kv, points, weights)
    }
}

/// The JSON form: degrees, knots, control points row by row as `[x, y, z]`, weights.
#[derive(serde::Serialize, serde::Deserialize)]
struct RawSurface {
    degree_u: usize,
    degree_v: usize,
    knots_u: Vec<f64>,
    knots_v: Vec<f64>,
    control_points: Vec<camber_geom::serde_support::RawPoint>,
    weights: Vec<f64>,
}

impl serde::Serialize for NurbsSurface<f64> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        RawSurface {
            degree_u: self.degree_u,
            degree_v: self.degree_v,
            knots_u: self.knots_u.as_slice().to_vec(),
            knots_v: self.knots_v.as_slice().to_vec(),
            control_points: camber_geom::serde_support::points_to_raw(&self.control_points),
            weights: self.weights.clone(),
        }
        .serialize(s)
    }
}

impl<'de> serde::Deserialize<'de> for NurbsSurface<f64> {
    /// Reads the JSON form and validates it with [`NurbsSurface::try_new`].
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        let raw = RawSurface::deserialize(d)?;
        let build = || -> Result<Self> {
            let ku = KnotVector::try_new(raw.knots_u)?;
            let kv = KnotVector::try_new(raw.knots_v)?;
            let points = camber_geom::serde_support::points_from_raw(&raw.control_points)?;
            Self::try_new(raw.degree_u, ku, raw.degree_v, kv, points, raw.weights)
        };
        build().map_err(serde::de::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn rational_basis_reproduces_the_point_and_tangents() {
        let k = KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]).unwrap();
        let pts: Vec<Point3<f64>> = (0..9)
            .map(|n| Point3::new((n / 3) as f64, (n % 3) as f64, ((n * 7) % 5) as f64 / 4.0))
            .collect();
        let w = vec![1.0, 0.5, 2.0, 1.5, 1.0, 0.7, 1.0, 3.0, 1.0];
        let s = NurbsSurface::try_new(2, k.clone(), 2, k, pts.clone(), w).unwrap();
        let (u, v) = (0.3, 0.8);
        let b = s.basis(u, v).unwrap();
        let d = s.derivatives(u, v).unwrap();
        let mut sum = [Vector3::zeros(); 3];
        for (k, &idx) in b.indices.iter().enumerate() {
            sum[0] += pts[idx].coords * b.value[k];
            sum[1] += pts[idx].coords * b.du[k];
            sum[2] += pts[idx].coords * b.dv[k];
        }
        assert_relative_eq!(sum[0], d.point.coords, epsilon = 1e-14);
        assert_relative_eq!(sum[1], d.su, epsilon = 1e-13);
        assert_relative_eq!(sum[2], d.sv, epsilon = 1e-13);
        assert_relative_eq!(b.value.iter().sum::<f64>(), 1.0, epsilon = 1e-15);
    }

    #[test]
    fn bad_parameters_and_degenerate_normals() {
        let k = KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0]).unwrap();
        // All points on one line: S_u × S_v = 0.
        let pts = vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(2.0, 0.0, 0.0),
        ];
        let s = NurbsSurface::try_with_unit_weights(1, k.clone(), 1, k, pts).unwrap();
        assert_eq!(
            s.normal(0.5, 0.5),
            Err(Error::DegenerateNormal { u: 0.5, v: 0.5 })
        );
        assert!(matches!(
            s.point(1.5, 0.0),
            Err(Error::Geom(
                camber_geom::Error::ParameterOutsideDomain { .. }
            ))
        ));
        assert!(s.isocurve(Direction::V, f64::NAN).is_err());
    }
}
