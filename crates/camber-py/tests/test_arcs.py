"""Arcs from Python: an arc added by centre, radius and angles, its file form and its exact
NURBS form on the circle, a fillet of a right-angled corner against its closed form (centre
and tangent points at the radius from the corner's sides), solved with every constraint kept,
an impossible fillet refused with nothing changed, and arcs surviving pickling bit for bit."""

import math
import pickle

import numpy as np
import pytest

import camber


def corner(radius=None):
    """Lines (2, 0)→(0, 0) and (0, 0)→(0, 2) joined at the origin, the far ends fixed."""
    s = camber.Sketch()
    a = s.add_line([2.0, 0.0], [0.0, 0.0])
    b = s.add_line([0.0, 0.0], [0.0, 2.0])
    joint = s.add_constraint("coincident", a={"end": a}, b={"start": b})
    s.add_constraint("fixed", target={"point": {"start": a}})
    s.add_constraint("fixed", target={"point": {"end": b}})
    return s, a, b, joint


def test_an_arc_has_its_file_form_and_an_exact_nurbs_form():
    s = camber.Sketch()
    arc = s.add_arc([1.0, 2.0], 1.5, 0.25, 2.0)
    form = s.entity(arc)
    assert form["kind"] == "arc"
    assert form["radius"] == pytest.approx(1.5, abs=1e-15)
    assert form["start_angle"] == pytest.approx(0.25, abs=1e-15)
    assert form["end_angle"] == pytest.approx(2.0, abs=1e-15)
    np.testing.assert_allclose(s.point({"start": arc}), [1 + 1.5 * math.cos(0.25), 2 + 1.5 * math.sin(0.25)], atol=1e-15)
    curve = s.curve(arc)
    assert isinstance(curve, camber.NurbsCurve)
    lo, hi = curve.domain
    on = curve.evaluate(np.linspace(lo, hi, 17))
    np.testing.assert_allclose(np.hypot(on[:, 0] - 1.0, on[:, 1] - 2.0), 1.5, atol=1e-13)
    np.testing.assert_allclose(curve.evaluate(hi), s.point({"end": arc}), atol=1e-13)


def test_bad_arcs_are_refused_with_the_value():
    s = camber.Sketch()
    with pytest.raises(camber.GeometryError, match="-1"):
        s.add_arc([0.0, 0.0], -1.0, 0.0, 1.0)
    with pytest.raises(camber.GeometryError, match="sweeps no angle"):
        s.add_arc([0.0, 0.0], 1.0, 2.0, 2.0)
    with pytest.raises(camber.GeometryError, match="center"):
        s.add_arc([0.0], 1.0, 0.0, 1.0)
    assert s.entity_ids() == []


def test_the_fillet_of_a_right_angle_meets_its_closed_form_and_solves():
    s, a, b, joint = corner()
    dof = [c["analysis"]["dof"] for c in s.analyze()]
    f = s.fillet(a, b, 0.5)
    assert f["removed"] == [joint]
    assert len(f["added"]) == 5
    arc = f["arc"]
    # A right angle: the centre is at (r, r), the tangent points at r along each side.
    np.testing.assert_allclose(s.point({"control": [arc, 0]}), [0.5, 0.5], atol=1e-15)
    np.testing.assert_allclose(s.point({"end": a}), [0.5, 0.0], atol=1e-15)
    np.testing.assert_allclose(s.point({"start": b}), [0.0, 0.5], atol=1e-15)
    assert s.entity(arc)["radius"] == pytest.approx(0.5, abs=1e-15)
    # The fillet adds no freedom: the corner point's 2 become the arc's.
    assert [c["analysis"]["dof"] for c in s.analyze()] == dof == [2]
    s.solve()
    c = s.point({"control": [arc, 0]})
    for end in ("start", "end"):
        assert np.linalg.norm(s.point({end: arc}) - c) == pytest.approx(0.5, abs=1e-10)


def test_an_impossible_fillet_raises_and_changes_nothing():
    s, a, b, _ = corner()
    before = s.to_json()
    with pytest.raises(camber.SketchError, match="beyond a line's far end"):
        s.fillet(a, b, 5.0)
    with pytest.raises(camber.SketchError, match="to itself"):
        s.fillet(a, a, 0.5)
    assert s.to_json() == before


def test_a_sketch_with_arcs_pickles_bit_for_bit():
    s, a, b, _ = corner()
    arc = s.fillet(a, b, 0.3)["arc"]
    # An end moved off the circle: solved back onto it only to the tolerance, which a file
    # of radius and angles alone would round away.
    end = s.point({"end": arc})
    s.set_point({"control": [arc, 2]}, end + [0.01, -0.02])
    s.solve()
    back = pickle.loads(pickle.dumps(s))
    assert back.to_json() == s.to_json()
    for e in s.entity_ids():
        assert back.entity(e) == s.entity(e)


def test_an_elliptic_arc_has_its_file_form_and_lies_on_its_ellipse():
    s = camber.Sketch()
    e = s.add_elliptic_arc([1.0, 2.0], 3.0, 1.5, 0.4, 0.5, 2.0)
    form = s.entity(e)
    assert form["kind"] == "elliptic_arc"
    assert form["semi_axis_b"] == pytest.approx(1.5, abs=1e-15)
    u = np.array([math.cos(0.4), math.sin(0.4)])
    v = np.array([-math.sin(0.4), math.cos(0.4)])
    start = np.array([1.0, 2.0]) + 3.0 * math.cos(0.5) * u + 1.5 * math.sin(0.5) * v
    np.testing.assert_allclose(s.point({"start": e}), start, atol=1e-14)
    curve = s.curve(e)
    lo, hi = curve.domain
    d = curve.evaluate(np.linspace(lo, hi, 17)) - np.array([1.0, 2.0])
    x, y = d @ u, d @ v
    np.testing.assert_allclose((x / 3.0) ** 2 + (y / 1.5) ** 2, 1.0, atol=1e-12)
    whole = s.add_ellipse([0.0, 0.0], 2.0, 1.0, 0.0)
    assert s.entity(whole)["kind"] == "ellipse"


def test_bad_ellipses_are_refused_with_the_value():
    s = camber.Sketch()
    with pytest.raises(camber.GeometryError, match="-1"):
        s.add_ellipse([0.0, 0.0], 2.0, -1.0, 0.0)
    with pytest.raises(camber.GeometryError, match="sweeps no angle"):
        s.add_elliptic_arc([0.0, 0.0], 2.0, 1.0, 0.0, 1.0, 1.0)
    assert s.entity_ids() == []


def test_arc_angle_and_arc_length_dimension_arcs_from_python():
    s = camber.Sketch()
    a = s.add_arc([0.0, 0.0], 2.0, 0.0, 1.0)
    s.add_constraint("fixed", target={"point": {"control": [a, 0]}})
    s.add_constraint("fixed", target={"point": {"start": a}})
    sweep = s.add_constraint("arc_angle", arc=a, angle=2.0)
    s.solve()
    np.testing.assert_allclose(s.point({"end": a}), [2 * math.cos(2.0), 2 * math.sin(2.0)], atol=1e-10)
    s.remove_constraint(sweep)
    s.add_constraint("arc_length", curve=a, length=3.0)
    s.solve()
    np.testing.assert_allclose(s.point({"end": a}), [2 * math.cos(1.5), 2 * math.sin(1.5)], atol=1e-10)
    with pytest.raises(camber.SketchError, match="arc angle"):
        s.add_constraint("arc_angle", arc=a, angle=7.0)


def test_a_line_and_a_bezier_fillet_keeps_the_dof_and_touches_both():
    s = camber.Sketch()
    line = s.add_line([-3.0, 0.0], [0.0, 0.0])
    curve = s.add_bezier([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]])
    joint = s.add_constraint("coincident", a={"end": line}, b={"start": curve})
    dof = [c["analysis"]["dof"] for c in s.analyze()]
    f = s.fillet(curve, line, 0.25)
    assert f["removed"] == [joint]
    centre = s.point({"control": [f["arc"], 0]})
    # The centre is 0.25 above the line y = 0 and 0.25 from the curve's new start.
    assert centre[1] == pytest.approx(0.25, abs=1e-12)
    assert np.linalg.norm(s.point({"start": curve}) - centre) == pytest.approx(0.25, abs=1e-12)
    assert [c["analysis"]["dof"] for c in s.analyze()] == dof
    s.solve()


def test_a_line_split_and_trimmed_at_a_circle_ends_on_it():
    s = camber.Sketch()
    a = s.add_line([0.0, 0.0], [4.0, 0.0])
    c = s.add_circle([2.0, 0.0], 1.0)
    before = s.to_json()
    with pytest.raises(camber.SketchError, match="crosses entity 1 2 times"):
        s.split_at_intersection(a, c)
    with pytest.raises(camber.SketchError, match="keep"):
        s.trim(a, c, "middle", [3.0, 0.0])
    assert s.to_json() == before
    split = s.split_at_intersection(a, c, near=[3.2, 0.1])
    np.testing.assert_allclose(split["point"], [3.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(s.point({"start": split["second"]}), [3.0, 0.0], atol=1e-12)
    t = s.trim(a, c, "end", [1.0, 0.0])
    np.testing.assert_allclose(s.point({"start": a}), [1.0, 0.0], atol=1e-12)
    assert t["removed"] == []
    s.solve()
    np.testing.assert_allclose(s.point({"end": a}), [3.0, 0.0], atol=1e-10)


def test_a_circle_trimmed_by_a_line_keeps_the_far_arc():
    # The unit circle cut by x = 1/2 (crossings at ±60°): removing the cap near (1, 0) keeps
    # the 240° arc from 60° to −60°, its ends held on the line.
    s = camber.Sketch()
    c = s.add_circle([0.0, 0.0], 1.0)
    line = s.add_line([0.5, -2.0], [0.5, 2.0])
    away = s.add_line([5.0, 0.0], [6.0, 0.0])
    before = s.to_json()
    with pytest.raises(camber.SketchError, match="needs two crossings"):
        s.trim_closed(c, [away], [1.0, 0.0])
    with pytest.raises(camber.SketchError, match="expected circle or ellipse"):
        s.trim_closed(line, [c], [1.0, 0.0])
    assert s.to_json() == before
    t = s.trim_closed(c, [line], [1.0, 0.0])
    h = np.sqrt(0.75)
    np.testing.assert_allclose(t["start"], [0.5, h], atol=1e-12)
    np.testing.assert_allclose(t["end"], [0.5, -h], atol=1e-12)
    assert len(t["added"]) == 2
    np.testing.assert_allclose(s.point({"end": c}), [0.5, -h], atol=1e-12)
    s.solve()
    assert s.point({"start": c})[0] == pytest.approx(0.5, abs=1e-10)


def test_a_curve_touches_an_ellipse_from_python_at_the_closed_form_point():
    # A segment from the held point (0, 2) touches x²/4 + y² = 1: the tangent line at
    # (x0, y0), x·x0/4 + y·y0 = 1, passes through (0, 2) when y0 = 1/2, so x0 = √3, θ = π/6.
    s = camber.Sketch()
    e = s.add_ellipse([0.0, 0.0], 2.0, 1.0, 0.0)
    s.add_constraint("fixed", target={"entity": e})
    line = s.add_line([0.0, 2.0], [3.0, -0.2])
    s.add_constraint("fixed", target={"point": {"start": line}})
    k = s.add_constraint(
        "tangent_to_ellipse", curve=line, ellipse=e, u={"free": 0.6}, theta=0.4,
        side="outside", rotation="clockwise",
    )
    s.solve()
    c = s.constraint(k)
    assert c["theta"] == pytest.approx(math.pi / 6, abs=1e-9)
    a, b = np.array(s.point({"start": line})), np.array(s.point({"end": line}))
    np.testing.assert_allclose(a + (b - a) * c["u"]["free"], [math.sqrt(3.0), 0.5], atol=1e-9)
