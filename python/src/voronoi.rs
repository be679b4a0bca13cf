//! `wdm_crust.voronoi` and the `Voronoi` result.

use numpy::{PyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::PyList;

use crate::arrays::{rows_array, vector};
use crate::errors::engine_error;
use crate::points::with_points;

/// The arrays of a Voronoi diagram, computed without the GIL; the cells as one flat list
/// with offsets (point `i`'s cell is `cell_vertices[cell_offsets[i]..cell_offsets[i + 1]]`).
pub struct VoronoiData {
    vertices: Vec<[f64; 2]>,
    edges: Vec<[i64; 2]>,
    rays: Vec<[f64; 3]>,
    cell_offsets: Vec<usize>,
    cell_vertices: Vec<i64>,
}

impl VoronoiData {
    /// The same data as the command line's JSON.
    pub fn of(vor: &wdm_crust::Voronoi<'_>) -> Self {
        let n = vor.triangulation().point_count();
        let mut cell_offsets = Vec::with_capacity(n + 1);
        let mut cell_vertices = Vec::new();
        cell_offsets.push(0);
        for p in 0..n as u32 {
            cell_vertices.extend(vor.cell(p).map(i64::from));
            cell_offsets.push(cell_vertices.len());
        }
        VoronoiData {
            vertices: vor.vertex_positions().to_vec(),
            edges: vor
                .finite_edges()
                .map(|(_, a, b)| [i64::from(a), i64::from(b)])
                .collect(),
            rays: vor
                .rays()
                .map(|(_, v, [dx, dy])| [f64::from(v), dx, dy])
                .collect(),
            cell_offsets,
            cell_vertices,
        }
    }
}

/// The Voronoi diagram of a point set, the dual of its exact Delaunay triangulation (see
/// `wdm_crust.voronoi`).
///
/// Attributes:
///     vertices: (v, 2) float64, the circumcenters of the Delaunay faces after merging the
///         faces that share a circumcircle (rounded to float64).
///     edges: (e, 2) int64, finite edges as pairs of vertex indices.
///     rays: (r, 3) float64 rows [a, dx, dy]: from vertex a (an exact integer value) to
///         infinity along (dx, dy), the outward normal of its convex hull edge.
///     cells: list of n int64 arrays: the vertices of each point's cell, counterclockwise
///         (for a hull point, from its outgoing ray's vertex to its incoming ray's vertex);
///         empty for a duplicate, and for every point of collinear input.
#[pyclass(module = "wdm_crust", frozen)]
pub struct Voronoi {
    vertices: Py<PyArray2<f64>>,
    edges: Py<PyArray2<i64>>,
    rays: Py<PyArray2<f64>>,
    cell_offsets: Vec<usize>,
    cell_vertices: Vec<i64>,
    /// The list of cell arrays, built on first use (n small arrays cost more than the rest).
    cells: PyOnceLock<Py<PyList>>,
}

impl Voronoi {
    /// The Python object holding `data`.
    pub fn new(py: Python<'_>, data: VoronoiData) -> PyResult<Self> {
        Ok(Voronoi {
            vertices: rows_array(py, data.vertices)?.unbind(),
            edges: rows_array(py, data.edges)?.unbind(),
            rays: rows_array(py, data.rays)?.unbind(),
            cell_offsets: data.cell_offsets,
            cell_vertices: data.cell_vertices,
            cells: PyOnceLock::new(),
        })
    }
}

#[pymethods]
impl Voronoi {
    /// (v, 2) float64: the Voronoi vertices (merged-face circumcenters).
    #[getter]
    fn vertices(&self, py: Python<'_>) -> Py<PyArray2<f64>> {
        self.vertices.clone_ref(py)
    }

    /// (e, 2) int64: the finite edges, as pairs of vertex indices.
    #[getter]
    fn edges(&self, py: Python<'_>) -> Py<PyArray2<i64>> {
        self.edges.clone_ref(py)
    }

    /// (r, 3) float64: the rays, rows [a, dx, dy] from vertex a along (dx, dy).
    #[getter]
    fn rays(&self, py: Python<'_>) -> Py<PyArray2<f64>> {
        self.rays.clone_ref(py)
    }

    /// list of int64 arrays: the vertices of each point's cell, counterclockwise.
    #[getter]
    fn cells(&self, py: Python<'_>) -> PyResult<Py<PyList>> {
        let cells = self.cells.get_or_try_init(py, || {
            let arrays = self
                .cell_offsets
                .windows(2)
                .map(|w| vector(py, self.cell_vertices[w[0]..w[1]].to_vec()));
            PyList::new(py, arrays).map(Bound::unbind)
        })?;
        Ok(cells.clone_ref(py))
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "Voronoi(vertices={}, edges={}, rays={}, cells={})",
            self.vertices.bind(py).shape()[0],
            self.edges.bind(py).shape()[0],
            self.rays.bind(py).shape()[0],
            self.cell_offsets.len() - 1
        )
    }
}

/// The Voronoi diagram of `points`: the dual of their exact Delaunay triangulation, with the
/// Delaunay faces that share a circumcircle merged into one vertex (four cocircular points
/// give one vertex, not a zero-length edge).
///
/// Args:
///     points: an (n, 2) array-like of real numbers (see `triangulate`).
///
/// Returns:
///     Voronoi with `vertices` (v, 2), `edges` (e, 2), `rays` (r, 3) and `cells` (a list of
///     n index arrays), the same data as `wdm-crust voronoi`'s JSON. Collinear input (or
///     fewer than three distinct points) has no vertex: the arrays are empty and every
///     cell is empty.
///
/// Raises:
///     ValueError, TypeError: as `triangulate`.
///
/// The GIL is released while the engine runs.
#[pyfunction]
pub fn voronoi(py: Python<'_>, points: &Bound<'_, PyAny>) -> PyResult<Voronoi> {
    let data = with_points(points, |points| {
        py.detach(|| {
            let tri = wdm_crust::triangulate(points)?;
            Ok(VoronoiData::of(&tri.voronoi()))
        })
        .map_err(engine_error)
    })?;
    Voronoi::new(py, data)
}
