"""wdm_crust.triangulate against scipy.spatial.Delaunay on the same uniform random points.

Both build the whole triangulation and hand back an (m, 3) index array; timed interleaved
in one run, the minimum of a few rounds each, so the ratio is what counts on a shared
machine. Run from the repository root after installing the wheel (see the README):

    python python/bench/bench_scipy.py                 # 10^5 and 10^6 points, 5 rounds
    python python/bench/bench_scipy.py --sizes 100000 --rounds 3
"""

import argparse
import os
import platform
import time

import numpy as np
import scipy
import scipy.spatial

import wdm_crust


def best_time(function, points, rounds):
    best = float("inf")
    for _ in range(rounds):
        start = time.perf_counter()
        function(points)
        best = min(best, time.perf_counter() - start)
    return best


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[100_000, 1_000_000])
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()

    print(
        f"wdm_crust {wdm_crust.__version__}, scipy {scipy.__version__}, numpy {np.__version__}, "
        f"Python {platform.python_version()}, {os.cpu_count()} cores"
    )
    print(f"minimum of {args.rounds} interleaved rounds, uniform random points in the unit square")
    print(f"| n | wdm_crust.triangulate | scipy.spatial.Delaunay | scipy / wdm_crust |")
    print(f"|---:|---:|---:|---:|")
    rng = np.random.default_rng(1)
    for n in args.sizes:
        points = rng.random((n, 2))
        ours = wdm_crust.triangulate(points).triangles
        theirs = scipy.spatial.Delaunay(points).simplices
        # Random points are in general position: both must find the same number of triangles.
        assert len(ours) == len(theirs), (len(ours), len(theirs))
        wdm, qhull = float("inf"), float("inf")
        for _ in range(args.rounds):
            wdm = min(wdm, best_time(lambda p: wdm_crust.triangulate(p).triangles, points, 1))
            qhull = min(qhull, best_time(lambda p: scipy.spatial.Delaunay(p).simplices, points, 1))
        print(f"| {n:,} | {wdm * 1e3:.0f} ms | {qhull * 1e3:.0f} ms | {qhull / wdm:.2f}× |")


if __name__ == "__main__":
    main()
