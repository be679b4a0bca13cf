"""What the package accepts as points, what it refuses and how, and how it treats the
caller's array (no copy of a C-contiguous float64 array, the GIL released meanwhile)."""

import ast
import re
import threading
import time
import tracemalloc
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import wdm_crust

from .exact import delaunay_problems

FUNCTIONS = [wdm_crust.triangulate, wdm_crust.voronoi, wdm_crust.reconstruct]
POINTS = np.random.default_rng(2).random((300, 2))


def triangles_of(points):
    return wdm_crust.triangulate(points).triangles.tolist()


@pytest.mark.parametrize("function", FUNCTIONS, ids=lambda f: f.__name__)
@pytest.mark.parametrize(
    "value,message",
    [
        (np.nan, "coordinate NaN is not a finite number"),
        (np.inf, "coordinate inf is not a finite number"),
        (-np.inf, "coordinate -inf is not a finite number"),
    ],
)
@pytest.mark.parametrize("index,axis", [(0, 0), (57, 1), (299, 0)])
def test_invalid_coordinates_raise_value_error_naming_the_point(function, value, message, index, axis):
    points = POINTS.copy()
    points[index, axis] = value
    with pytest.raises(ValueError, match=f"^point {index}: {message}"):
        function(points)


@pytest.mark.parametrize("value", [1e-300, -1e100, 1e300, 5e-324])
def test_extreme_magnitudes_are_exact_or_refused_naming_the_point(value):
    """Tiny, huge and subnormal coordinates: refused with the point's index where the
    engine's exact predicates do not reach them, else triangulated exactly."""
    points = POINTS[:60] * value
    points[0] = (0.0, 0.0)
    try:
        triangles = wdm_crust.triangulate(points).triangles
    except ValueError as error:
        first_nonzero = int(np.flatnonzero(np.any(points != 0.0, axis=1))[0])
        assert str(error).startswith(f"point {first_nonzero}: coordinate ")
    else:
        assert delaunay_problems(points, triangles) == []


def test_the_first_invalid_point_is_named():
    points = POINTS.copy()
    points[[40, 12, 200], 1] = np.nan
    with pytest.raises(ValueError, match="^point 12: "):
        wdm_crust.triangulate(points)


@pytest.mark.parametrize(
    "points,shape",
    [
        (np.zeros((5, 3)), r"\(5, 3\)"),
        (np.zeros(8), r"\(8,\)"),
        (np.zeros((4, 2, 1)), r"\(4, 2, 1\)"),
        (np.zeros(()), r"\(\)"),
        ([1.0, 2.0], r"\(2,\) \(for a single point, pass \[\[x, y\]\]\)"),
    ],
)
@pytest.mark.parametrize("function", FUNCTIONS, ids=lambda f: f.__name__)
def test_wrong_shapes_raise_value_error(function, points, shape):
    with pytest.raises(ValueError, match=rf"points must be an \(n, 2\) array.*got shape {shape}$"):
        function(points)


def test_ragged_lists_raise_value_error():
    with pytest.raises(ValueError):
        wdm_crust.triangulate([[0.0, 0.0], [1.0]])


@pytest.mark.parametrize(
    "points",
    [
        [["0", "1"], ["2", "3"], ["4", "0"]],
        np.zeros((3, 2), dtype=complex),
        np.zeros((3, 2), dtype=bool),
        [[Fraction(1, 3), 0], [1, 0], [0, 1]],
        [[None, 0.0], [1.0, 0.0], [0.0, 1.0]],
    ],
    ids=["strings", "complex", "bool", "fractions", "none"],
)
def test_non_numbers_raise_type_error(points):
    with pytest.raises(TypeError, match="points must be real numbers, got an array of dtype"):
        wdm_crust.triangulate(points)


def test_float32_lists_and_integers_are_accepted():
    as_float32 = POINTS.astype(np.float32)
    assert triangles_of(as_float32) == triangles_of(as_float32.astype(np.float64))
    assert triangles_of(POINTS.tolist()) == triangles_of(POINTS)
    assert triangles_of(tuple(map(tuple, POINTS.tolist()))) == triangles_of(POINTS)
    grid = np.array([(x, y) for x in range(6) for y in range(5)])
    assert grid.dtype.kind == "i"
    assert triangles_of(grid) == triangles_of(grid.astype(float))
    assert triangles_of(grid.astype(np.uint8)) == triangles_of(grid.astype(float))


def test_layouts_other_than_c_order_give_the_same_result():
    expected = triangles_of(POINTS)
    fortran = np.asfortranarray(POINTS)
    assert not fortran.flags.c_contiguous
    assert triangles_of(fortran) == expected
    big_endian = POINTS.astype(">f8")
    assert triangles_of(big_endian) == expected
    strided = np.zeros((300, 4))
    strided[:, ::2] = POINTS
    assert triangles_of(strided[:, ::2]) == expected
    every_other = POINTS[::2]
    assert triangles_of(every_other) == triangles_of(np.ascontiguousarray(every_other))


def test_the_callers_array_is_left_as_it_was():
    points = POINTS.copy()
    wdm_crust.reconstruct(points)
    assert np.array_equal(points, POINTS)
    assert points.flags.writeable


def numpy_bytes_allocated_during(call):
    """Peak bytes numpy (and Python) allocate while `call` runs: numpy reports its buffers
    to tracemalloc; the engine's own Rust allocations are not counted."""
    tracemalloc.start()
    try:
        call()
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def test_float64_c_contiguous_arrays_are_read_without_a_copy():
    points = np.random.default_rng(9).random((200_000, 2))
    copy_bytes = points.nbytes  # 3.2 MB
    as_float32 = points.astype(np.float32)
    # The measurement sees a conversion when there is one...
    assert numpy_bytes_allocated_during(lambda: wdm_crust.triangulate(as_float32)) >= copy_bytes
    # ...and the float64 array itself is never copied.
    assert numpy_bytes_allocated_during(lambda: wdm_crust.triangulate(points)) < copy_bytes / 4


def test_the_gil_is_released_while_the_engine_runs():
    """A Python thread keeps running while another triangulates: the longest pause it sees is
    far shorter than the triangulation (holding the GIL would pause it for all of it)."""
    points = np.random.default_rng(10).random((1_000_000, 2))
    start = time.perf_counter()
    wdm_crust.triangulate(points)
    alone = time.perf_counter() - start

    worker = threading.Thread(target=wdm_crust.triangulate, args=(points,))
    stamps = []
    worker.start()
    while worker.is_alive():
        stamps.append(time.perf_counter())
    worker.join()
    longest_pause = max(np.diff(stamps), default=0.0)
    assert len(stamps) > 1000
    assert longest_pause < alone / 3, (longest_pause, alone)


def test_reconstruct_options_are_checked():
    with pytest.raises(ValueError, match="algorithm must be one of 'wdm', 'crust', 'nn-crust', got 'nn_crust'"):
        wdm_crust.reconstruct(POINTS, algorithm="nn_crust")
    with pytest.raises(ValueError, match="medial_axis must be one of 'pruned', 'raw', 'none', got 'full'"):
        wdm_crust.reconstruct(POINTS, medial_axis="full")
    with pytest.raises(ValueError, match="peeling_budget must be a non-negative integer, got -1"):
        wdm_crust.reconstruct(POINTS, peeling_budget=-1)
    with pytest.raises(TypeError):
        wdm_crust.reconstruct(POINTS, "crust")  # options are keyword-only
    with pytest.raises(TypeError):
        wdm_crust.reconstruct(POINTS, algorithm=1)


@pytest.mark.parametrize("algorithm", ["crust", "nn-crust"])
@pytest.mark.parametrize(
    "options,message",
    [
        ({"medial_axis": "raw"}, "medial_axis='raw' does not apply to algorithm='{a}': {a} computes no medial axis"),
        ({"medial_axis": "pruned"}, "medial_axis='pruned' does not apply to algorithm='{a}': {a} computes no medial axis"),
        ({"peeling": True}, "peeling=True does not apply to algorithm='{a}': {a} runs one pass and has no peeling"),
        ({"peeling_budget": 4}, "peeling_budget does not apply to algorithm='{a}': {a} runs one pass and has no peeling"),
        ({"peeling": False, "peeling_budget": 0}, "peeling_budget does not apply to algorithm='{a}'"),
    ],
    ids=repr,
)
def test_options_that_do_not_apply_to_a_baseline_raise_value_error(algorithm, options, message):
    expected = "^" + re.escape(message.format(a=algorithm)) + ".*; leave it out, or use algorithm='wdm'$"
    with pytest.raises(ValueError, match=expected):
        wdm_crust.reconstruct(POINTS, algorithm=algorithm, **options)


@pytest.mark.parametrize("algorithm", ["crust", "nn-crust"])
def test_options_that_ask_a_baseline_for_nothing_are_accepted(algorithm):
    plain = wdm_crust.reconstruct(POINTS, algorithm=algorithm)
    for options in [{"medial_axis": "none"}, {"peeling": False}, {"medial_axis": None, "peeling": None}]:
        rec = wdm_crust.reconstruct(POINTS, algorithm=algorithm, **options)
        assert rec.edges.tolist() == plain.edges.tolist()
        assert [c.points.tolist() for c in rec.curves] == [c.points.tolist() for c in plain.curves]


def test_explicit_defaults_give_the_default_reconstruction():
    default = wdm_crust.reconstruct(POINTS)
    explicit = wdm_crust.reconstruct(POINTS, algorithm="wdm", peeling=True, medial_axis="pruned", peeling_budget=4)
    assert explicit.edges.tolist() == default.edges.tolist()
    assert [c.points.tolist() for c in explicit.curves] == [c.points.tolist() for c in default.curves]
    assert explicit.medial_axis[0].tolist() == default.medial_axis[0].tolist()
    assert explicit.medial_axis[1].tolist() == default.medial_axis[1].tolist()
    with pytest.raises(
        ValueError,
        match="^peeling_budget does not apply with peeling=False: peeling is off, so there is no "
        "peeling for the budget to bound; leave one of them out$",
    ):
        wdm_crust.reconstruct(POINTS, peeling=False, peeling_budget=2)


def test_results_describe_themselves():
    tri = wdm_crust.triangulate([[0, 0], [1, 0], [0, 1], [0, 0]])
    assert repr(tri) == "Triangulation(point_count=4, triangles=1, hull=3, duplicates=1)"
    assert repr(tri.voronoi()) == "Voronoi(vertices=1, edges=0, rays=3, cells=4)"
    rec = wdm_crust.reconstruct([[0, 0], [1, 0], [0, 1]])
    assert repr(rec) == (
        "Reconstruction(algorithm='wdm', point_count=3, edges=3, closed_curves=1, "
        "open_chains=0, medial_axis_edges=0, unassigned=0, passes=1)"
    )
    assert repr(rec.curves[0]) == "Curve(closed=True, points=3)"
    assert repr(rec.triangulation) == "Triangulation(point_count=3, triangles=1, hull=3, duplicates=0)"


def test_the_type_stubs_cover_the_module():
    package = Path(wdm_crust.__file__).parent
    assert (package / "py.typed").is_file()
    stub = ast.parse((package / "__init__.pyi").read_text())
    stubbed = {
        node.name for node in stub.body if isinstance(node, (ast.FunctionDef, ast.ClassDef))
    } | {
        node.target.id
        for node in stub.body
        if isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name)
    }
    assert stubbed == set(wdm_crust.__all__)
    for name in wdm_crust.__all__:
        assert hasattr(wdm_crust, name)
    assert wdm_crust.__version__ == "0.1.0"


def test_functions_and_classes_are_documented():
    for name in wdm_crust.__all__:
        item = getattr(wdm_crust, name)
        if callable(item):
            assert item.__doc__ and len(item.__doc__) > 40, name
