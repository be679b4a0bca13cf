"""The binding's overhead: `tri.locate`/`tri.nearest` of 10^6 queries and `reconstruct` of
10^6 points from Python, against the Rust library on the same points in the same run
(`examples/query_timing.rs`, run as a subprocess on the arrays written to files).

Run from the repository root after installing the package (see python/README.md):

    cargo build --release --example query_timing
    python python/bench/bench_binding.py                 # 10^6 points and queries, 3 rounds
    python python/bench/bench_binding.py --size 100000 --rounds 5

Every time is the best of the rounds, which alternate between the two sides. The queries run on one thread in both (the binding
with threads=1, the Rust side with one Locator) and, for the binding, also on all cores
(its default); `reconstruct` runs with the defaults in both (rayon's pool of all cores).
The answers are compared (check sums), so both sides did the same work.
"""

import argparse
import json
import math
import os
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

import wdm_crust

ROOT = Path(__file__).resolve().parents[2]
RUST = ROOT / "target" / "release" / "examples" / "query_timing"


def curve_points(n, rng):
    """n points on k × k circles of n / k^2 samples each, a little noise: curves to find."""
    k = max(1, int(math.sqrt(n / 1000)))
    per = n // (k * k)
    t = 2 * np.pi * (np.arange(per) + rng.random(per) * 0.3) / per
    ring = np.c_[np.cos(t), np.sin(t)] * 0.4
    centres = np.array([(i, j) for i in range(k) for j in range(k)], dtype=float)
    points = (centres[:, None, :] + ring[None, :, :]).reshape(-1, 2)
    return points + rng.normal(0.0, 1e-4 * 2 * np.pi * 0.4 / per, points.shape)


def best(rounds, job):
    """(least wall seconds, last result) of `rounds` calls."""
    least, result = math.inf, None
    for _ in range(rounds):
        start = time.perf_counter()
        result = job()
        least = min(least, time.perf_counter() - start)
    return least, result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--size", type=int, default=1_000_000)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    if not RUST.is_file():
        raise SystemExit(f"{RUST} is missing: cargo build --release --example query_timing")
    rng = np.random.default_rng(1)
    points = rng.random((args.size, 2))
    queries = rng.random((args.size, 2)) * 1.1 - 0.05
    curves = curve_points(args.size, rng)
    rust = {}
    python = {}

    def keep(table, name, seconds):
        table[name] = min(seconds, table.get(name, math.inf))

    with tempfile.TemporaryDirectory() as folder:
        files = [Path(folder) / name for name in ("points", "queries", "curves")]
        for array, path in zip((points, queries, curves), files):
            array.astype("<f8").tofile(path)
        # Interleaved: each round runs the Rust side once, then the binding once, so that a
        # change in the machine's load touches both alike.
        for _ in range(args.rounds):
            done = subprocess.run([str(RUST), *map(str, files), "1"], capture_output=True, check=True)
            answer = json.loads(done.stdout)
            for name in ("triangulate", "locate", "nearest", "reconstruct"):
                keep(rust, name, answer[name])
            seconds, tri = best(1, lambda: wdm_crust.triangulate(points))
            keep(python, "triangulate", seconds)
            seconds, located = best(1, lambda: tri.locate(queries, threads=1))
            keep(python, "locate", seconds)
            seconds, nearest = best(1, lambda: tri.nearest(queries, threads=1))
            keep(python, "nearest", seconds)
            seconds, rec = best(1, lambda: wdm_crust.reconstruct(curves))
            keep(python, "reconstruct", seconds)
            seconds, located_all = best(1, lambda: tri.locate(queries))
            keep(python, "locate, all cores", seconds)
            seconds, _ = best(1, lambda: tri.nearest(queries))
            keep(python, "nearest, all cores", seconds)
            # The same answers on both sides.
            assert int(located.sum()) == answer["located_sum"]
            assert (located_all >= 0).tolist() == (located >= 0).tolist()
            assert int(nearest.sum()) == answer["nearest_sum"]
            assert len(rec.edges) == answer["edges"]

    n = f"{args.size:.0e}".replace("e+0", "e")
    print(f"{os.cpu_count()} cores, {args.rounds} rounds, best of each; seconds")
    print(f"{'':38} {'Rust':>8} {'Python':>8} {'ratio':>6}")
    rows = [
        (f"triangulate {n} uniform points", "triangulate"),
        (f"locate {n} queries, 1 thread", "locate"),
        (f"nearest {n} queries, 1 thread", "nearest"),
        (f"reconstruct {n} curve points", "reconstruct"),
    ]
    for label, name in rows:
        r, p = rust[name], python[name]
        print(f"{label:38} {r:8.3f} {p:8.3f} {p / r:6.2f}")
    for name in ("locate, all cores", "nearest, all cores"):
        print(f"{name + ' (Python default)':38} {'':8} {python[name]:8.3f}")

if __name__ == "__main__":
    main()
