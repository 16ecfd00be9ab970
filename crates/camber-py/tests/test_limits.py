"""The package holds to the library's limits: Ctrl-C stops long calls with KeyboardInterrupt
and leaves the sketch as it was, batches cap their threads and keep each item's failure (a
Python exception included) on that item, sizes are checked before anything is sized by them,
absurd drag targets are refused, and solve errors name constraints by kind."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import camber


def slow_unsolvable(x):
    # x² + 1 = 0 has no real root: the solve searches until its budget is spent, ~10 ms a
    # call (time.sleep releases the GIL, as a long numpy call would).
    time.sleep(0.01)
    return [x[0] * x[0] + 1.0]


def state(s):
    """Every entity's file form (custom constraints written in Python have no file form)."""
    return [s.entity(i) for i in s.entity_ids()]


def interrupt_after(seconds):
    """Sends SIGINT to this process after `seconds`, as Ctrl-C in a terminal does."""
    timer = threading.Timer(seconds, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    return timer


def test_ctrl_c_stops_a_long_solve_within_a_second_and_leaves_the_sketch_unchanged():
    s = camber.Sketch()
    p = s.add_point([0.5, 0.0])
    cid = s.add_custom(slow_unsolvable, [p], dim=1, name="no real root")
    before = state(s)
    timer = interrupt_after(0.3)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        s.solve()
    elapsed = time.monotonic() - start
    timer.join()
    assert elapsed < 1.3, f"the interrupt took {elapsed - 0.3:.2f} s to stop the solve"
    assert state(s) == before
    # The sketch still works afterwards: the flag belonged to the interrupted call only.
    s.remove_constraint(cid)
    q = s.add_point([1.0, 1.0])
    s.add_constraint("fixed", target={"point": {"point": q}})
    s.solve()


def test_ctrl_c_stops_a_batch_and_leaves_every_item_unchanged():
    items = []
    for k in range(4):
        s = camber.Sketch()
        p = s.add_point([0.5 + k, 0.0])
        s.add_custom(slow_unsolvable, [p], dim=1)
        items.append(s)
    before = [state(s) for s in items]
    timer = interrupt_after(0.3)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        camber.solve_many(items, threads=2)
    elapsed = time.monotonic() - start
    timer.join()
    assert elapsed < 1.3, f"the interrupt took {elapsed - 0.3:.2f} s to stop the batch"
    assert [state(s) for s in items] == before


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
