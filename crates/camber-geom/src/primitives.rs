//! Points, lines, segments and circles in the plane.
//!
//! [`Line`] is an infinite line through a point along a direction, [`Segment`] the straight piece
//! between two points and [`Circle`] a circle of positive radius. All three are generic over the
//! scalar `T`, validated on construction (finite coordinates, non-degenerate shape) and offer the
//! elementary metric queries — distances, projections, parameters — that the curve queries in
//! [`crate::queries`] build on. Serde (for `f64`) goes through the same validation:
//! `{"point": [x, y], "direction": [dx, dy]}`, `{"start": …, "end": …}` and
//! `{"center": [x, y], "radius": r}`.

use nalgebra::{Point2, Vector2};
use serde::{de, Deserialize, Deserializer, Serialize, Serializer};

use crate::curve::check_points;
use crate::errors::{Error, Result};
use crate::scalar::{cst, re, Scalar};
use crate::serde_support::{
    point_from_raw, point_to_raw, vector_from_raw, vector_to_raw, RawPoint,
};

/// Checks that both coordinates of a vector are finite.
fn check_vector<T: Scalar>(what: &'static str, v: &Vector2<T>) -> Result<()> {
    for (index, &c) in v.iter().enumerate() {
        if !re(c).is_finite() {
            return Err(Error::NonFinite {
                what,
                index,
                value: re(c),
            });
        }
    }
    Ok(())
}

/// The left normal (−y, x) of a vector: the vector turned a quarter turn counter-clockwise.
fn left_perpendicular<T: Scalar>(v: &Vector2<T>) -> Vector2<T> {
    Vector2::new(-v.y, v.x)
}

/// An infinite line L(s) = P + s·d through a point P along a non-zero direction d.
///
/// The parameter s is measured in units of |d| (s = 1 is one direction vector away from P).
/// "Left" is the side the left normal n = (−d_y, d_x)/|d| points to.
///
/// ```
/// use camber_geom::Line;
/// use nalgebra::{Point2, Vector2};
/// let line = Line::try_new(Point2::new(0.0_f64, 1.0), Vector2::new(2.0, 0.0))?;
/// assert!((line.signed_distance(&Point2::new(5.0, 3.0)) - 2.0).abs() < 1e-15);
/// assert!((line.parameter_of(&Point2::new(5.0, 3.0)) - 2.5).abs() < 1e-15);
/// # Ok::<(), camber_geom::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line<T: Scalar> {
    point: Point2<T>,
    direction: Vector2<T>,
}

/// # Construction
impl<T: Scalar> Line<T> {
    /// The line through `point` along `direction`. Fails with [`Error::NonFinite`] for a
    /// non-finite coordinate and [`Error::ZeroLength`] for a zero direction.
    ///
    /// ```
    /// use camber_geom::{Error, Line};
    /// use nalgebra::{Point2, Vector2};
    /// let err = Line::try_new(Point2::new(0.0, 0.0), Vector2::new(0.0, 0.0)).unwrap_err();
    /// assert_eq!(err, Error::ZeroLength { what: "line direction" });
    /// ```
    pub fn try_new(point: Point2<T>, direction: Vector2<T>) -> Result<Self> {
        check_points(std::slice::from_ref(&point))?;
        check_vector("line direction coordinate", &direction)?;
        if re(direction.norm_squared()) <= 0.0 {
            return Err(Error::ZeroLength {
                what: "line direction",
            });
        }
        Ok(Self { point, direction })
    }

    /// The line through two distinct points, directed from `a` to `b` (L(0) = a, L(1) = b).
    pub fn through(a: Point2<T>, b: Point2<T>) -> Result<Self> {
        Self::try_new(a, b - a)
    }
}

impl<T: Scalar> Line<T> {
    /// The point P the line was built from (L(0)).
    pub fn point(&self) -> &Point2<T> {
        &self.point
    }

    /// The direction vector d as given (not normalised).
    pub fn direction(&self) -> &Vector2<T> {
        &self.direction
    }

    /// The point L(s) = P + s·d.
    pub fn point_at(&self, s: T) -> Point2<T> {
        self.point + self.direction * s
    }

    /// The unit direction d/|d|.
    pub fn unit_direction(&self) -> Vector2<T> {
        self.direction / self.direction.norm()
    }

    /// The unit left normal n = (−d_y, d_x)/|d|.
    pub fn normal(&self) -> Vector2<T> {
        left_perpendicular(&self.unit_direction())
    }

    /// The signed distance (p − P)·n of `p` to the line: positive on the left of the direction,
    /// negative on the right, in length units.
    pub fn signed_distance(&self, p: &Point2<T>) -> T {
        (p - self.point).dot(&self.normal())
    }

    /// The unsigned distance |(p − P)·n| of `p` to the line.
    pub fn distance(&self, p: &Point2<T>) -> T {
        self.signed_distance(p).abs()
    }

    /// The parameter s of the foot point of `p`: s = (p − P)·d/|d|², so that
    /// `point_at(parameter_of(p)) == project(p)`.
    pub fn parameter_of(&self, p: &Point2<T>) -> T {
        (p - self.point).dot(&self.direction) / self.direction.norm_squared()
    }

    /// The foot point of `p`: the point of the line closest to `p`.
    pub fn project(&self, p: &Point2<T>) -> Point2<T> {
        self.point_at(self.parameter_of(p))
    }
}

/// The straight segment S(t) = A + t·(B − A), t ∈ [0, 1], between two distinct points A and B.
///
/// ```
/// use camber_geom::Segment;
/// use nalgebra::Point2;
/// let s = Segment::try_new(Point2::new(0.0_f64, 0.0), Point2::new(4.0, 0.0))?;
/// assert!((s.length() - 4.0).abs() < 1e-15);
/// // Beyond the end, the closest point is the end itself.
/// assert!((s.distance(&Point2::new(7.0, 4.0)) - 5.0).abs() < 1e-15);
/// # Ok::<(), camber_geom::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment<T: Scalar> {
    start: Point2<T>,
    end: Point2<T>,
}

/// # Construction
impl<T: Scalar> Segment<T> {
    /// The segment from `start` to `end`. Fails with [`Error::NonFinite`] for a non-finite
    /// coordinate and [`Error::ZeroLength`] when the two points coincide.
    ///
    /// ```
    /// use camber_geom::{Error, Segment};
    /// use nalgebra::Point2;
    /// let p = Point2::new(1.0, 2.0);
    /// assert_eq!(Segment::try_new(p, p).unwrap_err(), Error::ZeroLength { what: "segment" });
    /// ```
    pub fn try_new(start: Point2<T>, end: Point2<T>) -> Result<Self> {
        check_points(&[start, end])?;
        if re((end - start).norm_squared()) <= 0.0 {
            return Err(Error::ZeroLength { what: "segment" });
        }
        Ok(Self { start, end })
    }
}

impl<T: Scalar> Segment<T> {
    /// The start point A (t = 0).
    pub fn start(&self) -> &Point2<T> {
        &self.start
    }

    /// The end point B (t = 1).
    pub fn end(&self) -> &Point2<T> {
        &self.end
    }

    /// The vector B − A.
    pub fn direction(&self) -> Vector2<T> {
        self.end - self.start
    }

    /// The length |B − A|.
    pub fn length(&self) -> T {
        self.direction().norm()
    }

    /// The point A + t·(B − A). Meant for t ∈ [0, 1]; other values extrapolate along the line.
    pub fn point_at(&self, t: T) -> Point2<T> {
        self.start + self.direction() * t
    }

    /// The parameter t ∈ [0, 1] of the point of the segment closest to `p` (the foot point on
    /// the line, clamped to the segment).
    pub fn closest_parameter(&self, p: &Point2<T>) -> T {
        let d = self.direction();
        let t = (p - self.start).dot(&d) / d.norm_squared();
        if t < T::zero() {
            T::zero()
        } else if t > T::one() {
            T::one()
        } else {
            t
        }
    }

    /// The point of the segment closest to `p`.
    pub fn project(&self, p: &Point2<T>) -> Point2<T> {
        self.point_at(self.closest_parameter(p))
    }

    /// The distance from `p` to the segment (to its closest point, ends included).
    pub fn distance(&self, p: &Point2<T>) -> T {
        (p - self.project(p)).norm()
    }

    /// The infinite line through the segment, L(s) = A + s·(B − A), so that the line and the
    /// segment share their parameter.
    pub fn line(&self) -> Line<T> {
        Line {
            point: self.start,
            direction: self.direction(),
        }
    }
}

/// A circle of centre c and radius r > 0, parameterised counter-clockwise by the angle θ:
/// K(θ) = c + r·(cos θ, sin θ).
///
/// ```
/// use camber_geom::Circle;
/// use nalgebra::Point2;
/// let c = Circle::try_new(Point2::new(1.0_f64, 0.0), 2.0)?;
/// assert!((c.signed_distance(&Point2::new(1.0, 5.0)) - 3.0).abs() < 1e-15);
/// let q = c.project(&Point2::new(1.0, 5.0)).unwrap();
/// assert!((q.x - 1.0).abs() < 1e-15 && (q.y - 2.0).abs() < 1e-15);
/// # Ok::<(), camber_geom::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle<T: Scalar> {
    center: Point2<T>,
    radius: T,
}

/// # Construction
impl<T: Scalar> Circle<T> {
    /// The circle of centre `center` and radius `radius`. Fails with [`Error::NonFinite`] for a
    /// non-finite coordinate or radius and [`Error::NonPositiveRadius`] for r ≤ 0.
    ///
    /// ```
    /// use camber_geom::{Circle, Error};
    /// use nalgebra::Point2;
    /// let err = Circle::try_new(Point2::new(0.0, 0.0), -1.0).unwrap_err();
    /// assert_eq!(err, Error::NonPositiveRadius { value: -1.0 });
    /// ```
    pub fn try_new(center: Point2<T>, radius: T) -> Result<Self> {
        check_points(std::slice::from_ref(&center))?;
        let r = re(radius);
        if !r.is_finite() {
            return Err(Error::NonFinite {
                what: "circle radius",
                index: 0,
                value: r,
            });
        }
        if r <= 0.0 {
            return Err(Error::NonPositiveRadius { value: r });
        }
        Ok(Self { center, radius })
    }
}

impl<T: Scalar> Circle<T> {
    /// The centre c.
    pub fn center(&self) -> &Point2<T> {
        &self.center
    }

    /// The radius r (> 0).
    pub fn radius(&self) -> T {
        self.radius
    }

    /// The point c + r·(cos θ, sin θ) at angle θ (radians, counter-clockwise from +x).
    pub fn point_at(&self, angle: T) -> Point2<T> {
        self.center + Vector2::new(angle.cos(), angle.sin()) * self.radius
    }

    /// The unit tangent (−sin θ, cos θ) at angle θ, pointing counter-clockwise.
    pub fn tangent_at(&self, angle: T) -> Vector2<T> {
        Vector2::new(-angle.sin(), angle.cos())
    }

    /// The angle θ ∈ (−π, π] of `p` seen from the centre, or `None` at the centre itself.
    pub fn angle_of(&self, p: &Point2<T>) -> Option<T> {
        let w = p - self.center;
        if re(w.norm_squared()) <= 0.0 {
            return None;
        }
        Some(w.y.atan2(w.x))
    }

    /// The signed distance |p − c| − r: negative inside, zero on the circle, positive outside.
    pub fn signed_distance(&self, p: &Point2<T>) -> T {
        (p - self.center).norm() - self.radius
    }

    /// The unsigned distance ||p − c| − r| from `p` to the circle.
    pub fn distance(&self, p: &Point2<T>) -> T {
        self.signed_distance(p).abs()
    }

    /// The point of the circle closest to `p`, c + r·(p − c)/|p − c|, or `None` when `p` is the
    /// centre (every point of the circle is then equally close).
    pub fn project(&self, p: &Point2<T>) -> Option<Point2<T>> {
        let w = p - self.center;
        let norm = w.norm();
        if re(norm) <= 0.0 {
            return None;
        }
        Some(self.center + w * (self.radius / norm))
    }

    /// Whether `p` lies in the closed disk |p − c| ≤ r.
    pub fn contains(&self, p: &Point2<T>) -> bool {
        (p - self.center).norm_squared() <= self.radius * self.radius
    }

    /// The circumference 2πr.
    pub fn circumference(&self) -> T {
        cst::<T>(std::f64::consts::TAU) * self.radius
    }
}

// ---------------------------------------------------------------------------------------------
// Serde (f64 only), validated through `try_new`.

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawLine {
    point: RawPoint,
    direction: RawPoint,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSegment {
    start: RawPoint,
    end: RawPoint,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCircle {
    center: RawPoint,
    radius: f64,
}

impl Serialize for Line<f64> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        RawLine {
            point: point_to_raw(&self.point),
            direction: vector_to_raw(&self.direction),
        }
        .serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Line<f64> {
    fn deserialize<De: Deserializer<'de>>(
        deserializer: De,
    ) -> std::result::Result<Self, De::Error> {
        let raw = RawLine::deserialize(deserializer)?;
        let point = point_from_raw::<2>(&raw.point, 0).map_err(de::Error::custom)?;
        let direction = vector_from_raw::<2>(&raw.direction, 1).map_err(de::Error::custom)?;
        Self::try_new(point, direction).map_err(de::Error::custom)
    }
}

impl Serialize for Segment<f64> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        RawSegment {
            start: point_to_raw(&self.start),
            end: point_to_raw(&self.end),
        }
        .serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Segment<f64> {
    fn deserialize<De: Deserializer<'de>>(
        deserializer: De,
    ) -> std::result::Result<Self, De::Error> {
        let raw = RawSegment::deserialize(deserializer)?;
        let start = point_from_raw::<2>(&raw.start, 0).map_err(de::Error::custom)?;
        let end = point_from_raw::<2>(&raw.end, 1).map_err(de::Error::custom)?;
        Self::try_new(start, end).map_err(de::Error::custom)
    }
}

impl Serialize for Circle<f64> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        RawCircle {
            center: point_to_raw(&self.center),
            radius: self.radius,
        }
        .serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Circle<f64> {
    fn deserialize<De: Deserializer<'de>>(
        deserializer: De,
    ) -> std::result::Result<Self, De::Error> {
        let raw = RawCircle::deserialize(deserializer)?;
        let center = point_from_raw::<2>(&raw.center, 0).map_err(de::Error::custom)?;
        Self::try_new(center, raw.radius).map_err(de::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn line_queries_by_hand() {
        // The line y = x through (1, 1), direction (2, 2): unit normal (−1, 1)/√2.
        let line = Line::try_new(Point2::new(1.0, 1.0), Vector2::new(2.0, 2.0)).unwrap();
        let p = Point2::new(0.0, 2.0);
        assert_relative_eq!(line.signed_distance(&p), 2.0_f64.sqrt(), epsilon = 1e-15);
        assert_relative_eq!(
            line.signed_distance(&Point2::new(2.0, 0.0)),
            -(2.0_f64.sqrt())
        );
        let foot = line.project(&p);
        assert_relative_eq!(foot, Point2::new(1.0, 1.0), epsilon = 1e-15);
        assert_relative_eq!(line.parameter_of(&Point2::new(3.0, 3.0)), 1.0);
        assert_relative_eq!(line.point_at(-0.5), Point2::new(0.0, 0.0));
        assert_relative_eq!(line.normal(), Vector2::new(-1.0, 1.0) / 2.0_f64.sqrt());
        let through = Line::through(Point2::new(1.0, 1.0), Point2::new(3.0, 3.0)).unwrap();
        assert_eq!(through, line);
    }

    #[test]
    fn line_rejects_bad_input() {
        let err = Line::try_new(Point2::new(0.0, f64::NAN), Vector2::new(1.0, 0.0)).unwrap_err();
        assert!(matches!(err, Error::NonFinite { index: 0, .. }));
        let err = Line::try_new(Point2::new(0.0, 0.0), Vector2::new(1.0, f64::INFINITY));
        assert!(matches!(
            err,
            Err(Error::NonFinite {
                what: "line direction coordinate",
                index: 1,
                ..
            })
        ));
    }

    #[test]
    fn segment_projection_is_clamped() {
        let s = Segment::try_new(Point2::new(0.0, 0.0), Point2::new(2.0, 0.0)).unwrap();
        assert_relative_eq!(s.closest_parameter(&Point2::new(1.5, 3.0)), 0.75);
        assert_relative_eq!(s.closest_parameter(&Point2::new(-1.0, 3.0)), 0.0);
        assert_relative_eq!(s.project(&Point2::new(5.0, -4.0)), Point2::new(2.0, 0.0));
        assert_relative_eq!(s.distance(&Point2::new(1.0, -3.0)), 3.0);
        assert_relative_eq!(s.distance(&Point2::new(-3.0, 4.0)), 5.0);
        assert_relative_eq!(s.point_at(0.25), Point2::new(0.5, 0.0));
        let line = s.line();
        assert_relative_eq!(line.point_at(0.25), s.point_at(0.25));
        assert_relative_eq!(s.length(), 2.0);
    }

    #[test]
    fn circle_queries_by_hand() {
        let c = Circle::try_new(Point2::new(1.0, -1.0), 2.0).unwrap();
        let quarter = std::f64::consts::FRAC_PI_2;
        assert_relative_eq!(c.point_at(quarter), Point2::new(1.0, 1.0), epsilon = 1e-15);
        assert_relative_eq!(c.tangent_at(0.0), Vector2::new(0.0, 1.0));
        assert_relative_eq!(
            c.tangent_at(quarter),
            Vector2::new(-1.0, 0.0),
            epsilon = 1e-15
        );
        // (4, 3): |p − c| = 5.
        let p = Point2::new(4.0, 3.0);
        assert_relative_eq!(c.signed_distance(&p), 3.0);
        assert_relative_eq!(c.signed_distance(&Point2::new(1.0, -0.5)), -1.5);
        assert_relative_eq!(
            c.project(&p).unwrap(),
            Point2::new(2.2, 0.6),
            epsilon = 1e-15
        );
        assert!(c.project(&Point2::new(1.0, -1.0)).is_none());
        assert!(c.contains(&Point2::new(2.0, 0.0)));
        assert!(c.contains(&Point2::new(3.0, -1.0)));
        assert!(!c.contains(&p));
        assert_relative_eq!(c.angle_of(&Point2::new(1.0, 5.0)).unwrap(), quarter);
        assert_relative_eq!(c.circumference(), 4.0 * std::f64::consts::PI);
        assert_eq!(
            Circle::try_new(Point2::new(0.0, 0.0), 0.0),
            Err(Error::NonPositiveRadius { value: 0.0 })
        );
    }

    #[test]
    fn serde_round_trips_and_validates() {
        let line = Line::try_new(Point2::new(1.0, 2.0), Vector2::new(0.0, -1.0)).unwrap();
        let json = serde_json::to_string(&line).unwrap();
        assert_eq!(json, r#"{"point":[1.0,2.0],"direction":[0.0,-1.0]}"#);
        assert_eq!(serde_json::from_str::<Line<f64>>(&json).unwrap(), line);
        assert!(serde_json::from_str::<Line<f64>>(r#"{"point":[0,0],"direction":[0,0]}"#).is_err());

        let seg = Segment::try_new(Point2::new(0.0, 0.0), Point2::new(1.0, 1.0)).unwrap();
        let json = serde_json::to_string(&seg).unwrap();
        assert_eq!(json, r#"{"start":[0.0,0.0],"end":[1.0,1.0]}"#);
        assert_eq!(serde_json::from_str::<Segment<f64>>(&json).unwrap(), seg);
        assert!(serde_json::from_str::<Segment<f64>>(r#"{"start":[1,1],"end":[1,1]}"#).is_err());
        assert!(serde_json::from_str::<Segment<f64>>(r#"{"start":[1],"end":[1,1]}"#).is_err());

        let circle = Circle::try_new(Point2::new(0.5, 0.0), 3.0).unwrap();
        let json = serde_json::to_string(&circle).unwrap();
        assert_eq!(json, r#"{"center":[0.5,0.0],"radius":3.0}"#);
        assert_eq!(serde_json::from_str::<Circle<f64>>(&json).unwrap(), circle);
        assert!(serde_json::from_str::<Circle<f64>>(r#"{"center":[0,0],"radius":-2}"#).is_err());
    }

    #[test]
    fn dual_numbers_carry_derivatives() {
        use num_dual::Dual64;
        // d/dy of the signed distance of (0, y) to the x axis is 1.
        let line = Line::try_new(
            Point2::new(Dual64::from(0.0), Dual64::from(0.0)),
            Vector2::new(Dual64::from(1.0), Dual64::from(0.0)),
        )
        .unwrap();
        let p = Point2::new(Dual64::from(0.0), Dual64::from(2.0).derivative());
        let d = line.signed_distance(&p);
        assert_relative_eq!(d.re, 2.0);
        assert_relative_eq!(d.eps, 1.0);
    }
}
