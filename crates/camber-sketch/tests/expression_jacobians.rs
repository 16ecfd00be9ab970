//! An expression constraint's exact Jacobian (dual numbers through the tape and the curve
//! calls) against the same residual written in Rust and against central differences, at
//! random points around a sketch: curve points and derivatives at a free and a fixed
//! parameter, a circle's centre and radius, a point.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber_geom::{BSplineCurve2, KnotVector};
use camber_sketch::constraints::expression::{ExprArg, ExprBlock, Expression};
use camber_sketch::curve_eval::CurveBasis;
use camber_sketch::{EntityId, Sketch};
use camber_solve::scalar::cst;
use camber_solve::testing::check_jacobian;
use camber_solve::{DynResidual, Residual, Scalar};
use nalgebra::Point2;
use proptest::prelude::*;

const ROWS: [&str; 2] = [
    "cross(C'(s), C(s) - K.center) - K.radius * norm(C'(s))",
    "dot(C''(0.3), P - K.center) + sin(s) * K.radius^2",
];

struct Fixture {
    sketch: Sketch,
    curve: EntityId,
    circle: EntityId,
    point: EntityId,
}

fn fixture() -> Fixture {
    let mut sketch = Sketch::new();
    let pts = [
        [0.0, 0.0],
        [1.0, 1.5],
        [2.0, -0.5],
        [3.0, 1.0],
        [4.0, 0.5],
        [5.0, 0.0],
    ];
    let c = BSplineCurve2::try_new(
        3,
        KnotVector::clamped_uniform(3, pts.len()).unwrap(),
        pts.iter().map(|p| Point2::new(p[0], p[1])).collect(),
    )
    .unwrap();
    let curve = sketch.add_bspline(c).unwrap();
    let circle = sketch.add_circle(Point2::new(2.0, 3.0), 0.8).unwrap();
    let point = sketch.add_point(Point2::new(-1.0, 2.0)).unwrap();
    Fixture {
        sketch,
        curve,
        circle,
        point,
    }
}

fn expression(f: &Fixture, s: f64) -> Expression {
    Expression::new("probe", &ROWS)
        .with_arg("C", ExprArg::Curve(f.curve))
        .with_arg("K", ExprArg::Circle(f.circle))
        .with_arg("P", ExprArg::Point(f.point))
        .with_arg("s", ExprArg::Free(s))
}

/// The same rows in Rust, reading the blocks where the expression's layout put them.
#[derive(Debug)]
struct Written {
    basis: CurveBasis,
    controls: Vec<usize>,
    center: usize,
    radius: usize,
    point: usize,
    s: usize,
    sizes: Vec<usize>,
}

impl Residual for Written {
    fn name(&self) -> &str {
        "written"
    }
    fn dim(&self) -> usize {
        2
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(self.sizes.clone())
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let pts: Vec<&[T]> = self.controls.iter().map(|b| x[*b]).collect();
        let s = x[self.s][0];
        let [c, d1, _] = self.basis.eval2(&pts, s);
        let [_, _, dd] = self.basis.eval2(&pts, cst(0.3));
        let (k, r, p) = (x[self.center], x[self.radius][0], x[self.point]);
        let cross = d1[0] * (c[1] - k[1]) - d1[1] * (c[0] - k[0]);
        out[0] = cross - r * (d1[0] * d1[0] + d1[1] * d1[1]).sqrt();
        out[1] = dd[0] * (p[0] - k[0]) + dd[1] * (p[1] - k[1]) + s.sin() * r * r;
    }
}

fn written(f: &Fixture, layout: &[ExprBlock]) -> Written {
    let find = |b: ExprBlock| layout.iter().position(|l| *l == b).unwrap();
    let n = f.sketch.entity(f.curve).unwrap().points().len();
    Written {
        basis: CurveBasis::of(f.sketch.entity(f.curve).unwrap()).unwrap(),
        controls: (0..n).map(|j| find(ExprBlock::Point(f.curve, j))).collect(),
        center: find(ExprBlock::Point(f.circle, 0)),
        radius: find(ExprBlock::Radius(f.circle)),
        point: find(ExprBlock::Point(f.point, 0)),
        s: layout
            .iter()
            .position(|l| matches!(l, ExprBlock::Free { .. }))
            .unwrap(),
        sizes: layout
            .iter()
            .map(|l| {
                if matches!(l, ExprBlock::Point(..)) {
                    2
                } else {
                    1
                }
            })
            .collect(),
    }
}

/// The values of the blocks now, plus `shift` (cycled).
fn values(f: &Fixture, layout: &[ExprBlock], shift: &[f64], s: f64) -> Vec<Vec<f64>> {
    let mut k = 0;
    let mut next = || {
        k += 1;
        shift[k % shift.len()]
    };
    layout
        .iter()
        .map(|l| match l {
            ExprBlock::Point(e, j) => {
                let p = f.sketch.entity(*e).unwrap().points()[*j];
                vec![p.x + next(), p.y + next()]
            }
            ExprBlock::Radius(_) => vec![0.8 + 0.5 * next().abs()],
            ExprBlock::Free { .. } => vec![s],
        })
        .collect()
}

proptest! {
    #[test]
    fn expression_jacobians_equal_the_rust_residual_and_central_differences(
        shift in prop::collection::vec(-0.3f64..0.3, 7),
        s in 0.05f64..0.95,
    ) {
        let f = fixture();
        let (residual, layout) = expression(&f, s).residual_for(&f.sketch).unwrap();
        prop_assert!(!Residual::is_affine(&residual));
        let rust = written(&f, &layout);
        let x = values(&f, &layout, &shift, s);
        let refs: Vec<&[f64]> = x.iter().map(Vec::as_slice).collect();
        let n: usize = x.iter().map(Vec::len).sum();
        let (mut ga, mut ja) = (vec![0.0; 2], vec![0.0; 2 * n]);
        let (mut gb, mut jb) = (vec![0.0; 2], vec![0.0; 2 * n]);
        DynResidual::jacobian(&residual, &refs, &mut ga, &mut ja).unwrap();
        DynResidual::jacobian(&rust, &refs, &mut gb, &mut jb).unwrap();
        for (a, b) in ga.iter().zip(&gb).chain(ja.iter().zip(&jb)) {
            prop_assert!((a - b).abs() <= 1e-11 * (1.0 + b.abs()), "{} vs {}", a, b);
        }
        let worst = check_jacobian(&residual, &refs, 1e-6, 1e-6).unwrap();
        prop_assert!(worst.error < 1e-6, "{:?}", worst);
    }
}

#[test]
fn an_affine_expression_has_the_constant_jacobian_of_its_combination() {
    let f = fixture();
    let e = Expression::new("", &["C'(0.25) - 2 * (K.center - P)"])
        .with_arg("C", ExprArg::Curve(f.curve))
        .with_arg("K", ExprArg::Circle(f.circle))
        .with_arg("P", ExprArg::Point(f.point));
    let (residual, layout) = e.residual_for(&f.sketch).unwrap();
    assert!(Residual::is_affine(&residual));
    // The same Jacobian at two different points.
    let n: usize = layout
        .iter()
        .map(|l| {
            if matches!(l, ExprBlock::Point(..)) {
                2
            } else {
                1
            }
        })
        .sum();
    let mut jacobians = Vec::new();
    for shift in [[0.1, -0.2, 0.3], [-1.0, 0.5, 2.0]] {
        let x = values(&f, &layout, &shift, 0.5);
        let refs: Vec<&[f64]> = x.iter().map(Vec::as_slice).collect();
        let (mut g, mut j) = (vec![0.0; 2], vec![0.0; 2 * n]);
        DynResidual::jacobian(&residual, &refs, &mut g, &mut j).unwrap();
        jacobians.push(j);
    }
    assert_eq!(jacobians[0], jacobians[1]);
}
