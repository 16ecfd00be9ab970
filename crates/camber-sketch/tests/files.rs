//! Sketch files: every bundled sketch loads, solves and survives save∘load unchanged; every
//! entity and constraint kind round-trips with its id; bad files fail with the JSON path or the
//! id of the offending item; custom kinds go through the registry.
//!
//! The bundled files are generated here: `CAMBER_BLESS=1 cargo test -p camber-sketch --test
//! files` rewrites them from the builders below; without it the test checks they match.

#![allow(clippy::unwrap_used)] // helpers outside #[test] fns unwrap like the tests do

use std::path::PathBuf;

use approx::assert_abs_diff_eq;
use camber_geom::{BSplineCurve2, BezierCurve2, KnotVector, NurbsCurve2};
use camber_sketch::constraints::{
    Angle, Coincident, CurveCurveTangent, DirectionalTangentAt, Distance, EndTangent, Fixed,
    G1Join, G1JoinFree, G2Join, Parallel, Perpendicular, PointAtParameter, PointOnCircle,
    PointOnCurve, Radius, StartTangent, TangentToCircle, TangentToLine, TangentToLineAt,
    TangentVectorAt,
};
use camber_sketch::file::{from_json, from_json_with, to_json, CustomRegistry, FileError};
use camber_sketch::{
    CircleSide, Constraint, Contact, Custom, EntityId, Error, FixTarget, LineSide, PointRef,
    Rotation, Sense, Sketch, TangentForm, Target,
};
use camber_solve::{Residual, Scalar};
use nalgebra::{Point2, Vector2};

fn sketches_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/sketches")
}

/// The blade section of the paper: pressure side, leading edge, suction side and a trailing
/// edge cap, four quintic/cubic Béziers joined G1 in a closed loop with the joint directions
/// fixed, and the two trailing-edge corners fixed.
fn blade_section() -> Sketch {
    let pts = |v: &[(f64, f64)]| v.iter().map(|(x, y)| Point2::new(*x, *y)).collect();
    let mut s = Sketch::new();
    let mut bez = |v: &[(f64, f64)]| s.add_bezier(BezierCurve2::try_new(pts(v)).unwrap());
    let pressure = bez(&[
        (1.0, -0.004),
        (0.8, -0.04),
        (0.6, -0.06),
        (0.35, -0.06),
        (0.15, -0.045),
        (0.05, -0.03),
    ])
    .unwrap();
    let leading = bez(&[
        (0.05, -0.03),
        (0.0, -0.0225),
        (-0.01, -0.01),
        (-0.01, 0.01),
        (0.0, 0.03),
        (0.05, 0.04),
    ])
    .unwrap();
    let suction = bez(&[
        (0.05, 0.04),
        (0.15, 0.06),
        (0.35, 0.08),
        (0.6, 0.075),
        (0.8, 0.05),
        (1.0, 0.004),
    ])
    .unwrap();
    let trailing = bez(&[(1.0, 0.004), (1.006, 0.003), (1.006, -0.003), (1.0, -0.004)]).unwrap();
    let join = |s: &mut Sketch, first: EntityId, second: EntityId, d: (f64, f64)| {
        s.add_constraint(G1Join {
            first,
            second,
            direction: Vector2::new(d.0, d.1),
        })
        .unwrap();
    };
    join(&mut s, pressure, leading, (-0.1, 0.015));
    join(&mut s, leading, suction, (0.05, 0.01));
    join(&mut s, suction, trailing, (1.0, -0.2));
    join(&mut s, trailing, pressure, (-1.0, -0.15));
    for p in [PointRef::Start(trailing), PointRef::End(trailing)] {
        s.add_constraint(Fixed::point(p)).unwrap();
    }
    s
}

/// Checks (or, with CAMBER_BLESS=1, writes) a bundled file against its builder.
fn bundled(name: &str, sketch: &Sketch) {
    let path = sketches_dir().join(name);
    let text = to_json(sketch).unwrap();
    if std::env::var_os("CAMBER_BLESS").is_some() {
        std::fs::create_dir_all(sketches_dir()).unwrap();
        std::fs::write(&path, &text).unwrap();
    }
    let on_disk = std::fs::read_to_string(&path).unwrap();
    assert_eq!(
        on_disk, text,
        "{name} is out of date: rerun with CAMBER_BLESS=1"
    );
}

#[test]
fn bundled_files_match_their_builders() {
    bundled("blade_section.json", &blade_section());
    bundled(
        "w3a_chain_1000.json",
        &camber_workloads::w3a_chain(1000).unwrap().0,
    );
}

#[test]
fn every_bundled_file_loads_solves_and_round_trips() {
    let mut seen = 0;
    for entry in std::fs::read_dir(sketches_dir()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("json") {
            continue;
        }
        seen += 1;
        let text = std::fs::read_to_string(&path).unwrap();
        let mut sketch = from_json(&text).unwrap();
        assert_eq!(to_json(&sketch).unwrap(), text, "{}", path.display());
        let report = sketch.solve().unwrap();
        assert!(!report.components.is_empty());
        // Constraints a priority let go are named in the report; every other one holds.
        let relaxed = report.relaxed();
        for c in &report.components {
            for r in c
                .report
                .residuals
                .iter()
                .filter(|r| !relaxed.contains(&r.constraint))
            {
                assert!(r.max_abs < 1e-9, "{}: {r:?}", path.display());
            }
        }
        // The solved sketch round-trips too.
        let solved = to_json(&sketch).unwrap();
        assert_eq!(to_json(&from_json(&solved).unwrap()).unwrap(), solved);
    }
    assert!(seen >= 2);
}

/// A sketch with every entity kind and every built-in constraint kind.
fn every_kind() -> Sketch {
    let mut s = Sketch::new();
    let p = s.add_point(Point2::new(0.5, 2.0)).unwrap();
    let line = s
        .add_line(Point2::new(-1.0, 0.0), Point2::new(-1.0, 1.0))
        .unwrap();
    let line2 = s
        .add_line(Point2::new(2.0, -1.0), Point2::new(4.0, -0.5))
        .unwrap();
    let circle = s.add_circle(Point2::new(3.0, 3.0), 0.75).unwrap();
    let bez = s
        .add_bezier(
            BezierCurve2::try_new(vec![
                Point2::new(0.0, 0.0),
                Point2::new(1.0, 1.0),
                Point2::new(2.0, 1.0),
                Point2::new(3.0, 0.0),
            ])
            .unwrap(),
        )
        .unwrap();
    let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]).unwrap();
    let cps: Vec<_> = (0..4)
        .map(|i| Point2::new(f64::from(i), f64::from(i % 2)))
        .collect();
    let bs = s
        .add_bspline(BSplineCurve2::try_new(2, knots.clone(), cps.clone()).unwrap())
        .unwrap();
    let nu = s
        .add_nurbs(NurbsCurve2::try_new(2, knots, cps, vec![1.0, 0.7, 1.3, 1.0]).unwrap())
        .unwrap();
    let cs = [
        Constraint::Fixed(Fixed {
            target: FixTarget::Entity(circle),
        }),
        Constraint::Fixed(Fixed {
            target: FixTarget::Point(PointRef::Control(line, 0)),
        }),
        Constraint::Coincident(Coincident {
            a: PointRef::Point(p),
            b: PointRef::End(bez),
        }),
        Constraint::PointAtParameter(PointAtParameter {
            curve: bs,
            u: 0.25,
            target: Target::At(Point2::new(0.1, 0.2)),
        }),
        Constraint::PointAtParameter(PointAtParameter {
            curve: nu,
            u: 0.75,
            target: Target::Point(PointRef::Start(bs)),
        }),
        Constraint::TangentVectorAt(TangentVectorAt {
            curve: bez,
            u: 0.5,
            vector: Vector2::new(3.0, 0.1),
        }),
        Constraint::DirectionalTangentAt(DirectionalTangentAt {
            curve: nu,
            u: 0.3,
            direction: Vector2::new(1.0, 0.2),
            sense: Sense::Oppose,
        }),
        Constraint::StartTangent(StartTangent {
            curve: bez,
            direction: Vector2::new(1.0, 1.0),
            sense: Sense::Agree,
            form: TangentForm::Elimination,
        }),
        Constraint::EndTangent(EndTangent {
            curve: bs,
            direction: Vector2::new(1.0, -1.0),
            sense: Sense::Oppose,
            form: TangentForm::Row,
        }),
        Constraint::TangentToLineAt(TangentToLineAt {
            curve: nu,
            u: 0.9,
            point: Point2::new(0.0, 5.0),
            direction: Vector2::new(1.0, 0.0),
            sense: Sense::Agree,
        }),
        Constraint::G1Join(G1Join {
            first: bs,
            second: nu,
            direction: Vector2::new(1.0, 0.0),
        }),
        Constraint::PointOnCurve(PointOnCurve {
            point: PointRef::Point(p),
            curve: bez,
            u: Contact::Free(0.4),
        }),
        Constraint::TangentToLine(TangentToLine {
            curve: bs,
            line,
            u: Contact::Free(0.5),
            side: LineSide::Left,
            sense: Sense::Oppose,
        }),
        Constraint::TangentToCircle(TangentToCircle {
            curve: nu,
            circle,
            u: Contact::At(0.6),
            side: CircleSide::Outside,
            rotation: Rotation::Clockwise,
        }),
        Constraint::PointOnCircle(PointOnCircle {
            point: PointRef::Control(line2, 1),
            circle,
        }),
        Constraint::Radius(Radius {
            circle,
            radius: 0.75,
        }),
        Constraint::Distance(Distance {
            a: PointRef::Control(line, 0),
            b: PointRef::Control(line2, 0),
            distance: 2.0,
        }),
        Constraint::Parallel(Parallel {
            first: line,
            second: line2,
        }),
        Constraint::Perpendicular(Perpendicular {
            first: line,
            second: line2,
        }),
        Constraint::Angle(Angle {
            first: line,
            second: line2,
            angle: 0.3,
        }),
        Constraint::G1JoinFree(G1JoinFree {
            first: bez,
            second: bs,
        }),
        Constraint::G2Join(G2Join {
            first: bs,
            second: nu,
        }),
        Constraint::CurveCurveTangent(CurveCurveTangent {
            first: bez,
            u: Contact::Free(0.2),
            second: nu,
            v: Contact::At(0.8),
            sense: Sense::Oppose,
        }),
    ];
    for c in cs {
        s.add_constraint(c).unwrap();
    }
    s
}

#[test]
fn every_kind_round_trips_with_its_ids() {
    let s = every_kind();
    let text = to_json(&s).unwrap();
    let back = from_json(&text).unwrap();
    let ids = |s: &Sketch| {
        (
            s.entities()
                .map(|(id, e)| (id, e.clone()))
                .collect::<Vec<_>>(),
            s.constraints()
                .map(|(id, c)| (id, c.clone()))
                .collect::<Vec<_>>(),
        )
    };
    assert_eq!(ids(&back), ids(&s));
    assert_eq!(to_json(&back).unwrap(), text);
    for tag in [
        "\"point\"",
        "\"line\"",
        "\"circle\"",
        "\"bezier\"",
        "\"bspline\"",
        "\"nurbs\"",
        "\"fixed\"",
        "\"coincident\"",
        "\"point_at_parameter\"",
        "\"tangent_vector_at\"",
        "\"directional_tangent_at\"",
        "\"start_tangent\"",
        "\"end_tangent\"",
        "\"tangent_to_line_at\"",
        "\"g1_join\"",
        "\"point_on_curve\"",
        "\"tangent_to_line\"",
        "\"tangent_to_circle\"",
        "\"point_on_circle\"",
        "\"radius\"",
        "\"distance\"",
        "\"parallel\"",
        "\"perpendicular\"",
        "\"angle\"",
        "\"g1_join_free\"",
        "\"g2_join\"",
        "\"curve_curve_tangent\"",
        "\"free\"",
        "\"clockwise\"",
        "\"outside\"",
        "\"left\"",
    ] {
        assert!(text.contains(tag), "{tag} missing");
    }
}

#[test]
fn ids_are_kept_and_new_ids_continue_after_them() {
    let text = r#"{"version": 1,
      "entities": [{"id": 10, "kind": "point", "at": [0, 0]}, {"id": 4, "kind": "point", "at": [1, 0]}],
      "constraints": [{"id": 20, "kind": "coincident", "a": {"point": 10}, "b": {"point": 4}}]}"#;
    let mut s = from_json(text).unwrap();
    assert!(s.entity(EntityId(4)).is_ok() && s.entity(EntityId(10)).is_ok());
    assert_eq!(s.add_point(Point2::origin()).unwrap(), EntityId(21));
    s.solve().unwrap();
    let a = s.point(PointRef::Point(EntityId(10))).unwrap();
    let b = s.point(PointRef::Point(EntityId(4))).unwrap();
    assert_abs_diff_eq!(a.x, b.x, epsilon = 1e-12);
}

fn load_err(text: &str) -> FileError {
    from_json(text).unwrap_err()
}

#[test]
fn bad_files_name_the_path_or_the_id() {
    // Syntax.
    assert!(matches!(
        load_err("{\"version\": 1,"),
        FileError::Syntax { .. }
    ));
    // A number outside the f64 range cannot become a coordinate.
    let e =
        load_err(r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [1e999, 0]}]}"#);
    assert!(
        matches!(&e, FileError::Syntax { message } if message.starts_with("non-finite number"))
    );
    // Version.
    assert_eq!(
        load_err(r#"{"version": 2}"#),
        FileError::Version { found: "2".into() }
    );
    assert!(matches!(load_err("{}"), FileError::Version { .. }));
    // Shape, with the path.
    let e = load_err(
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0, 0]}],
            "constraints": [{"id": 1, "kind": "g1_join", "first": "zero", "second": 0, "direction": [1, 0]}]}"#,
    );
    assert!(
        matches!(&e, FileError::Shape { path, .. } if path.starts_with("constraints[0]")),
        "{e}"
    );
    let e = load_err(r#"{"version": 1, "entities": [{"id": 0, "kind": "spiral"}]}"#);
    assert!(
        matches!(&e, FileError::Shape { path, message } if path.starts_with("entities[0]") && message.contains("spiral")),
        "{e}"
    );
    let e = load_err(r#"{"version": 1, "entitis": []}"#);
    assert!(matches!(&e, FileError::Shape { message, .. } if message.contains("entitis")));
    // The sketch's own checks, with the id.
    let e = load_err(
        r#"{"version": 1, "entities": [{"id": 0, "kind": "bezier", "control_points": [[0, 0], [1, 0]]}],
            "constraints": [{"id": 5, "kind": "g1_join", "first": 0, "second": 9, "direction": [1, 0]}]}"#,
    );
    assert_eq!(
        e,
        FileError::Constraint {
            id: 5,
            kind: "g1_join".into(),
            source: Error::UnknownEntity {
                entity: EntityId(9)
            }
        }
    );
    assert_eq!(
        e.to_string(),
        "constraint 5 (g1_join): entity 9 does not exist"
    );
    let e = load_err(
        r#"{"version": 1, "entities": [{"id": 3, "kind": "bspline", "degree": 2, "knots": [0, 0, 0, 1, 1],
            "control_points": [[0, 0], [1, 1], [2, 0]]}]}"#,
    );
    assert!(
        matches!(
            &e,
            FileError::Entity {
                id: 3,
                kind: "bspline",
                source: Error::Geometry(_)
            }
        ),
        "{e}"
    );
    let e = load_err(
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0, 0]}, {"id": 0, "kind": "point", "at": [1, 0]}]}"#,
    );
    assert!(matches!(
        e,
        FileError::Entity {
            id: 0,
            source: Error::DuplicateId { id: 0 },
            ..
        }
    ));
    let e = load_err(
        r#"{"version": 1, "entities": [{"id": 0, "kind": "circle", "center": [0, 0], "radius": -1}]}"#,
    );
    assert!(matches!(e, FileError::Entity { id: 0, .. }), "{e}");
    let e = load_err(
        r#"{"version": 1, "entities": [{"id": 0, "kind": "bezier", "control_points": [[0, 0], [1, 0]]}],
            "constraints": [{"id": 1, "kind": "point_at_parameter", "curve": 0, "u": 1.5, "target": {"at": [0, 0]}}]}"#,
    );
    assert!(
        matches!(
            &e,
            FileError::Constraint {
                id: 1,
                source: Error::ParameterOutsideDomain { .. },
                ..
            }
        ),
        "{e}"
    );
}

/// q.x − p.x = gap, a one-row affine custom residual.
#[derive(Debug)]
struct Gap(f64);

impl Residual for Gap {
    fn name(&self) -> &str {
        "gap"
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = x[1][0] - x[0][0] - nalgebra::convert::<f64, T>(self.0);
    }
    fn is_affine(&self) -> bool {
        true
    }
}

fn registry() -> CustomRegistry {
    let mut r = CustomRegistry::new();
    r.register("gap", |params, args| {
        let gap = params
            .get("gap")
            .and_then(serde_json::Value::as_f64)
            .ok_or_else(|| "needs a number \"gap\"".to_owned())?;
        Ok(Custom::plain(Gap(gap), args))
    });
    r
}

const GAP_FILE: &str = r#"{"version": 1,
  "entities": [{"id": 0, "kind": "point", "at": [0, 0]}, {"id": 1, "kind": "point", "at": [5, 1]}],
  "constraints": [
    {"id": 2, "kind": "fixed", "target": {"point": {"point": 0}}},
    {"id": 3, "kind": "custom", "name": "gap", "points": [{"point": 0}, {"point": 1}], "params": {"gap": 2.5}}
  ]}"#;

#[test]
fn registered_custom_kinds_load_solve_and_save() {
    let reg = registry();
    let mut s = from_json_with(GAP_FILE, &reg).unwrap();
    s.solve().unwrap();
    let q = s.point(PointRef::Point(EntityId(1))).unwrap();
    assert_abs_diff_eq!(q.x, 2.5, epsilon = 1e-12);
    let text = to_json(&s).unwrap();
    assert!(text.contains("\"custom\"") && text.contains("\"params\":{\"gap\":2.5}"));
    assert_eq!(
        to_json(&from_json_with(&text, &reg).unwrap()).unwrap(),
        text
    );
}

#[test]
fn unregistered_or_refused_custom_kinds_fail_plainly() {
    assert_eq!(
        from_json(GAP_FILE).unwrap_err(),
        FileError::UnregisteredCustom {
            id: 3,
            name: "gap".into()
        }
    );
    let bad = GAP_FILE.replace("{\"gap\": 2.5}", "{\"width\": 2.5}");
    let e = from_json_with(&bad, &registry()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "constraint 3: custom kind \"gap\": needs a number \"gap\""
    );
    // A custom constraint built in code without a file form cannot be saved.
    let mut s = Sketch::new();
    let a = s.add_point(Point2::origin()).unwrap();
    let b = s.add_point(Point2::new(1.0, 0.0)).unwrap();
    let id = s
        .add_constraint(Constraint::Custom(Custom::new(
            Gap(1.0),
            vec![PointRef::Point(a), PointRef::Point(b)],
        )))
        .unwrap();
    assert_eq!(
        to_json(&s).unwrap_err(),
        FileError::CustomNotSavable {
            id: id.0,
            name: "gap".into()
        }
    );
}

/// Issue 12: the `CustomRegistry` example with a file listing one point where the residual
/// reads two panicked inside the residual's `eval`; it is now refused when the file loads.
#[test]
fn a_custom_constraint_with_too_few_points_is_refused_on_load() {
    let one = GAP_FILE.replace(
        "\"points\": [{\"point\": 0}, {\"point\": 1}]",
        "\"points\": [{\"point\": 0}]",
    );
    let e = from_json_with(&one, &registry()).unwrap_err();
    assert!(
        matches!(
            &e,
            FileError::Constraint {
                id: 3,
                source: camber_sketch::Error::CustomArgs { .. },
                ..
            }
        ),
        "{e}"
    );
}

/// Every kind in the list has a file form that round-trips (the tags are unique and each
/// names its kind).
#[test]
fn every_kind_tag_is_unique() {
    let mut tags = Constraint::TAGS.to_vec();
    tags.sort_unstable();
    let n = tags.len();
    tags.dedup();
    assert_eq!(tags.len(), n);
    assert!(n >= 37, "{n} kinds");
}

/// Malformed files of every shape get messages in the file format's words: no Rust type name
/// of the library (`struct RawSketch`, `f64`, `usize`, `tuple variant Arg::FreeOf`) reaches the
/// user.
#[test]
fn file_errors_speak_json_not_rust() {
    let cases = [
        "null",
        "[]",
        "1",
        "\"x\"",
        "{}",
        r#"{"version": 1, "entities": null}"#,
        r#"{"version": 1, "entities": {}}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": null}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [1]}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": ["a", 1]}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "circle", "center": [0, 0], "radius": "a"}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "bspline", "degree": -1, "knots": [], "control_points": []}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "bspline", "degree": 1.5, "knots": [], "control_points": []}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "composite", "nodes": [[0,0],[1,1]], "tangents": [[1,0],[1,0]], "joins": [3]}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "composite", "nodes": [[0,0],[1,1]], "tangents": [[1,0],[1,0]], "joins": ["x"]}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "fixed", "target": null}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "fixed", "target": 3}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "fixed", "target": {"point": 3}}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "fixed", "target": {"point": {"pt": 0}}}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "distance", "a": {"point": 0}, "b": {"point": 0}, "distance": null}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "distance", "a": {"point": 0}, "b": {"point": 0}, "distance": "x"}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "point_at_parameter", "curve": -1, "u": 0, "target": {"at": [0,0]}}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "point_at_parameter", "curve": 0, "u": 0, "target": "free"}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "tangent_to_circle", "curve": 0, "circle": 0, "u": {"free": "a"}, "side": "up", "rotation": 1}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "horizontal", "of": 3}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "custom", "name": 3}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "custom", "name": "a", "args": [{"param": "x"}]}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "custom", "name": "a", "args": [{"free_of": [1]}]}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "start_tangent", "curve": 0, "direction": [1,0], "sense": 3, "form": "row"}]}"#,
        r#"{"version": 1, "entities": [{"id": 0, "kind": "point", "at": [0,0]}], "constraints": [{"id": 1, "kind": "angle", "a": 0, "b": 0, "degrees": true}]}"#,
    ];
    let rust_words = [
        "struct",
        "enum ",
        "variant",
        "f64",
        "f32",
        "usize",
        "u64",
        "u32",
        "i64",
        "Raw",
        "::",
        "sequence",
        "map,",
        "string or map",
        "floating point",
    ];
    for c in cases {
        let message = match from_json(c) {
            Ok(_) => panic!("accepted: {c}"),
            Err(e) => e.to_string(),
        };
        for w in rust_words {
            assert!(!message.contains(w), "{message:?} (for {c}) says {w:?}");
        }
    }
    assert_eq!(
        from_json("null").unwrap_err().to_string(),
        "at .: expected a sketch: an object with \"version\", \"entities\" and \"constraints\", found null"
    );
    let radius = r#"{"version": 1, "entities": [{"id": 0, "kind": "circle", "center": [0, 0], "radius": "a"}]}"#;
    assert_eq!(
        from_json(radius).unwrap_err().to_string(),
        "at entities[0].radius: invalid type: string \"a\", expected a number"
    );
}
