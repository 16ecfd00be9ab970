"""Inputs the package takes as documented: priorities through add_constraint and back through
constraint(), parameter arrays in any memory layout, and NaN fields named in the message."""

import numpy as np
import pytest

import camber


def two_wishes(priority):
    s = camber.Sketch()
    p, q = s.add_point([0, 0]), s.add_point([1.5, 0])
    s.add_constraint("fixed", target={"point": {"point": p}})
    must = s.add_constraint("distance", a={"point": p}, b={"point": q}, distance=1.0)
    wish = s.add_constraint(
        "distance", a={"point": p}, b={"point": q}, distance=2.0, priority=priority
    )
    return s, p, q, must, wish


def test_a_priority_given_to_add_constraint_makes_that_constraint_give_way():
    s, p, q, must, wish = two_wishes(1)
    assert s.priority(wish) == 1 and s.priority(must) == 0
    report = s.solve()
    assert np.linalg.norm(s.point(q) - s.point(p)) == pytest.approx(1.0, abs=1e-9)
    assert report.status == ["relaxed"]
    # constraint() gives the file form back with its priority, as a sketch file holds it.
    assert s.constraint(wish)["priority"] == 1
    assert "priority" not in s.constraint(must)
    # A sketch read from its file keeps the priority, and constraint() gives it back.
    again = camber.Sketch.from_json(s.to_json())
    assert again.priority(wish) == 1
    assert again.constraint(wish)["priority"] == 1
    # Without the priority the two distances conflict.
    s0 = two_wishes(0)[0]
    with pytest.raises(camber.SolveError, match="conflicting"):
        s0.solve()


@pytest.mark.parametrize("bad", [-1, 256, 1.5, "high"])
def test_a_priority_outside_0_to_255_is_refused_and_nothing_is_added(bad):
    s = camber.Sketch()
    p, q = s.add_point([0, 0]), s.add_point([1, 0])
    with pytest.raises(camber.SketchError, match="priority"):
        s.add_constraint("distance", a={"point": p}, b={"point": q}, distance=1.0, priority=bad)
    assert s.constraint_ids() == []


def test_strided_and_reversed_parameter_arrays_are_read_like_copies():
    c = camber.BezierCurve([[0, 0], [1, 2], [3, 2], [4, 0]])
    u = np.linspace(0.0, 1.0, 11)
    for view in (u[::2], u[::-1], u[1::3]):
        assert not view.flags["C_CONTIGUOUS"] or view.strides[0] < 0 or view.size < 2
        np.testing.assert_array_equal(c.evaluate(view), c.evaluate(np.ascontiguousarray(view)))
        np.testing.assert_array_equal(c.curvature(view), c.curvature(view.copy()))
    # A column of a 2-D array is a strided 1-D view too.
    grid = np.stack([u, u], axis=1)
    np.testing.assert_array_equal(c.evaluate(grid[:, 1]), c.evaluate(u))


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -float("inf"), np.float64("nan")])
def test_a_non_finite_field_is_named_in_the_message(bad):
    s = camber.Sketch()
    p, q = s.add_point([0, 0]), s.add_point([1, 0])
    with pytest.raises(camber.SketchError, match=r"distance is not finite"):
        s.add_constraint("distance", a={"point": p}, b={"point": q}, distance=bad)
    c = s.add_bezier([[0, 0], [1, 1], [2, 0]])
    with pytest.raises(camber.SketchError, match=r"target\.at\[1\] is not finite"):
        s.add_constraint("point_at_parameter", curve=c, u=0.5, target={"at": [0.0, bad]})
    with pytest.raises(camber.SketchError, match=r"param is not finite"):
        s.add_custom(lambda x: [x[0]], [p, {"param": bad}], dim=1)
    assert s.constraint_ids() == []


@pytest.mark.parametrize(
    "u", [np.array([0.1 + 0.5j, 0.2]), [0.25j], np.array([0.5 + 0j])[::-1]]
)
def test_complex_parameters_are_refused_rather_than_cut_to_their_real_part(u):
    c = camber.BezierCurve([[0, 0], [1, 2], [3, 2], [4, 0]])
    with pytest.raises(camber.GeometryError, match="complex"):
        c.evaluate(u)
    with pytest.raises(camber.GeometryError, match="complex"):
        c.curvature(u)


@pytest.mark.parametrize(
    "make",
    [
        lambda p: camber.BezierCurve(p),
        lambda p: camber.BSplineCurve(3, [0, 0, 0, 0, 1, 1, 1, 1], p),
        lambda p: camber.fit_to_tolerance(np.vstack([p, p + 5.0]), 3, 1e-3, "centripetal"),
        lambda p: camber.Sketch().add_bezier(p),
    ],
)
def test_complex_coordinates_are_refused_rather_than_cut_to_their_real_part(make):
    points = np.array([[0, 0], [1, 2], [3, 2j], [4, 0]], dtype=complex)
    with pytest.raises(camber.GeometryError, match="complex"):
        make(points)
