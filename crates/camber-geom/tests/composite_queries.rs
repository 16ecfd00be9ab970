//! Curve–curve queries on camber-geom's own composite curves (pieces of any kind, including a
//! piece known only through evaluation, which the queries enclose by sampling): hand-derived
//! crossings with line-like Béziers and a circle NURBS, a closest pair and an overlap by hand,
//! and random composites against a second method (the same query piece by piece).

// Test helpers outside #[test] functions unwrap too; a failed unwrap is a failed test.
#![allow(clippy::unwrap_used)]

use camber_geom::curve::check_parameter;
use camber_geom::queries::{
    closest_point, curve_distance, intersect_curves, intersect_curves_with_overlaps,
    sampled_pieces, CurveCurveOptions, CurvePairPoint,
};
use camber_geom::{
    BezierCurve2, CompositeCurve, CompositeCurve2, KnotVector, NurbsCurve2, ParametricCurve,
    Result, Segment,
};
use nalgebra::{Point2, SVector};
use proptest::prelude::*;

fn opts() -> CurveCurveOptions {
    CurveCurveOptions::default()
}

/// C(u) = Σ_k c_k u^k on [0, 1], known to the kernel only through evaluation (no Bézier form).
struct Poly(Vec<SVector<f64, 2>>);

impl ParametricCurve<f64, 2> for Poly {
    fn domain(&self) -> (f64, f64) {
        (0.0, 1.0)
    }

    fn derivatives_into(&self, u: f64, out: &mut [SVector<f64, 2>]) -> Result<()> {
        check_parameter(u, (0.0, 1.0))?;
        for (k, o) in out.iter_mut().enumerate() {
            *o = SVector::zeros();
            for (j, c) in self.0.iter().enumerate().skip(k) {
                let falling: f64 = (j - k + 1..=j).map(|m| m as f64).product();
                *o += c * (falling * u.powi((j - k) as i32));
            }
        }
        Ok(())
    }
}

fn p(x: f64, y: f64) -> Point2<f64> {
    Point2::new(x, y)
}

fn bezier(points: &[(f64, f64)]) -> BezierCurve2<f64> {
    BezierCurve2::try_new(points.iter().map(|&(x, y)| p(x, y)).collect()).unwrap()
}

/// The quarter of the circle about (0, 1) of radius 1 from (0, 0) to (1, 1), as a NURBS.
fn quarter_arc() -> NurbsCurve2<f64> {
    let w = std::f64::consts::FRAC_1_SQRT_2;
    NurbsCurve2::try_new(
        2,
        KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]).unwrap(),
        vec![p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0)],
        vec![1.0, w, 1.0],
    )
    .unwrap()
}

/// The full circle about `c` of radius `r` as a rational quadratic NURBS of nine points.
fn circle_nurbs(c: (f64, f64), r: f64) -> NurbsCurve2<f64> {
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let dirs = [
        (1.0, 0.0),
        (1.0, 1.0),
        (0.0, 1.0),
        (-1.0, 1.0),
        (-1.0, 0.0),
        (-1.0, -1.0),
        (0.0, -1.0),
        (1.0, -1.0),
        (1.0, 0.0),
    ];
    let points = dirs
        .iter()
        .map(|&(x, y)| p(c.0 + r * x, c.1 + r * y))
        .collect();
    let weights = (0..9).map(|i| if i % 2 == 0 { 1.0 } else { w }).collect();
    let knots = vec![
        0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
    ];
    NurbsCurve2::try_new(2, KnotVector::try_new(knots).unwrap(), points, weights).unwrap()
}

/// Global domain [0, 3]: the line y = 0 from (−2, 0) to (0, 0) (a Bézier), the quarter arc up
/// to (1, 1) (a NURBS), and the parabola (1 + u, 1 + u²) (evaluation only).
fn composite() -> CompositeCurve2<f64> {
    let parabola = Poly(vec![
        SVector::from([1.0, 1.0]),
        SVector::from([1.0, 0.0]),
        SVector::from([0.0, 1.0]),
    ]);
    CompositeCurve::try_new(vec![
        Box::new(bezier(&[(-2.0, 0.0), (0.0, 0.0)])),
        Box::new(quarter_arc()),
        Box::new(parabola),
    ])
    .unwrap()
}

fn check_hits<A, B>(a: &A, b: &B, hits: &[CurvePairPoint<2>])
where
    A: ParametricCurve<f64, 2> + ?Sized,
    B: ParametricCurve<f64, 2> + ?Sized,
{
    for h in hits {
        let pa = a.point(h.parameter_a).unwrap();
        let pb = b.point(h.parameter_b).unwrap();
        assert!((pa - pb).norm() <= 1e-9, "{h:?}");
        assert!((pa - h.point_a).norm() < 1e-15, "{h:?}");
    }
}

#[test]
fn composite_meets_line_like_beziers_by_hand() {
    let chain = composite();
    // x = −1, y = −1 + 4t: crosses the line piece at (−1, 0), s = 0.5, t = 0.25.
    let left = bezier(&[
        (-1.0, -1.0),
        (-1.0, 1.0 / 3.0),
        (-1.0, 5.0 / 3.0),
        (-1.0, 3.0),
    ]);
    let hits = intersect_curves(&chain, &left, &opts()).unwrap();
    check_hits(&chain, &left, &hits);
    assert_eq!(hits.len(), 1, "{hits:?}");
    assert!((hits[0].parameter_a - 0.5).abs() < 1e-12);
    assert!((hits[0].parameter_b - 0.25).abs() < 1e-12);
    assert!(!hits[0].tangential);
    // x = 1.5, y = 3t: crosses the sampled parabola at u = 0.5, (1.5, 1.25): s = 2.5.
    let right = bezier(&[(1.5, 0.0), (1.5, 1.0), (1.5, 2.0), (1.5, 3.0)]);
    let hits = intersect_curves(&chain, &right, &opts()).unwrap();
    check_hits(&chain, &right, &hits);
    assert_eq!(hits.len(), 1, "{hits:?}");
    assert!((hits[0].parameter_a - 2.5).abs() < 1e-12);
    assert!((hits[0].parameter_b - 1.25 / 3.0).abs() < 1e-12);
    // x = 0.5: crosses the arc x² + (y − 1)² = 1 at y = 1 − √3/2.
    let middle = bezier(&[(0.5, -1.0), (0.5, 3.0)]);
    let hits = intersect_curves(&chain, &middle, &opts()).unwrap();
    check_hits(&chain, &middle, &hits);
    assert_eq!(hits.len(), 1, "{hits:?}");
    assert!((hits[0].point_a - p(0.5, 1.0 - 0.75_f64.sqrt())).norm() < 1e-12);
    assert!(hits[0].parameter_a > 1.0 && hits[0].parameter_a < 2.0);
    // The same in the other order swaps the parameters.
    let back = intersect_curves(&middle, &chain, &opts()).unwrap();
    assert_eq!(back.len(), 1);
    assert!((back[0].parameter_b - hits[0].parameter_a).abs() < 1e-12);
}

#[test]
fn composite_meets_a_circle_nurbs_by_hand() {
    let chain = composite();
    // The circle about (1, 1) of radius 1 meets the arc where x = 1/2 (subtracting the two
    // circles' equations), at y = 1 − √3/2, and the parabola where u² + u⁴ = 1, that is
    // u² = (√5 − 1)/2.
    let circle = circle_nurbs((1.0, 1.0), 1.0);
    let hits = intersect_curves(&chain, &circle, &opts()).unwrap();
    check_hits(&chain, &circle, &hits);
    assert_eq!(hits.len(), 2, "{hits:?}");
    assert!((hits[0].point_a - p(0.5, 1.0 - 0.75_f64.sqrt())).norm() < 1e-12);
    let u2 = (5.0_f64.sqrt() - 1.0) / 2.0;
    let u = u2.sqrt();
    assert!((hits[1].parameter_a - (2.0 + u)).abs() < 1e-12);
    assert!((hits[1].point_a - p(1.0 + u, 1.0 + u2)).norm() < 1e-12);
    assert!(hits.iter().all(|h| !h.tangential));
}

#[test]
fn closest_pair_of_composite_and_circle_by_hand() {
    let chain = composite();
    // The circle about (−1, 2) of radius 1/2: the line piece is 2 from the centre at (−1, 0);
    // the arc and the parabola are at least √5 away (3 + 2 sin θ + 2 cos θ ≥ 5 on the arc,
    // (2 + u)² + (u² − 1)² ≥ 5 on the parabola). So the distance is 1.5.
    let circle = circle_nurbs((-1.0, 2.0), 0.5);
    let near = curve_distance(&chain, &circle, &opts()).unwrap();
    assert!((near.distance - 1.5).abs() < 1e-9, "{near:?}");
    assert!((near.point_a - p(-1.0, 0.0)).norm() < 1e-6);
    assert!((near.parameter_a - 0.5).abs() < 1e-6);
    assert!((near.point_b - p(-1.0, 1.5)).norm() < 1e-6);
}

#[test]
fn composite_overlapping_a_segment_by_hand() {
    let chain = composite();
    // The segment from (−1, 0) to (0.5, 0) runs along the line piece for s in [0.5, 1] and
    // leaves the chain at (0, 0), where the arc starts tangent to it. Within the tolerance the
    // overlap goes on a little along the arc, while its height x²/2 stays below 1e-9
    // (x < 4.5e-5), so its end is 1 to about 1e-4.
    let seg = Segment::try_new(p(-1.0, 0.0), p(0.5, 0.0)).unwrap();
    let found = intersect_curves_with_overlaps(&chain, &seg, &opts()).unwrap();
    assert_eq!(found.overlaps.len(), 1, "{found:?}");
    let o = found.overlaps[0];
    assert!((o.a.0 - 0.5).abs() < 1e-9, "{o:?}");
    assert!(o.a.1 >= 1.0 && o.a.1 - 1.0 < 1e-4, "{o:?}");
    assert!(o.b.0.abs() < 1e-9, "{o:?}");
    assert!(o.b.1 >= 2.0 / 3.0 && o.b.1 - 2.0 / 3.0 < 1e-4, "{o:?}");
    assert!(found.points.is_empty(), "{found:?}");
}

#[test]
fn a_sampled_curve_gives_what_its_exact_form_gives() {
    // (1 + u, 1 + u²) is the quadratic Bézier (1, 1), (1.5, 1), (2, 2): the sampled enclosure
    // and the exact form must find the same crossings with a wavy cubic.
    let sampled = Poly(vec![
        SVector::from([1.0, 1.0]),
        SVector::from([1.0, 0.0]),
        SVector::from([0.0, 1.0]),
    ]);
    let exact = bezier(&[(1.0, 1.0), (1.5, 1.0), (2.0, 2.0)]);
    let wave = bezier(&[(0.8, 1.1), (1.4, 0.2), (1.6, 2.6), (2.2, 1.2)]);
    let a = intersect_curves(&sampled, &wave, &opts()).unwrap();
    let b = intersect_curves(&exact, &wave, &opts()).unwrap();
    check_hits(&sampled, &wave, &a);
    assert!(!a.is_empty());
    assert_eq!(a.len(), b.len(), "{a:?} {b:?}");
    for (x, y) in a.iter().zip(&b) {
        assert!((x.parameter_a - y.parameter_a).abs() < 1e-10);
        assert!((x.parameter_b - y.parameter_b).abs() < 1e-10);
    }
    let post = Segment::try_new(p(3.0, -1.0), p(3.5, 2.0)).unwrap();
    let da = curve_distance(&sampled, &post, &opts()).unwrap();
    let db = curve_distance(&exact, &post, &opts()).unwrap();
    assert!((da.distance - db.distance).abs() < 1e-9);
    assert!((da.parameter_a - db.parameter_a).abs() < 1e-6);
}

/// A parabola facing a circle, their closest stretches nearly parallel: the distance is the
/// centre's distance to the parabola less the radius (second method: the point query), with
/// the leaf budget cut to 300 and with the default. (This pair once took 5 000 leaf refinements,
/// 0.46 s in release, the boxes' lower bound being only linear in the leaf size; its cost is
/// the `distance/parabola_facing_circle` bench.)
#[test]
fn distance_from_a_parabola_to_a_facing_circle() {
    let parabola = bezier(&[(1.0, 1.0), (1.5, 1.0), (2.0, 2.0)]);
    let round = circle_nurbs((3.0, 0.0), 0.5);
    let foot = closest_point(&parabola, &p(3.0, 0.0)).unwrap();
    let limited = opts().with_max_candidates(300);
    let near = curve_distance(&parabola, &round, &limited).unwrap();
    assert!(
        (near.distance - (foot.distance - 0.5)).abs() < 1e-9,
        "{near:?} {foot:?}"
    );
    assert!((near.parameter_a - foot.parameter).abs() < 1e-6);
    let full = curve_distance(&parabola, &round, &opts()).unwrap();
    assert!((full.distance - near.distance).abs() < 1e-12);
}

/// (u, |u − 0.4|) on [0, 1]: a kink the curve does not report as a breakpoint (and that no
/// halving of [0, 1] lands on).
struct Vee;

impl ParametricCurve<f64, 2> for Vee {
    fn domain(&self) -> (f64, f64) {
        (0.0, 1.0)
    }

    fn derivatives_into(&self, u: f64, out: &mut [SVector<f64, 2>]) -> Result<()> {
        check_parameter(u, (0.0, 1.0))?;
        let sign = if u < 0.4 { -1.0 } else { 1.0 };
        for (k, o) in out.iter_mut().enumerate() {
            *o = match k {
                0 => SVector::from([u, (u - 0.4).abs()]),
                1 => SVector::from([1.0, sign]),
                _ => SVector::zeros(),
            };
        }
        Ok(())
    }
}

/// The sampled enclosure halves around an unreported kink until its slack is small, so the
/// kinked piece of a composite is still found where it crosses: y = 0.2 meets (u, |u − 0.4|) at
/// u = 0.2 and 0.6, the chain's second piece, so s = 1.2 and 1.6.
#[test]
fn an_unreported_kink_is_enclosed() {
    let pieces = sampled_pieces(&Vee).unwrap();
    assert!(pieces.len() > 2);
    let around: Vec<_> = pieces
        .iter()
        .filter(|q| q.start <= 0.4 && q.end >= 0.4)
        .collect();
    assert!(around.iter().all(|q| q.end - q.start < 1e-3), "{around:?}");
    // Every point near the kink lies in the box of a piece holding its parameter.
    for k in 0..=20_000 {
        let u = 0.39 + 0.02 * f64::from(k) / 20_000.0;
        let q = Vee.point(u).unwrap().coords;
        let inside = pieces
            .iter()
            .filter(|piece| piece.start <= u && u <= piece.end)
            .any(|piece| {
                let (lo, hi) = piece.bounding_box();
                (0..2).all(|i| q[i] >= lo[i] && q[i] <= hi[i])
            });
        assert!(inside, "u = {u}");
    }
    let chain: CompositeCurve2<f64> = CompositeCurve::try_new(vec![
        Box::new(bezier(&[(-1.0, 1.5), (0.0, 0.4)])),
        Box::new(Vee),
    ])
    .unwrap();
    let level = bezier(&[(-2.0, 0.2), (2.0, 0.2)]);
    let hits = intersect_curves(&chain, &level, &opts()).unwrap();
    check_hits(&chain, &level, &hits);
    assert_eq!(hits.len(), 2, "{hits:?}");
    assert!((hits[0].parameter_a - 1.2).abs() < 1e-12);
    assert!((hits[1].parameter_a - 1.6).abs() < 1e-12);
}

fn coord() -> impl Strategy<Value = f64> {
    -2.0..2.0_f64
}

fn point() -> impl Strategy<Value = (f64, f64)> {
    (coord(), coord())
}

/// A C0 chain of a cubic Bézier, a quarter-circle-like NURBS and a cubic polynomial piece
/// known only through evaluation, each starting where the previous one ends.
fn random_composite() -> impl Strategy<Value = CompositeCurve2<f64>> {
    (
        prop::collection::vec(point(), 4),
        point(),
        point(),
        0.3..3.0_f64,
        prop::collection::vec(point(), 3),
    )
        .prop_map(|(cubic, mid, end, w, poly)| {
            let first = bezier(&cubic);
            let start = cubic[3];
            let arc = NurbsCurve2::try_new(
                2,
                KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]).unwrap(),
                vec![p(start.0, start.1), p(mid.0, mid.1), p(end.0, end.1)],
                vec![1.0, w, 1.0],
            )
            .unwrap();
            let mut coeffs = vec![SVector::from([end.0, end.1])];
            coeffs.extend(poly.iter().map(|&(x, y)| SVector::from([x, y])));
            CompositeCurve::try_new(vec![Box::new(first), Box::new(arc), Box::new(Poly(coeffs))])
                .unwrap()
        })
}

/// The hits of `chain` and `other` found piece by piece, on the chain's global parameter,
/// with the duplicates at joints merged.
fn piecewise_hits(chain: &CompositeCurve2<f64>, other: &BezierCurve2<f64>) -> Vec<f64> {
    let mut out: Vec<(f64, Point2<f64>)> = Vec::new();
    for (i, piece) in chain.pieces().iter().enumerate() {
        let (a, b) = piece.domain();
        for h in intersect_curves(piece.as_ref(), other, &opts()).unwrap() {
            let s = i as f64 + (h.parameter_a - a) / (b - a);
            if !out.iter().any(|(_, q)| (q - h.point_a).norm() < 1e-6) {
                out.push((s, h.point_a));
            }
        }
    }
    let mut params: Vec<f64> = out.into_iter().map(|(s, _)| s).collect();
    params.sort_by(f64::total_cmp);
    params
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Every intersection lies on both curves, and the chain finds what its pieces find one
    /// by one; its distance to a curve is the least of its pieces' distances.
    #[test]
    fn composite_queries_agree_with_their_pieces(
        chain in random_composite(),
        cubic in prop::collection::vec(point(), 4),
    ) {
        let other = bezier(&cubic);
        let hits = intersect_curves(&chain, &other, &opts()).unwrap();
        for h in &hits {
            let pa = chain.point(h.parameter_a).unwrap();
            let pb = other.point(h.parameter_b).unwrap();
            prop_assert!((pa - pb).norm() <= 1e-9, "{:?}", h);
            prop_assert!((pa - h.point_a).norm() < 1e-15);
        }
        // Near-tangent grazes may be seen by one method within the tolerance and not by the
        // other; compare only when every hit is a clean crossing.
        if hits.iter().all(|h| !h.tangential) {
            let by_piece = piecewise_hits(&chain, &other);
            if by_piece.len() == hits.len() {
                for (h, s) in hits.iter().zip(&by_piece) {
                    prop_assert!((h.parameter_a - s).abs() < 1e-7, "{:?} {:?}", hits, by_piece);
                }
            } else {
                // Only a graze (a near-tangent pair within the tolerance) may differ.
                let grazing = hits.iter().any(|h| {
                    let ta = chain.derivative(h.parameter_a).unwrap().normalize();
                    let tb = other.derivative(h.parameter_b).unwrap().normalize();
                    (ta.x * tb.y - ta.y * tb.x).abs() < 1e-3
                });
                prop_assert!(grazing, "{:?} vs {:?}", hits, by_piece);
            }
        }
        let moved = bezier(&cubic.iter().map(|&(x, y)| (x + 6.0, y)).collect::<Vec<_>>());
        let whole = curve_distance(&chain, &moved, &opts()).unwrap();
        let least = chain
            .pieces()
            .iter()
            .map(|piece| curve_distance(piece.as_ref(), &moved, &opts()).unwrap().distance)
            .fold(f64::INFINITY, f64::min);
        prop_assert!((whole.distance - least).abs() < 1e-9, "{} vs {}", whole.distance, least);
        let pa = chain.point(whole.parameter_a).unwrap();
        prop_assert!((pa - whole.point_a).norm() < 1e-15);
    }

    /// The sampled enclosure of a curve known only through evaluation holds the curve: every
    /// point lies in the (slack-grown) box of a piece whose interval holds its parameter.
    #[test]
    fn sampled_boxes_hold_the_curve(
        coeffs in prop::collection::vec(point(), 2..7),
    ) {
        let curve = Poly(coeffs.iter().map(|&(x, y)| SVector::from([x, y])).collect());
        let pieces = sampled_pieces(&curve).unwrap();
        prop_assert!((pieces[0].start - 0.0).abs() < 1e-300);
        prop_assert!((pieces.last().unwrap().end - 1.0).abs() < 1e-300);
        for w in pieces.windows(2) {
            prop_assert!(w[0].end.total_cmp(&w[1].start).is_eq());
        }
        for k in 0..=1000 {
            let u = k as f64 / 1000.0;
            let q = curve.point(u).unwrap().coords;
            let inside = pieces.iter().filter(|piece| piece.start <= u && u <= piece.end).any(|piece| {
                let (lo, hi) = piece.bounding_box();
                (0..2).all(|i| q[i] >= lo[i] - 1e-12 && q[i] <= hi[i] + 1e-12)
            });
            prop_assert!(inside, "u = {}", u);
        }
    }
}
