"""`wdm-crust voronoi --format geojson`: the clipped cells are valid polygons that tile the box.

Runs the release binary (`cargo build --release` first) on every point file in tests/data
and on generated degenerate inputs (grid, collinear, duplicates, cocircular, clustered,
huge and tiny scales, a box cutting through the points) and checks with shapely: every
polygon `is_valid` with a closed counterclockwise ring, one feature per distinct point, the
union and the sum of the areas equal to the box's area (relative 1e-9), no two cells with
intersecting interiors or an intersection of positive area, and every site in the box
covered by its own cell.
"""

import json
import math
import pathlib
import random
import subprocess

import pytest
import shapely
from shapely.geometry import Point, box, shape
from shapely.strtree import STRtree

ROOT = pathlib.Path(__file__).resolve().parents[2]
BINARY = ROOT / "target" / "release" / "wdm-crust"
DATA = ROOT / "tests" / "data"
POINT_SUFFIXES = {".txt", ".xy", ".xym", ".p2d", ".gtn", ".node", ".csv"}


def point_files(fuzz):
    """The real point sets (tests/data), or the fuzz regression inputs (tests/data/regressions)."""
    files = sorted(
        p
        for p in DATA.rglob("*")
        if p.is_file()
        and p.suffix in POINT_SUFFIXES
        and p.name != "GPL-3.0.txt"
        and (p.relative_to(DATA).parts[0] == "regressions") == fuzz
    )
    assert files, f"no point files under {DATA}"
    return files


def read_points(path):
    """The documented input formats: plain text / CSV (first two numbers of a line, a
    non-numeric header skipped) and .node/.gtn (header `N 2 A B`, then `index x y ...`)."""
    points = []
    node = path.suffix in {".node", ".gtn"}
    header_seen = False
    for raw in path.read_text().splitlines():
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        fields = line.replace(",", " ").split()
        if node:
            if not header_seen:
                header_seen = True
                continue
            fields = fields[1:]
        try:
            points.append((float(fields[0]), float(fields[1])))
        except ValueError:
            assert not points, f"{path}: unparsable line {raw!r}"
    return points


def default_box(points):
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    side = max(max(xs) - min(xs), max(ys) - min(ys))
    magnitude = max(abs(xs[0]), abs(ys[0]))
    # All points equal: 10 % of their magnitude, or 1 at the origin.
    margin = 0.1 * side if side > 0 else (0.1 * magnitude if magnitude > 0 else 1.0)
    return (min(xs) - margin, min(ys) - margin, max(xs) + margin, max(ys) + margin)


def run_voronoi(text, clip=None):
    assert BINARY.exists(), f"{BINARY} missing: run `cargo build --release` first"
    args = [str(BINARY), "voronoi", "--format", "geojson"]
    if clip is not None:
        args += ["--clip", ",".join(repr(c) for c in clip)]
    done = subprocess.run(args, input=text, capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def check_tiling(points, clip=None, union=True):
    collection = run_voronoi("".join(f"{x!r} {y!r}\n" for x, y in points), clip)
    bounds = clip if clip is not None else default_box(points)
    assert collection["type"] == "FeatureCollection"
    features = collection["features"]
    first = {}
    for i, p in enumerate(points):
        first.setdefault(p, i)
    distinct = sorted(first.values())
    assert [f["properties"]["site"] for f in features] == distinct

    cells = []
    for feature in features:
        assert feature["type"] == "Feature"
        site = feature["properties"]["site"]
        geometry = feature["geometry"]
        x, y = points[site]
        inside = bounds[0] <= x <= bounds[2] and bounds[1] <= y <= bounds[3]
        if geometry is None:
            assert not inside, f"site {site} in the box has no cell"
            continue
        assert geometry["type"] == "Polygon"
        ring = geometry["coordinates"][0]
        assert len(geometry["coordinates"]) == 1
        assert ring[0] == ring[-1], "ring not closed"
        polygon = shape(geometry)
        assert polygon.is_valid, (site, shapely.is_valid_reason(polygon))
        assert polygon.exterior.is_ccw, f"cell {site} is not counterclockwise"
        if inside:
            assert polygon.covers(Point(x, y)), f"cell {site} misses its site"
        cells.append(polygon)

    box_area = (bounds[2] - bounds[0]) * (bounds[3] - bounds[1])
    assert math.isclose(sum(c.area for c in cells), box_area, rel_tol=1e-9, abs_tol=0.0)
    # No overlaps, no gaps inside, shared edges matching vertex for vertex.
    assert shapely.coverage_is_valid(cells)
    if union:
        merged = shapely.union_all(cells)
        assert math.isclose(merged.area, box_area, rel_tol=1e-9, abs_tol=0.0)
        assert merged.difference(box(*bounds)).area <= 1e-9 * box_area

    tree = STRtree(cells)
    left, right = tree.query(cells, predicate="intersects")
    for i, j in zip(left, right):
        if i < j:
            a, b = cells[i], cells[j]
            assert not a.relate_pattern(b, "T********"), f"cells {i} and {j} overlap"
            assert a.intersection(b).area == 0.0, f"cells {i} and {j} overlap"
    return cells


@pytest.mark.parametrize("path", point_files(False), ids=lambda p: str(p.relative_to(DATA)))
def test_real_point_sets(path):
    points = read_points(path)
    assert len(points) >= 3, f"{path}: {len(points)} points read"
    check_tiling(points)


# Two known failures, strict so that a fix shows. The subnormal grid (points 1 ulp apart):
# the default box, 10 % of the extent beyond the points, rounds onto them and every clipped
# cell comes out empty (`null` geometry); the clipped cells are not computed in the
# reconstruction's rescaled frame. The fine cluster beside points up to 1e260: GEOS calls a
# cell ring self-intersecting, a judgement in floating point whose products overflow there
# (not checked exactly yet).
SUBNORMAL_BOX = pytest.mark.xfail(
    strict=True, reason="subnormal grid: empty cells; 1e260 cluster: GEOS validity in floating point"
)
ULP_APART = ("subnormal-", "near-duplicates-in-a-fine-cluster")
# Cells of order 1e180 and more: GEOS's orientation and areas are products in doubles,
# which overflow beyond about 1e154, so it cannot judge them (strict, so that a checker that
# can shows).
BEYOND_GEOS = pytest.mark.xfail(
    strict=True, reason="coordinates of 1e190: GEOS's orientation and areas overflow"
)
HUGE = (
    "flow-junctions-far-apart-in-scale",
    "facing-swap-at-the-ends-of-the-range",
    "chain-ends-at-junctions",
)


def fuzz_params():
    def param(p):
        if p.name.startswith(ULP_APART):
            return pytest.param(p, marks=SUBNORMAL_BOX)
        if p.name.startswith(HUGE):
            return pytest.param(p, marks=BEYOND_GEOS)
        return p

    return [param(p) for p in point_files(True)]


@pytest.mark.parametrize("path", fuzz_params(), ids=lambda p: str(p.relative_to(DATA)))
def test_fuzz_inputs(path):
    """Coordinates of 1e-42 and 1e59 in one input give cells 1e-42 wide and 1e56 long:
    GEOS's floating-point union loses some 1e-7 of the area there, so only the exact-edge
    checks (validity, coverage, the sum of the areas) apply."""
    points = read_points(path)
    assert len(points) >= 3, f"{path}: {len(points)} points read"
    check_tiling(points, union=False)


def grid(k, step=1.0):
    return [(i * step, j * step) for i in range(k) for j in range(k)]


def cocircular():
    pts = [(0.0, 0.0)]
    for a, b in [(3, 4), (5, 0), (7, 24), (15, 20), (25, 0), (16, 63), (33, 56), (39, 52)]:
        for sx in (1, -1):
            for sy in (1, -1):
                pts.append((float(a * sx), float(b * sy)))
                pts.append((float(b * sx), float(a * sy)))
    return pts


def generated():
    rng = random.Random(16)
    uniform = [(rng.random(), rng.random()) for _ in range(400)]
    clusters = [
        (cx + rng.uniform(-1e-9, 1e-9), cy + rng.uniform(-1e-9, 1e-9))
        for cx, cy in [(rng.uniform(-50, 50), rng.uniform(-50, 50)) for _ in range(4)]
        for _ in range(40)
    ]
    return {
        "grid": grid(12),
        "grid-tenths": grid(12, 0.1),
        "grid-duplicated": grid(6) + grid(6),
        "horizontal": [(float(i), 2.0) for i in range(20)],
        "vertical": [(-1.0, float(i)) for i in range(20)],
        "diagonal-duplicates": [(float(i % 7), float(i % 7)) for i in range(30)],
        "two-points": [(0.0, 0.0), (1.0, 3.0)],
        "one-point": [(4.0, -2.0)],
        "cocircular": cocircular(),
        "clusters": clusters,
        "uniform": uniform,
        "uniform-tiny": [(x * 1e-30, y * 1e-30) for x, y in uniform],
        "uniform-huge": [(x * 1e40, y * 1e40) for x, y in uniform],
        "far-from-origin": [(1e6 + x, -1e6 + y) for x, y in uniform],
    }


CASES = generated()


@pytest.mark.parametrize("name", sorted(CASES))
def test_generated_inputs(name):
    check_tiling(CASES[name])


@pytest.mark.parametrize("name", ["uniform", "grid", "cocircular", "horizontal"])
def test_a_box_cutting_through_the_points(name):
    points = CASES[name]
    x0, y0, x1, y1 = default_box(points)
    clip = (x0 + 0.3 * (x1 - x0), y0 + 0.25 * (y1 - y0), x1 - 0.2 * (x1 - x0), y1 - 0.35 * (y1 - y0))
    cells = check_tiling(points, clip)
    assert len(cells) < len({p for p in points}) or name == "horizontal"


def test_bad_clip_is_one_line_error():
    for clip in ["1,2,0,3", "0,0,nan,1", "0,0,1", "a,b,c,d"]:
        done = subprocess.run(
            [str(BINARY), "voronoi", "--clip", clip],
            input="0 0\n1 1\n",
            capture_output=True,
            text=True,
            check=False,
        )
        assert done.returncode == 2
        assert done.stdout == ""
        assert len(done.stderr.strip().splitlines()) == 1, done.stderr
