"""Exact 2D Delaunay triangulation, Voronoi diagram, curve reconstruction (WDM_CRUST) and
medial axis for numpy arrays of points.

Points are any (n, 2) array-like of real numbers: a C-contiguous float64 array is read in
place (no copy); other float or integer arrays, and lists, are converted to float64 first.
Every index in a result is a row of that array; index arrays are int64.
"""

import os
from typing import Any, Dict, List, Literal, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

_Points = npt.ArrayLike
"""An (n, 2) array-like of real numbers."""
_Point = Union[Sequence[float], npt.NDArray[np.floating]]
"""One point (x, y)."""
_IndexArray = npt.NDArray[np.int64]
_FloatArray = npt.NDArray[np.float64]
_Box = Tuple[float, float, float, float]
"""(xmin, ymin, xmax, ymax)."""
_Layer = Literal["delaunay", "voronoi", "labels"]

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
    @property
    def points(self) -> _FloatArray:
        """(n, 2) float64: the input points, duplicates included (a copy)."""
    def voronoi(self) -> Voronoi:
        """The Voronoi diagram, the dual of this triangulation (no new triangulation)."""
    def locate(self, queries: _Points, *, threads: Optional[int] = None) -> _IndexArray:
        """(m,) int64: for each (m, 2) query, the row of `triangles` whose closed triangle
        holds it (one of those around it on an edge or a vertex), -1 outside the convex hull
        or when there are no triangles. Exact; the GIL is released. ValueError for a NaN or
        infinite query, naming it."""
    def nearest(self, queries: _Points, *, threads: Optional[int] = None) -> _IndexArray:
        """(m,) int64: for each (m, 2) query, an input point at the least distance (compared
        exactly; the first occurrence of duplicated coordinates), -1 when there are no
        points. The GIL is released."""

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
    def clipped_cells(self, bbox: Optional[_Box] = None) -> List[_FloatArray]:
        """list of n (k, 2) float64 rings, one per input point: its cell clipped to the box
        (default: the points' bounding box enlarged by 10 % of its larger side on every
        side), counterclockwise, not closed; empty for a duplicate and for a cell that meets
        the box in no area. The cells of the distinct points tile the box."""
    def to_geojson(self, bbox: Optional[_Box] = None) -> str:
        """The clipped cells as GeoJSON, the text of `wdm-crust voronoi --format geojson`
        (with `--clip` for a bbox)."""

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

class Polygon:
    """Closed curves nested into a polygon: an exterior ring and its holes."""

    @property
    def exterior(self) -> _FloatArray:
        """(k, 2) float64: the outer ring, counterclockwise, not closed."""
    @property
    def holes(self) -> List[_FloatArray]:
        """(k, 2) float64 rings of the holes, clockwise, not closed."""
    @property
    def exterior_points(self) -> _IndexArray:
        """(k,) int64: the point indices of the outer ring."""
    @property
    def hole_points(self) -> List[_IndexArray]:
        """(k,) int64 point indices of each hole."""
    @property
    def __geo_interface__(self) -> Dict[str, Any]:
        """The GeoJSON Polygon geometry, rings closed."""

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
    def thinned(self) -> Optional[int]:
        """With a dense noisy band thinned: the number of representatives (the JSON's "thinned")."""
    @property
    def peeling_budget_exhausted(self) -> bool:
        """True when peeling stopped at its budget."""
    @property
    def point_count(self) -> int:
        """The number of input points, duplicates included."""
    @property
    def points(self) -> _FloatArray:
        """(n, 2) float64: the input points, duplicates included (a copy)."""
    @property
    def triangulation(self) -> Triangulation:
        """The Delaunay triangulation of all the points, built on first use."""
    @property
    def __geo_interface__(self) -> Dict[str, Any]:
        """The command line's GeoJSON FeatureCollection, as a dict."""
    def polygons(self) -> List[Polygon]:
        """The closed curves nested into polygons with holes, as the GeoJSON's polygons."""
    def to_geojson(self) -> str:
        """The text of `wdm-crust reconstruct --format geojson` with the same options."""
    def to_svg(
        self, *, y_down: bool = False, show: Sequence[_Layer] = (), no_points: bool = False
    ) -> str:
        """The SVG picture of `wdm-crust reconstruct --format svg` (--y-down, --show,
        --no-points)."""

def triangulate(points: _Points, *, threads: Optional[int] = None) -> Triangulation:
    """The exact Delaunay triangulation of `points`.

    Raises ValueError for a coordinate the engine refuses (NaN, infinite, or outside the
    range its exact predicates support), naming the point's index, and for a shape other
    than (n, 2); TypeError for points that are not real numbers. The GIL is released while the engine runs.
    """

def voronoi(points: _Points, *, threads: Optional[int] = None) -> Voronoi:
    """The Voronoi diagram of `points`, the dual of their exact Delaunay triangulation."""

def reconstruct(
    points: _Points,
    *,
    algorithm: Literal["wdm", "crust", "nn-crust"] = "wdm",
    peeling: Optional[bool] = None,
    medial_axis: Optional[Literal["pruned", "raw", "none"]] = None,
    peeling_budget: Optional[int] = None,
    smooth: bool = False,
    thinning: bool = True,
    threads: Optional[int] = None,
) -> Reconstruction:
    """Reconstructs the curves the points were sampled from, and their medial axis.

    None keeps the engine's default: for WDM, peeling on, the pruned medial axis, a peeling
    budget of 4. The WDM options that ask a baseline ('crust', 'nn-crust') for what it does
    not do raise ValueError saying why: medial_axis='pruned' or 'raw', peeling=True, any
    peeling_budget; medial_axis='none' and peeling=False are accepted with every algorithm.
    A peeling_budget with peeling=False raises ValueError too. smooth=True fits the curves
    to the samples (--smooth); thinning=False reconstructs a dense noisy band as it is
    (--no-thinning); threads is --threads (None: all cores).
    """

def read_points(
    path: Union[str, os.PathLike[str]],
    columns: Optional[Union[str, Tuple[Union[str, int], Union[str, int]]]] = None,
) -> _FloatArray:
    """(n, 2) float64: the points of a point file, read by the command line's parser (plain
    text, CSV, .node/.gtn); columns is --columns ("X,Y" or a pair, names or 1-based
    positions). ValueError "<path>:<line>: <problem>" for a bad file; OSError subclasses
    when it cannot be opened."""

def plot(
    rec: Reconstruction,
    ax: Optional[Any] = None,
    *,
    points: bool = True,
    medial_axis: bool = True,
    legend: bool = True,
) -> Any:
    """Draws rec with matplotlib (points, closed curves, open chains, points on no curve,
    medial axis) on ax, or a new figure's Axes; returns the Axes. ImportError naming
    `pip install matplotlib` without matplotlib."""

def orient2d(a: _Point, b: _Point, c: _Point) -> Literal[-1, 0, 1]:
    """Exact orientation of a → b → c: +1 counterclockwise, -1 clockwise, 0 collinear."""

def incircle(a: _Point, b: _Point, c: _Point, d: _Point) -> Literal[-1, 0, 1]:
    """Exact position of d against the circle through a, b, c (counterclockwise):
    +1 inside, 0 on, -1 outside."""
