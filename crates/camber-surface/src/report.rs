//! What a deformation achieved: normal angles along each shared edge before and after, the
//! boundary deviation, the control-point movement and the refinement rounds.
//!
//! The angle between two faces at an edge point is the angle between their tangent planes,
//! θ = atan2(|n₀ × n₁|, |n₀ · n₁|) ∈ [0°, 90°] for unit normals n₀, n₁: it does not depend on
//! how either face is oriented, and it is accurate for small angles (unlike acos).

use camber_solve::LsqReport;
use nalgebra::Vector3;

use crate::deform::Edge;

/// The angle in degrees between the planes with normals `a` and `b` (any lengths > 0).
///
/// ```
/// use nalgebra::Vector3;
/// let deg = camber_surface::plane_angle_deg(&Vector3::z(), &Vector3::new(0.0, 1.0, -1.0));
/// assert!((deg - 45.0).abs() < 1e-12);
/// ```
pub fn plane_angle_deg(a: &Vector3<f64>, b: &Vector3<f64>) -> f64 {
    a.cross(b).norm().atan2(a.dot(b).abs()).to_degrees()
}

/// Normal angles along one shared edge, at the continuity samples.
#[derive(Debug, Clone, PartialEq)]
pub struct EdgeReport {
    /// Index of the neighbour in the list given to the deformation.
    pub neighbour: usize,
    /// The face's edge it shares.
    pub edge: Edge,
    /// The samples' parameter along the edge (u for `VMin`/`VMax`, v for `UMin`/`UMax`).
    pub parameters: Vec<f64>,
    /// Angle between the face's and the neighbour's tangent planes before, in degrees.
    pub angles_before_deg: Vec<f64>,
    /// The same after the deformation.
    pub angles_after_deg: Vec<f64>,
}

impl EdgeReport {
    /// Largest angle before, in degrees (0 without samples).
    pub fn max_before_deg(&self) -> f64 {
        max(&self.angles_before_deg)
    }

    /// Mean angle before, in degrees (0 without samples).
    pub fn mean_before_deg(&self) -> f64 {
        mean(&self.angles_before_deg)
    }

    /// Largest angle after, in degrees.
    pub fn max_after_deg(&self) -> f64 {
        max(&self.angles_after_deg)
    }

    /// Mean angle after, in degrees.
    pub fn mean_after_deg(&self) -> f64 {
        mean(&self.angles_after_deg)
    }
}

/// The outcome of [`crate::deform_to_g1`]. Missing a tolerance after the last refinement round
/// is reported here (`met_tolerances = false`), not as an error.
#[derive(Debug, Clone, PartialEq)]
pub struct DeformationReport {
    /// One entry per neighbour.
    pub edges: Vec<EdgeReport>,
    /// Largest movement |S_new(w) − S_old(w)| of a boundary sample, in model units.
    pub max_boundary_deviation: f64,
    /// The size used for relative measures: the diagonal of the initial control box.
    pub size: f64,
    /// Largest movement of a control point (against the initial surface refined by the same
    /// knots, which is the same geometry), in model units.
    pub max_control_point_movement: f64,
    /// Refinement rounds used (0 when the first solve met the tolerances).
    pub refinement_rounds: usize,
    /// Knots inserted over all rounds.
    pub knots_inserted: usize,
    /// Whether the largest angle and the boundary deviation are within the tolerances.
    pub met_tolerances: bool,
    /// The least-squares report of the last solve.
    pub solve: LsqReport,
}

impl DeformationReport {
    /// The largest angle after deformation over every edge, in degrees.
    pub fn max_angle_after_deg(&self) -> f64 {
        self.edges
            .iter()
            .map(EdgeReport::max_after_deg)
            .fold(0.0, f64::max)
    }

    /// The largest angle before deformation over every edge, in degrees.
    pub fn max_angle_before_deg(&self) -> f64 {
        self.edges
            .iter()
            .map(EdgeReport::max_before_deg)
            .fold(0.0, f64::max)
    }
}

fn max(v: &[f64]) -> f64 {
    v.iter().copied().fold(0.0, f64::max)
}

fn mean(v: &[f64]) -> f64 {
    if v.is_empty() {
        0.0
    } else {
        v.iter().sum::<f64>() / v.len() as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn plane_angles_ignore_orientation() {
        let a = Vector3::new(0.0, 0.0, 2.0);
        let tilt = 10.0_f64.to_radians();
        let b = Vector3::new(0.0, tilt.sin(), tilt.cos());
        assert_relative_eq!(plane_angle_deg(&a, &b), 10.0, epsilon = 1e-12);
        assert_relative_eq!(plane_angle_deg(&a, &-b), 10.0, epsilon = 1e-12);
        let r = EdgeReport {
            neighbour: 0,
            edge: Edge::VMax,
            parameters: vec![0.0, 1.0],
            angles_before_deg: vec![1.0, 3.0],
            angles_after_deg: vec![],
        };
        assert_relative_eq!(r.mean_before_deg(), 2.0);
        assert_relative_eq!(r.max_before_deg(), 3.0);
        assert_relative_eq!(r.max_after_deg(), 0.0);
    }
}
