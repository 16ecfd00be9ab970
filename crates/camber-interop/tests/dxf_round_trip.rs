//! Sketch → DXF → sketch: every entity kind comes back as the same geometry with its tag, in
//! text and binary form: points, knots and weights bit for bit, arcs and ellipses (which pass
//! through angles) to a few units of the last place.
#![allow(clippy::unwrap_used)] // helpers outside #[test] functions unwrap too

use approx::assert_abs_diff_eq;
use camber_geom::{
    BSplineCurve2, BezierCurve2, CircularArc, Ellipse, EllipticArc, HermiteCurve2, KnotVector,
    NurbsCurve2, ParametricCurve,
};
use camber_interop::dxf::{self, Form, ReadOptions};
use camber_sketch::{Entity, EntityId, HermiteChain, Sketch};
use nalgebra::{Point2, Vector2};
use proptest::prelude::*;

/// A sketch with one entity of every kind, each on its own layer but the first.
fn every_kind() -> Sketch {
    let mut s = Sketch::new();
    let p = |x: f64, y: f64| Point2::new(x, y);
    let entities = vec![
        Entity::Point(p(0.125, -3.5)),
        Entity::Line([p(0.0, 0.0), p(1.0 / 3.0, 2.0)]),
        Entity::Circle {
            center: p(5.0, 5.0),
            radius: 0.7,
        },
        Entity::arc(&CircularArc::try_new(p(1.0, 1.0), 2.0, 0.3, 2.2).unwrap()),
        Entity::ellipse(&Ellipse::try_new(p(-1.0, 2.0), 3.0, 1.25, 0.4).unwrap()),
        Entity::elliptic_arc(
            &EllipticArc::try_new(p(2.0, -1.0), 2.0, 0.5, -0.3, 1.0, 4.0).unwrap(),
        ),
        Entity::Bezier(
            BezierCurve2::try_new(vec![p(0.0, 0.0), p(1.0, 2.0), p(3.0, 2.0), p(4.0, 0.1)])
                .unwrap(),
        ),
        Entity::BSpline(
            BSplineCurve2::try_new(
                2,
                KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.25, 0.7, 1.0, 1.0, 1.0]).unwrap(),
                vec![
                    p(0.0, 0.0),
                    p(1.0, 1.0),
                    p(2.0, 0.5),
                    p(3.0, 1.5),
                    p(4.0, 0.0),
                ],
            )
            .unwrap(),
        ),
        Entity::Nurbs(
            NurbsCurve2::try_new(
                2,
                KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]).unwrap(),
                vec![p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)],
                vec![1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0],
            )
            .unwrap(),
        ),
    ];
    for (k, e) in entities.into_iter().enumerate() {
        let id = s.add_entity(e).unwrap();
        if k > 0 {
            s.set_tag(id, Some(&format!("LAYER {k}"))).unwrap();
        }
    }
    s
}

fn round_trip(s: &Sketch, form: Form) -> Sketch {
    let bytes = dxf::write(s, form).expect("writable");
    let options = ReadOptions {
        join_tolerance: -1.0,
        ..ReadOptions::default()
    };
    let back = dxf::read(&bytes, &options).expect("readable");
    assert!(back.skipped.is_empty(), "{:?}", back.skipped);
    back.sketch
}

/// The numbers that define an entity, in one order for both sides.
fn numbers(e: &Entity) -> Vec<f64> {
    let xy = |ps: &[Point2<f64>]| ps.iter().flat_map(|p| [p.x, p.y]).collect::<Vec<_>>();
    match e {
        Entity::Point(p) => xy(&[*p]),
        Entity::Line(p) => xy(p),
        Entity::Circle { center, radius } => vec![center.x, center.y, *radius],
        Entity::Arc(p) => xy(p),
        Entity::Ellipse {
            points,
            semi_axis_b,
        } => [xy(points), vec![*semi_axis_b]].concat(),
        Entity::EllipticArc {
            points,
            semi_axis_b,
        } => [xy(points), vec![*semi_axis_b]].concat(),
        Entity::Bezier(c) => xy(c.control_points()),
        Entity::BSpline(c) => [xy(c.control_points()), c.knots().as_slice().to_vec()].concat(),
        Entity::Nurbs(c) => [
            xy(c.control_points()),
            c.knots().as_slice().to_vec(),
            c.weights().to_vec(),
        ]
        .concat(),
        Entity::Hermite(c) | Entity::Composite(c) => xy(c.blocks()),
    }
}

fn same_kind(a: &Entity, b: &Entity) -> bool {
    std::mem::discriminant(a) == std::mem::discriminant(b)
}

fn compare(a: &Sketch, b: &Sketch, tol: f64) {
    let (ea, eb): (Vec<_>, Vec<_>) = (a.entities().collect(), b.entities().collect());
    assert_eq!(ea.len(), eb.len());
    for ((ia, x), (ib, y)) in ea.iter().zip(&eb) {
        assert!(same_kind(x, y), "{x:?} came back as {y:?}");
        let (nx, ny) = (numbers(x), numbers(y));
        assert_eq!(nx.len(), ny.len());
        for (u, v) in nx.iter().zip(&ny) {
            assert_abs_diff_eq!(u, v, epsilon = tol);
        }
        assert_eq!(a.tag(*ia), b.tag(*ib));
    }
}

#[test]
fn every_kind_survives_a_round_trip_in_both_forms() {
    let s = every_kind();
    for form in [Form::Text, Form::Binary] {
        let back = round_trip(&s, form);
        // Arcs and ellipses pass through angles (degrees for arcs): a few units of the last
        // place.
        compare(&s, &back, 1e-14);
        // Points, lines and splines come back bit for bit.
        for ((_, x), (_, y)) in s.entities().zip(back.entities()) {
            if matches!(
                x,
                Entity::Point(_)
                    | Entity::Line(_)
                    | Entity::Bezier(_)
                    | Entity::BSpline(_)
                    | Entity::Nurbs(_)
            ) {
                assert_eq!(x, y, "{form:?}");
            }
        }
    }
}

#[test]
fn tiny_and_huge_numbers_survive_the_text_form() {
    let mut s = Sketch::new();
    let line = Entity::Line([
        Point2::new(1e-300, -2.5e-17),
        Point2::new(1.0 / 3.0, 6.02e23),
    ]);
    s.add_entity(line.clone()).unwrap();
    let back = round_trip(&s, Form::Text);
    assert_eq!(back.entities().next().unwrap().1, &line);
}

#[test]
fn an_ellipse_wider_than_tall_in_b_is_written_with_its_major_axis_along_b() {
    // b > a: DXF wants a ratio ≤ 1, so the b-axis is the major axis; the curve is the same.
    let mut s = Sketch::new();
    let e = Ellipse::try_new(Point2::new(1.0, 2.0), 1.0, 3.0, 0.5).unwrap();
    let arc = e.arc(0.2, 2.9).unwrap();
    s.add_entity(Entity::ellipse(&e)).unwrap();
    let id = s.add_entity(Entity::elliptic_arc(&arc)).unwrap();
    let back = round_trip(&s, Form::Binary);
    let ends = |sk: &Sketch, id: EntityId| {
        [
            camber_sketch::PointRef::Start(id),
            camber_sketch::PointRef::End(id),
        ]
        .map(|r| sk.point(r).unwrap())
    };
    let back_id = back.entities().nth(1).unwrap().0;
    for (p, q) in ends(&s, id).iter().zip(ends(&back, back_id)) {
        assert!((p - q).norm() < 1e-13, "{p} vs {q}");
    }
    // Every point of the arc lies on the ellipse read back.
    let Entity::Ellipse {
        points: [c, v],
        semi_axis_b,
    } = back.entities().next().unwrap().1.clone()
    else {
        panic!("an ellipse")
    };
    let w = v - c;
    let read = Ellipse::try_new(c, w.norm(), semi_axis_b, w.y.atan2(w.x)).unwrap();
    for k in 0..=20 {
        let p = arc.point(f64::from(k) / 20.0).unwrap();
        let q = read
            .point(read.angle_of(&p).rem_euclid(std::f64::consts::TAU))
            .unwrap();
        assert!(
            (p - q).norm() < 1e-12,
            "{p} is off the ellipse read back ({q})"
        );
    }
}

#[test]
fn hermite_and_composite_curves_are_written_as_the_same_cubic_spline() {
    let p = |x: f64, y: f64| Point2::new(x, y);
    let h = HermiteCurve2::try_new(
        p(0.0, 0.0),
        p(2.0, 1.0),
        Vector2::new(1.0, 2.0),
        Vector2::new(2.0, -1.0),
    )
    .unwrap();
    let mut s = Sketch::new();
    let id = s
        .add_entity(Entity::Hermite(HermiteChain::from_curve(&h).unwrap()))
        .unwrap();
    let back = round_trip(&s, Form::Binary);
    let (back_id, e) = back.entities().next().unwrap();
    assert!(matches!(e, Entity::Bezier(_) | Entity::BSpline(_)), "{e:?}");
    for k in 0..=10 {
        let u = f64::from(k) / 10.0;
        let (a, b) = (
            s.curve_point(id, u).unwrap(),
            back.curve_point(back_id, u).unwrap(),
        );
        assert!((a - b).norm() < 1e-14, "at {u}: {a} vs {b}");
    }
}

#[test]
fn a_tag_that_is_no_layer_name_is_refused_with_the_entity() {
    let mut s = Sketch::new();
    let id = s.add_entity(Entity::Point(Point2::new(0.0, 0.0))).unwrap();
    s.set_tag(id, Some("a/b")).unwrap();
    let err = dxf::write(&s, Form::Text).unwrap_err();
    assert!(
        matches!(err, dxf::Error::LayerName { entity, .. } if entity == id),
        "{err}"
    );
}

#[test]
fn a_spline_beyond_the_dxf_count_is_refused() {
    let n = dxf::MAX_SPLINE_ITEMS + 1;
    let points: Vec<_> = (0..n).map(|i| Point2::new(i as f64, 0.0)).collect();
    let mut knots = vec![0.0];
    knots.extend((0..n).map(|i| i as f64 / (n - 1) as f64));
    knots.push(1.0);
    let c = BSplineCurve2::try_new(1, KnotVector::try_new(knots).unwrap(), points).unwrap();
    let mut s = Sketch::new();
    let id = s.add_entity(Entity::BSpline(c)).unwrap();
    let err = dxf::write(&s, Form::Text).unwrap_err();
    assert!(
        matches!(err, dxf::Error::SplineTooLarge { entity, count, .. } if entity == id && count >= n),
        "{err}"
    );
}

/// Random clamped B-splines and NURBS curves of degree 1–5.
fn curve() -> impl Strategy<Value = Entity> {
    (1usize..=5, 0usize..6, any::<bool>()).prop_flat_map(|(degree, extra, rational)| {
        let n = degree + 1 + extra;
        (
            proptest::collection::vec((-1e3..1e3f64, -1e3..1e3f64), n),
            proptest::collection::vec(0.01..1.0f64, extra),
            proptest::collection::vec(0.1..10.0f64, n),
        )
            .prop_map(move |(points, steps, weights)| {
                let mut knots = vec![0.0; degree + 1];
                let mut t = 0.0;
                for s in &steps {
                    t += s;
                    knots.push(t);
                }
                knots.extend(vec![t + 1.0; degree + 1]);
                let knots = KnotVector::try_new(knots).unwrap();
                let points: Vec<_> = points.into_iter().map(|(x, y)| Point2::new(x, y)).collect();
                if rational {
                    Entity::Nurbs(NurbsCurve2::try_new(degree, knots, points, weights).unwrap())
                } else {
                    Entity::BSpline(BSplineCurve2::try_new(degree, knots, points).unwrap())
                }
            })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn random_splines_round_trip_exactly_in_both_forms(e in curve()) {
        let mut s = Sketch::new();
        s.add_entity(e.clone()).unwrap();
        for form in [Form::Text, Form::Binary] {
            let sketch = round_trip(&s, form);
            let back = sketch.entities().next().unwrap().1;
            // A one-span spline on [0, 1] comes back as a Bézier curve of the same points.
            if let Entity::Bezier(b) = back {
                let Entity::BSpline(c) = &e else { panic!("{back:?}") };
                prop_assert_eq!(b.control_points(), c.control_points());
            } else {
                prop_assert_eq!(back, &e);
            }
        }
    }
}
