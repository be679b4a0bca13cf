//! `wdm_crust.triangulate` and the `Triangulation` result.

use std::sync::Arc;

use numpy::{PyArray1, PyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use rayon::prelude::*;
use wdm_crust::delaunay::Locator;

use crate::arrays::{index_rows, indices, rows_array, vector};
use crate::errors::engine_error;
use crate::points::with_rows;
use crate::pool::{on_points, pool, run_in};
use crate::voronoi::{Voronoi, VoronoiData};

/// Queries per run of one locator: each run starts from a fresh copy of the same locator,
/// so the answers (which triangle on a shared edge, which of equally near points) depend on
/// this constant alone, never on the number of threads.
const QUERIES_PER_RUN: usize = 4096;

/// Where the engine's triangulation lives: in a triangulation of its own, or in the
/// reconstruction it was taken from (no copy); shared by the results made from it.
#[derive(Clone)]
pub enum Source {
    Own(Arc<wdm_crust::Triangulation>),
    Reconstruction(Arc<wdm_crust::Reconstruction>),
}

impl Source {
    pub fn get(&self) -> &wdm_crust::Triangulation {
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
            triangles: tri.triangles().map(|t| t.map(i64::from)).collect(),
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
///     points: (n, 2) float64, the input points (a copy).
///
/// Methods `locate(queries)` and `nearest(queries)` answer many point queries at once.
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

    /// (n, 2) float64: the input points, duplicates included (a copy).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        rows_array(py, input_points(self.source.get()))
    }

    /// The Voronoi diagram, the dual of this triangulation (no new triangulation is built).
    fn voronoi(&self, py: Python<'_>) -> PyResult<Voronoi> {
        let tri = self.source.get();
        let data = py.detach(|| VoronoiData::of(&tri.voronoi()));
        Voronoi::new(py, self.source.clone(), data)
    }

    /// The triangle that holds each query point.
    ///
    /// Args:
    ///     queries: an (m, 2) array-like of real numbers (read as `points` are: a
    ///         C-contiguous float64 array without a copy).
    ///
    /// Returns:
    ///     (m,) int64: for each query, the row of `triangles` whose closed triangle holds
    ///     it, or -1 outside the convex hull (and for every query when there are no
    ///     triangles: collinear input or fewer than three distinct points). A query on an
    ///     edge or on an input point gets one of the triangles around it. Decided exactly:
    ///     the orientation tests of the walk are exact.
    ///
    /// Raises:
    ///     ValueError: a query coordinate is NaN or infinite (naming the query), or the
    ///         shape is not (m, 2).
    ///     TypeError: the queries are not real numbers.
    ///
    /// The GIL is released while the queries run, on all cores (see `threads`).
    #[pyo3(signature = (queries, *, threads = None))]
    fn locate<'py>(
        &self,
        py: Python<'py>,
        queries: &Bound<'py, PyAny>,
        threads: Option<i64>,
    ) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let found = self.query(py, queries, threads, |locator, q| {
            locator
                .triangle_containing(q)
                .map(|t| t.map_or(-1, |t| i64::from(t.get())))
        })?;
        Ok(vector(py, found))
    }

    /// The input point nearest to each query point.
    ///
    /// Args:
    ///     queries: an (m, 2) array-like of real numbers (see `locate`).
    ///
    /// Returns:
    ///     (m,) int64: for each query, the index of an input point at the least distance
    ///     from it (compared exactly; the first occurrence of duplicated coordinates); when
    ///     several are equally near, one of them. -1 for every query when there are no
    ///     points.
    ///
    /// Raises:
    ///     ValueError, TypeError: as `locate`.
    ///
    /// The GIL is released while the queries run, on all cores (see `threads`).
    #[pyo3(signature = (queries, *, threads = None))]
    fn nearest<'py>(
        &self,
        py: Python<'py>,
        queries: &Bound<'py, PyAny>,
        threads: Option<i64>,
    ) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let found = self.query(py, queries, threads, |locator, q| {
            locator.nearest(q).map(|p| p.map_or(-1, i64::from))
        })?;
        Ok(vector(py, found))
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

impl Triangulation {
    /// `answer` for each row of `queries`, without the GIL, in runs of
    /// [`QUERIES_PER_RUN`] spread over the pool's threads.
    fn query(
        &self,
        py: Python<'_>,
        queries: &Bound<'_, PyAny>,
        threads: Option<i64>,
        answer: impl Fn(&mut Locator<'_>, [f64; 2]) -> Result<i64, wdm_crust::Error> + Sync,
    ) -> PyResult<Vec<i64>> {
        let pool = pool(threads)?;
        let tri = self.source.get();
        with_rows(queries, "queries", |queries| {
            if let Some((i, value)) = queries
                .iter()
                .enumerate()
                .find_map(|(i, q)| q.iter().find(|c| !c.is_finite()).map(|&c| (i, c)))
            {
                return Err(PyValueError::new_err(format!(
                    "query {i}: coordinate {value} is not a finite number"
                )));
            }
            py.detach(|| {
                run_in(pool.as_ref(), || {
                    let locator = tri.locator();
                    let runs: Result<Vec<Vec<i64>>, wdm_crust::Error> = queries
                        .par_chunks(QUERIES_PER_RUN)
                        .map(|run| {
                            let mut locator = locator.clone();
                            run.iter().map(|&q| answer(&mut locator, q)).collect()
                        })
                        .collect();
                    runs.map(|runs| runs.concat())
                })
            })
            .map_err(engine_error)
        })
    }
}

/// The input points of `tri` in the caller's order, duplicates included.
pub fn input_points(tri: &wdm_crust::Triangulation) -> Vec<[f64; 2]> {
    (0..tri.point_count() as u32)
        .map(|i| tri.point(i))
        .collect()
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
/// The GIL is released while the engine runs, on `threads` worker threads (the command
/// line's --threads; None: all cores, or RAYON_NUM_THREADS); the result does not depend on
/// their number. Do not write to `points` from another thread during the call.
#[pyfunction]
#[pyo3(signature = (points, *, threads = None))]
pub fn triangulate(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    threads: Option<i64>,
) -> PyResult<Triangulation> {
    let (tri, data) = on_points(py, points, threads, |points| {
        let tri = wdm_crust::triangulate(points)?;
        let data = TriangulationData::of(&tri);
        Ok((tri, data))
    })?;
    Triangulation::new(py, Source::Own(Arc::new(tri)), data)
}
