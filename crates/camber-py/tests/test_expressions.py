"""Expression constraints and named parameters from Python: add_expression, dimensions as
expressions, set_parameter, and sweeps with solve_many over a table of values."""

import math
import pathlib

import numpy as np
import pytest

import camber

ROOT = pathlib.Path(__file__).resolve().parents[3]
BLADE = ROOT / "examples" / "sketches" / "blade_parametric.json"


def test_an_expression_constraint_solves_and_saves():
    s = camber.Sketch()
    p = s.add_point([0.0, 0.0])
    q = s.add_point([3.0, 1.0])
    cid = s.add_expression("norm(Q - P) = 2", name="gap", P=p, Q=q)
    s.solve()
    d = np.array(s.point(q)) - np.array(s.point(p))
    assert abs(np.hypot(*d) - 2.0) < 1e-10
    assert s.constraint(cid)["rows"] == ["norm(Q - P) = 2"]
    again = camber.Sketch.from_json(s.to_json())
    assert again.to_json() == s.to_json()


def test_curves_and_free_parameters_are_read_by_name():
    s = camber.Sketch()
    c = s.add_bezier(np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 2.0], [3.0, 0.0]]))
    p = s.add_point([1.5, 2.0])
    s.add_constraint("fixed", target={"point": {"point": p}})
    cid = s.add_expression(["C(t) = P"], C=c, P=p, t={"free": 0.4})
    s.solve()
    t = s.constraint(cid)["args"]["t"]["free"]
    assert 0.0 <= t <= 1.0
    assert np.allclose(s.curve(c).evaluate(t), [1.5, 2.0], atol=1e-10)


def test_bad_expressions_raise_with_the_column():
    s = camber.Sketch()
    p = s.add_point([0.0, 0.0])
    with pytest.raises(camber.SketchError, match="column 5: `\\+` needs a vector, found a scalar"):
        s.add_expression("P + 1", P=p)
    with pytest.raises(camber.SketchError, match="unknown name `R`"):
        s.add_expression("norm(P - R)", P=p)
    with pytest.raises(camber.SketchError, match="more than 64 deep"):
        s.add_expression("(" * 100 + "P.x" + ")" * 100, P=p)
    with pytest.raises(camber.SketchError, match="bytes long"):
        s.add_expression("P.x+" * 300_000 + "1", P=p)


def test_parameters_drive_dimensions_and_set_parameter_re_solves():
    s = camber.Sketch.load(str(BLADE))
    s.solve()
    assert s.parameters["chord"] == 1.0
    s.set_parameter("chord", 1.5)
    te = s.curve(0).evaluate(1.0)
    assert abs(te[0] - 1.5) < 1e-9 and abs(te[1]) < 1e-9
    a = s.add_point([0.0, 3.0])
    b = s.add_point([1.0, 3.0])
    s.add_constraint("distance", a={"point": a}, b={"point": b}, distance="chord / 3")
    s.solve()
    assert abs(np.hypot(*(np.array(s.point(b)) - np.array(s.point(a)))) - 0.5) < 1e-9
    with pytest.raises(camber.CamberError):
        s.set_parameter("chord", float("nan"))


def test_a_dimension_value_binds_to_parameters_and_unbinds():
    s = camber.Sketch()
    a = s.add_point([0.0, 0.0])
    b = s.add_point([1.0, 0.0])
    s.add_constraint("fixed", target={"point": {"point": a}})
    d = s.add_constraint("distance", a={"point": a}, b={"point": b}, distance=1.0)
    s.set_parameter("w", 3.0)
    s.bind_value(d, "w / 2")
    s.solve()
    assert abs(np.hypot(*(np.array(s.point(b)) - np.array(s.point(a)))) - 1.5) < 1e-9
    with pytest.raises(camber.CamberError):
        s.set_value(d, 2.0)  # it follows w
    s.unbind_value(d)
    s.set_value(d, 2.0)
    s.solve()
    assert abs(np.hypot(*(np.array(s.point(b)) - np.array(s.point(a)))) - 2.0) < 1e-9
    with pytest.raises(camber.CamberError):
        s.bind_value(a + 100, "w")


def test_solve_many_sweeps_a_table_on_every_thread():
    s = camber.Sketch.load(str(BLADE))
    chords = np.linspace(0.8, 1.6, 16)
    table = {"chord": chords, "t_max": np.full(16, 0.1)}
    rows = camber.solve_many(s, parameters=table, threads=2)
    assert len(rows) == 16
    assert all(r["ok"] for r in rows)
    assert [r["chord"] for r in rows] == list(chords)
    assert max(r["max_residual"] for r in rows) < 1e-9
    # The sketch itself is unchanged, and one row equals a solve by hand.
    assert s.parameters["chord"] == 1.0
    pandas = pytest.importorskip("pandas")
    frame = pandas.DataFrame(table)
    assert [r["ok"] for r in camber.solve_many(str(BLADE), parameters=frame)] == [True] * 16
    with pytest.raises(camber.SketchError):
        camber.solve_many(s, parameters={"span": [1.0]})
    assert math.isfinite(rows[3]["max_residual"])
