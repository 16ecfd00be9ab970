"""DXF in and out, cross-checked with ezdxf, an independent reader and writer: what camber
writes ezdxf reads as the same geometry (text and binary), and what ezdxf writes camber
imports as the same geometry, with the layers as tags and what it cannot take listed."""

import math

import numpy as np
import pytest

import camber

ezdxf = pytest.importorskip("ezdxf")


def xy(v):
    """The x and y of an ezdxf vector."""
    return [v.x, v.y]


def every_kind():
    """A sketch with one entity of every kind DXF holds, each tagged but the point."""
    entities = {
        "point": {"kind": "point", "at": [0.125, -3.5]},
        "line": {"kind": "line", "from": [0, 0], "to": [1 / 3, 2]},
        "circle": {"kind": "circle", "center": [5, 5], "radius": 0.7},
        "arc": {"kind": "arc", "center": [1, 1], "radius": 2, "start_angle": 0.3, "end_angle": 2.2},
        "ellipse": {
            "kind": "ellipse", "center": [-1, 2], "semi_axis_a": 3, "semi_axis_b": 1.25, "rotation": 0.4,
        },
        "bspline": {
            "kind": "bspline",
            "degree": 2,
            "knots": [0, 0, 0, 0.25, 0.7, 1, 1, 1],
            "control_points": [[0, 0], [1, 1], [2, 0.5], [3, 1.5], [4, 0]],
        },
        "nurbs": {
            "kind": "nurbs",
            "degree": 2,
            "knots": [0, 0, 0, 1, 1, 1],
            "control_points": [[1, 0], [1, 1], [0, 1]],
            "weights": [1, math.sqrt(0.5), 1],
        },
    }
    ids = {}
    items = []
    for i, (name, e) in enumerate(entities.items()):
        ids[name] = i
        item = {"id": i, **e}
        if name != "point":
            item["tag"] = name.upper()
        items.append(item)
    return camber.Sketch.from_dict({"version": 1, "entities": items, "constraints": []}), ids


@pytest.mark.parametrize("binary", [False, True])
def test_ezdxf_reads_what_camber_writes_as_the_same_geometry(tmp_path, binary):
    s, ids = every_kind()
    path = tmp_path / "every.dxf"
    camber.write_dxf(s, str(path), binary=binary)
    doc = ezdxf.readfile(str(path))
    by_type = {}
    for e in doc.modelspace():
        by_type.setdefault(e.dxftype(), []).append(e)
    assert sorted(by_type) == ["ARC", "CIRCLE", "ELLIPSE", "LINE", "POINT", "SPLINE"]
    tol = 1e-12

    (p,) = by_type["POINT"]
    assert p.dxf.layer == "0"
    assert np.allclose(xy(p.dxf.location), [0.125, -3.5], atol=tol, rtol=0)
    (line,) = by_type["LINE"]
    assert line.dxf.layer == "LINE"
    assert np.allclose([*xy(line.dxf.start), *xy(line.dxf.end)], [0, 0, 1 / 3, 2], atol=tol, rtol=0)
    (circle,) = by_type["CIRCLE"]
    assert np.allclose([*xy(circle.dxf.center), circle.dxf.radius], [5, 5, 0.7], atol=tol, rtol=0)
    (arc,) = by_type["ARC"]
    assert arc.dxf.layer == "ARC"
    assert np.allclose(
        [*xy(arc.dxf.center), arc.dxf.radius, arc.dxf.start_angle, arc.dxf.end_angle],
        [1, 1, 2, math.degrees(0.3), math.degrees(2.2)],
        atol=1e-9,
        rtol=0,
    )
    (ellipse,) = by_type["ELLIPSE"]
    assert np.allclose(xy(ellipse.dxf.center), [-1, 2], atol=tol, rtol=0)
    assert np.allclose(xy(ellipse.dxf.major_axis), [3 * math.cos(0.4), 3 * math.sin(0.4)], atol=tol, rtol=0)
    assert ellipse.dxf.ratio == pytest.approx(1.25 / 3, abs=tol)
    splines = {e.dxf.layer: e for e in by_type["SPLINE"]}
    b = splines["BSPLINE"]
    assert b.dxf.degree == 2
    assert np.allclose(list(b.knots), [0, 0, 0, 0.25, 0.7, 1, 1, 1], atol=tol, rtol=0)
    assert np.allclose(np.asarray(b.control_points)[:, :2], [[0, 0], [1, 1], [2, 0.5], [3, 1.5], [4, 0]], atol=tol, rtol=0)
    n = splines["NURBS"]
    assert np.allclose(list(n.weights), [1, math.sqrt(0.5), 1], atol=tol, rtol=0)
    # ezdxf's own evaluation of the rational quarter circle: every point on the unit circle.
    for point in n.construction_tool().approximate(10):
        assert math.hypot(point.x, point.y) == pytest.approx(1.0, abs=1e-12)


def test_camber_imports_what_ezdxf_writes(tmp_path):
    doc = ezdxf.new("R2010")
    msp = doc.modelspace()
    msp.add_line((0, 0), (2, 0), dxfattribs={"layer": "PROFILE"})
    msp.add_arc((2, 1), 1, -90, 90, dxfattribs={"layer": "PROFILE"})
    msp.add_line((2, 2), (0, 2), dxfattribs={"layer": "PROFILE"})
    msp.add_circle((5, 5), 0.5)
    msp.add_ellipse((1, 1), major_axis=(2, 0), ratio=0.5, start_param=0, end_param=math.pi / 2)
    # A closed polyline with a bulged segment: a half circle about (11, 1) through (12, 1).
    msp.add_lwpolyline([(10, 0, 0), (11, 0, 1), (11, 2, 0), (10, 2, 0)], format="xyb", close=True)
    msp.add_open_spline([(0, 5), (1, 7), (3, 7), (4, 5), (5, 6)], degree=3)
    msp.add_rational_spline([(1, 0), (1, 1), (0, 1)], [1, math.sqrt(0.5), 1], degree=2)
    msp.add_text("not geometry")
    path = tmp_path / "ezdxf.dxf"
    doc.saveas(str(path))

    s, skipped = camber.read_dxf(str(path))
    assert [loc.split()[0] for loc, _ in skipped] == ["TEXT"], skipped
    kinds = [s.entity(i)["kind"] for i in s.entity_ids()]
    assert kinds == [
        "line", "arc", "line", "circle", "elliptic_arc",
        "line", "arc", "line", "line",
        "bspline", "nurbs",
    ], kinds
    ids = s.entity_ids()
    assert s.tag(ids[0]) == "PROFILE" and s.tag(ids[3]) is None
    arc = s.entity(ids[1])
    assert np.allclose(arc["center"], [2, 1], atol=1e-12)
    assert np.allclose(arc["start"], [2, 0], atol=1e-12)
    assert np.allclose(arc["end"], [2, 2], atol=1e-12)
    bulge = s.entity(ids[6])
    assert np.allclose(bulge["center"], [11, 1], atol=1e-12)
    ell = s.entity(ids[4])
    assert np.allclose(ell["start"], [3, 1], atol=1e-12)
    assert np.allclose(ell["end"], [1, 2], atol=1e-12)
    # The profile's three pieces and the polyline's four are joined end to end.
    joins = [s.constraint(c) for c in s.constraint_ids()]
    assert all(j["kind"] == "coincident" for j in joins)
    assert len(joins) == 2 + 4
    # ezdxf's spline evaluation against camber's at the same parameters.
    spline = next(e for e in msp if e.dxftype() == "SPLINE" and not e.weights)
    t = np.linspace(0, 1, 7)
    ours = s.curve(ids[9]).evaluate(t * s.curve(ids[9]).domain[1])
    knots = list(spline.knots)
    theirs = [spline.construction_tool().point(x * knots[-1]) for x in t]
    assert np.allclose(ours, [[p.x, p.y] for p in theirs], atol=1e-12)


def test_a_round_trip_through_both_forms_keeps_geometry_and_tags(tmp_path):
    s, ids = every_kind()
    for binary in (False, True):
        path = tmp_path / f"rt{int(binary)}.dxf"
        camber.write_dxf(s, str(path), binary=binary)
        back, skipped = camber.read_dxf(str(path), join_tolerance=-1)
        assert skipped == []
        assert [back.entity(i)["kind"] for i in back.entity_ids()] == [
            s.entity(i)["kind"] for i in s.entity_ids()
        ]
        assert [back.tag(i) for i in back.entity_ids()] == [s.tag(i) for i in s.entity_ids()]
        b, o = back.entity(back.entity_ids()[5]), s.entity(ids["bspline"])
        assert np.allclose(b["control_points"], o["control_points"], atol=1e-12, rtol=0)
        assert np.allclose(b["knots"], o["knots"], atol=1e-12, rtol=0)


def test_bad_files_raise_file_errors(tmp_path):
    with pytest.raises(camber.FileError):
        camber.read_dxf(str(tmp_path / "missing.dxf"))
    bad = tmp_path / "bad.dxf"
    bad.write_text("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\nnot a number\n")
    with pytest.raises(camber.FileError):
        camber.read_dxf(str(bad))
    s = camber.Sketch()
    i = s.add_point([0.0, 0.0])
    s.set_tag(i, "a/b")
    with pytest.raises(camber.FileError, match="layer"):
        camber.write_dxf(s, str(tmp_path / "out.dxf"))
    with pytest.raises(camber.SketchError):
        s.set_tag(i, "two\nlines")
