"""The package holds to the library's limits: Ctrl-C stops long calls with KeyboardInterrupt
and leaves the sketch as it was, batches cap their threads and keep each item's failure (a
Python exception included) on that item, sizes are checked before anything is sized by them,
absurd drag targets are refused, and solve errors name constraints by kind."""

import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import camber


def state(s):
    """Every entity's file form (custom constraints written in Python have no file form)."""
    return [s.entity(i) for i in s.entity_ids()]


# A script run in a fresh interpreter (so no other test's signal handling is in the way): it
# starts a long call and prints how long after its start the KeyboardInterrupt came and whether
# the sketches kept their state. The residual x² + 1 = 0 has no real root, so the solve
# searches until its budget is spent, 20 ms a call (time.sleep releases the GIL, as a long
# numpy call would): far longer than the test waits.
CTRL_C_SCRIPT = """
import signal, sys, time
import camber

# Ctrl-C as in a terminal, even when this runs under a CI job that started us with SIGINT
# ignored (a background job of a non-interactive shell), which Python then keeps.
signal.signal(signal.SIGINT, signal.default_int_handler)

def slow_unsolvable(x):
    time.sleep(0.02)
    return [x[0] * x[0] + 1.0]

def sketch(k):
    s = camber.Sketch()
    p = s.add_point([0.5 + k, 0.0])
    cid = s.add_custom(slow_unsolvable, [p], dim=1, name="no real root")
    return s, cid

def state(s):
    return [s.entity(i) for i in s.entity_ids()]

batch = sys.argv[1] == "batch"
items = [sketch(k) for k in range(4 if batch else 1)]
before = [state(s) for s, _ in items]
print("ready", flush=True)
start = time.monotonic()
try:
    if batch:
        camber.solve_many([s for s, _ in items], threads=2)
    else:
        items[0][0].solve()
    print("finished without an interrupt", flush=True)
except KeyboardInterrupt:
    elapsed = time.monotonic() - start
    print("interrupted", elapsed, [state(s) for s, _ in items] == before, flush=True)
# The sketch still works afterwards: the flag belonged to the interrupted call only.
s, cid = items[0]
s.remove_constraint(cid)
q = s.add_point([1.0, 1.0])
s.add_constraint("fixed", target={"point": {"point": q}})
s.solve()
print("usable", flush=True)
"""


def interrupted_run(script, *args):
    """Runs `script` with `args`, sends SIGINT 0.5 s after it prints "ready", as Ctrl-C in a
    terminal does; returns the words after "interrupted" on its first line (the seconds from
    the call's start to the KeyboardInterrupt first), once it has printed "usable"."""
    child = subprocess.Popen(
        [sys.executable, "-c", script, *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    assert child.stdout.readline().strip() == "ready"
    time.sleep(0.5)
    child.send_signal(signal.SIGINT)
    out, err = child.communicate(timeout=120)
    lines = out.split("\n")
    assert lines[0].startswith("interrupted"), (out, err)
    assert "usable" in lines, (out, err)
    return lines[0].split()[1:]


def interrupted_sketch_run(kind):
    """CTRL_C_SCRIPT interrupted: the seconds to the KeyboardInterrupt and whether the
    sketches were unchanged."""
    elapsed, unchanged = interrupted_run(CTRL_C_SCRIPT, kind)
    return float(elapsed), unchanged == "True"


def test_ctrl_c_stops_a_long_solve_within_a_second_and_leaves_the_sketch_unchanged():
    elapsed, unchanged = interrupted_sketch_run("solve")
    assert elapsed < 1.5, f"the interrupt took {elapsed - 0.5:.2f} s to stop the solve"
    assert unchanged


def test_ctrl_c_stops_a_batch_and_leaves_every_item_unchanged():
    elapsed, unchanged = interrupted_sketch_run("batch")
    assert elapsed < 1.5, f"the interrupt took {elapsed - 0.5:.2f} s to stop the batch"
    assert unchanged


# The curve toolkit's long calls hand the same flag to their work budget. Fitting 200,000
# noisy points to 1e-9 (far below the noise) runs for minutes: the adaptive search keeps
# adding knots.
TOOLKIT_CTRL_C_SCRIPT = """
import signal, time
import numpy as np
import camber

signal.signal(signal.SIGINT, signal.default_int_handler)  # as in CTRL_C_SCRIPT

t = np.linspace(0.0, 1.0, 200_000)
noise = 1e-3 * np.random.default_rng(1).standard_normal(t.size)
points = np.c_[t, np.sin(40.0 * t) + noise]
print("ready", flush=True)
start = time.monotonic()
try:
    camber.fit_to_tolerance(points, 3, 1e-9, "centripetal")
    print("finished without an interrupt", flush=True)
except KeyboardInterrupt:
    print("interrupted", time.monotonic() - start, flush=True)
# The toolkit still works afterwards.
camber.fit_to_tolerance(points[::1000], 3, 1e-2, "centripetal")
print("usable", flush=True)
"""


def test_ctrl_c_stops_a_long_curve_fit_within_a_second():
    elapsed = float(interrupted_run(TOOLKIT_CTRL_C_SCRIPT)[0])
    assert elapsed < 1.5, f"the interrupt took {elapsed - 0.5:.2f} s to stop the fit"


def chain(n=3):
    s = camber.Sketch()
    pts = [s.add_point([float(i), 0.3 * i]) for i in range(n)]
    s.add_constraint("fixed", target={"point": {"point": pts[0]}})
    for a, b in zip(pts, pts[1:]):
        s.add_constraint("distance", a={"point": a}, b={"point": b}, distance=1.5)
    return s


def test_absurd_thread_counts_are_capped_by_the_machine():
    items = [chain() for _ in range(6)]
    start = time.monotonic()
    results = camber.solve_many(items, threads=10**6)
    assert time.monotonic() - start < 30
    assert all(r["ok"] for r in results), [r["error"] for r in results]
    results = camber.solve_many([chain()], threads=0)
    assert results[0]["ok"]


def test_a_raising_residual_fails_its_own_item_and_the_others_are_written_back():
    def broken(x):
        raise ValueError("boom in item 1")

    good_a, bad, good_b = chain(), chain(), chain()
    p = bad.add_point([5.0, 5.0])
    bad.add_custom(broken, [p], dim=1, name="broken")
    bad_before = state(bad)
    results = camber.solve_many([good_a, bad, good_b], threads=2)
    assert results[0]["ok"] and results[2]["ok"]
    assert not results[1]["ok"]
    assert isinstance(results[1]["exception"], ValueError)
    assert "boom in item 1" in results[1]["error"] and "broken" in results[1]["error"]
    assert state(results[1]["sketch"]) == bad_before
    for s in (good_a, good_b):
        for a, b in [(0, 1), (1, 2)]:
            d = np.linalg.norm(s.point(a) - s.point(b))
            assert d == pytest.approx(1.5, abs=1e-9)
    # The exception is not raised again by a later call.
    good_a.solve(all=True)


def test_a_custom_dimension_nobody_can_hold_is_refused_before_any_allocation():
    s = camber.Sketch()
    p = s.add_point([0, 0])
    for dim in [10**9, 2**40, 0]:
        with pytest.raises(camber.SketchError, match=f"dim is {dim}"):
            s.add_custom(lambda x: [x[0]], [p], dim=dim)
    with pytest.raises(OverflowError):
        s.add_custom(lambda x: [x[0]], [p], dim=-1)
    assert s.constraint_ids() == []


def test_a_one_row_residual_may_return_its_number_alone():
    s = camber.Sketch()
    p = s.add_point([0.3, 0.4])
    s.add_constraint("fixed", target={"point": {"point": p}})
    q = s.add_point([2.0, 0.0])
    # |q - p|² - 1, returned as a plain number (a dual number inside the derivatives).
    s.add_custom(lambda x: (x[2] - x[0]) ** 2 + (x[3] - x[1]) ** 2 - 1.0, [p, q], dim=1)
    s.solve()
    assert np.linalg.norm(s.point(q) - s.point(p)) == pytest.approx(1.0, abs=1e-9)


def test_drag_targets_a_thousand_sketches_away_are_refused():
    s = chain()
    drag = s.drag({"point": 2})
    at = drag.point({"point": 2})
    for far in ([1e15, 0.0], [0.0, -1e10], [1e308, 1e308]):
        with pytest.raises(camber.SolveError, match="too far from the sketch"):
            drag.update(far)
        np.testing.assert_array_equal(drag.point({"point": 2}), at)
    with pytest.raises(camber.SketchError):
        drag.update([float("nan"), 0.0])
    drag.update(list(at + [0.05, 0.02]))
    drag.finish()


def test_solve_errors_name_the_constraints_by_kind():
    s = camber.Sketch()
    p, q = s.add_point([0, 0]), s.add_point([1, 0])
    s.add_constraint("fixed", target={"point": {"point": p}})
    s.add_constraint("fixed", target={"point": {"point": q}})
    s.add_constraint("distance", a={"point": p}, b={"point": q}, distance=3.0)
    with pytest.raises(camber.SolveError, match=r"\(distance\)"):
        s.solve()
