"""The package returns exactly what the command line writes, on the same points and with
the same options: triangulate, voronoi and reconstruct JSON, field by field."""

import numpy as np
import pytest

import wdm_crust
from .samples import SAMPLES

# (keyword arguments of wdm_crust.reconstruct, the same options on the command line)
RECONSTRUCT_OPTIONS = [
    ({}, []),
    ({"algorithm": "crust"}, ["--algorithm", "crust"]),
    ({"algorithm": "nn-crust"}, ["--algorithm", "nn-crust"]),
    ({"peeling": False}, ["--no-peeling"]),
    ({"medial_axis": "raw"}, ["--medial-axis", "raw"]),
    ({"medial_axis": "none"}, ["--medial-axis", "none"]),
    ({"peeling_budget": 0}, ["--peeling-budget", "0"]),
    ({"smooth": True}, ["--smooth"]),
    ({"thinning": False}, ["--no-thinning"]),
    ({"threads": 1}, ["--threads", "1"]),
    ({"algorithm": "crust", "medial_axis": "none", "threads": 2}, ["--algorithm", "crust", "--medial-axis", "none", "--threads", "2"]),
]


@pytest.mark.parametrize("name", list(SAMPLES))
def test_triangulate_matches_the_cli(cli, name):
    points = SAMPLES[name]()
    expected = cli("triangulate", points)
    tri = wdm_crust.triangulate(points)
    assert tri.point_count == expected["points"]
    assert tri.triangles.dtype == np.int64 and tri.triangles.shape == (len(expected["triangles"]), 3)
    assert tri.triangles.tolist() == expected["triangles"]
    assert tri.hull.tolist() == expected["hull"]
    assert tri.duplicates.shape == (len(expected["duplicates"]), 2)
    assert tri.duplicates.tolist() == expected["duplicates"]


@pytest.mark.parametrize("name", list(SAMPLES))
def test_voronoi_matches_the_cli(cli, name):
    points = SAMPLES[name]()
    expected = cli("voronoi", points)
    for vor in (wdm_crust.voronoi(points), wdm_crust.triangulate(points).voronoi()):
        assert vor.vertices.shape == (len(expected["vertices"]), 2)
        assert vor.vertices.tolist() == expected["vertices"]  # the same float64 values
        assert vor.edges.shape == (len(expected["edges"]), 2)
        assert vor.edges.tolist() == expected["edges"]
        assert vor.rays.shape == (len(expected["rays"]), 3)
        assert vor.rays.tolist() == expected["rays"]
        assert [cell.tolist() for cell in vor.cells] == expected["cells"]
        assert all(cell.dtype == np.int64 for cell in vor.cells)


@pytest.mark.parametrize("name", list(SAMPLES))
@pytest.mark.parametrize("options,flags", RECONSTRUCT_OPTIONS, ids=lambda o: repr(o))
def test_reconstruct_matches_the_cli(cli, name, options, flags):
    points = SAMPLES[name]()
    expected = cli("reconstruct", points, *flags)
    rec = wdm_crust.reconstruct(points, **options)
    assert rec.algorithm == expected["algorithm"]
    assert rec.point_count == expected["points"]
    assert rec.edges.dtype == np.int64 and rec.edges.shape == (len(expected["edges"]), 2)
    assert rec.edges.tolist() == expected["edges"]
    curves = [
        {"closed": c.closed, "points": c.points.tolist(), "coords": c.coords.tolist()}
        for c in rec.curves
    ]
    assert curves == expected["curves"]
    vertices, edges = rec.medial_axis
    assert vertices.shape == (len(expected["medial_axis"]["vertices"]), 2)
    assert vertices.tolist() == expected["medial_axis"]["vertices"]
    assert edges.shape == (len(expected["medial_axis"]["edges"]), 2)
    assert edges.tolist() == expected["medial_axis"]["edges"]
    assert rec.unassigned.dtype == np.int64
    assert rec.unassigned.tolist() == expected["unassigned"]
    assert rec.duplicates.dtype == np.int64
    assert rec.duplicates.shape == (len(expected["duplicates"]), 2)
    assert rec.duplicates.tolist() == expected["duplicates"]
    assert rec.warnings == [(w["code"], w["message"]) for w in expected["warnings"]]


@pytest.mark.parametrize("name", list(SAMPLES))
def test_curve_coords_are_the_points_along_the_curve(name):
    points = SAMPLES[name]()
    for curve in wdm_crust.reconstruct(points).curves:
        assert curve.coords.shape == (len(curve), 2)
        assert np.array_equal(curve.coords, points[curve.points])


def test_smoothed_coords_match_the_cli_and_move_the_vertices(cli):
    """A dense noisy circle: smooth=True gives the command line's --smooth coordinates,
    fitted (closer to the circle than the samples), on the same curves."""
    rng = np.random.default_rng(5)
    t = rng.uniform(0.0, 2.0 * np.pi, 1000)
    points = np.column_stack([np.cos(t), np.sin(t)]) + rng.normal(0.0, 0.014, (1000, 2))
    plain = wdm_crust.reconstruct(points)
    rec = wdm_crust.reconstruct(points, smooth=True)
    assert [c.points.tolist() for c in rec.curves] == [c.points.tolist() for c in plain.curves]
    expected = [c["coords"] for c in cli("reconstruct", points, "--smooth")["curves"]]
    assert [c.coords.tolist() for c in rec.curves] == expected
    off = lambda xy: np.abs(np.hypot(xy[:, 0], xy[:, 1]) - 1.0)
    fitted = np.concatenate([off(c.coords) for c in rec.curves])
    assert np.sqrt(np.mean(fitted**2)) < 0.6 * np.sqrt(np.mean(off(points) ** 2))


def test_a_dense_band_is_thinned_as_on_the_command_line(cli):
    """A band many spacings wide: thinned to representatives (the JSON's "thinned"), one
    loop through them; thinning=False is --no-thinning, the points as they are."""
    rng = np.random.default_rng(8)
    t = rng.uniform(0.0, 2.0 * np.pi, 3000)
    points = np.column_stack([np.cos(t), np.sin(t)]) + rng.normal(0.0, 0.03, (3000, 2))
    rec = wdm_crust.reconstruct(points)
    expected = cli("reconstruct", points)
    assert rec.thinned is not None and rec.thinned == expected["thinned"]
    assert rec.edges.tolist() == expected["edges"]
    assert [c.closed for c in rec.curves] == [True]
    plain = wdm_crust.reconstruct(points, thinning=False)
    expected = cli("reconstruct", points, "--no-thinning")
    assert plain.thinned is None and "thinned" not in expected
    assert plain.edges.tolist() == expected["edges"]


def test_the_samples_reach_every_part_of_the_output():
    """Guards the comparisons above against vacuous agreement on empty results."""
    with_duplicates = wdm_crust.triangulate(SAMPLES["uniform with duplicates"]())
    assert with_duplicates.duplicates.tolist() == [[400, 3], [401, 17], [402, 3], [403, 0], [404, 1]]
    lattice = wdm_crust.voronoi(SAMPLES["lattice"]())
    assert len(lattice.vertices) == 64  # one merged vertex per unit square
    nested = wdm_crust.reconstruct(SAMPLES["nested circles"]())
    assert nested.passes >= 2 and [c.closed for c in nested.curves] == [True, True]
    assert wdm_crust.reconstruct(SAMPLES["nested circles"](), peeling=False).passes == 1
    outline = wdm_crust.reconstruct(SAMPLES["noisy outline with outliers"]())
    assert len(outline.medial_axis[1]) > 0
    assert 301 in outline.unassigned.tolist()
    arc = wdm_crust.reconstruct(SAMPLES["open arc"](), algorithm="crust")
    assert [(c.closed, len(c)) for c in arc.curves] == [(False, 80)]


@pytest.mark.parametrize("name", list(SAMPLES))
def test_no_medial_axis_changes_nothing_else(name):
    points = SAMPLES[name]()
    full = wdm_crust.reconstruct(points)
    curves_only = wdm_crust.reconstruct(points, medial_axis="none")
    assert curves_only.edges.tolist() == full.edges.tolist()
    assert [c.points.tolist() for c in curves_only.curves] == [c.points.tolist() for c in full.curves]
    assert curves_only.unassigned.tolist() == full.unassigned.tolist()
    assert curves_only.passes == full.passes
    vertices, edges = curves_only.medial_axis
    assert vertices.shape == (0, 2) and edges.shape == (0, 2)
