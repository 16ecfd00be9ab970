"""Sweeps of the bundled diffuser sketch (examples/sketches/diffuser.json): variants of its
circles' radii and positions, and one solve per variant returning a table row. The functions
are plain and picklable, so any task engine can run them (docs/python.md runs them on Dask).
"""

import os
import random

import camber

#: The diffuser's circles: leading edge (entity 1), the middle contact (3), trailing edge (5).
CIRCLES = (1, 3, 5)


def diffuser_variants(count, seed=0, spread=0.1):
    """``count`` variants: each circle's radius and centre scaled/moved by up to ``spread``
    (relative to the radius), reproducibly from ``seed``."""
    rng = random.Random(seed)
    out = []
    for _ in range(count):
        out.append(
            {
                cid: {
                    "scale": 1.0 + rng.uniform(-spread, spread),
                    "dx": rng.uniform(-spread, spread),
                    "dy": rng.uniform(-spread, spread),
                }
                for cid in CIRCLES
            }
        )
    return out


def apply_variant(base_json, variant):
    """The diffuser sketch text with the variant's circles."""
    import json

    doc = json.loads(base_json)
    for e in doc["entities"]:
        change = variant.get(e["id"]) or variant.get(str(e["id"]))
        if change is None:
            continue
        r = e["radius"]
        e["radius"] = r * change["scale"]
        e["center"] = [e["center"][0] + change["dx"] * r, e["center"][1] + change["dy"] * r]
    return json.dumps(doc)


def solve_variant(base_json, variant):
    """Solves one variant; returns a row: ok, the error, the largest residual, the solved
    middle contact parameter, the solver time and the worker's process id."""
    sketch = camber.Sketch.from_json(apply_variant(base_json, variant))
    row = {"ok": False, "error": None, "max_residual": None, "contact_u": None}
    row["worker_pid"] = os.getpid()
    row.update({f"r{cid}": variant[cid]["scale"] for cid in CIRCLES if cid in variant})
    try:
        report = sketch.solve()
    except camber.CamberError as e:
        row["error"] = str(e)
        return row
    row["ok"] = True
    row["max_residual"] = report.max_residual
    row["contact_u"] = sketch.constraint(8)["u"]["free"]
    row["elapsed"] = report.elapsed
    return row


def solve_chunk(base_json, variants):
    """Solves a list of variants one after the other (one task of a chunked sweep: the task
    engine's cost per task is then paid once per chunk, not once per variant); returns their
    rows in order."""
    return [solve_variant(base_json, v) for v in variants]


#: The parameters of examples/sketches/diffuser_parametric.json: each circle's radius and centre.
PARAMETRIC_BASE = {
    "r1": 0.03, "x1": 0.03, "y1": 0.0,
    "r3": 0.07, "x3": 0.38, "y3": 0.04,
    "r5": 0.015, "x5": 0.985, "y5": 0.01,
}


def diffuser_table(count, seed=0, spread=0.1):
    """The variants of ``diffuser_variants`` as a table of the parametric diffuser's
    parameters (a dict of columns, one row per variant), for ``camber.solve_many(sketch,
    parameters=table)``."""
    table = {name: [] for name in PARAMETRIC_BASE}
    for variant in diffuser_variants(count, seed=seed, spread=spread):
        for cid in CIRCLES:
            change = variant[cid]
            r = PARAMETRIC_BASE[f"r{cid}"]
            table[f"r{cid}"].append(r * change["scale"])
            table[f"x{cid}"].append(PARAMETRIC_BASE[f"x{cid}"] + change["dx"] * r)
            table[f"y{cid}"].append(PARAMETRIC_BASE[f"y{cid}"] + change["dy"] * r)
    return table


def solve_table(base_json, table, threads=1):
    """One task of a parameter sweep: the parametric diffuser solved for every row of
    ``table`` by ``camber.solve_many`` (in Rust, the GIL released); returns the rows."""
    sketch = camber.Sketch.from_json(base_json)
    rows = camber.solve_many(sketch, parameters=table, threads=threads)
    for row in rows:
        row["worker_pid"] = os.getpid()
        row["contact_u"] = row.get("8.u")
    return rows
