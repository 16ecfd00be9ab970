"""The curve toolkit at its limits from Python (issue 27, the toolkit part): huge derivative
orders, tolerances below f64, a control point at 1e15, many lengths at once, the arc-length
map's error against a dense polyline, quadratic-spline offsets, NaN queries and overlapping
curves. Each answer is an exception or a right answer checked independently; nothing aborts
the interpreter or hangs."""

import math

import numpy as np
import pytest

import camber


def wave(degree, n):
    """A clamped B-spline through a wave of n control points."""
    x = np.arange(n) / 4.0
    return camber.BSplineCurve.clamped_uniform(
        degree, np.column_stack([x, np.sin(1.3 * x) + 0.3 * np.cos(3.1 * x)])
    )


def cumulative_polyline(curve, n=400_001):
    """Parameters and the cumulative length of a dense polyline along the curve."""
    u = np.linspace(*curve.domain, n)
    pts = curve.evaluate(u)
    steps = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    return u, np.concatenate([[0.0], np.cumsum(steps)])


def test_a_huge_derivative_order_raises_instead_of_aborting():
    c = wave(3, 8)
    with pytest.raises(camber.GeometryError, match="derivative order"):
        c.derivatives(0.5, 2**40)
    with pytest.raises(camber.GeometryError, match="derivative order"):
        c.derivatives(np.linspace(0, 1, 5), 2**40)
    assert c.derivatives(0.5, 64).shape == (65, 2)


@pytest.mark.parametrize("tolerance", [1e-15, 1e-16, 1e-17, 1e-300])
def test_map_tolerances_below_f64_are_raised_to_what_it_reaches(tolerance):
    c = wave(3, 12)
    m = c.arc_length_map(tolerance)
    assert m.tolerance > tolerance
    assert m.max_error <= m.tolerance < 1e-11 * m.length


@pytest.mark.parametrize("x", [1e7, 1e10, 1e15])
def test_a_far_control_point_is_measured(x):
    c = camber.BezierCurve([[0, 0], [x, 1], [2, 1], [3, 0]])
    length = c.arc_length()
    u, cumulative = cumulative_polyline(c)
    assert length == pytest.approx(cumulative[-1], rel=1e-6)
    half = c.parameter_at_length(0.5 * length)
    assert c.arc_length_between(0.0, half) == pytest.approx(0.5 * length, rel=1e-9)


def test_many_lengths_share_one_quadrature():
    c = wave(3, 200)
    total = c.arc_length()
    s = np.linspace(0.0, total, 100_001)
    u = c.parameter_at_length(s)
    assert u.shape == s.shape and np.all(np.diff(u) >= 0)
    for k in [0, 12_345, 50_000, 100_000]:
        assert c.arc_length_between(c.domain[0], u[k]) == pytest.approx(s[k], abs=1e-8)


def test_the_map_error_meets_the_request_against_a_dense_polyline():
    rng = np.random.default_rng(27)
    n = 9
    points = np.column_stack([np.arange(n) + rng.uniform(-0.5, 0.5, n), rng.uniform(-1.5, 1.5, n)])
    weights = 0.2 + rng.uniform(0, 1, n) * (1 + 4 * np.arange(n) / n)
    knots = [0, 0, 0, 0, 1 / 6, 2 / 6, 3 / 6, 4 / 6, 5 / 6, 1, 1, 1, 1]
    c = camber.NurbsCurve(3, knots, points, weights)
    tol = 4.6e-5
    m = c.arc_length_map(tol)
    assert m.max_error <= tol
    u_ref, cumulative = cumulative_polyline(c, 2_000_001)
    s = np.linspace(0.0, m.length, 5_001)
    along = np.interp(m.parameter(s), u_ref, cumulative)
    assert np.max(np.abs(along - s)) <= tol


def test_quadratic_spline_offsets_meet_the_tolerance_with_few_points():
    c = wave(2, 24)
    o, err = c.offset(0.1, 1e-6)
    assert err <= 1e-6
    assert len(o.control_points) < 1_000
    for s in np.linspace(0, 1, 201):
        _, _, d = c.closest_point(o.evaluate(s))
        assert d == pytest.approx(0.1, abs=2e-6)


def test_nan_queries_raise():
    c = wave(3, 8)
    with pytest.raises(camber.GeometryError, match="not finite"):
        c.closest_point([math.nan, 0.0])
    m = c.arc_length_map(1e-8)
    with pytest.raises(camber.GeometryError, match="not finite"):
        m.parameter(math.nan)
    with pytest.raises(camber.GeometryError, match="not finite"):
        c.parameter_at_length(np.array([1.0, math.nan]))


def test_overlapping_curves_give_an_interval_not_a_thousand_points():
    c = wave(3, 16)
    hits = c.intersect_curve(c)
    assert len(hits) == 1
    (o,) = hits
    assert o["kind"] == "overlap"
    assert o["interval_a"] == pytest.approx(c.domain, abs=1e-9)
    assert o["interval_b"] == pytest.approx(c.domain, abs=1e-9)
    # Crossing curves still give points.
    other = camber.BezierCurve([[0, -3], [4, 3]])
    points = c.intersect_curve(other)
    assert points and all(p["kind"] == "point" and p["distance"] <= 1e-9 for p in points)
