//! Named parameters: dimensions and expressions that read them, files that keep their texts,
//! `set_parameter` re-solving only what reads the parameter, bad values refused, and sweeps
//! over a table of values.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use approx::assert_abs_diff_eq;
use camber_geom::ParametricCurve;
use camber_sketch::constraints::Distance;
use camber_sketch::file::{from_json, to_json};
use camber_sketch::parameters::sweep::{solve_variants, Table};
use camber_sketch::{Entity, EntityId, PointRef, Sketch};
use nalgebra::{Point2, Vector2};

fn blade() -> Sketch {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/sketches/blade_parametric.json"
    );
    from_json(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn derivative(s: &Sketch, id: u64, u: f64) -> (Point2<f64>, Vector2<f64>) {
    let Ok(Entity::Bezier(c)) = s.entity(EntityId(id)).cloned() else {
        panic!("not a Bézier")
    };
    let [p, d, _] = c.second_order(u).unwrap();
    (Point2::from(p), d)
}

/// The blade's dimensions hold for the parameters now (an independent reading of the solved
/// curves).
fn check_blade(s: &Sketch) {
    let p = |n: &str| s.parameter(n).unwrap();
    let (le, _) = derivative(s, 0, 0.0);
    let (te, _) = derivative(s, 0, 1.0);
    assert_abs_diff_eq!(le, Point2::origin(), epsilon = 1e-12);
    assert_abs_diff_eq!(te, Point2::new(p("chord"), 0.0), epsilon = 1e-9);
    let angle = |id, u| {
        let (_, d) = derivative(s, id, u);
        d.y.atan2(d.x)
    };
    assert_abs_diff_eq!(angle(0, 0.0), p("le_angle"), epsilon = 1e-9);
    assert_abs_diff_eq!(angle(0, 1.0), p("te_angle"), epsilon = 1e-9);
    assert_abs_diff_eq!(angle(1, 0.0), p("le_angle") - p("le_wedge"), epsilon = 1e-9);
    assert_abs_diff_eq!(angle(1, 1.0), p("te_angle") + p("te_wedge"), epsilon = 1e-9);
    let thickness = (derivative(s, 0, 0.4).0 - derivative(s, 1, 0.4).0).norm();
    assert_abs_diff_eq!(thickness, p("t_max") * p("chord"), epsilon = 1e-9);
}

#[test]
fn a_blade_section_follows_its_chord_thickness_and_angles() {
    let mut s = blade();
    s.solve().unwrap();
    check_blade(&s);
    for (name, value) in [
        ("chord", 1.4),
        ("t_max", 0.08),
        ("le_angle", 0.5),
        ("te_wedge", 0.3),
    ] {
        s.set_parameter(name, value).unwrap();
        check_blade(&s);
    }
}

#[test]
fn a_file_keeps_its_parameters_and_dimension_texts() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/sketches/blade_parametric.json"
    );
    let text = std::fs::read_to_string(path).unwrap();
    let mut s = from_json(&text).unwrap();
    assert_eq!(to_json(&s).unwrap(), text);
    s.set_parameter("chord", 2.0).unwrap();
    let saved = to_json(&s).unwrap();
    assert!(saved.contains("\"chord\":2.0") && saved.contains("\"distance\":\"chord\""));
    let again = from_json(&saved).unwrap();
    assert_eq!(to_json(&again).unwrap(), saved);
}

#[test]
fn set_parameter_re_solves_only_the_components_that_read_it() {
    let mut s = Sketch::new();
    let (a, b) = (
        s.add_point(Point2::new(0.0, 0.0)).unwrap(),
        s.add_point(Point2::new(1.0, 0.0)).unwrap(),
    );
    let (c, d) = (
        s.add_point(Point2::new(5.0, 0.0)).unwrap(),
        s.add_point(Point2::new(6.0, 0.0)).unwrap(),
    );
    s.define_parameter("gap", 2.0).unwrap();
    s.define_parameter("other", 1.0).unwrap();
    let first = s
        .add_constraint(Distance {
            a: PointRef::Point(a),
            b: PointRef::Point(b),
            distance: 1.0,
        })
        .unwrap();
    s.bind_dimension(first, "distance", "gap").unwrap();
    s.add_constraint(Distance {
        a: PointRef::Point(c),
        b: PointRef::Point(d),
        distance: 1.5,
    })
    .unwrap();
    s.solve().unwrap();
    assert_eq!(s.parameter_readers("gap"), vec![first]);
    let report = s.set_parameter("gap", 3.0).unwrap();
    assert_eq!(report.components.len(), 1);
    assert_eq!(report.components[0].component.entities, vec![a, b]);
    let gap = (s.point(PointRef::Point(b)).unwrap() - s.point(PointRef::Point(a)).unwrap()).norm();
    assert_abs_diff_eq!(gap, 3.0, epsilon = 1e-10);
    // A parameter nothing reads re-solves nothing.
    assert!(s.set_parameter("other", 4.0).unwrap().components.is_empty());
}

#[test]
fn bad_parameters_and_dimension_texts_are_refused_and_nothing_changes() {
    let mut s = blade();
    s.solve().unwrap();
    let before = to_json(&s).unwrap();
    assert_eq!(
        s.define_parameter("chord", f64::NAN)
            .unwrap_err()
            .to_string(),
        "parameter 0 is not finite (NaN)"
    );
    // A chord of zero gives a horizontal distance of 0 (allowed) but the thickness row then
    // asks for a zero thickness: solvable. A negative t_max cannot be met by a norm.
    assert!(s.set_parameter("t_max", -0.1).is_err());
    assert!(s.define_parameter("pi", 3.0).is_err());
    assert!(s.define_parameter("2x", 3.0).is_err());
    assert_eq!(
        s.bind_dimension(camber_sketch::ConstraintId(5), "distance", "chord +").unwrap_err().to_string(),
        "column 8: expected an operand (a number, a name, `(` or `[`), found the end of the expression"
    );
    assert_eq!(
        s.bind_dimension(camber_sketch::ConstraintId(5), "sense", "chord")
            .unwrap_err()
            .to_string(),
        "column 1: `sense` is not a number of a horizontal_distance constraint"
    );
    assert!(s.remove_parameter("chord").is_err());
    assert_eq!(to_json(&s).unwrap(), before);
    let bad = before.replace("\"distance\":\"chord\"", "\"distance\":\"chrod\"");
    assert_eq!(
        from_json(&bad).unwrap_err().to_string(),
        "at constraints[3].distance: column 1: unknown name `chrod`"
    );
    let nan = before.replace("\"t_max\":0.12", "\"t_max\":1e999");
    assert!(from_json(&nan)
        .unwrap_err()
        .to_string()
        .starts_with("invalid JSON: non-finite number"));
}

#[test]
fn a_sweep_solves_one_variant_per_row_on_every_thread() {
    let s = blade();
    let chords: Vec<f64> = (0..24).map(|i| 0.8 + 0.05 * f64::from(i)).collect();
    let thick: Vec<f64> = (0..24).map(|i| 0.06 + 0.004 * f64::from(i)).collect();
    let table = Table::try_new(vec![
        ("chord".into(), chords.clone()),
        ("t_max".into(), thick),
    ])
    .unwrap();
    let rows = solve_variants(&s, &table, Some(2)).unwrap();
    assert_eq!(rows.len(), 24);
    for (i, r) in rows.iter().enumerate() {
        assert!(r.ok, "row {i}: {:?}", r.error);
        assert_eq!(r.row, i);
        assert!(r.max_residual <= 1e-9);
    }
    // Each variant equals solving the sketch with those values by hand.
    let mut by_hand = blade();
    by_hand.define_parameter("chord", chords[7]).unwrap();
    by_hand
        .define_parameter("t_max", 0.06 + 0.004 * 7.0)
        .unwrap();
    by_hand.solve().unwrap();
    check_blade(&by_hand);
    // A column that names no parameter is refused.
    let unknown = Table::try_new(vec![("span".into(), vec![1.0])]).unwrap();
    assert!(solve_variants(&s, &unknown, None).is_err());
    assert!(Table::try_new(vec![("chord".into(), vec![1.0]), ("t_max".into(), vec![])]).is_err());
}

fn diffuser() -> Sketch {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/sketches/diffuser_parametric.json"
    );
    from_json(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn a_sweep_reports_the_solved_contact_parameters_of_built_in_kinds() {
    // The parametric diffuser: circles placed by parameters, the curve tangent to the middle
    // circle at a free parameter (constraint 8, field `u`).
    let s = diffuser();
    let r3 = vec![0.065, 0.07, 0.075];
    let y3 = vec![0.035, 0.04, 0.045];
    let table = Table::try_new(vec![("r3".into(), r3.clone()), ("y3".into(), y3.clone())]).unwrap();
    let rows = solve_variants(&s, &table, Some(2)).unwrap();
    for (i, r) in rows.iter().enumerate() {
        assert!(r.ok, "row {i}: {:?}", r.error);
        let u: Vec<f64> = r
            .free
            .iter()
            .filter(|(id, name, _)| *id == 8 && name == "u")
            .map(|(_, _, u)| *u)
            .collect();
        assert_eq!(u.len(), 1, "row {i}: {:?}", r.free);
        // Independently: the curve solved by hand touches the circle at that parameter.
        let mut by_hand = diffuser();
        by_hand.define_parameter("r3", r3[i]).unwrap();
        by_hand.define_parameter("y3", y3[i]).unwrap();
        by_hand.solve().unwrap();
        let Ok(Entity::BSpline(c)) = by_hand.entity(EntityId(0)).cloned() else {
            panic!("not a B-spline")
        };
        let p = c.point(u[0]).unwrap();
        let gap = (p - Point2::new(0.38, y3[i])).norm() - r3[i];
        assert!(gap.abs() < 1e-9, "row {i}: gap {gap}");
    }
    // The contact moves with the circle: three different parameters.
    assert!(rows[0].free != rows[2].free);
}
