"""solve_many: sketches and paths solved in parallel give the same results as one-by-one
solves, failures stay on their own item, and sketches are solved in place."""

import shutil

import pytest

import camber


def test_paths_and_sketches_match_serial_solves(sketches, tmp_path):
    names = ["diffuser.json", "blade_section.json", "two_curves.json"]
    paths = [sketches / n for n in names]
    objects = [camber.Sketch.load(p) for p in paths]
    serial = []
    for p in paths:
        s = camber.Sketch.load(p)
        s.solve(all=True)
        serial.append(s.to_json())
    results = camber.solve_many(paths + objects, threads=2)
    assert len(results) == 6
    for i, r in enumerate(results):
        assert r["ok"], r["error"]
        assert isinstance(r["report"], camber.SolveReport)
        assert r["sketch"].to_json() == serial[i % 3]
    # Sketch objects were solved in place.
    for s, want in zip(objects, serial):
        assert s.to_json() == want


def test_a_failure_stays_on_its_item(sketches, tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text("{")
    good = tmp_path / "good.json"
    shutil.copy(sketches / "diffuser.json", good)
    r = camber.solve_many([bad, str(good)])
    assert not r[0]["ok"] and "invalid JSON" in r[0]["error"] and r[0]["sketch"] is None
    assert r[1]["ok"]
    with pytest.raises(camber.SketchError, match="Sketch objects and paths"):
        camber.solve_many([42])
