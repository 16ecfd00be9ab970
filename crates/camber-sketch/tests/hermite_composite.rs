//! Issue 16: cubic Hermite and composite curves as sketch entities — evaluation against the
//! geometry kernel and the Hermite-to-Bézier conversion, constraints solved to tolerance and
//! checked on the curves themselves, autodiff Jacobians against central differences, and the
//! file form.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use camber_geom::{BezierCurve2, HermiteCurve2, ParametricCurve};
use camber_sketch::constraints::g1_join::G1Join;
use camber_sketch::constraints::point_at_parameter::PointAtParameter;
use camber_sketch::constraints::point_on_curve::OnCurve;
use camber_sketch::constraints::start_tangent::StartTangent;
use camber_sketch::constraints::tangent_to_circle::{CircleContact, TangentToCircle};
use camber_sketch::constraints::tangent_to_line::{LineContact, TangentToLine};
use camber_sketch::constraints::tangent_vector_at::TangentVectorAt;
use camber_sketch::curve_eval::CurveBasis;
use camber_sketch::file::{from_json, to_json, FileError};
use camber_sketch::residuals::Param;
use camber_sketch::vocabulary::{
    CircleSide, Contact, LineSide, Rotation, Sense, TangentForm, Target,
};
use camber_sketch::{Entity, EntityId, Error, HermiteChain, Join, PointRef, Sketch};
use camber_solve::testing::check_jacobian;
use nalgebra::{Point2, Vector2};
use proptest::prelude::*;

fn hermite() -> HermiteChain {
    HermiteChain::single(
        Point2::new(0.0, 0.0),
        Point2::new(4.0, 1.0),
        Vector2::new(3.0, 4.0),
        Vector2::new(5.0, -2.0),
    )
    .unwrap()
}

fn composite() -> HermiteChain {
    HermiteChain::try_new(
        vec![
            Point2::new(0.0, 0.0),
            Point2::new(2.0, 1.5),
            Point2::new(4.0, 0.5),
            Point2::new(6.0, 2.0),
        ],
        vec![
            Vector2::new(2.0, 2.0),
            Vector2::new(2.0, 0.0),
            Vector2::new(2.0, -1.0),
            Vector2::new(2.0, 2.0),
            Vector2::new(2.0, 1.0),
        ],
        vec![Join::Smooth, Join::Corner],
    )
    .unwrap()
}

/// C(u) through the sketch (its linear coefficients on the blocks), through the basis evaluator
/// and through the kernel's Hermite curve and its Bézier conversion all agree.
#[test]
fn a_hermite_entity_evaluates_like_the_kernel_and_its_bezier() {
    let h = hermite();
    let mut s = Sketch::new();
    let id = s.add_entity(Entity::Hermite(h.clone())).unwrap();
    let kernel = HermiteCurve2::try_new(
        Point2::new(0.0, 0.0),
        Point2::new(4.0, 1.0),
        Vector2::new(3.0, 4.0),
        Vector2::new(5.0, -2.0),
    )
    .unwrap();
    // P₁ = p0 + t0/3, P₂ = p1 − t1/3, written out by hand.
    let bezier = BezierCurve2::try_new(vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 4.0 / 3.0),
        Point2::new(4.0 - 5.0 / 3.0, 1.0 + 2.0 / 3.0),
        Point2::new(4.0, 1.0),
    ])
    .unwrap();
    let e = s.entity(id).unwrap();
    let basis = CurveBasis::of(e).unwrap();
    let blocks: Vec<[f64; 2]> = e.points().iter().map(|p| [p.x, p.y]).collect();
    let refs: Vec<&[f64]> = blocks.iter().map(|b| &b[..]).collect();
    for u in [0.0, 0.1, 0.37, 0.5, 0.81, 1.0] {
        let (p, d) = kernel.point_and_derivative(u).unwrap();
        let (q, dq) = bezier.point_and_derivative(u).unwrap();
        assert_relative_eq!(p, q, epsilon = 1e-13);
        assert_relative_eq!(d, dq, epsilon = 1e-12);
        assert_relative_eq!(s.curve_point(id, u).unwrap(), p, epsilon = 1e-13);
        let (c, c1) = basis.eval::<f64>(&refs, u);
        assert_relative_eq!(c[0], p.x, epsilon = 1e-13);
        assert_relative_eq!(c1[1], d.y, epsilon = 1e-12);
        let t1 = e.coefficients(id, u, 1).unwrap();
        let tangent: f64 = t1.iter().map(|(j, k)| k * blocks[*j][0]).sum();
        assert_relative_eq!(tangent, d.x, epsilon = 1e-12);
        let (_, fixed_points) = basis.at(u, 2);
        assert!(fixed_points.windows(2).all(|w| w[0] < w[1]));
    }
    // The ends: C(0) = p0, C′(1) = t1, and `Start`/`End` resolve to the nodes.
    assert_eq!(s.point(PointRef::End(id)).unwrap(), Point2::new(4.0, 1.0));
    assert_relative_eq!(e.point_tangent(1.0).unwrap().1, Vector2::new(5.0, -2.0));
}

/// A composite's sketch evaluation is each segment's Hermite evaluation on [i, i + 1].
#[test]
fn a_composite_entity_evaluates_segment_by_segment() {
    let c = composite();
    let mut s = Sketch::new();
    let id = s.add_entity(Entity::Composite(c.clone())).unwrap();
    assert_eq!(s.entity(id).unwrap().domain(), Some((0.0, 3.0)));
    for (i, local) in [(0, 0.3), (1, 0.0), (1, 0.6), (2, 0.25), (2, 1.0)] {
        let seg = c.segment(i).unwrap();
        let u = i as f64 + local;
        assert_relative_eq!(
            s.curve_point(id, u).unwrap(),
            seg.point(local).unwrap(),
            epsilon = 1e-13
        );
        let t = s.entity(id).unwrap().coefficients(id, u, 1).unwrap();
        let blocks = s.entity(id).unwrap().points();
        let d: Vector2<f64> = t.iter().map(|(j, k)| blocks[*j].coords * *k).sum();
        assert_relative_eq!(d, seg.derivative(local).unwrap(), epsilon = 1e-12);
    }
}

fn max_residual(report: &camber_sketch::SketchReport) -> f64 {
    report
        .components
        .iter()
        .flat_map(|c| c.report.residuals.iter().map(|r| r.max_abs))
        .fold(0.0, f64::max)
}

/// Point at parameter, tangent vector, start tangent and a G1 join from a Hermite curve to a
/// Bézier curve: the affine path solves them, and the geometry satisfies each one.
#[test]
fn affine_constraints_on_a_hermite_curve_solve() {
    let mut s = Sketch::new();
    let h = s.add_entity(Entity::Hermite(hermite())).unwrap();
    let b = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(4.5, 1.0),
                Point2::new(6.0, 0.0),
                Point2::new(8.0, 1.0),
            ])
            .unwrap(),
        )
        .unwrap();
    s.add_constraint(PointAtParameter {
        curve: h,
        u: 0.5,
        target: Target::At(Point2::new(2.0, 2.0)),
    })
    .unwrap();
    s.add_constraint(StartTangent {
        curve: h,
        direction: Vector2::new(0.0, 1.0),
        sense: Sense::Agree,
        form: TangentForm::Row,
    })
    .unwrap();
    s.add_constraint(G1Join {
        first: h,
        second: b,
        direction: Vector2::new(1.0, 0.0),
    })
    .unwrap();
    s.add_constraint(TangentVectorAt {
        curve: b,
        u: 1.0,
        vector: Vector2::new(4.0, 0.0),
    })
    .unwrap();
    let report = s.solve().unwrap();
    assert!(max_residual(&report) < 1e-9, "{report:?}");
    let e = s.entity(h).unwrap();
    assert_relative_eq!(
        s.curve_point(h, 0.5).unwrap(),
        Point2::new(2.0, 2.0),
        epsilon = 1e-9
    );
    let (_, t0) = e.point_tangent(0.0).unwrap();
    assert!(t0.x.abs() < 1e-9 && t0.y > 0.0);
    let (end, t1) = e.point_tangent(1.0).unwrap();
    let second = s.entity(b).unwrap();
    let (start, d0) = second.point_tangent(0.0).unwrap();
    assert_relative_eq!(end, start, epsilon = 1e-9);
    assert!(t1.y.abs() < 1e-9 && t1.x > 0.0 && d0.y.abs() < 1e-9 && d0.x > 0.0);
    // The tangent blocks are unknowns: the start tangent turned to (0, +).
    assert!(s.point(PointRef::Control(h, 2)).unwrap().x.abs() < 1e-9);
}

/// A composite tangent to a line and to a circle at free contact parameters (the nonlinear
/// path), with a point pinned at a parameter inside the middle segment.
#[test]
fn contact_constraints_on_a_composite_solve() {
    let mut s = Sketch::new();
    let c = s.add_entity(Entity::Composite(composite())).unwrap();
    let line = s
        .add_line(Point2::new(-1.0, -0.5), Point2::new(7.0, -0.5))
        .unwrap();
    let circle = s.add_circle(Point2::new(3.0, 4.0), 1.0).unwrap();
    for fixed in [line, circle] {
        s.add_constraint(camber_sketch::constraints::fixed::Fixed {
            target: camber_sketch::vocabulary::FixTarget::Entity(fixed),
        })
        .unwrap();
    }
    s.add_constraint(PointAtParameter {
        curve: c,
        u: 0.0,
        target: Target::At(Point2::new(0.0, 0.0)),
    })
    .unwrap();
    s.add_constraint(TangentToLine {
        curve: c,
        line,
        u: Contact::Free(2.3),
        side: LineSide::Left,
        sense: Sense::Agree,
    })
    .unwrap();
    s.add_constraint(TangentToCircle {
        curve: c,
        circle,
        u: Contact::Free(1.1),
        side: CircleSide::Outside,
        rotation: Rotation::Clockwise,
    })
    .unwrap();
    let report = s.solve().unwrap();
    assert!(max_residual(&report) < 1e-8, "{report:?}");
    // On the curve itself: its lowest point touches y = −0.5, and its closest approach to the
    // circle centre is the radius (dense sampling, so the check does not use the solver).
    let e = s.entity(c).unwrap().clone();
    let curve = e.as_curve().unwrap();
    let samples: Vec<Point2<f64>> = (0..=30_000)
        .map(|k| curve.point(3.0 * f64::from(k) / 30_000.0).unwrap())
        .collect();
    let lowest = samples.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
    assert!((lowest + 0.5).abs() < 1e-6, "lowest {lowest}");
    let nearest = samples
        .iter()
        .map(|p| (p - Point2::new(3.0, 4.0)).norm())
        .fold(f64::INFINITY, f64::min);
    assert!((nearest - 1.0).abs() < 1e-6, "nearest {nearest}");
}

/// Blocks of the composite (nodes then tangents) perturbed by `wave`, then `extra`.
fn chain_blocks(wave: &[f64], extra: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let c = composite();
    let mut out: Vec<Vec<f64>> = c
        .blocks()
        .iter()
        .zip(wave)
        .map(|(p, w)| vec![p.x + w, p.y - w])
        .collect();
    out.extend(extra.iter().cloned());
    out
}

fn jacobian_error<R: camber_solve::Residual>(r: &R, blocks: &[Vec<f64>]) -> f64 {
    let refs: Vec<&[f64]> = blocks.iter().map(|b| &b[..]).collect();
    check_jacobian(r, &refs, 1e-6, 1.0).unwrap().error
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// The contact residuals over a composite curve (free parameter away from the joins, where
    /// the corner's derivative jumps): autodiff against central differences.
    #[test]
    fn composite_contact_jacobians_match_differences(
        wave in proptest::collection::vec(-0.3..0.3f64, 9),
        seg in 0usize..3,
        local in 0.05..0.95f64,
        q in (-2.0..8.0f64, -2.0..4.0f64),
        r in 0.3..2.0f64,
    ) {
        let basis = CurveBasis::of(&Entity::Composite(composite())).unwrap();
        let u = vec![seg as f64 + local];
        let on = OnCurve::new(basis.clone(), Param::Block);
        prop_assert!(jacobian_error(&on, &chain_blocks(&wave, &[u.clone(), vec![q.0, q.1]])) < 1e-6);
        let line = LineContact::new(basis.clone(), Param::Block);
        let ends = [u.clone(), vec![q.0, q.1], vec![q.0 + 3.0, q.1 - 1.0]];
        prop_assert!(jacobian_error(&line, &chain_blocks(&wave, &ends)) < 1e-6);
        let circle = CircleContact::new(basis, Param::Block, true);
        let disc = [u, vec![q.0, q.1], vec![r]];
        prop_assert!(jacobian_error(&circle, &chain_blocks(&wave, &disc)) < 1e-6);
    }

    /// C(u) through the sketch equals the kernel's Hermite segment and its Bézier conversion for
    /// random Hermite data.
    #[test]
    fn random_hermite_curves_match_their_bezier(
        v in proptest::collection::vec(-5.0..5.0f64, 8),
        u in 0.0..=1.0f64,
    ) {
        let (p0, p1) = (Point2::new(v[0], v[1]), Point2::new(v[2], v[3] + 11.0));
        let (t0, t1) = (Vector2::new(v[4], v[5]), Vector2::new(v[6], v[7]));
        let e = Entity::Hermite(HermiteChain::single(p0, p1, t0, t1).unwrap());
        let bezier = BezierCurve2::try_new(vec![p0, p0 + t0 / 3.0, p1 - t1 / 3.0, p1]).unwrap();
        let terms = e.coefficients(EntityId(0), u, 0).unwrap();
        let c: Vector2<f64> = terms.iter().map(|(j, k)| e.points()[*j].coords * *k).sum();
        let b = bezier.point(u).unwrap();
        prop_assert!((c - b.coords).norm() < 1e-12);
    }
}

#[test]
fn the_file_form_round_trips_and_names_bad_fields() {
    let mut s = Sketch::new();
    s.add_entity(Entity::Hermite(hermite())).unwrap();
    s.add_entity(Entity::Composite(composite())).unwrap();
    let text = to_json(&s).unwrap();
    assert!(
        text.contains("\"hermite\"") && text.contains("\"corner\""),
        "{text}"
    );
    let back = from_json(&text).unwrap();
    for (id, e) in s.entities() {
        assert_eq!(back.entity(id).unwrap(), e);
    }
    assert_eq!(to_json(&back).unwrap(), text);

    let bad_count = r#"{"version": 1, "entities": [{"id": 7, "kind": "composite",
        "nodes": [[0,0],[1,0],[2,1]], "tangents": [[1,0],[1,0]], "joins": ["smooth"]}]}"#;
    let version = camber_sketch::file::FORMAT_VERSION;
    let bad_count = bad_count.replace("\"version\": 1", &format!("\"version\": {version}"));
    assert_eq!(
        from_json(&bad_count).unwrap_err(),
        FileError::Entity {
            id: 7,
            kind: "composite",
            source: Error::CountMismatch {
                field: "tangents",
                expected: 3,
                found: 2
            }
        }
    );
    let bad_join = bad_count.replace("\"smooth\"", "\"kinked\"");
    match from_json(&bad_join).unwrap_err() {
        FileError::Shape { path, .. } => assert_eq!(path, "entities[0].joins[0]"),
        other => panic!("{other:?}"),
    }
    let bad_tangent = format!(
        r#"{{"version": {version}, "entities": [{{"id": 3, "kind": "hermite",
        "p0": [0,0], "p1": [1,0], "t0": [1,0]}}]}}"#
    );
    match from_json(&bad_tangent).unwrap_err() {
        FileError::Shape { path, message } => {
            assert_eq!(path, "entities[0]");
            assert!(message.contains("t1"), "{message}");
        }
        other => panic!("{other:?}"),
    }
    // All its positions at one place: refused, naming the entity.
    let flat = format!(
        r#"{{"version": {version}, "entities": [{{"id": 4, "kind": "hermite",
        "p0": [1,1], "p1": [1,1], "t0": [0,0], "t1": [0,0]}}]}}"#
    );
    assert!(matches!(
        from_json(&flat).unwrap_err(),
        FileError::Entity {
            id: 4,
            kind: "hermite",
            source: Error::DegenerateEntity { .. }
        }
    ));
}

/// A Hermite entity must keep one segment; the editor's rebuild keeps block counts.
#[test]
fn a_multi_segment_hermite_is_refused_and_rebuilds_keep_counts() {
    let mut s = Sketch::new();
    assert!(matches!(
        s.add_entity(Entity::Hermite(composite())),
        Err(Error::DegenerateEntity {
            kind: "Hermite curve",
            ..
        })
    ));
    let e = Entity::Composite(composite());
    assert!(matches!(
        e.with_points(&e.points()[1..], &[]),
        Err(Error::CountMismatch {
            field: "blocks",
            ..
        })
    ));
    let moved: Vec<Point2<f64>> = e
        .points()
        .iter()
        .map(|p| p + Vector2::new(1.0, 0.0))
        .collect();
    let rebuilt = e.with_points(&moved, &[]).unwrap();
    assert_eq!(rebuilt.points(), moved.as_slice());
    assert!(e.is_tangent_block(4) && !e.is_tangent_block(3));
}

/// The bundled example (examples/sketches/hermite_composite.json) loads, solves, round-trips,
/// and its solved geometry satisfies every constraint when measured on the curves.
#[test]
fn the_bundled_example_solves_to_valid_geometry() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/sketches/hermite_composite.json");
    let mut s = from_json(&std::fs::read_to_string(path).unwrap()).unwrap();
    let report = s.solve().unwrap();
    assert!(max_residual(&report) < 1e-9, "{report:?}");
    assert_eq!(
        to_json(&from_json(&to_json(&s).unwrap()).unwrap()).unwrap(),
        to_json(&s).unwrap()
    );
    let composite = s.entity(EntityId(0)).unwrap().clone();
    let hermite = s.entity(EntityId(1)).unwrap().clone();
    let curve = composite.as_curve().unwrap();
    assert_relative_eq!(curve.point(0.0).unwrap(), Point2::origin(), epsilon = 1e-12);
    let samples: Vec<Point2<f64>> = (0..=30_000)
        .map(|k| curve.point(3.0 * f64::from(k) / 30_000.0).unwrap())
        .collect();
    // Tangent to y = 0 from above (the start point lies on it too), outside the circle.
    let lowest = samples.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
    assert!(lowest.abs() < 1e-6, "lowest {lowest}");
    let nearest = samples
        .iter()
        .map(|p| (p - Point2::new(2.0, 3.0)).norm())
        .fold(f64::INFINITY, f64::min);
    assert!((nearest - 1.0).abs() < 1e-6, "nearest {nearest}");
    // G1 join along (2, 1); the Hermite end at (9, 0.5) heading down.
    let (end, d) = composite.point_tangent(3.0).unwrap();
    let (start, e) = hermite.point_tangent(0.0).unwrap();
    assert_relative_eq!(end, start, epsilon = 1e-9);
    for t in [d, e] {
        assert!((t.x - 2.0 * t.y).abs() < 1e-9 * t.norm() && t.x > 0.0);
    }
    let (p1, t1) = hermite.point_tangent(1.0).unwrap();
    assert_relative_eq!(p1, Point2::new(9.0, 0.5), epsilon = 1e-9);
    assert!(t1.x.abs() < 1e-9 && t1.y < 0.0);
}

/// The bundled example's DOF by hand: 24 free unknowns (the composite's 3 free nodes and 5
/// tangents, its first node fixed: 16; the Hermite's start point and two tangents, its end held
/// by the point-at-parameter: 6; the two contact parameters: 2) less 9 independent rows (2 per
/// contact, 2 for the join's position, 1 for each side's tangent along (2, 1), 1 for the end
/// tangent) is 15. The solve needs an active row of honest contact, an inequality, which takes
/// no dimension from the solution set: the solve report once counted it (DOF 14).
#[test]
fn the_bundled_example_reports_the_same_dof_solved_and_checked() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/sketches/hermite_composite.json");
    let mut s = from_json(&std::fs::read_to_string(path).unwrap()).unwrap();
    let before = s.analyze().unwrap();
    assert_eq!(before.len(), 1);
    assert_eq!(before[0].analysis.free_unknowns, 24);
    assert_eq!(before[0].analysis.rank, 9);
    assert_eq!(before[0].analysis.dof, 15);
    let report = s.solve().unwrap();
    let solved = &report.components[0].report;
    assert!(solved.reason.contains("active row"), "{}", solved.reason);
    assert_eq!((solved.rank, solved.dof), (9, 15), "{solved:?}");
    let after = s.analyze().unwrap();
    assert_eq!((after[0].analysis.rank, after[0].analysis.dof), (9, 15));
}

/// The curve passes through the point at its own free parameter s: C(s) − P = 0.
#[derive(Debug)]
struct Through;

impl camber_sketch::CustomResidual for Through {
    fn name(&self) -> &str {
        "through"
    }
    fn dim(&self) -> usize {
        2
    }
    fn arg_kinds(&self) -> Vec<camber_sketch::ArgKind> {
        use camber_sketch::ArgKind;
        vec![ArgKind::Curve, ArgKind::Point, ArgKind::Scalar]
    }
    fn eval<T: camber_solve::Scalar>(&self, a: &camber_sketch::Args<'_, T>, out: &mut [T]) {
        let (c, p) = (a.curve(0).point(a.scalar(2)), a.point(1));
        out[0] = c[0] - p[0];
        out[1] = c[1] - p[1];
    }
}

/// A custom constraint reads a composite curve like any other: its blocks (nodes and
/// tangents) through the same basis, and the solve puts the point on the curve.
#[test]
fn a_custom_constraint_reads_a_composite_curve() {
    use camber_sketch::{Arg, Custom};
    let mut s = Sketch::new();
    let c = s.add_entity(Entity::Composite(composite())).unwrap();
    let p = s.add_point(Point2::new(3.0, 2.0)).unwrap();
    s.add_constraint(camber_sketch::constraints::fixed::Fixed {
        target: camber_sketch::vocabulary::FixTarget::Point(PointRef::Point(p)),
    })
    .unwrap();
    let id = s
        .add_constraint(Custom::with_args(
            Through,
            vec![
                Arg::Curve(c),
                Arg::Point(PointRef::Point(p)),
                Arg::Param(1.4),
            ],
        ))
        .unwrap();
    let report = s.solve().unwrap();
    assert!(max_residual(&report) < 1e-9, "{report:?}");
    let Some(Arg::Param(u)) = s.constraint(id).unwrap().as_custom().map(|k| k.args()[2]) else {
        panic!("the custom constraint keeps its parameter");
    };
    // Checked through the kernel's evaluation of the solved entity, not the residual.
    let on = s.entity(c).unwrap().as_curve().unwrap().point(u).unwrap();
    assert_relative_eq!(on, Point2::new(3.0, 2.0), epsilon = 1e-9);
}

/// A sketch with the start and end tangencies in the given form (`"row"` or `"elimination"`).
fn with_form(template: &str, form: &str) -> Sketch {
    from_json(&template.replace("FORM", form)).unwrap()
}

/// The elimination form of the end tangencies on a Hermite curve: its end tangents are
/// themselves unknowns, T = t·d with t ≥ 0. Ends fixed and the midpoint pinned determine the
/// curve: C(½) = (p0 + p1)/2 + (t0 − t1)/8 = (2, 0) + ((α, 0) − (0, −β))/8 = (2.5, 1) gives
/// α = 4, β = 8. Row and elimination forms land on that one solution.
#[test]
fn hermite_end_tangents_eliminate_like_their_rows() {
    let template = r#"{"version": 1,
      "entities": [{"id": 0, "kind": "hermite", "p0": [0, 0], "p1": [4, 0],
                    "t0": [3, 1], "t1": [1, -3]}],
      "constraints": [
        {"id": 1, "kind": "fixed", "target": {"point": {"start": 0}}},
        {"id": 2, "kind": "fixed", "target": {"point": {"end": 0}}},
        {"id": 3, "kind": "start_tangent", "curve": 0, "direction": [1, 0], "sense": "agree", "form": "FORM"},
        {"id": 4, "kind": "end_tangent", "curve": 0, "direction": [0, -1], "sense": "agree", "form": "FORM"},
        {"id": 5, "kind": "point_at_parameter", "curve": 0, "u": 0.5, "target": {"at": [2.5, 1]}}
      ]}"#;
    let mut solved = Vec::new();
    for form in ["row", "elimination"] {
        let mut s = with_form(template, form);
        let before = s.analyze().unwrap();
        assert_eq!(
            before[0].analysis.dof, 0,
            "{form}: {:?}",
            before[0].analysis
        );
        // Rows: two tangent unknowns each; eliminated: one length each.
        let unknowns = if form == "row" { 4 } else { 2 };
        assert_eq!(before[0].analysis.free_unknowns, unknowns, "{form}");
        let report = s.solve().unwrap();
        assert!(max_residual(&report) < 1e-9, "{form}: {report:?}");
        assert_eq!(report.components[0].report.dof, 0, "{form}");
        let blocks = match s.entity(EntityId(0)).unwrap() {
            Entity::Hermite(c) => c.blocks().to_vec(),
            other => panic!("{other:?}"),
        };
        assert_relative_eq!(blocks[2], Point2::new(4.0, 0.0), epsilon = 1e-9);
        assert_relative_eq!(blocks[3], Point2::new(0.0, -8.0), epsilon = 1e-9);
        solved.push(blocks);
    }
    for (a, b) in solved[0].iter().zip(&solved[1]) {
        assert_relative_eq!(a, b, epsilon = 1e-9);
    }
}

/// The same on a composite of two segments with a smooth join: nodes fixed, start tangent
/// along (1, 1), end tangent along (1, −1), C(½) = (N₀ + N₁)/2 + (a₀ − t₁)/8 and
/// C(3/2) = (N₁ + N₂)/2 + (t₁ − b₂)/8 pinned: a₀ = (2, 2), t₁ = (2, 0), b₂ = (3, −3) give
/// (1, 0.75) and (2.875, 0.875), and the four equations in α, β and t₁ have only that solution.
#[test]
fn composite_end_tangents_eliminate_like_their_rows() {
    let template = r#"{"version": 1,
      "entities": [{"id": 0, "kind": "composite", "nodes": [[0, 0], [2, 1], [4, 0]],
                    "tangents": [[1, 0.3], [1, 1], [2, 0]], "joins": ["smooth"]}],
      "constraints": [
        {"id": 1, "kind": "fixed", "target": {"point": {"control": [0, 0]}}},
        {"id": 2, "kind": "fixed", "target": {"point": {"control": [0, 1]}}},
        {"id": 3, "kind": "fixed", "target": {"point": {"control": [0, 2]}}},
        {"id": 4, "kind": "start_tangent", "curve": 0, "direction": [1, 1], "sense": "agree", "form": "FORM"},
        {"id": 5, "kind": "end_tangent", "curve": 0, "direction": [1, -1], "sense": "agree", "form": "FORM"},
        {"id": 6, "kind": "point_at_parameter", "curve": 0, "u": 0.5, "target": {"at": [1, 0.75]}},
        {"id": 7, "kind": "point_at_parameter", "curve": 0, "u": 1.5, "target": {"at": [2.875, 0.875]}}
      ]}"#;
    let expected = [
        Point2::new(2.0, 2.0),
        Point2::new(2.0, 0.0),
        Point2::new(3.0, -3.0),
    ];
    let mut solved = Vec::new();
    for form in ["row", "elimination"] {
        let mut s = with_form(template, form);
        let report = s.solve().unwrap();
        assert!(max_residual(&report) < 1e-9, "{form}: {report:?}");
        assert_eq!(report.components[0].report.dof, 0, "{form}");
        let blocks = match s.entity(EntityId(0)).unwrap() {
            Entity::Composite(c) => c.blocks().to_vec(),
            other => panic!("{other:?}"),
        };
        for (got, want) in blocks[3..].iter().zip(&expected) {
            assert_relative_eq!(got, want, epsilon = 1e-9);
        }
        solved.push(blocks);
    }
    for (a, b) in solved[0].iter().zip(&solved[1]) {
        assert_relative_eq!(a, b, epsilon = 1e-9);
    }
}

/// The bundled example (nonlinear: contacts with a line and a circle, a G1 join) with its
/// Hermite end tangent in elimination form: it solves, the end tangent points down as asked,
/// and the DOF is the row form's (the elimination trades one unknown for one row).
#[test]
fn the_bundled_example_solves_with_an_eliminated_end_tangent() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/sketches/hermite_composite.json");
    let text = std::fs::read_to_string(path).unwrap();
    assert!(text.contains(r#""form":"row""#));
    let mut dof = Vec::new();
    for form in ["row", "elimination"] {
        let mut s =
            from_json(&text.replace(r#""form":"row""#, &format!(r#""form":"{form}""#))).unwrap();
        let report = s.solve().unwrap();
        assert!(max_residual(&report) < 1e-9, "{form}: {report:?}");
        let hermite = s.entity(EntityId(1)).unwrap();
        let (p1, t1) = hermite.point_tangent(1.0).unwrap();
        assert_relative_eq!(p1, Point2::new(9.0, 0.5), epsilon = 1e-9);
        assert!(t1.x.abs() < 1e-9 && t1.y < 0.0, "{form}: {t1}");
        dof.push(report.components[0].report.dof);
    }
    assert_eq!(dof[0], dof[1]);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Random determined Hermite curves: ends fixed, end tangent directions d0, d1 and the
    /// midpoint C(½) = (p0 + p1)/2 + (α·d0 − β·d1)/8 pinned, α, β > 0 (unique when d0 and d1
    /// are not parallel). Row and elimination forms both recover α·d0 and β·d1.
    #[test]
    fn eliminated_hermite_tangents_match_the_rows(
        ends in prop::array::uniform4(-3.0..3.0_f64),
        angles in prop::array::uniform2(0.0..std::f64::consts::TAU),
        lengths in prop::array::uniform2(0.5..4.0_f64),
    ) {
        let (d0, d1) = (
            Vector2::new(angles[0].cos(), angles[0].sin()),
            Vector2::new(angles[1].cos(), angles[1].sin()),
        );
        prop_assume!((d0.x * d1.y - d0.y * d1.x).abs() > 0.2);
        let (p0, p1) = (Point2::new(ends[0], ends[1]), Point2::new(ends[2], ends[3]));
        prop_assume!((p1 - p0).norm() > 0.5);
        let (t0, t1) = (d0 * lengths[0], d1 * lengths[1]);
        let mid = Point2::from((p0.coords + p1.coords) / 2.0 + (t0 - t1) / 8.0);
        let mut solved = Vec::new();
        for form in [TangentForm::Row, TangentForm::Elimination] {
            // Start from tangents turned 20° off and of other lengths.
            let turn = nalgebra::Rotation2::new(0.35);
            let mut s = Sketch::new();
            let h = s
                .add_entity(Entity::Hermite(
                    HermiteChain::single(p0, p1, turn * t0 * 1.3, turn * t1 * 0.8).unwrap(),
                ))
                .unwrap();
            for j in [0, 1] {
                s.add_constraint(camber_sketch::constraints::fixed::Fixed::point(
                    PointRef::Control(h, j),
                ))
                .unwrap();
            }
            s.add_constraint(StartTangent { curve: h, direction: d0, sense: Sense::Agree, form })
                .unwrap();
            s.add_constraint(camber_sketch::constraints::end_tangent::EndTangent {
                curve: h,
                direction: d1,
                sense: Sense::Agree,
                form,
            })
            .unwrap();
            s.add_constraint(PointAtParameter { curve: h, u: 0.5, target: Target::At(mid) })
                .unwrap();
            let report = s.solve().unwrap();
            prop_assert!(max_residual(&report) < 1e-9);
            let blocks = match s.entity(h).unwrap() {
                Entity::Hermite(c) => c.blocks().to_vec(),
                _ => unreachable!(),
            };
            prop_assert!((blocks[2].coords - t0).norm() < 1e-8, "{:?}: {:?} vs {}", form, blocks, t0);
            prop_assert!((blocks[3].coords - t1).norm() < 1e-8, "{:?}: {:?} vs {}", form, blocks, t1);
            solved.push(blocks);
        }
        for (a, b) in solved[0].iter().zip(&solved[1]) {
            prop_assert!((a - b).norm() < 1e-8);
        }
    }
}
