"""`CompositeCurve`: a chain of curves of any kind under one global parameter s ∈ [0, n],
checked against its pieces evaluated by hand through the affine map, finite differences, the
sum of the pieces' lengths, hand-derived joint reports, and exact JSON and pickle round trips."""

import json
import math
import pickle

import numpy as np
import pytest

import camber


def line(a, b):
    return camber.BezierCurve([a, b])


def quarter_arc():
    """The quarter circle of radius 2 about (1, 2) from (1, 0) to (3, 2), tangent to the x axis
    at its start."""
    return camber.NurbsCurve.circular_arc([1.0, 2.0], 2.0, -math.pi / 2, 0.0)


def bspline_on_2_5():
    """A cubic B-spline on the domain [2, 5] (so the chain rule's factor is 3), starting at
    (3, 2), where the arc ends."""
    knots = [2, 2, 2, 2, 3.5, 5, 5, 5, 5]
    pts = [[3, 2], [3, 3], [2, 4], [1, 4], [0, 3.5]]
    return camber.BSplineCurve(3, knots, pts)


def chain():
    return camber.CompositeCurve([line([0, 0], [1, 0]), quarter_arc(), bspline_on_2_5()])


def test_the_chain_evaluates_each_piece_through_the_affine_map_of_its_interval():
    c = chain()
    pieces = c.pieces
    assert len(c) == 3 and c.domain == (0.0, 3.0)
    assert [type(p).__name__ for p in pieces] == ["BezierCurve", "NurbsCurve", "BSplineCurve"]
    s = np.linspace(0.0, 3.0, 301)
    got = c.evaluate(s)
    for k, sk in enumerate(s):
        i = min(int(math.floor(sk)), 2)
        a, b = pieces[i].domain
        u = a + (sk - i) * (b - a)
        np.testing.assert_allclose(got[k], pieces[i].evaluate(u), atol=1e-14)
        assert c.locate(sk)[0] == i
        assert math.isclose(c.locate(sk)[1], u, abs_tol=1e-14)


def test_derivatives_in_the_global_parameter_carry_the_scale_of_each_piece():
    c = chain()
    # Inside the B-spline piece (domain length 3) the first derivative is 3 C'(u).
    s = 2.4
    _, u = c.locate(s)
    np.testing.assert_allclose(c.derivative(s), 3.0 * c.pieces[2].derivative(u), rtol=1e-13)
    second = c.derivatives(s, order=2)[2]
    np.testing.assert_allclose(second, 9.0 * c.pieces[2].derivatives(u, order=2)[2], rtol=1e-13)
    # And the evaluation agrees with central differences everywhere off the joints.
    h = 1e-6
    for s in [0.3, 1.2, 1.7, 2.05, 2.9]:
        fd = (c.evaluate(s + h) - c.evaluate(s - h)) / (2 * h)
        np.testing.assert_allclose(c.derivative(s), fd, atol=1e-7)


def test_joint_reports_match_the_hand_derived_values():
    c = chain()
    first, second = c.joints()
    # Line → arc: same point (1, 0), both tangents along +x; curvature jumps from 0 to 1/2.
    assert first["index"] == 0
    assert first["position_gap"] < 1e-15
    assert first["tangent_angle"] < 1e-15
    assert math.isclose(first["curvature_difference"], 0.5, rel_tol=1e-12)
    assert first["continuity"] == "G1"
    # Arc → B-spline: same point (3, 2), tangent +y on both sides.
    assert second["index"] == 1 and second["position_gap"] < 1e-15
    assert second["continuity"] in ("G1", "C1", "G2", "C2")
    assert second["tangent_angle"] < 1e-12
    # A corner is C0 with the corner's angle; a gap is no continuity.
    corner = camber.CompositeCurve([line([0, 0], [1, 0]), line([1, 0], [1, 1])]).joints()[0]
    assert corner["continuity"] == "C0"
    assert math.isclose(corner["tangent_angle"], math.pi / 2, rel_tol=1e-15)
    gap = camber.CompositeCurve([line([0, 0], [1, 0]), line([1, 0.5], [2, 0.5])]).joints()[0]
    assert gap["continuity"] == "none" and math.isclose(gap["position_gap"], 0.5)
    # A looser position tolerance accepts the gap: then the equal, straight legs make it C2.
    assert camber.CompositeCurve([line([0, 0], [1, 0]), line([1, 0.5], [2, 0.5])]).joints(
        position=0.6
    )[0]["continuity"] == "C2"


def test_the_length_of_the_chain_is_the_sum_of_its_pieces():
    c = chain()
    pieces = c.pieces
    total = sum(p.arc_length(tolerance=1e-12) for p in pieces)
    assert math.isclose(pieces[0].arc_length(), 1.0, rel_tol=1e-14)
    assert math.isclose(pieces[1].arc_length(), math.pi, rel_tol=1e-12)
    assert math.isclose(c.arc_length(tolerance=1e-12), total, rel_tol=1e-11)


def test_queries_answer_in_the_global_parameter():
    c = chain()
    # The point (3 + √2, 2 − √2)·… : the arc point at angle −π/4 is nearest to a point on its
    # radius outside the circle.
    theta = -math.pi / 4
    on_arc = np.array([1 + 2 * math.cos(theta), 2 + 2 * math.sin(theta)])
    outside = on_arc + 0.5 * np.array([math.cos(theta), math.sin(theta)])
    s, p, d = c.closest_point(outside)
    assert 1.0 < s < 2.0
    np.testing.assert_allclose(p, on_arc, atol=1e-9)
    assert math.isclose(d, 0.5, rel_tol=1e-9)
    # The line x = 2 crosses the arc once (at y = 2 − √3) and the B-spline once.
    params, points = c.intersect_line([2.0, -1.0], [0.0, 1.0])
    assert len(params) == 2
    assert 1.0 < params[0] < 2.0 < params[1] < 3.0
    np.testing.assert_allclose(points[0], [2.0, 2.0 - math.sqrt(3.0)], atol=1e-9)


def test_reversal_runs_the_chain_backwards_and_twice_is_identity():
    c = chain()
    r = c.reversed()
    assert isinstance(r, camber.CompositeCurve)
    s = np.linspace(0.0, 3.0, 61)
    np.testing.assert_allclose(r.evaluate(3.0 - s), c.evaluate(s), atol=1e-13)
    np.testing.assert_allclose(r.reversed().evaluate(s), c.evaluate(s), atol=1e-15)


def test_json_and_pickle_round_trips_are_exact():
    c = chain()
    text = c.to_json()
    form = json.loads(text)
    assert [p["type"] for p in form["pieces"]] == ["bezier", "nurbs", "bspline"]
    back = camber.CompositeCurve.from_json(text)
    s = np.linspace(0.0, 3.0, 97)
    assert np.array_equal(back.evaluate(s), c.evaluate(s))
    again = pickle.loads(pickle.dumps(c))
    assert isinstance(again, camber.CompositeCurve)
    assert np.array_equal(again.evaluate(s), c.evaluate(s))
    # A spatial chain (with a Hermite piece) round-trips too.
    h = camber.HermiteCurve([1, 0, 0], [2, 1, 1], [1, 0, 0], [0, 1, 1])
    c3 = camber.CompositeCurve([camber.BezierCurve([[0, 0, 0], [1, 0, 0]]), h])
    assert c3.dim == 3
    back3 = pickle.loads(pickle.dumps(c3))
    assert np.array_equal(back3.evaluate(s[s <= 2.0]), c3.evaluate(s[s <= 2.0]))


def test_a_split_fit_becomes_one_chain_and_reads_the_fit_file_form():
    x = 0.5 * (1 - np.cos(np.linspace(0, math.pi, 60)))
    yt = 0.6 * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1015 * x**4)
    pts = np.vstack([np.column_stack([x, yt])[::-1], np.column_stack([x, -yt])[1:]])
    curves, _, err = camber.fit_to_tolerance(pts, 3, 1e-4, split="leading_edge")
    c = camber.CompositeCurve(curves)
    assert len(c) == len(curves) == 2
    (joint,) = c.joints(position=1e-12, angle=1e-9)
    assert joint["continuity"] in ("G1", "C1", "G2", "C2")
    # Every data point within the fit's tolerance of the chain.
    _, _, dist = c.closest_point(pts)
    assert dist.max() <= 1e-4 + 1e-12 and err <= 1e-4
    # The file `camber fit --split` writes holds more keys beside the pieces; they are ignored.
    form = json.loads(c.to_json())
    form.update({"joints": [1], "continuity": "G1", "max_error": err})
    same = camber.CompositeCurve.from_json(json.dumps(form))
    assert np.array_equal(same.evaluate([0.0, 1.0, 2.0]), c.evaluate([0.0, 1.0, 2.0]))


def test_a_composite_among_the_pieces_contributes_its_pieces():
    inner = camber.CompositeCurve([line([0, 0], [1, 0]), line([1, 0], [1, 1])])
    outer = camber.CompositeCurve([inner, line([1, 1], [0, 1])])
    assert len(outer) == 3 and outer.domain == (0.0, 3.0)
    np.testing.assert_allclose(outer.evaluate(2.5), [0.5, 1.0], atol=1e-15)


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: camber.CompositeCurve([]), "at least one piece"),
        (
            lambda: camber.CompositeCurve([line([0, 0], [1, 0]), camber.BezierCurve([[1, 0, 0], [2, 0, 0]])]),
            "pieces[1]",
        ),
        (lambda: chain().evaluate(3.5), "outside the domain"),
        (lambda: chain().evaluate(float("nan")), "not finite"),
        (lambda: chain().locate(-0.1), "outside the domain"),
        (lambda: chain().joints(angle=-1.0), "angle"),
        (lambda: chain().joints(position=float("nan")), "position"),
        (lambda: camber.CompositeCurve.from_json('{"pieces": []}'), "composite"),
        (lambda: camber.CompositeCurve.from_json('{"pieces": [{"type": "spiral"}]}'), "composite"),
        (lambda: camber.CompositeCurve.from_json("[1, 2"), "composite"),
    ],
)
def test_bad_input_is_refused_with_a_geometry_error(make, message):
    with pytest.raises(camber.GeometryError, match=message.replace("[", r"\[").replace("]", r"\]")):
        make()


def test_a_non_curve_piece_is_a_type_error():
    with pytest.raises(TypeError):
        camber.CompositeCurve([line([0, 0], [1, 0]), "not a curve"])
