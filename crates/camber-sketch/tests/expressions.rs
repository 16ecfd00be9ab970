//! Expression constraints in sketches: they solve like the built-in kinds they restate, take
//! the linear path when affine, solve their own free parameters, say what no built-in kind
//! says (an enclosed area, equal curvature across a join), round-trip through files, and
//! refuse bad rows with the column.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_abs_diff_eq;
use camber_geom::{BezierCurve2, ParametricCurve};
use camber_sketch::constraints::expression::{ExprArg, Expression};
use camber_sketch::constraints::{Distance, Fixed, PointAtParameter};
use camber_sketch::file::{from_json, to_json};
use camber_sketch::{Constraint, EntityId, PointRef, Sketch, Target};
use camber_solve::SolverKind;
use nalgebra::Point2;

fn bezier(points: &[[f64; 2]]) -> BezierCurve2<f64> {
    BezierCurve2::try_new(points.iter().map(|p| Point2::new(p[0], p[1])).collect()).unwrap()
}

fn two_points() -> (Sketch, EntityId, EntityId) {
    let mut s = Sketch::new();
    let p = s.add_point(Point2::new(0.2, -0.1)).unwrap();
    let q = s.add_point(Point2::new(3.0, 1.0)).unwrap();
    (s, p, q)
}

#[test]
fn an_expression_restating_the_distance_residual_solves_to_the_same_points() {
    let (mut builtin, p, q) = two_points();
    builtin
        .add_constraint(Distance {
            a: PointRef::Point(p),
            b: PointRef::Point(q),
            distance: 2.0,
        })
        .unwrap();
    let (mut written, _, _) = two_points();
    // The built-in's own form: (|a − b|² − D²)/(2D).
    written
        .add_constraint(
            Expression::new("distance", &["(dot(P - Q, P - Q) - 2^2) / (2 * 2)"])
                .with_arg("P", ExprArg::Point(p))
                .with_arg("Q", ExprArg::Point(q)),
        )
        .unwrap();
    let (a, b) = (builtin.solve().unwrap(), written.solve().unwrap());
    assert_eq!(a.components[0].report.solver, SolverKind::Newton);
    assert_eq!(b.components[0].report.solver, SolverKind::Newton);
    for id in [p, q] {
        let (x, y) = (
            builtin.point(PointRef::Point(id)).unwrap(),
            written.point(PointRef::Point(id)).unwrap(),
        );
        assert_abs_diff_eq!(x, y, epsilon = 1e-12);
    }
}

#[test]
fn an_affine_expression_takes_the_linear_path_and_matches_the_built_in() {
    let pts = [[0.0, 0.0], [1.0, 2.0], [2.0, -1.0], [3.0, 0.5]];
    let mut builtin = Sketch::new();
    let c = builtin.add_bezier(bezier(&pts)).unwrap();
    builtin
        .add_constraint(PointAtParameter {
            curve: c,
            u: 0.3,
            target: Target::At(Point2::new(1.0, 1.0)),
        })
        .unwrap();
    let mut written = Sketch::new();
    written.add_bezier(bezier(&pts)).unwrap();
    written
        .add_constraint(Expression::new("", &["C(0.3) = [1, 1]"]).with_arg("C", ExprArg::Curve(c)))
        .unwrap();
    let (a, b) = (builtin.solve().unwrap(), written.solve().unwrap());
    assert!(matches!(
        b.components[0].report.solver,
        SolverKind::DenseMinNorm | SolverKind::SparseMinNorm
    ));
    assert_eq!(a.components[0].report.solver, b.components[0].report.solver);
    for j in 0..4 {
        let r = PointRef::Control(c, j);
        assert_abs_diff_eq!(
            builtin.point(r).unwrap(),
            written.point(r).unwrap(),
            epsilon = 1e-13
        );
    }
}

#[test]
fn a_free_parameter_is_solved_bounded_to_the_domain_and_written_back() {
    let mut s = Sketch::new();
    let c = s
        .add_bezier(bezier(&[[0.0, 0.0], [1.0, 2.0], [2.0, 2.0], [3.0, 0.0]]))
        .unwrap();
    let p = s.add_point(Point2::new(1.5, 2.0)).unwrap();
    s.add_constraint(Fixed::point(PointRef::Point(p))).unwrap();
    let id = s
        .add_constraint(
            Expression::new("through", &["C(s) = P"])
                .with_arg("C", ExprArg::Curve(c))
                .with_arg("P", ExprArg::Point(p))
                .with_arg("s", ExprArg::Free(0.4)),
        )
        .unwrap();
    s.solve().unwrap();
    let Constraint::Expression(e) = s.constraint(id).unwrap() else {
        panic!("not an expression")
    };
    let u = e.free_parameters()["s"];
    assert!((0.0..=1.0).contains(&u));
    let on = s.curve_point(c, u).unwrap();
    assert_abs_diff_eq!(on, Point2::new(1.5, 2.0), epsilon = 1e-10);
    // A free parameter read as a curve parameter must start inside the domain.
    let outside = Expression::new("", &["C(t) = P"])
        .with_arg("C", ExprArg::Curve(c))
        .with_arg("P", ExprArg::Point(p))
        .with_arg("t", ExprArg::Free(1.5));
    let err = s.add_constraint(outside).unwrap_err().to_string();
    assert!(
        err.starts_with("column 1: the free parameter starts at 1.5, outside the domain [0, 1]"),
        "{err}"
    );
}

/// The area enclosed by a cubic Bézier and its chord, ½∮(x dy − y dx): cross(C, C′) has
/// degree 5, so three Gauss–Legendre nodes on [0, 1] integrate it exactly; the chord from
/// C(1) back to C(0) adds ½·cross(C(1), C(0)).
const AREA_ROWS: &str = "0.5 * (5/18 * cross(C(0.1127016653792583), C'(0.1127016653792583)) \
     + 8/18 * cross(C(0.5), C'(0.5)) \
     + 5/18 * cross(C(0.8872983346207417), C'(0.8872983346207417)) \
     + cross(C(1), C(0))) = A";

/// The same area by the shoelace formula over a fine polygon (an independent method).
fn polygon_area(c: &BezierCurve2<f64>) -> f64 {
    let n = 20_000;
    let pts: Vec<Point2<f64>> = (0..=n)
        .map(|k| c.point(f64::from(k) / f64::from(n)).unwrap())
        .collect();
    let mut a = 0.0;
    for k in 0..pts.len() {
        let (p, q) = (pts[k], pts[(k + 1) % pts.len()]);
        a += p.x * q.y - p.y * q.x;
    }
    0.5 * a
}

#[test]
fn a_required_enclosed_area_no_built_in_kind_says() {
    let mut s = Sketch::new();
    let c = s
        .add_bezier(bezier(&[[0.0, 0.0], [0.5, 1.0], [2.5, 1.0], [3.0, 0.0]]))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(c, 0)))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(c, 3)))
        .unwrap();
    let area = -2.5; // clockwise: the curve runs left to right above its chord
    let rows = AREA_ROWS.replace('A', &format!("({area})"));
    s.add_constraint(Expression::new("area", &[rows.as_str()]).with_arg("C", ExprArg::Curve(c)))
        .unwrap();
    s.solve().unwrap();
    let Ok(camber_sketch::Entity::Bezier(solved)) = s.entity(c).cloned() else {
        panic!("not a Bézier")
    };
    assert_abs_diff_eq!(polygon_area(&solved), area, epsilon = 1e-6);
    assert_abs_diff_eq!(
        solved.control_points()[0],
        Point2::new(0.0, 0.0),
        epsilon = 1e-15
    );
}

#[test]
fn equal_curvature_across_a_join_no_built_in_kind_says_alone() {
    let mut s = Sketch::new();
    let a = s
        .add_bezier(bezier(&[[0.0, 0.0], [1.0, 0.6], [2.0, 1.0], [3.0, 1.0]]))
        .unwrap();
    let b = s
        .add_bezier(bezier(&[[3.0, 1.0], [4.0, 1.0], [5.0, 0.2], [6.0, -0.4]]))
        .unwrap();
    s.add_constraint(Fixed::entity(a)).unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(b, 0)))
        .unwrap();
    s.add_constraint(Fixed::point(PointRef::Control(b, 3)))
        .unwrap();
    // κ = cross(C′, C″)/|C′|³ equal at the joint, and the tangents parallel.
    s.add_constraint(
        Expression::new(
            "curvature",
            &[
                "cross(A'(1), A''(1)) / norm(A'(1))^3 = cross(B'(0), B''(0)) / norm(B'(0))^3",
                "cross(A'(1), B'(0))",
            ],
        )
        .with_arg("A", ExprArg::Curve(a))
        .with_arg("B", ExprArg::Curve(b)),
    )
    .unwrap();
    s.solve().unwrap();
    let curvature = |id: EntityId, u: f64| {
        let Ok(camber_sketch::Entity::Bezier(c)) = s.entity(id).cloned() else {
            panic!("not a Bézier")
        };
        let [_, d1, d2] = c.second_order(u).unwrap();
        (d1.x * d2.y - d1.y * d2.x) / d1.norm().powi(3)
    };
    assert_abs_diff_eq!(curvature(a, 1.0), curvature(b, 0.0), epsilon = 1e-9);
}

#[test]
fn an_expression_round_trips_through_a_file_and_solves_after_loading() {
    let text = r#"{
  "version": 1,
  "entities": [
    {"id":0,"kind":"line","from":[0.0,0.0],"to":[2.0,0.3]},
    {"id":1,"kind":"circle","center":[1.0,2.0],"radius":0.5}
  ],
  "constraints": [
    {"id":2,"kind":"expression","name":"touch","rows":["cross(L.dir, K.center - L.start) / norm(L.dir) = K.radius"],"args":{"K":{"circle":1},"L":{"line":0}}},
    {"id":3,"kind":"fixed","target":{"entity":0}}
  ]
}
"#;
    let mut s = from_json(text).unwrap();
    assert_eq!(to_json(&s).unwrap(), text);
    s.solve().unwrap();
    let (
        Ok(camber_sketch::Entity::Circle { center, radius }),
        Ok(camber_sketch::Entity::Line([a, b])),
    ) = (
        s.entity(EntityId(1)).cloned(),
        s.entity(EntityId(0)).cloned(),
    )
    else {
        panic!("kinds")
    };
    let d = b - a;
    let dist = (d.x * (center.y - a.y) - d.y * (center.x - a.x)) / d.norm();
    assert_abs_diff_eq!(dist, radius, epsilon = 1e-10);
}

#[test]
fn bad_expressions_are_refused_with_the_column_and_nothing_changes() {
    let (mut s, p, q) = two_points();
    let before = to_json(&s).unwrap();
    let cases: Vec<(Expression, &str)> = vec![
        (
            Expression::new("", &["norm(P - Q) +"]).with_arg("P", ExprArg::Point(p)).with_arg("Q", ExprArg::Point(q)),
            "column 14: expected an operand (a number, a name, `(` or `[`), found the end of the expression",
        ),
        (
            Expression::new("", &["P + 1"]).with_arg("P", ExprArg::Point(p)),
            "column 5: `+` needs a vector, found a scalar",
        ),
        (
            Expression::new("", &["norm(P - R)"]).with_arg("P", ExprArg::Point(p)),
            "column 10: unknown name `R`",
        ),
        (
            // Identically zero: the difference folds to the constant 0.
            Expression::new("", &["P.x / (Q.y - Q.y)"]).with_arg("P", ExprArg::Point(p)).with_arg("Q", ExprArg::Point(q)),
            "column 7: division by a constant zero",
        ),
        (
            Expression::new("", &["P.x / (Q.y - P.y)"]).with_arg("P", ExprArg::Point(p)).with_arg("Q", ExprArg::Point(q)),
            "",
        ),
        (
            Expression::new("", &["P.x / 0"]).with_arg("P", ExprArg::Point(p)),
            "column 7: division by a constant zero",
        ),
        (
            Expression::new("", &["P.x"]).with_arg("P", ExprArg::Point(p)).with_arg("Q", ExprArg::Point(q)),
            "column 1: the argument `Q` is not used by any row",
        ),
        (
            Expression::new("", &["dot.x"]).with_arg("dot", ExprArg::Point(p)),
            "column 1: `dot` is a built-in function or constant of the language",
        ),
        (
            Expression::new("", &["P.x"]).with_arg("P", ExprArg::Point(EntityId(99))),
            "entity 99 does not exist",
        ),
        (
            Expression::new("", &["C(0.5).x"]).with_arg("C", ExprArg::Curve(p)),
            "entity 0 is a point, expected curve",
        ),
        (
            Expression::new("", &["C.x"]).with_arg("C", ExprArg::Curve(p)),
            "column 3: a curve has the members `start`, `end` and `length`, not `x`",
        ),
        (
            Expression::new("", &["s"]).with_arg("s", ExprArg::Free(f64::NAN)),
            "free parameter 0 is not finite (NaN)",
        ),
        (
            Expression::new("", &[]),
            "an expression constraint has 0 rows, expected 1 to 64",
        ),
    ];
    for (e, message) in cases {
        let rows = e.rows.clone();
        match s.add_constraint(e) {
            Ok(_) if message.is_empty() => {}
            Ok(_) => panic!("{rows:?} was accepted"),
            Err(err) => assert_eq!(err.to_string(), message, "{rows:?}"),
        }
    }
    // The one accepted (a divisor that is zero only at these values) is solvable text; remove
    // it, and the sketch is as it was.
    let ids: Vec<_> = s.constraints().map(|(id, _)| id).collect();
    for id in ids {
        s.remove_constraint(id).unwrap();
    }
    assert_eq!(to_json(&s).unwrap(), before);
}
