//! The `expression` fuzz target: the input's lines are the rows of an expression constraint,
//! compiled against a fixed sketch whose names are `P`, `Q` (points), `C` (a cubic B-spline),
//! `L` (a line), `K` (a circle) and `s` (a free parameter), each declared when the text
//! mentions it.
//!
//! Promises: no panic; a refused text gets an error whose column lies inside the row it names
//! (or, for the size limits, none); an accepted one evaluates, differentiates, goes into the
//! sketch (its arguments are all read), and its Jacobian is the same at two points when the
//! tape says it is affine; a solve is bounded, leaves the sketch unchanged when it fails and
//! within tolerance when it succeeds; the sketch saves and loads again.

use std::collections::BTreeSet;

use camber_geom::{BSplineCurve2, KnotVector};
use camber_sketch::constraints::expression::{ExprArg, ExprBlock, Expression};
use camber_sketch::Sketch;
use camber_solve::DynResidual;
use nalgebra::Point2;

/// The sketch the rows are compiled against, and the argument each name would be.
fn fixture() -> Option<(Sketch, Vec<(&'static str, ExprArg)>)> {
    let mut s = Sketch::new();
    let p = s.add_point(Point2::new(0.5, -0.25)).ok()?;
    let q = s.add_point(Point2::new(2.0, 1.5)).ok()?;
    let pts = [[0.0, 0.0], [1.0, 1.5], [2.0, -0.5], [3.0, 1.0], [4.0, 0.0]];
    let c = s
        .add_bspline(
            BSplineCurve2::try_new(
                3,
                KnotVector::clamped_uniform(3, pts.len()).ok()?,
                pts.iter().map(|a| Point2::new(a[0], a[1])).collect(),
            )
            .ok()?,
        )
        .ok()?;
    let l = s
        .add_line(Point2::new(-1.0, 0.0), Point2::new(1.0, 2.0))
        .ok()?;
    let k = s.add_circle(Point2::new(1.0, 3.0), 0.75).ok()?;
    Some((
        s,
        vec![
            ("P", ExprArg::Point(p)),
            ("Q", ExprArg::Point(q)),
            ("C", ExprArg::Curve(c)),
            ("L", ExprArg::Line(l)),
            ("K", ExprArg::Circle(k)),
            ("s", ExprArg::Free(0.4)),
        ],
    ))
}

/// The names the text mentions (runs of name characters).
fn mentioned(text: &str) -> BTreeSet<&str> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .filter(|w| !w.is_empty())
        .collect()
}

/// The values of the blocks of `layout` in `s`, each point moved by `shift`.
fn values(s: &Sketch, layout: &[ExprBlock], shift: f64) -> Vec<Vec<f64>> {
    layout
        .iter()
        .map(|b| match b {
            ExprBlock::Point(e, j) => s
                .entity(*e)
                .ok()
                .and_then(|e| e.points().get(*j).copied())
                .map_or(vec![f64::NAN; 2], |p| vec![p.x + shift, p.y - shift]),
            ExprBlock::Radius(e) => match s.entity(*e) {
                Ok(camber_sketch::Entity::Circle { radius, .. }) => vec![radius + shift.abs()],
                _ => vec![f64::NAN],
            },
            ExprBlock::Free { start, .. } => vec![*start],
        })
        .collect()
}

/// Rows of expression text (see the module documentation).
///
/// # Panics
/// When the language or the sketch breaks a promise on this input (the fuzzer's finding).
pub fn expression(data: &[u8]) {
    // Past the language's own limit, so that its size check is reached.
    if data.len() > 2 * camber_expr::MAX_EXPRESSION_BYTES {
        return;
    }
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Some((sketch, names)) = fixture() else {
        panic!("the fixture sketch is refused");
    };
    let words = mentioned(text);
    let mut e = Expression::new("fuzz", &text.split('\n').collect::<Vec<_>>());
    for (name, arg) in &names {
        if words.contains(name) {
            e = e.with_arg(name, *arg);
        }
    }
    let compiled = e.residual_for(&sketch);
    let (residual, layout) = match compiled {
        Err(camber_sketch::Error::Expression(err)) => {
            if let Some(column) = err.column() {
                let row = err.row().map_or(0, |r| r - 1);
                let len = e.rows.get(row).map_or(0, |r| r.chars().count());
                assert!(
                    column >= 1 && column <= len + 1,
                    "{err}: column {column} outside row {row} of {len} characters"
                );
            }
            return;
        }
        // The sketch's own errors (an argument of the wrong kind for a call, say).
        Err(_) => return,
        Ok(r) => r,
    };
    let n: usize = layout
        .iter()
        .map(|b| usize::from(matches!(b, ExprBlock::Point(..))) + 1)
        .sum();
    let dim = residual.dim();
    let mut jacobians = Vec::new();
    for shift in [0.0, 0.37] {
        let x = values(&sketch, &layout, shift);
        let refs: Vec<&[f64]> = x.iter().map(Vec::as_slice).collect();
        let (mut g, mut j) = (vec![0.0; dim], vec![0.0; dim * n]);
        if let Err(err) = DynResidual::jacobian(&residual, &refs, &mut g, &mut j) {
            panic!("the Jacobian of a compiled expression fails: {err}");
        }
        let mut h = vec![0.0; n * n];
        let weights = vec![1.0; dim];
        let active = vec![true; layout.len()];
        let _ = DynResidual::weighted_hessian(&residual, &refs, &weights, &active, &mut h);
        jacobians.push(j);
    }
    if DynResidual::is_affine(&residual) {
        for (a, b) in jacobians[0].iter().zip(&jacobians[1]) {
            if a.is_finite() && b.is_finite() {
                assert!(
                    (a - b).abs() <= 1e-9 * (1.0 + a.abs()),
                    "an affine expression's Jacobian changes: {a} vs {b}"
                );
            }
        }
    }
    let mut s = sketch.clone();
    if let Err(err) = s.add_constraint(e.clone()) {
        panic!("a compiled expression is refused by the sketch: {err}");
    }
    let mut options = s.options().clone();
    options.nonlinear = options
        .nonlinear
        .with_max_evaluations(Some(super::SKETCH_SOLVE_EVALUATIONS));
    s.set_options(options);
    let saved = super::reloads(&s, "the sketch with the expression");
    match s.solve() {
        Err(_) => {
            let after = camber_sketch::file::to_json(&s).ok();
            assert_eq!(
                after.as_deref(),
                Some(saved.as_str()),
                "a failed solve changed the sketch"
            );
        }
        Ok(report) => {
            let tolerance = report.tolerance;
            for comp in &report.components {
                for r in &comp.report.residuals {
                    assert!(
                        r.max_abs <= tolerance,
                        "solve succeeded with constraint {} at {:e}",
                        r.constraint.0,
                        r.max_abs
                    );
                }
            }
            super::reloads(&s, "the solved sketch");
        }
    }
}
