"""Shared fixtures: the bundled sketches of examples/sketches."""

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]


@pytest.fixture
def sketches():
    """The directory of bundled sketch files."""
    return ROOT / "examples" / "sketches"
