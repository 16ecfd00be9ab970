"""Curve operations from Python against independent values: arc lengths of circles and lines
and dense polylines, points at a length on a circle by angle, natural extension by de
Casteljau outside [0, 1], extensions by a length, knot removal and degree reduction undoing
refinement and elevation, fits through data (hand chord-length parameters, exact parabolas),
curve-curve intersections and distances with hand roots, offsets of circles, and errors."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import camber

CUBIC = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])


def de_casteljau(cp, t):
    """An independent Bézier evaluation, valid for any real t (outside [0, 1] too)."""
    pts = np.array(cp, dtype=float)
    while len(pts) > 1:
        pts = (1 - t) * pts[:-1] + t * pts[1:]
    return pts[0]


def polyline_length(curve, n=200_001):
    pts = curve.evaluate(np.linspace(*curve.domain, n))
    return float(np.linalg.norm(np.diff(pts, axis=0), axis=1).sum())


# --- arc length --------------------------------------------------------------------------------


def test_arc_length_of_a_circular_arc_and_a_segment():
    arc = camber.NurbsCurve.circular_arc([1.0, -2.0], 2.0, 0.0, 2.0)
    assert arc.arc_length() == pytest.approx(4.0, abs=1e-9)  # r·θ
    line = camber.BezierCurve([[0, 0], [1, 1], [3, 3]])  # a straight but uneven Bézier
    assert line.arc_length() == pytest.approx(3 * math.sqrt(2), abs=1e-10)
    # Between two parameters: additive, and equal to the dense polyline.
    c = camber.BezierCurve(CUBIC)
    whole = c.arc_length()
    assert c.arc_length_between(0, 0.3) + c.arc_length_between(0.3, 1) == pytest.approx(whole, abs=1e-9)
    assert whole == pytest.approx(polyline_length(c), abs=1e-7)


def test_parameter_at_length_lands_at_the_angle_on_a_circle():
    r, center = 2.0, np.array([1.0, -2.0])
    arc = camber.NurbsCurve.circular_arc(center, r, 0.0, math.pi)
    s = np.linspace(0.0, math.pi * r, 9)
    u = arc.parameter_at_length(s)  # vectorised
    assert u.shape == (9,)
    want = center + r * np.column_stack([np.cos(s / r), np.sin(s / r)])
    np.testing.assert_allclose(arc.evaluate(u), want, atol=1e-8)
    assert arc.parameter_at_length(0.0) == pytest.approx(arc.domain[0])


def test_arc_length_map_spaces_points_evenly():
    r = 3.0
    arc = camber.NurbsCurve.circular_arc([0, 0], r, 0.0, 1.5)
    m = arc.arc_length_map(1e-9)
    assert isinstance(m, camber.ArcLengthMap)
    assert m.length == pytest.approx(r * 1.5, abs=1e-9)
    assert m.max_error <= 1e-9
    s = np.linspace(0, m.length, 50)
    pts = arc.evaluate(m.parameter(s))
    np.testing.assert_allclose(np.arctan2(pts[:, 1], pts[:, 0]), s / r, atol=1e-8)


@settings(max_examples=25, deadline=None)
@given(st.lists(st.floats(-5, 5), min_size=8, max_size=8), st.floats(0.05, 0.95))
def test_length_and_parameter_at_length_are_inverse(coords, frac):
    c = camber.BezierCurve(np.reshape(coords, (4, 2)))
    total = c.arc_length()
    if total < 1e-3:
        return
    assert total == pytest.approx(polyline_length(c, 20_001), rel=1e-5, abs=1e-6)
    u = c.parameter_at_length(frac * total, 1e-11)
    assert c.arc_length_between(0.0, u) == pytest.approx(frac * total, abs=1e-8)


# --- extension ---------------------------------------------------------------------------------


def test_natural_extension_continues_the_polynomial():
    c = camber.BezierCurve(CUBIC)
    e = c.extrapolated("end", 1.5)
    assert isinstance(e, camber.BezierCurve)
    # The new curve on [0, 1] is the old polynomial on [0, 1.5].
    for t in np.linspace(0, 1, 7):
        np.testing.assert_allclose(e.evaluate(t), de_casteljau(CUBIC, 1.5 * t), atol=1e-12)
    s = c.extrapolated("start", -0.5)
    np.testing.assert_allclose(s.evaluate(0.0), de_casteljau(CUBIC, -0.5), atol=1e-12)
    # A B-spline keeps its knots' parameterization: the domain grows.
    b = camber.BSplineCurve.clamped_uniform(3, CUBIC)
    be = b.extrapolated("end", 1.25)
    assert be.domain == pytest.approx((0.0, 1.25))
    np.testing.assert_allclose(be.evaluate(1.25), de_casteljau(CUBIC, 1.25), atol=1e-12)
    np.testing.assert_allclose(be.evaluate(0.4), b.evaluate(0.4), atol=1e-12)


def test_extension_by_length_g1_is_a_straight_piece_and_g2_adds_the_length():
    c = camber.BezierCurve(CUBIC)
    length = c.arc_length()
    g1 = c.extended_by_length("end", 1.0, "G1")
    assert isinstance(g1, camber.BSplineCurve)
    assert g1.arc_length() == pytest.approx(length + 1.0, abs=1e-8)
    tangent = c.derivative(1.0) / np.linalg.norm(c.derivative(1.0))
    np.testing.assert_allclose(g1.evaluate(g1.domain[1]), CUBIC[-1] + tangent, atol=1e-9)
    g2 = c.extended_by_length("start", 0.5, "G2")
    assert g2.arc_length() == pytest.approx(length + 0.5, abs=1e-6)
    # G2: the curvature is continuous where the old start now sits.
    u_join = g2.parameter_at_length(0.5)
    assert g2.curvature(u_join) == pytest.approx(c.curvature(0.0), rel=1e-6)
    n = camber.NurbsCurve.circular_arc([0, 0], 1.0, 0.0, 1.0)
    ne = n.extended_by_length("end", 0.5, "G2")
    # The arc continued naturally stays on the circle.
    np.testing.assert_allclose(np.linalg.norm(ne.evaluate(ne.domain[1])), 1.0, atol=1e-6)


# --- knot removal, degree reduction ------------------------------------------------------------


def test_knot_removal_undoes_refinement():
    b = camber.BSplineCurve(2, [0, 0, 0, 0.5, 1, 1, 1], [[0, 0], [1, 2], [3, 1], [4, 0]])
    busy = b.refine([0.2, 0.5, 0.7])
    clean, removed, bound = busy.remove_knots(1e-10)
    assert removed == 3 and bound < 1e-10
    np.testing.assert_allclose(clean.control_points, b.control_points, atol=1e-10)
    one, removed1, _ = busy.remove_knot(0.2, 1, 1e-10)
    assert removed1 == 1 and len(one.control_points) == len(busy.control_points) - 1
    # The original knot 0.5 holds a real corner of the polygon: not removable at 1e-10.
    _, none, _ = b.remove_knot(0.5, 1, 1e-10)
    assert none == 0


def test_degree_reduction_undoes_elevation_and_bounds_the_error():
    c = camber.BezierCurve(CUBIC)
    back, bound = c.elevate_degree(2).reduce_degree()
    assert back.degree == 4 and bound < 1e-10
    low, bound = c.reduce_degree()  # a real cubic: the quadratic deviates
    u = np.linspace(0, 1, 2001)
    deviation = np.linalg.norm(c.evaluate(u) - low.evaluate(u), axis=1).max()
    assert low.degree == 2 and 0 < deviation <= bound + 1e-12
    b = camber.BSplineCurve.clamped_uniform(2, CUBIC)
    rb, bound = b.elevate_degree(1).reduce_degree(1e-9)
    assert rb.degree == 2 and bound < 1e-9
    np.testing.assert_allclose(rb.evaluate(u), b.evaluate(u), atol=1e-9)
    n = camber.NurbsCurve.circular_arc([0, 0], 1.0, 0.0, 1.0)
    rn, bound = n.elevate_degree(1).reduce_degree(1e-9)
    assert rn.degree == 2
    np.testing.assert_allclose(rn.evaluate(np.linspace(0, 1, 50)), n.evaluate(np.linspace(0, 1, 50)), atol=1e-8)
    # A true quadratic spline cannot drop to lines within 1e-9: the bound says so and holds.
    lines, bound = b.reduce_degree(1e-9)
    deviation = np.linalg.norm(b.evaluate(u) - lines.evaluate(u), axis=1).max()
    assert lines.degree == 1 and 1e-9 < deviation <= bound + 1e-12


# --- fitting -----------------------------------------------------------------------------------


def test_interpolation_passes_through_the_data_at_chord_length_parameters():
    pts = np.array([[0, 0], [1, 1], [3, 1], [4, 3], [6, 2]], dtype=float)
    curve, params, err = camber.interpolate(pts, degree=3)
    chords = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    np.testing.assert_allclose(params, np.concatenate([[0], np.cumsum(chords)]) / chords.sum(), atol=1e-14)
    np.testing.assert_allclose(curve.evaluate(params), pts, atol=1e-10)
    assert err < 1e-10
    # End derivatives are met.
    c2, p2, _ = camber.interpolate(pts, 3, "centripetal", end_derivatives=([5, 0], [0, 5]))
    np.testing.assert_allclose(c2.derivative(0.0), [5, 0], atol=1e-9)
    np.testing.assert_allclose(c2.derivative(1.0), [0, 5], atol=1e-9)
    uni, pu, _ = camber.interpolate(pts, 2, "uniform")
    np.testing.assert_allclose(pu, np.linspace(0, 1, 5), atol=1e-15)
    # 3-D data.
    c3, p3, _ = camber.interpolate(np.column_stack([pts, pts[:, 0] ** 2]))
    assert c3.dim == 3


def test_least_squares_recovers_an_exact_parabola_and_fit_to_tolerance_holds():
    x = np.linspace(-1, 1, 40)
    data = np.column_stack([x, x * x])
    curve, params, err = camber.approximate(data, 2, 3, method="uniform")
    # y = x² over uniform x is a quadratic Bézier in the uniform parameter: exact.
    assert err < 1e-12
    np.testing.assert_allclose(curve.control_points, [[-1, 1], [0, -1], [1, 1]], atol=1e-12)
    t = np.linspace(0, 4 * math.pi, 200)
    wave = np.column_stack([t, np.sin(t)])
    fit, params, err = camber.fit_to_tolerance(wave, 3, 1e-4)
    assert err <= 1e-4
    measured = np.linalg.norm(fit.evaluate(params) - wave, axis=1).max()
    assert measured == pytest.approx(err, abs=1e-12)
    assert len(fit.control_points) < len(wave)


def naca0012(n):
    x = 0.5 * (1 - np.cos(np.linspace(0, np.pi, n)))
    yt = 0.6 * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1015 * x**4)
    return np.vstack([np.column_stack([x, yt])[::-1], np.column_stack([x, -yt])[1:]])


def test_adaptive_fits_report_distances_and_split_at_the_leading_edge():
    section = naca0012(101)  # 201 points, leading edge at index 100
    curve, params, err = camber.fit_to_tolerance(section, 3, 1e-4, method="centripetal")
    assert err <= 1e-4 and len(curve.control_points) < 40
    # The parameters are the closest points': the distance there is the reported error.
    assert np.linalg.norm(curve.evaluate(params) - section, axis=1).max() == pytest.approx(err, abs=1e-12)
    # Adaptive least squares beats averaged knots for the same count.
    _, _, averaged = camber.approximate(section, 3, 16)
    _, _, adaptive = camber.approximate(section, 3, 16, knots="adaptive")
    assert adaptive < 0.5 * averaged
    pieces, piece_params, err = camber.fit_to_tolerance(section, 3, 1e-4, split="leading_edge", joint="G2")
    assert len(pieces) == 2 and len(piece_params) == 2 and err <= 1e-4
    np.testing.assert_allclose(pieces[0].evaluate(1.0), section[100], atol=1e-12)
    np.testing.assert_allclose(pieces[1].evaluate(0.0), section[100], atol=1e-12)
    t0, t1 = pieces[0].derivative(1.0), pieces[1].derivative(0.0)
    assert abs(t0[0] * t1[1] - t0[1] * t1[0]) < 1e-9 * np.linalg.norm(t0) * np.linalg.norm(t1)


@pytest.mark.parametrize(
    "kwargs",
    [{"knots": "smart"}, {"split": "trailing_edge"}, {"split": [1.5]}, {"split": [float("nan")]},
     {"joint": "C1"}, {"split": [0.0]}],
)
def test_bad_fit_options_are_refused(kwargs):
    with pytest.raises(camber.CamberError):
        camber.fit_to_tolerance(naca0012(21), 3, 1e-4, **kwargs)


def test_hostile_fit_data_is_refused():
    for data in ([[0.0, 0.0]], np.zeros((0, 2)), [[0, 0], [1, np.nan], [2, 0], [3, 1]],
                 [[0, 0], [0, 0], [1, 1], [2, 0]]):
        with pytest.raises(camber.CamberError):
            camber.fit_to_tolerance(data, 3, 1e-4)
    with pytest.raises(camber.CamberError):
        camber.fit_to_tolerance(naca0012(21), 3, -1.0)


# --- curve-curve queries, offsets --------------------------------------------------------------


def test_parabola_meets_the_circle_at_the_roots_of_x4_minus_x2():
    parabola = camber.BezierCurve([[-2, 3], [0, -5], [2, 3]])  # y = x² − 1
    circle = camber.NurbsCurve.circular_arc([0, 0], 1.0, 0.0, 2 * math.pi)
    hits = parabola.intersect_curve(circle)
    xs = sorted(h["point_a"][0] for h in hits)
    np.testing.assert_allclose(xs, [-1, 0, 1], atol=1e-7)
    touch = [h for h in hits if abs(h["point_a"][0]) < 1e-6][0]
    assert touch["tangential"]
    for h in hits:
        np.testing.assert_allclose(parabola.evaluate(h["parameter_a"]), h["point_a"], atol=1e-12)
        np.testing.assert_allclose(circle.evaluate(h["parameter_b"]), h["point_b"], atol=1e-12)


def test_two_segments_cross_where_the_linear_system_says():
    a0, a1, b0, b1 = map(np.array, ([0.0, 0.0], [4.0, 2.0], [1.0, 3.0], [3.0, -1.0]))
    s, t = np.linalg.solve(np.column_stack([a1 - a0, b0 - b1]), b0 - a0)
    hits = camber.BezierCurve([a0, a1]).intersect_curve(camber.HermiteCurve(b0, b1, b1 - b0, b1 - b0))
    assert len(hits) == 1
    assert hits[0]["parameter_a"] == pytest.approx(s, abs=1e-9)
    assert hits[0]["parameter_b"] == pytest.approx(t, abs=1e-9)
    assert not hits[0]["tangential"]


def test_distance_between_curves():
    seg = camber.BezierCurve([[-1, 3], [1, 3]])
    circle = camber.NurbsCurve.circular_arc([0, 0], 1.0, 0.0, 2 * math.pi)
    near = seg.distance_to_curve(circle)
    assert near["distance"] == pytest.approx(2.0, abs=1e-9)
    np.testing.assert_allclose(near["point_b"], [0, 1], atol=1e-6)
    c3a = camber.BezierCurve([[0, 0, 0], [1, 0, 0]])
    c3b = camber.BezierCurve([[0.5, -1, 2], [0.5, 1, 2]])  # skew lines 2 apart
    assert c3a.distance_to_curve(c3b)["distance"] == pytest.approx(2.0, abs=1e-9)


def test_offset_of_a_circle_is_a_circle():
    arc = camber.NurbsCurve.circular_arc([1, 1], 2.0, 0.0, 2.0)
    inner, err = arc.offset(0.5, 1e-7)  # left of a counter-clockwise arc: towards the centre
    assert isinstance(inner, camber.BSplineCurve) and err <= 1e-7
    radii = np.linalg.norm(inner.evaluate(np.linspace(0, 1, 500)) - [1, 1], axis=1)
    np.testing.assert_allclose(radii, 1.5, atol=2e-7)
    outer, _ = camber.BezierCurve(CUBIC).offset(-0.25, 1e-6)
    pts = outer.evaluate(np.linspace(0, 1, 200))
    # Every point of the offset is 0.25 from the original (closest point query).
    base = camber.BezierCurve(CUBIC)
    dist = [base.closest_point(p)[2] for p in pts]
    np.testing.assert_allclose(dist, 0.25, atol=2e-6)


def test_hermite_curves_have_the_same_operations():
    h = camber.HermiteCurve([0, 0], [3, 0], [3, 0], [3, 0])  # the segment at unit speed ×3
    assert h.arc_length() == pytest.approx(3.0, abs=1e-12)
    assert h.parameter_at_length(1.0) == pytest.approx(1 / 3, abs=1e-10)
    assert h.curvature(0.5) == pytest.approx(0.0, abs=1e-12)
    u, p, d = h.closest_point([1.0, 2.0])
    assert (u, d) == (pytest.approx(1 / 3), pytest.approx(2.0))


# --- errors ------------------------------------------------------------------------------------


def test_bad_input_raises_camber_errors_with_the_value():
    c = camber.BezierCurve(CUBIC)
    with pytest.raises(camber.GeometryError, match="middle"):
        c.extrapolated("middle", 1.5)
    with pytest.raises(camber.GeometryError, match="G3"):
        c.extended_by_length("end", 1.0, "G3")
    with pytest.raises(camber.GeometryError, match="-1"):
        c.arc_length(-1.0)
    with pytest.raises(camber.GeometryError, match="same dimension"):
        c.intersect_curve(camber.BezierCurve([[0, 0, 0], [1, 1, 1]]))
    with pytest.raises(camber.GeometryError, match="planar"):
        camber.BezierCurve([[0, 0, 0], [1, 1, 1]]).offset(1.0)
    with pytest.raises(camber.GeometryError):
        c.parameter_at_length(100.0)
    with pytest.raises(camber.GeometryError):
        camber.interpolate([[0, 0], [0, 0], [1, 1]])  # coincident data points


def test_nurbs_knot_removal_and_natural_extension_stay_on_the_circle():
    arc = camber.NurbsCurve.circular_arc([0, 0], 2.0, 0.0, 1.2)
    busy = arc.insert_knot(0.3, 1)
    back, removed, bound = busy.remove_knot(0.3, 1, 1e-9)
    assert removed == 1 and bound < 1e-9
    assert len(back.control_points) == len(arc.control_points)
    u = np.linspace(*arc.domain, 40)
    np.testing.assert_allclose(back.evaluate(u), arc.evaluate(u), atol=1e-9)
    # The rational piece continued past its end is the same conic: still radius 2.
    a, b = arc.domain
    longer = arc.extrapolated("end", b + 0.2 * (b - a))
    radii = np.linalg.norm(longer.evaluate(np.linspace(*longer.domain, 60)), axis=1)
    np.testing.assert_allclose(radii, 2.0, atol=1e-10)


def test_long_operations_release_the_gil():
    import threading

    t = np.linspace(0, 40 * np.pi, 20_000)
    wave = np.column_stack([t, np.sin(t)])
    started, done = threading.Event(), threading.Event()
    result = {}

    def work():
        started.set()
        result["fit"] = camber.fit_to_tolerance(wave, 3, 1e-7)  # about half a second
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    started.wait()
    ticks = 0
    while not done.is_set():
        ticks += 1  # Python runs here only while the fit has let the GIL go
    worker.join()
    assert result["fit"][2] <= 1e-7
    assert ticks > 1000
