"""Exact 2D Delaunay triangulation, Voronoi diagram, curve reconstruction (WDM_CRUST) and
medial axis for numpy arrays of points.

Points are any (n, 2) array-like of real numbers: a C-contiguous float64 array is read in
place (no copy); other float or integer arrays, and lists, are converted to float64 first.
Every index in a result is a row of that array; index arrays are int64.
"""

from typing import List, Literal, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

_Points = npt.ArrayLike
"""An (n, 2) array-like of real numbers."""
_Point = Union[Sequence[float], npt.NDArray[np.floating]]
"""One point (x, y)."""
_IndexArray = npt.NDArray[np.int64]
_FloatArray = npt.NDArray[np.float64]

class Triangulation:
    """The exact Delaunay triangulation of a point set (see `triangulate`)."""

    @property
    def triangles(self) -> _IndexArray:
        """(m, 3) int64: the triangles, counterclockwise index triples."""
    @property
    def hull(self) -> _IndexArray:
        """(h,) int64: the convex hull, counterclockwise (collinear input: along the line)."""
    @property
    def duplicates(self) -> _IndexArray:
        """(k, 2) int64: [duplicate, kept] pairs, kept being the first occurrence."""
    @property
    def point_count(self) -> int:
        """The number of input points, duplicates included."""
    def voronoi(self) -> Voronoi:
        """The Voronoi diagram, the dual of this triangulation (no new triangulation)."""

class Voronoi:
    """The Voronoi diagram of a point set (see `voronoi`)."""

    @property
    def vertices(self) -> _FloatArray:
        """(v, 2) float64: the Voronoi vertices (merged-face circumcenters)."""
    @property
    def edges(self) -> _IndexArray:
        """(e, 2) int64: the finite edges, as pairs of vertex indices."""
    @property
    def rays(self) -> _FloatArray:
        """(r, 3) float64: the rays, rows [a, dx, dy] from vertex a along (dx, dy)."""
    @property
    def cells(self) -> List[_IndexArray]:
        """list of n int64 arrays: the vertices of each point's cell, counterclockwise."""

class Curve:
    """One reconstructed curve: a closed loop or an open chain."""

    @property
    def closed(self) -> bool:
        """True for a closed loop, False for an open chain."""
    @property
    def points(self) -> _IndexArray:
        """(k,) int64: the point indices along the curve."""
    @property
    def coords(self) -> _FloatArray:
        """(k, 2) float64: the coordinates of the points along the curve."""
    def __len__(self) -> int: ...

class Reconstruction:
    """The result of `reconstruct`."""

    @property
    def algorithm(self) -> Literal["wdm", "crust", "nn-crust"]:
        """The algorithm that ran."""
    @property
    def edges(self) -> _IndexArray:
        """(e, 2) int64: the reconstructed edges [i, j], i < j, sorted."""
    @property
    def curves(self) -> List[Curve]:
        """Closed loops and open chains assembled from the edges."""
    @property
    def medial_axis(self) -> Tuple[_FloatArray, _IndexArray]:
        """(vertices (v, 2) float64, edges (s, 2) int64): the medial axis (WDM only; empty
        with medial_axis="none")."""
    @property
    def unassigned(self) -> _IndexArray:
        """(u,) int64: the distinct points on no curve, sorted."""
    @property
    def duplicates(self) -> _IndexArray:
        """(k, 2) int64 rows [duplicate, kept], as the triangulation's."""
    @property
    def warnings(self) -> List[Tuple[str, str]]:
        """(code, message) pairs: the signs that the result is probably not what was
        wanted, as the command line's JSON "warnings"; empty when there is nothing to say."""
    @property
    def passes(self) -> int:
        """How many passes ran (more than one when peeling found nested curves)."""
    @property
    def peeling_budget_exhausted(self) -> bool:
        """True when peeling stopped at its budget."""
    @property
    def point_count(self) -> int:
        """The number of input points, duplicates included."""
    @property
    def triangulation(self) -> Triangulation:
        """The Delaunay triangulation of all the points, built on first use."""

def triangulate(points: _Points) -> Triangulation:
    """The exact Delaunay triangulation of `points`.

    Raises ValueError for a coordinate the engine refuses (NaN, infinite, or outside the
    range its exact predicates support), naming the point's index, and for a shape other
    than (n, 2); TypeError for points that are not real numbers. The GIL is released while the engine runs.
    """

def voronoi(points: _Points) -> Voronoi:
    """The Voronoi diagram of `points`, the dual of their exact Delaunay triangulation."""

def reconstruct(
    points: _Points,
    *,
    algorithm: Literal["wdm", "crust", "nn-crust"] = "wdm",
    peeling: Optional[bool] = None,
    medial_axis: Optional[Literal["pruned", "raw", "none"]] = None,
    peeling_budget: Optional[int] = None,
    smooth: bool = False,
) -> Reconstruction:
    """Reconstructs the curves the points were sampled from, and their medial axis.

    None keeps the engine's default: for WDM, peeling on, the pruned medial axis, a peeling
    budget of 4. The WDM options that ask a baseline ('crust', 'nn-crust') for what it does
    not do raise ValueError saying why: medial_axis='pruned' or 'raw', peeling=True, any
    peeling_budget; medial_axis='none' and peeling=False are accepted with every algorithm.
    A peeling_budget with peeling=False raises ValueError too.
    """

def orient2d(a: _Point, b: _Point, c: _Point) -> Literal[-1, 0, 1]:
    """Exact orientation of a → b → c: +1 counterclockwise, -1 clockwise, 0 collinear."""

def incircle(a: _Point, b: _Point, c: _Point, d: _Point) -> Literal[-1, 0, 1]:
    """Exact position of d against the circle through a, b, c (counterclockwise):
    +1 inside, 0 on, -1 outside."""
