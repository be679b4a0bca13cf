"""`wdm-crust voronoi --format geojson` against shapely/GEOS on the same uniform points, in one
run: the CLI's `write` phase (clipping the cells and writing GeoJSON) and the whole CLI run
(parse, triangulate, clip, write) against `shapely.voronoi_polygons(extend_to=box)` followed
by an intersection with the box (in memory, no I/O). Minimum of 3 rounds.

    cargo build --release && python3 benches/voronoi_geojson_vs_shapely.py   # needs shapely
"""
import pathlib
import random
import subprocess
import tempfile
import time

import shapely
from shapely.geometry import MultiPoint, box

B = str(pathlib.Path(__file__).resolve().parents[1] / "target" / "release" / "wdm-crust")
TMP = pathlib.Path(tempfile.mkdtemp())
for n in (10_000, 100_000):
    rng = random.Random(n)
    pts = [(rng.random(), rng.random()) for _ in range(n)]
    path = str(TMP / f"uniform{n}.txt")
    open(path, "w").write("".join(f"{x!r} {y!r}\n" for x, y in pts))
    xs = [p[0] for p in pts]; ys = [p[1] for p in pts]
    side = max(max(xs) - min(xs), max(ys) - min(ys)); m = 0.1 * side
    bounds = (min(xs) - m, min(ys) - m, max(xs) + m, max(ys) + m)
    best_w = best_s = best_tot = 1e9
    for _ in range(3):
        t = time.perf_counter()
        out = subprocess.run([B, "voronoi", path, "--format", "geojson", "--timings", "-o", str(TMP / "cells.geojson")], capture_output=True, text=True)
        best_tot = min(best_tot, time.perf_counter() - t)
        line = [l for l in out.stderr.splitlines() if l.strip().startswith("write")][0]
        best_w = min(best_w, float(line.split()[1]) / 1e3)
        mp = MultiPoint(pts); bx = box(*bounds)
        t = time.perf_counter()
        cells = shapely.voronoi_polygons(mp, extend_to=bx)
        clipped = shapely.intersection(shapely.get_parts(cells), bx)
        best_s = min(best_s, time.perf_counter() - t)
    print(f"n={n}: wdm-crust write phase (clip + GeoJSON) {best_w*1e3:.1f} ms, whole CLI run {best_tot*1e3:.1f} ms; "
          f"shapely voronoi_polygons + clip {best_s*1e3:.1f} ms; ratio write/shapely {best_w/best_s:.2f}, CLI/shapely {best_tot/best_s:.2f}")
