"""The G1 deformation of a bundled creased case from Python: the creases shrink below the
tolerance and the boundary barely moves; bad input raises SurfaceError."""

import json

import pytest

import camber


def test_creased_case_becomes_g1():
    case = camber.creased_face_case(5, 2)
    assert len(json.loads(case)["neighbours"]) == 2
    face, report = camber.deform_case_to_g1(case)
    assert report["max_angle_before_deg"] > 3.9
    assert report["max_angle_after_deg"] < 0.1
    assert report["max_boundary_deviation"] < 1e-2 * report["size"]
    assert [e["edge"] for e in report["edges"]] == ["UMin", "UMax"]
    assert "control_points" in json.loads(face) or json.loads(face)


def test_bad_case_is_a_surface_error():
    with pytest.raises(camber.SurfaceError, match="invalid case JSON"):
        camber.deform_case_to_g1("{}")
