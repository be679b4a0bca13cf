"""Point sets on which floating-point Delaunay triangulations go wrong, built
deterministically: each is the float64 values as given, and the exact answer is defined on
exactly those values."""

import math

import numpy as np


def near_collinear():
    """Kettner et al.'s classic: a 16 × 16 grid of points 1 ulp apart near (0.5, 0.5) and
    two far points on the diagonal, so that orientations are decided by the last bit."""
    ulp = 2.0 ** -53
    grid = [(0.5 + i * ulp, 0.5 + j * ulp) for i in range(16) for j in range(16)]
    return np.array(grid + [(12.0, 12.0), (24.0, 24.0), (0.0, 0.0)])


def ulp_spaced():
    """Points on a line y = x + c in float64 (so off it by rounding), a few ulps apart,
    plus two points off the line."""
    x = 1.0
    points = []
    for _ in range(200):
        points.append((x, x * 3.0 + 0.1))
        x = np.nextafter(x, 2.0)
    return np.array(points + [(0.0, 0.0), (2.0, 0.0)])


def huge(scale):
    """Random points times `scale`, and the same points' neighbours 1 ulp away."""
    rng = np.random.default_rng(7)
    base = rng.random((200, 2)) * scale
    return np.vstack([base, np.nextafter(base, np.inf)])


def tiny_clusters():
    """Ten clusters of 30 points each, 1e-12 across, on the unit square."""
    rng = np.random.default_rng(11)
    centers = rng.random((10, 2))
    return np.vstack([c + rng.random((30, 2)) * 1e-12 for c in centers])


def circle_by_trigonometry(n=1000):
    """n points on the unit circle by cos/sin: rounded, so nearly but not exactly
    cocircular, and every in-circle test among them is decided by the last bits."""
    t = 2.0 * math.pi * np.arange(n) / n
    return np.c_[np.cos(t), np.sin(t)]


def exact_grid_circle():
    """The lattice points on a circle of radius 65 (exactly cocircular: 36 of them), and
    the centre: the triangulation must be one of the many valid ones."""
    r = 65
    points = [(x, y) for x in range(-r, r + 1) for y in range(-r, r + 1) if x * x + y * y == r * r]
    return np.array(points + [(0, 0)], dtype=float)


# name -> points; the test ids.
CASES = {
    "near-collinear (ulp grid)": near_collinear,
    "ulp-spaced along a line": ulp_spaced,
    "huge coordinates (1e60)": lambda: huge(1e60),
    "1e-12 clusters": tiny_clusters,
    "circle by cos/sin": circle_by_trigonometry,
    "exactly cocircular lattice": exact_grid_circle,
    "uniform random": lambda: np.random.default_rng(3).random((2000, 2)),
}
