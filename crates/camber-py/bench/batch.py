"""Batch speed-up: copies of the bundled diffuser and two-curves sketches solved by
``camber.solve_many`` on 1 and on 2 threads (best of several runs each).

    python crates/camber-py/bench/batch.py [COPIES]
"""

import sys
import time
from pathlib import Path

import camber

ROOT = Path(__file__).resolve().parents[3]


def main(copies):
    texts = [
        (ROOT / "examples" / "sketches" / n).read_text()
        for n in ("diffuser.json", "two_curves.json")
    ]
    times = {}
    for threads in (1, 2):
        best = float("inf")
        for _ in range(5):
            items = [camber.Sketch.from_json(t) for t in texts for _ in range(copies)]
            t0 = time.perf_counter()
            results = camber.solve_many(items, threads=threads)
            best = min(best, time.perf_counter() - t0)
            assert all(r["ok"] for r in results)
        times[threads] = best
        print(f"{len(items)} sketches on {threads} thread(s): {best * 1e3:.0f} ms")
    print(f"speed-up: {times[1] / times[2]:.2f}x")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 200)
