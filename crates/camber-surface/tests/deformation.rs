//! The G1 deformation on the bundled cases: the 10° crease is removed while the shared edge
//! stays put, a G1 pair is left alone, refinement is bounded, bad input is refused.

use approx::assert_relative_eq;
use camber_surface::examples::{crease_pair, creased_face, creased_neighbour};
use camber_surface::{deform_to_g1, plane_angle_deg, DeformOptions, Edge, Error};

#[test]
fn ten_degree_crease_is_removed_and_the_edge_stays() {
    let (face, nb) = crease_pair(10.0).unwrap();
    let (deformed, report) = deform_to_g1(&face, &[nb], &DeformOptions::default()).unwrap();
    let edge = &report.edges[0];
    assert_eq!(edge.edge, Edge::VMax);
    assert_eq!(edge.parameters.len(), 50);
    assert!(edge.max_before_deg() > 9.9 && edge.max_before_deg() < 10.1);
    assert!(edge.mean_before_deg() > 9.0);
    assert!(edge.max_after_deg() < 0.1, "{}", edge.max_after_deg());
    assert!(edge.mean_after_deg() <= edge.max_after_deg());
    assert!(report.met_tolerances);
    // The shared edge moves by less than 1e-3 of the patch size, checked densely.
    let size = face.size();
    assert_relative_eq!(report.size, size);
    assert!(report.max_boundary_deviation < 1e-3 * size);
    for k in 0..=400 {
        let u = k as f64 / 400.0;
        let moved = (deformed.point(u, 1.0).unwrap() - face.point(u, 1.0).unwrap()).norm();
        assert!(moved < 1e-3 * size, "u = {u}: {moved}");
    }
    // The angle stays below 0.1° between the samples too: checked densely against the
    // neighbour's normal at the same edge parameter (its edge v = 0 runs like the face's v = 1).
    let nb = &crease_pair(10.0).unwrap().1;
    for k in 0..=400 {
        let u = k as f64 / 400.0;
        let n0 = deformed.normal(u, 1.0).unwrap();
        let n1 = nb.surface.normal(u, 0.0).unwrap();
        assert!((nb.surface.point(u, 0.0).unwrap() - face.point(u, 1.0).unwrap()).norm() < 1e-12);
        let deg = plane_angle_deg(&n0, &n1);
        assert!(deg < 0.1, "u = {u}: {deg}°");
    }
    // Something did move: the row next to the edge turns by about the crease.
    assert!(report.max_control_point_movement > 0.01 * size);
    assert!(report.solve.affine && report.solve.iterations == 1);
    assert!(report.solve.final_cost < report.solve.initial_cost);
}

#[test]
fn a_face_that_is_already_g1_is_left_almost_unchanged() {
    let (face, nb) = crease_pair(0.0).unwrap();
    let (deformed, report) = deform_to_g1(&face, &[nb], &DeformOptions::default()).unwrap();
    assert!(report.max_angle_before_deg() < 1e-9);
    assert!(report.max_angle_after_deg() < 1e-9);
    assert!(report.max_control_point_movement < 1e-9 * face.size());
    for (a, b) in face.control_points().iter().zip(deformed.control_points()) {
        assert_relative_eq!(a, b, epsilon = 1e-9);
    }
    assert_eq!(report.refinement_rounds, 0);
}

#[test]
fn refinement_rounds_are_bounded_and_keep_the_geometry_class() {
    // Two creased neighbours meeting at a corner ask for two different tangent planes there:
    // the tolerance cannot be met, so every refinement round is used.
    let case = creased_face(5, 2).unwrap();
    let options = DeformOptions::default()
        .with_samples_per_edge(20)
        .with_max_refinements(2)
        .with_tolerances(1e-6, 1e-4);
    let (deformed, report) = deform_to_g1(&case.face, &case.neighbours, &options).unwrap();
    assert_eq!(report.refinement_rounds, 2);
    assert!(report.knots_inserted > 0);
    assert!(!report.met_tolerances);
    let (nu, nv) = deformed.counts();
    assert!(nu * nv > 25);
    // Away from the corners the creases are still mostly removed.
    for e in &report.edges {
        assert!(e.mean_after_deg() < 0.5 * e.mean_before_deg(), "{e:?}");
    }
}

#[test]
fn bad_options_and_distant_neighbours_are_refused() {
    let (face, nb) = crease_pair(10.0).unwrap();
    let bad = DeformOptions::default().with_weights(-1.0, 1.0, 1.0);
    assert_eq!(
        deform_to_g1(&face, std::slice::from_ref(&nb), &bad).unwrap_err(),
        Error::InvalidOption {
            what: "alpha",
            value: -1.0
        }
    );
    let few = DeformOptions::default().with_samples_per_edge(1);
    assert!(matches!(
        deform_to_g1(&face, &[nb], &few),
        Err(Error::InvalidOption {
            what: "samples_per_edge",
            ..
        })
    ));
    // A neighbour built on the opposite edge is not adjacent to v = 1.
    let mut far = creased_neighbour(&face, Edge::VMin, 10.0).unwrap();
    far.face_edge = Edge::VMax;
    assert!(matches!(
        deform_to_g1(&face, &[far], &DeformOptions::default()),
        Err(Error::NotAdjacent { neighbour: 0, .. })
    ));
}

#[test]
fn the_case_file_round_trips() {
    let case = creased_face(4, 1).unwrap();
    let text = serde_json::to_string(&case).unwrap();
    let back: camber_surface::examples::DeformationCase = serde_json::from_str(&text).unwrap();
    assert_eq!(back, case);
}
