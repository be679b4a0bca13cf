"""Point sets for comparing the package with the command line: each exercises a different
part of the output (duplicates, hull, merged Voronoi vertices, rays, holes, open chains,
unassigned points, collinear input)."""

import math

import numpy as np


def circle(n, radius=1.0, centre=(0.0, 0.0), start=0.0):
    t = start + 2.0 * math.pi * np.arange(n) / n
    return np.c_[centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t)]


def uniform_with_duplicates():
    points = np.random.default_rng(5).random((400, 2))
    return np.vstack([points, points[[3, 17, 3]], points[:2]])


def noisy_outline_with_outliers():
    rng = np.random.default_rng(8)
    t = np.sort(rng.random(300)) * 2.0 * math.pi
    r = 1.0 + 0.3 * np.cos(3 * t) + rng.normal(0.0, 0.004, t.size)
    outline = np.c_[r * np.cos(t), r * np.sin(t)]
    return np.vstack([outline, [[0.05, 0.02], [2.5, 2.5]]])


def nested_circles():
    """A ring with a hole: peeling finds the inner curve."""
    return np.vstack([circle(120), circle(60, radius=0.4, start=0.05)])


def open_arc():
    t = np.linspace(0.0, 2.5, 80)
    return np.c_[np.cos(t) * 3.0, np.sin(t) * 3.0]


def lattice():
    """A 9 × 9 integer grid: every Delaunay face is cocircular with a neighbour."""
    return np.array([(x, y) for x in range(9) for y in range(9)], dtype=float)


def collinear():
    return np.array([[k * 0.1, 0.5 - k * 0.2] for k in (4, 0, 7, 2, 9, 1)])


SAMPLES = {
    "uniform with duplicates": uniform_with_duplicates,
    "noisy outline with outliers": noisy_outline_with_outliers,
    "nested circles": nested_circles,
    "open arc": open_arc,
    "lattice": lattice,
    "collinear": collinear,
    "three points": lambda: np.array([[0.0, 0.0], [1.0, 0.0], [0.3, 0.8]]),
    "no points": lambda: np.zeros((0, 2)),
}
