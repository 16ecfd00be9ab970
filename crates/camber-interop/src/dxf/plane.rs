//! The sketch plane of a DXF entity: which entities lie in a plane parallel to XY, and how
//! the object coordinates of a planar entity (ARC, CIRCLE, LWPOLYLINE) map to world x, y.
//!
//! An entity's extrusion direction N fixes its object coordinate system. For N = +Z the object
//! axes are the world's. For N = −Z the arbitrary-axis rule gives the object x axis
//! Wy × N = (−1, 0, 0) and the y axis N × x = (0, 1, 0): object (x, y) is world (−x, y), a
//! mirror, so counter-clockwise in object coordinates is clockwise in the world. Any other N
//! tilts the entity out of the sketch plane.

/// How far a unit extrusion direction may lean from ±Z and still count as ±Z.
const AXIS_TOLERANCE: f64 = 1e-12;

/// The two object coordinate systems of entities in the XY plane.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Facing {
    /// N = +Z: object coordinates are world coordinates.
    Up,
    /// N = −Z: object (x, y) is world (−x, y).
    Down,
}

impl Facing {
    /// The facing of an extrusion direction, `None` when it is not ±Z (or not finite).
    pub(super) fn of(n: &dxf::Vector) -> Option<Facing> {
        let len = (n.x * n.x + n.y * n.y + n.z * n.z).sqrt();
        if !(len.is_finite() && len > 0.0) {
            return None;
        }
        let (x, y, z) = (n.x / len, n.y / len, n.z / len);
        if x.abs() > AXIS_TOLERANCE || y.abs() > AXIS_TOLERANCE {
            return None;
        }
        if z > 0.0 {
            Some(Facing::Up)
        } else {
            Some(Facing::Down)
        }
    }

    /// World x of object x.
    pub(super) fn x(self, x: f64) -> f64 {
        match self {
            Facing::Up => x,
            Facing::Down => -x,
        }
    }

    /// The world angle (radians) of the object direction at angle `a` (radians): a mirror in
    /// x turns a into π − a.
    pub(super) fn angle(self, a: f64) -> f64 {
        match self {
            Facing::Up => a,
            Facing::Down => std::f64::consts::PI - a,
        }
    }
}

/// The common z of `zs`, `None` when they differ (exactly: points of one plane carry one z).
#[allow(clippy::float_cmp)]
pub(super) fn common_z(zs: impl IntoIterator<Item = f64>) -> Option<f64> {
    let mut zs = zs.into_iter();
    let first = zs.next()?;
    zs.all(|z| z == first).then_some(first)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64, z: f64) -> dxf::Vector {
        dxf::Vector::new(x, y, z)
    }

    #[test]
    fn the_z_axes_face_up_and_down_and_others_are_refused() {
        assert_eq!(Facing::of(&v(0.0, 0.0, 1.0)), Some(Facing::Up));
        assert_eq!(Facing::of(&v(0.0, 0.0, 3.0)), Some(Facing::Up));
        assert_eq!(Facing::of(&v(0.0, 0.0, -1.0)), Some(Facing::Down));
        assert_eq!(Facing::of(&v(0.0, 1.0, 0.0)), None);
        assert_eq!(Facing::of(&v(0.1, 0.0, 1.0)), None);
        assert_eq!(Facing::of(&v(0.0, 0.0, 0.0)), None);
        assert_eq!(Facing::of(&v(f64::NAN, 0.0, 1.0)), None);
    }

    #[test]
    fn facing_down_mirrors_x_and_angles() {
        // Object direction at 30° is (cos 30°, sin 30°); mirrored it is (−cos 30°, sin 30°),
        // the world direction at 150°.
        let a = 30f64.to_radians();
        let w = Facing::Down.angle(a);
        assert!((w.cos() - Facing::Down.x(a.cos())).abs() < 1e-15);
        assert!((w.sin() - a.sin()).abs() < 1e-15);
        assert!((Facing::Up.angle(a) - a).abs() <= 0.0);
    }

    #[test]
    fn a_common_z_is_found_only_when_all_agree() {
        assert_eq!(common_z([2.0, 2.0, 2.0]), Some(2.0));
        assert_eq!(common_z([0.0, 1e-12]), None);
        assert_eq!(common_z(std::iter::empty()), None);
    }
}
