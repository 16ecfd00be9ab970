//! The two-curve sketch of the seed's demo: two cubics held tangent to circles, to lines and
//! to each other (at contact parameters that are unknowns), with its own validity check.

use camber_geom::BezierCurve2;
use nalgebra::{Point2, Vector2};

use super::cross;
use camber_sketch::constraints::{CurveCurveTangent, Fixed, TangentToCircle, TangentToLine};
use camber_sketch::vocabulary::{CircleSide, Contact, LineSide, Rotation, Sense};
use camber_sketch::Entity;
use camber_sketch::EntityId;
use camber_sketch::Result;
use camber_sketch::Sketch;

/// The entities of the two-curve sketch ([`two_curves`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TwoCurves {
    /// The lower cubic, an arch from the inlet line to the right circle.
    pub lower: EntityId,
    /// The upper cubic, a valley from the left circle to the outlet line.
    pub upper: EntityId,
    /// The inlet line, along which the lower curve leaves (fixed).
    pub inlet: EntityId,
    /// The outlet line, along which the upper curve arrives (fixed).
    pub outlet: EntityId,
    /// The circle the upper curve leaves from (fixed).
    pub left: EntityId,
    /// The circle the lower curve arrives on (fixed).
    pub right: EntityId,
}

/// The centre and radius of the two-curve sketch's left and right circles.
pub const TWO_CURVES_CIRCLES: [([f64; 2], f64); 2] =
    [([0.219, 2.705], 0.3), ([3.795, -0.219], 0.3)];

/// The two-curve sketch at its rough start: two cubic Béziers held tangent to circles, to
/// lines and to each other. The lower curve, an arch from (0, 0) to (4, 0), leaves along the
/// inlet line (tangent to it at u = 0, curving to its right) and arrives on the right circle
/// (tangent at u = 1, outside, clockwise); the upper curve, a valley from (0, 2.5) to
/// (4, 2.5), leaves from the left circle (tangent at u = 0, outside, counter-clockwise) and
/// arrives along the outlet line (tangent at u = 1, curving to its left). The arch and the
/// valley start 0.25 apart and must touch, with parallel tangents running the same way, at
/// parameters that are unknowns. Lines and circles are fixed: 16 control-point coordinates
/// and 2 contact parameters against 11 rows, 7 DOF.
///
/// ```
/// let (mut s, t) = camber_workloads::two_curves()?;
/// assert!(!camber_workloads::two_curves_valid(&s, &t, 1e-6));
/// s.solve()?;
/// assert!(camber_workloads::two_curves_valid(&s, &t, 1e-6));
/// # Ok::<(), camber_sketch::Error>(())
/// ```
///
/// # Errors
/// None in practice (the data are valid); the signature carries the sketch's errors.
pub fn two_curves() -> Result<(Sketch, TwoCurves)> {
    let pts = |v: &[(f64, f64)]| v.iter().map(|(x, y)| Point2::new(*x, *y)).collect();
    let mut s = Sketch::new();
    let lower = s.add_bezier(BezierCurve2::try_new(pts(&[
        (0.0, 0.0),
        (1.5, 1.4),
        (2.5, 1.4),
        (4.0, 0.0),
    ]))?)?;
    let upper = s.add_bezier(BezierCurve2::try_new(pts(&[
        (0.0, 2.5),
        (1.5, 0.9),
        (2.5, 0.9),
        (4.0, 2.5),
    ]))?)?;
    let inlet = s.add_line(Point2::new(-1.5, -1.4), Point2::new(0.0, 0.0))?;
    let outlet = s.add_line(Point2::new(4.0, 2.5), Point2::new(5.5, 4.1))?;
    let [(lc, lr), (rc, rr)] = TWO_CURVES_CIRCLES;
    let left = s.add_circle(Point2::new(lc[0], lc[1]), lr)?;
    let right = s.add_circle(Point2::new(rc[0], rc[1]), rr)?;
    for e in [inlet, outlet, left, right] {
        s.add_constraint(Fixed::entity(e))?;
    }
    s.add_constraint(TangentToLine {
        curve: lower,
        line: inlet,
        u: Contact::At(0.0),
        side: LineSide::Right,
        sense: Sense::Agree,
    })?;
    s.add_constraint(TangentToCircle {
        curve: lower,
        circle: right,
        u: Contact::At(1.0),
        side: CircleSide::Outside,
        rotation: Rotation::Clockwise,
    })?;
    s.add_constraint(TangentToCircle {
        curve: upper,
        circle: left,
        u: Contact::At(0.0),
        side: CircleSide::Outside,
        rotation: Rotation::CounterClockwise,
    })?;
    s.add_constraint(TangentToLine {
        curve: upper,
        line: outlet,
        u: Contact::At(1.0),
        side: LineSide::Left,
        sense: Sense::Agree,
    })?;
    s.add_constraint(CurveCurveTangent {
        first: lower,
        u: Contact::Free(0.5),
        second: upper,
        v: Contact::Free(0.5),
        sense: Sense::Agree,
    })?;
    Ok((
        s,
        TwoCurves {
            lower,
            upper,
            inlet,
            outlet,
            left,
            right,
        },
    ))
}

/// The two-curve validity check, independent of the solver (tolerance `tol`): the lower
/// curve starts on the inlet line running along it, and ends on the right circle with its
/// tangent perpendicular to the radius; the upper curve starts on the left circle likewise and
/// ends on the outlet line running along it; neither curve comes inside a circle (least
/// distance from each centre at least the radius); and the two curves touch: their least
/// distance is at most `tol`, and at the nearest point of the lower curve to the upper the
/// tangents are parallel and run the same way. Lines and circles are read from the sketch and
/// must still be where [`two_curves`] put them.
pub fn two_curves_valid(s: &Sketch, t: &TwoCurves, tol: f64) -> bool {
    two_curves_check(s, t, tol).unwrap_or(false)
}

/// [`two_curves_valid`] with the lookups' errors.
fn two_curves_check(s: &Sketch, t: &TwoCurves, tol: f64) -> Result<bool> {
    use camber_geom::ParametricCurve;
    let (Entity::Bezier(lower), Entity::Bezier(upper)) = (s.entity(t.lower)?, s.entity(t.upper)?)
    else {
        return Ok(false);
    };
    let unit_sin = |a: Vector2<f64>, b: Vector2<f64>| cross(a, b) / (a.norm() * b.norm());
    // Along a line: on it and parallel to it, the same way.
    let along_line = |line: EntityId, p: Point2<f64>, d: Vector2<f64>| -> Result<bool> {
        let Entity::Line([a, b]) = s.entity(line)? else {
            return Ok(false);
        };
        let dir = b - a;
        Ok(cross(p - a, dir).abs() <= tol * dir.norm()
            && unit_sin(d, dir).abs() <= tol
            && d.dot(&dir) > 0.0)
    };
    let on_circle = |k: usize, p: Point2<f64>, d: Vector2<f64>| {
        let (c, r) = TWO_CURVES_CIRCLES[k];
        let v = p - Point2::new(c[0], c[1]);
        (v.norm() - r).abs() <= tol && (v.dot(&d) / (v.norm() * d.norm())).abs() <= tol
    };
    let (l0, dl0) = lower.point_and_derivative(0.0)?;
    let (l1, dl1) = lower.point_and_derivative(1.0)?;
    let (u0, du0) = upper.point_and_derivative(0.0)?;
    let (u1, du1) = upper.point_and_derivative(1.0)?;
    if !(along_line(t.inlet, l0, dl0)?
        && on_circle(1, l1, dl1)
        && on_circle(0, u0, du0)
        && along_line(t.outlet, u1, du1)?)
    {
        return Ok(false);
    }
    for (k, circle) in [t.left, t.right].into_iter().enumerate() {
        let (c, r) = TWO_CURVES_CIRCLES[k];
        let Entity::Circle { center, radius } = s.entity(circle)? else {
            return Ok(false);
        };
        if (center - Point2::new(c[0], c[1])).norm() > tol || (radius - r).abs() > tol {
            return Ok(false);
        }
        for curve in [lower, upper] {
            let near = camber_geom::queries::closest_point(curve, center)?;
            if near.distance < r - tol {
                return Ok(false);
            }
        }
    }
    // The touch: the distance from lower(u) to the upper curve, sampled in u and then
    // narrowed by golden-section search around the best sample.
    let gap_at = |u: f64| -> Result<(f64, f64)> {
        let near = camber_geom::queries::closest_point(upper, &lower.point(u)?)?;
        Ok((near.distance, near.parameter))
    };
    let mut best = (f64::INFINITY, 0.0);
    for i in 0..=200 {
        let u = f64::from(i) / 200.0;
        let (d, _) = gap_at(u)?;
        if d < best.0 {
            best = (d, u);
        }
    }
    let (mut a, mut b) = ((best.1 - 0.005).max(0.0), (best.1 + 0.005).min(1.0));
    let r = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..80 {
        let (c, d) = (b - r * (b - a), a + r * (b - a));
        if gap_at(c)?.0 < gap_at(d)?.0 {
            b = d;
        } else {
            a = c;
        }
    }
    let u = 0.5 * (a + b);
    let (gap, v) = gap_at(u)?;
    let (_, ta) = lower.point_and_derivative(u)?;
    let (_, tb) = upper.point_and_derivative(v)?;
    Ok(gap <= tol && unit_sin(ta, tb).abs() <= 1e-3 && ta.dot(&tb) > 0.0)
}
