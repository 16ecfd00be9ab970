"""`Sketch.curve` for every curve-like entity: ellipses and elliptic arcs as exact NURBS,
Hermite curves as themselves, composites as the exact cubic B-spline, each checked against
the entity's own closed form."""

import math

import numpy as np
import pytest

import camber


def sketch_of(*entities):
    items = [{"id": i, **e} for i, e in enumerate(entities)]
    return camber.Sketch.from_dict({"version": 1, "entities": items, "constraints": []})


def hermite(p0, p1, t0, t1, s):
    """The cubic Hermite basis at local s ∈ [0, 1]."""
    h00, h10 = 2 * s**3 - 3 * s**2 + 1, s**3 - 2 * s**2 + s
    h01, h11 = -2 * s**3 + 3 * s**2, s**3 - s**2
    return h00 * np.array(p0) + h10 * np.array(t0) + h01 * np.array(p1) + h11 * np.array(t1)


def test_an_ellipse_and_an_elliptic_arc_are_exact_nurbs_curves():
    c, a, b, rot = np.array([1.0, -2.0]), 3.0, 1.25, 0.4
    s = sketch_of(
        {"kind": "ellipse", "center": list(c), "semi_axis_a": a, "semi_axis_b": b, "rotation": rot},
        {
            "kind": "elliptic_arc", "center": list(c), "semi_axis_a": a, "semi_axis_b": b,
            "rotation": rot, "start_angle": 0.5, "end_angle": 2.5,
        },
    )
    u = np.array([math.cos(rot), math.sin(rot)])
    v = np.array([-u[1], u[0]])
    for i in (0, 1):
        curve = s.curve(i)
        assert isinstance(curve, camber.NurbsCurve)
        lo, hi = curve.domain
        pts = curve.evaluate(np.linspace(lo, hi, 41)) - c
        # Every point satisfies (x'/a)² + (y'/b)² = 1 in the ellipse's frame.
        np.testing.assert_allclose((pts @ u / a) ** 2 + (pts @ v / b) ** 2, 1.0, atol=1e-13)
    arc = s.curve(1)
    lo, hi = arc.domain
    np.testing.assert_allclose(arc.evaluate(lo), c + a * math.cos(0.5) * u + b * math.sin(0.5) * v, atol=1e-13)
    np.testing.assert_allclose(arc.evaluate(hi), c + a * math.cos(2.5) * u + b * math.sin(2.5) * v, atol=1e-13)


def test_a_hermite_curve_is_itself_and_a_composite_its_cubic_bspline():
    s = sketch_of(
        {"kind": "hermite", "p0": [0, 0], "p1": [2, 1], "t0": [1, 2], "t1": [2, -1]},
        {
            "kind": "composite",
            "nodes": [[0, 0], [1, 1], [2, 0]],
            "tangents": [[1, 2], [1, 0], [1, -2]],
            "joins": ["smooth"],
        },
    )
    h = s.curve(0)
    assert isinstance(h, camber.HermiteCurve)
    t = np.linspace(0, 1, 11)
    np.testing.assert_allclose(h.evaluate(t), [hermite([0, 0], [2, 1], [1, 2], [2, -1], x) for x in t], atol=1e-14)
    chain = s.curve(1)
    assert isinstance(chain, camber.BSplineCurve)
    assert chain.domain == (0.0, 2.0)
    for seg, (p0, p1, t0, t1) in enumerate(
        [([0, 0], [1, 1], [1, 2], [1, 0]), ([1, 1], [2, 0], [1, 0], [1, -2])]
    ):
        expected = [hermite(p0, p1, t0, t1, x) for x in t]
        np.testing.assert_allclose(chain.evaluate(seg + t), expected, atol=1e-14)
    # The same points as the sketch's own evaluation.
    np.testing.assert_allclose(chain.evaluate(1.5), s.curve_point(1, 1.5), atol=1e-14)


def test_points_and_circles_are_not_curves():
    s = sketch_of({"kind": "point", "at": [0, 0]}, {"kind": "circle", "center": [0, 0], "radius": 1})
    for i in (0, 1):
        with pytest.raises(camber.SketchError, match="not a curve"):
            s.curve(i)
