"""The blade section (examples/sketches/blade_section.json), solved with camber and drawn with
matplotlib: each curve, its control polygon, and its curvature comb (spikes along the normal,
length proportional to the signed curvature), saved as a PNG.

    python examples/python/blade.py [OUT.png]
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import camber  # noqa: E402

HERE = Path(__file__).resolve().parent
SKETCH = HERE.parent / "sketches" / "blade_section.json"


def comb(curve, samples=120, scale=None):
    """Points, comb tips and the scale used: the tip is C(u) − s·κ(u)·n(u), n the left normal."""
    a, b = curve.domain
    u = np.linspace(a, b, samples)
    d = curve.derivatives(u, 1)
    p, t = d[:, 0], d[:, 1]
    n = np.stack([-t[:, 1], t[:, 0]], axis=1) / np.linalg.norm(t, axis=1)[:, None]
    k = curve.signed_curvature(u)
    if scale is None:
        scale = 0.03 / max(np.abs(k).max(), 1e-12)
    return p, p - scale * k[:, None] * n, scale


def draw(sketch, out):
    fig, ax = plt.subplots(figsize=(12, 3.5), dpi=120)
    curves = [sketch.curve(e) for e in sketch.entity_ids() if sketch.entity(e)["kind"] == "bezier"]
    # One comb scale per curve (the leading and trailing edges curve far more than the
    # sides): the longest spike of each comb is 0.03 chord.
    for i, c in enumerate(curves):
        a, b = c.domain
        pts = c.evaluate(np.linspace(a, b, 400))
        ax.plot(pts[:, 0], pts[:, 1], lw=2, color=f"C{i}", label=f"curve {i}")
        cp = c.control_points
        ax.plot(cp[:, 0], cp[:, 1], "--o", ms=3, lw=0.8, color=f"C{i}", alpha=0.6)
        p, tip, _ = comb(c)
        for (x0, y0), (x1, y1) in zip(p, tip):
            ax.plot([x0, x1], [y0, y1], lw=0.5, color="0.5")
        ax.plot(tip[:, 0], tip[:, 1], lw=0.8, color="0.3")
    ax.set_aspect("equal")
    ax.set_title("blade section: curves, control polygons, curvature combs")
    ax.legend(loc="lower center", ncol=4, fontsize=8)
    fig.tight_layout()
    fig.savefig(out)
    plt.close(fig)


def run(out):
    sketch = camber.Sketch.load(SKETCH)
    report = sketch.solve()
    if report.max_residual > 1e-8:
        raise RuntimeError(f"the blade did not solve: {report}")
    draw(sketch, out)
    return report


if __name__ == "__main__":
    target = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("blade_section.png")
    print(run(target))
    print(f"wrote {target}")
