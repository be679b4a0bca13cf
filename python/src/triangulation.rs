//! `wdm_crust.triangulate` and the `Triangulation` result.

use std::sync::Arc;

use numpy::{PyArray1, PyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;

use crate::arrays::{index_rows, indices, rows_array, vector};
use crate::errors::engine_error;
use crate::points::with_points;
use crate::voronoi::{Voronoi, VoronoiData};

/// Where the engine's triangulation lives: in the result itself, or in the reconstruction
/// it was taken from (no copy).
pub enum Source {
    Own(wdm_crust::Triangulation),
    Reconstruction(Arc<wdm_crust::Reconstruction>),
}

impl Source {
    fn get(&self) -> &wdm_crust::Triangulation {
        match self {
            Source::Own(tri) => tri,
            Source::Reconstruction(rec) => rec.triangulation(),
        }
    }
}

/// The arrays of a triangulation, computed without the GIL.
pub struct TriangulationData {
    triangles: Vec<[i64; 3]>,
    hull: Vec<i64>,
    duplicates: Vec<[i64; 2]>,
}

impl TriangulationData {
    /// The same data as the command line's JSON, in caller indices.
    pub fn of(tri: &wdm_crust::Triangulation) -> Self {
        TriangulationData {
            triangles: (0..tri.triangle_count())
                .map(|t| tri.triangle(t).map(i64::from))
                .collect(),
            hull: indices(tri.hull()),
            duplicates: index_rows(tri.duplicates()),
        }
    }
}

/// The exact Delaunay triangulation of a point set (see `wdm_crust.triangulate`).
///
/// Attributes:
///     triangles: (m, 3) int64, the triangles as counterclockwise index triples.
///     hull: (h,) int64, the convex hull counterclockwise, every point on its boundary
///         included; for collinear input, the points in order along the line.
///     duplicates: (k, 2) int64 rows [duplicate, kept]: kept is the first occurrence of
///         the same coordinates; sorted by duplicate.
///     point_count: the number of input points, duplicates included.
#[pyclass(module = "wdm_crust", frozen)]
pub struct Triangulation {
    source: Source,
    triangles: Py<PyArray2<i64>>,
    hull: Py<PyArray1<i64>>,
    duplicates: Py<PyArray2<i64>>,
}

impl Triangulation {
    /// The Python object over `source`, whose arrays are `data`.
    pub fn new(py: Python<'_>, source: Source, data: TriangulationData) -> PyResult<Self> {
        Ok(Triangulation {
            source,
            triangles: rows_array(py, data.triangles)?.unbind(),
            hull: vector(py, data.hull).unbind(),
            duplicates: rows_array(py, data.duplicates)?.unbind(),
        })
    }
}

#[pymethods]
impl Triangulation {
    /// (m, 3) int64: the triangles, counterclockwise index triples.
    #[getter]
    fn triangles(&self, py: Python<'_>) -> Py<PyArray2<i64>> {
        self.triangles.clone_ref(py)
    }

    /// (h,) int64: the convex hull, counterclockwise (collinear input: along the line).
    #[getter]
    fn hull(&self, py: Python<'_>) -> Py<PyArray1<i64>> {
        self.hull.clone_ref(py)
    }

    /// (k, 2) int64: [duplicate, kept] pairs, kept being the first occurrence.
    #[getter]
    fn duplicates(&self, py: Python<'_>) -> Py<PyArray2<i64>> {
        self.duplicates.clone_ref(py)
    }

    /// The number of input points, duplicates included.
    #[getter]
    fn point_count(&self) -> usize {
        self.source.get().point_count()
    }

    /// The Voronoi diagram, the dual of this triangulation (no new triangulation is built).
    fn voronoi(&self, py: Python<'_>) -> PyResult<Voronoi> {
        let tri = self.source.get();
        let data = py.detach(|| VoronoiData::of(&tri.voronoi()));
        Voronoi::new(py, data)
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "Triangulation(point_count={}, triangles={}, hull={}, duplicates={})",
            self.point_count(),
            self.triangles.bind(py).shape()[0],
            self.hull.bind(py).len(),
            self.duplicates.bind(py).shape()[0]
        )
    }
}

/// The exact Delaunay triangulation of `points`.
///
/// Args:
///     points: an (n, 2) array-like of real numbers. A C-contiguous float64 array is read
///         in place, without a copy; other arrays and lists are converted to float64.
///
/// Returns:
///     Triangulation with `triangles` (m, 3), `hull` (h,) and `duplicates` (k, 2), all
///     int64 row indices of `points`. Every decision (orientation, in-circle) is exact, so
///     the result is a Delaunay triangulation of the float64 values as given; points on a
///     common circle get one of its valid triangulations, the same whatever the input
///     order. Every distinct point is in at least one triangle unless all are collinear
///     (then `triangles` is empty and `hull` lists the points along the line).
///
/// Raises:
///     ValueError: the engine refuses a coordinate (NaN, infinite, or outside the range
///         its exact predicates support); the message names the point's index. Also for a
///         shape other than (n, 2).
///     TypeError: the points are not real numbers (strings, complex, booleans, objects).
///
/// The GIL is released while the engine runs. Do not write to `points` from another
/// thread during the call.
#[pyfunction]
pub fn triangulate(py: Python<'_>, points: &Bound<'_, PyAny>) -> PyResult<Triangulation> {
    let (tri, data) = with_points(points, |points| {
        py.detach(|| {
            let tri = wdm_crust::triangulate(points)?;
            let data = TriangulationData::of(&tri);
            Ok((tri, data))
        })
        .map_err(engine_error)
    })?;
    Triangulation::new(py, Source::Own(tri), data)
}
