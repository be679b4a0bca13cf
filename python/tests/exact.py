"""An exact reference in rational arithmetic (fractions.Fraction): orientation, in-circle,
convex hull, and a checker that a triangulation is the Delaunay triangulation of every
distinct point and covers the convex hull."""

from fractions import Fraction


def sign(value):
    return (value > 0) - (value < 0)


def orient(a, b, c):
    """Sign of the orientation determinant of a → b → c (+1 counterclockwise)."""
    (ax, ay), (bx, by), (cx, cy) = a, b, c
    return sign((ax - cx) * (by - cy) - (ay - cy) * (bx - cx))


def incircle(a, b, c, d):
    """Sign of the in-circle determinant (+1: d inside the circle of counterclockwise a, b, c)."""
    rows = []
    for (px, py) in (a, b, c):
        dx, dy = px - d[0], py - d[1]
        rows.append((dx, dy, dx * dx + dy * dy))
    (a0, a1, a2), (b0, b1, b2), (c0, c1, c2) = rows
    det = a0 * (b1 * c2 - b2 * c1) - a1 * (b0 * c2 - b2 * c0) + a2 * (b0 * c1 - b1 * c0)
    return sign(det)


def rational_points(points):
    """Each float64 coordinate as the exact rational it is."""
    return [(Fraction(float(x)), Fraction(float(y))) for x, y in points]


def convex_hull(points):
    """Indices of the exact convex hull counterclockwise, every point on its boundary
    included (Andrew's monotone chain with exact orientation). Duplicates are left out."""
    order = sorted(set(range(len(points))), key=lambda i: points[i])
    distinct = []
    for i in order:
        if not distinct or points[distinct[-1]] != points[i]:
            distinct.append(i)
    if len(distinct) < 3:
        return distinct

    def chain(indices):
        out = []
        for i in indices:
            # Pop only on a right turn: collinear boundary points stay.
            while len(out) >= 2 and orient(points[out[-2]], points[out[-1]], points[i]) < 0:
                out.pop()
            out.append(i)
        return out

    lower = chain(distinct)
    upper = chain(reversed(distinct))
    if len(lower) == len(distinct) and all(
        orient(points[distinct[0]], points[distinct[-1]], points[i]) == 0 for i in distinct
    ):
        return distinct  # all collinear: the points along the line
    return lower[:-1] + upper[:-1]


def twice_area(points, polygon):
    total = Fraction(0)
    for k, i in enumerate(polygon):
        j = polygon[(k + 1) % len(polygon)]
        total += points[i][0] * points[j][1] - points[j][0] * points[i][1]
    return total


def delaunay_problems(float_points, triangles):
    """What is wrong with `triangles` as the Delaunay triangulation of `float_points`, in
    exact arithmetic: an empty list when it is one. Checks that every triangle is strictly
    counterclockwise, every edge has at most one triangle on each side, the edges with one
    triangle are exactly the convex hull's, the triangles' area is the hull's (so they tile
    it), every distinct point is a corner, and every interior edge is locally Delaunay
    (which, for a triangulation, makes it globally Delaunay)."""
    points = rational_points(float_points)
    problems = []
    triangles = [tuple(int(i) for i in t) for t in triangles]
    for t in triangles:
        if orient(*(points[i] for i in t)) <= 0:
            problems.append(f"triangle {t} is not counterclockwise")
    directed = {}
    for t in triangles:
        for k in range(3):
            edge = (t[k], t[(k + 1) % 3])
            if edge in directed:
                problems.append(f"edge {edge} is in two triangles on the same side")
            directed[edge] = t[(k + 2) % 3]
    boundary = {e for e in directed if (e[1], e[0]) not in directed}
    hull = convex_hull(points)
    hull_edges = {(hull[k], hull[(k + 1) % len(hull)]) for k in range(len(hull))}
    if len(hull) >= 3 and twice_area(points, hull) != 0:
        if boundary != hull_edges:
            problems.append(
                f"boundary edges are not the convex hull's: {len(boundary ^ hull_edges)} differ"
            )
        area = sum(twice_area(points, t) for t in triangles)
        if area != twice_area(points, hull):
            problems.append("the triangles do not cover the convex hull exactly")
        first = {}
        for i, p in enumerate(points):
            first.setdefault(p, i)
        corners = {i for t in triangles for i in t}
        missing = set(first.values()) - corners
        if missing:
            problems.append(f"{len(missing)} distinct points are in no triangle")
    for (a, b), c in directed.items():
        d = directed.get((b, a))
        if d is not None and incircle(points[a], points[b], points[c], points[d]) > 0:
            problems.append(f"edge {(a, b)} is not locally Delaunay")
    return problems
