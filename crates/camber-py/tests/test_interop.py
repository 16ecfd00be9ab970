"""Curves to and from scipy's BSpline and geomdl's curves: the same numbers both ways (round
trips exact), the same points (each library's own evaluation against camber's), and clean
refusals of what has no counterpart."""

import math

import numpy as np
import pytest
from geomdl import BSpline as GeomdlBSpline
from geomdl import NURBS as GeomdlNURBS
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.interpolate import BSpline, make_interp_spline

import camber
from camber.interop import from_geomdl, from_scipy, to_geomdl, to_scipy


def quarter_circle(radius=2.0):
    """A rational quadratic quarter of a circle, on the unnormalised domain [0, 2.5]."""
    w = math.sqrt(0.5)
    return camber.NurbsCurve(
        2,
        [0.0, 0.0, 0.0, 2.5, 2.5, 2.5],
        np.array([[radius, 0.0], [radius, radius], [0.0, radius]]),
        [1.0, w, 1.0],
    )


def wave(dim=2):
    pts = np.array([[i, math.sin(i), math.cos(i)][:dim] for i in range(7)], dtype=float)
    return camber.BSplineCurve(3, [0, 0, 0, 0, 0.7, 1.1, 2.0, 3, 3, 3, 3], pts)


def params(curve, count=101):
    a, b = curve.domain
    return np.linspace(a, b, count)


@pytest.mark.parametrize("dim", [2, 3])
def test_a_bspline_goes_to_scipy_and_back_with_the_same_numbers(dim):
    c = wave(dim)
    s = to_scipy(c)
    assert s.k == 3
    np.testing.assert_array_equal(s.t, c.knots)
    u = params(c)
    # scipy's own evaluation of the converted spline agrees with camber's.
    assert np.max(np.abs(s(u) - c.evaluate(u))) < 1e-12
    back = from_scipy(s)
    assert back.degree == c.degree
    np.testing.assert_array_equal(back.knots, c.knots)
    np.testing.assert_array_equal(back.control_points, c.control_points)


def test_a_bezier_goes_to_scipy_on_clamped_knots():
    b = camber.BezierCurve(np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]))
    s = to_scipy(b)
    np.testing.assert_array_equal(s.t, [0, 0, 0, 0, 1, 1, 1, 1])
    u = np.linspace(0, 1, 33)
    assert np.max(np.abs(s(u) - b.evaluate(u))) < 1e-12


def test_scipy_interpolating_and_unclamped_splines_come_in_with_their_points():
    x = np.linspace(0, 2, 12)
    y = np.column_stack([np.cos(3 * x), np.sin(2 * x)])
    clamped = make_interp_spline(x, y, k=3)
    # Uniform knots, not clamped: the base interval is [t[k], t[n]].
    unclamped = BSpline(np.arange(11.0), np.column_stack([np.arange(7.0), np.arange(7.0) ** 2]), 3)
    for s in (clamped, unclamped):
        c = from_scipy(s)
        lo, hi = s.t[s.k], s.t[len(s.t) - s.k - 1]
        assert c.domain == pytest.approx((lo, hi), abs=0)
        u = np.linspace(lo, hi, 57)
        assert np.max(np.abs(c.evaluate(u) - s(u))) < 1e-12


def test_scipy_coefficient_rows_beyond_the_knots_are_ignored_as_scipy_does():
    t = [0, 0, 0, 1, 2, 2, 2]
    c = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0], [99.0, 99.0]])
    s = BSpline(t, c, 2)
    curve = from_scipy(s)
    assert len(curve.control_points) == 4
    u = np.linspace(0, 2, 9)
    assert np.max(np.abs(curve.evaluate(u) - s(u))) < 1e-12


def test_what_has_no_counterpart_is_refused_by_name():
    with pytest.raises(ValueError, match="shape"):
        from_scipy(BSpline([0, 0, 1, 1], [1.0, 2.0], 1))  # a scalar spline
    with pytest.raises(ValueError, match="coefficient rows"):
        from_scipy(BSpline.construct_fast(np.array([0, 0, 0, 1, 1, 1.0]), np.zeros((2, 2)), 2))
    uneven = quarter_circle()
    with pytest.raises(ValueError, match="unequal weights"):
        to_scipy(uneven)
    hermite = camber.BezierCurve(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])).to_hermite()
    for convert in (to_scipy, to_geomdl):
        with pytest.raises(TypeError, match="HermiteCurve"):
            convert(hermite)
    with pytest.raises(camber.GeometryError, match="point 1 is not finite"):
        from_scipy(BSpline([0, 0, 1, 1], np.array([[0.0, 0.0], [np.nan, 1.0]]), 1))
    bad = GeomdlBSpline.Curve()
    bad.degree = 1
    bad.ctrlpts = [[0.0, 0.0, 0.0, 0.0], [1.0, 1.0, 1.0, 1.0]]  # four coordinates
    bad.knotvector = [0, 0, 1, 1]
    with pytest.raises(ValueError, match="2 or 3 coordinates"):
        from_geomdl(bad)


def test_equal_weights_go_to_scipy_as_a_plain_spline():
    c = camber.NurbsCurve(2, [0, 0, 0, 1, 1, 1], np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]), [3.0] * 3)
    s = to_scipy(c)
    u = np.linspace(0, 1, 21)
    assert np.max(np.abs(s(u) - c.evaluate(u))) < 1e-12


def test_a_nurbs_arc_goes_to_geomdl_and_back_with_the_same_numbers():
    c = quarter_circle()
    g = to_geomdl(c)
    assert isinstance(g, GeomdlNURBS.Curve)
    assert list(g.knotvector) == [0.0, 0.0, 0.0, 2.5, 2.5, 2.5]
    u = params(c, 41)
    ours = c.evaluate(u)
    theirs = np.array([g.evaluate_single(float(x)) for x in u])
    assert np.max(np.abs(ours - theirs)) < 1e-12
    # Still on the circle: an independent check of both evaluations.
    assert np.max(np.abs(np.linalg.norm(theirs, axis=1) - 2.0)) < 1e-12
    back = from_geomdl(g)
    assert isinstance(back, camber.NurbsCurve)
    np.testing.assert_array_equal(back.knots, c.knots)
    np.testing.assert_allclose(back.control_points, c.control_points, rtol=0, atol=1e-15)
    np.testing.assert_array_equal(back.weights, c.weights)


def test_a_geomdl_curve_comes_in_and_goes_back_out_unchanged():
    g = GeomdlBSpline.Curve()  # geomdl's default: knots rescaled to [0, 1]
    g.degree = 3
    g.ctrlpts = [[0, 0, 0], [1, 2, 0], [2, -1, 1], [3, 1, 0], [4, 0, 2]]
    g.knotvector = [0, 0, 0, 0, 4, 10, 10, 10, 10]
    c = from_geomdl(g)
    assert isinstance(c, camber.BSplineCurve)
    u = params(c, 31)
    theirs = np.array([g.evaluate_single(float(x)) for x in u])
    assert np.max(np.abs(c.evaluate(u) - theirs)) < 1e-12
    again = to_geomdl(c)
    assert [float(k) for k in again.knotvector] == [float(k) for k in g.knotvector]
    assert np.asarray(again.ctrlpts).tolist() == np.asarray(g.ctrlpts, dtype=float).tolist()


@st.composite
def bsplines(draw):
    degree = draw(st.integers(1, 5))
    count = draw(st.integers(degree + 1, degree + 8))
    dim = draw(st.sampled_from([2, 3]))
    steps = draw(st.lists(st.floats(0.05, 3.0), min_size=count - degree, max_size=count - degree))
    interior = np.cumsum(steps)[:-1].tolist()
    start = draw(st.floats(-5.0, 5.0))
    end = start + float(np.sum(steps))
    knots = [start] * (degree + 1) + [start + k for k in interior] + [end] * (degree + 1)
    coords = st.floats(-1e3, 1e3, allow_nan=False)
    pts = draw(st.lists(st.lists(coords, min_size=dim, max_size=dim), min_size=count, max_size=count))
    return camber.BSplineCurve(degree, knots, np.array(pts, dtype=float))


@settings(max_examples=60, deadline=None)
@given(bsplines())
def test_any_bspline_round_trips_exactly_through_both_libraries(c):
    for there, back in ((to_scipy, from_scipy), (to_geomdl, from_geomdl)):
        r = back(there(c))
        assert r.degree == c.degree
        np.testing.assert_array_equal(r.knots, c.knots)
        np.testing.assert_array_equal(r.control_points, c.control_points)
    u = params(c, 17)
    scale = 1.0 + np.max(np.abs(c.control_points))
    assert np.max(np.abs(to_scipy(c)(u) - c.evaluate(u))) < 1e-12 * scale


def every_curve_kind():
    pts = np.array([[0.0, 0.0], [1.0, 2.0 / 3.0], [2.5, -1.0], [3.0, 0.1]])
    return [
        camber.BezierCurve(pts),
        wave(2),
        wave(3),
        quarter_circle(),
        camber.BezierCurve(pts).to_hermite(),
    ]


@pytest.mark.parametrize("curve", every_curve_kind(), ids=lambda c: type(c).__name__)
def test_curves_pickle_to_the_same_numbers(curve):
    import pickle

    back = pickle.loads(pickle.dumps(curve))
    assert type(back) is type(curve)
    assert back.to_json() == curve.to_json()
    u = np.linspace(*curve.domain, 23)
    np.testing.assert_array_equal(back.evaluate(u), curve.evaluate(u))


def test_a_sketch_pickles_and_goes_through_plain_dicts(sketches):
    import copy
    import json
    import pickle

    s = camber.Sketch.load(sketches / "blade_section.json")
    for back in (pickle.loads(pickle.dumps(s)), copy.deepcopy(s), camber.Sketch.from_dict(s.to_dict())):
        assert back.to_json() == s.to_json()
    d = s.to_dict()
    assert d == json.loads(s.to_json())
    assert isinstance(d, dict)
    # A dict that is not a sketch is refused as a file error, naming what is wrong.
    with pytest.raises(camber.FileError):
        camber.Sketch.from_dict({"entities": "none"})


def test_a_sketch_with_a_python_constraint_refuses_to_pickle():
    import pickle

    s = camber.Sketch()
    p, q = s.add_point([0, 0]), s.add_point([3, 0])
    s.add_custom(lambda x: [x[2] - x[0] - 1.0], [p, q], dim=1, name="unit apart", affine=True)
    with pytest.raises(camber.CamberError):
        pickle.dumps(s)
