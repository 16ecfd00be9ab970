"""Vectorised evaluation against the Rust loop: 10^6 parameters of a cubic B-spline in one
``Curve.evaluate`` call (numpy in, numpy out) against the same loop timed inside Rust
(``camber._native._eval_loop_seconds``), best of several runs each.

    python crates/camber-py/bench/evaluate.py [N]
"""

import sys
import time

import numpy as np

import camber
from camber._native import _eval_loop_seconds


def best(f, runs=7):
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return min(times)


def main(n):
    cp = np.array([[0, 0], [1, 2], [2, -1], [3, 2], [4, 0], [5, 1], [6, -1], [7, 0.0]])
    curve = camber.BSplineCurve.clamped_uniform(3, cp)
    u = np.linspace(0.0, 1.0, n)
    out = curve.evaluate(u)
    assert out.shape == (n, 2)
    py = best(lambda: curve.evaluate(u))
    rust = min(_eval_loop_seconds(curve, n) for _ in range(7))
    # Context: a Python loop of single evaluations, per point.
    m = 20_000
    loop = best(lambda: [curve.evaluate(float(x)) for x in u[:m]], runs=3) / m
    print(f"parameters: {n}")
    print(f"Curve.evaluate(array): {py * 1e3:.1f} ms ({py / n * 1e9:.1f} ns/point)")
    print(f"Rust loop:             {rust * 1e3:.1f} ms ({rust / n * 1e9:.1f} ns/point)")
    print(f"ratio:                 {py / rust:.2f}x")
    print(f"Python loop of single evaluations: {loop * 1e9:.0f} ns/point")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 10**6)
