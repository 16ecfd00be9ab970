"""Custom constraints written in Python: solved through the library's custom path, their
Jacobian (from num-dual's dual numbers) equal to central differences, nonlinear residuals
with numpy ufuncs, own parameters written back, and Python errors raised after the solve."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import camber
from camber._native import _custom_derivatives
from camber.custom import finite_difference_jacobian


def unit_apart(x):
    # q.x - p.x - 1
    return [x[2] - x[0] - 1.0]


def test_affine_custom_constraint_is_solved():
    s = camber.Sketch()
    p, q = s.add_point([0, 0]), s.add_point([3, 0])
    s.add_constraint("fixed", target={"point": {"point": p}})
    cid = s.add_custom(unit_apart, [p, q], dim=1, name="unit apart", affine=True)
    report = s.solve()
    assert s.point(q)[0] - s.point(p)[0] == pytest.approx(1.0, abs=1e-10)
    assert report.residuals[cid] < 1e-10
    # Declared affine, the component takes the linear path and moves q the least: along x.
    np.testing.assert_allclose(s.point(q), [1.0, 0.0], atol=1e-10)


def on_unit_circle(x):
    return [x[0] * x[0] + x[1] * x[1] - 1.0]


def test_nonlinear_custom_constraint_with_numpy_functions():
    s = camber.Sketch()
    p = s.add_point([0.3, 0.9])
    # The point sits on the unit circle at the angle of an own parameter, which is 0.5 rad.
    s.add_custom(
        lambda x: [x[0] - np.cos(x[2]), x[1] - np.sin(x[2]), x[2] - 0.5],
        [p, {"param": 0.4}],
        dim=3,
        name="on a ray",
    )
    report = s.solve()
    np.testing.assert_allclose(s.point(p), [np.cos(0.5), np.sin(0.5)], atol=1e-9)
    assert report.max_residual < 1e-9


def test_own_parameter_is_written_back():
    s = camber.Sketch()
    p = s.add_point([1.0, 0.75])
    s.add_constraint("fixed", target={"point": {"point": p}})
    # p lies on the parabola y = 4t(1 - t) at a free parameter t, starting at 0.2: t = 0.25.
    cid = s.add_custom(lambda x: [x[1] - 4 * x[2] * (1 - x[2])], [p, {"param": 0.2}], dim=1)
    s.solve()
    (t,) = s.custom_params(cid)
    assert t == pytest.approx(0.25, abs=1e-9)


def test_python_errors_are_raised_after_the_solve():
    def broken(x):
        raise ValueError("boom from the residual")

    s = camber.Sketch()
    p = s.add_point([0, 0])
    s.add_custom(broken, [p], dim=1)
    with pytest.raises(ValueError, match="boom"):
        s.solve()


def test_wrong_number_of_values_is_an_error():
    s = camber.Sketch()
    p = s.add_point([0, 0])
    s.add_custom(lambda x: [x[0], x[1]], [p], dim=1)
    with pytest.raises(camber.SketchError, match="declared dim 1"):
        s.solve()


def residual(x):
    # Two rows mixing products, quotients and ufuncs of four numbers.
    return [
        x[0] * x[1] - np.sin(x[2]) + x[3] ** 3,
        np.exp(0.1 * x[0]) / (2.0 + x[1] * x[1]) + np.sqrt(1.0 + x[2] * x[2]) * x[3],
    ]


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-2, 2), min_size=4, max_size=4), st.floats(-1, 1), st.floats(-1, 1))
def test_camber_jacobian_and_hessian_equal_central_differences(x, w0, w1):
    # Blocks as a point and two numbers read them: (x0, x1), x2, x3.
    values, jac, hess = _custom_derivatives(residual, [2, 1, 1], x, 2, [w0, w1])
    np.testing.assert_allclose(values, [float(v) for v in residual(x)], rtol=1e-13, atol=1e-13)
    fd = finite_difference_jacobian(residual, x, h=1e-6)
    np.testing.assert_allclose(jac, fd, rtol=1e-6, atol=1e-7)

    # The weighted Hessian: central differences of the weighted gradient (itself exact).
    def grad(y):
        _, j, _ = _custom_derivatives(residual, [2, 1, 1], y, 2, [w0, w1])
        return w0 * np.array(j[0]) + w1 * np.array(j[1])

    h = 1e-5
    fd_h = np.array(
        [(grad(np.add(x, h * e)) - grad(np.subtract(x, h * e))) / (2 * h) for e in np.eye(4)]
    )
    np.testing.assert_allclose(hess, fd_h, rtol=1e-5, atol=1e-6)


# --- Custom residuals reading whole curves ---------------------------------------------------

from camber.custom import control_points, curve_point, real  # noqa: E402


def test_curve_point_helper_matches_the_library_on_every_kind():
    bez = camber.BezierCurve([[0, 0], [1, 2], [3, 2], [4, 0]])
    bsp = camber.BSplineCurve(2, [0, 0, 0, 0.3, 1, 1, 1], [[0, 0], [1, 2], [3, 1], [4, 0]])
    nrb = camber.NurbsCurve(2, [0, 0, 0, 1, 1, 1], [[1, 0], [1, 1], [0, 1]], [1, 0.5**0.5, 1])
    for c in (bez, bsp, nrb):
        pts = [list(p) for p in c.control_points]
        for u in np.linspace(*c.domain, 7):
            np.testing.assert_allclose(curve_point(c, pts, u), c.evaluate(u), atol=1e-13)


def through_point_sketch():
    """A free B-spline, a fixed point off it, and a custom constraint C(t) = P with an own
    parameter t: only the curve can move."""
    s = camber.Sketch()
    ctrl = [[0, 0], [1, 2], [3, 2], [4, 0]]
    cid = s.add_curve(camber.BSplineCurve(2, [0, 0, 0, 0.5, 1, 1, 1], ctrl))
    p = s.add_point([2.0, 2.5])
    s.add_constraint("fixed", target={"point": {"point": p}})
    shape = s.curve(cid)  # degree and knots: data, read before the solve

    def through(x):
        pts = control_points(x, 0, 4)
        c = curve_point(shape, pts, x[8])
        return [c[0] - x[9], c[1] - x[10]]

    k = s.add_custom(through, [{"curve": cid}, {"param": 0.5}, p], dim=2, name="through")
    return s, cid, p, k


def test_custom_residual_reading_a_whole_curve_is_solved():
    s, cid, p, k = through_point_sketch()
    before = s.curve(cid).control_points.copy()
    report = s.solve()
    (t,) = s.custom_params(k)
    # The library's own evaluation of the solved curve passes through the point.
    np.testing.assert_allclose(s.curve(cid).evaluate(t), s.point(p), atol=1e-9)
    assert report.residuals[k] < 1e-9
    # The control points moved (the point was 0.9 off the curve).
    assert np.abs(s.curve(cid).control_points - before).max() > 0.05


def nurbs_residual(shape, n):
    def g(x):
        c = curve_point(shape, control_points(x, 0, n), x[2 * n])
        # Two rows: a nonlinear function of the curve point and of the control polygon.
        edge = (x[2] - x[0]) ** 2 + (x[3] - x[1]) ** 2
        return [c[0] * c[1] - 0.3, c[0] ** 2 + np.sin(c[1]) + 0.1 * edge]

    return g


@settings(max_examples=25, deadline=None)
@given(
    st.lists(st.floats(-1, 1), min_size=8, max_size=8),
    st.floats(0.05, 0.95),
    st.floats(-1, 1),
    st.floats(-1, 1),
)
def test_curve_residual_jacobian_and_hessian_equal_central_differences(moves, u, w0, w1):
    base = np.array([[0, 0], [1, 2], [3, 1], [4, 0]], dtype=float)
    shape = camber.NurbsCurve(2, [0, 0, 0, 0.4, 1, 1, 1], base, [1, 2, 0.5, 1])
    g = nurbs_residual(shape, 4)
    x = list((base + 0.2 * np.reshape(moves, (4, 2))).ravel()) + [u]
    sizes = [2, 2, 2, 2, 1]  # the blocks a curve of 4 control points and a parameter give
    values, jac, hess = _custom_derivatives(g, sizes, x, 2, [w0, w1])
    np.testing.assert_allclose(values, [real(v) for v in g(x)], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(jac, finite_difference_jacobian(g, x, h=1e-6), rtol=1e-6, atol=1e-7)

    def grad(y):
        _, j, _ = _custom_derivatives(g, sizes, list(y), 2, [w0, w1])
        return w0 * np.array(j[0]) + w1 * np.array(j[1])

    h = 1e-5
    fd_h = np.array(
        [(grad(np.add(x, h * e)) - grad(np.subtract(x, h * e))) / (2 * h) for e in np.eye(9)]
    )
    np.testing.assert_allclose(hess, fd_h, rtol=1e-5, atol=1e-5)


def test_a_curve_argument_must_be_a_curve():
    s = camber.Sketch()
    p = s.add_point([0, 0])
    with pytest.raises(camber.SketchError, match=str(p)):
        s.add_custom(lambda x: [x[0]], [{"curve": p}], dim=1)
