"""Sketches from Python: file load/save round trips, constraints of several kinds through
their file form, solve reports with per-constraint residuals checked against the geometry,
the DOF analysis, drag sessions, iterative displacement, and errors with the library's
messages and ids."""

import json
import math

import numpy as np
import pytest

import camber


def two_points():
    s = camber.Sketch()
    p = s.add_point([0.0, 0.0])
    q = s.add_point([3.0, 1.0])
    return s, p, q


def test_distance_and_horizontal_are_met_and_reported_per_constraint():
    s, p, q = two_points()
    fix = s.add_constraint("fixed", target={"point": {"point": p}})
    h = s.add_constraint("horizontal", of={"a": {"point": p}, "b": {"point": q}})
    d = s.add_constraint("distance", a={"point": p}, b={"point": q}, distance=2.0)
    report = s.solve()
    assert isinstance(report, camber.SolveReport)
    a, b = s.point(p), s.point(q)
    np.testing.assert_allclose(a, [0, 0], atol=1e-12)
    assert abs(b[1] - a[1]) < 1e-9
    assert abs(np.linalg.norm(b - a) - 2.0) < 1e-9
    res = report.residuals
    assert set([h, d]) <= set(res)
    assert all(v < 1e-9 for v in res.values())
    assert report.dof == 0
    assert s.constraint(d) == {"kind": "distance", "a": {"point": p}, "b": {"point": q}, "distance": 2.0}
    assert fix in s.constraint_ids()


def test_file_round_trip_gives_the_same_text(sketches):
    s = camber.Sketch.load(sketches / "diffuser.json")
    text = s.to_json()
    again = camber.Sketch.from_json(text)
    assert again.to_json() == text
    assert again.entity(1) == {"kind": "circle", "center": [0.03, 0.0], "radius": 0.03}


def test_diffuser_solves_and_touches_its_circles(sketches, tmp_path):
    s = camber.Sketch.load(sketches / "diffuser.json")
    report = s.solve()
    assert report.max_residual < 1e-8
    assert {7, 8, 9} <= set(report.residuals)
    curve = s.curve(0)
    for cid in (1, 3, 5):
        e = s.entity(cid)
        _, _, gap = curve.distance_to_circle(e["center"], e["radius"])
        assert abs(gap) < 1e-6, (cid, gap)
    s.save(tmp_path / "solved.json")
    assert camber.Sketch.load(tmp_path / "solved.json").to_json() == s.to_json()
    # The free contact parameter was written back.
    assert s.constraint(8)["u"]["free"] != 0.495


def test_analysis_names_the_redundant_constraint():
    s, p, q = two_points()
    s.add_constraint("fixed", target={"point": {"point": p}})
    s.add_constraint("horizontal", of={"a": {"point": p}, "b": {"point": q}})
    again = s.add_constraint("horizontal", of={"a": {"point": p}, "b": {"point": q}})
    comps = s.analyze()
    assert len(comps) == 1
    analysis = comps[0]["analysis"]
    assert analysis["dof"] == 1
    assert again in analysis["redundant"] or len(analysis["redundant"]) == 1


def test_conflicting_constraints_raise_solve_error_and_leave_the_sketch():
    s, p, q = two_points()
    s.add_constraint("fixed", target={"point": {"point": p}})
    s.add_constraint("fixed", target={"point": {"point": q}})
    s.add_constraint("horizontal", of={"a": {"point": p}, "b": {"point": q}})
    before = s.to_json()
    with pytest.raises(camber.SolveError):
        s.solve()
    assert s.to_json() == before


def test_bad_input_names_the_field_or_id():
    s, p, q = two_points()
    with pytest.raises(camber.FileError, match="unknown constraint kind `nope`"):
        s.add_constraint("nope", a=1)
    with pytest.raises(camber.FileError, match="distance"):
        s.add_constraint("distance", a={"point": p}, b={"point": q})
    with pytest.raises(camber.SketchError, match="entity 99"):
        s.add_constraint("distance", a={"point": p}, b={"point": 99}, distance=1.0)
    with pytest.raises(camber.FileError, match="invalid JSON"):
        camber.Sketch.from_json("{")
    with pytest.raises(camber.SketchError):
        s.entity(42)
    assert issubclass(camber.FileError, camber.SketchError)
    assert issubclass(camber.SolveError, camber.CamberError)


def test_drag_follows_the_start_tangent_and_finishes_into_the_sketch():
    d = np.array([math.cos(math.radians(30)), math.sin(math.radians(30))])
    s = camber.Sketch()
    c = s.add_bezier([[0, 0], 1.2 * d, [2.2, 0.9], [3.0, 0.0]])
    s.add_constraint("fixed", target={"point": {"control": [c, 3]}})
    tangent = s.add_constraint("start_tangent", curve=c, direction=d, sense="agree", form="row")
    drag = s.drag({"control": [c, 1]})
    moved = drag.update(1.2 * d + [0.0, 0.1])
    # What the update changed: the curve, and the tangent's residual at the new state (the
    # fixed point is a binding and has no rows).
    assert moved["moved"] == [c]
    assert list(moved["residuals"]) == [tangent] and moved["residuals"][tangent] < 1e-12
    p0, p1 = drag.point({"control": [c, 0]}), drag.point({"control": [c, 1]})
    t = p1 - p0
    assert abs(t[0] * d[1] - t[1] * d[0]) < 1e-12 and t @ d > 0
    drag.finish()
    np.testing.assert_allclose(s.point({"control": [c, 1]}), p1, atol=1e-12)
    with pytest.raises(camber.SolveError, match="finished"):
        drag.update([0, 0])


def test_iterative_displacement_on_the_diffuser(sketches):
    s = camber.Sketch.load(sketches / "diffuser.json")
    run = s.solve_by_displacement()
    assert run["rounds"] >= 1
    assert isinstance(run["report"], camber.SolveReport)
    assert run["history"][-1] <= run["history"][0]


def test_entities_from_curve_objects():
    s = camber.Sketch()
    b = camber.BSplineCurve.clamped_uniform(2, [[0, 0], [1, 1], [2, 0]])
    cid = s.add_curve(b)
    assert s.entity(cid)["kind"] == "bspline"
    np.testing.assert_allclose(s.curve_point(cid, 0.5), b.evaluate(0.5), atol=1e-14)
    circ = s.add_circle([0, 0], 1.0)
    with pytest.raises(camber.SketchError, match="not a curve"):
        s.curve(circ)
    json.dumps(s.components())
