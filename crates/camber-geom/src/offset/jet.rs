//! The exact offset point and its first two derivatives, from the curve's first three.
//!
//! With v = C′, s = |v|, the unit tangent t = v/s and the left normal n = J·t (J turns a
//! vector a quarter turn counter-clockwise, J(x, y) = (−y, x)), the offset is
//! O = C + d·n, so O′ = C′ + d·J·t′ and O″ = C″ + d·J·t″, where, with a = C″ and w = C‴,
//!
//! t′ = (a − t(t·a))/s,
//! t″ = (w − t′(t·a) − t(t′·a + t·w))/s − t′(t·a)/s
//!
//! (the second from differentiating s·t′ = a − t(t·a) and s′ = t·a).

use nalgebra::{Point2, SVector, Vector2};

use crate::curve::ParametricCurve;
use crate::errors::{Error, Result};
use crate::scalar::{re, Scalar};

/// The offset O(u), O′(u) and O″(u) (derivatives with respect to the curve's parameter u)
/// at signed `distance`, read from the derivatives of `curve` at `u` (its right-hand limits
/// at a breakpoint).
///
/// Errors: [`Error::ZeroLength`] where the curve has no tangent, and the curve's evaluation
/// errors.
pub(crate) fn offset_jet<T, C>(
    curve: &C,
    distance: T,
    u: T,
) -> Result<(Point2<T>, Vector2<T>, Vector2<T>)>
where
    T: Scalar,
    C: ParametricCurve<T, 2> + ?Sized,
{
    let mut d = [SVector::<T, 2>::zeros(); 4];
    curve.derivatives_into(u, &mut d)?;
    let [c, v, a, w] = d;
    let s = v.norm();
    if re(s) <= 0.0 {
        return Err(Error::ZeroLength {
            what: "tangent of the curve to offset",
        });
    }
    let turn = |x: Vector2<T>| Vector2::new(-x.y, x.x);
    let t = v / s;
    let ta = t.dot(&a);
    let t1 = (a - t * ta) / s;
    let t2 = (w - t1 * ta - t * (t1.dot(&a) + t.dot(&w))) / s - t1 * (ta / s);
    Ok((
        Point2::from(c + turn(t) * distance),
        v + turn(t1) * distance,
        a + turn(t2) * distance,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{BSplineCurve2, KnotVector};

    fn wave() -> BSplineCurve2<f64> {
        let points = (0..9)
            .map(|i| {
                let x = f64::from(i) * 0.4;
                Point2::new(x, (1.3 * x).sin() + 0.3 * (3.1 * x).cos())
            })
            .collect();
        BSplineCurve2::try_new(3, KnotVector::clamped_uniform(3, 9).unwrap(), points).unwrap()
    }

    #[test]
    fn derivatives_match_central_differences_of_the_offset_point() {
        let c = wave();
        let d = 0.15;
        let h = 1e-5;
        for &u in &[0.13, 0.37, 0.52, 0.81] {
            let (o, o1, o2) = offset_jet(&c, d, u).unwrap();
            let (m, m1, _) = offset_jet(&c, d, u - h).unwrap();
            let (p, p1, _) = offset_jet(&c, d, u + h).unwrap();
            assert!((o - (p.coords + m.coords) / 2.0).coords.norm() < 1e-8);
            let fd1 = (p - m) / (2.0 * h);
            assert!(
                (fd1 - o1).norm() < 1e-6 * (1.0 + o1.norm()),
                "{fd1} vs {o1}"
            );
            let fd2 = (p1 - m1) / (2.0 * h);
            assert!(
                (fd2 - o2).norm() < 1e-5 * (1.0 + o2.norm()),
                "{fd2} vs {o2}"
            );
        }
    }

    #[test]
    fn a_circle_offset_has_the_scaled_derivatives() {
        // C(u) = (cos u, sin u): n = −C (left of counter-clockwise travel is inwards), so
        // O = (1 − d)C, O′ = (1 − d)C′, O″ = (1 − d)C″.
        struct Circle;
        impl ParametricCurve<f64, 2> for Circle {
            fn domain(&self) -> (f64, f64) {
                (0.0, 6.0)
            }
            fn derivatives_into(&self, u: f64, out: &mut [SVector<f64, 2>]) -> Result<()> {
                let (s, c) = u.sin_cos();
                let all = [
                    Vector2::new(c, s),
                    Vector2::new(-s, c),
                    Vector2::new(-c, -s),
                    Vector2::new(s, -c),
                ];
                for (o, v) in out.iter_mut().zip(all) {
                    *o = v;
                }
                Ok(())
            }
        }
        let (o, o1, o2) = offset_jet(&Circle, 0.25, 0.7).unwrap();
        let (s, c) = 0.7_f64.sin_cos();
        assert!((o - Point2::new(0.75 * c, 0.75 * s)).norm() < 1e-15);
        assert!((o1 - Vector2::new(-0.75 * s, 0.75 * c)).norm() < 1e-15);
        assert!((o2 - Vector2::new(-0.75 * c, -0.75 * s)).norm() < 1e-15);
    }
}
