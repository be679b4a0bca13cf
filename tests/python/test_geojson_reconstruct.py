"""`wdm-crust reconstruct --format geojson` checked with shapely.

Runs the built command line (`target/release/wdm-crust`; build it with `cargo build --release`)
on every real point file the repository carries (tests/data) and on
generated held-out style inputs (nested shapes, noise, outliers, clusters, grids, collinear
and duplicated points), with each algorithm, and asserts:

* the structure of the contract's "GeoJSON output": a FeatureCollection of curve Polygons,
  chain LineStrings, one medial-axis MultiLineString and an unassigned MultiPoint (left out
  when empty), in that order, with their properties;
* every polygon is valid by shapely's `is_valid`, its rings are closed, the exterior runs
  counterclockwise and the holes clockwise;
* every position is the input point its index names, to the bit; every closed curve of the
  JSON output is one ring, every open chain one line string.

A missing binary or data directory fails; nothing is skipped.
"""

import json
import math
import pathlib
import subprocess

import numpy as np
import pytest
import shapely
from shapely.geometry import shape

ROOT = pathlib.Path(__file__).resolve().parents[2]
BIN = ROOT / "target" / "release" / "wdm-crust"
DATA_DIR = ROOT / "tests" / "data"
POINT_SUFFIXES = {".txt", ".p2d", ".xy", ".xym", ".gtn"}
ALGORITHMS = ["wdm", "crust", "nn-crust"]


def real_point_files():
    """Every point file in tests/data, by its path relative to it. Only the repository's
    copies: the same files on every machine, and a missing one fails."""
    found = {}
    for path in sorted(DATA_DIR.rglob("*")):
        if path.suffix in POINT_SUFFIXES and path.name != "GPL-3.0.txt":
            found[str(path.relative_to(DATA_DIR))] = path
    assert len(found) >= 25, f"the real point sets are missing: {DATA_DIR}"
    return sorted(found.items())


def read_points(path):
    """The points as the command line reads them (its JSON `points` count is checked)."""
    lines = path.read_text().splitlines()
    if path.suffix == ".gtn":
        lines = lines[1:]
    points = []
    for line in lines:
        fields = line.replace(",", " ").split()
        if not fields or line.startswith("#"):
            continue
        values = [float(f) for f in fields]
        points.append(values[1:3] if path.suffix == ".gtn" else values[:2])
    return np.array(points, dtype=np.float64)


def run(args, stdin=None):
    assert BIN.exists(), f"{BIN} is missing: run `cargo build --release` first"
    done = subprocess.run(
        [str(BIN), *args], input=stdin, capture_output=True, text=True, timeout=600
    )
    assert done.returncode == 0, done.stderr
    return done.stdout


def points_text(points):
    # repr() of a float is its shortest round-trip form: the binary reads the same doubles.
    return "".join(f"{x!r} {y!r}\n" for x, y in points.tolist())


def check(points, geojson_text, json_text):
    """Everything the module docstring promises, for one run."""
    collection = json.loads(geojson_text)
    reference = json.loads(json_text)
    assert collection["type"] == "FeatureCollection"
    assert reference["points"] == len(points)
    order = ["curve", "chain", "medial_axis", "unassigned"]
    kinds = [f["properties"]["kind"] for f in collection["features"]]
    assert kinds == sorted(kinds, key=order.index), kinds
    assert kinds.count("medial_axis") == 1
    assert kinds.count("unassigned") <= 1

    def same_point(position, index):
        x, y = points[index]
        return position[0] == x and position[1] == y and len(position) == 2

    rings, chains = [], []
    for feature in collection["features"]:
        assert feature["type"] == "Feature"
        geometry, props = feature["geometry"], feature["properties"]
        kind = props["kind"]
        if kind == "curve":
            assert geometry["type"] == "Polygon"
            assert set(props) == {"kind", "points", "holes"}
            polygon = shape(geometry)
            assert polygon.is_valid, shapely.validation.explain_validity(polygon)
            assert exactly_ccw(geometry["coordinates"][0]), "exterior counterclockwise"
            assert all(not exactly_ccw(hole) for hole in geometry["coordinates"][1:]), "holes clockwise"
            named = [props["points"], *props["holes"]]
            assert len(named) == len(geometry["coordinates"])
            for ring, indices in zip(geometry["coordinates"], named):
                assert ring[0] == ring[-1], "closed ring"
                assert len(ring) == len(indices) + 1 >= 4
                assert all(same_point(p, i) for p, i in zip(ring, indices))
                rings.append(sorted(indices))
        elif kind == "chain":
            assert geometry["type"] == "LineString"
            assert set(props) == {"kind", "points"}
            line = geometry["coordinates"]
            assert len(line) == len(props["points"]) >= 2
            assert all(same_point(p, i) for p, i in zip(line, props["points"]))
            chains.append(props["points"])
        elif kind == "medial_axis":
            assert geometry["type"] == "MultiLineString"
            assert props == {"kind": "medial_axis"}
            segments = geometry["coordinates"]
            assert len(segments) == len(reference["medial_axis"]["edges"])
            assert all(len(s) == 2 and all(map(math.isfinite, sum(s, []))) for s in segments)
        else:
            assert geometry["type"] == "MultiPoint"
            assert props["points"], "omitted when empty"
            assert props["points"] == reference["unassigned"]
            assert all(same_point(p, i) for p, i in zip(geometry["coordinates"], props["points"]))
    if "unassigned" not in kinds:
        assert reference["unassigned"] == []
    closed = sorted(sorted(c["points"]) for c in reference["curves"] if c["closed"])
    assert sorted(rings) == closed, "every closed curve is one ring"
    assert chains == [c["points"] for c in reference["curves"] if not c["closed"]]
    return collection


def exactly_ccw(ring):
    """The ring's orientation from its signed area in rationals: shapely's floating-point
    area overflows for coordinates beyond about 1e154 (the regression inputs reach 1e260)."""
    from fractions import Fraction

    twice_area = sum(
        Fraction(x0) * Fraction(y1) - Fraction(x1) * Fraction(y0)
        for (x0, y0), (x1, y1) in zip(ring, ring[1:])
    )
    return twice_area > 0


def reconstruct_both(args):
    geojson_text = run(["reconstruct", *args, "--format", "geojson"])
    json_text = run(["reconstruct", *args, "--format", "json"])
    return geojson_text, json_text


@pytest.mark.parametrize("algorithm", ALGORITHMS)
@pytest.mark.parametrize("name,path", real_point_files(), ids=lambda v: v if isinstance(v, str) else "")
def test_real_point_file(name, path, algorithm):
    points = read_points(path)
    geojson_text, json_text = reconstruct_both([str(path), "--algorithm", algorithm])
    check(points, geojson_text, json_text)


# Held-out style inputs, generated here: none of them is in the repository.


def ellipse(rng, centre, a, b, n, angle=0.0):
    step = 2 * np.pi / n
    t = np.arange(n) * step + rng.uniform(-0.3, 0.3, n) * step
    c, s = math.cos(angle), math.sin(angle)
    x, y = a * np.cos(t), b * np.sin(t)
    return np.column_stack([centre[0] + c * x - s * y, centre[1] + s * x + c * y])


def star(centre, r, arms, depth, n, phase=0.0):
    t = np.linspace(0, 2 * np.pi, n, endpoint=False) + phase
    radius = r * (1 + depth * np.cos(arms * t))
    return np.column_stack([centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t)])


def nested_rings(rng):
    """Concentric shapes four deep, beside a ring with two holes and a star."""
    parts = [ellipse(rng, (0, 0), 10 - 2.2 * k, 7 - 1.5 * k, 120 - 25 * k, 0.3) for k in range(4)]
    parts.append(ellipse(rng, (30, 0), 9, 6, 140))
    parts.append(ellipse(rng, (27, 0), 2, 1.5, 30))
    parts.append(ellipse(rng, (33, 1), 1.8, 2.5, 30))
    parts.append(star((0, 25), 5, 5, 0.25, 150))
    return np.concatenate(parts)


def moved(points, rng):
    angle = rng.uniform(0, 2 * np.pi)
    c, s = math.cos(angle), math.sin(angle)
    scale = 10.0 ** rng.uniform(-3, 4)
    offset = rng.uniform(-1e4, 1e4, 2)
    out = points @ np.array([[c, s], [-s, c]]) * scale + offset
    return out[rng.permutation(len(out))]


def held_out_inputs():
    rng = np.random.default_rng(20261130)
    cases = {}
    base = nested_rings(rng)
    cases["nested"] = moved(base, rng)
    noisy = base + rng.normal(0, 0.05, base.shape)
    cases["nested-noisy"] = moved(noisy, rng)
    lo, hi = base.min(axis=0), base.max(axis=0)
    outliers = rng.uniform(lo, hi, (len(base) // 20, 2))
    cases["nested-outliers"] = moved(np.concatenate([base, outliers]), rng)
    cases["stars"] = moved(
        np.concatenate(
            [star((12 * i, 12 * j), 4, 3 + i + j, 0.3, 80 + 10 * i) for i in range(3) for j in range(3)]
        ),
        rng,
    )
    arc = np.column_stack([np.linspace(0, 3, 40), np.sin(np.linspace(0, 3, 40))])
    cases["arcs-and-loop"] = moved(np.concatenate([arc, arc + [0, 3], ellipse(rng, (1.5, -4), 2, 1, 50)]), rng)
    cases["uniform-noise"] = rng.uniform(0, 1, (2000, 2))
    cases["clusters"] = np.concatenate([rng.normal(c, 0.01, (100, 2)) for c in rng.uniform(0, 1, (10, 2))])
    grid = np.array([[i, j] for i in range(25) for j in range(25)], dtype=np.float64)
    cases["grid"] = grid[rng.permutation(len(grid))]
    cases["grid-with-duplicates"] = np.concatenate([grid, grid[:100]])
    cases["collinear"] = np.column_stack([np.arange(30.0), 0.5 * np.arange(30.0)])
    cases["two-points"] = np.array([[0.0, 0.0], [1.0, 1.0]])
    cases["one-point"] = np.array([[3.0, 4.0]])
    cases["duplicates-only"] = np.array([[1.0, 1.0]] * 5)
    cases["tiny-coordinates"] = moved(base, rng) * 1e-30
    return sorted(cases.items())


@pytest.mark.parametrize("algorithm", ALGORITHMS)
@pytest.mark.parametrize("name,points", held_out_inputs(), ids=lambda v: v if isinstance(v, str) else "")
def test_held_out_input(name, points, algorithm):
    text = points_text(points)
    geojson_text = run(["reconstruct", "-", "--algorithm", algorithm, "--format", "geojson"], text)
    json_text = run(["reconstruct", "-", "--algorithm", algorithm, "--format", "json"], text)
    check(points, geojson_text, json_text)


def test_nesting_known_answer():
    """Four concentric circles and a ring with two holes: exact expected polygon shapes."""
    circle = lambda c, r, n: np.array(
        [[c[0] + r * math.cos(2 * math.pi * k / n), c[1] + r * math.sin(2 * math.pi * k / n)] for k in range(n)]
    )
    points = np.concatenate(
        [circle((0, 0), r, n) for r, n in [(16, 160), (12, 120), (8, 80), (4, 40)]]
        + [circle((40, 0), 8, 80), circle((37, 0), 2, 20), circle((43, 0), 2, 20)]
    )
    text = points_text(points)
    collection = check(
        points,
        run(["reconstruct", "-", "--format", "geojson"], text),
        run(["reconstruct", "-", "--format", "json"], text),
    )
    polygons = [shape(f["geometry"]) for f in collection["features"] if f["properties"]["kind"] == "curve"]
    summary = sorted((len(p.exterior.coords) - 1, sorted(len(h.coords) - 1 for h in p.interiors)) for p in polygons)
    assert summary == [(80, [20, 20]), (80, [40]), (160, [120])]
    # The polygons do not overlap: the island sits in the hole of the outer ring.
    total = sum(p.area for p in polygons)
    assert math.isclose(shapely.union_all(polygons).area, total, rel_tol=1e-12)


def test_output_file_extension_selects_geojson(tmp_path):
    out = tmp_path / "shapes.geojson"
    run(["reconstruct", "-", "-o", str(out)], "0 0\n2 0\n2 2\n0 2\n1 0.2\n")
    assert json.loads(out.read_text())["type"] == "FeatureCollection"
