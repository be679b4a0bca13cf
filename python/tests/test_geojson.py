"""GeoJSON and polygons: `rec.to_geojson()` is the text `wdm-crust reconstruct --format
geojson` writes on the same points with the same options, byte for byte; the polygons are
its Polygon features; shapely and geopandas take the results directly."""

import json

import numpy as np
import pytest
import shapely
from shapely.geometry import LinearRing, shape
from shapely.geometry import Polygon as ShapelyPolygon

import wdm_crust
from .real_files import real_point_files
from .samples import SAMPLES
from .test_cli_agreement import RECONSTRUCT_OPTIONS

REAL = real_point_files()


@pytest.mark.parametrize("name", list(SAMPLES))
@pytest.mark.parametrize("options,flags", RECONSTRUCT_OPTIONS, ids=lambda o: repr(o))
def test_geojson_is_the_cli_text(cli_text, name, options, flags):
    points = SAMPLES[name]()
    expected = cli_text("reconstruct", "--format", "geojson", *flags, points=points)
    rec = wdm_crust.reconstruct(points, **options)
    assert rec.to_geojson() == expected
    assert rec.__geo_interface__ == json.loads(expected)
    check_polygons(rec, json.loads(expected), smoothed=options.get("smooth", False))


@pytest.mark.parametrize("name,path", REAL, ids=[name for name, _ in REAL])
def test_real_file_read_and_written_as_the_cli_does(cli_text, name, path):
    points = wdm_crust.read_points(path)
    assert points.dtype == np.float64 and points.shape[1:] == (2,)
    # The same points as the command line read: the same triangulation of the file.
    expected = json.loads(cli_text("triangulate", path))
    tri = wdm_crust.triangulate(points)
    assert tri.point_count == expected["points"]
    assert tri.triangles.tolist() == expected["triangles"]
    assert tri.hull.tolist() == expected["hull"]
    assert tri.duplicates.tolist() == expected["duplicates"]
    rec = wdm_crust.reconstruct(points)
    text = cli_text("reconstruct", "--format", "geojson", path)
    assert rec.to_geojson() == text
    check_polygons(rec, json.loads(text))


def check_polygons(rec, collection, smoothed=False):
    """The polygons are the collection's curve features, field for field, and valid."""
    curve_features = [f for f in collection["features"] if f["properties"]["kind"] == "curve"]
    polygons = rec.polygons()
    assert len(polygons) == len(curve_features)
    assert sum(1 + len(p.holes) for p in polygons) == sum(c.closed for c in rec.curves)
    for polygon, feature in zip(polygons, curve_features):
        assert polygon.__geo_interface__ == feature["geometry"]
        rings = feature["geometry"]["coordinates"]
        assert polygon.exterior.dtype == np.float64
        assert polygon.exterior.tolist() == rings[0][:-1]
        assert [h.tolist() for h in polygon.holes] == [r[:-1] for r in rings[1:]]
        assert polygon.exterior_points.dtype == np.int64
        assert polygon.exterior_points.tolist() == feature["properties"]["points"]
        assert [h.tolist() for h in polygon.hole_points] == feature["properties"]["holes"]
        if not smoothed:
            points = rec.points
            assert np.array_equal(points[polygon.exterior_points], polygon.exterior)
            for ring, indices in zip(polygon.holes, polygon.hole_points):
                assert np.array_equal(points[indices], ring)
        geometry = shape(polygon)
        assert geometry.is_valid, shapely.validation.explain_validity(geometry)
        assert LinearRing(polygon.exterior).is_ccw
        outer = ShapelyPolygon(polygon.exterior)
        for hole in polygon.holes:
            assert not LinearRing(hole).is_ccw
            assert outer.contains(ShapelyPolygon(hole))


def test_polygons_nest_holes_and_islands():
    """A ring with a hole holding an island: two polygons, the first with one hole."""
    def circle(n, r):
        t = 2 * np.pi * np.arange(n) / n
        return np.c_[r * np.cos(t), r * np.sin(t)]

    points = np.vstack([circle(160, 3.0), circle(100, 2.0), circle(40, 0.8)])
    rec = wdm_crust.reconstruct(points)
    polygons = rec.polygons()
    assert [(len(p.exterior), len(p.holes)) for p in polygons] == [(160, 1), (40, 0)]
    assert len(polygons[0].holes[0]) == 100
    check_polygons(rec, rec.__geo_interface__)
    assert repr(polygons[0]) == "Polygon(exterior=160, holes=1)"


def test_geopandas_takes_the_result():
    geopandas = pytest.importorskip(
        "geopandas", reason="geopandas is not installed (pip install geopandas)"
    )
    points = SAMPLES["nested circles"]()
    rec = wdm_crust.reconstruct(points)
    frame = geopandas.GeoDataFrame.from_features(rec)
    kinds = [f["properties"]["kind"] for f in rec.__geo_interface__["features"]]
    assert list(frame["kind"]) == kinds
    assert frame.geometry.is_valid.all()
    polygon = frame.geometry.iloc[0]
    assert polygon.equals(shape(rec.polygons()[0]))
    assert len(polygon.interiors) == 1
    # A GeoSeries of the polygons alone, from their own __geo_interface__.
    series = geopandas.GeoSeries([shape(p) for p in rec.polygons()])
    assert series.area.iloc[0] == pytest.approx(polygon.area)


SVG_OPTIONS = [
    ({}, {}, []),
    ({}, {"y_down": True, "show": ["delaunay", "voronoi", "labels"]}, ["--y-down", "--show", "delaunay,voronoi,labels"]),
    ({"smooth": True}, {"no_points": True}, ["--smooth", "--no-points"]),
    ({"algorithm": "nn-crust"}, {"show": ["voronoi"]}, ["--algorithm", "nn-crust", "--show", "voronoi"]),
]


@pytest.mark.parametrize("name", ["noisy outline with outliers", "nested circles", "open arc", "collinear"])
@pytest.mark.parametrize("options,svg,flags", SVG_OPTIONS, ids=repr)
def test_svg_is_the_cli_picture(cli_text, name, options, svg, flags):
    points = SAMPLES[name]()
    expected = cli_text("reconstruct", "--format", "svg", *flags, points=points)
    assert wdm_crust.reconstruct(points, **options).to_svg(**svg) == expected


def test_svg_options_are_checked():
    rec = wdm_crust.reconstruct(SAMPLES["open arc"](), algorithm="crust", medial_axis="none")
    with pytest.raises(ValueError, match="^show must list some of 'delaunay', 'voronoi', 'labels', got 'mesh'$"):
        rec.to_svg(show=["mesh"])
    with pytest.raises(ValueError, match="^show=\\['labels'\\] does not apply to algorithm='crust'"):
        rec.to_svg(show=["labels"])


def test_threads_change_nothing():
    points = SAMPLES["uniform with duplicates"]()
    one, two = wdm_crust.triangulate(points, threads=1), wdm_crust.triangulate(points, threads=2)
    assert one.triangles.tolist() == two.triangles.tolist()
    assert wdm_crust.voronoi(points, threads=1).vertices.tolist() == wdm_crust.voronoi(points).vertices.tolist()
    with pytest.raises(ValueError, match="^threads must be a whole number of at least 1, got -2$"):
        wdm_crust.reconstruct(points, threads=-2)
