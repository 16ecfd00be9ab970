"""Curves from numpy arrays: evaluation against hand values and independent numpy formulas,
vectorised results equal to one-by-one results, operations that keep the shape, queries,
and errors raised as camber exceptions."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import camber

CUBIC = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])


def bernstein_point(cp, t):
    """An independent cubic Bézier evaluation (power basis of the Bernstein polynomials)."""
    n = len(cp) - 1
    return sum(math.comb(n, i) * t**i * (1 - t) ** (n - i) * cp[i] for i in range(n + 1))


def test_bezier_evaluates_like_the_bernstein_formula():
    c = camber.BezierCurve(CUBIC)
    u = np.linspace(0.0, 1.0, 101)
    got = c.evaluate(u)
    assert got.shape == (101, 2)
    want = np.array([bernstein_point(CUBIC, t) for t in u])
    np.testing.assert_allclose(got, want, atol=1e-13)
    # One parameter gives one point.
    np.testing.assert_allclose(c.evaluate(0.5), [2.0, 1.5], atol=1e-14)


def test_derivatives_match_the_hand_values_and_finite_differences():
    c = camber.BezierCurve(CUBIC)
    d = c.derivatives(0.5, 2)
    assert d.shape == (3, 2)
    np.testing.assert_allclose(d[1], [4.5, 0.0], atol=1e-13)
    # C''(t) = 6[(1-t)(P2 - 2P1 + P0) + t(P3 - 2P2 + P1)]
    p = CUBIC
    want2 = 6 * (0.5 * (p[2] - 2 * p[1] + p[0]) + 0.5 * (p[3] - 2 * p[2] + p[1]))
    np.testing.assert_allclose(d[2], want2, atol=1e-12)
    u = np.linspace(0.1, 0.9, 9)
    h = 1e-6
    fd = (c.evaluate(u + h) - c.evaluate(u - h)) / (2 * h)
    np.testing.assert_allclose(c.derivative(u), fd, atol=1e-7)
    assert c.derivatives(u, 3).shape == (9, 4, 2)


def test_bspline_clamped_uniform_matches_the_library_example():
    c = camber.BSplineCurve(3, [0, 0, 0, 0, 1, 1, 1, 1], CUBIC)
    np.testing.assert_allclose(c.evaluate(0.5), [2.0, 1.5], atol=1e-12)
    assert c.degree == 3 and c.domain == (0.0, 1.0)
    d = camber.BSplineCurve.clamped_uniform(3, CUBIC)
    np.testing.assert_allclose(d.knots, [0, 0, 0, 0, 1, 1, 1, 1])


def test_nurbs_circular_arc_lies_on_its_circle_with_curvature_one_over_r():
    arc = camber.NurbsCurve.circular_arc([1.0, -2.0], 3.0, 0.0, 1.5 * math.pi)
    a, b = arc.domain
    u = np.linspace(a, b, 57)
    r = np.linalg.norm(arc.evaluate(u) - [1.0, -2.0], axis=1)
    np.testing.assert_allclose(r, 3.0, atol=1e-12)
    np.testing.assert_allclose(arc.curvature(u), 1 / 3, atol=1e-10)
    np.testing.assert_allclose(arc.signed_curvature(u), 1 / 3, atol=1e-10)
    assert not arc.is_polynomial()


def test_hermite_ends_and_tangents():
    h = camber.HermiteCurve([0, 0], [1, 0], [1, 1], [1, -1])
    np.testing.assert_allclose(h.evaluate(np.array([0.0, 1.0])), [[0, 0], [1, 0]], atol=1e-15)
    np.testing.assert_allclose(h.derivative(0.0), [1, 1], atol=1e-14)
    np.testing.assert_allclose(h.derivative(1.0), [1, -1], atol=1e-14)
    b = h.to_bezier()
    u = np.linspace(0, 1, 11)
    np.testing.assert_allclose(b.evaluate(u), h.evaluate(u), atol=1e-14)
    assert isinstance(b, camber.BezierCurve)


def test_three_dimensional_curves():
    cp = np.array([[0, 0, 0], [1, 2, 1], [3, 2, -1], [4, 0, 0.0]])
    c = camber.BezierCurve(cp)
    assert c.dim == 3 and c.evaluate(np.linspace(0, 1, 4)).shape == (4, 3)
    t, p, dist = c.closest_point([2.0, 3.0, 0.0])
    np.testing.assert_allclose(p, c.evaluate(t), atol=1e-12)
    assert dist == pytest.approx(np.linalg.norm(p - [2.0, 3.0, 0.0]))


def test_operations_keep_the_shape():
    b = camber.BSplineCurve.clamped_uniform(3, [[0, 0], [1, 2], [2, -1], [3, 2], [4, 0]])
    u = np.linspace(0, 1, 41)
    for other in [b.insert_knot(0.3, 2), b.refine([0.2, 0.4, 0.6]), b.elevate_degree(1)]:
        np.testing.assert_allclose(other.evaluate(u), b.evaluate(u), atol=1e-12)
    left, right = b.split(0.4)
    np.testing.assert_allclose(left.evaluate(0.2), b.evaluate(0.2), atol=1e-12)
    np.testing.assert_allclose(right.evaluate(0.7), b.evaluate(0.7), atol=1e-12)
    rev = b.reversed()
    np.testing.assert_allclose(rev.evaluate(1 - u), b.evaluate(u), atol=1e-12)
    rep = b.reparameterized(2.0, 4.0)
    np.testing.assert_allclose(rep.evaluate(2 + 2 * u), b.evaluate(u), atol=1e-12)
    segs = b.to_bezier_segments()
    assert len(segs) == 2
    for a0, a1, seg in segs:
        np.testing.assert_allclose(seg.evaluate(0.5), b.evaluate(0.5 * (a0 + a1)), atol=1e-12)
    bz = camber.BezierCurve(CUBIC)
    s0, s1 = bz.subdivide(0.25)
    np.testing.assert_allclose(s1.evaluate(0.0), bz.evaluate(0.25), atol=1e-14)
    np.testing.assert_allclose(bz.elevate_degree(2).evaluate(u), bz.evaluate(u), atol=1e-13)
    np.testing.assert_allclose(bz.to_bspline().evaluate(u), bz.evaluate(u), atol=1e-13)
    np.testing.assert_allclose(bz.hodograph().evaluate(u), bz.derivative(u), atol=1e-12)


def test_json_round_trip():
    n = camber.NurbsCurve(2, [0, 0, 0, 1, 1, 1], [[0, 0], [1, 1], [2, 0]], [1, 2, 1])
    back = camber.NurbsCurve.from_json(n.to_json())
    u = np.linspace(0, 1, 7)
    np.testing.assert_allclose(back.evaluate(u), n.evaluate(u), atol=0)
    np.testing.assert_allclose(back.weights, [1, 2, 1])


def test_intersections_with_a_line_and_a_circle():
    c = camber.BezierCurve(CUBIC)
    params, points = c.intersect_line([0.0, 1.0], [1.0, 0.0])
    assert len(params) == 2
    np.testing.assert_allclose(points[:, 1], 1.0, atol=1e-9)
    np.testing.assert_allclose(c.evaluate(params), points, atol=1e-12)
    params, points = c.intersect_circle([2.0, 0.0], 1.0)
    np.testing.assert_allclose(np.linalg.norm(points - [2.0, 0.0], axis=1), 1.0, atol=1e-9)
    t, p, d = c.distance_to_line([0.0, 3.0], [1.0, 0.0])
    assert d == pytest.approx(1.5, abs=1e-9) and t == pytest.approx(0.5, abs=1e-7)


def test_errors_are_camber_exceptions_with_the_library_messages():
    with pytest.raises(camber.GeometryError, match="smaller than the knot before it"):
        camber.BSplineCurve(1, [0, 1, 0.5, 1], [[0, 0], [1, 1]])
    c = camber.BezierCurve(CUBIC)
    with pytest.raises(camber.GeometryError, match="outside"):
        c.evaluate(np.array([0.5, 1.5]))
    with pytest.raises(camber.GeometryError, match="weight"):
        camber.NurbsCurve(1, [0, 0, 1, 1], [[0, 0], [1, 1]], [1, -1])
    with pytest.raises(camber.GeometryError, match="needs a planar curve"):
        camber.BezierCurve([[0, 0, 0], [1, 1, 1]]).intersect_line([0, 0], [1, 0])
    with pytest.raises(camber.GeometryError, match="expected 2 coordinates"):
        c.closest_point([1.0, 2.0, 3.0])
    assert issubclass(camber.GeometryError, camber.CamberError)


finite = st.floats(-10, 10, allow_nan=False)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(finite, finite), min_size=2, max_size=7), st.floats(0, 1))
def test_vectorised_equals_one_by_one_and_de_casteljau(points, t):
    cp = np.array(points)
    c = camber.BezierCurve(cp)
    u = np.array([0.0, t, 1.0])
    many = c.evaluate(u)
    for i, ui in enumerate(u):
        np.testing.assert_array_equal(many[i], c.evaluate(float(ui)))
    # de Casteljau in numpy, an independent method.
    q = cp.copy()
    while len(q) > 1:
        q = (1 - t) * q[:-1] + t * q[1:]
    np.testing.assert_allclose(many[1], q[0], atol=1e-9 * (1 + np.abs(cp).max()))


@settings(max_examples=30, deadline=None)
@given(st.floats(0.05, 0.95), st.integers(1, 2))
def test_knot_insertion_never_moves_the_curve(u, times):
    # Up to twice: a cubic's interior knots (multiplicity 1) take at most 2 more.
    b = camber.BSplineCurve.clamped_uniform(3, [[0, 0], [1, 2], [2, -1], [3, 2], [4, 0], [5, 1]])
    v = np.linspace(0, 1, 23)
    np.testing.assert_allclose(b.insert_knot(u, times).evaluate(v), b.evaluate(v), atol=1e-11)


def test_closest_point_takes_an_array_of_points_and_answers_like_one_at_a_time():
    c = camber.BSplineCurve(
        3, [0, 0, 0, 0, 0.5, 1, 1, 1, 1], np.array([[0, 0], [1, 2], [2, -1], [3, 1], [4, 0.0]])
    )
    rng = np.random.default_rng(7)
    pts = rng.uniform(-1, 5, size=(40, 2))
    for arg in (pts, pts.astype(np.float32), pts[::-1], pts.T.copy().T, pts.tolist()):
        u, q, d = c.closest_point(arg)
        expected = np.asarray(arg, dtype=float)
        assert u.shape == (40,) and q.shape == (40, 2) and d.shape == (40,)
        for i, p in enumerate(expected):
            ui, qi, di = c.closest_point(p)
            assert u[i] == ui and d[i] == di
            np.testing.assert_array_equal(q[i], qi)
    u, q, d = c.closest_point(np.zeros((0, 2)))
    assert u.shape == (0,) and q.shape == (0, 2)
    with pytest.raises(camber.CamberError, match=r"\(n, 2\)"):
        c.closest_point(np.zeros((3, 3)))
    with pytest.raises(camber.GeometryError):
        c.closest_point(np.array([[0.0, 0.0], [np.nan, 1.0]]))
