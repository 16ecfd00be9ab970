"""The Dask sweep of docs/python.md: ``count`` variants of the bundled diffuser (circle radii
and positions) solved on a LocalCluster of 2 worker processes, gathered into a table whose
summary is printed with the wall time.

    python examples/python/dask_sweep.py 10000          # one task per variant
    python examples/python/dask_sweep.py 10000 250      # tasks of 250 variants each
    python examples/python/dask_sweep.py 10000 250 table
        # the parametric diffuser (examples/sketches/diffuser_parametric.json): tasks of 250
        # rows of a parameter table, each solved by camber.solve_many(sketch, parameters=…)

Needs ``dask[distributed]`` (pandas is not needed: the summary is computed here).
"""

import statistics
import sys
import time
from collections import Counter
from pathlib import Path

from dask.distributed import Client, LocalCluster

from camber.sweep import diffuser_table, diffuser_variants, solve_chunk, solve_table, solve_variant

SKETCH = Path(__file__).resolve().parents[2] / "examples" / "sketches" / "diffuser.json"
PARAMETRIC = SKETCH.with_name("diffuser_parametric.json")


def summary(rows, wall):
    """Printable lines: counts, residuals, the solved contact parameter and the load split."""
    ok = [r for r in rows if r["ok"]]
    errors = Counter(r["error"].split(":")[0] for r in rows if not r["ok"])
    lines = [
        f"variants {len(rows)}, solved {len(ok)}, failed {len(rows) - len(ok)}",
        f"wall {wall:.2f} s ({1e3 * wall / max(len(rows), 1):.2f} ms per variant)",
    ]
    if ok:
        us = [r["contact_u"] for r in ok if r.get("contact_u") is not None]
        lines += [
            f"largest residual {max(r['max_residual'] for r in ok):.2e}",
        ]
        if us:
            lines.append(f"contact u: min {min(us):.4f}, mean {statistics.fmean(us):.4f}, max {max(us):.4f}")
        if all("elapsed" in r for r in ok):
            lines.append(f"solver time per variant: mean {1e3 * statistics.fmean(r['elapsed'] for r in ok):.2f} ms")
    lines.append(f"tasks per worker process: {sorted(Counter(r['worker_pid'] for r in rows).values())}")
    lines += [f"failure '{k}': {v}" for k, v in errors.most_common(5)]
    return lines


def main():
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 10_000
    chunk = int(sys.argv[2]) if len(sys.argv) > 2 else 0
    table_mode = len(sys.argv) > 3 and sys.argv[3] == "table"
    base = SKETCH.read_text()
    variants = diffuser_variants(count, seed=1, spread=0.1)
    with LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, Client(cluster) as client:
        start = time.perf_counter()
        if table_mode:
            table = diffuser_table(count, seed=1, spread=0.1)
            step = chunk or count
            parts = [{k: v[i : i + step] for k, v in table.items()} for i in range(0, count, step)]
            futures = client.map(solve_table, [PARAMETRIC.read_text()] * len(parts), parts)
            rows = [row for part in client.gather(futures) for row in part]
        elif chunk > 0:
            chunks = [variants[i : i + chunk] for i in range(0, count, chunk)]
            futures = client.map(solve_chunk, [base] * len(chunks), chunks)
            rows = [row for part in client.gather(futures) for row in part]
        else:
            futures = client.map(solve_variant, [base] * count, variants, batch_size=500)
            rows = client.gather(futures)
        wall = time.perf_counter() - start
    print("\n".join(summary(rows, wall)))


if __name__ == "__main__":
    main()
