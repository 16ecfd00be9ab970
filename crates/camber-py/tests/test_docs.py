"""docs/python.md's Python blocks, run in order in one namespace as a reader would paste them
(from a scratch directory that sees the repository's examples/): every block runs, and the
Dask sweep runs with 12 variants instead of its 10,000."""

import os
import re

import pytest

from conftest import ROOT

GUIDE = ROOT / "docs" / "python.md"


def blocks():
    return re.findall(r"^```python\n(.*?)^```", GUIDE.read_text(), flags=re.S | re.M)


def test_the_guide_has_its_blocks():
    assert len(blocks()) >= 6


def test_the_guide_blocks_run_in_order(tmp_path, monkeypatch, capsys):
    pytest.importorskip("dask.distributed")
    (tmp_path / "examples").symlink_to(ROOT / "examples")
    monkeypatch.chdir(tmp_path)
    namespace = {"__name__": "__main__"}
    for i, block in enumerate(blocks(), start=1):
        if "sweep(10_000)" in block:
            block = block.replace("sweep(10_000)", "sweep(12)")
        try:
            exec(compile(block, f"docs/python.md block {i}", "exec"), namespace)
        except Exception as e:  # the block's number in the failure
            raise AssertionError(f"docs/python.md block {i} failed: {e!r}\n{block}") from e
    assert (tmp_path / "solved.json").exists()
    assert all(r["ok"] for r in namespace["results"]), [r["error"] for r in namespace["results"]]
    assert "12 of 12 solved" in capsys.readouterr().out
    assert os.getcwd() == str(tmp_path)
