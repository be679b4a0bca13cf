"""`vor.clipped_cells(bbox)` and `vor.to_geojson(bbox)`: the command line's clipped cells
(`wdm-crust voronoi --format geojson [--clip ...]`), ring for ring; the cells of the
distinct points are valid polygons that tile the box."""

import json
import math

import numpy as np
import pytest
import shapely
from shapely.geometry import Point, box
from shapely.geometry import Polygon as ShapelyPolygon
from shapely.strtree import STRtree

import wdm_crust
from .real_files import real_point_files
from .samples import SAMPLES

BOXES = [None, (-0.25, -0.5, 0.75, 0.6), (-10.0, -10.0, 10.0, 10.0)]


def clip_flags(bbox):
    return [] if bbox is None else ["--clip", ",".join(repr(v) for v in bbox)]


def check_tiling(cells, bbox, points, duplicates):
    """Valid counterclockwise rings whose areas add up to the box's, no two overlapping,
    every site in the box inside its own cell."""
    area = (bbox[2] - bbox[0]) * (bbox[3] - bbox[1])
    duplicate = set(duplicates[:, 0].tolist())
    polygons = {}
    for site, ring in enumerate(cells):
        assert ring.dtype == np.float64 and ring.shape[1:] == (2,)
        if site in duplicate:
            assert len(ring) == 0
        if len(ring) == 0:
            continue
        polygon = ShapelyPolygon(ring)
        assert polygon.is_valid, (site, shapely.validation.explain_validity(polygon))
        assert polygon.exterior.is_ccw
        assert box(*bbox).buffer(1e-9 * math.sqrt(area)).contains(polygon)
        polygons[site] = polygon
    assert math.fsum(p.area for p in polygons.values()) == pytest.approx(area, rel=1e-9)
    sites = list(polygons)
    geometries = [polygons[s] for s in sites]
    tree = STRtree(geometries)
    for i, j in zip(*tree.query(geometries, predicate="intersects")):
        if i < j:
            assert geometries[i].intersection(geometries[j]).area <= 1e-9 * area
    for site, (x, y) in enumerate(points):
        if site in duplicate or not (bbox[0] < x < bbox[2] and bbox[1] < y < bbox[3]):
            continue
        assert polygons[site].buffer(1e-9 * math.sqrt(area)).contains(Point(x, y))


def default_box(points):
    """The command line's default box: the bounding box enlarged by 10 % of its larger side
    (to rounding; the checks allow 1e-9 of it)."""
    lo, hi = points.min(axis=0), points.max(axis=0)
    margin = 0.1 * (hi - lo).max()
    return (lo[0] - margin, lo[1] - margin, hi[0] + margin, hi[1] + margin)


@pytest.mark.parametrize("name", [n for n in SAMPLES if n not in ("no points",)])
@pytest.mark.parametrize("bbox", BOXES, ids=repr)
def test_cells_are_the_cli_cells(cli_text, name, bbox):
    points = SAMPLES[name]()
    text = cli_text("voronoi", "--format", "geojson", *clip_flags(bbox), points=points)
    vor = wdm_crust.voronoi(points)
    assert vor.to_geojson(bbox) == text
    features = json.loads(text)["features"]
    cells = vor.clipped_cells(bbox)
    assert len(cells) == len(points)
    tri = wdm_crust.triangulate(points)
    duplicates = set(tri.duplicates[:, 0].tolist())
    assert [f["properties"]["site"] for f in features] == [
        i for i in range(len(points)) if i not in duplicates
    ]
    for feature in features:
        ring = cells[feature["properties"]["site"]]
        if feature["geometry"] is None:
            assert len(ring) == 0
        else:
            assert feature["geometry"]["coordinates"] == [ring.tolist() + ring[:1].tolist()]
    if tri.triangles.size:
        check_tiling(cells, default_box(points) if bbox is None else bbox, points, tri.duplicates)
    # The same cells from a triangulation's Voronoi diagram.
    assert [c.tolist() for c in tri.voronoi().clipped_cells(bbox)] == [c.tolist() for c in cells]


@pytest.mark.parametrize("name,path", real_point_files()[::3], ids=lambda v: str(v))
def test_real_cells_tile_the_box(cli_text, name, path):
    points = wdm_crust.read_points(path)
    vor = wdm_crust.voronoi(points)
    assert vor.to_geojson() == cli_text("voronoi", "--format", "geojson", path)
    lo, hi = points.min(axis=0), points.max(axis=0)
    bbox = (lo[0], lo[1], (lo[0] + hi[0]) / 2, hi[1])  # a box cutting through the points
    cells = vor.clipped_cells(bbox)
    check_tiling(cells, bbox, points, wdm_crust.triangulate(points).duplicates)


def test_bad_boxes_are_refused():
    vor = wdm_crust.voronoi(SAMPLES["lattice"]())
    with pytest.raises(ValueError, match="^bbox: "):
        vor.clipped_cells((1.0, 0.0, 0.0, 1.0))
    with pytest.raises(ValueError, match="^bbox: "):
        vor.clipped_cells((0.0, 0.0, math.nan, 1.0))
    with pytest.raises(ValueError, match="length 4"):
        vor.clipped_cells((0.0, 0.0, 1.0))
    assert wdm_crust.voronoi(np.zeros((0, 2))).clipped_cells() == []
