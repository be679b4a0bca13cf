"""Exact 2D Delaunay triangulation, Voronoi diagram, curve reconstruction (WDM_CRUST) and
medial axis for numpy arrays of points.

Points are any (n, 2) array-like of real numbers: a C-contiguous float64 array is read in
place (no copy); other float or integer arrays, and lists, are converted to float64 first.
Every index in a result is a row of that array; index arrays are int64. Every
combinatorial decision is the one exact arithmetic on the float64 inputs makes.

The engine is the compiled extension `wdm_crust._native`; everything it defines is here,
with `plot` (matplotlib, an optional dependency) beside it.
"""

from . import _native
from ._native import *  # noqa: F401,F403  (the names of _native.__all__)
from ._plot import plot

__doc__ = __doc__
__all__ = [*_native.__all__, "plot"]
