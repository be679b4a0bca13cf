//! `wdm_crust.voronoi` and the `Voronoi` result.

use std::sync::Arc;

use numpy::{PyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::PyList;
use wdm_crust::BoundingBox;

use crate::arrays::{rows_array, vector};
use crate::pool::on_points;
use crate::triangulation::{input_points, Source};

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
            cell_vertices.extend(vor.cell(p).map(|v| i64::from(v.get())));
            cell_offsets.push(cell_vertices.len());
        }
        VoronoiData {
            vertices: vor.vertex_positions().to_vec(),
            edges: vor
                .finite_edges()
                .map(|(_, a, b)| [i64::from(a.get()), i64::from(b.get())])
                .collect(),
            rays: vor
                .rays()
                .map(|(_, v, [dx, dy])| [f64::from(v.get()), dx, dy])
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
///
/// Methods `clipped_cells(bbox)` and `to_geojson(bbox)` clip the cells to a box.
#[pyclass(module = "wdm_crust", frozen)]
pub struct Voronoi {
    /// The triangulation the diagram is the dual of (for the clipped cells).
    source: Source,
    vertices: Py<PyArray2<f64>>,
    edges: Py<PyArray2<i64>>,
    rays: Py<PyArray2<f64>>,
    cell_offsets: Vec<usize>,
    cell_vertices: Vec<i64>,
    /// The list of cell arrays, built on first use (n small arrays cost more than the rest).
    cells: PyOnceLock<Py<PyList>>,
}

impl Voronoi {
    /// The Python object holding `data`, the diagram of the triangulation in `source`.
    pub fn new(py: Python<'_>, source: Source, data: VoronoiData) -> PyResult<Self> {
        Ok(Voronoi {
            source,
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

    /// The cells clipped to a box: polygons that tile it.
    ///
    /// Args:
    ///     bbox: (xmin, ymin, xmax, ymax), or None (the default) for the command line's
    ///         default box: the points' bounding box enlarged on every side by 10 % of its
    ///         larger side.
    ///
    /// Returns:
    ///     list of n float64 arrays of shape (k, 2), one per input point (by its index):
    ///     its cell clipped to the box, counterclockwise, not closed (the first vertex is
    ///     not repeated), from its lexicographically smallest vertex. The cells of the
    ///     distinct points tile the box (their areas add up to its area, no two overlap).
    ///     Empty, shape (0, 2), for a duplicate point (its first occurrence has the cell)
    ///     and for a cell that meets the box in no area. The same rings as the command
    ///     line's `voronoi --format geojson --clip ...`.
    ///
    /// Raises:
    ///     ValueError: a box with a NaN or infinite bound, or min not below max; no bbox
    ///         for points whose default box would overflow float64.
    #[pyo3(signature = (bbox = None))]
    fn clipped_cells<'py>(
        &self,
        py: Python<'py>,
        bbox: Option<[f64; 4]>,
    ) -> PyResult<Bound<'py, PyList>> {
        let tri = self.source.get();
        let Some(bbox) = clip_box(tri, bbox)? else {
            if tri.point_count() > 0 {
                return Err(PyValueError::new_err(
                    "the points' default box would overflow float64 (coordinates near \
                     ±1.8e308): pass bbox=(xmin, ymin, xmax, ymax)",
                ));
            }
            return PyList::new(py, Vec::<Bound<'py, PyArray2<f64>>>::new());
        };
        let rings = py.detach(|| tri.voronoi().clipped_cells(&bbox));
        let arrays = rings
            .into_iter()
            .map(|ring| rows_array(py, ring))
            .collect::<PyResult<Vec<_>>>()?;
        PyList::new(py, arrays)
    }

    /// The clipped cells as GeoJSON: the text `wdm-crust voronoi --format geojson` writes
    /// (with `--clip` for a `bbox`), a FeatureCollection of one Polygon per distinct point
    /// with properties {"site": i}.
    ///
    /// Args:
    ///     bbox: as `clipped_cells`.
    ///
    /// Returns:
    ///     str, the GeoJSON document (`json.loads` makes it a dict).
    ///
    /// Raises:
    ///     ValueError: as `clipped_cells`.
    #[pyo3(signature = (bbox = None))]
    fn to_geojson(&self, py: Python<'_>, bbox: Option<[f64; 4]>) -> PyResult<String> {
        let tri = self.source.get();
        let Some(bbox) = clip_box(tri, bbox)? else {
            // No points, or no default box that f64 can hold: no cells, as on the command line.
            return Ok("{\"type\":\"FeatureCollection\",\"features\":[]}\n".to_string());
        };
        let out = py.detach(|| {
            let mut out = Vec::new();
            wdm_crust::io::write_voronoi_geojson(&tri.voronoi(), &bbox, &mut out).map(|()| out)
        });
        let out = out.map_err(|e| PyRuntimeError::new_err(format!("writing GeoJSON: {e}")))?;
        String::from_utf8(out).map_err(|e| PyRuntimeError::new_err(format!("writing GeoJSON: {e}")))
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
/// The GIL is released while the engine runs, on `threads` worker threads (see
/// `triangulate`).
#[pyfunction]
#[pyo3(signature = (points, *, threads = None))]
pub fn voronoi(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    threads: Option<i64>,
) -> PyResult<Voronoi> {
    let (tri, data) = on_points(py, points, threads, |points| {
        let tri = wdm_crust::triangulate(points)?;
        let data = VoronoiData::of(&tri.voronoi());
        Ok((tri, data))
    })?;
    Voronoi::new(py, Source::Own(Arc::new(tri)), data)
}

/// The box `bbox` names, or the command line's default box around the points of `tri`
/// (`None` when there are no points: then there are no cells either).
fn clip_box(
    tri: &wdm_crust::Triangulation,
    bbox: Option<[f64; 4]>,
) -> PyResult<Option<BoundingBox>> {
    match bbox {
        Some([xmin, ymin, xmax, ymax]) => BoundingBox::new([xmin, ymin], [xmax, ymax])
            .map(Some)
            .map_err(|e| PyValueError::new_err(format!("bbox: {e}"))),
        None => Ok(BoundingBox::around(&input_points(tri))),
    }
}
