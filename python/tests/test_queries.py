"""`tri.locate(queries)` and `tri.nearest(queries)` against brute force in exact rational
arithmetic: the triangle returned holds the query (closed triangle, exact orientation), -1
exactly when no triangle does; the point returned is at the least exact distance."""

import threading
from fractions import Fraction

import numpy as np
import pytest

import wdm_crust
from .exact import convex_hull, orient, rational_points
from .real_files import real_point_files
from .samples import SAMPLES


def exact(p):
    return (Fraction(float(p[0])), Fraction(float(p[1])))


def in_closed_triangle(points, triangle, q):
    a, b, c = (exact(points[i]) for i in triangle)
    return all(orient(u, v, q) >= 0 for u, v in ((a, b), (b, c), (c, a)))


def queries_for(points, rng):
    """Random queries over the points' box and beyond, the points themselves, the midpoints
    of some point pairs (on Delaunay edges, often exactly) and far-away queries."""
    lo, hi = points.min(axis=0), points.max(axis=0)
    span = np.maximum(hi - lo, 1.0)
    random = lo - 0.2 * span + rng.random((300, 2)) * 1.4 * span
    pairs = rng.integers(0, len(points), (100, 2))
    midpoints = (points[pairs[:, 0]] + points[pairs[:, 1]]) / 2
    far = np.array([[lo[0] - 10 * span[0], lo[1]], [hi[0], hi[1] + 1e6 * span[1]]])
    return np.vstack([random, points[rng.integers(0, len(points), 60)], midpoints, far])


def check_locate(points, tri, queries):
    found = tri.locate(queries)
    assert found.dtype == np.int64 and found.shape == (len(queries),)
    triangles = tri.triangles
    rational = rational_points(points)
    hull = convex_hull(rational) if len(triangles) else []
    for q, t in zip(queries, found.tolist()):
        q = exact(q)
        if t >= 0:
            assert in_closed_triangle(points, triangles[t], q)
        else:
            # In no closed triangle: outside the exact convex hull (strictly right of one of
            # its counterclockwise edges), which the triangles cover.
            edges = zip(hull, hull[1:] + hull[:1])
            assert not hull or any(orient(rational[a], rational[b], q) < 0 for a, b in edges)


def check_nearest(points, tri, queries):
    found = tri.nearest(queries)
    assert found.dtype == np.int64 and found.shape == (len(queries),)
    duplicate = dict(tri.duplicates.tolist())
    for q, p in zip(queries, found.tolist()):
        assert p not in duplicate  # the first occurrence of repeated coordinates
        # Exact distances for every point that float64 finds about as near as the nearest.
        d = ((points - q) ** 2).sum(axis=1)
        candidates = np.flatnonzero(d <= d.min() * (1 + 1e-6) + 1e-300).tolist()
        q = exact(q)
        exact_d = {i: (exact(points[i])[0] - q[0]) ** 2 + (exact(points[i])[1] - q[1]) ** 2 for i in candidates + [p]}
        assert exact_d[p] == min(exact_d.values())


CASES = {
    **{name: make for name, make in SAMPLES.items() if name != "no points"},
    "real: fitconnect/data/bot.txt": lambda: wdm_crust.read_points(
        next(p for n, p in real_point_files() if n.endswith("bot.txt"))
    ),
}


@pytest.mark.parametrize("name", list(CASES))
def test_locate_and_nearest_against_brute_force(name):
    points = np.asarray(CASES[name](), dtype=float)
    tri = wdm_crust.triangulate(points)
    queries = queries_for(points, np.random.default_rng(len(name)))
    check_locate(points, tri, queries)
    check_nearest(points, tri, queries)


def test_queries_on_the_edges_and_vertices_of_a_lattice():
    """A grid of cocircular squares: half-integer queries lie exactly on edges, integer ones
    on vertices, and every Delaunay diagonal's midpoint is a square's centre."""
    points = SAMPLES["lattice"]()
    tri = wdm_crust.triangulate(points)
    g = np.arange(-1.0, 9.5, 0.5)
    queries = np.array([(x, y) for x in g for y in g])
    check_locate(points, tri, queries)
    check_nearest(points, tri, queries)
    inside = (queries >= 0).all(axis=1) & (queries <= 8).all(axis=1)
    assert ((tri.locate(queries) >= 0) == inside).all()


def test_many_queries_and_threads_give_the_same_answers():
    points = np.random.default_rng(3).random((5000, 2))
    tri = wdm_crust.triangulate(points)
    queries = np.random.default_rng(4).random((20000, 2)) * 1.2 - 0.1
    located = tri.locate(queries)
    assert (tri.locate(queries, threads=1) == located).all()
    assert (tri.locate(queries, threads=2) == located).all()
    nearest = tri.nearest(queries)
    assert (tri.nearest(queries, threads=1) == nearest).all()
    sample = np.random.default_rng(5).choice(len(queries), 300, replace=False)
    check_nearest(points, tri, queries[sample])
    check_locate(points, tri, queries[sample])


def test_the_gil_is_released_during_queries():
    points = np.random.default_rng(6).random((20000, 2))
    tri = wdm_crust.triangulate(points)
    queries = np.random.default_rng(7).random((400000, 2))
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(1)

    thread = threading.Thread(target=tick)
    thread.start()
    try:
        before = len(ticks)
        tri.locate(queries, threads=1)
        during = len(ticks) - before
    finally:
        done.set()
        thread.join()
    assert during > 100


def test_degenerate_and_empty_triangulations():
    collinear = SAMPLES["collinear"]()
    tri = wdm_crust.triangulate(collinear)
    queries = np.vstack([collinear, [[5.0, 5.0], [0.45, 0.35]]])
    assert (tri.locate(queries) == -1).all()
    check_nearest(collinear, tri, queries)
    empty = wdm_crust.triangulate(np.zeros((0, 2)))
    assert empty.locate([[0.0, 0.0]]).tolist() == [-1]
    assert empty.nearest([[0.0, 0.0]]).tolist() == [-1]
    assert tri.locate(np.zeros((0, 2))).shape == (0,)


def test_bad_queries_are_refused():
    tri = wdm_crust.triangulate(SAMPLES["lattice"]())
    with pytest.raises(ValueError, match=r"^query 2: coordinate NaN is not a finite number$"):
        tri.locate([[0, 0], [1, 1], [np.nan, 0]])
    with pytest.raises(ValueError, match=r"^query 0: coordinate inf "):
        tri.nearest([[np.inf, 0]])
    with pytest.raises(ValueError, match=r"^queries must be an \(n, 2\) array"):
        tri.locate([0.5, 0.5])
    with pytest.raises(TypeError, match="^queries must be real numbers"):
        tri.nearest([["a", "b"]])
    with pytest.raises(ValueError, match="^threads must be"):
        tri.locate([[0, 0]], threads=0)
    # Other dtypes and layouts are converted, as points are.
    q = np.array([[1, 2], [3, 4]], dtype=np.int32)
    assert (tri.nearest(q) == tri.nearest(q.astype(float))).all()
    assert (tri.locate(np.asfortranarray(q.astype(float))) == tri.locate(q)).all()
