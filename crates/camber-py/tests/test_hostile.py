"""Hostile input over the package: NaN and infinities, huge and tiny magnitudes, wrong shapes
and dtypes, non-contiguous arrays, absurd counts, raising and misbehaving callbacks.

Every call must either answer with finite numbers or raise one of the documented exceptions
(`camber.CamberError` and its subclasses, or Python's `TypeError`, `ValueError`,
`OverflowError` for arguments of the wrong type or range) within a few seconds; an abort kills
the test process and a hang is stopped by an alarm (the package's long calls honour signals)
and fails the example. After a refused call the object is as it was.

CI runs a few dozen examples per test; `CAMBER_HOSTILE_EXAMPLES=N` runs N (the long runs
before closing an issue use thousands).
"""

import json
import math
import os
import signal
from contextlib import contextmanager

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import camber

EXAMPLES = int(os.environ.get("CAMBER_HOSTILE_EXAMPLES", "30"))
# The most one call may take: far above any answer (milliseconds), far below a hang.
SECONDS = 20.0

hostile = settings(
    max_examples=EXAMPLES,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)

ALLOWED = (camber.CamberError, TypeError, ValueError, OverflowError)


class Hang(Exception):
    """A call gave no answer in SECONDS."""


@contextmanager
def bounded(seconds=SECONDS):
    """Raises Hang in the main thread after `seconds` (a SIGALRM handler: the package's long
    calls look at signals every 50 ms and stop)."""

    def on_alarm(signum, frame):
        raise Hang(f"no answer in {seconds} s")

    previous = signal.signal(signal.SIGALRM, on_alarm)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def finite(value, where="answer"):
    """Asserts that every number inside `value` is finite."""
    if isinstance(value, np.ndarray):
        if value.dtype.kind in "fc":
            assert np.all(np.isfinite(value)), f"{where}: non-finite {value}"
    elif isinstance(value, (float, np.floating)):
        assert math.isfinite(value), f"{where}: {value}"
    elif isinstance(value, dict):
        for k, v in value.items():
            finite(v, f"{where}[{k!r}]")
    elif isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            finite(v, f"{where}[{i}]")
    elif isinstance(value, camber.SolveReport):
        finite(value.residuals, f"{where}.residuals")


def call(f, *args, **kwargs):
    """f(*args, **kwargs) bounded in time: its finite answer, or the allowed exception."""
    with bounded():
        try:
            out = f(*args, **kwargs)
        except ALLOWED as e:
            return e
    finite(out)
    return out


def state(s):
    """A sketch's entities (their file forms), which must stay finite."""
    return [s.entity(i) for i in s.entity_ids()]


# --- strategies ---------------------------------------------------------------------------

EDGES = [0.0, -0.0, 5e-324, -5e-324, 1e-300, 1e-17, 1e7, 1e15, 1e154, 1e308, -1e308]
numbers = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from(EDGES + [math.nan, math.inf, -math.inf]),
    st.integers(-(2**70), 2**70),
)
counts = st.one_of(
    st.integers(-5, 5), st.sampled_from([2**31, 2**40, 2**63 - 1, 2**64, 10**30])
)
pairs = st.lists(numbers, min_size=0, max_size=3)
dtypes = st.sampled_from([np.float64, np.float32, np.int64, np.bool_, np.complex128, object])


@st.composite
def arrays(draw, max_dims=2):
    """Arrays of hostile dtypes, shapes and values, sometimes a strided or reversed view."""
    dtype = draw(dtypes)
    shape = draw(hnp.array_shapes(min_dims=0, max_dims=max_dims, min_side=0, max_side=6))
    if dtype is object:
        a = np.array(draw(st.lists(numbers, min_size=1, max_size=4)), dtype=object)
    else:
        elements = (
            st.floats(allow_nan=True, allow_infinity=True, width=32 if dtype is np.float32 else 64)
            if dtype in (np.float64, np.float32)
            else None
        )
        a = draw(hnp.arrays(dtype, shape, elements=elements))
    view = draw(st.sampled_from(["plain", "strided", "reversed"]))
    if a.ndim >= 1 and view == "strided":
        a = a[::2]
    elif a.ndim >= 1 and view == "reversed":
        a = a[::-1]
    return a


def base_sketch():
    """Points, a line, a circle and a cubic, held by a few constraints."""
    s = camber.Sketch()
    p, q = s.add_point([0.0, 0.0]), s.add_point([2.0, 0.0])
    line = s.add_line([0.0, 1.0], [2.0, 1.5])
    circle = s.add_circle([5.0, 0.0], 1.0)
    curve = s.add_bezier([[0, 3], [1, 4], [2, 4], [3, 3]])
    s.add_constraint("fixed", target={"point": {"point": p}})
    s.add_constraint("distance", a={"point": p}, b={"point": q}, distance=2.0)
    return s, {"p": p, "q": q, "line": line, "circle": circle, "curve": curve}


# --- sketches -----------------------------------------------------------------------------


@hostile
@given(xy=pairs, c=pairs, r=numbers, a=pairs, b=pairs)
def test_entities_from_hostile_numbers_are_refused_or_finite(xy, c, r, a, b):
    s = camber.Sketch()
    for f, args in [
        (s.add_point, (xy,)),
        (s.add_circle, (c, r)),
        (s.add_line, (a, b)),
        (s.add_bezier, ([a, b, xy],)),
    ]:
        call(f, *args)
        finite(state(s), "sketch")
    call(s.solve)
    finite(state(s), "sketch after solve")


KINDS = {
    "distance": lambda ids, v: {"a": {"point": ids["p"]}, "b": {"point": ids["q"]}, "distance": v},
    "radius": lambda ids, v: {"circle": ids["circle"], "radius": v},
    "horizontal": lambda ids, v: {"line": ids["line"]},
    "point_at_parameter": lambda ids, v: {
        "curve": ids["curve"],
        "u": v,
        "target": {"point": {"point": ids["q"]}},
    },
    "tangent_to_circle": lambda ids, v: {
        "curve": ids["curve"],
        "circle": ids["circle"],
        "u": {"free": v},
        "side": "outside",
        "rotation": "clockwise",
    },
}


@hostile
@given(kind=st.sampled_from(sorted(KINDS)), value=numbers, priority=counts)
def test_constraints_with_hostile_values_are_refused_or_solved_to_finite_geometry(
    kind, value, priority
):
    s, ids = base_sketch()
    fields = KINDS[kind](ids, value)
    before = state(s)
    added = call(s.add_constraint, kind, priority=priority, **fields)
    if isinstance(added, Exception):
        assert state(s) == before
        assert len(s.constraint_ids()) == 2
        return
    snapshot = state(s)
    solved = call(s.solve)
    if isinstance(solved, Exception):
        assert state(s) == snapshot, "a failed solve changed the sketch"
    finite(state(s), "sketch after solve")
    call(s.analyze)


@hostile
@given(targets=st.lists(pairs, min_size=1, max_size=4), which=st.sampled_from(["q", "circle", "curve"]))
def test_drags_to_hostile_targets_are_refused_or_move_to_finite_places(targets, which):
    s, ids = base_sketch()
    ref = {
        "q": {"point": ids["q"]},
        "circle": {"control": [ids["circle"], 0]},
        "curve": {"control": [ids["curve"], 1]},
    }[which]
    drag = call(s.drag, ref)
    if isinstance(drag, Exception):
        return
    for t in targets:
        at = drag.point(ref)
        moved = call(drag.update, t)
        if isinstance(moved, Exception):
            np.testing.assert_array_equal(drag.point(ref), at)
        finite(drag.point(ref), "dragged point")
    call(drag.finish)
    finite(state(s), "sketch after the drag")


def raising(x):
    raise ValueError("residual raised")


BEHAVIOURS = {
    "raises": raising,
    "wrong length": lambda x: [x[0], x[1], x[0]],
    "nan": lambda x: [x[0] * math.nan],
    "inf": lambda x: [x[0] * 0 + math.inf],
    "string": lambda x: "not numbers",
    "none": lambda x: None,
    "huge": lambda x: [x[0] * 1e300],
    "numpy array": lambda x: np.array([x[0] - 1.0], dtype=object),
    "scalar": lambda x: x[0] - 1.0,
    "nested": lambda x: [[x[0]]],
    "recursion": lambda x: BEHAVIOURS["recursion"](x),
}


@hostile
@given(behaviour=st.sampled_from(sorted(BEHAVIOURS)), dim=counts, start=numbers)
def test_misbehaving_residuals_fail_their_solve_cleanly(behaviour, dim, start):
    s = camber.Sketch()
    p = s.add_point([0.5, 0.5])
    before = state(s)
    added = call(
        s.add_custom, BEHAVIOURS[behaviour], [p, {"param": start}], dim=dim, name=behaviour
    )
    if isinstance(added, Exception):
        assert s.constraint_ids() == []
        return
    with ignoring_warnings():
        try:
            outcome = call(s.solve)
        except RecursionError as e:  # the residual's own exception, raised again as it was
            outcome = e
    if isinstance(outcome, Exception):
        assert state(s) == before
    finite(state(s))
    # The sketch stays usable: without the residual a later solve raises nothing old.
    s.remove_constraint(added)
    q = s.add_point([1.0, 1.0])
    s.add_constraint("fixed", target={"point": {"point": q}})
    assert not isinstance(call(s.solve), Exception)


@contextmanager
def ignoring_warnings():
    """Warnings are allowed (a residual that raised at a trial point of a solve that succeeded
    is reported by a RuntimeWarning)."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        yield


@hostile
@given(threads=st.one_of(st.none(), counts), junk=st.sampled_from([None, 3, "no/such/file.json", b"\0"]))
def test_batches_take_hostile_thread_counts_and_items(threads, junk):
    good, _ = base_sketch()
    results = call(camber.solve_many, [good, junk], threads=threads)
    if isinstance(results, Exception):
        return
    assert results[0]["ok"], results[0]["error"]
    assert not results[1]["ok"]


json_values = st.recursive(
    st.one_of(st.none(), st.booleans(), numbers.filter(lambda v: not isinstance(v, float) or math.isfinite(v)), st.text(max_size=5)),
    lambda inner: st.one_of(
        st.lists(inner, max_size=4), st.dictionaries(st.text(max_size=8), inner, max_size=4)
    ),
    max_leaves=20,
)


@hostile
@given(body=json_values, raw=st.sampled_from(["null", "[]", "{", "1e999", '{"version": 1e308}', "NaN"]))
def test_sketch_files_of_any_shape_are_refused_with_a_file_error_or_read(body, raw):
    for text in (json.dumps(body), raw):
        s = call(camber.Sketch.from_json, text)
        if isinstance(s, Exception):
            assert isinstance(s, camber.FileError), repr(s)
        else:
            finite(state(s))


# --- curves -------------------------------------------------------------------------------


@hostile
@given(points=arrays(), u=arrays(max_dims=1))
def test_curves_from_hostile_arrays_are_refused_or_evaluate_to_finite_points(points, u):
    c = call(camber.BezierCurve, points)
    if isinstance(c, Exception):
        return
    for f in (c.evaluate, c.derivative, c.curvature):
        call(f, u)
    call(c.evaluate, 0.5)


@hostile
@given(degree=counts, knots=st.lists(numbers, max_size=10), points=arrays())
def test_bsplines_from_hostile_knots_and_degrees_are_refused_or_finite(degree, knots, points):
    c = call(camber.BSplineCurve, degree, knots, points)
    if isinstance(c, Exception):
        return
    a, b = c.domain
    call(c.evaluate, np.linspace(a, b, 7))


@hostile
@given(points=arrays(), query=arrays())
def test_closest_points_of_hostile_point_arrays_are_refused_or_finite(points, query):
    c = camber.BSplineCurve(3, [0, 0, 0, 0, 0.5, 1, 1, 1, 1], [[0, 0], [1, 2], [2, -1], [3, 1], [4, 0]])
    call(c.closest_point, query)
    call(c.closest_point, points)


class _Spline:
    """A duck-typed scipy BSpline: anything with t, c and k."""

    def __init__(self, t, c, k):
        self.t, self.c, self.k = t, c, k


@hostile
@given(t=st.one_of(arrays(max_dims=1), st.lists(numbers, max_size=10)), c=arrays(), k=counts)
def test_hostile_scipy_like_splines_are_refused_or_come_in_finite(t, c, k):
    from camber.interop import from_scipy, to_geomdl, to_scipy

    curve = call(from_scipy, _Spline(t, c, k))
    if isinstance(curve, Exception):
        return
    a, b = curve.domain
    call(curve.evaluate, np.linspace(a, b, 5))
    call(to_scipy, curve)
    call(to_geomdl, curve)


@hostile
@given(degree=counts, knots=st.lists(numbers, max_size=10), points=arrays(), weights=arrays(max_dims=1))
def test_hostile_geomdl_like_curves_are_refused_or_come_in_finite(degree, knots, points, weights):
    from types import SimpleNamespace

    from camber.interop import from_geomdl

    ctrl = points.tolist() if isinstance(points, np.ndarray) else points
    duck = SimpleNamespace(degree=degree, knotvector=knots, ctrlpts=ctrl, weights=weights.tolist())
    curve = call(from_geomdl, duck)
    if isinstance(curve, Exception):
        return
    a, b = curve.domain
    call(curve.evaluate, np.linspace(a, b, 5))


@hostile
@given(
    op=st.sampled_from(["fillet", "split", "trim"]),
    a=st.sampled_from(["p", "line", "circle", "curve", "cross", "unknown"]),
    b=st.sampled_from(["p", "line", "circle", "curve", "cross", "unknown"]),
    radius=numbers,
    near=st.one_of(st.none(), pairs),
    keep=st.one_of(st.sampled_from(["start", "end"]), st.text(max_size=4)),
)
def test_fillets_splits_and_trims_of_hostile_inputs_are_refused_or_finite(
    op, a, b, radius, near, keep
):
    s, ids = base_sketch()
    # A line crossing the line and the cubic, and joined to the line's end for fillets.
    ids["cross"] = s.add_line([2.0, 1.5], [1.0, 5.0])
    s.add_constraint("coincident", a={"end": ids["line"]}, b={"start": ids["cross"]})
    ids["unknown"] = 2**40
    before = state(s)
    if op == "fillet":
        out = call(s.fillet, ids[a], ids[b], radius)
    elif op == "split":
        out = call(s.split_at_intersection, ids[a], ids[b], near)
    else:
        out = call(s.trim, ids[a], ids[b], keep, near)
    if isinstance(out, Exception):
        assert state(s) == before, f"a refused {op} changed the sketch"
        return
    finite(state(s), f"sketch after {op}")
    snapshot = state(s)
    solved = call(s.solve)
    if isinstance(solved, Exception):
        assert state(s) == snapshot, "a failed solve changed the sketch"
    finite(state(s), "sketch after solve")
