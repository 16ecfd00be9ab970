//! Bundled test cases, generated in code: a face with creased neighbours.
//!
//! A neighbour across edge e of a face is built from the face's own control points: with E_k
//! the edge row and I_k the row next to it, the outward cross vector c_k = E_k − I_k is turned
//! by the crease angle θ about the edge direction (Rodrigues' formula), and the neighbour's rows
//! are Q_r,k = E_k + r·R_θ(c_k) for r = 0 … 3 (bicubic across, the face's knots along the edge).
//! Row 0 is the face's edge row, so both faces share the edge exactly; for θ = 0 the neighbour
//! continues the face's cross tangent and the pair is G1 (even C1) across the edge. For θ ≠ 0
//! the tangent planes meet at an angle close to θ along the edge.

use camber_geom::KnotVector;
use nalgebra::{Point3, Rotation3, Unit};

use crate::deform::{Edge, Neighbour};
use crate::errors::Result;
use crate::surface::NurbsSurface;

/// A face and its neighbours, the input of [`crate::deform_to_g1`], with a JSON form.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct DeformationCase {
    /// The face F0 to deform.
    pub face: NurbsSurface<f64>,
    /// Its neighbours.
    pub neighbours: Vec<Neighbour>,
}

/// A bicubic face on an n × n net over the unit square (n ≥ 4) with a gentle bump: control
/// point (i, j) at (x_i, y_j, z) with x_i = i/(n−1), y_j = j/(n−1) and
/// z = 0.08·sin(π x)·(0.5 + y) + 0.03·x·cos(2π y).
///
/// # Errors
/// Knot construction errors for n < 4.
pub fn bumpy_face(n: usize) -> Result<NurbsSurface<f64>> {
    let last = n.saturating_sub(1).max(1) as f64;
    let mut points = Vec::with_capacity(n * n);
    for i in 0..n {
        for j in 0..n {
            let (x, y) = (i as f64 / last, j as f64 / last);
            let pi = std::f64::consts::PI;
            let z = 0.08 * (pi * x).sin() * (0.5 + y) + 0.03 * x * (2.0 * pi * y).cos();
            points.push(Point3::new(x, y, z));
        }
    }
    let k = KnotVector::clamped_uniform(3, n)?;
    NurbsSurface::try_with_unit_weights(3, k.clone(), 3, k, points)
}

/// The neighbour across `edge` of a non-rational `face`, creased by `angle_deg` (module
/// documentation). Its own shared edge is [`Edge::VMin`].
///
/// # Errors
/// Surface construction errors.
pub fn creased_neighbour(
    face: &NurbsSurface<f64>,
    edge: Edge,
    angle_deg: f64,
) -> Result<Neighbour> {
    let (nu, nv) = face.counts();
    let pts = face.control_points();
    let at = |i: usize, j: usize| pts.get(i * nv + j).copied().unwrap_or_else(Point3::origin);
    let (count, (degree_u, degree_v)) = match edge {
        Edge::UMin | Edge::UMax => (nv, face.degrees()),
        Edge::VMin | Edge::VMax => (nu, face.degrees()),
    };
    let (degree, knots) = match edge {
        Edge::UMin | Edge::UMax => (degree_v, face.knots_v().clone()),
        Edge::VMin | Edge::VMax => (degree_u, face.knots_u().clone()),
    };
    let row = |k: usize| -> (Point3<f64>, Point3<f64>) {
        match edge {
            Edge::UMin => (at(0, k), at(1, k)),
            Edge::UMax => (at(nu - 1, k), at(nu.saturating_sub(2), k)),
            Edge::VMin => (at(k, 0), at(k, 1)),
            Edge::VMax => (at(k, nv - 1), at(k, nv.saturating_sub(2))),
        }
    };
    let across = 4;
    let mut points = Vec::with_capacity(count * across);
    for k in 0..count {
        let (e, inner) = row(k);
        let prev = row(k.saturating_sub(1)).0;
        let next = row((k + 1).min(count - 1)).0;
        let c = e - inner;
        let turned = Unit::try_new(next - prev, 1e-300)
            .map(|axis| Rotation3::from_axis_angle(&axis, angle_deg.to_radians()) * c)
            .unwrap_or(c);
        for r in 0..across {
            points.push(e + turned * r as f64);
        }
    }
    let surface = NurbsSurface::try_with_unit_weights(
        degree,
        knots,
        3,
        KnotVector::clamped_uniform(3, across)?,
        points,
    )?;
    Ok(Neighbour {
        surface,
        face_edge: edge,
        neighbour_edge: Edge::VMin,
    })
}

/// The bundled case: two bicubic patches (4 × 4 nets, about unit size) meeting along the face's
/// edge v = 1 with a crease of `angle_deg` degrees.
///
/// ```
/// let (face, nb) = camber_surface::examples::crease_pair(10.0)?;
/// assert_eq!((face.counts(), nb.surface.counts()), ((4, 4), (4, 4)));
/// # Ok::<(), camber_surface::Error>(())
/// ```
///
/// # Errors
/// None in practice (construction errors are passed on).
pub fn crease_pair(angle_deg: f64) -> Result<(NurbsSurface<f64>, Neighbour)> {
    let face = bumpy_face(4)?;
    let nb = creased_neighbour(&face, Edge::VMax, angle_deg)?;
    Ok((face, nb))
}

/// The benchmark case: an n × n bicubic face with creased neighbours on its first `k` edges
/// (k ≤ 4, in the order UMin, UMax, VMin, VMax), creases of 4°, 6°, 8°, 10°.
///
/// # Errors
/// Construction errors for n < 4.
pub fn creased_face(n: usize, k: usize) -> Result<DeformationCase> {
    let face = bumpy_face(n)?;
    let neighbours = Edge::ALL
        .iter()
        .zip([4.0, 6.0, 8.0, 10.0])
        .take(k)
        .map(|(e, a)| creased_neighbour(&face, *e, a))
        .collect::<Result<Vec<_>>>()?;
    Ok(DeformationCase { face, neighbours })
}
