//! `wdm_crust.reconstruct`, its options, and the `Reconstruction` and `Curve` results.

use std::sync::Arc;

use numpy::{PyArray1, PyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyDict, PyList, PyTuple};
use wdm_crust::io::SvgOptions;
use wdm_crust::reconstruct::{Algorithm, MedialAxisMode, Options, OptionsConflict, WdmSetting};

use crate::arrays::{index_rows, indices, rows_array, vector};
use crate::pool::on_points;
use crate::triangulation::{input_points, Source, Triangulation, TriangulationData};

/// The SVG underlays by their command-line names (`--show`).
const LAYERS: [&str; 3] = ["delaunay", "voronoi", "labels"];

/// The algorithms by their command-line names (`--algorithm`).
const ALGORITHMS: [Algorithm; 3] = [Algorithm::Wdm, Algorithm::Crust, Algorithm::NnCrust];
/// The medial-axis modes by their command-line names (`--medial-axis`).
const MEDIAL_AXIS_MODES: [MedialAxisMode; 3] = [
    MedialAxisMode::Pruned,
    MedialAxisMode::Raw,
    MedialAxisMode::Omitted,
];

/// The engine's options from the keyword arguments given (`None`: the engine's default);
/// unknown names are a `ValueError` that lists the known ones, and so are options that do not
/// apply to the algorithm (the engine's [`Options::check`]), saying why.
fn options(
    algorithm: &str,
    peeling: Option<bool>,
    medial_axis: Option<&str>,
    peeling_budget: Option<i64>,
    smooth: bool,
    thinning: bool,
) -> PyResult<Options> {
    let algorithm = by_name(&ALGORITHMS, Algorithm::name, "algorithm", algorithm)?;
    let mut options = Options::new().with_algorithm(algorithm);
    if let Some(peeling) = peeling {
        options = options.with_peeling(peeling);
    }
    if let Some(name) = medial_axis {
        let mode = by_name(
            &MEDIAL_AXIS_MODES,
            MedialAxisMode::name,
            "medial_axis",
            name,
        )?;
        options = options.with_medial_axis(mode);
    }
    options = options.with_smoothing(smooth).with_thinning(thinning);
    if let Some(budget) = peeling_budget {
        let budget = usize::try_from(budget).map_err(|_| {
            PyValueError::new_err(format!(
                "peeling_budget must be a non-negative integer, got {budget}"
            ))
        })?;
        options = options.with_peeling_budget(budget);
    }
    options.check().map_err(|conflict| {
        PyValueError::new_err(match conflict {
            OptionsConflict::WdmOnly { setting, .. } => {
                let keyword = match setting {
                    WdmSetting::MedialAxis => {
                        format!("medial_axis='{}'", options.medial_axis().name())
                    }
                    WdmSetting::Peeling => "peeling=True".to_string(),
                    WdmSetting::PeelingBudget => "peeling_budget".to_string(),
                    other => format!("the {} setting", other.name()),
                };
                format!(
                    "{keyword} does not apply to algorithm='{}': {}; leave it out, or use \
                     algorithm='wdm'",
                    algorithm.name(),
                    conflict.reason()
                )
            }
            OptionsConflict::BudgetWithoutPeeling => format!(
                "peeling_budget does not apply with peeling=False: {}; leave one of them out",
                conflict.reason()
            ),
            other => other.to_string(),
        })
    })?;
    Ok(options)
}

/// The item of `items` called `wanted`.
fn by_name<T: Copy>(
    items: &[T],
    name: fn(T) -> &'static str,
    option: &str,
    wanted: &str,
) -> PyResult<T> {
    items
        .iter()
        .copied()
        .find(|&item| name(item) == wanted)
        .ok_or_else(|| {
            let known: Vec<String> = items.iter().map(|&i| format!("'{}'", name(i))).collect();
            PyValueError::new_err(format!(
                "{option} must be one of {}, got '{wanted}'",
                known.join(", ")
            ))
        })
}

/// One curve's arrays, computed without the GIL.
struct CurveData {
    closed: bool,
    points: Vec<i64>,
    coords: Vec<[f64; 2]>,
}

/// The arrays of a reconstruction, computed without the GIL.
struct ReconstructionData {
    edges: Vec<[i64; 2]>,
    curves: Vec<CurveData>,
    medial_vertices: Vec<[f64; 2]>,
    medial_edges: Vec<[i64; 2]>,
    unassigned: Vec<i64>,
}

impl ReconstructionData {
    /// The same data as the command line's JSON; the curves' coordinates are the caller's
    /// points, or the fitted ones with smoothing.
    fn of(rec: &wdm_crust::Reconstruction) -> Self {
        let curves = rec
            .curves()
            .iter()
            .map(|curve| CurveData {
                closed: curve.closed,
                points: indices(curve.points.iter().copied()),
                coords: rec.curve_coords(curve),
            })
            .collect();
        let medial_axis = rec.medial_axis();
        ReconstructionData {
            edges: index_rows(rec.edges()),
            curves,
            medial_vertices: medial_axis.vertices.clone(),
            medial_edges: index_rows(&medial_axis.edges),
            unassigned: indices(rec.unassigned().iter().copied()),
        }
    }
}

/// One reconstructed curve: a closed loop or an open chain.
///
/// Attributes:
///     closed: True for a closed loop (its last point connects back to the first).
///     points: (k,) int64, the point indices along the curve. A closed loop lists each
///         point once, counterclockwise, from its smallest index.
///     coords: (k, 2) float64, the coordinates of those points, the fitted ones with
///         `smooth=True` (for plotting a closed loop, repeat the first row at the end).
#[pyclass(module = "wdm_crust", frozen)]
pub struct Curve {
    closed: bool,
    points: Py<PyArray1<i64>>,
    coords: Py<PyArray2<f64>>,
}

#[pymethods]
impl Curve {
    /// True for a closed loop, False for an open chain.
    #[getter]
    fn closed(&self) -> bool {
        self.closed
    }

    /// (k,) int64: the point indices along the curve.
    #[getter]
    fn points(&self, py: Python<'_>) -> Py<PyArray1<i64>> {
        self.points.clone_ref(py)
    }

    /// (k, 2) float64: the coordinates of the points along the curve.
    #[getter]
    fn coords(&self, py: Python<'_>) -> Py<PyArray2<f64>> {
        self.coords.clone_ref(py)
    }

    /// The number of points on the curve.
    fn __len__(&self, py: Python<'_>) -> usize {
        self.points.bind(py).len()
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "Curve(closed={}, points={})",
            if self.closed { "True" } else { "False" },
            self.points.bind(py).len()
        )
    }
}

/// One polygon's rings, computed without the GIL.
struct PolygonData {
    exterior_points: Vec<i64>,
    exterior: Vec<[f64; 2]>,
    hole_points: Vec<Vec<i64>>,
    holes: Vec<Vec<[f64; 2]>>,
}

/// A polygon made of reconstructed closed curves: an exterior ring and the rings of its
/// holes (the closed curves directly inside it), nested exactly as the command line's
/// GeoJSON nests them.
///
/// Attributes:
///     exterior: (k, 2) float64, the outer ring counterclockwise, not closed (the first
///         vertex is not repeated); the curve's coordinates (fitted with `smooth=True`).
///     holes: list of (k, 2) float64 arrays, the rings of the holes, clockwise, not closed.
///     exterior_points: (k,) int64, the point indices of the outer ring.
///     hole_points: list of (k,) int64 arrays, the point indices of each hole.
///     __geo_interface__: the GeoJSON Polygon geometry (closed rings), as a dict, so that
///         `shapely.geometry.shape(polygon)` and other GIS tools take it directly.
#[pyclass(module = "wdm_crust", frozen)]
pub struct Polygon {
    exterior_points: Py<PyArray1<i64>>,
    exterior: Py<PyArray2<f64>>,
    hole_points: Vec<Py<PyArray1<i64>>>,
    holes: Vec<Py<PyArray2<f64>>>,
    /// The rings as given, for `__geo_interface__`.
    rings: Vec<Vec<[f64; 2]>>,
}

impl Polygon {
    fn new(py: Python<'_>, data: PolygonData) -> PyResult<Self> {
        let mut rings = vec![data.exterior.clone()];
        rings.extend(data.holes.iter().cloned());
        Ok(Polygon {
            exterior_points: vector(py, data.exterior_points).unbind(),
            exterior: rows_array(py, data.exterior)?.unbind(),
            hole_points: data
                .hole_points
                .into_iter()
                .map(|ring| vector(py, ring).unbind())
                .collect(),
            holes: data
                .holes
                .into_iter()
                .map(|ring| rows_array(py, ring).map(Bound::unbind))
                .collect::<PyResult<_>>()?,
            rings,
        })
    }
}

#[pymethods]
impl Polygon {
    /// (k, 2) float64: the outer ring, counterclockwise, not closed.
    #[getter]
    fn exterior(&self, py: Python<'_>) -> Py<PyArray2<f64>> {
        self.exterior.clone_ref(py)
    }

    /// list of (k, 2) float64 arrays: the holes, clockwise, not closed.
    #[getter]
    fn holes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        PyList::new(py, self.holes.iter().map(|h| h.clone_ref(py)))
    }

    /// (k,) int64: the point indices of the outer ring.
    #[getter]
    fn exterior_points(&self, py: Python<'_>) -> Py<PyArray1<i64>> {
        self.exterior_points.clone_ref(py)
    }

    /// list of (k,) int64 arrays: the point indices of each hole.
    #[getter]
    fn hole_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        PyList::new(py, self.hole_points.iter().map(|h| h.clone_ref(py)))
    }

    /// The GeoJSON geometry {"type": "Polygon", "coordinates": [ring, ...]}, each ring a
    /// list of [x, y] closed (its first position repeated last): the geometry of the
    /// command line's GeoJSON feature for this polygon.
    #[getter]
    fn __geo_interface__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let rings = self
            .rings
            .iter()
            .map(|ring| {
                let positions = ring.iter().chain(ring.first()).map(|&[x, y]| [x, y]);
                PyList::new(py, positions)
            })
            .collect::<PyResult<Vec<_>>>()?;
        let geometry = PyDict::new(py);
        geometry.set_item("type", "Polygon")?;
        geometry.set_item("coordinates", PyList::new(py, rings)?)?;
        Ok(geometry)
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "Polygon(exterior={}, holes={})",
            self.exterior_points.bind(py).len(),
            self.holes.len()
        )
    }
}

/// The result of `wdm_crust.reconstruct`.
///
/// Attributes:
///     algorithm: 'wdm', 'crust' or 'nn-crust'.
///     edges: (e, 2) int64, the reconstructed edges [i, j] with i < j, sorted.
///     curves: list of Curve, the edges assembled into closed loops and open chains (open
///         chains first, then loops by their smallest index).
///     medial_axis: (vertices (v, 2) float64, edges (s, 2) int64): the WDM_MAT segments
///         between inner Voronoi vertices; empty for 'crust' and 'nn-crust'.
///     unassigned: (u,) int64, the points on no curve (outliers, leftovers of noise),
///         sorted; duplicates are not listed.
///     passes: how many passes ran (more than one when peeling found nested curves).
///     peeling_budget_exhausted: True when peeling stopped at its budget.
///     point_count: the number of input points, duplicates included.
///     points: (n, 2) float64, the input points (a copy).
///     duplicates: (k, 2) int64 rows [duplicate, kept].
///     warnings: list of (code, message), as the command line's JSON "warnings".
///     triangulation: the Delaunay triangulation of all the points (built on first use).
///     __geo_interface__: the command line's GeoJSON FeatureCollection, as a dict.
///
/// Methods `polygons()`, `to_geojson()` and `to_svg()` give the closed curves as polygons
/// with holes, the command line's GeoJSON and its SVG picture.
#[pyclass(module = "wdm_crust", frozen)]
pub struct Reconstruction {
    inner: Arc<wdm_crust::Reconstruction>,
    edges: Py<PyArray2<i64>>,
    curves: Vec<Py<Curve>>,
    medial_vertices: Py<PyArray2<f64>>,
    medial_edges: Py<PyArray2<i64>>,
    unassigned: Py<PyArray1<i64>>,
    triangulation: PyOnceLock<Py<Triangulation>>,
}

impl Reconstruction {
    fn new(
        py: Python<'_>,
        inner: wdm_crust::Reconstruction,
        data: ReconstructionData,
    ) -> PyResult<Self> {
        let curves = data
            .curves
            .into_iter()
            .map(|curve| {
                let curve = Curve {
                    closed: curve.closed,
                    points: vector(py, curve.points).unbind(),
                    coords: rows_array(py, curve.coords)?.unbind(),
                };
                Py::new(py, curve)
            })
            .collect::<PyResult<Vec<_>>>()?;
        Ok(Reconstruction {
            inner: Arc::new(inner),
            edges: rows_array(py, data.edges)?.unbind(),
            curves,
            medial_vertices: rows_array(py, data.medial_vertices)?.unbind(),
            medial_edges: rows_array(py, data.medial_edges)?.unbind(),
            unassigned: vector(py, data.unassigned).unbind(),
            triangulation: PyOnceLock::new(),
        })
    }
}

#[pymethods]
impl Reconstruction {
    /// 'wdm', 'crust' or 'nn-crust'.
    #[getter]
    fn algorithm(&self) -> &'static str {
        self.inner.algorithm().name()
    }

    /// (e, 2) int64: the reconstructed edges [i, j], i < j, sorted.
    #[getter]
    fn edges(&self, py: Python<'_>) -> Py<PyArray2<i64>> {
        self.edges.clone_ref(py)
    }

    /// list of Curve: closed loops and open chains.
    #[getter]
    fn curves<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        PyList::new(py, self.curves.iter().map(|c| c.clone_ref(py)))
    }

    /// (vertices (v, 2) float64, edges (s, 2) int64): the medial axis.
    #[getter]
    fn medial_axis<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(
            py,
            [
                self.medial_vertices.clone_ref(py).into_any(),
                self.medial_edges.clone_ref(py).into_any(),
            ],
        )
    }

    /// (u,) int64: the points on no curve, sorted.
    #[getter]
    fn unassigned(&self, py: Python<'_>) -> Py<PyArray1<i64>> {
        self.unassigned.clone_ref(py)
    }

    /// (k, 2) int64 rows [duplicate, kept]: a point with the same coordinates as an
    /// earlier one, and that first occurrence (as the triangulation's).
    #[getter]
    fn duplicates<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<i64>>> {
        rows_array(py, index_rows(self.inner.duplicates()))
    }

    /// list of (code, message): the signs that the result is probably not what was wanted
    /// (most points on no curve, a scatter rather than curves, an edge far longer than its
    /// neighbours, a loop closed across a gap, curves closer than the spacing, peeling
    /// stopped at its budget), each message saying what to try; the same as the command
    /// line's JSON "warnings", empty when there is nothing to say. Computed on first use.
    #[getter]
    fn warnings(&self) -> Vec<(&'static str, String)> {
        self.inner
            .warnings()
            .iter()
            .map(|w| (w.code.name(), w.message.clone()))
            .collect()
    }

    /// How many passes ran.
    #[getter]
    fn passes(&self) -> usize {
        self.inner.passes()
    }

    /// int or None: when the input was a dense noisy band and thinned, the number of
    /// representatives the curves run through (every other point is unassigned); the
    /// command line's JSON "thinned".
    #[getter]
    fn thinned(&self) -> Option<usize> {
        self.inner.thinned()
    }

    /// True when peeling stopped at its budget (the unassigned points may hold curves).
    #[getter]
    fn peeling_budget_exhausted(&self) -> bool {
        self.inner.peeling_budget_exhausted()
    }

    /// The number of input points, duplicates included.
    #[getter]
    fn point_count(&self) -> usize {
        self.inner.triangulation().point_count()
    }

    /// (n, 2) float64: the input points, duplicates included (a copy).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        rows_array(py, input_points(self.inner.triangulation()))
    }

    /// The Delaunay triangulation of all the points, built on first use.
    #[getter]
    fn triangulation(&self, py: Python<'_>) -> PyResult<Py<Triangulation>> {
        let tri = self.triangulation.get_or_try_init(py, || {
            let data = py.detach(|| TriangulationData::of(self.inner.triangulation()));
            let source = Source::Reconstruction(Arc::clone(&self.inner));
            Py::new(py, Triangulation::new(py, source, data)?)
        })?;
        Ok(tri.clone_ref(py))
    }

    /// The closed curves as polygons with holes: a closed curve inside no other, or inside
    /// a hole, is the exterior of a polygon; the closed curves directly inside it are its
    /// holes. Nested exactly, as the command line's GeoJSON (one Polygon feature each, in
    /// the same order). Computed on each call.
    ///
    /// Returns:
    ///     list of Polygon.
    fn polygons(&self, py: Python<'_>) -> PyResult<Vec<Polygon>> {
        let rec = &self.inner;
        let data: Vec<PolygonData> = py.detach(|| {
            rec.polygons()
                .into_iter()
                .map(|polygon| PolygonData {
                    exterior_points: indices(polygon.exterior.iter().copied()),
                    exterior: polygon.exterior_coords(rec),
                    hole_points: polygon
                        .holes
                        .iter()
                        .map(|ring| indices(ring.iter().copied()))
                        .collect(),
                    holes: polygon.hole_coords(rec),
                })
                .collect()
        });
        data.into_iter().map(|p| Polygon::new(py, p)).collect()
    }

    /// The reconstruction as GeoJSON (RFC 7946): the text `wdm-crust reconstruct --format
    /// geojson` writes on the same points with the same options, byte for byte. A
    /// FeatureCollection of one Polygon per outer closed curve (holes inside), one
    /// LineString per open chain, one MultiLineString for the medial axis and one
    /// MultiPoint of the unassigned points (left out when there are none), with the
    /// collection's own properties "duplicates" and "warnings".
    ///
    /// Returns:
    ///     str, the GeoJSON document.
    fn to_geojson(&self, py: Python<'_>) -> PyResult<String> {
        let rec = &self.inner;
        let out = py.detach(|| {
            let mut out = Vec::new();
            wdm_crust::io::write_reconstruction_geojson(rec, &mut out).map(|()| out)
        });
        text(out, "GeoJSON")
    }

    /// The command line's GeoJSON FeatureCollection (`to_geojson`) as a dict, so that
    /// `geopandas.GeoDataFrame.from_features(rec)` and other GIS tools take the result
    /// directly. Computed on each use.
    #[getter]
    fn __geo_interface__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let text = self.to_geojson(py)?;
        py.import("json")?.call_method1("loads", (text,))
    }

    /// The reconstruction drawn as an SVG picture, the command line's `--format svg`: the
    /// points, the curves (closed red, open purple), the medial axis (green), the
    /// unassigned points (grey rings) and a legend.
    ///
    /// Args:
    ///     y_down: the data is in image coordinates (y grows downwards): draw it the right
    ///         way up (--y-down).
    ///     show: underlays, any of 'delaunay', 'voronoi', 'labels' (WDM only) (--show).
    ///     no_points: leave out the input points, dots and rings (--no-points).
    ///
    /// Returns:
    ///     str, the SVG document.
    ///
    /// Raises:
    ///     ValueError: an unknown underlay, or 'labels' for 'crust' or 'nn-crust'.
    #[pyo3(signature = (*, y_down = false, show = Vec::new(), no_points = false))]
    fn to_svg(
        &self,
        py: Python<'_>,
        y_down: bool,
        show: Vec<String>,
        no_points: bool,
    ) -> PyResult<String> {
        let mut options = SvgOptions::default();
        for layer in &show {
            match layer.as_str() {
                "delaunay" => options.delaunay = true,
                "voronoi" => options.voronoi = true,
                "labels" => options.labels = true,
                other => {
                    let known: Vec<String> = LAYERS.iter().map(|l| format!("'{l}'")).collect();
                    return Err(PyValueError::new_err(format!(
                        "show must list some of {}, got '{other}'",
                        known.join(", ")
                    )));
                }
            }
        }
        if options.labels && self.inner.algorithm() != Algorithm::Wdm {
            return Err(PyValueError::new_err(format!(
                "show=['labels'] does not apply to algorithm='{}': only WDM labels the \
                 Voronoi vertices; leave it out, or use algorithm='wdm'",
                self.algorithm()
            )));
        }
        options.y_down = y_down;
        options.points = !no_points;
        let rec = &self.inner;
        let out = py.detach(|| {
            let mut out = Vec::new();
            wdm_crust::io::write_reconstruction_svg(rec, &options, &mut out).map(|()| out)
        });
        text(out, "SVG")
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        let closed = self.curves.iter().filter(|c| c.get().closed).count();
        format!(
            "Reconstruction(algorithm='{}', point_count={}, edges={}, closed_curves={}, open_chains={}, medial_axis_edges={}, unassigned={}, passes={})",
            self.algorithm(),
            self.point_count(),
            self.edges.bind(py).shape()[0],
            closed,
            self.curves.len() - closed,
            self.medial_edges.bind(py).shape()[0],
            self.unassigned.bind(py).len(),
            self.passes()
        )
    }
}

/// The text a writer produced into memory.
fn text(out: std::io::Result<Vec<u8>>, what: &str) -> PyResult<String> {
    let out = out.map_err(|e| PyRuntimeError::new_err(format!("writing {what}: {e}")))?;
    String::from_utf8(out).map_err(|e| PyRuntimeError::new_err(format!("writing {what}: {e}")))
}

/// Reconstructs the curves the points were sampled from, and their medial axis.
///
/// Args:
///     points: an (n, 2) array-like of real numbers (see `triangulate`).
///     algorithm: 'wdm' (WDM_CRUST, the default), 'crust' (Amenta–Bern–Eppstein) or
///         'nn-crust' (Dey–Kumar); the baselines return no medial axis.
///     peeling: WDM: rerun on the points no curve reached, to find nested curves (holes);
///         False runs the paper's single pass. None (the default) is True for WDM.
///     medial_axis: WDM: 'pruned' (what None, the default, gives WDM: spurious branches
///         removed), 'raw' (the paper's WDM_MAT, every Voronoi edge between two inner
///         vertices) or 'none' (the curves only, in about half the time; the medial axis
///         returned is empty).
///     peeling_budget: WDM: the extra passes together may run on at most this many times
///         the input's points; None keeps the engine's default (as the command line's).
///     smooth: fit the curves to the samples (the command line's --smooth): every curve
///         vertex is placed on a local fit of the noisy samples around it, and each curve's
///         `coords` are the fitted positions; False (the default) keeps the input points.
///     thinning: WDM: True (the default) thins a dense noisy band (points many sample
///         spacings wide around their curves) to representatives near its middle and
///         reconstructs the curves through them, every other point unassigned
///         (`Reconstruction.thinned` counts them); False reconstructs the points as they
///         are (the command line's --no-thinning).
///     threads: worker threads (the command line's --threads); None: all cores, or
///         RAYON_NUM_THREADS. The result does not depend on their number.
///
/// The WDM options that ask a baseline for what it does not do are refused with 'crust'
/// and 'nn-crust': medial_axis='pruned' or 'raw', peeling=True, any peeling_budget.
/// medial_axis='none' and peeling=False ask for nothing a baseline does and are accepted
/// with every algorithm. A peeling_budget with peeling=False is refused too.
///
/// Returns:
///     Reconstruction with `edges`, `curves`, `medial_axis`, `unassigned`: the same data as
///     `wdm-crust reconstruct`'s JSON with the same options.
///
/// Raises:
///     ValueError: invalid points (as `triangulate`), an unknown algorithm or medial_axis
///         name, a negative peeling_budget, or an option that does not apply to the
///         algorithm (saying why).
///     TypeError: the points are not real numbers.
///
/// The GIL is released while the engine runs.
#[pyfunction]
#[allow(clippy::too_many_arguments)] // the keywords of the command line's options
#[pyo3(signature = (points, *, algorithm = "wdm", peeling = None, medial_axis = None, peeling_budget = None, smooth = false, thinning = true, threads = None))]
pub fn reconstruct(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    algorithm: &str,
    peeling: Option<bool>,
    medial_axis: Option<&str>,
    peeling_budget: Option<i64>,
    smooth: bool,
    thinning: bool,
    threads: Option<i64>,
) -> PyResult<Reconstruction> {
    let options = options(
        algorithm,
        peeling,
        medial_axis,
        peeling_budget,
        smooth,
        thinning,
    )?;
    let (rec, data) = on_points(py, points, threads, |points| {
        let rec = wdm_crust::reconstruct_with(points, &options)?;
        let data = ReconstructionData::of(&rec);
        Ok((rec, data))
    })?;
    Reconstruction::new(py, rec, data)
}
