//! The bundled surface case file matches the case generated in code, and deforming it meets the
//! issue's figures through the facade.

use camber::surface::examples::{crease_pair, DeformationCase};
use camber::surface::{deform_to_g1, DeformOptions};

#[test]
fn bundled_crease_file_is_the_generated_case_and_deforms_to_g1() {
    let text = include_str!("../examples/data/surface_crease10.json");
    let case: DeformationCase = serde_json::from_str(text).unwrap();
    let (face, neighbour) = crease_pair(10.0).unwrap();
    assert_eq!(case.face, face);
    assert_eq!(case.neighbours, vec![neighbour]);
    let (_, report) =
        deform_to_g1(&case.face, &case.neighbours, &DeformOptions::default()).unwrap();
    assert!(report.max_angle_after_deg() < 0.1);
    assert!(report.max_boundary_deviation < 1e-3 * report.size);
}
