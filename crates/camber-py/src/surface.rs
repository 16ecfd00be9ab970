//! Surfaces: the bundled creased cases as JSON (`DeformationCase`'s serde form) and the minimal
//! G1 deformation of a case, its report as a dict. The deformation releases the GIL.

use camber_surface::examples::{creased_face, DeformationCase};
use camber_surface::{deform_to_g1, DeformOptions};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors;

/// The bundled benchmark case as JSON: an n × n bicubic face with creased neighbours on its
/// first k edges (creases of 4°, 6°, 8°, 10°).
#[pyfunction]
#[pyo3(signature = (n = 6, k = 2))]
pub fn creased_face_case(n: usize, k: usize) -> PyResult<String> {
    let case = creased_face(n, k).map_err(errors::surface)?;
    serde_json::to_string(&case).map_err(|e| errors::SurfaceError::new_err(e.to_string()))
}

/// Deforms the face of a case (its JSON form) as little as possible to G1 with its
/// neighbours. Returns (deformed face as JSON, report dict with per-edge normal angles before
/// and after in degrees, the boundary deviation, the refinement rounds, whether the
/// tolerances were met).
#[pyfunction]
#[pyo3(signature = (case_json, samples_per_edge = None, max_refinements = None))]
pub fn deform_case_to_g1(
    py: Python<'_>,
    case_json: &str,
    samples_per_edge: Option<usize>,
    max_refinements: Option<usize>,
) -> PyResult<(String, Py<PyAny>)> {
    let case: DeformationCase = serde_json::from_str(case_json)
        .map_err(|e| errors::SurfaceError::new_err(format!("invalid case JSON: {e}")))?;
    let mut options = DeformOptions::default();
    if let Some(n) = samples_per_edge {
        options = options.with_samples_per_edge(n);
    }
    if let Some(r) = max_refinements {
        options = options.with_max_refinements(r);
    }
    let (face, report) = py
        .detach(|| deform_to_g1(&case.face, &case.neighbours, &options))
        .map_err(errors::surface)?;
    let out = PyDict::new(py);
    let edges = pyo3::types::PyList::empty(py);
    for e in &report.edges {
        let d = PyDict::new(py);
        d.set_item("neighbour", e.neighbour)?;
        d.set_item("edge", format!("{:?}", e.edge))?;
        d.set_item("max_before_deg", e.max_before_deg())?;
        d.set_item("max_after_deg", e.max_after_deg())?;
        d.set_item("mean_before_deg", e.mean_before_deg())?;
        d.set_item("mean_after_deg", e.mean_after_deg())?;
        edges.append(d)?;
    }
    out.set_item("edges", edges)?;
    out.set_item("max_angle_before_deg", report.max_angle_before_deg())?;
    out.set_item("max_angle_after_deg", report.max_angle_after_deg())?;
    out.set_item("max_boundary_deviation", report.max_boundary_deviation)?;
    out.set_item("size", report.size)?;
    out.set_item(
        "max_control_point_movement",
        report.max_control_point_movement,
    )?;
    out.set_item("refinement_rounds", report.refinement_rounds)?;
    out.set_item("knots_inserted", report.knots_inserted)?;
    out.set_item("met_tolerances", report.met_tolerances)?;
    let face_json =
        serde_json::to_string(&face).map_err(|e| errors::SurfaceError::new_err(e.to_string()))?;
    Ok((face_json, out.into_any().unbind()))
}
