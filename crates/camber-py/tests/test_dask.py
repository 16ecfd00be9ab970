"""The Dask recipe of docs/python.md, small: diffuser variants swept on a LocalCluster with
two worker processes, gathered into a table that matches solving the same variants here."""

import pytest

distributed = pytest.importorskip("dask.distributed")

from camber.sweep import diffuser_variants, solve_chunk, solve_variant  # noqa: E402


def test_sweep_on_a_local_cluster_matches_local_solves(sketches):
    base = (sketches / "diffuser.json").read_text()
    variants = diffuser_variants(12, seed=3)
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as client:
        futures = client.map(solve_variant, [base] * len(variants), variants)
        rows = client.gather(futures)
        # The chunked form of the docs (tasks of several variants) gives the same rows.
        chunks = [variants[i : i + 5] for i in range(0, len(variants), 5)]
        chunked = [r for part in client.gather(client.map(solve_chunk, [base] * 3, chunks)) for r in part]
    assert len(rows) == 12
    assert len({r["worker_pid"] for r in rows}) >= 1
    local = [solve_variant(base, v) for v in variants]
    for got, want in zip(rows, local):
        assert got["ok"] == want["ok"]
        if got["ok"]:
            assert got["max_residual"] < 1e-6
            assert got["contact_u"] == pytest.approx(want["contact_u"], abs=1e-9)
    assert sum(r["ok"] for r in rows) >= 10
    for got, want in zip(chunked, rows):
        assert got["ok"] == want["ok"]
        if got["ok"]:
            assert got["contact_u"] == pytest.approx(want["contact_u"], abs=1e-9)


def test_parameter_table_sweep_on_a_local_cluster_matches_the_moved_circles(sketches):
    # The same variants as a table of the parametric diffuser's parameters, in tasks that
    # each call solve_many(parameters=…): the contact found equals that of the plain diffuser
    # with its circles moved in the file (an independent construction of the same sketch).
    from camber.sweep import diffuser_table, solve_table

    base = (sketches / "diffuser.json").read_text()
    parametric = (sketches / "diffuser_parametric.json").read_text()
    variants = diffuser_variants(12, seed=3)
    table = diffuser_table(12, seed=3)
    parts = [{k: v[i : i + 5] for k, v in table.items()} for i in range(0, 12, 5)]
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as client:
        futures = client.map(solve_table, [parametric] * len(parts), parts)
        rows = [r for part in client.gather(futures) for r in part]
    assert len(rows) == 12
    for got, variant in zip(rows, variants):
        want = solve_variant(base, variant)
        assert got["ok"] == want["ok"], (got, want)
        if got["ok"]:
            assert got["max_residual"] < 1e-9
            assert got["contact_u"] == pytest.approx(want["contact_u"], abs=1e-9)
