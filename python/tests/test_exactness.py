"""wdm_crust.triangulate is the exact Delaunay triangulation on inputs where floating-point
triangulations fail, checked in rational arithmetic. scipy.spatial.Delaunay runs on the same
points and its verdict is shown in the terminal summary, never asserted."""

import numpy as np
import pytest
import scipy.spatial

import wdm_crust
from .adversarial import CASES, huge
from .exact import convex_hull, delaunay_problems, orient, rational_points
from .scipy_report import VERDICTS


def counterclockwise(points, triangles):
    """scipy's triangles, each turned counterclockwise (scipy does not orient them)."""
    exact = rational_points(points)
    return [
        (a, b, c) if orient(exact[a], exact[b], exact[c]) >= 0 else (a, c, b)
        for a, b, c in triangles
    ]


def scipy_verdict(points):
    try:
        simplices = scipy.spatial.Delaunay(points).simplices
    except Exception as error:  # Qhull refuses some inputs outright
        return f"raised {type(error).__name__}: {str(error).splitlines()[0][:60]}"
    problems = delaunay_problems(points, counterclockwise(points, simplices))
    if not problems:
        return "exact Delaunay"
    return f"{len(problems)} problems, e.g. {problems[0]}"


def cyclic_edges(cycle):
    return {(cycle[k], cycle[(k + 1) % len(cycle)]) for k in range(len(cycle))}


@pytest.mark.parametrize("name", list(CASES))
def test_triangulation_is_exactly_delaunay(name):
    points = CASES[name]()
    tri = wdm_crust.triangulate(points)
    assert tri.triangles.shape[1:] == (3,) and len(tri.triangles) > 0
    assert delaunay_problems(points, tri.triangles) == []
    # The hull is the exact convex hull, every point on its boundary included.
    hull = [int(i) for i in tri.hull]
    assert cyclic_edges(hull) == cyclic_edges(convex_hull(rational_points(points)))
    VERDICTS.append((name, scipy_verdict(points)))


def test_the_checker_catches_a_non_delaunay_triangulation():
    # The square's two triangulations: a point inside the circumcircle makes one invalid.
    points = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.5]])
    good = wdm_crust.triangulate(points).triangles
    assert delaunay_problems(points, good) == []
    flipped = [(0, 1, 3), (1, 2, 3)] if {0, 2} <= set(good[0]) else [(0, 1, 2), (0, 2, 3)]
    assert any("locally Delaunay" in p for p in delaunay_problems(points, flipped))
    assert delaunay_problems(points, flipped[:1]) != []  # no longer covers the hull


def test_huge_coordinates_are_exact_or_refused_naming_the_point():
    """1e200: an engine whose exact predicates stop at 2^201 refuses it, naming the first
    point; one that accepts it must triangulate it exactly."""
    points = huge(1e200)
    try:
        triangles = wdm_crust.triangulate(points).triangles
    except ValueError as error:
        assert str(error).startswith("point 0: coordinate 6.250954666046669e199 ")
    else:
        assert delaunay_problems(points, triangles) == []
    VERDICTS.append(("huge coordinates (1e200)", scipy_verdict(points)))


def test_collinear_input_has_no_triangle_and_the_line_as_hull():
    ulp = 2.0 ** -52
    points = np.array([[1.0 + k * ulp, 2.0 + 2 * k * ulp] for k in (5, 0, 3, 1, 4, 2)])
    tri = wdm_crust.triangulate(points)
    assert tri.triangles.shape == (0, 3)
    assert tri.hull.tolist() in ([1, 3, 5, 2, 4, 0], [0, 4, 2, 5, 3, 1])
