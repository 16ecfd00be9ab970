"""Control points of camber's fit_to_tolerance against scipy's splprep (FITPACK) on generated
NACA four- and five-digit sections (15 codes, 35 to 400 points, cosine and uniform spacing) at
1e-3, 1e-4 and 1e-5 chord. Both curves are measured the same way, independently of either
library: the largest distance from a data point to the curve (dense samples, then Newton).
splprep is given every smoothing factor s of a log sweep (and s = 0) and credited with the
fewest coefficients of any s whose measured deviation is within the tolerance.

scipy is needed here only (not by camber or its tests):

    pip install scipy
    python crates/camber-py/bench/fit_airfoils.py [--quick]
"""

import os
import sys
import time
import warnings

# scipy's OpenBLAS threads spin while they wait for work: on a small machine they take the
# cores camber's timed calls run on (the same fit measured 2 ms without them, 7 ms with them).
# One BLAS thread is enough for the few small products here. Set before numpy loads.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np
from scipy.interpolate import BSpline, splprep
from scipy.spatial import cKDTree

import camber

FIVE = {1: (0.0580, 361.4), 2: (0.1260, 51.64), 3: (0.2025, 15.957), 4: (0.2900, 6.643), 5: (0.3910, 3.230)}
CODES = ["0006", "0012", "0018", "2412", "2415", "4412", "4424", "6409",
         "21012", "22012", "23012", "23015", "23018", "24012", "25012"]
COUNTS = [35, 71, 141, 201, 281, 400]
TOLERANCES = [1e-3, 1e-4, 1e-5]


def naca(code, points, spacing):
    """The section in the Selig order (as camber_workloads::airfoils::naca)."""
    n = points // 2 + 1
    s = np.linspace(0.0, 1.0, n)
    x = 0.5 * (1.0 - np.cos(np.pi * s)) if spacing == "cosine" else s
    t = int(code[-2:]) / 100
    yt = 5 * t * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1015 * x**4)
    if len(code) == 4:
        m, p = int(code[0]) / 100, int(code[1]) / 10
        if m == 0:
            yc, dy = np.zeros_like(x), np.zeros_like(x)
        else:
            yc = np.where(x < p, m / p**2 * (2 * p * x - x**2), m / (1 - p) ** 2 * ((1 - 2 * p) + 2 * p * x - x**2))
            dy = np.where(x < p, 2 * m / p**2 * (p - x), 2 * m / (1 - p) ** 2 * (p - x))
    else:
        r, k1 = FIVE[int(code[1])]
        cl = int(code[0]) * 0.15 / 0.3
        yc = cl * np.where(x < r, k1 / 6 * (x**3 - 3 * r * x**2 + r**2 * (3 - r) * x), k1 * r**3 / 6 * (1 - x))
        dy = cl * np.where(x < r, k1 / 6 * (3 * x**2 - 6 * r * x + r**2 * (3 - r)), -k1 * r**3 / 6)
    th = np.arctan(dy)
    up = np.column_stack([x - yt * np.sin(th), yc + yt * np.cos(th)])[::-1]
    lo = np.column_stack([x + yt * np.sin(th), yc - yt * np.cos(th)])[1:]
    pts = np.vstack([up, lo])
    if points % 2 == 0:
        pts = np.delete(pts, n + (n - 1) // 2, axis=0)
    return pts


def max_distance(t, c, k, pts, per_span=64):
    """max over the data of the distance to the spline (t, c, k): nearest of dense samples on
    every knot span, then Newton on (C - Q).C' from the three nearest samples."""
    spl = BSpline(np.asarray(t), np.asarray(c), k)
    d1, d2 = spl.derivative(1), spl.derivative(2)
    breaks = np.unique(t[k:len(t) - k])
    u = np.concatenate([np.linspace(a, b, per_span, endpoint=False) for a, b in zip(breaks[:-1], breaks[1:])] + [breaks[-1:]])
    samples = spl(u)
    _, idx = cKDTree(samples).query(pts, k=3)
    best = np.linalg.norm(samples[idx[:, 0]] - pts, axis=1)
    step_cap = 2 * (breaks[-1] - breaks[0]) / len(u)
    for j in range(idx.shape[1]):
        uu = u[idx[:, j]].copy()
        for _ in range(8):
            w = spl(uu) - pts
            dp, ddp = d1(uu), d2(uu)
            f = np.sum(w * dp, axis=1)
            fp = np.sum(dp * dp, axis=1) + np.sum(w * ddp, axis=1)
            step = np.where(fp > 0, -f / np.where(fp > 0, fp, 1.0), 0.0)
            uu = np.clip(uu + np.clip(step, -step_cap, step_cap), breaks[0], breaks[-1])
        best = np.minimum(best, np.linalg.norm(spl(uu) - pts, axis=1))
    return float(best.max())


def scipy_best(pts, tol, k=3, grid=48):
    """The fewest splprep coefficients with a measured deviation within tol, over s."""
    best = None
    for s in [0.0] + list(len(pts) * tol**2 * np.logspace(1, -6, grid)):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                (t, c, _), _ = splprep([pts[:, 0], pts[:, 1]], s=s, k=k, quiet=1)
        except Exception:
            continue
        n = len(t) - k - 1
        if best is not None and n >= best:
            continue
        if max_distance(t, np.array(c)[:, :n].T, k, pts) <= tol:
            best = n
    return best


def main(quick):
    codes = CODES[::4] if quick else CODES
    for tol in TOLERANCES:
        ours, theirs, over, interpolated, times, times_400 = [], [], 0, 0, [], []
        for code in codes:
            for n in COUNTS:
                for spacing in ("cosine", "uniform"):
                    pts = naca(code, n, spacing)
                    t0 = time.perf_counter()
                    curve, _, err = camber.fit_to_tolerance(pts, 3, tol, method="centripetal")
                    times.append(time.perf_counter() - t0)
                    if n == 400:
                        times_400.append(times[-1])
                    cps = np.asarray(curve.control_points)
                    measured = max_distance(np.asarray(curve.knots), cps, 3, pts)
                    over += measured > tol * (1 + 1e-6)
                    interpolated += len(cps) == len(pts)
                    ours.append(len(cps))
                    theirs.append(scipy_best(pts, tol))
        print(f"tol {tol:g}: camber median {np.median(ours):.0f} control points, "
              f"splprep median {np.median(theirs):.0f}; sections {len(ours)}, "
              f"camber over tolerance (measured here) {over}, interpolated {interpolated}, "
              f"camber median time {np.median(times) * 1e3:.2f} ms, "
              f"400-point sections median {np.median(times_400) * 1e3:.2f} ms, "
              f"slowest {np.max(times_400) * 1e3:.2f} ms")


if __name__ == "__main__":
    main("--quick" in sys.argv)
