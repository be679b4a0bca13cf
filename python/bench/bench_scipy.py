"""wdm_crust.triangulate against scipy.spatial.Delaunay on the same uniform random points.

Both build the whole triangulation and hand back an (m, 3) index array; timed interleaved
in one run, the minimum of a few rounds each, so the ratio is what counts on a shared
machine. Wall time and process CPU time are both reported: on a loaded machine the CPU
time is the steadier of the two (both libraries run on one thread). Run from the repository root after installing the wheel (see the README):

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


def timed(function, points):
    """(wall seconds, process CPU seconds) of one call."""
    wall, cpu = time.perf_counter(), time.process_time()
    function(points)
    return time.perf_counter() - wall, time.process_time() - cpu


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
    print("| n | wdm_crust.triangulate wall / CPU | scipy.spatial.Delaunay wall / CPU "
          "| scipy / wdm_crust wall / CPU |")
    print("|---:|---:|---:|---:|")
    rng = np.random.default_rng(1)
    for n in args.sizes:
        points = rng.random((n, 2))
        ours = wdm_crust.triangulate(points).triangles
        theirs = scipy.spatial.Delaunay(points).simplices
        # Random points are in general position: both must find the same number of triangles.
        assert len(ours) == len(theirs), (len(ours), len(theirs))
        wdm, qhull = [float("inf")] * 2, [float("inf")] * 2
        for _ in range(args.rounds):
            ours = timed(lambda p: wdm_crust.triangulate(p).triangles, points)
            theirs = timed(lambda p: scipy.spatial.Delaunay(p).simplices, points)
            wdm = [min(best, t) for best, t in zip(wdm, ours)]
            qhull = [min(best, t) for best, t in zip(qhull, theirs)]
        print(
            f"| {n:,} | {wdm[0] * 1e3:.0f} / {wdm[1] * 1e3:.0f} ms "
            f"| {qhull[0] * 1e3:.0f} / {qhull[1] * 1e3:.0f} ms "
            f"| {qhull[0] / wdm[0]:.1f}× / {qhull[1] / wdm[1]:.1f}× |"
        )


if __name__ == "__main__":
    main()
