"""`camber batch DIR --jobs N` against `camber.solve_many(paths, threads=N)` on the same files,
interleaved round by round so that both see the same machine load (hyperfine-style repeated
runs; the median and the best of each are printed with the CPU the runs got).

    cargo build --release -p camber-cli
    python crates/camber-py/bench/batch_cli.py [COPIES] [ROUNDS] [SKETCH]

Default: 40 copies of examples/sketches/w3a_chain_1000.json, 7 rounds. The CPU column is
(user + system CPU seconds) / wall seconds: 2.0 means both cores were ours all along, so a
speed-up below 2 at a CPU figure well below 2 is the machine's load, not the program.
"""

import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import camber

ROOT = Path(__file__).resolve().parents[3]


def cli_run(binary, folder, jobs):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(
        [str(binary), "batch", str(folder), "--jobs", str(jobs)],
        check=True,
        stdout=subprocess.DEVNULL,
    )
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def py_run(paths, threads):
    before = os.times()
    t0 = time.perf_counter()
    results = camber.solve_many(paths, threads=threads)
    wall = time.perf_counter() - t0
    after = os.times()
    assert all(r["ok"] for r in results)
    return wall, (after.user - before.user) + (after.system - before.system)


def main(copies, rounds, sketch):
    binary = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target")) / "release" / "camber"
    folder = Path(tempfile.mkdtemp(prefix="camber-batch-"))
    try:
        for i in range(copies):
            shutil.copy(sketch, folder / f"s{i:04}.json")
        paths = sorted(str(p) for p in folder.glob("*.json"))
        runs = {}
        for _ in range(rounds):
            for jobs in (1, 2):
                runs.setdefault(("camber batch --jobs", jobs), []).append(cli_run(binary, folder, jobs))
                runs.setdefault(("solve_many threads=", jobs), []).append(py_run(paths, jobs))
        print(f"{copies} x {Path(sketch).name}, {rounds} rounds, load average {os.getloadavg()[0]:.1f}")
        medians = {}
        for (what, n), rs in runs.items():
            walls = [w for w, _ in rs]
            cpu_share = statistics.median(c / w for w, c in rs)
            medians[(what, n)] = statistics.median(walls)
            print(
                f"{what}{n}: median {medians[(what, n)]:.3f} s, best {min(walls):.3f} s, "
                f"CPU {cpu_share:.2f} cores"
            )
        for what in ("camber batch --jobs", "solve_many threads="):
            print(f"{what.split()[0]} speed-up (median): {medians[(what, 1)] / medians[(what, 2)]:.2f}x")
    finally:
        shutil.rmtree(folder)


if __name__ == "__main__":
    main(
        int(sys.argv[1]) if len(sys.argv) > 1 else 40,
        int(sys.argv[2]) if len(sys.argv) > 2 else 7,
        sys.argv[3] if len(sys.argv) > 3 else ROOT / "examples" / "sketches" / "w3a_chain_1000.json",
    )
